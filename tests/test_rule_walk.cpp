// Tests of Wan and Gao's (2022) grid decision rules (problems/grid/rough_rules.hpp) and the walk they drive
// (problems/grid/rule_walk.hpp): the table's sizes at every step, the rules against the labelling
// policy and the full table, hand-made situations, completeness against A* on random maps, the
// bundled maps, determinism.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "framework/random.hpp"
#include "problems/grid/map.hpp"
#include "problems/grid/map_io.hpp"
#include "problems/grid/path.hpp"
#include "problems/grid/planners/astar.hpp"
#include "problems/grid/rough_rules.hpp"
#include "problems/grid/rule_walk.hpp"
#include "problems/grid/walk.hpp"
#include "roughset/roughset.hpp"
#include "tests/grid_support.hpp"

using namespace pride::grid;
namespace rs = pride::roughset;
using pride::test::below;
using pride::test::map_of;

namespace {

GridMap open_map(int w, int h) {
    return GridMap(w, h, std::vector<std::uint8_t>(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0));
}

/// The checks every successful walk must pass: legal, from s to g, no cell twice.
void check_walk(const GridMap& map, const Path& path, Cell s, Cell g, bool corner_cutting) {
    CHECK(path_violation(map, path, s, g, corner_cutting).empty());
    std::vector<std::uint8_t> seen(map.size(), 0);
    bool twice = false;
    for (const Cell c : path) {
        if (!map.inside(c)) continue;
        twice = twice || seen[map.index(c)] != 0;
        seen[map.index(c)] = 1;
    }
    CHECK_FALSE(twice);
}

std::filesystem::path bundled_maps() {
    return std::filesystem::path(PRIDE_SOURCE_DIR) / "examples" / "maps";
}

}  // namespace

TEST_CASE("rule walk: the grid decision table, its reduct and minimal rules", "[grid][roughset]") {
    const GridRuleBook& book = grid_rule_book();
    const rs::DecisionTable& t = book.table;
    const rs::Attributes c = t.conditions(), d = t.decision();

    SECTION("the full table: every state once, labelled by the policy, consistent") {
        REQUIRE(t.rows() == 6561);
        REQUIRE(t.columns() == 9);
        CHECK(t.name(0) == "X1");
        CHECK(t.name(7) == "X8");
        CHECK(t.name(8) == "Y");
        for (std::size_t i = 0; i < t.rows(); ++i) {
            const std::array<int, 8> v = state_values(i);
            CHECK(state_index(v) == i);
            for (std::size_t a = 0; a < 8; ++a) REQUIRE(t.value(i, a) == v[a]);
            REQUIRE(t.value(i, 8) == policy_move(v));
        }
        CHECK(rs::consistent(t, c, d));
        CHECK(rs::dependency(t, c, d) == 1.0);
    }

    SECTION("the reduct is {X1, X2, X3, X7, X8}, the only one; X4, X5, X6 are dispensable") {
        // Y is a function of X1, X2, X8, X3, X7 only, so they keep the table consistent. Each of them
        // is indispensable: two states differing only in it (it 3 or 1, every other of the five 1)
        // have different decisions (it, or back). So the five form the core, the core is itself a
        // reduct, and no other reduct exists (every reduct contains the core).
        const rs::Attributes expected{0, 1, 2, 6, 7};
        CHECK(book.reduct == expected);
        CHECK(rs::reducts(t, c, d) == std::vector<rs::Attributes>{expected});
        CHECK(rs::core(t, c, d) == expected);
        CHECK(rs::quick_reduct(t, c, d) == expected);
        for (const std::size_t backward : {3u, 4u, 5u}) {
            rs::Attributes without;
            for (const std::size_t a : c)
                if (a != backward) without.push_back(a);
            CHECK(rs::dependency(t, without, d) == 1.0);
        }
        CHECK(rs::consistent(t, book.reduct, d));
    }

    SECTION("sizes: 6561 rows, 5 attributes, 243 distinct rows, 63 rules") {
        // 3^5 = 243: every combination of the five kept values occurs. 63 = 1 + 2 + 4 + 8 + 16 + 32:
        // move k needs "X_k = 3" and "not 3" (1 or 2) on each neighbour before it in the policy's
        // order, and every such value is needed, because 3 there would change the decision; the same
        // holds for the 32 combinations of 1 and 2 on all five that mean back.
        CHECK(t.rows() == 6561);
        CHECK(book.reduct.size() == 5);
        CHECK(book.reduced_rows == 243);
        CHECK(book.rules.size() == 63);
        std::array<int, 10> per_move{};
        for (const rs::Rule& rule : book.rules) {
            REQUIRE(rule.decision.size() == 1);
            ++per_move[static_cast<std::size_t>(rule.decision.front())];
        }
        CHECK(per_move == std::array<int, 10>{0, 1, 2, 8, 0, 0, 0, 16, 4, 32});
    }

    SECTION("every rule is certain on the full table, and the rules cover it") {
        std::vector<std::uint8_t> covered(t.rows(), 0);
        for (const rs::Rule& rule : book.rules) {
            std::size_t matched = 0;
            for (std::size_t r = 0; r < t.rows(); ++r) {
                if (!rs::matches(t, rule, r)) continue;
                ++matched;
                covered[r] = 1;
                REQUIRE(t.value(r, 8) == rule.decision.front());
            }
            CHECK(matched == rule.support.size());
            for (const rs::Condition& k : rule.conditions)
                CHECK(std::find(book.reduct.begin(), book.reduct.end(), k.attribute) != book.reduct.end());
        }
        CHECK(std::count(covered.begin(), covered.end(), 1) == 6561);
    }

    SECTION("the lookup built from the rules equals the labelling policy on every state") {
        for (std::size_t i = 0; i < kGridStates; ++i) {
            const std::array<int, 8> v = state_values(i);
            REQUIRE(book.decide(v) == policy_move(v));
        }
    }
}

TEST_CASE("rule walk: goal direction and neighbour numbering", "[grid][roughset]") {
    const Cell c{5, 5};
    CHECK(goal_direction(c, {9, 5}) == 0);  // east
    CHECK(goal_direction(c, {9, 6}) == 0);  // 14 degrees below east
    CHECK(goal_direction(c, {9, 7}) == 1);  // 27 degrees: south-east
    CHECK(goal_direction(c, {5, 9}) == 2);  // south (y grows downwards)
    CHECK(goal_direction(c, {0, 5}) == 4);  // west
    CHECK(goal_direction(c, {1, 4}) == 4);  // just above west
    CHECK(goal_direction(c, {5, 0}) == 6);  // north
    CHECK(goal_direction(c, {9, 0}) == 7);  // north-east
    CHECK(neighbour_direction(7, 1) == 7);
    CHECK(neighbour_direction(7, 2) == 0);  // X2 is 45 degrees clockwise from X1
    CHECK(neighbour_direction(7, 8) == 6);  // X8 is 45 degrees counter-clockwise
}

TEST_CASE("rule walk: hand-made situations", "[grid][roughset]") {
    RuleWalker walker;
    Path path;

    SECTION("open map: every step is X1, the goal direction") {
        const GridMap map = open_map(12, 9);
        const Cell s{1, 2}, g{10, 6};
        for (const bool cutting : {false, true}) {
            // Without jitter X1 is the direction nearest the goal angle.
            walker.jitter = false;
            pride::Rng rng(1);
            REQUIRE(walker.walk(map, s, g, rng, path, cutting));
            check_walk(map, path, s, g, cutting);
            for (std::size_t i = 0; i + 1 < path.size(); ++i)
                CHECK(direction(path[i], path[i + 1]) == goal_direction(path[i], g));
            CHECK(path.size() == 10);  // Chebyshev distance 9, plus the start
            CHECK(walker.cells_entered() == path.size());
            // With jitter (the default) X1 is one of the two directions bracketing the goal angle,
            // so every step still shortens the Chebyshev distance, and the walks differ.
            walker.jitter = true;
            std::set<std::vector<int>> distinct;
            for (std::uint64_t seed = 0; seed < 50; ++seed) {
                pride::Rng r(seed);
                REQUIRE(walker.walk(map, s, g, r, path, cutting));
                check_walk(map, path, s, g, cutting);
                CHECK(path.size() == 10);
                std::vector<int> steps;
                for (std::size_t i = 0; i + 1 < path.size(); ++i) {
                    const int d = direction(path[i], path[i + 1]);
                    const double angle = std::atan2(g.y - path[i].y, g.x - path[i].x) / (std::numbers::pi / 4);
                    CHECK((d == (static_cast<int>(std::floor(angle)) + 8) % 8 ||
                           d == (static_cast<int>(std::ceil(angle)) + 8) % 8));
                    steps.push_back(d);
                }
                distinct.insert(steps);
            }
            CHECK(distinct.size() > 10);
        }
        walker.jitter = true;
    }

    SECTION("X1 blocked: X2 or X8, both seen over many seeds") {
        // Goal to the south-east, the south-east neighbour blocked: X2 = south and X8 = east are both
        // legal (orthogonal), free and unvisited.
        const GridMap map = map_of({".......",  //
                                    ".......",  //
                                    ".......",  //
                                    "...@...",  //
                                    ".......",  //
                                    ".......",  //
                                    "......."});
        const Cell s{2, 2}, g{6, 6};
        bool south = false, east = false;
        for (std::uint64_t seed = 0; seed < 200; ++seed) {
            pride::Rng rng(seed);
            REQUIRE(walker.walk(map, s, g, rng, path));
            check_walk(map, path, s, g, false);
            south = south || path[1] == Cell{2, 3};
            east = east || path[1] == Cell{3, 2};
            CHECK((path[1] == Cell{2, 3} || path[1] == Cell{3, 2}));
        }
        CHECK(south);
        CHECK(east);
    }

    SECTION("X1 blocked orthogonally: without corner cutting X3 or X7, with it X2 or X8") {
        const GridMap map = map_of({".......",  //
                                    ".......",  //
                                    ".......",  //
                                    "...@...",  //
                                    ".......",  //
                                    ".......",  //
                                    "......."});
        const Cell s{2, 3}, g{6, 3};
        std::vector<Cell> first_strict, first_cutting;
        for (std::uint64_t seed = 0; seed < 200; ++seed) {
            pride::Rng rng(seed);
            REQUIRE(walker.walk(map, s, g, rng, path, false));
            check_walk(map, path, s, g, false);
            first_strict.push_back(path[1]);
            REQUIRE(walker.walk(map, s, g, rng, path, true));
            check_walk(map, path, s, g, true);
            first_cutting.push_back(path[1]);
        }
        const auto seen = [](const std::vector<Cell>& v, Cell c) {
            return std::find(v.begin(), v.end(), c) != v.end();
        };
        CHECK(seen(first_strict, Cell{2, 4}));  // X3: south
        CHECK(seen(first_strict, Cell{2, 2}));  // X7: north
        CHECK(std::all_of(first_strict.begin(), first_strict.end(), [](Cell c) {
            return c == Cell{2, 4} || c == Cell{2, 2};
        }));
        CHECK(seen(first_cutting, Cell{3, 4}));  // X2: south-east, cutting the corner of (3, 3)
        CHECK(seen(first_cutting, Cell{3, 2}));  // X8: north-east
        CHECK(std::all_of(first_cutting.begin(), first_cutting.end(), [](Cell c) {
            return c == Cell{3, 4} || c == Cell{3, 2};
        }));
    }

    SECTION("dead end: the rules say back") {
        const GridRuleBook& book = grid_rule_book();
        for (std::size_t i = 0; i < kGridStates; ++i) {
            const std::array<int, 8> v = state_values(i);
            const bool front_open = v[0] == kOpen || v[1] == kOpen || v[2] == kOpen || v[6] == kOpen || v[7] == kOpen;
            REQUIRE((book.decide(v) == kBack) == !front_open);
        }
        const std::array<int, 8> pocket{kBlocked, kBlocked, kBlocked, kBlocked, kVisited, kBlocked, kBlocked, kBlocked};
        CHECK(book.decide(pocket) == kBack);
    }

    SECTION("dead end: the walk backs out of a corridor aimed at the goal") {
        // The corridor on row 2 ends at the wall before the goal; the walk runs into it, backs up to
        // the start, leaves through the west opening (X5, the detour tier) and goes round.
        const GridMap map = map_of({".........",  //
                                    ".@@@@@@@.",  //
                                    "........@",  //
                                    ".@@@@@@@.",  //
                                    "........."});
        const Cell s{1, 2}, g{8, 4};
        for (std::uint64_t seed = 0; seed < 20; ++seed) {
            pride::Rng rng(seed);
            REQUIRE(walker.walk(map, s, g, rng, path));
            check_walk(map, path, s, g, false);
            CHECK(path[1] == Cell{0, 2});
            CHECK(walker.cells_entered() > path.size());  // the corridor was entered and abandoned
            CHECK(std::find(path.begin(), path.end(), Cell{7, 2}) == path.end());
        }
    }

    SECTION("unreachable goal, blocked start or goal: false") {
        const GridMap map = map_of({".....",  //
                                    "...@@",  //
                                    "...@.",  //
                                    "...@@"});
        pride::Rng rng(3);
        CHECK_FALSE(walker.walk(map, {0, 0}, {4, 2}, rng, path));
        CHECK(path.empty());
        CHECK(walker.cells_entered() == 14);  // every cell reachable from the start, once
        CHECK_FALSE(walker.walk(map, {3, 1}, {0, 0}, rng, path));
        CHECK_FALSE(walker.walk(map, {0, 0}, {3, 2}, rng, path));
        CHECK(walker.walk(map, {0, 0}, {0, 0}, rng, path));
        CHECK(path == Path{{0, 0}});
    }
}

TEST_CASE("rule walk: complete on 2000 random maps, agrees with A*", "[grid][roughset]") {
    pride::Rng rng(2024);
    RuleWalker walker;
    AStar astar;
    Path path;
    int reachable = 0, unreachable = 0;
    for (int m = 0; m < 2000; ++m) {
        const int w = 5 + below(rng, 36), h = 5 + below(rng, 36);
        const double density = 0.45 * rng.uniform();
        std::vector<std::uint8_t> blocked(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
        for (auto& b : blocked) b = rng.uniform() < density ? 1 : 0;
        const Cell s{below(rng, w), below(rng, h)}, g{below(rng, w), below(rng, h)};
        blocked[static_cast<std::size_t>(s.y * w + s.x)] = 0;  // random free start and goal
        blocked[static_cast<std::size_t>(g.y * w + g.x)] = 0;
        const GridMap map(w, h, std::move(blocked), "random");
        std::size_t free_cells = 0;
        for (std::size_t i = 0; i < map.size(); ++i) free_cells += map.free_index(i) ? 1 : 0;
        for (const bool cutting : {false, true}) {
            INFO("map " << m << " " << w << "x" << h << " corner cutting " << cutting);
            const bool found = astar.search(map, s, g, nullptr, nullptr, cutting) >= 0.0;
            pride::Rng walk_rng(static_cast<std::uint64_t>(m), cutting ? 1 : 0);
            REQUIRE(walker.walk(map, s, g, walk_rng, path, cutting) == found);
            CHECK(walker.cells_entered() <= free_cells);
            if (found) {
                check_walk(map, path, s, g, cutting);
                ++reachable;
            } else {
                CHECK(path.empty());
                ++unreachable;
            }
        }
    }
    // Both outcomes are exercised.
    CHECK(reachable > 1000);
    CHECK(unreachable > 100);
}

TEST_CASE("rule walk: the bundled maps, and walk lengths beside the random walk", "[grid][roughset]") {
    const std::filesystem::path dir = bundled_maps();
    REQUIRE(std::filesystem::is_directory(dir));
    int maps = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        if (entry.path().extension() != ".map") continue;
        ++maps;
        INFO(entry.path().filename().string());
        const GridMap map = read_map(entry.path().string());
        const auto scen = read_scenario(entry.path().string() + ".scen");
        REQUIRE(scen.size() == 1);
        const Cell s = scen[0].start, g = scen[0].goal;
        AStar astar;
        const double optimum = astar.search(map, s, g);
        REQUIRE(optimum > 0.0);
        RuleWalker rules, fixed;
        fixed.jitter = false;
        RandomWalker random;
        Path path;
        double rule_sum = 0.0, fixed_sum = 0.0, random_sum = 0.0;
        std::set<std::vector<std::size_t>> distinct, distinct_fixed;
        constexpr int kWalks = 200;
        for (int i = 0; i < kWalks; ++i) {
            pride::Rng rng(static_cast<std::uint64_t>(i));
            REQUIRE(rules.walk(map, s, g, rng, path));
            check_walk(map, path, s, g, false);
            const double length = metrics(path).length;
            CHECK(length >= optimum - 1e-9);
            rule_sum += length;
            std::vector<std::size_t> cells;
            for (const Cell c : path) cells.push_back(map.index(c));
            distinct.insert(cells);
            REQUIRE(fixed.walk(map, s, g, rng, path));
            check_walk(map, path, s, g, false);
            fixed_sum += metrics(path).length;
            cells.clear();
            for (const Cell c : path) cells.push_back(map.index(c));
            distinct_fixed.insert(cells);
            REQUIRE(random.walk(map, s, g, rng, path));
            random_sum += metrics(path).length;
        }
        // The project's decision asks for walks that differ: with the goal direction drawn between the two
        // directions that bracket the goal angle they do, on every bundled map.
        CHECK(distinct.size() > 5);
        WARN(entry.path().filename().string()
             << ": over " << kWalks << " walks: rules mean length " << rule_sum / kWalks << ", " << distinct.size()
             << " distinct; without jitter " << fixed_sum / kWalks << ", " << distinct_fixed.size()
             << " distinct; random walk " << random_sum / kWalks << "; A* optimum " << optimum);
    }
    CHECK(maps == 8);  // Wan and Gao (2022), Zhang et al. (2025) and Cai and Du (2021), with Cai and Du's (2021) three
                       // environments
}

TEST_CASE("rule walk: the same seed gives the same path, different seeds differ", "[grid][roughset]") {
    const GridMap map = read_map((bundled_maps() / "wan2022-10x10.map").string());
    RuleWalker a, b;
    Path pa, pb;
    std::vector<Path> distinct;
    for (std::uint64_t seed = 0; seed < 50; ++seed) {
        pride::Rng ra(seed), rb(seed);
        REQUIRE(a.walk(map, {0, 0}, {9, 9}, ra, pa));
        REQUIRE(b.walk(map, {0, 0}, {9, 9}, rb, pb));
        CHECK(pa == pb);
        // Reusing a walker (stamps, no clearing) gives the same path as a fresh one.
        pride::Rng rc(seed);
        REQUIRE(a.walk(map, {0, 0}, {9, 9}, rc, pb));
        CHECK(pa == pb);
        if (std::find(distinct.begin(), distinct.end(), pa) == distinct.end()) distinct.push_back(pa);
    }
    CHECK(distinct.size() > 1);
}

// Tests of Zhang et al.'s (2025) SITP initialisation (problems/grid/sitp.hpp) and of the IQGA operators the
// chain space offers as optional capabilities (problems/grid/iqga_moves.hpp, framework/chain.hpp):
//   - eq. 7's weights on hand-computed angles; the three bands of rows and the transition points;
//   - the regions of eqs. 14-15 on the paper's 10x10 layout (fig. 4) and a non-square rectangle;
//   - SITP walks, crossover, the three mutations and regeneration keep paths legal and simple on
//     hundreds of random maps and the bundled maps; SITP is reproducible from its seed;
//   - init = "sitp" through the engine (chains, line) and `pride path --init sitp`; error paths.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "engine/run.hpp"
#include "framework/chain.hpp"
#include "framework/error.hpp"
#include "framework/random.hpp"
#include "problems/grid/chain.hpp"
#include "problems/grid/grid_problem.hpp"
#include "problems/grid/iqga_moves.hpp"
#include "problems/grid/map.hpp"
#include "problems/grid/map_io.hpp"
#include "problems/grid/objectives.hpp"
#include "problems/grid/path.hpp"
#include "problems/grid/sitp.hpp"
#include "tests/cli_runner.hpp"
#include "tests/counting_space.hpp"
#include "tests/grid_support.hpp"

using namespace pride::grid;
using pride::Rng;
using pride::test::below;
using pride::test::map_of;

namespace {

namespace fs = std::filesystem;

static_assert(pride::NumberedMutations<ChainSpace<IqgaObjective>>);
static_assert(pride::RegionOf<ChainSpace<IqgaObjective>>);
static_assert(pride::TwoPointCrossover<ChainSpace<LinearObjective>>);
static_assert(pride::SegmentRegeneration<ChainSpace<LengthObjective>>);

fs::path bundled_maps() {
    return fs::path(PRIDE_SOURCE_DIR) / "examples" / "maps";
}

GridMap open_map(int w, int h) {
    return GridMap(w, h, std::vector<std::uint8_t>(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0));
}

struct Instance {
    std::shared_ptr<const GridMap> map;
    Cell start, goal;
    bool corner_cutting = false;
};

/// Random maps 8x8 .. 30x30 with 0-35 % obstacles and reachable start/goal pairs; every fifth map
/// allows corner cutting, every fourth pair shares a column, every seventh has the goal next to the
/// start.
std::vector<Instance> random_instances(std::uint64_t seed, int maps, int pairs) {
    Rng rng(seed);
    std::vector<Instance> out;
    for (int m = 0; m < maps; ++m) {
        const int w = 8 + below(rng, 23), h = 8 + below(rng, 23);
        std::vector<std::uint8_t> blocked(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
        const double density = 0.35 * rng.uniform();
        for (auto& b : blocked) b = rng.uniform() < density ? 1 : 0;
        auto map = std::make_shared<const GridMap>(w, h, std::move(blocked), "random");
        const bool cc = m % 5 == 4;
        for (int q = 0, tries = 0; q < pairs && tries < 3000; ++tries) {
            const Cell s{below(rng, w), below(rng, h)};
            Cell g{below(rng, w), below(rng, h)};
            if (q % 4 == 1) g.x = s.x;
            if (q % 7 == 6) {
                const int d = below(rng, 8);
                g = {s.x + kDx[d], s.y + kDy[d]};
            }
            if (!map->free(s) || !map->free(g) || s == g || !reachable_from(*map, s, cc)[map->index(g)]) continue;
            out.push_back({map, s, g, cc});
            ++q;
        }
    }
    return out;
}

std::string describe(const Instance& in) {
    return std::to_string(in.map->width()) + "x" + std::to_string(in.map->height()) + " " + to_string(in.start) +
           " -> " + to_string(in.goal) + (in.corner_cutting ? " corner cutting" : "");
}

bool is_simple(const Path& p) {
    std::set<std::pair<int, int>> seen;
    for (const Cell& c : p)
        if (!seen.insert({c.x, c.y}).second) return false;
    return true;
}

/// "" when p is a legal path from start to goal with no cell twice, else why not.
std::string chain_problem(const GridMap& map, Cell s, Cell g, bool cc, const Path& p) {
    const std::string why = path_violation(map, p, s, g, cc);
    if (!why.empty()) return why;
    return is_simple(p) ? "" : "a cell appears twice";
}
std::string chain_problem(const Instance& in, const Path& p) {
    return chain_problem(*in.map, in.start, in.goal, in.corner_cutting, p);
}

template <class Objective = IqgaObjective>
ChainSpace<Objective> sitp_space(const Instance& in) {
    ChainSpace<Objective> space(GridProblem<Objective>(in.map, in.start, in.goal, {}, in.corner_cutting));
    space.set_init(Walks::sitp);
    return space;
}

std::vector<Instance> bundled_instances() {
    std::vector<Instance> out;
    for (const char* name : {"wan2022-10x10", "wan2022-13x13", "zhang2025-20x20", "zhang2025-40x40", "cai2021-50x50"}) {
        auto map = std::make_shared<const GridMap>(read_map((bundled_maps() / (std::string(name) + ".map")).string()));
        const auto scen = read_scenario((bundled_maps() / (std::string(name) + ".map.scen")).string());
        out.push_back({map, scen.at(0).start, scen.at(0).goal, false});
    }
    return out;
}

bool share_interior_cell(const Path& a, const Path& b) {
    std::set<std::pair<int, int>> ia;
    for (std::size_t i = 1; i + 1 < a.size(); ++i) ia.insert({a[i].x, a[i].y});
    for (std::size_t j = 1; j + 1 < b.size(); ++j)
        if (ia.count({b[j].x, b[j].y})) return true;
    return false;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Eq. 7, bands, transition points

TEST_CASE("sitp: eq. 7 weights on hand-computed angles", "[sitp]") {
    // (7 - 10 ln(theta / 90))^2: 45 -> (7 + 10 ln 2)^2 = 13.931472^2 = 194.085907; 90 -> 7^2 = 49;
    // 135 -> (7 - 10 ln 1.5)^2 = 2.945349^2 = 8.675080; 180 -> (7 - 10 ln 2)^2 = 0.068528^2 = 0.004696.
    CHECK(sitp_weight(0.0) == 1e15);
    CHECK(sitp_weight(45.0) == Approx(194.085907).epsilon(1e-8));
    CHECK(sitp_weight(90.0) == 49.0);
    CHECK(sitp_weight(135.0) == Approx(8.675080).epsilon(1e-6));
    CHECK(sitp_weight(180.0) == Approx(0.004696).epsilon(1e-3));
    // Steps against the direction (5, 0) to the segment's end.
    CHECK(sitp_step_weight(1, 0, 5, 0) == 1e15);                              // theta = 0
    CHECK(sitp_step_weight(1, 1, 5, 0) == Approx(194.085907).epsilon(1e-8));  // 45
    CHECK(sitp_step_weight(0, -1, 5, 0) == Approx(49.0).epsilon(1e-12));      // 90
    CHECK(sitp_step_weight(-1, 1, 5, 0) == Approx(8.675080).epsilon(1e-6));   // 135
    CHECK(sitp_step_weight(-1, 0, 5, 0) == Approx(0.004696).epsilon(1e-3));   // 180
    CHECK(sitp_step_weight(1, 1, 3, 3) == 1e15);                              // diagonal, aligned
    CHECK(sitp_step_weight(1, 0, 3, 3) == Approx(194.085907).epsilon(1e-8));  // 45 off a diagonal
    // A small non-zero angle: step (1, 0), end (10, 1): theta = atan(0.1) = 5.7106 degrees.
    const double theta = std::atan(0.1) * 180.0 / 3.14159265358979323846;
    CHECK(sitp_step_weight(1, 0, 10, 1) == Approx(sitp_weight(theta)).epsilon(1e-12));
    CHECK(sitp_step_weight(1, 0, 10, 1) < 1e15);
}

TEST_CASE("sitp: three bands of rows between start and goal, transition points on x_r in their band", "[sitp]") {
    const GridMap map = open_map(20, 20);
    // Paper's 20x20 task: (0,19) -> (19,0), rows 0..19: bands 0..5, 6..12, 13..19.
    const Cell s{0, 19}, g{19, 0};
    CHECK(sitp_band(map, s, g, 0).first == 0);
    CHECK(sitp_band(map, s, g, 0).last == 5);
    CHECK(sitp_band(map, s, g, 1).first == 6);
    CHECK(sitp_band(map, s, g, 1).last == 12);
    CHECK(sitp_band(map, s, g, 2).first == 13);
    CHECK(sitp_band(map, s, g, 2).last == 19);
    // Rows 4..9 (6 rows): 4..5, 6..7, 8..9.
    CHECK(sitp_band(map, {2, 9}, {7, 4}, 1).first == 6);
    CHECK(sitp_band(map, {2, 9}, {7, 4}, 1).last == 7);
    // One row: widened to three around it (rows 6..8), one row per band; at the bottom edge
    // widened upwards (17..19).
    CHECK(sitp_band(map, {1, 7}, {12, 7}, 0).first == 6);
    CHECK(sitp_band(map, {1, 7}, {12, 7}, 0).last == 6);
    CHECK(sitp_band(map, {1, 7}, {12, 7}, 2).first == 8);
    CHECK(sitp_band(map, {1, 7}, {12, 7}, 2).last == 8);
    CHECK(sitp_band(map, {1, 19}, {12, 19}, 0).first == 17);
    CHECK(sitp_band(map, {1, 19}, {12, 19}, 2).last == 19);

    SitpWalker w;
    w.midpoint_column = true;  // eq. 3's formula; the text's random column is checked below
    Rng rng(3);
    const auto all = [&](Cell c) { return map.free(c); };
    for (int band = 0; band < 3; ++band) {
        const RowBand rows = sitp_band(map, s, g, band);
        std::set<int> drawn;
        for (int k = 0; k < 300; ++k) {
            Cell t;
            REQUIRE(w.transition_point(map, s, g, band, rng, all, t));
            CHECK(t.x == 9);  // floor((0 + 19) / 2)
            CHECK(t.y >= rows.first);
            CHECK(t.y <= rows.last);
            drawn.insert(t.y);
        }
        CHECK(static_cast<int>(drawn.size()) == rows.last - rows.first + 1);  // every row of the band
    }
    // Blocked cells of the band are never drawn; a band with no free cell falls back to the
    // nearest free cell of the column.
    std::vector<std::string> rows(20, std::string(20, '.'));
    for (int y = 0; y <= 12; ++y) rows[static_cast<std::size_t>(y)][9] = '@';
    rows[3][9] = '.';  // band 0 keeps row 3 only
    for (int y = 6; y <= 12; ++y) rows[static_cast<std::size_t>(y)][9] = '@';
    const GridMap holed = map_of(rows);
    const auto free_cell = [&](Cell c) { return holed.free(c); };
    for (int k = 0; k < 50; ++k) {
        Cell t;
        REQUIRE(w.transition_point(holed, s, g, 0, rng, free_cell, t));
        CHECK(t == Cell{9, 3});
        REQUIRE(w.transition_point(holed, s, g, 1, rng, free_cell, t));
        CHECK(t == Cell{9, 13});  // rows 6..12 blocked: row 13 is 1 away, row 5 is blocked, row 3 is 3 away
    }
    // Start and goal in one column: the transition point lies on it.
    for (int k = 0; k < 50; ++k) {
        Cell t;
        REQUIRE(w.transition_point(map, {4, 2}, {4, 17}, k % 3, rng, all, t));
        CHECK(t.x == 4);
    }
    // No reachable cell on the column at all.
    Cell t;
    CHECK_FALSE(w.transition_point(
        map, s, g, 0, rng, [](Cell) { return false; }, t));

    // The default, as the text under eq. 3 reads: x_r a random integer between the start's and the
    // goal's columns, both included, each about equally often; the row still in the band.
    SitpWalker text;
    std::map<int, int> columns;
    for (int k = 0; k < 4000; ++k) {
        Cell r;
        REQUIRE(text.transition_point(map, {3, 19}, {12, 0}, 1, rng, all, r));
        CHECK(r.x >= 3);
        CHECK(r.x <= 12);
        CHECK(r.y >= sitp_band(map, {3, 19}, {12, 0}, 1).first);
        CHECK(r.y <= sitp_band(map, {3, 19}, {12, 0}, 1).last);
        ++columns[r.x];
    }
    REQUIRE(columns.size() == 10);
    for (const auto& [x, n] : columns) CHECK(std::abs(n - 400) < 100);  // 400 expected, sd 19
    // Goal left of the start: the same columns.
    for (int k = 0; k < 200; ++k) {
        Cell r;
        REQUIRE(text.transition_point(map, {12, 0}, {3, 19}, 0, rng, all, r));
        CHECK(r.x >= 3);
        CHECK(r.x <= 12);
    }
}

// ---------------------------------------------------------------------------------------------
// Regions (eqs. 14-15)

TEST_CASE("sitp: the regions of eqs. 14-15 on the paper's 10x10 example", "[sitp]") {
    // Fig. 4: start (1,1) and goal (10,10) in the paper's numbering are (0,9) and (9,0) here. L = 9,
    // l = 4; the lines are X - Y = +-4 (paper coordinates), i.e. x + y = 13 and x + y = 5 here.
    // Region 0 (D1, right of start -> goal: the bottom right) is x + y > 13, region 1 (D2, top
    // left) is x + y < 5, the lines themselves and between them region 2 (D3).
    const Cell s{0, 9}, g{9, 0};
    const std::vector<std::string> expected = {
        "1111122222",  // y = 0 (the paper's row 10)
        "1111222222", "1112222222", "1122222222", "1222222222", "2222222220", "2222222200", "2222222000", "2222220000",
        "2222200000",  // y = 9 (the paper's row 1)
    };
    for (int y = 0; y < 10; ++y)
        for (int x = 0; x < 10; ++x) {
            INFO("cell (" << x << "," << y << ")");
            CHECK(iqga_cell_region(s, g, {x, y}) ==
                  expected[static_cast<std::size_t>(y)][static_cast<std::size_t>(x)] - '0');
        }
    // Reversing the direction swaps the two sides.
    CHECK(iqga_cell_region(g, s, {9, 9}) == 1);
    CHECK(iqga_cell_region(g, s, {0, 0}) == 0);
    // Outside the rectangle the lines extend: far right on the start row is region 0.
    CHECK(iqga_cell_region(s, g, {15, 9}) == 0);

    // Cell sets (a path's region only counts its cells). Along the bottom and up the right edge:
    // 9 of its 19 cells in region 0 ((5..9, 9) and (9, 5..8)), 10 in the middle: region 2; up the
    // left edge and along the top likewise. `corner`: (0..4, 9) in the middle (5 cells) against
    // (5..9, 9), (9, 8..5), (8,8), (7,8), (8,7) in region 0 (12 cells): region 0; its mirror image
    // through the centre: region 1. The diagonal: region 2.
    Path edge_right, edge_left, corner, top_corner, diagonal;
    for (int x = 0; x <= 9; ++x) edge_right.push_back({x, 9});
    for (int y = 8; y >= 0; --y) edge_right.push_back({9, y});
    for (int y = 9; y >= 0; --y) edge_left.push_back({0, y});
    for (int x = 1; x <= 9; ++x) edge_left.push_back({x, 0});
    for (int x = 0; x <= 9; ++x) corner.push_back({x, 9});
    for (int y = 8; y >= 5; --y) corner.push_back({9, y});
    for (const Cell c : {Cell{8, 8}, Cell{7, 8}, Cell{8, 7}}) corner.push_back(c);
    for (const Cell& c : corner) top_corner.push_back({9 - c.x, 9 - c.y});  // the mirror image: region 1
    for (int k = 0; k <= 9; ++k) diagonal.push_back({k, 9 - k});
    CHECK(iqga_path_region(s, g, edge_right) == 2);
    CHECK(iqga_path_region(s, g, edge_left) == 2);
    CHECK(iqga_path_region(s, g, corner) == 0);
    CHECK(iqga_path_region(s, g, top_corner) == 1);
    CHECK(iqga_path_region(s, g, diagonal) == 2);
    // Ties: 2 wins, then 0.  Cells (9,9),(8,9) are region 0; (5,5),(4,4) region 2: tie -> 2.
    CHECK(iqga_path_region(s, g, Path{{9, 9}, {8, 9}, {5, 5}, {4, 4}}) == 2);
    CHECK(iqga_path_region(s, g, Path{{9, 9}, {0, 0}}) == 0);

    // Non-square: (0,0) -> (9,3): L = 3, l = 1, the shift along y (the shorter side); cross =
    // 9 y - 3 x, region 0 when cross > 9, region 1 when cross < -9.
    CHECK(iqga_cell_region({0, 0}, {9, 3}, {0, 2}) == 0);  // 18
    CHECK(iqga_cell_region({0, 0}, {9, 3}, {0, 1}) == 2);  // 9: on the line
    CHECK(iqga_cell_region({0, 0}, {9, 3}, {6, 0}) == 1);  // -18
    CHECK(iqga_cell_region({0, 0}, {9, 3}, {3, 0}) == 2);  // -9
    // L = 1, l = 0: every cell off the diagonal is on a side.
    CHECK(iqga_cell_region({0, 0}, {9, 1}, {4, 0}) == 1);
    CHECK(iqga_cell_region({0, 0}, {9, 1}, {0, 1}) == 0);
    // The chain space reports the same.
    auto map = std::make_shared<const GridMap>(open_map(10, 10));
    const ChainSpace<IqgaObjective> space(GridProblem<IqgaObjective>(map, s, g));
    CHECK(space.region_count() == 3);
    CHECK(space.region(corner) == 0);
    CHECK(space.region(top_corner) == 1);
    CHECK(space.region(diagonal) == 2);
}

// ---------------------------------------------------------------------------------------------
// SITP walks

TEST_CASE("sitp: walks are legal simple paths, reproducible from the seed, on random and bundled maps", "[sitp]") {
    auto instances = random_instances(11, 150, 3);
    REQUIRE(instances.size() >= 400);
    for (const auto& b : bundled_instances()) instances.push_back(b);
    Rng rng(12);
    for (const auto& in : instances) {
        INFO(describe(in));
        auto space = sitp_space(in);
        auto again = sitp_space(in);
        const std::uint64_t seed = rng.below(1u << 30);
        Rng r1(seed), r2(seed);
        for (int k = 0; k < 4; ++k) {
            Path a, b;
            space.random_chain(r1, a, pride::test::uncounted_score(space));
            again.random_chain(r2, b, pride::test::uncounted_score(again));
            REQUIRE(chain_problem(in, a) == "");
            CHECK(a == b);
        }
        // The walker on its own (its own reachability, length score) agrees with the legality.
        SitpWalker w;
        Path p;
        REQUIRE(w.walk(*in.map, in.start, in.goal, rng, p, in.corner_cutting));
        CHECK(chain_problem(in, p) == "");
        REQUIRE(w.angle_walk(*in.map, in.start, in.goal, rng, p, in.corner_cutting));
        CHECK(chain_problem(in, p) == "");
    }
}

TEST_CASE("sitp: the transition point's band cycles and the path passes through it", "[sitp]") {
    // An open 30x30 map: the straight angle walks on the way make the path pass its transition
    // point, so the path's cells on column x_r include a cell of the band.
    auto map = std::make_shared<const GridMap>(open_map(30, 30));
    const Cell s{0, 29}, g{29, 0};
    ChainSpace<LengthObjective> space(GridProblem<LengthObjective>(map, s, g));
    space.set_init(Walks::sitp);
    space.set_sitp(true, SitpScore::objective);  // eq. 3's midpoint column: x_r = 14
    Rng rng(4);
    for (int k = 0; k < 60; ++k) {
        Path p;
        space.random_chain(rng, p, pride::test::uncounted_score(space));
        REQUIRE(path_violation(*map, p, s, g) == "");
        const RowBand rows = sitp_band(*map, s, g, k % 3);
        bool in_band = false;
        for (const Cell c : p) in_band = in_band || (c.x == 14 && c.y >= rows.first && c.y <= rows.last);
        INFO("chain " << k << " band " << k % 3);
        CHECK(in_band);
    }
}

TEST_CASE("sitp: the cases the paper leaves out", "[sitp]") {
    SitpWalker w;
    Rng rng(9);
    Path p;
    // Unreachable goal: false and an empty path, as the other walkers do.
    const GridMap wall = map_of({"..@..", "..@..", "..@..", "..@.."});
    CHECK_FALSE(w.walk(wall, {0, 0}, {4, 3}, rng, p));
    CHECK(p.empty());
    CHECK_FALSE(w.angle_walk(wall, {0, 0}, {4, 3}, rng, p));
    CHECK(p.empty());
    // Blocked start or goal.
    CHECK_FALSE(w.walk(wall, {2, 0}, {4, 3}, rng, p));
    CHECK_FALSE(w.walk(wall, {0, 0}, {2, 3}, rng, p));
    // Start = goal: the one-cell path.
    REQUIRE(w.walk(wall, {1, 1}, {1, 1}, rng, p));
    CHECK(p == Path{{1, 1}});
    // Same column, with the column blocked between them: the transition point is the start or
    // the goal's side of the column, and the path goes round.
    const GridMap column = map_of({".....", "..@..", "..@..", "..@..", "....."});
    for (int k = 0; k < 30; ++k) {
        REQUIRE(w.walk(column, {2, 0}, {2, 4}, rng, p, false, k % 3));
        CHECK(chain_problem(column, {2, 0}, {2, 4}, false, p) == "");
    }
    // The transition column's only reachable cells lie outside every band of the segment.
    const GridMap gate = map_of({"...@...", "...@...", "...@...", "...@...", "...@...", ".......", "......."});
    for (int k = 0; k < 30; ++k) {
        REQUIRE(w.walk(gate, {0, 0}, {6, 2}, rng, p, false, k % 3));
        CHECK(chain_problem(gate, {0, 0}, {6, 2}, false, p) == "");
    }
    // A chain space refuses other walks than random and SITP.
    auto map = std::make_shared<const GridMap>(open_map(5, 5));
    ChainSpace<CellsObjective> space(GridProblem<CellsObjective>(map, {0, 0}, {4, 4}));
    CHECK_THROWS_AS(space.set_init(Walks::rules), pride::InputError);
    CHECK(space.init() == Walks::random);
}

// ---------------------------------------------------------------------------------------------
// Crossover, mutations, regeneration

TEST_CASE("sitp: the two-point crossover of fig. 7 on a hand-made pair", "[sitp]") {
    auto map = std::make_shared<const GridMap>(open_map(8, 4));
    ChainSpace<LengthObjective> space(GridProblem<LengthObjective>(map, {0, 1}, {7, 1}));
    // a runs along row 1; b leaves it and meets it at (2,1) and (5,1).
    const Path a = {{0, 1}, {1, 1}, {2, 1}, {3, 1}, {4, 1}, {5, 1}, {6, 1}, {7, 1}};
    const Path b = {{0, 1}, {1, 2}, {2, 1}, {3, 0}, {4, 0}, {5, 1}, {6, 2}, {7, 1}};
    Rng rng(1);
    Path x = a, y = b;
    REQUIRE(space.crossover_two_point(x, y, rng));  // the only two common interior cells
    CHECK(x == Path{{0, 1}, {1, 1}, {2, 1}, {3, 0}, {4, 0}, {5, 1}, {6, 1}, {7, 1}});
    CHECK(y == Path{{0, 1}, {1, 2}, {2, 1}, {3, 1}, {4, 1}, {5, 1}, {6, 2}, {7, 1}});
    // One common interior cell: the goal is the second cut point (the tails are swapped).
    const Path c = {{0, 1}, {1, 2}, {2, 2}, {3, 1}, {4, 2}, {5, 2}, {6, 2}, {7, 1}};
    x = a;
    y = c;
    REQUIRE(space.crossover_two_point(x, y, rng));
    CHECK(x == Path{{0, 1}, {1, 1}, {2, 1}, {3, 1}, {4, 2}, {5, 2}, {6, 2}, {7, 1}});
    CHECK(y == Path{{0, 1}, {1, 2}, {2, 2}, {3, 1}, {4, 1}, {5, 1}, {6, 1}, {7, 1}});
    // None: false, the parents unchanged.
    const Path d = {{0, 1}, {1, 0}, {2, 0}, {3, 0}, {4, 0}, {5, 0}, {6, 0}, {7, 1}};
    x = a;
    y = d;
    CHECK_FALSE(space.crossover_two_point(x, y, rng));
    CHECK(x == a);
    CHECK(y == d);
}

TEST_CASE("sitp: crossover keeps paths legal and simple on random and bundled maps", "[sitp]") {
    auto instances = random_instances(21, 120, 3);
    for (const auto& b : bundled_instances()) instances.push_back(b);
    Rng rng(22);
    int crossed = 0;
    for (const auto& in : instances) {
        auto space = sitp_space<LinearObjective>(in);
        for (int k = 0; k < 6; ++k) {
            Path a, b;
            space.random_chain(rng, a, pride::test::uncounted_score(space));
            space.random_chain(rng, b, pride::test::uncounted_score(space));
            const Path pa = a, pb = b;
            const bool share = share_interior_cell(a, b);
            INFO(describe(in));
            REQUIRE(space.crossover_two_point(a, b, rng) == share);
            if (!share) {
                CHECK(a == pa);
                CHECK(b == pb);
                continue;
            }
            ++crossed;
            REQUIRE(chain_problem(in, a) == "");
            REQUIRE(chain_problem(in, b) == "");
        }
    }
    CHECK(crossed > 1000);
}

TEST_CASE("sitp: every mutation operator and regeneration keeps paths legal and simple", "[sitp]") {
    auto instances = random_instances(31, 120, 3);
    for (const auto& b : bundled_instances()) instances.push_back(b);
    Rng rng(32);
    int changed[3] = {0, 0, 0};
    for (const auto& in : instances) {
        auto space = sitp_space(in);
        REQUIRE(space.mutation_count() == 3);
        Path c;
        space.random_chain(rng, c, pride::test::uncounted_score(space));
        for (int step = 0; step < 24; ++step) {
            const std::size_t k = static_cast<std::size_t>(step % 3);
            const Path before = c;
            space.mutate(k, c, rng, rng.uniform(), pride::test::uncounted_score(space));
            INFO(describe(in) << " operator " << k << " step " << step);
            REQUIRE(chain_problem(in, c) == "");
            changed[k] += !(c == before);
            if (c.size() >= 3 && step % 4 == 0) {
                const std::size_t i = rng.below(c.size() - 1), j = i + 1 + rng.below(c.size() - 1 - i);
                REQUIRE(space.regenerate(c, i, j, rng, pride::test::uncounted_score(space)));
                REQUIRE(chain_problem(in, c) == "");
            }
        }
        // Out-of-range and unordered positions leave the chain as it is; k >= 3 changes nothing.
        const Path before = c;
        CHECK_FALSE(space.regenerate(c, 2, 1, rng));
        CHECK_FALSE(space.regenerate(c, 0, c.size(), rng));
        space.mutate(3, c, rng);
        CHECK(c == before);
    }
    for (int k = 0; k < 3; ++k) {
        INFO("operator " << k);
        CHECK(changed[k] > 500);
    }
}

TEST_CASE("sitp: a straight path has no turning point and no operator changes it", "[sitp]") {
    auto map = std::make_shared<const GridMap>(open_map(12, 5));
    ChainSpace<IqgaObjective> space(GridProblem<IqgaObjective>(map, {0, 2}, {11, 2}));
    Path line;
    for (int x = 0; x <= 11; ++x) line.push_back({x, 2});
    Rng rng(5);
    for (std::size_t k = 0; k < 3; ++k)
        for (int r = 0; r < 20; ++r) {
            Path c = line;
            space.mutate(k, c, rng, 0.0, pride::test::uncounted_score(space));
            CHECK(c == line);
        }
}

TEST_CASE("sitp: the mutation rules on paths whose regeneration is forced", "[sitp]") {
    // A corridor one cell wide turns once, at (3,0), orthogonally by 90 degrees, with the corner
    // (2,1) blocked. Its only turning point is d_i = d_j, so the part regenerated is (2,0) ..
    // (3,1), which without corner cutting can only come back the same; the deletion, mid-point and
    // turning-point rules would then drop (3,0), but the diagonal (2,0) -> (3,1) is illegal, so
    // the path stays. With corner cutting allowed, (3,0) goes (the SITP walk takes the diagonal,
    // weight 1e15 against 194, and the rules would drop it too).
    const std::vector<std::string> rows = {"....", "@@@.", "@@@.", "@@@."};
    auto map = std::make_shared<const GridMap>(map_of(rows));
    const Path l = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {3, 2}, {3, 3}};
    Rng rng(6);
    {
        ChainSpace<LengthObjective> space(GridProblem<LengthObjective>(map, {0, 0}, {3, 3}));
        for (std::size_t k = 0; k < 3; ++k)
            for (int r = 0; r < 20; ++r) {
                Path c = l;
                space.mutate(k, c, rng, 0.0, pride::test::uncounted_score(space));
                CHECK(c == l);
            }
    }
    {
        ChainSpace<LengthObjective> space(GridProblem<LengthObjective>(map, {0, 0}, {3, 3}, {}, true));
        int cut = 0;
        for (std::size_t k = 0; k < 3; ++k)
            for (int r = 0; r < 20; ++r) {
                Path c = l;
                space.mutate(k, c, rng, 0.0, pride::test::uncounted_score(space));
                REQUIRE(chain_problem(*map, {0, 0}, {3, 3}, true, c) == "");
                cut += c.size() == l.size() - 1;  // (3,0) went: (2,0) -> (3,1) diagonally
            }
        CHECK(cut > 20);
    }
}

// ---------------------------------------------------------------------------------------------
// init = "sitp" through the engine and the command line

TEST_CASE("sitp: init sitp through the engine for chains and line genotypes, error paths", "[sitp]") {
    namespace engine = pride::engine;
    engine::GridSpec g;
    g.map = engine::load_map((bundled_maps() / "zhang2025-20x20.map").string());
    g.start = {0, 19};
    g.goal = {19, 0};
    g.objective = "iqga";
    g.encoding = "chain";
    engine::Budget budget;
    budget.iterations = 5;
    engine::AlgorithmSpec ga{"ga", {}};
    const auto plain = engine::run(ga, engine::Problem(g), budget, 3);
    g.init = "sitp";
    const auto sitp = engine::run(ga, engine::Problem(g), budget, 3);
    const auto again = engine::run(ga, engine::Problem(g), budget, 3);
    REQUIRE(sitp.grid);
    CHECK(sitp.grid->feasible);
    CHECK(path_violation(*g.map, sitp.grid->path, g.start, g.goal) == "");
    CHECK(sitp.history == again.history);
    CHECK(sitp.history != plain.history);
    g.init = "walk";  // chains' default, said aloud
    CHECK(engine::run(ga, engine::Problem(g), budget, 3).history == plain.history);
    // line genotypes seeded from SITP walks
    g.init = "sitp";
    g.encoding = "line";
    g.objective = "length";
    const auto pso = engine::run({"pso", {}}, engine::Problem(g), budget, 2);
    REQUIRE(pso.grid);
    CHECK(pso.grid->feasible);
    g.init = "uniform";
    CHECK(engine::run({"pso", {}}, engine::Problem(g), budget, 2).history != pso.history);
    // Errors
    g.init = "nosuch";
    CHECK_THROWS_WITH(engine::Problem(g), Catch::Contains("sitp"));
    g.init = "rules";
    g.encoding = "chain";
    CHECK_THROWS_WITH(engine::Problem(g), Catch::Contains("chain"));
}

TEST_CASE("sitp: pride path --algo ga --encoding chain --init sitp", "[sitp][cli]") {
    const std::string map = (bundled_maps() / "zhang2025-20x20.map").string();
    const std::string args = "path --map '" + map +
                             "' --start 0,19 --goal 19,0 --algo ga --encoding chain --objective iqga "
                             "--iters 5 --json --init sitp";
    const auto r = pride::test::run_pride(args);
    INFO(r.err);
    REQUIRE(r.status == 0);
    const auto j = pride::test::parse_json(r.out);
    CHECK(j.at("feasible").kind == pride::test::JsonValue::Kind::boolean);
    const auto k = pride::test::parse_json(pride::test::run_pride(args).out);  // same seed, same run
    CHECK(pride::test::json_numbers(k.at("history")) == pride::test::json_numbers(j.at("history")));
    CHECK(k.at("path").items.size() == j.at("path").items.size());
    const auto pso = pride::test::run_pride("path --map '" + map +
                                            "' --start 0,19 --goal 19,0 --algo pso --iters 3 --json --init sitp");
    INFO(pso.err);
    CHECK(pso.status == 0);
    pride::test::expect_input_error("path --map '" + map + "' --start 0,19 --goal 19,0 --algo ga --init sitpx",
                                    {"--init", "sitpx"});
}

TEST_CASE("sitp: campaign files take init = \"sitp\"", "[sitp][cli]") {
    const pride::test::TempDir dir;
    const std::string map = (bundled_maps() / "zhang2025-20x20.map").string();
    auto campaign = [&](const std::string& init, const std::string& encoding) {
        return "name = \"s\"\nseeds = 2\n[budget]\niterations = 3\n[[problem]]\nid = \"p\"\ntype = \"grid\"\nmap = \"" +
               map + "\"\nstart = [0, 19]\ngoal = [19, 0]\nobjective = \"iqga\"\nencoding = \"" + encoding +
               "\"\ninit = \"" + init + "\"\n[[algorithm]]\nid = \"ga\"\ntype = \"ga\"\n";
    };
    const std::string good = dir.write("good.toml", campaign("sitp", "chain"));
    const auto r = pride::test::run_pride("bench '" + good + "' --out '" + dir.file("out.sqlite") + "'");
    INFO(r.out << r.err);
    CHECK(r.status == 0);
    const std::string line = dir.write("line.toml", campaign("sitp", "line"));
    CHECK(pride::test::run_pride("bench '" + line + "' --out '" + dir.file("line.sqlite") + "'").status == 0);
    const std::string bad = dir.write("bad.toml", campaign("rules", "chain"));
    pride::test::expect_input_error("bench '" + bad + "' --out '" + dir.file("bad.sqlite") + "'", {"rules", "chain"});
}

TEST_CASE("sitp: the weight table holds sitp_step_weight's own bits, direction() inverts kDx / kDy", "[sitp]") {
    // Every offset of a 13 x 9 map, every step: the table's value is the function's, bit for bit
    // (so the walks draw as without the table), and a second lookup returns the same.
    const GridMap map(13, 9, std::vector<std::uint8_t>(13 * 9, 0));
    SitpWalker w;
    for (int ty = -8; ty <= 8; ++ty)
        for (int tx = -12; tx <= 12; ++tx) {
            if (tx == 0 && ty == 0) continue;
            const double* e = w.step_weights(map, tx, ty);
            REQUIRE(e != nullptr);
            for (int d = 0; d < 8; ++d) {
                const double f = sitp_step_weight(kDx[d], kDy[d], tx, ty);
                REQUIRE(std::memcmp(&e[d], &f, sizeof f) == 0);
            }
            REQUIRE(w.step_weights(map, tx, ty) == e);
        }
    // A map too large for a table (8 x 799 x 799 > 2^20 entries): no table, the walk computes.
    const GridMap big(400, 400, std::vector<std::uint8_t>(400 * 400, 0));
    CHECK(w.step_weights(big, 3, 4) == nullptr);
    Path p;
    Rng rng(4);
    REQUIRE(w.angle_walk(big, {0, 0}, {399, 399}, rng, p));
    CHECK(p.size() == 400);  // the diagonal: weight 1e15 at every step
    // direction(): the index d with (kDx[d], kDy[d]) = b - a, -1 for anything else.
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
            int expected = -1;
            for (int d = 0; d < 8; ++d)
                if (kDx[d] == dx && kDy[d] == dy) expected = d;
            CHECK(direction({5, 5}, {5 + dx, 5 + dy}) == expected);
        }
}

TEST_CASE("sitp: the ablation flags and IAGA's pm_min out of range are input errors naming them", "[sitp][cli]") {
    const std::string map = std::string(PRIDE_SOURCE_DIR) + "/examples/maps/zhang2025-20x20.map";
    const std::string base = "path --map " + map + " --start 0,19 --goal 19,0 --encoding chain --objective iqga ";
    for (const char* bad :
         {"--algo iqga --param regions=2", "--algo iqga --param elite_crossover=-1",
          "--algo iqga --param qlearning=0.5", "--algo iaga --param pm_min=1.5", "--algo iaga --param pm_min=-0.1"}) {
        INFO(bad);
        const auto r = pride::test::run_pride(base + bad);
        CHECK(r.status == 2);
        const std::string name = std::string(bad).substr(std::string(bad).find("--param ") + 8);
        CHECK(r.err.find(name.substr(0, name.find('='))) != std::string::npos);
        CHECK(r.out.empty());
    }
    const auto ok = pride::test::run_pride(base + "--algo iqga --iters 5 --param regions=0 --param qlearning=0 --json");
    CHECK(ok.status == 0);
}

// Tests of WOA and HS-WOA on chains (Cai and Du (2021) on grids): the whale chain moves of
// problems/grid/whale_chain.hpp on hand-made maps (the line-of-sight shortcut, moving a whale
// towards another inside a window around the target's section, a whale towards itself), and the
// Woa skeleton on ChainSpace (algorithms/parts/whale/pods.hpp): every whale of every iteration a
// legal simple path on every bundled map and on 200 random maps, reproducible bit for bit, budgets
// exact, and the registry entries on grids with the chain encoding (N = 20, 50 iterations).
#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/woa.hpp"
#include "engine/registry.hpp"
#include "engine/run.hpp"
#include "engine/specs.hpp"
#include "framework/chain.hpp"
#include "framework/error.hpp"
#include "framework/termination.hpp"
#include "problems/grid/chain.hpp"
#include "problems/grid/grid_problem.hpp"
#include "problems/grid/map.hpp"
#include "problems/grid/map_io.hpp"
#include "problems/grid/objectives.hpp"
#include "problems/grid/path.hpp"
#include "problems/grid/planners/astar.hpp"
#include "problems/grid/whale_chain.hpp"
#include "tests/counting_space.hpp"
#include "tests/grid_support.hpp"

namespace {

using namespace pride;
namespace fs = std::filesystem;
using Space = grid::ChainSpace<grid::LinearObjective>;
static_assert(TowardMoves<Space> && Shortening<Space>);

using HsWoa = Woa<PerWhaleDraws, BalanceMode, HarmonySecondStep>;
using PlainWoa = Woa<>;

bool same_bits(double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

fs::path bundled_maps() {
    return fs::path(PRIDE_SOURCE_DIR) / "examples" / "maps";
}

using Instance = test::GridInstance;

std::vector<Instance> bundled_instances() {
    return test::bundled_instances(bundled_maps());
}
using test::random_instances;

grid::GridProblem<grid::LinearObjective> problem_of(const Instance& in) {
    return {in.map, in.start, in.goal, grid::LinearObjective::of(grid::HswoaObjective{}), in.corner_cutting};
}
Space space_of(const Instance& in) {
    return Space(problem_of(in));
}

Instance bundled(const std::string& name) {
    auto map = std::make_shared<const grid::GridMap>(grid::read_map((bundled_maps() / name).string()));
    const auto scen = grid::read_scenario((bundled_maps() / (name + ".scen")).string());
    return {map, scen.at(0).start, scen.at(0).goal};
}

bool is_simple(const grid::Path& p) {
    std::set<std::pair<int, int>> seen;
    for (const grid::Cell& c : p)
        if (!seen.insert({c.x, c.y}).second) return false;
    return true;
}

std::string legal(const Instance& in, const grid::Path& p) {
    std::string why = grid::path_violation(*in.map, p, in.start, in.goal, in.corner_cutting);
    if (why.empty() && !is_simple(p)) why = "a cell twice";
    return why;
}

/// Counts whales of every iteration that are not legal simple paths or whose fitness is not their value.
struct LegalityChecker {
    Instance in;
    std::shared_ptr<std::int64_t> bad = std::make_shared<std::int64_t>(0);
    std::shared_ptr<std::int64_t> seen = std::make_shared<std::int64_t>(0);
    std::shared_ptr<std::string> first = std::make_shared<std::string>();
    template <class View>
    void operator()(const View& view) const {
        const auto problem = problem_of(in);
        const std::vector<grid::Path>& pod = view.population;
        for (std::size_t i = 0; i < pod.size(); ++i) {
            ++*seen;
            std::string why = legal(in, pod[i]);
            if (why.empty() && std::isfinite(view.fitness[i]) && view.fitness[i] != problem.evaluate(pod[i]))
                why = "fitness is not the path's value";
            if (!why.empty()) {
                if (first->empty()) *first = why;
                ++*bad;
            }
        }
    }
};

/// The chain space, counting every call of its objective (tests/counting_space.hpp).
using CountedSpace = test::CountingSpace<Space>;

grid::Path path_of(std::initializer_list<std::pair<int, int>> cells) {
    grid::Path p;
    for (const auto& [x, y] : cells) p.push_back({x, y});
    return p;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// The chain moves, one step at a time

TEST_CASE("whale chains: the line-of-sight shortcut joins each cell to the farthest one it sees", "[woa][chain]") {
    grid::WhaleChainMoves moves;
    grid::Path out;
    SECTION("open map: an L becomes the straight line") {
        const auto map = test::map_of({".....", ".....", ".....", ".....", "....."});
        const auto c = path_of({{0, 0}, {0, 1}, {0, 2}, {0, 3}, {0, 4}, {1, 4}, {2, 4}, {3, 4}, {4, 4}});
        moves.shortcut(map, c, out, false);
        CHECK(out == path_of({{0, 0}, {1, 1}, {2, 2}, {3, 3}, {4, 4}}));
    }
    SECTION("a block in the way: the path bends at the first cell that sees the goal") {
        // Row 1 blocked at x = 1..3: from (0, 0) the goal (4, 2) is out of sight; (0, 1) is the
        // farthest cell of c that (0, 0) sees along c... the scan keeps c's cells it must.
        const auto map = test::map_of({".....", ".@@@.", "....."});
        const auto c = path_of({{0, 0}, {0, 1}, {0, 2}, {1, 2}, {2, 2}, {3, 2}, {4, 2}});
        moves.shortcut(map, c, out, false);
        // (0, 0) sees (1, 2)? The line (0,0)-(1,2) steps through (0,1) or (1,1): Bresenham gives
        // (0,1) then (1,2), a diagonal step past the blocked (1, 1): illegal without corner
        // cutting. It sees (0, 2), and (0, 2) sees the goal.
        CHECK(out == path_of({{0, 0}, {0, 1}, {0, 2}, {1, 2}, {2, 2}, {3, 2}, {4, 2}}));
        CHECK(grid::path_violation(map, out, {0, 0}, {4, 2}).empty());
    }
    SECTION("a detour around nothing is cut; never longer, always legal") {
        const auto map = test::map_of({"......", "..@...", "......", "......"});
        const auto c = path_of({{0, 3}, {0, 2}, {0, 1}, {1, 0}, {2, 0}, {3, 0}, {4, 1}, {5, 2}, {5, 3}});
        moves.shortcut(map, c, out, false);
        CHECK(out.front() == c.front());
        CHECK(out.back() == c.back());
        CHECK(grid::path_violation(map, out, c.front(), c.back()).empty());
        CHECK(grid::metrics(out).length == Approx(5.0));  // the bottom row, straight
    }
}

TEST_CASE("whale chains: a whale moved towards another passes through its section, inside the window", "[woa][chain]") {
    // Start bottom-left, goal bottom-right; the target runs along the bottom row, c over the top.
    const auto map = test::map_of({"..........", "..........", "..........", "..........", "..........", ".........."});
    const grid::Cell s{0, 5}, g{9, 5};
    grid::Path target;
    for (int x = 0; x <= 9; ++x) target.push_back({x, 5});
    grid::Path top = path_of({{0, 5}, {0, 4}, {0, 3}, {0, 2}, {0, 1}, {1, 0}});
    for (int x = 2; x <= 8; ++x) top.push_back({x, 0});
    for (int y = 1; y <= 5; ++y) top.push_back({9, y});
    REQUIRE(grid::path_violation(map, top, s, g).empty());
    grid::WhaleChainMoves moves;
    int through = 0;
    for (std::uint64_t seed = 1; seed <= 50; ++seed) {
        INFO("seed " << seed);
        Rng rng(seed);
        // Share 1: the whole chain, through the target's middle cell, within 2 rows of the target.
        grid::Path c = top;
        moves.toward(map, c, target, 1.0, rng, false);
        CHECK(grid::path_violation(map, c, s, g).empty());
        CHECK(is_simple(c));
        // Through the target's middle cell, unless the second walk crossed the first and the loop
        // cut took it out.
        through += std::find(c.begin(), c.end(), target[4]) != c.end();
        for (const auto& cell : c) CHECK(cell.y >= 3);  // the window: the bottom row grown by 2
        // Share 0: two steps of c regenerated, the rest kept.
        c = top;
        moves.toward(map, c, target, 0.0, rng, false);
        CHECK(grid::path_violation(map, c, s, g).empty());
        CHECK(is_simple(c));
        // Towards itself: a perturbation, still legal.
        c = top;
        moves.toward(map, c, c, 0.3, rng, false);
        CHECK(grid::path_violation(map, c, s, g).empty());
        CHECK(is_simple(c));
    }
    CHECK(through >= 40);
}

TEST_CASE("whale chains: the window is left only when it must be", "[woa][chain]") {
    // A wall across the bottom rows with one gap at the top: the target's window (rows 3-5) is cut
    // in two, so the walk leaves it, and still arrives.
    const auto map = test::map_of({".........", "....@....", "....@....", "....@....", "....@....", "....@...."});
    const grid::Cell s{0, 5}, g{8, 5};
    const grid::Path target = path_of(
        {{0, 5}, {1, 4}, {2, 3}, {3, 2}, {3, 1}, {3, 0}, {4, 0}, {5, 0}, {5, 1}, {5, 2}, {6, 3}, {7, 4}, {8, 5}});
    REQUIRE(grid::path_violation(map, target, s, g).empty());
    grid::WhaleChainMoves moves;
    for (std::uint64_t seed = 1; seed <= 50; ++seed) {
        Rng rng(seed);
        grid::Path c = target;
        moves.toward(map, c, target, 0.2, rng, false);
        INFO("seed " << seed);
        CHECK(grid::path_violation(map, c, s, g).empty());
        CHECK(is_simple(c));
    }
}

TEST_CASE("whale chains: the space's shortcut, straight or with elbows, kept if not worse on request", "[woa][chain]") {
    const auto map = test::map_of({".......", ".......", "......."});
    const Instance in{std::make_shared<const grid::GridMap>(map), {0, 0}, {6, 2}};
    const grid::Path c = path_of({{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}, {5, 1}, {6, 2}});
    SECTION("none leaves chains as they are") {
        Space space = space_of(in);
        space.set_shortcut(grid::Shortcut::none);
        grid::Path d = c;
        space.shorten(d);
        CHECK(d == c);
    }
    SECTION("line: grid.md's straight cell line, whatever it does to the turns, at no evaluation") {
        // Bresenham's line from (0, 0) to (6, 2) is a staircase: (0,0) (1,0) (2,1) (3,1) (4,1) (5,2) (6,2).
        Space space = space_of(in);
        space.set_shortcut(grid::Shortcut::line);
        grid::Path d = c;
        space.shorten(d);  // unscored: no evaluation is needed
        CHECK(d == path_of({{0, 0}, {1, 0}, {2, 1}, {3, 1}, {4, 1}, {5, 2}, {6, 2}}));
        CHECK(grid::metrics(d).length == Approx(grid::metrics(c).length));
        CHECK(grid::metrics(d).turns > grid::metrics(c).turns);
    }
    SECTION("elbow: a one-turn join first") {
        Space space = space_of(in);
        space.set_shortcut(grid::Shortcut::elbow);
        grid::Path d = path_of({{0, 0}, {1, 1}, {2, 2}, {3, 2}, {4, 1}, {5, 0}, {6, 0}});
        const Instance flat{in.map, {0, 0}, {6, 0}};
        Space flat_space = space_of(flat);
        flat_space.set_shortcut(grid::Shortcut::elbow);
        flat_space.shorten(d);
        CHECK(d == path_of({{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}, {5, 0}, {6, 0}}));
    }
    SECTION("keep if not worse: two counted evaluations, the shortened chain refused when it is worse") {
        Space space = space_of(in);
        space.set_shortcut(grid::Shortcut::line, true);
        grid::Path d = c;
        CHECK_THROWS_AS(space.shorten(d), std::logic_error);  // scoring without the run's guard
        int calls = 0;
        space.shorten(d, [&](const grid::Path& x) {
            ++calls;
            return space.evaluate(x);
        });
        CHECK(calls == 2);
        CHECK(d == c);  // the staircase has more turns: worse under hswoa, refused
    }
}

// ---------------------------------------------------------------------------------------------
// WOA and HS-WOA on chains

TEST_CASE("woa on chains: every whale legal on every bundled map and 200 random maps", "[woa][chain]") {
    std::vector<Instance> instances = bundled_instances();
    REQUIRE(instances.size() >= 8);
    const std::size_t bundled_count = instances.size();
    for (const auto& r : random_instances(2026, 200)) instances.push_back(r);
    REQUIRE(instances.size() == bundled_count + 200);
    for (std::size_t k = 0; k < instances.size(); ++k) {
        const Instance& in = instances[k];
        INFO("instance " << k << " " << in.map->width() << "x" << in.map->height() << " " << grid::to_string(in.start)
                         << " -> " << grid::to_string(in.goal));
        const Termination stop = max_iterations(k < bundled_count ? 10 : 4);
        for (int which = 0; which < 2; ++which) {
            LegalityChecker checker{in};
            grid::Path best;
            if (which == 0) {
                HsWoa a;
                a.population = k < bundled_count ? 20 : 8;
                a.mode.thr = 0;  // stagnation often: the reconstruction runs too
                best = a.run(space_of(in), stop, k, checker).best_x;
            } else {
                PlainWoa a;
                a.population = k < bundled_count ? 20 : 8;
                best = a.run(space_of(in), stop, k, checker).best_x;
            }
            INFO((which == 0 ? "hswoa" : "woa"));
            CHECK(*checker.bad == 0);
            if (*checker.bad) FAIL_CHECK(*checker.first);
            CHECK(*checker.seen > 0);
            CHECK(legal(in, best).empty());
        }
    }
}

TEST_CASE("woa on chains: reproducible bit for bit, never worse than the first pod", "[woa][chain]") {
    const Instance in = bundled("cai2021-50x50.map");
    HsWoa a;
    a.population = 20;
    const auto r1 = a.run(space_of(in), max_iterations(20), 11);
    const auto r2 = a.run(space_of(in), max_iterations(20), 11);
    REQUIRE(same_bits(r1.best_f, r2.best_f));
    REQUIRE(r1.best_x == r2.best_x);
    REQUIRE(r1.evaluations == r2.evaluations);
    REQUIRE(r1.history.size() == r2.history.size());
    for (std::size_t k = 0; k < r1.history.size(); ++k) REQUIRE(same_bits(r1.history[k], r2.history[k]));
    for (std::size_t k = 1; k < r1.history.size(); ++k) CHECK(r1.history[k] <= r1.history[k - 1]);
    const auto other = a.run(space_of(in), max_iterations(20), 12);
    CHECK((other.history != r1.history || other.best_x != r1.best_x));
    // The value is the path's hswoa value, and no better than the exact optimum.
    const auto problem = problem_of(in);
    CHECK(r1.best_f == problem.evaluate(r1.best_x));
    const auto m = grid::metrics(r1.best_x);
    CHECK(r1.best_f == Approx(m.length + m.turns));
}

TEST_CASE("woa on chains: budgets are exact", "[woa][chain]") {
    const Instance in = bundled("cai2021-env1-30x30.map");
    for (const std::int64_t budget : {1, 19, 20, 21, 59, 60, 61, 333}) {
        INFO("budget " << budget);
        for (int which = 0; which < 2; ++which) {
            CountedSpace problem{space_of(in)};
            LegalityChecker checker{in};
            BasicResult<grid::Path> r;
            if (which == 0) {
                HsWoa a;
                a.population = 20;
                r = a.run(problem, max_evaluations(budget), 5, checker);
            } else {
                PlainWoa a;
                a.population = 20;
                r = a.run(problem, max_evaluations(budget), 5, checker);
            }
            CHECK(*problem.count == budget);
            CHECK(r.evaluations == budget);
            CHECK(r.history_evaluations.back() == budget);
            CHECK(std::isfinite(r.best_f));
            CHECK(*checker.bad == 0);
        }
    }
    // Iterations: N + T N (woa), at most N + 3 T N (the harmony second step, no balance factor: a
    // harmony that copies a member as it is costs no evaluation).
    Woa<PerWhaleDraws, ConvergenceMode, HarmonySecondStep> hs;
    hs.population = 20;
    CountedSpace p1{space_of(in)};
    const auto h = hs.run(p1, max_iterations(7), 3);
    CHECK(h.iterations == 7);
    CHECK(*p1.count == h.evaluations);
    CHECK(*p1.count < 20 + 7 * 60);
    CHECK(*p1.count > 20 + 7 * 40);
    PlainWoa w;
    w.population = 20;
    CountedSpace p2{space_of(in)};
    w.run(p2, max_iterations(7), 3);
    CHECK(*p2.count == 20 + 7 * 20);
}

TEST_CASE("woa on chains: per-coordinate draws are refused", "[woa][chain]") {
    Woa<PerCoordinateDraws> a;
    a.population = 5;
    CHECK_THROWS_AS(a.run(space_of(bundled("cai2021-env1-30x30.map")), max_iterations(2), 1), InputError);
}

TEST_CASE("woa entries on grids: the chain encoding, N = 20 and 50 iterations, objective hswoa",
          "[woa][chain][engine]") {
    engine::GridSpec g;
    g.map = engine::load_map((bundled_maps() / "cai2021-50x50.map").string());
    const auto scen = grid::read_scenario((bundled_maps() / "cai2021-50x50.map.scen").string());
    g.start = scen.at(0).start;
    g.goal = scen.at(0).goal;
    g.encoding = "chain";
    g.objective = "hswoa";
    const engine::Budget budget;  // the grid default: 50 iterations
    for (const std::string name : {"woa", "woa-hs", "woa-balance", "hswoa"}) {
        INFO(name);
        const auto* e = engine::algorithms().find(name);
        REQUIRE(e != nullptr);
        const auto spaces = e->spaces();
        CHECK(std::find(spaces.begin(), spaces.end(), "chain") != spaces.end());
        CHECK(std::find(spaces.begin(), spaces.end(), "box") != spaces.end());
        const auto r = engine::run({name, {}}, engine::Problem(g), budget, 4);
        REQUIRE(r.grid.has_value());
        CHECK(r.grid->feasible);
        CHECK(r.iterations == 50);
        CHECK(r.history_evaluations.front() == 20);
        if (name == "woa") CHECK(r.evaluations == 20 + 50 * 20);
        if (name == "woa-hs") CHECK(r.evaluations < 20 + 50 * 60);  // copied harmonies are not evaluated
        CHECK(r.history == engine::run({name, {}}, engine::Problem(g), budget, 4).history);
        // Box-only parameters are refused on chains.
        engine::AlgorithmSpec bad{name, {}};
        bad.params.set("per_coordinate", 1);
        CHECK_THROWS_AS(engine::run(bad, engine::Problem(g), budget, 1), InputError);
    }
}

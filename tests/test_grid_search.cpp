// Tests of searching and decoding on grids (docs/grid.md): A* against the optimal lengths
// recorded in the Moving AI scenario files, the exact oracle against brute force, the path
// metrics, loop cutting and straight lines on hand-made examples, the random walker, the `line`
// and `free` decoders under both connectors, and the grid problem's input errors.
#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "framework/encoding.hpp"
#include "framework/error.hpp"
#include "framework/problem.hpp"
#include "framework/random.hpp"
#include "problems/grid/connectors.hpp"
#include "problems/grid/encodings.hpp"
#include "problems/grid/grid_problem.hpp"
#include "problems/grid/map.hpp"
#include "problems/grid/map_io.hpp"
#include "problems/grid/objectives.hpp"
#include "problems/grid/path.hpp"
#include "problems/grid/planners/astar.hpp"
#include "problems/grid/planners/oracle.hpp"
#include "problems/grid/walk.hpp"
#include "tests/grid_support.hpp"
#include "tests/test_support.hpp"

using namespace pride::grid;
using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;
using pride::test::below;
using pride::test::input_error_message;
using pride::test::map_of;

namespace {

/// A w x h map whose cells are blocked independently with probability `density`.
GridMap random_map(pride::Rng& rng, int w, int h, double density) {
    std::vector<std::uint8_t> blocked(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
    for (auto& b : blocked) b = rng.uniform() < density ? 1 : 0;
    return GridMap(w, h, std::move(blocked), "random");
}

/// A uniformly drawn free cell (the map must have one).
Cell random_free_cell(pride::Rng& rng, const GridMap& map) {
    for (;;) {
        const Cell c{below(rng, map.width()), below(rng, map.height())};
        if (map.free(c)) return c;
    }
}

bool has_free_cell(const GridMap& map) {
    for (std::size_t i = 0; i < map.size(); ++i)
        if (map.free_index(i)) return true;
    return false;
}

/// No cell twice.
bool is_simple(const Path& path) {
    std::set<std::pair<int, int>> seen;
    for (const Cell c : path)
        if (!seen.insert({c.x, c.y}).second) return false;
    return true;
}

/// Consecutive cells are 8-neighbours, start first, goal last (legal or not).
bool is_chain(const Path& path, Cell start, Cell goal) {
    if (path.empty() || !(path.front() == start) || !(path.back() == goal)) return false;
    for (std::size_t i = 1; i < path.size(); ++i)
        if (direction(path[i - 1], path[i]) < 0) return false;
    return true;
}

// ---------------------------------------------------------------------------------------------
// Brute force for the oracle.
//
// It enumerates every simple path (no cell twice) from s to g by depth-first search and keeps the
// smallest objective value, computed from metrics() of the whole chain, independently of the
// step/turn costs the oracle adds up. Branch and bound: a partial chain whose value is already
// >= the best is not extended, which is exact because every term of these objectives (cells,
// length, turns, angle penalty, with non-negative weights) can only grow as a chain grows.
//
// Why simple paths suffice although the oracle searches walks (cells may repeat): take an optimal
// walk with a repeated cell and an innermost loop X -> Y1 -> ... -> Yk -> X (no other repeat),
// entered in direction d1, left in d4, and cut it out (X -> next directly). Cutting removes at
// least two steps (length never grows) and the turns at X and inside the loop, and adds at most
// one turn at X, which costs at most c(4) = w_turn + 50 w_angle (c(k) = w_turn + w_angle W(k)
// is non-decreasing in k). A closed polygon turns by at least 360 degrees in total (8 steps of
// 45 degrees), of which the closing turn at X (from the arriving to the leaving direction) is at
// most 4; it is exactly 4 only when the loop arrives from Y1 itself, i.e. k = 1 (X -> Y1 -> X, a
// single U-turn at Y1 costing c(4)). Otherwise the turns inside the loop add up to at least 5
// steps, and since W(k) >= 10 k for k = 1..4 they cost at least w_turn + 50 w_angle. Either way the
// cut walk costs no more, so for cells, length, weighted (any weights >= 0) and hswoa
// (lambda >= 0) some optimal walk is a simple path, and the two optima are equal.
template <class Objective>
struct BruteForce {
    const GridMap& map;
    Cell goal;
    const Objective& objective;
    bool corner_cutting;
    double best = std::numeric_limits<double>::infinity();
    Path chain;
    std::vector<std::uint8_t> on_chain;

    void extend() {
        const double value = objective(metrics(chain));
        if (value >= best) return;
        const Cell c = chain.back();
        if (c == goal) {
            best = value;
            return;
        }
        for (int d = 0; d < 8; ++d) {
            if (!map.legal_step(c, d, corner_cutting)) continue;
            const Cell n{c.x + kDx[d], c.y + kDy[d]};
            if (on_chain[map.index(n)]) continue;
            on_chain[map.index(n)] = 1;
            chain.push_back(n);
            extend();
            chain.pop_back();
            on_chain[map.index(n)] = 0;
        }
    }
};

/// The best value of `objective` over simple paths from s to g, or -1 when there is none.
template <class Objective>
double brute_force(const GridMap& map, Cell s, Cell g, const Objective& objective, bool corner_cutting) {
    BruteForce<Objective> bf{map,
                             g,
                             objective,
                             corner_cutting,
                             std::numeric_limits<double>::infinity(),
                             {s},
                             std::vector<std::uint8_t>(map.size(), 0)};
    bf.on_chain[map.index(s)] = 1;
    bf.extend();
    return std::isinf(bf.best) ? -1.0 : bf.best;
}

/// Checks the oracle (guided and plain Dijkstra) against brute force on one query.
template <class Objective>
void check_oracle(Oracle& guided, Oracle& plain, const GridMap& map, Cell s, Cell g, const Objective& objective,
                  bool corner_cutting) {
    Path path, plain_path;
    const double expected = brute_force(map, s, g, objective, corner_cutting);
    const double value = guided.solve(map, s, g, objective, &path, corner_cutting);
    const double plain_value = plain.solve(map, s, g, objective, &plain_path, corner_cutting);
    INFO("objective " << Objective::name << " from (" << s.x << "," << s.y << ") to (" << g.x << "," << g.y
                      << ") corner cutting " << corner_cutting);
    if (expected < 0) {
        CHECK(value == -1.0);
        CHECK(plain_value == -1.0);
        return;
    }
    CHECK_THAT(value, WithinAbs(expected, 1e-9));
    CHECK_THAT(plain_value, WithinAbs(expected, 1e-9));
    CHECK(path_violation(map, path, s, g, corner_cutting).empty());
    CHECK(path_violation(map, plain_path, s, g, corner_cutting).empty());
    CHECK_THAT(objective(metrics(path)), WithinAbs(value, 1e-9));
    CHECK_THAT(objective(metrics(plain_path)), WithinAbs(plain_value, 1e-9));
}

/// The number of cells of a shortest (fewest steps) legal path, by breadth-first search; -1 when
/// g cannot be reached.
int bfs_cells(const GridMap& map, Cell s, Cell g, bool corner_cutting = false) {
    if (!map.free(s) || !map.free(g)) return -1;
    std::vector<int> dist(map.size(), -1);
    std::vector<Cell> queue{s};
    dist[map.index(s)] = 1;
    for (std::size_t head = 0; head < queue.size(); ++head) {
        const Cell c = queue[head];
        if (c == g) return dist[map.index(c)];
        for (int d = 0; d < 8; ++d) {
            if (!map.legal_step(c, d, corner_cutting)) continue;
            const Cell n{c.x + kDx[d], c.y + kDy[d]};
            if (dist[map.index(n)] >= 0) continue;
            dist[map.index(n)] = dist[map.index(c)] + 1;
            queue.push_back(n);
        }
    }
    return -1;
}

template <class Oracle_, class Objective>
concept OracleAccepts = requires(Oracle_& o, const GridMap& m, Cell c, const Objective& obj) {
    o.solve(m, c, c, obj);
};

}  // namespace

// ---------------------------------------------------------------------------------------------
// A* and the Moving AI scenarios

TEST_CASE("A* returns the optimal lengths recorded in the Moving AI scenario files", "[grid][astar][movingai]") {
    // Every line of every map up to 64 x 64 cells. The larger maps: every line in optimised
    // builds (about 4 s on one core at -O2), every 10th line (0, 10, 20, ... of each file, so every
    // bucket range is sampled) in unoptimised ones. The oracle's `length` is checked on every line
    // of the small maps and every 10th line of the larger ones.
    namespace fs = std::filesystem;
    const auto data = pride::test::shared_data("movingai", "Moving AI maps and scenarios");
    if (!data) return;
    const fs::path dir = *data;
    const std::vector<fs::path> scenarios = pride::test::movingai_scenarios(dir);
    REQUIRE(scenarios.size() >= 16);

    AStar astar;
    Oracle oracle;
    Path path;
    std::size_t checked = 0, small_maps = 0;
    for (const auto& scen : scenarios) {
        const auto entries = read_scenario(scen.string());
        REQUIRE(!entries.empty());
        const GridMap map = read_map((dir / entries.front().map).string());
        const bool small = map.width() <= 64 && map.height() <= 64;
        small_maps += small;
#ifdef NDEBUG
        const std::size_t stride = 1;
#else
        const std::size_t stride = small ? 1 : 10;
#endif
        for (std::size_t i = 0; i < entries.size(); i += stride) {
            const ScenarioEntry& e = entries[i];
            INFO(scen.filename().string() << " line " << e.line);
            REQUIRE(e.width == map.width());
            REQUIRE(e.height == map.height());
            const double length = astar.search(map, e.start, e.goal, &path);
            CHECK_THAT(length, WithinAbs(e.optimal, 1e-6));
            CHECK(path_violation(map, path, e.start, e.goal).empty());
            CHECK_THAT(metrics(path).length, WithinAbs(length, 1e-9));
            // The oracle's `length` is A*'s (grid.md).
            if (small || i % 10 == 0)
                CHECK_THAT(oracle.solve(map, e.start, e.goal, LengthObjective{}), WithinAbs(e.optimal, 1e-6));
            ++checked;
        }
    }
    CHECK(small_maps >= 8);
    CHECK(checked >= 2000);
}

TEST_CASE("A* on hand-made maps: no corner cutting, windows, unreachable goals", "[grid][astar]") {
    const GridMap map = map_of({
        "....",
        ".@..",
        "..@.",
        "....",
    });
    AStar astar;
    Path path;
    // (1,2) -> (2,1) is a diagonal between the two blocked cells (1,1) and (2,2): illegal. So are
    // (1,2) -> (0,1), (1,2) -> (2,3), (1,0) -> (2,1) and (3,2) -> (2,1), which each pass one of
    // them. The shortest legal paths go round either block with orthogonal steps only:
    // (1,2) (0,2) (0,1) (0,0) (1,0) (2,0) (2,1) or (1,2) (1,3) (2,3) (3,3) (3,2) (3,1) (2,1): 6.
    const double strict = astar.search(map, {1, 2}, {2, 1}, &path);
    CHECK(strict == 6.0);
    CHECK(path_violation(map, path, {1, 2}, {2, 1}).empty());
    Oracle oracle;
    CHECK_THAT(oracle.solve(map, {1, 2}, {2, 1}, LengthObjective{}), WithinAbs(strict, 1e-12));
    CHECK_THAT(astar.search(map, {1, 2}, {2, 1}, &path, nullptr, true), WithinAbs(kSqrt2, 1e-12));
    CHECK(path == Path{{1, 2}, {2, 1}});
    // Same cell: length 0, one cell.
    CHECK(astar.search(map, {3, 3}, {3, 3}, &path) == 0.0);
    CHECK(path == Path{{3, 3}});
    // Blocked ends and a window that excludes every detour.
    CHECK(astar.search(map, {1, 1}, {3, 3}) == -1.0);
    const Window tight{1, 1, 2, 2};
    CHECK(astar.search(map, {1, 2}, {2, 1}, nullptr, &tight) == -1.0);
    const GridMap walled = map_of({
        ".@.",
        ".@.",
        ".@.",
    });
    CHECK(astar.search(walled, {0, 0}, {2, 2}) == -1.0);
}

// ---------------------------------------------------------------------------------------------
// The oracle

TEST_CASE("the oracle equals brute force over simple paths on tiny random maps", "[grid][oracle]") {
    // 1200 maps of 4x4, 5x4 and 5x5 cells with 0 to 30 % obstacles, 3 start/goal pairs each
    // (unreachable pairs included), every additive objective, with and without corner cutting.
    Oracle guided, plain;
    plain.use_heuristic = false;
    pride::Rng rng(20240611);
    const WeightedObjective weighted_default{};
    const WeightedObjective weighted_turny{1.0, 2.0, 0.5};
    const WeightedObjective weighted_angle{0.5, 0.0, 1.0};
    const WeightedObjective weighted_no_length{0.0, 0.0, 1.0};  // zero-cost steps
    const HswoaObjective hswoa_1{1.0};
    const HswoaObjective hswoa_25{2.5};
    int queries = 0;
    for (int m = 0; m < 1200; ++m) {
        const int w = m % 3 == 0 ? 4 : 5, h = m % 3 == 2 ? 5 : 4;
        const GridMap map = random_map(rng, w, h, 0.3 * rng.uniform());
        if (!has_free_cell(map)) continue;
        for (int q = 0; q < 3; ++q) {
            const Cell s = random_free_cell(rng, map), g = random_free_cell(rng, map);
            const bool cc = q == 2;
            check_oracle(guided, plain, map, s, g, CellsObjective{}, cc);
            check_oracle(guided, plain, map, s, g, LengthObjective{}, cc);
            check_oracle(guided, plain, map, s, g, weighted_default, cc);
            check_oracle(guided, plain, map, s, g, weighted_turny, cc);
            check_oracle(guided, plain, map, s, g, weighted_angle, cc);
            check_oracle(guided, plain, map, s, g, weighted_no_length, cc);
            check_oracle(guided, plain, map, s, g, hswoa_1, cc);
            check_oracle(guided, plain, map, s, g, hswoa_25, cc);
            ++queries;
        }
    }
    CHECK(queries >= 3000);
}

TEST_CASE("the oracle's cells is a breadth-first count and its length is A*'s", "[grid][oracle]") {
    Oracle oracle;
    AStar astar;
    pride::Rng rng(7);
    Path path;
    for (int m = 0; m < 300; ++m) {
        const int w = 10 + below(rng, 31), h = 10 + below(rng, 31);
        const GridMap map = random_map(rng, w, h, 0.4 * rng.uniform());
        if (!has_free_cell(map)) continue;
        for (int q = 0; q < 5; ++q) {
            const Cell s = random_free_cell(rng, map), g = random_free_cell(rng, map);
            const bool cc = q == 4;
            const int cells = bfs_cells(map, s, g, cc);
            const double by_oracle = oracle.solve(map, s, g, CellsObjective{}, &path, cc);
            CHECK(by_oracle == static_cast<double>(cells));
            if (cells > 0) {
                CHECK(path_violation(map, path, s, g, cc).empty());
                CHECK(static_cast<int>(path.size()) == cells);
            }
            const double length = astar.search(map, s, g, nullptr, nullptr, cc);
            CHECK_THAT(oracle.solve(map, s, g, LengthObjective{}, &path, cc), WithinAbs(length, 1e-9));
            if (length >= 0) CHECK_THAT(metrics(path).length, WithinAbs(length, 1e-9));
        }
    }
}

TEST_CASE("the oracle on hand-made maps: turns cost what the objective says", "[grid][oracle]") {
    // An empty 5x5 map from (0,0) to (4,2): the shortest path is 2 diagonals + 2 orthogonals
    // (length 2 + 2 sqrt 2), with one 45-degree turn; hswoa = length + lambda * 1.
    const GridMap open = map_of({".....", ".....", ".....", ".....", "....."});
    Oracle oracle;
    Path path;
    CHECK_THAT(oracle.solve(open, {0, 0}, {4, 2}, LengthObjective{}), WithinAbs(2 + 2 * kSqrt2, 1e-12));
    CHECK_THAT(oracle.solve(open, {0, 0}, {4, 2}, HswoaObjective{1.0}, &path), WithinAbs(3 + 2 * kSqrt2, 1e-12));
    CHECK(metrics(path).turns == 1);
    // weighted (1, 1, 0.1): the one turn is 45 degrees, W = 10: 2 + 2 sqrt 2 + 1 + 1.
    CHECK_THAT(oracle.solve(open, {0, 0}, {4, 2}, WeightedObjective{}, &path), WithinAbs(4 + 2 * kSqrt2, 1e-12));
    CHECK(metrics(path).angle_penalty == 10);
    // cells: 5 cells (Chebyshev distance 4, plus one).
    CHECK(oracle.solve(open, {0, 0}, {4, 2}, CellsObjective{}) == 5.0);
    // A straight line costs no turn: (0,0) to (4,0) is 4 for hswoa.
    CHECK(oracle.solve(open, {0, 0}, {4, 0}, HswoaObjective{2.5}, &path) == 4.0);
    CHECK(path == Path{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}});
    // start == goal: start_cost alone, one cell.
    CHECK(oracle.solve(open, {2, 2}, {2, 2}, CellsObjective{}, &path) == 1.0);
    CHECK(path == Path{{2, 2}});
    CHECK(oracle.solve(open, {2, 2}, {2, 2}, LengthObjective{}) == 0.0);
    // A wall with one gap at the bottom: with a large turn cost, the fewest-turn path wins over
    // the shortest one. From (0,0) to (4,0) round the wall in column 2 (gap at (2,4)):
    //   ..@..
    //   ..@..
    //   ..@..
    //   ..@..
    //   .....
    // fewest turns: down column 0, along row 4, up column 4: 2 turns of 90 degrees, length 12.
    const GridMap wall = map_of({"..@..", "..@..", "..@..", "..@..", "....."});
    CHECK_THAT(oracle.solve(wall, {0, 0}, {4, 0}, HswoaObjective{100.0}, &path), WithinAbs(12 + 200.0, 1e-9));
    CHECK(metrics(path).turns == 2);
    CHECK(path_violation(wall, path, {0, 0}, {4, 0}).empty());
    // Unreachable, blocked or outside ends: -1, and `out` untouched.
    const GridMap walled = map_of({".@.", ".@.", ".@."});
    path = Path{{9, 9}};
    CHECK(oracle.solve(walled, {0, 0}, {2, 2}, LengthObjective{}, &path) == -1.0);
    CHECK(oracle.solve(walled, {1, 0}, {2, 2}, LengthObjective{}, &path) == -1.0);
    CHECK(oracle.solve(walled, {0, 0}, {3, 0}, LengthObjective{}, &path) == -1.0);
    CHECK(path == Path{{9, 9}});
    // The oracle refuses non-additive objectives at compile time.
    static_assert(OracleAccepts<Oracle, LengthObjective>);
    static_assert(!OracleAccepts<Oracle, IqgaObjective>);
}

TEST_CASE("the oracle is deterministic and reusable across maps of different sizes", "[grid][oracle]") {
    pride::Rng rng(99);
    Oracle reused;
    for (int m = 0; m < 20; ++m) {
        const GridMap map = random_map(rng, 5 + below(rng, 30), 5 + below(rng, 30), 0.25);
        if (!has_free_cell(map)) continue;
        const Cell s = random_free_cell(rng, map), g = random_free_cell(rng, map);
        Oracle fresh;
        Path a, b;
        const double va = reused.solve(map, s, g, WeightedObjective{}, &a);
        const double vb = fresh.solve(map, s, g, WeightedObjective{}, &b);
        CHECK(va == vb);
        CHECK(a == b);
    }
}

// ---------------------------------------------------------------------------------------------
// Metrics

TEST_CASE("metrics and objectives of a straight line", "[grid][metrics]") {
    // (0,0) -> (3,0): 4 cells, 3 east steps, no turn.
    const Path p{{0, 0}, {1, 0}, {2, 0}, {3, 0}};
    const PathMetrics m = metrics(p);
    CHECK(m.cells == 4);
    CHECK(m.length == 3.0);
    CHECK(m.turns == 0);
    CHECK(m.turn_angle_deg == 0);
    CHECK(m.angle_penalty == 0);
    // iqga on a straight path: 1/f2 reads as 0.2 and 1/f3 as 2: -(1/3 + 0.2 + 2).
    CHECK_THAT(IqgaObjective{}(m), WithinAbs(-(1.0 / 3 + 0.2 + 2.0), 1e-12));
    CHECK(CellsObjective{}(m) == 4.0);
    CHECK(LengthObjective{}(m) == 3.0);
    CHECK(HswoaObjective{}(m) == 3.0);
    CHECK(WeightedObjective{}(m) == 3.0);
}

TEST_CASE("metrics of a single cell", "[grid][metrics]") {
    // One cell: length 0, so 1/f1 reads as 2 (twice the reciprocal of the shortest step, 1):
    // iqga = -(2 + 0.2 + 2) = -4.2.
    const PathMetrics m = metrics(Path{{2, 3}});
    CHECK(m.cells == 1);
    CHECK(m.length == 0.0);
    CHECK(m.turns == 0);
    CHECK_THAT(IqgaObjective{}(m), WithinAbs(-4.2, 1e-12));
}

TEST_CASE("metrics of a zig-zag", "[grid][metrics]") {
    // (0,0) SE (1,1) NE (2,0) SE (3,1) NE (4,0): 4 diagonal steps, length 4 sqrt 2; the direction
    // alternates between SE (1) and NE (7), 90 degrees apart, at the 3 interior cells: 3 turns,
    // 270 degrees, penalty 3 * 20 = 60.
    const Path p{{0, 0}, {1, 1}, {2, 0}, {3, 1}, {4, 0}};
    const PathMetrics m = metrics(p);
    CHECK(m.cells == 5);
    CHECK_THAT(m.length, WithinAbs(4 * kSqrt2, 1e-12));
    CHECK(m.turns == 3);
    CHECK(m.turn_angle_deg == 270);
    CHECK(m.angle_penalty == 60);
    CHECK_THAT(IqgaObjective{}(m), WithinAbs(-(1 / (4 * kSqrt2) + 1.0 / 60 + 1.0 / 3), 1e-12));
    // weighted (1, 1, 0.1): 4 sqrt 2 + 3 + 6; hswoa lambda 2.5: 4 sqrt 2 + 7.5.
    CHECK_THAT(WeightedObjective{}(m), WithinAbs(4 * kSqrt2 + 9, 1e-12));
    CHECK_THAT(HswoaObjective{2.5}(m), WithinAbs(4 * kSqrt2 + 7.5, 1e-12));
}

TEST_CASE("metrics of a U-turn", "[grid][metrics]") {
    // (0,0) E (1,0) E (2,0) W (1,0): the direction reverses at (2,0): one turn of 180 degrees,
    // W = 50 (above 90); length 3, 4 cells.
    const PathMetrics m = metrics(Path{{0, 0}, {1, 0}, {2, 0}, {1, 0}});
    CHECK(m.cells == 4);
    CHECK(m.length == 3.0);
    CHECK(m.turns == 1);
    CHECK(m.turn_angle_deg == 180);
    CHECK(m.angle_penalty == 50);
    CHECK_THAT(IqgaObjective{}(m), WithinAbs(-(1.0 / 3 + 1.0 / 50 + 1.0), 1e-12));
    // A U-shaped path instead: E, S, W: two turns of 90 degrees, penalty 40, length 3.
    const PathMetrics u = metrics(Path{{0, 0}, {1, 0}, {1, 1}, {0, 1}});
    CHECK(u.turns == 2);
    CHECK(u.turn_angle_deg == 180);
    CHECK(u.angle_penalty == 40);
    CHECK(u.length == 3.0);
}

TEST_CASE("metrics of a 45-degree turn", "[grid][metrics]") {
    // (0,0) E (1,0) SE (2,1): one turn of 45 degrees, W = 10; length 1 + sqrt 2.
    const PathMetrics m = metrics(Path{{0, 0}, {1, 0}, {2, 1}});
    CHECK(m.cells == 3);
    CHECK_THAT(m.length, WithinAbs(1 + kSqrt2, 1e-12));
    CHECK(m.turns == 1);
    CHECK(m.turn_angle_deg == 45);
    CHECK(m.angle_penalty == 10);
    CHECK_THAT(IqgaObjective{}(m), WithinAbs(-(1 / (1 + kSqrt2) + 0.1 + 1.0), 1e-12));
    // weighted (1, 1, 0.1): 1 + sqrt 2 + 1 + 1.
    CHECK_THAT(WeightedObjective{}(m), WithinAbs(3 + kSqrt2, 1e-12));
}

TEST_CASE("metrics of a 90-degree turn", "[grid][metrics]") {
    // (0,0) E (1,0) S (1,1): one turn of 90 degrees, W = 20; length 2.
    const PathMetrics m = metrics(Path{{0, 0}, {1, 0}, {1, 1}});
    CHECK(m.cells == 3);
    CHECK(m.length == 2.0);
    CHECK(m.turns == 1);
    CHECK(m.turn_angle_deg == 90);
    CHECK(m.angle_penalty == 20);
    CHECK_THAT(IqgaObjective{}(m), WithinAbs(-(0.5 + 0.05 + 1.0), 1e-12));
    CHECK_THAT(WeightedObjective{}(m), WithinAbs(2 + 1 + 2, 1e-12));
}

TEST_CASE("metrics of a 135-degree turn", "[grid][metrics]") {
    // (0,0) E (1,0) SW (0,1): east (0) then south-west (3), 3 * 45 = 135 degrees, W = 50;
    // length 1 + sqrt 2.
    const PathMetrics m = metrics(Path{{0, 0}, {1, 0}, {0, 1}});
    CHECK(m.cells == 3);
    CHECK_THAT(m.length, WithinAbs(1 + kSqrt2, 1e-12));
    CHECK(m.turns == 1);
    CHECK(m.turn_angle_deg == 135);
    CHECK(m.angle_penalty == 50);
    CHECK_THAT(IqgaObjective{}(m), WithinAbs(-(1 / (1 + kSqrt2) + 0.02 + 1.0), 1e-12));
    CHECK_THAT(WeightedObjective{}(m), WithinAbs(1 + kSqrt2 + 1 + 5, 1e-12));
    CHECK_THAT(HswoaObjective{}(m), WithinAbs(2 + kSqrt2, 1e-12));
}

TEST_CASE("the oracle's step and turn costs add up to each objective on hand-made paths", "[grid][metrics][oracle]") {
    // start_cost + step costs + turn costs of a chain = the objective of its metrics.
    const std::vector<Path> paths{
        {{0, 0}, {1, 0}, {2, 0}, {3, 0}},
        {{0, 0}, {1, 1}, {2, 0}, {3, 1}, {4, 0}},
        {{0, 0}, {1, 0}, {2, 0}, {1, 0}},
        {{0, 0}, {1, 0}, {2, 1}},
        {{0, 0}, {1, 0}, {1, 1}},
        {{0, 0}, {1, 0}, {0, 1}},
        {{2, 2}, {3, 3}, {3, 4}, {2, 4}, {1, 3}},
        {{4, 4}},
    };
    const auto additive = [](const Path& p, const auto& o) {
        double v = o.start_cost();
        for (std::size_t i = 1; i < p.size(); ++i) {
            const int d = direction(p[i - 1], p[i]);
            v += o.step_cost(d);
            if (i >= 2) {
                const int e = direction(p[i - 2], p[i - 1]);
                if (e != d) v += o.turn_cost(turn_steps(e, d));
            }
        }
        return v;
    };
    for (const Path& p : paths) {
        const PathMetrics m = metrics(p);
        CHECK_THAT(additive(p, CellsObjective{}), WithinAbs(CellsObjective{}(m), 1e-12));
        CHECK_THAT(additive(p, LengthObjective{}), WithinAbs(LengthObjective{}(m), 1e-12));
        CHECK_THAT(additive(p, WeightedObjective{}), WithinAbs(WeightedObjective{}(m), 1e-12));
        CHECK_THAT(additive(p, WeightedObjective{0.5, 2.0, 0.3}),
                   WithinAbs(WeightedObjective{0.5, 2.0, 0.3}(m), 1e-12));
        CHECK_THAT(additive(p, HswoaObjective{2.5}), WithinAbs(HswoaObjective{2.5}(m), 1e-12));
    }
}

// ---------------------------------------------------------------------------------------------
// Loops and lines

TEST_CASE("cut_loops cuts a loop in the middle", "[grid][path]") {
    const GridMap map = map_of({".....", ".....", "....."});
    std::vector<std::int32_t> seen;
    // A B C D B E -> A B E: (1,0) comes back, the cells between its visits go.
    Path p{{0, 0}, {1, 0}, {2, 0}, {2, 1}, {1, 0}, {1, 1}};
    cut_loops(p, map, seen);
    CHECK(p == Path{{0, 0}, {1, 0}, {1, 1}});
}

TEST_CASE("cut_loops cuts a loop back to the start", "[grid][path]") {
    const GridMap map = map_of({".....", ".....", "....."});
    std::vector<std::int32_t> seen;
    // A B C A D -> A D.
    Path p{{0, 0}, {1, 0}, {1, 1}, {0, 0}, {0, 1}};
    cut_loops(p, map, seen);
    CHECK(p == Path{{0, 0}, {0, 1}});
}

TEST_CASE("cut_loops cuts nested and overlapping loops", "[grid][path]") {
    const GridMap map = map_of({".....", ".....", "....."});
    std::vector<std::int32_t> seen;
    // Nested: A B C D C B E -> A B C (cut D C) -> A B (cut C B) -> A B E.
    Path nested{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {2, 0}, {1, 0}, {1, 1}};
    cut_loops(nested, map, seen);
    CHECK(nested == Path{{0, 0}, {1, 0}, {1, 1}});
    // Overlapping: A B C B C D -> A B (cut C B) then C D: A B C D.
    Path overlapping{{0, 0}, {1, 0}, {2, 0}, {1, 0}, {2, 0}, {3, 0}};
    cut_loops(overlapping, map, seen);  // `seen` reused without clearing
    CHECK(overlapping == Path{{0, 0}, {1, 0}, {2, 0}, {3, 0}});
    // A loop inside a loop that closes further out: A B C D E C F B G -> A B G.
    Path outer{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {2, 0}, {2, 1}, {1, 0}, {0, 1}};
    cut_loops(outer, map, seen);
    CHECK(outer == Path{{0, 0}, {1, 0}, {0, 1}});
}

TEST_CASE("cut_loops leaves a path without loops alone", "[grid][path]") {
    const GridMap map = map_of({".....", ".....", "....."});
    std::vector<std::int32_t> seen(map.size(), 3);  // stale scratch from an earlier call
    const Path simple{{0, 0}, {1, 1}, {2, 1}, {3, 2}, {4, 2}};
    Path p = simple;
    cut_loops(p, map, seen);
    CHECK(p == simple);
    Path one{{2, 2}};
    cut_loops(one, map, seen);
    CHECK(one == Path{{2, 2}});
}

TEST_CASE("append_line draws the straight 8-connected line", "[grid][path]") {
    Path p;
    append_line({0, 0}, {3, 0}, p);  // b included, a not
    CHECK(p == Path{{1, 0}, {2, 0}, {3, 0}});
    p.clear();
    append_line({0, 0}, {2, 2}, p);
    CHECK(p == Path{{1, 1}, {2, 2}});
    p.clear();
    // Bresenham from (0,0) to (4,2), worked out step by step (err starts at 4 - 2 = 2).
    append_line({0, 0}, {4, 2}, p);
    CHECK(p == Path{{1, 1}, {2, 1}, {3, 2}, {4, 2}});
    p.clear();
    append_line({4, 2}, {0, 0}, p);
    CHECK(p == Path{{3, 1}, {2, 1}, {1, 0}, {0, 0}});
    p.clear();
    append_line({0, 5}, {0, 2}, p);
    CHECK(p == Path{{0, 4}, {0, 3}, {0, 2}});
    p.clear();
    append_line({3, 3}, {3, 3}, p);  // a == b: nothing
    CHECK(p.empty());
}

TEST_CASE("line_is_free checks cells and diagonal steps", "[grid][path]") {
    // (1,0) and (0,1) are blocked: the diagonal (0,0) -> (1,1) cuts between them.
    const GridMap corner = map_of({
        ".@..",
        "@...",
        "....",
    });
    CHECK_FALSE(line_is_free(corner, {0, 0}, {1, 1}));
    CHECK(line_is_free(corner, {0, 0}, {1, 1}, true));  // allowed when corner cutting is
    // One blocked orthogonal neighbour is enough to forbid the diagonal without corner cutting.
    const GridMap one = map_of({
        ".@..",
        "....",
        "....",
    });
    CHECK_FALSE(line_is_free(one, {0, 0}, {1, 1}));
    CHECK(line_is_free(one, {0, 0}, {1, 1}, true));
    CHECK(line_is_free(one, {0, 1}, {3, 1}));
    // (0,2) -> (3,0): cells (1,1) (2,1) (3,0) (Bresenham, err from 3 - 2 = 1); the diagonal
    // (0,2) -> (1,1) has (1,2) and (0,1) free, the diagonal (2,1) -> (3,0) has (3,1) and (2,0)
    // free: a legal join, although (1,0) next to it is blocked.
    Path line;
    append_line({0, 2}, {3, 0}, line);
    CHECK(line == Path{{1, 1}, {2, 1}, {3, 0}});
    CHECK(line_is_free(one, {0, 2}, {3, 0}));
    // (0,0) -> (2,2) on `corner`: every cell free, but its first diagonal cuts the corner.
    CHECK(corner.free({1, 1}));
    CHECK(corner.free({2, 2}));
    CHECK_FALSE(line_is_free(corner, {0, 0}, {2, 2}));
    CHECK(line_is_free(corner, {0, 0}, {2, 2}, true));
    // A blocked cell on the line, a blocked first cell, a blocked last cell.
    CHECK_FALSE(line_is_free(one, {0, 0}, {3, 0}));
    CHECK_FALSE(line_is_free(one, {1, 0}, {3, 0}));
    CHECK_FALSE(line_is_free(one, {3, 0}, {1, 0}));
    CHECK(line_is_free(one, {2, 2}, {2, 2}));  // a free cell joins itself
}

TEST_CASE("line_is_free agrees with the legality of the line append_line draws", "[grid][path]") {
    pride::Rng rng(314);
    for (int m = 0; m < 40; ++m) {
        const GridMap map = random_map(rng, 12, 9, 0.3 * rng.uniform());
        for (int q = 0; q < 50; ++q) {
            const Cell a{below(rng, 12), below(rng, 9)}, b{below(rng, 12), below(rng, 9)};
            for (const bool cc : {false, true}) {
                Path full{a};
                append_line(a, b, full);
                CHECK(line_is_free(map, a, b, cc) == path_violation(map, full, a, b, cc).empty());
            }
        }
    }
}

// ---------------------------------------------------------------------------------------------
// The random walker

TEST_CASE("RandomWalker returns a legal simple path, or false exactly when the goal is unreachable", "[grid][walk]") {
    pride::Rng rng(4242);
    pride::Rng walk_rng(17);
    RandomWalker walker;
    Path path;
    int reached = 0, unreachable = 0;
    for (int m = 0; m < 150; ++m) {
        const int w = 5 + below(rng, 26), h = 5 + below(rng, 26);
        const GridMap map = random_map(rng, w, h, 0.45 * rng.uniform());
        if (!has_free_cell(map)) continue;
        walker.bias = m % 3 == 0 ? 0.0 : 2.0;
        for (int q = 0; q < 6; ++q) {
            const Cell s = random_free_cell(rng, map), g = random_free_cell(rng, map);
            const bool cc = q == 5;
            const bool reachable = reachable_from(map, s, cc)[map.index(g)] != 0;
            const bool ok = walker.walk(map, s, g, walk_rng, path, cc);
            REQUIRE(ok == reachable);
            if (ok) {
                CHECK(path_violation(map, path, s, g, cc).empty());
                CHECK(is_simple(path));
                ++reached;
            } else {
                CHECK(path.empty());
                ++unreachable;
            }
        }
        // Blocked ends: false.
        CHECK_FALSE(walker.walk(map, {-1, 0}, random_free_cell(rng, map), walk_rng, path));
    }
    CHECK(reached > 100);
    CHECK(unreachable > 20);
}

// ---------------------------------------------------------------------------------------------
// Decoders

namespace {

struct Instance {
    std::shared_ptr<const GridMap> map;
    Cell start, goal;
    bool corner_cutting;
};

/// Random maps 10x10 .. 30x30 with 0-35 % obstacles, and start/goal pairs with the goal
/// reachable and at least two rows or columns apart (so that `line` has a gene).
std::vector<Instance> random_instances(std::uint64_t seed, int maps, int pairs) {
    pride::Rng rng(seed);
    std::vector<Instance> out;
    for (int m = 0; m < maps; ++m) {
        const int w = 10 + below(rng, 21), h = 10 + below(rng, 21);
        auto map = std::make_shared<const GridMap>(random_map(rng, w, h, 0.35 * rng.uniform()));
        if (!has_free_cell(*map)) continue;
        const bool cc = m % 5 == 4;
        for (int q = 0, tries = 0; q < pairs && tries < 1000; ++tries) {
            const Cell s = random_free_cell(rng, *map), g = random_free_cell(rng, *map);
            if (std::max(std::abs(s.x - g.x), std::abs(s.y - g.y)) < 2) continue;
            if (!reachable_from(*map, s, cc)[map->index(g)]) continue;
            out.push_back({map, s, g, cc});
            ++q;
        }
    }
    return out;
}

/// Random genotypes for a box: uniform inside, and some genes outside, NaN or infinite.
std::vector<std::vector<double>> random_genotypes(pride::Rng& rng, std::span<const double> lower,
                                                  std::span<const double> upper, int count) {
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    std::vector<std::vector<double>> out;
    for (int j = 0; j < count; ++j) {
        std::vector<double> g(lower.size());
        for (std::size_t i = 0; i < g.size(); ++i) {
            g[i] = rng.uniform(lower[i], upper[i]);
            if (j % 4 == 3) {  // every fourth genotype: some wild genes
                switch (below(rng, 6)) {
                    case 0:
                        g[i] = nan;
                        break;
                    case 1:
                        g[i] = lower[i] - 1 - 10 * rng.uniform();
                        break;
                    case 2:
                        g[i] = upper[i] + 1 + 10 * rng.uniform();
                        break;
                    case 3:
                        g[i] = rng.uniform() < 0.5 ? inf : -inf;
                        break;
                    default:
                        break;
                }
            }
        }
        out.push_back(std::move(g));
    }
    return out;
}

/// Repair: a legal path from start to goal, no cell twice, no violation.
template <class Objective, class Encoding>
void check_repair(const GridProblem<Objective>& problem, Encoding& encoding,
                  const std::vector<std::vector<double>>& genotypes) {
    for (const auto& g : genotypes) {
        const DecodedPath& d = encoding.decode(problem, g);
        INFO("start (" << problem.start().x << "," << problem.start().y << ") goal (" << problem.goal().x << ","
                       << problem.goal().y << ") map " << problem.map().width() << "x" << problem.map().height());
        CHECK(d.violations == 0);
        CHECK(path_violation(problem.map(), d.path, problem.start(), problem.goal(), problem.corner_cutting()) == "");
        CHECK(is_simple(d.path));
    }
}

/// Penalty: a chain from start to goal, scored >= M exactly when it is illegal, else its objective.
template <class Objective, class Encoding>
void check_penalty(const GridProblem<Objective>& problem, Encoding& encoding,
                   const std::vector<std::vector<double>>& genotypes, int& illegal) {
    for (const auto& g : genotypes) {
        const DecodedPath& d = encoding.decode(problem, g);
        const double value = problem.evaluate(d);
        const std::string why =
            path_violation(problem.map(), d.path, problem.start(), problem.goal(), problem.corner_cutting());
        INFO("start (" << problem.start().x << "," << problem.start().y << ") goal (" << problem.goal().x << ","
                       << problem.goal().y << ") violations " << d.violations << " why '" << why << "'");
        CHECK(is_chain(d.path, problem.start(), problem.goal()));
        CHECK(is_simple(d.path));
        CHECK((value >= problem.penalty()) == !why.empty());
        if (why.empty()) CHECK(value == problem.objective()(metrics(d.path)));
        illegal += !why.empty();
    }
}

}  // namespace

TEST_CASE("line and free decoders with the repair connector always give a legal simple path", "[grid][encoding]") {
    pride::Rng rng(555);
    int cases = 0;
    for (const Instance& in : random_instances(2025, 60, 3)) {
        const GridProblem<LengthObjective> problem(in.map, in.start, in.goal, {}, in.corner_cutting);
        LineEncoding<RepairConnector> line(problem);
        check_repair(problem, line, random_genotypes(rng, line.lower(problem), line.upper(problem), 24));
        FreeEncoding<RepairConnector> free(problem, 1 + below(rng, 6));
        check_repair(problem, free, random_genotypes(rng, free.lower(problem), free.upper(problem), 24));
        ++cases;
    }
    CHECK(cases >= 150);
}

TEST_CASE("line and free decoders with the penalty connector score M exactly when the chain is illegal",
          "[grid][encoding]") {
    pride::Rng rng(556);
    int cases = 0, illegal = 0;
    for (const Instance& in : random_instances(2026, 60, 3)) {
        const GridProblem<CellsObjective> problem(in.map, in.start, in.goal, {}, in.corner_cutting);
        LineEncoding<PenaltyConnector> line(problem);
        check_penalty(problem, line, random_genotypes(rng, line.lower(problem), line.upper(problem), 24), illegal);
        FreeEncoding<PenaltyConnector> free(problem, 1 + below(rng, 6));
        check_penalty(problem, free, random_genotypes(rng, free.lower(problem), free.upper(problem), 24), illegal);
        ++cases;
    }
    CHECK(cases >= 150);
    CHECK(illegal > 100);
}

TEST_CASE("the penalty decoder counts no violation on a part of the chain that loop cutting removed",
          "[grid][encoding]") {
    // 12 x 4, one blocked cell (8,1). Start (0,0), goal (0,3): `line` has genes for rows 1 and 2.
    // Waypoints (10,1) and (0,2): the line (0,0) -> (10,1) runs along row 0 to x = 4 and along
    // row 1 from x = 5 to 10, through the blocked (8,1); the line (10,1) -> (0,2) comes back along
    // row 1 (x = 9 .. 6, through (8,1) again) and drops to row 2 at x = 5. Cutting the loops
    // leaves ... (5,1) (6,1) (5,2) ...: the decoded chain never enters (8,1) and is legal, so it
    // must score its plain objective, not objective + 2 M.
    auto map = std::make_shared<const GridMap>(map_of({
        "............",
        "........@...",
        "............",
        "............",
    }));
    const GridProblem<LengthObjective> problem(map, {0, 0}, {0, 3});
    LineEncoding<PenaltyConnector> line(problem);
    const std::vector<double> genotype{10.0, 0.0};
    const DecodedPath& d = line.decode(problem, genotype);
    REQUIRE(path_violation(*map, d.path, {0, 0}, {0, 3}).empty());
    CHECK(d.violations == 0);
    CHECK(problem.evaluate(d) < problem.penalty());
    CHECK(problem.evaluate(d) == metrics(d.path).length);
}

TEST_CASE("Encoded grid problems are box problems whose starting points fill the box", "[grid][encoding]") {
    using LineProblem = pride::Encoded<GridProblem<CellsObjective>, LineEncoding<>>;
    using FreeProblem = pride::Encoded<GridProblem<CellsObjective>, FreeEncoding<>>;
    static_assert(pride::BoxProblem<LineProblem>);
    static_assert(pride::SuggestsStartingPoints<LineProblem>);
    static_assert(pride::BoxProblem<FreeProblem>);
    static_assert(pride::SuggestsStartingPoints<FreeProblem>);
    static_assert(pride::BoxProblem<pride::Encoded<GridProblem<HswoaObjective>, LineEncoding<PenaltyConnector>>>);

    pride::Rng rng(8);
    const auto check = [&rng](auto& encoded, const auto& problem) {
        const std::size_t dim = encoded.dimension();
        const auto lower = encoded.lower(), upper = encoded.upper();
        REQUIRE(lower.size() == dim);
        REQUIRE(upper.size() == dim);
        pride::Matrix points =
            pride::Matrix::Constant(static_cast<Eigen::Index>(dim), 12, std::numeric_limits<double>::quiet_NaN());
        encoded.starting_points(rng, points);
        for (Eigen::Index j = 0; j < points.cols(); ++j) {
            for (std::size_t i = 0; i < dim; ++i) {
                const double v = points(static_cast<Eigen::Index>(i), j);
                CHECK(v >= lower[i]);  // false for NaN: every gene is filled
                CHECK(v <= upper[i]);
            }
            // A suggested genotype decodes (repair) to a legal path: a finite value below M.
            const double value = encoded.evaluate(pride::column(points, j));
            CHECK(std::isfinite(value));
            CHECK(value < problem.penalty());
        }
    };
    for (const Instance& in : random_instances(77, 20, 2)) {
        const GridProblem<CellsObjective> problem(in.map, in.start, in.goal, {}, in.corner_cutting);
        LineProblem lp(problem, LineEncoding<>(problem));
        check(lp, problem);
        FreeProblem fp(problem, FreeEncoding<>(problem, 1 + below(rng, 4)));
        check(fp, problem);
    }
}

// ---------------------------------------------------------------------------------------------
// Input errors

TEST_CASE("GridProblem rejects start and goal outside, blocked or unreachable, naming the field", "[grid][errors]") {
    auto map = std::make_shared<const GridMap>(map_of({
        "..@..",
        "..@..",
        "..@.@",
    }));
    const auto make = [&](Cell s, Cell g) { return [=] { GridProblem<LengthObjective> p(map, s, g); }; };
    CHECK_THAT(input_error_message(make({-1, 0}, {1, 1})), Contains("start:") && Contains("outside"));
    CHECK_THAT(input_error_message(make({0, 3}, {1, 1})), Contains("start:") && Contains("outside"));
    CHECK_THAT(input_error_message(make({0, 0}, {5, 0})), Contains("goal:") && Contains("outside"));
    CHECK_THAT(input_error_message(make({0, 0}, {1, -2})), Contains("goal:") && Contains("outside"));
    CHECK_THAT(input_error_message(make({2, 0}, {1, 1})), Contains("start:") && Contains("blocked"));
    CHECK_THAT(input_error_message(make({0, 0}, {4, 2})), Contains("goal:") && Contains("blocked"));
    CHECK_THAT(input_error_message(make({0, 0}, {4, 0})), Contains("goal:") && Contains("cannot be reached"));
    CHECK(input_error_message(make({0, 0}, {1, 2})) == "<no InputError thrown>");
    // Column 2 is a full wall: no pair across it is connected, even with corner cutting.
    const auto cutting = [&](Cell s, Cell g) { return [=] { GridProblem<LengthObjective> p(map, s, g, {}, true); }; };
    CHECK_THAT(input_error_message(cutting({1, 2}, {3, 2})), Contains("goal:") && Contains("cannot be reached"));
}

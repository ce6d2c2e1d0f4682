// Tests of the clearance cost (problems/grid/clearance.hpp) and of clearance as the fourth criterion
// of the exact Pareto fronts (problems/grid/pareto.hpp).
//
// The references are written here, apart from the library: distances by brute force over every
// blocked cell, the band rule in floating point from its formula, and a depth-first enumeration of
// every simple cell path with its own move rules and metrics (angles from the step vectors, W(theta)
// from the angle in degrees, lengths as long doubles), whose non-dominated projections are compared
// with the library's front for each of the 15 subsets of {length, turns, angle_penalty, clearance}.
// The enumeration prunes a partial path only when an already complete path is no worse in all four
// metrics (each only grows as a path grows), which loses no point of any subset's front.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <queue>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "cli_runner.hpp"
#include "json_reader.hpp"
#include "problems/grid/clearance.hpp"
#include "problems/grid/map_io.hpp"
#include "problems/grid/pareto.hpp"
#include "problems/grid/planners/astar.hpp"
#include "tests/grid_support.hpp"
#include "tests/test_support.hpp"

namespace {

using pride::test::angle_between;
using pride::test::w_of_degrees;

using namespace pride;
using grid::Cell;
using grid::ClearanceParams;
using grid::Criteria;
using grid::GridMap;
using grid::MapClearance;
using grid::Path;

// ---------------------------------------------------------------------------------------------
// References

/// The squared distance from c to the nearest blocked cell, over all of them; -1 when none.
long long brute_d2(const GridMap& m, Cell c) {
    long long best = -1;
    for (int y = 0; y < m.height(); ++y)
        for (int x = 0; x < m.width(); ++x)
            if (!m.free({x, y})) {
                const long long d2 = 1LL * (x - c.x) * (x - c.x) + 1LL * (y - c.y) * (y - c.y);
                if (best < 0 || d2 < best) best = d2;
            }
    return best;
}

/// The band rule as written in docs/grid.md, in floating point: max(0, B - floor((d - 1) / w)).
int formula_cost(long long d2, const ClearanceParams& p) {
    if (d2 < 0) return 0;  // no obstacle
    const double d = std::sqrt(static_cast<double>(d2));
    return std::max(0, p.bands - static_cast<int>(std::floor((d - 1.0) / p.band_width)));
}

/// Every cell's cost from the two references above.
std::vector<int> brute_costs(const GridMap& m, const ClearanceParams& p) {
    std::vector<int> out;
    for (int y = 0; y < m.height(); ++y)
        for (int x = 0; x < m.width(); ++x) out.push_back(formula_cost(brute_d2(m, {x, y}), p));
    return out;
}

GridMap random_map(Rng& rng, int w, int h, int percent) {
    std::vector<std::uint8_t> blocked(static_cast<std::size_t>(w * h));
    for (auto& b : blocked) b = test::below(rng, 100) < percent ? 1 : 0;
    return GridMap(w, h, std::move(blocked), "random");
}

Cell random_free(Rng& rng, const GridMap& m) {
    for (;;) {
        const Cell c{test::below(rng, m.width()), test::below(rng, m.height())};
        if (m.free(c)) return c;
    }
}

bool any_free(const GridMap& m) {
    for (std::size_t i = 0; i < m.size(); ++i)
        if (m.free_index(i)) return true;
    return false;
}

struct Cost {
    int straight = 0, diagonal = 0, turns = 0, angle = 0, clearance = 0;
    long double length() const { return straight + diagonal * std::sqrt(2.0L); }
};

bool no_worse(const Cost& a, const Cost& b, const Criteria& c) {
    if (c.length && a.length() > b.length() + 1e-9L) return false;
    if (c.turns && a.turns > b.turns) return false;
    if (c.angle_penalty && a.angle > b.angle) return false;
    if (c.clearance && a.clearance > b.clearance) return false;
    return true;
}

const Criteria kAll{true, true, true, true};

Criteria criteria_of(int mask) {
    return Criteria{(mask & 1) != 0, (mask & 2) != 0, (mask & 4) != 0, (mask & 8) != 0};
}

/// A point projected onto the chosen criteria (unchosen ones 0; lengths in millionths, rounded).
using Key = std::tuple<long long, int, int, int>;
Key key_of(const Cost& x, const Criteria& c) {
    return {c.length ? std::llround(x.length() * 1e6L) : 0, c.turns ? x.turns : 0, c.angle_penalty ? x.angle : 0,
            c.clearance ? x.clearance : 0};
}

std::set<Key> non_dominated(const std::vector<Cost>& costs, const Criteria& c) {
    std::set<Key> out;
    for (const Cost& x : costs) {
        bool dominated = false;
        for (const Cost& y : costs) dominated = dominated || (no_worse(y, x, c) && !no_worse(x, y, c));
        if (!dominated) out.insert(key_of(x, c));
    }
    return out;
}

/// Every simple path from s to g, by depth-first search, with the cell costs `costs`.
struct Brute {
    const GridMap& map;
    std::vector<int> costs;
    Cell goal;
    bool cutting;
    std::vector<Cost> found;  // complete paths' costs, none no worse than another in all four
    std::vector<char> on;

    bool free(int x, int y) const {
        return x >= 0 && y >= 0 && x < map.width() && y < map.height() && map.free({x, y});
    }
    bool legal(Cell a, int dx, int dy) const {
        if (!free(a.x + dx, a.y + dy)) return false;
        if (dx != 0 && dy != 0 && !cutting) return free(a.x + dx, a.y) && free(a.x, a.y + dy);
        return true;
    }
    int cost_at(Cell c) const { return costs[static_cast<std::size_t>(c.y * map.width() + c.x)]; }
    bool dominated(const Cost& x) const {
        for (const Cost& f : found)
            if (no_worse(f, x, kAll)) return true;
        return false;
    }
    void dfs(Cell c, const Cost& cost, int pdx, int pdy) {
        if (dominated(cost)) return;
        if (c == goal) {
            std::erase_if(found, [&](const Cost& f) { return no_worse(cost, f, kAll); });
            found.push_back(cost);
            return;
        }
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                if ((dx == 0 && dy == 0) || !legal(c, dx, dy)) continue;
                const Cell n{c.x + dx, c.y + dy};
                const auto i = static_cast<std::size_t>(n.y * map.width() + n.x);
                if (on[i]) continue;
                Cost next = cost;
                (dx != 0 && dy != 0 ? next.diagonal : next.straight) += 1;
                if (pdx != 0 || pdy != 0) {
                    const double theta = angle_between(pdx, pdy, dx, dy);
                    if (theta > 1e-9) ++next.turns;
                    next.angle += w_of_degrees(theta);
                }
                next.clearance += cost_at(n);
                on[i] = 1;
                dfs(n, next, dx, dy);
                on[i] = 0;
            }
    }
    void run(Cell s) {
        on.assign(map.size(), 0);
        on[static_cast<std::size_t>(s.y * map.width() + s.x)] = 1;
        Cost start;
        start.clearance = cost_at(s);
        dfs(s, start, 0, 0);
    }
};

/// A path's metrics as the brute force measures them; clearance from `costs`.
Cost cost_of(const Path& p, const GridMap& map, const std::vector<int>& costs) {
    Cost c;
    for (std::size_t i = 0; i < p.size(); ++i) {
        c.clearance += costs[static_cast<std::size_t>(p[i].y * map.width() + p[i].x)];
        if (i == 0) continue;
        const int dx = p[i].x - p[i - 1].x, dy = p[i].y - p[i - 1].y;
        (dx != 0 && dy != 0 ? c.diagonal : c.straight) += 1;
        if (i >= 2) {
            const double theta = angle_between(p[i - 1].x - p[i - 2].x, p[i - 1].y - p[i - 2].y, dx, dy);
            if (theta > 1e-9) ++c.turns;
            c.angle += w_of_degrees(theta);
        }
    }
    return c;
}

bool legal_path(const GridMap& map, const Path& p, Cell s, Cell g, bool cutting) {
    if (p.empty() || !(p.front() == s) || !(p.back() == g)) return false;
    Brute b{map, {}, g, cutting, {}, {}};
    if (!b.free(s.x, s.y)) return false;
    for (std::size_t i = 1; i < p.size(); ++i) {
        const int dx = p[i].x - p[i - 1].x, dy = p[i].y - p[i - 1].y;
        if (std::max(std::abs(dx), std::abs(dy)) != 1 || !b.legal(p[i - 1], dx, dy)) return false;
    }
    return true;
}

/// The library's front, checked point by point (legal, its metrics as measured here, sorted by
/// length, none no worse than another in the criteria), as keys.
std::set<Key> checked_front(const GridMap& map, const MapClearance& mc, const std::vector<int>& costs, Cell s, Cell g,
                            const Criteria& c, bool cutting, bool heuristic) {
    grid::ParetoOptions o;
    o.corner_cutting = cutting;
    o.use_heuristic = heuristic;
    const auto front = grid::pareto_front(map, mc, s, g, c, o);
    std::set<Key> keys;
    std::vector<Cost> seen;
    for (std::size_t i = 0; i < front.size(); ++i) {
        const auto& p = front[i];
        CHECK(legal_path(map, p.path, s, g, cutting));
        const Cost m = cost_of(p.path, map, costs);
        CHECK(m.straight == p.steps.straight);
        CHECK(m.diagonal == p.steps.diagonal);
        CHECK(m.turns == p.turns);
        CHECK(m.angle == p.angle_penalty);
        CHECK(m.clearance == p.clearance);
        CHECK(grid::clearance_cost(mc, p.path) == p.clearance);
        if (i > 0) CHECK(front[i - 1].length <= p.length + 1e-9);
        for (const Cost& other : seen) CHECK_FALSE(no_worse(other, m, c));
        seen.push_back(m);
        keys.insert(key_of(m, c));
    }
    return keys;
}

/// The least clearance of a legal path from s to g: Dijkstra over cells, each entered cell adding
/// its cost (the start's counted first); -1 when g cannot be reached.
long long least_clearance(const GridMap& map, const std::vector<int>& costs, Cell s, Cell g) {
    const Brute rules{map, {}, g, false, {}, {}};
    std::vector<long long> best(map.size(), -1);
    using Item = std::pair<long long, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
    const auto at = [&](Cell c) { return c.y * map.width() + c.x; };
    open.push({costs[static_cast<std::size_t>(at(s))], at(s)});
    while (!open.empty()) {
        const auto [d, i] = open.top();
        open.pop();
        if (best[static_cast<std::size_t>(i)] >= 0) continue;
        best[static_cast<std::size_t>(i)] = d;
        const Cell c{i % map.width(), i / map.width()};
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx)
                if ((dx != 0 || dy != 0) && rules.legal(c, dx, dy)) {
                    const Cell n{c.x + dx, c.y + dy};
                    if (best[static_cast<std::size_t>(at(n))] < 0)
                        open.push({d + costs[static_cast<std::size_t>(at(n))], at(n)});
                }
    }
    return best[static_cast<std::size_t>(at(g))];
}

std::vector<int> library_costs(const MapClearance& mc, const GridMap& m) {
    std::vector<int> out;
    for (std::size_t i = 0; i < m.size(); ++i) out.push_back(mc.cost(i));
    return out;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// The distance transform and the bands

TEST_CASE("clearance: the distance transform equals brute force over every blocked cell", "[clearance]") {
    Rng rng(20260428);
    int cells = 0;
    for (int trial = 0; trial < 400; ++trial) {
        const int w = 1 + test::below(rng, trial % 4 == 0 ? 40 : 12), h = 1 + test::below(rng, 12);
        const int percent = trial % 10 == 0 ? 0 : (trial % 10 == 1 ? 100 : test::below(rng, 40));
        const GridMap map = random_map(rng, w, h, percent);
        INFO("trial " << trial << "\n" << grid::to_movingai(map));
        const auto d2 = grid::squared_distance_transform(map);
        REQUIRE(d2.size() == map.size());
        for (std::size_t i = 0; i < map.size(); ++i) {
            const long long expected = brute_d2(map, map.cell(i));
            CHECK(d2[i] == (expected < 0 ? grid::kNoObstacle : expected));
            ++cells;
        }
    }
    CHECK(cells > 20000);
}

TEST_CASE("clearance: the transform is exact far from the obstacles of a long map", "[clearance]") {
    // One blocked cell at the left end of a 3000 x 2 map: the squared distances grow to 9e6 and
    // every one is x^2 + dy^2 exactly.
    std::vector<std::uint8_t> blocked(6000, 0);
    blocked[0] = 1;
    const GridMap map(3000, 2, std::move(blocked), "long");
    const auto d2 = grid::squared_distance_transform(map);
    for (int x = 0; x < 3000; ++x) {
        CHECK(d2[map.index({x, 0})] == 1LL * x * x);
        CHECK(d2[map.index({x, 1})] == 1LL * x * x + 1);
    }
}

TEST_CASE("clearance: the band rule in integers equals its formula", "[clearance]") {
    const ClearanceParams b3{3, 1};
    // Touching (d = 1, sqrt 2): 3; 2 <= d < 3: 2; 3 <= d < 4: 1; from 4 on: 0; blocked: B + 1.
    CHECK(grid::clearance_band_cost(1, b3) == 3);
    CHECK(grid::clearance_band_cost(2, b3) == 3);
    CHECK(grid::clearance_band_cost(3, b3) == 3);
    CHECK(grid::clearance_band_cost(4, b3) == 2);
    CHECK(grid::clearance_band_cost(8, b3) == 2);
    CHECK(grid::clearance_band_cost(9, b3) == 1);
    CHECK(grid::clearance_band_cost(15, b3) == 1);
    CHECK(grid::clearance_band_cost(16, b3) == 0);
    CHECK(grid::clearance_band_cost(grid::kNoObstacle, b3) == 0);
    CHECK(grid::clearance_band_cost(0, b3) == 4);
    // Two bands of width 3: d in [1, 4) costs 2, [4, 7) costs 1.
    const ClearanceParams b2w3{2, 3};
    CHECK(grid::clearance_band_cost(15, b2w3) == 2);
    CHECK(grid::clearance_band_cost(16, b2w3) == 1);
    CHECK(grid::clearance_band_cost(48, b2w3) == 1);
    CHECK(grid::clearance_band_cost(49, b2w3) == 0);
    for (const ClearanceParams& p : {b3, b2w3, ClearanceParams{1, 1}, ClearanceParams{63, 1}, ClearanceParams{5, 7},
                                     ClearanceParams{63, 1000000}}) {
        INFO(p.bands << " bands of width " << p.band_width);
        int previous = p.bands;
        for (long long d2 = 1; d2 <= 20000; ++d2) {
            const int c = grid::clearance_band_cost(d2, p);
            CHECK(c == formula_cost(d2, p));
            CHECK(c <= previous);  // never grows with the distance
            previous = c;
        }
    }
}

TEST_CASE("clearance: the worked example of grid.md", "[clearance]") {
    // One blocked cell in the corner; 3 bands of width 1. Costs by hand from d^2 = x^2 + y^2:
    // (1,0), (0,1), (1,1): d^2 1, 1, 2 -> 3; (2,0), (2,1), (2,2): 4, 5, 8 -> 2; (3,0), (3,2): 9, 13
    // -> 1; (3,3): 18, d = 4.24 -> 0 (its Chebyshev distance, 3, would still cost 1).
    const GridMap map = test::map_of({"@.....", "......", "......", "......", "......"});
    const MapClearance mc(map);
    const std::vector<int> expected = {4, 3, 2, 1, 0, 0,  //
                                       3, 3, 2, 1, 0, 0,  //
                                       2, 2, 2, 1, 0, 0,  //
                                       1, 1, 1, 0, 0, 0,  //
                                       0, 0, 0, 0, 0, 0};
    CHECK(library_costs(mc, map) == expected);
    CHECK(library_costs(mc, map) == brute_costs(map, {}));
    // The diagonal path (0,1) (1,2) (2,3) (3,4): 3 + 2 + 1 + 0 = 6, start and goal included.
    CHECK(grid::clearance_cost(mc, Path{{0, 1}, {1, 2}, {2, 3}, {3, 4}}) == 6);
    // Along the top row from (1,0) to (5,0): 3 + 2 + 1 + 0 + 0.
    CHECK(grid::clearance_cost(mc, Path{{1, 0}, {2, 0}, {3, 0}, {4, 0}, {5, 0}}) == 6);
    CHECK(grid::clearance_cost(mc, Path{}) == 0);
    CHECK(grid::clearance_cost(mc, Path{{5, 4}}) == 0);
    // Outside the map and on the blocked cell: B + 1 each (illegal chains are scored too).
    CHECK(grid::clearance_cost(mc, Path{{-1, 0}, {0, 0}, {6, 4}}) == 12);
    // Four bands of width 2: d in [1, 3) costs 4, [3, 5) costs 3.
    const MapClearance wide(map, {4, 2});
    CHECK(wide.cost(Cell{2, 2}) == 4);  // d = 2.83
    CHECK(wide.cost(Cell{3, 0}) == 3);  // d = 3
    CHECK(wide.cost(Cell{5, 4}) == 2);  // d = 6.4
    CHECK(library_costs(wide, map) == brute_costs(map, {4, 2}));
}

TEST_CASE("clearance: costs equal the references on random maps, cells outside the map are no obstacle",
          "[clearance]") {
    Rng rng(77);
    for (int trial = 0; trial < 200; ++trial) {
        const GridMap map = random_map(rng, 1 + test::below(rng, 30), 1 + test::below(rng, 30), test::below(rng, 20));
        const ClearanceParams p{1 + test::below(rng, 6), 1 + test::below(rng, 3)};
        INFO("trial " << trial << ", " << p.bands << " bands of width " << p.band_width);
        CHECK(library_costs(MapClearance(map, p), map) == brute_costs(map, p));
    }
    // A map without blocked cells costs nothing anywhere, its border included.
    const GridMap open = test::map_of({"....", "....", "...."});
    CHECK(library_costs(MapClearance(open), open) == std::vector<int>(12, 0));
}

TEST_CASE("clearance: bad parameters and a clearance of another map are one-line input errors", "[clearance]") {
    const GridMap map = test::map_of({"...", ".@.", "..."});
    const auto message = [&](ClearanceParams p) { return test::input_error_message([&] { MapClearance(map, p); }); };
    CHECK(message({0, 1}) == "clearance: bands must be a whole number in [1, 63], got 0");
    CHECK(message({64, 1}) == "clearance: bands must be a whole number in [1, 63], got 64");
    CHECK(message({3, 0}) == "clearance: band_width must be a whole number in [1, 1000000], got 0");
    CHECK(message({3, 1000001}) == "clearance: band_width must be a whole number in [1, 1000000], got 1000001");
    CHECK(test::input_error_message([] {
              grid::clearance_band_cost(4, {-1, 1});
          }) == "clearance: bands must be a whole number in [1, 63], got -1");
    CHECK(test::input_error_message([] { grid::clearance_band_cost(-3, {}); }) ==
          "clearance: a squared distance must be >= 0, got -3");
    const GridMap other = test::map_of({"....", "....", "...."});
    CHECK(test::input_error_message([&] {
              grid::pareto_front(map, MapClearance(other), {0, 0}, {2, 2}, kAll);
          }) == "clearance: computed for a 4x3 map, not for the 3x3 map hand");
}

// ---------------------------------------------------------------------------------------------
// The fourth criterion

TEST_CASE("clearance: criteria lists name clearance", "[clearance][pareto]") {
    CHECK(grid::parse_criteria("clearance,length") == Criteria{true, false, false, true});
    CHECK(grid::parse_criteria("turns,clearance") == Criteria{false, true, false, true});
    CHECK(grid::parse_criteria("clearance,angle,turns,length") == kAll);
    CHECK(grid::parse_criteria("length,turns") == Criteria{true, true, false, false});
    CHECK(grid::criteria_names(kAll) == std::vector<std::string>{"length", "turns", "angle_penalty", "clearance"});
    CHECK(grid::criteria_names(Criteria{false, false, true, true}) ==
          std::vector<std::string>{"angle_penalty", "clearance"});
    CHECK(kAll.count() == 4);
    CHECK(test::input_error_message([] { grid::parse_criteria("length,speed"); }) ==
          "objectives: unknown objective 'speed' (expected length, turns, angle or clearance)");
    CHECK(test::input_error_message([] { grid::parse_criteria("clearance,length,clearance"); }) ==
          "objectives: 'clearance' is given twice");
    CHECK(test::input_error_message([] {
              grid::parse_criteria("clearance");
          }).find("objectives: a Pareto front needs two to four objectives, got only 'clearance'") == 0);
    CHECK(test::input_error_message([] {
              grid::pareto_front(test::map_of({"..."}), {0, 0}, {2, 0}, Criteria{false, false, false, false});
          }) == "objectives: at least one of length, turns, angle and clearance is needed");
}

TEST_CASE("clearance: a worked front of length and clearance", "[clearance][pareto]") {
    // One obstacle between start and goal. Costs (3 bands of width 1), rows top to bottom:
    //   1 2 2 2 2 2 1
    //   1 2 3 3 3 2 1
    //   1 2 3 @ 3 2 1
    //   1 2 3 3 3 2 1
    //   1 2 2 2 2 2 1
    // The shortest way round passes (3,1): 4 + 2 sqrt 2 long, as (0,2) (1,2) (2,1) (3,1) (4,1) (5,2)
    // (6,2), and every such path enters three cells of cost 3: 1+2+3+3+3+2+1 = 15. A path crosses
    // columns 1 to 5, each costing at least 2, so its clearance is at least 12; (0,2) (1,1) (2,0)
    // (3,0) (4,0) (5,1) (6,2) has 12 and is 2 + 4 sqrt 2 long, the least length round (3,2) by row
    // 0 (or 4). A path through (3,1) (or (3,3)) stays under 15 only by entering (2,0) or (4,0), and
    // from (0,2) by (2,0) and (3,1) to (6,2) is at least 2 sqrt 2 + sqrt 2 + (2 + sqrt 2) long: no
    // shorter than the 12. So the front has two points.
    const GridMap map = test::map_of({".......", ".......", "...@...", ".......", "......."});
    const auto front = grid::pareto_front(map, {0, 2}, {6, 2}, Criteria{true, false, false, true});
    REQUIRE(front.size() == 2);
    CHECK(front[0].steps == grid::StepCounts{4, 2});
    CHECK(front[0].clearance == 15);
    CHECK(front[1].steps == grid::StepCounts{2, 4});
    CHECK(front[1].clearance == 12);
    const Path top{{0, 2}, {1, 1}, {2, 0}, {3, 0}, {4, 0}, {5, 1}, {6, 2}};
    const Path bottom{{0, 2}, {1, 3}, {2, 4}, {3, 4}, {4, 4}, {5, 3}, {6, 2}};
    CHECK((front[1].path == top || front[1].path == bottom));
    // Without clearance among the criteria the front is the shortest path alone, which still
    // reports its clearance.
    const auto length_only = grid::pareto_front(map, {0, 2}, {6, 2}, Criteria{true, false, false, false});
    REQUIRE(length_only.size() == 1);
    CHECK(length_only[0].clearance == grid::clearance_cost(MapClearance(map), length_only[0].path));
    const auto same = grid::pareto_front(map, {1, 1}, {1, 1}, kAll);
    REQUIRE(same.size() == 1);
    CHECK(same[0].clearance == 2);
}

TEST_CASE("clearance: on tiny random maps every front with clearance equals brute force's",
          "[clearance][pareto][brute]") {
    Rng rng(20260429);
    int maps = 0, points = 0, with_clearance = 0;
    for (int trial = 0; trial < 600; ++trial) {
        const int w = 4 + test::below(rng, 2), h = 4 + test::below(rng, 2);
        const GridMap map = random_map(rng, w, h, 5 + test::below(rng, 26));
        if (!any_free(map)) continue;
        const Cell s = random_free(rng, map), g = random_free(rng, map);
        const bool cutting = trial % 5 == 4;
        const ClearanceParams p =
            trial % 3 == 0 ? ClearanceParams{} : ClearanceParams{1 + test::below(rng, 4), 1 + test::below(rng, 2)};
        INFO("trial " << trial << " " << w << "x" << h << " s " << s.x << "," << s.y << " g " << g.x << "," << g.y
                      << " cutting " << cutting << " bands " << p.bands << " width " << p.band_width << "\n"
                      << grid::to_movingai(map));
        const std::vector<int> costs = brute_costs(map, p);
        const MapClearance mc(map, p);
        REQUIRE(library_costs(mc, map) == costs);
        Brute b{map, costs, g, cutting, {}, {}};
        b.run(s);
        for (int mask = 1; mask < 16; ++mask) {
            const Criteria c = criteria_of(mask);
            INFO("criteria " << mask);
            const std::set<Key> expected = non_dominated(b.found, c);
            const std::set<Key> got = checked_front(map, mc, costs, s, g, c, cutting, true);
            CHECK(got == expected);
            if (trial % 4 == 0) CHECK(checked_front(map, mc, costs, s, g, c, cutting, false) == expected);
            points += static_cast<int>(got.size());
            if (c.clearance && got.size() > 1) ++with_clearance;
        }
        ++maps;
    }
    CHECK(maps >= 590);
    CHECK(points > 3000);
    CHECK(with_clearance > 250);  // fronts where clearance trades against something
}

TEST_CASE("clearance: on the bundled maps the fronts' ends are A*'s length and Dijkstra's least clearance",
          "[clearance][pareto]") {
    for (const auto& instance : test::bundled_instances(std::string(PRIDE_SOURCE_DIR) + "/examples/maps")) {
        const GridMap& map = *instance.map;
        INFO(map.name() << " " << instance.start.x << "," << instance.start.y);
        const MapClearance mc(map);
        const std::vector<int> costs = library_costs(mc, map);
        const long long least = least_clearance(map, costs, instance.start, instance.goal);
        REQUIRE(least >= 0);
        grid::AStar astar;
        const double shortest = astar.search(map, instance.start, instance.goal);
        const auto only =
            grid::pareto_front(map, mc, instance.start, instance.goal, Criteria{false, false, false, true});
        REQUIRE(only.size() == 1);
        CHECK(only[0].clearance == least);
        for (const int mask : {9, 11, 13, 15}) {  // length, clearance and any of turns, angle
            const Criteria c = criteria_of(mask);
            const auto front = grid::pareto_front(map, mc, instance.start, instance.goal, c);
            REQUIRE_FALSE(front.empty());
            CHECK(std::abs(front.front().length - shortest) < 1e-9);
            int lowest = std::numeric_limits<int>::max();
            for (const auto& p : front) {
                CHECK(grid::path_violation(map, p.path, instance.start, instance.goal).empty());
                CHECK(grid::clearance_cost(mc, p.path) == p.clearance);
                lowest = std::min(lowest, p.clearance);
            }
            CHECK(lowest == least);
        }
        // The default parameters' overload computes the same clearance.
        const auto a = grid::pareto_front(map, instance.start, instance.goal, Criteria{true, true, false, true});
        const auto b = grid::pareto_front(map, mc, instance.start, instance.goal, Criteria{true, true, false, true});
        REQUIRE(a.size() == b.size());
        for (std::size_t i = 0; i < a.size(); ++i) {
            CHECK(a[i].path == b[i].path);
            CHECK(a[i].clearance == b[i].clearance);
        }
    }
}

// ---------------------------------------------------------------------------------------------
// pride pareto

TEST_CASE("clearance: pride pareto prints clearance when it is among the objectives", "[clearance][pareto][cli]") {
    const std::string map = std::string(PRIDE_SOURCE_DIR) + "/examples/maps/zhang2025-40x40.map";
    const GridMap m = grid::read_map(map);
    const auto front = grid::pareto_front(m, {1, 38}, {38, 1}, Criteria{true, false, false, true});
    REQUIRE(front.size() > 1);
    const std::string args = "pareto --map '" + map + "' --start 1,38 --goal 38,1 --objectives clearance,length";
    const auto text = test::run_pride(args);
    INFO(text.err);
    REQUIRE(text.status == 0);
    const auto lines = test::lines_of(text.out);
    REQUIRE(lines.size() == front.size() + 1);
    CHECK(lines[0] == "length turns angle_penalty clearance");
    CHECK(lines[1].substr(lines[1].rfind(' ') + 1) == std::to_string(front[0].clearance));
    const auto json_run = test::run_pride(args + " --json");
    REQUIRE(json_run.status == 0);
    const auto j = test::parse_json(json_run.out);
    REQUIRE(j.at("objectives").items.size() == 2);
    CHECK(j.at("objectives").items[0].text == "clearance");
    REQUIRE(j.at("front").items.size() == front.size());
    for (std::size_t i = 0; i < front.size(); ++i) {
        const auto& p = j.at("front").items[i];
        CHECK(p.keys() == std::vector<std::string>{"length", "turns", "angle_penalty", "clearance", "path"});
        CHECK(p.at("length").number == front[i].length);
        CHECK(p.at("clearance").number == front[i].clearance);
    }
    // Without clearance among the objectives, the output is what it was.
    const auto plain = test::run_pride("pareto --map '" + map + "' --start 1,38 --goal 38,1 --objectives length,turns");
    REQUIRE(plain.status == 0);
    CHECK(test::lines_of(plain.out).at(0) == "length turns angle_penalty");
    test::check_input_error(
        test::run_pride("pareto --map '" + map + "' --start 1,38 --goal 38,1 --objectives clearance"),
        {"--objectives", "two to four"});
}

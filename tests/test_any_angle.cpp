// Any-angle planning (problems/grid/planners/any_angle.hpp, theta_star.hpp): the exact segment test on hand
// cases, the exact oracle on hand-computed geometry and against a brute-force visibility graph
// over every grid point and cell centre, and Theta* and Lazy Theta* between the oracle and A*.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <vector>

#include "framework/random.hpp"
#include "grid_support.hpp"
#include "problems/grid/map_io.hpp"
#include "problems/grid/planners/any_angle.hpp"
#include "problems/grid/planners/astar.hpp"
#include "problems/grid/planners/theta_star.hpp"

using namespace pride;
using namespace pride::grid;

namespace {

/// Dijkstra over the complete visibility graph of every grid point a path may pass (not inside the
/// obstacles, not a squeeze point) and every free cell's centre: no corner argument, no pruning.
double brute_force(const GridMap& map, Cell s, Cell g) {
    std::vector<HalfPoint> nodes{centre_of(s), centre_of(g)};
    for (int j = 0; j <= map.height(); ++j)
        for (int i = 0; i <= map.width(); ++i) {
            const int blocked =
                !map.free({i - 1, j - 1}) + !map.free({i, j - 1}) + !map.free({i - 1, j}) + !map.free({i, j});
            if (blocked < 4 && !is_squeeze_point(map, i, j)) nodes.push_back({2 * i, 2 * j});
        }
    for (int y = 0; y < map.height(); ++y)
        for (int x = 0; x < map.width(); ++x)
            if (map.free({x, y})) nodes.push_back(centre_of({x, y}));
    const std::size_t n = nodes.size();
    std::vector<double> dist(n, std::numeric_limits<double>::infinity());
    std::vector<char> done(n, 0);
    dist[0] = 0.0;
    for (;;) {
        std::size_t u = n;
        for (std::size_t v = 0; v < n; ++v)
            if (!done[v] && std::isfinite(dist[v]) && (u == n || dist[v] < dist[u])) u = v;
        if (u == n) return -1.0;
        if (u == 1) return dist[1];
        done[u] = 1;
        for (std::size_t v = 0; v < n; ++v)
            if (!done[v] && dist[u] + distance(nodes[u], nodes[v]) < dist[v] &&
                segment_is_free(map, nodes[u], nodes[v]))
                dist[v] = dist[u] + distance(nodes[u], nodes[v]);
    }
}

GridMap random_map(Rng& rng, int w, int h, double density) {
    std::vector<std::uint8_t> blocked(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
    for (auto& b : blocked) b = rng.uniform() < density ? 1 : 0;
    return GridMap(w, h, std::move(blocked), "random");
}

/// Every segment of the polyline free, and its length the one returned.
void check_polyline(const GridMap& map, const std::vector<Cell>& cells, Cell s, Cell g, double length) {
    REQUIRE(!cells.empty());
    CHECK(cells.front() == s);
    CHECK(cells.back() == g);
    for (std::size_t i = 1; i < cells.size(); ++i)
        CHECK(segment_is_free(map, centre_of(cells[i - 1]), centre_of(cells[i])));
    CHECK(polyline_length(centres(cells)) == Approx(length).epsilon(1e-12).margin(1e-12));
}

}  // namespace

TEST_CASE("any-angle: the segment test touches obstacles but enters none and squeezes through no corner") {
    const GridMap map = test::map_of({
        "....",
        ".@..",
        "..@.",
        ".@@.",
    });
    // Through the corner of one blocked square: allowed (cell (0,1) to (1,0) touches (1,1) at (1,1)).
    CHECK(segment_is_free(map, Point{0.5, 1.5}, Point{1.5, 0.5}));
    // Through the interior of (1,1).
    CHECK_FALSE(segment_is_free(map, Point{0.5, 1.5}, Point{2.5, 1.5}));
    // Through the squeeze point (2,2) between (1,1) and (2,2): forbidden, as for a grid step.
    CHECK_FALSE(segment_is_free(map, Point{1.5, 2.5}, Point{2.5, 1.5}));
    CHECK_FALSE(segment_is_free(map, Point{1, 2}, Point{3, 2}));  // along a line through that point
    // Along an edge with a free cell on one side, and along the edge between (1,3) and (2,3)'s tops.
    CHECK(segment_is_free(map, Point{0, 0}, Point{4, 0}));
    CHECK(segment_is_free(map, Point{1, 3}, Point{1, 4}));                 // between (0,3) free and (1,3) blocked
    CHECK_FALSE(segment_is_free(map, Point{2, 3}, Point{2, 4}));           // between (1,3) and (2,3), both blocked
    CHECK(segment_is_free(map, Point{4, 0}, Point{4, 4}));                 // the map's right border
    CHECK_FALSE(segment_is_free(map, Point{0.5, 0.5}, Point{-0.5, 0.5}));  // leaves the map
    // Any points, not only the half lattice (segment.cpp; tests/test_ompl_planner.cpp tests more).
    CHECK(segment_is_free(map, Point{0.25, 0.5}, Point{1.5, 0.5}));
    CHECK_FALSE(segment_is_free(map, Point{0.25, 1.5}, Point{1.5, 1.25}));
    // Every legal grid step is a free segment between centres (no corner cutting).
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x)
            for (int d = 0; d < 8; ++d)
                if (map.free({x, y}) && map.legal_step({x, y}, d))
                    CHECK(segment_is_free(map, centre_of({x, y}), centre_of({x + kDx[d], y + kDy[d]})));
}

TEST_CASE("any-angle: hand-computed lengths of the oracle, Theta* and Lazy Theta*") {
    const GridMap empty(7, 5, std::vector<std::uint8_t>(35, 0), "empty");
    AnyAngleOracle on_empty(empty);
    CHECK(on_empty.corners().empty());
    std::vector<Point> line;
    CHECK(on_empty.solve({0, 0}, {6, 2}, &line) == Approx(std::sqrt(40.0)).epsilon(1e-15));
    CHECK(line == std::vector<Point>{{0.5, 0.5}, {6.5, 2.5}});
    CHECK(on_empty.solve({3, 3}, {3, 3}, &line) == 0.0);
    CHECK(line.size() == 1);

    // One blocked square in the middle: round its corners (1,1) and (2,1), 1 + 2 sqrt(0.5).
    const GridMap one = test::map_of({"...", ".@.", "..."});
    AnyAngleOracle oracle(one);
    CHECK(oracle.corners().size() == 4);
    std::vector<Point> poly;
    CHECK(oracle.solve({0, 1}, {2, 1}, &poly) == Approx(1.0 + kSqrt2).epsilon(1e-14));
    CHECK(poly.size() == 4);
    CHECK(polyline_length(poly) == Approx(1.0 + kSqrt2).epsilon(1e-14));
    // Theta* from centre to centre: (0,1) -> (1,0) touches the corner, then (1,0) -> (2,1): 2 sqrt(2);
    // A* may not cut that corner: 4.
    ThetaStar theta, lazy(true);
    std::vector<Cell> cells;
    CHECK(theta.search(one, {0, 1}, {2, 1}, &cells) == Approx(2.0 * kSqrt2).epsilon(1e-14));
    CHECK(cells.size() == 3);
    CHECK(lazy.search(one, {0, 1}, {2, 1}, &cells) == Approx(2.0 * kSqrt2).epsilon(1e-14));
    AStar astar;
    CHECK(astar.search(one, {0, 1}, {2, 1}) == 4.0);

    // Two diagonally touching blocked cells close the way: no path for any of them.
    const GridMap squeeze = test::map_of({".@", "@."});
    AnyAngleOracle closed(squeeze);
    CHECK(closed.solve({0, 0}, {1, 1}) == -1.0);
    CHECK(theta.search(squeeze, {0, 0}, {1, 1}) == -1.0);
    CHECK(lazy.search(squeeze, {0, 0}, {1, 1}) == -1.0);
    CHECK(astar.search(squeeze, {0, 0}, {1, 1}) == -1.0);

    // Bad input.
    CHECK_THROWS_AS(oracle.solve({1, 1}, {0, 0}), InputError);
    CHECK_THROWS_AS(oracle.solve({0, 0}, {3, 0}), InputError);
    CHECK_THROWS_AS(theta.search(one, {1, 1}, {0, 0}), InputError);
    CHECK_THROWS_AS(lazy.search(one, {0, 0}, {0, 9}), InputError);
}

TEST_CASE("any-angle: the oracle equals a brute-force visibility graph on small random maps") {
    Rng rng(29);
    int compared = 0, unreachable = 0;
    for (int m = 0; m < 150; ++m) {
        const GridMap map = random_map(rng, 1 + test::below(rng, 9), 1 + test::below(rng, 9), 0.45 * rng.uniform());
        AnyAngleOracle oracle(map);
        for (int q = 0; q < 4; ++q) {
            const Cell s{test::below(rng, map.width()), test::below(rng, map.height())};
            const Cell g{test::below(rng, map.width()), test::below(rng, map.height())};
            if (!map.free(s) || !map.free(g)) continue;
            std::vector<Point> poly;
            const double exact = oracle.solve(s, g, &poly);
            const double brute = brute_force(map, s, g);
            INFO("map " << m << " (" << s.x << "," << s.y << ") -> (" << g.x << "," << g.y << ")\n"
                        << to_movingai(map));
            if (brute < 0.0) {
                CHECK(exact == -1.0);
                ++unreachable;
                continue;
            }
            CHECK(exact == Approx(brute).epsilon(1e-12).margin(1e-12));
            CHECK(polyline_length(poly) == Approx(exact).epsilon(1e-12).margin(1e-12));
            for (std::size_t i = 1; i < poly.size(); ++i) CHECK(segment_is_free(map, poly[i - 1], poly[i]));
            ++compared;
        }
    }
    CHECK(compared > 200);
    CHECK(unreachable > 0);
}

TEST_CASE("any-angle: oracle <= Theta* and Lazy Theta* <= A* on random maps, fewer line-of-sight tests lazily") {
    Rng rng(2029);
    ThetaStar theta, lazy(true);
    AStar astar;
    int queries = 0;
    for (int m = 0; m < 60; ++m) {
        const GridMap map = random_map(rng, 2 + test::below(rng, 40), 2 + test::below(rng, 40), 0.4 * rng.uniform());
        AnyAngleOracle oracle(map);
        for (int q = 0; q < 10; ++q) {
            const Cell s{test::below(rng, map.width()), test::below(rng, map.height())};
            const Cell g{test::below(rng, map.width()), test::below(rng, map.height())};
            if (!map.free(s) || !map.free(g)) continue;
            INFO("map " << m << " (" << s.x << "," << s.y << ") -> (" << g.x << "," << g.y << ")\n"
                        << to_movingai(map));
            const double grid = astar.search(map, s, g), exact = oracle.solve(s, g);
            std::vector<Cell> pt, pl;
            const double t = theta.search(map, s, g, &pt), l = lazy.search(map, s, g, &pl);
            if (grid < 0.0) {
                CHECK(exact == -1.0);
                CHECK(t == -1.0);
                CHECK(l == -1.0);
                continue;
            }
            ++queries;
            CHECK(exact <= t + 1e-9);
            CHECK(t <= grid + 1e-9);
            CHECK(exact <= l + 1e-9);
            CHECK(l <= grid + 1e-9);
            check_polyline(map, pt, s, g, t);
            check_polyline(map, pl, s, g, l);
        }
    }
    CHECK(queries > 300);
    CHECK(lazy.los_checks() < theta.los_checks());
}

TEST_CASE("any-angle: Theta* and Lazy Theta* follow the straight line on empty maps") {
    Rng rng(7);
    const GridMap map(30, 20, std::vector<std::uint8_t>(600, 0), "empty");
    ThetaStar theta, lazy(true);
    for (int q = 0; q < 200; ++q) {
        const Cell s{test::below(rng, 30), test::below(rng, 20)}, g{test::below(rng, 30), test::below(rng, 20)};
        const double straight = std::hypot(s.x - g.x, s.y - g.y);
        std::vector<Cell> cells;
        CHECK(theta.search(map, s, g, &cells) == Approx(straight).epsilon(1e-12).margin(1e-12));
        CHECK(cells.size() == (s == g ? 1u : 2u));
        CHECK(lazy.search(map, s, g, &cells) == Approx(straight).epsilon(1e-12).margin(1e-12));
        CHECK(cells.size() == (s == g ? 1u : 2u));
    }
}

TEST_CASE("any-angle: oracle <= Theta* <= the scenario's optimum on a Moving AI map") {
    const auto dir = pride::test::shared_data("movingai", "Moving AI maps and scenarios");
    if (!dir) return;
    const auto entries = read_scenario((*dir / "random-32-32-20-even-10.scen").string());
    const GridMap map = read_map((*dir / entries.at(0).map).string());
    AnyAngleOracle oracle(map);
    ThetaStar theta, lazy(true);
    for (std::size_t i = 0; i < entries.size(); i += 4) {
        const auto& e = entries[i];
        const double exact = oracle.solve(e.start, e.goal), t = theta.search(map, e.start, e.goal),
                     l = lazy.search(map, e.start, e.goal);
        CHECK(exact > 0.0);
        CHECK(exact <= t + 1e-9);
        CHECK(exact <= l + 1e-9);
        CHECK(t <= e.optimal + 1e-6);
        CHECK(l <= e.optimal + 1e-6);
    }
}

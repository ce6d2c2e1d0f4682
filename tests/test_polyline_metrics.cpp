// Tests of the polyline path type and its Bench-MR metrics (problems/grid/polyline.hpp).
//
// The references are written here, apart from the library: hand-computed shapes, path.hpp's
// metrics() on legal cell chains, the closed form 2 sin(theta / 2) / h of an isolated turn, and the
// distance from a point to every blocked square of a map, by brute force.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <vector>

#include "framework/random.hpp"
#include "problems/grid/map.hpp"
#include "problems/grid/path.hpp"
#include "problems/grid/planners/any_angle.hpp"
#include "problems/grid/planners/astar.hpp"
#include "problems/grid/polyline.hpp"
#include "tests/grid_support.hpp"

namespace {

using namespace pride;
using grid::Cell;
using grid::GridMap;
using grid::Path;
using grid::PathPoint;
using grid::Polyline;
using grid::PolylineMetrics;
using grid::PolylineScorer;

constexpr double kPi = std::numbers::pi;

GridMap random_map(Rng& rng, int w, int h, double density) {
    std::vector<std::uint8_t> blocked(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
    for (auto& b : blocked) b = rng.uniform() < density ? 1 : 0;
    return GridMap(w, h, std::move(blocked), "random");
}

/// The distance from p to the nearest blocked square (cell (x, y) = [x - 0.5, x + 0.5] x
/// [y - 0.5, y + 0.5]), over every one of them; nullopt when none is blocked.
std::optional<double> brute_clearance(const GridMap& m, PathPoint p) {
    std::optional<double> best;
    for (int y = 0; y < m.height(); ++y)
        for (int x = 0; x < m.width(); ++x)
            if (!m.free({x, y})) {
                const double dx = std::max(std::abs(p.x - x) - 0.5, 0.0), dy = std::max(std::abs(p.y - y) - 0.5, 0.0);
                const double d = std::sqrt(dx * dx + dy * dy);
                if (!best || d < *best) best = d;
            }
    return best;
}

/// A random 8-connected walk of legal steps (reversals included) from a free cell; with `repeats`,
/// some cells are listed twice in a row (zero-length segments, which metrics() skips too).
Path random_walk(Rng& rng, const GridMap& m, int steps, bool repeats = true) {
    Path path;
    for (int tries = 0; tries < 1000 && path.empty(); ++tries) {
        const Cell c{test::below(rng, m.width()), test::below(rng, m.height())};
        if (m.free(c)) path.push_back(c);
    }
    if (path.empty()) return path;
    for (int s = 0; s < steps; ++s) {
        const Cell c = path.back();
        if (repeats && test::below(rng, 10) == 0) {  // a repeated cell: a zero-length segment
            path.push_back(c);
            continue;
        }
        int d = -1;
        for (int tries = 0; tries < 16 && d < 0; ++tries) {
            const int e = test::below(rng, 8);
            if (m.legal_step(c, e)) d = e;
        }
        if (d < 0) break;
        path.push_back({c.x + grid::kDx[d], c.y + grid::kDy[d]});
    }
    return path;
}

/// `path` with collinear vertices inserted on random segments, and some vertices repeated.
Polyline with_insertions(Rng& rng, const Polyline& path) {
    Polyline out;
    for (std::size_t i = 0; i < path.size(); ++i) {
        if (i > 0) {
            const int extra = test::below(rng, 4);
            std::vector<double> ts;
            for (int k = 0; k < extra; ++k) ts.push_back(0.05 + 0.9 * rng.uniform());
            std::sort(ts.begin(), ts.end());
            for (const double t : ts)
                out.push_back(
                    {path[i - 1].x + t * (path[i].x - path[i - 1].x), path[i - 1].y + t * (path[i].y - path[i - 1].y)});
        }
        out.push_back(path[i]);
        if (test::below(rng, 8) == 0) out.push_back(path[i]);
    }
    return out;
}

void require_same(const PolylineMetrics& a, const PolylineMetrics& b) {
    CHECK(a.turns == b.turns);
    CHECK(a.length == Approx(b.length).epsilon(1e-12));
    CHECK(a.total_turn_deg == Approx(b.total_turn_deg).margin(1e-6));
    CHECK(a.max_turn_deg == Approx(b.max_turn_deg).margin(1e-6));
    CHECK(a.angle_over_length == Approx(b.angle_over_length).margin(1e-9));
    CHECK(a.max_curvature == Approx(b.max_curvature).margin(1e-7));
    REQUIRE(a.min_clearance.has_value() == b.min_clearance.has_value());
    REQUIRE(a.mean_clearance.has_value() == b.mean_clearance.has_value());
    if (a.min_clearance) {
        CHECK(*a.min_clearance == Approx(*b.min_clearance).margin(1e-9));
        CHECK(*a.mean_clearance == Approx(*b.mean_clearance).margin(1e-9));
    }
}

Polyline rotated(const Polyline& p, double phi, PathPoint shift) {
    Polyline out;
    for (const PathPoint q : p)
        out.push_back(
            {shift.x + q.x * std::cos(phi) - q.y * std::sin(phi), shift.y + q.x * std::sin(phi) + q.y * std::cos(phi)});
    return out;
}

}  // namespace

TEST_CASE("polyline_of a cell chain is its cells and of square points their centres", "[polyline]") {
    const Path chain{{0, 0}, {1, 1}, {2, 1}};
    CHECK(grid::polyline_of(chain) == Polyline{{0, 0}, {1, 1}, {2, 1}});
    const std::vector<grid::Point> square{{0.5, 0.5}, {3, 2}, {4.5, 7.5}};
    CHECK(grid::polyline_of(square) == Polyline{{0, 0}, {2.5, 1.5}, {4, 7}});

    // An any-angle path from the oracle: its ends are the cells themselves, and its length is kept.
    const GridMap m = test::map_of({"......", "..@@..", "..@@..", "......"});
    grid::AnyAngleOracle oracle(m);
    std::vector<grid::Point> points;
    const double length = oracle.solve({0, 1}, {5, 2}, &points);
    REQUIRE(length > 0);
    const Polyline line = grid::polyline_of(points);
    CHECK(line.front() == PathPoint{0, 1});
    CHECK(line.back() == PathPoint{5, 2});
    CHECK(grid::polyline_metrics(line).length == Approx(length).epsilon(1e-12));
    CHECK(PolylineScorer(m).score(line).min_clearance.value() == Approx(0.0).margin(1e-12));  // it runs along corners
}

TEST_CASE("polyline metrics of a 90-degree L", "[polyline]") {
    const PolylineMetrics m = grid::polyline_metrics({{0, 0}, {2, 0}, {2, 2}});
    CHECK(m.length == 4.0);
    CHECK(m.turns == 1);
    CHECK(m.total_turn_deg == Approx(90.0));
    CHECK(m.max_turn_deg == Approx(90.0));
    CHECK(m.angle_over_length == Approx(kPi / 2 / 4));
    CHECK(m.max_curvature == Approx(std::sqrt(2.0)));  // 2 sin(45) / 1
    CHECK(!m.min_clearance);
    CHECK(!m.mean_clearance);

    // The same L as a cell chain, one cell per unit: the same numbers.
    const PolylineMetrics c = grid::polyline_metrics(grid::polyline_of(Path{{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}}));
    CHECK(c.length == 4.0);
    CHECK(c.turns == 1);
    CHECK(c.max_curvature == Approx(std::sqrt(2.0)));

    // An arm shorter than h = 1 is clamped to the path's start: p0 = (0, 0), p2 = (0.5, 1).
    const PolylineMetrics s = grid::polyline_metrics({{0, 0}, {0.5, 0}, {0.5, 2}});
    CHECK(s.max_curvature == Approx(2.0 * 0.5 * 1.0 / (0.5 * 1.0 * std::hypot(0.5, 1.0))));
}

TEST_CASE("polyline metrics of a 45-degree bend", "[polyline]") {
    const PolylineMetrics m = grid::polyline_metrics({{0, 0}, {3, 0}, {5, 2}});
    CHECK(m.length == Approx(3.0 + 2.0 * std::sqrt(2.0)));
    CHECK(m.turns == 1);
    CHECK(m.total_turn_deg == Approx(45.0));
    CHECK(m.max_turn_deg == Approx(45.0));
    CHECK(m.angle_over_length == Approx(kPi / 4 / m.length));
    CHECK(m.max_curvature == Approx(2.0 * std::sin(kPi / 8)));

    // A cell chain with a 45 then a 90 degree turn.
    const Path chain{{0, 0}, {1, 0}, {2, 1}, {3, 0}};
    const PolylineMetrics c = grid::polyline_metrics(grid::polyline_of(chain));
    CHECK(c.turns == 2);
    CHECK(c.total_turn_deg == Approx(135.0));
    CHECK(c.max_turn_deg == Approx(90.0));
    CHECK(c.length == Approx(1.0 + 2.0 * std::sqrt(2.0)));
}

TEST_CASE("polyline metrics of a reversal", "[polyline]") {
    const PolylineMetrics m = grid::polyline_metrics({{0, 0}, {3, 0}, {1, 0}});
    CHECK(m.length == 5.0);
    CHECK(m.turns == 1);
    CHECK(m.total_turn_deg == Approx(180.0));
    CHECK(m.max_turn_deg == Approx(180.0));
    CHECK(m.angle_over_length == Approx(kPi / 5));
    CHECK(m.max_curvature == Approx(2.0));  // p0 == p2: the limit 2 / h

    // Near the end the arm back is 0.5: the circle of diameter 0.5.
    CHECK(grid::polyline_metrics({{0, 0}, {3, 0}, {2.5, 0}}).max_curvature == Approx(4.0));
    // A diagonal reversal of a cell chain: metrics() counts it as a 180-degree turn too.
    const Path chain{{0, 0}, {1, 1}, {2, 2}, {1, 1}};
    const PolylineMetrics c = grid::polyline_metrics(grid::polyline_of(chain));
    CHECK(c.turns == grid::metrics(chain).turns);
    CHECK(c.total_turn_deg == Approx(grid::metrics(chain).turn_angle_deg));
    CHECK(c.max_curvature == Approx(2.0));
}

TEST_CASE("polyline metrics of one point and of no point", "[polyline]") {
    const GridMap m = test::map_of({"....", ".@..", "...."});
    const PolylineScorer scorer(m);
    for (const Polyline& p : {Polyline{{3, 1}}, Polyline{{3, 1}, {3, 1}, {3, 1}}}) {
        const PolylineMetrics s = scorer.score(p);
        CHECK(s.length == 0.0);
        CHECK(s.turns == 0);
        CHECK(s.total_turn_deg == 0.0);
        CHECK(s.max_turn_deg == 0.0);
        CHECK(s.angle_over_length == 0.0);
        CHECK(s.max_curvature == 0.0);
        CHECK(s.min_clearance.value() == Approx(1.5));
        CHECK(s.mean_clearance.value() == Approx(1.5));
    }
    const PolylineMetrics e = scorer.score({});
    CHECK(e.length == 0.0);
    CHECK(e.turns == 0);
    CHECK(!e.min_clearance);
}

TEST_CASE("polyline clearance beside a wall, and none without obstacles", "[polyline]") {
    const GridMap m = test::map_of({"@@@@@@", "......", "......"});
    const PolylineScorer scorer(m);
    const Path chain{{0, 1}, {1, 1}, {2, 1}, {3, 1}, {4, 1}, {5, 1}};
    const PolylineMetrics s = scorer.score(grid::polyline_of(chain));
    CHECK(s.min_clearance.value() == Approx(0.5));
    CHECK(s.mean_clearance.value() == Approx(0.5));

    // A step away from the wall: the clearance grows linearly to 1.5 at (2, 2); the trapezoid rule is exact.
    const PolylineMetrics v = scorer.score({{0, 1}, {2, 1}, {2, 2}, {4, 2}});
    CHECK(v.min_clearance.value() == Approx(0.5));
    CHECK(v.mean_clearance.value() == Approx((2 * 0.5 + 1.0 + 2 * 1.5) / 5));

    // Cells outside the map are no obstacle; a map with no blocked cell has no clearance.
    CHECK(scorer.clearance({2, 2}).value() == Approx(1.5));
    CHECK(scorer.clearance({2, 0}).value() == 0.0);
    CHECK(scorer.clearance({2, -3}).value() == Approx(2.5));  // above the wall
    CHECK(scorer.clearance({2, 7.5}).value() == Approx(7.0));
    CHECK(scorer.clearance({-1e6, 2}).value() == Approx(std::hypot(1e6 - 0.5, 1.5)));  // far outside
    CHECK(std::isnan(scorer.clearance({std::nan(""), 1}).value()));
    const PolylineScorer open(test::map_of({"....", "...."}));
    CHECK(!open.has_obstacles());
    CHECK(!open.clearance({1, 1}));
    CHECK(!open.score(grid::polyline_of(chain)).min_clearance);
    CHECK(!open.score(grid::polyline_of(chain)).mean_clearance);
}

TEST_CASE("polyline turns and length equal metrics() on random legal chains", "[polyline]") {
    Rng rng(20240617);
    for (int k = 0; k < 300; ++k) {
        const int w = 4 + test::below(rng, 30), h = 4 + test::below(rng, 30);
        const GridMap m = random_map(rng, w, h, 0.3 * rng.uniform());
        const bool repeats = k % 2 == 1;
        const Path chain = random_walk(rng, m, test::below(rng, 80), repeats);
        if (chain.empty()) continue;
        if (!repeats) REQUIRE(grid::path_violation(m, chain, chain.front(), chain.back()).empty());
        const grid::PathMetrics ref = grid::metrics(chain);
        const PolylineMetrics got = grid::polyline_metrics(grid::polyline_of(chain));
        CHECK(got.turns == ref.turns);
        CHECK(got.total_turn_deg ==
              static_cast<double>(ref.turn_angle_deg));  // exactly: each turn rounded to 1e-9 degree
        CHECK(got.length == Approx(ref.length).epsilon(1e-12).margin(0));
    }
    // Optimal chains from A*.
    grid::AStar astar;
    for (const test::GridInstance& in : test::random_instances(77, 40)) {
        if (in.corner_cutting) continue;
        Path chain;
        REQUIRE(astar.search(*in.map, in.start, in.goal, &chain) > 0);
        const grid::PathMetrics ref = grid::metrics(chain);
        const PolylineMetrics got = PolylineScorer(*in.map).score(grid::polyline_of(chain));
        CHECK(got.turns == ref.turns);
        CHECK(got.total_turn_deg == static_cast<double>(ref.turn_angle_deg));
        CHECK(got.length == Approx(ref.length).epsilon(1e-12).margin(0));
        if (got.min_clearance) CHECK(*got.min_clearance >= 0.5 - 1e-12);  // a chain's cells are free
    }
}

TEST_CASE("polyline max curvature of an isolated turn is 2 sin(theta / 2) / h", "[polyline]") {
    Rng rng(5);
    for (const double deg : {45.0, 90.0, 135.0}) {
        const double theta = deg * kPi / 180;
        for (int k = 0; k < 20; ++k) {
            const double a = 1.0 + 3 * rng.uniform(), b = 1.0 + 3 * rng.uniform();  // arms >= h = 1
            const Polyline base{{-a, 0}, {0, 0}, {b * std::cos(theta), b * std::sin(theta)}};
            const Polyline p = rotated(base, 2 * kPi * rng.uniform(), {10 * rng.uniform(), 10 * rng.uniform()});
            const PolylineMetrics m = grid::polyline_metrics(p);
            CHECK(m.turns == 1);
            CHECK(m.max_turn_deg == Approx(deg));
            CHECK(m.max_curvature == Approx(2 * std::sin(theta / 2) / grid::kCurvatureArm).epsilon(1e-9));
            // Denser vertices measure the same turn.
            CHECK(grid::polyline_metrics(with_insertions(rng, p)).max_curvature ==
                  Approx(m.max_curvature).epsilon(1e-7));
        }
    }
}

TEST_CASE("polyline metrics do not change when collinear vertices are inserted", "[polyline]") {
    Rng rng(99);
    for (int k = 0; k < 200; ++k) {
        const GridMap m = random_map(rng, 6 + test::below(rng, 20), 6 + test::below(rng, 20), 0.2 * rng.uniform());
        const PolylineScorer scorer(m);
        Polyline p;
        if (k % 2 == 0) {
            p = grid::polyline_of(random_walk(rng, m, test::below(rng, 40)));
        } else {  // any-angle: random points in the map, with some reversals
            const int n = 1 + test::below(rng, 8);
            for (int i = 0; i < n; ++i) {
                if (i >= 2 && test::below(rng, 5) == 0) {
                    const PathPoint a = p[p.size() - 2], b = p.back();
                    p.push_back({b.x + 0.6 * (a.x - b.x), b.y + 0.6 * (a.y - b.y)});
                } else {
                    p.push_back({(m.width() - 1) * rng.uniform(), (m.height() - 1) * rng.uniform()});
                }
            }
        }
        if (p.empty()) continue;
        require_same(scorer.score(with_insertions(rng, p)), scorer.score(p));
    }
}

TEST_CASE("polyline clearance equals the brute-force distance to every blocked square", "[polyline]") {
    Rng rng(31337);
    for (int k = 0; k < 60; ++k) {
        // From one obstacle in a wide open map (a large annulus) to dense clutter.
        const double density = k % 3 == 0 ? 0.003 : (k % 3 == 1 ? 0.05 : 0.35);
        const int w = 3 + test::below(rng, 60), h = 3 + test::below(rng, 60);
        const GridMap m = random_map(rng, w, h, density);
        const PolylineScorer scorer(m);
        for (int i = 0; i < 200; ++i) {
            // Points in and around the map (outside too), some on cell borders and corners.
            PathPoint p{-3 + (w + 5) * rng.uniform(), -3 + (h + 5) * rng.uniform()};
            if (i % 4 == 1) p = {std::round(p.x) + 0.5, std::round(p.y)};
            if (i % 4 == 2) p = {std::round(p.x) + 0.5, std::round(p.y) - 0.5};
            const std::optional<double> ref = brute_clearance(m, p);
            const std::optional<double> got = scorer.clearance(p);
            REQUIRE(got.has_value() == ref.has_value());
            if (ref) REQUIRE(*got == Approx(*ref).margin(1e-12));
        }
        if (!scorer.has_obstacles()) continue;
        // Random any-angle paths in the map: the samples are the ends, the turn vertices and
        // ceil(L / 0.25) equal steps of each segment (random points: no collinear vertices).
        for (int j = 0; j < 5; ++j) {
            Polyline p;
            const int n = 1 + test::below(rng, 6);
            for (int i = 0; i < n; ++i) p.push_back({(w - 1) * rng.uniform(), (h - 1) * rng.uniform()});
            double low = *brute_clearance(m, p[0]), integral = 0, total = 0, last = low;
            for (std::size_t i = 1; i < p.size(); ++i) {
                const double dx = p[i].x - p[i - 1].x, dy = p[i].y - p[i - 1].y, len = std::hypot(dx, dy);
                const int steps = std::max(1, static_cast<int>(std::ceil(len / grid::kClearanceSpacing)));
                for (int s = 1; s <= steps; ++s) {
                    const double t = static_cast<double>(s) / steps;
                    const double c = *brute_clearance(m, {p[i - 1].x + t * dx, p[i - 1].y + t * dy});
                    integral += 0.5 * (last + c) * len / steps;
                    low = std::min(low, c);
                    last = c;
                }
                total += len;
            }
            const PolylineMetrics got = scorer.score(p);
            REQUIRE(got.min_clearance.has_value());
            CHECK(*got.min_clearance == Approx(low).margin(1e-12));
            CHECK(*got.mean_clearance == Approx(total > 0 ? integral / total : last).margin(1e-9));
        }
    }
}

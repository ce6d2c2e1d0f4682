// The exact any-angle oracle (any_angle.hpp): convex corners, tangent edges, A* over the
// visibility graph with edges tested when their first end is expanded.
#include "problems/grid/planners/any_angle.hpp"

#include <algorithm>
#include <limits>
#include <string>

#include "framework/error.hpp"

namespace pride::grid {

namespace {

/// The direction w lies strictly inside the quadrant of a corner's blocked cell (bit 0: on the
/// side of larger x, bit 1: of larger y).
bool strictly_inside(std::uint8_t quadrant, int wx, int wy) {
    const int qx = (quadrant & 1) ? 1 : -1, qy = (quadrant & 2) ? 1 : -1;
    return wx * qx > 0 && wy * qy > 0;
}

}  // namespace

AnyAngleOracle::AnyAngleOracle(const GridMap& map) : map_(&map) {
    for (int j = 1; j < map.height(); ++j)  // border points have two outside cells: never convex
        for (int i = 1; i < map.width(); ++i) {
            const bool b[4] = {!map.free({i - 1, j - 1}), !map.free({i, j - 1}), !map.free({i - 1, j}),
                               !map.free({i, j})};
            if (b[0] + b[1] + b[2] + b[3] != 1) continue;
            corners_.push_back({2 * i, 2 * j});
            quadrant_.push_back(static_cast<std::uint8_t>(b[1] ? 1 : b[2] ? 2 : b[3] ? 3 : 0));
        }
}

double AnyAngleOracle::solve(Cell s, Cell g, std::vector<Point>* out) {
    const GridMap& map = *map_;
    require(map.free(s), "start", "(" + std::to_string(s.x) + "," + std::to_string(s.y) + ") is blocked or outside");
    require(map.free(g), "goal", "(" + std::to_string(g.x) + "," + std::to_string(g.y) + ") is blocked or outside");
    stopped_ = false;
    if (s == g) {
        if (out) *out = {centre_point(s)};
        return 0.0;
    }
    require(corners_.size() <= max_corners, map.name(),
            "the exact any-angle shortest path is searched among at most " + std::to_string(max_corners) +
                " convex obstacle corners (its time grows with their square); this map has " +
                std::to_string(corners_.size()) + " (plan with theta-star, or without --gaps)");
    // Nodes: the corners, then the start and the goal.
    const auto k = static_cast<std::uint32_t>(corners_.size());
    const std::uint32_t start = k, goal = k + 1, n = k + 2;
    const HalfPoint hs = centre_of(s), hg = centre_of(g);
    const auto point = [&](std::uint32_t v) { return v < k ? corners_[v] : v == start ? hs : hg; };
    g_.assign(n, std::numeric_limits<double>::infinity());
    parent_.assign(n, start);
    closed_.assign(n, 0);
    heap_.clear();
    const auto later = [](const Entry& a, const Entry& b) { return a.f > b.f; };
    g_[start] = 0.0;
    heap_.push_back({distance(hs, hg), start});
    while (!heap_.empty()) {
        std::pop_heap(heap_.begin(), heap_.end(), later);
        const std::uint32_t u = heap_.back().node;
        const double fu = heap_.back().f;
        heap_.pop_back();
        if (closed_[u] || fu > g_[u] + distance(point(u), hg)) continue;  // stale
        closed_[u] = 1;
        if (u == goal) break;
        if ((stop_ && stop_->load(std::memory_order_relaxed)) ||
            (deadline_ && std::chrono::steady_clock::now() >= *deadline_)) {
            stopped_ = true;
            return -1.0;
        }
        const HalfPoint pu = point(u);
        for (std::uint32_t v = 0; v < n; ++v) {
            if (closed_[v] || v == start) continue;
            const HalfPoint pv = point(v);
            const double ng = g_[u] + distance(pu, pv);
            if (ng >= g_[v]) continue;
            // Tangent at both ends (a corner's incoming and outgoing edges keep its square on one side).
            if (u < k && strictly_inside(quadrant_[u], pu.x - pv.x, pu.y - pv.y)) continue;
            if (v < k && strictly_inside(quadrant_[v], pv.x - pu.x, pv.y - pu.y)) continue;
            ++segment_tests_;
            if (!segment_is_free(map, pu, pv)) continue;
            g_[v] = ng;
            parent_[v] = u;
            heap_.push_back({ng + distance(pv, hg), v});
            std::push_heap(heap_.begin(), heap_.end(), later);
        }
    }
    if (!closed_[goal]) return -1.0;
    if (out) {
        out->clear();
        for (std::uint32_t v = goal;; v = parent_[v]) {
            out->push_back(to_point(point(v)));
            if (v == start) break;
        }
        std::reverse(out->begin(), out->end());
    }
    return g_[goal];
}

}  // namespace pride::grid

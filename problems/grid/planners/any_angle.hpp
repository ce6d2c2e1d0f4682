#pragma once
// Any-angle planning on a GridMap: paths are polylines in the map's plane, not cell chains.
//
// Geometry (decided here; grid.md's cells as squares): cell (x, y) is the closed unit square
// [x, x + 1] x [y, y + 1] (x to the right, y downwards, as map.hpp), its centre (x + 0.5, y + 0.5).
// The obstacles are the blocked squares and everything outside the map. A segment is free when
//   - it enters the interior of no blocked square (nor leaves the map); it may touch obstacles:
//     run along an edge with a free cell on at least one side, pass through the corner of a
//     blocked square;
//   - it runs along no edge between two blocked cells (that edge lies inside the obstacle), and
//   - it passes through no grid point where exactly two diagonally opposite cells are blocked
//     (a "squeeze" point). Such a point touches both squares only at a corner, but an 8-connected
//     path may not squeeze between two diagonally touching blocked cells (map.hpp, no corner
//     cutting), so neither may a polyline: any-angle lengths then stay comparable with the grid's.
// With these rules every legal 8-connected step (no corner cutting) is a free segment between cell
// centres, so any legal grid path is a free polyline and the exact any-angle length below is at
// most A*'s.
//
// The test is exact: points are cell centres or grid points, held in doubled integer coordinates
// (HalfPoint), and the walk over the cells a segment crosses compares crossing parameters by
// cross-multiplication, with a crossing exactly through a grid point handled as such.
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "problems/grid/map.hpp"

namespace pride::grid {

/// A point in the map's plane (units of cells; cell (x, y) is [x, x + 1] x [y, y + 1]).
struct Point {
    double x = 0.0;
    double y = 0.0;
    friend bool operator==(const Point&, const Point&) = default;
};

/// A point of the half-unit lattice, in doubled coordinates: the grid point (i, j) is (2i, 2j),
/// the centre of cell (x, y) is (2x + 1, 2y + 1).
struct HalfPoint {
    int x = 0;
    int y = 0;
    friend bool operator==(const HalfPoint&, const HalfPoint&) = default;
};

inline HalfPoint centre_of(Cell c) noexcept {
    return {2 * c.x + 1, 2 * c.y + 1};
}
inline Point to_point(HalfPoint p) noexcept {
    return {0.5 * p.x, 0.5 * p.y};
}
inline Point centre_point(Cell c) noexcept {
    return {c.x + 0.5, c.y + 0.5};
}
inline double distance(HalfPoint a, HalfPoint b) noexcept {
    const double dx = b.x - a.x, dy = b.y - a.y;
    return 0.5 * std::sqrt(dx * dx + dy * dy);
}
/// The Euclidean length of a polyline.
inline double polyline_length(const std::vector<Point>& points) noexcept {
    double length = 0.0;
    for (std::size_t i = 1; i < points.size(); ++i)
        length += std::hypot(points[i].x - points[i - 1].x, points[i].y - points[i - 1].y);
    return length;
}

/// Grid point (i, j) has exactly two diagonally opposite blocked cells around it (outside counts
/// as blocked): no segment may pass through it.
inline bool is_squeeze_point(const GridMap& map, int i, int j) noexcept {
    const bool a = !map.free({i - 1, j - 1}), b = !map.free({i, j - 1}), c = !map.free({i - 1, j}),
               d = !map.free({i, j});
    return (a && d && !b && !c) || (b && c && !a && !d);
}

/// Whether the segment from a to b (cell centres or grid points) is free (the rules at the top).
inline bool segment_is_free(const GridMap& map, HalfPoint a, HalfPoint b) noexcept {
    const int dx = b.x - a.x, dy = b.y - a.y;
    if (dx == 0 && dy == 0) return true;
    const int sx = (dx > 0) - (dx < 0), sy = (dy > 0) - (dy < 0);
    // Along a grid line (both ends grid points): each unit edge needs a free cell on one side, and
    // no grid point inside the segment may be a squeeze point.
    if (dx == 0 && (a.x & 1) == 0) {
        const int i = a.x / 2, j0 = std::min(a.y, b.y) / 2, j1 = std::max(a.y, b.y) / 2;
        for (int j = j0; j < j1; ++j) {
            if (!map.free({i - 1, j}) && !map.free({i, j})) return false;
            if (j > j0 && is_squeeze_point(map, i, j)) return false;
        }
        return true;
    }
    if (dy == 0 && (a.y & 1) == 0) {
        const int j = a.y / 2, i0 = std::min(a.x, b.x) / 2, i1 = std::max(a.x, b.x) / 2;
        for (int i = i0; i < i1; ++i) {
            if (!map.free({i, j - 1}) && !map.free({i, j})) return false;
            if (i > i0 && is_squeeze_point(map, i, j)) return false;
        }
        return true;
    }
    // Otherwise the segment crosses cell interiors: walk them. The cell just after a (a centre's
    // own cell; from a grid point, the one the segment enters).
    int cx = (a.x & 1) ? (a.x - 1) / 2 : a.x / 2 - (sx < 0);
    int cy = (a.y & 1) ? (a.y - 1) / 2 : a.y / 2 - (sy < 0);
    if (!map.free({cx, cy})) return false;
    // ex, ey: the distances (doubled, along each axis) from a to the next vertical / horizontal
    // grid line; the crossing's parameter is ex / |dx| (ey / |dy|), compared by cross-multiplying.
    const std::int64_t adx = std::abs(dx), ady = std::abs(dy);
    std::int64_t ex = (a.x & 1) ? 1 : 2, ey = (a.y & 1) ? 1 : 2;
    for (;;) {
        const bool has_x = sx != 0 && ex < adx, has_y = sy != 0 && ey < ady;  // crossings before b
        if (!has_x && !has_y) return true;
        const std::int64_t tx = ex * ady, ty = ey * adx;
        if (has_x && has_y && tx == ty) {  // through a grid point, into the diagonal cell
            if (!map.free({cx + sx, cy}) && !map.free({cx, cy + sy})) return false;  // a squeeze
            cx += sx;
            cy += sy;
            ex += 2;
            ey += 2;
        } else if (has_x && (!has_y || tx < ty)) {
            cx += sx;
            ex += 2;
        } else {
            cy += sy;
            ey += 2;
        }
        if (!map.free({cx, cy})) return false;
    }
}

/// Whether a point of the plane is free: finite, inside [0, W] x [0, H], in the closed square of
/// at least one free cell (so not inside a blocked square, nor on an edge between two blocked
/// cells), and not a squeeze point. Exact. With the segment rules at the top: a segment of positive
/// length is free exactly when every point of it is free, its two ends excepted from the squeeze
/// rule (the half-lattice test lets a segment end at a squeeze point; point_is_free does not, so a
/// sampling planner never stops there).
bool point_is_free(const GridMap& map, Point p) noexcept;

/// segment_is_free for any two points of the plane (segment.cpp): the rules at the top, decided
/// exactly on the doubles given (the crossings are ordered by an exact orientation predicate), so
/// on cell centres and grid points it answers as the half-lattice test. Conservative only for a
/// coordinate of magnitude below 2^-400 other than 0 (the predicate's products could underflow):
/// such a segment is called blocked. A zero-length segment is free wherever it is (nothing is
/// crossed, as the half-lattice test); otherwise an end that is not finite or lies outside the map
/// makes it blocked.
bool segment_is_free(const GridMap& map, Point a, Point b) noexcept;

/// The most convex obstacle corners the exact any-angle oracle searches among (AnyAngleOracle).
inline constexpr std::size_t kMaxAnyAngleCorners = 100'000;

/// The exact any-angle oracle: the Euclidean shortest path between the centres of two cells among
/// the obstacles (the rules at the top of this file). The path bends only at convex corners of the
/// obstacles, grid points with exactly one blocked cell around them (outside counts as blocked,
/// so no point of the map's border is one; squeeze points are excluded by the rules), so it is the
/// shortest path in the visibility graph over those corners plus the two centres (Lozano-Perez and
/// Wesley 1979). Edges are kept only when they are tangent at each corner they join (the line
/// through the corner leaves its blocked square on one side): a path bending elsewhere can be
/// shortened. The graph is searched by A* with the Euclidean heuristic, each expanded vertex's
/// edges tested when it is expanded (no graph is stored).
///
/// Made for one map (which must outlive it): the corners are found once; solve() reuses its arrays.
class AnyAngleOracle {
  public:
    explicit AnyAngleOracle(const GridMap& map);

    /// The Euclidean shortest length from the centre of s to the centre of g, or -1 when there is
    /// no path. With `out`, the polyline (s's centre, the corners, g's centre) replaces its
    /// contents. s or g outside or blocked: InputError.
    double solve(Cell s, Cell g, std::vector<Point>* out = nullptr);

    /// Limits of solve(): it gives up at `deadline` or once `*stop` is set (the run's wall time,
    /// Ctrl-C), returning -1 with stopped() true. Read once per expansion (each tests every vertex).
    void set_limits(std::optional<std::chrono::steady_clock::time_point> deadline,
                    std::shared_ptr<const std::atomic<bool>> stop) {
        deadline_ = deadline;
        stop_ = std::move(stop);
    }
    /// Whether the last solve() gave up at its limits (its -1 then says nothing about a path).
    bool stopped() const noexcept { return stopped_; }

    /// The most convex corners solve() searches among: a search expands up to every corner and
    /// each expansion looks at every corner, so its time grows with their square (measured in
    /// docs/reliability.md). Past it, solve() refuses the map in one line.
    static constexpr std::size_t max_corners = kMaxAnyAngleCorners;

    /// The convex corners (the graph's vertices besides the two centres).
    const std::vector<HalfPoint>& corners() const noexcept { return corners_; }
    /// Segment tests made since construction.
    std::int64_t segment_tests() const noexcept { return segment_tests_; }

  private:
    const GridMap* map_;
    std::vector<HalfPoint> corners_;
    std::vector<std::uint8_t> quadrant_;  // per corner: its blocked cell, bit 0 x > corner, bit 1 y > corner
    std::vector<double> g_;
    std::vector<std::uint32_t> parent_;
    std::vector<std::uint8_t> closed_;
    struct Entry {
        double f;
        std::uint32_t node;
    };
    std::vector<Entry> heap_;
    std::int64_t segment_tests_ = 0;
    std::optional<std::chrono::steady_clock::time_point> deadline_;
    std::shared_ptr<const std::atomic<bool>> stop_;
    bool stopped_ = false;
};

}  // namespace pride::grid

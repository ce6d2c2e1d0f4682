// The segment and point tests of any_angle.hpp for any points of the plane (not only the half
// lattice): the same walk over the cells a segment crosses as the half-lattice test, with the order
// of two crossings (or a crossing exactly through a grid point) decided by the exact sign of an
// orientation determinant on the doubles given. Sampling planners (ompl_planner.cpp) rely on it:
// a rounding error here would let a path through a squeeze point or a blocked corner.
#include <cmath>

#include "problems/grid/planners/any_angle.hpp"

namespace pride::grid {

namespace {

// Below this magnitude a coordinate's products with others may underflow, and the exact sum below
// would no longer be exact.
constexpr double kTiny = 0x1p-400;

bool representable(Point p) noexcept {
    const auto ok = [](double v) { return v == 0.0 || std::abs(v) >= kTiny; };
    return ok(p.x) && ok(p.y);
}

bool inside_map(const GridMap& map, Point p) noexcept {
    // NaN fails every comparison.
    return p.x >= 0.0 && p.y >= 0.0 && p.x <= map.width() && p.y <= map.height();
}

bool is_integer(double v) noexcept {
    return v == std::floor(v);
}

/// s + e == a + b exactly (Knuth's two-sum).
void two_sum(double a, double b, double& s, double& e) noexcept {
    s = a + b;
    const double bv = s - a, av = s - bv;
    e = (a - av) + (b - bv);
}

/// The sign of (b - a) x (c - a), exact for finite coordinates that pass representable().
int orientation(Point a, Point b, Point c) noexcept {
    // Fast path: the rounded determinant with a bound on its error (Shewchuk 1997, orient2d's
    // first stage); decides all but near-collinear triples.
    const double left = (a.x - c.x) * (b.y - c.y), right = (a.y - c.y) * (b.x - c.x), det = left - right;
    const double bound = (3.0 + 16.0 * 0x1p-53) * 0x1p-53 * (std::abs(left) + std::abs(right));
    if (det > bound) return 1;
    if (-det > bound) return -1;
    // Exact: the determinant as six products, each split by fma into its rounded value and exact
    // error, summed into a non-overlapping expansion whose largest component carries the sign.
    const double factors[6][2] = {{b.x, c.y}, {-b.x, a.y}, {-a.x, c.y}, {-b.y, c.x}, {b.y, a.x}, {a.y, c.x}};
    double expansion[13];
    int n = 0;
    const auto grow = [&](double v) {
        for (int i = 0; i < n; ++i) two_sum(v, expansion[i], v, expansion[i]);
        expansion[n++] = v;
    };
    for (const auto& f : factors) {
        const double p = f[0] * f[1];
        grow(std::fma(f[0], f[1], -p));
        grow(p);
    }
    for (int i = n - 1; i >= 0; --i)
        if (expansion[i] != 0.0) return expansion[i] > 0.0 ? 1 : -1;
    return 0;
}

}  // namespace

bool point_is_free(const GridMap& map, Point p) noexcept {
    if (!inside_map(map, p)) return false;
    // The cells whose closed squares hold p: one per axis, two when p lies on a grid line.
    const int x1 = static_cast<int>(std::floor(p.x)), y1 = static_cast<int>(std::floor(p.y));
    const int x0 = is_integer(p.x) ? x1 - 1 : x1, y0 = is_integer(p.y) ? y1 - 1 : y1;
    if (x0 != x1 && y0 != y1 && is_squeeze_point(map, x1, y1)) return false;
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x)
            if (map.free({x, y})) return true;
    return false;
}

bool segment_is_free(const GridMap& map, Point a, Point b) noexcept {
    if (a == b) return true;  // wherever it is, as the half-lattice test
    if (!inside_map(map, a) || !inside_map(map, b)) return false;
    if (!representable(a) || !representable(b)) return false;
    // Along a grid line: each unit edge it overlaps needs a free cell on one side, and no grid
    // point strictly inside it may be a squeeze point (as the half-lattice test).
    if (a.x == b.x && is_integer(a.x)) {
        const int i = static_cast<int>(a.x);
        const int j0 = static_cast<int>(std::floor(std::min(a.y, b.y))),
                  j1 = static_cast<int>(std::ceil(std::max(a.y, b.y)));
        for (int j = j0; j < j1; ++j) {
            if (!map.free({i - 1, j}) && !map.free({i, j})) return false;
            if (j > j0 && is_squeeze_point(map, i, j)) return false;
        }
        return true;
    }
    if (a.y == b.y && is_integer(a.y)) {
        const int j = static_cast<int>(a.y);
        const int i0 = static_cast<int>(std::floor(std::min(a.x, b.x))),
                  i1 = static_cast<int>(std::ceil(std::max(a.x, b.x)));
        for (int i = i0; i < i1; ++i) {
            if (!map.free({i, j - 1}) && !map.free({i, j})) return false;
            if (i > i0 && is_squeeze_point(map, i, j)) return false;
        }
        return true;
    }
    // Otherwise the segment crosses cell interiors: walk them from the cell it enters at a (on a
    // grid line, the one on the side it moves to; sx == 0 means a.x is not an integer here).
    const int sx = (b.x > a.x) - (b.x < a.x), sy = (b.y > a.y) - (b.y < a.y);
    int cx = static_cast<int>(std::floor(a.x)), cy = static_cast<int>(std::floor(a.y));
    if (sx < 0 && is_integer(a.x)) --cx;
    if (sy < 0 && is_integer(a.y)) --cy;
    if (!map.free({cx, cy})) return false;
    for (;;) {
        // The next vertical and horizontal grid lines ahead, and whether the segment crosses them
        // before it ends (a crossing at b itself is no crossing: the segment stops there).
        const double gx = sx > 0 ? cx + 1 : cx, gy = sy > 0 ? cy + 1 : cy;
        const bool has_x = sx > 0 ? gx < b.x : sx < 0 && gx > b.x;
        const bool has_y = sy > 0 ? gy < b.y : sy < 0 && gy > b.y;
        if (!has_x && !has_y) return true;
        // Which comes first: the x crossing exactly when the grid point (gx, gy) lies on the
        // side of the line that sx * sy * orientation > 0 says; on the line, both at once.
        const int order = has_x && has_y ? sx * sy * orientation(a, b, {gx, gy}) : has_x ? 1 : -1;
        if (order == 0) {  // through the grid point, into the diagonal cell
            if (!map.free({cx + sx, cy}) && !map.free({cx, cy + sy})) return false;  // a squeeze point
            cx += sx;
            cy += sy;
        } else if (order > 0) {
            cx += sx;
        } else {
            cy += sy;
        }
        if (!map.free({cx, cy})) return false;
    }
}

}  // namespace pride::grid

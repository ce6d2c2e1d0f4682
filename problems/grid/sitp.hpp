#pragma once
// SITP, Zhang et al.'s (2025) "segmented intermediate transition point" initialisation (section 2.2, eqs.
// 3-7; docs/algorithms.md "IQGA"): a path from s to g through a transition point on the
// column x_r, drawn in one of three bands of rows. x_r is "a random integer between the start's
// and the end's x" as the text under eq. 3 says (随机整数; the project's decision follows the text): uniform
// over the columns from min(x_s, x_g) to max(x_s, x_g), both included; eq. 3's own formula,
// floor((x_s + x_g) / 2), is the option `midpoint_column`. Each half (s to the
// transition point, the transition point to g) is the best of `walks_per_segment` angle walks; the
// two halves are joined and loops cut.
//
// The angle walk (steps 2-3): a depth-first walk with a taboo list, every visited cell staying
// taboo, that draws the next cell among the free, unvisited, legal neighbours by roulette with
// weight (7 - 10 ln(theta / 90))^2, theta the angle in degrees between the step and the direction
// from the current cell to the segment's end, and 1e15 when theta = 0 (eq. 7). A dead end backs up
// one cell. So, like RandomWalker, it reaches the end whenever the end can be reached, entering
// each cell at most once, and reports when it cannot.
//
// Project decisions where Zhang et al. (2025) are silent or unclear (the project's decision says only "three bands of
// rows"):
//   - bands: eq. 3 splits rows by (y_s + y_e) / 3, which is a third of the rows only when the
//     start is on row 0; the bands here are the three near-equal thirds of the rows from
//     min(y_s, y_g) to max(y_s, y_g) (band b: rows lo + floor(b n / 3) .. lo + floor((b + 1) n / 3)
//     - 1 of the n rows), the row span widened to three rows (inside the map) when shorter, so that
//     start and goal on one row or two still give three bands;
//   - the transition point is drawn uniformly among the cells of column x_r in the band that are
//     free and reachable (eq. 3's R, "the non-obstacle coordinates on x = x_r"): a blocked draw is
//     never made. A band without such a cell falls back to the reachable cell of the column
//     nearest to the band (ties: the lower row). Every path from s to g crosses column x_r, so the
//     column always has one when g is reachable;
//   - start and goal in one column: x_r is that column and the transition point lies on it;
//   - "keep the best" of a segment's walks: the lowest score, by default the segment's length
//     (eq. 8); the chain space scores by the problem's objective (eq. 12's fitness under iqga).
//     Ties: the earlier walk. N / 8 walks per segment with the paper's N = 40 is the default 5;
//   - which band: the caller says (the chain space cycles 0, 1, 2 so that a population of N has
//     N / 3 per band, step 1); band < 0 draws one uniformly.
// Unreachable goal: walk() returns false and leaves `out` empty, as the other walkers do.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "framework/random.hpp"
#include "problems/grid/grid_problem.hpp"
#include "problems/grid/map.hpp"
#include "problems/grid/path.hpp"
#include "problems/grid/search_arrays.hpp"
#include "problems/grid/walk.hpp"

namespace pride::grid {

/// The weight of eq. 7 for an angle of theta degrees (0 <= theta <= 180): 1e15 at theta = 0, else
/// (7 - 10 ln(theta / 90))^2. 45: 194.09, 90: 49, 135: 8.675, 180: 0.0047.
inline double sitp_weight(double theta_deg) {
    if (theta_deg == 0.0) return 1e15;
    const double t = 7.0 - 10.0 * std::log(theta_deg / 90.0);
    return t * t;
}

/// The eq. 7 weight of a step (dx, dy) from a cell whose segment end lies at (tx, ty) from it
/// (not both 0): theta is exactly 0 when the two vectors point the same way (integer test).
inline double sitp_step_weight(int dx, int dy, int tx, int ty) {
    const long cross = static_cast<long>(dx) * ty - static_cast<long>(dy) * tx;
    const long dot = static_cast<long>(dx) * tx + static_cast<long>(dy) * ty;
    if (cross == 0 && dot > 0) return sitp_weight(0.0);
    const double c = static_cast<double>(dot) / (std::hypot(dx, dy) * std::hypot(tx, ty));
    const double theta = std::acos(std::clamp(c, -1.0, 1.0)) * (180.0 / 3.14159265358979323846);
    return sitp_weight(theta > 0.0 ? theta : 1e-12);
}

/// The rows [first, last] of band b (0, 1, 2) for a segment from s to g on `map` (see the header).
struct RowBand {
    int first = 0;
    int last = 0;
};
inline RowBand sitp_band(const GridMap& map, Cell s, Cell g, int b) {
    int lo = std::min(s.y, g.y), hi = std::max(s.y, g.y);
    while (hi - lo + 1 < 3 && (lo > 0 || hi + 1 < map.height())) {  // widen to three rows
        if (hi + 1 < map.height()) ++hi;
        if (hi - lo + 1 < 3 && lo > 0) --lo;
    }
    const int n = hi - lo + 1;
    if (n < 3) return {lo + std::min(b, n - 1), lo + std::min(b, n - 1)};  // a map of one or two rows
    return {lo + b * n / 3, lo + (b + 1) * n / 3 - 1};
}

class SitpWalker {
  public:
    /// Angle walks per segment, of which the best is kept: N / 8 with the paper's N = 40.
    int walks_per_segment = 5;
    /// The transition column: eq. 3's midpoint instead of the text's random column.
    bool midpoint_column = false;

    /// The transition point of a segment from s to g in band `band` (0..2): a uniform draw among
    /// the cells of the transition column (random, or floor((s.x + g.x) / 2) with midpoint_column)
    /// in the band for which `reachable(cell)` holds, else the reachable cell of the column
    /// nearest to the band; false when the column has none. The random column is drawn first.
    template <class Reachable>
    bool transition_point(const GridMap& map, Cell s, Cell g, int band, Rng& rng, Reachable&& reachable,
                          Cell& out) const {
        const int lo = std::min(s.x, g.x), hi = std::max(s.x, g.x);
        // Coordinates are >= 0: the division is the floor. Every path from s to g crosses every
        // column from lo to hi, so the column has a reachable cell whenever g is reachable.
        const int x = midpoint_column ? (s.x + g.x) / 2
                                      : lo + static_cast<int>(rng.below(static_cast<std::uint64_t>(hi - lo + 1)));
        const RowBand rows = sitp_band(map, s, g, band);
        int count = 0;
        for (int y = rows.first; y <= rows.last; ++y) count += reachable(Cell{x, y}) ? 1 : 0;
        if (count > 0) {
            int pick = static_cast<int>(rng.below(static_cast<std::uint64_t>(count)));
            for (int y = rows.first; y <= rows.last; ++y) {
                if (!reachable(Cell{x, y})) continue;
                if (pick-- == 0) {
                    out = {x, y};
                    return true;
                }
            }
        }
        int best = -1, best_gap = map.height() + 1;
        for (int y = 0; y < map.height(); ++y) {
            if (!reachable(Cell{x, y})) continue;
            const int gap = y < rows.first ? rows.first - y : y - rows.last;
            if (gap < best_gap) best_gap = gap, best = y;
        }
        if (best < 0) return false;
        out = {x, best};
        return true;
    }

    /// One angle walk (steps 2-3) from s to g into `out`: a legal path with no cell twice, or false
    /// (and `out` empty) when g cannot be reached.
    bool angle_walk(const GridMap& map, Cell s, Cell g, Rng& rng, Path& out, bool corner_cutting = false) {
        return walk_.walk(map, s, g, rng, out, corner_cutting, [&](Cell c) {
            const double* w = step_weights(map, g.x - c.x, g.y - c.y);
            return [w, g, c](Cell, int d) {
                return w != nullptr ? w[d] : sitp_step_weight(kDx[d], kDy[d], g.x - c.x, g.y - c.y);
            };
        });
    }

    /// The eq. 7 weights of the eight steps from a cell whose segment end lies at (tx, ty) from it,
    /// from a table filled as offsets are met (a logarithm, an arc cosine and two hypot calls per
    /// neighbour were most of a walk's time); the values are sitp_step_weight's own, so the walks
    /// draw exactly as without the table. Null when the map is too large for one (more than
    /// kMaxTable entries): the caller then computes the weight.
    const double* step_weights(const GridMap& map, int tx, int ty) {
        const std::size_t w = 2 * static_cast<std::size_t>(map.width()) - 1;
        const std::size_t h = 2 * static_cast<std::size_t>(map.height()) - 1;
        if (w * h * 8 > kMaxTable) return nullptr;
        if (table_w_ != w || table_h_ != h) {
            table_.assign(w * h * 8, std::numeric_limits<double>::quiet_NaN());
            table_w_ = w;
            table_h_ = h;
        }
        const std::size_t at =
            (static_cast<std::size_t>(ty + map.height() - 1) * w + static_cast<std::size_t>(tx + map.width() - 1)) * 8;
        double* e = table_.data() + at;
        if (std::isnan(e[0]))
            for (int d = 0; d < 8; ++d) e[d] = sitp_step_weight(kDx[d], kDy[d], tx, ty);
        return e;
    }

    /// The best of walks_per_segment angle walks from s to g by `score` (lower is better; ties:
    /// the earlier walk) into `out`; false when g cannot be reached.
    template <class Score>
    bool best_walk(const GridMap& map, Cell s, Cell g, Rng& rng, Path& out, bool corner_cutting, Score&& score) {
        out.clear();
        double best = 0.0;
        for (int k = 0; k < std::max(1, walks_per_segment); ++k) {
            if (!angle_walk(map, s, g, rng, trial_, corner_cutting)) return false;
            const double v = score(trial_);
            if (k == 0 || v < best) {
                best = v;
                out.swap(trial_);
            }
        }
        return true;
    }

    /// One SITP path from s to g through a transition point of band `band` (0..2; < 0: drawn),
    /// choosing it among the cells for which `reachable(cell)` holds (free and connected to s),
    /// each half the best of walks_per_segment walks by `score`; loops cut. False (and `out` empty)
    /// when g cannot be reached.
    template <class Reachable, class Score>
    bool walk(const GridMap& map, Cell s, Cell g, Rng& rng, Path& out, bool corner_cutting, int band,
              Reachable&& reachable, Score&& score) {
        out.clear();
        if (!map.free(s) || !map.free(g) || !reachable(g)) return false;
        if (s == g) {
            out.push_back(s);
            return true;
        }
        if (band < 0 || band > 2) band = static_cast<int>(rng.below(3));
        Cell t;
        if (!transition_point(map, s, g, band, rng, reachable, t)) return false;
        if (!best_walk(map, s, t, rng, out, corner_cutting, score)) return false;
        if (!best_walk(map, t, g, rng, half_, corner_cutting, score)) {
            out.clear();
            return false;
        }
        out.insert(out.end(), half_.begin() + 1, half_.end());  // path b without its first cell
        cut_loops(out, map, seen_);
        return true;
    }

    /// The same with the segments scored by length and reachability worked out here (a
    /// breadth-first search per call: callers that know it pass it, as the chain space does).
    bool walk(const GridMap& map, Cell s, Cell g, Rng& rng, Path& out, bool corner_cutting = false, int band = -1) {
        const std::vector<std::uint8_t> reach = reachable_from(map, s, corner_cutting);
        return walk(
            map, s, g, rng, out, corner_cutting, band,
            [&](Cell c) { return map.inside(c) && reach[map.index(c)] != 0; },
            [](const Path& p) { return metrics(p, false).length; });
    }

  private:
    static constexpr std::size_t kMaxTable = std::size_t{1} << 20;  // 8 MB: maps up to about 360 x 360
    TabooRouletteWalk walk_;
    Path trial_, half_;
    std::vector<std::int32_t> seen_;
    std::vector<double> table_;  // step_weights' table: NaN where not yet met
    std::size_t table_w_ = 0, table_h_ = 0;
};

}  // namespace pride::grid

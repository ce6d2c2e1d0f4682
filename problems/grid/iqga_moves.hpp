#pragma once
// Zhang et al.'s (2025) IQGA operators on grid paths (sections 2.3-2.4; docs/algorithms.md "IQGA"),
// which ChainSpace (chain.hpp) offers as the optional chain capabilities of framework/chain.hpp:
//   region      eqs. 14-15: which of three regions of the start-goal rectangle a path lies in;
//   crossover   fig. 7: two common cells of the parents are the cut points, the parts between them
//               are swapped;
//   mutation k  section 2.4.3, eqs. 20-22: 0 deletion, 1 mid-point, 2 turning point, each first
//               regenerating the part between two random turning points' outer neighbours with
//               the SITP walk (sitp.hpp);
//   regenerate  the part between two positions of a path made anew by an SITP walk.
// Every result is a legal path from start to goal with no cell twice: replacements are checked
// step by step (free cell, legal step, corner rule), joins happen at shared cells, and loops are
// cut (cut_loops, as the other chain operators do).
//
// Project decisions where Zhang et al. (2025) are silent:
//   - regions: the paper's eq. 15 assumes the start at the bottom left and its boundary constants
//     contradict its own excluded points, so the project's words decide: the two lines are parallel
//     to the start-goal diagonal, shifted from it by l = floor(L / 2) along the axis of the
//     shorter side (x when |dx| <= |dy|, the paper's first case). A cell strictly beyond a line is
//     in region 0 (D1: right of the direction start -> goal, as drawn on the screen) or 1 (D2:
//     left); the rest, the lines included, is region 2 (D3, the middle band holding the
//     diagonal, which eq. 16 gives the remaining selections). The lines extend beyond the
//     rectangle, so every cell of the map has a region. A path is in the region holding most of
//     its cells (start and goal included); ties: the middle, then region 0;
//   - the turn vectors of the deletion rule are the steps into and out of d_k, so "angle > 90"
//     is a turn of 135 degrees (its neighbours are then adjacent and d_k goes);
//   - crossover with one common interior cell: the goal is the second cut point (the tails are
//     swapped); with none: false, the parents unchanged. Two common cells met in opposite orders
//     by the parents: the swapped part is reversed (a reversed legal path is legal);
//   - mutation with fewer than two turning points: one turning point is both d_i and d_j; none
//     (a straight path): no regeneration. The n_m nodes (eq. 20) are drawn uniformly among the
//     interior cells, distinct, and at most the interior's count; eq. 20's B is the caller's
//     `badness` (0 when the caller has no population ranking). A replacement or deletion that
//     would break the path (blocked cell, illegal step) is skipped.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <tuple>
#include <utility>
#include <vector>

#include "framework/random.hpp"
#include "problems/grid/grid_problem.hpp"
#include "problems/grid/map.hpp"
#include "problems/grid/path.hpp"
#include "problems/grid/sitp.hpp"

namespace pride::grid {

/// The region of cell c for a start s and goal g (eqs. 14-15 as read above): 0 right of the
/// direction s -> g beyond the first line, 1 left beyond the second, 2 the middle band.
inline int iqga_cell_region(Cell s, Cell g, Cell c) {
    const long dx = g.x - s.x, dy = g.y - s.y;
    const long L = std::min(dx < 0 ? -dx : dx, dy < 0 ? -dy : dy), l = L / 2;
    const long longer = std::max(dx < 0 ? -dx : dx, dy < 0 ? -dy : dy);
    // cross / longer is the offset of c from the diagonal along the shorter side's axis.
    const long cross = dx * (c.y - s.y) - dy * (c.x - s.x);  // > 0: right of s -> g on the screen
    const long size = cross < 0 ? -cross : cross;
    if (cross == 0 || size <= l * longer) return 2;
    return cross > 0 ? 0 : 1;
}

/// The region of a path: the one holding most of its cells (ties: 2, then 0).
inline std::size_t iqga_path_region(Cell s, Cell g, const Path& path) {
    int count[3] = {0, 0, 0};
    for (const Cell& c : path) ++count[iqga_cell_region(s, g, c)];
    if (count[2] >= count[0] && count[2] >= count[1]) return 2;
    return count[0] >= count[1] ? 0 : 1;
}

/// The positions of a path's turning points: interior cells where the step direction changes.
inline void turning_points(const Path& path, std::vector<std::size_t>& out) {
    out.clear();
    for (std::size_t k = 1; k + 1 < path.size(); ++k)
        if (direction(path[k - 1], path[k]) != direction(path[k], path[k + 1])) out.push_back(k);
}

/// Eq. 20: the number of nodes to mutate on a path of n_all cells whose badness is B.
inline int iqga_mutation_points(std::size_t n_all, double badness, Rng& rng) {
    int n = 0;
    if (badness < 0.5) {
        const int hi = std::max(2, static_cast<int>(0.25 * static_cast<double>(n_all)));
        n = 2 + static_cast<int>(rng.below(static_cast<std::uint64_t>(hi - 2 + 1)));
    } else {
        n = static_cast<int>(0.4 * static_cast<double>(n_all) * badness);
    }
    return std::clamp(n, 2, 10);
}

/// Eq. 21: the mid-point of two cells (coordinates >= 0, so int() is the floor).
inline Cell iqga_mid_point(Cell a, Cell b) {
    return {(a.x + b.x) / 2, (a.y + b.y) / 2};
}

class IqgaMoves {
  public:
    static constexpr std::size_t kMutations = 3;  // 0 deletion, 1 mid-point, 2 turning point
    SitpWalker sitp;

    /// The part of `c` between positions i < j (both kept) replaced by an SITP walk between the
    /// two cells (band drawn), its segments' walks ranked by `score` (the chain space passes the
    /// run's counted objective, or the length); loops cut. False, c unchanged, unless
    /// i < j < c.size().
    template <class Objective, class Score>
    bool regenerate(const GridProblem<Objective>& p, Path& c, std::size_t i, std::size_t j, Rng& rng, Score&& score) {
        if (!(i < j && j < c.size())) return false;
        const bool ok = sitp.walk(
            p.map(), c[i], c[j], rng, segment_, p.corner_cutting(), -1, [&](Cell x) { return p.reachable(x); }, score);
        if (!ok) return false;  // cannot happen: c[i] and c[j] lie on one legal chain
        tail_.assign(c.begin() + static_cast<std::ptrdiff_t>(j) + 1, c.end());
        c.resize(i);
        c.insert(c.end(), segment_.begin(), segment_.end());
        c.insert(c.end(), tail_.begin(), tail_.end());
        cut_loops(c, p.map(), seen_);
        return true;
    }

    /// Fig. 7's crossover (see the header for one or no common cell).
    template <class Objective>
    bool crossover(const GridProblem<Objective>& p, Path& a, Path& b, Rng& rng) {
        const GridMap& map = p.map();
        if (position_.size() != map.size()) position_.assign(map.size(), -1);
        for (std::size_t j = 1; j + 1 < b.size(); ++j) position_[map.index(b[j])] = static_cast<std::int32_t>(j);
        common_.clear();
        for (std::size_t i = 1; i + 1 < a.size(); ++i) {
            const std::int32_t j = position_[map.index(a[i])];
            if (j > 0 && static_cast<std::size_t>(j) + 1 < b.size() && b[static_cast<std::size_t>(j)] == a[i])
                common_.emplace_back(i, static_cast<std::size_t>(j));
        }
        for (std::size_t j = 1; j + 1 < b.size(); ++j) position_[map.index(b[j])] = -1;
        if (common_.empty()) return false;
        std::size_t i1 = 0, j1 = 0, i2 = 0, j2 = 0;
        if (common_.size() == 1) {
            std::tie(i1, j1) = common_[0];
            i2 = a.size() - 1;  // the goal
            j2 = b.size() - 1;
        } else {
            std::size_t u = rng.below(common_.size()), v = rng.below(common_.size() - 1);
            if (v >= u) ++v;
            if (u > v) std::swap(u, v);
            std::tie(i1, j1) = common_[u];  // a meets them in this order (common_ follows a)
            std::tie(i2, j2) = common_[v];
        }
        // a' = a[..i1] + b's part between the two cells + a[i2..]; b' likewise.
        const bool reversed = j1 > j2;
        const std::size_t bl = reversed ? j2 : j1, bh = reversed ? j1 : j2;
        part_a_.assign(a.begin() + static_cast<std::ptrdiff_t>(i1) + 1, a.begin() + static_cast<std::ptrdiff_t>(i2));
        part_b_.assign(b.begin() + static_cast<std::ptrdiff_t>(bl) + 1, b.begin() + static_cast<std::ptrdiff_t>(bh));
        if (reversed) {
            std::reverse(part_a_.begin(), part_a_.end());
            std::reverse(part_b_.begin(), part_b_.end());
        }
        tail_.assign(a.begin() + static_cast<std::ptrdiff_t>(i2), a.end());
        a.resize(i1 + 1);
        a.insert(a.end(), part_b_.begin(), part_b_.end());
        a.insert(a.end(), tail_.begin(), tail_.end());
        tail_.assign(b.begin() + static_cast<std::ptrdiff_t>(bh), b.end());
        b.resize(bl + 1);
        b.insert(b.end(), part_a_.begin(), part_a_.end());
        b.insert(b.end(), tail_.begin(), tail_.end());
        cut_loops(a, map, seen_);
        cut_loops(b, map, seen_);
        return true;
    }

    /// Mutation operator k (0 deletion, 1 mid-point, 2 turning point; k >= 3: no change) on c; the
    /// regeneration's walks are ranked by `score`.
    template <class Objective, class Score>
    void mutate(const GridProblem<Objective>& p, std::size_t k, Path& c, Rng& rng, double badness, Score&& score) {
        if (k >= kMutations || c.size() < 3) return;
        // Every operator first regenerates d_{i-1} .. d_{j+1} for two random turning points.
        turning_points(c, turns_);
        if (!turns_.empty()) {
            std::size_t u = rng.below(turns_.size()), v = u;
            if (turns_.size() > 1) {
                v = rng.below(turns_.size() - 1);
                if (v >= u) ++v;
            }
            const std::size_t i = std::min(turns_[u], turns_[v]), j = std::max(turns_[u], turns_[v]);
            regenerate(p, c, i - 1, j + 1, rng, score);
        }
        if (c.size() < 3) return;
        // The nodes d_k, processed from the goal's end so that earlier positions stay valid.
        nodes_.clear();
        if (k == 2) {  // eq. 22: n_m = rand(1, n_diver) turning points
            turning_points(c, nodes_);
            if (nodes_.empty()) return;
            const std::size_t n = 1 + rng.below(nodes_.size());
            partial_shuffle(nodes_, n, rng);
        } else {  // eq. 20 over the interior cells
            for (std::size_t q = 1; q + 1 < c.size(); ++q) nodes_.push_back(q);
            const std::size_t n =
                std::min(nodes_.size(),
                         static_cast<std::size_t>(iqga_mutation_points(c.size(), std::clamp(badness, 0.0, 1.0), rng)));
            partial_shuffle(nodes_, n, rng);
        }
        std::sort(nodes_.begin(), nodes_.end(), std::greater<>());
        const GridMap& map = p.map();
        const bool cc = p.corner_cutting();
        for (const std::size_t q : nodes_) {
            if (q == 0 || q + 1 >= c.size()) continue;
            const Cell a = c[q - 1], m = c[q], b = c[q + 1];
            if (k == 0)
                deletion(map, c, q, a, m, b, cc);
            else if (k == 1)
                mid_point(map, c, q, a, b, cc);
            else
                turning_point(map, c, q, a, m, b, cc, rng);
        }
        cut_loops(c, map, seen_);
    }

  private:
    static bool step_ok(const GridMap& map, Cell a, Cell b, bool cc) {
        const int d = direction(a, b);
        return d >= 0 && map.legal_step(a, d, cc);
    }
    static bool adjacent(Cell a, Cell b) { return !(a == b) && std::abs(a.x - b.x) <= 1 && std::abs(a.y - b.y) <= 1; }
    /// Removes c[q] when its neighbours are one legal step apart.
    static bool remove(const GridMap& map, Path& c, std::size_t q, Cell a, Cell b, bool cc) {
        if (!step_ok(map, a, b, cc)) return false;
        c.erase(c.begin() + static_cast<std::ptrdiff_t>(q));
        return true;
    }
    /// Replaces c[q] by x when a -> x -> b are legal steps.
    static bool replace(const GridMap& map, Path& c, std::size_t q, Cell a, Cell x, Cell b, bool cc) {
        if (!step_ok(map, a, x, cc) || !step_ok(map, x, b, cc)) return false;
        c[q] = x;
        return true;
    }
    /// Section 2.4.3, deletion: the turn at d_k above 90 degrees: delete d_k; 90 degrees entered
    /// orthogonally: delete d_k; entered diagonally: d_k becomes the mid-point of eq. 21.
    static void deletion(const GridMap& map, Path& c, std::size_t q, Cell a, Cell m, Cell b, bool cc) {
        const int din = direction(a, m), dout = direction(m, b);
        if (din < 0 || dout < 0) return;
        const int turn = turn_steps(din, dout);
        if (turn >= 3) {
            remove(map, c, q, a, b, cc);
        } else if (turn == 2) {
            if (!is_diagonal(din))
                remove(map, c, q, a, b, cc);
            else
                replace(map, c, q, a, iqga_mid_point(a, b), b, cc);
        }
    }
    /// Mid-point: neighbours adjacent: delete d_k; else d_k becomes the mid-point of eq. 21.
    static void mid_point(const GridMap& map, Path& c, std::size_t q, Cell a, Cell b, bool cc) {
        if (adjacent(a, b))
            remove(map, c, q, a, b, cc);
        else if (!(a == b))
            replace(map, c, q, a, iqga_mid_point(a, b), b, cc);
    }
    /// Turning point: neighbours adjacent: delete d_k; else d_k becomes the mid-point when it is a
    /// common free neighbour of both (d_k excluded), else a random such common neighbour.
    void turning_point(const GridMap& map, Path& c, std::size_t q, Cell a, Cell m, Cell b, bool cc, Rng& rng) {
        if (adjacent(a, b)) {
            remove(map, c, q, a, b, cc);
            return;
        }
        if (a == b) return;
        int count = 0;
        const Cell mid = iqga_mid_point(a, b);
        for (int d = 0; d < 8; ++d) {
            const Cell x{a.x + kDx[d], a.y + kDy[d]};
            if (x == m || !adjacent(x, b) || !step_ok(map, a, x, cc) || !step_ok(map, x, b, cc)) continue;
            if (x == mid) {
                c[q] = mid;
                return;
            }
            common_cells_[count++] = x;
        }
        if (count > 0) c[q] = common_cells_[rng.below(static_cast<std::uint64_t>(count))];
    }
    /// The first n entries of v become a uniform draw of n distinct entries; v keeps those n.
    static void partial_shuffle(std::vector<std::size_t>& v, std::size_t n, Rng& rng) {
        for (std::size_t t = 0; t < n && t + 1 < v.size(); ++t) std::swap(v[t], v[t + rng.below(v.size() - t)]);
        v.resize(std::min(n, v.size()));
    }

    std::vector<std::int32_t> position_, seen_;
    std::vector<std::pair<std::size_t, std::size_t>> common_;
    std::vector<std::size_t> turns_, nodes_;
    Cell common_cells_[8];
    Path segment_, tail_, part_a_, part_b_;
};

}  // namespace pride::grid

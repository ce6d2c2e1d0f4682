#pragma once
// Paths on a grid (docs/grid.md): the chain of cells from start to goal, consecutive cells
// one legal step apart; their five metrics; loop cutting; and the straight 8-connected cell line
// that joins two distant cells.
#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <vector>

#include "framework/error.hpp"
#include "problems/grid/map.hpp"

namespace pride::grid {

using Path = std::vector<Cell>;

inline constexpr double kSqrt2 = 1.4142135623730951;

/// The five metrics of grid.md, for every path.
struct PathMetrics {
    int cells = 0;           // start and goal included (Wan and Gao 2022, eq. 13)
    double length = 0.0;     // sum of step lengths, 1 or sqrt(2) (Zhang et al. 2025, eq. 8)
    int turns = 0;           // interior cells where the direction changes (Zhang et al. 2025, eq. 11)
    int turn_angle_deg = 0;  // sum of the direction changes, multiples of 45
    int angle_penalty = 0;   // sum of W(theta): 10 below 90, 20 at 90, 50 above (Zhang et al. 2025, eq. 10)
};

/// W(theta) of eq. 10 of Zhang et al. (2025) for a turn of k * 45 degrees.
inline constexpr int angle_penalty_of_turn(int k) {
    return k == 0 ? 0 : (k == 1 ? 10 : (k == 2 ? 20 : 50));
}

/// Metrics of a chain whose consecutive cells are neighbours (legal or not: the penalty decoder
/// scores illegal chains too). A pair of equal consecutive cells counts as no step. With
/// `with_turns` false, turns, turn_angle_deg and angle_penalty are left 0 (the same length, cheaper).
inline PathMetrics metrics(const Path& path, bool with_turns = true) {
    PathMetrics m;
    m.cells = static_cast<int>(path.size());
    int previous = -1;
    for (std::size_t i = 1; i < path.size(); ++i) {
        const int d = direction(path[i - 1], path[i]);
        if (d < 0) continue;
        m.length += is_diagonal(d) ? kSqrt2 : 1.0;
        if (with_turns && previous >= 0 && d != previous) {
            const int k = turn_steps(previous, d);
            ++m.turns;
            m.turn_angle_deg += 45 * k;
            m.angle_penalty += angle_penalty_of_turn(k);
        }
        previous = d;
    }
    return m;
}

/// Why `path` is not a legal path from start to goal on `map`, or "" when it is: non-empty, ends
/// at start and goal, every cell free, every step to one of the 8 neighbours and legal (no corner
/// cutting unless `corner_cutting`).
inline std::string path_violation(const GridMap& map, const Path& path, Cell start, Cell goal,
                                  bool corner_cutting = false) {
    if (path.empty()) return "the path is empty";
    if (!(path.front() == start)) return "the path does not begin at the start";
    if (!(path.back() == goal)) return "the path does not end at the goal";
    for (std::size_t i = 0; i < path.size(); ++i) {
        const Cell c = path[i];
        if (!map.free(c))
            return "cell " + std::to_string(i) + " (" + std::to_string(c.x) + "," + std::to_string(c.y) +
                   ") is blocked or outside";
        if (i == 0) continue;
        const int d = direction(path[i - 1], c);
        if (d < 0) return "cells " + std::to_string(i - 1) + " and " + std::to_string(i) + " are not neighbours";
        if (!map.legal_step(path[i - 1], d, corner_cutting)) return "step " + std::to_string(i) + " cuts a corner";
    }
    return {};
}

/// The violations in steps `first`.. of a chain (step i goes from cell i - 1 to cell i): each step
/// onto a blocked or outside cell, and each step that cuts a corner, counts once.
inline int count_violations(const GridMap& map, const Path& path, std::size_t first = 1, bool corner_cutting = false) {
    int violations = 0;
    for (std::size_t i = std::max<std::size_t>(first, 1); i < path.size(); ++i) {
        if (!map.free(path[i]))
            ++violations;
        else if (!map.legal_step(path[i - 1], direction(path[i - 1], path[i]), corner_cutting))
            ++violations;
    }
    return violations;
}

/// Cuts every loop: when a cell comes back, the cells between its two visits go. `seen` is
/// scratch with one entry per map cell (the position of the cell's kept visit); an entry counts
/// only when the path still holds that cell there, so it never needs clearing.
inline void cut_loops(Path& path, const GridMap& map, std::vector<std::int32_t>& seen) {
    if (seen.size() != map.size()) seen.assign(map.size(), -1);
    std::size_t out = 0;
    for (std::size_t i = 0; i < path.size(); ++i) {
        const Cell c = path[i];
        const std::size_t key = map.index(c);
        const std::int32_t at = seen[key];
        if (at >= 0 && static_cast<std::size_t>(at) < out && path[static_cast<std::size_t>(at)] == c) {
            out = static_cast<std::size_t>(at) + 1;  // keep the first visit, drop the loop
        } else {
            seen[key] = static_cast<std::int32_t>(out);
            path[out++] = c;
        }
    }
    path.resize(out);
}

/// A chain of cells, as map indices, built from segments and cut of its loops: after begin(start)
/// and append(s1), append(s2), ..., to_path gives exactly what cut_loops leaves of the raw chain
/// start + s1 + s2 + ..., cell for cell. It uses the other form of that cut (chronological loop
/// erasure, Lawler): the kept chain is raw[j0], raw[j1], ... with j0 the last visit of raw[0] and
/// j(k+1) the last visit of raw[jk + 1], ending at the last raw cell. So append only stores the raw
/// cells and, per map cell, the position of its latest visit: one write each, no lookup, and no
/// clearing, because to_path reads the visits only of cells this chain wrote. (Cutting as the chain
/// grew cost a lookup per raw cell, and a write and a clear for each cell a later join took back.)
/// Segments may hold a cell twice. No allocation once grown to a map and a raw length (the
/// decoders keep one per copy).
class LoopFreeChain {
  public:
    /// A new chain holding only `start`; the scratch is sized once per map.
    void begin(const GridMap& map, std::uint32_t start) {
        if (last_.size() != map.size() || width_ != map.width()) {
            last_.assign(map.size(), 0);
            cell_of_.resize(map.size());
            for (std::size_t i = 0; i < map.size(); ++i) cell_of_[i] = map.cell(i);
            kept_.resize(map.size());
            width_ = map.width();
        }
        if (raw_.empty()) raw_.resize(map.size());
        raw_[0] = start;
        last_[start] = 0;
        size_ = 1;
    }

    /// Appends a segment (the cells after the chain's last, map indices of begin()'s map). Inlined
    /// into the decoders' loop over joins, where a call cost 12 instructions more per join.
    [[gnu::always_inline]] void append(std::span<const std::uint32_t> segment) {
        const std::size_t n = segment.size();
        if (n >= kMaxRaw - size_) [[unlikely]]
            too_long();
        if (size_ + n > raw_.size()) raw_.resize(std::max(2 * raw_.size(), size_ + n));
        // Raw pointers and a local position: stores through the members could otherwise alias and
        // force reloads in the loop (it runs once per raw cell). The copy goes 16 bytes at a time in
        // the same loop: a memmove call per join cost 20 instructions more.
        const std::uint32_t* const s = segment.data();
        std::uint32_t* const raw = raw_.data() + size_;
        std::uint32_t* const last = last_.data();
        auto at = static_cast<std::uint32_t>(size_);
        std::size_t i = 0;
        for (; i + 4 <= n; i += 4, at += 4) {
            std::memcpy(raw + i, s + i, 16);
            last[s[i]] = at;
            last[s[i + 1]] = at + 1;
            last[s[i + 2]] = at + 2;
            last[s[i + 3]] = at + 3;
        }
        for (; i < n; ++i, ++at) {
            raw[i] = s[i];
            last[s[i]] = at;
        }
        size_ += n;
    }

    /// The chain cut of its loops, as cells (the map must be the one of the last begin()).
    void to_path(Path& out) {
        if (size_ == 0) {  // no begin() yet
            out.clear();
            return;
        }
        const std::uint32_t* const raw = raw_.data();
        const std::uint32_t* const last = last_.data();
        const Cell* const cell_of = cell_of_.data();
        Cell* const kept = kept_.data();
        const std::size_t end = size_ - 1;  // the walk ends on the last raw cell
        std::size_t i = 0, k = 0;
        for (;;) {
            const std::uint32_t c = raw[i];
            kept[k++] = cell_of[c];
            const std::size_t j = last[c];
            // Most cells are not visited again (j == i), so step on from i and branch on j: the
            // next cell's loads then need not wait for this one's. GCC folds the branch into
            // i = j (the same value), which chains every step on two loads; the empty asm hides
            // that i equals j on the common path.
            if (j != i) [[unlikely]]
                i = j;
            else
                asm("" : "+r"(i));
            if (i == end) break;
            ++i;
        }
        out.assign(kept, kept + k);
    }

  private:
    static constexpr std::size_t kMaxRaw = 0xffffffffu;

    /// Positions are 32 bits: a raw chain of 2^32 cells (16 GB of them) is refused, not wrapped.
    [[noreturn, gnu::cold, gnu::noinline]] static void too_long() {
        throw InputError("decode", "the raw chain of joins exceeds 2^32 - 1 cells");
    }

    std::vector<std::uint32_t> raw_;   // the raw chain in raw_[0, size_); grows, never shrinks
    std::vector<std::uint32_t> last_;  // per map cell: the position of its latest visit in raw_
    std::vector<Cell> cell_of_;        // per map cell: the cell (GridMap::cell divides)
    std::vector<Cell> kept_;           // scratch: the kept chain (no cell twice, so at most the map)
    std::size_t size_ = 0;
    int width_ = 0;
};

/// The cells of the straight 8-connected line from a to b (Bresenham), one step at a time:
/// `for (LineSteps line(a, b); !line.done();) { Cell next = line.next(); ... }` visits the cells
/// after a, b included.
class LineSteps {
  public:
    LineSteps(Cell a, Cell b) noexcept
        : c_(a),
          b_(b),
          dx_(std::abs(b.x - a.x)),
          dy_(-std::abs(b.y - a.y)),
          sx_(a.x < b.x ? 1 : -1),
          sy_(a.y < b.y ? 1 : -1),
          err_(dx_ + dy_) {}
    bool done() const noexcept { return c_ == b_; }
    Cell current() const noexcept { return c_; }
    Cell next() noexcept {
        const int e2 = 2 * err_;
        if (e2 >= dy_) {
            err_ += dy_;
            c_.x += sx_;
        }
        if (e2 <= dx_) {
            err_ += dx_;
            c_.y += sy_;
        }
        return c_;
    }

  private:
    Cell c_, b_;
    int dx_, dy_, sx_, sy_, err_;
};

/// Appends the straight 8-connected cell line from a to b, b included and a not.
inline void append_line(Cell a, Cell b, Path& out) {
    for (LineSteps line(a, b); !line.done();) out.push_back(line.next());
}

/// True when the straight line from a to b is a legal join: every cell free, every diagonal step
/// legal (grid.md: "the join is legal only if every cell of that line is free and every diagonal
/// step in it is legal").
inline bool line_is_free(const GridMap& map, Cell a, Cell b, bool corner_cutting = false) {
    if (!map.free(a)) return false;
    for (LineSteps line(a, b); !line.done();) {
        const Cell c = line.current();
        if (!map.legal_move(c, line.next(), corner_cutting)) return false;
    }
    return true;
}

}  // namespace pride::grid

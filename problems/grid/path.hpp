#pragma once
// Paths on a grid (shared/spec/grid.md): the chain of cells from start to goal, consecutive cells
// one legal step apart; their five metrics; loop cutting; and the straight 8-connected cell line
// that joins two distant cells.
#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "problems/grid/map.hpp"

namespace pride::grid {

using Path = std::vector<Cell>;

inline constexpr double kSqrt2 = 1.4142135623730951;

/// The five metrics of grid.md, for every path.
struct PathMetrics {
    int cells = 0;           // start and goal included (file 000 eq. 13)
    double length = 0.0;     // sum of step lengths, 1 or sqrt(2) (file 002 eq. 8)
    int turns = 0;           // interior cells where the direction changes (file 002 eq. 11)
    int turn_angle_deg = 0;  // sum of the direction changes, multiples of 45
    int angle_penalty = 0;   // sum of W(theta): 10 below 90, 20 at 90, 50 above (file 002 eq. 10)
};

/// W(theta) of file 002 eq. 10 for a turn of k * 45 degrees.
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

/// A chain of cells, as map indices, built from segments and cut of its loops as it grows: after
/// begin(start) and append(s1), append(s2), ..., it holds exactly what cut_loops leaves of the raw
/// chain start + s1 + s2 + ..., cell for cell. Each segment must hold no cell twice (a straight
/// line or a shortest path does not). Then the cut of one segment needs no writes for the cells
/// it drops: cutting the raw chain cell by cell, a segment cell can only meet a cell of the chain
/// as it was before the segment, each meeting cuts back to a position below the previous one, so
/// the chain ends cut back to the lowest position any segment cell holds, followed by the segment
/// cells after that one. The cost is one position lookup per raw cell and one write per kept cell,
/// with no hashing and no allocation once sized for a map (the decoders keep one per copy).
class LoopFreeChain {
  public:
    /// A new chain holding only `start`: the marks of the previous chain are cleared (as many writes
    /// as it had cells), the scratch is sized once per map.
    void begin(const GridMap& map, std::uint32_t start) {
        if (position_.size() != map.size() || width_ != map.width()) {
            position_.assign(map.size(), kAbsent);
            chain_.assign(map.size(), 0);
            cell_of_.resize(map.size());
            for (std::size_t i = 0; i < map.size(); ++i) cell_of_[i] = map.cell(i);
            width_ = map.width();
            size_ = 0;
        }
        forget(position_.data(), chain_.data(), 0, size_);
        chain_[0] = start;
        position_[start] = 0;
        size_ = 1;
    }

    /// Appends a segment (cells after the chain's last, none twice) and cuts the loops it closes.
    void append(std::span<const std::uint32_t> segment) {
        // Raw pointers and a local size: stores through them could otherwise alias the members
        // and force reloads in the loops below (they run once per raw cell).
        const std::uint32_t* const s = segment.data();
        const std::size_t n = segment.size();
        std::uint32_t* const position = position_.data();
        std::uint32_t* const chain = chain_.data();
        std::size_t size = size_;
        // The lowest position a segment cell holds (branch-free: in a retrace, where the segment
        // walks back along the chain, almost every cell lowers it).
        std::uint32_t lowest = kAbsent;
        std::size_t i = 0;
        for (; i + 4 <= n; i += 4) {
            const std::uint32_t p0 = position[s[i]], p1 = position[s[i + 1]];
            const std::uint32_t p2 = position[s[i + 2]], p3 = position[s[i + 3]];
            lowest = std::min(lowest, std::min(std::min(p0, p1), std::min(p2, p3)));
        }
        for (; i < n; ++i) lowest = std::min(lowest, position[s[i]]);
        std::size_t from = 0;     // the first segment cell kept: the one after the cell at `lowest`
        if (lowest != kAbsent) {  // cut back to the segment cell's earlier visit, which stays
            from = static_cast<std::size_t>(std::find(s, s + n, chain[lowest]) - s) + 1;
            forget(position, chain, lowest + 1, size);
            size = lowest + 1;
        }
        // The chain holds no cell twice, so it never outgrows the map (a segment breaking the
        // precondition would show here first).
        assert(size + (n - from) <= chain_.size());
        std::copy(s + from, s + n, chain + size);
        auto at = static_cast<std::uint32_t>(size);
        std::size_t k = from;
        for (; k + 4 <= n; k += 4, at += 4) {
            position[s[k]] = at;
            position[s[k + 1]] = at + 1;
            position[s[k + 2]] = at + 2;
            position[s[k + 3]] = at + 3;
        }
        for (; k < n; ++k) position[s[k]] = at++;
        size_ = at;
    }

    std::size_t size() const noexcept { return size_; }
    std::span<const std::uint32_t> cells() const noexcept { return {chain_.data(), size_}; }

    /// The chain as cells (the map must be the one of the last begin()).
    void to_path(Path& out) const {
        out.resize(size_);
        Cell* const o = out.data();
        const Cell* const cell_of = cell_of_.data();
        const std::uint32_t* const chain = chain_.data();
        std::size_t j = 0;
        for (; j + 4 <= size_; j += 4) {
            o[j] = cell_of[chain[j]];
            o[j + 1] = cell_of[chain[j + 1]];
            o[j + 2] = cell_of[chain[j + 2]];
            o[j + 3] = cell_of[chain[j + 3]];
        }
        for (; j < size_; ++j) o[j] = cell_of[chain[j]];
    }

  private:
    static constexpr std::uint32_t kAbsent = 0xffffffffu;

    /// Marks the cells chain[from..to) absent (unrolled by 4: it runs once per dropped cell).
    [[gnu::always_inline]] static void forget(std::uint32_t* position, const std::uint32_t* chain, std::size_t from,
                                              std::size_t to) {
        std::size_t j = from;
        for (; j + 4 <= to; j += 4) {
            position[chain[j]] = kAbsent;
            position[chain[j + 1]] = kAbsent;
            position[chain[j + 2]] = kAbsent;
            position[chain[j + 3]] = kAbsent;
        }
        for (; j < to; ++j) position[chain[j]] = kAbsent;
    }

    std::vector<std::uint32_t> chain_;     // the chain's cells in chain_[0, size_)
    std::vector<std::uint32_t> position_;  // per map cell: its position in the chain, or kAbsent
    std::vector<Cell> cell_of_;            // per map cell: the cell (GridMap::cell divides)
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

#pragma once
// Paths on a grid (shared/spec/grid.md): the chain of cells from start to goal, consecutive cells
// one legal step apart; their five metrics; loop cutting; and the straight 8-connected cell line
// that joins two distant cells.
#include <algorithm>
#include <cmath>
#include <cstdint>
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
        if (!((map.moves(map.index(c), corner_cutting) >> direction(c, line.next())) & 1u)) return false;
    }
    return true;
}

}  // namespace pride::grid

#pragma once
// Feasible paths from Wan and Gao's (2022) rough-set rules (section 2.2): a depth-first walk whose next cell
// is the move the minimal rules of grid_rule_book() prescribe for the current neighbourhood. Same
// contract as RandomWalker (walk.hpp): a legal path that never repeats a cell, false exactly when the
// goal cannot be reached, each cell entered at most once per walk.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "framework/random.hpp"
#include "problems/grid/map.hpp"
#include "problems/grid/path.hpp"
#include "problems/grid/rough_rules.hpp"
#include "problems/grid/search_arrays.hpp"

namespace pride::grid {

class RuleWalker {
  public:
    /// Draw the goal direction X1 between the two directions that bracket the goal angle (see
    /// goal_direction(c, g, rng)); false: always the nearest one, and walks differ only where two
    /// neighbours are equally far off it.
    bool jitter = true;

    /// A legal path from s to g in `out` (no cell twice), or false when g cannot be reached.
    bool walk(const GridMap& map, Cell s, Cell g, Rng& rng, Path& out, bool corner_cutting = false) {
        const GridRuleBook& book = grid_rule_book();
        out.clear();
        entered_ = 0;
        if (!map.free(s) || !map.free(g)) return false;
        visited_.begin(map.size());
        out.push_back(s);
        visited_.visit(map.index(s));
        entered_ = 1;
        std::array<int, 8> values{};
        while (!out.empty()) {
            const Cell c = out.back();
            if (c == g) return true;
            const int d1 = jitter ? goal_direction(c, g, rng) : goal_direction(c, g);
            for (int k = 1; k <= 8; ++k) {
                const int d = neighbour_direction(d1, k);
                const Cell n{c.x + kDx[d], c.y + kDy[d]};
                values[k - 1] = !map.legal_step(c, d, corner_cutting) ? kBlocked
                                : visited_.visited(map.index(n))      ? kVisited
                                                                      : kOpen;
            }
            int k = book.decide(values);
            // Equally good neighbours (the same angle off the goal direction): the rules name the
            // clockwise one, the walk draws between the two so that walks differ.
            if ((k == 2 && values[7] == kOpen) || (k == 3 && values[6] == kOpen)) {
                if (rng.below(2) == 1) k = 10 - k;
            }
            // Project decision: Wan and Gao (2022) say only "backtrack", but a walk that backs up while a
            // backward-facing neighbour is still free and unvisited can strand itself at the start
            // with the goal reachable (a start in a pocket facing the goal), so "back" first tries
            // X4/X6 (drawn when both are open), then X5, and only then steps back one cell.
            if (k == kBack) k = detour(values, rng);
            if (k == 0) {  // dead end: back up one cell; it stays visited
                out.pop_back();
                continue;
            }
            const int d = neighbour_direction(d1, k);
            const Cell n{c.x + kDx[d], c.y + kDy[d]};
            visited_.visit(map.index(n));
            out.push_back(n);
            ++entered_;
        }
        return false;
    }

    /// The cells the last walk entered, backtracked ones included (at most the free cells).
    std::size_t cells_entered() const noexcept { return entered_; }

  private:
    /// A backward-facing free unvisited neighbour (X4 or X6, then X5) as k, or 0 when none.
    static int detour(const std::array<int, 8>& values, Rng& rng) {
        const bool x4 = values[3] == kOpen, x6 = values[5] == kOpen;
        if (x4 && x6) return rng.below(2) == 0 ? 4 : 6;
        if (x4) return 4;
        if (x6) return 6;
        return values[4] == kOpen ? 5 : 0;
    }

    VisitMarks visited_;  // generation stamps: no clearing between walks
    std::size_t entered_ = 0;
};

}  // namespace pride::grid

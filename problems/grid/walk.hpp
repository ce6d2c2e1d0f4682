#pragma once
// Feasible random paths: a randomised walk with a taboo list and backtracking from dead ends
// (Cai and Du 2021, section 3.2, Zhang et al. (2025) step 2), biased towards the goal. A depth-first search whose
// next cell is drawn by roulette: every visited cell stays taboo, so the walk ends at the goal
// whenever the goal can be reached, and reports when it cannot, after at most one visit per cell.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "framework/random.hpp"
#include "problems/grid/map.hpp"
#include "problems/grid/path.hpp"
#include "problems/grid/planners/astar.hpp"
#include "problems/grid/search_arrays.hpp"

namespace pride::grid {

/// The walk itself, for every walker: a depth-first search with a taboo list whose next cell is
/// drawn by roulette among the free, unvisited, legal neighbours. `weights_at(c)` returns, for the
/// current cell c, the weight of a step: w(n, d) for the neighbour n in direction d. A dead end
/// backs up one cell (it stays taboo).
class TabooRouletteWalk {
  public:
    template <class WeightsAt>
    bool walk(const GridMap& map, Cell s, Cell g, Rng& rng, Path& out, bool corner_cutting, WeightsAt&& weights_at) {
        out.clear();
        if (!map.free(s) || !map.free(g)) return false;
        visited_.begin(map.size());
        out.push_back(s);
        visited_.visit(map.index(s));
        while (!out.empty()) {
            const Cell c = out.back();
            if (c == g) return true;
            const auto weight = weights_at(c);
            int count = 0;
            double total = 0.0;
            // The map's legal-step mask (one byte) and index offsets instead of up to three cell
            // tests per direction: the same neighbours in the same order, so the same draws.
            const std::size_t at = map.index(c);
            const std::uint8_t legal = map.moves(at, corner_cutting);
            for (int d = 0; d < 8; ++d) {
                if (!(legal & (1u << d))) continue;
                const std::size_t ni = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(at) + map.offset(d));
                if (visited_.visited(ni)) continue;
                const Cell n{c.x + kDx[d], c.y + kDy[d]};
                const double w = weight(n, d);
                candidates_[count] = n;
                indices_[count] = ni;
                weights_[count++] = w;
                total += w;
            }
            if (count == 0) {  // dead end: back up one cell; it stays taboo
                out.pop_back();
                continue;
            }
            double r = rng.uniform() * total;
            int pick = 0;
            while (pick + 1 < count && r >= weights_[pick]) r -= weights_[pick++];
            visited_.visit(indices_[pick]);
            out.push_back(candidates_[pick]);
        }
        return false;
    }

  private:
    VisitMarks visited_;  // generation stamps: no clearing between walks
    // Scratch of one step; zeroed only so that copying a fresh walk reads no indeterminate value.
    Cell candidates_[8]{};
    std::size_t indices_[8]{};
    double weights_[8]{};
};

/// How a random walk weighs the neighbours it draws from.
///   eq10:       Cai and Du's (2021) eq. 10 as this project reads it (the text around the equation is lost;
///               the project's decision says only "biased towards the goal"): the fitness of a neighbour n is
///               D - dist(n, goal), D the map's diagonal sqrt(W^2 + H^2) and dist the Euclidean
///               distance, used as its roulette weight (always > 0: no cell is D from another);
///   octile_exp: this project's earlier stand-in, exp(-bias * (the change of the octile distance
///               to the goal)), a much stronger pull (a step away weighs e^-4 of one towards).
enum class GoalBias { eq10, octile_exp };

class RandomWalker {
  public:
    GoalBias rule = GoalBias::octile_exp;
    /// octile_exp's bias: 0 walks blindly.
    double bias = 2.0;

    /// A legal path from s to g in `out` (no cell twice), or false when g cannot be reached.
    bool walk(const GridMap& map, Cell s, Cell g, Rng& rng, Path& out, bool corner_cutting = false) {
        if (rule == GoalBias::eq10) {
            const double diagonal = std::hypot(static_cast<double>(map.width()), static_cast<double>(map.height()));
            return walk_.walk(map, s, g, rng, out, corner_cutting, [&](Cell) {
                return [&](Cell n, int) { return diagonal - std::hypot(n.x - g.x, n.y - g.y); };
            });
        }
        return walk_.walk(map, s, g, rng, out, corner_cutting, [&](Cell c) {
            const double here = octile(c, g);
            return [&, here](Cell n, int) { return std::exp(-bias * (octile(n, g) - here)); };
        });
    }

  private:
    TabooRouletteWalk walk_;
};

}  // namespace pride::grid

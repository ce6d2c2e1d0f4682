#pragma once
// The `chain` encoding of shared/spec/grid.md: the individual is the cell chain itself, searched
// with discrete operators, not through a box. ChainSpace turns a GridProblem into a ChainProblem
// (framework/chain.hpp), so the GA runs on paths without a line of grid code of its own:
//   random_chain: the goal-biased random walk with taboo list and backtracking (walk.hpp);
//   crossover:    at a common cell (start and goal excluded), chosen uniformly among the cells the
//                 two parents share; the parents swap their tails there (spec: "crossover at a
//                 common cell"); loops in the children are cut;
//   mutate:       two distinct cells of the chain chosen uniformly, the segment between them
//                 replaced by a new random walk between the same two cells (spec: "mutation by
//                 replacing the segment between two random cells of the path with a new random
//                 feasible segment"); loops are cut.
// Every operator keeps the chain legal: joins happen at shared cells, walks take legal steps.
#include <cstdint>
#include <span>
#include <vector>

#include "framework/random.hpp"
#include "problems/grid/grid_problem.hpp"
#include "problems/grid/walk.hpp"

namespace pride::grid {

template <class Objective>
class ChainSpace {
  public:
    using chain_type = Path;

    explicit ChainSpace(GridProblem<Objective> problem) : problem_(std::move(problem)) {}

    const GridProblem<Objective>& problem() const noexcept { return problem_; }
    double evaluate(const Path& chain) const { return problem_.evaluate(chain); }

    void random_chain(Rng& rng, Path& out) {
        walker_.walk(problem_.map(), problem_.start(), problem_.goal(), rng, out, problem_.corner_cutting());
    }

    bool crossover(Path& a, Path& b, Rng& rng) {
        const GridMap& map = problem_.map();
        if (position_.size() != map.size()) position_.assign(map.size(), -1);
        // Interior cells of b by position (chains hold no cell twice: every operator cuts loops).
        for (std::size_t j = 1; j + 1 < b.size(); ++j) position_[map.index(b[j])] = static_cast<std::int32_t>(j);
        common_.clear();
        for (std::size_t i = 1; i + 1 < a.size(); ++i) {
            const std::int32_t j = position_[map.index(a[i])];
            if (j > 0 && static_cast<std::size_t>(j) + 1 < b.size() && b[static_cast<std::size_t>(j)] == a[i])
                common_.emplace_back(i, static_cast<std::size_t>(j));
        }
        for (std::size_t j = 1; j + 1 < b.size(); ++j) position_[map.index(b[j])] = -1;
        if (common_.empty()) return false;
        const auto [i, j] = common_[rng.below(common_.size())];
        tail_.assign(a.begin() + static_cast<std::ptrdiff_t>(i) + 1, a.end());
        a.resize(i + 1);
        a.insert(a.end(), b.begin() + static_cast<std::ptrdiff_t>(j) + 1, b.end());
        b.resize(j + 1);
        b.insert(b.end(), tail_.begin(), tail_.end());
        cut_loops(a, map, seen_);
        cut_loops(b, map, seen_);
        return true;
    }

    void mutate(Path& c, Rng& rng) {
        if (c.size() < 3) return;
        std::size_t i = rng.below(c.size()), j = rng.below(c.size() - 1);
        if (j >= i) ++j;  // two distinct positions
        if (i > j) std::swap(i, j);
        walker_.walk(problem_.map(), c[i], c[j], rng, segment_, problem_.corner_cutting());
        // c[i] and c[j] lie on one legal chain, so the walk between them always arrives.
        tail_.assign(c.begin() + static_cast<std::ptrdiff_t>(j) + 1, c.end());
        c.resize(i);
        c.insert(c.end(), segment_.begin(), segment_.end());
        c.insert(c.end(), tail_.begin(), tail_.end());
        cut_loops(c, problem_.map(), seen_);
    }

  private:
    GridProblem<Objective> problem_;
    RandomWalker walker_;  // scratch below, reused: no allocation once the run has warmed up
    std::vector<std::int32_t> position_, seen_;
    std::vector<std::pair<std::size_t, std::size_t>> common_;
    Path tail_, segment_;
};

}  // namespace pride::grid

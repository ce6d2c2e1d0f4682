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
// Initial chains come from those random walks, or, with set_init(Walks::sitp), from file 002's SITP
// walks (sitp.hpp), whose transition-point band cycles 0, 1, 2 over the chains a space makes, so
// that a population of N has N / 3 per band (step 1 of section 2.2).
// The optional capabilities of framework/chain.hpp (file 002's IQGA operators, iqga_moves.hpp):
//   region(c)                      eqs. 14-15, 0..2 (RegionOf);
//   crossover_two_point(a, b, rng) fig. 7 (TwoPointCrossover);
//   mutate(k, c, rng, badness)     section 2.4.3: 0 deletion, 1 mid-point, 2 turning point
//                                  (NumberedMutations);
//   regenerate(c, i, j, rng)       the SITP walk between c[i] and c[j] (SegmentRegeneration);
//   length(c)                      the path's length, eq. 8 (ChainLength).
// File 003's whale moves (whale_chain.hpp), for HS-WOA on grids:
//   toward(c, t, w, rng)           c's section regenerated within a window around t's (TowardMoves);
//   shorten(c)                     the line-of-sight shortcut, kept when it does not raise the
//                                  objective (a Bresenham join may add turns) (Shortening).
// Every operator keeps the chain legal: joins happen at shared cells, walks take legal steps.
#include <cstdint>
#include <span>
#include <vector>

#include "framework/error.hpp"
#include "framework/random.hpp"
#include "problems/grid/grid_problem.hpp"
#include "problems/grid/iqga_moves.hpp"
#include "problems/grid/sitp.hpp"
#include "problems/grid/walk.hpp"
#include "problems/grid/whale_chain.hpp"

namespace pride::grid {

template <class Objective>
class ChainSpace {
  public:
    using chain_type = Path;

    explicit ChainSpace(GridProblem<Objective> problem) : problem_(std::move(problem)) {}

    const GridProblem<Objective>& problem() const noexcept { return problem_; }
    double evaluate(const Path& chain) const { return problem_.evaluate(chain); }

    /// Which walks make random chains: Walks::random (the default) or Walks::sitp.
    Walks init() const noexcept { return init_; }
    void set_init(Walks w) {
        require(w == Walks::random || w == Walks::sitp, "init", "chains start from random walks or SITP walks");
        init_ = w;
    }

    void random_chain(Rng& rng, Path& out) {
        if (init_ == Walks::sitp) {
            const int band = static_cast<int>(sitp_count_++ % 3);
            moves_.sitp.walk(
                problem_.map(), problem_.start(), problem_.goal(), rng, out, problem_.corner_cutting(), band,
                [&](Cell c) { return problem_.reachable(c); }, [&](const Path& s) { return problem_.evaluate(s); });
            return;
        }
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

    // The IQGA capabilities (framework/chain.hpp; iqga_moves.hpp says how).
    double length(const Path& c) const { return metrics(c, false).length; }  // ChainLength
    std::size_t region_count() const noexcept { return 3; }
    std::size_t region(const Path& c) const { return iqga_path_region(problem_.start(), problem_.goal(), c); }
    bool crossover_two_point(Path& a, Path& b, Rng& rng) { return moves_.crossover(problem_, a, b, rng); }
    std::size_t mutation_count() const noexcept { return IqgaMoves::kMutations; }
    void mutate(std::size_t k, Path& c, Rng& rng, double badness = 0.0) { moves_.mutate(problem_, k, c, rng, badness); }
    bool regenerate(Path& c, std::size_t i, std::size_t j, Rng& rng) {
        return moves_.regenerate(problem_, c, i, j, rng);
    }

    // The whale capabilities (framework/chain.hpp; whale_chain.hpp says how).
    void toward(Path& c, const Path& target, double w, Rng& rng) {
        whale_.toward(problem_.map(), c, target, w, rng, problem_.corner_cutting());
    }
    void shorten(Path& c) {
        whale_.shortcut(problem_.map(), c, shortened_, problem_.corner_cutting());
        if (problem_.evaluate(shortened_) <= problem_.evaluate(c)) c.swap(shortened_);
    }

  private:
    GridProblem<Objective> problem_;
    Walks init_ = Walks::random;
    std::uint64_t sitp_count_ = 0;  // SITP chains made so far: their band is sitp_count_ % 3
    IqgaMoves moves_;
    RandomWalker walker_;  // scratch below, reused: no allocation once the run has warmed up
    std::vector<std::int32_t> position_, seen_;
    std::vector<std::pair<std::size_t, std::size_t>> common_;
    Path tail_, segment_;
    WhaleChainMoves whale_;
    Path shortened_;
};

}  // namespace pride::grid

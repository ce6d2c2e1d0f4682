#pragma once
// The `chain` encoding of docs/grid.md: the individual is the cell chain itself, searched
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
// Initial chains come from those random walks, or, with set_init(Walks::sitp), from Zhang et al.'s (2025) SITP
// walks (sitp.hpp), whose transition-point band cycles 0, 1, 2 over the chains a space makes, so
// that a population of N has N / 3 per band (step 1 of section 2.2).
// The optional capabilities of framework/chain.hpp (Zhang et al.'s (2025) IQGA operators, iqga_moves.hpp):
//   region(c)                      eqs. 14-15, 0..2 (RegionOf);
//   crossover_two_point(a, b, rng) fig. 7 (TwoPointCrossover);
//   mutate(k, c, rng, badness)     section 2.4.3: 0 deletion, 1 mid-point, 2 turning point
//                                  (NumberedMutations);
//   regenerate(c, i, j, rng)       the SITP walk between c[i] and c[j] (SegmentRegeneration);
//   length(c)                      the path's length, eq. 8 (ChainLength).
// Cai and Du's (2021) whale moves (whale_chain.hpp), for HS-WOA on grids:
//   toward(c, t, w, rng)           c's section regenerated within a window around t's (TowardMoves);
//   shorten(c)                     the space's shortcut on c (Shortening).
// Every operator keeps the chain legal: joins happen at shared cells, walks take legal steps.
//
// Settings of the space, the same for every algorithm that plans on it (spec: an operator that
// improves solutions belongs to the space, not to the algorithm that first used it):
//   shortcut  none | line | elbow: applied to every chain an operator makes or changes (random
//             chains, children, mutants, regenerated and moved chains), at no evaluation: `line` is
//             grid.md's straight line-of-sight join (Cai and Du 2021), `elbow` this project's addition (a
//             one-turn octile elbow tried first, the straight line after); neither lengthens a
//             chain. With keep_if_not_worse the shortened chain replaces the chain only when its
//             objective is not higher, which costs two counted evaluations whenever it differs;
//   walks     the random walk's bias (walk.hpp: Cai and Du's (2021) eq. 10 or the octile exp rule);
//   sitp      the transition column (random, as Zhang et al.'s (2025) text under eq. 3 says, or eq. 3's
//             midpoint) and how a segment's N/8 walks are ranked (by the objective, Zhang et al.'s (2025)
//             reading, each call a counted evaluation; or by length, no evaluation).
// An operator that scores a chain by the objective does so only through the `score` it is given
// (framework/counted_chain.hpp: the run's evaluation guard); the forms without it refuse to.
#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

#include "framework/error.hpp"
#include "framework/random.hpp"
#include "problems/grid/grid_problem.hpp"
#include "problems/grid/iqga_moves.hpp"
#include "problems/grid/sitp.hpp"
#include "problems/grid/walk.hpp"
#include "problems/grid/whale_chain.hpp"

namespace pride::grid {

/// The shortcut a chain space applies to every chain its operators make (see the header).
enum class Shortcut { none, line, elbow };
/// How SITP ranks a segment's walks: by the objective (counted evaluations) or by length.
enum class SitpScore { objective, length };

/// The score of the unscored operator forms: scoring by the objective there is a bug (an
/// evaluation outside the budget), so it throws instead.
struct NoScore {
    [[noreturn]] double operator()(const Path&) const {
        throw std::logic_error(
            "chain space: an operator scored a chain by the objective outside the run's evaluation guard "
            "(call it through CountedChains, framework/counted_chain.hpp)");
    }
};

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
    Shortcut shortcut() const noexcept { return shortcut_; }
    bool keeps_if_not_worse() const noexcept { return keep_if_not_worse_; }
    void set_shortcut(Shortcut s, bool keep_if_not_worse = false) noexcept {
        shortcut_ = s;
        keep_if_not_worse_ = keep_if_not_worse;
    }
    void set_walks(GoalBias rule) noexcept { walker_.rule = rule; }
    GoalBias walks() const noexcept { return walker_.rule; }
    /// SITP's transition column (midpoint: eq. 3's formula; else a random column between start and
    /// goal, the text's reading) and the ranking of a segment's walks.
    void set_sitp(bool midpoint_column, SitpScore score) noexcept {
        moves_.sitp.midpoint_column = midpoint_column;
        sitp_score_ = score;
    }
    bool sitp_midpoint() const noexcept { return moves_.sitp.midpoint_column; }
    SitpScore sitp_score() const noexcept { return sitp_score_; }

    template <class Score>
    void random_chain(Rng& rng, Path& out, Score&& score) {
        if (init_ == Walks::sitp) {
            const int band = static_cast<int>(sitp_count_++ % 3);
            moves_.sitp.walk(
                problem_.map(), problem_.start(), problem_.goal(), rng, out, problem_.corner_cutting(), band,
                [&](Cell c) { return problem_.reachable(c); }, segment_score(score));
        } else {
            walker_.walk(problem_.map(), problem_.start(), problem_.goal(), rng, out, problem_.corner_cutting());
        }
        polish(out, score);
    }
    void random_chain(Rng& rng, Path& out) { random_chain(rng, out, NoScore{}); }

    template <class Score>
    bool crossover(Path& a, Path& b, Rng& rng, Score&& score) {
        if (!cross_at_one_cell(a, b, rng)) return false;
        polish(a, score);
        polish(b, score);
        return true;
    }
    bool crossover(Path& a, Path& b, Rng& rng) { return crossover(a, b, rng, NoScore{}); }

    template <class Score>
    void mutate(Path& c, Rng& rng, Score&& score) {
        replace_segment(c, rng);
        polish(c, score);
    }
    void mutate(Path& c, Rng& rng) { mutate(c, rng, NoScore{}); }

    // The IQGA capabilities (framework/chain.hpp; iqga_moves.hpp says how).
    double length(const Path& c) const { return metrics(c, false).length; }  // ChainLength
    std::size_t region_count() const noexcept { return 3; }
    std::size_t region(const Path& c) const { return iqga_path_region(problem_.start(), problem_.goal(), c); }
    template <class Score>
    bool crossover_two_point(Path& a, Path& b, Rng& rng, Score&& score) {
        if (!moves_.crossover(problem_, a, b, rng)) return false;
        polish(a, score);
        polish(b, score);
        return true;
    }
    bool crossover_two_point(Path& a, Path& b, Rng& rng) { return crossover_two_point(a, b, rng, NoScore{}); }
    std::size_t mutation_count() const noexcept { return IqgaMoves::kMutations; }
    template <class Score>
    void mutate(std::size_t k, Path& c, Rng& rng, double badness, Score&& score) {
        moves_.mutate(problem_, k, c, rng, badness, segment_score(score));
        polish(c, score);
    }
    void mutate(std::size_t k, Path& c, Rng& rng, double badness = 0.0) { mutate(k, c, rng, badness, NoScore{}); }
    template <class Score>
    bool regenerate(Path& c, std::size_t i, std::size_t j, Rng& rng, Score&& score) {
        if (!moves_.regenerate(problem_, c, i, j, rng, segment_score(score))) return false;
        polish(c, score);
        return true;
    }
    bool regenerate(Path& c, std::size_t i, std::size_t j, Rng& rng) { return regenerate(c, i, j, rng, NoScore{}); }

    // The whale capabilities (framework/chain.hpp; whale_chain.hpp says how).
    template <class Score>
    void toward(Path& c, const Path& target, double w, Rng& rng, Score&& score) {
        whale_.toward(problem_.map(), c, target, w, rng, problem_.corner_cutting());
        polish(c, score);
    }
    void toward(Path& c, const Path& target, double w, Rng& rng) { toward(c, target, w, rng, NoScore{}); }
    template <class Score>
    void shorten(Path& c, Score&& score) {
        polish(c, score);
    }
    void shorten(Path& c) { shorten(c, NoScore{}); }

  private:
    /// SITP's ranking of a segment's walks: the objective through `score`, or the length.
    template <class Score>
    auto segment_score(Score& score) const {
        return [this, &score](const Path& segment) {
            return sitp_score_ == SitpScore::length ? metrics(segment, false).length : score(segment);
        };
    }
    /// The space's shortcut on c (see the header); `score` only with keep_if_not_worse.
    template <class Score>
    void polish(Path& c, Score& score) {
        if (shortcut_ == Shortcut::none) return;
        whale_.shortcut(problem_.map(), c, shortened_, problem_.corner_cutting(), shortcut_ == Shortcut::elbow);
        if (shortened_ == c) return;  // nothing to cut: nothing to compare either
        if (keep_if_not_worse_ && !(score(shortened_) <= score(c))) return;
        c.swap(shortened_);
    }

    bool cross_at_one_cell(Path& a, Path& b, Rng& rng) {
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

    void replace_segment(Path& c, Rng& rng) {
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

    GridProblem<Objective> problem_;
    Walks init_ = Walks::random;
    Shortcut shortcut_ = Shortcut::none;
    bool keep_if_not_worse_ = false;
    SitpScore sitp_score_ = SitpScore::objective;
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

#pragma once
// Grid planning with several objectives: two to four of length, turns, angle penalty
// (Zhang et al.'s (2025) eqs. 8, 11 and 10) and clearance (clearance.hpp), in that order (pareto.hpp's
// Criteria), the same criteria whose exact front ParetoSearch computes. Searched as a box through
// an encoding (`line` or `free`, encodings.hpp): MultiObjectivePaths is a MultiObjectiveProblem
// (framework/multi_objective.hpp), so every multi-objective algorithm plans on it unchanged.
//
// A decoded chain with violations (the penalty connector lets blocked cells and corner cuts
// through) gets P = 64 W H + 64 per violation added to every objective: a loop-free chain (the
// encodings cut loops) has at most W H cells, so each of its criteria is below 64 W H (length
// sqrt(2), turns 1, angle penalty 50, clearance B + 1 <= 64 per cell), and a chain with a violation
// is dominated by every legal path.
//
// MultiObjectiveChains is the same criteria on the `chain` encoding (chain.hpp): the chain space's
// operators (random or SITP walks, crossover at a common cell, the GA's and IQGA's mutations, the
// space's shortcut) make only legal chains, so no penalty is needed. Where the space would rank
// by a single objective (SITP's choice among a segment's walks, a shortcut kept only when not
// worse) a front has no such value: SITP ranks by length and a kept-if-not-worse shortcut is
// refused.
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "problems/grid/chain.hpp"
#include "problems/grid/clearance.hpp"
#include "problems/grid/grid_problem.hpp"
#include "problems/grid/objectives.hpp"
#include "problems/grid/pareto.hpp"
#include "problems/grid/path.hpp"

namespace pride::grid {

/// The chosen criteria of a path, in the canonical order.
class PathCriteria {
  public:
    /// The clearance costs are computed here when `criteria` has clearance (InputError("clearance",
    /// ...) for bad parameters); InputError("objectives", ...) for fewer than two criteria.
    PathCriteria(const GridMap& map, const Criteria& criteria, const ClearanceParams& params = {})
        : criteria_(criteria) {
        require(criteria.count() >= 2, "objectives", "a multi-objective grid problem needs at least two criteria");
        if (criteria.clearance) clearance_ = std::make_shared<const MapClearance>(map, params);
    }

    std::size_t count() const noexcept { return static_cast<std::size_t>(criteria_.count()); }
    const Criteria& criteria() const noexcept { return criteria_; }
    /// Empty unless clearance is a criterion.
    const std::shared_ptr<const MapClearance>& clearance() const noexcept { return clearance_; }

    /// f <- the criteria of `path`, f.size() == count(). The length is a + b sqrt(2) from the
    /// numbers of orthogonal and diagonal steps (StepCounts::value, as the exact front's), not a
    /// sum in the order of the steps: two paths of equal length then have equal bits, and neither
    /// dominates the other by a rounding.
    void operator()(const Path& path, std::span<double> f) const noexcept {
        const PathMetrics m = metrics(path, criteria_.turns || criteria_.angle_penalty);
        std::size_t k = 0;
        if (criteria_.length) {
            StepCounts steps;
            for (std::size_t i = 1; i < path.size(); ++i) {
                const int d = direction(path[i - 1], path[i]);
                if (d >= 0) ++(is_diagonal(d) ? steps.diagonal : steps.straight);
            }
            f[k++] = steps.value();
        }
        if (criteria_.turns) f[k++] = m.turns;
        if (criteria_.angle_penalty) f[k++] = m.angle_penalty;
        if (criteria_.clearance) f[k++] = static_cast<double>(clearance_cost(*clearance_, path));
    }

  private:
    Criteria criteria_;
    std::shared_ptr<const MapClearance> clearance_;  // shared: problems are copied per run
};

/// A grid problem with the criteria as its objectives, seen through `Encoding` as a box.
template <class Encoding>
class MultiObjectivePaths {
  public:
    using Carrier = GridProblem<CellsObjective>;  // the map, start, goal and reachability the encoding reads

    MultiObjectivePaths(Carrier problem, Encoding encoding, PathCriteria criteria)
        : problem_(std::move(problem)), encoding_(std::move(encoding)), criteria_(std::move(criteria)) {
        const auto& map = problem_.map();
        penalty_ = 64.0 * static_cast<double>(map.width()) * static_cast<double>(map.height()) + 64.0;
    }

    std::size_t dimension() const { return encoding_.dimension(problem_); }
    std::span<const double> lower() const { return encoding_.lower(problem_); }
    std::span<const double> upper() const { return encoding_.upper(problem_); }
    std::size_t objectives() const noexcept { return criteria_.count(); }

    /// One evaluation: decodes g and writes its criteria (plus P per violation) into f.
    void evaluate(std::span<const double> g, std::span<double> f) {
        if (calls_) calls_->fetch_add(1, std::memory_order_relaxed);
        const DecodedPath& d = encoding_.decode(problem_, g);
        criteria_(d.path, f);
        if (d.violations > 0)
            for (double& v : f) v += penalty_ * d.violations;
    }

    /// The path g stands for and whether it is legal (no violation); not an evaluation (the run's
    /// result is reported with it).
    std::pair<Path, bool> path(std::span<const double> g) {
        const DecodedPath& d = encoding_.decode(problem_, g);
        return {d.path, d.violations == 0};
    }

    /// Counts every evaluation in `calls` (shared by the copies), a check from outside of a run's count.
    void count_calls(std::shared_ptr<std::atomic<std::int64_t>> calls) noexcept { calls_ = std::move(calls); }

    const Carrier& problem() const noexcept { return problem_; }
    const PathCriteria& criteria() const noexcept { return criteria_; }
    double penalty() const noexcept { return penalty_; }

  private:
    Carrier problem_;
    Encoding encoding_;
    PathCriteria criteria_;
    double penalty_ = 0.0;
    std::shared_ptr<std::atomic<std::int64_t>> calls_;
};

/// A grid problem with the criteria as its objectives, searched on cell chains with the chain
/// space's operators (a MultiObjectiveChainProblem, framework/multi_objective.hpp).
class MultiObjectiveChains {
  public:
    using chain_type = Path;
    using Space = ChainSpace<CellsObjective>;

    /// InputError("shortcut_keep", ...) when the space keeps a shortcut only if not worse.
    MultiObjectiveChains(Space space, PathCriteria criteria)
        : space_(std::move(space)), criteria_(std::move(criteria)) {
        space_.set_sitp(space_.sitp_midpoint(), SitpScore::length);
        configured();
    }

    std::size_t objectives() const noexcept { return criteria_.count(); }

    /// One evaluation: the criteria of chain c (legal by construction).
    void evaluate(const Path& c, std::span<double> f) {
        if (calls_) calls_->fetch_add(1, std::memory_order_relaxed);
        criteria_(c, f);
    }

    void random_chain(Rng& rng, Path& out) { space_.random_chain(rng, out); }
    bool crossover(Path& a, Path& b, Rng& rng) { return space_.crossover(a, b, rng); }
    void mutate(Path& c, Rng& rng) { space_.mutate(c, rng); }
    // IQGA's numbered mutations (framework/chain.hpp's NumberedMutations).
    std::size_t mutation_count() const noexcept { return space_.mutation_count(); }
    void mutate(std::size_t k, Path& c, Rng& rng, double badness = 0.0) { space_.mutate(k, c, rng, badness); }

    /// The space's settings (chain.hpp); call configured() after changing them.
    Space& space() noexcept { return space_; }
    const Space& space() const noexcept { return space_; }
    /// InputError for the settings that need a single objective (the header says why).
    void configured() const {
        require(!space_.keeps_if_not_worse(), "shortcut_keep",
                "a front has no single objective to compare a shortcut with: keep it always or not at all");
        require(space_.sitp_score() == SitpScore::length, "sitp_score",
                "a front has no single objective to rank SITP's walks by: use length");
    }

    void count_calls(std::shared_ptr<std::atomic<std::int64_t>> calls) noexcept { calls_ = std::move(calls); }
    const GridProblem<CellsObjective>& problem() const noexcept { return space_.problem(); }
    const PathCriteria& criteria() const noexcept { return criteria_; }

  private:
    Space space_;
    PathCriteria criteria_;
    std::shared_ptr<std::atomic<std::int64_t>> calls_;
};

}  // namespace pride::grid

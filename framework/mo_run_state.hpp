#pragma once
// The run driver of multi-objective algorithms, as run_state.hpp is of the others: the
// evaluation guard (exact budget; a point with a NaN or +-inf objective gets +inf in every one,
// worse than every point with finite values), the
// stopping rules, the evaluations after each iteration, the observer calls and the wall clock.
// A run's result is the non-dominated set of its final population, points (or chains) and values.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "framework/error.hpp"
#include "framework/multi_objective.hpp"
#include "framework/problem.hpp"
#include "framework/random.hpp"
#include "framework/run_state.hpp"
#include "framework/termination.hpp"

namespace pride {

/// Population: Matrix for boxes (one column per point), std::vector<chain> for chains.
template <class Population>
struct BasicMultiObjectiveResult {
    Population x;  // the non-dominated members of the final population
    Matrix f;      // their objective values, M rows, one column per member of x
    std::int64_t evaluations = 0;
    std::int64_t iterations = 0;  // completed iterations after the initial population
    /// history_evaluations[k]: the evaluations spent when iteration k ended (k = 0: the initial
    /// population).
    std::vector<std::int64_t> history_evaluations;
    double wall_ms = 0.0;
    // Problems with constraints: each member's violation (0: feasible; empty without constraints),
    // and the evaluation that first found a feasible point (empty: none, or no constraints).
    std::vector<double> violation;
    std::optional<std::int64_t> first_feasible;
};
using MultiObjectiveResult = BasicMultiObjectiveResult<Matrix>;

/// What an observer of a multi-objective run sees at the end of each iteration.
template <class Population>
struct BasicMultiObjectiveIterationView {
    std::int64_t iteration;  // 0 = the initial population
    std::int64_t evaluations;
    const Population& population;  // one column (or chain) per individual
    const Matrix& values;          // M rows, one column per individual (+inf where not evaluated)
};
using MultiObjectiveIterationView = BasicMultiObjectiveIterationView<Matrix>;

class MultiObjectiveRunState {
  public:
    MultiObjectiveRunState(const Termination& termination, std::size_t objectives)
        : termination_(termination),
          limit_(termination.max_evaluations.value_or(std::numeric_limits<std::int64_t>::max())),
          objectives_(objectives) {
        progress_.start = Clock::now();
    }

    /// Evaluates the first min(points.cols(), remaining()) columns into the same columns of
    /// `values` (objectives() rows) and returns how many; the columns past the budget get +inf in
    /// every objective. Each column is one evaluation, whatever the number of objectives.
    template <MultiObjectiveProblem P>
    Eigen::Index evaluate_columns(P& problem, MatrixView points, Matrix& values) {
        const Eigen::Index n = std::min<Eigen::Index>(points.cols(), static_cast<Eigen::Index>(remaining()));
        const auto m = static_cast<std::size_t>(objectives_);
        if constexpr (BatchMultiObjectiveProblem<P>) {
            if (n > 0) {
                // A scratch of the state's, so that an algorithm evaluating one child at a time
                // (MOEA/D, SMS-EMOA) allocates nothing per evaluation.
                batch_.resize(static_cast<Eigen::Index>(m), n);
                problem.evaluate_batch(points.leftCols(n), batch_);
                values.leftCols(n) = batch_;
            }
        } else {
            for (Eigen::Index j = 0; j < n; ++j)
                problem.evaluate(std::span<const double>(points.col(j).data(), static_cast<std::size_t>(points.rows())),
                                 std::span<double>(values.col(j).data(), m));
        }
        // A point with a NaN or infinite objective is +inf in all of them: dominated by every point
        // whose values are finite, equal to every other such point.
        for (Eigen::Index j = 0; j < values.cols(); ++j)
            if (j >= n || !values.col(j).allFinite()) values.col(j).setConstant(kInf);
        progress_.evaluations += n;
        return n;
    }

    /// A problem with constraints: as above, and each evaluated column's violation into the same
    /// entry of `violations` (the problem's measure; NaN counts as +inf), +inf past the budget. A
    /// column with a non-finite objective keeps its violation: feasibility is the constraints'.
    template <ConstrainedMultiObjectiveProblem P>
    Eigen::Index evaluate_columns(P& problem, MatrixView points, Matrix& values, std::span<double> violations) {
        const Eigen::Index n = std::min<Eigen::Index>(points.cols(), static_cast<Eigen::Index>(remaining()));
        const auto m = static_cast<std::size_t>(objectives_);
        constraint_values_.resize(problem.constraint_counts().total());  // sized once
        constrained_ = !constraint_values_.empty();
        for (Eigen::Index j = 0; j < n; ++j) {
            problem.evaluate_constrained(
                std::span<const double>(points.col(j).data(), static_cast<std::size_t>(points.rows())),
                std::span<double>(values.col(j).data(), m), std::span<double>(constraint_values_));
            const double v = problem.violation(std::span<const double>(constraint_values_));
            violations[static_cast<std::size_t>(j)] = std::isnan(v) ? kInf : v;
            if (v == 0.0 && !first_feasible_) first_feasible_ = progress_.evaluations + j + 1;
        }
        for (Eigen::Index j = 0; j < values.cols(); ++j) {
            if (j >= n) violations[static_cast<std::size_t>(j)] = kInf;
            if (j >= n || !values.col(j).allFinite()) values.col(j).setConstant(kInf);
        }
        progress_.evaluations += n;
        return n;
    }

    /// The chains' version: the first min(chains.size(), remaining()) chains into the same columns
    /// of `values`, the rest +inf.
    template <MultiObjectiveChainProblem P>
    std::size_t evaluate_chains(P& problem, std::span<const typename P::chain_type> chains, Matrix& values) {
        const std::size_t n = std::min<std::size_t>(chains.size(), static_cast<std::size_t>(remaining()));
        const auto m = static_cast<std::size_t>(objectives_);
        for (std::size_t j = 0; j < n; ++j)
            problem.evaluate(chains[j], std::span<double>(values.col(static_cast<Eigen::Index>(j)).data(), m));
        for (Eigen::Index j = 0; j < values.cols(); ++j)
            if (static_cast<std::size_t>(j) >= n || !values.col(j).allFinite()) values.col(j).setConstant(kInf);
        progress_.evaluations += static_cast<std::int64_t>(n);
        return n;
    }

    bool exhausted() const noexcept { return progress_.evaluations >= limit_; }
    std::int64_t remaining() const noexcept { return limit_ - progress_.evaluations; }
    bool done() const { return exhausted() || termination_.done(progress_); }
    std::size_t objectives() const noexcept { return objectives_; }
    const Progress& progress() const noexcept { return progress_; }

    /// Closes an iteration (the first call: the initial population) and shows the population.
    template <class O, class Population>
    void end_iteration(O& observer, const Population& population, const Matrix& values) {
        if (started_) ++progress_.iterations;
        started_ = true;
        history_evaluations_.push_back(progress_.evaluations);
        using View = BasicMultiObjectiveIterationView<Population>;
        if constexpr (std::is_invocable_v<O&, const View&>)
            observer(View{progress_.iterations, progress_.evaluations, population, values});
    }

    /// The result: the members `front` of the final population (its non-dominated ones), columns
    /// of a Matrix or elements of a vector of chains.
    template <class Population>
    BasicMultiObjectiveResult<Population> finish(const Population& population, const Matrix& values,
                                                 std::span<const std::size_t> front,
                                                 std::span<const double> violations = {}) {
        BasicMultiObjectiveResult<Population> r;
        // A problem that declares no constraint (a suite's unconstrained members) reports none.
        if (constrained_) {
            for (const std::size_t k : front) r.violation.push_back(violations[k]);
            r.first_feasible = first_feasible_;
        }
        r.wall_ms = std::chrono::duration<double, std::milli>(Clock::now() - progress_.start).count();
        r.f.resize(values.rows(), static_cast<Eigen::Index>(front.size()));
        if constexpr (std::is_same_v<Population, Matrix>)
            r.x.resize(population.rows(), static_cast<Eigen::Index>(front.size()));
        for (std::size_t k = 0; k < front.size(); ++k) {
            if constexpr (std::is_same_v<Population, Matrix>)
                r.x.col(static_cast<Eigen::Index>(k)) = population.col(static_cast<Eigen::Index>(front[k]));
            else
                r.x.push_back(population[front[k]]);
            r.f.col(static_cast<Eigen::Index>(k)) = values.col(static_cast<Eigen::Index>(front[k]));
        }
        r.evaluations = progress_.evaluations;
        r.iterations = progress_.iterations;
        r.history_evaluations = std::move(history_evaluations_);
        return r;
    }

  private:
    Termination termination_;
    std::int64_t limit_;
    std::size_t objectives_;
    Progress progress_;
    std::vector<std::int64_t> history_evaluations_;
    Matrix batch_;
    std::vector<double> constraint_values_;
    std::optional<std::int64_t> first_feasible_;
    bool constrained_ = false;  // evaluated with at least one constraint
    bool started_ = false;
};

/// What every multi-objective run begins with once its algorithm's own parameters are checked: the
/// stopping rules checked, M (at least 1), the problem's noise seeded, the run's generator and its
/// evaluation guard.
struct MultiObjectiveStart {
    std::size_t objectives;
    Rng rng;
    MultiObjectiveRunState state;
};

template <class P>
requires MultiObjectiveProblem<P> || MultiObjectiveChainProblem<P> MultiObjectiveStart
start_multiobjective_run(const std::string& who, P& problem, const Termination& termination, std::uint64_t seed) {
    termination.validate(who);
    const std::size_t m = problem.objectives();
    require(m >= 1, who, "the problem has no objectives");
    seed_noise(problem, seed);
    return {m, Rng(seed), MultiObjectiveRunState(termination, m)};
}

}  // namespace pride

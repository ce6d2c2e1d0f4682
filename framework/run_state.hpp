#pragma once
// The run driver every algorithm shares: the evaluation guard (exact budget, NaN/inf never best,
// the best point ever evaluated), the stopping rules, the history and the observer calls, and the
// wall clock. An algorithm's loop is then only its own equations.
//
// On a constrained problem (framework/constraints.hpp) one evaluation gives f and the point's
// violation v, counted once. The run's best point is the best by Deb's feasibility rules, whatever
// handler the algorithm compares with: the best feasible point, or while there is none the least
// violating one. The best value that stopping rules, targets and the history see is the best
// feasible f (+inf until a feasible point is found). The COCO trace (framework/coco_trace.hpp)
// follows COCO's bbob logger on constrained problems instead: the least of max(f, f_opt) + v over
// every point evaluated, feasible or not (with f_opt unknown, f for a feasible point and
// 1e10 + v for an infeasible one); its evaluation triggers count f and constraint evaluations,
// and it ends at the run's last evaluation.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "framework/coco_trace.hpp"
#include "framework/constraints.hpp"
#include "framework/observer.hpp"
#include "framework/problem.hpp"
#include "framework/result.hpp"
#include "framework/termination.hpp"

namespace pride {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

/// NaN and +-inf become +inf: worse than every finite value, so never the best.
inline double sanitize(double f) noexcept {
    return std::isfinite(f) ? f : kInf;
}

/// `Solution` is what is searched: a point of a box (std::vector<double>, the default, kept as
/// the span evaluated) or a chain for algorithms on chains.
template <class Solution = std::vector<double>>
class BasicRunState {
    // Declared first: clang 14 does not look ahead in the class from a trailing requires-clause
    // (evaluate_columns), which the fuzz build (fuzz/, clang) needs.
    static constexpr bool is_point = std::is_same_v<Solution, std::vector<double>>;

  public:
    /// `dimension`: the length of a point, for box problems (the best point is allocated once).
    explicit BasicRunState(const Termination& termination, std::size_t dimension = 0)
        : termination_(termination),
          limit_(termination.max_evaluations.value_or(std::numeric_limits<std::int64_t>::max())),
          trace_(termination.optimum.value_or(0.0), dimension) {
        if constexpr (is_point) best_x_.assign(dimension, std::numeric_limits<double>::quiet_NaN());
        target_hits_.reserve(termination.recorded_targets.size());
        checkpoints_.reserve(termination.recorded_evaluations.size());
        if (!termination.recorded_evaluations.empty()) next_checkpoint_ = termination.recorded_evaluations.front();
        progress_.start = Clock::now();
    }

    /// One counted evaluation of a point (box problems) or a chain. Precondition: !exhausted();
    /// breaking it is a bug in the algorithm, and throws rather than overspend the budget.
    template <class P, class X>
    double evaluate(P& problem, const X& x) {
        if (progress_.evaluations >= limit_) throw std::logic_error("evaluation budget overspent");
        const double f = sanitize(problem.evaluate(x));
        ++progress_.evaluations;
        const bool better = f < progress_.best;
        if (better) {
            improved(f);
            if constexpr (is_point)
                std::copy(x.begin(), x.end(), best_x_.begin());
            else
                best_x_ = x;
        }
        trace_.record(progress_.evaluations, progress_.best, better);
        checkpoint();
        return f;
    }

    /// One counted evaluation of a partial solution (a segment an operator scores while it builds a
    /// chain): counted and within the budget like any other, but never the best (it is not a
    /// solution). Partial scoring never spends the budget's last evaluation, so that a run always
    /// evaluates at least one whole solution: +inf without a call when one or none is left.
    template <class P, class X>
    double evaluate_partial(const P& problem, const X& x) {
        if (progress_.evaluations + 1 >= limit_) return kInf;
        ++progress_.evaluations;
        const double f = sanitize(problem.evaluate(x));
        trace_.record(progress_.evaluations, progress_.best, false);
        checkpoint();
        return f;
    }

    /// Evaluates the first min(points.cols(), remaining()) columns into `values` and returns how
    /// many; columns past the budget get +inf. Uses the problem's batch evaluation when it has one.
    template <BoxProblem P>
    Eigen::Index evaluate_columns(P& problem, MatrixView points, std::span<double> values) requires is_point {
        const Eigen::Index n = std::min<Eigen::Index>(points.cols(), static_cast<Eigen::Index>(remaining()));
        if constexpr (BatchBoxProblem<P>) {
            problem.evaluate_batch(points.leftCols(n), values.first(static_cast<std::size_t>(n)));
            for (Eigen::Index j = 0; j < n; ++j) {
                auto& f = values[static_cast<std::size_t>(j)];
                f = sanitize(f);
                ++progress_.evaluations;
                const bool better = f < progress_.best;
                if (better) {
                    improved(f);
                    std::copy_n(points.col(j).data(), points.rows(), best_x_.begin());
                }
                trace_.record(progress_.evaluations, progress_.best, better);
                checkpoint();
            }
        } else {
            for (Eigen::Index j = 0; j < n; ++j)
                values[static_cast<std::size_t>(j)] = evaluate(
                    problem, std::span<const double>(points.col(j).data(), static_cast<std::size_t>(points.rows())));
        }
        for (auto j = static_cast<std::size_t>(n); j < static_cast<std::size_t>(points.cols()); ++j) values[j] = kInf;
        return n;
    }

    /// The same for a constrained problem: f into `values` and each point's violation into
    /// `violations` (+inf past the budget), one counted evaluation per point. When `constraints`
    /// is given (m + p values per point, point after point), each evaluated point's constraint
    /// values are copied there too, for algorithms that read them (COLSHADE's tolerances).
    template <ConstrainedProblem P>
    Eigen::Index evaluate_columns(P& problem, MatrixView points, std::span<double> values, std::span<double> violations,
                                  std::span<double> constraints = {}) requires is_point {
        const Eigen::Index n = std::min<Eigen::Index>(points.cols(), static_cast<Eigen::Index>(remaining()));
        const auto k = problem.constraint_counts().total();
        if (constraint_values_.size() != k) constraint_values_.assign(k, 0.0);  // once per run
        for (Eigen::Index j = 0; j < n; ++j) {
            const std::span<const double> x(points.col(j).data(), static_cast<std::size_t>(points.rows()));
            const double f = sanitize(problem.evaluate_constrained(x, constraint_values_));
            const double v = problem.violation(constraint_values_);
            const double vs = std::isnan(v) ? kInf : v;
            values[static_cast<std::size_t>(j)] = f;
            violations[static_cast<std::size_t>(j)] = vs;
            if (!constraints.empty())
                std::copy(constraint_values_.begin(), constraint_values_.end(),
                          constraints.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(j) * k));
            record_constrained(x, f, vs);
        }
        for (auto j = static_cast<std::size_t>(n); j < static_cast<std::size_t>(points.cols()); ++j) {
            values[j] = kInf;
            violations[j] = kInf;
        }
        return n;
    }

    /// One evaluation of a population's columns on any problem: values, and on a constrained one
    /// violations too (left as they are otherwise: 0 for every point).
    template <BoxProblem P>
    Eigen::Index evaluate_population(P& problem, MatrixView points, std::span<double> values,
                                     std::span<double> violations) requires is_point {
        if constexpr (ConstrainedProblem<P>)
            return evaluate_columns(problem, points, values, violations);
        else
            return evaluate_columns(problem, points, values);
    }

    bool exhausted() const noexcept { return progress_.evaluations >= limit_; }
    std::int64_t remaining() const noexcept { return limit_ - progress_.evaluations; }
    /// True once a stopping rule holds or the budget is spent.
    bool done() const { return exhausted() || termination_.done(progress_); }

    /// Closes an iteration: the first call closes the initial population (iteration 0), each later
    /// one the next iteration. Records the history and shows the population to the observer.
    template <class O, class Population>
    void end_iteration(O& observer, const Population& population, std::span<const double> fitness) {
        if (started_) ++progress_.iterations;
        started_ = true;
        history_.push_back(progress_.best);
        history_evaluations_.push_back(progress_.evaluations);
        if constexpr (is_point)
            observer(IterationView{progress_.iterations, progress_.evaluations, progress_.best, best_x_, population,
                                   fitness});
        else
            observer(BasicIterationView<const Solution&, Population>{progress_.iterations, progress_.evaluations,
                                                                     progress_.best, best_x_, population, fitness});
    }

    const Progress& progress() const noexcept { return progress_; }
    std::int64_t iteration() const noexcept { return progress_.iterations; }
    double best() const noexcept { return progress_.best; }
    const Solution& best_x() const noexcept { return best_x_; }
    const Termination& termination() const noexcept { return termination_; }

    BasicResult<Solution> finish() {
        BasicResult<Solution> r;
        r.wall_ms = std::chrono::duration<double, std::milli>(Clock::now() - progress_.start).count();
        r.best_x = std::move(best_x_);
        r.best_f = progress_.best;
        r.evaluations = progress_.evaluations;
        r.iterations = progress_.iterations;
        r.history = std::move(history_);
        r.history_evaluations = std::move(history_evaluations_);
        r.target_hits = std::move(target_hits_);
        if (constrained_) trace_.close(progress_.evaluations, coco_best_);
        r.trace_targets = std::move(trace_.targets());
        r.trace_evaluations = std::move(trace_.evaluations());
        r.checkpoints = std::move(checkpoints_);
        if (constrained_) {
            if (!have_feasible_) r.best_f = infeasible_best_f_;
            r.best_violation = best_violation_;
            if (first_feasible_ > 0) r.first_feasible = first_feasible_;
        }
        return r;
    }

  private:
    /// After every evaluation: at each of Termination::recorded_evaluations, the best value so far
    /// (one compare in the common case).
    void checkpoint() {
        if (progress_.evaluations == next_checkpoint_) [[unlikely]]
            record_checkpoint();
    }

    [[gnu::noinline]] void record_checkpoint() {
        checkpoints_.push_back({progress_.evaluations, progress_.best});
        const auto& wanted = termination_.recorded_evaluations;
        next_checkpoint_ = checkpoints_.size() < wanted.size() ? wanted[checkpoints_.size()]
                                                               : std::numeric_limits<std::int64_t>::max();
    }

    /// After a counted evaluation of a constrained point: Deb's best point, the best feasible value.
    void record_constrained(std::span<const double> x, double f, double v) {
        ++progress_.evaluations;
        if (!constrained_) trace_.count_constraints();
        constrained_ = true;
        const bool feasible = v == 0.0;
        bool improved_value = false;
        if (feasible) {
            if (first_feasible_ == 0) first_feasible_ = progress_.evaluations;
            improved_value = f < progress_.best;
            if (!have_feasible_ || improved_value) {
                have_feasible_ = true;
                best_violation_ = 0.0;
                std::copy(x.begin(), x.end(), best_x_.begin());
            }
            if (improved_value) improved(f);
        } else if (!have_feasible_ && v < best_violation_) {
            best_violation_ = v;
            infeasible_best_f_ = f;
            std::copy(x.begin(), x.end(), best_x_.begin());
        }
        // COCO's logged value (logger_bbob_evaluate): (f - f_opt)^+ + v, infeasible points included.
        const auto& optimum = termination_.optimum;
        const double logged = (optimum ? std::max(f, *optimum) : v > 0.0 ? kCocoInfeasiblePenalty : f) + v;
        const bool logged_better = logged < coco_best_;
        if (logged_better || progress_.evaluations == 1) coco_best_ = logged;
        trace_.record(progress_.evaluations, coco_best_, logged_better);
        checkpoint();
    }

    /// A new best value (rare): the targets it reaches are recorded with the evaluation count.
    void improved(double f) {
        progress_.best = f;
        const auto& targets = termination_.recorded_targets;
        while (target_hits_.size() < targets.size() && f <= targets[target_hits_.size()])
            target_hits_.push_back(progress_.evaluations);
    }

    Termination termination_;
    std::int64_t limit_;
    Progress progress_;
    Solution best_x_;
    std::vector<double> history_;
    std::vector<std::int64_t> history_evaluations_;
    std::vector<std::int64_t> target_hits_;
    CocoTrace trace_;
    std::vector<TracePoint> checkpoints_;
    std::int64_t next_checkpoint_ = std::numeric_limits<std::int64_t>::max();
    bool started_ = false;
    // Constrained problems only: the constraint values of the point being evaluated, Deb's best.
    std::vector<double> constraint_values_;
    bool constrained_ = false, have_feasible_ = false;
    double best_violation_ = kInf, infeasible_best_f_ = kInf;
    double coco_best_ = kInf;  // COCO's logged best (record_constrained)
    // COCO's LOGGER_BBOB_INFEASIBLE_PENALTY: an infeasible point's value when f_opt is unknown.
    static constexpr double kCocoInfeasiblePenalty = 1e10;
    std::int64_t first_feasible_ = 0;
};

using RunState = BasicRunState<>;

}  // namespace pride

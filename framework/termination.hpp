#pragma once
// Stopping rules: maximum evaluations (exact: the evaluation guard never exceeds it), maximum
// iterations, a target value, wall time. Each is a Termination with one limit set; `a | b` stops
// at whichever comes first. Checked once per iteration, never per evaluation.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "framework/error.hpp"

namespace pride {

using Clock = std::chrono::steady_clock;

/// Where a run stands, as the stopping rules see it.
struct Progress {
    std::int64_t evaluations = 0;
    std::int64_t iterations = 0;  // completed iterations after the initial population
    double best = std::numeric_limits<double>::infinity();
    Clock::time_point start{};
};

class Termination {
  public:
    std::optional<std::int64_t> max_evaluations;
    std::optional<std::int64_t> max_iterations;
    std::optional<double> target;  // stop once best <= target
    std::optional<Clock::duration> wall_time;
    // Not a stopping rule: values, in decreasing order, whose first reaching the evaluation guard
    // records as an exact evaluation count (COCO's targets f_opt + 10^k: Result::target_hits).
    std::vector<double> recorded_targets;
    // Not a stopping rule: f_opt when known, the reference of the run's COCO trace
    // (Result::trace_targets); without it the trace's triggers follow the values themselves.
    std::optional<double> optimum;
    // Not a stopping rule: evaluation counts, increasing, after each of which the evaluation guard
    // records the best value so far (Result::checkpoints; campaigns: the CEC reports' checkpoints).
    std::vector<std::int64_t> recorded_evaluations;
    // Not a limit: a flag set from outside the run's loop (an observer asking to stop, a front end
    // cancelling), read with the other rules once per iteration; unset costs one test.
    std::shared_ptr<const std::atomic<bool>> stop;

    /// True when any limit set is reached.
    bool done(const Progress& p) const {
        if (stop && stop->load(std::memory_order_relaxed)) return true;
        if (max_evaluations && p.evaluations >= *max_evaluations) return true;
        if (max_iterations && p.iterations >= *max_iterations) return true;
        if (target && p.best <= *target) return true;
        if (wall_time && Clock::now() - p.start >= *wall_time) return true;
        return false;
    }

    /// Throws unless a run under these rules is bound to end (a target alone may never be met).
    void validate(const std::string& where) const {
        require(max_evaluations || max_iterations || wall_time, where,
                "no evaluation, iteration or wall-time limit is set, so the run might never end");
        if (max_evaluations) require(*max_evaluations >= 1, where, "the evaluation limit must be >= 1");
        if (max_iterations) require(*max_iterations >= 0, where, "the iteration limit must be >= 0");
        for (std::size_t i = 1; i < recorded_targets.size(); ++i)
            require(recorded_targets[i] <= recorded_targets[i - 1], where, "recorded targets must not increase");
        for (std::size_t i = 0; i < recorded_evaluations.size(); ++i)
            require(recorded_evaluations[i] >= 1 && (i == 0 || recorded_evaluations[i] > recorded_evaluations[i - 1]),
                    where, "recorded evaluation counts must be >= 1 and increase");
    }

    /// The number of iterations T that schedules (inertia weight, step sizes) run over: the
    /// iteration limit, or the iterations the evaluation limit allows after an initial population
    /// of `initial_evaluations` at `evaluations_per_iteration` each (a partial last iteration
    /// counts). Empty when neither limit is set.
    std::optional<std::int64_t> horizon(std::int64_t initial_evaluations,
                                        std::int64_t evaluations_per_iteration) const {
        std::optional<std::int64_t> t = max_iterations;
        if (max_evaluations && evaluations_per_iteration > 0) {
            const std::int64_t left = std::max<std::int64_t>(0, *max_evaluations - initial_evaluations);
            const std::int64_t by_evals = (left + evaluations_per_iteration - 1) / evaluations_per_iteration;
            t = t ? std::min(*t, by_evals) : by_evals;
        }
        return t;
    }

    friend Termination operator|(Termination a, const Termination& b) {
        auto tighter = [](auto& x, const auto& y, auto pick) {
            if (y) x = x ? pick(*x, *y) : *y;
        };
        auto min = [](auto u, auto v) { return std::min(u, v); };
        auto max = [](auto u, auto v) { return std::max(u, v); };
        tighter(a.max_evaluations, b.max_evaluations, min);
        tighter(a.max_iterations, b.max_iterations, min);
        tighter(a.target, b.target, max);
        tighter(a.wall_time, b.wall_time, min);
        if (a.recorded_targets.empty()) a.recorded_targets = b.recorded_targets;
        if (a.recorded_evaluations.empty()) a.recorded_evaluations = b.recorded_evaluations;
        if (!a.optimum) a.optimum = b.optimum;
        if (!a.stop) a.stop = b.stop;
        return a;
    }
};

inline Termination max_evaluations(std::int64_t n) {
    Termination t;
    t.max_evaluations = n;
    return t;
}
inline Termination max_iterations(std::int64_t n) {
    Termination t;
    t.max_iterations = n;
    return t;
}
inline Termination target_value(double f) {
    Termination t;
    t.target = f;
    return t;
}
inline Termination wall_time(Clock::duration d) {
    Termination t;
    t.wall_time = d;
    return t;
}

}  // namespace pride

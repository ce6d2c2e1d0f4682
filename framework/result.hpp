#pragma once
// What every run reports, whatever the algorithm: the best point ever evaluated and its value,
// the evaluations and iterations used, the best value after each iteration, and the wall time.
#include <cstdint>
#include <optional>
#include <vector>

#include "framework/coco_trace.hpp"

namespace pride {

/// `Solution` is what the algorithm searched: a point of the box (the default) or, for algorithms
/// on chains, a chain.
template <class Solution = std::vector<double>>
struct BasicResult {
    Solution best_x;      // a point: the genotype, which an Encoded problem's decode() turns into the solution
    double best_f = 0.0;  // +inf when no evaluation gave a finite value
    // Constrained problems (framework/constraints.hpp): the best point's violation (0: feasible;
    // best_f is then the best feasible value, else the least violating point's f), and the
    // evaluation that first found a feasible point (empty: none, or no constraints).
    double best_violation = 0.0;
    std::optional<std::int64_t> first_feasible;
    std::int64_t evaluations = 0;
    std::int64_t iterations = 0;  // completed iterations after the initial population
    /// history[k]: best value after iteration k (k = 0 is the initial population), and
    /// history_evaluations[k] the evaluations spent by then; one entry more than `iterations`
    /// when the run stopped at the end of an iteration.
    std::vector<double> history;
    std::vector<std::int64_t> history_evaluations;
    /// target_hits[k]: the evaluations after which the best value first was <= the k-th of
    /// Termination::recorded_targets, for the targets reached (a prefix: they decrease).
    std::vector<std::int64_t> target_hits;
    /// (evaluations, best so far) at COCO's target triggers and at its evaluation triggers
    /// (framework/coco_trace.hpp): what COCO's .dat and .tdat files hold.
    std::vector<TracePoint> trace_targets, trace_evaluations;
    /// (evaluations, best so far) after each of Termination::recorded_evaluations the run reached,
    /// taken at that very evaluation (not at the end of its iteration).
    std::vector<TracePoint> checkpoints;
    double wall_ms = 0.0;  // from population set-up to the end of the run
};

using Result = BasicResult<>;

}  // namespace pride

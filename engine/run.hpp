#pragma once
// The one function that runs: (algorithm spec, problem, budget, seed) -> result. A Problem
// (engine/problem.hpp) is built once from its spec and copied into every run, so runs never share
// state.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/grid_names.hpp"
#include "engine/grid_outcome.hpp"
#include "engine/problem.hpp"
#include "engine/specs.hpp"
#include "framework/coco_trace.hpp"
#include "framework/memory.hpp"
#include "framework/observer.hpp"

namespace pride::engine {

/// What a run of several objectives found: its non-dominated set, each objective vector once (the
/// first point of each, in the population's order), in lexicographic order of the objectives.
struct Front {
    Matrix f;                       // the objective values: M rows, one column per point
    Matrix x;                       // their points (grids: genotypes; none on chains)
    std::vector<grid::Path> paths;  // grids: the path of each point
    std::vector<char> feasible;     // grids: whether it is a legal path (no violation)
    std::vector<double> violation;  // problems with constraints: each point's violation (0: feasible)
};

struct RunResult {
    std::string algorithm;
    // The minimised value (+inf when nothing finite was found); NaN for several objectives, whose
    // result is `front`.
    double best_f = 0.0;
    std::vector<double> best_x;    // the best point (grids: the genotype; chains: empty)
    std::int64_t evaluations = 0;  // A*: node expansions
    std::int64_t iterations = 0;
    double wall_ms = 0.0;
    std::vector<double> history;  // best value after each iteration (0: the initial population)
    std::vector<std::int64_t> history_evaluations;
    std::vector<std::int64_t> target_hits;  // Budget::recorded_targets reached: evaluations at each
    // (evaluations, best so far) at COCO's target and evaluation triggers (framework/coco_trace.hpp),
    // the reference being the problem's f_opt when known: what COCO's .dat and .tdat files hold.
    std::vector<TracePoint> trace_targets, trace_evaluations;
    // (evaluations, best so far) after each of Budget::recorded_evaluations the run reached.
    std::vector<TracePoint> checkpoints;
    std::optional<GridOutcome> grid;
    std::optional<Front> front;  // several objectives
    // Problems with constraints: the best point's violation (0: feasible; best_f is then the best
    // feasible value, else the least violating point's), and the evaluation that first found a
    // feasible point (empty: none).
    std::optional<double> best_violation;
    std::optional<std::int64_t> first_feasible;
};

/// Every check a run of `algorithm` on `problem` under `budget` would make, without running:
/// the name, whether it optimises as many objectives as the problem has, the parameters against
/// their declared ranges, whether the algorithm runs on the problem's space, the budget, and the
/// memory the run needs. InputError naming what is wrong.
void check(const AlgorithmSpec& algorithm, const Problem& problem, const Budget& budget);

/// The checks of Problem(spec) and check() that need nothing built, for a front end that builds a
/// problem from a size (Python: `dim`): the problem's own memory ("dim"), then the algorithm, its
/// parameters, the budget and the run's memory, so that nothing is allocated for a run check()
/// would refuse. For a ContinuousSpec, or a CallbackSpec whose bounds (of `dimension`
/// coordinates) are not built yet; nothing for a grid (its size is its map's).
void check_before_building(const AlgorithmSpec& algorithm, const ProblemSpec& spec, std::int64_t dimension,
                           const Budget& budget);

/// Runs once. The same inputs give the same result, bit for bit (bar wall_ms), on any thread. A
/// problem of several objectives takes a multi-objective algorithm and gives its `front`; its
/// budget records no targets or checkpoints, runs on one thread, and without evaluations or
/// iterations is 10,000 evaluations per variable (grids: 50 iterations), as for one objective.
RunResult run(const AlgorithmSpec& algorithm, const Problem& problem, const Budget& budget, std::uint64_t seed);

/// Sees every iteration of an observed run (iteration 0: the initial population) and returns
/// false to stop it there, as a stopping rule would: the result is the run up to that iteration.
using IterationObserver = std::function<bool(const IterationView&)>;

/// run() with an observer: box algorithms of one objective only (continuous, callback and grid
/// problems through the line and free encodings); InputError("observer", ...) for chains,
/// whole-map algorithms and several objectives.
/// The observer changes nothing else: the same inputs give the same result as run() when it
/// never stops the run.
RunResult run(const AlgorithmSpec& algorithm, const Problem& problem, const Budget& budget, std::uint64_t seed,
              const IterationObserver& observer);

// framework/memory.hpp's, under the names the engine's users know.
using pride::available_memory;
using pride::format_bytes;

}  // namespace pride::engine

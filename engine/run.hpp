#pragma once
// The one function that runs: (algorithm spec, problem, budget, seed) -> result. A Problem is
// built once from its spec (a campaign builds each once: maps parsed once, reachability and
// encodings' tables computed once) and copied into every run, so runs never share state.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/specs.hpp"
#include "framework/coco_trace.hpp"
#include "framework/memory.hpp"
#include "framework/observer.hpp"
#include "problems/grid/path.hpp"
#include "problems/grid/polyline.hpp"

namespace pride::engine {

/// The largest weight a grid objective takes (--weights, --lambda): a path of a billion cells
/// at this weight still has a finite value and a finite penalty bound.
inline constexpr double max_weight = 1e9;
/// The largest count every front end accepts (evaluations, iterations, population, dimension):
/// beyond any run that can finish, and far from the int64 limit, so that counts never overflow;
/// what does not fit in memory is refused before anything is allocated.
inline constexpr std::int64_t max_budget = 1'000'000'000'000'000;

struct Prepared;  // engine/run.cpp

/// A problem ready to run: every check of its spec done, every table built.
class Problem {
  public:
    /// Throws InputError naming the field of the spec that is wrong.
    explicit Problem(const ProblemSpec& spec);

    bool is_grid() const;
    /// A grid problem whose objective is a sum of step and turn costs (the oracle's objectives).
    bool additive() const;
    /// A grid problem whose objective has an exact optimum: every additive one (the oracle) and
    /// iqga (over the 3-D Pareto front).
    bool has_optimum() const;
    /// The same grid problem with the exact optimum computed beside every run (GridSpec::oracle),
    /// without building it again; InputError when the objective has none.
    Problem with_oracle() const;
    /// The dimension of the box an algorithm searches (grids: of the encoding's genotype; chains: 0).
    std::size_t dimension() const;
    const ProblemSpec& spec() const;
    /// The problem's display name: the function, "grid" or the callback's name.
    std::string name() const;
    /// A continuous function's instance (0: as defined; BBOB: COCO's, from 1); 0 for others.
    std::int64_t instance() const;
    /// A continuous function's known minimum at this instance and dimension (for targets).
    std::optional<double> optimum_value() const;

    const Prepared& prepared() const { return *prepared_; }
    /// What a run of `algorithm` plans on: on a grid, the encoding, connector and init the run
    /// names, else the problem's, else the algorithm's native encoding (built once per plan and
    /// shared by the problem's copies); the problem itself otherwise. InputError for a space the
    /// algorithm cannot use.
    std::shared_ptr<const Prepared> planned_for(const AlgorithmSpec& algorithm) const;

  private:
    struct Variants;
    explicit Problem(std::shared_ptr<const Prepared> prepared);
    std::shared_ptr<const Prepared> prepared_;
    std::shared_ptr<Variants> variants_;
};

/// What a grid run found, beside the search's own result.
struct GridOutcome {
    std::string encoding = "none";  // line, free, chain; none for whole-map algorithms
    bool feasible = false;          // an infeasible candidate is never returned as a path
    grid::Path path;                // start first; empty when infeasible or when the planner plans polylines
    double value = 0.0;             // the objective of the path (when feasible)
    std::optional<double> optimum;  // with GridSpec::oracle, or for the exact algorithm
    grid::Path optimal_path;
    // The path as every planner's is scored (problems/grid/polyline.hpp): a chain's cells, or a
    // polyline planner's vertices; empty when infeasible. Its metrics when feasible.
    grid::Polyline polyline;
    grid::PolylineMetrics metrics;
    // With GridSpec::path_gaps: the shortest lengths of the problem (the 8-connected grid's, by
    // A*, and the exact any-angle one) and the path's length over each, minus 1. Empty when the
    // run found no path or the goal cannot be reached.
    std::optional<double> shortest_grid_length, shortest_any_angle_length;
    std::optional<double> grid_gap, any_angle_gap;
};

struct RunResult {
    std::string algorithm;
    double best_f = 0.0;           // the minimised value (+inf when nothing finite was found)
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
};

/// The checks of a grid spec that need no map (names and their combinations): front ends call it
/// before reading a map, so a misspelt name is reported before a missing file.
void check_grid_names(const GridSpec& spec);

/// Every check a run of `algorithm` on `problem` under `budget` would make, without running:
/// the name, the parameters against their declared ranges, whether the algorithm runs on the
/// problem's space, the budget, and the memory the run needs. InputError naming what is wrong.
void check(const AlgorithmSpec& algorithm, const Problem& problem, const Budget& budget);

/// The checks of Problem(spec) and check() that need nothing built, for a front end that builds a
/// problem from a size (Python: `dim`): the problem's own memory ("dim"), then the algorithm, its
/// parameters, the budget and the run's memory, so that nothing is allocated for a run check()
/// would refuse. For a ContinuousSpec, or a CallbackSpec whose bounds (of `dimension`
/// coordinates) are not built yet; nothing for a grid (its size is its map's).
void check_before_building(const AlgorithmSpec& algorithm, const ProblemSpec& spec, std::int64_t dimension,
                           const Budget& budget);

/// Runs once. The same inputs give the same result, bit for bit (bar wall_ms), on any thread.
RunResult run(const AlgorithmSpec& algorithm, const Problem& problem, const Budget& budget, std::uint64_t seed);

/// Sees every iteration of an observed run (iteration 0: the initial population) and returns
/// false to stop it there, as a stopping rule would: the result is the run up to that iteration.
using IterationObserver = std::function<bool(const IterationView&)>;

/// run() with an observer: box algorithms only (continuous, callback and grid problems through
/// the line and free encodings); InputError("observer", ...) for chains and whole-map algorithms.
/// The observer changes nothing else: the same inputs give the same result as run() when it
/// never stops the run.
RunResult run(const AlgorithmSpec& algorithm, const Problem& problem, const Budget& budget, std::uint64_t seed,
              const IterationObserver& observer);

// framework/memory.hpp's, under the names the engine's users know.
using pride::available_memory;
using pride::format_bytes;

/// The names the grid spec takes, with a few words each (for listings and error messages).
struct NamedItem {
    std::string name;
    std::string summary;
};
const std::vector<NamedItem>& grid_objectives();
const std::vector<NamedItem>& grid_encodings();
const std::vector<NamedItem>& grid_connectors();
const std::vector<NamedItem>& grid_inits();

}  // namespace pride::engine

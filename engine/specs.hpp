#pragma once
// Problems, algorithms and budgets as plain structs: what every front end (command line, campaign
// files, Python) fills in, and what the engine runs. Names are checked by the engine, with errors
// naming the field ("start", "encoding", "dim"), never a front end's flag.
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "engine/other_objective.hpp"
#include "engine/params.hpp"
#include "framework/problem.hpp"
#include "framework/termination.hpp"
#include "framework/variables.hpp"
#include "problems/grid/map.hpp"
#include "problems/grid/map_io.hpp"

namespace pride::engine {

/// The largest weight a grid objective takes (--weights, --lambda): a path of a billion cells
/// at this weight still has a finite value and a finite penalty bound.
inline constexpr double max_weight = 1e9;
/// The largest count every front end accepts (evaluations, iterations, population, dimension):
/// beyond any run that can finish, and far from the int64 limit, so that counts never overflow;
/// what does not fit in memory is refused before anything is allocated.
inline constexpr std::int64_t max_budget = 1'000'000'000'000'000;

/// A registered function in a dimension: a continuous function (sphere, bbob-f1, cec2017-f3) at an
/// instance (empty: the function's default, 0 = as defined; 1 for BBOB), or a problem of several
/// objectives (zdt1..zdt6, dtlz1..dtlz7; problems/multiobjective/catalog.hpp), which has no instance.
struct ContinuousSpec {
    std::string function;
    std::int64_t dim = 0;  // several objectives: 0 for the paper's n
    std::optional<std::int64_t> instance = std::nullopt;
    std::int64_t objectives = 0;  // M; 0: the function's own (1; 2 for ZDT, 3 for DTLZ, which takes any)
};

/// One planning problem on a grid. The map is shared and already parsed (and inflated), so that
/// a campaign reads each map once.
struct GridSpec {
    std::shared_ptr<const grid::GridMap> map;
    grid::Cell start{};
    grid::Cell goal{};
    std::string objective = "cells";  // cells, length, weighted, iqga, hswoa (see objectives()); user
    // A user's objective on paths (objective "user"): its value, and optionally its per-step
    // costs for the exact optimum (engine/other_objective.hpp).
    std::shared_ptr<const UserPathObjective> path_objective;
    std::vector<double> weights;       // weighted: {w_len, w_turn, w_angle}; empty: the defaults
    std::optional<double> lambda;      // hswoa: the turn weight; empty: the default
    std::string encoding;              // line, free, chain (see encodings()); empty: each algorithm's native one
    std::string connector = "repair";  // repair, penalty (line and free)
    std::int64_t waypoints = 3;        // free
    // uniform, walk (random feasible walks) or rules (Wan and Gao's (2022) rough-set rule walks); empty: the
    // algorithm's own choice (its walk_init parameter)
    std::string init;
    bool corner_cutting = false;
    bool oracle = false;  // also compute the exact optimum (additive objectives)
    // Also compute the problem's shortest lengths (grid and any-angle, once per problem) and each
    // run's gaps to them (GridOutcome::grid_gap, any_angle_gap): the any-angle oracle is slow on
    // large open maps, so it is asked for.
    bool path_gaps = false;
    // When set, counts every evaluation of the objective by every run of the problem (a check of
    // the runs' `evaluations` from outside: tests, pride path --count-calls).
    std::shared_ptr<std::atomic<std::int64_t>> objective_calls;
    // Several criteria at once: two to four of length, turns, angle, clearance (a problem of several
    // objectives, searched on the spec's encoding: line by default, free, or chain with init walk or
    // sitp); empty: the one `objective`. objective, weights, lambda and oracle are then left alone.
    std::string objectives;
    std::int64_t clearance_bands = 3;  // B of clearance.hpp
    std::int64_t clearance_width = 1;  // w of clearance.hpp
};

/// A user function on a box: type erasure at this edge only. `batch`, when set, evaluates every
/// column of a matrix (one point per column) in one call, and is used instead of `scalar`. With
/// several objectives, `values` fills a point's M values and `values_batch` the M rows of a matrix
/// for every column of the points (used instead of `values` when set).
struct CallbackSpec {
    std::string name = "callback";
    std::vector<double> lower, upper;
    std::function<double(std::span<const double>)> scalar;
    std::function<void(MatrixView, std::span<double>)> batch;
    std::int64_t objectives = 1;  // M
    std::function<void(std::span<const double>, std::span<double>)> values = nullptr;
    std::function<void(MatrixView, Matrix&)> values_batch = nullptr;
    /// Constraints (framework/constraints.hpp), one objective: `constrained` returns f and writes
    /// the `inequalities` values g_i (g_i <= 0 feasible), then the `equalities` values h_j (h_j = 0
    /// within `tolerance`), and is used instead of scalar and batch; a point's violation is the
    /// mean of their excess (CEC 2006 and 2020).
    std::int64_t inequalities = 0;
    std::int64_t equalities = 0;
    double tolerance = 1e-4;
    std::function<double(std::span<const double>, std::span<double>)> constrained = nullptr;
    /// The functions may be called from several threads at once (Budget::threads > 1). A run with
    /// threads asks for it and refuses a callback without it (Python functions hold the GIL: leave
    /// it false for them).
    bool thread_safe = false;
    /// The function's minimum, when the user knows it: reports then give precisions f - f_opt,
    /// and campaigns record when runs reach f_opt + 10^k (ERT, ECDF), as for the catalog's.
    std::optional<double> f_opt = std::nullopt;
    /// The variables' types (framework/variables.hpp), one per coordinate; empty: all real. An
    /// integer variable has integer bounds; a categorical one bounds 0 and k - 1 (k >= 2 choices,
    /// the function receives the index). The function receives integer values on them.
    std::vector<VariableType> types = {};
};

using ProblemSpec = std::variant<ContinuousSpec, GridSpec, CallbackSpec>;

struct AlgorithmSpec {
    std::string name;  // a registered algorithm: pso, ga-plus, nlopt:LN_SBPLX, astar, ...
    ParamValues params;
};

/// The stopping rules of a run. With neither evaluations nor iterations set, continuous and
/// callback problems get 10,000 evaluations per dimension (the CEC convention) and grids 50
/// iterations (the papers' T).
struct Budget {
    std::optional<std::int64_t> evaluations;
    std::optional<std::int64_t> iterations;
    std::optional<double> target;   // stop once the best value is <= this
    std::optional<double> wall_ms;  // stop after this many milliseconds
    // Not a limit: decreasing values whose first reaching each run records exactly
    // (RunResult::target_hits; campaigns: COCO's targets f_opt + 10^k).
    std::vector<double> recorded_targets;
    // Not a limit either: increasing evaluation counts after each of which the run records its best
    // value so far (RunResult::checkpoints; campaigns: the CEC reports' checkpoints).
    std::vector<std::int64_t> recorded_evaluations;
    // Not a limit either: how many threads evaluate one population (1..256). Box algorithms hand
    // callbacks and grids (line and free encodings) a population cut into that many slices, one
    // per thread, with results bit-identical to one thread; continuous functions (cheaper than a
    // thread's wake-up) and chains (evaluated one at a time) run on the run's thread whatever it is.
    std::int64_t threads = 1;
    // Not a limit either: a flag a front end sets to stop its runs from outside (Python: Ctrl-C,
    // the interpreter's exit), read once per iteration (Termination::stop); empty costs nothing.
    std::shared_ptr<const std::atomic<bool>> stop;

    /// The stopping rules for a problem of `dimension` (grid: whether it is a grid problem);
    /// InputError naming the field for a limit out of range.
    Termination termination(std::size_t dimension, bool grid) const;
};

}  // namespace pride::engine

namespace pride::engine {

/// Reads a map file (any format of grid::read_map, with its options) and inflates its obstacles by `inflate` cells
/// (0..1000): what a GridSpec's map is made from. InputError naming the file or "inflate".
std::shared_ptr<const grid::GridMap> load_map(const std::string& file, std::int64_t inflate = 0,
                                              const grid::MapReadOptions& options = {});

/// The cell holding the world point (x, y) in metres. InputError(`where`, ...) when the map has no
/// world frame (the message ends "give `instead`"), the point lies outside the map (with its
/// bounds in metres) or in a blocked cell (naming the cell).
grid::Cell world_cell(const grid::GridMap& map, double x, double y, const std::string& where,
                      const std::string& instead);

/// `e` placed under `start` when its place is "start", under `goal` when it is "goal" (an empty
/// name keeps the place): a grid problem checks its ends as cells, and a front end that took an
/// end from a world point (`--goal-world`, `goal_world`) says so in the error, not `--goal`.
InputError endpoint_error(const InputError& e, const std::string& start, const std::string& goal);

}  // namespace pride::engine

#pragma once
// The algorithm registry: every algorithm by name, with a one-line summary, the spaces it runs on
// and its parameters declared once. Each family registers itself in its own file under
// engine/entries/ (see docs/adding-an-algorithm.md); the list of those files is made by CMake,
// so adding an algorithm is adding one file. `pride list`, the help texts, parameter checking in
// every front end and the parameter tables of docs/cli.md all come from here.
//
// Type erasure happens here, once per run: a runner receives a target (a variant of the concrete
// problem types, engine/targets.hpp) and visits it, so the run itself is fully typed.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/params.hpp"
#include "framework/mo_run_state.hpp"
#include "framework/observer.hpp"
#include "framework/result.hpp"
#include "framework/termination.hpp"
#include "problems/grid/path.hpp"
#include "problems/grid/polyline.hpp"

namespace pride::engine {

struct BoxTarget;      // engine/targets.hpp
struct ChainTarget;    // engine/targets.hpp
struct GridTarget;     // engine/targets.hpp
struct MoTarget;       // engine/mo_targets.hpp
struct MoChainTarget;  // engine/mo_targets.hpp

using ChainResult = BasicResult<grid::Path>;
using MoChainResult = BasicMultiObjectiveResult<std::vector<grid::Path>>;

/// What an observed box run calls at the end of every iteration (iteration 0: the initial
/// population); once per iteration, never per evaluation.
using BoxObserver = std::function<void(const IterationView&)>;

/// What a whole-map algorithm (A*, the exact optimum) returns: a legal path and the work it took
/// (A*: node expansions). A polyline planner (AlgorithmEntry::plans_polylines) returns its
/// polyline instead, empty when it found none.
struct GridSolution {
    grid::Path path;
    grid::Polyline polyline;
    /// The polyline's points as the planner checked them (any_angle.hpp's plane, cell (x, y) =
    /// [x, x + 1] x [y, y + 1]), when it has them: the engine checks these, not a conversion.
    std::vector<grid::Point> plane;
    std::int64_t work = 0;
    /// The planner's own time when it measures it (OMPL's: without waiting for its lock); else the
    /// engine's clock around the call.
    std::optional<double> planning_ms;
};

struct AlgorithmEntry {
    std::string name;     // pso, ga-plus, nlopt:LN_SBPLX, ...
    std::string family;   // the skeleton it configures: pso, ga, lso, nlopt, astar, exact
    std::string summary;  // one line
    std::vector<ParamSpec> params;

    /// Runs on a box (continuous problems, grids through the line and free encodings, callbacks).
    std::function<Result(const Params&, const BoxTarget&, const Termination&, std::uint64_t seed)> run_box;
    /// run_box with an observer (engine::run with an observer; box_algorithm sets both, one
    /// instantiation for the two). Empty: the entry's box runs cannot be observed.
    std::function<Result(const Params&, const BoxTarget&, const Termination&, std::uint64_t seed, const BoxObserver&)>
        run_box_observed;
    /// Runs on cell chains (grids with the chain encoding).
    std::function<ChainResult(const Params&, const ChainTarget&, const Termination&, std::uint64_t seed)> run_chain;
    /// Runs on a problem of several objectives (engine/multiobjective.hpp): its result is the
    /// non-dominated set. A multi-objective algorithm has no other runner.
    std::function<MultiObjectiveResult(const Params&, const MoTarget&, const Termination&, std::uint64_t seed)>
        run_multiobjective;
    /// Runs on a grid of several criteria searched on cell chains (the chain encoding); only a
    /// multi-objective entry may have it.
    std::function<MoChainResult(const Params&, const MoChainTarget&, const Termination&, std::uint64_t seed)>
        run_multiobjective_chain;
    /// Solves a grid as a whole (baselines): no budget, no seed.
    std::function<GridSolution(const GridTarget&)> solve_grid;
    /// Plans on a grid's plane as a whole with a seed and a budget (sampling-based planners: OMPL's):
    /// its validity checks are its evaluations, counted (GridSolution::work) and within the budget.
    std::function<GridSolution(const Params&, const GridTarget&, const Termination&, std::uint64_t seed)> sample_grid;
    /// Whole-map algorithms that return the exact optimum say so: the objective must have one
    /// (GridTarget::has_optimum), and the run records it beside the result.
    bool needs_optimum = false;
    /// Plans polylines in the map's plane (Theta*, the exact any-angle path), not cell chains: it
    /// runs on the length objective only, where a polyline's value is its Euclidean length.
    bool plans_polylines = false;
    /// False when one seed need not give the same bits: resumes and merges then compare its runs
    /// by their definition (problem, algorithm, seed), not by their values (OMPL's planners: a
    /// process-wide seed generator, and time limits).
    bool reproducible = true;
    /// The population on grids when none is given (for entries with a `pop` parameter): the papers'
    /// N = 20, IQGA's N = 40 (Zhang et al. 2025, table 1; docs/algorithms.md).
    std::int64_t grid_population = 20;
    /// Bytes a run needs besides the problem, for a population algorithm in `dimension`; checked
    /// against the machine's memory before anything is allocated.
    std::function<double(const Params&, std::size_t dimension)> memory;

    /// The grid encoding it plans on when neither the run nor the problem names one: the one its
    /// paper plans on (`chain` for Zhang et al.'s (2025) and Cai and Du's (2021) planners; `line` for PSO, LSO, ILSO
    /// and the GA, as Wan and Gao (2022) plan with them, and for every box algorithm). Filled in by the
    /// registry when left empty; whole-map algorithms (A*, exact) plan on the grid itself.
    std::string native_encoding;

    /// "box", "chain", "grid", "multi-objective": the spaces it runs on.
    std::vector<std::string> spaces() const;
    /// The grid encodings it can plan through: line and free with a box runner, chain with a chain one.
    std::vector<std::string> encodings() const;
    /// False for whole-map planners (A*, exact), which do not evaluate the objective: they have no
    /// evaluation budget, and comparisons at equal evaluations exempt them. A sampling planner's
    /// validity checks are its evaluations.
    bool evaluates() const { return !solve_grid; }
    /// Plans on the whole map (no encoding): solve_grid or sample_grid.
    bool whole_map() const { return solve_grid || sample_grid; }
    bool multiobjective() const { return static_cast<bool>(run_multiobjective); }
    const ParamSpec* param(std::string_view name) const;
};

class AlgorithmRegistry {
  public:
    /// Adds an entry; a name already registered is an error naming it (std::logic_error: a bug in
    /// a registration, not bad input).
    void add(AlgorithmEntry entry);
    /// The entry, or InputError("algo: unknown algorithm 'x' ...").
    const AlgorithmEntry& at(std::string_view name) const;
    const AlgorithmEntry* find(std::string_view name) const;
    const std::vector<AlgorithmEntry>& entries() const { return entries_; }

  private:
    std::vector<AlgorithmEntry> entries_;
};

/// The process's registry, with every built-in family registered at first use.
AlgorithmRegistry& algorithms();

/// Registers an algorithm from a translation unit linked into the program (a user's or a test's):
/// `static const pride::engine::Registration r{entry};` at namespace scope.
struct Registration {
    explicit Registration(AlgorithmEntry entry);
};

}  // namespace pride::engine

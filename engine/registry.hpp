#pragma once
// The algorithm registry: every algorithm by name, with a one-line summary, the spaces it runs on
// and its parameters declared once. Each family registers itself in its own file under
// engine/entries/ (see docs/adding-an-algorithm.md); the list of those files is made by CMake,
// so adding an algorithm is adding one file. `pride list`, the help texts, parameter checking in
// every front end and the parameter tables of docs/cli.md all come from here.
//
// Type erasure happens here, once per run: an entry's one runner receives a target (a variant of
// the concrete problem types, engine/target.hpp) and visits it, so the run itself is fully typed.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/params.hpp"
#include "engine/runner.hpp"

namespace pride::engine {

struct AlgorithmEntry {
    std::string name;     // pso, ga-plus, nlopt:LN_SBPLX, ...
    std::string family;   // the skeleton it configures: pso, ga, lso, nlopt, astar, exact
    std::string summary;  // one line
    std::vector<ParamSpec> params;

    /// The kinds of run it takes (runner.hpp); everything the registry says about where it runs
    /// (spaces, encodings, whether it evaluates) is read from here.
    Kinds kinds;
    /// Runs it: visits the target once (one of `kinds`) and runs typed code. The builders of
    /// engine/family.hpp make it; a builder that adds a kind wraps the runner it had.
    Runner run;
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
    /// Multi-objective entries: refuses, before the run, parameters that a run on this many
    /// objectives cannot honour (SMS-EMOA's population beyond what exact contributions allow).
    std::function<void(const Params&, std::size_t objectives)> check_objectives;

    /// The grid encoding it plans on when neither the run nor the problem names one: the one its
    /// paper plans on (`chain` for Zhang et al.'s (2025) and Cai and Du's (2021) planners; `line` for PSO, LSO, ILSO
    /// and the GA, as Wan and Gao (2022) plan with them, and for every box algorithm). Filled in by the
    /// registry when left empty; whole-map algorithms (A*, exact) plan on the grid itself.
    std::string native_encoding;

    /// "box", "chain", "grid", "multi-objective": the spaces it runs on.
    std::vector<std::string> spaces() const;
    /// The grid encodings it can plan through: line and free on boxes, chain on chains.
    std::vector<std::string> encodings() const;
    /// False for whole-map planners (A*, exact), which do not evaluate the objective: they have no
    /// evaluation budget, and comparisons at equal evaluations exempt them. A sampling planner's
    /// validity checks are its evaluations.
    bool evaluates() const { return !runs(Kind::grid); }
    /// Plans on the whole map (no encoding): solved or sampled.
    bool whole_map() const { return runs(Kind::grid) || runs(Kind::sampled_grid); }
    bool multiobjective() const { return runs(Kind::multiobjective); }
    bool runs(Kind kind) const { return kinds.has(kind); }
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

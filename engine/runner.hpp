#pragma once
// What an algorithm's one runner receives and returns. The engine hands every run of an entry to
// the same function: a request (parameters, stopping rules, seed, optional observer) and a target,
// a variant over the kinds of run (engine/target.hpp). The runner visits the target once and then
// runs fully typed code, so type erasure happens once per run, never per evaluation.
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <optional>
#include <variant>
#include <vector>

#include "engine/params.hpp"
#include "framework/mo_run_state.hpp"
#include "framework/observer.hpp"
#include "framework/result.hpp"
#include "framework/termination.hpp"
#include "problems/grid/path.hpp"
#include "problems/grid/polyline.hpp"

namespace pride::engine {

struct BoxTarget;             // engine/target.hpp
struct ChainTarget;           // engine/target.hpp
struct GridTarget;            // engine/target.hpp
struct MoBoxTarget;           // engine/target.hpp
struct MoChainTarget;         // engine/target.hpp
struct ConstrainedBoxTarget;  // engine/target.hpp

/// What a run searches or plans on: a box (continuous problems, grids through the line and free
/// encodings, callbacks), cell chains, a whole grid, the same box and chains with several
/// objectives, and a box with constraints.
using Target = std::variant<BoxTarget, ChainTarget, GridTarget, MoBoxTarget, MoChainTarget, ConstrainedBoxTarget>;

/// The kinds of run an entry's runner takes. A whole grid is planned on in two ways: solved (no
/// budget, no seed, no evaluations: A*, the exact optimum) or sampled (seeded, its validity
/// checks counted as evaluations within the budget: OMPL's planners); both receive a GridTarget.
enum class Kind : unsigned {
    box = 1u << 0,
    chain = 1u << 1,
    grid = 1u << 2,
    sampled_grid = 1u << 3,
    multiobjective = 1u << 4,
    multiobjective_chain = 1u << 5,
    constrained_box = 1u << 6,
};

/// A set of kinds: what an entry declares it runs on.
class Kinds {
  public:
    constexpr Kinds() = default;
    constexpr Kinds(std::initializer_list<Kind> kinds) {
        for (const Kind k : kinds) add(k);
    }
    constexpr void add(Kind k) { bits_ |= static_cast<unsigned>(k); }
    constexpr bool has(Kind k) const { return (bits_ & static_cast<unsigned>(k)) != 0; }
    constexpr bool empty() const { return bits_ == 0; }

  private:
    unsigned bits_ = 0;
};

using ChainResult = BasicResult<grid::Path>;
using MoChainResult = BasicMultiObjectiveResult<std::vector<grid::Path>>;

/// What an observed box run calls at the end of every iteration (iteration 0: the initial
/// population); once per iteration, never per evaluation.
using BoxObserver = std::function<void(const IterationView&)>;

/// One run as the engine asks for it, after every check.
struct RunRequest {
    Params params;
    Termination termination;
    std::uint64_t seed = 0;
    /// Box runs only; null: not observed.
    const BoxObserver* observer = nullptr;
};

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

/// A runner's result, by the kind of run: box, chain, whole grid, multi-objective box and chain.
using Outcome = std::variant<Result, ChainResult, GridSolution, MultiObjectiveResult, MoChainResult>;

/// An entry's one runner.
using Runner = std::function<Outcome(const RunRequest&, const Target&)>;

}  // namespace pride::engine

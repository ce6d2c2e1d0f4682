#pragma once
// The concrete problem types the engine runs, one struct per kind of run (the alternatives of
// Target, engine/runner.hpp): an entry's runner visits the target once per run and then executes
// fully typed code (no virtual call per evaluation). Grid objectives linear in a path's metrics
// share one type (LinearObjective), and the connector is a run-time setting, so the grid
// contributes four box types and two chain types; the continuous functions one (catalog.hpp).
// With several objectives: the catalog (one type for ZDT and DTLZ), a grid through each of the two
// box encodings and a user's function, and a grid on cell chains.
#include <memory>
#include <mutex>
#include <optional>
#include <variant>

#include "engine/callback.hpp"
#include "engine/other_objective.hpp"
#include "engine/runner.hpp"
#include "framework/encoding.hpp"
#include "problems/continuous/bbob_constrained/bbob_constrained.hpp"
#include "problems/continuous/catalog.hpp"
#include "problems/continuous/cec2006/cec2006.hpp"
#include "problems/continuous/cec2020rw/cec2020rw.hpp"
#include "problems/grid/chain.hpp"
#include "problems/grid/connectors.hpp"
#include "problems/grid/encodings.hpp"
#include "problems/grid/grid_problem.hpp"
#include "problems/grid/multiobjective.hpp"
#include "problems/grid/objectives.hpp"
#include "problems/multiobjective/catalog.hpp"
#include "problems/multiobjective/constrained.hpp"
#include "problems/multiobjective/re/re.hpp"

namespace pride::engine {

template <class Objective>
using GridLine = Encoded<grid::GridProblem<Objective>, grid::LineEncoding<grid::SelectableConnector>>;
template <class Objective>
using GridFree = Encoded<grid::GridProblem<Objective>, grid::FreeEncoding<grid::SelectableConnector>>;

// Every continuous function is one type (continuous::Function: dispatch once per batch), so an
// algorithm is compiled once for all of them.
// The grid's objectives are two types: the linear ones (cells, length, weighted, hswoa) and the
// others (iqga, a user's: other_objective.hpp).
using BoxVariant = std::variant<continuous::Function, GridLine<grid::LinearObjective>, GridLine<OtherObjective>,
                                GridFree<grid::LinearObjective>, GridFree<OtherObjective>, CallbackProblem>;
using ChainVariant = std::variant<grid::ChainSpace<grid::LinearObjective>, grid::ChainSpace<OtherObjective>>;
using GridVariant = std::variant<grid::GridProblem<grid::LinearObjective>, grid::GridProblem<OtherObjective>>;

/// A problem an algorithm searches as a box of reals. Each run copies the alternative it holds.
struct BoxTarget {
    BoxVariant problem;
};
/// A problem whose solutions are cell chains, searched with the chain operators.
struct ChainTarget {
    ChainVariant problem;
};
/// The exact optimum of iqga (over the 3-D Pareto front, problems/grid/pareto.hpp), worked out
/// once per prepared problem and shared by its copies and its runs.
struct FrontOptimum {
    std::once_flag once;
    std::optional<double> value;
    grid::Path path;
};

/// What scores the paths of one prepared problem (its clearance field), and its shortest lengths
/// (GridSpec::path_gaps), each made once and shared by the problem's copies and runs.
struct PathScoring {
    std::once_flag scorer_once, lengths_once;
    std::optional<grid::PolylineScorer> scorer;
    double grid_length = -1.0, any_angle_length = -1.0;  // -1: unreachable
};

/// A grid problem as whole-map algorithms (A*, the exact optimum) see it.
struct GridTarget {
    GridVariant problem;
    std::shared_ptr<FrontOptimum> front_optimum = std::make_shared<FrontOptimum>();
    std::shared_ptr<PathScoring> scoring = std::make_shared<PathScoring>();
    bool additive() const {
        return std::visit([](const auto& p) { return std::decay_t<decltype(p.objective())>::additive; }, problem);
    }
    /// The optimum is the oracle's (an additive objective, or a user's with per-step costs), not
    /// iqga's Pareto front.
    bool additive_or_steps() const {
        if (const auto* o = std::get_if<grid::GridProblem<OtherObjective>>(&problem))
            return o->objective().user && o->objective().has_steps();
        return true;
    }
    /// The objective has an exact optimum: the additive ones through the oracle (oracle.hpp),
    /// iqga through the 3-D Pareto front (pareto.hpp), a user's through the oracle on its per-step
    /// form when it gives one.
    bool has_optimum() const {
        if (const auto* o = std::get_if<grid::GridProblem<OtherObjective>>(&problem))
            return !o->objective().user || o->objective().has_steps();
        return true;
    }
};

using MoGridLine = grid::MultiObjectivePaths<grid::LineEncoding<grid::SelectableConnector>>;
using MoGridFree = grid::MultiObjectivePaths<grid::FreeEncoding<grid::SelectableConnector>>;
using MoVariant = std::variant<multiobjective::Benchmark, MoGridLine, MoGridFree, MoCallbackProblem,
                               multiobjective::ConstrainedBenchmark, multiobjective::re::Problem>;

/// A problem of several objectives searched as a box: its result is the non-dominated set.
struct MoBoxTarget {
    MoVariant problem;
};

/// A grid of several criteria on cell chains (the chain encoding), for the algorithms that have
/// chain operators (Kind::multiobjective_chain).
using MoGridChain = grid::MultiObjectiveChains;
struct MoChainTarget {
    MoGridChain problem;
};

/// A box with constraints, for the algorithms that handle them (Kind::constrained_box).
using ConstrainedVariant = std::variant<continuous::cec2006::Problem, continuous::cec2020rw::Problem,
                                        ConstrainedCallbackProblem, continuous::bbob_constrained::Problem>;
struct ConstrainedBoxTarget {
    ConstrainedVariant problem;
};

/// The exact optimum of the target's objective and one optimal path (into `out` when given), or
/// -1 when the goal cannot be reached: the oracle for an additive objective, the least iqga value
/// on the 3-D Pareto front for iqga (computed once per prepared problem).
double grid_optimum(const GridTarget& target, grid::Path* out);

}  // namespace pride::engine

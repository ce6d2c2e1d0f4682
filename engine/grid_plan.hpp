#pragma once
// What a run plans on, made from a grid spec: the one place where the spec's encoding, connector,
// waypoints and initial walks become a chain space or an encoding, for runs of one objective and of
// several alike.
#include <variant>

#include "engine/specs.hpp"
#include "problems/grid/chain.hpp"
#include "problems/grid/connectors.hpp"
#include "problems/grid/encodings.hpp"
#include "problems/grid/grid_problem.hpp"

namespace pride::engine {

using LinePlan = grid::LineEncoding<grid::SelectableConnector>;
using FreePlan = grid::FreeEncoding<grid::SelectableConnector>;

/// The chain space (the chain encoding), or the line or free encoding with its connector.
template <class Objective>
using GridPlan = std::variant<grid::ChainSpace<Objective>, LinePlan, FreePlan>;

/// What a run on `problem` plans through by the spec's encoding (empty: line): on chains, a space
/// that starts from SITP walks with init sitp, else from random walks; on line and free, the
/// encoding of the spec's waypoints joined by its connector. InputError when the encoding cannot be
/// built on the map.
template <class Objective>
GridPlan<Objective> plan_grid(const GridSpec& g, const grid::GridProblem<Objective>& problem);

/// The walks a problem's suggested starting points come from (line and free): rule walks unless
/// random (init walk) or SITP walks (init sitp) are asked for.
grid::Walks suggested_walks(const GridSpec& g);

}  // namespace pride::engine

#include "engine/grid_plan.hpp"

#include <utility>

#include "engine/other_objective.hpp"
#include "problems/grid/objectives.hpp"

namespace pride::engine {

template <class Objective>
GridPlan<Objective> plan_grid(const GridSpec& g, const grid::GridProblem<Objective>& problem) {
    if (g.encoding == "chain") {
        grid::ChainSpace<Objective> space(problem);
        if (g.init == "sitp") space.set_init(grid::Walks::sitp);
        return GridPlan<Objective>(std::in_place_type<grid::ChainSpace<Objective>>, std::move(space));
    }
    // check_grid_names admits repair and penalty only.
    const grid::SelectableConnector connector(g.connector == "penalty" ? grid::SelectableConnector::Kind::penalty
                                                                       : grid::SelectableConnector::Kind::repair);
    if (g.encoding == "free") return FreePlan(problem, static_cast<int>(g.waypoints), connector);
    return LinePlan(problem, connector);
}

// The objectives grids are planned with: the linear ones and the others (one objective), and the
// cell count under the criteria of several.
template GridPlan<grid::LinearObjective> plan_grid(const GridSpec&, const grid::GridProblem<grid::LinearObjective>&);
template GridPlan<OtherObjective> plan_grid(const GridSpec&, const grid::GridProblem<OtherObjective>&);
template GridPlan<grid::CellsObjective> plan_grid(const GridSpec&, const grid::GridProblem<grid::CellsObjective>&);

grid::Walks suggested_walks(const GridSpec& g) {
    return g.init == "walk" ? grid::Walks::random : g.init == "sitp" ? grid::Walks::sitp : grid::Walks::rules;
}

}  // namespace pride::engine

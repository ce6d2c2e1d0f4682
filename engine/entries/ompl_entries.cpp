// OMPL's asymptotically optimal sampling-based planners (problems/grid/planners/ompl_planner.hpp) as
// seeded, budgeted whole-map planners on the grid's plane: ompl:RRTstar, ompl:InformedRRTstar,
// ompl:BITstar, ompl:PRMstar. Compiled only when OMPL is built (engine/CMakeLists.txt).
//
// The budget is the run's evaluations: every state and motion validity check counts one, and the
// planner stops when they are spent (or at the budget's wall time); the result is its best path
// then, a polyline whose value is its length (the length objective only, as every polyline
// planner). The project's decisions: OMPL's path simplification is a parameter, off by default
// (with it a tenth of the checks is kept for the simplifier, so both stay within the budget); PRM* only grows its
// roadmap (OMPL's solve() alternates on a wall-clock timer, which no seed reproduces). With an
// evaluation budget alone a seed gives the same path in any process of the same build, but OMPL
// draws its seeds from one process-wide generator (runs are serialised behind a lock) and a wall
// time never reproduces: the entries are marked not reproducible, so that merges compare their
// runs by definition.
#include <chrono>
#include <cmath>

#include "problems/grid/planners/ompl_planner.hpp"
#include "problems/grid/polyline.hpp"

#include "engine/family.hpp"

namespace pride::engine {

namespace {

const char* summary_of(const std::string& planner) {
    if (planner == "RRTstar") return "grids only: OMPL's RRT* (Karaman and Frazzoli 2011), a seeded sampling planner";
    if (planner == "InformedRRTstar")
        return "grids only: OMPL's Informed RRT* (Gammell, Srinivasa and Barfoot 2014), a seeded sampling planner";
    if (planner == "BITstar")
        return "grids only: OMPL's BIT* (Gammell, Srinivasa and Barfoot 2015), a seeded sampling planner";
    return "grids only: OMPL's PRM* (Karaman and Frazzoli 2011), the roadmap grown only, a seeded sampling planner";
}

}  // namespace

void register_ompl(AlgorithmRegistry& registry) {
    for (const std::string& planner : grid::ompl_planner_names()) {
        AlgorithmEntry e;
        e.name = "ompl:" + planner;
        e.family = "ompl";
        e.summary = summary_of(planner);
        e.plans_polylines = true;
        e.reproducible = false;
        e.params = {flag("simplify", false,
                         "OMPL's PathSimplifier::simplifyMax on the path found, with a tenth of the evaluations "
                         "kept for it (planning and simplifying within the budget)")};
        add_runner<GridTarget>(e, Kind::sampled_grid, [planner](const RunRequest& r, const GridTarget& target) {
            grid::OmplRequest request;
            request.planner = planner;
            request.max_checks = r.termination.max_evaluations.value_or(0);
            if (r.termination.wall_time)
                request.time_limit_s = std::chrono::duration<double>(*r.termination.wall_time).count();
            request.simplify = r.params.flag("simplify");
            request.seed = r.seed;
            return std::visit(
                [&](const auto& g) {
                    const grid::OmplOutcome o = grid::plan_with_ompl(g.map(), g.start(), g.goal(), request);
                    GridSolution s;
                    if (o.solved) {
                        s.polyline = grid::polyline_of(o.polyline);
                        s.plane = o.polyline;
                    }
                    s.work = o.state_checks + o.motion_checks + o.simplify_checks;
                    s.planning_ms = o.planning_ms;
                    return s;
                },
                target.problem);
        });
        registry.add(std::move(e));
    }
}

}  // namespace pride::engine

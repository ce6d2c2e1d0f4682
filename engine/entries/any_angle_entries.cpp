// Any-angle planners on the grid's plane (problems/grid/planners/theta_star.hpp, any_angle.hpp) as
// whole-map baselines: Theta* (Nash et al. 2007), Lazy Theta* (Nash, Koenig and Tovey 2010) and
// the exact any-angle shortest path (a visibility graph over the obstacles' convex corners). Their
// paths are polylines, not cell chains, so they plan for the length objective only: a polyline's
// value is its Euclidean length, which the chain objectives (cells, turns, angle penalties) do
// not define.
#include "problems/grid/planners/any_angle.hpp"
#include "problems/grid/planners/theta_star.hpp"
#include "problems/grid/polyline.hpp"

#include "engine/family.hpp"

namespace pride::engine {

namespace {

AlgorithmEntry theta_star(bool lazy) {
    AlgorithmEntry e;
    e.name = lazy ? "lazy-theta-star" : "theta-star";
    e.family = "theta-star";
    e.summary = lazy ? "grids only: Lazy Theta* (Nash, Koenig and Tovey 2010), any-angle paths between cell "
                       "centres, one line-of-sight test per expansion"
                     : "grids only: Theta* (Nash, Daniel, Koenig and Felner 2007), any-angle paths between cell "
                       "centres";
    e.plans_polylines = true;
    add_runner<GridTarget>(e, Kind::grid, [lazy](const RunRequest&, const GridTarget& target) {
        return std::visit(
            [lazy](const auto& g) {
                grid::ThetaStar search(lazy);
                std::vector<grid::Cell> vertices;
                GridSolution s;
                if (search.search(g.map(), g.start(), g.goal(), &vertices) >= 0.0)
                    s.polyline = grid::polyline_of(grid::centres(vertices));
                s.work = search.expansions();
                return s;
            },
            target.problem);
    });
    // Its records (g, parent, stamp: 16 bytes) for every cell of the map, and its heap.
    e.memory = [](const Params&, std::size_t cells) { return 32.0 * static_cast<double>(cells); };
    return e;
}

}  // namespace

void register_any_angle(AlgorithmRegistry& registry) {
    registry.add(theta_star(false));
    registry.add(theta_star(true));
    AlgorithmEntry e;
    e.name = "any-angle-exact";
    e.family = "any-angle-exact";
    e.summary =
        "grids only: the exact any-angle shortest path (visibility graph over the obstacles' convex "
        "corners, A*), the polylines' optimum";
    e.plans_polylines = true;
    add_runner<GridTarget>(e, Kind::grid, [](const RunRequest& r, const GridTarget& target) {
        // The run's wall time and stop flag reach into the search: it has no iterations to stop
        // between, and takes minutes on a large map with many obstacles (docs/reliability.md).
        std::optional<std::chrono::steady_clock::time_point> deadline;
        if (r.termination.wall_time) deadline = std::chrono::steady_clock::now() + *r.termination.wall_time;
        return std::visit(
            [&](const auto& g) {
                grid::AnyAngleOracle oracle(g.map());
                oracle.set_limits(deadline, r.termination.stop);
                std::vector<grid::Point> points;
                GridSolution s;
                if (oracle.solve(g.start(), g.goal(), &points) >= 0.0) {
                    s.polyline = grid::polyline_of(points);
                    s.plane = std::move(points);
                }
                s.work = oracle.segment_tests();
                return s;
            },
            target.problem);
    });
    // Per cell at most one corner, with its g, parent, flags and heap entry (about 40 bytes).
    e.memory = [](const Params&, std::size_t cells) { return 40.0 * static_cast<double>(cells); };
    registry.add(std::move(e));
}

}  // namespace pride::engine

// A* (problems/grid/planners/astar.hpp) as a whole-map baseline: the shortest path by length.
#include "problems/grid/planners/astar.hpp"

#include "engine/family.hpp"

namespace pride::engine {

void register_astar(AlgorithmRegistry& registry) {
    AlgorithmEntry e;
    e.name = "astar";
    e.family = "astar";
    e.summary = "grids only: A* with the octile heuristic, the shortest path by length";
    add_runner<GridTarget>(e, Kind::grid, [](const RunRequest&, const GridTarget& target) {
        return std::visit(
            [](const auto& g) {
                grid::AStar astar;
                GridSolution s;
                astar.search(g.map(), g.start(), g.goal(), &s.path, nullptr, g.corner_cutting());
                s.work = astar.expansions();
                return s;
            },
            target.problem);
    });
    // Its records (g, parent, stamp: 16 bytes) for every cell of the map.
    e.memory = [](const Params&, std::size_t cells) { return 16.0 * static_cast<double>(cells); };
    registry.add(std::move(e));
}

}  // namespace pride::engine

// Jump Point Search (problems/grid/planners/jps.hpp) as a whole-map baseline: A*'s shortest path by
// length, found by expanding jump points only (Harabor and Grastien 2011, no corner cutting).
#include "problems/grid/planners/jps.hpp"

#include "engine/family.hpp"

namespace pride::engine {

void register_jps(AlgorithmRegistry& registry) {
    AlgorithmEntry e;
    e.name = "jps";
    e.family = "jps";
    e.summary = "grids only: Jump Point Search (no corner cutting), the shortest path by length as A*, faster";
    add_runner<GridTarget>(e, Kind::grid, [](const RunRequest&, const GridTarget& target) {
        return std::visit(
            [](const auto& g) {
                grid::JumpPointSearch jps;
                GridSolution s;
                jps.search(g.map(), g.start(), g.goal(), &s.path, g.corner_cutting());
                s.work = jps.expansions();
                return s;
            },
            target.problem);
    });
    // Its records (g, parent, stamp: 16 bytes) for every cell of the map.
    e.memory = [](const Params&, std::size_t cells) { return 16.0 * static_cast<double>(cells); };
    registry.add(std::move(e));
}

}  // namespace pride::engine

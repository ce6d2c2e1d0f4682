// The exact optimum as a whole-map baseline: the oracle (problems/grid/planners/oracle.hpp) for every
// objective that is a sum of step and turn costs, the 3-D Pareto front (problems/grid/pareto.hpp)
// for iqga, whose minimum lies on it.
#include "problems/grid/planners/oracle.hpp"

#include "engine/family.hpp"

namespace pride::engine {

void register_exact(AlgorithmRegistry& registry) {
    AlgorithmEntry e;
    e.name = "exact";
    e.family = "exact";
    e.summary = "grids only: the exact optimum, over (cell, last direction); iqga: over the 3-D Pareto front";
    e.needs_optimum = true;
    add_runner<GridTarget>(e, Kind::grid, [](const RunRequest&, const GridTarget& target) {
        GridSolution s;
        if (!target.additive()) {
            grid_optimum(target, &s.path);
            return s;
        }
        return std::visit(
            [&s](const auto& g) {
                if constexpr (std::decay_t<decltype(g.objective())>::additive) {
                    grid::Oracle oracle;
                    oracle.solve(g.map(), g.start(), g.goal(), g.objective(), &s.path, g.corner_cutting());
                }
                return s;  // work 0: the oracle's expansions are not evaluations
            },
            target.problem);
    });
    registry.add(std::move(e));
}

}  // namespace pride::engine

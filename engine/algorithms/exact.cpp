// The exact optimum (problems/grid/oracle.hpp) as a whole-map baseline, for every objective that is
// a sum of step and turn costs.
#include "problems/grid/oracle.hpp"

#include "engine/family.hpp"

namespace pride::engine {

void register_exact(AlgorithmRegistry& registry) {
    AlgorithmEntry e;
    e.name = "exact";
    e.family = "exact";
    e.summary = "grids only: the exact optimum of an additive objective, over (cell, last direction)";
    e.needs_additive_objective = true;
    e.solve_grid = [](const GridTarget& target) {
        return std::visit(
            [](const auto& g) {
                GridSolution s;
                if constexpr (std::decay_t<decltype(g.objective())>::additive) {
                    grid::Oracle oracle;
                    oracle.solve(g.map(), g.start(), g.goal(), g.objective(), &s.path, g.corner_cutting());
                }
                return s;  // work 0: the oracle's expansions are not evaluations
            },
            target.problem);
    };
    registry.add(std::move(e));
}

}  // namespace pride::engine

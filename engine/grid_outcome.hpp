#pragma once
// What a grid run found, beside the search's own result, and how it is scored: whether the path is
// legal, its value and metrics, the exact optimum beside it, and its gaps to the problem's shortest
// lengths. Every planner's path is scored the same way, whoever planned it.
#include <optional>
#include <string>

#include "engine/runner.hpp"
#include "problems/grid/path.hpp"
#include "problems/grid/polyline.hpp"

namespace pride::engine {

/// What a grid run found, beside the search's own result.
struct GridOutcome {
    std::string encoding = "none";  // line, free, chain; none for whole-map algorithms
    bool feasible = false;          // an infeasible candidate is never returned as a path
    grid::Path path;                // start first; empty when infeasible or when the planner plans polylines
    double value = 0.0;             // the objective of the path (when feasible)
    std::optional<double> optimum;  // with GridSpec::oracle, or for the exact algorithm
    grid::Path optimal_path;
    // The path as every planner's is scored (problems/grid/polyline.hpp): a chain's cells, or a
    // polyline planner's vertices; empty when infeasible. Its metrics when feasible.
    grid::Polyline polyline;
    grid::PolylineMetrics metrics;
    // With GridSpec::path_gaps: the shortest lengths of the problem (the 8-connected grid's, by
    // A*, and the exact any-angle one) and the path's length over each, minus 1. Empty when the
    // run found no path or the goal cannot be reached.
    std::optional<double> shortest_grid_length, shortest_any_angle_length;
    std::optional<double> grid_gap, any_angle_gap;
};

/// The candidate is the result only when it is legal (grid.md: an infeasible candidate is never
/// returned as a result). `value` is its objective, known from the run's own evaluation: the
/// objective is not called again to report it (a user counting its calls sees the run's only).
void record_path(GridOutcome& o, const GridTarget& target, const grid::Path& candidate, bool no_violations,
                 double value);

/// A whole-map planner's solution as the result (its path or polyline moved out of `s`); returns
/// the run's best value: the path's, or +inf when a polyline planner found no legal polyline.
double record_solution(GridOutcome& o, const GridTarget& target, GridSolution& s, bool polylines);

/// What every grid run's outcome gets last: a user's objective checked against its optimum, and the
/// path's metrics, with `gaps` its gaps to the problem's shortest lengths.
void score_outcome(GridOutcome& o, const GridTarget& target, bool gaps);

}  // namespace pride::engine

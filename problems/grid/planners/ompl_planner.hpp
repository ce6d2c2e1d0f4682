#pragma once
// OMPL's asymptotically optimal sampling-based planners on the grid's plane (any_angle.hpp's
// geometry): the state is a point of [0, W] x [0, H], valid when point_is_free, and a motion is
// valid when segment_is_free, so every returned segment is free by pride's rules. The objective is
// the path's length; the planner runs until its budget ends and the result is its best path then.
//
// Built only when OMPL is found (CMake's PRIDE_HAVE_OMPL; the code that calls it, the engine's
// ompl.cpp and its tests, is compiled only then); this header includes no OMPL header.
//
// Budget: checks, time or both. Every state and motion validity check counts one (a motion check
// is one call, however long the segment); once max_checks have been made, further checks answer
// "invalid" without being made or counted, and the planner stops at its next termination test.
// So state_checks + motion_checks <= max_checks exactly (no slack).
//
// Reproducibility: with a check budget and no time limit, a seed gives the same polyline, counts
// and solved flag in the same process and across processes (same OMPL build, same map and
// request). plan_with_ompl reseeds OMPL's process-wide seed generator (ompl::RNG::setSeed) before
// it builds anything, so every RNG OMPL creates for the run (samplers, planner, nearest
// neighbours, simplifier) draws the same seeds; runs are serialised by a process-wide mutex so
// that no other run draws from that generator in between (run several in parallel as processes).
// PRMstar is driven by pride: OMPL's PRM::solve alternates growing and expanding the roadmap on a
// 0.2 s wall-clock timer and reads its solution from a second thread, neither reproducible, so the
// roadmap is only grown (OMPL's PRM::growRoadmap, PRM*'s k-nearest connections) and the shortest
// roadmap path is taken at the end. A time limit is never reproducible, nor are the times.
// OMPL's console output is silenced during a run (its log level restored afterwards).
#include <cstdint>
#include <string>
#include <vector>

#include "problems/grid/map.hpp"
#include "problems/grid/planners/any_angle.hpp"

namespace pride::grid {

struct OmplRequest {
    std::string planner;          // one of ompl_planner_names()
    double time_limit_s = 0.0;    // 0: no time limit
    std::int64_t max_checks = 0;  // budget in state and motion validity checks (0: none); at least one budget
    bool simplify = false;  // OMPL's PathSimplifier::simplifyMax on the solution (a tenth of max_checks kept for it)
    std::uint64_t seed = 1;
};

struct OmplOutcome {
    bool solved = false;                               // an exact solution reaching the goal
    std::vector<Point> polyline;                       // start centre first, goal centre last; empty when not solved
    double first_solution_ms = -1;                     // from the start of planning to the first solution (-1: none)
    double planning_ms = 0;                            // the planner's setup and solve, without simplification
    std::int64_t state_checks = 0, motion_checks = 0;  // within the budget
    std::int64_t simplify_checks = 0;                  // the simplifier's checks (states and motions)
};

/// "RRTstar", "InformedRRTstar", "BITstar", "PRMstar".
const std::vector<std::string>& ompl_planner_names();

/// Plans from the centre of `start` to the centre of `goal`. InputError naming the field for an
/// unknown planner, no budget, a negative or non-finite budget, or a start or goal outside or
/// blocked. start == goal: solved with one point, no planning.
OmplOutcome plan_with_ompl(const GridMap& map, Cell start, Cell goal, const OmplRequest& request);

}  // namespace pride::grid

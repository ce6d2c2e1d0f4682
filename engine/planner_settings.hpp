#pragma once
// The settings of one planning run (`pride path`, Python's plan) that a whole-map planner (A*,
// the exact optimum, JPS, Theta*, Lazy Theta*, the exact any-angle path, OMPL's planners) does
// not use: refused in one line naming the setting, never silently ignored. A campaign is not
// checked here: its budget and its problems' settings are shared by every algorithm it runs, so
// a planner beside a metaheuristic takes them without using them (experiment/campaign/run_one.cpp
// records no evaluation budget beside its runs).
#include <string>

#include "engine/registry.hpp"
#include "engine/specs.hpp"
#include "framework/error.hpp"

namespace pride::engine {

/// How the front end names each setting in its messages (the engine's words by default; the
/// command line turns them into its flags).
struct PlannerSettingNames {
    std::string encoding = "encoding";
    std::string init = "init";
    std::string connector = "connector";
    std::string waypoints = "waypoints";
    std::string threads = "threads";
    std::string evaluations = "evaluations";
    std::string iterations = "iterations";
};

/// InputError naming the first setting of `spec` and `budget` that `algorithm`, a whole-map
/// planner, would ignore. Other algorithms (and unknown names, which check() refuses) pass. A
/// planner that counts evaluations (OMPL's validity checks: AlgorithmEntry::evaluates) keeps its
/// evaluation budget.
inline void refuse_unused_planner_settings(const AlgorithmSpec& algorithm, const GridSpec& spec, const Budget& budget,
                                           const PlannerSettingNames& names = {}) {
    const AlgorithmEntry* entry = algorithms().find(algorithm.name);
    if (!entry || !entry->whole_map()) return;
    const std::string planner = entry->name + " plans on the whole map";
    require(spec.encoding.empty(), names.encoding,
            planner + ", not through an encoding; it has no meaning there: leave it out");
    require(spec.init.empty(), names.init,
            planner + " and starts from no population; it has no meaning there: leave it out");
    require(spec.connector == "repair", names.connector,
            planner + " and joins no waypoints; it has no meaning there: leave it out");
    require(spec.waypoints == 3, names.waypoints, planner + ", it has no waypoints: leave it out");
    require(budget.threads == 1, names.threads, planner + " on one thread; it has no meaning there: leave it out");
    require(!budget.iterations, names.iterations,
            planner + " in one search, not in iterations; it has no meaning there: leave it out");
    require(entry->evaluates() || !budget.evaluations, names.evaluations,
            planner +
                " and evaluates no objective, so it has no evaluation budget (its work is reported as work): "
                "leave it out");
}

}  // namespace pride::engine

#pragma once
// `pride path` (one run on a grid) and `pride scen` (A* against Moving AI scenario files), as in
// shared/spec/cli.md.
#include <cstdint>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "problems/grid/map.hpp"
#include "problems/grid/path.hpp"

namespace pride::cli {

struct PathOptions {
    std::string map;
    std::string start;  // "X,Y"
    std::string goal;
    std::string algo;
    std::string objective = "cells";
    std::string encoding = "line";
    std::string connector = "repair";
    // uniform, walk (random feasible walks) or rules (file 000's rough-set rule walks); empty: the
    // algorithm's own choice (rules for ilso, uniform for the others)
    std::string init;
    std::optional<std::int64_t> pop;
    std::optional<std::int64_t> iters;
    std::optional<std::int64_t> evals;
    std::int64_t seed = 1;
    std::int64_t inflate = 0;
    std::int64_t waypoints = 3;
    std::optional<std::string> weights;  // "L,T,A" for the weighted objective
    std::optional<double> lambda;        // for the hswoa objective
    bool corner_cutting = false;
    bool oracle = false;
    bool json = false;
    std::string svg;
    std::string png;
    std::vector<std::string> params;
};
int path_command(const PathOptions& o, std::ostream& out);

/// What one run on a grid produced, whatever made it (pride path, campaigns).
struct PathRun {
    std::string encoding = "none";
    bool feasible = false;
    grid::Path path;     // start first
    double value = 0.0;  // the objective of the path (when feasible)
    std::int64_t evaluations = 0;
    std::int64_t iterations = 0;
    double wall_ms = 0.0;
    std::vector<double> history;
    std::vector<std::int64_t> history_evaluations;
    std::optional<double> optimum;  // with o.oracle (or algo exact)
    grid::Path optimal_path;
};

/// Loads the map and runs `o.algo` on it as `pride path` does (no printing, no pictures); the map
/// as loaded (inflated) into `map` when given.
PathRun plan_path(const PathOptions& o, std::shared_ptr<const grid::GridMap>* map = nullptr);

struct ScenOptions {
    std::string file;
    std::string map_dir;  // default: the scenario file's folder
    bool json = false;
};
int scen_command(const ScenOptions& o, std::ostream& out);

}  // namespace pride::cli

#pragma once
// `pride path` (one run on a grid) and `pride scen` (A* against Moving AI scenario files), as in
// docs/cli.md.
#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "engine/run.hpp"
#include "engine/specs.hpp"

namespace pride::cli {

struct PathOptions {
    std::string map;
    std::string start;  // "X,Y"
    std::string goal;
    std::string start_world;  // "X,Y" in metres, instead of start (maps with a world frame)
    std::string goal_world;
    bool unknown_free = false;  // unknown cells of image maps free (grid::MapReadOptions)
    std::string algo;
    // Empty: the algorithm's own: length for a planner of polylines (its only one), cells otherwise.
    std::string objective;
    std::string encoding;  // empty: the algorithm's native one
    std::string connector = "repair";
    // uniform, walk (random feasible walks) or rules (Wan and Gao's (2022) rough-set rule walks); empty: the
    // algorithm's own choice (rules for ilso, uniform for the others)
    std::string init;
    std::optional<std::string> pop;  // as given: its range is the algorithm's
    engine::Budget budget;           // --iters, --evals, --threads
    std::uint64_t seed = 1;
    std::int64_t inflate = 0;
    std::optional<std::int64_t> waypoints;  // free only (default 3); named with another encoding: refused
    std::optional<std::string> weights;     // "L,T,A" for the weighted objective
    std::optional<double> lambda;           // for the hswoa objective
    bool corner_cutting = false;
    bool oracle = false;
    bool gaps = false;  // the shortest grid and any-angle lengths and the path's gaps to them
    bool json = false;
    std::string svg;
    std::string png;
    std::vector<std::string> params;
};
int path_command(const PathOptions& o, std::ostream& out);

/// Loads the map and runs `o.algo` on it as `pride path` does (no printing, no pictures); the spec
/// it ran (the map as loaded and inflated, start, goal) into `spec` when given.
engine::RunResult plan_path(const PathOptions& o, engine::GridSpec* spec = nullptr);

/// The words of `pride path`'s picture legend for the run's path and for the exact optimum
/// (html::PathLabels); on a map with a world frame each also gives its length in cells and metres.
std::pair<std::string, std::string> picture_labels(const PathOptions& o, const engine::GridSpec& spec,
                                                   const engine::GridOutcome& run);

/// A cell given as "X,Y" (integers); InputError naming `where` otherwise.
grid::Cell parse_cell(const std::string& text, const std::string& where);
/// The cell holding the world point "X,Y" (metres) of `map`; InputError naming `where` when the map
/// has no world frame or the point is outside it.
grid::Cell parse_world_cell(const std::string& text, const grid::GridMap& map, const std::string& where);
/// A path's cells as world points (cell centres, rounded to 1e-9 m), "[[x, y], ...]".
std::string json_world_path(const grid::GridMap& map, const grid::Path& path);

struct ScenOptions {
    std::string file;
    std::string map_dir;  // default: the scenario file's folder
    bool json = false;
};
int scen_command(const ScenOptions& o, std::ostream& out);

}  // namespace pride::cli

#pragma once
// What the HTML report reads from a campaign store beyond storage::read_store (which it reads
// first, so the store is known to be sound): the campaign file's text, where each grid problem's
// map is, each algorithm's best path on it, and the fronts of multi-objective runs.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "framework/problem.hpp"
#include "problems/grid/map.hpp"
#include "problems/grid/path.hpp"
#include "problems/grid/polyline.hpp"

namespace pride::html {

struct GridProblemInfo {
    std::string id;
    std::string map;  // the map file as pride bench resolved it (absolute); empty for a map given in code
    grid::Cell start, goal;
    std::int64_t inflate = 0;
    bool unknown_free =
        false;  // from the definition too     // from the problem's definition (0 in stores from before definitions)
    bool corner_cutting = false;  // likewise
};

/// The best run of one algorithm on one grid problem: the lowest feasible value (ties: the
/// lowest seed) and its path.
struct BestPath {
    std::string problem, algorithm;
    std::int64_t seed = 0;
    double value = 0;
    std::optional<double> optimum;  // the exact optimum, when the campaign had it computed
    grid::Path path;
    grid::Polyline polyline;  // a polyline planner's path (runs.polyline; `path` is then empty)
};

/// A multi-objective run's front as stored (experiment/campaign.cpp, engine::front_json).
struct StoredFront {
    std::string problem, algorithm;
    std::int64_t seed = 0;
    std::vector<std::string> objectives;  // their names, M of them
    double hypervolume_ratio = 0;
    Matrix f;                       // M rows, one column per point
    std::vector<grid::Path> paths;  // grids: each point's path
    std::vector<char> legal;        // grids: whether it is a legal path
    std::string error;              // not empty: the solution is not what pride bench writes (why)
};

struct PageStore {
    std::string text;  // the campaign file as stored (the newest, for a campaign that grew)
    std::vector<GridProblemInfo> grids;
    std::vector<BestPath> best_paths;  // by problem, then algorithm (runs of one objective)
    std::vector<StoredFront> fronts;   // by problem, algorithm, seed
};

/// Reads them, read-only. InputError when the file cannot be read, storage::DamagedStore when a
/// value is not what pride bench writes (a solution that is not a list of [x, y] cells, a start
/// that is not "x,y"). A front of the wrong form is kept with its `error` instead: the page says
/// so under its problem's figures and draws the other runs.
PageStore read_page_store(const std::string& path);

}  // namespace pride::html

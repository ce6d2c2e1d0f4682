#include "engine/scenarios.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>

#include "framework/error.hpp"
#include "framework/termination.hpp"
#include "problems/grid/grid_problem.hpp"
#include "problems/grid/map_io.hpp"
#include "problems/grid/planners/astar.hpp"

namespace pride::engine {

ScenarioCheck check_scenarios(const std::string& file, const std::string& map_dir) {
    using namespace pride::grid;
    const auto entries = read_scenario(file);
    const std::filesystem::path dir =
        map_dir.empty() ? std::filesystem::path(file).parent_path() : std::filesystem::path(map_dir);
    std::map<std::string, GridMap> maps;
    AStar astar;
    ScenarioCheck out;
    double seconds = 0.0;
    for (const auto& e : entries) {
        const std::string where = file + ":" + std::to_string(e.line);
        auto it = maps.find(e.map);
        if (it == maps.end()) {
            try {
                MapReadOptions read;
                read.named_in_file = true;  // a scenario line's map: never standard input
                it = maps.emplace(e.map, read_map((dir / e.map).string(), read)).first;
            } catch (const InputError& error) {
                throw InputError(where + ": " + error.what());
            }
        }
        const GridMap& map = it->second;
        require(map.width() == e.width && map.height() == e.height, where,
                fmt::format("the scenario says {}x{}, but {} is {}x{}", e.width, e.height, e.map, map.width(),
                            map.height()));
        require(map.free(e.start), where, "the start " + to_string(e.start) + " is blocked on " + e.map);
        require(map.free(e.goal), where, "the goal " + to_string(e.goal) + " is blocked on " + e.map);
        const auto t0 = Clock::now();
        const double length = astar.search(map, e.start, e.goal);
        seconds += std::chrono::duration<double>(Clock::now() - t0).count();
        const double diff = length < 0 ? std::numeric_limits<double>::infinity() : std::abs(length - e.optimal);
        if (diff > 1e-6) ++out.differ;
        out.max_diff = std::max(out.max_diff, diff);
    }
    out.checked = entries.size();
    out.expansions_per_s = seconds > 0 ? static_cast<double>(astar.expansions()) / seconds : 0.0;
    return out;
}

}  // namespace pride::engine

#pragma once
// Moving AI scenario files checked with A*: every line solved and compared with its recorded
// optimal length (what `pride scen` prints).
#include <cstddef>
#include <string>

namespace pride::engine {

struct ScenarioCheck {
    std::size_t checked = 0;
    std::size_t differ = 0;  // lines whose A* length differs from the recorded one by more than 1e-6
    double max_diff = 0.0;
    double expansions_per_s = 0.0;
};

/// Reads `file` and its maps (from `map_dir`, or the file's folder when empty; each map once) and
/// solves every line. InputError naming the file and line for a map that does not match the line.
ScenarioCheck check_scenarios(const std::string& file, const std::string& map_dir = "");

}  // namespace pride::engine

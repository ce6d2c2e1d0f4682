#pragma once
// `pride pareto` (docs/cli.md): the exact Pareto front of a grid path's length, turns,
// angle penalty and clearance (problems/grid/pareto.hpp), as text or JSON, and drawn.
#include <cstdint>
#include <iosfwd>
#include <string>

namespace pride::cli {

struct ParetoOptions {
    std::string map;
    std::string start;  // "X,Y"
    std::string goal;
    std::string objectives;  // two to four of length, turns, angle, clearance (any order)
    std::int64_t inflate = 0;
    bool unknown_free = false;  // images and map_server maps: unknown cells free
    bool corner_cutting = false;
    bool json = false;
    std::string svg;
    std::string png;
    std::string plot;  // SVG: the front in objective space, the first two objectives as given
};
int pareto_command(const ParetoOptions& o, std::ostream& out);

}  // namespace pride::cli

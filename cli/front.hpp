#pragma once
// `pride front`: one run of a multi-objective algorithm, on a catalog problem (ZDT,
// DTLZ) or on a grid with two to four criteria; prints the non-dominated set it found and its
// quality against the problem's reference front (the analytic front sampled, or the grid's exact
// front), as text or JSON, and on grids draws the set's paths.
#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "engine/specs.hpp"

namespace pride::cli {

struct FrontOptions {
    std::string algo;
    // A catalog problem, or a grid (map, start, goal).
    std::string problem;
    std::optional<std::int64_t> dim;
    std::string map, start, goal;
    // Boxes: M (DTLZ; empty: its default); grids: two to four of length, turns, angle, clearance.
    std::string objectives;
    std::string encoding;  // grids: line (default), free or chain
    std::string init;      // grids on chains: walk or sitp
    std::string connector = "repair";
    std::optional<std::int64_t> waypoints;
    std::int64_t inflate = 0;
    bool unknown_free = false;  // images and map_server maps: unknown cells free
    bool corner_cutting = false;
    engine::Budget budget;           // --evals, --iters, --wall-ms
    std::optional<std::string> pop;  // as given: its range is the algorithm's
    std::uint64_t seed = 1;
    std::vector<std::string> params;
    bool json = false;
    bool no_reference = false;  // skip the reference front and the indicators
    std::string svg, png;
    std::string plot;  // SVG: the set in objective space (the first two objectives), with the reference front
};
int front_command(const FrontOptions& o, std::ostream& out);

}  // namespace pride::cli

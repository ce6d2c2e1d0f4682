#pragma once
// Reading maps and scenarios (docs/grid.md, "Maps"). The map formats are told apart by
// their content, never by the file name:
//   - Moving AI `.map`: `type octile`, `height H`, `width W`, `map` (in this order), then H lines of
//     W characters; `.` `G` `S` are free, `@` `O` `T` `W` blocked.
//   - plain matrix: H lines of W tokens `0` (free) / `1` (blocked), separated by blanks ("0 1 0"),
//     by commas (CSV: "0,1,0", blanks around the commas allowed) or not at all ("010"); a line with
//     blanks is read token by token, so "0 10" is an error, not 3 cells.
//   - images: PNG (its signature) and Netpbm PGM/PPM/PBM/PAM (`P1`..`P7`), read as a plain image
//     with map_server's default thresholds (image_map.hpp);
//   - ROS map_server YAML (a text file with `image:` and `resolution:` lines), its image read from
//     beside it, its resolution and origin kept as the map's world frame (ros_map.hpp); read_map
//     only, since parse_map reads no other file.
// The text formats accept CRLF line ends, trailing blanks on any line, a missing final newline, blank lines
// before the first line and after the last one, and a UTF-8 byte-order mark.
//
// Every malformed input throws pride::InputError with one line `FILE:LINE:COL: what is wrong`
// (LINE and COL 1-based, COL counted in characters; COL is left out when no column makes sense,
// e.g. "too few rows"). Binary input (a NUL byte, bytes that are not UTF-8) is an error too, never
// a crash. A file that cannot be read is `FILE: cannot open ...`.
#include <string>
#include <string_view>
#include <vector>

#include "problems/grid/map.hpp"

namespace pride::grid {

/// Choices made where a map is loaded.
struct MapReadOptions {
    /// Unknown cells of images and map_server maps (image_map.hpp) are free, not blocked.
    bool unknown_free = false;
    /// The map's path was read from inside a file (a campaign, a scenario line), not from the
    /// user's command line: a regular file only, never standard input (framework/read_file.hpp).
    bool named_in_file = false;
};

/// Parses a map held in `text`; `name` stands for the file in messages and becomes the map's name.
GridMap parse_map(std::string_view text, const std::string& name, const MapReadOptions& options = {});
/// Reads and parses the map file at `path` (the map's name is the path).
GridMap read_map(const std::string& path, const MapReadOptions& options = {});

/// One line of a Moving AI scenario file (`.map.scen`, and the MAPF `-even-N.scen` files, which
/// share the format): `bucket map width height start_x start_y goal_x goal_y optimal_length`.
/// Cells are in the (x, y) convention of map.hpp; `line` is the 1-based line in the file.
struct ScenarioEntry {
    int bucket = 0;
    std::string map;
    int width = 0;
    int height = 0;
    Cell start;
    Cell goal;
    double optimal = 0.0;
    int line = 0;
};

/// Parses a scenario held in `text`: a `version 1` (or `version 1.0`) line, then one entry per
/// line, fields separated by tabs or spaces; blank lines are skipped. Start and goal must lie inside
/// width x height and the optimal length must be finite and >= 0; any malformed line throws
/// InputError `FILE:LINE: ...`. Whether start and goal are free is for the caller to check on the map.
std::vector<ScenarioEntry> parse_scenario(std::string_view text, const std::string& name);
/// Reads and parses the scenario file at `path`.
std::vector<ScenarioEntry> read_scenario(const std::string& path);

/// The map in Moving AI format (`.` free, `@` blocked), "\n" line ends; parse_map reads it back.
std::string to_movingai(const GridMap& map);

}  // namespace pride::grid

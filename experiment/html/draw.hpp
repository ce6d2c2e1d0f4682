#pragma once
// Pictures of a grid run: the map, start, goal, the path found and (optionally) the optimal path,
// or several paths (a Pareto front, the best path of each algorithm of a campaign), as SVG or PNG,
// drawn once with cairo (Debian's libcairo2) for both formats; for `pride path`, `pride pareto` and
// the HTML report alike.
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "experiment/html/colour.hpp"
#include "framework/output_files.hpp"
#include "problems/grid/map.hpp"
#include "problems/grid/path.hpp"
#include "problems/grid/polyline.hpp"

namespace pride::html {

enum class PictureFormat { svg, png };

/// What a picture's legend says of each thing drawn (under the map: a swatch and its words).
struct PathLabels {
    std::string path = "path found";        // the run's path
    std::string optimal = "exact optimum";  // the optimal path, when drawn
};

/// "length 23.4 cells = 1.17 m": a path's length in a legend, on a map with a world frame (docs/grid.md,
/// "World coordinates"), the metres the cells times the resolution.
std::string length_words(double cells, const grid::WorldFrame& frame);

/// Writes the picture into `file` and closes it (it is in place once its OutputFiles commits).
/// `path` (a chain's cells or a polyline planner's vertices) and `optimal` may be null. A legend
/// under the map names start, goal and each path drawn. InputError naming the file when it cannot
/// be written.
void draw_grid(const grid::GridMap& map, grid::Cell start, grid::Cell goal, const grid::Polyline* path,
               const grid::Path* optimal, const PathLabels& labels, OutputFiles::File& file, PictureFormat format);

/// The cells a picture shows: columns x0 to x1 - 1 and rows y0 to y1 - 1 of its map.
struct MapWindow {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool whole(const grid::GridMap& map) const { return x0 == 0 && y0 == 0 && x1 == map.width() && y1 == map.height(); }
};

/// The whole map.
MapWindow whole_map(const grid::GridMap& map);

/// The region of the map around start, goal and every path's vertices, with a margin of a tenth of
/// its size (at least 5 cells), so that paths on a large map are drawn large enough to be seen;
/// the whole map when that region would cover most of it (70 % or more of its width and height).
MapWindow paths_window(const grid::GridMap& map, grid::Cell start, grid::Cell goal,
                       const std::vector<grid::Polyline>& paths);

/// A caption's words for `w`: empty for the whole map, else which columns and rows are shown.
std::string window_words(const grid::GridMap& map, const MapWindow& w);

/// The map with several paths (a Pareto front), each in its own colour, from blue (the first) to
/// red (the last), or `colours[i]` for path i when given (one per path), and a legend naming each
/// (`labels`, one per path).
void draw_grid_paths(const grid::GridMap& map, grid::Cell start, grid::Cell goal, const std::vector<grid::Path>& paths,
                     const std::vector<std::string>& labels, OutputFiles::File& file, PictureFormat format,
                     const std::vector<Rgb>& colours = {});
/// The same with polylines (cell (i, j)'s centre at (i, j)): chains and polyline planners' paths;
/// only `window` of the map when given (paths_window), else the whole map.
void draw_grid_paths(const grid::GridMap& map, grid::Cell start, grid::Cell goal,
                     const std::vector<grid::Polyline>& paths, const std::vector<std::string>& labels,
                     OutputFiles::File& file, PictureFormat format, const std::vector<Rgb>& colours = {},
                     const std::optional<MapWindow>& window = std::nullopt);

/// The height in pixels of a legend of `entries` lines under a map drawn `width` pixels wide.
double legend_height(std::size_t entries);

/// Draws every (file, format) with `draw_one` into `files`, for the caller to commit once all
/// succeeded (and what it prints was printed), so that a failure leaves no picture. Devices and
/// pipes are written directly, after the others. One file named twice is refused before anything
/// is drawn, a folder before its picture is.
void write_pictures(const std::vector<std::pair<std::string, PictureFormat>>& pictures, OutputFiles& files,
                    const std::function<void(OutputFiles::File& file, PictureFormat)>& draw_one);

}  // namespace pride::html

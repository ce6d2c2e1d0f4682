#pragma once
// Pictures of a grid run: the map, start, goal, the path found and (optionally) the optimal path,
// or several paths (a Pareto front, the best path of each algorithm of a campaign), as SVG or PNG,
// drawn once with cairo (Debian's libcairo2) for both formats; for `pride path`, `pride pareto` and
// the HTML report alike.
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "experiment/html/colour.hpp"
#include "problems/grid/map.hpp"
#include "problems/grid/path.hpp"

namespace pride::html {

enum class PictureFormat { svg, png };

/// What a picture's legend says of each thing drawn (under the map: a swatch and its words).
struct PathLabels {
    std::string path = "path found";        // the run's path
    std::string optimal = "exact optimum";  // the optimal path, when drawn
};

/// Writes the picture to `file` (callers that must not leave half-written files write to a
/// temporary name and rename it; errors name `shown_as`). `path` and `optimal` may be null.
/// A legend under the map names start, goal and each path drawn. InputError when it cannot.
void draw_grid(const grid::GridMap& map, grid::Cell start, grid::Cell goal, const grid::Path* path,
               const grid::Path* optimal, const PathLabels& labels, const std::string& file,
               const std::string& shown_as, PictureFormat format);

/// The map with several paths (a Pareto front), each in its own colour, from blue (the first) to
/// red (the last), or `colours[i]` for path i when given (one per path), and a legend naming each
/// (`labels`, one per path).
void draw_grid_paths(const grid::GridMap& map, grid::Cell start, grid::Cell goal, const std::vector<grid::Path>& paths,
                     const std::vector<std::string>& labels, const std::string& file, const std::string& shown_as,
                     PictureFormat format, const std::vector<Rgb>& colours = {});

/// The height in pixels of a legend of `entries` lines under a map drawn `width` pixels wide.
double legend_height(std::size_t entries);

/// Draws every (file, format) with `draw_one(temporary, file, format)` to a temporary name beside
/// the file and renames them all only when all succeeded, so that a failure leaves no picture.
/// Files that are neither regular nor new (devices, pipes, symbolic links) are written directly.
/// One file named twice, or a folder, is refused before anything is drawn.
void write_pictures(
    const std::vector<std::pair<std::string, PictureFormat>>& pictures,
    const std::function<void(const std::string& file, const std::string& shown_as, PictureFormat)>& draw_one);

}  // namespace pride::html

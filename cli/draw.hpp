#pragma once
// Pictures of a grid run: the map, start, goal, the path found and (optionally) the optimal path,
// as SVG or PNG, drawn once with cairo (Debian's libcairo2) for both formats.
#include <string>

#include "problems/grid/map.hpp"
#include "problems/grid/path.hpp"

namespace pride::cli {

enum class PictureFormat { svg, png };

/// Writes the picture to `file` (callers that must not leave half-written files write to a
/// temporary name and rename it; errors name `shown_as`). `path` and `optimal` may be null.
/// InputError when it cannot.
void draw_grid(const grid::GridMap& map, grid::Cell start, grid::Cell goal, const grid::Path* path,
               const grid::Path* optimal, const std::string& file, const std::string& shown_as, PictureFormat format);

}  // namespace pride::cli

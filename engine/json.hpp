#pragma once
// Numbers and names as JSON text, for results, stores and front ends: every double in its
// shortest form that reads back as the same double.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/run.hpp"
#include "problems/grid/path.hpp"
#include "problems/grid/polyline.hpp"

namespace pride::engine {

/// Shortest text that reads back as the same double; JSON has no inf or NaN, so those are null.
std::string json_number(double v);
/// [v1, v2, ...] with json_number each.
std::string json_array(const std::vector<double>& values);
/// [n1, n2, ...].
std::string json_integers(const std::vector<std::int64_t>& values);
/// A path as [[x,y],...].
std::string json_cells(const grid::Path& path);
/// A JSON string literal with the necessary escapes.
std::string json_string(std::string_view s);
/// A polyline as [[x, y], ...] (cell units, cell (i, j)'s centre at (i, j)).
std::string json_polyline(const grid::Polyline& line);
/// A grid run's path metrics (problems/grid/polyline.hpp) as one object, keys in the order of
/// PolylineMetrics, clearances null on a map without obstacles; with `gaps`, the problem's
/// shortest lengths and the path's gaps to them (GridSpec::path_gaps) after them. On a map with a
/// world frame, the lengths in metres last: length_m, min_clearance_m and mean_clearance_m, each
/// the value in cells times the resolution.
std::string json_path_metrics(const GridOutcome& run, bool gaps,
                              const std::optional<grid::WorldFrame>& frame = std::nullopt);

}  // namespace pride::engine

#pragma once
// ROS map_server maps: a YAML file (read with yaml-cpp) naming an image (image_map.hpp) and its
// world frame, as nav2_map_server's loadMapYaml reads it (nav2_map_server/src/map_io.cpp; the
// keys of ROS 1's map_server are the same, wiki.ros.org/map_server "YAML format"):
//   image: map.pgm            the image, relative to the YAML file's folder unless absolute
//   resolution: 0.05          metres per pixel (> 0)
//   origin: [-10, -10, 0]     the world point x, y of the map's bottom-left corner, and a yaw
//   occupied_thresh: 0.65     optional here (map_server requires it), default 0.65
//   free_thresh: 0.196        optional here, default 0.196
//   negate: 0                 optional here, default 0; 0/1 or true/false
//   mode: trinary             optional: trinary (default), scale or raw
// Other keys are ignored, as map_server ignores them. A non-zero yaw is refused: pride's cells
// are the image's pixels and world coordinates are only a shift and a scale of them (map.hpp).
// Errors are InputError "FILE:LINE:COL: what" (one line), or "FILE: what" with no place to name.
#include <string>
#include <string_view>

#include "problems/grid/image_map.hpp"
#include "problems/grid/map.hpp"

namespace pride::grid {

struct RosMapInfo {
    std::string image;  // as written in the file
    WorldFrame frame;
    double yaw = 0.0;
    Occupancy occupancy;
};

/// Whether `text` looks like a map_server YAML file: a line starting with `image:` and one
/// starting with `resolution:` (what tells it from the text map formats).
bool looks_like_ros_yaml(std::string_view text) noexcept;

/// Parses and checks the YAML of a map_server map; `name` stands for the file in messages.
RosMapInfo parse_ros_yaml(std::string_view text, const std::string& name);

/// The map of a map_server YAML file whose content is `text` (read from `path`): its image read
/// from beside it, its world frame set; unknown cells free when `unknown_free`.
GridMap read_ros_map(const std::string& path, std::string_view text, bool unknown_free = false);

}  // namespace pride::grid

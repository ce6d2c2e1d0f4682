#pragma once
// Map images: PNG (libpng) and Netpbm (PBM, PGM, PPM, PAM: libnetpbm), told apart by their first
// bytes, and how their pixels become free or blocked cells, as ROS map_server reads them (the
// nav2_map_server of ROS 2, nav2_map_server/src/map_io.cpp, loadMapFromFile; ROS 1's map_server
// agrees on images without alpha; ros_map.hpp reads the YAML file that names the image).
//
// A pixel's shade is the mean of its colour channels (a grey pixel: its value) over maxval; in
// trinary mode an image with alpha averages the opacity in too (map_server's behaviour). Its
// occupancy is occ = 1 - shade (occ = shade with `negate`), so black is occupied:
//   - trinary: occ > occupied_thresh occupied, occ < free_thresh free, unknown otherwise;
//   - scale: the same, but a pixel that is not opaque is unknown, and map_server's scaled costs
//     between the thresholds are unknown here (pride's cells are free or blocked);
//   - raw: the value round(255 * shade) is an occupancy percentage (negate and alpha ignored, as
//     map_server does); 0..100 is compared with the thresholds as value / 100, above 100 unknown.
// Unknown cells are blocked unless `unknown_free`. Pixel (column x, row r from the image's top) is
// cell (x, r): the image's first row is y = 0 as a Moving AI map's first line (map.hpp).
//
// A plain image (no YAML) is read with map_server's usual values: trinary, occupied_thresh 0.65,
// free_thresh 0.196, no negate, unknown blocked. So a map_saver PGM (0 occupied, 254 free, 205
// unknown) keeps its three kinds of cells, and a black-and-white image is blocked where black.
//
// Errors are InputError "NAME: what" (one line); sizes are checked before any pixel buffer is
// allocated: at most kMaxImageCells cells, and no more pixels than the file's bytes can hold.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "problems/grid/map.hpp"

namespace pride::grid {

/// 2^25 cells (5792 x 5792): the largest ROS maps are a few thousand pixels a side.
inline constexpr std::size_t kMaxImageCells = std::size_t{1} << 25;

/// Decoded pixels, row by row from the top; `channels` samples each (1 grey, 2 grey and alpha,
/// 3 RGB, 4 RGBA; alpha is opacity), each in 0..maxval.
struct Image {
    int width = 0;
    int height = 0;
    int channels = 1;
    unsigned maxval = 255;
    std::vector<std::uint16_t> samples;
    bool has_alpha() const noexcept { return channels == 2 || channels == 4; }
};

/// The PNG signature.
bool is_png(std::string_view bytes) noexcept;
/// A Netpbm magic number: `P1` to `P7` then a blank or line end.
bool is_netpbm(std::string_view bytes) noexcept;

Image decode_png(std::string_view bytes, const std::string& name);
Image decode_netpbm(std::string_view bytes, const std::string& name);
/// PNG or Netpbm by content; anything else is an InputError.
Image decode_image(std::string_view bytes, const std::string& name);

enum class MapMode { trinary, scale, raw };

/// How pixels become cells (the top of this file); the defaults are those of a plain image.
struct Occupancy {
    MapMode mode = MapMode::trinary;
    double occupied_thresh = 0.65;
    double free_thresh = 0.196;
    bool negate = false;
    bool unknown_free = false;
};

/// A cell's state before the choice for unknown cells.
enum class CellState : std::uint8_t { free, occupied, unknown };
/// The state of pixel i of `image`.
CellState pixel_state(const Image& image, std::size_t i, const Occupancy& occupancy) noexcept;

/// The map of `image` (no world frame), named `name`.
GridMap image_to_map(const Image& image, const Occupancy& occupancy, const std::string& name);

/// Decodes a PNG or Netpbm image and reads it as a plain image map (the defaults of Occupancy,
/// unknown cells free when `unknown_free`).
GridMap parse_image_map(std::string_view bytes, const std::string& name, bool unknown_free = false);

}  // namespace pride::grid

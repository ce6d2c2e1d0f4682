#pragma once
// The grid map of docs/grid.md: H rows by W columns of free or blocked cells; a cell is
// (x, y), x the column from the left, y the row from the first line of the file downwards (the
// Moving AI convention). The papers' bottom-left numbering is only a conversion (paper_number,
// from_paper_number), never a second convention inside the code.
//
// World frame (maps read through a ROS map_server YAML, problems/grid/ros_map.hpp): metres per
// cell and the world point (origin x, y) of the map's bottom-left corner, as map_server's `origin`
// (its yaw must be 0). The image's first row is the top of the map and y = 0 here, as a Moving AI
// map's first line: cell (x, y) covers world x in origin_x + [x, x + 1) * resolution and world y in
// origin_y + [H - 1 - y, H - y) * resolution; its world point is the centre of that square.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "framework/error.hpp"

namespace pride::grid {

struct Cell {
    int x = 0;
    int y = 0;
    friend bool operator==(const Cell&, const Cell&) = default;
};

/// The 8 moves, clockwise on the screen (y grows downwards), starting east; direction d and
/// (d + 4) % 8 are opposite, and the angle between d and e is 45 * min(|d - e|, 8 - |d - e|).
inline constexpr int kDx[8] = {1, 1, 0, -1, -1, -1, 0, 1};
inline constexpr int kDy[8] = {0, 1, 1, 1, 0, -1, -1, -1};
inline constexpr bool is_diagonal(int d) {
    return (d & 1) != 0;
}
/// The direction of a one-cell step from a to b, or -1 when b is not one of a's 8 neighbours.
inline int direction(Cell a, Cell b) {
    // A table on (dx, dy) in {-1, 0, 1}^2 (kDx / kDy inverted): path metrics call this per step.
    constexpr int kTable[9] = {5, 6, 7, 4, -1, 0, 3, 2, 1};
    const int dx = b.x - a.x, dy = b.y - a.y;
    if (static_cast<unsigned>(dx + 1) > 2u || static_cast<unsigned>(dy + 1) > 2u) return -1;
    return kTable[(dy + 1) * 3 + (dx + 1)];
}
/// The turn between two directions in multiples of 45 degrees (0..4).
inline constexpr int turn_steps(int d, int e) {
    const int k = d > e ? d - e : e - d;
    return k < 8 - k ? k : 8 - k;
}

/// Metres per cell and the world point of the map's bottom-left corner (see the top of this file).
struct WorldFrame {
    double resolution = 1.0;
    double origin_x = 0.0;
    double origin_y = 0.0;
    friend bool operator==(const WorldFrame&, const WorldFrame&) = default;
};
struct WorldPoint {
    double x = 0.0;
    double y = 0.0;
};

/// The index of the cell that holds world coordinate v along one axis, cells [k, k + 1) * resolution
/// from `origin`, a border belonging to the cell after it (right, or above). The quotient
/// (v - origin) / resolution carries the rounding of the decimal numbers the user wrote (x = 1.6,
/// origin -10, resolution 0.05: 231.99999999999997, where the real quotient is the border 232), so
/// a quotient within a tolerance of a whole number k is that border, cell k: 1e-9 of a cell, or
/// when larger 8 units in the last place of the numbers involved, counted in cells (with
/// GridMap::check_frame's least resolution, at most 4e-5 of a cell inside the map). Comparing v with the border
/// recomputed, origin + k * resolution, does not help: that sum rounds too (to 1.6000000000000014).
/// NaN for NaN.
inline double world_index(double v, double origin, double resolution) {
    const double q = (v - origin) / resolution;
    const double k = std::round(q);
    constexpr double eps = 2.220446049250313e-16;  // DBL_EPSILON
    const double tolerance = std::max(1e-9, 8.0 * eps * ((std::abs(v) + std::abs(origin)) / resolution + std::abs(q)));
    return std::abs(q - k) <= tolerance ? k : std::floor(q);
}

/// A world coordinate as printed (`pride path --json`'s path_world, Python's): rounded to 15
/// significant digits, which drops the last bit of a sum (-10 + 0.5 * 0.05 is -9.975, not
/// -9.975000000000001) and keeps any two distinct vertices apart: the frame's resolution is at least
/// 1e-10 of every coordinate (GridMap::check_frame), and vertices lie half a cell apart or more.
/// (Rounding to a fixed 1e-9 m printed every cell of a 1e-10 m map as 0.)
inline double printed_world(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.15g", v);
    return std::strtod(text, nullptr) + 0.0;  // + 0.0: no -0
}

class GridMap {
  public:
    GridMap() = default;
    /// `blocked` row by row, top row first; `name` says where the map came from (for messages).
    GridMap(int width, int height, std::vector<std::uint8_t> blocked, std::string name = "map")
        : width_(width), height_(height), blocked_(std::move(blocked)), name_(std::move(name)) {
        require(width >= 1 && height >= 1, name_, "a map needs at least one row and one column");
        require(blocked_.size() == static_cast<std::size_t>(width) * static_cast<std::size_t>(height), name_,
                "cell count does not match width x height");
        moves_.resize(blocked_.size());
        moves_cutting_.resize(blocked_.size());
        for (std::size_t i = 0; i < blocked_.size(); ++i) {
            std::uint8_t strict = 0, cutting = 0;
            for (int d = 0; d < 8; ++d) {
                if (legal_step(cell(i), d, false)) strict |= static_cast<std::uint8_t>(1u << d);
                if (legal_step(cell(i), d, true)) cutting |= static_cast<std::uint8_t>(1u << d);
            }
            moves_[i] = strict;
            moves_cutting_[i] = cutting;
        }
    }

    int width() const noexcept { return width_; }
    int height() const noexcept { return height_; }
    std::size_t size() const noexcept { return blocked_.size(); }
    const std::string& name() const noexcept { return name_; }

    /// The world frame, when the map came with one (a map_server YAML); none otherwise.
    const std::optional<WorldFrame>& frame() const noexcept { return frame_; }
    /// Gives the map a world frame; InputError naming the map when check_frame() refuses it.
    void set_frame(const WorldFrame& f) {
        check_frame(f, width_, height_, name_);
        frame_ = f;
    }
    /// The largest world coordinate (metres, either sign) a frame may reach, and the least
    /// resolution relative to it: cells stay apart (1e-10 leaves some 20 of a double's 52 bits of
    /// precision below a cell) and every coordinate prints as a number.
    static constexpr double max_world = 1e15, min_relative_resolution = 1e-10;
    /// A finite resolution > 0 and a finite origin, whose cells of a width x height map all have
    /// finite world coordinates within max_world and can be told apart.
    static void check_frame(const WorldFrame& f, int width, int height, const std::string& name) {
        require(std::isfinite(f.resolution) && f.resolution > 0.0, name,
                "resolution must be a number > 0 (metres per cell), got " + std::to_string(f.resolution));
        require(std::isfinite(f.origin_x) && std::isfinite(f.origin_y), name, "the origin must be finite");
        const double far_x = f.origin_x + static_cast<double>(width) * f.resolution;
        const double far_y = f.origin_y + static_cast<double>(height) * f.resolution;
        const double reach =
            std::max({std::fabs(f.origin_x), std::fabs(f.origin_y), std::fabs(far_x), std::fabs(far_y)});
        require(reach <= max_world, name,
                "the world frame reaches beyond 1e15 metres (origin plus the map's size times the resolution)");
        require(f.resolution >= min_relative_resolution * reach, name,
                "the resolution is too small beside the origin: cells could not be told apart in world "
                "coordinates (it must be at least 1e-10 of the largest coordinate)");
    }
    /// The world point (metres) of the centre of cell c; the map must have a frame.
    WorldPoint world(Cell c) const {
        require(frame_.has_value(), name_, "the map has no world frame (resolution and origin)");
        return {frame_->origin_x + (c.x + 0.5) * frame_->resolution,
                frame_->origin_y + (height_ - 1 - c.y + 0.5) * frame_->resolution};
    }
    /// The world point (metres) of a path's vertex (x, y) in cells, cell (i, j)'s centre at (i, j)
    /// (grid::PathPoint); the map must have a frame.
    WorldPoint world(double x, double y) const {
        require(frame_.has_value(), name_, "the map has no world frame (resolution and origin)");
        return {frame_->origin_x + (x + 0.5) * frame_->resolution,
                frame_->origin_y + (height_ - 1 - y + 0.5) * frame_->resolution};
    }
    /// The cell holding world point p (a point on a border between cells belongs to the cell
    /// right of it or above it, world_index), or none when p is outside the map (the far right and
    /// top edges included: no cell lies beyond them); the map must have a frame.
    std::optional<Cell> cell_at(WorldPoint p) const {
        require(frame_.has_value(), name_, "the map has no world frame (resolution and origin)");
        const double col = world_index(p.x, frame_->origin_x, frame_->resolution);
        const double row = world_index(p.y, frame_->origin_y, frame_->resolution);              // from the bottom
        if (!(col >= 0.0 && col < width_ && row >= 0.0 && row < height_)) return std::nullopt;  // NaN too
        return Cell{static_cast<int>(col), height_ - 1 - static_cast<int>(row)};
    }

    bool inside(Cell c) const noexcept { return c.x >= 0 && c.y >= 0 && c.x < width_ && c.y < height_; }
    std::size_t index(Cell c) const noexcept {
        return static_cast<std::size_t>(c.y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(c.x);
    }
    Cell cell(std::size_t index) const noexcept {
        return {static_cast<int>(index % static_cast<std::size_t>(width_)),
                static_cast<int>(index / static_cast<std::size_t>(width_))};
    }
    /// Inside and not blocked.
    bool free(Cell c) const noexcept { return inside(c) && blocked_[index(c)] == 0; }
    bool free_index(std::size_t i) const noexcept { return blocked_[i] == 0; }

    /// A one-cell step from a in direction d is legal when the target is free and, for a diagonal,
    /// both orthogonally adjacent cells are free too (no corner cutting), unless `corner_cutting`.
    bool legal_step(Cell a, int d, bool corner_cutting = false) const noexcept {
        const Cell b{a.x + kDx[d], a.y + kDy[d]};
        if (!free(b)) return false;
        if (!is_diagonal(d) || corner_cutting) return true;
        return free(Cell{a.x + kDx[d], a.y}) && free(Cell{a.x, a.y + kDy[d]});
    }

    /// The legal steps from cell `index` as a bit mask (bit d: direction d), worked out once per map
    /// so that searches test one byte instead of up to three cells.
    std::uint8_t moves(std::size_t index, bool corner_cutting = false) const noexcept {
        return corner_cutting ? moves_cutting_[index] : moves_[index];
    }
    /// Whether the one-cell step from a to its neighbour b is legal, read from a's step mask
    /// (legal_step's answer in one byte test).
    bool legal_move(Cell a, Cell b, bool corner_cutting = false) const noexcept {
        return (moves(index(a), corner_cutting) >> direction(a, b)) & 1u;
    }
    /// The index offset of a step in direction d.
    std::ptrdiff_t offset(int d) const noexcept { return static_cast<std::ptrdiff_t>(kDy[d]) * width_ + kDx[d]; }

    /// Obstacle inflation (Cai and Du 2021, section 3.1): every cell within Chebyshev distance r of a
    /// blocked cell becomes blocked.
    GridMap inflated(int r) const {
        require(r >= 0, "inflate", "radius must be >= 0, got " + std::to_string(r));
        if (r == 0) return *this;
        r = std::min(r, std::max(width_, height_));  // a larger radius blocks no more
        // Chebyshev dilation = a sliding-window maximum along rows, then along columns (prefix
        // counts make each pass linear in the map size, whatever r is).
        std::vector<std::uint8_t> rows(blocked_.size()), out(blocked_.size());
        std::vector<int> prefix(static_cast<std::size_t>(std::max(width_, height_)) + 1);
        for (int y = 0; y < height_; ++y) {
            for (int x = 0; x < width_; ++x) prefix[x + 1] = prefix[x] + blocked_[index({x, y})];
            for (int x = 0; x < width_; ++x)
                rows[index({x, y})] = prefix[std::min(width_, x + r + 1)] - prefix[std::max(0, x - r)] > 0;
        }
        for (int x = 0; x < width_; ++x) {
            for (int y = 0; y < height_; ++y) prefix[y + 1] = prefix[y] + rows[index({x, y})];
            for (int y = 0; y < height_; ++y)
                out[index({x, y})] = prefix[std::min(height_, y + r + 1)] - prefix[std::max(0, y - r)] > 0;
        }
        GridMap m(width_, height_, std::move(out), name_ + " inflated by " + std::to_string(r));
        m.frame_ = frame_;
        return m;
    }

    /// Eq. 2 of Zhang et al. (2025) numbers cells from 0, left to right and bottom to top.
    long paper_number(Cell c) const noexcept { return static_cast<long>(height_ - 1 - c.y) * width_ + c.x; }
    Cell from_paper_number(long g) const {
        require(g >= 0 && g < static_cast<long>(size()), name_, "paper cell number out of range: " + std::to_string(g));
        return {static_cast<int>(g % width_), height_ - 1 - static_cast<int>(g / width_)};
    }

  private:
    int width_ = 0;
    int height_ = 0;
    std::vector<std::uint8_t> blocked_;                // 1 = blocked, row by row from the top
    std::vector<std::uint8_t> moves_, moves_cutting_;  // legal steps per cell, bit d = direction d
    std::string name_;
    std::optional<WorldFrame> frame_;
};

}  // namespace pride::grid

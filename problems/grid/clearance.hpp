#pragma once
// Clearance: how close a path runs to obstacles, as an additive integer cost per cell (docs/grid.md,
// "Clearance"). A cell's cost falls in bands with d, the exact Euclidean distance from its centre to
// the centre of the nearest blocked cell (Felzenszwalb and Huttenlocher 2012):
//     cost = max(0, B - floor((d - 1) / w))    (B bands of width w cells)
// so a free cell touching an obstacle (d = 1 or sqrt 2) costs B, and cells from d = 1 + B w on cost
// 0. Cells outside the map are not obstacles. A path's clearance is the sum over its cells, start
// and goal included. Integer and non-negative, so the Pareto label setting takes it as a criterion.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "problems/grid/map.hpp"
#include "problems/grid/path.hpp"

namespace pride::grid {

/// The band rule's parameters, both whole numbers.
struct ClearanceParams {
    /// B: the cost of a cell touching an obstacle, and the number of non-zero bands. At most 63, so
    /// that a Pareto label's clearance (at most 2^25 cells, each costing <= B) fits in 31 bits.
    int bands = 3;
    /// w: the width of a band, in cells (the distance d counts in cell widths).
    int band_width = 1;

    /// InputError("clearance", ...) unless 1 <= bands <= 63 and 1 <= band_width <= 1000000.
    void validate() const;
    friend bool operator==(const ClearanceParams&, const ClearanceParams&) = default;
};

/// The squared distance of a map without blocked cells: every cell is infinitely far.
inline constexpr std::int64_t kNoObstacle = std::numeric_limits<std::int64_t>::max();

/// The exact squared Euclidean distance from each cell's centre to the nearest blocked cell's
/// centre, row by row (index y * W + x): 0 on blocked cells, kNoObstacle everywhere when no cell is
/// blocked. Linear in the map's size (a lower envelope of parabolas per column, then per row),
/// compared in integers, so exact.
std::vector<std::int64_t> squared_distance_transform(const GridMap& map);

/// The cost of a cell at squared distance d2 (the rule above, decided in integers: the band is the
/// largest k <= B with (1 + k w)^2 <= d2). A blocked cell (d2 = 0) costs B + 1, the rule at d = 0.
int clearance_band_cost(std::int64_t squared_distance, const ClearanceParams& params);

/// Every cell's cost on one map, computed once (a search then reads one byte per step).
class MapClearance {
  public:
    MapClearance() = default;
    /// Validates `params` before anything is allocated.
    explicit MapClearance(const GridMap& map, const ClearanceParams& params = {});

    int width() const noexcept { return width_; }
    int height() const noexcept { return height_; }
    const ClearanceParams& params() const noexcept { return params_; }
    /// The cost of cell `index` (index y * W + x of the map it was computed for).
    int cost(std::size_t index) const noexcept { return cost_[index]; }
    /// The cost of a cell; outside the map, B + 1 (as a blocked cell: no legal path goes there).
    int cost(Cell c) const noexcept {
        if (c.x < 0 || c.y < 0 || c.x >= width_ || c.y >= height_) return params_.bands + 1;
        return cost_[static_cast<std::size_t>(c.y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(c.x)];
    }

  private:
    int width_ = 0;
    int height_ = 0;
    ClearanceParams params_;
    std::vector<std::uint8_t> cost_;  // per cell, row by row; <= 64
};

/// A path's clearance: the sum of its cells' costs, start and goal included (a cell listed twice
/// counts twice). Beside PathMetrics rather than in it: metrics() has no map.
inline std::int64_t clearance_cost(const MapClearance& clearance, const Path& path) noexcept {
    std::int64_t sum = 0;
    for (const Cell c : path) sum += clearance.cost(c);
    return sum;
}

}  // namespace pride::grid

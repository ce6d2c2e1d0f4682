#pragma once
// One path type for every planner: a polyline in cell units, and its metrics as Bench-MR defines
// them (Heiden et al., "Bench-MR: A Motion Planning Benchmark for Wheeled Mobile Robots", IEEE RA-L
// 6(3), 2021): angle over length, maximum curvature and clearance, beside length and turns.
//
// Frame: cell (i, j)'s CENTRE is the point (i, j), so a cell chain's polyline is its cells and its
// cell covers [i - 0.5, i + 0.5] x [j - 0.5, j + 0.5]. (any_angle.hpp's Point puts cell (x, y) at
// [x, x + 1] x [y, y + 1]: polyline_of subtracts 0.5.)
//
// Geometry: zero-length segments are skipped; a vertex is a TURN when the heading changes there by
// more than kCollinearRadians (a collinear vertex, e.g. one inserted on a segment, is no turn, and
// the tolerance absorbs the rounding of such an inserted point). A reversal is a turn of 180
// degrees. The path's shape is its ends and turn vertices: collinear vertices change no metric
// (up to rounding), because the clearance samples and the curvature's arc-length points depend on
// that shape only.
//
// Where this departs from Bench-MR, and why:
//  - Max curvature. Bench-MR interpolates the path to 500 states and takes the largest inverse
//    circumradius of three states at least 0.3 apart, so its value depends on the path's length
//    and vertex density, and it skips reversals. Here it is measured at every turn vertex v with
//    p0, p2 the points at arc length h = 1 cell before and after v (each clamped to the path's
//    end): the Menger curvature 2 |cross(v - p0, p2 - v)| / (|p0 v| |v p2| |p0 p2|). An isolated
//    turn of theta with both neighbouring segments >= h gives 2 sin(theta / 2) / h, whatever the
//    vertex density. A reversal (p0, v, p2 on one ray from v, p0 == p2 when both arms are straight
//    and long) takes the limit of that circle, the one with diameter min(|p0 v|, |v p2|):
//    2 / min(|p0 v|, |v p2|), i.e. 2 / h for a clean reversal (Bench-MR skips these; a robot must
//    stop and turn there, so it counts as the sharpest turn).
//  - Clearance. Bench-MR reads a (bilinearly interpolated) distance field at each of its 500
//    states and averages them. Here it is the exact Euclidean distance to the nearest blocked
//    square (0 on its boundary; outside the map is not an obstacle, as clearance.hpp), sampled at
//    every end and turn vertex and at arc-length spacing <= 0.25 cell on each straight run between
//    them; the mean is the arc-length mean (trapezoid rule), so it does not depend on where a
//    planner puts its vertices.
//  - AOL is Bench-MR's (total absolute heading change in radians / length, duplicates skipped,
//    each change in [0, pi]), with 0 for a path of length 0 instead of a division by zero.
#include <cstdint>
#include <optional>
#include <vector>

#include "problems/grid/map.hpp"
#include "problems/grid/path.hpp"
#include "problems/grid/planners/any_angle.hpp"

namespace pride::grid {

/// A path's vertex in cell units with cell (i, j)'s CENTRE at (i, j): a cell chain's polyline is its cells.
struct PathPoint {
    double x = 0, y = 0;
    friend bool operator==(const PathPoint&, const PathPoint&) = default;
};
using Polyline = std::vector<PathPoint>;

/// The cells' centres, in order (equal consecutive cells kept: they are zero-length segments).
Polyline polyline_of(const Path& chain);
/// any_angle / Theta* points (cell (x, y) = [x, x + 1] x [y, y + 1]): each minus 0.5.
Polyline polyline_of(const std::vector<Point>& square);

/// A heading change at most this (radians) is no turn: collinear up to rounding.
inline constexpr double kCollinearRadians = 1e-9;
/// The arc length (cells) before and after a turn vertex at which the curvature is measured.
inline constexpr double kCurvatureArm = 1.0;
/// The largest arc-length spacing (cells) of the clearance samples on a straight run.
inline constexpr double kClearanceSpacing = 0.25;

struct PolylineMetrics {
    double length = 0;             // Euclidean, in cells
    int turns = 0;                 // interior vertices where the heading changes (reversal = 180)
    double total_turn_deg = 0;     // sum of |heading change| (each in [0, 180], rounded to 1e-9 degree)
    double max_turn_deg = 0;       // the largest of them
    double angle_over_length = 0;  // Bench-MR AOL: total turn in radians / length (0 for length 0)
    double max_curvature = 0;      // 1/cell, at turn vertices (the top of this file); 0 without turns
    std::optional<double> min_clearance, mean_clearance;  // cells; nullopt when no cell is blocked
};

/// Scores polylines on one map. Keeps its own copy of the map's squared distance transform
/// (8 bytes per cell; a blocked cell is one at distance 0), so the map need not outlive it.
/// score() allocates nothing and is const, so one scorer may serve several threads.
class PolylineScorer {
  public:
    explicit PolylineScorer(const GridMap& map);

    /// The metrics of `path` (an empty path: all 0, clearances nullopt; one point, or only
    /// repeats of one: length 0, no turns, the clearance of that point).
    PolylineMetrics score(const Polyline& path) const;

    /// The exact Euclidean distance from p to the nearest blocked square (0 inside or on one), or
    /// nullopt when the map has no blocked cell. p may lie outside the map (NaN when not finite).
    /// Scans only the blocked candidates the distance transform allows, an annulus about 2 cells
    /// wide at the distance D of p's cell: O(D) cells (about 10 us at D = 1000, far less in clutter).
    std::optional<double> clearance(PathPoint p) const;

    bool has_obstacles() const noexcept { return has_obstacles_; }

  private:
    double clearance_unchecked(PathPoint p) const noexcept;

    int width_ = 0, height_ = 0;
    bool has_obstacles_ = false;
    std::vector<std::int64_t> d2_;  // squared_distance_transform of the map: centre to blocked centre
};

/// A map-free score (length, turns, AOL, curvature; clearances nullopt).
PolylineMetrics polyline_metrics(const Polyline& path);

}  // namespace pride::grid

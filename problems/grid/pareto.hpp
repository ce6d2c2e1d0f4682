#pragma once
// The exact Pareto front of a path's cost vector over a subset of {length, turns, angle_penalty,
// clearance} (docs/grid.md's metrics, clearance.hpp's clearance; docs/cli.md's
// `pride pareto`), by multi-objective label
// setting (Martins' algorithm, with the octile distance guiding the length) over the oracle's
// states (cell, direction of the last step), with the oracle's moves: 8-connected, no corner
// cutting unless asked.
//
// A label is the cost vector of one walk from the start to a state. A state keeps only labels that
// no other label of the same state weakly dominates in the chosen criteria (an equal vector keeps
// the label found first); the open list pops labels in lexicographic order of (length + octile
// distance to the goal, then the other chosen criteria, then creation order), a key that never
// decreases along a step, so a popped label is never dominated later and is final. Labels at the
// goal are not extended and share one list whatever their last direction: its labels at the end
// are the front. A label whose cost plus a lower bound of the rest (octile length; one turn and
// W = 10 when the goal is not straight ahead; the goal cell's clearance cost) is weakly dominated
// by a goal label is dropped. Clearance is a cost per cell entered (the start's in the first label).
//
// Lengths are exact: a length is a + b sqrt(2) with a the number of orthogonal and b the number of
// diagonal steps, and two lengths are compared through the sign of (a1 - a2) - (b2 - b1) sqrt(2),
// decided with integers (x - y sqrt(2) > 0 iff x > 0 >= y, or x, y > 0 and x^2 > 2 y^2, ...), so
// equal lengths are equal and no tolerance is involved.
//
// Walks and simple paths have the same front: cutting an innermost loop out of a walk shortens it
// and adds neither turns nor angle penalty (tests/test_grid_search.cpp gives the argument, for
// each criterion on its own, for the same cut), nor clearance (it drops cells, each costing >= 0),
// so every walk is weakly dominated by a simple path.
//
// iqga = -(1/f1 + 1/f2 + 1/f3) (objectives.hpp) does not decrease when any of length, angle
// penalty and turns grows, so its minimum over all paths is attained on the 3-D front:
// iqga_optimum evaluates it on each point of that front.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "problems/grid/clearance.hpp"
#include "problems/grid/map.hpp"
#include "problems/grid/path.hpp"

namespace pride::grid {

/// Which of length, turns, angle_penalty and clearance the front is taken over (at least one).
struct Criteria {
    bool length = true;
    bool turns = false;
    bool angle_penalty = false;
    bool clearance = false;

    int count() const noexcept { return int(length) + int(turns) + int(angle_penalty) + int(clearance); }
    friend bool operator==(const Criteria&, const Criteria&) = default;
};

/// Parses a comma-separated list of two to four criteria: `length`, `turns`, `angle` (or
/// `angle_penalty`) and `clearance`, each at most once, in any order. InputError("objectives", ...)
/// on an empty list, an unknown or a repeated name, or a single one.
Criteria parse_criteria(std::string_view list);
/// The criteria as a list of names in the canonical order: length, turns, angle_penalty, clearance.
std::vector<std::string> criteria_names(const Criteria& c);

/// A length a + b sqrt(2): `straight` orthogonal and `diagonal` diagonal steps.
struct StepCounts {
    std::int64_t straight = 0;
    std::int64_t diagonal = 0;
    double value() const noexcept { return static_cast<double>(straight) + static_cast<double>(diagonal) * kSqrt2; }
    friend bool operator==(const StepCounts&, const StepCounts&) = default;
};
/// The sign (-1, 0, 1) of x - y, exactly.
int compare_lengths(const StepCounts& x, const StepCounts& y) noexcept;

/// One point of the front and one path that has it.
struct FrontPoint {
    StepCounts steps;     // the exact length
    double length = 0.0;  // metrics(path).length (the same bits as `pride path` reports)
    int turns = 0;
    int angle_penalty = 0;
    int clearance = 0;  // clearance_cost of the path, on the search's MapClearance
    Path path;          // start first, goal last
};

struct ParetoOptions {
    bool corner_cutting = false;
    /// Guide the length by the octile distance and prune with lower bounds; false: plain Martins.
    /// Both give the same front (the same points; the paths of tied points may differ).
    bool use_heuristic = true;
    /// InputError("pareto", ...) instead of creating more labels than this (at most 2^25; memory:
    /// 29 bytes each, plus 24 while it is live and 24 while it is open). Maps of more than a million
    /// cells are refused before anything is allocated (the per-state lists take 24 bytes a state).
    std::size_t max_labels = std::size_t{1} << 25;
};

/// The largest `ParetoOptions::max_labels` that keeps a search on a map of `cells` cells within
/// `memory` bytes: the per-state lists (24 bytes a state, 9 states a cell) must fit in half of it
/// (InputError("map", ...) naming `map_name` otherwise), and the labels (at most 77 bytes each:
/// the label, its place in its state's list and in the open list) in what is left of 80 %.
std::size_t label_limit(std::size_t cells, double memory, const std::string& map_name);

/// The front, sorted by length, then by the other criteria (lexicographically, in the canonical
/// order). With fewer than four criteria each point still reports all four metrics of its path
/// (a tie in the chosen criteria keeps the path found first). Empty when g cannot be reached or s
/// or g is outside or blocked; s == g gives the one-cell path.
class ParetoSearch {
  public:
    /// Clearance with the default ClearanceParams, computed for this search.
    std::vector<FrontPoint> front(const GridMap& map, Cell s, Cell g, const Criteria& criteria,
                                  const ParetoOptions& options = {});
    /// Clearance as computed once for this map (any parameters); InputError("clearance", ...) when
    /// it was computed for a map of another size.
    std::vector<FrontPoint> front(const GridMap& map, const MapClearance& clearance, Cell s, Cell g,
                                  const Criteria& criteria, const ParetoOptions& options = {});
    /// Labels created by the last search (a measure of its work).
    std::size_t labels() const noexcept { return labels_; }

  private:
    std::size_t labels_ = 0;
};

inline std::vector<FrontPoint> pareto_front(const GridMap& map, Cell s, Cell g, const Criteria& criteria,
                                            const ParetoOptions& options = {}) {
    return ParetoSearch{}.front(map, s, g, criteria, options);
}
inline std::vector<FrontPoint> pareto_front(const GridMap& map, const MapClearance& clearance, Cell s, Cell g,
                                            const Criteria& criteria, const ParetoOptions& options = {}) {
    return ParetoSearch{}.front(map, clearance, s, g, criteria, options);
}

/// The minimum of the iqga objective over all legal paths from s to g, taken over the 3-D front
/// (the first front point with the least value, in the front's order); nullopt when g cannot be
/// reached. With `out`, that point's path replaces its contents.
std::optional<double> iqga_optimum(const GridMap& map, Cell s, Cell g, bool corner_cutting = false,
                                   Path* out = nullptr);

}  // namespace pride::grid

#pragma once
// Section 2.2 of Wan and Gao (2022) on this project's grid: the decision table "eight neighbours X1..X8 of the
// current cell -> the move Y", reduced and minimised with the rough-set module
// (docs/algorithms.md, "Rough-set decision rules"). The walk (rule_walk.hpp) asks the minimal
// rules through GridRuleBook::decide; the labelling policy below only builds the table.
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <span>
#include <vector>

#include "framework/random.hpp"
#include "problems/grid/map.hpp"
#include "roughset/roughset.hpp"

namespace pride::grid {

/// Neighbour values: blocked, outside, or a diagonal that would cut a corner (an illegal step).
inline constexpr int kBlocked = 1;
/// Free but already visited on this walk.
inline constexpr int kVisited = 2;
/// Free and unvisited.
inline constexpr int kOpen = 3;
/// The decision "back"; decisions 1..8 move to X1..X8.
inline constexpr int kBack = 9;
/// 3^8 neighbourhood states.
inline constexpr std::size_t kGridStates = 6561;

/// The angle of g - c in units of 45 degrees, in (-4, 4]: direction d lies at d (mod 8).
inline double goal_angle(Cell c, Cell g) {
    return std::atan2(static_cast<double>(g.y - c.y), static_cast<double>(g.x - c.x)) / (std::numbers::pi / 4);
}

/// d1: the direction nearest in angle to g - c (c != g). No tie is possible: an integer vector lies
/// half-way between two directions only if tan(22.5 deg), an irrational number, were a ratio of
/// integers.
inline int goal_direction(Cell c, Cell g) {
    const auto d = static_cast<int>(std::lround(goal_angle(c, g)));
    return (d + 8) % 8;
}

/// d1 drawn between the two directions that bracket the goal angle, the nearer one with the larger
/// probability (linear in the angle: at 10 degrees off a direction it is chosen 35 times in 45); a
/// goal exactly on a direction keeps it. The rule walks' reading of "equally good neighbours".
inline int goal_direction(Cell c, Cell g, Rng& rng) {
    const double u = goal_angle(c, g);
    const double lower = std::floor(u);
    const double frac = u - lower;
    auto d = static_cast<int>(lower);
    if (frac > 0.0 && rng.uniform() < frac) ++d;
    return ((d % 8) + 8) % 8;
}

/// The direction of neighbour X_k (k = 1..8): numbered clockwise from the goal direction d1.
inline constexpr int neighbour_direction(int d1, int k) {
    return (d1 + k - 1) % 8;
}

/// The row of a state in the full table: X1 varies slowest, X8 fastest, values 1..3.
inline std::size_t state_index(std::span<const int, 8> values) {
    std::size_t index = 0;
    for (const int v : values) index = index * 3 + static_cast<std::size_t>(v - 1);
    return index;
}

/// The values X1..X8 of row `index` of the full table.
inline std::array<int, 8> state_values(std::size_t index) {
    std::array<int, 8> values{};
    for (int k = 7; k >= 0; --k, index /= 3) values[k] = static_cast<int>(index % 3) + 1;
    return values;
}

/// The labelling policy of the full table: among the five neighbours that face the goal, in the
/// order of their angle to it (X1; X2, X8 at 45 degrees; X3, X7 at 90; ties clockwise first), the
/// first free unvisited one; none -> back.
inline int policy_move(std::span<const int, 8> values) {
    static constexpr int kOrder[5] = {1, 2, 8, 3, 7};
    for (const int k : kOrder)
        if (values[k - 1] == kOpen) return k;
    return kBack;
}

/// The table, its reduct and the minimal rules, with a per-state lookup built from the rules.
struct GridRuleBook {
    roughset::DecisionTable table;      // all 6561 states, columns X1..X8, Y (labelled by policy_move)
    roughset::Attributes reduct;        // the only reduct, as column indices of `table`
    std::size_t reduced_rows = 0;       // distinct rows of the table on the reduct
    std::vector<roughset::Rule> rules;  // minimal_rules on the reduct
    /// The move every rule matching state i prescribes (1..8 or kBack), derived from `rules` alone.
    std::array<std::uint8_t, kGridStates> moves{};

    /// The rules' decision for the neighbour values X1..X8.
    int decide(std::span<const int, 8> values) const { return moves[state_index(values)]; }
};

/// Built once per process (thread-safe). Throws std::logic_error when the table is inconsistent,
/// when its reduct is not unique or keeps a backward-facing attribute, or when the rules leave a state
/// unmatched, disagree on one, or send the walk to a neighbour that is not free and unvisited.
const GridRuleBook& grid_rule_book();

}  // namespace pride::grid

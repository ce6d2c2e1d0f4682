#pragma once
// The objectives of docs/grid.md as policy types, all minimised. Each turns a path's
// metrics into a value. The additive ones (all but iqga) also say what one step and one turn cost,
// which is what the exact oracle searches over:
//     value = start_cost() + sum over steps of step_cost(d) + sum over turns of turn_cost(k),
// with d the direction of a step and k the turn in multiples of 45 degrees (1..4).
#include <string>
#include <string_view>

#include "framework/error.hpp"
#include "problems/grid/path.hpp"

namespace pride::grid {

/// cells: the number of cells (Wan and Gao 2022, eq. 13, f = d).
struct CellsObjective {
    static constexpr std::string_view name = "cells";
    static constexpr bool additive = true;
    double operator()(const PathMetrics& m) const noexcept { return m.cells; }
    /// The same value without measuring the path (GCC does not drop the unused metrics loop).
    double of_path(const Path& path) const noexcept { return static_cast<int>(path.size()); }
    double start_cost() const noexcept { return 1.0; }
    double step_cost(int) const noexcept { return 1.0; }
    double turn_cost(int) const noexcept { return 0.0; }
};

/// length: the sum of step lengths (Zhang et al. (2025) f1, eq. 8).
struct LengthObjective {
    static constexpr std::string_view name = "length";
    static constexpr bool additive = true;
    double operator()(const PathMetrics& m) const noexcept { return m.length; }
    /// The same value without counting turns.
    double of_path(const Path& path) const noexcept { return metrics(path, false).length; }
    double start_cost() const noexcept { return 0.0; }
    double step_cost(int d) const noexcept { return is_diagonal(d) ? kSqrt2 : 1.0; }
    double turn_cost(int) const noexcept { return 0.0; }
};

/// weighted: w_len * length + w_turn * turns + w_angle * angle_penalty (grid.md's general form).
/// The defaults (1, 1, 0.1) are this project's choice: the papers leave the weights to the user.
struct WeightedObjective {
    static constexpr std::string_view name = "weighted";
    static constexpr bool additive = true;
    double w_len = 1.0;
    double w_turn = 1.0;
    double w_angle = 0.1;
    double operator()(const PathMetrics& m) const noexcept {
        return w_len * m.length + w_turn * m.turns + w_angle * m.angle_penalty;
    }
    double start_cost() const noexcept { return 0.0; }
    double step_cost(int d) const noexcept { return w_len * (is_diagonal(d) ? kSqrt2 : 1.0); }
    double turn_cost(int k) const noexcept { return w_turn + w_angle * angle_penalty_of_turn(k); }
    /// An upper bound of the value of a legal path on a map of `cells` cells.
    double bound(double cells) const noexcept { return cells * (w_len * kSqrt2 + w_turn + 50.0 * w_angle); }
    void validate() const {
        require(w_len >= 0 && w_turn >= 0 && w_angle >= 0, "weighted", "weights must be >= 0");
        require(w_len > 0 || w_turn > 0 || w_angle > 0, "weighted", "at least one weight must be > 0");
    }
};

/// hswoa: length + lambda * turns (Cai and Du (2021) name length and turning points; its formula is lost).
struct HswoaObjective {
    static constexpr std::string_view name = "hswoa";
    static constexpr bool additive = true;
    double lambda = 1.0;
    double operator()(const PathMetrics& m) const noexcept { return m.length + lambda * m.turns; }
    double start_cost() const noexcept { return 0.0; }
    double step_cost(int d) const noexcept { return is_diagonal(d) ? kSqrt2 : 1.0; }
    double turn_cost(int) const noexcept { return lambda; }
    /// An upper bound of the value of a legal path on a map of `cells` cells.
    double bound(double cells) const noexcept { return cells * (kSqrt2 + lambda); }
    void validate() const { require(lambda >= 0, "hswoa", "lambda must be >= 0"); }
};

/// The objectives that are linear in a path's metrics as one type with weights:
///     w_cells cells + w_len length + w_turn turns + w_angle angle_penalty.
/// cells, length, weighted and hswoa are its configurations (below), so that one instantiation of
/// every algorithm and encoding carries all four; each gives the same value, oracle costs and
/// penalty bound, bit for bit, as its own type above (a zero weight adds an exact +0).
struct LinearObjective {
    static constexpr bool additive = true;
    double w_cells = 0.0;
    double w_len = 0.0;
    double w_turn = 0.0;
    double w_angle = 0.0;

    static LinearObjective of(const CellsObjective&) noexcept { return {1.0, 0.0, 0.0, 0.0}; }
    static LinearObjective of(const LengthObjective&) noexcept { return {0.0, 1.0, 0.0, 0.0}; }
    static LinearObjective of(const WeightedObjective& w) noexcept { return {0.0, w.w_len, w.w_turn, w.w_angle}; }
    static LinearObjective of(const HswoaObjective& h) noexcept { return {0.0, 1.0, h.lambda, 0.0}; }

    double operator()(const PathMetrics& m) const noexcept {
        return w_cells * m.cells + w_len * m.length + w_turn * m.turns + w_angle * m.angle_penalty;
    }
    /// The value of a path, measuring only what a non-zero weight needs: a fixed objective type
    /// gets that for free (the compiler drops unused metrics), a weighted one must ask. A metric
    /// left 0 has weight 0, so the value is the same to the bit.
    double of_path(const Path& path) const noexcept {
        if (w_len == 0.0 && w_turn == 0.0 && w_angle == 0.0) return w_cells * static_cast<int>(path.size());
        return (*this)(metrics(path, w_turn != 0.0 || w_angle != 0.0));
    }
    double start_cost() const noexcept { return w_cells; }
    double step_cost(int d) const noexcept { return w_cells + w_len * (is_diagonal(d) ? kSqrt2 : 1.0); }
    double turn_cost(int k) const noexcept { return w_turn + w_angle * angle_penalty_of_turn(k); }
    /// An upper bound of the value of a legal path on a map of `cells` cells.
    double bound(double cells) const noexcept { return cells * (w_cells + w_len * kSqrt2 + w_turn + 50.0 * w_angle); }
};

/// iqga: -(1/f1 + 1/f2 + 1/f3), f1 = length, f2 = angle_penalty, f3 = turns (Zhang et al. 2025, eq. 12,
/// maximised there, so negated here). A zero term reads as twice the reciprocal of the smallest
/// positive value the term can take (grid.md): 1/f1 = 2, 1/f2 = 0.2, 1/f3 = 2. Not additive: the
/// oracle does not apply.
struct IqgaObjective {
    static constexpr std::string_view name = "iqga";
    static constexpr bool additive = false;
    double operator()(const PathMetrics& m) const noexcept {
        const double inv_length = m.length > 0 ? 1.0 / m.length : 2.0;
        const double inv_penalty = m.angle_penalty > 0 ? 1.0 / m.angle_penalty : 0.2;
        const double inv_turns = m.turns > 0 ? 1.0 / m.turns : 2.0;
        return -(inv_length + inv_penalty + inv_turns);
    }
};

}  // namespace pride::grid

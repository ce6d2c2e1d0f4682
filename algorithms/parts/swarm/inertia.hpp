#pragma once
// Inertia-weight schedules w(t), t = 0..T-1 the iteration being computed, T the horizon. Usable by
// any algorithm with a velocity or a multiplicative weight (PSO's velocity, ILSO's eqs. 11-12).
#include <cstdint>
#include <string>

#include "framework/error.hpp"
#include "framework/one_of.hpp"

namespace pride {

/// w falls linearly from `start` at the first iteration to `end` at the last (Shi and Eberhart
/// 1998; 0.9 -> 0.4 is the project's PSO default).
struct LinearInertia {
    double start = 0.9;
    double end = 0.4;
    double operator()(std::int64_t t, std::int64_t horizon) const noexcept {
        if (horizon <= 1) return start;
        return start - (start - end) * static_cast<double>(t) / static_cast<double>(horizon - 1);
    }
    void validate(const std::string& where) const {
        require(start >= 0.0 && start <= 1.5, where, "w_start must be in [0, 1.5], got " + std::to_string(start));
        require(end >= 0.0 && end <= 1.5, where, "w_end must be in [0, 1.5], got " + std::to_string(end));
    }
};

/// A constant weight.
struct ConstantInertia {
    double w = 0.7298;
    double operator()(std::int64_t, std::int64_t) const noexcept { return w; }
    void validate(const std::string& where) const {
        require(w >= 0.0 && w <= 1.5, where, "w must be in [0, 1.5], got " + std::to_string(w));
    }
};

/// Eq. (10) of Wan and Gao (2022): w = w_max - (w_max - w_min) t^2 / T^2, with the paper's t = 1..T counting
/// the iterations that move (t = our 0-based index + 1): it starts just below w_max, falls slowly
/// early and fast late, and reaches w_min on the last iteration. Defaults 0.99 and 0.35 (Wan and Gao 2022).
struct QuadraticInertia {
    double start = 0.99;
    double end = 0.35;
    double operator()(std::int64_t t, std::int64_t horizon) const noexcept {
        if (horizon <= 0) return start;
        const double ratio = static_cast<double>(t + 1) / static_cast<double>(horizon);
        return start - (start - end) * ratio * ratio;
    }
    void validate(const std::string& where) const {
        require(start >= 0.0 && start <= 1.5, where, "w_max must be in [0, 1.5], got " + std::to_string(start));
        require(end >= 0.0 && end <= 1.5, where, "w_min must be in [0, 1.5], got " + std::to_string(end));
    }
};

/// No weight: w = 1 exactly, so a multiplication by it changes no bit (LSO, which has none).
struct UnitWeight {
    double operator()(std::int64_t, std::int64_t) const noexcept { return 1.0; }
    void validate(const std::string&) const {}
};

}  // namespace pride

namespace pride {

/// LSO's unit weight or ILSO's eq. (10), chosen at run time (one choice per iteration).
using SelectableWeight = OneOf<UnitWeight, QuadraticInertia>;

}  // namespace pride

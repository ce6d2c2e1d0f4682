#pragma once
// Inertia-weight schedules w(t), t = 0..T-1 the iteration being computed, T the horizon. Usable by
// any algorithm with a velocity or a multiplicative weight (PSO here, ILSO's eq. 10 later).
#include <cstdint>
#include <string>

#include "framework/error.hpp"

namespace pride {

/// w falls linearly from `start` at the first iteration to `end` at the last (Shi and Eberhart
/// 1998; 0.9 -> 0.4 is the spec's PSO default).
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

}  // namespace pride

#pragma once
// PSO velocity rules: what multiplies the old velocity and the two attractions in
//     v <- a v + b1 r1 (p - x) + b2 r2 (g - x).
// Written as policies so that the inertia-weight and the constriction forms share one loop.
#include <cstdint>
#include <string>

#include "algorithms/parts/swarm/inertia.hpp"
#include "framework/error.hpp"
#include "framework/one_of.hpp"

namespace pride {

struct VelocityCoefficients {
    double a;   // on the old velocity
    double b1;  // cognitive (personal best)
    double b2;  // social (global best)
};

/// v <- w(t) v + c1 r1 (p - x) + c2 r2 (g - x) (Shi and Eberhart 1998), w from a schedule.
template <class Inertia = LinearInertia>
struct InertiaVelocity {
    Inertia inertia{};
    double c1 = 2.0;
    double c2 = 2.0;
    VelocityCoefficients operator()(std::int64_t t, std::int64_t horizon) const noexcept {
        return {inertia(t, horizon), c1, c2};
    }
    void validate(const std::string& where) const {
        inertia.validate(where);
        require(c1 >= 0.0 && c1 <= 10.0, where, "c1 must be in [0, 10], got " + std::to_string(c1));
        require(c2 >= 0.0 && c2 <= 10.0, where, "c2 must be in [0, 10], got " + std::to_string(c2));
    }
};

/// v <- chi (v + c r1 (p - x) + c r2 (g - x)) (Clerc and Kennedy 2002), chi = 0.7298, c = 2.05.
struct ConstrictionVelocity {
    double chi = 0.7298;
    double c = 2.05;
    VelocityCoefficients operator()(std::int64_t, std::int64_t) const noexcept { return {chi, chi * c, chi * c}; }
    void validate(const std::string& where) const {
        require(chi > 0.0 && chi < 1.0, where, "chi must be in (0, 1), got " + std::to_string(chi));
        require(c > 0.0 && c <= 10.0, where, "c must be in (0, 10], got " + std::to_string(c));
    }
};

/// |v_i| <= fraction * (high_i - low_i) (the project's decision: 0.2).
struct RangeVelocityClamp {
    double fraction = 0.2;
    double limit(double low, double high) const noexcept { return fraction * (high - low); }
    void validate(const std::string& where) const {
        require(fraction > 0.0 && fraction <= 1.0, where, "vmax must be in (0, 1], got " + std::to_string(fraction));
    }
};

/// No clamp: |v_i| <= the whole range only as a guard against overflow.
struct NoVelocityClamp {
    double limit(double low, double high) const noexcept { return high - low; }
    void validate(const std::string&) const {}
};

}  // namespace pride

namespace pride {

/// The inertia-weight or the constriction rule, chosen at run time (one choice per iteration):
/// `pso` and `pso-constriction` are two configurations of one instantiation.
using SelectableVelocity = OneOf<InertiaVelocity<LinearInertia>, ConstrictionVelocity>;

}  // namespace pride

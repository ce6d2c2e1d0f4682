#pragma once
// How an algorithm compares two points of a run: by value alone on a problem without constraints
// (PlainOrder: f_a < f_b, the same code and bits as before constraints existed), or by (f, v) with
// the handler the algorithm is configured with (ConstraintOrder: Deb's feasibility rules, the
// epsilon level, or a static penalty; framework/constraint_handlers.hpp). An algorithm keeps its
// population's violations beside its values (0 for every point without constraints) and asks its
// order wherever its paper compares two values or looks for the best; `order_for<P>` picks the one
// for the problem type, so a run without constraints pays nothing.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include "framework/constraint_handlers.hpp"
#include "framework/constraints.hpp"
#include "framework/error.hpp"

namespace pride {

/// The handlers an algorithm that compares pairs of points may use, with their parameters.
struct ConstraintHandling {
    enum class Handler { deb, epsilon, penalty };
    Handler handler = Handler::deb;
    constraints::EpsilonSchedule epsilon{};  // Handler::epsilon
    double penalty = 1e6;                    // Handler::penalty: r of f + r v

    void validate(const std::string& who) const {
        require(std::isfinite(epsilon.cp) && epsilon.cp > 0.0, who,
                "epsilon_cp must be a finite number > 0, got " + std::to_string(epsilon.cp));
        require(epsilon.tc >= 1, who, "epsilon_tc must be >= 1, got " + std::to_string(epsilon.tc));
        require(std::isfinite(epsilon.theta) && epsilon.theta > 0.0 && epsilon.theta <= 1.0, who,
                "epsilon_theta must be in (0, 1], got " + std::to_string(epsilon.theta));
        require(std::isfinite(penalty) && penalty >= 0.0, who,
                "penalty must be a finite number >= 0, got " + std::to_string(penalty));
    }
};

/// The order of a problem without constraints: by value; violations are never read.
struct PlainOrder {
    bool better(double fa, double /*va*/, double fb, double /*vb*/) const noexcept { return fa < fb; }
    void start(std::span<const double> /*violations*/) noexcept {}
    void generation(std::int64_t /*t*/) noexcept {}
};

/// The order of a constrained problem under one handler. The epsilon level follows the run's
/// generations (start() with the initial population's violations, then generation(t)).
class ConstraintOrder {
  public:
    explicit ConstraintOrder(const ConstraintHandling& h) : handling_(h) {}

    bool better(double fa, double va, double fb, double vb) const noexcept {
        switch (handling_.handler) {
            case ConstraintHandling::Handler::deb:
                return constraints::deb_better(fa, va, fb, vb);
            case ConstraintHandling::Handler::epsilon:
                return constraints::epsilon_better(fa, va, fb, vb, level_);
            case ConstraintHandling::Handler::penalty:
                return constraints::static_penalty(fa, va, handling_.penalty) <
                       constraints::static_penalty(fb, vb, handling_.penalty);
        }
        return false;
    }
    void start(std::span<const double> violations) {
        handling_.epsilon.start(violations);
        level_ = handling_.epsilon.level(0);
    }
    void generation(std::int64_t t) noexcept { level_ = handling_.epsilon.level(t); }
    double level() const noexcept { return level_; }

  private:
    ConstraintHandling handling_;
    double level_ = 0.0;
};

/// The order a run on P uses.
template <class P>
auto order_for(const ConstraintHandling& handling) {
    if constexpr (ConstrainedProblem<P>)
        return ConstraintOrder(handling);
    else
        return PlainOrder{};
}

/// The index of the best of the first f.size() points by `order` (the first of equals).
template <class Order>
std::size_t best_index(const Order& order, std::span<const double> f, std::span<const double> v) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < f.size(); ++i)
        if (order.better(f[i], v[i], f[best], v[best])) best = i;
    return best;
}

}  // namespace pride

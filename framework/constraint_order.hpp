#pragma once
// How an algorithm compares two points of a run: by value alone on a problem without constraints
// (PlainOrder: f_a < f_b, the same code and bits as before constraints existed), or by (f, v) with
// the handler the algorithm is configured with (ConstraintOrder: Deb's feasibility rules, the
// epsilon level, or a static penalty; framework/constraint_handlers.hpp). Two handlers rank a whole
// population rather than compare two points, so only an algorithm that ranks one offers them:
// the adaptive penalty (APM), under which the algorithm computes the population's penalised values
// and the order compares those as plain values, and stochastic ranking, under which the algorithm
// ranks by constraints::stochastic_rank with its run's Rng (pairs compare by Deb's rules, its
// P_f = 0 case, wherever such an algorithm still compares two points). An algorithm keeps its
// population's violations beside its values (0 for every point without constraints) and asks its
// order wherever its paper compares two values or looks for the best; `order_for<P>` picks the one
// for the problem type, so a run without constraints pays nothing.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <span>
#include <string>
#include <type_traits>

#include "framework/constraint_handlers.hpp"
#include "framework/constraints.hpp"
#include "framework/error.hpp"

namespace pride {

/// The handlers an algorithm that compares pairs of points may use, with their parameters.
struct ConstraintHandling {
    enum class Handler { deb, epsilon, penalty, apm, stochastic_ranking };
    Handler handler = Handler::deb;
    constraints::EpsilonSchedule epsilon{};  // Handler::epsilon
    double penalty = 1e6;                    // Handler::penalty: r of f + r v
    double pf = 0.45;                        // Handler::stochastic_ranking: P_f (Runarsson and Yao 2000)

    /// `apm`, `ranking`: whether the algorithm offers the adaptive penalty and stochastic ranking
    /// (those that only compare pairs of points offer neither, and refuse them here).
    void validate(const std::string& who, bool apm = false, bool ranking = false) const {
        require(handler != Handler::apm || apm, who, "does not offer constraints = apm (the adaptive penalty)");
        require(handler != Handler::stochastic_ranking || ranking, who,
                "does not offer constraints = stochastic-ranking");
        require(std::isfinite(pf) && pf >= 0.0 && pf <= 1.0, who, "pf must be in [0, 1], got " + std::to_string(pf));
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
            case ConstraintHandling::Handler::apm:  // the values are the population's penalised ones
                return fa < fb;
            case ConstraintHandling::Handler::stochastic_ranking:  // a pair: P_f = 0, Deb's rules
                return constraints::deb_better(fa, va, fb, vb);
        }
        return false;
    }
    ConstraintHandling::Handler handler() const noexcept { return handling_.handler; }
    double pf() const noexcept { return handling_.pf; }
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

/// The first `leading` entries of `order` <- those of 0, 1, ..., k - 1 (k its size) best first by
/// `by`, ties to the lower index: a total order, so the same entries whether the whole is sorted or
/// only its head. By value alone (f_a < f_b) under PlainOrder.
template <class Order>
void rank_by(const Order& by, std::span<const double> f, std::span<const double> v, std::span<std::size_t> order,
             std::size_t leading) {
    const auto before = [&](std::size_t a, std::size_t b) {
        if constexpr (std::is_same_v<Order, PlainOrder>)
            return f[a] < f[b] || (f[a] == f[b] && a < b);
        else
            return by.better(f[a], v[a], f[b], v[b]) || (!by.better(f[b], v[b], f[a], v[a]) && a < b);
    };
    leading = std::min(leading, order.size());
    if (leading == 0) return;
    std::iota(order.begin(), order.end(), std::size_t{0});
    if (leading == 1)
        order[0] = *std::min_element(order.begin(), order.end(), before);
    else
        std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(leading), order.end(), before);
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

#pragma once
// The two-objective test problems of E. Zitzler, K. Deb, L. Thiele, "Comparison of multiobjective
// evolutionary algorithms: empirical results", Evolutionary Computation 8(2), 2000, 173-195,
// the test functions T1-T6 of its Section 3, known since as ZDT1-ZDT6 (cited below by the paper's
// names for them). Each is built on Deb's construction:
//
//   minimise T(x) = (f1(x1), f2(x)),   f2(x) = g(x2, ..., xn) h(f1(x1), g(x2, ..., xn)),
//
// with the paper's functions T1, T2, T3, T4 and T6 below (T5 is binary-coded: not a box problem).
// The paper writes m for the number of variables; here it is n, any n >= 2 (its default is the
// constructor's). The Pareto-optimal set is g = 1, at x2..xn = 0 for all five, and the fronts
// (fronts.hpp) are f2 = h(f1, 1) over the f1 the set reaches.
//
//   class  paper  n (default)  box                              front (g = 1)
//   Zdt1   T1     30           [0,1]^n                          f2 = 1 - sqrt(f1), f1 in [0,1]
//   Zdt2   T2     30           [0,1]^n                          f2 = 1 - f1^2
//   Zdt3   T3     30           [0,1]^n                          5 pieces of 1 - sqrt(f1) - f1 sin(10 pi f1)
//   Zdt4   T4     10           x1 in [0,1], x2..xn in [-5,5]    f2 = 1 - sqrt(f1)
//   Zdt6   T6     10           [0,1]^n                          f2 = 1 - f1^2, f1 in [0.2807753188, 1]
//
// Each evaluates in the paper's order of operations: the sums over x2..xn left to right, then g,
// then h, then f2 = g h. No allocation per evaluation.
#include <cassert>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <span>
#include <string_view>

#include "problems/multiobjective/box.hpp"

namespace pride::multiobjective {

namespace detail {

/// sum_{i=2}^n x_i, left to right.
inline double tail_sum(std::span<const double> x) noexcept {
    double s = 0.0;
    for (std::size_t i = 1; i < x.size(); ++i) s += x[i];
    return s;
}

/// T1-T3's g = 1 + 9 sum_{i=2}^n x_i / (n - 1).
inline double linear_g(std::span<const double> x) noexcept {
    return 1.0 + 9.0 * tail_sum(x) / static_cast<double>(x.size() - 1);
}

}  // namespace detail

/// T1 (ZDT 2000, Sec. 3): f1 = x1, g = 1 + 9 sum_{i=2}^n x_i / (n - 1), h = 1 - sqrt(f1 / g).
/// Convex front.
class Zdt1 : public MultiObjectiveBox {
  public:
    static constexpr std::string_view name() noexcept { return "zdt1"; }
    explicit Zdt1(std::size_t n = 30) : MultiObjectiveBox(name(), n, 2, 0.0, 1.0, 2) {}
    void evaluate(std::span<const double> x, std::span<double> f) const noexcept {
        assert(x.size() == dimension() && f.size() == 2);
        const double f1 = x[0];
        const double g = detail::linear_g(x);
        const double h = 1.0 - std::sqrt(f1 / g);
        f[0] = f1;
        f[1] = g * h;
    }
};

/// T2 (ZDT 2000, Sec. 3): T1's f1 and g, h = 1 - (f1 / g)^2. Non-convex front.
class Zdt2 : public MultiObjectiveBox {
  public:
    static constexpr std::string_view name() noexcept { return "zdt2"; }
    explicit Zdt2(std::size_t n = 30) : MultiObjectiveBox(name(), n, 2, 0.0, 1.0, 2) {}
    void evaluate(std::span<const double> x, std::span<double> f) const noexcept {
        assert(x.size() == dimension() && f.size() == 2);
        const double f1 = x[0];
        const double g = detail::linear_g(x);
        const double r = f1 / g;
        f[0] = f1;
        f[1] = g * (1.0 - r * r);
    }
};

/// T3 (ZDT 2000, Sec. 3): T1's f1 and g, h = 1 - sqrt(f1 / g) - (f1 / g) sin(10 pi f1).
/// Disconnected front: five convex pieces (fronts.hpp, zdt3_front_pieces()).
class Zdt3 : public MultiObjectiveBox {
  public:
    static constexpr std::string_view name() noexcept { return "zdt3"; }
    explicit Zdt3(std::size_t n = 30) : MultiObjectiveBox(name(), n, 2, 0.0, 1.0, 2) {}
    void evaluate(std::span<const double> x, std::span<double> f) const noexcept {
        assert(x.size() == dimension() && f.size() == 2);
        const double f1 = x[0];
        const double g = detail::linear_g(x);
        const double r = f1 / g;
        f[0] = f1;
        f[1] = g * (1.0 - std::sqrt(r) - r * std::sin(10.0 * std::numbers::pi * f1));
    }
};

/// T4 (ZDT 2000, Sec. 3): f1 = x1, g = 1 + 10 (n - 1) + sum_{i=2}^n (x_i^2 - 10 cos(4 pi x_i)),
/// h = 1 - sqrt(f1 / g); x1 in [0, 1], x2..xn in [-5, 5]. 21^9 local fronts (the paper's n = 10);
/// the global one is T1's.
class Zdt4 : public MultiObjectiveBox {
  public:
    static constexpr std::string_view name() noexcept { return "zdt4"; }
    explicit Zdt4(std::size_t n = 10) : MultiObjectiveBox(name(), n, 2, -5.0, 5.0, 2) { set_bounds(0, 0.0, 1.0); }
    void evaluate(std::span<const double> x, std::span<double> f) const noexcept {
        assert(x.size() == dimension() && f.size() == 2);
        const double f1 = x[0];
        double s = 0.0;
        for (std::size_t i = 1; i < x.size(); ++i) s += x[i] * x[i] - 10.0 * std::cos(4.0 * std::numbers::pi * x[i]);
        const double g = 1.0 + 10.0 * static_cast<double>(x.size() - 1) + s;
        f[0] = f1;
        f[1] = g * (1.0 - std::sqrt(f1 / g));
    }
};

/// T6 (ZDT 2000, Sec. 3): f1 = 1 - exp(-4 x1) sin^6(6 pi x1),
/// g = 1 + 9 (sum_{i=2}^n x_i / (n - 1))^0.25, h = 1 - (f1 / g)^2. Non-convex front, its points
/// unevenly spread along it (f1 in [0.2807753188, 1]).
class Zdt6 : public MultiObjectiveBox {
  public:
    static constexpr std::string_view name() noexcept { return "zdt6"; }
    explicit Zdt6(std::size_t n = 10) : MultiObjectiveBox(name(), n, 2, 0.0, 1.0, 2) {}
    void evaluate(std::span<const double> x, std::span<double> f) const noexcept {
        assert(x.size() == dimension() && f.size() == 2);
        const double s6 = std::pow(std::sin(6.0 * std::numbers::pi * x[0]), 6.0);
        const double f1 = 1.0 - std::exp(-4.0 * x[0]) * s6;
        const double g = 1.0 + 9.0 * std::pow(detail::tail_sum(x) / static_cast<double>(x.size() - 1), 0.25);
        const double r = f1 / g;
        f[0] = f1;
        f[1] = g * (1.0 - r * r);
    }
};

}  // namespace pride::multiobjective

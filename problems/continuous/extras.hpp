#pragma once
// Four scalable functions beside Yao's suite, in their usual definitions and boxes (as in
// Surjanovic and Bingham's Virtual Library of Simulation Experiments, sfu.ca/~ssurjano).
#include <Eigen/Core>
#include <cmath>
#include <numbers>
#include <span>

#include "framework/problem.hpp"
#include "problems/continuous/batch.hpp"
#include "problems/continuous/box_function.hpp"

namespace pride::continuous {

/// The axis-parallel hyper-ellipsoid f = sum_{i=1}^n i x_i^2 (of the several "ellipsoids" in use,
/// this one: weights i, not 10^6 powers), on [-5.12, 5.12].
struct Ellipsoid : BoxFunction {
    static constexpr FunctionInfo info{
        "ellipsoid", "axis-parallel hyper-ellipsoid sum i x_i^2; unimodal, separable", -5.12, 5.12, 1, 0.0, 0.0};
    explicit Ellipsoid(std::size_t dim) : BoxFunction(dim, info) {}
    double evaluate(std::span<const double> x) const noexcept {
        double f = 0.0;
        for (std::size_t i = 0; i < x.size(); ++i) f += static_cast<double>(i + 1) * x[i] * x[i];
        return f;
    }
    void evaluate_batch(MatrixView points, std::span<double> values) const {
        accumulate_rows(points, values, 0.0,
                        [](auto& f, const auto& v, Eigen::Index i) { f += static_cast<double>(i + 1) * v * v; });
    }
};

/// Levy's function: w_i = 1 + (x_i - 1)/4,
/// f = sin^2(pi w_1) + sum_{i<n} (w_i - 1)^2 [1 + 10 sin^2(pi w_i + 1)] + (w_n - 1)^2 [1 + sin^2(2 pi w_n)],
/// on [-10, 10]; minimum 0 at (1, ..., 1).
struct Levy : BoxFunction {
    static constexpr FunctionInfo info{"levy", "many local minima; minimum at (1,...,1)", -10.0, 10.0, 1, 1.0, 0.0};
    explicit Levy(std::size_t dim) : BoxFunction(dim, info) {}
    double evaluate(std::span<const double> x) const noexcept {
        constexpr double pi = std::numbers::pi;
        const std::size_t n = x.size();
        auto w = [&](std::size_t i) { return 1.0 + (x[i] - 1.0) / 4.0; };
        const double s1 = std::sin(pi * w(0));
        double f = s1 * s1;
        for (std::size_t i = 0; i + 1 < n; ++i) {
            const double d = w(i) - 1.0;
            const double s = std::sin(pi * w(i) + 1.0);
            f += d * d * (1.0 + 10.0 * s * s);
        }
        const double dn = w(n - 1) - 1.0;
        const double sn = std::sin(2.0 * pi * w(n - 1));
        return f + dn * dn * (1.0 + sn * sn);
    }
};

/// Zakharov's function: f = sum x_i^2 + (sum 0.5 i x_i)^2 + (sum 0.5 i x_i)^4, on [-5, 10];
/// minimum 0 at 0.
struct Zakharov : BoxFunction {
    static constexpr FunctionInfo info{
        "zakharov", "sum x^2 + s^2 + s^4, s = sum i x_i / 2; unimodal, non-separable", -5.0, 10.0, 1, 0.0, 0.0};
    explicit Zakharov(std::size_t dim) : BoxFunction(dim, info) {}
    double evaluate(std::span<const double> x) const noexcept {
        double squares = 0.0, s = 0.0;
        for (std::size_t i = 0; i < x.size(); ++i) {
            squares += x[i] * x[i];
            s += 0.5 * static_cast<double>(i + 1) * x[i];
        }
        const double s2 = s * s;
        return squares + s2 + s2 * s2;
    }
};

/// The Styblinski-Tang function: f = 0.5 sum (x_i^4 - 16 x_i^2 + 5 x_i), on [-5, 5]. The minimum
/// depends on n: info.optimum_value is the minimum per coordinate, -39.16616570377141546...
/// (mpmath, 50 digits) at x_i = -2.90353402777117709..., and optimum_value() returns n times it.
struct StyblinskiTang : BoxFunction {
    static constexpr FunctionInfo info{"styblinski-tang",
                                       "0.5 sum(x^4 - 16x^2 + 5x); minimum -39.166 n near x_i = -2.9035",
                                       -5.0,
                                       5.0,
                                       1,
                                       -2.903534027771177,
                                       -39.16616570377141};
    explicit StyblinskiTang(std::size_t dim) : BoxFunction(dim, info) {}
    double optimum_value() const noexcept { return static_cast<double>(dimension()) * info.optimum_value; }
    double evaluate(std::span<const double> x) const noexcept {
        double f = 0.0;
        for (double v : x) {
            const double v2 = v * v;
            f += v2 * v2 - 16.0 * v2 + 5.0 * v;
        }
        return 0.5 * f;
    }
};

}  // namespace pride::continuous

#pragma once
// The classic test functions, in the conventions of pagmo2 (formulas and boxes as listed in
// $PRIDE_DATA/continuous/reference_values.md). Each evaluates in the same order of operations as
// pagmo2, so values agree with it to the last bit or nearly so.
#include <cmath>
#include <numbers>
#include <span>

#include "problems/continuous/box_function.hpp"

namespace pride::continuous {

/// cos(2 pi v), also where 2 pi v overflows: every double of magnitude >= 2^52 is an integer, whose
/// cosine is 1 (std::cos(inf) is NaN). Below that it is std::cos(2 pi v), bit for bit.
inline double cos_two_pi(double v) noexcept {
    constexpr double omega = 2.0 * std::numbers::pi;
    return std::abs(v) >= 0x1p52 ? 1.0 : std::cos(omega * v);
}

/// f = sum x_i^2.
struct Sphere : BoxFunction {
    static constexpr FunctionInfo info{"sphere", "sum of squares; unimodal, separable", -5.12, 5.12, 1, 0.0, 0.0};
    explicit Sphere(std::size_t dim) : BoxFunction(dim, info) {}
    /// The same formula under another static table (name, box; never a temporary): yao.hpp.
    Sphere(std::size_t dim, const FunctionInfo& other) : BoxFunction(dim, other) {}
    double evaluate(std::span<const double> x) const noexcept {
        double f = 0.0;
        for (double v : x) f += v * v;
        return f;
    }
};

/// f = 10 n + sum (x_i^2 - 10 cos(2 pi x_i)).
struct Rastrigin : BoxFunction {
    static constexpr FunctionInfo info{
        "rastrigin", "10n + sum(x^2 - 10cos(2 pi x)); highly multimodal", -5.12, 5.12, 1, 0.0, 0.0};
    explicit Rastrigin(std::size_t dim) : BoxFunction(dim, info) {}
    /// The same formula under another static table (name, box; never a temporary): yao.hpp.
    Rastrigin(std::size_t dim, const FunctionInfo& other) : BoxFunction(dim, other) {}
    double evaluate(std::span<const double> x) const noexcept {
        double f = 10.0 * static_cast<double>(x.size());
        for (double v : x) f += v * v - 10.0 * cos_two_pi(v);
        return f;
    }
};

/// f = sum_{i<n} 100 (x_i^2 - x_{i+1})^2 + (x_i - 1)^2.
struct Rosenbrock : BoxFunction {
    static constexpr FunctionInfo info{"rosenbrock", "curved narrow valley; minimum at (1,...,1)", -5.0, 10.0, 2, 1.0,
                                       0.0};
    explicit Rosenbrock(std::size_t dim) : BoxFunction(dim, info) {}
    /// The same formula under another static table (name, box; never a temporary): yao.hpp.
    Rosenbrock(std::size_t dim, const FunctionInfo& other) : BoxFunction(dim, other) {}
    double evaluate(std::span<const double> x) const noexcept {
        double f = 0.0;
        for (std::size_t i = 0; i + 1 < x.size(); ++i) {
            const double a = x[i] * x[i] - x[i + 1];
            const double b = x[i] - 1.0;
            f += 100.0 * a * a + b * b;
        }
        return f;
    }
};

/// f = -20 exp(-0.2 sqrt(sum x_i^2 / n)) - exp(sum cos(2 pi x_i) / n) + 20 + e.
struct Ackley : BoxFunction {
    static constexpr FunctionInfo info{"ackley", "nearly flat outer region, deep central hole", -15.0, 30.0, 1, 0.0,
                                       0.0};
    explicit Ackley(std::size_t dim) : BoxFunction(dim, info) {}
    /// The same formula under another static table (name, box; never a temporary): yao.hpp.
    Ackley(std::size_t dim, const FunctionInfo& other) : BoxFunction(dim, other) {}
    double evaluate(std::span<const double> x) const noexcept {
        // Far out s1 overflows to inf and the first term is exp(-inf) = 0, its limit.
        double s1 = 0.0, s2 = 0.0;
        for (double v : x) {
            s1 += v * v;
            s2 += cos_two_pi(v);
        }
        const double inv_n = 1.0 / static_cast<double>(x.size());
        return -20.0 * std::exp(-0.2 * std::sqrt(inv_n * s1)) - std::exp(inv_n * s2) + 20.0 + std::numbers::e;
    }
};

/// f = sum x_i^2 / 4000 - prod cos(x_i / sqrt(i)) + 1, i = 1..n.
struct Griewank : BoxFunction {
    static constexpr FunctionInfo info{"griewank", "sum x^2/4000 - prod cos(x_i/sqrt(i)) + 1", -600.0, 600.0, 1, 0.0,
                                       0.0};
    explicit Griewank(std::size_t dim) : BoxFunction(dim, info) {}
    /// The same formula under another static table (name, box; never a temporary): yao.hpp.
    Griewank(std::size_t dim, const FunctionInfo& other) : BoxFunction(dim, other) {}
    double evaluate(std::span<const double> x) const noexcept {
        double sum = 0.0, prod = 1.0;
        for (double v : x) sum += v * v;
        for (std::size_t i = 0; i < x.size(); ++i) prod *= std::cos(x[i] / std::sqrt(static_cast<double>(i + 1)));
        return sum / 4000.0 - prod + 1.0;
    }
};

/// f = 418.9828872724338 n - sum x_i sin(sqrt|x_i|); minimum near 420.9687 in every coordinate.
struct Schwefel : BoxFunction {
    // The optimum coordinate is the root of the derivative to double precision; f there is about
    // 6e-14 per coordinate rather than 0, because 418.9828872724338 is itself rounded.
    static constexpr FunctionInfo info{
        "schwefel", "deceptive: the second-best region is far from the best", -500.0, 500.0, 1, 420.968746359982, 0.0,
        0, true};  // bounded_domain: below its optimum outside [-500, 500] (instance.hpp)
    explicit Schwefel(std::size_t dim) : BoxFunction(dim, info) {}
    double evaluate(std::span<const double> x) const noexcept {
        double s = 0.0;
        for (double v : x) s += v * std::sin(std::sqrt(std::abs(v)));
        return 418.9828872724338 * static_cast<double>(x.size()) - s;
    }
};

}  // namespace pride::continuous

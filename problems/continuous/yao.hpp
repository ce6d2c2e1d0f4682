#pragma once
// The scalable functions F1-F13 of Yao, Liu and Lin (1999), "Evolutionary programming made
// faster", IEEE TEC 3(2), Table I, with the boxes of that table (the paper's n = 30).
//
//   F1  sphere          Sphere(dim, yao_f1_info)    [-100, 100]     "yao-f1"  (formula of functions.hpp)
//   F2  schwefel-2.22   Schwefel222(dim)            [-10, 10]
//   F3  schwefel-1.2    Schwefel12(dim)             [-100, 100]
//   F4  schwefel-2.21   Schwefel221(dim)            [-100, 100]
//   F5  rosenbrock      Rosenbrock(dim, yao_f5_info) [-30, 30]      "yao-f5"
//   F6  step            Step(dim)                   [-100, 100]
//   F7  quartic-noise   QuarticNoise(dim)           [-1.28, 1.28]
//   F8  schwefel-2.26   Schwefel226(dim)            [-500, 500]
//   F9  rastrigin       Rastrigin(dim)              [-5.12, 5.12]   (the existing function as is)
//   F10 ackley          Ackley(dim, yao_f10_info)   [-32, 32]       "yao-f10"
//   F11 griewank        Griewank(dim)               [-600, 600]     (the existing function as is)
//   F12 penalized-1     Penalized1(dim)             [-50, 50]
//   F13 penalized-2     Penalized2(dim)             [-50, 50]
//   F14-F23: yao_fixed.hpp.
//
// The whole map, for a catalog: yao_table below (and yao_names, the function of each F number).
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <span>
#include <string_view>
#include <vector>

#include "framework/problem.hpp"
#include "framework/random.hpp"
#include "problems/continuous/batch.hpp"
#include "problems/continuous/box_function.hpp"
#include "problems/continuous/functions.hpp"
#include "problems/continuous/yao_fixed.hpp"

namespace pride::continuous {

// F1, F5, F10: the formulas of functions.hpp under Yao's boxes (pagmo2's boxes there differ).
inline constexpr FunctionInfo yao_f1_info{
    "yao-f1", "sphere on Yao's box [-100, 100] (Yao et al. 1999 F1)", -100.0, 100.0, 1, 0.0, 0.0};
inline constexpr FunctionInfo yao_f5_info{
    "yao-f5", "rosenbrock on Yao's box [-30, 30] (Yao et al. 1999 F5)", -30.0, 30.0, 2, 1.0, 0.0};
inline constexpr FunctionInfo yao_f10_info{
    "yao-f10", "ackley on Yao's box [-32, 32] (Yao et al. 1999 F10)", -32.0, 32.0, 1, 0.0, 0.0};

/// F2 (Yao et al. 1999 Table I), Schwefel's problem 2.22: f = sum |x_i| + prod |x_i|.
struct Schwefel222 : BoxFunction {
    static constexpr FunctionInfo info{
        "schwefel-2.22", "sum |x| + prod |x|; unimodal (Yao et al. 1999 F2)", -10.0, 10.0, 1, 0.0, 0.0};
    explicit Schwefel222(std::size_t dim) : BoxFunction(dim, info) {}
    double evaluate(std::span<const double> x) const noexcept {
        double s = 0.0, p = 1.0;
        for (double v : x) {
            s += std::abs(v);
            p *= std::abs(v);
        }
        return s + p;
    }
};

/// F3 (Yao et al. 1999 Table I), Schwefel's problem 1.2: f = sum_i (sum_{j<=i} x_j)^2.
struct Schwefel12 : BoxFunction {
    static constexpr FunctionInfo info{"schwefel-1.2",
                                       "sum of squared prefix sums; unimodal, non-separable (Yao et al. 1999 F3)",
                                       -100.0,
                                       100.0,
                                       1,
                                       0.0,
                                       0.0};
    explicit Schwefel12(std::size_t dim) : BoxFunction(dim, info) {}
    double evaluate(std::span<const double> x) const noexcept {
        double f = 0.0, prefix = 0.0;
        for (double v : x) {
            prefix += v;
            f += prefix * prefix;
        }
        return f;
    }
};

/// F4 (Yao et al. 1999 Table I), Schwefel's problem 2.21: f = max |x_i|.
struct Schwefel221 : BoxFunction {
    static constexpr FunctionInfo info{
        "schwefel-2.21", "max |x_i|; unimodal, non-differentiable (Yao et al. 1999 F4)", -100.0, 100.0, 1, 0.0, 0.0};
    explicit Schwefel221(std::size_t dim) : BoxFunction(dim, info) {}
    double evaluate(std::span<const double> x) const noexcept {
        double m = 0.0;
        for (double v : x) m = std::max(m, std::abs(v));
        return m;
    }
    void evaluate_batch(MatrixView points, std::span<double> values) const {
        accumulate_rows(points, values, 0.0, [](auto& m, const auto& v, Eigen::Index) { m = m.max(v.abs()); });
    }
};

/// F6 (Yao et al. 1999 Table I), the step function: f = sum floor(x_i + 0.5)^2. This is the 1999
/// version, with the floor; some later papers drop it and so list a plain sphere as "step".
struct Step : BoxFunction {
    // Minimum 0 on the whole cube [-0.5, 0.5)^n; x* = 0 is one of its points.
    static constexpr FunctionInfo info{
        "step", "sum floor(x + 0.5)^2; plateaus, discontinuous (Yao et al. 1999 F6)", -100.0, 100.0, 1, 0.0, 0.0};
    explicit Step(std::size_t dim) : BoxFunction(dim, info) {}
    double evaluate(std::span<const double> x) const noexcept {
        double f = 0.0;
        for (double v : x) {
            const double r = std::floor(v + 0.5);
            f += r * r;
        }
        return f;
    }
};

/// F7 (Yao et al. 1999 Table I), the quartic function with noise: f = sum_{i=1}^n i x_i^4 + u,
/// u in [0, 1).
///
/// The noise is a counter-based stream, so a run is reproducible: the k-th evaluation (k = 0, 1,
/// ...) after reseed(s) adds u_k = noise(s, k), the top 53 bits of splitmix64 (framework/random.hpp)
/// applied to the state (s ^ kNoiseSalt) + k * 0x9E3779B97F4A7C15 - that is, the (k+1)-th output of
/// a splitmix64 generator started at s ^ kNoiseSalt. The seed is 0 until reseed() is called.
/// evaluate() is therefore non-const (it advances the counter); a copy continues the copied count.
/// info.optimum_value is the noise-free minimum 0: the value at x* lies in [0, 1).
struct QuarticNoise : BoxFunction {
    static constexpr FunctionInfo info{
        "quartic-noise", "sum i x_i^4 + uniform noise in [0, 1) (Yao et al. 1999 F7)", -1.28, 1.28, 1, 0.0, 0.0};
    static constexpr std::uint64_t kNoiseSalt = 0x51A7C0FFEE5EED07ULL;  // keeps seed 0 off splitmix64's state 0
    explicit QuarticNoise(std::size_t dim) : BoxFunction(dim, info) {}

    void reseed(std::uint64_t seed) noexcept {
        seed_ = seed;
        counter_ = 0;
    }
    std::uint64_t seed() const noexcept { return seed_; }
    /// Evaluations since the last reseed (the k of the next one).
    std::uint64_t counter() const noexcept { return counter_; }

    /// u_k of the stream seeded with `seed`, in [0, 1).
    static double noise(std::uint64_t seed, std::uint64_t k) noexcept {
        std::uint64_t state = (seed ^ kNoiseSalt) + k * 0x9E3779B97F4A7C15ULL;
        return static_cast<double>(splitmix64(state) >> 11) * 0x1.0p-53;
    }
    /// The formula without its noise.
    static double quartic(std::span<const double> x) noexcept {
        double f = 0.0;
        for (std::size_t i = 0; i < x.size(); ++i) {
            const double v2 = x[i] * x[i];
            f += static_cast<double>(i + 1) * (v2 * v2);
        }
        return f;
    }
    double evaluate(std::span<const double> x) noexcept { return quartic(x) + noise(seed_, counter_++); }

  private:
    std::uint64_t seed_ = 0;
    std::uint64_t counter_ = 0;
};

/// F8 (Yao et al. 1999 Table I), Schwefel's problem 2.26: f = sum -x_i sin(sqrt|x_i|).
///
/// Unlike "schwefel" (functions.hpp) there is no 418.98 n offset, so the minimum depends on n:
/// info.optimum_value is the minimum per coordinate and optimum_value() returns n times it. Yao's
/// table quotes -12569.5, which is n = 30 only (30 * -418.9829). The per-coordinate value is
/// min_t -t sin(sqrt t), at t = 420.968746359982027..., -418.982887272433706274786... (mpmath,
/// 50 digits; some sources print ...433799807..., 1e-13 too low). The formula has lower values
/// outside [-500, 500] (bounded_domain).
struct Schwefel226 : BoxFunction {
    static constexpr FunctionInfo info{"schwefel-2.26",
                                       "sum -x sin(sqrt|x|); deceptive, minimum -418.98 n (Yao et al. 1999 F8)",
                                       -500.0,
                                       500.0,
                                       1,
                                       420.96874635998205,
                                       -418.9828872724337,
                                       0,
                                       true};
    explicit Schwefel226(std::size_t dim) : BoxFunction(dim, info) {}
    double optimum_value() const noexcept { return static_cast<double>(dimension()) * info.optimum_value; }
    double evaluate(std::span<const double> x) const noexcept {
        double s = 0.0;
        for (double v : x) s += v * std::sin(std::sqrt(std::abs(v)));
        return -s;
    }
};

namespace detail {
/// Yao's penalty u(x, a, k, m) for m = 4: k (|x| - a)^4 outside [-a, a], 0 inside.
inline double yao_penalty4(double x, double a, double k) noexcept {
    const double d = x > a ? x - a : (x < -a ? -x - a : 0.0);
    const double d2 = d * d;
    return k * (d2 * d2);
}
}  // namespace detail

/// F12 (Yao et al. 1999 Table I), the first generalized penalized function:
/// f = pi/n {10 sin^2(pi y_1) + sum_{i<n} (y_i - 1)^2 [1 + 10 sin^2(pi y_{i+1})] + (y_n - 1)^2}
///     + sum u(x_i, 10, 100, 4),  y_i = 1 + (x_i + 1)/4; minimum 0 at x = (-1, ..., -1).
struct Penalized1 : BoxFunction {
    static constexpr FunctionInfo info{
        "penalized-1", "generalized penalized function 1 (Yao et al. 1999 F12)", -50.0, 50.0, 1, -1.0, 0.0};
    explicit Penalized1(std::size_t dim) : BoxFunction(dim, info) {}
    double evaluate(std::span<const double> x) const noexcept {
        constexpr double pi = std::numbers::pi;
        const std::size_t n = x.size();
        auto y = [&](std::size_t i) { return 1.0 + (x[i] + 1.0) / 4.0; };
        const double s1 = std::sin(pi * y(0));
        double f = 10.0 * s1 * s1;
        for (std::size_t i = 0; i + 1 < n; ++i) {
            const double d = y(i) - 1.0;
            const double s = std::sin(pi * y(i + 1));
            f += d * d * (1.0 + 10.0 * s * s);
        }
        const double dn = y(n - 1) - 1.0;
        f += dn * dn;
        double penalty = 0.0;
        for (double v : x) penalty += detail::yao_penalty4(v, 10.0, 100.0);
        return pi / static_cast<double>(n) * f + penalty;
    }
};

/// F13 (Yao et al. 1999 Table I), the second generalized penalized function:
/// f = 0.1 {sin^2(3 pi x_1) + sum_{i<n} (x_i - 1)^2 [1 + sin^2(3 pi x_{i+1})]
///          + (x_n - 1)^2 [1 + sin^2(2 pi x_n)]} + sum u(x_i, 5, 100, 4); minimum 0 at (1, ..., 1).
struct Penalized2 : BoxFunction {
    static constexpr FunctionInfo info{
        "penalized-2", "generalized penalized function 2 (Yao et al. 1999 F13)", -50.0, 50.0, 1, 1.0, 0.0};
    explicit Penalized2(std::size_t dim) : BoxFunction(dim, info) {}
    double evaluate(std::span<const double> x) const noexcept {
        constexpr double pi = std::numbers::pi;
        const std::size_t n = x.size();
        const double s1 = std::sin(3.0 * pi * x[0]);
        double f = s1 * s1;
        for (std::size_t i = 0; i + 1 < n; ++i) {
            const double d = x[i] - 1.0;
            const double s = std::sin(3.0 * pi * x[i + 1]);
            f += d * d * (1.0 + s * s);
        }
        const double dn = x[n - 1] - 1.0;
        const double sn = std::sin(2.0 * pi * x[n - 1]);
        f += dn * dn * (1.0 + sn * sn);
        double penalty = 0.0;
        for (double v : x) penalty += detail::yao_penalty4(v, 5.0, 100.0);
        return 0.1 * f + penalty;
    }
};

/// One row of Yao's Table I for a catalog. Build F number k (1-based) as
///   yao_table[k-1].function's class, constructed (dim, *info) when info->name starts with "yao-"
///   (Sphere, Rosenbrock, Ackley with a Yao box) and (dim) otherwise (info is then X::info);
/// in dimension default_dim (the paper's 30, or the fixed dimension of F14-F23).
struct YaoEntry {
    std::string_view alias;     // "yao-f1" ... "yao-f23"
    std::string_view function;  // info.name of the class whose formula it is
    const FunctionInfo* info;   // the table (box, optimum) to build it with
    std::size_t default_dim;
};

inline constexpr std::array<YaoEntry, 23> yao_table{{
    {"yao-f1", "sphere", &yao_f1_info, 30},
    {"yao-f2", "schwefel-2.22", &Schwefel222::info, 30},
    {"yao-f3", "schwefel-1.2", &Schwefel12::info, 30},
    {"yao-f4", "schwefel-2.21", &Schwefel221::info, 30},
    {"yao-f5", "rosenbrock", &yao_f5_info, 30},
    {"yao-f6", "step", &Step::info, 30},
    {"yao-f7", "quartic-noise", &QuarticNoise::info, 30},
    {"yao-f8", "schwefel-2.26", &Schwefel226::info, 30},
    {"yao-f9", "rastrigin", &Rastrigin::info, 30},
    {"yao-f10", "ackley", &yao_f10_info, 30},
    {"yao-f11", "griewank", &Griewank::info, 30},
    {"yao-f12", "penalized-1", &Penalized1::info, 30},
    {"yao-f13", "penalized-2", &Penalized2::info, 30},
    {"yao-f14", "shekel-foxholes", &ShekelFoxholes::info, 2},
    {"yao-f15", "kowalik", &Kowalik::info, 4},
    {"yao-f16", "six-hump-camel", &SixHumpCamel::info, 2},
    {"yao-f17", "branin", &Branin::info, 2},
    {"yao-f18", "goldstein-price", &GoldsteinPrice::info, 2},
    {"yao-f19", "hartman-3", &Hartman3::info, 3},
    {"yao-f20", "hartman-6", &Hartman6::info, 6},
    {"yao-f21", "shekel-5", &Shekel5::info, 4},
    {"yao-f22", "shekel-7", &Shekel7::info, 4},
    {"yao-f23", "shekel-10", &Shekel10::info, 4},
}};

/// yao_names[k-1]: the function (info.name of its class) that Yao's F number k is.
inline constexpr std::array<std::string_view, 23> yao_names = [] {
    std::array<std::string_view, 23> names{};
    for (std::size_t i = 0; i < names.size(); ++i) names[i] = yao_table[i].function;
    return names;
}();

}  // namespace pride::continuous

#pragma once
// BBOB f1-f5, the separable functions (Hansen, Finck, Ros, Auger 2009, INRIA RR-6829, f1-f5).
#include <cmath>
#include <numbers>
#include <span>
#include <vector>

#include "framework/problem.hpp"
#include "problems/continuous/bbob/bbob_function.hpp"
#include "problems/continuous/bbob/transforms.hpp"

namespace pride::continuous::bbob {

/// f1, sphere: ||z||^2 + f_opt, z = x - x_opt (RR-6829 f1; COCO f_sphere.c).
class F1 : public BbobFunction {
  public:
    static constexpr int id = 1;
    static constexpr FunctionInfo info{"bbob-f1", "sphere (separable)", -5.0, 5.0, 2, unknown, unknown};
    F1(std::size_t dim, std::int64_t instance) : BbobFunction(dim, instance, info, id), z_(dim) {
        x_opt_ = compute_xopt(dim, seed_);
    }
    double evaluate(std::span<const double> x) noexcept {
        shift(x, x_opt_, z_);
        double f = 0.0;
        for (double v : z_) f += v * v;
        return f + f_opt_;
    }
    /// evaluate() on two points at a time, their sums interleaved: each is still one chain of
    /// additions in COCO's order (the same bits), but the two chains overlap. Point by point, the
    /// batch route was 1.2x slower than the scalar one at D = 40, the overlap of one
    /// point's chain with the next depending on the code around the loop.
    void evaluate_batch(MatrixView points, std::span<double> values) noexcept {
        const auto n = static_cast<std::size_t>(points.rows());
        const auto count = static_cast<std::size_t>(points.cols());
        std::size_t j = 0;
        for (; j + 1 < count; j += 2) {
            const double* a = points.col(static_cast<Eigen::Index>(j)).data();
            const double* b = points.col(static_cast<Eigen::Index>(j + 1)).data();
            double fa = 0.0, fb = 0.0;
            for (std::size_t i = 0; i < n; ++i) {
                const double va = a[i] - x_opt_[i], vb = b[i] - x_opt_[i];
                fa += va * va;
                fb += vb * vb;
            }
            values[j] = fa + f_opt_;
            values[j + 1] = fb + f_opt_;
        }
        if (j < count) values[j] = evaluate({points.col(static_cast<Eigen::Index>(j)).data(), n});
    }

  private:
    std::vector<double> z_;
};

/// f2, separable ellipsoid: sum 10^(6 (i-1)/(D-1)) z_i^2, z = T_osz(x - x_opt) (RR-6829 f2; COCO f_ellipsoid.c).
class F2 : public BbobFunction {
  public:
    static constexpr int id = 2;
    static constexpr FunctionInfo info{"bbob-f2", "ellipsoid (separable, condition 1e6)", -5.0, 5.0, 2, unknown,
                                       unknown};
    F2(std::size_t dim, std::int64_t instance)
        : BbobFunction(dim, instance, info, id), weight_(power_ramp(1.0e6, dim)), z_(dim) {
        x_opt_ = compute_xopt(dim, seed_);
    }
    double evaluate(std::span<const double> x) noexcept {
        shift(x, x_opt_, z_);
        tosz(z_);
        double f = z_[0] * z_[0];
        for (std::size_t i = 1; i < z_.size(); ++i) f += weight_[i] * z_[i] * z_[i];
        return f + f_opt_;
    }

  private:
    std::vector<double> weight_;
    std::vector<double> z_;
};

/// Rastrigin's sum, 10 (D - sum cos(2 pi z_i)) + ||z||^2, as f_rastrigin.c sums it (f3, f15).
inline double rastrigin_sum(std::span<const double> z) noexcept {
    double cosines = 0.0, squares = 0.0;
    for (double v : z) {
        cosines += std::cos(2.0 * std::numbers::pi * v);
        squares += v * v;
    }
    return 10.0 * (static_cast<double>(z.size()) - cosines) + squares;
}

/// f3, separable Rastrigin: z = Lambda^10 T_asy^0.2(T_osz(x - x_opt)) (RR-6829 f3; COCO f_rastrigin.c).
class F3 : public BbobFunction {
  public:
    static constexpr int id = 3;
    static constexpr FunctionInfo info{"bbob-f3", "Rastrigin (separable, multimodal)", -5.0, 5.0, 2, unknown, unknown};
    F3(std::size_t dim, std::int64_t instance)
        : BbobFunction(dim, instance, info, id), lambda_(conditioning_diagonal(10.0, dim)), z_(dim) {
        x_opt_ = compute_xopt(dim, seed_);
    }
    double evaluate(std::span<const double> x) noexcept {
        shift(x, x_opt_, z_);
        tosz(z_);
        tasy(z_, 0.2);
        for (std::size_t i = 0; i < z_.size(); ++i) z_[i] = lambda_[i] * z_[i];
        return rastrigin_sum(z_) + f_opt_;
    }

  private:
    std::vector<double> lambda_;
    std::vector<double> z_;
};

/// f4, Bueche-Rastrigin: z_i = s_i T_osz(x_i - x_opt_i), s_i = 10^(0.5 (i-1)/(D-1)), times 10 at
/// odd i (1-based) where the argument is positive; + 100 f_pen (RR-6829 f4; COCO f_bueche_rastrigin.c,
/// transform_vars_brs.c). COCO (as the 2009 code) also makes x_opt's odd coordinates positive,
/// which RR-6829 does not say; f4 shares f3's seed, so its x_opt is f3's with those made positive.
class F4 : public BbobFunction {
  public:
    static constexpr int id = 4;
    static constexpr FunctionInfo info{
        "bbob-f4", "Bueche-Rastrigin (separable, asymmetric multimodal)", -5.0, 5.0, 2, unknown, unknown};
    F4(std::size_t dim, std::int64_t instance)
        : BbobFunction(dim, instance, info, id), scale_(power_ramp(std::sqrt(10.0), dim)), z_(dim) {
        x_opt_ = compute_xopt(dim, seed_);
        for (std::size_t i = 0; i < dim; i += 2) x_opt_[i] = std::fabs(x_opt_[i]);
    }
    double evaluate(std::span<const double> x) noexcept {
        const double penalty = boundary_penalty(x);
        shift(x, x_opt_, z_);
        tosz(z_);
        for (std::size_t i = 0; i < z_.size(); ++i) {
            double factor = scale_[i];
            if (z_[i] > 0.0 && i % 2 == 0) factor *= 10.0;
            z_[i] = factor * z_[i];
        }
        return rastrigin_sum(z_) + f_opt_ + 100.0 * penalty;
    }

  private:
    std::vector<double> scale_;
    std::vector<double> z_;
};

/// f5, linear slope: sum 5 |s_i| - s_i z_i, s_i = sign(x_opt_i) 10^((i-1)/(D-1)), where
/// z_i = x_i unless x_i lies beyond the corner x_opt (RR-6829 f5; COCO f_linear_slope.c). x_opt is the corner
/// 5 sign(u_i) of the usual random x_opt; the function has no f_pen.
class F5 : public BbobFunction {
  public:
    static constexpr int id = 5;
    static constexpr FunctionInfo info{
        "bbob-f5", "linear slope (separable, optimum in a corner)", -5.0, 5.0, 2, unknown, unknown};
    F5(std::size_t dim, std::int64_t instance) : BbobFunction(dim, instance, info, id), slope_(dim) {
        x_opt_ = compute_xopt(dim, seed_);
        const std::vector<double> ramp = power_ramp(std::sqrt(100.0), dim);
        for (std::size_t i = 0; i < dim; ++i) {
            x_opt_[i] = x_opt_[i] < 0.0 ? -5.0 : 5.0;
            slope_[i] = x_opt_[i] > 0.0 ? ramp[i] : -ramp[i];
        }
    }
    double evaluate(std::span<const double> x) const noexcept {
        double f = 0.0;
        for (std::size_t i = 0; i < x.size(); ++i) {
            const double s = slope_[i];
            if (x[i] * x_opt_[i] < 25.0)
                f += 5.0 * std::fabs(s) - s * x[i];
            else
                f += 5.0 * std::fabs(s) - s * x_opt_[i];
        }
        return f + f_opt_;
    }

  private:
    std::vector<double> slope_;
};

}  // namespace pride::continuous::bbob

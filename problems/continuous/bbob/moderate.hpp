#pragma once
// BBOB f6-f9, functions with low or moderate conditioning (Hansen, Finck, Ros, Auger 2009,
// INRIA RR-6829, f6-f9).
#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include "problems/continuous/bbob/bbob_function.hpp"
#include "problems/continuous/bbob/transforms.hpp"

namespace pride::continuous::bbob {

/// f6, attractive sector: T_osz(sum (s_i z_i)^2)^0.9, s_i = 100 where z_i x_opt_i > 0, else 1;
/// z = Q Lambda^10 R (x - x_opt) (RR-6829 f6; COCO f_attractive_sector.c; R from seed, Q from seed + 1e6).
class F6 : public BbobFunction {
  public:
    static constexpr int id = 6;
    static constexpr FunctionInfo info{"bbob-f6", "attractive sector (moderate conditioning)", -5.0, 5.0, 2, unknown,
                                       unknown};
    F6(std::size_t dim, std::int64_t instance)
        : BbobFunction(dim, instance, info, id),
          m_(scaled_product(compute_rotation(dim, seed_ + 1000000), power_ramp(std::sqrt(10.0), dim),
                            compute_rotation(dim, seed_))),
          shifted_(dim),
          z_(dim) {
        x_opt_ = compute_xopt(dim, seed_);
    }
    double evaluate(std::span<const double> x) noexcept {
        shift(x, x_opt_, shifted_);
        affine(m_, shifted_, z_);
        double f = 0.0;
        for (std::size_t i = 0; i < z_.size(); ++i)
            f += x_opt_[i] * z_[i] > 0.0 ? 100.0 * 100.0 * z_[i] * z_[i] : z_[i] * z_[i];
        return std::pow(tosz(f), 0.9) + f_opt_;
    }

  private:
    AffineMatrix m_;
    std::vector<double> shifted_;
    std::vector<double> z_;
};

/// f7, step ellipsoid: 0.1 max(|zhat_1|/1e4, sum 10^(2(i-1)/(D-1)) z_i^2) + f_pen, zhat =
/// Lambda^10 R (x - x_opt), z = Q round(zhat) (RR-6829 f7; COCO f_step_ellipsoid.c; R from seed, Q from
/// seed + 1e6). RR-6829 writes the rounding as floor(0.5 + zhat) for |zhat| > 0.5, else
/// floor(0.5 + 10 zhat)/10, as COCO does; the 1e-4 |zhat_1| term uses the unrounded zhat_1.
class F7 : public BbobFunction {
  public:
    static constexpr int id = 7;
    static constexpr FunctionInfo info{
        "bbob-f7", "step ellipsoid (plateaus, moderate conditioning)", -5.0, 5.0, 2, unknown, unknown};
    F7(std::size_t dim, std::int64_t instance)
        : BbobFunction(dim, instance, info, id),
          q_(compute_rotation(dim, seed_ + 1000000)),
          lambda_r_(compute_rotation(dim, seed_)),
          weight_(power_ramp(100.0, dim)),
          zhat_(dim),
          z_(dim) {
        x_opt_ = compute_xopt(dim, seed_);
        // COCO multiplies each term by sqrt(pow(10, i/(D-1))) inside the sum: fold it into R's row.
        for (std::size_t i = 0; i < dim; ++i) {
            const double c = std::sqrt(std::pow(100.0 / 10.0, static_cast<double>(i) / static_cast<double>(dim - 1)));
            for (std::size_t j = 0; j < dim; ++j) lambda_r_(Eigen::Index(i), Eigen::Index(j)) *= c;
        }
    }
    double evaluate(std::span<const double> x) noexcept {
        const double penalty = boundary_penalty(x);
        const std::size_t n = x.size();
        for (std::size_t i = 0; i < n; ++i) {
            double sum = 0.0;
            for (std::size_t j = 0; j < n; ++j) sum += lambda_r_(Eigen::Index(i), Eigen::Index(j)) * (x[j] - x_opt_[j]);
            zhat_[i] = sum;
        }
        const double zhat_1 = zhat_[0];
        for (double& v : zhat_) v = std::fabs(v) > 0.5 ? std::floor(v + 0.5) : std::floor(10.0 * v + 0.5) / 10.0;
        affine(q_, zhat_, z_);
        double f = 0.0;
        for (std::size_t i = 0; i < n; ++i) f += weight_[i] * z_[i] * z_[i];
        return 0.1 * std::max(std::fabs(zhat_1) * 1.0e-4, f) + penalty + f_opt_;
    }

  private:
    AffineMatrix q_;
    RowMatrix lambda_r_;  // Lambda^10 R, row i scaled as COCO does
    std::vector<double> weight_;
    std::vector<double> zhat_;
    std::vector<double> z_;
};

/// Rosenbrock's sum 100 sum (z_i^2 - z_{i+1})^2 + sum (z_i - 1)^2, as f_rosenbrock.c sums it.
inline double rosenbrock_sum(std::span<const double> z) noexcept {
    double s1 = 0.0, s2 = 0.0;
    for (std::size_t i = 0; i + 1 < z.size(); ++i) {
        const double a = z[i] * z[i] - z[i + 1];
        s1 += a * a;
        const double b = z[i] - 1.0;
        s2 += b * b;
    }
    return 100.0 * s1 + s2;
}

/// f8, Rosenbrock: z = max(1, sqrt(D)/8) (x - x_opt) + 1 (RR-6829 f8; COCO f_rosenbrock.c). COCO scales
/// x_opt by 0.75 (RR-6829: x_opt in [-3, 3]^D).
class F8 : public BbobFunction {
  public:
    static constexpr int id = 8;
    static constexpr FunctionInfo info{"bbob-f8", "Rosenbrock (original, moderate conditioning)", -5.0, 5.0, 2, unknown,
                                       unknown};
    F8(std::size_t dim, std::int64_t instance)
        : BbobFunction(dim, instance, info, id),
          factor_(std::max(1.0, std::sqrt(static_cast<double>(dim)) / 8.0)),
          z_(dim) {
        x_opt_ = compute_xopt(dim, seed_);
        for (double& v : x_opt_) v *= 0.75;
    }
    double evaluate(std::span<const double> x) noexcept {
        for (std::size_t i = 0; i < x.size(); ++i) z_[i] = factor_ * (x[i] - x_opt_[i]) - (-1.0);
        return rosenbrock_sum(z_) + f_opt_;
    }

  private:
    double factor_;
    std::vector<double> z_;
};

/// f9, rotated Rosenbrock: z = max(1, sqrt(D)/8) R x + 1/2 (RR-6829 f9; COCO f_rosenbrock.c, R from seed).
/// x_opt is COCO's best parameter R^T 1 / (2 max(1, sqrt(D)/8)), where z = 1.
class F9 : public BbobFunction {
  public:
    static constexpr int id = 9;
    static constexpr FunctionInfo info{"bbob-f9", "Rosenbrock (rotated, moderate conditioning)", -5.0, 5.0, 2, unknown,
                                       unknown};
    F9(std::size_t dim, std::int64_t instance) : BbobFunction(dim, instance, info, id), z_(dim) {
        const RowMatrix r = compute_rotation(dim, seed_);
        const double factor = std::max(1.0, std::sqrt(static_cast<double>(dim)) / 8.0);
        m_ = factor * r;
        x_opt_.assign(dim, 0.0);
        for (std::size_t j = 0; j < dim; ++j) {
            double column_sum = 0.0;
            for (std::size_t i = 0; i < dim; ++i) column_sum += r(Eigen::Index(i), Eigen::Index(j));
            x_opt_[j] = column_sum / (2.0 * factor);
        }
    }
    double evaluate(std::span<const double> x) noexcept {
        affine(m_, x, z_, 0.5);
        return rosenbrock_sum(z_) + f_opt_;
    }

  private:
    AffineMatrix m_;
    std::vector<double> z_;
};

}  // namespace pride::continuous::bbob

#pragma once
// BBOB f10-f14, unimodal functions with high conditioning (Hansen, Finck, Ros, Auger 2009,
// INRIA RR-6829, f10-f14).
#include <cmath>
#include <span>
#include <vector>

#include "problems/continuous/bbob/bbob_function.hpp"
#include "problems/continuous/bbob/transforms.hpp"

namespace pride::continuous::bbob {

/// f10, rotated ellipsoid: sum 10^(6 (i-1)/(D-1)) z_i^2, z = T_osz(R (x - x_opt)) (RR-6829
/// f10; COCO f_ellipsoid.c, R from seed + 1e6).
class F10 : public BbobFunction {
  public:
    static constexpr int id = 10;
    static constexpr FunctionInfo info{"bbob-f10", "ellipsoid (rotated, condition 1e6)", -5.0, 5.0, 2, unknown,
                                       unknown};
    F10(std::size_t dim, std::int64_t instance)
        : BbobFunction(dim, instance, info, id),
          r_(compute_rotation(dim, seed_ + 1000000)),
          weight_(power_ramp(1.0e6, dim)),
          shifted_(dim),
          z_(dim) {
        x_opt_ = compute_xopt(dim, seed_);
    }
    double evaluate(std::span<const double> x) noexcept {
        shift(x, x_opt_, shifted_);
        affine(r_, shifted_, z_);
        tosz(z_);
        double f = z_[0] * z_[0];
        for (std::size_t i = 1; i < z_.size(); ++i) f += weight_[i] * z_[i] * z_[i];
        return f + f_opt_;
    }

  private:
    AffineMatrix r_;
    std::vector<double> weight_;
    std::vector<double> shifted_;
    std::vector<double> z_;
};

/// f11, discus: 1e6 z_1^2 + sum_{i>1} z_i^2, z = T_osz(R (x - x_opt)) (RR-6829 f11; COCO f_discus.c, R from
/// seed + 1e6).
class F11 : public BbobFunction {
  public:
    static constexpr int id = 11;
    static constexpr FunctionInfo info{"bbob-f11", "discus (one steep direction, condition 1e6)", -5.0, 5.0, 2, unknown,
                                       unknown};
    F11(std::size_t dim, std::int64_t instance)
        : BbobFunction(dim, instance, info, id), r_(compute_rotation(dim, seed_ + 1000000)), shifted_(dim), z_(dim) {
        x_opt_ = compute_xopt(dim, seed_);
    }
    double evaluate(std::span<const double> x) noexcept {
        shift(x, x_opt_, shifted_);
        affine(r_, shifted_, z_);
        tosz(z_);
        double f = 1.0e6 * z_[0] * z_[0];
        for (std::size_t i = 1; i < z_.size(); ++i) f += z_[i] * z_[i];
        return f + f_opt_;
    }

  private:
    AffineMatrix r_;
    std::vector<double> shifted_;
    std::vector<double> z_;
};

/// f12, bent cigar: z_1^2 + 1e6 sum_{i>1} z_i^2, z = R T_asy^0.5(R (x - x_opt)) (RR-6829
/// f12; COCO f_bent_cigar.c). Unlike the other functions, COCO draws this x_opt from seed + 1e6, the
/// rotation's seed.
class F12 : public BbobFunction {
  public:
    static constexpr int id = 12;
    static constexpr FunctionInfo info{"bbob-f12", "bent cigar (narrow ridge, condition 1e6)", -5.0, 5.0, 2, unknown,
                                       unknown};
    F12(std::size_t dim, std::int64_t instance)
        : BbobFunction(dim, instance, info, id), r_(compute_rotation(dim, seed_ + 1000000)), a_(dim), b_(dim) {
        x_opt_ = compute_xopt(dim, seed_ + 1000000);
    }
    double evaluate(std::span<const double> x) noexcept {
        shift(x, x_opt_, a_);
        affine(r_, a_, b_);
        tasy(b_, 0.5);
        affine(r_, b_, a_);
        double f = a_[0] * a_[0];
        for (std::size_t i = 1; i < a_.size(); ++i) f += 1.0e6 * a_[i] * a_[i];
        return f + f_opt_;
    }

  private:
    AffineMatrix r_;
    std::vector<double> a_;
    std::vector<double> b_;
};

/// f13, sharp ridge: z_1^2 + 100 sqrt(sum_{i>1} z_i^2), z = Q Lambda^10 R (x - x_opt) (RR-6829
/// f13; COCO f_sharp_ridge.c, R from seed, Q from seed + 1e6; COCO adds z_1^2 after the root).
class F13 : public BbobFunction {
  public:
    static constexpr int id = 13;
    static constexpr FunctionInfo info{"bbob-f13", "sharp ridge (non-differentiable ridge)", -5.0, 5.0, 2, unknown,
                                       unknown};
    F13(std::size_t dim, std::int64_t instance)
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
        double ridge = 0.0;
        for (std::size_t i = 1; i < z_.size(); ++i) ridge += z_[i] * z_[i];
        double f = 100.0 * std::sqrt(ridge / 1.0);
        f += z_[0] * z_[0] / 1.0;
        return f + f_opt_;
    }

  private:
    AffineMatrix m_;
    std::vector<double> shifted_;
    std::vector<double> z_;
};

/// f14, different powers: sqrt(sum |z_i|^(2 + 4 (i-1)/(D-1))), z = R (x - x_opt) (RR-6829
/// f14; COCO f_different_powers.c, R from seed + 1e6).
class F14 : public BbobFunction {
  public:
    static constexpr int id = 14;
    static constexpr FunctionInfo info{"bbob-f14", "different powers (rotated)", -5.0, 5.0, 2, unknown, unknown};
    F14(std::size_t dim, std::int64_t instance)
        : BbobFunction(dim, instance, info, id),
          r_(compute_rotation(dim, seed_ + 1000000)),
          exponent_(dim),
          shifted_(dim),
          z_(dim) {
        x_opt_ = compute_xopt(dim, seed_);
        for (std::size_t i = 0; i < dim; ++i)
            exponent_[i] = 2.0 + (4.0 * static_cast<double>(i)) / (static_cast<double>(dim) - 1.0);
    }
    double evaluate(std::span<const double> x) noexcept {
        shift(x, x_opt_, shifted_);
        affine(r_, shifted_, z_);
        double sum = 0.0;
        for (std::size_t i = 0; i < z_.size(); ++i) sum += std::pow(std::fabs(z_[i]), exponent_[i]);
        return std::sqrt(sum) + f_opt_;
    }

  private:
    AffineMatrix r_;
    std::vector<double> exponent_;
    std::vector<double> shifted_;
    std::vector<double> z_;
};

}  // namespace pride::continuous::bbob

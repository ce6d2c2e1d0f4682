#pragma once
// BBOB f15-f19, multimodal functions with adequate global structure (Hansen, Finck, Ros, Auger
// 2009, INRIA RR-6829, f15-f19).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>
#include <vector>

#include "problems/continuous/bbob/bbob_function.hpp"
#include "problems/continuous/bbob/separable.hpp"
#include "problems/continuous/bbob/transforms.hpp"

namespace pride::continuous::bbob {

/// f15, rotated Rastrigin: z = R Lambda^10 Q T_asy^0.2(T_osz(R (x - x_opt))) (RR-6829 f15; COCO f_rastrigin.c;
/// R from seed + 1e6, Q from seed).
class F15 : public BbobFunction {
  public:
    static constexpr int id = 15;
    static constexpr FunctionInfo info{"bbob-f15", "Rastrigin (rotated, multimodal)", -5.0, 5.0, 2, unknown, unknown};
    F15(std::size_t dim, std::int64_t instance)
        : BbobFunction(dim, instance, info, id), r_(compute_rotation(dim, seed_ + 1000000)), a_(dim), b_(dim) {
        m_ = scaled_product(r_, power_ramp(std::sqrt(10.0), dim), compute_rotation(dim, seed_));
        x_opt_ = compute_xopt(dim, seed_);
    }
    double evaluate(std::span<const double> x) noexcept {
        shift(x, x_opt_, a_);
        affine(r_, a_, b_);
        tosz(b_);
        tasy(b_, 0.2);
        affine(m_, b_, a_);
        return rastrigin_sum(a_) + f_opt_;
    }

  private:
    AffineMatrix r_;
    AffineMatrix m_;
    std::vector<double> a_;
    std::vector<double> b_;
};

/// f16, Weierstrass: 10 (1/D sum_i sum_k 2^-k cos(2 pi 3^k (z_i + 1/2)) - f0)^3 + 10/D f_pen,
/// z = R Lambda^(1/100) Q T_osz(R (x - x_opt)), k = 0..11 (RR-6829 f16; COCO f_weierstrass.c; R from seed + 1e6, Q from
/// seed).
class F16 : public BbobFunction {
  public:
    static constexpr int id = 16;
    static constexpr FunctionInfo info{"bbob-f16", "Weierstrass (rugged, repetitive)", -5.0, 5.0, 2, unknown, unknown};
    F16(std::size_t dim, std::int64_t instance)
        : BbobFunction(dim, instance, info, id),
          r_(compute_rotation(dim, seed_ + 1000000)),
          penalty_factor_(10.0 / static_cast<double>(dim)),
          a_(dim),
          b_(dim) {
        m_ = scaled_product(r_, power_ramp(1.0 / std::sqrt(100.0), dim), compute_rotation(dim, seed_));
        x_opt_ = compute_xopt(dim, seed_);
        for (int k = 0; k < terms; ++k) {
            amplitude_[k] = std::pow(0.5, static_cast<double>(k));
            frequency_[k] = std::pow(3.0, static_cast<double>(k));
            f0_ += amplitude_[k] * std::cos(2.0 * std::numbers::pi * frequency_[k] * 0.5);
        }
    }
    double evaluate(std::span<const double> x) noexcept {
        const double penalty = boundary_penalty(x);
        shift(x, x_opt_, a_);
        affine(r_, a_, b_);
        tosz(b_);
        affine(m_, b_, a_);
        double sum = 0.0;
        for (double z : a_)
            for (int k = 0; k < terms; ++k)
                sum += std::cos(2.0 * std::numbers::pi * (z + 0.5) * frequency_[k]) * amplitude_[k];
        const double f = 10.0 * std::pow(sum / static_cast<double>(a_.size()) - f0_, 3.0);
        return f + f_opt_ + penalty_factor_ * penalty;
    }

  private:
    static constexpr int terms = 12;
    AffineMatrix r_;
    AffineMatrix m_;
    double penalty_factor_;
    double amplitude_[terms]{};
    double frequency_[terms]{};
    double f0_ = 0.0;
    std::vector<double> a_;
    std::vector<double> b_;
};

/// Schaffers F7 and the shared transformation of f17 and f18: z = Lambda^c Q T_asy^0.5(R (x -
/// x_opt)), f = (1/(D-1) sum sqrt(s_i) + sqrt(s_i) sin^2(50 s_i^0.2))^2 + 10 f_pen, s_i =
/// sqrt(z_i^2 + z_{i+1}^2) (RR-6829 f17, f18; COCO f_schaffers.c; R from seed + 1e6, Q from seed).
class SchaffersF7 : public BbobFunction {
  public:
    double evaluate(std::span<const double> x) noexcept {
        const double penalty = boundary_penalty(x);
        shift(x, x_opt_, a_);
        affine(r_, a_, b_);
        tasy(b_, 0.5);
        affine(m_, b_, a_);
        double sum = 0.0;
        for (std::size_t i = 0; i + 1 < a_.size(); ++i) {
            const double s = a_[i] * a_[i] + a_[i + 1] * a_[i + 1];
            sum += std::pow(s, 0.25) * (1.0 + std::pow(std::sin(50.0 * std::pow(s, 0.1)), 2.0));
        }
        const double f = std::pow(sum / (static_cast<double>(a_.size()) - 1.0), 2.0);
        return f + f_opt_ + 10.0 * penalty;
    }

  protected:
    SchaffersF7(std::size_t dim, std::int64_t instance, const FunctionInfo& info, int id, double conditioning)
        : BbobFunction(dim, instance, info, id), r_(compute_rotation(dim, seed_ + 1000000)), a_(dim), b_(dim) {
        // Lambda^c Q: row i of Q times sqrt(c)^(i/(D-1)), in COCO's order Q_ij * lambda_i.
        m_ = compute_rotation(dim, seed_);
        const std::vector<double> lambda = power_ramp(std::sqrt(conditioning), dim);
        for (std::size_t i = 0; i < dim; ++i)
            for (std::size_t j = 0; j < dim; ++j) m_(Eigen::Index(i), Eigen::Index(j)) *= lambda[i];
        x_opt_ = compute_xopt(dim, seed_);
    }

  private:
    AffineMatrix r_;
    AffineMatrix m_;
    std::vector<double> a_;
    std::vector<double> b_;
};

/// f17, Schaffers F7 with condition 10.
class F17 : public SchaffersF7 {
  public:
    static constexpr int id = 17;
    static constexpr FunctionInfo info{"bbob-f17", "Schaffers F7 (multimodal, condition 10)", -5.0, 5.0, 2, unknown,
                                       unknown};
    F17(std::size_t dim, std::int64_t instance) : SchaffersF7(dim, instance, info, id, 10.0) {}
};

/// f18, Schaffers F7 with condition 1000; COCO gives it f17's seed (so f17's x_opt, R, Q, f_opt).
class F18 : public SchaffersF7 {
  public:
    static constexpr int id = 18;
    static constexpr FunctionInfo info{"bbob-f18", "Schaffers F7 (multimodal, condition 1000)", -5.0, 5.0, 2, unknown,
                                       unknown};
    F18(std::size_t dim, std::int64_t instance) : SchaffersF7(dim, instance, info, id, 1000.0) {}
};

/// f19, composite Griewank-Rosenbrock F8F2: 10/(D-1) sum (s_i/4000 - cos(s_i)) + 10, s_i =
/// 100 (z_i^2 - z_{i+1})^2 + (z_i - 1)^2, z = max(1, sqrt(D)/8) R x + 1/2 (RR-6829
/// f19; COCO f_griewank_rosenbrock.c, R from seed; COCO writes (1 - z_i)^2). x_opt is COCO's best
/// parameter R^T 1 / (2 max(1, sqrt(D)/8)).
class F19 : public BbobFunction {
  public:
    static constexpr int id = 19;
    static constexpr FunctionInfo info{
        "bbob-f19", "Griewank-Rosenbrock F8F2 (composite, multimodal)", -5.0, 5.0, 2, unknown, unknown};
    F19(std::size_t dim, std::int64_t instance) : BbobFunction(dim, instance, info, id), a_(dim), z_(dim) {
        const double scale = std::max(1.0, std::sqrt(static_cast<double>(dim)) / 8.0);
        m_ = compute_rotation(dim, seed_) * scale;
        x_opt_.assign(dim, 0.0);
        for (std::size_t j = 0; j < dim; ++j) {
            double column_sum = 0.0;
            for (std::size_t i = 0; i < dim; ++i) column_sum += m_(Eigen::Index(i), Eigen::Index(j));
            x_opt_[j] = column_sum / (2.0 * scale);
        }
    }
    double evaluate(std::span<const double> x) noexcept {
        affine(m_, x, a_);
        for (std::size_t i = 0; i < a_.size(); ++i) z_[i] = a_[i] - (-0.5);
        double sum = 0.0;
        for (std::size_t i = 0; i + 1 < z_.size(); ++i) {
            const double c1 = z_[i] * z_[i] - z_[i + 1];
            const double c2 = 1.0 - z_[i];
            const double s = 100.0 * c1 * c1 + c2 * c2;
            sum += s / 4000.0 - std::cos(s);
        }
        const double f = 10.0 + 10.0 * sum / static_cast<double>(z_.size() - 1);
        return f + f_opt_;
    }

  private:
    AffineMatrix m_;
    std::vector<double> a_;
    std::vector<double> z_;
};

}  // namespace pride::continuous::bbob

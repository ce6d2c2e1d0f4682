#pragma once
// BBOB f20-f24, multimodal functions with weak global structure (Hansen, Finck, Ros, Auger 2009,
// INRIA RR-6829, f20-f24).
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <span>
#include <vector>

#include "problems/continuous/bbob/bbob_function.hpp"
#include "problems/continuous/bbob/transforms.hpp"

namespace pride::continuous::bbob {

/// f20, Schwefel x sin(x): 0.01 (418.9828872724339 - 1/D sum z_i sin(sqrt|z_i|)) + 100 f_pen(z/100)
/// with z = 100 (Lambda^10 (zhat - 2|x_opt|) + 2|x_opt|), zhat_1 = xhat_1, zhat_i = xhat_i +
/// 0.25 (xhat_{i-1} - 2|x_opt_{i-1}|), xhat = 2 sign(x_opt) x, x_opt = 4.2096874637/2 sign(u)
/// (RR-6829 f20; COCO f_schwefel.c, transform_vars_x_hat.c, transform_vars_z_hat.c). COCO writes
/// the penalty as 0.01 sum max(0, |z_i| - 500)^2 inside the bracket (the same value). Its best
/// parameter, returned by optimum_point(), derives from 420.96874633 (not ...637): near, not at,
/// the minimiser, so f(x_opt) exceeds f_opt by about 1e-15.
class F20 : public BbobFunction {
  public:
    static constexpr int id = 20;
    static constexpr FunctionInfo info{"bbob-f20", "Schwefel x*sin(x) (weak structure)", -5.0, 5.0, 2, unknown,
                                       unknown};
    F20(std::size_t dim, std::int64_t instance)
        : BbobFunction(dim, instance, info, id),
          lambda_(conditioning_diagonal(10.0, dim)),
          twice_abs_opt_(dim),
          flip_(dim),
          xhat_(dim),
          z_(dim) {
        const std::vector<double> u = uniform(dim, seed_);
        std::vector<double> location(dim);  // the x_opt of RR-6829, which defines the transformation
        for (std::size_t i = 0; i < dim; ++i) {
            flip_[i] = u[i] < 0.5;
            location[i] = (u[i] < 0.5 ? -1.0 : 1.0) * 0.5 * 4.2096874637;
            twice_abs_opt_[i] = 2.0 * std::fabs(location[i]);
        }
        // COCO's best parameter: the raw function's 420.96874633 taken back through the
        // transformations that update it (scale 100, the two shifts, scale 2, the sign flips).
        x_opt_.resize(dim);
        for (std::size_t i = 0; i < dim; ++i) {
            double v = 420.96874633 / 100.0;
            v += -twice_abs_opt_[i];
            v += twice_abs_opt_[i];
            v /= 2.0;
            x_opt_[i] = flip_[i] ? -v : v;
        }
    }
    double evaluate(std::span<const double> x) noexcept {
        const std::size_t n = x.size();
        for (std::size_t i = 0; i < n; ++i) xhat_[i] = 2.0 * (flip_[i] ? -x[i] : x[i]);
        z_[0] = xhat_[0];
        for (std::size_t i = 1; i < n; ++i) z_[i] = xhat_[i] + 0.25 * (xhat_[i - 1] - twice_abs_opt_[i - 1]);
        for (std::size_t i = 0; i < n; ++i)
            z_[i] = 100.0 * (lambda_[i] * (z_[i] - twice_abs_opt_[i]) - (-twice_abs_opt_[i]));
        double penalty = 0.0;
        for (double v : z_) {
            const double excess = std::fabs(v) - 500.0;
            if (excess > 0.0) penalty += excess * excess;
        }
        double sum = 0.0;
        for (double v : z_) sum += v * std::sin(std::sqrt(std::fabs(v)));
        const double f = 0.01 * (penalty + 418.9828872724339 - sum / static_cast<double>(n));
        return f + f_opt_;
    }

  private:
    std::vector<double> lambda_;
    std::vector<double> twice_abs_opt_;
    std::vector<char> flip_;  // x_hat's sign: u_i < 0.5
    std::vector<double> xhat_;
    std::vector<double> z_;
};

/// Gallagher's Gaussian peaks, f21 (101 peaks) and f22 (21): T_osz(10 - max_p w_p exp(-1/(2D)
/// (x - y_p)^T R^T C_p R (x - y_p)))^2 + f_pen (RR-6829 f21, f22; COCO f_gallagher.c, R from seed). COCO builds
/// C_p = alpha_p^(j/(D-1) - 1/2) directly, with alpha_p the square roots of RR-6829's (f21:
/// global peak sqrt(1000), others 1000^(j/99); f22: 1000 and 1000^(j/19)), which is the same
/// matrix as RR-6829's Lambda^(alpha_p)/alpha_p^(1/4); x_opt = y_1.
class Gallagher : public BbobFunction {
  public:
    double evaluate(std::span<const double> x) noexcept {
        const std::size_t n = x.size();
        const double penalty = boundary_penalty(x);
        affine(peaks_.rotation, x, rx_);
        const double fac = -0.5 / static_cast<double>(n);
        double best = 0.0;
        const auto peaks = static_cast<std::size_t>(peaks_.local.rows());
        for (std::size_t p = 0; p < peaks; ++p) {
            const double* local = peaks_.local.data() + p * n;
            const double* scale = peaks_.scales.data() + p * n;
            double q = 0.0;
            for (std::size_t j = 0; j < n; ++j) {
                const double d = rx_[j] - local[j];
                q += scale[j] * d * d;
            }
            best = std::max(best, peaks_.heights[p] * std::exp(fac * q));
        }
        double f = tosz(10.0 - best);
        f *= f;
        f += penalty;
        return f + f_opt_;
    }

  protected:
    Gallagher(std::size_t dim, std::int64_t instance, const FunctionInfo& info, int id, std::size_t peaks)
        : BbobFunction(dim, instance, info, id), peaks_(make_gallagher_peaks(dim, peaks, seed_)), rx_(dim) {
        x_opt_ = peaks_.best;
    }

  private:
    GallagherPeaks peaks_;
    std::vector<double> rx_;
};

/// f21, Gallagher with 101 peaks.
class F21 : public Gallagher {
  public:
    static constexpr int id = 21;
    static constexpr FunctionInfo info{
        "bbob-f21", "Gallagher 101 Gaussian peaks (weak structure)", -5.0, 5.0, 2, unknown, unknown};
    F21(std::size_t dim, std::int64_t instance) : Gallagher(dim, instance, info, id, 101) {}
};

/// f22, Gallagher with 21 peaks.
class F22 : public Gallagher {
  public:
    static constexpr int id = 22;
    static constexpr FunctionInfo info{
        "bbob-f22", "Gallagher 21 Gaussian peaks (weak structure)", -5.0, 5.0, 2, unknown, unknown};
    F22(std::size_t dim, std::int64_t instance) : Gallagher(dim, instance, info, id, 21) {}
};

/// f23, Katsuura: 10/D^2 prod (1 + i sum_{j=1}^{32} |2^j z_i - round(2^j z_i)| 2^-j)^(10/D^1.2)
/// - 10/D^2 + f_pen, z = Q Lambda^100 R (x - x_opt) (RR-6829 f23; COCO f_katsuura.c; R from seed, Q from
/// seed + 1e6).
class F23 : public BbobFunction {
  public:
    static constexpr int id = 23;
    /// 2^j for j = 0..32, made once: the same bits as std::pow(2.0, j) (powers of two are exact),
    /// which COCO calls 32 D times per evaluation (5x faster than the calls).
    static constexpr std::array<double, 33> powers_of_two = [] {
        std::array<double, 33> p{};
        double v = 1.0;
        for (double& e : p) {
            e = v;
            v *= 2.0;
        }
        return p;
    }();
    static constexpr FunctionInfo info{"bbob-f23", "Katsuura (rugged, repetitive)", -5.0, 5.0, 2, unknown, unknown};
    F23(std::size_t dim, std::int64_t instance)
        : BbobFunction(dim, instance, info, id),
          m_(scaled_product(compute_rotation(dim, seed_ + 1000000), power_ramp(std::sqrt(100.0), dim),
                            compute_rotation(dim, seed_))),
          exponent_(10.0 / std::pow(static_cast<double>(dim), 1.2)),
          shifted_(dim),
          z_(dim) {
        x_opt_ = compute_xopt(dim, seed_);
    }
    double evaluate(std::span<const double> x) noexcept {
        const double penalty = boundary_penalty(x);
        shift(x, x_opt_, shifted_);
        affine(m_, shifted_, z_);
        const std::size_t n = z_.size();
        double product = 1.0;
        for (std::size_t i = 0; i < n; ++i) {
            double sum = 0.0;
            for (int j = 1; j < 33; ++j) {
                const double power = powers_of_two[static_cast<std::size_t>(j)];
                const double scaled = power * z_[i];
                sum += std::fabs(scaled - std::floor(scaled + 0.5)) / power;
            }
            product *= std::pow(1.0 + (static_cast<double>(i) + 1.0) * sum, exponent_);
        }
        const double d = static_cast<double>(n);
        const double f = 10.0 / d / d * (-1.0 + product);
        return f + f_opt_ + 1.0 * penalty;
    }

  private:
    AffineMatrix m_;
    double exponent_;
    std::vector<double> shifted_;
    std::vector<double> z_;
};

/// f24, Lunacek bi-Rastrigin: min(sum (xhat_i - mu0)^2, D + s sum (xhat_i - mu1)^2) + 10 (D -
/// sum cos(2 pi z_i)) + 1e4 f_pen, xhat = 2 sign(x_opt) x, z = Q Lambda^100 R (xhat - mu0),
/// mu0 = 2.5, mu1 = -sqrt((mu0^2 - 1)/s), s = 1 - 1/(2 sqrt(D + 20) - 8.2) (RR-6829
/// f24; COCO f_lunacek_bi_rastrigin.c; R from seed, Q from seed + 1e6). x_opt = mu0/2 sign(g_i), g from
/// gauss(D, seed), not the usual uniform draw.
class F24 : public BbobFunction {
  public:
    static constexpr int id = 24;
    static constexpr FunctionInfo info{
        "bbob-f24", "Lunacek bi-Rastrigin (weak structure, two funnels)", -5.0, 5.0, 2, unknown, unknown};
    F24(std::size_t dim, std::int64_t instance)
        : BbobFunction(dim, instance, info, id),
          q_(compute_rotation(dim, seed_ + 1000000)),
          lambda_r_(compute_rotation(dim, seed_)),
          s_(1.0 - 0.5 / (std::sqrt(static_cast<double>(dim + 20)) - 4.1)),
          mu1_(-std::sqrt((mu0 * mu0 - 1.0) / s_)),
          xhat_(dim),
          a_(dim),
          z_(dim) {
        const std::vector<double> g = gauss(dim, seed_);
        x_opt_.resize(dim);
        for (std::size_t i = 0; i < dim; ++i) x_opt_[i] = g[i] < 0.0 ? -(0.5 * mu0) : 0.5 * mu0;
        for (std::size_t i = 0; i < dim; ++i) {
            const double c = std::pow(std::sqrt(100.0), static_cast<double>(i) / static_cast<double>(dim - 1));
            for (std::size_t j = 0; j < dim; ++j) lambda_r_(Eigen::Index(i), Eigen::Index(j)) *= c;
        }
    }
    double evaluate(std::span<const double> x) noexcept {
        const std::size_t n = x.size();
        const double penalty = boundary_penalty(x);
        for (std::size_t i = 0; i < n; ++i) xhat_[i] = x_opt_[i] < 0.0 ? -(2.0 * x[i]) : 2.0 * x[i];
        for (std::size_t i = 0; i < n; ++i) {
            double sum = 0.0;
            for (std::size_t j = 0; j < n; ++j) sum += lambda_r_(Eigen::Index(i), Eigen::Index(j)) * (xhat_[j] - mu0);
            a_[i] = sum;
        }
        affine(q_, a_, z_);
        double near = 0.0, far = 0.0, cosines = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            near += (xhat_[i] - mu0) * (xhat_[i] - mu0);
            far += (xhat_[i] - mu1_) * (xhat_[i] - mu1_);
            cosines += std::cos(2.0 * std::numbers::pi * z_[i]);
        }
        const double d = static_cast<double>(n);
        const double f = std::min(near, 1.0 * d + s_ * far) + 10.0 * (d - cosines) + 1e4 * penalty;
        return f + f_opt_;
    }

  private:
    static constexpr double mu0 = 2.5;
    AffineMatrix q_;
    RowMatrix lambda_r_;  // Lambda^100 R, row i scaled as COCO does
    double s_;
    double mu1_;
    std::vector<double> xhat_;
    std::vector<double> a_;
    std::vector<double> z_;
};

}  // namespace pride::continuous::bbob

#pragma once
// CMA-ES with margin: integer variables for CMA-ES.
//
//   Hamano, R., Saito, S., Nomura, M. and Shirakawa, S. (2022). CMA-ES with Margin: Lower-Bounding
//     Marginal Probability for Mixed-Integer Black-Box Optimization. Proc. GECCO 2022, 639-647.
//
// Followed as Debian's python3-cmaes 0.9.1 implements it (cmaes.CMAwM, which Optuna's
// CmaEsSampler(with_margin=True) builds), read for its behaviour. An integer coordinate j with
// values z_1 < ... < z_K has the thresholds l_k = (z_k + z_{k+1}) / 2 between them. Each sample x
// of the normal distribution is evaluated at its encoding: coordinate j becomes the z_k whose
// interval holds m_j + A_j (x_j - m_j) (A_j = 1 at the start); the raw x enters CMA-ES's update.
// After each update the margin keeps, on every integer coordinate, the probability of leaving
// the interval of the mean's value at least alpha (default 1 / (n lambda), the paper's):
//   with l_low, l_up the thresholds around m_j (both the first or the last one at an end),
//   s = sigma A_j sqrt(C_jj), p_low = Phi((l_low - m_j) / s), p_up = 1 - Phi((l_up - m_j) / s):
//   - at an end (max(p_low, p_up) > 0.5), when min(p_low, p_up) < alpha, the mean moves to
//     l_up + sign(m_j - l_up) sigma A_j sqrt(chi2_1^-1(1 - 2 alpha) C_jj) (the paper's eq. 14);
//   - inside (max(p_low, p_up) <= 0.5), p_low and p_up are raised to alpha / 2 at least and the
//     rest shared as the paper's eq. 16-17 do; A_j and m_j then solve the two equations that put
//     those probabilities at l_low and l_up (eq. 18-19), sigma and C unchanged.
// Decided by this project: only integer coordinates are encoded (categorical ones are refused by
// the skeleton); a coordinate with one value is left to the problem (the encoding maps every
// value to it).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

#include <boost/math/distributions/normal.hpp>

namespace pride::cma {

class Margin {
  public:
    /// Integer coordinates `integers` with their values lo[j] .. hi[j]; alpha <= 0: 1 / (n lambda).
    void reset(std::span<const std::size_t> integers, std::span<const double> lo, std::span<const double> hi,
               double alpha, std::size_t n, std::int64_t lambda) {
        alpha_ = alpha > 0.0 ? alpha : 1.0 / (static_cast<double>(n) * static_cast<double>(lambda));
        coords_.assign(integers.begin(), integers.end());
        a_.assign(coords_.size(), 1.0);
        lo_.clear();
        count_.clear();
        for (const std::size_t j : coords_) {
            lo_.push_back(lo[j]);
            count_.push_back(static_cast<std::size_t>(hi[j] - lo[j]) + 1);
        }
    }

    bool active() const noexcept { return !coords_.empty(); }
    double alpha() const noexcept { return alpha_; }
    /// A_j of the c-th integer coordinate.
    double scale(std::size_t c) const noexcept { return a_[c]; }

    /// Writes into `eval` the encoding of the raw sample `x` around the mean `m`: the integer
    /// coordinates replaced by their values.
    template <class X, class M, class E>
    void encode(const X& x, const M& m, E&& eval) const {
        for (std::size_t c = 0; c < coords_.size(); ++c) {
            const auto j = static_cast<Eigen::Index>(coords_[c]);
            const double v = (x[j] - m[j]) * a_[c] + m[j];
            eval[j] = lo_[c] + static_cast<double>(below(c, v));
        }
    }

    /// The margin's correction of the mean `m` after an update with step `sigma` and diag(C) `cdiag`.
    template <class M, class D>
    void correct(M& m, double sigma, const D& cdiag) {
        const boost::math::normal standard;
        const double edge_distance = boost::math::quantile(standard, 1.0 - alpha_);  // sqrt(chi2_1^-1(1 - 2 alpha))
        const auto phi = [](double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); };
        const auto inverse_tail = [&](double p) { return boost::math::quantile(boost::math::complement(standard, p)); };
        for (std::size_t c = 0; c < coords_.size(); ++c) {
            const std::size_t k = count_[c];
            if (k < 2) continue;
            const auto j = static_cast<Eigen::Index>(coords_[c]);
            const double mean = m[j];
            const std::size_t pos = below(c, mean);
            const double low = threshold(c, pos == 0 ? 0 : pos - 1), up = threshold(c, pos == k - 1 ? k - 2 : pos);
            const double root_c = std::sqrt(cdiag[j]);
            const double s = sigma * a_[c] * root_c;
            double p_low = phi((low - mean) / s), p_up = 1.0 - phi((up - mean) / s);
            const double p_mid = 1.0 - (p_low + p_up);
            if (std::max(p_low, p_up) > 0.5) {
                if (std::min(p_low, p_up) < alpha_) {
                    const double sign = mean > up ? 1.0 : mean < up ? -1.0 : 0.0;
                    m[j] = up + sign * sigma * a_[c] * edge_distance * root_c;
                }
                continue;
            }
            const double h = alpha_ / 2.0;
            p_low = std::max(p_low, h);
            p_up = std::max(p_up, h);
            const double rest = 1.0 - p_low - p_up - p_mid, total = p_low + p_mid + p_up - 3.0 * h;
            const double q_low = std::clamp(p_low + rest * (p_low - h) / total, 1e-10, 0.5 - 1e-10);
            const double q_up = std::clamp(p_up + rest * (p_up - h) / total, 1e-10, 0.5 - 1e-10);
            const double chi_low = inverse_tail(q_low), chi_up = inverse_tail(q_up);
            a_[c] = (up - low) / ((chi_low + chi_up) * sigma * root_c);
            m[j] = (low * chi_up + up * chi_low) / (chi_low + chi_up);
        }
    }

  private:
    /// l_t, the threshold between the values lo + t and lo + t + 1.
    double threshold(std::size_t c, std::size_t t) const noexcept { return lo_[c] + static_cast<double>(t) + 0.5; }
    /// How many thresholds of coordinate c lie below v: the index of v's value.
    std::size_t below(std::size_t c, double v) const noexcept {
        const double t = std::ceil(v - lo_[c] - 0.5);  // thresholds lo + 0.5, lo + 1.5, ... strictly below v
        if (!(t > 0.0)) return 0;
        return std::min(static_cast<std::size_t>(t), count_[c] - 1);
    }

    double alpha_ = 0.0;
    std::vector<std::size_t> coords_, count_;
    std::vector<double> lo_, a_;
};

}  // namespace pride::cma

#pragma once
// The augmented Lagrangian constraint handling of CMA-ES with adaptive coefficients:
//
//   Atamna, Auger and Hansen (2016), "Augmented Lagrangian constraint handling for CMA-ES - case of
//     a single linear constraint", PPSN XIV.
//   Atamna, Auger and Hansen (2017), "Linearly convergent evolution strategies via augmented
//     Lagrangian constraint handling", FOGA '17: several constraints, Algorithm 1.
//
// as pycma implements them (cma.constraints_handler: AugmentedLagrangian with set_algorithm(1), the
// "Atamna et al 2017" setting, driven as ConstrainedFitnessAL drives it). Names below are pycma's.
// For each constraint i, with g_i(x) <= 0 an inequality and h_i(x) = 0 an equality (raw values,
// no tolerance), multiplier lam_i and penalty coefficient mu_i:
//   __call__:   the penalty of a point, sum_i lam_i g_i + mu_i g_i^2 / 2, where an inequality's g_i
//               is first raised to -lam_i / mu_i (the term is then its minimum, -lam_i^2 / (2 mu_i));
//               the point is ranked by f + that sum, with the coefficients it was evaluated with.
//   set_coefficients (each generation until every constraint is initialised, from the
//               generation's f and g values, when all f are finite): for a constraint not yet
//               initialised (or with mu_i = 0) that is an equality or was violated by more than
//               10% of the points (sign average > -0.8),
//                 mu_i = 2/5 iqr(f) / n / (iqr(g_i) + 1e-6 iqr(g_i^2) + 1e-11 (iqr(f) + 1)),
//                 lam_i = iqr(f) / (n iqr(g_i) + 1e-11 (iqr(f) + 1))  (inequalities only),
//               iqr the interquartile range of numpy's linear percentiles; it counts as initialised
//               when |sign average| < 0.8 or more than 2 + n updates were made.
//   update (after each generation, with (f, g) of the generation's best point by the penalised
//               value, pycma's which = 'best'; the first call only stores them): when some mu_i > 0,
//               dh = f + P(g) - f_prev - P(g_prev) with the present coefficients, dg = g - g_prev, and
//               for each i with mu_i > 0:
//                 lam_i += mu_i g_i / dgamma  (Algorithm 1's multiplier step), for an inequality only
//                   when g_i or g_prev_i or a point of the generation lay where the penalty is
//                   quadratic (mu_i g > -lam_i);
//                 an inequality's lam_i below 0 is set to 0 and its mu_i is not changed; nor is it
//                   while mu_i g_i < -lam_i (the constraint is inactive);
//                 mu_i *= chi^(1/4) if mu_i g_i^2 < k1 |dh| / n or k2 |dg_i| < |g_prev_i|,
//                 else mu_i /= chi   (Algorithm 1's coefficient step),
//               with k1 = 3, k2 = 5, dgamma = 5 and chi = 2^(1 / (5 n)) (pycma's set_atamna2017).
// Decided by this project where the papers and pycma leave it open: pycma's default rule for mu
// (its algorithm 0, empirical feasibility ratios) is not implemented, only Algorithm 1; the
// coefficients and stored values start afresh with each CMA-ES run of a restart sequence;
// equalities are handled as pycma's AugmentedLagrangian(equality=True) handles them, not split
// into two inequalities; f values are the run guard's (NaN and inf are +inf: such a generation
// neither initialises the coefficients nor updates them when its best f is not finite); likewise
// NaN or infinite constraint values (pycma would spread the NaN into the coefficients); with
// mu_i = 0 the term is lam_i g_i (pycma's formula is NaN there).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "framework/constraints.hpp"
#include "framework/error.hpp"

namespace pride::cma {

/// The parameters of Algorithm 1 (pycma's names); chi 0: 2^(1 / (5 n)).
struct AlSettings {
    double k1 = 3.0;
    double k2 = 5.0;
    double dgamma = 5.0;
    double chi = 0.0;

    void validate(const std::string& who) const {
        require(std::isfinite(k1) && k1 > 0.0, who, "al_k1 must be a finite number > 0, got " + std::to_string(k1));
        require(std::isfinite(k2) && k2 > 0.0, who, "al_k2 must be a finite number > 0, got " + std::to_string(k2));
        require(std::isfinite(dgamma) && dgamma > 0.0, who,
                "al_dgamma must be a finite number > 0, got " + std::to_string(dgamma));
        require(chi == 0.0 || (std::isfinite(chi) && chi > 1.0), who,
                "al_chi must be 0 (2^(1/(5 D))) or a finite number > 1, got " + std::to_string(chi));
    }
};

/// numpy.percentile(data, q) with linear interpolation (its default); sorts `data`.
inline double linear_percentile(std::vector<double>& data, double q) {
    std::sort(data.begin(), data.end());
    const double pos = q / 100.0 * static_cast<double>(data.size() - 1);
    const auto lo = static_cast<std::size_t>(std::floor(pos));
    const std::size_t hi = std::min(lo + 1, data.size() - 1);
    return data[lo] + (pos - static_cast<double>(lo)) * (data[hi] - data[lo]);
}

/// The interquartile range of `data` (pycma's Mh.iqr); sorts it.
inline double interquartile_range(std::vector<double>& data) {
    if (data.empty()) return 0.0;
    const double q75 = linear_percentile(data, 75.0);
    return q75 - linear_percentile(data, 25.0);
}

class AugmentedLagrangian {
  public:
    /// A fresh state for dimension n and these constraints (the coefficients not yet set).
    void reset(std::size_t n, const ConstraintCounts& counts, const AlSettings& s) {
        n_ = static_cast<double>(n);
        k_ = counts.total();
        inequalities_ = counts.inequalities;
        k1_ = s.k1, k2_ = s.k2, dgamma_ = s.dgamma;
        chi_ = s.chi > 0.0 ? s.chi : std::pow(2.0, 1.0 / (5.0 * n_));
        lam_.assign(k_, 0.0), mu_.assign(k_, 0.0), g_prev_.assign(k_, 0.0);
        initialized_.assign(k_, false);
        hits_.assign(k_, 0);
        set_ = false, stored_ = false;
        f_prev_ = 0.0;
        count_ = 0;
    }

    /// The penalty of a point with constraint values g (pycma's sum(__call__(g))); records which
    /// constraints lay where the penalty is quadratic (the multiplier step's condition).
    double penalty(std::span<const double> g) {
        double sum = 0.0;
        for (std::size_t i = 0; i < k_; ++i) {
            if (mu_[i] * g[i] > -lam_[i]) ++hits_[i];
            sum += term(i, g[i]);
        }
        return sum;
    }

    /// After a generation of `f.size()` points: `g` their constraint values (k per point, point after
    /// point), `fitness` their penalised values f + penalty(g) as ranked. set_coefficients while
    /// not initialised, then update with the best point by `fitness`.
    void end_generation(std::span<const double> f, std::span<const double> g, std::span<const double> fitness) {
        if (k_ == 0 || f.empty()) return;
        auto finite = [](std::span<const double> v) {
            return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
        };
        if (!all_initialized() && finite(f) && finite(g)) set_coefficients(f, g);
        std::size_t best = 0;  // the first of the least (numpy's nanargmin)
        while (best + 1 < fitness.size() && std::isnan(fitness[best])) ++best;
        for (std::size_t j = best + 1; j < fitness.size(); ++j)
            if (fitness[j] < fitness[best]) best = j;
        const auto gb = g.subspan(best * k_, k_);
        if (std::isfinite(f[best]) && finite(gb)) update(f[best], gb);
    }

    const std::vector<double>& multipliers() const { return lam_; }  // lam
    const std::vector<double>& coefficients() const { return mu_; }  // mu
    double chi() const { return chi_; }
    bool initialized(std::size_t i) const { return initialized_[i]; }

    /// pycma's set_coefficients (see the file's comment); public for the tests.
    void set_coefficients(std::span<const double> f, std::span<const double> g) {
        set_ = true;
        const std::size_t p = f.size();
        std::vector<double> data(f.begin(), f.end());
        const double df = interquartile_range(data);
        for (std::size_t i = 0; i < k_; ++i) {
            std::size_t positive = 0;
            for (std::size_t j = 0; j < p; ++j) positive += g[j * k_ + i] > 0.0 ? 1 : 0;
            const double sign_average = -1.0 + 2.0 * static_cast<double>(positive) / static_cast<double>(p);
            if (!((!initialized_[i] || mu_[i] == 0.0) && (sign_average > -0.8 || equality(i)))) continue;
            for (std::size_t j = 0; j < p; ++j) data[j] = g[j * k_ + i];
            const double dg = interquartile_range(data);
            for (std::size_t j = 0; j < p; ++j) data[j] = g[j * k_ + i] * g[j * k_ + i];
            const double dg2 = interquartile_range(data);
            mu_[i] = 2.0 / 5.0 * df / n_ / (dg + 1e-6 * dg2 + 1e-11 * (df + 1.0));
            if (!equality(i)) lam_[i] = df / (n_ * dg + 1e-11 * (df + 1.0));
            if (static_cast<double>(count_) > 2.0 + n_ || std::abs(sign_average) < 0.8) initialized_[i] = true;
        }
    }

    /// pycma's update(f, g) with Algorithm 1's rules (see the file's comment); public for the tests.
    void update(double f, std::span<const double> g) {
        if (!set_) return;  // pycma: no coefficients yet, nothing stored
        if (stored_ && std::any_of(mu_.begin(), mu_.end(), [](double m) { return m > 0.0; })) {
            // The two penalties of dh count as calls too.
            const double dh = f + penalty(g) - f_prev_ - penalty(g_prev_);
            for (std::size_t i = 0; i < k_; ++i) {
                if (mu_[i] == 0.0) continue;
                const double dg = g[i] - g_prev_[i];
                if (equality(i) || mu_[i] * g[i] > -lam_[i] || hits_[i] > 0) lam_[i] += mu_[i] * g[i] / dgamma_;
                if (!equality(i) && lam_[i] < 0.0) {
                    lam_[i] = 0.0;
                    continue;
                }
                if (!equality(i) && g[i] * mu_[i] < -lam_[i]) continue;
                if (mu_[i] * g[i] * g[i] < k1_ * std::abs(dh) / n_ || k2_ * std::abs(dg) < std::abs(g_prev_[i]))
                    mu_[i] *= std::pow(chi_, 0.25);
                else
                    mu_[i] /= chi_;
            }
            ++count_;
        }
        f_prev_ = f;
        std::copy(g.begin(), g.end(), g_prev_.begin());
        stored_ = true;
        std::fill(hits_.begin(), hits_.end(), 0);
    }

  private:
    bool equality(std::size_t i) const { return i >= inequalities_; }
    bool all_initialized() const {
        return set_ && std::all_of(initialized_.begin(), initialized_.end(), [](bool b) { return b; });
    }
    double term(std::size_t i, double gi) const {
        if (mu_[i] == 0.0) return lam_[i] * gi;
        if (!equality(i) && mu_[i] * gi < -lam_[i]) gi = -lam_[i] / mu_[i];
        return lam_[i] * gi + 0.5 * mu_[i] * gi * gi;
    }

    double n_ = 1.0, k1_ = 3.0, k2_ = 5.0, dgamma_ = 5.0, chi_ = 1.0, f_prev_ = 0.0;
    std::size_t k_ = 0, inequalities_ = 0;
    std::vector<double> lam_, mu_, g_prev_;
    std::vector<bool> initialized_;
    std::vector<std::int64_t> hits_;
    bool set_ = false, stored_ = false;
    std::int64_t count_ = 0;
};

}  // namespace pride::cma

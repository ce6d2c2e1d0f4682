#pragma once
// The moves of WOA (Cai and Du 2021, eqs. 1-7; Mirjalili and Lewis 2016), of harmony search (Geem, Kim and
// Loganathan 2001) and HS-WOA's second step and balance factor (Cai and Du 2021, eqs. 8-9), as functions of
// given draws, so that each equation can be checked on hand-computed values. `Draws` is anything
// with uniform() in [0, 1) and below(n) in [0, n): the run's Rng, or a scripted source in tests.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <span>
#include <type_traits>
#include <vector>

#include "framework/problem.hpp"
#include "framework/random.hpp"

namespace pride {
/// The move eqs. 1-7 make of a whale (the Mode policies of woa.hpp choose it).
enum class WhaleMove { search, encircle, spiral };
}  // namespace pride

namespace pride::whale {

/// a of eqs. 3-4 at iteration t of T (t = 0..T-1): 2 - 2t/T, from 2 towards 0 (WOA.m).
inline double a(std::int64_t t, std::int64_t horizon) noexcept {
    return 2.0 - 2.0 * static_cast<double>(t) / static_cast<double>(horizon);
}
/// a2 of WOA.m: -1 - t/T, from -1 towards -2; l = (a2 - 1) r + 1 lies in [a2, 1].
inline double a2(std::int64_t t, std::int64_t horizon) noexcept {
    return -1.0 - static_cast<double>(t) / static_cast<double>(horizon);
}
inline double l(double a2, double r) noexcept {
    return (a2 - 1.0) * r + 1.0;
}
/// Eq. 3: A = 2 a r1 - a.  Eq. 4: C = 2 r2.
inline double coefficient_a(double a, double r1) noexcept {
    return 2.0 * a * r1 - a;
}
inline double coefficient_c(double r2) noexcept {
    return 2.0 * r2;
}

/// Eqs. 1-2, one coordinate: D = |C X* - X|, X <- X* - A D (encircling the best).
inline double encircle(double x, double best, double A, double C) noexcept {
    return best - A * std::abs(C * best - x);
}
/// Eqs. 6-7, one coordinate: D = |C X_rand - X|, X <- X_rand - A D (search relative to a random whale).
inline double search(double x, double other, double A, double C) noexcept {
    return other - A * std::abs(C * other - x);
}
/// Eq. 5's factor e^{b l} cos(2 pi l), the same for every coordinate of a whale.
inline double spiral_factor(double l, double b) noexcept {
    return std::exp(b * l) * std::cos(2.0 * std::numbers::pi * l);
}
/// Eq. 5, one coordinate: D' = |X* - X|, X <- D' e^{b l} cos(2 pi l) + X* (the spiral), with the
/// factor of spiral_factor.
inline double spiral(double x, double best, double factor) noexcept {
    return std::abs(best - x) * factor + best;
}

/// Eq. 8, one coordinate: X <- X + r (target - X); the target is X* when f_i < f_avg, a random
/// whale otherwise.
inline double toward(double x, double target, double r) noexcept {
    return x + r * (target - x);
}

/// Harmony search's rates: memory consideration, pitch adjustment, bandwidth as a fraction of
/// each coordinate's range.
struct HarmonyRates {
    double hmcr = 0.9;
    double par = 0.3;
    double bw = 0.01;
};

namespace detail {
template <class Draws>
void improvise_with(const Matrix& memory, std::span<const double> lo, std::span<const double> hi,
                    const HarmonyRates& rates, Draws& u, std::span<double> out) {
    const auto n = static_cast<std::uint64_t>(memory.cols());
    for (std::size_t d = 0; d < out.size(); ++d) {
        if (u.uniform() < rates.hmcr) {
            const auto member = static_cast<Eigen::Index>(u.below(n));
            double v = memory(static_cast<Eigen::Index>(d), member);
            if (u.uniform() < rates.par) v += (2.0 * u.uniform() - 1.0) * rates.bw * (hi[d] - lo[d]);
            out[d] = v;
        } else {
            out[d] = lo[d] + u.uniform() * (hi[d] - lo[d]);
        }
    }
}

/// The integer k such that, for a generator step `bits`, uniform() < p exactly when (bits >> 11)
/// < k: uniform() is (bits >> 11) 2^-53 exactly, so the test is (bits >> 11) < p 2^53 (exact: a
/// power-of-two scaling), and for an integer that is < ceil(p 2^53). p > 1 always holds, p < 0 and
/// NaN never.
inline std::uint64_t unit_threshold(double p) noexcept {
    if (p > 1.0) return std::uint64_t{1} << 53;
    if (!(p >= 0.0)) return 0;
    return static_cast<std::uint64_t>(std::ceil(p * 0x1.0p53));
}

/// improvise_with for the run's Rng, from a local copy (its state then stays in registers) and with
/// the consider and pitch tests on the integer bits (unit_threshold): the same draws, values and
/// operations, but the branches on the coins are decided a conversion and a multiplication
/// earlier, which is what a misprediction (a third of the variables) costs.
inline void improvise_rng(const Matrix& memory, std::span<const double> lo, std::span<const double> hi,
                          const HarmonyRates& rates, Rng& rng, std::span<double> out) {
    const auto n = static_cast<std::uint64_t>(memory.cols());
    const std::uint64_t consider = unit_threshold(rates.hmcr), pitch = unit_threshold(rates.par);
    const double bw = rates.bw;
    const double* member0 = memory.data();
    const auto stride = static_cast<std::size_t>(memory.rows());
    const double *l = lo.data(), *h = hi.data();
    double* y = out.data();
    Rng g = rng;
    for (std::size_t d = 0; d < out.size(); ++d) {
        if ((g() >> 11) < consider) {
            const double v = member0[d + static_cast<std::size_t>(g.below(n)) * stride];
            y[d] = (g() >> 11) < pitch ? v + (2.0 * g.uniform() - 1.0) * bw * (h[d] - l[d]) : v;
        } else {
            y[d] = l[d] + g.uniform() * (h[d] - l[d]);
        }
    }
    rng = g;
}

}  // namespace detail

/// One improvisation (Geem et al. 2001), continuous form: per variable d, with probability HMCR
/// the value of a random memory member (one member drawn per variable), then with probability PAR
/// moved by U(-1, 1) BW (high_d - low_d); otherwise uniform in [low_d, high_d]. Draw order per
/// variable: consider; member (considered) or value (not); pitch; adjustment (pitched).
/// The result may leave the box by the pitch adjustment: the caller applies its Bounds policy.
/// For the run's Rng, detail::improvise_rng: the same draws and values, faster.
template <class Draws>
void improvise(const Matrix& memory, std::span<const double> lo, std::span<const double> hi, const HarmonyRates& rates,
               Draws& u, std::span<double> out) {
    if constexpr (std::is_same_v<Draws, Rng>)
        detail::improvise_rng(memory, lo, hi, rates, u, out);
    else
        detail::improvise_with(memory, lo, hi, rates, u, out);
}

/// The index of the worst value (the first of equals).
inline std::size_t worst(std::span<const double> f) noexcept {
    return static_cast<std::size_t>(std::max_element(f.begin(), f.end()) - f.begin());
}

/// The balance factor's state (eq. 9): balance is the probability of exploring.
struct BalanceState {
    double balance = 0.8;
    std::int64_t count = 0;   // iterations without improvement of the best
    bool exploiting = false;  // after a switch away from the starting balance
};

/// Eq. 9 after an iteration: count counts the iterations without improvement; when count > thr
/// the mode switches (balance <- 1 - balance) and count resets. A switch while exploiting is
/// stagnation: balance and count are reset to their starting values and true is returned (the
/// caller rebuilds the population).
inline bool balance_step(BalanceState& s, bool improved, double start, std::int64_t thr) noexcept {
    s.count = improved ? 0 : s.count + 1;
    if (s.count <= thr) return false;
    s.count = 0;
    if (!s.exploiting) {
        s.balance = 1.0 - s.balance;
        s.exploiting = true;
        return false;
    }
    s.balance = start;
    s.exploiting = false;
    return true;
}

/// The whales kept by the reconstruction (Cai and Du 2021, section 2.2): the best, then binary tournaments
/// among the whales not yet kept until `keep` are kept. `order` (size N) is workspace; the kept
/// indices are its first `keep` entries, the best first.
template <class Draws>
void tournament_keep(std::span<const double> f, std::size_t keep, Draws& u, std::span<std::size_t> order) {
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    const auto best = static_cast<std::size_t>(std::min_element(f.begin(), f.end()) - f.begin());
    std::swap(order[0], order[best]);
    for (std::size_t k = 1; k < keep; ++k) {
        const std::size_t left = order.size() - k;  // candidates order[k..N)
        std::size_t i = k + static_cast<std::size_t>(u.below(left));
        if (left > 1) {
            std::size_t j = k + static_cast<std::size_t>(u.below(left - 1));
            if (j >= i) ++j;  // a second, distinct candidate
            if (f[order[j]] < f[order[i]] || (f[order[j]] == f[order[i]] && order[j] < order[i])) i = j;
        }
        std::swap(order[k], order[i]);
    }
}

}  // namespace pride::whale

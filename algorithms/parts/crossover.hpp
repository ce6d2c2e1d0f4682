#pragma once
// Crossover for real-coded GAs.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <utility>

#include "algorithms/parts/branchless.hpp"
#include "algorithms/parts/power.hpp"
#include "framework/error.hpp"
#include "framework/random.hpp"

namespace pride {

/// Simulated binary crossover, bounded form (Deb and Agrawal 1995, Complex Systems 9:115-148; the
/// bounded spread factor as in Deb's NSGA-II reference code, which pagmo2 also follows). Applied to
/// a pair with probability `probability`; then each coordinate with probability 1/2:
///   beta  = 1 + 2 (y1 - low) / (y2 - y1),  alpha = 2 - beta^-(eta+1)
///   betaq = (u alpha)^(1/(eta+1))            if u <= 1/alpha
///         = (1 / (2 - u alpha))^(1/(eta+1))  otherwise
///   c1 = ((y1 + y2) - betaq (y2 - y1)) / 2, and c2 likewise with beta = 1 + 2 (high - y2)/(y2 - y1),
/// the children's coordinates swapped with probability 1/2. Spec: eta = 15, probability 0.9.
class SbxCrossover {
  public:
    double eta = 15.0;
    double probability = 0.9;

    void validate(const std::string& where) const {
        require(eta >= 0.0 && eta <= 1000.0, where, "eta_c must be in [0, 1000], got " + std::to_string(eta));
        require(probability >= 0.0 && probability <= 1.0, where,
                "pc must be in [0, 1], got " + std::to_string(probability));
    }

    /// The operator with its constants worked out once per run (see Prepared).
    class Prepared;
    Prepared prepare(std::size_t dim) const;

    void operator()(std::span<double> a, std::span<double> b, std::span<const double> lo, std::span<const double> hi,
                    Rng& rng) const;
};

class SbxCrossover::Prepared {
  public:
    Prepared(double eta, double probability) : probability_(probability), power_(eta + 1.0), root_(1.0 / (eta + 1.0)) {}

    void operator()(std::span<double> a, std::span<double> b, std::span<const double> lo, std::span<const double> hi,
                    Rng& rng) const {
        if (rng.bernoulli(probability_)) cross(a, b, lo, hi, rng);
    }

    /// The crossover itself, without the test of `probability` (for policies that decide it
    /// otherwise, as IAGA's adaptive pc: adaptive_rates.hpp).
    void cross(std::span<double> a, std::span<double> b, std::span<const double> lo, std::span<const double> hi,
               Rng& run_rng) const {
        // Drawn from a local copy, put back at the end: its state stays in registers (the same draws
        // in the same order), where the run's would be loaded and stored at every step.
        Rng rng = run_rng;
        // Coordinates go in blocks of 64: one 64-bit draw gives the block's "cross this
        // coordinate?" coins, a second its "swap the children?" coins; the roots of a block are
        // then taken in one pass (see FixedPower::apply).
        double y1[64], y2[64], arg[128];  // arg[k]: first child's, arg[64 + k]: second child's
        std::size_t index[64];
        for (std::size_t start = 0; start < a.size(); start += 64) {
            const std::size_t end = std::min(a.size(), start + 64);
            const std::size_t width = end - start;
            std::uint64_t cross = rng(), swap = rng();
            if (width < 64) cross &= (std::uint64_t{1} << width) - 1;
            std::size_t m = 0;
            // Visiting only the set bits avoids a coin-flip branch per coordinate (half of them
            // would be mispredicted); the coordinates are still taken in increasing order.
            for (; cross != 0; cross &= cross - 1) {
                const std::size_t i = start + static_cast<std::size_t>(std::countr_zero(cross));
                if (std::abs(a[i] - b[i]) <= 1e-14) continue;
                const double lower = std::min(a[i], b[i]), upper = std::max(a[i], b[i]);
                const double inv_gap = 1.0 / (upper - lower);
                const double u = rng.uniform();
                arg[m] = root_argument(u, 1.0 + 2.0 * (lower - lo[i]) * inv_gap);
                arg[64 + m] = root_argument(u, 1.0 + 2.0 * (hi[i] - upper) * inv_gap);
                y1[m] = lower;
                y2[m] = upper;
                index[m++] = i;
            }
            if (m == 0) continue;
            if (m < 64) std::copy_n(arg + 64, m, arg + m);  // both children's arguments side by side
            root_.apply({arg, 2 * m});                      // betaq of each child
            for (std::size_t k = 0; k < m; ++k, swap >>= 1) {
                const std::size_t i = index[k];
                const double c1 = std::clamp(0.5 * ((y1[k] + y2[k]) - arg[k] * (y2[k] - y1[k])), lo[i], hi[i]);
                const double c2 = std::clamp(0.5 * ((y1[k] + y2[k]) + arg[m + k] * (y2[k] - y1[k])), lo[i], hi[i]);
                const bool swapped = (swap & 1u) != 0;  // selects, not a branch: a coin flip mispredicts
                a[i] = detail::select(swapped, c2, c1);
                b[i] = detail::select(swapped, c1, c2);
            }
        }
        run_rng = rng;
    }

  private:
    /// What betaq is the (eta+1)-th root of, for spread factor beta, with one division instead of
    /// three: with B = beta^(eta+1), alpha = 2 - 1/B and t = u (2B - 1) = u alpha B,
    ///   u <= 1/alpha  <=>  t <= B,   u alpha = t / B,   1 / (2 - u alpha) = B / (2B - t).
    double root_argument(double u, double beta) const noexcept {
        const double big = power_(beta);
        if (!(big < 1e300)) return u <= 0.5 ? 2.0 * u : 1.0 / (2.0 - 2.0 * u);  // beta^-(eta+1) = 0: alpha = 2
        const double t = u * (2.0 * big - 1.0);
        const bool near = t <= big;  // selects, then one division: the test is a coin flip
        return detail::select(near, t, big) / detail::select(near, big, 2.0 * big - t);
    }

    double probability_;
    FixedPower power_;
    FixedPower root_;
};

inline SbxCrossover::Prepared SbxCrossover::prepare(std::size_t) const {
    return Prepared(eta, probability);
}

inline void SbxCrossover::operator()(std::span<double> a, std::span<double> b, std::span<const double> lo,
                                     std::span<const double> hi, Rng& rng) const {
    prepare(a.size())(a, b, lo, hi, rng);
}

}  // namespace pride

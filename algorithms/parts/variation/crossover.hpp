#pragma once
// Crossover for real-coded GAs.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <utility>

#include "algorithms/parts/common/branchless.hpp"
#include "algorithms/parts/common/power.hpp"
#include "framework/error.hpp"
#include "framework/random.hpp"

namespace pride {

namespace detail {
/// SBX's root argument when beta^(eta+1) is beyond 1e300 (or NaN): beta^-(eta+1) = 0, alpha = 2.
inline double sbx_overflow_argument(double u) noexcept {
    return u <= 0.5 ? 2.0 * u : 1.0 / (2.0 - 2.0 * u);
}

#ifdef PRIDE_ROOTS_AVX
/// root_argument for four lanes: beta^(eta+1) by `squarings` squarings, then the selects and
/// the division; lanes whose power is not below 1e300 (or NaN) redone by sbx_overflow_argument.
[[gnu::target("avx"), gnu::always_inline]] inline void sbx_argument4(__m256d u, __m256d beta, int squarings,
                                                                     double* out, const double* us) noexcept {
    const __m256d one = _mm256_set1_pd(1.0), two = _mm256_set1_pd(2.0);
    __m256d big = beta;
    for (int s = 0; s < squarings; ++s) big = _mm256_mul_pd(big, big);
    const __m256d twice = _mm256_mul_pd(two, big);
    const __m256d t = _mm256_mul_pd(u, _mm256_sub_pd(twice, one));
    const __m256d near = _mm256_cmp_pd(t, big, _CMP_LE_OQ);
    // near ? t : big and near ? big : 2B - t, as masks (GCC lowers AVX's blendv to scalar code
    // without AVX2's integer compares).
    const __m256d num = _mm256_or_pd(_mm256_and_pd(near, t), _mm256_andnot_pd(near, big));
    const __m256d den = _mm256_or_pd(_mm256_and_pd(near, big), _mm256_andnot_pd(near, _mm256_sub_pd(twice, t)));
    _mm256_storeu_pd(out, _mm256_div_pd(num, den));
    const int fine = _mm256_movemask_pd(_mm256_cmp_pd(big, _mm256_set1_pd(1e300), _CMP_LT_OQ));  // false for NaN
    if (fine != 0xF) [[unlikely]]
        for (int lane = 0; lane < 4; ++lane)
            if (!(fine >> lane & 1)) out[lane] = sbx_overflow_argument(us[lane]);
}

/// SbxCrossover's root arguments (its root_argument, for both children) four coordinates at a
/// time, with beta^(eta+1) as `squarings` squarings; returns how many coordinates it did (m rounded
/// down to a multiple of 4; the caller does the rest). Each lane does root_argument's operations
/// in its order (no fused multiply-add: the target is AVX alone), so the bits are the scalar ones;
/// lanes whose power is not below 1e300 are redone by sbx_overflow_argument.
[[gnu::target("avx")]] inline std::size_t sbx_arguments_avx(std::size_t m, const double* y1, const double* y2,
                                                            const double* low, const double* high, const double* u,
                                                            int squarings, double* arg) noexcept {
    const __m256d one = _mm256_set1_pd(1.0), two = _mm256_set1_pd(2.0);
    std::size_t k = 0;
    for (; k + 4 <= m; k += 4) {
        const __m256d lower = _mm256_loadu_pd(y1 + k), upper = _mm256_loadu_pd(y2 + k);
        const __m256d inv_gap = _mm256_div_pd(one, _mm256_sub_pd(upper, lower));
        const __m256d uu = _mm256_loadu_pd(u + k);
        // 1 + 2 (y1 - low) / gap and 1 + 2 (high - y2) / gap, as ((2 d) inv_gap) + 1
        const __m256d b1 = _mm256_add_pd(
            one, _mm256_mul_pd(_mm256_mul_pd(two, _mm256_sub_pd(lower, _mm256_loadu_pd(low + k))), inv_gap));
        const __m256d b2 = _mm256_add_pd(
            one, _mm256_mul_pd(_mm256_mul_pd(two, _mm256_sub_pd(_mm256_loadu_pd(high + k), upper)), inv_gap));
        sbx_argument4(uu, b1, squarings, arg + k, u + k);
        sbx_argument4(uu, b2, squarings, arg + m + k, u + k);
    }
    return k;
}

/// SBX's children from the roots: arg[k] becomes the first child's coordinate
/// clamp(((y1 + y2) - betaq (y2 - y1)) / 2, low, high), arg[m + k] the second's (+ betaq), four
/// coordinates at a time; returns how many it did (the caller does the rest). std::clamp is
/// min(max(v, low), high) with std::max(v, low) = v < low ? low : v, which is vmaxpd(low, v), and
/// std::min(w, high) = high < w ? high : w, which is vminpd(high, w): the same bits, NaN included.
[[gnu::target("avx")]] inline std::size_t sbx_children_avx(std::size_t m, const double* y1, const double* y2,
                                                           const double* low, const double* high,
                                                           double* arg) noexcept {
    const __m256d half = _mm256_set1_pd(0.5);
    std::size_t k = 0;
    for (; k + 4 <= m; k += 4) {
        const __m256d lower = _mm256_loadu_pd(y1 + k), upper = _mm256_loadu_pd(y2 + k);
        const __m256d sum = _mm256_add_pd(lower, upper), gap = _mm256_sub_pd(upper, lower);
        const __m256d l = _mm256_loadu_pd(low + k), h = _mm256_loadu_pd(high + k);
        const __m256d c1 = _mm256_mul_pd(half, _mm256_sub_pd(sum, _mm256_mul_pd(_mm256_loadu_pd(arg + k), gap)));
        const __m256d c2 = _mm256_mul_pd(half, _mm256_add_pd(sum, _mm256_mul_pd(_mm256_loadu_pd(arg + m + k), gap)));
        _mm256_storeu_pd(arg + k, _mm256_min_pd(h, _mm256_max_pd(l, c1)));
        _mm256_storeu_pd(arg + m + k, _mm256_min_pd(h, _mm256_max_pd(l, c2)));
    }
    return k;
}
#endif
}  // namespace detail

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
        // coordinate?" coins, a second its "swap the children?" coins. A block's crossed
        // coordinates are gathered first (with their draws, in increasing order), their roots'
        // arguments then worked out in one vector pass (sbx_arguments) and their roots in another
        // (FixedPower::apply).
        double y1[64], y2[64], low[64], high[64], u[64], arg[128];  // arg[k], arg[m + k]: the children's
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
                y1[m] = std::min(a[i], b[i]);
                y2[m] = std::max(a[i], b[i]);
                low[m] = lo[i];
                high[m] = hi[i];
                u[m] = rng.uniform();
                index[m++] = i;
            }
            if (m == 0) continue;
            arguments(m, y1, y2, low, high, u, arg);
            root_.apply({arg, 2 * m});  // betaq of each child
            children(m, y1, y2, low, high, arg);
            for (std::size_t k = 0; k < m; ++k, swap >>= 1) {
                const std::size_t i = index[k];
                const bool swapped = (swap & 1u) != 0;  // selects, not a branch: a coin flip mispredicts
                a[i] = detail::select(swapped, arg[m + k], arg[k]);
                b[i] = detail::select(swapped, arg[k], arg[m + k]);
            }
        }
        run_rng = rng;
    }

  private:
    /// The roots' arguments of m crossed coordinates: arg[k] for the first child (spread factor
    /// beta = 1 + 2 (y1 - low) / (y2 - y1)), arg[m + k] for the second (1 + 2 (high - y2) / (y2 - y1)).
    /// Four coordinates per instruction where the processor has AVX and beta^(eta+1) is repeated
    /// squaring (eta + 1 a power of two, as the project's 15); the same operations in the same order
    /// as the scalar form, so the same bits.
    void arguments(std::size_t m, const double* y1, const double* y2, const double* low, const double* high,
                   const double* u, double* arg) const noexcept {
        std::size_t k = 0;
#ifdef PRIDE_ROOTS_AVX
        if (const int squarings = power_.squarings(); squarings >= 0 && detail::roots_avx_supported())
            k = detail::sbx_arguments_avx(m, y1, y2, low, high, u, squarings, arg);
#endif
        for (; k < m; ++k) {
            const double inv_gap = 1.0 / (y2[k] - y1[k]);
            arg[k] = root_argument(u[k], 1.0 + 2.0 * (y1[k] - low[k]) * inv_gap);
            arg[m + k] = root_argument(u[k], 1.0 + 2.0 * (high[k] - y2[k]) * inv_gap);
        }
    }

    /// The children's coordinates from their roots betaq (in arg, as arguments() placed them):
    ///   c1 = clamp(((y1 + y2) - betaq1 (y2 - y1)) / 2), c2 = clamp(((y1 + y2) + betaq2 (y2 - y1)) / 2).
    static void children(std::size_t m, const double* y1, const double* y2, const double* low, const double* high,
                         double* arg) noexcept {
        std::size_t k = 0;
#ifdef PRIDE_ROOTS_AVX
        if (detail::roots_avx_supported()) k = detail::sbx_children_avx(m, y1, y2, low, high, arg);
#endif
        for (; k < m; ++k) {
            arg[k] = std::clamp(0.5 * ((y1[k] + y2[k]) - arg[k] * (y2[k] - y1[k])), low[k], high[k]);
            arg[m + k] = std::clamp(0.5 * ((y1[k] + y2[k]) + arg[m + k] * (y2[k] - y1[k])), low[k], high[k]);
        }
    }

    /// What betaq is the (eta+1)-th root of, for spread factor beta, with one division instead of
    /// three: with B = beta^(eta+1), alpha = 2 - 1/B and t = u (2B - 1) = u alpha B,
    ///   u <= 1/alpha  <=>  t <= B,   u alpha = t / B,   1 / (2 - u alpha) = B / (2B - t).
    double root_argument(double u, double beta) const noexcept {
        const double big = power_(beta);
        if (!(big < 1e300)) return detail::sbx_overflow_argument(u);  // beta^-(eta+1) = 0: alpha = 2
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

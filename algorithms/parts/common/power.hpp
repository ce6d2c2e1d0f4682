#pragma once
// x^e for a fixed exponent e, computed many times. The operators of Deb's real-coded GA raise to
// 1/(eta+1) and eta+1, and std::pow costs tens of nanoseconds; for the usual integer eta these are
// integer powers (repeated squaring, rounded at each multiply: within a few ulps of std::pow) or,
// when eta+1 is a power of two, repeated square roots (each correctly rounded). Other exponents
// fall back to std::pow. The result depends only on (x, e), so runs stay bit-reproducible.
#include <Eigen/Core>
#include <bit>
#include <cmath>
#include <cstddef>
#include <span>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define PRIDE_ROOTS_AVX 1
#endif

namespace pride {

#ifdef PRIDE_ROOTS_AVX
namespace detail {
/// `times` square roots of each of v[0..n), four lanes per instruction: the build targets
/// baseline x86-64 (two lanes), and the GA's roots are bound by the square-root unit's throughput,
/// which AVX doubles. Square roots are correctly rounded, so the bits are those of the two-lane
/// and of the scalar form. Called only where the processor has AVX (roots_avx_supported).
[[gnu::target("avx")]] inline void roots_avx(double* v, std::size_t n, int times) noexcept {
    const std::size_t wide = n - n % 4;
    for (int k = 0; k < times; ++k) {
        for (std::size_t i = 0; i < wide; i += 4) _mm256_storeu_pd(v + i, _mm256_sqrt_pd(_mm256_loadu_pd(v + i)));
        for (std::size_t i = wide; i < n; ++i) _mm_store_sd(v + i, _mm_sqrt_sd(_mm_setzero_pd(), _mm_load_sd(v + i)));
    }
}
inline bool roots_avx_supported() noexcept {
    // __builtin_cpu_init first: the test may run before libgcc's own initialiser (static set-up).
    static const bool yes = (__builtin_cpu_init(), __builtin_cpu_supports("avx") != 0);
    return yes;
}
}  // namespace detail
#endif

class FixedPower {
  public:
    explicit FixedPower(double exponent) : e_(exponent) {
        if (exponent == std::floor(exponent) && std::abs(exponent) <= 64.0) {
            kind_ = Kind::integer;
            n_ = static_cast<int>(std::abs(exponent));
            negative_ = exponent < 0;
            // n = 2^k: the squaring loop's result is 1 * x^(2^k) (one multiplication by 1, exact),
            // so k squarings give the same bits without the loop's tests (SBX's eta 15: x^16).
            if (n_ >= 1 && (n_ & (n_ - 1)) == 0) {
                kind_ = Kind::squares;
                squares_ = std::countr_zero(static_cast<unsigned>(n_));
            }
        } else {
            const double inv = 1.0 / exponent;
            for (int k = 1; k <= 6; ++k)
                if (inv == static_cast<double>(1 << k)) {
                    kind_ = Kind::roots;
                    n_ = k;
                }
        }
    }

    double operator()(double x) const noexcept {
        switch (kind_) {
            case Kind::integer: {
                double result = 1.0, base = x;
                for (int n = n_; n > 0; n >>= 1) {
                    if (n & 1) result *= base;
                    base *= base;
                }
                return negative_ ? 1.0 / result : result;
            }
            case Kind::squares:
                for (int k = 0; k < squares_; ++k) x *= x;
                return negative_ ? 1.0 / x : x;
            case Kind::roots:
                for (int k = 0; k < n_; ++k) x = std::sqrt(x);
                return x;
            default:
                return std::pow(x, e_);
        }
    }

    /// k when the power is x^(2^k) by k squarings (SBX's eta 15: 4), else -1: for callers that
    /// work out such powers in their own vector loop (SbxCrossover), with the same bits.
    int squarings() const noexcept { return kind_ == Kind::squares && !negative_ ? squares_ : -1; }

    /// Raises every element of `values` in place. Repeated square roots run over the whole array
    /// at once (four lanes per instruction where the processor has AVX, else Eigen's packet sqrt:
    /// two lanes), which is where the real-coded GA spends most of its own time.
    void apply(std::span<double> values) const noexcept {
        if (kind_ == Kind::roots) {
#ifdef PRIDE_ROOTS_AVX
            if (detail::roots_avx_supported()) return detail::roots_avx(values.data(), values.size(), n_);
#endif
            Eigen::Map<Eigen::ArrayXd> a(values.data(), static_cast<Eigen::Index>(values.size()));
            for (int k = 0; k < n_; ++k) a = a.sqrt();
        } else {
            for (double& v : values) v = (*this)(v);
        }
    }

  private:
    enum class Kind { integer, squares, roots, general };
    double e_;
    Kind kind_ = Kind::general;
    int n_ = 0;
    int squares_ = 0;  // Kind::squares: n = 2^squares_
    bool negative_ = false;
};

}  // namespace pride

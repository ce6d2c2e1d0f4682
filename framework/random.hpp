#pragma once
// Seeded random streams. There is no global generator: every run owns an Rng made from
// (master seed, stream index), so a run is reproducible from its seed alone, bit for bit, whatever
// else runs beside it. The generator is xoshiro256++ (Blackman and Vigna 2019) seeded through
// splitmix64; the variates are computed here rather than with <random>'s distributions, whose
// results differ between standard libraries.
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>

namespace pride {

/// splitmix64 step (Steele, Lea and Flood 2014): a bijective mixer used to expand seeds.
constexpr std::uint64_t splitmix64(std::uint64_t& state) noexcept {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

__extension__ typedef unsigned __int128 uint128;  // GCC/Clang built-in, for Lemire's method

class Rng {
  public:
    using result_type = std::uint64_t;

    /// One generator for one (master seed, stream) pair. Different pairs give streams whose
    /// 256-bit starting states are hashed apart by splitmix64; stream 0 is the run's own stream.
    explicit Rng(std::uint64_t seed, std::uint64_t stream = 0) noexcept {
        std::uint64_t sm = seed;
        std::uint64_t mixed = splitmix64(sm) ^ (stream * 0xD1B54A32D192ED03ULL + 0x8CB92BA72F3D8DD7ULL);
        for (auto& word : s_) word = splitmix64(mixed);
    }

    static constexpr result_type min() noexcept { return 0; }
    static constexpr result_type max() noexcept { return std::numeric_limits<result_type>::max(); }

    // The steps are always inlined (so is below): a loop drawing from a local copy of the generator
    // then keeps its state in registers; GCC at -O2 otherwise leaves some calls, which force it
    // into memory.
    [[gnu::always_inline]] result_type operator()() noexcept { return step(s_[0], s_[1], s_[2], s_[3]); }

    /// U[0, 1) with 53 random bits.
    [[gnu::always_inline]] double uniform() noexcept { return to_unit((*this)()); }

    /// Fills `out` with U[0, 1) draws: the same numbers, in the same order, as out.size() calls
    /// of uniform(), but with the state held in registers, so hot loops can draw in bulk first
    /// and then run vectorisable arithmetic.
    void fill_uniform(std::span<double> out) noexcept {
        std::uint64_t a = s_[0], b = s_[1], c = s_[2], d = s_[3];
        for (double& v : out) v = to_unit(step(a, b, c, d));
        s_[0] = a;
        s_[1] = b;
        s_[2] = c;
        s_[3] = d;
    }

    /// U[a, b); b itself only through rounding, when |a| is much larger than b - a.
    double uniform(double a, double b) noexcept { return a + (b - a) * uniform(); }

    /// Uniform integer in [0, n), unbiased (Lemire 2019), n > 0.
    [[gnu::always_inline]] std::uint64_t below(std::uint64_t n) noexcept {
        uint128 m = static_cast<uint128>((*this)()) * n;
        auto low = static_cast<std::uint64_t>(m);
        if (low < n) [[unlikely]] {  // rare for small n: the fast path stays small enough to inline
            const std::uint64_t threshold = (0 - n) % n;
            while (low < threshold) {
                m = static_cast<uint128>((*this)()) * n;
                low = static_cast<std::uint64_t>(m);
            }
        }
        return static_cast<std::uint64_t>(m >> 64);
    }

    bool bernoulli(double p) noexcept { return uniform() < p; }

    /// N(0, 1) by Marsaglia's polar method; the second variate of each pair is kept for the next
    /// call, so the sequence depends only on the seed.
    double normal() noexcept {
        if (has_spare_) {
            has_spare_ = false;
            return spare_;
        }
        double u, v, s;
        do {
            u = 2.0 * uniform() - 1.0;
            v = 2.0 * uniform() - 1.0;
            s = u * u + v * v;
        } while (s >= 1.0 || s == 0.0);
        const double factor = std::sqrt(-2.0 * std::log(s) / s);
        spare_ = v * factor;
        has_spare_ = true;
        return u * factor;
    }

    /// U[0, 1) with 32 bits: from the high and from the low half of one step's bits (the pair
    /// fill_uniform_pairs makes; for loops that draw the step themselves, as PSO's).
    [[gnu::always_inline]] static double high_unit(std::uint64_t bits) noexcept {
        return static_cast<double>(static_cast<std::int64_t>(bits >> 32)) * 0x1.0p-32;
    }
    [[gnu::always_inline]] static double low_unit(std::uint64_t bits) noexcept {
        return static_cast<double>(static_cast<std::int64_t>(bits & 0xFFFFFFFFu)) * 0x1.0p-32;
    }

    /// Fills `a` and `b` (same size) with U[0, 1) draws of 32 random bits each, a[i] from the high
    /// and b[i] from the low half of one generator step: half the cost of two uniform() calls,
    /// for random weights where a resolution of 2^-32 is plenty (PSO's r1, r2).
    void fill_uniform_pairs(std::span<double> a, std::span<double> b) noexcept {
        std::uint64_t s0 = s_[0], s1 = s_[1], s2 = s_[2], s3 = s_[3];
        for (std::size_t i = 0; i < a.size(); ++i) {
            const std::uint64_t bits = step(s0, s1, s2, s3);
            a[i] = high_unit(bits);
            b[i] = low_unit(bits);
        }
        s_[0] = s0;
        s_[1] = s1;
        s_[2] = s2;
        s_[3] = s3;
    }

  private:
    // Through int64: the value fits, and a signed conversion is one instruction.
    [[gnu::always_inline]] static double to_unit(std::uint64_t bits) noexcept {
        return static_cast<double>(static_cast<std::int64_t>(bits >> 11)) * 0x1.0p-53;
    }

    /// One xoshiro256++ step on the state words given.
    [[gnu::always_inline]] static std::uint64_t step(std::uint64_t& s0, std::uint64_t& s1, std::uint64_t& s2,
                                                     std::uint64_t& s3) noexcept {
        const std::uint64_t result = std::rotl(s0 + s3, 23) + s0;
        const std::uint64_t t = s1 << 17;
        s2 ^= s0;
        s3 ^= s1;
        s1 ^= s2;
        s0 ^= s3;
        s2 ^= t;
        s3 = std::rotl(s3, 45);
        return result;
    }

    std::uint64_t s_[4]{};
    double spare_ = 0.0;
    bool has_spare_ = false;
};

}  // namespace pride

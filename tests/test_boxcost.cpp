// The framework's cost per evaluation: the faster forms of PSO's move, harmony search's
// improvisation (and its integer coin tests), SBX's selects and vector passes and FixedPower's
// powers of two give the same bits as the plain forms they replace.
#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <tuple>
#include <utility>
#include <vector>

#include "algorithms/parts/common/power.hpp"
#include "algorithms/parts/variation/crossover.hpp"
#include "algorithms/parts/whale/moves.hpp"
#include "algorithms/pso.hpp"
#include "framework/bounds.hpp"
#include "framework/random.hpp"

namespace {

bool same_bits(double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (!same_bits(a[i], b[i])) return false;
    return true;
}

/// FixedPower's integer loop as it was before the squares form (repeated squaring).
double squaring_loop(double x, int n, bool negative) {
    double result = 1.0, base = x;
    for (; n > 0; n >>= 1) {
        if (n & 1) result *= base;
        base *= base;
    }
    return negative ? 1.0 / result : result;
}

/// Eqs. (1)-(3) of pso.hpp on one coordinate, as the scalar loop computes them, then Clamp.
void move_scalar(std::uint64_t bits, double a, double b1, double b2, double& x, double& v, double p, double g,
                 double vmax, double lo, double hi) {
    const double r1 = static_cast<double>(static_cast<std::int64_t>(bits >> 32)) * 0x1.0p-32;
    const double r2 = static_cast<double>(static_cast<std::int64_t>(bits & 0xFFFFFFFFu)) * 0x1.0p-32;
    const double vd = a * v + b1 * r1 * (p - x) + b2 * r2 * (g - x);
    v = std::max(-vmax, std::min(vd, vmax));
    x += v;
    x = std::max(lo, std::min(x, hi));
}

/// Forwards to an Rng held by reference: improvise takes its generic path (no local copy).
struct Forward {
    pride::Rng* rng;
    double uniform() { return rng->uniform(); }
    std::uint64_t below(std::uint64_t n) { return rng->below(n); }
};

}  // namespace

TEST_CASE("FixedPower: powers of two by squarings give the squaring loop's bits", "[operators][boxcost]") {
    const double inf = std::numeric_limits<double>::infinity();
    std::vector<double> xs{0.0,
                           -0.0,
                           1.0,
                           -1.0,
                           2.0,
                           0.5,
                           1e-300,
                           -1e-300,
                           1e300,
                           4.9e-324,
                           inf,
                           -inf,
                           std::numeric_limits<double>::quiet_NaN()};
    pride::Rng rng(11);
    for (int k = 0; k < 2000; ++k) xs.push_back(rng.uniform(-3.0, 3.0));
    for (const int n : {1, 2, 4, 8, 16, 32, 64}) {
        for (const bool negative : {false, true}) {
            const pride::FixedPower power(negative ? -n : n);
            for (const double x : xs) {
                INFO("x = " << x << ", exponent " << (negative ? -n : n));
                CHECK(same_bits(power(x), squaring_loop(x, n, negative)));
            }
        }
    }
}

TEST_CASE("FixedPower: the roots of apply (four lanes where AVX is) give the scalar roots' bits",
          "[operators][boxcost]") {
    const double inf = std::numeric_limits<double>::infinity();
    std::vector<double> specials{
        0.0, -0.0, 1.0, 4.9e-324, 2.2e-308, 1e-300, 1e300, inf, -1.0, -inf, std::numeric_limits<double>::quiet_NaN()};
    pride::Rng rng(13);
    for (const int k : {1, 2, 4, 6}) {
        const pride::FixedPower root(1.0 / static_cast<double>(1 << k));
        // Every length from 0 to 70 (the AVX loop's tail of 0-3 lanes), specials at varying places.
        for (std::size_t n = 0; n <= 70; ++n) {
            std::vector<double> v(n);
            for (std::size_t i = 0; i < n; ++i)
                v[i] = i % 7 == 3 ? specials[(i + n) % specials.size()] : rng.uniform(0.0, 1e6);
            std::vector<double> expected(n);
            for (std::size_t i = 0; i < n; ++i) expected[i] = root(v[i]);  // k calls of std::sqrt
            root.apply(std::span<double>(v));
            INFO("1/2^" << k << ", n = " << n);
            REQUIRE(same_bits(v, expected));
        }
    }
}

namespace {

/// SBX as it was written before its vector passes: coordinate by coordinate, in increasing order
/// (SbxCrossover::Prepared::cross, without the test of its probability).
void sbx_by_coordinate(double eta, std::vector<double>& a, std::vector<double>& b, const std::vector<double>& lo,
                       const std::vector<double>& hi, pride::Rng& rng) {
    const pride::FixedPower power(eta + 1.0), root(1.0 / (eta + 1.0));
    const auto argument = [&](double u, double beta) {
        const double big = power(beta);
        if (!(big < 1e300)) return u <= 0.5 ? 2.0 * u : 1.0 / (2.0 - 2.0 * u);
        const double t = u * (2.0 * big - 1.0);
        return t <= big ? t / big : big / (2.0 * big - t);
    };
    for (std::size_t start = 0; start < a.size(); start += 64) {
        const std::size_t width = std::min<std::size_t>(64, a.size() - start);
        std::uint64_t cross = rng(), swap = rng();
        for (std::size_t j = 0; j < width; ++j) {
            if (!(cross >> j & 1)) continue;
            const std::size_t i = start + j;
            if (std::abs(a[i] - b[i]) <= 1e-14) continue;
            const double y1 = std::min(a[i], b[i]), y2 = std::max(a[i], b[i]);
            const double inv_gap = 1.0 / (y2 - y1);
            const double u = rng.uniform();
            const double q1 = root(argument(u, 1.0 + 2.0 * (y1 - lo[i]) * inv_gap));
            const double q2 = root(argument(u, 1.0 + 2.0 * (hi[i] - y2) * inv_gap));
            const double c1 = std::clamp(0.5 * ((y1 + y2) - q1 * (y2 - y1)), lo[i], hi[i]);
            const double c2 = std::clamp(0.5 * ((y1 + y2) + q2 * (y2 - y1)), lo[i], hi[i]);
            const bool swapped = (swap & 1u) != 0;  // one swap coin per crossed coordinate
            swap >>= 1;
            a[i] = swapped ? c2 : c1;
            b[i] = swapped ? c1 : c2;
        }
    }
}

}  // namespace

TEST_CASE("SBX: the vector passes (four lanes where AVX is) give the bits of coordinate by coordinate",
          "[operators][sbx][boxcost]") {
    // eta 15, 1 and 0: beta^(eta+1) by squarings (the vector form); 3: an integer power (x^4 is
    // squarings too), 2.5: std::pow. Lengths 1-70 cover the lanes' tails and a second block of 64;
    // some coordinates are equal or nearly equal (not crossed), some pairs are so close near a
    // face that beta^(eta+1) passes 1e300 (the overflow form), some parents sit on a face.
    for (const double eta : {15.0, 1.0, 0.0, 3.0, 2.5}) {
        pride::SbxCrossover::Prepared sbx = pride::SbxCrossover{eta, 1.0}.prepare(0);
        pride::Rng data(11);
        for (std::size_t n = 1; n <= 70; ++n) {
            std::vector<double> lo(n), hi(n), a(n), b(n);
            for (std::size_t i = 0; i < n; ++i) {
                lo[i] = data.uniform(-1e6, 0.0);
                hi[i] = lo[i] + data.uniform(1.0, 2e6);
                a[i] = data.uniform(lo[i], hi[i]);
                b[i] = data.uniform(lo[i], hi[i]);
                switch (i % 9) {
                    case 2:  // equal
                        b[i] = a[i];
                        break;
                    case 4:  // within 1e-14
                        b[i] = a[i] + 5e-15;
                        break;
                    case 5:  // 2e-13 apart, far above lo: beta 1e19 or 1e21, beta^16 beyond 1e300 or inf
                        lo[i] = n % 2 ? -1e6 : -1e8, hi[i] = 1.0, a[i] = 0.5, b[i] = 0.5 + 2e-13;
                        break;
                    case 7:  // on a face
                        a[i] = lo[i];
                        break;
                    default:
                        break;
                }
                b[i] = std::clamp(b[i], lo[i], hi[i]);
            }
            for (int call = 0; call < 20; ++call) {
                auto av = a, bv = b, as = a, bs = b;
                pride::Rng vector(100 + call), scalar(100 + call);
                sbx.cross(av, bv, lo, hi, vector);
                sbx_by_coordinate(eta, as, bs, lo, hi, scalar);
                INFO("eta " << eta << ", n " << n << ", call " << call);
                REQUIRE(same_bits(av, as));
                REQUIRE(same_bits(bv, bs));
                REQUIRE(vector() == scalar());  // the same number of draws
            }
        }
    }
}

TEST_CASE("PSO's two-lane move equals the scalar loop bit for bit", "[pso][boxcost]") {
    pride::Rng data(5);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (const std::size_t dim : {1u, 2u, 3u, 8u, 30u, 31u}) {
        std::vector<double> x(dim), v(dim), p(dim), g(dim), vmax(dim), lo(dim), hi(dim);
        for (std::size_t d = 0; d < dim; ++d) {
            lo[d] = data.uniform(-10.0, 0.0);
            hi[d] = lo[d] + data.uniform(0.5, 20.0);
            vmax[d] = 0.2 * (hi[d] - lo[d]);
            x[d] = data.uniform(lo[d] - 1.0, hi[d] + 1.0);  // some outside the box
            v[d] = data.uniform(-2.0 * vmax[d], 2.0 * vmax[d]);
            p[d] = data.uniform(lo[d], hi[d]);
            g[d] = data.uniform(lo[d], hi[d]);
        }
        if (dim > 2) x[1] = nan, p[2] = nan;  // NaN goes where the scalar min and max send it
        for (const auto& [a, b1, b2] : {std::tuple{0.9, 2.0, 2.0}, std::tuple{0.7298, 0.7298 * 2.05, 0.7298 * 2.05}}) {
            auto xs = x, vs = v, xv = x, vv = v;
            pride::Rng scalar(42), vector(42);
            for (std::size_t d = 0; d < dim; ++d)
                move_scalar(scalar(), a, b1, b2, xs[d], vs[d], p[d], g[d], vmax[d], lo[d], hi[d]);
            const std::size_t moved = pride::detail::move_pairs<true>(vector, a, b1, b2, xv.data(), vv.data(), p.data(),
                                                                      g.data(), vmax.data(), lo.data(), hi.data(), dim);
            CHECK(moved <= dim);
            for (std::size_t d = moved; d < dim; ++d)
                move_scalar(vector(), a, b1, b2, xv[d], vv[d], p[d], g[d], vmax[d], lo[d], hi[d]);
            INFO("dim " << dim << ", a " << a);
            CHECK(same_bits(xs, xv));
            CHECK(same_bits(vs, vv));
            CHECK(scalar() == vector());  // the same number of steps
        }
    }
}

TEST_CASE("harmony search: the improvisation from a local copy draws as from the run's Rng", "[hs][boxcost]") {
    // The Rng path (detail::improvise_rng: integer coin tests) against the generic path through a
    // forwarding draw source, for the rates of hs and hswoa and the edge rates 0 and 1, several
    // memory sizes and dimensions.
    const std::vector<pride::whale::HarmonyRates> all_rates{{0.9, 0.3, 0.01}, {0.8, 0.3, 0.01}, {1.0, 1.0, 0.5},
                                                            {0.0, 0.3, 0.01}, {1.0, 0.0, 0.01}, {0.5, 0.5, 1.0}};
    for (const auto& rates : all_rates)
        for (const auto& [dim, members] : {std::pair{7, 30}, std::pair{30, 50}, std::pair{1, 1}, std::pair{31, 2}}) {
            pride::Rng data(3);
            pride::Matrix memory(dim, members);
            for (Eigen::Index i = 0; i < memory.size(); ++i) memory.data()[i] = data.uniform(-5.0, 5.0);
            std::vector<double> lo(static_cast<std::size_t>(dim)), hi(lo.size());
            for (std::size_t d = 0; d < lo.size(); ++d) {
                lo[d] = -5.0 - static_cast<double>(d);
                hi[d] = 5.0 + 0.5 * static_cast<double>(d);
            }
            pride::Rng direct(9), forwarded(9);
            Forward f{&forwarded};
            std::vector<double> a(lo.size()), b(lo.size());
            for (int k = 0; k < 200; ++k) {
                pride::whale::improvise(memory, lo, hi, rates, direct, std::span<double>(a));
                pride::whale::improvise(memory, lo, hi, rates, f, std::span<double>(b));
                REQUIRE(same_bits(a, b));
            }
            CHECK(direct() == forwarded());  // the run's generator is left where the draws ended
        }
}

TEST_CASE("harmony search: the integer coin test decides as uniform() < p", "[hs][boxcost]") {
    const double tiny = std::numeric_limits<double>::denorm_min(), inf = std::numeric_limits<double>::infinity();
    const std::vector<double> ps{0.0,
                                 tiny,
                                 0x1.0p-53,
                                 0x1.8p-53,
                                 0.3,
                                 0.5,
                                 std::nextafter(0.5, 1.0),
                                 0.8,
                                 0.9,
                                 std::nextafter(1.0, 0.0),
                                 1.0,
                                 1.5,
                                 inf,
                                 -0.3,
                                 -inf,
                                 std::numeric_limits<double>::quiet_NaN()};
    pride::Rng rng(5);
    for (const double p : ps) {
        const std::uint64_t t = pride::whale::detail::unit_threshold(p);
        // The steps whose 53 bits are next to the threshold, the extremes, and random ones.
        std::vector<std::uint64_t> ks{0, 1, (std::uint64_t{1} << 53) - 1};
        for (std::uint64_t dk = 0; dk < 3; ++dk)
            for (const std::uint64_t k : {t - 1 + dk, t + dk - 2})
                if (k < (std::uint64_t{1} << 53)) ks.push_back(k);
        for (int r = 0; r < 1000; ++r) ks.push_back(rng() >> 11);
        for (const std::uint64_t k : ks)
            for (const std::uint64_t low : {std::uint64_t{0}, std::uint64_t{0x7FF}}) {
                const std::uint64_t bits = (k << 11) | low;
                const double u = static_cast<double>(static_cast<std::int64_t>(bits >> 11)) * 0x1.0p-53;  // uniform()
                INFO("p = " << p << ", k = " << k);
                REQUIRE(((bits >> 11) < t) == (u < p));
            }
    }
}

// Tests of the framework's generic parts: random streams, stopping rules, bound handling, the run
// driver (evaluation guard, history, observer), encodings, parameters and registries.
#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <set>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "framework/bounds.hpp"
#include "framework/encoding.hpp"
#include "framework/error.hpp"
#include "framework/error_place.hpp"
#include "framework/initializer.hpp"
#include "framework/observer.hpp"
#include "framework/problem.hpp"
#include "framework/random.hpp"
#include "framework/registry.hpp"
#include "framework/result.hpp"
#include "framework/run_state.hpp"
#include "framework/termination.hpp"
#include "problems/continuous/functions.hpp"
#include "problems/continuous/transformed.hpp"
#include "tests/test_support.hpp"

using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;
using pride::test::input_error_message;

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();
constexpr double nan_ = std::numeric_limits<double>::quiet_NaN();

/// A 2-D box problem in [-1, 1]^2 whose objective is not always finite: x0 > 0.5 gives NaN,
/// x0 < -0.5 gives +inf when x1 > 0 and -inf otherwise; elsewhere the sum of squares. Counts its
/// evaluations.
struct WildProblem {
    std::vector<double> lo{-1.0, -1.0};
    std::vector<double> hi{1.0, 1.0};
    int calls = 0;
    std::size_t dimension() const { return 2; }
    std::span<const double> lower() const { return lo; }
    std::span<const double> upper() const { return hi; }
    double evaluate(std::span<const double> x) {
        ++calls;
        if (x[0] > 0.5) return nan_;
        if (x[0] < -0.5) return x[1] > 0 ? inf : -inf;
        return x[0] * x[0] + x[1] * x[1];
    }
};

/// The same objective with a batch evaluation, to exercise RunState's batch path.
struct WildBatchProblem : WildProblem {
    int batch_calls = 0;
    Eigen::Index batch_columns = 0;
    void evaluate_batch(pride::MatrixView points, std::span<double> values) {
        ++batch_calls;
        batch_columns += points.cols();
        REQUIRE(values.size() == static_cast<std::size_t>(points.cols()));
        for (Eigen::Index j = 0; j < points.cols(); ++j) {
            const double x[2] = {points(0, j), points(1, j)};
            values[static_cast<std::size_t>(j)] = WildProblem::evaluate(x);
        }
    }
};

static_assert(pride::BoxProblem<WildProblem>);
static_assert(!pride::BatchBoxProblem<WildProblem>);
static_assert(pride::BatchBoxProblem<WildBatchProblem>);

pride::Matrix points_matrix(const std::vector<std::vector<double>>& cols) {
    pride::Matrix m(2, static_cast<Eigen::Index>(cols.size()));
    for (std::size_t j = 0; j < cols.size(); ++j) {
        m(0, static_cast<Eigen::Index>(j)) = cols[j][0];
        m(1, static_cast<Eigen::Index>(j)) = cols[j][1];
    }
    return m;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Rng

TEST_CASE("framework: splitmix64 matches the published reference sequence", "[framework][rng]") {
    // splitmix64 from state 0 (Vigna's reference implementation).
    std::uint64_t s = 0;
    CHECK(pride::splitmix64(s) == 0xE220A8397B1DCDAFULL);
    CHECK(pride::splitmix64(s) == 0x6E789E6AA1B965F4ULL);
    CHECK(pride::splitmix64(s) == 0x06C45D188009454FULL);
}

TEST_CASE("framework: Rng regression values for seed 42", "[framework][rng]") {
    // Recorded once (and cross-checked with an independent Python transcription of the seeding
    // and of xoshiro256++); they pin reproducibility across builds and platforms.
    pride::Rng r(42);
    CHECK(r() == 0x13D36F4A16E6DA4FULL);
    CHECK(r() == 0xC2E6A798FF82E7A4ULL);
    CHECK(r() == 0xCC08AF486E587AC3ULL);
    pride::Rng r1(42, 1);
    CHECK(r1() == 0x314630721BFEFDD2ULL);
    CHECK(r1() == 0xA0D1089FCF119DD0ULL);
    CHECK(r1() == 0x1CC9D6383AE3C102ULL);
    // The variates are derived from those words in a fixed way.
    pride::Rng u(42);
    CHECK(u.uniform() == static_cast<double>(0x13D36F4A16E6DA4FULL >> 11) * 0x1.0p-53);
    CHECK(pride::Rng(42).uniform() == 0.077444987858054204);
}

TEST_CASE("framework: Rng same seed and stream reproduce, others differ", "[framework][rng]") {
    pride::Rng a(12345, 3), b(12345, 3);
    for (int i = 0; i < 1000; ++i) REQUIRE(a() == b());
    // Mixed variates stay in step too (normal() keeps a spare).
    for (int i = 0; i < 1001; ++i) {
        REQUIRE(a.normal() == b.normal());
        REQUIRE(a.uniform() == b.uniform());
        REQUIRE(a.below(17) == b.below(17));
    }
    // A copy continues the same sequence.
    pride::Rng c = a;
    for (int i = 0; i < 100; ++i) REQUIRE(a() == c());

    auto count_equal = [](pride::Rng x, pride::Rng y) {
        int same = 0;
        for (int i = 0; i < 1000; ++i) same += x() == y();
        return same;
    };
    CHECK(count_equal(pride::Rng(1, 0), pride::Rng(2, 0)) == 0);
    CHECK(count_equal(pride::Rng(1, 0), pride::Rng(1, 1)) == 0);
    CHECK(count_equal(pride::Rng(1, 1), pride::Rng(1, 2)) == 0);
    CHECK(count_equal(pride::Rng(0, 0), pride::Rng(0, 1)) == 0);
    // The default stream is stream 0.
    CHECK(count_equal(pride::Rng(77), pride::Rng(77, 0)) == 1000);
    // Seed and stream are not interchangeable.
    CHECK(count_equal(pride::Rng(1, 2), pride::Rng(2, 1)) == 0);
}

TEST_CASE("framework: Rng uniform() is in 0 to 1 (1 excluded) with the right moments", "[framework][rng]") {
    pride::Rng r(2718, 0);
    constexpr int n = 1'000'000;
    double sum = 0.0, sum2 = 0.0, lo = 1.0, hi = 0.0;
    int below_half = 0;
    for (int i = 0; i < n; ++i) {
        const double u = r.uniform();
        REQUIRE(u >= 0.0);
        REQUIRE(u < 1.0);
        sum += u;
        sum2 += u * u;
        lo = std::min(lo, u);
        hi = std::max(hi, u);
        below_half += u < 0.5;
    }
    const double mean = sum / n;
    const double var = sum2 / n - mean * mean;
    CHECK(std::abs(mean - 0.5) < 0.002);         // sd of the mean is 2.9e-4
    CHECK(std::abs(var - 1.0 / 12.0) < 0.002);   // sd about 7.5e-5
    CHECK(std::abs(below_half - n / 2) < 5000);  // sd 500
    CHECK(lo < 1e-4);
    CHECK(hi > 1.0 - 1e-4);

    // uniform(a, b) stays in [a, b).
    for (int i = 0; i < 10000; ++i) {
        const double v = r.uniform(-3.0, 7.0);
        REQUIRE(v >= -3.0);
        REQUIRE(v < 7.0);
    }
}

TEST_CASE("framework: Rng below(n) is in range and roughly uniform", "[framework][rng]") {
    pride::Rng r(31337, 5);
    for (std::uint64_t n : {1ULL, 2ULL, 3ULL, 7ULL, 1000ULL, (1ULL << 63) + 12345ULL}) {
        for (int i = 0; i < 20000; ++i) REQUIRE(r.below(n) < n);
    }
    for (int i = 0; i < 100; ++i) CHECK(r.below(1) == 0u);

    // Chi-square over 10 bins, 200000 draws: df = 9, P(chi2 > 40) is about 7e-6.
    constexpr int bins = 10, draws = 200000;
    std::vector<int> counts(bins, 0);
    for (int i = 0; i < draws; ++i) ++counts[r.below(bins)];
    double chi2 = 0.0;
    const double expected = static_cast<double>(draws) / bins;
    for (int c : counts) chi2 += (c - expected) * (c - expected) / expected;
    INFO("chi2 = " << chi2);
    CHECK(chi2 < 40.0);

    // A range that is not a power of two and near 2^64: the upper and lower thirds get about
    // as many draws each (a modulo-biased method would favour the low values), and so do the
    // residues mod 3. Multiply-shift without Lemire's rejection step maps two of the 2^64 words
    // to every multiple of 3 and one to the others, so half the draws would be multiples of 3.
    const std::uint64_t big = 0xC000000000000000ULL;  // 3 * 2^62
    int low_third = 0, high_third = 0, multiple_of_3 = 0;
    for (int i = 0; i < 90000; ++i) {
        const std::uint64_t v = r.below(big);
        REQUIRE(v < big);
        low_third += v < big / 3;
        high_third += v >= 2 * (big / 3);
        multiple_of_3 += v % 3 == 0;
    }
    CHECK(std::abs(low_third - 30000) < 1000);  // sd 141
    CHECK(std::abs(high_third - 30000) < 1000);
    CHECK(std::abs(multiple_of_3 - 30000) < 1000);
}

TEST_CASE("framework: Rng normal() has mean 0 and variance 1", "[framework][rng]") {
    pride::Rng r(4242, 9);
    constexpr int n = 1'000'000;
    double s1 = 0.0, s2 = 0.0, s3 = 0.0, s4 = 0.0;
    int within_one = 0;
    for (int i = 0; i < n; ++i) {
        const double z = r.normal();
        REQUIRE(std::isfinite(z));
        s1 += z;
        s2 += z * z;
        s3 += z * z * z;
        s4 += z * z * z * z;
        within_one += std::abs(z) < 1.0;
    }
    const double mean = s1 / n;
    const double var = s2 / n - mean * mean;
    CHECK(std::abs(mean) < 0.005);         // sd 0.001
    CHECK(std::abs(var - 1.0) < 0.01);     // sd 0.0014
    CHECK(std::abs(s3 / n) < 0.02);        // skewness, sd 0.0024
    CHECK(std::abs(s4 / n - 3.0) < 0.05);  // kurtosis, sd 0.005
    CHECK(std::abs(within_one / double(n) - 0.6826894921370859) < 0.003);
}

// ---------------------------------------------------------------------------------------------
// Termination

TEST_CASE("framework: Termination criteria alone", "[framework][termination]") {
    using pride::Progress;
    SECTION("evaluations") {
        const auto t = pride::max_evaluations(100);
        Progress p;
        p.start = pride::Clock::now();
        p.evaluations = 99;
        CHECK_FALSE(t.done(p));
        p.evaluations = 100;
        CHECK(t.done(p));
        p.evaluations = 0;
        p.iterations = 1'000'000;
        p.best = -1e300;
        CHECK_FALSE(t.done(p));
        CHECK(t.max_evaluations == 100);
        CHECK_FALSE(t.max_iterations);
        CHECK_FALSE(t.target);
        CHECK_FALSE(t.wall_time);
    }
    SECTION("iterations") {
        const auto t = pride::max_iterations(5);
        Progress p;
        p.start = pride::Clock::now();
        p.iterations = 4;
        p.evaluations = 1'000'000;
        CHECK_FALSE(t.done(p));
        p.iterations = 5;
        CHECK(t.done(p));
    }
    SECTION("target") {
        const auto t = pride::target_value(1.0);
        Progress p;
        p.start = pride::Clock::now();
        CHECK_FALSE(t.done(p));  // best starts at +inf
        p.best = 1.0000001;
        CHECK_FALSE(t.done(p));
        p.best = 1.0;
        CHECK(t.done(p));
        p.best = -5.0;
        CHECK(t.done(p));
    }
    SECTION("wall time") {
        const auto t = pride::wall_time(std::chrono::hours(1));
        Progress p;
        p.start = pride::Clock::now();
        CHECK_FALSE(t.done(p));
        p.start = pride::Clock::now() - std::chrono::hours(2);
        CHECK(t.done(p));
    }
    SECTION("nothing set never stops") {
        const pride::Termination t;
        Progress p;
        p.evaluations = 1'000'000'000;
        p.iterations = 1'000'000'000;
        p.best = -inf;
        CHECK_FALSE(t.done(p));
    }
}

TEST_CASE("framework: Termination | keeps the tighter limit", "[framework][termination]") {
    const auto e = pride::max_evaluations(100) | pride::max_evaluations(50);
    CHECK(e.max_evaluations == 50);
    CHECK((pride::max_evaluations(50) | pride::max_evaluations(100)).max_evaluations == 50);
    CHECK((pride::max_iterations(3) | pride::max_iterations(10)).max_iterations == 3);
    CHECK((pride::max_iterations(10) | pride::max_iterations(3)).max_iterations == 3);
    // A higher target is met earlier, so it is the tighter one.
    CHECK((pride::target_value(1.0) | pride::target_value(2.0)).target == 2.0);
    CHECK((pride::target_value(2.0) | pride::target_value(1.0)).target == 2.0);
    CHECK((pride::wall_time(std::chrono::seconds(5)) | pride::wall_time(std::chrono::seconds(2))).wall_time ==
          std::chrono::seconds(2));

    // Different criteria combine: whichever comes first stops.
    const auto t = pride::max_evaluations(100) | pride::max_iterations(5) | pride::target_value(0.0);
    CHECK(t.max_evaluations == 100);
    CHECK(t.max_iterations == 5);
    CHECK(t.target == 0.0);
    CHECK_FALSE(t.wall_time);
    pride::Progress p;
    p.start = pride::Clock::now();
    p.evaluations = 50;
    p.iterations = 2;
    p.best = 1.0;
    CHECK_FALSE(t.done(p));
    p.iterations = 5;
    CHECK(t.done(p));
    p.iterations = 2;
    p.evaluations = 100;
    CHECK(t.done(p));
    p.evaluations = 50;
    p.best = 0.0;
    CHECK(t.done(p));
}

TEST_CASE("framework: Termination validate", "[framework][termination]") {
    CHECK_THAT(input_error_message([] { pride::target_value(0.0).validate("--target"); }),
               Contains("--target") && Contains("never end"));
    CHECK_THAT(input_error_message([] { pride::Termination{}.validate("run"); }), Contains("run"));
    CHECK_NOTHROW(pride::max_evaluations(1).validate("x"));
    CHECK_NOTHROW(pride::max_iterations(0).validate("x"));
    CHECK_NOTHROW(pride::wall_time(std::chrono::seconds(1)).validate("x"));
    CHECK_NOTHROW((pride::target_value(0.0) | pride::max_iterations(10)).validate("x"));
    CHECK_THAT(input_error_message([] { pride::max_evaluations(0).validate("--max-evals"); }), Contains("--max-evals"));
    CHECK_THAT(input_error_message([] { pride::max_evaluations(-5).validate("w"); }), Contains("evaluation limit"));
    CHECK_THAT(input_error_message([] { pride::max_iterations(-1).validate("w"); }), Contains("iteration limit"));
}

TEST_CASE("framework: Termination horizon", "[framework][termination]") {
    CHECK(pride::max_evaluations(100).horizon(10, 10) == 9);
    CHECK(pride::max_evaluations(105).horizon(10, 10) == 10);  // a partial last iteration counts
    CHECK(pride::max_evaluations(101).horizon(10, 10) == 10);
    CHECK(pride::max_evaluations(110).horizon(10, 10) == 10);
    CHECK(pride::max_evaluations(111).horizon(10, 10) == 11);
    CHECK(pride::max_evaluations(10).horizon(10, 10) == 0);
    CHECK(pride::max_evaluations(5).horizon(10, 10) == 0);  // budget smaller than the population
    CHECK(pride::max_evaluations(1000).horizon(20, 1) == 980);
    CHECK((pride::max_evaluations(100) | pride::max_iterations(5)).horizon(10, 10) == 5);
    CHECK((pride::max_evaluations(100) | pride::max_iterations(20)).horizon(10, 10) == 9);
    CHECK(pride::max_iterations(7).horizon(10, 10) == 7);
    CHECK(pride::max_iterations(7).horizon(10, 0) == 7);
    CHECK_FALSE(pride::max_evaluations(100).horizon(10, 0).has_value());
    CHECK_FALSE(pride::target_value(1.0).horizon(10, 10).has_value());
    CHECK_FALSE(pride::wall_time(std::chrono::seconds(1)).horizon(10, 10).has_value());
}

// ---------------------------------------------------------------------------------------------
// Bounds

TEST_CASE("framework: Clamp and Reflect always land inside the box", "[framework][bounds]") {
    pride::Rng rng(8);
    constexpr std::size_t n = 12;
    const std::vector<double> specials{
        inf, -inf, nan_,  1e300, -1e300, std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(),
        0.0, -0.0, 1e-320};
    for (int trial = 0; trial < 300; ++trial) {
        std::vector<double> lo(n), hi(n), x(n);
        for (std::size_t i = 0; i < n; ++i) {
            const double a = rng.uniform(-100.0, 100.0), b = rng.uniform(-100.0, 100.0);
            lo[i] = std::min(a, b);
            hi[i] = std::max(a, b);
            switch (rng.below(5)) {
                case 0:
                    x[i] = rng.uniform(-1e6, 1e6);
                    break;
                case 1:
                    x[i] = specials[rng.below(specials.size())];
                    break;
                case 2:
                    x[i] = rng.bernoulli(0.5) ? lo[i] : hi[i];
                    break;
                case 3:
                    x[i] = rng.uniform(lo[i], hi[i]);
                    break;
                default:
                    x[i] = rng.uniform(-1e15, 1e15);
                    break;
            }
        }
        auto c = x, r = x;
        pride::Clamp{}(c, lo, hi);
        pride::Reflect{}(r, lo, hi);
        for (std::size_t i = 0; i < n; ++i) {
            INFO("x = " << x[i] << " in [" << lo[i] << ", " << hi[i] << "]");
            CHECK(c[i] >= lo[i]);
            CHECK(c[i] <= hi[i]);
            CHECK(r[i] >= lo[i]);
            CHECK(r[i] <= hi[i]);
            if (x[i] >= lo[i] && x[i] <= hi[i]) {  // inside (or on a face): untouched
                CHECK(c[i] == x[i]);
                CHECK(r[i] == x[i]);
            } else if (std::isnan(x[i])) {
                CHECK(c[i] == lo[i]);
                CHECK(r[i] == lo[i]);
            } else {  // Clamp goes to the nearest face
                CHECK(c[i] == (x[i] < lo[i] ? lo[i] : hi[i]));
            }
        }
    }
}

TEST_CASE("framework: Clamp and Reflect on hand-worked examples", "[framework][bounds]") {
    auto reflect1 = [](double v, double lo, double hi) {
        double x[1] = {v};
        const double l[1] = {lo}, h[1] = {hi};
        pride::Reflect{}(x, l, h);
        return x[0];
    };
    auto clamp1 = [](double v, double lo, double hi) {
        double x[1] = {v};
        const double l[1] = {lo}, h[1] = {hi};
        pride::Clamp{}(x, l, h);
        return x[0];
    };
    // Box [0, 10].
    CHECK(reflect1(12.0, 0.0, 10.0) == 8.0);
    CHECK(reflect1(-3.0, 0.0, 10.0) == 3.0);
    CHECK(reflect1(25.0, 0.0, 10.0) == 5.0);  // 25 -> -5 (at 10) -> 5 (at 0)
    CHECK(reflect1(31.0, 0.0, 10.0) == 9.0);  // 31 -> -11 -> 11 -> 9
    CHECK(reflect1(20.0, 0.0, 10.0) == 0.0);
    CHECK(reflect1(-10.0, 0.0, 10.0) == 10.0);
    CHECK(reflect1(-13.0, 0.0, 10.0) == 7.0);  // -13 -> 13 -> 7
    CHECK(reflect1(10.0, 0.0, 10.0) == 10.0);
    CHECK(reflect1(0.0, 0.0, 10.0) == 0.0);
    CHECK(reflect1(inf, 0.0, 10.0) == 10.0);
    CHECK(reflect1(-inf, 0.0, 10.0) == 0.0);
    CHECK(reflect1(nan_, 0.0, 10.0) == 0.0);
    // An offset box [2, 5].
    CHECK(reflect1(6.0, 2.0, 5.0) == 4.0);
    CHECK(reflect1(1.0, 2.0, 5.0) == 3.0);
    CHECK(reflect1(9.0, 2.0, 5.0) == 3.0);   // 9 -> 1 -> 3
    CHECK(reflect1(-2.5, 2.0, 5.0) == 3.5);  // -2.5 -> 6.5 -> 3.5
    // A negative box [-5, -1].
    CHECK(reflect1(0.0, -5.0, -1.0) == -2.0);
    CHECK(reflect1(-7.0, -5.0, -1.0) == -3.0);
    // A degenerate box [3, 3].
    CHECK(reflect1(7.0, 3.0, 3.0) == 3.0);
    CHECK(reflect1(-7.0, 3.0, 3.0) == 3.0);
    CHECK(reflect1(nan_, 3.0, 3.0) == 3.0);

    CHECK(clamp1(12.0, 0.0, 10.0) == 10.0);
    CHECK(clamp1(-3.0, 0.0, 10.0) == 0.0);
    CHECK(clamp1(4.5, 0.0, 10.0) == 4.5);
    CHECK(clamp1(nan_, 0.0, 10.0) == 0.0);
    CHECK(clamp1(inf, 0.0, 10.0) == 10.0);
    CHECK(clamp1(-inf, 0.0, 10.0) == 0.0);
}

TEST_CASE("framework: Reflect on boxes with a face at +-DBL_MAX", "[framework][bounds]") {
    // A half-unbounded box written with DBL_MAX, as a user-defined problem might. The excursion is
    // small, so one mirror at the crossed face is the answer; v - lo and 2 * width overflow, which
    // must not turn the coordinate into NaN (nor move it to the far face).
    constexpr double big = std::numeric_limits<double>::max();
    auto reflect1 = [](double v, double lo, double hi) {
        double x[1] = {v};
        const double l[1] = {lo}, h[1] = {hi};
        pride::Reflect{}(x, l, h);
        return x[0];
    };
    const double a = reflect1(5.0, -big, 0.0);
    CHECK_FALSE(std::isnan(a));
    CHECK(a == -5.0);
    const double b = reflect1(-5.0, 0.0, big);
    CHECK(b == 5.0);
    const double c = reflect1(1.7e308, -1e308, 1e308);  // width overflows to +inf
    CHECK_FALSE(std::isnan(c));
    CHECK(c >= -1e308);
    CHECK(c <= 1e308);
}

TEST_CASE("framework: Reflect agrees with mirroring step by step", "[framework][bounds]") {
    pride::Rng rng(55);
    for (int k = 0; k < 5000; ++k) {
        const double lo = rng.uniform(-10.0, 10.0);
        const double hi = lo + rng.uniform(0.1, 20.0);
        const double v0 = rng.uniform(lo - 10.0 * (hi - lo), hi + 10.0 * (hi - lo));
        double v = v0;
        while (v < lo || v > hi) v = v > hi ? 2.0 * hi - v : 2.0 * lo - v;
        double x[1] = {v0};
        const double l[1] = {lo}, h[1] = {hi};
        pride::Reflect{}(x, l, h);
        INFO("v0 = " << v0 << " in [" << lo << ", " << hi << "]");
        CHECK_THAT(x[0], WithinAbs(v, 1e-9 * (1.0 + std::abs(v0))));
    }
}

// ---------------------------------------------------------------------------------------------
// RunState

TEST_CASE("framework: RunState counts, sanitises and keeps the best", "[framework][runstate]") {
    WildProblem p;
    pride::RunState rs(pride::max_evaluations(8), 2);
    CHECK(rs.best() == inf);
    CHECK(rs.remaining() == 8);
    for (double v : rs.best_x()) CHECK(std::isnan(v));  // nothing evaluated yet

    const std::vector<double> a{0.9, 0.0};    // NaN
    const std::vector<double> b{-0.9, 0.5};   // +inf
    const std::vector<double> c{-0.9, -0.5};  // -inf
    const std::vector<double> d{0.3, 0.4};    // 0.25
    const std::vector<double> e{0.1, -0.2};   // 0.05
    const std::vector<double> f{0.4, 0.4};    // 0.32

    CHECK(rs.evaluate(p, a) == inf);
    CHECK(rs.evaluate(p, b) == inf);
    CHECK(rs.evaluate(p, c) == inf);  // -inf is not a better value: it is no value
    CHECK(rs.best() == inf);
    for (double v : rs.best_x()) CHECK(std::isnan(v));
    CHECK(rs.progress().evaluations == 3);

    CHECK(rs.evaluate(p, d) == 0.25);
    CHECK(rs.best() == 0.25);
    CHECK(std::vector<double>(rs.best_x().begin(), rs.best_x().end()) == d);
    CHECK(rs.evaluate(p, e) == Approx(0.05));
    CHECK(rs.evaluate(p, f) == Approx(0.32));
    CHECK(rs.evaluate(p, a) == inf);
    CHECK(rs.best() == Approx(0.05));
    CHECK(std::vector<double>(rs.best_x().begin(), rs.best_x().end()) == e);
    CHECK(rs.progress().evaluations == 7);
    CHECK(rs.remaining() == 1);
    CHECK_FALSE(rs.exhausted());
    CHECK_FALSE(rs.done());

    CHECK(rs.evaluate(p, d) == 0.25);
    CHECK(rs.exhausted());
    CHECK(rs.done());
    CHECK(p.calls == 8);
    // Past the budget: a logic error, and the problem is not called.
    CHECK_THROWS_AS(rs.evaluate(p, d), std::logic_error);
    CHECK(p.calls == 8);
    CHECK(rs.progress().evaluations == 8);

    const pride::Result r = rs.finish();
    CHECK(r.evaluations == 8);
    CHECK(r.best_f == Approx(0.05));
    CHECK(r.best_x == e);
}

TEST_CASE("framework: sanitize", "[framework][runstate]") {
    CHECK(pride::sanitize(nan_) == inf);
    CHECK(pride::sanitize(-inf) == inf);
    CHECK(pride::sanitize(inf) == inf);
    CHECK(pride::sanitize(-1e308) == -1e308);
    CHECK(pride::sanitize(0.0) == 0.0);
}

TEST_CASE("framework: RunState with no finite value reports +inf", "[framework][runstate]") {
    WildProblem p;
    pride::RunState rs(pride::max_evaluations(3), 2);
    const std::vector<double> a{0.9, 0.0}, c{-0.9, -0.5};
    rs.evaluate(p, a);
    rs.evaluate(p, c);
    rs.evaluate(p, a);
    const auto r = rs.finish();
    CHECK(r.best_f == inf);
    REQUIRE(r.best_x.size() == 2);
    CHECK(std::isnan(r.best_x[0]));
}

TEMPLATE_TEST_CASE("framework: RunState evaluate_columns stops exactly at the budget", "[framework][runstate]",
                   WildProblem, WildBatchProblem) {
    TestType p;
    pride::RunState rs(pride::max_evaluations(5), 2);
    // Columns: 0.25, NaN, 0.05, -inf, 0.02, | past the budget: 0.0, 0.01, 0.5
    const auto pts = points_matrix(
        {{0.3, 0.4}, {0.9, 0.0}, {0.1, -0.2}, {-0.9, -0.5}, {0.1, 0.1}, {0.0, 0.0}, {0.1, 0.0}, {0.5, 0.5}});
    std::vector<double> values(8, -123.0);
    CHECK(rs.evaluate_columns(p, pts, values) == 5);
    CHECK(values[0] == 0.25);
    CHECK(values[1] == inf);
    CHECK(values[2] == Approx(0.05));
    CHECK(values[3] == inf);
    CHECK(values[4] == Approx(0.02));
    CHECK(values[5] == inf);
    CHECK(values[6] == inf);
    CHECK(values[7] == inf);
    CHECK(p.calls == 5);
    CHECK(rs.progress().evaluations == 5);
    CHECK(rs.exhausted());
    // The best is the best evaluated column, not the (better) unevaluated origin.
    CHECK(rs.best() == Approx(0.02));
    CHECK(rs.best_x()[0] == 0.1);
    CHECK(rs.best_x()[1] == 0.1);
    if constexpr (std::is_same_v<TestType, WildBatchProblem>) {
        CHECK(p.batch_calls == 1);
        CHECK(p.batch_columns == 5);
    }

    // Once spent, nothing more is evaluated and every value is +inf.
    std::vector<double> more(8, -1.0);
    CHECK(rs.evaluate_columns(p, pts, more) == 0);
    for (double v : more) CHECK(v == inf);
    CHECK(p.calls == 5);
    CHECK(rs.progress().evaluations == 5);
}

TEMPLATE_TEST_CASE("framework: RunState keeps the first of equal best values", "[framework][runstate]", WildProblem,
                   WildBatchProblem) {
    // docs/architecture.md: the best point is the first one to reach the best value. These three
    // points have exactly the same value, 0.3^2 + 0.4^2 (addition commutes, and the sign squares away).
    TestType p;
    const std::vector<double> first{0.3, 0.4}, second{0.4, 0.3}, third{-0.3, 0.4};
    REQUIRE(p.evaluate(first) == p.evaluate(second));
    REQUIRE(p.evaluate(first) == p.evaluate(third));
    {
        pride::RunState rs(pride::max_evaluations(10), 2);
        rs.evaluate(p, first);
        rs.evaluate(p, second);
        rs.evaluate(p, third);
        CHECK(std::vector<double>(rs.best_x().begin(), rs.best_x().end()) == first);
        CHECK(rs.finish().best_x == first);
    }
    {
        pride::RunState rs(pride::max_evaluations(10), 2);
        const auto pts = points_matrix({{0.9, 0.0}, second, first, third});  // NaN first, then the ties
        std::vector<double> values(4);
        CHECK(rs.evaluate_columns(p, pts, values) == 4);
        CHECK(std::vector<double>(rs.best_x().begin(), rs.best_x().end()) == second);
        // A later batch with the same value does not replace it either.
        const auto again = points_matrix({first, third});
        std::vector<double> more(2);
        rs.evaluate_columns(p, again, more);
        CHECK(std::vector<double>(rs.best_x().begin(), rs.best_x().end()) == second);
    }
}

TEST_CASE("framework: RunState evaluate_columns without a budget evaluates all", "[framework][runstate]") {
    WildBatchProblem p;
    pride::RunState rs(pride::max_iterations(3), 2);
    const auto pts = points_matrix({{0.3, 0.4}, {0.9, 0.0}, {0.0, 0.2}});
    std::vector<double> values(3);
    CHECK(rs.evaluate_columns(p, pts, values) == 3);
    CHECK(values[1] == inf);
    CHECK(rs.best() == Approx(0.04));
    CHECK(rs.best_x()[1] == 0.2);
    CHECK(rs.progress().evaluations == 3);
    CHECK_FALSE(rs.exhausted());
}

TEST_CASE("framework: RunState end_iteration records history and calls the observer", "[framework][runstate]") {
    WildProblem p;
    pride::RunState rs(pride::max_evaluations(100) | pride::max_iterations(2), 2);
    struct Seen {
        std::int64_t iteration, evaluations;
        double best_f;
        std::vector<double> best_x;
        Eigen::Index population_cols;
        std::size_t fitness_size;
    };
    std::vector<Seen> seen;
    auto observer = [&](const pride::IterationView& v) {
        seen.push_back({v.iteration,
                        v.evaluations,
                        v.best_f,
                        {v.best_x.begin(), v.best_x.end()},
                        v.population.cols(),
                        v.fitness.size()});
    };

    // Iteration 0: the initial population.
    auto pop = points_matrix({{0.3, 0.4}, {0.9, 0.0}, {0.4, 0.4}});
    std::vector<double> fit(3);
    rs.evaluate_columns(p, pop, fit);
    rs.end_iteration(observer, pop, fit);
    CHECK(rs.iteration() == 0);
    CHECK_FALSE(rs.done());

    // Iteration 1: better.
    pop = points_matrix({{0.1, -0.2}, {-0.9, 0.5}, {0.4, 0.4}});
    rs.evaluate_columns(p, pop, fit);
    rs.end_iteration(observer, pop, fit);
    CHECK(rs.iteration() == 1);
    CHECK_FALSE(rs.done());

    // Iteration 2: worse, so the best stays.
    pop = points_matrix({{0.5, 0.5}, {0.9, 0.9}, {0.4, 0.4}});
    rs.evaluate_columns(p, pop, fit);
    rs.end_iteration(observer, pop, fit);
    CHECK(rs.iteration() == 2);
    CHECK(rs.done());  // the iteration limit

    REQUIRE(seen.size() == 3);
    for (std::size_t k = 0; k < 3; ++k) {
        CHECK(seen[k].iteration == static_cast<std::int64_t>(k));
        CHECK(seen[k].evaluations == 3 * static_cast<std::int64_t>(k + 1));
        CHECK(seen[k].population_cols == 3);
        CHECK(seen[k].fitness_size == 3u);
    }
    CHECK(seen[0].best_f == 0.25);
    CHECK(seen[0].best_x == std::vector<double>{0.3, 0.4});
    CHECK(seen[1].best_f == Approx(0.05));
    CHECK(seen[1].best_x == std::vector<double>{0.1, -0.2});
    CHECK(seen[2].best_f == Approx(0.05));

    const pride::Result r = rs.finish();
    CHECK(r.iterations == 2);
    CHECK(r.evaluations == 9);
    REQUIRE(r.history.size() == 3);
    REQUIRE(r.history_evaluations.size() == 3);
    CHECK(r.history[0] == 0.25);
    CHECK(r.history[1] == Approx(0.05));
    CHECK(r.history[2] == Approx(0.05));
    CHECK(r.history_evaluations == std::vector<std::int64_t>{3, 6, 9});
    CHECK(r.best_x == std::vector<double>{0.1, -0.2});
    CHECK(r.wall_ms >= 0.0);

    // The no-op observer compiles and runs.
    pride::RunState rs2(pride::max_evaluations(10), 2);
    pride::NoObserver none;
    rs2.end_iteration(none, pop, fit);
    CHECK(rs2.finish().history.size() == 1u);
}

TEST_CASE("framework: RunState done() follows the target", "[framework][runstate]") {
    WildProblem p;
    pride::RunState rs(pride::max_evaluations(100) | pride::target_value(0.01), 2);
    const std::vector<double> d{0.3, 0.4}, g{0.05, 0.05};
    rs.evaluate(p, d);
    CHECK_FALSE(rs.done());
    rs.evaluate(p, g);  // 0.005 <= 0.01
    CHECK(rs.done());
    CHECK_FALSE(rs.exhausted());
}

// ---------------------------------------------------------------------------------------------
// Encodings

TEST_CASE("framework: Encoded<P, IdentityEncoding> is the problem itself", "[framework][encoding]") {
    using pride::continuous::Rastrigin;
    using pride::continuous::Shifted;
    using E1 = pride::Encoded<Rastrigin, pride::IdentityEncoding>;
    using E2 = pride::Encoded<Shifted<Rastrigin>, pride::IdentityEncoding>;
    static_assert(pride::EncodingFor<pride::IdentityEncoding, Rastrigin>);
    static_assert(pride::BoxProblem<E1>);
    static_assert(pride::BoxProblem<E2>);
    static_assert(pride::BoxProblem<pride::Encoded<WildProblem, pride::IdentityEncoding>>);
    static_assert(!pride::BoxProblem<int>);

    constexpr std::size_t dim = 6;
    Rastrigin plain(dim);
    Shifted<Rastrigin> shifted(dim);
    E1 e1(Rastrigin(dim), pride::IdentityEncoding{});
    E2 e2(Shifted<Rastrigin>(dim), pride::IdentityEncoding{});

    CHECK(e1.dimension() == dim);
    REQUIRE(e1.lower().size() == dim);
    REQUIRE(e1.upper().size() == dim);
    for (std::size_t i = 0; i < dim; ++i) {
        CHECK(e1.lower()[i] == plain.lower()[i]);
        CHECK(e1.upper()[i] == plain.upper()[i]);
        CHECK(e2.lower()[i] == shifted.lower()[i]);
        CHECK(e2.upper()[i] == shifted.upper()[i]);
    }
    CHECK(e1.problem().dimension() == dim);

    pride::Rng rng(5);
    for (int k = 0; k < 200; ++k) {
        std::vector<double> x(dim);
        for (auto& v : x) v = rng.uniform(-5.12, 5.12);
        CHECK(e1.evaluate(x) == plain.evaluate(x));
        CHECK(e2.evaluate(x) == shifted.evaluate(x));
        const auto dec = e1.decode(x);
        CHECK(dec.data() == x.data());
        CHECK(dec.size() == dim);
    }
    const auto o = shifted.optimum_point();
    CHECK(e2.evaluate(o) == 0.0);

    // Through a RunState, like an algorithm would use it.
    WildProblem w;
    pride::Encoded<WildProblem, pride::IdentityEncoding> ew(w, {});
    pride::RunState rs(pride::max_evaluations(2), 2);
    const std::vector<double> a{0.9, 0.0}, d{0.3, 0.4};
    CHECK(rs.evaluate(ew, a) == inf);
    CHECK(rs.evaluate(ew, d) == 0.25);
    CHECK(ew.problem().calls == 2);
}

// ---------------------------------------------------------------------------------------------
// Initialisers

namespace {
struct SuggestingProblem : WildProblem {
    void starting_points(pride::Rng&, pride::Matrix& out) const { out.setConstant(0.125); }
};
}  // namespace

TEST_CASE("framework: UniformInit and SuggestedInit", "[framework][init]") {
    static_assert(pride::SuggestsStartingPoints<SuggestingProblem>);
    static_assert(!pride::SuggestsStartingPoints<WildProblem>);
    pride::continuous::Ackley f(4);
    pride::Matrix a(4, 50), b(4, 50);
    pride::Rng r1(3), r2(3);
    pride::UniformInit{}(f, r1, a);
    pride::SuggestedInit{}(f, r2, b);  // no suggestions: uniform, the same draws
    CHECK(a == b);
    // Column by column, coordinate by coordinate.
    pride::Rng r3(3);
    for (Eigen::Index j = 0; j < a.cols(); ++j)
        for (Eigen::Index i = 0; i < a.rows(); ++i) CHECK(a(i, j) == r3.uniform(-15.0, 30.0));
    for (Eigen::Index j = 0; j < a.cols(); ++j)
        for (Eigen::Index i = 0; i < a.rows(); ++i) {
            CHECK(a(i, j) >= -15.0);
            CHECK(a(i, j) < 30.0);
        }

    SuggestingProblem s;
    pride::Matrix c(2, 5);
    pride::Rng r4(3);
    pride::SuggestedInit{}(s, r4, c);
    CHECK((c.array() == 0.125).all());
}

// ---------------------------------------------------------------------------------------------
// Registry

TEST_CASE("framework: Registry add, find and order", "[framework][registry]") {
    pride::Registry<int> r;
    CHECK(r.items().empty());
    CHECK(r.find("x") == nullptr);
    r.add("zeta", "last letter", 26).add("alpha", "first letter", 1);
    r.add("mu", "middle", 12);
    REQUIRE(r.items().size() == 3);
    // Insertion order, not alphabetical.
    CHECK(r.items()[0].name == "zeta");
    CHECK(r.items()[1].name == "alpha");
    CHECK(r.items()[2].name == "mu");
    const auto* a = r.find("alpha");
    REQUIRE(a != nullptr);
    CHECK(a->entry == 1);
    CHECK(a->summary == "first letter");
    CHECK(a == &r.items()[1]);
    REQUIRE(r.find("mu") != nullptr);
    CHECK(r.find("mu")->entry == 12);
    CHECK(r.find("Mu") == nullptr);    // case-sensitive
    CHECK(r.find("alph") == nullptr);  // whole names only
    CHECK(r.find("") == nullptr);
}

TEST_CASE("renamed_message: the first word of an error's place in a front end's words", "[framework][errors]") {
    const std::map<std::string, std::string, std::less<>> names{{"evaluations", "--evals"}, {"parameter", "--param"}};
    CHECK(pride::renamed_message(pride::InputError("evaluations", "must be >= 1"), names) == "--evals: must be >= 1");
    CHECK(pride::renamed_message(pride::InputError("parameter pop", "must be >= 4, got 2"), names) ==
          "--param pop: must be >= 4, got 2");
    CHECK_FALSE(pride::renamed_message(pride::InputError("start", "outside the map"), names));
    CHECK_FALSE(pride::renamed_message(pride::InputError("a whole message"), names));
    CHECK_FALSE(pride::renamed_message(pride::InputError("evaluationsx", "d"), names));  // whole words only
}

// Cheaper forms of the real-coded GA's roots, measured before any is adopted.
//   SBX (eta_c 15) takes two 16th roots per crossed coordinate, the polynomial mutation (eta_m 20)
//   a 21st root per mutated gene (algorithms/parts/common/power.hpp: four correctly rounded square roots,
//   four lanes per instruction; std::pow). This program
//   (1) times each form per value (the least of --rounds batches), CSV `what,ns_per_value`;
//   (2) with --draws N, draws N outputs of each operator with the exact root and, from another
//       stream, with the candidate root, and prints per operator and setting: the two-sample
//       Kolmogorov-Smirnov statistic and its asymptotic p-value, the sample moments beside the
//       closed forms of Deb and Agrawal (1995, Complex Systems 9:115-148: the spread factor's
//       density 0.5 (eta+1) beta^eta for beta <= 1, 0.5 (eta+1) / beta^(eta+2) beyond; the
//       mutation's delta density 0.5 (eta+1) (1 - |delta|)^eta), and the largest difference in ulps
//       between the two roots on the same draws. CSV `operator,setting,form,...`.
// The candidates (not used by the library; the measurements are in docs/benchmarks.md):
//   root16_float: x^(1/16) from four float square roots (x rounded to float; eight lanes per AVX
//     instruction), refined by one Halley step in double (Traub 1964, sec. 8.4: cubic convergence;
//     the float estimate's relative error, about 1e-7, becomes about 1e-20); x outside float's
//     normal range takes std::pow.
//   root_halley: x^(1/n) from an estimate whose bits are those of x divided by n (Blinn 1997,
//     "Floating-point tricks", IEEE CG&A 17(4): up to 6 % off) refined by four Halley steps (three leave up to
//     hundreds of ulps for n = 21: the first step from 6 % is not yet in the cubic regime).
// Every candidate uses IEEE square roots, additions, multiplications and divisions in a fixed order
// (no fused multiply-add in a baseline x86-64 build), so its bits depend only on x.
#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "algorithms/parts/common/power.hpp"
#include "bench/best_time.hpp"
#include "framework/random.hpp"

namespace {

using namespace pride;

/// One Halley step for y^n = x, as a correction (its rounding costs a fraction of an ulp):
/// y + y 2 (x - P) / ((n + 1) P + (n - 1) x), P = y^n.
double halley(double x, double y, double p, double n) {
    return y + y * ((2.0 * (x - p)) / ((n + 1.0) * p + (n - 1.0) * x));
}

double root16_float(double x) {
    if (!(x >= 0x1p-126 && x <= 0x1p127)) return std::pow(x, 1.0 / 16.0);
    float f = static_cast<float>(x);
    for (int k = 0; k < 4; ++k) f = std::sqrt(f);
    const double y = f;
    double p = y;
    for (int k = 0; k < 4; ++k) p *= p;
    return halley(x, y, p, 16.0);
}

double root_halley(double x, int n) {
    if (!(x >= 0x1p-1000 && x <= 0x1p1000)) return std::pow(x, 1.0 / n);
    constexpr std::uint64_t one = 0x3FF0000000000000u;
    const auto un = static_cast<std::uint64_t>(n);
    double y = std::bit_cast<double>(std::bit_cast<std::uint64_t>(x) / un + (one - one / un));
    for (int step = 0; step < 4; ++step) {
        double p = 1.0, base = y;
        for (int k = n; k > 0; k >>= 1) {
            if (k & 1) p *= base;
            base *= base;
        }
        y = halley(x, y, p, n);
    }
    return y;
}

#ifdef PRIDE_ROOTS_AVX
/// root16_float, eight values per pass (the same bits lane by lane). Only where AVX is.
[[gnu::target("avx")]] void root16_float_avx(double* v, std::size_t n) {
    const __m256d two = _mm256_set1_pd(2.0), up = _mm256_set1_pd(17.0), down = _mm256_set1_pd(15.0);
    std::size_t i = 0;
    for (; i + 8 <= n; i += 8) {
        const __m256d x0 = _mm256_loadu_pd(v + i), x1 = _mm256_loadu_pd(v + i + 4);
        __m256 f = _mm256_insertf128_ps(_mm256_castps128_ps256(_mm256_cvtpd_ps(x0)), _mm256_cvtpd_ps(x1), 1);
        for (int k = 0; k < 4; ++k) f = _mm256_sqrt_ps(f);
        const __m256d y[2] = {_mm256_cvtps_pd(_mm256_castps256_ps128(f)), _mm256_cvtps_pd(_mm256_extractf128_ps(f, 1))};
        const __m256d x[2] = {x0, x1};
        for (int h = 0; h < 2; ++h) {
            __m256d p = y[h];
            for (int s = 0; s < 4; ++s) p = _mm256_mul_pd(p, p);
            const __m256d den = _mm256_add_pd(_mm256_mul_pd(up, p), _mm256_mul_pd(down, x[h]));
            const __m256d corr = _mm256_div_pd(_mm256_mul_pd(two, _mm256_sub_pd(x[h], p)), den);
            _mm256_storeu_pd(v + i + 4 * h, _mm256_add_pd(y[h], _mm256_mul_pd(y[h], corr)));
        }
        // (the range check of root16_float is left out of the timing: SBX's arguments are in range)
    }
    for (; i < n; ++i) v[i] = root16_float(v[i]);
}
#endif

using pride::bench::least_ns;

/// Two-sample Kolmogorov-Smirnov statistic of a and b (sorted here), and its asymptotic p-value
/// (Numerical Recipes, 3rd ed., sec. 14.3.3: Q_KS((sqrt(ne) + 0.12 + 0.11 / sqrt(ne)) D)).
std::pair<double, double> ks_two_sample(std::vector<double>& a, std::vector<double>& b) {
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    const double na = static_cast<double>(a.size()), nb = static_cast<double>(b.size());
    std::size_t i = 0, j = 0;
    double d = 0.0;
    while (i < a.size() && j < b.size()) {
        const double v = std::min(a[i], b[j]);
        while (i < a.size() && a[i] == v) ++i;
        while (j < b.size() && b[j] == v) ++j;
        d = std::max(d, std::abs(static_cast<double>(i) / na - static_cast<double>(j) / nb));
    }
    const double ne = std::sqrt(na * nb / (na + nb));
    const double lambda = (ne + 0.12 + 0.11 / ne) * d;
    double q = 0.0;
    for (int k = 1; k <= 200; ++k) q += (k % 2 ? 2.0 : -2.0) * std::exp(-2.0 * k * k * lambda * lambda);
    return {d, std::clamp(q, 0.0, 1.0)};
}

struct Moments {
    double mean = 0, var = 0, abs_mean = 0, below = 0;  // below: the share of values <= the setting's pivot
};

Moments moments(const std::vector<double>& v, double pivot) {
    Moments m;
    for (double x : v) {
        m.mean += x;
        m.abs_mean += std::abs(x);
        m.below += x <= pivot ? 1.0 : 0.0;
    }
    const double n = static_cast<double>(v.size());
    m.mean /= n;
    m.abs_mean /= n;
    m.below /= n;
    for (double x : v) m.var += (x - m.mean) * (x - m.mean);
    m.var /= n - 1.0;
    return m;
}

double ulps(double a, double b) {
    return std::abs(static_cast<double>(std::bit_cast<std::int64_t>(a) - std::bit_cast<std::int64_t>(b)));
}

/// SBX's root argument as SbxCrossover::Prepared::root_argument works it out (crossover.hpp).
double sbx_argument(double u, double beta, const FixedPower& power) {
    const double big = power(beta);
    if (!(big < 1e300)) return u <= 0.5 ? 2.0 * u : 1.0 / (2.0 - 2.0 * u);
    const double t = u * (2.0 * big - 1.0);
    return t <= big ? t / big : big / (2.0 * big - t);
}

/// The polynomial mutation's root argument and sign (PolynomialMutation, mutation.hpp): delta =
/// sign (root(val) - 1).
std::pair<double, double> mutation_argument(double u, double d_low, double d_high, const FixedPower& power) {
    if (u <= 0.5) return {2.0 * u + (1.0 - 2.0 * u) * power(1.0 - d_low), 1.0};
    return {2.0 * (1.0 - u) + 2.0 * (u - 0.5) * power(1.0 - d_high), -1.0};
}

void distribution(std::int64_t draws) {
    fmt::print(
        "operator,setting,form,n,mean,closed_mean,var,closed_var,abs_mean,closed_abs_mean,share_le_pivot,"
        "closed_share,ks_d,ks_p,max_ulps_same_draws\n");
    const FixedPower power16(16.0), root16(1.0 / 16.0), power21(21.0), root21(1.0 / 21.0);
    const auto n = static_cast<std::size_t>(draws);

    // SBX: the first child's spread factor betaq = ((y1 + y2) - 2 c1) / (y2 - y1) = root(arg), for
    // parents y1 < y2 in [low, high]. "unbounded": y1 = 0, y2 = 1 in [-1e6, 1e6], where alpha = 2 -
    // beta^-16 rounds to 2, which is Deb and Agrawal's unbounded SBX (the closed forms, eta 15: E beta
    // = 8 (1/17 + 1/15), E beta^2 = 8 (1/18 + 1/14), P(beta <= 1) = 1/2). "near-face": y1 = -5.1,
    // y2 = -4.5 in [-5.12, 5.12] (beta = 1.067, alpha = 1.64: the bound shapes it; no closed form
    // here, the test is between the two roots).
    struct SbxSetting {
        const char* name;
        double y1, y2, low;
        bool closed;
    };
    for (const SbxSetting s :
         {SbxSetting{"unbounded", 0.0, 1.0, -1e6, true}, SbxSetting{"near-face", -5.1, -4.5, -5.12, false}}) {
        const double beta = 1.0 + 2.0 * (s.y1 - s.low) / (s.y2 - s.y1);
        std::vector<double> exact(n), fast(n);
        Rng e(101), f(202), same(303);
        for (std::size_t k = 0; k < n; ++k) {
            exact[k] = root16(sbx_argument(e.uniform(), beta, power16));
            fast[k] = root16_float(sbx_argument(f.uniform(), beta, power16));
        }
        double worst = 0.0;
        for (std::size_t k = 0; k < n; ++k) {
            const double arg = sbx_argument(same.uniform(), beta, power16);
            worst = std::max(worst, ulps(root16(arg), root16_float(arg)));
        }
        const double eta = 15.0;
        const double c_mean = 0.5 * (eta + 1) * (1 / (eta + 2) + 1 / eta);
        const double c_m2 = 0.5 * (eta + 1) * (1 / (eta + 3) + 1 / (eta - 1));
        const Moments me = moments(exact, 1.0), mf = moments(fast, 1.0);
        const auto [d, p] = ks_two_sample(exact, fast);
        for (const auto& [form, m] : {std::pair{"exact", me}, std::pair{"root16_float", mf}}) {
            if (s.closed)
                fmt::print(
                    "sbx-betaq,{},{},{},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.3g},{:.3g},{}\n",
                    s.name, form, n, m.mean, c_mean, m.var, c_m2 - c_mean * c_mean, m.abs_mean, c_mean, m.below, 0.5, d,
                    p, worst);
            else
                fmt::print("sbx-betaq,{},{},{},{:.6f},,{:.6f},,{:.6f},,{:.6f},,{:.3g},{:.3g},{}\n", s.name, form, n,
                           m.mean, m.var, m.abs_mean, m.below, d, p, worst);
        }
    }

    // Polynomial mutation (bounded form): delta = (child - y) / (high - low) for y in the middle
    // ("middle": d_low = d_high = 1/2, where (1 - d)^21 = 4.8e-7 leaves the unbounded form's
    // closed forms, eta 20: E delta = 0, E delta^2 = 2 / (22 * 23), E |delta| = 1 / 22) and near a
    // face ("near-face": d_low = 0.02). The simple form of pagmo2 (SimplePolynomialMutation) takes
    // the same roots of 2u and 2(1 - u): its delta is "middle"'s.
    struct MutSetting {
        const char* name;
        double d_low;
        bool closed;
    };
    for (const MutSetting s : {MutSetting{"middle", 0.5, true}, MutSetting{"near-face", 0.02, false}}) {
        std::vector<double> exact(n), fast(n);
        Rng e(404), f(505), same(606);
        const auto delta = [&](Rng& r, const auto& root) {
            const auto [val, sign] = mutation_argument(r.uniform(), s.d_low, 1.0 - s.d_low, power21);
            return sign * (root(val) - 1.0);
        };
        const auto exact_root = [&](double v) { return root21(v); };
        const auto fast_root = [](double v) { return root_halley(v, 21); };
        for (std::size_t k = 0; k < n; ++k) {
            exact[k] = delta(e, exact_root);
            fast[k] = delta(f, fast_root);
        }
        double worst = 0.0;
        for (std::size_t k = 0; k < n; ++k) {
            const auto [val, sign] = mutation_argument(same.uniform(), s.d_low, 1.0 - s.d_low, power21);
            worst = std::max(worst, ulps(root21(val), root_halley(val, 21)));
        }
        const double eta = 20.0;
        const Moments me = moments(exact, 0.0), mf = moments(fast, 0.0);
        const auto [d, p] = ks_two_sample(exact, fast);
        for (const auto& [form, m] : {std::pair{"exact", me}, std::pair{"root_halley", mf}}) {
            if (s.closed)
                fmt::print(
                    "mutation-delta,{},{},{},{:.6f},{:.6f},{:.7f},{:.7f},{:.6f},{:.6f},{:.6f},{:.6f},{:.3g},{:.3g},{}"
                    "\n",
                    s.name, form, n, m.mean, 0.0, m.var, 2.0 / ((eta + 2) * (eta + 3)), m.abs_mean, 1.0 / (eta + 2),
                    m.below, 0.5, d, p, worst);
            else
                fmt::print("mutation-delta,{},{},{},{:.6f},,{:.7f},,{:.6f},,{:.6f},,{:.3g},{:.3g},{}\n", s.name, form,
                           n, m.mean, m.var, m.abs_mean, m.below, d, p, worst);
        }
    }
}

void timing(int rounds) {
    // SBX's root arguments: alpha u and 1 / (2 - alpha u) for u in [0, 1), alpha in (1, 2].
    Rng rng(7);
    constexpr std::size_t kValues = 4096;
    std::vector<double> args(kValues), work(kValues);
    for (double& v : args) {
        const double u = rng.uniform(), alpha = 1.0 + rng.uniform();
        v = u * alpha <= 1.0 ? u * alpha : 1.0 / (2.0 - u * alpha);
    }
    double sink = 0.0;
    const auto row = [&](const char* what, const std::function<void(std::vector<double>&)>& f) {
        fmt::print("{},{:.2f}\n", what, least_ns(rounds, kValues, [&] {
                       work = args;
                       f(work);
                       sink += work[kValues / 2];
                   }));
    };
    fmt::print("what,ns_per_value\n");
    row("copy only", [](std::vector<double>&) {});
    const FixedPower root16(1.0 / 16.0), root21(1.0 / 21.0);
    row("16th root: FixedPower::apply (4 square roots, 4 lanes)", [&](std::vector<double>& v) { root16.apply(v); });
#ifdef PRIDE_ROOTS_AVX
    if (detail::roots_avx_supported()) {
        row("16th root: root16_float (8 lanes, 1 Halley step)",
            [&](std::vector<double>& v) { root16_float_avx(v.data(), v.size()); });
        // The lanes' bits against the scalar form's (the claim that a value's bits do not depend
        // on its lane), on the arguments and on 2^-40 .. 2^40.
        std::vector<double> xs = args;
        for (int e = -40; e <= 40; ++e) xs.push_back(std::ldexp(1.0 + 0.37 * (e + 40) / 80.0, e));
        std::vector<double> lanes = xs;
        root16_float_avx(lanes.data(), lanes.size());
        std::size_t differ = 0;
        for (std::size_t i = 0; i < xs.size(); ++i)
            differ += std::bit_cast<std::uint64_t>(lanes[i]) != std::bit_cast<std::uint64_t>(root16_float(xs[i]));
        fmt::print("root16_float: values whose 8-lane bits differ from the scalar form's (of {}),{}\n", xs.size(),
                   differ);
    }
#endif
    row("16th root: root_halley (scalar, 4 Halley steps)", [&](std::vector<double>& v) {
        for (double& x : v) x = root_halley(x, 16);
    });
    row("21st root: std::pow (scalar)", [&](std::vector<double>& v) {
        for (double& x : v) x = root21(x);
    });
    row("21st root: root_halley (scalar, 4 Halley steps)", [&](std::vector<double>& v) {
        for (double& x : v) x = root_halley(x, 21);
    });
    row("21st root: exp(log(x) / 21) (scalar)", [&](std::vector<double>& v) {
        for (double& x : v) x = std::exp(std::log(x) / 21.0);
    });
    row("16th root: Eigen exp(log(x) / 16) (packets)", [&](std::vector<double>& v) {
        Eigen::Map<Eigen::ArrayXd> a(v.data(), static_cast<Eigen::Index>(v.size()));
        a = (a.log() * (1.0 / 16.0)).exp();
    });
    if (sink == 42.0) fmt::print(stderr, "\n");  // keeps the work
}

}  // namespace

int main(int argc, char** argv) {
    int rounds = 200;
    std::int64_t draws = 0;
    CLI::App app{
        "the GA's roots: cost per value of each form (CSV what,ns_per_value); with --draws, the "
        "candidates' output distributions against the exact roots'"};
    app.add_option("--rounds", rounds, "repetitions of each timing; the least is printed (default 200)")
        ->check(CLI::Range(1, 100000));
    app.add_option("--draws", draws, "instead: this many draws per operator, setting and form (1e6)")
        ->check(CLI::Range(std::int64_t{1000}, std::int64_t{100'000'000}));
    CLI11_PARSE(app, argc, argv);
    if (draws > 0)
        distribution(draws);
    else
        timing(rounds);
    return 0;
}

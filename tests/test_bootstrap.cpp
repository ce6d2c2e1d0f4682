// COCO's simulated restarts, the ERT's spread and bootstrap interval, and the ECDF with simulated
// restarts (experiment/report/bootstrap.hpp): exact properties, hand-worked cases, and a
// statistical comparison with cocopp's own functions on the same data.
//
// The cocopp numbers below were printed by
//     /usr/bin/python3 scripts/cocopp_bootstrap_reference.py
// (cocopp from numbbo/coco-postprocess's source, run unmodified on Debian 12's numpy 1.24.2;
// toolsstats.drawSP, toolsstats.draw with func=sp, toolsstats.prctile, and pprldmany's recipe
// for its ECDF). cocopp samples from numpy's generator and pride from its own, so the samples
// differ and are compared statistically: distributions by a two-sample Kolmogorov-Smirnov bound
// at alpha = 0.001 (c = sqrt(-ln(alpha/2)/2) = 1.949; Smirnov 1948), checked at fixed points,
// and percentiles by the bracket that bound implies.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <vector>

#include "experiment/report/bootstrap.hpp"
#include "framework/error.hpp"

namespace {

using pride::report::coco::TargetRun;
constexpr double inf = std::numeric_limits<double>::infinity();

/// Runs on one target: `hits` reached it (after so many evaluations, of `budget`), `fails` did
/// not (all their evaluations).
std::vector<TargetRun> runs_of(const std::vector<std::int64_t>& hits, const std::vector<std::int64_t>& fails,
                               std::int64_t budget, std::int64_t dim = 1) {
    std::vector<TargetRun> runs;
    for (const auto h : hits) runs.push_back({budget, h, dim});
    for (const auto f : fails) runs.push_back({f, std::nullopt, dim});
    return runs;
}

/// The data of scripts/cocopp_bootstrap_reference.py: 15 runs, 5 of which reached the target.
const std::vector<std::int64_t> hits{230, 410, 415, 980, 1200};
const std::vector<std::int64_t> fails{3000, 3000, 3000, 2500, 1800, 3200, 2900, 3000, 3000, 2750};

/// Fraction of the ascending `sorted` at most t.
double cdf_at(const std::vector<double>& sorted, double t) {
    return static_cast<double>(std::upper_bound(sorted.begin(), sorted.end(), t) - sorted.begin()) /
           static_cast<double>(sorted.size());
}

/// Two-sample KS critical distance at alpha = 0.001 for samples of n and m.
double ks_bound(double n, double m) {
    return 1.949 * std::sqrt((n + m) / (n * m));
}

/// The ECDF step function at x = b: the y of the last point at or before b, 0 before the first.
double ecdf_at(const pride::report::coco::Ecdf& e, double b) {
    double y = 0;
    for (std::size_t k = 0; k < e.x.size() && e.x[k] <= b + 1e-12; ++k) y = e.y[k];
    return y;
}

}  // namespace

TEST_CASE("bootstrap: balanced sample sizes are cocopp's bootstrap_sample_size", "[report][bootstrap]") {
    using pride::report::coco::balanced_sample_size;
    CHECK(balanced_sample_size(1000, 15) == 1005);  // ceil(1000 / 15) * 15
    CHECK(balanced_sample_size(30, 15) == 30);
    CHECK(balanced_sample_size(10, 15) == 15);  // at least one of each run
    CHECK(balanced_sample_size(0, 15) == 15);
    CHECK(balanced_sample_size(7, 0) == 7);
}

TEST_CASE("bootstrap: percentiles are cocopp's prctile (numpy's Hazen percentile)", "[report][bootstrap]") {
    using pride::report::coco::percentile;
    // scripts/cocopp_bootstrap_reference.py: toolsstats.prctile([3, 1, 4, 1, 5, 9, 2, 6], ps) and
    // numpy.percentile(..., method="hazen") both print these.
    const std::vector<double> x{1, 1, 2, 3, 4, 5, 6, 9};
    const std::vector<std::pair<double, double>> expected{{0, 1.0},  {5, 1.0},  {10, 1.0}, {25, 1.5}, {50, 3.5},
                                                          {75, 5.5}, {90, 8.1}, {95, 9.0}, {100, 9.0}};
    for (const auto& [p, v] : expected) CHECK(percentile(x, p) == Approx(v).epsilon(1e-14));
    // By hand: {1, 2, 3, 4} at 50 sits at position 1.5, half way between 2 and 3.
    CHECK(percentile(std::vector<double>{1, 2, 3, 4}, 50) == 2.5);
    // +inf: at an exact position it is that value; interpolating towards it gives +inf, never NaN.
    const std::vector<double> with_inf{1, 2, inf};
    CHECK(percentile(with_inf, 50) == 2.0);  // position 3 * 0.5 - 0.5 = 1 exactly
    CHECK(percentile(with_inf, 60) == inf);
    CHECK(percentile(with_inf, 0) == 1.0);
    CHECK(std::isnan(percentile(std::vector<double>{}, 50)));
}

TEST_CASE("bootstrap: all runs successful: every simulated runtime is a hit, each equally often",
          "[report][bootstrap]") {
    const auto runs = runs_of({5, 7, 11}, {}, 20);
    const auto t = pride::report::coco::simulated_runtimes(runs, 30, 1);
    REQUIRE(t.size() == 30);
    CHECK(std::is_sorted(t.begin(), t.end()));
    std::map<double, int> count;
    for (double v : t) ++count[v];
    // The first draws are permutations of the runs (cocopp's randint_derandomized): 30 = 10 * 3.
    CHECK(count == std::map<double, int>{{5, 10}, {7, 10}, {11, 10}});
}

TEST_CASE("bootstrap: no run reached the target: no simulated runtime, infinite ERT and spread",
          "[report][bootstrap]") {
    using namespace pride::report::coco;
    const auto runs = runs_of({}, {100, 200}, 0);
    CHECK(simulated_runtimes(runs, 100, 1).empty());
    CHECK(simulated_runtimes({}, 100, 1).empty());
    const ErtSpread s = ert_spread(runs, 100, 1);
    CHECK(s.ert.value == inf);
    CHECK(s.samples == 0);
    CHECK(s.runtimes.p10 == inf);
    CHECK(s.runtimes.p50 == inf);
    CHECK(s.runtimes.p90 == inf);
    const Percentiles c = ert_confidence(runs, 50, 1);
    CHECK((c.p10 == inf && c.p50 == inf && c.p90 == inf));
    const Percentiles none = ert_confidence({}, 50, 1);
    CHECK(none.p50 == inf);
    CHECK(simulated_runtimes(runs_of({5}, {}, 10), 0, 1).empty());  // nothing asked, nothing drawn
}

TEST_CASE("bootstrap: two runs worked by hand", "[report][bootstrap]") {
    // Run A reached the target after 10 of its 100 evaluations, run B spent 50 without. A simulated
    // runtime is 10 + 50 G, G the number of times B is drawn before A: P(G = g) = 2^-(g + 1).
    // The first draws alternate by permutation, so exactly half of the runtimes are 10.
    // ERT = (10 + 50) / 1 = 60 = 10 + 50 E[G].
    const auto runs = runs_of({10}, {50}, 100);
    const std::size_t n = 10000;
    const auto t = pride::report::coco::simulated_runtimes(runs, n, 7);
    REQUIRE(t.size() == n);
    CHECK(std::count(t.begin(), t.end(), 10.0) == static_cast<std::ptrdiff_t>(n / 2));
    CHECK(std::all_of(t.begin(), t.end(), [](double v) { return std::fmod(v - 10.0, 50.0) == 0.0; }));
    // Among the n/2 that start with B, P(G = 1) = 1/2 given G >= 1: binomial(5000, 1/2), sd 35.4.
    const auto sixty = static_cast<double>(std::count(t.begin(), t.end(), 60.0));
    CHECK(std::abs(sixty - 2500.0) < 5 * 35.4);
    CHECK(pride::report::coco::ert(runs).value == 60.0);
}

TEST_CASE("bootstrap: the mean of simulated runtimes is the ERT", "[report][bootstrap]") {
    // E[T] = E[S] + E[G] E[U] = ERT, where S is a successful run's hit, U an unsuccessful run's
    // evaluations and G ~ geometric (failures before the first success, p = successes / runs):
    // E[G] = (1 - p) / p, Var[G] = (1 - p) / p^2, so
    //     Var[T] = Var[S] + E[G] Var[U] + Var[G] E[U]^2
    // (the variance of a random sum, Wald). Drawn independently, the mean of n runtimes has sd
    // sqrt(Var[T] / n); cocopp's balanced first draws only lower it. Tolerance: 5 sd.
    const auto runs = runs_of(hits, fails, 3000);
    const auto mean_var = [](const std::vector<std::int64_t>& v) {
        double m = 0, s = 0;
        for (auto x : v) m += static_cast<double>(x);
        m /= static_cast<double>(v.size());
        for (auto x : v) s += (static_cast<double>(x) - m) * (static_cast<double>(x) - m);
        return std::pair{m, s / static_cast<double>(v.size())};
    };
    const auto [es, vs] = mean_var(hits);
    const auto [eu, vu] = mean_var(fails);
    const double p = 5.0 / 15.0, eg = (1 - p) / p, vg = (1 - p) / (p * p);
    const double ert = pride::report::coco::ert(runs).value;
    CHECK(ert == 6277.0);  // cocopp's toolsstats.sp on the same data: 6277.0
    CHECK(es + eg * eu == Approx(ert).epsilon(1e-14));
    const double var = vs + eg * vu + vg * eu * eu;
    for (const std::size_t n : {1000u, 100000u}) {
        const auto t = pride::report::coco::simulated_runtimes(runs, n, 11);
        double mean = 0;
        for (double v : t) mean += v;
        mean /= static_cast<double>(n);
        INFO("n = " << n << ", mean " << mean << ", ERT " << ert << ", sd of the mean " << std::sqrt(var / n));
        CHECK(std::abs(mean - ert) < 5 * std::sqrt(var / static_cast<double>(n)));
    }
}

TEST_CASE("bootstrap: a seed gives the same numbers, another seed others", "[report][bootstrap]") {
    using namespace pride::report::coco;
    const auto runs = runs_of(hits, fails, 3000);
    CHECK(simulated_runtimes(runs, 500, 3) == simulated_runtimes(runs, 500, 3));
    CHECK(simulated_runtimes(runs, 500, 3) != simulated_runtimes(runs, 500, 4));
    const Percentiles a = ert_confidence(runs, 500, 3), b = ert_confidence(runs, 500, 3);
    CHECK((a.p10 == b.p10 && a.p50 == b.p50 && a.p90 == b.p90));
    std::vector<std::vector<TargetRun>> pairs{runs, runs_of({40, 60}, {200}, 200, 2)};
    const Ecdf e1 = ecdf_simulated_restarts(pairs, 100, 9), e2 = ecdf_simulated_restarts(pairs, 100, 9);
    CHECK((e1.x == e2.x && e1.y == e2.y));
}

TEST_CASE("bootstrap: simulated runtimes agree with cocopp's drawSP", "[report][bootstrap][cocopp]") {
    const auto runs = runs_of(hits, fails, 3000);
    const std::size_t n = 100000;  // as many as the reference drew
    const auto t = pride::report::coco::simulated_runtimes(runs, n, 1);
    // drawSP n=100000 (np.random.seed(1)): CDF at these thresholds.
    const std::vector<std::pair<double, double>> reference{
        {230, 0.06667},  {415, 0.19999},  {1200, 0.33333}, {2000, 0.33333}, {3500, 0.47021},
        {5000, 0.56146}, {7000, 0.68527}, {10000, 0.7931}, {15000, 0.8928}, {25000, 0.97532}};
    const double bound = ks_bound(static_cast<double>(n), 100000.0);  // 0.0087
    for (const auto& [threshold, f] : reference) {
        INFO("threshold " << threshold);
        CHECK(std::abs(cdf_at(t, threshold) - f) <= bound);
    }
    // The table's percentiles: within the reference's percentiles at p -+ 100 * bound (the script
    // prints them), as a KS distance below the bound implies.
    const auto s = pride::report::coco::ert_spread(runs, n, 1);
    CHECK(s.ert.value == 6277.0);
    CHECK(s.samples == n);
    CHECK(s.runtimes.p10 == 410.0);   // reference bracket [410, 410]; its p10: 410
    CHECK(s.runtimes.p50 >= 3880.0);  // reference bracket [3880, 3980]; its p50: 3980
    CHECK(s.runtimes.p50 <= 3980.0);
    CHECK(s.runtimes.p90 >= 14930.0);  // reference bracket [14930, 15860]; its p90: 15365
    CHECK(s.runtimes.p90 <= 15860.0);
    CHECK(s.half_range() == Approx((s.runtimes.p90 - 410.0) / 2));
}

TEST_CASE("bootstrap: the ERT's bootstrap interval agrees with cocopp's draw(func=sp)", "[report][bootstrap][cocopp]") {
    using namespace pride::report::coco;
    const auto runs = runs_of(hits, fails, 3000);
    const std::size_t m = 20000;
    // draw(data, [10, 50, 90], samplesize=20000, func=sp) (np.random.seed(2)): percentiles
    // 3579.29, 6338, 12425; brackets at p -+ 1.949 (a KS bound for two samples of 20000):
    // [3317.75, 3735], [6267, 6398], [12203.33, 17060.75].
    const Percentiles c = ert_confidence(runs, m, 5);
    CHECK(c.p10 >= 3317.75);
    CHECK(c.p10 <= 3735.0);
    CHECK(c.p50 >= 6267.0);
    CHECK(c.p50 <= 6398.0);
    CHECK(c.p90 >= 12203.3);
    CHECK(c.p90 <= 17060.8);
    CHECK(c.p10 < 6277.0);  // the interval holds the ERT of the data
    CHECK(c.p90 > 6277.0);
}

TEST_CASE("bootstrap: the ECDF with simulated restarts agrees with cocopp's pprldmany", "[report][bootstrap][cocopp]") {
    using namespace pride::report::coco;
    // The pairs of the script: (dim, hits, evaluations of the runs that missed); the budgets of the
    // successful runs (not in cocopp's input) only set max_budget.
    const std::vector<std::vector<TargetRun>> pairs{
        runs_of({40, 60, 80, 100}, {200}, 200, 2),
        runs_of({150}, {200, 200, 180, 200}, 200, 2),
        runs_of({500, 700, 900, 1100, 1300, 1500}, {}, 2000, 5),
        runs_of({}, {2000, 2000, 2000, 2000, 2000, 2000}, 2000, 5),
        runs_of({3000, 4000}, {10000, 10000, 8000}, 10000, 10),
        runs_of({9000}, {10000, 10000, 10000, 8000}, 10000, 10),
    };
    const std::size_t m = 10000;
    const Ecdf e = ecdf_simulated_restarts(pairs, m, 3);
    CHECK(e.pairs == 6);
    CHECK(e.max_budget == 3.0);  // log10(10000 / 10)
    CHECK(std::is_sorted(e.x.begin(), e.x.end()));
    CHECK(std::is_sorted(e.y.begin(), e.y.end()));
    CHECK(e.y.back() == 5.0 / 6.0);  // pair 4 reached nothing: its 10000 entries stay unreached
    // pprldmany's ECDF (np.random.seed(3)) at log10(evaluations / dimension) = b. Each y is a mean
    // over the 6 pairs of the fraction of m draws at most 10^b; its variance is at most
    // (1/4) (1/m) / 6 for either sample, so the difference has sd at most sqrt((2/m) / 24): 4 sd
    // for 11 points.
    const std::vector<std::pair<double, double>> reference{{1.0, 0.0},
                                                           {1.5, 0.06666666666666667},
                                                           {1.8, 0.13333333333333333},
                                                           {2.0, 0.19445},
                                                           {2.3, 0.30301666666666666},
                                                           {2.5, 0.44643333333333335},
                                                           {2.8, 0.5235333333333333},
                                                           {3.0, 0.5825},
                                                           {3.3, 0.6646833333333333},
                                                           {3.6, 0.7450166666666667},
                                                           {4.0, 0.8160333333333334}};
    const double tolerance = 4 * std::sqrt((2.0 / static_cast<double>(m)) / 24.0);  // 0.0115
    for (const auto& [b, y] : reference) {
        INFO("log10 budget " << b);
        CHECK(std::abs(ecdf_at(e, b) - y) <= tolerance);
    }
}

TEST_CASE("bootstrap: with every run successful the simulated ECDF is the plain ECDF", "[report][bootstrap]") {
    using namespace pride::report::coco;
    const std::vector<std::vector<TargetRun>> pairs{runs_of({3, 9, 27}, {}, 50, 3), runs_of({10, 20, 40}, {}, 50, 2)};
    std::vector<TargetRun> all;
    for (const auto& p : pairs) all.insert(all.end(), p.begin(), p.end());
    const Ecdf plain = ecdf(all);
    const Ecdf simulated = ecdf_simulated_restarts(pairs, 12, 4);  // 12: a multiple of 3 runs
    CHECK(simulated.x == plain.x);
    CHECK(simulated.y == plain.y);
    CHECK(simulated.max_budget == plain.max_budget);
    CHECK(simulated.pairs == 2);
}

TEST_CASE("bootstrap: the ECDF refuses a pair whose runs have different dimensions", "[report][bootstrap]") {
    std::vector<TargetRun> mixed = runs_of({3}, {}, 10, 2);
    mixed.push_back({10, 4, 5});
    CHECK_THROWS_AS(pride::report::coco::ecdf_simulated_restarts({mixed}, 10, 1), pride::InputError);
    // A pair without runs counts as unreached.
    const auto e = pride::report::coco::ecdf_simulated_restarts({runs_of({10}, {}, 10), {}}, 4, 1);
    CHECK(e.y == std::vector<double>{0.5});
    CHECK(e.x == std::vector<double>{1.0});
}

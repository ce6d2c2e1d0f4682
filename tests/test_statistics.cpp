// The statistics of experiment/report/statistics.hpp against scipy 1.10.1 (Debian's python3-scipy) on
// fixed data; scripts/statistics_reference.py prints the values hard-coded here.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "experiment/report/statistics.hpp"
#include "framework/error.hpp"

namespace {
const std::vector<double> x{0.31, 1.2, 0.05, 2.4, 0.77, 1.9, 0.42, 3.3, 0.9, 1.1};
const std::vector<double> y{1.5, 2.2, 0.95, 3.1, 2.8, 1.7, 4.0, 2.5, 1.35, 2.9};
const std::vector<double> t1{12, 12, 13, 12, 14, 12, 13, 12, 12, 15};
const std::vector<double> t2{12, 13, 13, 14, 14, 13, 15, 12, 16, 14, 13, 13};
}  // namespace

TEST_CASE("statistics: average ranks share tied ranks", "[statistics]") {
    const std::vector<double> v{3.0, 1.0, 3.0, 2.0, 3.0};
    const auto r = pride::stats::average_ranks(v);
    CHECK(r == std::vector<double>{4.0, 1.0, 4.0, 2.0, 4.0});
}

TEST_CASE("statistics: the sample standard deviation of values whose squares overflow", "[statistics]") {
    // Deviations of 1e200 (CEC 2017's F2 early in a run reaches 1e166): the squares overflow, not the
    // deviation. By hand: mean 0, deviations +-1e200 and 0, sum of squares 2e400 over n - 1 = 2.
    const std::vector<double> v{1e200, -1e200, 0.0};
    CHECK(pride::stats::sample_std(v) == Approx(1e200).epsilon(1e-15));
    const std::vector<double> w{3e160, 3e160, 3e160, 3e160 + 4e160};
    CHECK(pride::stats::sample_std(w) == Approx(2e160).epsilon(1e-15));  // sqrt((3 x 1e320 + 9e320) / 3)
    CHECK(pride::stats::sample_std(std::vector<double>{1.0, 2.0, 4.0}) == Approx(std::sqrt(7.0 / 3.0)));
}

TEST_CASE("statistics: rank-sum test equals scipy's mannwhitneyu (asymptotic)", "[statistics]") {
    const auto a = pride::stats::rank_sum_test(x, y);
    CHECK(a.u == 20.0);
    CHECK(a.p_value == Approx(0.025748080821108063).epsilon(1e-12));
    const auto b = pride::stats::rank_sum_test(y, x);  // symmetric p, complementary U
    CHECK(b.u == 80.0);
    CHECK(b.p_value == Approx(0.025748080821108063).epsilon(1e-12));
    const auto tied = pride::stats::rank_sum_test(t1, t2);  // many ties: the tie correction matters
    CHECK(tied.u == 34.0);
    CHECK(tied.p_value == Approx(0.07874119697697302).epsilon(1e-12));
}

TEST_CASE("statistics: rank-sum test edge cases", "[statistics]") {
    const std::vector<double> same{5, 5, 5};
    CHECK(pride::stats::rank_sum_test(same, same).p_value == 1.0);  // all tied: no evidence
    const std::vector<double> empty;
    CHECK_THROWS_AS(pride::stats::rank_sum_test(empty, same), pride::InputError);
    const std::vector<double> nan{1.0, std::nan("")};
    CHECK_THROWS_AS(pride::stats::rank_sum_test(nan, same), pride::InputError);
}

TEST_CASE("statistics: Holm's adjustment worked by hand", "[statistics]") {
    // sorted 0.01, 0.02, 0.03, 0.5 times 4, 3, 2, 1 = 0.04, 0.06, 0.06, 0.5 (made non-decreasing)
    const std::vector<double> p{0.03, 0.5, 0.01, 0.02};
    const auto h = pride::stats::holm(p);
    CHECK(h[2] == Approx(0.04));
    CHECK(h[3] == Approx(0.06));
    CHECK(h[0] == Approx(0.06));
    CHECK(h[1] == Approx(0.5));
    const std::vector<double> big{0.4, 0.6};
    CHECK(pride::stats::holm(big) == std::vector<double>{0.8, 0.8});  // monotone
}

TEST_CASE("statistics: Holm's adjusted p-values are capped at 1", "[statistics]") {
    // 0.6 * 2 = 1.2 and 0.7 * 1 = 0.7, made non-decreasing (1.2, 1.2): both are 1 after the cap.
    // Without the cap the first would be 1.2, which no probability is.
    CHECK(pride::stats::holm(std::vector<double>{0.6, 0.7}) == std::vector<double>{1.0, 1.0});
    CHECK(pride::stats::holm(std::vector<double>{0.7, 0.6}) == std::vector<double>{1.0, 1.0});
    const auto h = pride::stats::holm(std::vector<double>{0.01, 0.3, 0.9});  // 0.03, 0.6, 0.9
    CHECK(h[0] == Approx(0.03));
    CHECK(h[1] == Approx(0.6));
    CHECK(h[2] == Approx(0.9));
    for (const double v : pride::stats::holm(std::vector<double>{0.2, 0.4, 0.5, 0.9})) CHECK(v <= 1.0);
}

TEST_CASE("statistics: Friedman test equals scipy's friedmanchisquare", "[statistics]") {
    const std::vector<std::vector<double>> blocks{
        {3.2, 1.1, 2.5, 4.0}, {0.5, 0.7, 0.6, 0.9}, {10.0, 8.0, 8.0, 12.0},
        {1.0, 2.0, 3.0, 4.0}, {7.5, 7.5, 7.5, 6.0}, {0.01, 0.02, 0.005, 0.03},
    };
    const auto f = pride::stats::friedman(blocks);
    CHECK(f.statistic == Approx(5.290909090909101).epsilon(1e-12));
    CHECK(f.p_value == Approx(0.15169337530933427).epsilon(1e-12));
    REQUIRE(f.average_ranks.size() == 4);
    CHECK(f.average_ranks[0] == Approx(2.1666666666666665));
    CHECK(f.average_ranks[1] == Approx(2.25));
    CHECK(f.average_ranks[2] == Approx(2.0833333333333335));
    CHECK(f.average_ranks[3] == Approx(3.5));
    const std::vector<std::vector<double>> ragged{{1, 2}, {1}};
    CHECK_THROWS_AS(pride::stats::friedman(ragged), pride::InputError);
}

TEST_CASE("statistics: Vargha-Delaney A from scipy's Mann-Whitney U and by hand", "[statistics]") {
    using pride::stats::vargha_delaney_a;
    // scipy.stats.mannwhitneyu(x, y).statistic = U_x = the pairs with x > y plus half the ties
    // (20 and 34 above), so the chance that x is the smaller is 1 - U_x / (n m).
    CHECK(vargha_delaney_a(x, y) == Approx(1.0 - 20.0 / 100.0).epsilon(1e-15));
    CHECK(vargha_delaney_a(t1, t2) == Approx(1.0 - 34.0 / 120.0).epsilon(1e-15));
    CHECK(vargha_delaney_a(y, x) + vargha_delaney_a(x, y) == Approx(1.0).epsilon(1e-15));
    CHECK(vargha_delaney_a(t2, t1) + vargha_delaney_a(t1, t2) == Approx(1.0).epsilon(1e-15));
    // By hand: {1,2,3} against {2,2,4}: 1 < 2, 1 < 2, 1 < 4, 2 < 4, 3 < 4 and two ties: 6 / 9.
    CHECK(vargha_delaney_a(std::vector<double>{1, 2, 3}, std::vector<double>{2, 2, 4}) == Approx(6.0 / 9.0));
    CHECK(vargha_delaney_a(std::vector<double>{5, 5}, std::vector<double>{5}) == 0.5);  // no effect
    CHECK(vargha_delaney_a(std::vector<double>{0}, std::vector<double>{1, 2}) == 1.0);
    CHECK(std::isnan(vargha_delaney_a(std::vector<double>{}, std::vector<double>{1})));
}

TEST_CASE("statistics: Friedman post-hoc pairs, by hand and against scipy's normal", "[statistics]") {
    // k = 3 over N = 10 blocks: se = sqrt(3 x 4 / 60) = sqrt(0.2). Ranks 1.5, 2, 2.5: z = -1.118,
    // -2.236, -1.118; scipy.stats.norm.sf gives p = 0.2635524772829727 and 0.025347318677468252.
    const std::vector<double> ranks{1.5, 2.0, 2.5};
    const auto pairs = pride::stats::friedman_pairs(ranks, 10);
    REQUIRE(pairs.size() == 3);
    CHECK(pairs[0].a == 0);
    CHECK(pairs[0].b == 1);
    CHECK(pairs[1].b == 2);
    CHECK(pairs[1].z == Approx(-2.23606797749979).epsilon(1e-12));
    CHECK(pairs[0].p == Approx(0.2635524772829727).epsilon(1e-12));
    CHECK(pairs[1].p == Approx(0.025347318677468252).epsilon(1e-12));
    CHECK(pairs[2].p == Approx(0.2635524772829727).epsilon(1e-12));
    // Holm over 3: 3 x 0.02535 = 0.07604; then 2 x 0.26355 = 0.5271 for both others.
    CHECK(pairs[1].p_holm == Approx(3 * 0.025347318677468252).epsilon(1e-12));
    CHECK(pairs[0].p_holm == Approx(2 * 0.2635524772829727).epsilon(1e-12));
    CHECK(pairs[2].p_holm == Approx(2 * 0.2635524772829727).epsilon(1e-12));
}

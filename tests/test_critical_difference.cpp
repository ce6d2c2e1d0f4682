// The critical-difference statistics of experiment/report/critical_difference.hpp against
// J. Demsar, "Statistical comparisons of classifiers over multiple data sets", JMLR 7:1-30 (2006):
// his table 5a and his worked example (sections 3.2.2 and 3.2.4, the four variants of C4.5), and against
// scipy 1.10.1's studentized_range (Debian's python3-scipy): scripts/critical_difference_reference.py
// prints the values hard-coded here.
#include <boost/math/distributions/normal.hpp>
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "experiment/report/critical_difference.hpp"
#include "experiment/report/statistics.hpp"
#include "framework/error.hpp"

using pride::stats::nemenyi_q;

TEST_CASE("critical difference: Nemenyi's q_alpha is Demsar's table 5a", "[statistics][critical-difference]") {
    // Demsar's table prints 3 decimals of the studentized range's 3-decimal tables divided by
    // sqrt(2) (so 2.343 for 3.314 / sqrt(2) = 2.3434, where the exact value is 2.34370): within 1e-3.
    const std::vector<double> q05{1.960, 2.343, 2.569, 2.728, 2.850, 2.949, 3.031, 3.102, 3.164};
    const std::vector<double> q10{1.645, 2.052, 2.291, 2.459, 2.589, 2.693, 2.780, 2.855, 2.920};
    for (std::size_t k = 2; k <= 10; ++k) {
        INFO("k = " << k);
        CHECK(std::abs(nemenyi_q(0.05, k) - q05[k - 2]) <= 1e-3);
        CHECK(std::abs(nemenyi_q(0.10, k) - q10[k - 2]) <= 1e-3);
    }
}

TEST_CASE("critical difference: the studentized range equals scipy's", "[statistics][critical-difference]") {
    struct Case {
        double alpha;
        std::size_t k;
        double q;  // scipy.stats.studentized_range.ppf(1 - alpha, k, inf)
    };
    const std::vector<Case> cases{
        {0.01, 2, 3.642772735436894},  {0.01, 5, 4.602821042201571},   {0.01, 10, 5.156634960089622},
        {0.01, 50, 6.228392608582205}, {0.05, 3, 3.314493155398122},   {0.05, 7, 4.169554155006547},
        {0.05, 15, 4.795923860431186}, {0.05, 20, 5.0116887941184425}, {0.10, 4, 3.240446220927359},
        {0.10, 9, 4.037023130237707},  {0.10, 50, 5.356686875267444}};
    for (const auto& c : cases) {
        INFO("alpha = " << c.alpha << ", k = " << c.k);
        CHECK(pride::stats::studentized_range_quantile(c.alpha, c.k) == Approx(c.q).epsilon(1e-10));
        CHECK(nemenyi_q(c.alpha, c.k) == Approx(c.q / std::sqrt(2.0)).epsilon(1e-10));
    }
    struct Point {
        double q;
        std::size_t k;
        double cdf;  // scipy.stats.studentized_range.cdf(q, k, inf)
    };
    for (const auto& p : std::vector<Point>{{1.0, 2, 0.5204998778130465},
                                            {3.0, 3, 0.9144574283450421},
                                            {2.5, 5, 0.6074572367587359},
                                            {4.0, 10, 0.8731478678494035},
                                            {5.5, 20, 0.9851716833094663}}) {
        INFO("q = " << p.q << ", k = " << p.k);
        CHECK(pride::stats::studentized_range_cdf(p.q, p.k) == Approx(p.cdf).epsilon(1e-10));
    }
}

TEST_CASE("critical difference: two treatments reduce to the normal quantile", "[statistics][critical-difference]") {
    // The range of two N(0, 1) is |Z1 - Z2| = sqrt(2) |N(0, 1)|, so q_alpha = z_{1 - alpha/2}
    // exactly: the Nemenyi test of two treatments is the z test of friedman_pairs.
    const boost::math::normal normal;
    for (const double alpha : {0.01, 0.05, 0.10, 0.2}) {
        INFO("alpha = " << alpha);
        CHECK(nemenyi_q(alpha, 2) == Approx(boost::math::quantile(normal, 1 - alpha / 2)).epsilon(1e-12));
    }
    CHECK(pride::stats::studentized_range_cdf(0.0, 4) == 0.0);
    CHECK(pride::stats::studentized_range_cdf(30.0, 4) == Approx(1.0).epsilon(1e-15));
    CHECK_THROWS_AS(pride::stats::studentized_range_cdf(1.0, 1), pride::InputError);
    CHECK_THROWS_AS(pride::stats::studentized_range_quantile(0.0, 3), pride::InputError);
    CHECK_THROWS_AS(pride::stats::studentized_range_quantile(1.0, 3), pride::InputError);
}

TEST_CASE("critical difference: Demsar's worked example, four variants of C4.5 on 14 data sets",
          "[statistics][critical-difference]") {
    // Demsar 2006, section 3.2.2: average ranks of C4.5, C4.5+m, C4.5+cf, C4.5+m+cf; "CD = 2.569
    // sqrt(4 * 5 / (6 * 14)) = 1.25" at alpha = 0.05 and 1.12 at alpha = 0.10, where C4.5+m+cf is
    // better than C4.5 (3.143 - 1.964 = 1.179 > 1.12) and no other pair differs.
    const std::vector<double> ranks{3.143, 2.000, 2.893, 1.964};
    const auto at05 = pride::stats::critical_difference(ranks, 14, 0.05);
    CHECK(at05.cd == Approx(1.25).margin(0.005));
    CHECK(at05.cd == Approx(2.569031772546482 * std::sqrt(20.0 / 84.0)).epsilon(1e-12));  // scipy's q
    // One bar over all four: no pair differs at 0.05.
    CHECK(at05.cliques == std::vector<std::vector<std::size_t>>{{3, 1, 2, 0}});
    const auto at10 = pride::stats::critical_difference(ranks, 14, 0.10);
    CHECK(at10.cd == Approx(1.12).margin(0.005));
    // Two bars: {C4.5+m+cf, C4.5+m, C4.5+cf} and {C4.5+cf, C4.5}: only C4.5+m+cf and C4.5 are
    // joined by none, the one difference Demsar finds.
    CHECK(at10.cliques == std::vector<std::vector<std::size_t>>{{3, 1, 2}, {2, 0}});
    // The same difference through the post-hoc z of statistics.hpp: |z| = 1.179 / sqrt(20 / 84).
    const auto pairs = pride::stats::friedman_pairs(ranks, 14);
    CHECK(std::abs(pairs[2].z) == Approx(1.179 / std::sqrt(20.0 / 84.0)).epsilon(1e-12));  // pair (0, 3)
}

TEST_CASE("critical difference: cliques worked by hand", "[statistics][critical-difference]") {
    using pride::stats::critical_difference_cliques;
    using Cliques = std::vector<std::vector<std::size_t>>;
    // All far apart: no bar.
    CHECK(critical_difference_cliques(std::vector<double>{1, 2, 3}, 0.5).empty());
    // A difference of exactly CD is significant (Demsar: "differ by at least the critical difference").
    CHECK(critical_difference_cliques(std::vector<double>{1, 2}, 1.0).empty());
    // All tied: one bar.
    CHECK(critical_difference_cliques(std::vector<double>{2, 2, 2}, 0.1) == Cliques{{0, 1, 2}});
    // {1, 1.2, 1.4} in one bar; {1.2, 1.4} lies inside it and is not drawn again; 3 stands alone.
    CHECK(critical_difference_cliques(std::vector<double>{3, 1.4, 1.2, 1}, 0.5) == Cliques{{3, 2, 1}});
    // Overlapping bars: 1-1.6, 1.6-2.4 (1.6 within 0.8 of both ends, 1 and 2.4 not).
    CHECK(critical_difference_cliques(std::vector<double>{1, 1.6, 2.4}, 0.8) == Cliques{{0, 1}, {1, 2}});
    // From Friedman's average ranks of statistics.hpp: 3 algorithms, 4 problems, the same order on
    // each: ranks 1, 2, 3; CD(0.05, k = 3, N = 4) = 2.3437 * sqrt(12 / 24) = 1.657: {1, 2}, {2, 3}.
    const std::vector<std::vector<double>> blocks{{1, 2, 3}, {4, 5, 6}, {0.1, 0.2, 0.3}, {7, 8, 9}};
    const auto f = pride::stats::friedman(blocks);
    const auto d = pride::stats::critical_difference(f.average_ranks, blocks.size(), 0.05);
    CHECK(d.cd == Approx(2.343700586378409 * std::sqrt(0.5)).epsilon(1e-12));
    CHECK(d.cliques == Cliques{{0, 1}, {1, 2}});
}

#pragma once
// The statistics a comparison of optimisers needs (the campaign report): ranks with
// ties, the Wilcoxon rank-sum (Mann-Whitney U) test, Holm's step-down correction, and Friedman's
// average ranks and test. The distributions come from Boost.Math; the formulas are those of
// scipy.stats (mannwhitneyu with method="asymptotic", friedmanchisquare), against which
// tests/test_statistics.cpp checks them on fixed data.
#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/normal.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <span>
#include <string>
#include <vector>

#include "framework/error.hpp"

namespace pride::stats {

/// The mean of `values` (not empty).
inline double mean_of(std::span<const double> values) {
    return std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
}

/// The median of `values` (not empty): the mean of the two middle values for an even count.
inline double median_of(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

/// The sample standard deviation (n - 1); 0 for a single value, +inf when a value is infinite.
inline double sample_std(std::span<const double> values) {
    if (values.size() < 2) return 0.0;
    if (std::any_of(values.begin(), values.end(), [](double x) { return std::isinf(x); }))
        return std::numeric_limits<double>::infinity();
    const double m = mean_of(values);
    double s = 0.0;
    for (const double x : values) s += (x - m) * (x - m);
    return std::sqrt(s / static_cast<double>(values.size() - 1));
}

/// Ranks 1..n of `values`, ties sharing the average of their ranks (NaN not allowed).
inline std::vector<double> average_ranks(std::span<const double> values) {
    std::vector<std::size_t> order(values.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
    std::vector<double> ranks(values.size());
    for (std::size_t i = 0; i < order.size();) {
        std::size_t j = i;
        while (j + 1 < order.size() && values[order[j + 1]] == values[order[i]]) ++j;
        const double rank = 0.5 * static_cast<double>(i + j) + 1.0;  // average of ranks i+1 .. j+1
        for (std::size_t k = i; k <= j; ++k) ranks[order[k]] = rank;
        i = j + 1;
    }
    return ranks;
}

struct RankSumTest {
    double u;        // Mann-Whitney U of the first sample
    double z;        // standardised, with tie and continuity corrections
    double p_value;  // two-sided
};

/// Wilcoxon rank-sum / Mann-Whitney U test, two-sided, normal approximation with the tie
/// correction and the continuity correction (scipy.stats.mannwhitneyu(x, y,
/// method="asymptotic", use_continuity=True)). p = 1 when every value is tied.
inline RankSumTest rank_sum_test(std::span<const double> x, std::span<const double> y) {
    require(!x.empty() && !y.empty(), "rank-sum test", "both samples must be non-empty");
    std::vector<double> all(x.begin(), x.end());
    all.insert(all.end(), y.begin(), y.end());
    for (double v : all) require(!std::isnan(v), "rank-sum test", "a sample holds NaN");
    const std::vector<double> ranks = average_ranks(all);
    const double n1 = static_cast<double>(x.size()), n2 = static_cast<double>(y.size()), n = n1 + n2;
    const double r1 = std::accumulate(ranks.begin(), ranks.begin() + static_cast<std::ptrdiff_t>(x.size()), 0.0);
    const double u = r1 - n1 * (n1 + 1.0) / 2.0;
    // Tie correction: sum over groups of tied values of (t^3 - t).
    std::vector<double> sorted = all;
    std::sort(sorted.begin(), sorted.end());
    double ties = 0.0;
    for (std::size_t i = 0; i < sorted.size();) {
        std::size_t j = i;
        while (j + 1 < sorted.size() && sorted[j + 1] == sorted[i]) ++j;
        const double t = static_cast<double>(j - i + 1);
        ties += t * t * t - t;
        i = j + 1;
    }
    const double variance = n1 * n2 / 12.0 * ((n + 1.0) - ties / (n * (n - 1.0)));
    if (!(variance > 0.0)) return {u, 0.0, 1.0};
    const double mean = n1 * n2 / 2.0;
    // scipy: the larger of U1 and U2 less half, then z.
    const double big = std::max(u, n1 * n2 - u);
    const double z = (big - mean - 0.5) / std::sqrt(variance);
    const boost::math::normal normal;
    const double p = std::min(1.0, 2.0 * boost::math::cdf(boost::math::complement(normal, z)));
    return {u, z, p};
}

/// Vargha and Delaney's A (2000, "A critique and improvement of the CL common language effect
/// size statistics of McGraw and Wong", J. Educ. Behav. Stat. 25(2)): the probability that a value
/// drawn from x is smaller (better, minimising) than one drawn from y, ties counting half; 0.5 is
/// no effect, 1 means x always better. Equals U_x / (n m), U_x the Mann-Whitney count of pairs
/// with x < y plus half the ties. A(x, y) + A(y, x) = 1. NaN for an empty sample.
inline double vargha_delaney_a(std::span<const double> x, std::span<const double> y) {
    if (x.empty() || y.empty()) return std::numeric_limits<double>::quiet_NaN();
    double wins = 0.0;
    for (const double a : x)
        for (const double b : y) wins += a < b ? 1.0 : (a == b ? 0.5 : 0.0);
    return wins / (static_cast<double>(x.size()) * static_cast<double>(y.size()));
}

/// Holm's step-down adjustment of m p-values (Holm 1979): sorted ascending, p_(i) * (m - i + 1),
/// made non-decreasing, capped at 1; returned in the input order.
inline std::vector<double> holm(std::span<const double> p) {
    const std::size_t m = p.size();
    std::vector<std::size_t> order(m);
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return p[a] < p[b]; });
    std::vector<double> adjusted(m);
    double running = 0.0;
    for (std::size_t i = 0; i < m; ++i) {
        running = std::max(running, std::min(1.0, p[order[i]] * static_cast<double>(m - i)));
        adjusted[order[i]] = running;
    }
    return adjusted;
}

struct FriedmanTest {
    std::vector<double> average_ranks;  // per treatment (algorithm), 1 = best (smallest value)
    double statistic;                   // chi-squared, with the tie correction
    double p_value;                     // from chi-squared with k - 1 degrees of freedom
};

/// Friedman's test on `blocks` (one row per block, i.e. problem; one column per treatment, i.e.
/// algorithm; smaller is better), as scipy.stats.friedmanchisquare with its tie correction.
inline FriedmanTest friedman(const std::vector<std::vector<double>>& blocks) {
    require(!blocks.empty(), "Friedman test", "needs at least one block (problem)");
    const std::size_t k = blocks.front().size();
    require(k >= 2, "Friedman test", "needs at least two treatments (algorithms)");
    const double n = static_cast<double>(blocks.size()), kk = static_cast<double>(k);
    std::vector<double> rank_sums(k, 0.0);
    double ties = 0.0;
    for (const auto& row : blocks) {
        require(row.size() == k, "Friedman test", "every block needs one value per treatment");
        const std::vector<double> r = average_ranks(row);
        for (std::size_t j = 0; j < k; ++j) rank_sums[j] += r[j];
        std::vector<double> sorted = r;
        std::sort(sorted.begin(), sorted.end());
        for (std::size_t i = 0; i < k;) {
            std::size_t j = i;
            while (j + 1 < k && sorted[j + 1] == sorted[i]) ++j;
            const double t = static_cast<double>(j - i + 1);
            ties += t * t * t - t;
            i = j + 1;
        }
    }
    FriedmanTest result;
    double sum_squares = 0.0;
    for (double s : rank_sums) {
        result.average_ranks.push_back(s / n);
        sum_squares += s * s;
    }
    const double correction = 1.0 - ties / (kk * (kk * kk - 1.0) * n);
    const double chi2 = (12.0 / (n * kk * (kk + 1.0)) * sum_squares - 3.0 * n * (kk + 1.0));
    result.statistic = correction > 0 ? chi2 / correction : 0.0;
    const boost::math::chi_squared distribution(kk - 1.0);
    result.p_value =
        correction > 0 ? boost::math::cdf(boost::math::complement(distribution, std::max(0.0, result.statistic))) : 1.0;
    return result;
}

/// One pair of treatments after Friedman's test: the z statistic of their average ranks' difference
/// and its two-sided p-value, raw and Holm-corrected over all pairs.
struct RankPair {
    std::size_t a = 0, b = 0;  // a < b, indices of the treatments
    double z = 0, p = 1, p_holm = 1;
};

/// The post-hoc comparison of every pair after Friedman's test (Demsar 2006, "Statistical
/// comparisons of classifiers over multiple data sets", JMLR 7, section 3.2.2; Garcia and Herrera
/// 2008): z = (R_a - R_b) / sqrt(k (k + 1) / (6 N)) for k treatments over N blocks, p from the
/// normal distribution, Holm's correction over the k (k - 1) / 2 pairs.
inline std::vector<RankPair> friedman_pairs(std::span<const double> average_ranks, std::size_t blocks) {
    const std::size_t k = average_ranks.size();
    require(k >= 2 && blocks >= 1, "Friedman post-hoc", "needs two treatments and a block");
    const double kk = static_cast<double>(k);
    const double se = std::sqrt(kk * (kk + 1.0) / (6.0 * static_cast<double>(blocks)));
    const boost::math::normal normal;
    std::vector<RankPair> pairs;
    std::vector<double> p;
    for (std::size_t a = 0; a < k; ++a)
        for (std::size_t b = a + 1; b < k; ++b) {
            RankPair r{a, b, (average_ranks[a] - average_ranks[b]) / se, 1, 1};
            r.p = std::min(1.0, 2.0 * boost::math::cdf(boost::math::complement(normal, std::abs(r.z))));
            pairs.push_back(r);
            p.push_back(r.p);
        }
    const auto adjusted = holm(p);
    for (std::size_t i = 0; i < pairs.size(); ++i) pairs[i].p_holm = adjusted[i];
    return pairs;
}

}  // namespace pride::stats

#pragma once
// The statistics a comparison of optimisers needs (the campaign report): ranks with
// ties, the Wilcoxon rank-sum (Mann-Whitney U) test, Holm's step-down correction, and Friedman's
// average ranks and test. The distributions come from Boost.Math; the formulas are those of
// scipy.stats (mannwhitneyu with method="asymptotic", friedmanchisquare), against which
// tests/test_statistics.cpp checks them on fixed data.
#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace pride::stats {

/// The mean of `values` (not empty).
double mean_of(std::span<const double> values);

/// The median of `values` (not empty): the mean of the two middle values for an even count.
double median_of(std::vector<double> values);

/// The sample standard deviation (n - 1); 0 for a single value, +inf when a value is infinite.
double sample_std(std::span<const double> values);

/// Ranks 1..n of `values`, ties sharing the average of their ranks (NaN not allowed).
std::vector<double> average_ranks(std::span<const double> values);

struct RankSumTest {
    double u;        // Mann-Whitney U of the first sample
    double z;        // standardised, with tie and continuity corrections
    double p_value;  // two-sided
};

/// Wilcoxon rank-sum / Mann-Whitney U test, two-sided, normal approximation with the tie
/// correction and the continuity correction (scipy.stats.mannwhitneyu(x, y,
/// method="asymptotic", use_continuity=True)). p = 1 when every value is tied.
RankSumTest rank_sum_test(std::span<const double> x, std::span<const double> y);

/// Vargha and Delaney's A (2000, "A critique and improvement of the CL common language effect
/// size statistics of McGraw and Wong", J. Educ. Behav. Stat. 25(2)): the probability that a value
/// drawn from x is smaller (better, minimising) than one drawn from y, ties counting half; 0.5 is
/// no effect, 1 means x always better. Equals U_x / (n m), U_x the Mann-Whitney count of pairs
/// with x < y plus half the ties. A(x, y) + A(y, x) = 1. NaN for an empty sample.
double vargha_delaney_a(std::span<const double> x, std::span<const double> y);

/// Holm's step-down adjustment of m p-values (Holm 1979): sorted ascending, p_(i) * (m - i + 1),
/// made non-decreasing, capped at 1; returned in the input order.
std::vector<double> holm(std::span<const double> p);

struct FriedmanTest {
    std::vector<double> average_ranks;  // per treatment (algorithm), 1 = best (smallest value)
    double statistic;                   // chi-squared, with the tie correction
    double p_value;                     // from chi-squared with k - 1 degrees of freedom
};

/// Friedman's test on `blocks` (one row per block, i.e. problem; one column per treatment, i.e.
/// algorithm; smaller is better), as scipy.stats.friedmanchisquare with its tie correction.
FriedmanTest friedman(const std::vector<std::vector<double>>& blocks);

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
std::vector<RankPair> friedman_pairs(std::span<const double> average_ranks, std::size_t blocks);

}  // namespace pride::stats

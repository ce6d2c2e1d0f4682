#pragma once
// The statistics of a critical-difference diagram (J. Demsar, "Statistical comparisons of
// classifiers over multiple data sets", JMLR 7:1-30, 2006, section 3.2.2 and figure 1): after
// Friedman's test (statistics.hpp), k treatments (algorithms) ranked over N blocks (problems)
// differ significantly by Nemenyi's test when their average ranks differ by at least
//     CD = q_alpha * sqrt(k (k + 1) / (6 N)),
// q_alpha the upper alpha quantile of the studentized range of k means with infinite degrees of
// freedom, divided by sqrt(2) (Demsar's table 5a). The diagram joins by a bar each maximal group
// of treatments whose average ranks all lie within less than CD of each other.
//
// The studentized range with infinite degrees of freedom is the range of k independent N(0, 1):
//     P(range <= q) = k * integral over z of phi(z) (Phi(z) - Phi(z - q))^(k - 1) dz
// (H. A. David, H. N. Nagaraja, "Order statistics", 3rd ed., Wiley 2003, the distribution of the
// sample range), integrated here by adaptive Gauss-Kronrod quadrature (Boost.Math) and inverted by
// TOMS 748; tests/test_critical_difference.cpp checks it against Demsar's table and
// scipy.stats.studentized_range.
#include <cstddef>
#include <span>
#include <vector>

namespace pride::stats {

/// P(range of k independent standard normals <= q), k >= 2; 0 for q <= 0. Absolute error about
/// 1e-14.
double studentized_range_cdf(double q, std::size_t k);

/// The upper alpha quantile q_{alpha,k,inf} of the studentized range with infinite degrees of
/// freedom: studentized_range_cdf(q, k) = 1 - alpha, for alpha in (0, 1) and k >= 2 (relative
/// error about 1e-14 / alpha in alpha, so alpha >= 1e-6 or so).
double studentized_range_quantile(double alpha, std::size_t k);

/// Nemenyi's critical value q_alpha = q_{alpha,k,inf} / sqrt(2) (Demsar 2006, table 5a: 2.343 for
/// k = 3 at alpha = 0.05). For k = 2 it is the normal quantile z_{1 - alpha/2}.
double nemenyi_q(double alpha, std::size_t k);

/// Nemenyi's critical difference of average ranks for k treatments over `blocks` problems:
/// nemenyi_q(alpha, k) * sqrt(k (k + 1) / (6 blocks)).
double nemenyi_critical_difference(double alpha, std::size_t k, std::size_t blocks);

/// The bars of the critical-difference diagram: every maximal run of treatments, in order of
/// average rank, whose ranks differ by less than `cd` (Demsar: "significantly different if the
/// corresponding average ranks differ by at least the critical difference"), as treatment
/// indices from best (smallest rank) to worst; a treatment in no bar differs from every other.
/// Runs of one treatment are left out, and so are runs inside a longer one.
std::vector<std::vector<std::size_t>> critical_difference_cliques(std::span<const double> average_ranks, double cd);

/// One critical-difference diagram: its CD and its bars.
struct CriticalDifference {
    double alpha = 0.05;
    double cd = 0;
    std::vector<std::vector<std::size_t>> cliques;
};

/// The diagram of friedman(blocks).average_ranks over `blocks` problems at level alpha.
CriticalDifference critical_difference(std::span<const double> average_ranks, std::size_t blocks, double alpha = 0.05);

}  // namespace pride::stats

#include "experiment/report/critical_difference.hpp"

#include <boost/math/distributions/normal.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/tools/roots.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>

#include "framework/error.hpp"

namespace pride::stats {
namespace {

constexpr double sqrt_half = 0.70710678118654752440;

/// Phi(z) - Phi(z - q) for q >= 0, from the tail nearer to z so that neither term is close to 1.
double band(double z, double q) {
    if (z > q / 2) return 0.5 * (std::erfc((z - q) * sqrt_half) - std::erfc(z * sqrt_half));
    return 0.5 * (std::erfc(-z * sqrt_half) - std::erfc((q - z) * sqrt_half));
}

}  // namespace

double studentized_range_cdf(double q, std::size_t k) {
    require(k >= 2, "studentized range", "needs at least two means (k >= 2)");
    if (!(q > 0)) return 0.0;
    const double km1 = static_cast<double>(k - 1);
    const double inv_sqrt_2pi = 0.39894228040143267794;
    const auto integrand = [&](double z) { return inv_sqrt_2pi * std::exp(-0.5 * z * z) * std::pow(band(z, q), km1); };
    // Beyond |z| = 12 the normal density is below 1e-31: nothing of the integral is left there.
    // Split at the band's centre (the integrand's peak for large q) so that the rule sees it.
    double error = 0;
    const double mid = std::min(q / 2, 11.0);
    using rule = boost::math::quadrature::gauss_kronrod<double, 31>;
    const double left = rule::integrate(integrand, -12.0, mid, 15, 1e-13, &error);
    const double right = rule::integrate(integrand, mid, 12.0, 15, 1e-13, &error);
    return std::min(1.0, static_cast<double>(k) * (left + right));
}

double studentized_range_quantile(double alpha, std::size_t k) {
    require(alpha > 0 && alpha < 1, "studentized range quantile", "alpha must lie in (0, 1)");
    require(k >= 2, "studentized range quantile", "needs at least two means (k >= 2)");
    const auto f = [&](double q) { return studentized_range_cdf(q, k) - (1 - alpha); };
    // Bracket: the range of k normals is at most twice their largest |value|, so by Bonferroni
    // its 1 - alpha quantile is below 2 z_{1 - alpha/(2k)}; it is above 0.
    const boost::math::normal normal;
    double hi = 2 * boost::math::quantile(boost::math::complement(normal, alpha / (2 * static_cast<double>(k))));
    while (f(hi) < 0) hi *= 2;  // only if the bound were wrong numerically
    std::uintmax_t iterations = 200;
    const auto [a, b] = boost::math::tools::toms748_solve(f, 0.0, hi, -(1 - alpha), f(hi),
                                                          boost::math::tools::eps_tolerance<double>(52), iterations);
    return 0.5 * (a + b);
}

double nemenyi_q(double alpha, std::size_t k) {
    return studentized_range_quantile(alpha, k) * sqrt_half;
}

double nemenyi_critical_difference(double alpha, std::size_t k, std::size_t blocks) {
    require(blocks >= 1, "critical difference", "needs at least one block (problem)");
    const double kk = static_cast<double>(k);
    return nemenyi_q(alpha, k) * std::sqrt(kk * (kk + 1) / (6 * static_cast<double>(blocks)));
}

std::vector<std::vector<std::size_t>> critical_difference_cliques(std::span<const double> average_ranks, double cd) {
    const std::size_t k = average_ranks.size();
    std::vector<std::size_t> order(k);
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return average_ranks[a] < average_ranks[b]; });
    std::vector<std::vector<std::size_t>> cliques;
    std::size_t covered = 0;  // end (exclusive) of the last bar, in rank order
    for (std::size_t i = 0; i < k; ++i) {
        std::size_t j = i;
        while (j + 1 < k && average_ranks[order[j + 1]] - average_ranks[order[i]] < cd) ++j;
        // j never decreases with i, so [i, j] lies inside an earlier bar exactly when j < covered.
        if (j > i && j + 1 > covered) {
            cliques.emplace_back(order.begin() + static_cast<std::ptrdiff_t>(i),
                                 order.begin() + static_cast<std::ptrdiff_t>(j + 1));
            covered = j + 1;
        }
    }
    return cliques;
}

CriticalDifference critical_difference(std::span<const double> average_ranks, std::size_t blocks, double alpha) {
    CriticalDifference out;
    out.alpha = alpha;
    out.cd = nemenyi_critical_difference(alpha, average_ranks.size(), blocks);
    out.cliques = critical_difference_cliques(average_ranks, out.cd);
    return out;
}

}  // namespace pride::stats

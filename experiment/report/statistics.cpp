#include "experiment/report/statistics.hpp"

// Boost.Math stays in this file: the report's units include the header, not the distributions.
#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/normal.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "framework/error.hpp"

namespace pride::stats {

double mean_of(std::span<const double> values) {
    return std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
}

double median_of(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

double sample_std(std::span<const double> values) {
    if (values.size() < 2) return 0.0;
    if (std::any_of(values.begin(), values.end(), [](double x) { return std::isinf(x); }))
        return std::numeric_limits<double>::infinity();
    const double m = mean_of(values);
    double s = 0.0;
    for (const double x : values) s += (x - m) * (x - m);
    if (std::isinf(s) && std::isfinite(m)) {
        // Squares beyond the largest double (deviations over 1e154: CEC 2017's F2 early in a run)
        // overflow though the deviation does not: summed again in units of the largest deviation.
        double scale = 0.0;
        for (const double x : values) scale = std::max(scale, std::abs(x - m));
        s = 0.0;
        for (const double x : values) s += ((x - m) / scale) * ((x - m) / scale);
        return scale * std::sqrt(s / static_cast<double>(values.size() - 1));
    }
    return std::sqrt(s / static_cast<double>(values.size() - 1));
}

std::vector<double> average_ranks(std::span<const double> values) {
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

RankSumTest rank_sum_test(std::span<const double> x, std::span<const double> y) {
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

double vargha_delaney_a(std::span<const double> x, std::span<const double> y) {
    if (x.empty() || y.empty()) return std::numeric_limits<double>::quiet_NaN();
    double wins = 0.0;
    for (const double a : x)
        for (const double b : y) wins += a < b ? 1.0 : (a == b ? 0.5 : 0.0);
    return wins / (static_cast<double>(x.size()) * static_cast<double>(y.size()));
}

std::vector<double> holm(std::span<const double> p) {
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

FriedmanTest friedman(const std::vector<std::vector<double>>& blocks) {
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

std::vector<RankPair> friedman_pairs(std::span<const double> average_ranks, std::size_t blocks) {
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

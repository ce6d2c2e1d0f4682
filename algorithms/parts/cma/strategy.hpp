#pragma once
// The CMA-ES strategy parameters: table 1 of Hansen (2016), "The CMA Evolution Strategy: A
// Tutorial", arXiv:1604.00772, eqs. (48)-(58), and their separable form (Ros and Hansen 2008).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace pride::cma {

/// Eq. (48): the default population size 4 + floor(3 ln n).
inline std::int64_t default_lambda(std::size_t n) {
    return 4 + static_cast<std::int64_t>(std::floor(3.0 * std::log(static_cast<double>(n))));
}

/// Everything table 1 derives from (n, lambda).
struct Strategy {
    std::int64_t lambda = 0, mu = 0;
    std::vector<double> weights;  // w_1..w_lambda by rank: mu positive, then <= 0 (eq. 53)
    double mueff = 0.0, mueff_minus = 0.0;
    double cm = 1.0;             // eq. (54)
    double cs = 0.0, ds = 0.0;   // eq. (55)
    double cc = 0.0;             // eq. (56)
    double c1 = 0.0, cmu = 0.0;  // eqs. (57), (58)
    double sum_weights = 0.0;    // sum of all w_j, the decay term of eq. (47)
    double chi_n = 0.0;          // E||N(0, I)||, the tutorial's approximation
};

/// Table 1 for dimension n and population lambda >= 2. `active`: the negative weights of eq. (53)
/// (the tutorial's active update); without, they are 0 (Hansen and Kern 2004's rank-mu update).
/// `separable`: c1 and c_mu times (n + 2) / 3 (Ros and Hansen 2008, eq. 6), the learning rates of
/// a diagonal covariance; the alphas of eqs. (50)-(52) then use the scaled rates.
inline Strategy make_strategy(std::size_t dimension, std::int64_t lambda, bool active, bool separable) {
    const double n = static_cast<double>(dimension);
    Strategy s;
    s.lambda = lambda;
    s.mu = lambda / 2;
    const auto l = static_cast<std::size_t>(lambda), mu = static_cast<std::size_t>(s.mu);
    std::vector<double> w(l);  // eq. (49): w'_i = ln((lambda + 1) / 2) - ln i
    for (std::size_t i = 0; i < l; ++i)
        w[i] = std::log((static_cast<double>(lambda) + 1.0) / 2.0) - std::log(static_cast<double>(i + 1));
    double pos = 0.0, pos2 = 0.0, neg = 0.0, neg2 = 0.0;
    for (std::size_t i = 0; i < mu; ++i) pos += w[i], pos2 += w[i] * w[i];
    for (std::size_t i = mu; i < l; ++i) neg += w[i], neg2 += w[i] * w[i];
    s.mueff = pos * pos / pos2;
    s.mueff_minus = neg2 > 0.0 ? neg * neg / neg2 : 0.0;
    s.cs = (s.mueff + 2.0) / (n + s.mueff + 5.0);                                           // (55)
    s.ds = 1.0 + 2.0 * std::max(0.0, std::sqrt((s.mueff - 1.0) / (n + 1.0)) - 1.0) + s.cs;  // (55)
    s.cc = (4.0 + s.mueff / n) / (n + 4.0 + 2.0 * s.mueff / n);                             // (56)
    constexpr double alpha_cov = 2.0;
    s.c1 = alpha_cov / ((n + 1.3) * (n + 1.3) + s.mueff);  // (57)
    s.cmu = std::min(1.0 - s.c1, alpha_cov * (s.mueff - 2.0 + 1.0 / s.mueff) /
                                     ((n + 2.0) * (n + 2.0) + alpha_cov * s.mueff / 2.0));  // (58)
    if (separable) {
        s.c1 = std::min(1.0, s.c1 * (n + 2.0) / 3.0);
        s.cmu = std::min(1.0 - s.c1, s.cmu * (n + 2.0) / 3.0);
    }
    // Eq. (53): positive weights sum to 1; negative ones to -alpha_min, the least of eqs. (50)-(52).
    const double alpha_mu = s.cmu > 0.0 ? 1.0 + s.c1 / s.cmu : INFINITY;                      // (50)
    const double alpha_mueff = 1.0 + 2.0 * s.mueff_minus / (s.mueff + 2.0);                   // (51)
    const double alpha_posdef = s.cmu > 0.0 ? (1.0 - s.c1 - s.cmu) / (n * s.cmu) : INFINITY;  // (52)
    const double alpha_min = std::min({alpha_mu, alpha_mueff, alpha_posdef});
    double negative_sum = 0.0;  // sum |w'_j| over the negative w'_j
    for (std::size_t i = 0; i < l; ++i)
        if (w[i] < 0.0) negative_sum -= w[i];
    double positive_sum = 0.0;
    for (std::size_t i = 0; i < l; ++i)
        if (w[i] >= 0.0) positive_sum += w[i];
    s.weights.resize(l);
    for (std::size_t i = 0; i < l; ++i)
        s.weights[i] = w[i] >= 0.0 ? w[i] / positive_sum : (active ? alpha_min * w[i] / negative_sum : 0.0);
    s.sum_weights = 0.0;
    for (double wi : s.weights) s.sum_weights += wi;
    s.chi_n = std::sqrt(n) * (1.0 - 1.0 / (4.0 * n) + 1.0 / (21.0 * n * n));
    return s;
}

}  // namespace pride::cma

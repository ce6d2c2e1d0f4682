#pragma once
// Crossover for real-coded GAs.
#include <algorithm>
#include <cmath>
#include <span>
#include <string>
#include <utility>

#include "algorithms/parts/power.hpp"
#include "framework/error.hpp"
#include "framework/random.hpp"

namespace pride {

/// Simulated binary crossover, bounded form (Deb and Agrawal 1995, Complex Systems 9:115-148; the
/// bounded spread factor as in Deb's NSGA-II reference code, which pagmo2 also follows). Applied to
/// a pair with probability `probability`; then each coordinate with probability 1/2:
///   beta  = 1 + 2 (y1 - low) / (y2 - y1),  alpha = 2 - beta^-(eta+1)
///   betaq = (u alpha)^(1/(eta+1))            if u <= 1/alpha
///         = (1 / (2 - u alpha))^(1/(eta+1))  otherwise
///   c1 = ((y1 + y2) - betaq (y2 - y1)) / 2, and c2 likewise with beta = 1 + 2 (high - y2)/(y2 - y1),
/// the children's coordinates swapped with probability 1/2. Spec: eta = 15, probability 0.9.
class SbxCrossover {
public:
    double eta = 15.0;
    double probability = 0.9;

    void validate(const std::string& where) const {
        require(eta >= 0.0 && eta <= 1000.0, where, "eta_c must be in [0, 1000], got " + std::to_string(eta));
        require(probability >= 0.0 && probability <= 1.0, where,
                "pc must be in [0, 1], got " + std::to_string(probability));
    }

    void operator()(std::span<double> a, std::span<double> b, std::span<const double> lo, std::span<const double> hi,
                    Rng& rng) const {
        if (!rng.bernoulli(probability)) return;
        const FixedPower spread(-(eta + 1.0));
        const FixedPower root(1.0 / (eta + 1.0));
        for (std::size_t i = 0; i < a.size(); ++i) {
            if (!rng.bernoulli(0.5)) continue;
            if (std::abs(a[i] - b[i]) <= 1e-14) continue;
            const double y1 = std::min(a[i], b[i]);
            const double y2 = std::max(a[i], b[i]);
            const double u = rng.uniform();
            auto betaq = [&](double beta) {
                const double alpha = 2.0 - spread(beta);
                return u <= 1.0 / alpha ? root(u * alpha) : root(1.0 / (2.0 - u * alpha));
            };
            double c1 = 0.5 * ((y1 + y2) - betaq(1.0 + 2.0 * (y1 - lo[i]) / (y2 - y1)) * (y2 - y1));
            double c2 = 0.5 * ((y1 + y2) + betaq(1.0 + 2.0 * (hi[i] - y2) / (y2 - y1)) * (y2 - y1));
            c1 = std::clamp(c1, lo[i], hi[i]);
            c2 = std::clamp(c2, lo[i], hi[i]);
            if (rng.bernoulli(0.5)) std::swap(c1, c2);
            a[i] = c1;
            b[i] = c2;
        }
    }
};

}  // namespace pride

#pragma once
// Parent selection for the GA.
#include <cstdint>
#include <span>
#include <string>

#include "framework/error.hpp"
#include "framework/random.hpp"

namespace pride {

/// k-tournament with replacement: k members drawn uniformly, the fittest wins (the first drawn on
/// ties). The project's GA uses k = 2.
struct TournamentSelection {
    std::int64_t size = 2;
    std::size_t operator()(std::span<const double> fitness, Rng& rng) const noexcept {
        std::size_t best = rng.below(fitness.size());
        for (std::int64_t k = 1; k < size; ++k) {
            const std::size_t c = rng.below(fitness.size());
            if (fitness[c] < fitness[best]) best = c;
        }
        return best;
    }
    /// The same tournament under a constraint order (framework/constraint_order.hpp) on (f, v):
    /// Deb's (2000) tournament when `by` is Deb's rules; the same draws.
    template <class Order>
    std::size_t operator()(const Order& by, std::span<const double> f, std::span<const double> v,
                           Rng& rng) const noexcept {
        std::size_t best = rng.below(f.size());
        for (std::int64_t k = 1; k < size; ++k) {
            const std::size_t c = rng.below(f.size());
            if (by.better(f[c], v[c], f[best], v[best])) best = c;
        }
        return best;
    }
    void validate(const std::string& where) const {
        require(size >= 1, where, "tournament size must be >= 1, got " + std::to_string(size));
    }
};

}  // namespace pride

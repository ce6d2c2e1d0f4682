#pragma once
// ICGA's catastrophe (the "improved catastrophe GA" [31] that Zhang et al. (2025) compare with;
// docs/algorithms.md, GA: "a catastrophe step that re-seeds all but the elite after k
// generations without improvement"), as a GA per-generation hook (generation_hook.hpp).
//
//   Xu, X., Yu, X., Zhao, Y. et al. (2022). Global path planning of mobile robot based on improved
//     genetic algorithm. Computer Integrated Manufacturing Systems 28(6), 1659-1672 (Zhang et al.'s (2025) [31]).
//
// After generation t's replacement, when the best value the run has found has not improved for
// k generations (context.stagnation = k, and again at 2k, 3k, ... while it still does not), the
// `elite` best members of the population are kept and every other member is re-seeded: by the
// Init policy then the Bounds policy on boxes, by the problem's random chains on chains, evaluated
// in order through the run's budget guard (population.renew). A catastrophe that finds a better
// member restarts the count.
// Decided by this project (Zhang et al. (2025) give neither value, and [31] is not at hand): k = 10 and
// elite = 1 (the GA's own elitism); the elite are the `elite` smallest values, ties to the lower
// index; the re-seeded members are renewed in increasing index order.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <span>
#include <string>
#include <vector>

#include "algorithms/parts/ga/generation_context.hpp"
#include "framework/error.hpp"
#include "framework/random.hpp"

namespace pride {

struct CatastropheHook {
    std::int64_t k = 10;     // generations without improvement of the best before a catastrophe
    std::int64_t elite = 1;  // best members kept through it

    void validate(const std::string& where, std::int64_t population) const {
        require(k >= 1, where, "catastrophe k must be >= 1, got " + std::to_string(k));
        require(elite >= 0 && elite < population, where,
                "catastrophe elite must be in [0, population), got " + std::to_string(elite));
    }

    /// Whether the generation just completed ends with a catastrophe.
    bool due(const GenerationContext& c) const noexcept { return c.stagnation > 0 && c.stagnation % k == 0; }

    /// The members a catastrophe keeps (the `elite` best, ties to the lower index), in increasing order.
    std::vector<std::size_t> kept(std::span<const double> f) const {
        std::vector<std::size_t> order(f.size());
        std::iota(order.begin(), order.end(), std::size_t{0});
        const auto m = std::min(order.size(), static_cast<std::size_t>(std::max<std::int64_t>(elite, 0)));
        std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(m), order.end(),
                          [&](std::size_t a, std::size_t b) { return f[a] < f[b] || (f[a] == f[b] && a < b); });
        order.resize(m);
        std::sort(order.begin(), order.end());
        return order;
    }

    template <class Population>
    void operator()(const GenerationContext& c, Population& population, Rng& rng) const {
        if (!due(c)) return;
        const auto keep = kept(population.fitness());
        std::vector<std::size_t> renewed;
        renewed.reserve(population.size() - keep.size());
        for (std::size_t i = 0, j = 0; i < population.size(); ++i) {
            if (j < keep.size() && keep[j] == i)
                ++j;
            else
                renewed.push_back(i);
        }
        population.renew(renewed, rng);
    }
};

}  // namespace pride

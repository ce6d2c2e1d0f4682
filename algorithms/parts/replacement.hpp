#pragma once
// Replacement (reinsertion) for the GA: which parents and children form the next population. A
// policy only chooses, by index into the pool "parents 0..n-1, then children n..": the GA copies,
// whatever its individuals are (points or chains).
#include <algorithm>
#include <cstdint>
#include <numeric>
#include <span>
#include <string>
#include <vector>

#include "framework/error.hpp"
#include "framework/one_of.hpp"

namespace pride {

/// Scratch a replacement policy may use, owned by the run (policies stay stateless and shareable).
struct ReplacementScratch {
    std::vector<std::size_t> order;
    std::vector<double> pool;
};

namespace detail {
/// The indices of the k best of `f` in `order`'s first k places, best first; ties go to the lower
/// index, so the choice is reproducible.
inline void best_first(std::span<const double> f, std::size_t k, std::vector<std::size_t>& order) {
    order.resize(f.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    const auto before = [&](std::size_t a, std::size_t b) { return f[a] < f[b] || (f[a] == f[b] && a < b); };
    // The order is total (ties by index), so any sort gives the same first k. For k near n (ga-plus:
    // the best 50 of 100) a full introsort costs half of partial_sort's heap (issue 15's profile).
    if (2 * k >= f.size())
        std::sort(order.begin(), order.end(), before);
    else
        std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(k), order.end(), before);
}
}  // namespace detail

/// Generational with elitism (the spec's GA): the `elitism` best parents pass on unchanged, the
/// other N - elitism places go to the children in the order they were made.
struct ElitistReplacement {
    std::int64_t elitism = 1;

    static constexpr const char* name = "elitist";
    std::int64_t offspring(std::int64_t population) const { return population - elitism; }
    void validate(const std::string& where, std::int64_t population) const {
        require(elitism >= 0 && elitism < population, where,
                "elitism must be in [0, population), got " + std::to_string(elitism));
    }

    void operator()(std::span<const double> fp, std::span<const double> fc, std::span<std::size_t> chosen,
                    ReplacementScratch& scratch) const {
        const auto e = static_cast<std::size_t>(elitism);
        detail::best_first(fp, e, scratch.order);
        std::copy_n(scratch.order.begin(), e, chosen.begin());
        std::iota(chosen.begin() + static_cast<std::ptrdiff_t>(e), chosen.end(), fp.size());
        (void)fc;
    }
};

/// (mu + lambda) "pure elitism", as pagmo2's sga: N children, and the best N of parents and
/// children together form the next population (ties: parents first, then earlier members).
struct PlusReplacement {
    static constexpr const char* name = "plus";
    std::int64_t offspring(std::int64_t population) const { return population; }
    void validate(const std::string&, std::int64_t) const {}

    void operator()(std::span<const double> fp, std::span<const double> fc, std::span<std::size_t> chosen,
                    ReplacementScratch& scratch) const {
        scratch.pool.assign(fp.begin(), fp.end());
        scratch.pool.insert(scratch.pool.end(), fc.begin(), fc.end());
        detail::best_first(scratch.pool, chosen.size(), scratch.order);
        std::copy_n(scratch.order.begin(), chosen.size(), chosen.begin());
    }
};

}  // namespace pride

namespace pride {

/// The elitist or the (mu + lambda) replacement, chosen at run time (one choice per generation):
/// `ga` and `ga-plus` are two configurations of one instantiation.
struct SelectableReplacement : OneOf<ElitistReplacement, PlusReplacement> {
    using OneOf::OneOf;
    std::int64_t offspring(std::int64_t population) const {
        return visit([&](const auto& r) { return r.offspring(population); });
    }
};

}  // namespace pride

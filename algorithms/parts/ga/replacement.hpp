#pragma once
// Replacement (reinsertion) for the GA: which parents and children form the next population. A
// policy only chooses, by index into the pool "parents 0..n-1, then children n..": the GA copies,
// whatever its individuals are (points or chains). Under constraints a policy chooses by the
// run's constraint order on (value, violation) (framework/constraint_order.hpp: rank_by, the
// ranking the DE family uses), ties to the lower index as by value.
#include <algorithm>
#include <cstdint>
#include <numeric>
#include <span>
#include <string>
#include <vector>

#include "framework/constraint_order.hpp"
#include "framework/error.hpp"
#include "framework/one_of.hpp"

namespace pride {

/// Scratch a replacement policy may use, owned by the run (policies stay stateless and shareable).
struct ReplacementScratch {
    std::vector<std::size_t> order;
    std::vector<double> pool, pool_v;
};

namespace detail {
/// The indices of the k best of `f` in `order`'s first k places, best first; ties go to the lower
/// index, so the choice is reproducible.
inline void best_first(std::span<const double> f, std::size_t k, std::vector<std::size_t>& order) {
    order.resize(f.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    const auto before = [&](std::size_t a, std::size_t b) { return f[a] < f[b] || (f[a] == f[b] && a < b); };
    // The order is total (ties by index), so any sort gives the same first k. For k near n (ga-plus:
    // the best 50 of 100) a full introsort costs half of partial_sort's heap (measured in a profile).
    if (2 * k >= f.size())
        std::sort(order.begin(), order.end(), before);
    else
        std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(k), order.end(), before);
}
}  // namespace detail

/// Generational with elitism (the project's GA): the `elitism` best parents pass on unchanged, the
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
    /// Under a constraint order: the elite are the best parents by `by`.
    static constexpr bool ranks_children = false;
    template <class Order>
    void operator()(const Order& by, std::span<const double> fp, std::span<const double> vp,
                    std::span<const double> /*fc*/, std::span<const double> /*vc*/, std::span<std::size_t> chosen,
                    ReplacementScratch& scratch) const {
        const auto e = static_cast<std::size_t>(elitism);
        scratch.order.resize(fp.size());
        rank_by(by, fp, vp, scratch.order, e);
        std::copy_n(scratch.order.begin(), e, chosen.begin());
        std::iota(chosen.begin() + static_cast<std::ptrdiff_t>(e), chosen.end(), fp.size());
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
        // The parents come best first after every generation of this replacement (its own output
        // order); then only the children that can enter are sorted and merged with them: the same
        // order as the whole pool's sort (total: ties by index, so a parent goes before a child of
        // equal value), at a fraction of its cost (that sort of 100 was a quarter of
        // ga-plus's run at D = 30). Unsorted parents (the first generation) take the full sort.
        if (chosen.size() <= fp.size() && std::is_sorted(fp.begin(), fp.end())) {
            merge_children(fp, fc, chosen, scratch.order);
            return;
        }
        scratch.pool.assign(fp.begin(), fp.end());
        scratch.pool.insert(scratch.pool.end(), fc.begin(), fc.end());
        detail::best_first(scratch.pool, chosen.size(), scratch.order);
        std::copy_n(scratch.order.begin(), chosen.size(), chosen.begin());
    }

    /// Under a constraint order: the best N of parents and children by `by`.
    static constexpr bool ranks_children = true;
    template <class Order>
    void operator()(const Order& by, std::span<const double> fp, std::span<const double> vp, std::span<const double> fc,
                    std::span<const double> vc, std::span<std::size_t> chosen, ReplacementScratch& scratch) const {
        scratch.pool.assign(fp.begin(), fp.end());
        scratch.pool.insert(scratch.pool.end(), fc.begin(), fc.end());
        scratch.pool_v.assign(vp.begin(), vp.end());
        scratch.pool_v.insert(scratch.pool_v.end(), vc.begin(), vc.end());
        scratch.order.resize(scratch.pool.size());
        rank_by(by, scratch.pool, scratch.pool_v, scratch.order, chosen.size());
        std::copy_n(scratch.order.begin(), chosen.size(), chosen.begin());
    }

  private:
    /// chosen = the best chosen.size() (<= fp.size()) of the parents (sorted) and the children, best
    /// first. Only children strictly better than the worst parent can be among the first fp.size()
    /// (on a tie the parent's lower index wins), so only those are sorted, by (value, index), in
    /// `order` (indices into fc), then merged with the parents.
    static void merge_children(std::span<const double> fp, std::span<const double> fc, std::span<std::size_t> chosen,
                               std::vector<std::size_t>& order) {
        const std::size_t n = fp.size();
        order.resize(fc.size());
        std::size_t m = 0;
        if (n > 0)
            for (std::size_t c = 0; c < fc.size(); ++c) {
                order[m] = c;  // kept (m advances) only if better: no branch on an unpredictable test
                m += fc[c] < fp[n - 1] ? 1 : 0;
            }
        std::sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(m),
                  [&](std::size_t a, std::size_t b) { return fc[a] < fc[b] || (fc[a] == fc[b] && a < b); });
        std::size_t p = 0, c = 0;
        for (std::size_t& out : chosen) {
            // A child goes first only if strictly better: on a tie the parent's lower index wins.
            const bool child = c < m && (p == n || fc[order[c]] < fp[p]);
            out = child ? n + order[c++] : p++;
        }
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

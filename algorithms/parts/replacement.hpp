#pragma once
// Replacement (reinsertion) for the GA: how parents and children form the next population.
#include <algorithm>
#include <cstdint>
#include <numeric>
#include <span>
#include <string>
#include <vector>

#include "framework/error.hpp"
#include "framework/problem.hpp"

namespace pride {

namespace detail {
/// The indices of the k best of `f` in `order`'s first k places, best first; ties go to the lower
/// index, so the choice is reproducible.
inline void best_first(std::span<const double> f, std::size_t k, std::vector<std::size_t>& order) {
    order.resize(f.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(k), order.end(),
                      [&](std::size_t a, std::size_t b) { return f[a] < f[b] || (f[a] == f[b] && a < b); });
}
}  // namespace detail

/// Generational with elitism (the spec's GA): the `elitism` best parents pass on unchanged, the
/// other N - elitism places go to the children in the order they were made.
struct ElitistReplacement {
    std::int64_t elitism = 1;

    static constexpr const char* name = "elitist";
    Eigen::Index offspring(Eigen::Index population) const { return population - elitism; }
    void validate(const std::string& where, std::int64_t population) const {
        require(elitism >= 0 && elitism < population, where,
                "elitism must be in [0, population), got " + std::to_string(elitism));
    }

    void operator()(const Matrix& parents, std::span<const double> fp, const Matrix& children,
                    std::span<const double> fc, Matrix& next, std::span<double> fnext,
                    std::vector<std::size_t>& order) const {
        const auto e = static_cast<std::size_t>(elitism);
        detail::best_first(fp, e, order);
        for (std::size_t k = 0; k < e; ++k) {
            next.col(static_cast<Eigen::Index>(k)) = parents.col(static_cast<Eigen::Index>(order[k]));
            fnext[k] = fp[order[k]];
        }
        next.rightCols(children.cols()) = children;
        std::copy(fc.begin(), fc.end(), fnext.begin() + static_cast<std::ptrdiff_t>(e));
    }
};

/// (mu + lambda) "pure elitism", as pagmo2's sga: N children, and the best N of parents and
/// children together form the next population (ties: parents first, then earlier members).
struct PlusReplacement {
    static constexpr const char* name = "plus";
    Eigen::Index offspring(Eigen::Index population) const { return population; }
    void validate(const std::string&, std::int64_t) const {}

    void operator()(const Matrix& parents, std::span<const double> fp, const Matrix& children,
                    std::span<const double> fc, Matrix& next, std::span<double> fnext,
                    std::vector<std::size_t>& order) const {
        const std::size_t n = fp.size();
        pool_.assign(fp.begin(), fp.end());
        pool_.insert(pool_.end(), fc.begin(), fc.end());
        detail::best_first(pool_, n, order);
        for (std::size_t k = 0; k < n; ++k) {
            const std::size_t from = order[k];
            next.col(static_cast<Eigen::Index>(k)) = from < n ? parents.col(static_cast<Eigen::Index>(from))
                                                              : children.col(static_cast<Eigen::Index>(from - n));
            fnext[k] = pool_[from];
        }
    }

private:
    mutable std::vector<double> pool_;  // scratch, reused: no allocation after the first generation
};

}  // namespace pride

#pragma once
// Pareto dominance between objective vectors, every objective minimised. A set of
// objective vectors is a Matrix with one column per point (M rows), as a population is.
#include <Eigen/Core>
#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <span>
#include <string>
#include <vector>

#include "framework/error.hpp"
#include "framework/problem.hpp"

namespace pride::pareto {

/// Column i of a set of points as a span (columns are contiguous in a MatrixView).
inline std::span<const double> point(const MatrixView& f, Eigen::Index i) {
    return {f.col(i).data(), static_cast<std::size_t>(f.rows())};
}

/// a <= b in every objective.
inline bool weakly_dominates(std::span<const double> a, std::span<const double> b) noexcept {
    assert(a.size() == b.size());
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i] > b[i]) return false;
    return true;
}

/// a <= b in every objective and a < b in at least one.
inline bool dominates(std::span<const double> a, std::span<const double> b) noexcept {
    assert(a.size() == b.size());
    bool better = false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (a[i] > b[i]) return false;
        if (a[i] < b[i]) better = true;
    }
    return better;
}

namespace detail {

/// The first column holding a NaN, or -1. NaN compares false both ways, so with one the dominance
/// relation is no longer a partial order and no front is defined: the callers refuse it.
inline Eigen::Index first_nan_column(const MatrixView& f) noexcept {
    for (Eigen::Index j = 0; j < f.cols(); ++j)
        for (Eigen::Index i = 0; i < f.rows(); ++i)
            if (std::isnan(f(i, j))) return j;
    return -1;
}

/// Lexicographic order of columns, ties (equal columns) by index: the order in which a point can
/// only be dominated by points before it.
inline bool lexicographically_before(const MatrixView& f, Eigen::Index a, Eigen::Index b) noexcept {
    for (Eigen::Index i = 0; i < f.rows(); ++i)
        if (f(i, a) != f(i, b)) return f(i, a) < f(i, b);
    return a < b;
}

}  // namespace detail

/// Indices (ascending) of the columns of `f` that no other column dominates; of equal columns,
/// only the first is kept. O(N log N + N K M) for K non-dominated points: in lexicographic order a
/// point can only be dominated by an earlier one, and whoever dominates it, a kept point weakly
/// dominates too (dominance is transitive), so each point is compared with the kept ones only.
inline std::vector<std::size_t> nondominated(const MatrixView& f) {
    const Eigen::Index nan = detail::first_nan_column(f);
    require(nan < 0, "nondominated", "point " + std::to_string(nan) + " has a NaN objective value");
    std::vector<Eigen::Index> order(static_cast<std::size_t>(f.cols()));
    std::iota(order.begin(), order.end(), Eigen::Index{0});
    std::sort(order.begin(), order.end(),
              [&f](Eigen::Index a, Eigen::Index b) { return detail::lexicographically_before(f, a, b); });
    std::vector<std::size_t> kept;
    for (const Eigen::Index j : order) {
        const auto p = point(f, j);
        const bool covered = std::any_of(kept.begin(), kept.end(), [&](std::size_t k) {
            return weakly_dominates(point(f, static_cast<Eigen::Index>(k)), p);
        });
        if (!covered) kept.push_back(static_cast<std::size_t>(j));
    }
    std::sort(kept.begin(), kept.end());
    return kept;
}

}  // namespace pride::pareto

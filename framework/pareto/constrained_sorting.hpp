#pragma once
// Constrained domination (Deb, Pratap, Agarwal and Meyarivan 2002, NSGA-II, sec. VI-A): point i
// constrained-dominates point j when i is feasible and j is not; or both are infeasible and i has
// the smaller violation; or both are feasible and i dominates j. Sorting a population into fronts
// by this relation gives, exactly: the feasible points' own fronts first (framework/pareto/
// sorting.hpp, on them alone), then one front per distinct violation of the infeasible points,
// the least first (infeasible points of equal violation do not dominate each other: one front).
// A point's violation is the one its problem defines (framework/constraints.hpp), 0 when feasible;
// an empty span of violations is a problem without constraints, sorted as before constraints
// existed.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "framework/error.hpp"
#include "framework/pareto/dominance.hpp"
#include "framework/pareto/sorting.hpp"
#include "framework/problem.hpp"

namespace pride::pareto {

/// i constrained-dominates j (the header's rule); `va`, `vb` the two violations.
inline bool constrained_dominates(std::span<const double> fa, double va, std::span<const double> fb,
                                  double vb) noexcept {
    const bool feasible_a = va == 0.0, feasible_b = vb == 0.0;
    if (feasible_a && feasible_b) return dominates(fa, fb);
    if (feasible_a != feasible_b) return feasible_a;
    return va < vb;
}

/// Buffers of constrained_sort, reused from call to call (no allocation once grown).
struct ConstrainedSortScratch {
    SortScratch sort;
    Matrix feasible_f;                  // the feasible points' columns
    std::vector<std::size_t> feasible;  // their indices
    std::vector<std::size_t> feasible_rank;
    std::vector<std::size_t> infeasible;  // the others, by (violation, index)
};

/// rank[i] = the front of column i under constrained domination; returns the number of fronts.
/// `violation` has one entry per column, or none (no constraints: nondominated_sort itself).
inline std::size_t constrained_sort(const MatrixView& f, std::span<const double> violation, std::span<std::size_t> rank,
                                    ConstrainedSortScratch& s) {
    if (violation.empty()) return nondominated_sort(f, rank, s.sort);
    const auto n = static_cast<std::size_t>(f.cols());
    if (violation.size() != n)
        throw InputError("constrained_sort", "violation has " + std::to_string(violation.size()) + " entries for " +
                                                 std::to_string(n) + " points");
    s.feasible.clear();
    s.infeasible.clear();
    for (std::size_t i = 0; i < n; ++i) {
        if (std::isnan(violation[i]))
            throw InputError("constrained_sort", "point " + std::to_string(i) + " has a NaN violation");
        (violation[i] == 0.0 ? s.feasible : s.infeasible).push_back(i);
    }
    if (s.infeasible.empty()) return nondominated_sort(f, rank, s.sort);
    std::size_t fronts = 0;
    if (!s.feasible.empty()) {
        const auto k = static_cast<Eigen::Index>(s.feasible.size());
        s.feasible_f.resize(f.rows(), k);
        for (Eigen::Index j = 0; j < k; ++j) s.feasible_f.col(j) = f.col(static_cast<Eigen::Index>(s.feasible[j]));
        s.feasible_rank.resize(s.feasible.size());
        fronts = nondominated_sort(s.feasible_f, std::span<std::size_t>(s.feasible_rank), s.sort);
        for (std::size_t j = 0; j < s.feasible.size(); ++j) rank[s.feasible[j]] = s.feasible_rank[j];
    }
    std::sort(s.infeasible.begin(), s.infeasible.end(), [&](std::size_t a, std::size_t b) {
        return violation[a] != violation[b] ? violation[a] < violation[b] : a < b;
    });
    for (std::size_t k = 0; k < s.infeasible.size(); ++k) {
        if (k > 0 && violation[s.infeasible[k]] != violation[s.infeasible[k - 1]]) ++fronts;
        rank[s.infeasible[k]] = fronts;
    }
    return fronts + 1;
}

}  // namespace pride::pareto

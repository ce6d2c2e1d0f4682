#pragma once
// Non-dominated sorting and crowding distance, the two rankings of NSGA-II (Deb, Pratap, Agarwal
// and Meyarivan 2002, "A fast and elitist multiobjective genetic algorithm: NSGA-II", IEEE TEC
// 6(2), sec. III-A and III-B). All objectives are minimised; f has one column per point.
//
// Two algorithms give the same ranks (the fronts are defined by dominance alone):
// - M != 2: Deb's fast non-dominated sort, O(M N^2), with S_p (the points p dominates) kept as one
//   row of an N x N bit matrix, so that its memory depends on N only and is reused every call;
// - M == 2: O(N log N). Sorted by (f1, f2), a point can only be dominated by points before it, and
//   within a front the points come in increasing f1 and decreasing f2 (or are equal), so the last
//   point put in a front dominates the new point whenever any point of that front does. Whether
//   front k dominates the new point is monotone in k (a point of front k+1 is dominated by one of
//   front k), so its front is found by binary search over the fronts' last points (Jensen 2003,
//   "Reducing the run-time complexity of multiobjective EAs: the NSGA-II and other algorithms",
//   IEEE TEC 7(5); the two-objective case of the "efficient non-domination level update" idea).
//
// Decisions the papers leave open: equal points are in the same front (neither dominates the
// other); NaN is refused (with it dominance is not a partial order); the crowding distance sorts
// each objective by (value, column index), so that ties, and so the result, do not depend on the
// order of `members`, bit for bit; an objective whose max == min over the front contributes 0 to
// every member, its ends included (which tied point would be "the boundary" is arbitrary);
// non-finite values are refused by crowding_distance (inf - inf has no distance).
#include <Eigen/Core>
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <span>
#include <string>
#include <vector>

#include "framework/error.hpp"
#include "framework/pareto/dominance.hpp"
#include "framework/problem.hpp"

namespace pride::pareto {

/// Buffers reused from one call to the next: after a first call with as many points, a call
/// allocates nothing (NSGA-II sorts every generation). For M != 2 it holds N^2 / 8 bytes of
/// dominance bits (125 kB for N = 1000).
struct SortScratch {
    std::vector<std::size_t> order;        // the points in sorting order, or the fronts one after another
    std::vector<std::size_t> last;         // M == 2: the last point put in each front
    std::vector<std::size_t> count;        // Deb: how many points dominate each point (n_p)
    std::vector<std::uint64_t> dominated;  // Deb: bit q of row p set when p dominates q (S_p)
};

namespace detail {

// Errors are checked before any message is built: a call that succeeds must not allocate.
inline void check_sort_input(const MatrixView& f, std::size_t rank_size) {
    if (rank_size != static_cast<std::size_t>(f.cols()))
        throw InputError("nondominated_sort", "rank has " + std::to_string(rank_size) + " entries for " +
                                                  std::to_string(f.cols()) + " points");
    if (const Eigen::Index nan = first_nan_column(f); nan >= 0)
        throw InputError("nondominated_sort", "point " + std::to_string(nan) + " has a NaN objective value");
}

/// Deb et al. 2002's fast non-dominated sort, any M.
inline std::size_t nondominated_sort_deb(const MatrixView& f, std::span<std::size_t> rank, SortScratch& s) {
    check_sort_input(f, rank.size());
    const std::size_t n = static_cast<std::size_t>(f.cols());
    const std::size_t m = static_cast<std::size_t>(f.rows());
    if (n == 0) return 0;
    const std::size_t words = (n + 63) / 64;
    s.dominated.assign(n * words, 0);
    s.count.assign(n, 0);
    s.order.resize(n);
    for (std::size_t p = 0; p < n; ++p) {
        const double* a = f.col(static_cast<Eigen::Index>(p)).data();
        for (std::size_t q = p + 1; q < n; ++q) {
            const double* b = f.col(static_cast<Eigen::Index>(q)).data();
            bool a_better = false, b_better = false;
            for (std::size_t i = 0; i < m; ++i) {
                a_better |= a[i] < b[i];
                b_better |= b[i] < a[i];
            }
            if (a_better && !b_better) {
                s.dominated[p * words + q / 64] |= std::uint64_t{1} << (q % 64);
                ++s.count[q];
            } else if (b_better && !a_better) {
                s.dominated[q * words + p / 64] |= std::uint64_t{1} << (p % 64);
                ++s.count[p];
            }
        }
    }
    // The fronts one after another in s.order: [begin, end) is the current front.
    std::size_t end = 0;
    for (std::size_t p = 0; p < n; ++p)
        if (s.count[p] == 0) {
            rank[p] = 0;
            s.order[end++] = p;
        }
    std::size_t begin = 0, fronts = 0;
    while (begin < end) {
        const std::size_t front_end = end;
        for (std::size_t k = begin; k < front_end; ++k) {
            const std::uint64_t* row = s.dominated.data() + s.order[k] * words;
            for (std::size_t w = 0; w < words; ++w)
                for (std::uint64_t bits = row[w]; bits != 0; bits &= bits - 1) {
                    const std::size_t q = w * 64 + static_cast<std::size_t>(std::countr_zero(bits));
                    if (--s.count[q] == 0) {
                        rank[q] = fronts + 1;
                        s.order[end++] = q;
                    }
                }
        }
        begin = front_end;
        ++fronts;
    }
    return fronts;
}

/// The O(N log N) sort for two objectives (see the top of this file).
inline std::size_t nondominated_sort_2d(const MatrixView& f, std::span<std::size_t> rank, SortScratch& s) {
    check_sort_input(f, rank.size());
    const std::size_t n = static_cast<std::size_t>(f.cols());
    s.order.resize(n);
    s.last.resize(n);
    std::iota(s.order.begin(), s.order.end(), std::size_t{0});
    const double* v = f.data();
    const auto stride = static_cast<std::size_t>(f.outerStride());
    std::sort(s.order.begin(), s.order.end(), [v, stride](std::size_t a, std::size_t b) {
        const double* pa = v + a * stride;
        const double* pb = v + b * stride;
        if (pa[0] != pb[0]) return pa[0] < pb[0];
        if (pa[1] != pb[1]) return pa[1] < pb[1];
        return a < b;
    });
    std::size_t fronts = 0;
    for (const std::size_t p : s.order) {
        const double* pp = v + p * stride;
        // The last point L of a front came earlier in (f1, f2) order: L1 <= p1, so L dominates p
        // exactly when L2 < p2, or L2 == p2 and L1 < p1.
        const auto covers = [v, stride, pp](std::size_t last) {
            const double* pl = v + last * stride;
            return pl[1] < pp[1] || (pl[1] == pp[1] && pl[0] < pp[0]);
        };
        const auto it =
            std::partition_point(s.last.begin(), s.last.begin() + static_cast<std::ptrdiff_t>(fronts), covers);
        const auto k = static_cast<std::size_t>(it - s.last.begin());
        if (k == fronts) ++fronts;
        s.last[k] = p;
        rank[p] = k;
    }
    return fronts;
}

}  // namespace detail

/// rank[i] = the front of column i (0 = non-dominated, 1 = non-dominated once front 0 is removed, ...).
/// Returns the number of fronts. rank.size() == f.cols(). No allocation when `scratch` has been used before
/// with as many points (the hot loop of NSGA-II calls it every generation).
inline std::size_t nondominated_sort(const MatrixView& f, std::span<std::size_t> rank, SortScratch& scratch) {
    if (f.rows() == 2) return detail::nondominated_sort_2d(f, rank, scratch);
    return detail::nondominated_sort_deb(f, rank, scratch);
}

/// crowding distance (Deb et al. 2002, sec. III-B) of the points `members` (indices into f's columns; one front),
/// into distance[k] for members[k]; boundary points of each objective get +infinity; a front of <= 2 points: all
/// +infinity. Objectives whose max == min contribute 0.
inline void crowding_distance(const MatrixView& f, std::span<const std::size_t> members, std::span<double> distance,
                              SortScratch& scratch) {
    const std::size_t n = members.size();
    if (distance.size() != n)
        throw InputError("crowding_distance", "distance has " + std::to_string(distance.size()) + " entries for " +
                                                  std::to_string(n) + " members");
    for (const std::size_t j : members) {
        if (j >= static_cast<std::size_t>(f.cols()))
            throw InputError("crowding_distance", "member " + std::to_string(j) + " is not a column of f (" +
                                                      std::to_string(f.cols()) + " points)");
        if (!f.col(static_cast<Eigen::Index>(j)).allFinite())
            throw InputError("crowding_distance", "point " + std::to_string(j) + " has a non-finite objective value");
    }
    constexpr double inf = std::numeric_limits<double>::infinity();
    if (n <= 2) {
        std::fill(distance.begin(), distance.end(), inf);
        return;
    }
    std::fill(distance.begin(), distance.end(), 0.0);
    auto& order = scratch.order;  // positions in `members`
    order.resize(n);
    for (Eigen::Index i = 0; i < f.rows(); ++i) {
        const auto value = [&](std::size_t k) { return f(i, static_cast<Eigen::Index>(members[k])); };
        std::iota(order.begin(), order.end(), std::size_t{0});
        std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
            const double va = value(a), vb = value(b);
            if (va != vb) return va < vb;
            if (members[a] != members[b]) return members[a] < members[b];
            return a < b;
        });
        const double lo = value(order.front()), hi = value(order.back());
        if (!(hi > lo)) continue;
        const double range = hi - lo;
        distance[order.front()] = inf;
        distance[order.back()] = inf;
        for (std::size_t k = 1; k + 1 < n; ++k)
            distance[order[k]] += (value(order[k + 1]) - value(order[k - 1])) / range;
    }
}

}  // namespace pride::pareto

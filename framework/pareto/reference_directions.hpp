#pragma once
// Reference directions on the unit simplex: the weight vectors of decomposition-based
// algorithms (MOEA/D: algorithms/moead.hpp; NSGA-III) and the lattice the DTLZ1-4 fronts are
// sampled on (problems/multiobjective/fronts.hpp). The project's one simplex lattice.
//
//   Das, I. and Dennis, J. E. (1998). Normal-boundary intersection: a new method for generating
//     the Pareto surface in nonlinear multicriteria optimization problems. SIAM J. Optim. 8(3).
//   Deb, K. and Jain, H. (2014). An evolutionary many-objective optimization algorithm using
//     reference-point-based nondominated sorting approach, part I. IEEE TEC 18(4), 577-601
//     (sec. IV-B: the two layers, for M large enough that one lattice with H >= M is too big).
//
// A set of directions is a Matrix with M rows, one column per direction, every column >= 0 and
// summing to 1. Every size is checked before anything is allocated.
#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

#include "framework/error.hpp"
#include "framework/problem.hpp"

namespace pride::pareto {

/// The largest set built: M x directions values (128 MiB).
inline constexpr std::size_t kMaxLatticeValues = std::size_t{1} << 24;
/// The largest M (as the problems' kMaxObjectives).
inline constexpr std::size_t kMaxLatticeObjectives = 10'000;

namespace detail {
/// C(H + M - 1, M - 1), or cap + 1 when larger than cap (M <= kMaxLatticeObjectives,
/// H <= kMaxLatticeValues, cap <= kMaxLatticeValues: no product overflows).
inline std::size_t lattice_size(std::size_t m, std::size_t h, std::size_t cap) {
    const std::size_t n = h + m - 1, r = std::min(h, m - 1);
    std::size_t c = 1;  // C(n - r + i, i), exact at each step
    for (std::size_t i = 1; i <= r; ++i) {
        c = c * (n - r + i) / i;
        if (c > cap) return cap + 1;
    }
    return c;
}
}  // namespace detail

/// The largest full grid over the first M - 1 coordinates that `points` allows: its side s >= 2
/// and its s^(M-1) points. InputError naming `who` when not even 2^(M-1) fit.
struct GridSide {
    std::size_t side, size;
};
inline GridSide grid_side(std::size_t m, std::size_t points, const std::string& who) {
    require(m - 1 < 25 && (std::size_t{1} << (m - 1)) <= points, who,
            "a front of M = " + std::to_string(m) + " objectives needs at least 2^(M-1) points, got " +
                std::to_string(points));
    const auto power = [&](std::size_t s) {  // s^(M-1), or points + 1 when larger
        std::size_t p = 1;
        for (std::size_t i = 0; i + 1 < m; ++i)
            if ((p *= s) > points) return points + 1;
        return p;
    };
    std::size_t s = 2;
    while (power(s + 1) <= points) ++s;
    return {s, power(s)};
}

/// The size of the simplex lattice of M objectives and H divisions, C(H + M - 1, M - 1), or
/// kMaxLatticeValues + 1 when larger than kMaxLatticeValues.
inline std::size_t simplex_lattice_size(std::size_t objectives, std::size_t divisions) {
    require(
        objectives >= 1 && objectives <= kMaxLatticeObjectives, "simplex_lattice",
        "needs 1 <= M <= " + std::to_string(kMaxLatticeObjectives) + " objectives, got " + std::to_string(objectives));
    if (divisions > kMaxLatticeValues) return kMaxLatticeValues + 1;
    return detail::lattice_size(objectives, divisions, kMaxLatticeValues);
}

/// The largest H >= 1 whose lattice has at most `points` directions (points >= M, the size for
/// H = 1). The size grows with H, so a bisection finds it.
inline std::size_t simplex_lattice_divisions(std::size_t objectives, std::size_t points) {
    const std::size_t m = objectives;
    require(m >= 2 && m <= kMaxLatticeObjectives, "simplex_lattice",
            "needs 2 <= M <= " + std::to_string(kMaxLatticeObjectives) + " objectives, got " + std::to_string(m));
    require(points >= m, "simplex_lattice",
            "a lattice of M = " + std::to_string(m) + " objectives has at least " + std::to_string(m) +
                " directions (H = 1), got " + std::to_string(points));
    std::size_t lo = 1, hi = points;  // size(lo) <= points < size(hi): size(H) >= H + 1 for M >= 2
    while (hi - lo > 1) {
        const std::size_t mid = lo + (hi - lo) / 2;
        (simplex_lattice_size(m, mid) <= points ? lo : hi) = mid;
    }
    return lo;
}

/// Das and Dennis's simplex lattice: every point with coordinates in {0, 1/H, ..., 1} summing to 1,
/// one column each (M rows, C(H + M - 1, M - 1) columns), in lexicographic order of the first
/// M - 1 coordinates.
inline Matrix simplex_lattice(std::size_t objectives, std::size_t divisions) {
    const std::size_t m = objectives, h = divisions;
    require(m >= 2 && m <= kMaxLatticeObjectives, "simplex_lattice",
            "needs 2 <= M <= " + std::to_string(kMaxLatticeObjectives) + " objectives, got " + std::to_string(m));
    require(h >= 1, "simplex_lattice", "needs H >= 1 divisions, got " + std::to_string(h));
    const std::size_t size = simplex_lattice_size(m, h);
    require(size <= kMaxLatticeValues / m, "simplex_lattice",
            "is built up to " + std::to_string(kMaxLatticeValues) +
                " values (M x points), got M = " + std::to_string(m) + " and H = " + std::to_string(h));
    Matrix out(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(size));
    std::vector<std::size_t> c(m - 1, 0);  // the first M - 1 counts; the last is H - their sum
    std::size_t sum = 0;
    const double hd = static_cast<double>(h);
    for (Eigen::Index col = 0; col < out.cols(); ++col) {
        for (std::size_t i = 0; i + 1 < m; ++i) out(static_cast<Eigen::Index>(i), col) = static_cast<double>(c[i]) / hd;
        out(static_cast<Eigen::Index>(m - 1), col) = static_cast<double>(h - sum) / hd;
        // The next counts: an odometer, the last digit fastest, kept to sum <= H.
        for (std::size_t p = m - 1; p-- > 0;) {
            if (sum < h) {
                ++c[p], ++sum;
                break;
            }
            sum -= c[p];
            c[p] = 0;
        }
    }
    return out;
}

/// The size of Deb and Jain's two-layer set: C(H1 + M - 1, M - 1) + C(H2 + M - 1, M - 1), or
/// kMaxLatticeValues + 1 when larger than kMaxLatticeValues.
inline std::size_t two_layer_lattice_size(std::size_t objectives, std::size_t outer, std::size_t inner) {
    const std::size_t a = simplex_lattice_size(objectives, outer), b = simplex_lattice_size(objectives, inner);
    return a + b > kMaxLatticeValues ? kMaxLatticeValues + 1 : a + b;
}

/// Deb and Jain's two layers: the lattice of H1 = `outer` divisions (the boundary layer), then the
/// lattice of H2 = `inner` divisions shrunk by 1/2 toward the centre c = (1/M, ..., 1/M),
/// v -> (v + c) / 2, so that the inner points stay off the boundary (its columns after the
/// outer's). M = 8, H1 = 3, H2 = 2 gives 120 + 36 = 156 directions (the paper's Table I).
inline Matrix two_layer_lattice(std::size_t objectives, std::size_t outer, std::size_t inner) {
    const std::size_t m = objectives;
    require(m >= 2 && m <= kMaxLatticeObjectives, "two_layer_lattice",
            "needs 2 <= M <= " + std::to_string(kMaxLatticeObjectives) + " objectives, got " + std::to_string(m));
    require(outer >= 1 && inner >= 1, "two_layer_lattice",
            "needs H1 >= 1 and H2 >= 1 divisions, got H1 = " + std::to_string(outer) +
                " and H2 = " + std::to_string(inner));
    const std::size_t size = two_layer_lattice_size(m, outer, inner);
    require(size <= kMaxLatticeValues / m, "two_layer_lattice",
            "is built up to " + std::to_string(kMaxLatticeValues) + " values (M x points), got M = " +
                std::to_string(m) + ", H1 = " + std::to_string(outer) + " and H2 = " + std::to_string(inner));
    const Matrix a = simplex_lattice(m, outer), b = simplex_lattice(m, inner);
    Matrix out(a.rows(), a.cols() + b.cols());
    out.leftCols(a.cols()) = a;
    const double centre = 1.0 / static_cast<double>(m);
    out.rightCols(b.cols()) = (b.array() + centre) * 0.5;
    return out;
}

}  // namespace pride::pareto

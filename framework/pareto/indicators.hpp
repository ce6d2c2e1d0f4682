#pragma once
// Distance-based quality indicators of a set A (the columns of f) against a reference set Z (the
// columns of `reference`, usually points of the exact Pareto front), all objectives minimised.
// Nothing is normalised: the user scales the objectives beforehand if they differ in range
// (docs/multiobjective.md). Each is O(|A| |Z| M), with no allocation.
//
// Sources of the formulas, d(x, y) being the Euclidean distance:
// - GD and IGD as means, as Ishibuchi, Masuda, Tanigaki and Nojima 2015 ("Modified distance
//   calculation in generational distance and inverted generational distance", EMO 2015, LNCS 9019)
//   write them: GD(A) = 1/|A| sum_{a in A} min_{z in Z} d(a, z) and
//   IGD(A) = 1/|Z| sum_{z in Z} min_{a in A} d(z, a).
//   Decision: Van Veldhuizen's original GD is (sum d^2)^(1/2) / |A|; the mean (p = 1) is used
//   here, as in Ishibuchi et al. and in Coello and Reyes Sierra 2004's IGD, so that GD and IGD are
//   on the same scale as the distances themselves.
// - IGD+ and GD+ (Ishibuchi et al. 2015): d+(z, a) = sqrt(sum_i max(a_i - z_i, 0)^2), how far a is
//   worse than z, counting only the objectives in which it is worse; IGD+(A) = 1/|Z| sum_z
//   min_a d+(z, a) and GD+(A) = 1/|A| sum_a min_z d+(z, a). IGD+ is weakly Pareto compliant;
//   IGD+ <= IGD since d+ <= d.
// - The additive epsilon indicator (Zitzler, Thiele, Laumanns, Fonseca and Grunert da Fonseca 2003,
//   "Performance assessment of multiobjective optimizers: an analysis and review", IEEE TEC 7(2)):
//   I_eps+(A, Z) = the smallest eps such that every z is weakly dominated by some a - eps
//   = max_{z in Z} min_{a in A} max_i (a_i - z_i). It is negative when A is strictly better than Z.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>

#include "framework/error.hpp"
#include "framework/problem.hpp"

namespace pride::pareto {

namespace detail {

inline void check_indicator_input(const char* who, const MatrixView& f, const MatrixView& reference) {
    require(f.rows() > 0, who, "the points have no objectives (M == 0)");
    require(reference.rows() == f.rows(), who,
            "the reference set has " + std::to_string(reference.rows()) + " objectives, the points " +
                std::to_string(f.rows()));
    require(f.cols() > 0, who, "the set of points is empty");
    require(reference.cols() > 0, who, "the reference set is empty");
    require(!f.hasNaN(), who, "a point has a NaN objective value");
    require(!reference.hasNaN(), who, "a reference point has a NaN objective value");
}

/// d(z, a), Euclidean (a function object, so that mean_nearest inlines it).
inline constexpr auto distance = [](const MatrixView& z, Eigen::Index i, const MatrixView& a, Eigen::Index j) noexcept {
    double sum = 0.0;
    for (Eigen::Index r = 0; r < z.rows(); ++r) {
        const double diff = a(r, j) - z(r, i);
        sum += diff * diff;
    }
    return std::sqrt(sum);
};

/// d+(z, a) = sqrt(sum max(a_r - z_r, 0)^2): how far a is worse than z.
inline constexpr auto distance_plus = [](const MatrixView& z, Eigen::Index i, const MatrixView& a,
                                         Eigen::Index j) noexcept {
    double sum = 0.0;
    for (Eigen::Index r = 0; r < z.rows(); ++r) {
        const double diff = std::max(a(r, j) - z(r, i), 0.0);
        sum += diff * diff;
    }
    return std::sqrt(sum);
};

/// 1/|from| sum_{x in from} min_{y in to} dist(x, y), dist being called as dist(from, x, to, y)
/// or, `swapped`, as dist(to, y, from, x) (d+ is not symmetric).
template <bool swapped, class Distance>
double mean_nearest(const MatrixView& from, const MatrixView& to, Distance dist) {
    double sum = 0.0;
    for (Eigen::Index x = 0; x < from.cols(); ++x) {
        double nearest = std::numeric_limits<double>::infinity();
        for (Eigen::Index y = 0; y < to.cols(); ++y)
            nearest = std::min(nearest, swapped ? dist(to, y, from, x) : dist(from, x, to, y));
        sum += nearest;
    }
    return sum / static_cast<double>(from.cols());
}

}  // namespace detail

/// IGD: the mean over the reference points of the Euclidean distance to the nearest point of f.
inline double igd(const MatrixView& f, const MatrixView& reference) {
    detail::check_indicator_input("igd", f, reference);
    return detail::mean_nearest<false>(reference, f, detail::distance);
}

/// IGD+: as IGD with d+(z, a) = sqrt(sum_i max(a_i - z_i, 0)^2) (z a reference point, a in f).
inline double igd_plus(const MatrixView& f, const MatrixView& reference) {
    detail::check_indicator_input("igd+", f, reference);
    return detail::mean_nearest<false>(reference, f, detail::distance_plus);
}

/// GD: the mean over the points of f of the Euclidean distance to the nearest reference point.
inline double gd(const MatrixView& f, const MatrixView& reference) {
    detail::check_indicator_input("gd", f, reference);
    return detail::mean_nearest<false>(f, reference, detail::distance);
}

/// GD+: the mean over the points a of f of min_z d+(z, a).
inline double gd_plus(const MatrixView& f, const MatrixView& reference) {
    detail::check_indicator_input("gd+", f, reference);
    return detail::mean_nearest<true>(f, reference, detail::distance_plus);
}

/// The additive epsilon indicator I_eps+(f, reference) = max_z min_a max_i (a_i - z_i): the
/// smallest eps by which every point of f may be moved so that each reference point is weakly
/// dominated by one of them.
inline double epsilon_additive(const MatrixView& f, const MatrixView& reference) {
    detail::check_indicator_input("epsilon", f, reference);
    double worst = -std::numeric_limits<double>::infinity();
    for (Eigen::Index z = 0; z < reference.cols(); ++z) {
        double best = std::numeric_limits<double>::infinity();
        for (Eigen::Index a = 0; a < f.cols(); ++a) {
            double shift = -std::numeric_limits<double>::infinity();
            for (Eigen::Index i = 0; i < f.rows(); ++i) shift = std::max(shift, f(i, a) - reference(i, z));
            best = std::min(best, shift);
        }
        worst = std::max(worst, best);
    }
    return worst;
}

}  // namespace pride::pareto

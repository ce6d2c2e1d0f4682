#pragma once
// Constraints: a box problem may declare m inequality constraints g_i(x) <= 0 and p equality
// constraints h_j(x) = 0. One evaluation gives f and the m + p constraint values together (the m
// inequalities first, then the p equalities), counted once. A point's violation is one number,
// 0 when it is feasible; how it is measured is the suite's (its problem's `violation`); the default
// is CEC 2006's and CEC 2020's (Liang et al. 2006, Kumar et al. 2020): the mean, over the m + p
// constraints, of G_i = max(0, g_i) and H_j = |h_j| where |h_j| > tolerance (else 0), tolerance 1e-4
// (Liang et al. 2006, sec. 2; Kumar et al. 2020's guidelines, eq. 2).
//
// Decisions left open by those reports: a constraint value that is NaN makes the point infeasible
// with an infinite violation; +-inf values count as they are (+inf: an infinite violation).
#include <cmath>
#include <concepts>
#include <cstddef>
#include <limits>
#include <span>

#include "framework/problem.hpp"

namespace pride {

/// How many constraints a problem has, of each kind.
struct ConstraintCounts {
    std::size_t inequalities = 0;  // m: g_i(x) <= 0
    std::size_t equalities = 0;    // p: h_j(x) = 0 within the tolerance
    std::size_t total() const noexcept { return inequalities + equalities; }
    friend bool operator==(const ConstraintCounts&, const ConstraintCounts&) = default;
};

/// The tolerance within which an equality constraint holds (CEC 2006 and CEC 2020: 1e-4).
inline constexpr double kEqualityTolerance = 1e-4;

/// The part of one constraint's value that is a violation: max(0, g) for an inequality, |h| for an
/// equality beyond the tolerance (0 within it: the tolerance decides feasibility only); +inf for NaN.
inline double inequality_violation(double g) noexcept {
    if (std::isnan(g)) return std::numeric_limits<double>::infinity();
    return g > 0.0 ? g : 0.0;
}
inline double equality_violation(double h, double tolerance) noexcept {
    if (std::isnan(h)) return std::numeric_limits<double>::infinity();
    const double magnitude = std::abs(h);
    return magnitude - tolerance > 0.0 ? magnitude : 0.0;
}

/// CEC 2006's and CEC 2020's violation: the mean of the constraints' violations (0 without
/// constraints). `values` holds the m inequalities, then the p equalities.
inline double mean_violation(std::span<const double> values, const ConstraintCounts& counts,
                             double tolerance = kEqualityTolerance) noexcept {
    if (counts.total() == 0) return 0.0;
    double sum = 0.0;
    for (std::size_t i = 0; i < counts.inequalities; ++i) sum += inequality_violation(values[i]);
    for (std::size_t j = 0; j < counts.equalities; ++j)
        sum += equality_violation(values[counts.inequalities + j], tolerance);
    return sum / static_cast<double>(counts.total());
}

/// A box problem with constraints: its counts, an evaluation that gives f and writes the m + p
/// constraint values into `constraints` (inequalities first), and its measure of a point's
/// violation from those values (mean_violation for the CEC suites).
template <class P>
concept ConstrainedProblem = BoxProblem<P> &&
    requires(P& p, const P& cp, std::span<const double> x, std::span<double> c, std::span<const double> cc) {
    { cp.constraint_counts() } -> std::convertible_to<ConstraintCounts>;
    { p.evaluate_constrained(x, c) } -> std::convertible_to<double>;
    { cp.violation(cc) } -> std::convertible_to<double>;
};

}  // namespace pride

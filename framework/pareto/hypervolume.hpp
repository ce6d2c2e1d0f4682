#pragma once
// The hypervolume indicator (Zitzler and Thiele 1998): the Lebesgue measure of the region that a
// set of points dominates and that dominates the reference point r, all objectives minimised.
// The user chooses r; nothing is normalised here (docs/multiobjective.md).
//
//   M = 1: r - min f;   M = 2: sweep, O(N log N);   M = 3: Beume et al. 2009's sweep, O(N log N)
//   (hypervolume_sweep.hpp);   M > 3: WFG (While, Bradstreet and Barone 2012, hypervolume_wfg.hpp)
//   with the 3-D sweep as its base case.
//
// contributions(): each point's exclusive hypervolume HV(S) - HV(S \ {p}) (what SMS-EMOA removes
// the least of; Beume, Naujoks and Emmerich 2007). M = 2 from the sorted neighbours; otherwise as
// WFG's exclhv: inclhv(p) - HV(nds({max(p, q) : q != p})), which is exact and cancels against p's
// own box rather than against the whole set's volume.
// Decisions left open: a point that does not strictly dominate r (r_i - p_i > 0 in every
// objective) contributes nothing, even if it lies on the boundary of r's box (zero volume); a
// point weakly dominated by another (an equal one included) contributes 0; rounding below 0 in a
// contribution is returned as 0.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <span>
#include <string>
#include <vector>

#include "framework/error.hpp"
#include "framework/pareto/dominance.hpp"
#include "framework/pareto/hypervolume_sweep.hpp"
#include "framework/pareto/hypervolume_wfg.hpp"
#include "framework/problem.hpp"

namespace pride::pareto {

namespace detail {

/// Refuses input that has no hypervolume: one line naming what (`who`: the function called).
inline void check_hypervolume_input(const char* who, const MatrixView& f, std::span<const double> ref) {
    require(f.rows() > 0, who, "the points have no objectives (M == 0)");
    require(ref.size() == static_cast<std::size_t>(f.rows()), who,
            "the reference point has " + std::to_string(ref.size()) + " coordinates for " + std::to_string(f.rows()) +
                " objectives");
    // The messages are built once per call, not once per value checked.
    const auto bad_ref = std::find_if(ref.begin(), ref.end(), [](double v) { return !std::isfinite(v); });
    require(bad_ref == ref.end(), who,
            "reference point coordinate " + std::to_string(bad_ref - ref.begin()) + " is not finite");
    const Eigen::Index nan = first_nan_column(f);
    require(nan < 0, who, "point " + std::to_string(nan) + " has a NaN objective value");
    Eigen::Index minus_infinity = 0;
    while (minus_infinity < f.cols() &&
           (f.col(minus_infinity).array() != -std::numeric_limits<double>::infinity()).all())
        ++minus_infinity;
    require(minus_infinity == f.cols(), who,
            "point " + std::to_string(minus_infinity) + " has an objective at -infinity (an infinite volume)");
}

/// The scratch of WFG for n points in m objectives, in bytes: m + 1 limit sets of n points.
inline double wfg_scratch_bytes(std::size_t n, std::size_t m) {
    return 8.0 * static_cast<double>(m + 1) * static_cast<double>(n) * (static_cast<double>(m) + 1.0);
}

/// Refuses an exact computation (`who`: hypervolume or contributions) of n mutually non-dominated
/// points in m objectives beyond exact_hypervolume_points() (for contributions, half of it: each
/// point's exclusive volume is a WFG call of its own) or beyond 256 MiB of scratch.
inline void check_exact_size(const char* who, std::size_t n, std::size_t m, bool contributions);

/// The points of f that strictly dominate ref, flat (M apart), with their column indices.
struct Dominating {
    std::vector<double> values;
    std::vector<std::size_t> columns;
    std::size_t size() const noexcept { return columns.size(); }
    const double* at(std::size_t k) const noexcept { return values.data() + k * m; }
    std::size_t m = 0;
};

inline Dominating dominating(const MatrixView& f, std::span<const double> ref) {
    Dominating d;
    d.m = static_cast<std::size_t>(f.rows());
    for (Eigen::Index j = 0; j < f.cols(); ++j) {
        bool inside = true;
        for (std::size_t i = 0; i < d.m; ++i) inside = inside && f(static_cast<Eigen::Index>(i), j) < ref[i];
        if (!inside) continue;
        d.values.insert(d.values.end(), f.col(j).data(), f.col(j).data() + d.m);
        d.columns.push_back(static_cast<std::size_t>(j));
    }
    return d;
}

/// The hypervolume of n flat points (each strictly dominating ref) in m objectives. `base` is the
/// dimension WFG hands to a sweep (3; 2 to check the 3-D sweep against WFG).
inline double hypervolume_flat(const double* p, std::size_t n, std::size_t m, const double* ref, WfgScratch& s) {
    if (n == 0) return 0.0;
    if (n == 1) return box_volume(p, m, ref);
    if (m == 1) {
        double lo = p[0];
        for (std::size_t k = 1; k < n; ++k) lo = std::min(lo, p[k * s.stride]);
        return ref[0] - lo;
    }
    return wfg(p, n, m, ref, s);  // dispatches M = 2, 3 to the sweeps
}

/// hypervolume() with WFG's base case chosen (2 or 3).
inline double hypervolume_with_base(const MatrixView& f, std::span<const double> ref, std::size_t base) {
    check_hypervolume_input("hypervolume", f, ref);
    Dominating d = dominating(f, ref);
    const std::size_t m = d.m;
    std::size_t n = d.size();
    if (m > 3) {  // WFG's cost grows fast with N: dominated points go first
        std::size_t kept = 0;
        for (std::size_t k = 0; k < n; ++k) kept = add_nondominated(d.values.data(), kept, d.at(k), m, m);
        n = kept;
        check_exact_size("hypervolume", n, m, false);
    }
    WfgScratch s;
    s.prepare(n, m, base);
    return hypervolume_flat(d.values.data(), n, m, ref.data(), s);
}

/// The exclusive contributions for M = 2: sorted by (f1, f2), the non-dominated points form a
/// staircase; point k of it alone covers the rectangle [x_k, x_{k+1}) x [y_k, y_{k-1}) (x_{K} = r1,
/// y_{-1} = r2), less what the points it dominates cover there (they would be uncovered without it).
inline void contributions_2d(const Dominating& d, const double* ref, std::vector<double>& out) {
    const std::size_t n = d.size();
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&d](std::size_t a, std::size_t b) {
        const double *pa = d.at(a), *pb = d.at(b);
        if (pa[0] != pb[0]) return pa[0] < pb[0];
        if (pa[1] != pb[1]) return pa[1] < pb[1];
        return a < b;
    });
    // Pass 1: the staircase (position in `order` of each step), and which steps have an equal point.
    constexpr std::size_t none = std::numeric_limits<std::size_t>::max();
    std::vector<std::size_t> steps;
    std::vector<char> repeated;
    std::vector<std::size_t> step_of(n, none);  // the step whose rectangle a dominated point may cut
    for (std::size_t k = 0; k < n; ++k) {
        const double* q = d.at(order[k]);
        if (!steps.empty()) {
            const double* l = d.at(order[steps.back()]);
            if (q[0] == l[0] && q[1] == l[1]) {
                repeated.back() = 1;
                continue;
            }
            if (q[1] >= l[1]) {  // dominated by the last step, the lowest one so far
                step_of[k] = steps.size() - 1;
                continue;
            }
        }
        steps.push_back(k);
        repeated.push_back(0);
    }
    // Pass 2: the dominated points of each rectangle come right after its step, in increasing f1.
    for (std::size_t t = 0; t < steps.size(); ++t) {
        const double* p = d.at(order[steps[t]]);
        const double right = t + 1 < steps.size() ? d.at(order[steps[t + 1]])[0] : ref[0];
        const double top = t > 0 ? d.at(order[steps[t - 1]])[1] : ref[1];
        double covered = 0.0, lowest = top;
        for (std::size_t k = steps[t] + 1; k < n && (t + 1 == steps.size() || k < steps[t + 1]); ++k) {
            if (step_of[k] != t) continue;
            const double* q = d.at(order[k]);
            if (q[1] < lowest) {
                covered += (right - q[0]) * (lowest - q[1]);
                lowest = q[1];
            }
        }
        if (!repeated[t]) out[d.columns[order[steps[t]]]] = std::max(0.0, (right - p[0]) * (top - p[1]) - covered);
    }
}

}  // namespace detail

/// The most mutually non-dominated points whose hypervolume is computed exactly in m objectives.
/// WFG's time grows exponentially with M; measured in its worst case (points spread on the unit
/// sphere, none dominated: DTLZ2's front), each bound takes 0.05 to 0.9 s on the 2-core machine
/// (docs/multiobjective.md gives the table), so that a wall-time limit or Ctrl-C is never held up
/// longer inside one computation. M <= 3 (sweeps, O(N log N)) has no bound but memory's.
inline std::size_t exact_hypervolume_points(std::size_t m) {
    constexpr std::size_t by_objectives[] = {8000, 4000, 1000, 400, 150, 100, 64, 48, 40, 32, 28, 24, 24};  // M = 4..16
    if (m <= 3) return std::numeric_limits<std::size_t>::max();
    if (m <= 16) return by_objectives[m - 4];
    return std::max<std::size_t>(2, 384 / m);  // past 16 objectives each point costs its M coordinates
}

namespace detail {
inline void check_exact_size(const char* who, std::size_t n, std::size_t m, bool contributions) {
    const std::size_t most = contributions ? exact_hypervolume_points(m) / 2 : exact_hypervolume_points(m);
    require(n <= most, who,
            "an exact " + std::string(contributions ? "hypervolume contribution" : "hypervolume") + " of " +
                std::to_string(n) + " non-dominated points in " + std::to_string(m) +
                " objectives is beyond what is computed in about a second (at most " + std::to_string(most) +
                " points in " + std::to_string(m) + " objectives; fewer points or objectives)");
    require(wfg_scratch_bytes(n, m) <= 256.0 * 1024 * 1024, who,
            "an exact hypervolume of " + std::to_string(n) + " points in " + std::to_string(m) +
                " objectives needs more than 256 MiB of scratch memory (fewer points or objectives)");
}
}  // namespace detail

/// The hypervolume of the columns of `f` (M rows) with respect to `ref` (M values). Points that do
/// not strictly dominate ref add nothing; the set need not be non-dominated.
inline double hypervolume(const MatrixView& f, std::span<const double> ref) {
    return detail::hypervolume_with_base(f, ref, 3);
}

/// contributions[j] = HV(S) - HV(S without column j) for every column j of f (0 for a point that
/// does not strictly dominate ref, that another point weakly dominates, or that has an equal).
inline std::vector<double> contributions(const MatrixView& f, std::span<const double> ref) {
    detail::check_hypervolume_input("contributions", f, ref);
    const detail::Dominating d = detail::dominating(f, ref);
    const std::size_t m = d.m, n = d.size();
    std::vector<double> out(static_cast<std::size_t>(f.cols()), 0.0);
    if (m == 2) {
        detail::contributions_2d(d, ref.data(), out);
        return out;
    }
    detail::check_exact_size("contributions", n, m, true);
    detail::WfgScratch s;
    s.prepare(n, m, 3);
    double* limit = s.limit[m].data();  // WFG in m objectives works in limit[m - 1] and below
    double* w = s.candidate[m].data();
    for (std::size_t k = 0; k < n; ++k) {
        const double* p = d.at(k);
        std::size_t count = 0;
        bool covered = false;  // another point weakly dominates p: its limit point is p itself
        for (std::size_t j = 0; j < n && !covered; ++j) {
            if (j == k) continue;
            const double* q = d.at(j);
            for (std::size_t i = 0; i < m; ++i) w[i] = std::max(p[i], q[i]);
            covered = detail::weakly_dominates_flat(q, p, m);
            count = detail::add_nondominated(limit, count, w, m, m);
        }
        if (covered) continue;
        const double alone = detail::box_volume(p, m, ref.data());
        out[d.columns[k]] = std::max(0.0, alone - detail::hypervolume_flat(limit, count, m, ref.data(), s));
    }
    return out;
}

}  // namespace pride::pareto

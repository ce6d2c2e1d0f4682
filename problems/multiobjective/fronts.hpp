#pragma once
// The analytic Pareto fronts of the ZDT and DTLZ problems (zdt.hpp, dtlz.hpp), sampled, and the
// distance of a point to them.
//
//   Matrix reference_front(name, M, points)   M rows, one column per point of the front
//   Matrix reference_front(problem, points)   the same for a problem object (its name and M)
//   double distance_to_front(name, f)         Euclidean distance of the objective vector f to it
//   double dtlz7_front_gap(f)                 DTLZ7's residual (no closed-form distance)
//
// Names: "zdt1", "zdt2", "zdt3", "zdt4", "zdt6" (M = 2) and "dtlz1" ... "dtlz7" (M >= 2), as the
// classes' name(). How many points a front has, and how they are spread:
//
//   zdt1, zdt4  f2 = 1 - sqrt(f1), f1 in [0, 1]                 exactly `points`, evenly in f1
//   zdt2        f2 = 1 - f1^2, f1 in [0, 1]                     exactly `points`, evenly in f1
//   zdt3        f2 = 1 - sqrt(f1) - f1 sin(10 pi f1), f1 on the  exactly `points`, evenly in f1
//               five pieces where it is non-dominated            over the pieces
//   zdt6        f2 = 1 - f1^2, f1 in [zdt6_front_f1_min(), 1]   exactly `points`, evenly in f1
//   dtlz1       sum f = 0.5, f >= 0                             the largest Das-Dennis lattice of
//   dtlz2-4     sum f^2 = 1, f >= 0                             at most `points` (the lattice's points
//                                                               scaled by 0.5, or normalised)
//   dtlz5, 6    the quarter circle f = (cos t) w + (sin t) e_M,  exactly `points`, evenly in t
//               t in [0, pi/2], w = (2^-(M-2)/2, 2^-(M-2)/2, 2^-(M-3)/2, ..., 2^-1/2, 0)
//               (M = 2: w = (1, 0), DTLZ2's quarter circle)
//   dtlz7       f_M = 2 (M - sum_{i<M} f_i / 2 (1 + sin(3 pi f_i))), each f_i (i < M) on the two
//               pieces of dtlz7_front_pieces(): a grid of s^(M-1) points, s the largest with
//               s^(M-1) <= points (s >= 2), each axis spread evenly over the two pieces
//
// Why DTLZ7's grid needs no filtering: with g = 1, f_M = 2M - sum_i phi(f_i), phi(t) = t (1 + sin
// 3 pi t), is separable, so a point of the grid over [0, 1]^(M-1) is non-dominated exactly when each
// of its f_i is non-dominated for the single pair (f_i, -phi(f_i)), i.e. lies on the pieces. The
// grid over [0, 1]^(M-1) filtered by dominance therefore keeps the product of the pieces, which is
// what is sampled directly. Likewise ZDT3's pieces are where f2 is below its value at every smaller
// f1. The closed ends of the later pieces (where f2, or phi, ties the previous piece's end) are
// limits of the front: weakly dominated by a hair, kept as the front's closure.
//
// distance_to_front: for zdt1, 2, 3, 4, 6 a scan of the curve and a golden-section refinement (to about
// 1e-15); dtlz1 the exact projection onto the simplex; dtlz2-4 the closed form (the nearest point of
// the sphere's positive part is max(f, 0) normalised); dtlz5, 6 the closed form for the quarter
// circle (the part of f off its plane, and the distance in the plane).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <numbers>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "framework/error.hpp"
#include "framework/pareto/reference_directions.hpp"
#include "framework/problem.hpp"
#include "problems/multiobjective/box.hpp"

namespace pride::multiobjective {

/// The largest front reference_front() builds: M x points values (128 MiB).
inline constexpr std::size_t kMaxFrontValues = std::size_t{1} << 24;

/// A closed interval [lo, hi] of one objective.
struct Interval {
    double lo;
    double hi;
};

namespace detail {

/// A root of `fn` in [a, b], where fn(a) < 0 <= fn(b) or fn(a) >= 0 > fn(b): bisection to the last
/// bit.
template <class Fn>
double bisect(Fn fn, double a, double b) {
    const bool a_negative = fn(a) < 0.0;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (a + b);
        if (mid <= a || mid >= b) break;
        ((fn(mid) < 0.0) == a_negative ? a : b) = mid;
    }
    return 0.5 * (a + b);
}

/// The pieces of [0, 1] where q(t) < q(s) for every s < t: where the pair (t, q(t)), both
/// minimised, is non-dominated. `dq` is q's derivative. A scan of 10^5 steps finds where each piece
/// ends (dq turns from < 0 to >= 0: a local minimum, or t = 1) and where the next begins (q drops
/// below that minimum); bisection then places both to the last bit.
template <class Q, class DQ>
std::vector<Interval> running_minimum_pieces(Q q, DQ dq) {
    constexpr int steps = 100'000;
    auto at = [](int i) { return static_cast<double>(i) / steps; };
    std::vector<Interval> pieces;
    double start = 0.0;
    int i = 0;
    while (true) {
        // The end of the piece from `start`: the first local minimum of q after it.
        while (i < steps && !(dq(std::max(at(i), 1e-12)) < 0.0 && dq(at(i + 1)) >= 0.0)) ++i;
        const double end = i == steps ? 1.0 : bisect(dq, std::max(at(i), 1e-12), at(i + 1));
        pieces.push_back({start, end});
        if (i == steps) break;
        // The next piece starts where q first drops below q(end).
        const double level = q(end);
        ++i;
        while (i < steps && !(q(at(i + 1)) < level)) ++i;
        if (i == steps) break;
        start = bisect([&](double t) { return level - q(t); }, at(i), at(i + 1));
    }
    return pieces;
}

inline double total_length(std::span<const Interval> pieces) {
    double length = 0.0;
    for (const auto& p : pieces) length += p.hi - p.lo;
    return length;
}

/// The point `u` of the way along the pieces laid end to end (u in [0, total_length]).
inline double along(std::span<const Interval> pieces, double u) {
    for (const auto& p : pieces) {
        if (u <= p.hi - p.lo) return p.lo + u;
        u -= p.hi - p.lo;
    }
    return pieces.back().hi;
}

/// `count` points spread evenly over the pieces laid end to end, both ends included (count >= 2).
inline std::vector<double> spread_over(std::span<const Interval> pieces, std::size_t count) {
    const double length = total_length(pieces);
    std::vector<double> t(count);
    for (std::size_t j = 0; j < count; ++j)
        t[j] = j + 1 == count ? pieces.back().hi
                              : along(pieces, length * static_cast<double>(j) / static_cast<double>(count - 1));
    return t;
}

/// The distance from t to the nearest of the pieces.
inline double distance_to_pieces(std::span<const Interval> pieces, double t) {
    double best = std::numeric_limits<double>::infinity();
    for (const auto& p : pieces) best = std::min(best, t < p.lo ? p.lo - t : t > p.hi ? t - p.hi : 0.0);
    return best;
}

/// The distance from (px, py) to the curve u -> c(u), u in [a, b] (c smooth): a scan of 512 steps,
/// then golden-section search between the neighbours of the nearest scanned point.
template <class Curve>
double distance_to_curve(Curve c, double a, double b, double px, double py) {
    auto d2 = [&](double u) {
        const auto [x, y] = c(u);
        return (x - px) * (x - px) + (y - py) * (y - py);
    };
    constexpr int steps = 512;
    auto at = [&](int i) { return i == steps ? b : a + (b - a) * static_cast<double>(i) / steps; };
    int best = 0;
    double best_d2 = d2(a);
    for (int i = 1; i <= steps; ++i) {
        const double v = d2(at(i));
        if (v < best_d2) best_d2 = v, best = i;
    }
    double lo = at(std::max(best - 1, 0)), hi = at(std::min(best + 1, steps));
    const double r = (std::sqrt(5.0) - 1.0) / 2.0;
    double x1 = hi - r * (hi - lo), x2 = lo + r * (hi - lo);
    double f1 = d2(x1), f2 = d2(x2);
    for (int it = 0; it < 200 && hi - lo > 1e-17; ++it) {
        if (f1 <= f2) {
            hi = x2, x2 = x1, f2 = f1;
            x1 = hi - r * (hi - lo), f1 = d2(x1);
        } else {
            lo = x1, x1 = x2, f1 = f2;
            x2 = lo + r * (hi - lo), f2 = d2(x2);
        }
    }
    return std::sqrt(std::min({best_d2, f1, f2, d2(lo), d2(hi)}));
}

/// ZDT3's front, f2 = h(f1) with g = 1.
inline double zdt3_h(double t) {
    return 1.0 - std::sqrt(t) - t * std::sin(10.0 * std::numbers::pi * t);
}

/// DTLZ7's phi(t) = t (1 + sin(3 pi t)): f_M = 2 (M - sum phi(f_i) / 2) on the front.
inline double dtlz7_phi(double t) {
    return t * (1.0 + std::sin(3.0 * std::numbers::pi * t));
}

enum class Family { zdt1, zdt2, zdt3, zdt4, zdt6, dtlz1, dtlz2, dtlz3, dtlz4, dtlz5, dtlz6, dtlz7 };

inline constexpr std::array<std::pair<std::string_view, Family>, 12> kFamilies{{{"zdt1", Family::zdt1},
                                                                                {"zdt2", Family::zdt2},
                                                                                {"zdt3", Family::zdt3},
                                                                                {"zdt4", Family::zdt4},
                                                                                {"zdt6", Family::zdt6},
                                                                                {"dtlz1", Family::dtlz1},
                                                                                {"dtlz2", Family::dtlz2},
                                                                                {"dtlz3", Family::dtlz3},
                                                                                {"dtlz4", Family::dtlz4},
                                                                                {"dtlz5", Family::dtlz5},
                                                                                {"dtlz6", Family::dtlz6},
                                                                                {"dtlz7", Family::dtlz7}}};

/// The family of `name`, and a check that it has `m` objectives; `where` names the caller.
inline Family family(std::string_view where, std::string_view name, std::size_t m) {
    for (const auto& [n, f] : kFamilies) {
        if (n != name) continue;
        const std::string w(name);
        if (n.starts_with("zdt")) {
            require(m == 2, w, "has 2 objectives, got " + std::to_string(m));
        } else {
            require(m >= 2, w, "needs M >= 2 objectives, got " + std::to_string(m));
            require(m <= kMaxObjectives, w,
                    "is built up to M = " + std::to_string(kMaxObjectives) + " objectives, got " + std::to_string(m));
        }
        return f;
    }
    std::string names;
    for (const auto& entry : kFamilies) names += (names.empty() ? "" : ", ") + std::string(entry.first);
    throw InputError(std::string(where), "unknown problem '" + std::string(name) + "' (known: " + names + ")");
}

/// The unit vector w of DTLZ5's and DTLZ6's front in the first M - 1 objectives:
/// w_1 = 2^-(M-2)/2, w_j = 2^-(M-j)/2 (j = 2..M-1). (At g = 0 every angle but the first is pi/4.)
inline double degenerate_weight(std::size_t m, std::size_t j) {  // j = 0..M-2
    const std::size_t e = j == 0 ? m - 2 : m - 1 - j;
    return std::pow(0.5, 0.5 * static_cast<double>(e));
}

}  // namespace detail

/// The five pieces of f1 on which ZDT3's front lies (about [0, 0.0830], [0.1822, 0.2578],
/// [0.4093, 0.4539], [0.6184, 0.6525], [0.8233, 0.8518]); computed once, to the last bit.
inline const std::vector<Interval>& zdt3_front_pieces() {
    static const std::vector<Interval> pieces = detail::running_minimum_pieces(detail::zdt3_h, [](double t) {
        const double w = 10.0 * std::numbers::pi;
        return -0.5 / std::sqrt(t) - std::sin(w * t) - w * t * std::cos(w * t);
    });
    return pieces;
}

/// The two pieces of each f_i (i < M) on which DTLZ7's front lies (about [0, 0.2514] and
/// [0.6316, 0.8594]); computed once, to the last bit.
inline const std::vector<Interval>& dtlz7_front_pieces() {
    static const std::vector<Interval> pieces =
        detail::running_minimum_pieces([](double t) { return -detail::dtlz7_phi(t); },
                                       [](double t) {
                                           const double w = 3.0 * std::numbers::pi;
                                           return -(1.0 + std::sin(w * t) + w * t * std::cos(w * t));
                                       });
    return pieces;
}

/// The smallest f1 of ZDT6, 0.28077531881537: f1 = 1 - exp(-4 x) sin^6(6 pi x) is least where
/// d/dx log(exp(-4 x) sin^6(6 pi x)) = -4 + 36 pi cot(6 pi x) = 0, x = atan(9 pi) / (6 pi) (the
/// first lobe of sin^6; exp(-4 x) makes the later ones lower). The 0.2807753191 often quoted is a
/// numerical estimate, 3e-10 above it.
inline double zdt6_front_f1_min() {
    const double x = std::atan(9.0 * std::numbers::pi) / (6.0 * std::numbers::pi);
    return 1.0 - std::exp(-4.0 * x) * std::pow(std::sin(6.0 * std::numbers::pi * x), 6.0);
}

/// The simplex lattice is the project's one (framework/pareto/reference_directions.hpp); it is
/// named here too, as the DTLZ1-4 fronts are built on it.
using pareto::simplex_lattice;
using pareto::simplex_lattice_size;
static_assert(kMaxFrontValues == pareto::kMaxLatticeValues && kMaxObjectives == pareto::kMaxLatticeObjectives,
              "the lattice's limits are the fronts'");

/// The analytic Pareto front of the problem `name` with M = `objectives`, sampled with `points`
/// points or, for the lattices and DTLZ7's grid, the largest one of at most `points` (the table at
/// the top of this file): M rows, one column per point. InputError when the name is unknown, M is
/// not the problem's, `points` is below the smallest front (2; M for dtlz1-4; 2^(M-1) for dtlz7)
/// or M x points is beyond kMaxFrontValues.
inline Matrix reference_front(std::string_view name, std::size_t objectives, std::size_t points) {
    using detail::Family;
    const std::string w(name);
    const Family fam = detail::family("reference_front", name, objectives);
    const std::size_t m = objectives;
    require(points <= kMaxFrontValues / m, w,
            "a front is built up to " + std::to_string(kMaxFrontValues) +
                " values (M x points), got M = " + std::to_string(m) + " and " + std::to_string(points) + " points");
    const auto cols = [](std::size_t n) { return static_cast<Eigen::Index>(n); };

    switch (fam) {
        case Family::dtlz1:
        case Family::dtlz2:
        case Family::dtlz3:
        case Family::dtlz4: {
            require(points >= m, w,
                    "a front of M = " + std::to_string(m) + " objectives needs at least " + std::to_string(m) +
                        " points (the lattice with H = 1), got " + std::to_string(points));
            Matrix out = simplex_lattice(m, pareto::simplex_lattice_divisions(m, points));
            if (fam == Family::dtlz1) {
                out *= 0.5;
            } else {
                out.colwise().normalize();
            }
            return out;
        }
        case Family::dtlz7: {
            const auto [s, size] = pareto::grid_side(m, points, w);
            const std::vector<double> t = detail::spread_over(dtlz7_front_pieces(), s);
            Matrix out(cols(m), cols(size));
            std::vector<std::size_t> digit(m - 1, 0);
            for (Eigen::Index col = 0; col < out.cols(); ++col) {
                // As Dtlz7::evaluate with g = 1: h = M - sum f_i / 2 (1 + sin(3 pi f_i)), f_M = 2 h.
                double hv = static_cast<double>(m);
                for (std::size_t i = 0; i + 1 < m; ++i) {
                    const double fi = t[digit[i]];
                    out(cols(i), col) = fi;
                    hv -= fi / 2.0 * (1.0 + std::sin(3.0 * std::numbers::pi * fi));
                }
                out(cols(m - 1), col) = 2.0 * hv;
                for (std::size_t p = m - 1; p-- > 0;) {
                    if (++digit[p] < s) break;
                    digit[p] = 0;
                }
            }
            return out;
        }
        default:
            break;
    }

    require(points >= 2, w, "a front needs at least 2 points, got " + std::to_string(points));
    Matrix out(cols(m), cols(points));
    const double last = static_cast<double>(points - 1);
    switch (fam) {
        case Family::dtlz5:
        case Family::dtlz6:
            for (std::size_t j = 0; j < points; ++j) {
                const double a = std::numbers::pi / 2.0 * (static_cast<double>(j) / last);
                for (std::size_t i = 0; i + 1 < m; ++i)
                    out(cols(i), cols(j)) = std::cos(a) * detail::degenerate_weight(m, i);
                out(cols(m - 1), cols(j)) = std::sin(a);
            }
            break;
        case Family::zdt3: {
            const std::vector<double> t = detail::spread_over(zdt3_front_pieces(), points);
            for (std::size_t j = 0; j < points; ++j) {
                out(0, cols(j)) = t[j];
                out(1, cols(j)) = detail::zdt3_h(t[j]);
            }
            break;
        }
        default: {  // zdt1, zdt2, zdt4, zdt6
            const double lo = fam == Family::zdt6 ? zdt6_front_f1_min() : 0.0;
            for (std::size_t j = 0; j < points; ++j) {
                const double f1 = j + 1 == points ? 1.0 : lo + (1.0 - lo) * (static_cast<double>(j) / last);
                out(0, cols(j)) = f1;
                out(1, cols(j)) = fam == Family::zdt1 || fam == Family::zdt4 ? 1.0 - std::sqrt(f1) : 1.0 - f1 * f1;
            }
        }
    }
    return out;
}

/// The front of a problem object of zdt.hpp or dtlz.hpp: its name and its number of objectives.
template <class P>
Matrix reference_front(const P& problem, std::size_t points) {
    return reference_front(P::name(), problem.objectives(), points);
}

/// The Euclidean distance from the objective vector f (M = f.size()) to the analytic front of
/// `name` (the methods at the top of this file). InputError for dtlz7 (dtlz7_front_gap() instead),
/// an unknown name, or an M that is not the problem's.
inline double distance_to_front(std::string_view name, std::span<const double> f) {
    using detail::Family;
    const std::size_t m = f.size();
    const Family fam = detail::family("distance_to_front", name, m);
    switch (fam) {
        case Family::zdt1:
        case Family::zdt4:  // (u^2, 1 - u), u = sqrt(f1): smooth where the slope in f1 is infinite
            return detail::distance_to_curve([](double u) { return std::pair{u * u, 1.0 - u}; }, 0.0, 1.0, f[0], f[1]);
        case Family::zdt2:
        case Family::zdt6: {
            const double lo = fam == Family::zdt6 ? zdt6_front_f1_min() : 0.0;
            return detail::distance_to_curve([](double t) { return std::pair{t, 1.0 - t * t}; }, lo, 1.0, f[0], f[1]);
        }
        case Family::zdt3: {
            double best = std::numeric_limits<double>::infinity();
            for (const auto& p : zdt3_front_pieces())
                best = std::min(best, detail::distance_to_curve(
                                          [](double u) {
                                              return std::pair{u * u, detail::zdt3_h(u * u)};
                                          },
                                          std::sqrt(p.lo), std::sqrt(p.hi), f[0], f[1]));
            return best;
        }
        case Family::dtlz1: {
            // Projection onto {y >= 0, sum y = 0.5} (Duchi et al. 2008, "Efficient projections onto
            // the l1-ball", Fig. 1): y = max(f - theta, 0), theta from the sorted coordinates.
            std::vector<double> u(f.begin(), f.end());
            std::sort(u.begin(), u.end(), std::greater<>());
            double prefix = 0.0, theta = 0.0;
            for (std::size_t j = 0; j < m; ++j) {
                prefix += u[j];
                const double t = (prefix - 0.5) / static_cast<double>(j + 1);
                if (u[j] - t > 0.0) theta = t;
            }
            double d2 = 0.0;
            for (double v : f) {
                const double r = v - std::max(v - theta, 0.0);
                d2 += r * r;
            }
            return std::sqrt(d2);
        }
        case Family::dtlz2:
        case Family::dtlz3:
        case Family::dtlz4: {
            double plus2 = 0.0, all2 = 0.0, largest = -std::numeric_limits<double>::infinity();
            for (double v : f) {
                plus2 += std::max(v, 0.0) * std::max(v, 0.0);
                all2 += v * v;
                largest = std::max(largest, v);
            }
            if (plus2 == 0.0) return std::sqrt(std::max(all2 - 2.0 * largest + 1.0, 0.0));  // nearest: a corner
            const double norm = std::sqrt(plus2);
            double d2 = 0.0;
            for (double v : f) {
                const double r = v - std::max(v, 0.0) / norm;
                d2 += r * r;
            }
            return std::sqrt(d2);
        }
        case Family::dtlz5:
        case Family::dtlz6: {
            // f = a w + b e_M + (the rest, off the plane); then the distance within the plane.
            double a = 0.0;
            for (std::size_t i = 0; i + 1 < m; ++i) a += f[i] * detail::degenerate_weight(m, i);
            const double b = f[m - 1];
            double off2 = 0.0;
            for (std::size_t i = 0; i + 1 < m; ++i) {
                const double r = f[i] - a * detail::degenerate_weight(m, i);
                off2 += r * r;
            }
            const double in_plane = a >= 0.0 && b >= 0.0 && (a > 0.0 || b > 0.0)
                                        ? std::abs(std::hypot(a, b) - 1.0)
                                        : std::min(std::hypot(a - 1.0, b), std::hypot(a, b - 1.0));
            return std::sqrt(off2 + in_plane * in_plane);
        }
        case Family::dtlz7:
            break;
    }
    throw InputError("dtlz7", "distance_to_front: the front has no closed-form distance (dtlz7_front_gap)");
}

/// How far f (M = f.size() >= 2) is from DTLZ7's front, as a residual that is 0 exactly on it: the
/// largest of the distances of f_1..f_{M-1} to the pieces of dtlz7_front_pieces() and of
/// |f_M - 2 (M - sum_{i<M} f_i / 2 (1 + sin(3 pi f_i)))|.
inline double dtlz7_front_gap(std::span<const double> f) {
    const std::size_t m = f.size();
    detail::family("dtlz7_front_gap", "dtlz7", m);
    double gap = 0.0, hv = static_cast<double>(m);
    for (std::size_t i = 0; i + 1 < m; ++i) {
        gap = std::max(gap, detail::distance_to_pieces(dtlz7_front_pieces(), f[i]));
        hv -= f[i] / 2.0 * (1.0 + std::sin(3.0 * std::numbers::pi * f[i]));
    }
    return std::max(gap, std::abs(f[m - 1] - 2.0 * hv));
}

}  // namespace pride::multiobjective

#pragma once
// The nine problems of the WFG toolkit: S. Huband, P. Hingston, L. Barone, L. While, "A review of
// multiobjective test problems and a scalable test problem toolkit", IEEE Transactions on
// Evolutionary Computation 10(5), 2006, 477-506 ("the paper" below): its transformation functions
// (b_poly, b_flat, b_param, s_linear, s_decept, s_multi, r_sum, r_nonsep), its shape functions
// (linear, convex, concave, mixed, disconnected) and its nine problems, in the toolkit's general
// form:
//
//   f_m = D x_M + S_m h_m(x_1, ..., x_{M-1}),  D = 1, S_m = 2m,
//   x_i = max(t_M, A_i) (t_i - 0.5) + 0.5 (i < M),  x_M = t_M,  A_i = 1 (WFG3: A_1 = 1, A_i = 0),
//
// t the last transition of z / (2, 4, ..., 2n). M >= 2 objectives; k position parameters (a
// multiple of M - 1), l >= 1 distance parameters (even for WFG2 and WFG3); n = k + l variables,
// z_i in [0, 2i]. Defaults k = 2 (M - 1) and l = 20 (common in the literature; pagmo2's own
// defaults, n = 5 and k = 4 at M = 3, are smaller).
//
//   problem  shape                         distance parameters at the optimum (z_i, i > k)
//   WFG1     convex, mixed (alpha 1, A 5)  2i 0.35
//   WFG2     convex, disconnected (A 5)    2i 0.35
//   WFG3     linear, degenerate            2i 0.35
//   WFG4-7   concave                       2i 0.35
//   WFG8     concave                       Wfg::optimal_solution(): b_param's inverse, in order
//   WFG9     concave                       Wfg::optimal_solution(): b_param's inverse, last first
//
// The oracle is pagmo2 2.18's `wfg` (tests/data/wfg/README.md); the values agree with it to the
// last bit except where the paper and pagmo2 differ, where this file states which it follows:
// - WFG8 (followed: pagmo2): the paper's t1_i = b_param(y_i, r_sum({y_1, ..., y_{i-1}}), ...)
//   takes y as the transition's input; pagmo2 takes y_{k+1}..y_{i-1} already transformed by the
//   same transition (its loop overwrites them). Both are WFG8-like; this follows pagmo2, so that
//   the optimum's distance parameters are those for which every transformed one is 0.35.
// - r_nonsep's normalisation (followed: the paper): pagmo2 computes ceil(A / 2) as an integer
//   division, so for odd A (WFG6, WFG9 with k / (M - 1) or l odd) its t exceeds [0, 1]; here
//   ceil(A / 2) is the paper's. For even A (the defaults) the two are the same operations.
// - WFG1's b_flat (followed: neither): at the optimum, y = 0.35, b_flat's formula rounds to
//   -1.1e-16 and pagmo2's b_poly(y, 0.02) of it is NaN; where no double z_i has z_i / 2i = 0.35
//   exactly (i = 3, 6, 12, 24, 48, 53 among 1..60: the defaults' n holds some) the nearest z_i
//   leaves +1.1e-16, and b_poly makes it 0.48, so the front is out of reach in double precision
//   (at the defaults x_M >= 0.040 for M = 2, 0.069 for M = 3, in every f_m). Here b_flat's
//   values below 1e-15, rounding at its zero, are 0 (and above 1, 1, as the WFG toolkit's
//   reference code corrects them). That changes only the distance parameters y_i within 6e-16 of
//   0.35 (a few doubles), where pagmo2 gives NaN or b_poly's 0.48 to 0.5.
// pagmo2's order of operations is kept (sums left to right, weights summed as it sums them), which
// is why WFG7-9's r_sum over the other parameters costs O(n^2) per evaluation, as the definition.
#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "framework/error.hpp"
#include "framework/pareto/dominance.hpp"
#include "framework/pareto/reference_directions.hpp"
#include "framework/problem.hpp"
#include "problems/multiobjective/box.hpp"

namespace pride::multiobjective {

/// The paper's transformations and shapes, in pagmo2's order of operations.
namespace wfg {

inline double b_poly(double y, double alpha) {
    return std::pow(y, alpha);
}
inline double b_flat(double y, double a, double b, double c) {
    const double v = a + std::min(0.0, std::floor(y - b)) * a * (b - y) / b -
                     std::min(0.0, std::floor(c - y)) * (1.0 - a) * (y - c) / (1.0 - c);
    // The file's note: at its zero the formula's rounding leaves up to a few 1e-16 either side, which
    // WFG1's b_poly(., 0.02) would make NaN (below 0) or 0.48 (above).
    return v < 1e-15 ? 0.0 : std::min(v, 1.0);
}
inline double b_param(double y, double u, double a, double b, double c) {
    const double v = a - (1.0 - 2.0 * u) * std::abs(std::floor(0.5 - u) + a);
    return std::pow(y, b + (c - b) * v);
}
inline double s_linear(double y, double a) {
    return std::abs(y - a) / std::abs(std::floor(a - y) + a);
}
inline double s_decept(double y, double a, double b, double c) {
    return 1.0 +
           (std::abs(y - a) - b) * ((std::floor(y - a + b) * (1.0 - c + (a - b) / b)) / (a - b) +
                                    (std::floor(a + b - y) * (1.0 - c + (1.0 - a - b) / b)) / (1.0 - a - b) + 1.0 / b);
}
inline double s_multi(double y, double a, double b, double c) {
    const double r = std::abs(y - c) / (2.0 * (std::floor(c - y) + c));
    return (1.0 + std::cos((4.0 * a + 2.0) * std::numbers::pi * (0.5 - r)) + 4.0 * b * std::pow(r, 2.0)) / (b + 2.0);
}
/// r_sum(y, w) with w_i = weight(i).
template <class Weight>
double r_sum(std::span<const double> y, Weight weight) {
    double num = 0.0, den = 0.0;
    for (std::size_t i = 0; i < y.size(); ++i) {
        num += weight(i) * y[i];
        den += weight(i);
    }
    return num / den;
}
inline double r_sum(std::span<const double> y) {
    return r_sum(y, [](std::size_t) { return 1.0; });
}
/// The paper's r_nonsep(y, A), |y| a multiple of A (A = 1: r_sum with equal weights).
inline double r_nonsep(std::span<const double> y, std::size_t a) {
    if (a == 1) return r_sum(y);
    const std::size_t len = y.size();
    double g = 0.0;
    for (std::size_t j = 0; j < len; ++j) {
        g += y[j];
        for (std::size_t i = 0; i + 2 <= a; ++i) g += std::abs(y[j] - y[(1 + j + i) % len]);
    }
    const double half = static_cast<double>((a + 1) / 2);  // ceil(A / 2)
    return g / (static_cast<double>(len / a) * half * (1.0 + 2.0 * static_cast<double>(a) - 2.0 * half));
}

// The shapes h_m, m = 1..M, of the parameters x_1..x_{M-1} (x.size() >= M - 1).
inline double linear(std::span<const double> x, std::size_t m, std::size_t mm) {
    double g = 1.0;
    if (m == mm) return 1.0 - x[0];
    for (std::size_t i = 0; i < mm - m; ++i) g *= x[i];
    return m == 1 ? g : g * (1.0 - x[mm - m]);
}
inline double convex(std::span<const double> x, std::size_t m, std::size_t mm) {
    constexpr double half_pi = std::numbers::pi / 2.0;
    double g = 1.0;
    for (std::size_t i = 0; i < mm - m; ++i) g *= 1.0 - std::cos(x[i] * half_pi);
    return m == 1 ? g : g * (1.0 - std::sin(x[mm - m] * half_pi));
}
inline double concave(std::span<const double> x, std::size_t m, std::size_t mm) {
    constexpr double half_pi = std::numbers::pi / 2.0;
    if (m == mm) return std::cos(x[0] * half_pi);
    double g = 1.0;
    for (std::size_t i = 0; i < mm - m; ++i) g *= std::sin(x[i] * half_pi);
    return m == 1 ? g : g * std::cos(x[mm - m] * half_pi);
}
inline double mixed(double x0, double alpha, double a) {
    constexpr double pi = std::numbers::pi;
    return std::pow(1.0 - x0 - std::cos(2.0 * a * pi * x0 + pi / 2.0) / (2.0 * a * pi), alpha);
}
inline double disconnected(double x0, double alpha, double beta, double a) {
    return 1.0 - std::pow(x0, alpha) * std::pow(std::cos(a * std::pow(x0, beta) * std::numbers::pi), 2.0);
}

/// The problems' shapes from the parameters x_1..x_M (x_M the distance): f_m = x_M + 2m h_m.
inline void objectives(int problem, std::span<const double> x, std::span<double> f) {
    const std::size_t mm = f.size();
    for (std::size_t m = 1; m <= mm; ++m) {
        double h;
        if (problem <= 2 && m == mm)
            h = problem == 1 ? mixed(x[0], 1.0, 5.0) : disconnected(x[0], 1.0, 1.0, 5.0);
        else if (problem <= 2)
            h = convex(x, m, mm);
        else if (problem == 3)
            h = linear(x, m, mm);
        else
            h = concave(x, m, mm);
        f[m - 1] = x[mm - 1] + 2.0 * static_cast<double>(m) * h;
    }
}

}  // namespace wfg

/// WFG1-WFG9 (the file's table): `problem` 1..9, M objectives, k position and l distance
/// parameters (0: the defaults 2 (M - 1) and 20).
class Wfg : public MultiObjectiveBox {
  public:
    Wfg(int problem, std::size_t objectives, std::size_t k = 0, std::size_t l = 0)
        : MultiObjectiveBox(checked_name(problem), checked_n(problem, objectives, k, l), 2, 0.0, 1.0, objectives),
          problem_(problem),
          k_(k == 0 ? 2 * (objectives - 1) : k) {
        for (std::size_t i = 0; i < dimension(); ++i) set_bounds(i, 0.0, 2.0 * static_cast<double>(i + 1));
    }

    std::string_view name() const noexcept { return kNames[static_cast<std::size_t>(problem_ - 1)]; }
    int problem() const noexcept { return problem_; }
    std::size_t k() const noexcept { return k_; }
    std::size_t l() const noexcept { return dimension() - k_; }

    void evaluate(std::span<const double> z, std::span<double> f) const {
        assert(z.size() == dimension() && f.size() == objectives());
        // Scratch per thread, so that an evaluation allocates nothing once it has grown (a const
        // problem may be evaluated from several threads).
        thread_local std::vector<double> y, x;
        y.resize(z.size());  // the transitions in place
        for (std::size_t i = 0; i < y.size(); ++i) y[i] = z[i] / upper()[i];
        transform(y);
        const std::size_t mm = f.size();
        x.assign(mm, 0.0);  // t_1..t_M, then x_1..x_M
        reduce(y, x);
        const double tm = x[mm - 1];
        for (std::size_t i = 0; i + 1 < mm; ++i) {
            const double a = problem_ == 3 && i > 0 ? 0.0 : 1.0;
            x[i] = std::max(tm, a) * (x[i] - 0.5) + 0.5;
        }
        wfg::objectives(problem_, x, f);
    }

    /// A Pareto-optimal z: the position parameters from `position` (k values in [0, 1], scaled to
    /// their boxes), the distance parameters at the optimum (the file's table).
    std::vector<double> optimal_solution(std::span<const double> position) const;

  private:
    static constexpr std::string_view kNames[9] = {"wfg1", "wfg2", "wfg3", "wfg4", "wfg5",
                                                   "wfg6", "wfg7", "wfg8", "wfg9"};
    static constexpr double kParamA = 0.98 / 49.98;

    static std::string_view checked_name(int problem) {
        require(problem >= 1 && problem <= 9, "wfg", "the problems are WFG1-WFG9, got " + std::to_string(problem));
        return kNames[static_cast<std::size_t>(problem - 1)];
    }
    static std::size_t checked_n(int problem, std::size_t m, std::size_t k, std::size_t l) {
        const std::string w(checked_name(problem));
        require(m >= 2 && m <= kMaxObjectives, w,
                "needs 2 <= M <= " + std::to_string(kMaxObjectives) + " objectives, got " + std::to_string(m));
        const std::size_t kk = k == 0 ? 2 * (m - 1) : k, ll = l == 0 ? 20 : l;
        require(kk % (m - 1) == 0, w,
                "needs k (position parameters) a multiple of M - 1 = " + std::to_string(m - 1) +
                    ", got k = " + std::to_string(kk));
        require((problem != 2 && problem != 3) || ll % 2 == 0, w,
                "needs an even l = n - k (distance parameters), got l = " + std::to_string(ll));
        require(kk <= kMaxVariables && ll <= kMaxVariables - kk, w,
                "is built up to n = k + l = " + std::to_string(kMaxVariables) + " variables");
        return kk + ll;
    }

    // The transitions before the reduction (the paper's t1, t2, ...), on y = z / (2, ..., 2n).
    void transform(std::vector<double>& y) const {
        const std::size_t n = y.size(), k = k_;
        switch (problem_) {
            case 1:
                for (std::size_t i = k; i < n; ++i) y[i] = wfg::b_flat(wfg::s_linear(y[i], 0.35), 0.8, 0.75, 0.85);
                for (double& v : y) v = wfg::b_poly(v, 0.02);
                break;
            case 2:
            case 3:  // t1, then t2's pairs r_nonsep into y[k .. k + l/2 - 1]
                for (std::size_t i = k; i < n; ++i) y[i] = wfg::s_linear(y[i], 0.35);
                for (std::size_t i = k; i < k + (n - k) / 2; ++i)
                    y[i] = wfg::r_nonsep(std::span<const double>(y).subspan(k + 2 * (i - k), 2), 2);
                break;
            case 4:
                for (double& v : y) v = wfg::s_multi(v, 30.0, 10.0, 0.35);
                break;
            case 5:
                for (double& v : y) v = wfg::s_decept(v, 0.35, 0.001, 0.05);
                break;
            case 6:
                for (std::size_t i = k; i < n; ++i) y[i] = wfg::s_linear(y[i], 0.35);
                break;
            case 7:  // u from the untransformed y_{i+1}..y_n: left to right, so i ascending
                for (std::size_t i = 0; i < k; ++i)
                    y[i] =
                        wfg::b_param(y[i], wfg::r_sum(std::span<const double>(y).subspan(i + 1)), kParamA, 0.02, 50.0);
                for (std::size_t i = k; i < n; ++i) y[i] = wfg::s_linear(y[i], 0.35);
                break;
            case 8:  // u from y_1..y_{i-1}, those beyond k already transformed (the file's note)
                for (std::size_t i = k; i < n; ++i)
                    y[i] = wfg::b_param(y[i], wfg::r_sum(std::span<const double>(y).first(i)), kParamA, 0.02, 50.0);
                for (std::size_t i = k; i < n; ++i) y[i] = wfg::s_linear(y[i], 0.35);
                break;
            default:  // 9: u from the untransformed y_{i+1}..y_n, so i ascending
                for (std::size_t i = 0; i + 1 < n; ++i)
                    y[i] =
                        wfg::b_param(y[i], wfg::r_sum(std::span<const double>(y).subspan(i + 1)), kParamA, 0.02, 50.0);
                for (std::size_t i = 0; i < n; ++i)
                    y[i] = i < k ? wfg::s_decept(y[i], 0.35, 0.001, 0.05) : wfg::s_multi(y[i], 30.0, 95.0, 0.35);
        }
    }

    // The last transition: M - 1 groups of k / (M - 1) position values and the distance values into
    // t_1..t_M (in x).
    void reduce(std::span<const double> y, std::span<double> t) const {
        const std::size_t mm = t.size(), k = k_, group = k / (mm - 1);
        const std::size_t dist = problem_ == 2 || problem_ == 3 ? (y.size() - k) / 2 : y.size() - k;
        const auto pos = [&](std::size_t i) { return y.subspan(i * group, group); };
        const auto far = y.subspan(k, dist);
        for (std::size_t i = 0; i + 1 < mm; ++i) {
            switch (problem_) {
                case 1:
                    t[i] =
                        wfg::r_sum(pos(i), [&](std::size_t j) { return 2.0 * static_cast<double>(i * group + j + 1); });
                    break;
                case 6:
                case 9:
                    t[i] = wfg::r_nonsep(pos(i), group);
                    break;
                default:
                    t[i] = wfg::r_sum(pos(i));
            }
        }
        switch (problem_) {
            case 1:
                t[mm - 1] = wfg::r_sum(far, [&](std::size_t j) { return 2.0 * static_cast<double>(k + j + 1); });
                break;
            case 6:
            case 9:
                t[mm - 1] = wfg::r_nonsep(far, dist);
                break;
            default:
                t[mm - 1] = wfg::r_sum(far);
        }
    }

    int problem_;
    std::size_t k_;
};

inline std::vector<double> Wfg::optimal_solution(std::span<const double> position) const {
    require(position.size() == k_, std::string(name()),
            "optimal_solution needs k = " + std::to_string(k_) + " position values, got " +
                std::to_string(position.size()));
    const std::size_t n = dimension();
    std::vector<double> y(n, 0.35);  // the distance parameters' transformed value at the optimum
    for (std::size_t i = 0; i < k_; ++i) y[i] = position[i];
    // b_param(y, u) = 0.35 for y = 0.35^(1 / exponent(u)).
    const auto inverse = [](double u) {
        const double v = kParamA - (1.0 - 2.0 * u) * std::abs(std::floor(0.5 - u) + kParamA);
        return std::pow(0.35, 1.0 / (0.02 + (50.0 - 0.02) * v));
    };
    std::vector<double> z(n);
    if (problem_ == 8) {  // u over y_1..y_{i-1} as evaluate() sees them: the transformed ones 0.35
        for (std::size_t i = k_; i < n; ++i) z[i] = inverse(wfg::r_sum(std::span<const double>(y).first(i)));
    } else if (problem_ == 9) {  // u over the untransformed y_{i+1}..y_n: from the last one back
        for (std::size_t i = n - 1; i-- > k_;) y[i] = inverse(wfg::r_sum(std::span<const double>(y).subspan(i + 1)));
        for (std::size_t i = k_; i < n; ++i) z[i] = y[i];
    } else {
        for (std::size_t i = k_; i < n; ++i) z[i] = 0.35;
    }
    for (std::size_t i = 0; i < n; ++i) {
        // z_i with z_i / (2i) exactly the value wanted where a double has it, so that s_linear gives
        // 0 (where none has, b_flat's 1e-15 in WFG1 takes the rounding; the file's note).
        const double want = i < k_ ? position[i] : z[i], box = upper()[i];
        double v = want * box;
        for (int step = 0; step < 8 && v / box != want; ++step) v = std::nextafter(v, v / box < want ? box : 0.0);
        z[i] = v;
    }
    return z;
}

/// The front of WFG`problem` with M objectives, at most `points` points (M rows): the problem's
/// shapes at x_M = 0, x_1..x_{M-1} (i.e. not z) sampled as follows. WFG4-9: the concave
/// surface sum (f_m / 2m)^2 = 1 at the normalised Das-Dennis lattice (as DTLZ2's front); WFG3: the
/// degenerate line (x_1 evenly in [0, 1], x_2..x_{M-1} = 0.5, where A_i = 0 puts them); WFG1 and
/// WFG2: a grid of s^(M-1) points over [0, 1]^(M-1) (s the largest with s^(M-1) <= points), its
/// dominated points removed (WFG2's disconnected shape has dominated parts). WFG3's line is the
/// whole front only for M = 2: for M >= 3 points with t_M > 0 off the line are dominated by none of
/// it (docs/multiobjective.md, "WFG"), so this front is then a part of the true one.
/// InputError when `points` is below the smallest front (M for the lattice, 2 otherwise, 2^(M-1)
/// for the grid) or M x points is beyond kMaxLatticeValues.
inline Matrix wfg_reference_front(int problem, std::size_t objectives, std::size_t points) {
    const Wfg shape(problem, objectives);  // checks the problem and M
    const std::string w(shape.name());
    const std::size_t m = objectives;
    const auto cols = [](std::size_t c) { return static_cast<Eigen::Index>(c); };
    require(points <= pareto::kMaxLatticeValues / m, w,
            "a front is built up to " + std::to_string(pareto::kMaxLatticeValues) +
                " values (M x points), got M = " + std::to_string(m) + " and " + std::to_string(points) + " points");
    if (problem >= 4) {
        require(points >= m, w,
                "a front of M = " + std::to_string(m) + " objectives needs at least " + std::to_string(m) +
                    " points (the lattice with H = 1), got " + std::to_string(points));
        Matrix out = pareto::simplex_lattice(m, pareto::simplex_lattice_divisions(m, points));
        out.colwise().normalize();
        for (std::size_t i = 0; i < m; ++i) out.row(cols(i)) *= 2.0 * static_cast<double>(i + 1);
        return out;
    }
    std::vector<double> x(m, 0.5), f(m);
    x[m - 1] = 0.0;  // x_M = t_M = 0 on the front
    if (problem == 3) {
        require(points >= 2, w, "a front needs at least 2 points, got " + std::to_string(points));
        Matrix out(cols(m), cols(points));
        for (std::size_t j = 0; j < points; ++j) {
            x[0] = static_cast<double>(j) / static_cast<double>(points - 1);
            wfg::objectives(problem, x, f);
            for (std::size_t i = 0; i < m; ++i) out(cols(i), cols(j)) = f[i];
        }
        return out;
    }
    const auto [s, size] = pareto::grid_side(m, points, w);
    Matrix grid(cols(m), cols(size));
    std::vector<std::size_t> digit(m - 1, 0);
    for (Eigen::Index col = 0; col < grid.cols(); ++col) {
        for (std::size_t i = 0; i + 1 < m; ++i) x[i] = static_cast<double>(digit[i]) / static_cast<double>(s - 1);
        wfg::objectives(problem, x, f);
        for (std::size_t i = 0; i < m; ++i) grid(cols(i), col) = f[i];
        for (std::size_t p = m - 1; p-- > 0;) {
            if (++digit[p] < s) break;
            digit[p] = 0;
        }
    }
    const std::vector<std::size_t> kept = pareto::nondominated(grid);
    Matrix out(cols(m), cols(kept.size()));
    for (std::size_t j = 0; j < kept.size(); ++j) out.col(cols(j)) = grid.col(cols(kept[j]));
    return out;
}

}  // namespace pride::multiobjective

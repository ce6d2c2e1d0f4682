#pragma once
// The scalable test problems DTLZ1-DTLZ7 of K. Deb, L. Thiele, M. Laumanns, E. Zitzler, "Scalable
// test problems for evolutionary multiobjective optimization", in A. Abraham, L. Jain, R. Goldberg
// (eds.), Evolutionary Multiobjective Optimization, Springer, 2005, 105-145 (the problems of the
// same authors' "Scalable multi-objective optimization test problems", CEC 2002, 825-830, and of
// their TIK report 112, 2001). Below, "the chapter" is the 2005 text; each class names the
// problem it follows.
//
// Any number of objectives M >= 2. The n = M + k - 1 variables, all in [0, 1], are the M - 1
// position variables x_1..x_{M-1} and the k distance variables x_M = (x_M, ..., x_n), on which g
// depends; g's minimum (0, or 1 for DTLZ7) makes the Pareto-optimal set.
//
//   class  k (default)  g's minimum at        front (fronts.hpp)
//   Dtlz1  5            x_M = 0.5             the simplex sum f = 0.5, f >= 0
//   Dtlz2  10           x_M = 0.5             the unit sphere's positive part
//   Dtlz3  10           x_M = 0.5             the same (DTLZ1's multimodal g)
//   Dtlz4  10           x_M = 0.5             the same (alpha = 100 biases the points)
//   Dtlz5  10           x_M = 0.5             a curve on that sphere (degenerate front)
//   Dtlz6  10           x_M = 0               the same curve (a harder g)
//   Dtlz7  20           x_M = 0               2^(M-1) disconnected regions
//
// Where the sources differ, these follow the chapter, read as jMetal and pymoo implement it:
// - DTLZ5 and DTLZ6: the chapter writes theta_i = pi / (4 (1 + g)) (1 + 2 g x_i) (i = 2..M-1)
//   and then cos(theta_i pi / 2), which taken literally applies pi / 2 twice. Here, as in jMetal
//   and pymoo, the first angle is x_1 pi / 2 and, for i >= 2, the angle is
//   pi / (4 (1 + g)) (1 + 2 g x_i) itself. At g = 0 every angle but the first is then pi / 4 and
//   the front is the quarter circle through (0, ..., 0, 1) and, for M = 3, (1/sqrt 2, 1/sqrt 2, 0):
//   the curve of jMetal's reference fronts (tests/test_mo_problems.cpp checks DTLZ5.3D's).
// - DTLZ6's g is sum_{x_i in x_M} x_i^0.1, as in the chapter (jMetal and pymoo agree).
// - DTLZ7's g is 1 + 9 / k sum_{x_i in x_M} x_i, h = M - sum_{i<M} f_i / (1 + g) (1 + sin(3 pi f_i)).
//
// The products run as the chapter writes them, left to right from (1 + g): f_j =
// (1 + g) c_1 c_2 ... c_{M-j} s_{M-j+1}, the same order as jMetal's. No allocation per evaluation.
#include <cassert>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <span>
#include <string>
#include <string_view>

#include "problems/multiobjective/box.hpp"

namespace pride::multiobjective {

/// The part every DTLZ problem shares: M, k, and the box [0, 1]^(M + k - 1).
class Dtlz : public MultiObjectiveBox {
  public:
    /// M objectives and k distance variables; `where` names the problem in errors.
    Dtlz(std::string_view where, std::size_t objectives, std::size_t k)
        : MultiObjectiveBox(where, checked_dimension(where, objectives, k), 2, 0.0, 1.0, objectives), k_(k) {}
    /// The number of distance variables, the last k of x.
    std::size_t k() const noexcept { return k_; }

  private:
    static std::size_t checked_dimension(std::string_view where, std::size_t m, std::size_t k) {
        const std::string w(where);
        require(m >= 2, w, "needs M >= 2 objectives, got " + std::to_string(m));
        require(m <= kMaxObjectives, w,
                "is built up to M = " + std::to_string(kMaxObjectives) + " objectives, got " + std::to_string(m));
        require(k >= 1, w, "needs k >= 1 distance variables, got " + std::to_string(k));
        require(k <= kMaxVariables && m + k - 1 <= kMaxVariables, w,
                "is built up to n = M + k - 1 = " + std::to_string(kMaxVariables) +
                    " variables, got M = " + std::to_string(m) + " and k = " + std::to_string(k));
        return m + k - 1;
    }

    std::size_t k_;
};

namespace detail {

/// DTLZ1's and DTLZ3's g: 100 (k + sum_{x_i in x_M} ((x_i - 0.5)^2 - cos(20 pi (x_i - 0.5)))).
inline double dtlz_rastrigin_g(std::span<const double> xm) noexcept {
    double s = 0.0;
    for (double v : xm) s += (v - 0.5) * (v - 0.5) - std::cos(20.0 * std::numbers::pi * (v - 0.5));
    return 100.0 * (static_cast<double>(xm.size()) + s);
}

/// DTLZ2's g: sum_{x_i in x_M} (x_i - 0.5)^2.
inline double dtlz_sphere_g(std::span<const double> xm) noexcept {
    double s = 0.0;
    for (double v : xm) s += (v - 0.5) * (v - 0.5);
    return s;
}

/// The spherical map of DTLZ2-6: f_j = r cos(a_1) ... cos(a_{M-j}) sin(a_{M-j+1}) (no sine for
/// j = 1), with the angles a_1..a_{M-1} given by angle(i), i = 0..M-2.
template <class Angle>
void spherical(double r, std::span<double> f, Angle angle) noexcept {
    const std::size_t m = f.size();
    double prod = r;  // r cos(a_1) ... cos(a_i)
    for (std::size_t i = 0; i + 1 < m; ++i) {
        const double a = angle(i);
        f[m - 1 - i] = prod * std::sin(a);
        prod *= std::cos(a);
    }
    f[0] = prod;
}

}  // namespace detail

/// DTLZ1 (the chapter's DTLZ1): f_1 = 1/2 x_1 x_2 ... x_{M-1} (1 + g),
/// f_j = 1/2 x_1 ... x_{M-j} (1 - x_{M-j+1}) (1 + g), ..., f_M = 1/2 (1 - x_1) (1 + g), with
/// DTLZ1's g (11^k - 1 local fronts). Front: the simplex sum f_j = 0.5.
class Dtlz1 : public Dtlz {
  public:
    static constexpr std::string_view name() noexcept { return "dtlz1"; }
    explicit Dtlz1(std::size_t objectives, std::size_t k = 5) : Dtlz(name(), objectives, k) {}
    void evaluate(std::span<const double> x, std::span<double> f) const noexcept {
        assert(x.size() == dimension() && f.size() == objectives());
        const std::size_t m = f.size();
        const double g = detail::dtlz_rastrigin_g(x.subspan(m - 1));
        double prod = 0.5 * (1.0 + g);  // 1/2 (1 + g) x_1 ... x_i
        for (std::size_t i = 0; i + 1 < m; ++i) {
            f[m - 1 - i] = prod * (1.0 - x[i]);
            prod *= x[i];
        }
        f[0] = prod;
    }
};

/// DTLZ2 (the chapter's DTLZ2): f_j = (1 + g) cos(x_1 pi/2) ... cos(x_{M-j} pi/2) sin(x_{M-j+1} pi/2)
/// (no sine for f_1), g = sum_{x_i in x_M} (x_i - 0.5)^2. Front: sum f_j^2 = 1, f >= 0.
class Dtlz2 : public Dtlz {
  public:
    static constexpr std::string_view name() noexcept { return "dtlz2"; }
    explicit Dtlz2(std::size_t objectives, std::size_t k = 10) : Dtlz(name(), objectives, k) {}
    void evaluate(std::span<const double> x, std::span<double> f) const noexcept {
        assert(x.size() == dimension() && f.size() == objectives());
        const double g = detail::dtlz_sphere_g(x.subspan(f.size() - 1));
        detail::spherical(1.0 + g, f, [&](std::size_t i) { return x[i] * (std::numbers::pi / 2.0); });
    }
};

/// DTLZ3 (the chapter's DTLZ3): DTLZ2's objectives with DTLZ1's g (3^k - 1 local fronts).
class Dtlz3 : public Dtlz {
  public:
    static constexpr std::string_view name() noexcept { return "dtlz3"; }
    explicit Dtlz3(std::size_t objectives, std::size_t k = 10) : Dtlz(name(), objectives, k) {}
    void evaluate(std::span<const double> x, std::span<double> f) const noexcept {
        assert(x.size() == dimension() && f.size() == objectives());
        const double g = detail::dtlz_rastrigin_g(x.subspan(f.size() - 1));
        detail::spherical(1.0 + g, f, [&](std::size_t i) { return x[i] * (std::numbers::pi / 2.0); });
    }
};

/// DTLZ4 (the chapter's DTLZ4): DTLZ2 with each position variable x_i replaced by x_i^alpha
/// (the chapter's alpha = 100), which crowds the points towards the f_M-f_1 plane.
class Dtlz4 : public Dtlz {
  public:
    static constexpr std::string_view name() noexcept { return "dtlz4"; }
    /// `alpha`: finite and > 0.
    explicit Dtlz4(std::size_t objectives, std::size_t k = 10, double alpha = 100.0)
        : Dtlz(name(), objectives, k), alpha_(alpha) {
        require(alpha > 0.0 && alpha <= 1e300, std::string(name()),
                "alpha must be finite and > 0, got " + std::to_string(alpha));
    }
    double alpha() const noexcept { return alpha_; }
    void evaluate(std::span<const double> x, std::span<double> f) const noexcept {
        assert(x.size() == dimension() && f.size() == objectives());
        const double g = detail::dtlz_sphere_g(x.subspan(f.size() - 1));
        detail::spherical(1.0 + g, f, [&](std::size_t i) { return std::pow(x[i], alpha_) * (std::numbers::pi / 2.0); });
    }

  private:
    double alpha_;
};

namespace detail {

/// DTLZ5's and DTLZ6's objectives from their g: angle_1 = x_1 pi/2 and
/// angle_i = pi / (4 (1 + g)) (1 + 2 g x_i), i = 2..M-1 (the file's note on the sources).
inline void dtlz_degenerate(double g, std::span<const double> x, std::span<double> f) noexcept {
    const double t = std::numbers::pi / (4.0 * (1.0 + g));
    spherical(1.0 + g, f,
              [&](std::size_t i) { return i == 0 ? x[0] * (std::numbers::pi / 2.0) : t * (1.0 + 2.0 * g * x[i]); });
}

}  // namespace detail

/// DTLZ5 (the chapter's DTLZ5): DTLZ2's g; the angles of detail::dtlz_degenerate. Front: a curve,
/// the quarter circle of radius 1 through (0, ..., 0, 1) (fronts.hpp).
class Dtlz5 : public Dtlz {
  public:
    static constexpr std::string_view name() noexcept { return "dtlz5"; }
    explicit Dtlz5(std::size_t objectives, std::size_t k = 10) : Dtlz(name(), objectives, k) {}
    void evaluate(std::span<const double> x, std::span<double> f) const noexcept {
        assert(x.size() == dimension() && f.size() == objectives());
        detail::dtlz_degenerate(detail::dtlz_sphere_g(x.subspan(f.size() - 1)), x, f);
    }
};

/// DTLZ6 (the chapter's DTLZ6): DTLZ5 with g = sum_{x_i in x_M} x_i^0.1 (minimum 0 at x_M = 0).
class Dtlz6 : public Dtlz {
  public:
    static constexpr std::string_view name() noexcept { return "dtlz6"; }
    explicit Dtlz6(std::size_t objectives, std::size_t k = 10) : Dtlz(name(), objectives, k) {}
    void evaluate(std::span<const double> x, std::span<double> f) const noexcept {
        assert(x.size() == dimension() && f.size() == objectives());
        double g = 0.0;
        for (double v : x.subspan(f.size() - 1)) g += std::pow(v, 0.1);
        detail::dtlz_degenerate(g, x, f);
    }
};

/// DTLZ7 (the chapter's DTLZ7): f_i = x_i (i < M), f_M = (1 + g) h, g = 1 + 9 / k sum_{x_i in x_M}
/// x_i, h = M - sum_{i<M} f_i / (1 + g) (1 + sin(3 pi f_i)). Front (g = 1): 2^(M-1) disconnected
/// regions.
class Dtlz7 : public Dtlz {
  public:
    static constexpr std::string_view name() noexcept { return "dtlz7"; }
    explicit Dtlz7(std::size_t objectives, std::size_t k = 20) : Dtlz(name(), objectives, k) {}
    void evaluate(std::span<const double> x, std::span<double> f) const noexcept {
        assert(x.size() == dimension() && f.size() == objectives());
        const std::size_t m = f.size();
        double s = 0.0;
        for (double v : x.subspan(m - 1)) s += v;
        const double g = 1.0 + 9.0 * s / static_cast<double>(k());
        double h = static_cast<double>(m);
        for (std::size_t i = 0; i + 1 < m; ++i) {
            f[i] = x[i];
            h -= x[i] / (1.0 + g) * (1.0 + std::sin(3.0 * std::numbers::pi * x[i]));
        }
        f[m - 1] = (1.0 + g) * h;
    }
};

}  // namespace pride::multiobjective

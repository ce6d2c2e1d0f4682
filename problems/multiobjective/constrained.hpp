#pragma once
// Multi-objective test problems with constraints, each with its Pareto front computed from its
// definition (reference_front), for the constrained runs of NSGA-II, NSGA-III, MOEA/D and SMS-EMOA
// (framework/multi_objective.hpp's ConstrainedMultiObjectiveProblem):
//
//   Deb, Pratap, Agarwal and Meyarivan (2002), NSGA-II, sec. VI-B and Table V: CONSTR, SRN
//   (Srinivas and Deb 1994) and TNK (Tanaka et al. 1995), two variables, two objectives, two
//   inequality constraints each, written here g(x) <= 0 as the table's inequalities rearranged
//   (x2 + 9 x1 >= 6 becomes 6 - x2 - 9 x1 <= 0), unnormalised.
//   Jain and Deb (2014), "An evolutionary many-objective optimization algorithm using
//   reference-point based nondominated sorting approach, part II", sec. VI: C1-DTLZ1 (DTLZ1 with
//   c(x) = 1 - f_M / 0.6 - sum_{i<M} f_i / 0.5 >= 0: only a band above the front is feasible) and
//   C2-DTLZ2 (DTLZ2 with r = 0.4 for M = 3, 0.5 otherwise and c(x) = -min(min_i [(f_i - 1)^2 +
//   sum_{j != i} f_j^2 - r^2], sum_i (f_i - 1/sqrt M)^2 - r^2) >= 0: only M + 1 caps of the front
//   are feasible), as g = -c <= 0, on pride's DTLZ1 and DTLZ2 (dtlz.hpp).
//
// A point's violation is the sum of the constraints' violations, sum_i max(0, g_i) (the "overall
// constraint violation" of Deb et al. 2002, sec. VI-A, and of Jain and Deb 2014, eq. 1, with the
// constraints as written, not normalised); NaN counts as +inf (framework/constraints.hpp).
// Decided by this project: TNK's arctan(x1 / x2) is atan2(x1, x2), equal for x2 > 0 and defined
// at x2 = 0 (pi / 2, the limit), where the quotient is not.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "framework/constraints.hpp"
#include "framework/error.hpp"
#include "framework/pareto/dominance.hpp"
#include "framework/problem.hpp"
#include "problems/multiobjective/box.hpp"
#include "problems/multiobjective/dtlz.hpp"
#include "problems/multiobjective/fronts.hpp"

namespace pride::multiobjective {

/// The sum of the constraints' violations (the header's measure); all inequalities.
inline double sum_violation(std::span<const double> g) noexcept {
    double v = 0.0;
    for (const double gi : g) v += inequality_violation(gi);
    return v;
}

/// What the two-variable problems share: a box of two coordinates, two objectives, two
/// inequalities.
class TwoByTwo : public MultiObjectiveBox {
  public:
    TwoByTwo(std::string_view where, double lo1, double hi1, double lo2, double hi2)
        : MultiObjectiveBox(where, 2, 2, lo1, hi1, 2) {
        set_bounds(1, lo2, hi2);
    }
    ConstraintCounts constraint_counts() const noexcept { return {2, 0}; }
    double violation(std::span<const double> g) const noexcept { return sum_violation(g); }
};

/// CONSTR: f1 = x1, f2 = (1 + x2) / x1; x2 + 9 x1 >= 6, -x2 + 9 x1 >= 1; x1 in [0.1, 1], x2 in [0, 5].
class Constr : public TwoByTwo {
  public:
    static constexpr std::string_view name() noexcept { return "constr"; }
    Constr() : TwoByTwo(name(), 0.1, 1.0, 0.0, 5.0) {}
    void evaluate_constrained(std::span<const double> x, std::span<double> f, std::span<double> g) const noexcept {
        f[0] = x[0];
        f[1] = (1.0 + x[1]) / x[0];
        g[0] = 6.0 - x[1] - 9.0 * x[0];
        g[1] = 1.0 + x[1] - 9.0 * x[0];
    }
    /// The front: x2 = 6 - 9 x1 for x1 in [7/18, 2/3] (f2 = (7 - 9 f1) / f1), x2 = 0 for x1 in
    /// [2/3, 1] (f2 = 1 / f1); `points` spread evenly in f1.
    static Matrix reference_front(std::size_t points) {
        Matrix f(2, static_cast<Eigen::Index>(points));
        const double a = 7.0 / 18.0;
        for (std::size_t k = 0; k < points; ++k) {
            const double t = points == 1 ? 0.0 : static_cast<double>(k) / static_cast<double>(points - 1);
            const double f1 = a + t * (1.0 - a);
            f(0, static_cast<Eigen::Index>(k)) = f1;
            f(1, static_cast<Eigen::Index>(k)) = f1 <= 2.0 / 3.0 ? (7.0 - 9.0 * f1) / f1 : 1.0 / f1;
        }
        return f;
    }
};

/// SRN: f1 = (x1 - 2)^2 + (x2 - 1)^2 + 2, f2 = 9 x1 - (x2 - 1)^2; x1^2 + x2^2 <= 225,
/// x1 - 3 x2 <= -10; x in [-20, 20]^2.
class Srn : public TwoByTwo {
  public:
    static constexpr std::string_view name() noexcept { return "srn"; }
    Srn() : TwoByTwo(name(), -20.0, 20.0, -20.0, 20.0) {}
    void evaluate_constrained(std::span<const double> x, std::span<double> f, std::span<double> g) const noexcept {
        const double a = x[0] - 2.0, b = x[1] - 1.0;
        f[0] = a * a + b * b + 2.0;
        f[1] = 9.0 * x[0] - b * b;
        g[0] = x[0] * x[0] + x[1] * x[1] - 225.0;
        g[1] = x[0] - 3.0 * x[1] + 10.0;
    }
    /// The front: x1 = -2.5, x2 in [2.5, sqrt(225 - 6.25)] (the second constraint and the circle
    /// bound it; tests/test_mo_constrained.cpp checks that no feasible point of a dense sample
    /// dominates it); spread evenly in x2.
    static Matrix reference_front(std::size_t points) {
        Matrix f(2, static_cast<Eigen::Index>(points));
        const double lo = 2.5, hi = std::sqrt(225.0 - 6.25);
        for (std::size_t k = 0; k < points; ++k) {
            const double t = points == 1 ? 0.0 : static_cast<double>(k) / static_cast<double>(points - 1);
            const double x2 = lo + t * (hi - lo), b = x2 - 1.0;
            f(0, static_cast<Eigen::Index>(k)) = 20.25 + b * b + 2.0;
            f(1, static_cast<Eigen::Index>(k)) = -22.5 - b * b;
        }
        return f;
    }
};

/// TNK: f1 = x1, f2 = x2; -x1^2 - x2^2 + 1 + 0.1 cos(16 arctan(x1 / x2)) <= 0,
/// (x1 - 0.5)^2 + (x2 - 0.5)^2 <= 0.5; x in [0, pi]^2.
class Tnk : public TwoByTwo {
  public:
    static constexpr std::string_view name() noexcept { return "tnk"; }
    Tnk() : TwoByTwo(name(), 0.0, std::numbers::pi, 0.0, std::numbers::pi) {}
    void evaluate_constrained(std::span<const double> x, std::span<double> f, std::span<double> g) const noexcept {
        f[0] = x[0];
        f[1] = x[1];
        g[0] = -x[0] * x[0] - x[1] * x[1] + 1.0 + 0.1 * std::cos(16.0 * std::atan2(x[0], x[1]));
        g[1] = (x[0] - 0.5) * (x[0] - 0.5) + (x[1] - 0.5) * (x[1] - 0.5) - 0.5;
    }
    /// The front: the non-dominated points of the first constraint's boundary, r^2 = 1 +
    /// 0.1 cos(16 theta) at the angle theta = atan2(f1, f2), inside the second's disc; sampled at
    /// `points` angles in [0, pi/2] (fewer points remain: the dominated arcs are left out).
    static Matrix reference_front(std::size_t points) {
        Matrix all(2, static_cast<Eigen::Index>(points));
        Eigen::Index kept = 0;
        for (std::size_t k = 0; k < points; ++k) {
            const double t = points == 1 ? 0.0 : static_cast<double>(k) / static_cast<double>(points - 1);
            const double theta = t * std::numbers::pi / 2.0, r = std::sqrt(1.0 + 0.1 * std::cos(16.0 * theta));
            const double x1 = r * std::sin(theta), x2 = r * std::cos(theta);
            if ((x1 - 0.5) * (x1 - 0.5) + (x2 - 0.5) * (x2 - 0.5) > 0.5) continue;
            all(0, kept) = x1;
            all(1, kept) = x2;
            ++kept;
        }
        return nondominated_columns(all.leftCols(kept));
    }

    static Matrix nondominated_columns(const MatrixView& f) {
        const auto keep = pareto::nondominated(f);
        Matrix out(f.rows(), static_cast<Eigen::Index>(keep.size()));
        for (std::size_t k = 0; k < keep.size(); ++k)
            out.col(static_cast<Eigen::Index>(k)) = f.col(static_cast<Eigen::Index>(keep[k]));
        return out;
    }
};

/// What C1-DTLZ1 and C2-DTLZ2 share: a DTLZ problem's box and objectives, and one inequality.
template <class Dtlz>
class DtlzWithConstraint {
  public:
    DtlzWithConstraint(std::size_t objectives, std::size_t k) : dtlz_(objectives, k) {}
    std::size_t dimension() const noexcept { return dtlz_.dimension(); }
    std::span<const double> lower() const noexcept { return dtlz_.lower(); }
    std::span<const double> upper() const noexcept { return dtlz_.upper(); }
    std::size_t objectives() const noexcept { return dtlz_.objectives(); }
    ConstraintCounts constraint_counts() const noexcept { return {1, 0}; }
    double violation(std::span<const double> g) const noexcept { return sum_violation(g); }

  protected:
    Dtlz dtlz_;
};

/// C1-DTLZ1 (Jain and Deb 2014): DTLZ1 and g = f_M / 0.6 + sum_{i<M} f_i / 0.5 - 1 <= 0.
class C1Dtlz1 : public DtlzWithConstraint<Dtlz1> {
  public:
    static constexpr std::string_view name() noexcept { return "c1-dtlz1"; }
    C1Dtlz1(std::size_t objectives, std::size_t k) : DtlzWithConstraint(objectives, k) {}
    void evaluate_constrained(std::span<const double> x, std::span<double> f, std::span<double> g) const noexcept {
        dtlz_.evaluate(x, f);
        const std::size_t m = f.size();
        double s = f[m - 1] / 0.6;
        for (std::size_t i = 0; i + 1 < m; ++i) s += f[i] / 0.5;
        g[0] = s - 1.0;
    }
    /// DTLZ1's front, every point of which is feasible.
    Matrix reference_front(std::size_t points) const {
        return multiobjective::reference_front("dtlz1", objectives(), points);
    }
};

/// C2-DTLZ2 (Jain and Deb 2014): DTLZ2 and g = min(min_i [(f_i - 1)^2 + sum_{j != i} f_j^2 - r^2],
/// sum_i (f_i - 1/sqrt M)^2 - r^2) <= 0, r = 0.4 for M = 3 and 0.5 otherwise.
class C2Dtlz2 : public DtlzWithConstraint<Dtlz2> {
  public:
    static constexpr std::string_view name() noexcept { return "c2-dtlz2"; }
    C2Dtlz2(std::size_t objectives, std::size_t k)
        : DtlzWithConstraint(objectives, k), r_(objectives == 3 ? 0.4 : 0.5) {}
    void evaluate_constrained(std::span<const double> x, std::span<double> f, std::span<double> g) const noexcept {
        dtlz_.evaluate(x, f);
        g[0] = constraint(f);
    }
    double constraint(std::span<const double> f) const noexcept {
        const std::size_t m = f.size();
        double squares = 0.0;
        for (const double v : f) squares += v * v;
        double least = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < m; ++i)  // (f_i - 1)^2 + sum_{j != i} f_j^2 = squares - 2 f_i + 1
            least = std::min(least, squares - 2.0 * f[i] + 1.0 - r_ * r_);
        const double centre = 1.0 / std::sqrt(static_cast<double>(m));
        double middle = 0.0;
        for (const double v : f) middle += (v - centre) * (v - centre);
        return std::min(least, middle - r_ * r_);
    }
    /// The feasible part of DTLZ2's front: its sample with `points` points, the infeasible ones
    /// left out (about a fifth remain at M = 3).
    Matrix reference_front(std::size_t points) const {
        const Matrix all = multiobjective::reference_front("dtlz2", objectives(), points);
        Matrix out(all.rows(), all.cols());
        Eigen::Index kept = 0;
        for (Eigen::Index j = 0; j < all.cols(); ++j)
            if (constraint(std::span<const double>(all.col(j).data(), static_cast<std::size_t>(all.rows()))) <= 0.0)
                out.col(kept++) = all.col(j);
        return out.leftCols(kept);
    }

  private:
    double r_;
};

struct ConstrainedCatalogEntry {
    std::string_view name;
    std::string_view summary;
    std::size_t k;           // DTLZ's default distance variables (0: a fixed n of 2)
    std::size_t objectives;  // the default M
};

inline constexpr std::array<ConstrainedCatalogEntry, 5> kConstrainedCatalog{{
    {"constr", "CONSTR (Deb et al. 2002): 2 variables, 2 constraints, a front in two pieces", 0, 2},
    {"srn", "SRN (Srinivas and Deb 1994): 2 variables, 2 constraints", 0, 2},
    {"tnk", "TNK (Tanaka et al. 1995): 2 variables, 2 constraints, a wavy disconnected front", 0, 2},
    {"c1-dtlz1", "C1-DTLZ1 (Jain and Deb 2014): DTLZ1 with a feasible band above its front, k = 5", 5, 3},
    {"c2-dtlz2", "C2-DTLZ2 (Jain and Deb 2014): DTLZ2 with M + 1 feasible caps of its front, k = 10", 10, 3},
}};

inline const ConstrainedCatalogEntry* find_constrained_problem(std::string_view name) {
    for (const auto& e : kConstrainedCatalog)
        if (e.name == name) return &e;
    return nullptr;
}

/// One of the constrained problems, chosen by name at construction (no virtual call per evaluation).
class ConstrainedBenchmark {
  public:
    /// `variables` n (0: the default; fixed at 2 for CONSTR, SRN, TNK); `objectives` M (0: the
    /// default; 2 for CONSTR, SRN, TNK). InputError naming `where`.
    ConstrainedBenchmark(std::string_view name, std::size_t variables = 0, std::size_t objectives = 0,
                         std::string_view where = "problem")
        : problem_(make(name, variables, objectives, where)) {}

    std::string_view name() const {
        return std::visit([](const auto& p) { return std::string_view(p.name()); }, problem_);
    }
    std::size_t dimension() const {
        return std::visit([](const auto& p) { return p.dimension(); }, problem_);
    }
    std::span<const double> lower() const {
        return std::visit([](const auto& p) { return p.lower(); }, problem_);
    }
    std::span<const double> upper() const {
        return std::visit([](const auto& p) { return p.upper(); }, problem_);
    }
    std::size_t objectives() const {
        return std::visit([](const auto& p) { return p.objectives(); }, problem_);
    }
    ConstraintCounts constraint_counts() const {
        return std::visit([](const auto& p) { return p.constraint_counts(); }, problem_);
    }
    double violation(std::span<const double> g) const { return sum_violation(g); }
    void evaluate_constrained(std::span<const double> x, std::span<double> f, std::span<double> g) const {
        std::visit([&](const auto& p) { p.evaluate_constrained(x, f, g); }, problem_);
    }
    /// The objectives alone (the constraints computed and dropped: still one evaluation).
    void evaluate(std::span<const double> x, std::span<double> f) const {
        double g[1 + 1];
        evaluate_constrained(x, f, std::span<double>(g, constraint_counts().total()));
    }
    /// The front computed from the definition, with (at most) `points` points.
    Matrix reference_front(std::size_t points) const {
        return std::visit([&](const auto& p) { return p.reference_front(points); }, problem_);
    }

  private:
    using Any = std::variant<Constr, Srn, Tnk, C1Dtlz1, C2Dtlz2>;

    static Any make(std::string_view name, std::size_t n, std::size_t m, std::string_view where) {
        const ConstrainedCatalogEntry* e = find_constrained_problem(name);
        if (e == nullptr)
            throw InputError(std::string(where), "unknown constrained problem '" + std::string(name) + "'");
        const std::string w(name);
        if (e->k == 0) {
            require(n == 0 || n == 2, w, "has 2 variables, got " + std::to_string(n));
            require(m == 0 || m == 2, w, "has 2 objectives, got " + std::to_string(m));
            if (name == "constr") return Constr();
            if (name == "srn") return Srn();
            return Tnk();
        }
        const std::size_t mm = m == 0 ? e->objectives : m;
        require(mm >= 2 && mm <= kMaxObjectives, w,
                "needs 2 <= M <= " + std::to_string(kMaxObjectives) + " objectives, got " + std::to_string(mm));
        require(n == 0 || n >= mm, w,
                "needs n >= M = " + std::to_string(mm) + " variables (k = n - M + 1 >= 1), got " + std::to_string(n));
        const std::size_t k = n == 0 ? e->k : n - mm + 1;
        if (name == "c1-dtlz1") return C1Dtlz1(mm, k);
        return C2Dtlz2(mm, k);
    }

    Any problem_;
};

}  // namespace pride::multiobjective

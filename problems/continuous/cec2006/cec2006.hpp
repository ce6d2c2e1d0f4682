#pragma once
// The CEC 2006 constrained suite, g01-g24 (Liang, Runarsson, Mezura-Montes, Clerc, Suganthan,
// Coello Coello, Deb 2006, "Problem definitions and evaluation criteria for the CEC 2006 special
// session on constrained real-parameter optimization", the September 2006 report): minimise f(x)
// subject to g_i(x) <= 0 and h_j(x) = 0 on a box, an equality holding when |h_j| <= 1e-4.
// Dimensions, counts and bounds are the report's Tables 3 and 4; f* and x* are its problem texts'
// (g20's f*, which only Table 4 gives, from there).
//
// Where the report and pagmo2's cec2006 (after the organisers' C code, fcnsuite.c) differ:
// - g17's objective: the report's f is f1(x1) + f2(x2) (30 x1 or 31 x1; 28 x2, 29 x2 or 30 x2);
//   pagmo2 multiplies those rates by 300 - (...) and -(...), the x1 and x2 that h1 = 0 and h2 = 0
//   ask for, that is by x1 + h1 and x2 + h2. They agree where h1 = h2 = 0.
//   The report is followed here; its f* = 8853.53967480648 is the code's value at its x*, where the
//   report's own formula gives 8853.5340 (see best_known_value()).
// - g17 at x1 = 400 or x2 = 1000: the report's pieces end open (x1 < 400, x2 < 1000) at the
//   bounds; the last piece is taken to include the bound, as pagmo2 does.
// - g02 and g14: the report's box is open at 0 (0 < x_i); here, as in pagmo2, it is [0, 10].
//   g14's terms x_i ln(x_i / sum) are taken as their limit 0 at x_i = 0 (pagmo2: NaN), so that a
//   point clamped to the bound has a value. g02 divides by 0 at x = 0 (f = -inf, an infeasible
//   point) and g08 at x1 = 0 (NaN), as in pagmo2: the report's formulas have no value there.
// - The order of the constraint values: pagmo2 gives the equalities first; here the inequalities
//   come first (framework/constraints.hpp), each kind in the report's order.
// - The violation: the report's mean violation counts an equality as |h_j| where |h_j| > 1e-4;
//   violation() is the framework's mean_violation, which counts |h_j| - 1e-4 there. Both are 0
//   exactly on the feasible points.
// Elsewhere pagmo2 computes the report's formulas in other orders (g03's product, g16's sum), which
// changes the last bits only. The report's x* has misprints read as follows: g04's lacks a
// parenthesis; g23's runs x8 and x9 together ("2000.0100000100000100008": x8 = 200,
// x9 = 0.0100000100000100008); g24's lacks its comma (2.32952019747762, 3.17849307411774).
#include <cstddef>
#include <span>
#include <string_view>

#include "framework/constraints.hpp"

namespace pride::continuous::cec2006 {

/// How many problems the suite has: g01 ... g24.
inline constexpr int kProblems = 24;

/// One problem of the suite. A copy is a few views of constant tables: copying is free, and
/// evaluation neither allocates nor touches shared mutable state.
class Problem {
  public:
    /// `number` 1..24 (g01..g24); InputError("problem", ...) otherwise.
    explicit Problem(int number);

    int number() const noexcept { return number_; }
    /// "g01" ... "g24".
    std::string_view name() const noexcept { return name_; }
    std::size_t dimension() const noexcept { return lower_.size(); }
    std::span<const double> lower() const noexcept { return lower_; }
    std::span<const double> upper() const noexcept { return upper_; }
    /// m inequalities and p equalities, as the report's Table 3 (LI + NI, LE + NE).
    ConstraintCounts constraint_counts() const noexcept { return counts_; }

    /// f(x); x has dimension() values.
    double evaluate(std::span<const double> x) const noexcept;
    /// f(x), and into c (at least constraint_counts().total() values) the m inequality values
    /// g_i(x), then the p equality values h_j(x), each kind in the report's order.
    double evaluate_constrained(std::span<const double> x, std::span<double> c) const noexcept;
    /// The mean violation of the values evaluate_constrained() wrote (framework/constraints.hpp).
    double violation(std::span<const double> c) const noexcept {
        return mean_violation(c, counts_, kEqualityTolerance);
    }

    /// f(x*) as the report gives it. Not always f at best_known_point(): the report's x* are
    /// rounded; g17's f* is the organisers' code's value at x*, 6.4e-7 relative above the
    /// report's formula there. g20's x* is infeasible, as the report says (no feasible point is
    /// known): it meets the equalities within 1e-4, but g1 = 0.144 > 0.
    double best_known_value() const noexcept { return best_value_; }
    /// x* as the report prints it (with the misprints above read as stated).
    std::span<const double> best_known_point() const noexcept { return best_point_; }

  private:
    double compute(const double* x, double* c) const noexcept;

    int number_;
    std::string_view name_;
    ConstraintCounts counts_;
    std::span<const double> lower_;
    std::span<const double> upper_;
    std::span<const double> best_point_;
    double best_value_;
};

}  // namespace pride::continuous::cec2006

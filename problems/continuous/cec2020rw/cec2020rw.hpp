#pragma once
// The CEC 2020 real-world constrained suite, RC01-RC57 (Kumar, Wu, Ali, Mallipeddi, Suganthan, Das
// 2020, "A test-suite of non-convex constrained optimization problems from the real-world and some
// baseline results", and the competition's guidelines): minimise f(x) subject to g_i(x) <= 0 and
// h_j(x) = 0 on a box, an equality holding when |h_j| <= 1e-4. Each problem is what the
// organisers' MATLAB code (P-N-Suganthan/2020-RW-Constrained-Optimisation, SOFTWARE.zip:
// cec20_func.m, Cal_par.m) computes: bounds and dimensions are Cal_par.m's, f* is Table 3 of the
// definitions. The code is followed where it and the definitions differ; its quirks, kept:
// - Integer and discrete variables are rounded inside the functions (round half away from 0):
//   RC08 x2, RC09 x3, RC10 x3, RC11 x5-x6, RC12 x4-x7, RC13 x4-x5, RC14 x1-x3, RC18 x1-x2 (then
//   times 0.0625), RC22 round(|x|) of all nine, RC26 all 22, RC28 x3, RC30 x1 and x3 (an index).
//   Where a rounded index would leave its table (only outside the box) it is clamped to the table.
// - Constraint counts are what the code returns, not Cal_par.m's: RC17 has 4 inequalities (Cal_par
//   and Table 3: 3), RC21 8 (7), RC44 91 (Cal_par 105; the code's pair loop, j from i+1 to 14,
//   leaves turbine 15 out; Table 3 says 91). A problem without inequalities or equalities returns
//   a column of zeros for them in the code: it is no constraint here, except RC31 (gear train,
//   unconstrained in the code) which keeps Table 3's one inequality and one equality, both 0.
// - Formulas as coded: RC12 has (x1 - 1)^22; RC13's f and g use the rounded y1, y2; RC26's
//   constraints 79 and 80 take Np2 and Np3 where the pattern has Np3 and Np4, and every c_i is
//   measured from (xp1, yp1); RC30's wire table holds 0.0105 where the definitions' has 0.105;
//   RC45-RC50's harmonics skip 89; the unit of RC45-RC50's angles is degrees.
// - Non-real values: RC22's g8 is 1e6 where beta = acos(...) is not real; RC26's infinite g are
//   1e6. Elsewhere a value the code
//   would make complex (a power or acos out of its real domain, only outside the feasible region)
//   is NaN here, which the framework counts as an infinite violation.
// - RC22, RC27, RC33, RC34-RC44 and RC45-RC50 loop over the population point by point in the
//   code; each point is evaluated alone here.
// - RC27's eigenproblem and RC33's linear solve are Eigen's where the code calls MATLAB's eig and
//   sparse backslash: they agree with the code to rounding (1e-13 relative at the test's points).
// - RC44's cosd and sind are Octave's, cos(theta / 180 * pi) and sin(theta / 180 * pi) (MATLAB's
//   reduce the angle first: the last bits may differ).
// - RC34-RC43 read the organisers' data files' tables, restated in cec2020rw_tables.cpp.
// - RC24, the robot gripper: its f is the difference of a maximum and a minimum over z that the
//   code finds with fminbnd (1e4 where they come out complex); pride follows Octave's fminbnd step
//   by step, with Octave's complex arithmetic and ordering (cec2020rw_gripper.cpp says where
//   MATLAB's can differ).
// - The violation is the framework's mean_violation, the guidelines' eq. 2.
#include <cstddef>
#include <span>
#include <string_view>

#include "framework/constraints.hpp"

namespace pride::continuous::cec2020rw {

/// How many problems the suite has: RC01 ... RC57.
inline constexpr int kProblems = 57;

/// One problem of the suite. A copy is a few views of constant tables: copying is free, and
/// evaluation neither allocates nor touches shared mutable state.
class Problem {
  public:
    /// `number` 1..57 (RC01..RC57); InputError("problem", ...) otherwise.
    explicit Problem(int number);

    int number() const noexcept { return number_; }
    /// "RC01" ... "RC57".
    std::string_view name() const noexcept { return name_; }
    std::size_t dimension() const noexcept { return lower_.size(); }
    std::span<const double> lower() const noexcept { return lower_; }
    std::span<const double> upper() const noexcept { return upper_; }
    /// m inequalities and p equalities, as the code returns them (see the quirks above).
    ConstraintCounts constraint_counts() const noexcept { return counts_; }

    /// f(x); x has dimension() values.
    double evaluate(std::span<const double> x) const noexcept;
    /// f(x), and into c (at least constraint_counts().total() values) the m inequality values
    /// g_i(x), then the p equality values h_j(x), each kind in the code's order.
    double evaluate_constrained(std::span<const double> x, std::span<double> c) const noexcept;
    /// The mean violation of the values evaluate_constrained() wrote (framework/constraints.hpp).
    double violation(std::span<const double> c) const noexcept {
        return mean_violation(c, counts_, kEqualityTolerance);
    }

    /// f(x*) as Table 3 of the definitions gives it (the best known feasible value).
    double best_known_value() const noexcept { return best_value_; }

  private:
    int number_;
    std::string_view name_;
    ConstraintCounts counts_;
    std::span<const double> lower_;
    std::span<const double> upper_;
    double best_value_;
};

}  // namespace pride::continuous::cec2020rw

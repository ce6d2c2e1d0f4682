#pragma once
// COCO's bbob-constrained suite, as COCO's C code defines it (suite_cons_bbob.c,
// suite_cons_bbob_problems.c and c_linear.c of numbbo/coco-experiment at commit e6356d2e,
// v2.8.2-4, the version $PRIDE_DATA/bbob's values come from): 54 functions, minimise f(x) subject to g_i(x) <= 0 on
// [-5, 5]^D, built from nine bbob objectives (sphere, separable ellipsoid, linear slope, rotated ellipsoid, discus,
// bent cigar, different powers, separable and rotated Rastrigin), each with six numbers of
// linear constraints. Function N has objective ceil(N / 6) and, with p = (N - 1) mod 6 + 1, m
// active constraints: 1, 2, 6, 6 + floor(D/2), 6 + D, 6 + 3D for p = 1..6; COCO adds floor(m/2)
// inactive ones (shifted away from the optimum), so a problem has m + floor(m/2) constraints.
// The suite's dimensions are 2, 3, 5, 10, 20, 40 and its instances 1-15.
//
// How COCO builds a problem, reproduced here with its order of operations so that f and every g_i
// are COCO's bit for bit (tests/test_bbob_constrained.cpp, against values COCO's C code printed):
// - the objective f_o(z) is the bbob function with its own x_o (seed N + 20000 i), rotation
//   (seed N + 20000 i + 1e6) and f_opt (bbob's rule with N as the function number);
// - a feasible direction p: the gradient of f_o at the origin, scaled so that x* + p stays in
//   [-5, 5]^D (by a random factor in [0.75, 1]);
// - the constraints g_k(z) = sum_i a_ki (z_i - s_k a_ki / ||a_k||), a term counted only if it is
//   < 0 or > 1e-11 (COCO's guard against rounding at the optimum). One active constraint's
//   gradient is -p (scaled), the others' are random normals (COCO's lagged-Fibonacci generator,
//   coco_random.c); each is flipped if p is infeasible for it; s_k = 0 for the active ones and in
//   [0.01, 2.01) for the inactive ones. With m > 1 the gradient -p is then mixed with the other
//   active gradients ("disguised") without moving the optimum;
// - the problem is the origin's: z = T(x - x*), with x* COCO's x_opt (seed N + 10000 i) and T
//   T_osz (ellipsoids, discus), T_asy^0.2 (bent cigar), T_asy^0.2 o T_osz (Rastrigin) or none; the
//   linear slope's f is taken at x itself (only its constraints are shifted);
// - f is scaled: x 10 (sphere, slope, Rastrigin), x 1e-4 (ellipsoids, discus, bent cigar), x 100
//   (different powers). f(x*) is the optimum value, x* the optimum.
//
// Counting: COCO counts f evaluations and constraint evaluations apart (coco_evaluate_function,
// coco_evaluate_constraint; each call of the latter gives all g_i and counts one). One evaluation
// here gives f and every g_i and counts once: it is one COCO f evaluation plus one COCO constraint
// evaluation, so after N evaluations COCO's two counters would both read N.
//
// The violation is COCO's own measure (logger_bbob.c): the sum of the positive g_i, not the
// framework's mean. COCO's initial solution (the feasible direction mapped back through T by
// Brent's method) is not reproduced.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "framework/constraints.hpp"
#include "problems/continuous/bbob/instance.hpp"

namespace pride::continuous::bbob_constrained {

/// How many functions the suite has: f1 ... f54.
inline constexpr int kFunctions = 54;
/// The largest dimension: the suite's largest, and near COCO's own limit (its rotations assert
/// D^2 < 2000, so it builds no rotated function beyond D = 44). Any D from 2 to 40 is accepted.
inline constexpr std::size_t kMaxDimension = 40;
/// The name's prefix: bbob-constrained-f1 ... bbob-constrained-f54 (as bbob's bbob-f1 ...).
inline constexpr const char* kPrefix = "bbob-constrained-f";

/// One problem of the suite. Copies are independent (values only); evaluation does not allocate
/// (it writes into the copy's scratch vectors).
class Problem {
  public:
    /// `function` 1..54, `dim` 2..kMaxDimension, `instance` 1..bbob::kMaxInstance; InputError
    /// ("problem", "dim" or "instance", ...) otherwise.
    Problem(int function, std::size_t dim, std::int64_t instance);

    int function() const noexcept { return function_; }
    std::int64_t instance() const noexcept { return instance_; }
    /// "bbob-constrained-fN".
    const std::string& name() const noexcept { return name_; }
    std::size_t dimension() const noexcept { return lower_.size(); }
    std::span<const double> lower() const noexcept { return lower_; }
    std::span<const double> upper() const noexcept { return upper_; }
    /// m + floor(m/2) inequalities (active ones and COCO's inactive ones), no equality.
    ConstraintCounts constraint_counts() const noexcept { return {constraint_count_, 0}; }
    /// m, the active constraints (COCO's nb_of_linear_constraints).
    std::size_t active_constraints() const noexcept { return active_; }

    /// f(x); x has dimension() values.
    double evaluate(std::span<const double> x) noexcept;
    /// f(x), and into c (at least constraint_counts().total() values) g_1(x) ... in COCO's order.
    double evaluate_constrained(std::span<const double> x, std::span<double> c) noexcept;
    /// COCO's measure of the values evaluate_constrained() wrote: the sum of the positive g_i
    /// (+inf where one is NaN).
    double violation(std::span<const double> c) const noexcept;

    /// x*, COCO's best parameter (its x_opt for this function and instance).
    std::span<const double> optimum_point() const noexcept { return x_star_; }
    /// f(x*), COCO's best value; every g_i(x*) <= 0.
    double optimum_value() const noexcept { return f_star_; }

  private:
    double objective(const double* z) noexcept;  // f before the scale, at the transformed point
    void constraints(const double* z, double* c) const noexcept;
    const double* transformed(std::span<const double> x) noexcept;  // z = T(x - x*) into z_

    int function_;
    int type_;  // 1..9: the objective
    std::int64_t instance_;
    std::string name_;
    std::vector<double> lower_, upper_;
    std::size_t active_ = 0;
    std::size_t constraint_count_ = 0;
    std::vector<double> x_star_;
    std::vector<double> x_o_;           // the objective's own optimum (the slope's corner)
    std::vector<double> weight_;        // ellipsoid weights, slope's s_i, different powers' exponents
    bbob::AffineMatrix rotation_;       // types 4, 5, 6, 7, 9
    double f_opt_ = 0.0;                // added before the scale
    double scale_ = 1.0;                // COCO's transform_obj_scale
    std::vector<double> gradients_;     // row k: a_k
    std::vector<double> shift_factor_;  // s_k / ||a_k||
    double f_star_ = 0.0;
    std::vector<double> shifted_, z_, u_;  // scratch
};

}  // namespace pride::continuous::bbob_constrained

#pragma once
// COCO's bbob-mixint suite, as COCO's C code defines it (suite_bbob_mixint.c,
// transform_vars_discretize.c and transform_obj_scale.c of numbbo/coco-experiment at commit
// e6356d2e, v2.8.2-4): the 24 bbob functions with integer variables (Tusar, Brockhoff, Hansen
// 2019, "Mixed-integer benchmark problems for single- and bi-objective optimization").
//
// In dimension D (a multiple of 5), the variables come in five blocks of D/5: the first four are
// integer with 2, 4, 8 and 16 values (0 .. n-1), the last is continuous in [-5, 5]. COCO's
// functions take real x and discretize inside, and so does evaluate():
// - an integer coordinate is rounded (floor(x + 0.5)), clamped to [0, n-1], and mapped onto n
//   evenly spaced points of the bbob function's [-4, 4] ((u - l)/(n + 1) apart, and from the
//   ends), shifted by an offset so that the bbob optimum's closest point is one of them;
// - a continuous coordinate goes to the bbob function as it is (outside [-5, 5] too);
// - f is the bbob function's value times a factor per function (COCO's scaling factors, 1e-4 to
//   10), and the optimum value is f_opt times that factor.
// x* has the integer values nearest to the bbob optimum (in the outer coordinates, + 1e-7 and
// rounded, as COCO) and the bbob optimum's continuous coordinates.
//
// COCO's suite has dimensions 5, 10, 20, 40, 80 and 160; from D = 50 on it builds the functions
// of its bbob-largescale suite, which pride does not have, so only D = 5 to 40 are here (any
// multiple of 5: COCO's bbob rotations stop below 45). Instances 1 to bbob::kMaxInstance.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "problems/continuous/bbob/suite.hpp"
#include "problems/continuous/box_function.hpp"

namespace pride::continuous::bbob_mixint {

/// How many functions the suite has: f1 ... f24, bbob's.
inline constexpr int kFunctions = 24;
/// The dimensions accepted: multiples of 5 from 5 to 40 (the suite's 5, 10, 20, 40 among them).
inline constexpr std::size_t kMinDimension = 5;
inline constexpr std::size_t kMaxDimension = 40;
/// The name's prefix: bbob-mixint-f1 ... bbob-mixint-f24.
inline constexpr const char* kPrefix = "bbob-mixint-f";

/// "bbob-mixint-fN".
std::string name_of(int function);
/// The words a dimension outside 5, 10, ..., 40 is refused with (after "dim: ").
std::string dimension_message(int function, std::int64_t dim);

template <class Tuple>
struct VariantOf;
template <class... F>
struct VariantOf<std::tuple<F...>> {
    using type = std::variant<F...>;
};
/// One of bbob's 24 classes (the inner, continuous function).
using Inner = VariantOf<bbob::All>::type;

/// One problem of the suite. Copies are independent (values only).
class Problem {
  public:
    /// `function` 1..24, `dim` a multiple of 5 in [5, 40], `instance` 1..bbob::kMaxInstance;
    /// InputError ("problem", "dim" or "instance", one line) otherwise.
    Problem(int function, std::size_t dim, std::int64_t instance);

    int function() const noexcept { return function_; }
    std::int64_t instance() const noexcept { return instance_; }
    /// "bbob-mixint-fN".
    std::string_view name() const noexcept { return name_; }
    std::size_t dimension() const noexcept { return lower_.size(); }
    /// COCO's box: 0 and n - 1 for an integer coordinate, -5 and 5 for a continuous one.
    std::span<const double> lower() const noexcept { return lower_; }
    std::span<const double> upper() const noexcept { return upper_; }
    /// How many variables are integer: the first 4D/5 (COCO's number_of_integer_variables).
    std::size_t integer_variables() const noexcept { return integers_; }
    /// Whether coordinate i is integer; its values are then lower()[i] .. upper()[i].
    bool is_integer(std::size_t i) const noexcept { return i < integers_; }

    /// f(x), COCO's: x real, its integer coordinates rounded and clamped inside; NaN if x has one.
    double evaluate(std::span<const double> x) noexcept;

    /// x*, COCO's best parameter (integers on the integer coordinates).
    std::vector<double> optimum_point() const { return x_star_; }
    /// COCO's best value: the bbob f_opt times the function's factor.
    double optimum_value() const noexcept { return f_star_; }

  private:
    int function_;
    std::int64_t instance_;
    std::string name_;
    std::size_t integers_;
    std::vector<double> lower_, upper_;
    Inner inner_;
    std::vector<double> inner_low_, inner_width_, offset_;  // per integer coordinate (see evaluate())
    double factor_;
    std::vector<double> x_star_;
    double f_star_;
    std::vector<double> z_;  // scratch: the point the bbob function gets
};

}  // namespace pride::continuous::bbob_mixint

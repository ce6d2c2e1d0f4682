#pragma once
// The shift transform: Shifted<F> is F with its optimum moved from x* = (c, ..., c) to a point o
// inside the box, f(x) = F(x - o + x*), same optimum value. Benchmarks need it because an
// algorithm that pulls positions towards the origin (ILSO's inertia weight) looks better than it is
// on functions whose optimum sits at the origin.
//
// o is fixed and documented so that anyone can recompute it: with phi = (sqrt(5) - 1) / 2 and
// frac() the fractional part, o_i = low + (high - low) * (0.1 + 0.8 * frac((i + 1) * phi)),
// i = 0..n-1 (a golden-ratio sequence: spread over the middle 80 % of each interval, never on the
// centre line).
#include <cmath>
#include <span>
#include <string>
#include <vector>

#include "problems/continuous/box_function.hpp"

namespace pride::continuous {

inline std::vector<double> shift_optimum(std::size_t dim, double lower, double upper) {
    constexpr double phi = 0.6180339887498949;
    std::vector<double> o(dim);
    for (std::size_t i = 0; i < dim; ++i) {
        const double t = static_cast<double>(i + 1) * phi;
        o[i] = lower + (upper - lower) * (0.1 + 0.8 * (t - std::floor(t)));
    }
    return o;
}

/// Composition, not inheritance: whatever capability F gains later (batch evaluation, say) does
/// not leak through unshifted.
template <class F>
class Shifted {
  public:
    static inline const std::string shifted_name = "shifted-" + std::string(F::info.name);

    explicit Shifted(std::size_t dim)
        : base_(dim), optimum_(shift_optimum(dim, F::info.lower, F::info.upper)), moved_(dim) {}

    std::size_t dimension() const noexcept { return base_.dimension(); }
    std::span<const double> lower() const noexcept { return base_.lower(); }
    std::span<const double> upper() const noexcept { return base_.upper(); }
    std::string_view name() const noexcept { return shifted_name; }
    std::vector<double> optimum_point() const { return optimum_; }
    double optimum_value() const noexcept { return F::info.optimum_value; }

    double evaluate(std::span<const double> x) {
        const double c = F::info.optimum_coordinate;
        for (std::size_t i = 0; i < moved_.size(); ++i) moved_[i] = x[i] - optimum_[i] + c;
        return base_.evaluate(std::span<const double>(moved_.data(), x.size()));
    }

  private:
    F base_;
    std::vector<double> optimum_;
    std::vector<double> moved_;  // scratch: no allocation per evaluation
};

}  // namespace pride::continuous

#pragma once
// A function under an instance transform (instance.hpp), fully typed: Transformed<F> evaluates
// F(x* + R (x - o)) with one matrix-vector product (none when R = I) and no allocation.
// Shifted<F> is the fixed golden-ratio shift of the `shifted-*` problems. Composition, not
// inheritance: whatever capability F gains (batch evaluation, say) does not leak through
// untransformed.
#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "framework/problem.hpp"
#include "problems/continuous/instance.hpp"

namespace pride::continuous {

template <class F>
class Transformed {
  public:
    Transformed(F base, Transform transform, std::string name)
        : base_(std::move(base)),
          transform_(std::move(transform)),
          name_(std::move(name)),
          z_(base_.dimension()),
          diff_(static_cast<Eigen::Index>(base_.dimension())) {}

    std::size_t dimension() const noexcept { return base_.dimension(); }
    std::span<const double> lower() const noexcept { return base_.lower(); }
    std::span<const double> upper() const noexcept { return base_.upper(); }
    std::string_view name() const noexcept { return name_; }
    std::vector<double> optimum_point() const { return transform_.shift; }
    double optimum_value() const { return base_.optimum_value(); }
    const Transform& transform() const noexcept { return transform_; }
    const F& base() const noexcept { return base_; }
    template <class G = F>
    void reseed(std::uint64_t seed) noexcept requires Reseedable<G> {
        base_.reseed(seed);
    }

    double evaluate(std::span<const double> x) {
        const double penalty = transform_.apply(x, z_, diff_);
        const double f = base_.evaluate(std::span<const double>(z_.data(), x.size()));
        return transform_.clamp_lower.empty() ? f : f + penalty;  // no + 0.0: keeps -0.0 and the bits
    }

  private:
    F base_;
    Transform transform_;
    std::string name_;
    std::vector<double> z_;  // scratch: no allocation per evaluation
    Eigen::VectorXd diff_;
};

/// F with its optimum moved to the fixed point shift_optimum() (instance.hpp), f(x) = F(x* + x - o).
template <class F>
class Shifted : public Transformed<F> {
  public:
    explicit Shifted(std::size_t dim)
        : Transformed<F>(F(dim), make_transform(dim), "shifted-" + std::string(F::info.name)) {}

  private:
    static Transform make_transform(std::size_t dim) {
        Transform t;
        t.shift = shift_optimum(dim, F::info.lower, F::info.upper);
        t.anchor.assign(dim, F::info.optimum_coordinate);
        return t;
    }
};

}  // namespace pride::continuous

#pragma once
// What every continuous test function shares: its box, its name, and its known optimum. Each
// function is then one small class adding its formula. A function class is usable on its own in
// fully typed code (`Pso{}.run(Rastrigin(30), ...)`); the catalog (catalog.hpp) wraps them all in
// one type for the engine, which dispatches once per batch of evaluations.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "framework/error.hpp"

namespace pride::continuous {

/// Facts about a function, identical in every dimension.
struct FunctionInfo {
    std::string_view name;
    std::string_view summary;
    double lower;  // box, every coordinate (functions with per-coordinate boxes pass them apart)
    double upper;
    std::size_t min_dim;        // smallest dimension the formula is defined for
    double optimum_coordinate;  // x* = (c, ..., c); NaN when x* is not of that form (optimum_point())
    double optimum_value;       // f(x*)
    std::size_t fixed_dim = 0;  // 0: scalable; else the only dimension (Yao's F14-F23)
    // The formula's infimum over R^n lies outside the box (Schwefel's sine functions), so an
    // instance that moves the argument out of the box must bring it back (instance.hpp).
    bool bounded_domain = false;
};

class BoxFunction {
  public:
    BoxFunction(std::size_t dim, const FunctionInfo& info)
        : info_(&info), lower_(dim, info.lower), upper_(dim, info.upper) {
        check(dim);
    }
    /// A box that differs per coordinate (Branin).
    BoxFunction(std::vector<double> lower, std::vector<double> upper, const FunctionInfo& info)
        : info_(&info), lower_(std::move(lower)), upper_(std::move(upper)) {
        check(lower_.size());
    }
    std::size_t dimension() const noexcept { return lower_.size(); }
    std::span<const double> lower() const noexcept { return lower_; }
    std::span<const double> upper() const noexcept { return upper_; }
    std::string_view name() const noexcept { return info_->name; }
    const FunctionInfo& info() const noexcept { return *info_; }
    std::vector<double> optimum_point() const { return std::vector<double>(dimension(), info_->optimum_coordinate); }
    double optimum_value() const noexcept { return info_->optimum_value; }

  private:
    void check(std::size_t dim) const {
        require(dim >= info_->min_dim, std::string(info_->name),
                "dimension must be >= " + std::to_string(info_->min_dim) + ", got " + std::to_string(dim));
        require(info_->fixed_dim == 0 || dim == info_->fixed_dim, std::string(info_->name),
                "is defined in dimension " + std::to_string(info_->fixed_dim) + " only, got " + std::to_string(dim));
    }

    const FunctionInfo* info_;  // points at a function's static constexpr table, never owned
    std::vector<double> lower_;
    std::vector<double> upper_;
};

}  // namespace pride::continuous

#pragma once
// What every continuous test function shares: its box (the same interval in every coordinate),
// its name, and its known optimum. Each function is then one small class adding its formula.
#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include "framework/error.hpp"

namespace pride::continuous {

/// Facts about a function, identical in every dimension.
struct FunctionInfo {
    std::string_view name;
    std::string_view summary;
    double lower;  // box, every coordinate
    double upper;
    std::size_t min_dim;        // smallest dimension the formula is defined for
    double optimum_coordinate;  // x* = (c, ..., c)
    double optimum_value;       // f(x*)
};

class BoxFunction {
  public:
    BoxFunction(std::size_t dim, const FunctionInfo& info)
        : info_(&info), lower_(dim, info.lower), upper_(dim, info.upper) {
        require(dim >= info.min_dim, std::string(info.name),
                "dimension must be >= " + std::to_string(info.min_dim) + ", got " + std::to_string(dim));
    }
    std::size_t dimension() const noexcept { return lower_.size(); }
    std::span<const double> lower() const noexcept { return lower_; }
    std::span<const double> upper() const noexcept { return upper_; }
    std::string_view name() const noexcept { return info_->name; }
    const FunctionInfo& info() const noexcept { return *info_; }
    std::vector<double> optimum_point() const { return std::vector<double>(dimension(), info_->optimum_coordinate); }
    double optimum_value() const noexcept { return info_->optimum_value; }

  private:
    const FunctionInfo* info_;  // points at a function's static constexpr table, never owned
    std::vector<double> lower_;
    std::vector<double> upper_;
};

}  // namespace pride::continuous

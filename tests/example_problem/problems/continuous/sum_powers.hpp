// problems/continuous/sum_powers.hpp
#pragma once
// The sum of different powers (e.g. Surjanovic and Bingham, Virtual Library of Simulation
// Experiments): unimodal, minimum 0 at the origin.
#include <Eigen/Core>
#include <cmath>
#include <span>

#include "framework/problem.hpp"
#include "problems/continuous/batch.hpp"
#include "problems/continuous/box_function.hpp"

namespace pride::continuous {

/// f = sum_{i=1}^n |x_i|^(i+1), on [-1, 1]^n.
struct SumPowers : BoxFunction {
    static constexpr FunctionInfo info{
        "sum-powers", "sum |x_i|^(i+1); unimodal, separable", -1.0, 1.0, 1, 0.0, 0.0};
    explicit SumPowers(std::size_t dim) : BoxFunction(dim, info) {}
    double evaluate(std::span<const double> x) const noexcept {
        double f = 0.0;
        for (std::size_t i = 0; i < x.size(); ++i) f += std::pow(std::abs(x[i]), static_cast<double>(i + 2));
        return f;
    }
    /// Optional: a whole population at once, the same operations in the same order per point.
    void evaluate_batch(MatrixView points, std::span<double> values) const {
        accumulate_rows(points, values, 0.0, [](auto& f, const auto& v, Eigen::Index i) {
            const double p = static_cast<double>(i + 2);
            f += v.unaryExpr([p](double t) { return std::pow(std::abs(t), p); });
        });
    }
};

}  // namespace pride::continuous

#pragma once
// A constrained problem for tests: the disc's edge, with an inequality and a known optimum.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "framework/constraints.hpp"

namespace pride::test {

/// min x1^2 + x2^2 subject to g(x) = 1 - x1 - x2 <= 0 on [-2, 2]^2: the optimum is 0.5 at
/// (0.5, 0.5). Counts its calls (shared by copies) so that a test sees every evaluation.
struct Disc {
    std::vector<double> lo{-2.0, -2.0}, hi{2.0, 2.0};
    std::shared_ptr<std::int64_t> constrained_calls = std::make_shared<std::int64_t>(0);
    std::shared_ptr<std::int64_t> plain_calls = std::make_shared<std::int64_t>(0);
    std::size_t dimension() const { return 2; }
    std::span<const double> lower() const { return lo; }
    std::span<const double> upper() const { return hi; }
    double evaluate(std::span<const double> x) {
        ++*plain_calls;
        return x[0] * x[0] + x[1] * x[1];
    }
    ConstraintCounts constraint_counts() const { return {1, 0}; }
    double evaluate_constrained(std::span<const double> x, std::span<double> c) {
        ++*constrained_calls;
        c[0] = 1.0 - x[0] - x[1];
        return x[0] * x[0] + x[1] * x[1];
    }
    double violation(std::span<const double> c) const { return mean_violation(c, constraint_counts()); }
};
static_assert(ConstrainedProblem<Disc>);

}  // namespace pride::test

#pragma once
// Problems with several objectives: what a multi-objective algorithm needs of a box
// problem. The number of objectives M is known before a run (objectives()), and one evaluation
// writes all M values at once (an objective evaluated on its own is still one evaluation of the
// problem: the budget counts points, not objective values). A single-objective algorithm never
// sees such a problem directly: WeightedSum is its scalar view.
#include <algorithm>
#include <concepts>
#include <cstddef>
#include <numeric>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "framework/chain.hpp"
#include "framework/constraints.hpp"
#include "framework/error.hpp"
#include "framework/problem.hpp"

namespace pride {

/// The objectives are minimised, every one.
template <class P>
concept MultiObjectiveProblem = std::copy_constructible<P> &&
    requires(P& p, const P& cp, std::span<const double> x, std::span<double> f) {
    { cp.dimension() } -> std::convertible_to<std::size_t>;
    { cp.lower() } -> std::convertible_to<std::span<const double>>;
    { cp.upper() } -> std::convertible_to<std::span<const double>>;
    { cp.objectives() } -> std::convertible_to<std::size_t>;
    p.evaluate(x, f);  // f.size() == objectives()
};

/// A problem of several objectives with constraints (framework/constraints.hpp): one evaluation
/// writes the M objective values into `f` and the m + p constraint values into `c` (inequalities
/// g_i <= 0 first, then equalities), counted once; violation(c) is the suite's measure of a point's
/// violation from those values (0: feasible).
template <class P>
concept ConstrainedMultiObjectiveProblem = MultiObjectiveProblem<P> &&
    requires(P& p, const P& cp, std::span<const double> x, std::span<double> f, std::span<double> c,
             std::span<const double> cc) {
    { cp.constraint_counts() } -> std::convertible_to<ConstraintCounts>;
    p.evaluate_constrained(x, f, c);
    { cp.violation(cc) } -> std::convertible_to<double>;
};

/// A problem of several objectives whose solutions are chains searched with the chain operators of
/// framework/chain.hpp (grid paths): random_chain, crossover and mutate as a ChainProblem's, and
/// evaluate(c, f) writing the M values of chain c (one evaluation).
template <class P>
concept MultiObjectiveChainProblem = ChainOperators<P> &&
    requires(P& p, const P& cp, const typename P::chain_type& a, std::span<double> f) {
    { cp.objectives() } -> std::convertible_to<std::size_t>;
    p.evaluate(a, f);  // f.size() == objectives()
};

/// Optional: the columns of `points` into the columns of `values` (M rows) in one call.
template <class P>
concept BatchMultiObjectiveProblem = MultiObjectiveProblem<P> && requires(P& p, MatrixView points, Matrix& values) {
    p.evaluate_batch(points, values);
};

/// The scalar problem sum_i w_i f_i(x) of a multi-objective problem: a view that evaluates the
/// problem it holds (a problem shares its definition between copies, as every problem does), so
/// that the weighted single-objective algorithms of the papers (Zhang et al.'s (2025) eq. 12) and the
/// multi-objective ones search the same objectives. Each call of evaluate() is one evaluation of
/// the multi-objective problem.
template <MultiObjectiveProblem P>
class WeightedSum {
  public:
    /// `weights`: one per objective, finite and >= 0, not all 0.
    WeightedSum(P problem, std::vector<double> weights)
        : problem_(std::move(problem)), weights_(std::move(weights)), values_(weights_.size()) {
        const std::size_t m = problem_.objectives();
        require(weights_.size() == m, "weights",
                "a weighted sum needs one weight per objective: " + std::to_string(m) + " objectives, " +
                    std::to_string(weights_.size()) + " weights");
        for (std::size_t i = 0; i < m; ++i)
            require(weights_[i] >= 0.0 && weights_[i] <= 1e300, "weights",
                    "weight " + std::to_string(i + 1) + " must be finite and >= 0");
        require(std::any_of(weights_.begin(), weights_.end(), [](double w) { return w > 0.0; }), "weights",
                "at least one weight must be > 0");
    }

    std::size_t dimension() const { return problem_.dimension(); }
    std::span<const double> lower() const { return problem_.lower(); }
    std::span<const double> upper() const { return problem_.upper(); }

    double evaluate(std::span<const double> x) {
        problem_.evaluate(x, std::span<double>(values_));
        // In objective order, from 0: the same bits as the papers' sum written out.
        double sum = 0.0;
        for (std::size_t i = 0; i < values_.size(); ++i) sum += weights_[i] * values_[i];
        return sum;
    }

    /// The objective values of the last point evaluated (for reports that show both).
    std::span<const double> last_objectives() const { return values_; }
    std::span<const double> weights() const { return weights_; }
    const P& problem() const { return problem_; }

  private:
    P problem_;
    std::vector<double> weights_;
    std::vector<double> values_;  // scratch, sized once: no allocation per evaluation
};

}  // namespace pride

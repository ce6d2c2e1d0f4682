#pragma once
// Box problems over a user function (C++ callable, Python function) of one objective or of several
// (MoCallbackProblem): type erasure at the edge, so every box algorithm can optimise code the
// engine was not compiled with. With a batch
// function the evaluation guard hands it the whole population (or what is left of the budget) in
// one call; registered problems keep their fully typed hot loop and never pass through here.
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "framework/constraints.hpp"
#include "framework/problem.hpp"
#include "framework/variables.hpp"

namespace pride::engine {

class CallbackProblem {
  public:
    using Scalar = std::function<double(std::span<const double>)>;
    using Batch = std::function<void(MatrixView, std::span<double>)>;
    /// Fills every column of a matrix with a starting point (as SuggestsStartingPoints).
    using Starts = std::function<void(Rng&, Matrix&)>;

    /// Throws InputError for an empty box, lower > upper, a non-finite bound, or no function.
    /// `thread_safe`: the functions may be called from several threads at once (RunSettings'
    /// threads); `starts`: the problem's own starting points (empty: uniform in the box).
    CallbackProblem(std::string name, std::vector<double> lower, std::vector<double> upper, Scalar scalar,
                    Batch batch = {}, bool thread_safe = false, Starts starts = {},
                    std::vector<VariableType> types = {});

    std::size_t dimension() const noexcept { return shared_->lower.size(); }
    std::span<const double> lower() const noexcept { return shared_->lower; }
    std::span<const double> upper() const noexcept { return shared_->upper; }
    std::string_view name() const noexcept { return shared_->name; }
    bool thread_safe() const noexcept { return shared_->thread_safe; }
    /// The declared type of variable i (real when none was declared). The function receives the
    /// integer and categorical coordinates rounded to their values (round_to_types).
    VariableType variable_type(std::size_t i) const noexcept {
        return shared_->types.empty() ? VariableType::real : shared_->types[i];
    }

    double evaluate(std::span<const double> x);
    void evaluate_batch(MatrixView points, std::span<double> values);
    /// The given starting points, or uniform ones drawn as UniformInit draws them (so a callback
    /// without starts runs as it did before it had any).
    void starting_points(Rng& rng, Matrix& out) const;

  private:
    /// evaluate and evaluate_batch on points already in the declared types.
    double evaluate_point(std::span<const double> x);
    void evaluate_typed(MatrixView points, std::span<double> values);

    struct Shared {
        std::string name;
        std::vector<double> lower, upper;
        Scalar scalar;
        Batch batch;
        bool thread_safe = false;
        Starts starts;
        std::vector<VariableType> types;  // empty: all real
    };
    std::shared_ptr<const Shared> shared_;  // copies per run share the function and the box
};

/// A user's function of M objectives: the edge where a call goes through std::function. With a
/// batch function, a population is one call.
class MoCallbackProblem {
  public:
    using Scalar = std::function<void(std::span<const double>, std::span<double>)>;
    using Batch = std::function<void(MatrixView, Matrix&)>;

    /// `types` as CallbackProblem's (checked as there).
    MoCallbackProblem(std::string name, std::vector<double> lower, std::vector<double> upper, std::size_t objectives,
                      Scalar scalar, Batch batch, std::vector<VariableType> types = {});

    std::size_t dimension() const noexcept { return shared_->lower.size(); }
    std::span<const double> lower() const noexcept { return shared_->lower; }
    std::span<const double> upper() const noexcept { return shared_->upper; }
    std::size_t objectives() const noexcept { return shared_->objectives; }
    const std::string& name() const noexcept { return shared_->name; }
    VariableType variable_type(std::size_t i) const noexcept {
        return shared_->types.empty() ? VariableType::real : shared_->types[i];
    }

    void evaluate(std::span<const double> x, std::span<double> f);
    void evaluate_batch(MatrixView points, Matrix& values);

  private:
    void evaluate_typed(std::span<const double> x, std::span<double> f);
    void evaluate_batch_typed(MatrixView points, Matrix& values);

    struct Shared {
        std::string name;
        std::vector<double> lower, upper;
        std::size_t objectives;
        Scalar scalar;
        Batch batch;
        std::vector<VariableType> types;  // empty: all real
    };
    std::shared_ptr<const Shared> shared_;
    Matrix one_;  // scratch of the batch-only route
};

/// A user's function with constraints: f and the m + p constraint values (inequalities first) from
/// one call, the violation CEC's mean (framework/constraints.hpp) with the given tolerance.
class ConstrainedCallbackProblem {
  public:
    using Function = std::function<double(std::span<const double>, std::span<double>)>;

    /// Throws InputError as CallbackProblem does, and for no constraint or a tolerance that is not a
    /// finite number >= 0.
    /// `types` as CallbackProblem's: the function receives the integer and categorical
    /// coordinates rounded to their values.
    ConstrainedCallbackProblem(std::string name, std::vector<double> lower, std::vector<double> upper,
                               ConstraintCounts counts, double tolerance, Function function,
                               std::vector<VariableType> types = {});

    std::size_t dimension() const noexcept { return shared_->lower.size(); }
    std::span<const double> lower() const noexcept { return shared_->lower; }
    std::span<const double> upper() const noexcept { return shared_->upper; }
    std::string_view name() const noexcept { return shared_->name; }
    ConstraintCounts constraint_counts() const noexcept { return shared_->counts; }
    VariableType variable_type(std::size_t i) const noexcept {
        return shared_->types.empty() ? VariableType::real : shared_->types[i];
    }

    /// f alone (the constraints' values computed and dropped): what an algorithm without
    /// constraint handling would see; the engine never runs one on this problem.
    double evaluate(std::span<const double> x);
    double evaluate_constrained(std::span<const double> x, std::span<double> constraints);
    double violation(std::span<const double> constraints) const noexcept {
        return mean_violation(constraints, shared_->counts, shared_->tolerance);
    }

  private:
    struct Shared {
        std::string name;
        std::vector<double> lower, upper;
        ConstraintCounts counts;
        double tolerance = kEqualityTolerance;
        Function function;
        std::vector<VariableType> types;  // empty: all real
    };
    std::shared_ptr<const Shared> shared_;
    std::vector<double> scratch_;  // evaluate()'s constraint values, per copy
};

}  // namespace pride::engine

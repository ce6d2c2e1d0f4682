#pragma once
// Ask and tell: any box algorithm driven from outside, one batch at a time. The run proceeds on
// its own thread over a callback problem whose batch function hands each batch the evaluation
// guard asks for (the population, or what is left of the budget) to the caller and waits for its
// values, so no algorithm is rewritten and the run is the one engine::run gives with the same
// function: the same seed, the same bits. A multi-objective algorithm is driven the same way, told
// M values per point. A run with constraints (the algorithms that handle them) is told each point's
// f and its m + p constraint values; the engine evaluates a constrained point at a time
// (RunState::evaluate_columns calls evaluate_constrained per column), so such a run asks for one
// point per batch.
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <mutex>
#include <optional>
#include <span>
#include <thread>
#include <vector>

#include "engine/problem.hpp"
#include "engine/run.hpp"
#include "engine/specs.hpp"
#include "framework/problem.hpp"

namespace pride::engine {

/// The constraints of an ask-and-tell run: as CallbackSpec's (m inequalities g_i <= 0, then p
/// equalities h_j = 0 within `tolerance`); none by default.
struct AskTellConstraints {
    std::int64_t inequalities = 0;
    std::int64_t equalities = 0;
    double tolerance = 1e-4;
    std::int64_t total() const noexcept { return inequalities + equalities; }
};

class AskTell {
  public:
    /// Checks everything engine::check does on the box [lower, upper] (InputError naming what is
    /// wrong), then starts the run; it waits at its first batch.
    /// `objectives` M: 1 for a single-objective algorithm, at least 2 for a multi-objective one
    /// (engine/multiobjective.hpp; InputError("objectives", ...) otherwise). `constraints`: the
    /// counts and tolerance the engine checks for a user's function (InputError "inequalities",
    /// "equalities", "tolerance"), one objective only, an algorithm that handles them. `types`:
    /// the variables' types (CallbackSpec::types; the points asked for have them).
    AskTell(AlgorithmSpec algorithm, std::vector<double> lower, std::vector<double> upper, Budget budget,
            std::uint64_t seed, std::int64_t objectives = 1, AskTellConstraints constraints = {},
            std::vector<VariableType> types = {});
    /// A run still going is stopped at its pending batch and its thread joined.
    ~AskTell();
    AskTell(const AskTell&) = delete;
    AskTell& operator=(const AskTell&) = delete;

    std::size_t dimension() const noexcept { return dimension_; }
    std::size_t objectives() const noexcept { return objectives_; }
    /// m + p: the constraint values told per point (0 without constraints).
    std::size_t constraints() const noexcept { return constraints_; }

    /// The points the run wants evaluated next, one per column (0 columns once the run has
    /// ended); asking again before telling gives the same points. Blocks until the run asks or ends.
    /// The matrix is the run's: valid until tell(), after which the run may refill it.
    const Matrix& ask();
    /// The values of the points of the last ask(), one each (NaN: worse than every value); with
    /// M objectives, M per point, the point's values together (point after point).
    /// With constraints, `constraints` holds each point's m + p values together (point after point;
    /// NaN: infeasible, with an infinite violation); without, it is empty.
    /// InputError("tell", ...) after the end, before an ask, or for a wrong number of values; a
    /// refused tell changes nothing (the same points may be told again).
    void tell(std::span<const double> values, std::span<const double> constraints = {});
    /// True once the run has ended (blocks until the run asks or ends).
    bool done();
    /// The run's result (with several objectives, its `front`); InputError("result", ...) before
    /// the end. Rethrows what stopped the run if it failed.
    const RunResult& result();

  private:
    void work(AlgorithmSpec algorithm, Problem problem, Budget budget, std::uint64_t seed);
    /// The state the run ended in, checked for the result (`ready`: the run's kind has one).
    void wait_for_result(bool ready);
    /// The batch function: publishes `points`, waits for tell() (or cancellation); writes the told
    /// values and, with constraints, their values.
    void exchange(MatrixView points, std::span<double> values, std::span<double> constraints = {});
    void wait_for_run(std::unique_lock<std::mutex>& lock);

    struct Cancelled {};
    enum class State { running, asking, finished };

    std::size_t dimension_ = 0;
    std::size_t objectives_ = 1;
    std::size_t constraints_ = 0;
    std::mutex mutex_;
    std::condition_variable changed_;
    State state_ = State::running;
    bool asked_ = false;   // ask() has shown the pending points
    bool cancel_ = false;  // the destructor wants the run to end
    Matrix pending_;       // the points of the pending batch
    std::vector<double> values_, constraint_values_;
    bool told_ = false;
    std::optional<RunResult> result_;
    std::exception_ptr failure_;
    std::thread worker_;  // last: started once everything above exists
};

}  // namespace pride::engine

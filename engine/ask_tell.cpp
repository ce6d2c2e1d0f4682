#include "engine/ask_tell.hpp"

#include <algorithm>
#include <string>

#include "engine/registry.hpp"
#include "framework/error.hpp"

namespace pride::engine {

AskTell::AskTell(AlgorithmSpec algorithm, std::vector<double> lower, std::vector<double> upper, Budget budget,
                 std::uint64_t seed, std::int64_t objectives, AskTellConstraints constraints,
                 std::vector<VariableType> types) {
    dimension_ = lower.size();
    const bool several = algorithms().at(algorithm.name).multiobjective();
    require(several ? objectives >= 2 : objectives == 1, "objectives",
            several ? algorithm.name + " is multi-objective: give the number of objectives M >= 2, got " +
                          std::to_string(objectives)
                    : algorithm.name + " optimises one objective, got " + std::to_string(objectives));
    objectives_ = static_cast<std::size_t>(objectives);
    const bool constrained = constraints.inequalities != 0 || constraints.equalities != 0;
    require(!several || !constrained, "inequalities",
            algorithm.name + " is multi-objective: constraints are for algorithms of one objective");
    CallbackSpec spec;
    spec.name = "bounds";
    spec.lower = std::move(lower);
    spec.upper = std::move(upper);
    spec.objectives = objectives;
    spec.inequalities = constraints.inequalities;
    spec.equalities = constraints.equalities;
    spec.tolerance = constraints.tolerance;
    spec.types = std::move(types);
    if (constrained)
        // One point per batch: the engine evaluates constrained points one at a time.
        spec.constrained = [this](std::span<const double> x, std::span<double> c) -> double {
            double f = 0.0;
            exchange(Eigen::Map<const Matrix>(x.data(), static_cast<Eigen::Index>(x.size()), 1),
                     std::span<double>(&f, 1), c);
            return f;
        };
    else if (several)
        spec.values_batch = [this](MatrixView points, Matrix& values) {
            exchange(points, std::span<double>(values.data(), static_cast<std::size_t>(values.size())));
        };
    else
        spec.batch = [this](MatrixView points, std::span<double> values) { exchange(points, values); };
    Problem problem(spec);  // checks the counts and the tolerance
    check(algorithm, problem, budget);
    if (constrained) constraints_ = static_cast<std::size_t>(constraints.total());
    worker_ = std::thread([this, algorithm, problem, budget, seed] { work(algorithm, problem, budget, seed); });
}

AskTell::~AskTell() {
    {
        const std::lock_guard lock(mutex_);
        cancel_ = true;
    }
    changed_.notify_all();
    if (worker_.joinable()) worker_.join();
}

void AskTell::work(AlgorithmSpec algorithm, Problem problem, Budget budget, std::uint64_t seed) {
    std::optional<RunResult> result;
    std::exception_ptr failure;
    try {
        result = run(algorithm, problem, budget, seed);
    } catch (...) {
        failure = std::current_exception();  // Cancelled, or NLopt's own error around it
    }
    {
        const std::lock_guard lock(mutex_);
        if (!cancel_) {
            result_ = std::move(result);
            failure_ = failure;
        }
        state_ = State::finished;
    }
    changed_.notify_all();
}

void AskTell::exchange(MatrixView points, std::span<double> values, std::span<double> constraints) {
    std::unique_lock lock(mutex_);
    if (cancel_) throw Cancelled{};
    pending_ = points;
    told_ = false;
    asked_ = false;
    state_ = State::asking;
    changed_.notify_all();
    changed_.wait(lock, [&] { return told_ || cancel_; });
    if (cancel_) throw Cancelled{};
    // M values per point, the point's together: the column of an M x n matrix.
    std::copy(values_.begin(), values_.end(), values.begin());
    std::copy(constraint_values_.begin(), constraint_values_.end(), constraints.begin());
    state_ = State::running;
}

void AskTell::wait_for_run(std::unique_lock<std::mutex>& lock) {
    changed_.wait(lock, [&] { return state_ != State::running; });
}

const Matrix& AskTell::ask() {
    std::unique_lock lock(mutex_);
    wait_for_run(lock);
    if (state_ == State::finished) {
        if (failure_) std::rethrow_exception(failure_);
        pending_.resize(static_cast<Eigen::Index>(dimension_), 0);
        return pending_;
    }
    asked_ = true;
    return pending_;
}

void AskTell::tell(std::span<const double> values, std::span<const double> constraints) {
    {
        std::unique_lock lock(mutex_);
        wait_for_run(lock);
        require(state_ != State::finished, "tell", "the run has ended (done is true): nothing more to tell");
        require(asked_, "tell", "no points were asked for: call ask() first");
        const auto expected = static_cast<std::size_t>(pending_.cols()) * objectives_;
        require(values.size() == expected, "tell",
                objectives_ == 1 ? "expected " + std::to_string(pending_.cols()) +
                                       " values, one per point asked for, got " + std::to_string(values.size())
                                 : "expected " + std::to_string(pending_.cols()) + " x " + std::to_string(objectives_) +
                                       " values, " + std::to_string(objectives_) + " per point asked for, got " +
                                       std::to_string(values.size()));
        const auto expected_constraints = static_cast<std::size_t>(pending_.cols()) * constraints_;
        if (constraints_ == 0)
            require(constraints.empty(), "tell",
                    "constraint values were given, but the run has no constraints (declare inequalities or "
                    "equalities when it is made)");
        else
            require(constraints.size() == expected_constraints, "tell",
                    "expected " + std::to_string(pending_.cols()) + " x " + std::to_string(constraints_) +
                        " constraint values, " + std::to_string(constraints_) + " per point asked for, got " +
                        std::to_string(constraints.size()));
        values_.assign(values.begin(), values.end());
        constraint_values_.assign(constraints.begin(), constraints.end());
        told_ = true;
        asked_ = false;
        state_ = State::running;
    }
    changed_.notify_all();
}

bool AskTell::done() {
    std::unique_lock lock(mutex_);
    wait_for_run(lock);
    return state_ == State::finished;
}

void AskTell::wait_for_result(bool ready) {
    std::unique_lock lock(mutex_);
    wait_for_run(lock);
    if (failure_) std::rethrow_exception(failure_);
    require(state_ == State::finished && ready, "result",
            "the run has not ended yet: tell the values of every batch until done is true");
}

const RunResult& AskTell::result() {
    wait_for_result(true);
    const std::lock_guard lock(mutex_);
    require(result_.has_value(), "result",
            "the run has not ended yet: tell the values of every batch until done is true");
    return *result_;
}

}  // namespace pride::engine

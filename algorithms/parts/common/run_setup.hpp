#pragma once
// How every population run begins, written once for PSO, the GA and LSO: the checks (the
// algorithm's parameters, the stopping rules, and the horizon T when a schedule needs one), the
// run's Rng and RunState, then for boxes the initial population: drawn by the Init policy, put in
// the box by the Bounds policy, evaluated, and recorded as iteration 0. Each algorithm's loop then
// starts where its own equations do.
//
// An algorithm passed in provides name(), validate() and `population`, and for box runs `init` and
// `bounds` (the policies of that name).
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "framework/constraints.hpp"
#include "framework/error.hpp"
#include "framework/problem.hpp"
#include "framework/random.hpp"
#include "framework/run_state.hpp"
#include "framework/termination.hpp"
#include "framework/variables.hpp"

namespace pride {

/// What a run needs of the horizon T (Termination::horizon, after an initial population of N).
struct HorizonNeed {
    std::int64_t per_iteration = 0;      // evaluations per iteration; 0: no horizon is worked out
    const char* required_for = nullptr;  // set: a run without T is refused, and this says why
};

/// A run before its population: its horizon, generator and state.
template <class Solution = std::vector<double>>
struct RunStart {
    std::optional<std::int64_t> horizon;  // T, when asked for and a limit gives it
    Rng rng;
    BasicRunState<Solution> state;
};

/// Checks before anything is drawn, so that a bad parameter never costs a run. `dimension`: the
/// length of a point (box runs), for the state's best point.
template <class Solution = std::vector<double>, class Algorithm>
RunStart<Solution> start_run(const Algorithm& algorithm, const Termination& termination, std::uint64_t seed,
                             HorizonNeed need = {}, std::size_t dimension = 0) {
    algorithm.validate();
    termination.validate(algorithm.name());
    std::optional<std::int64_t> horizon;
    if (need.per_iteration > 0) {
        horizon = termination.horizon(algorithm.population, need.per_iteration);
        if (need.required_for)
            require(horizon.has_value(), algorithm.name(),
                    std::string("needs an iteration or evaluation limit ") + need.required_for);
    }
    return {horizon, Rng(seed), BasicRunState<Solution>(termination, dimension)};
}

/// A box run once its initial population is in: x (one column per individual), its fitness fx
/// and violations vx (framework/constraints.hpp; 0 for every point of a problem without
/// constraints), iteration 0 recorded and shown to the observer.
struct BoxRun : RunStart<> {
    std::span<const double> lo, hi;  // the problem's box (the run's copy of the problem owns it)
    std::size_t dim = 0;
    Matrix x;
    std::vector<double> fx, vx;
    std::vector<double> cx;  // constrained problems, when asked for: the m + p values of each point in turn
    // The integer and categorical coordinates the algorithm rounds (its `round_integers`; empty
    // on a problem of real variables): the typed space's rounding operator.
    Rounding discrete = {};
    /// The integer coordinates of x put on their values (nothing on a problem of real variables).
    void round(std::span<double> x) const noexcept { discrete(x, lo, hi); }
};

/// `constraint_values`: on a constrained problem, keep the initial points' constraint values in cx.
template <class Algorithm, BoxProblem P, class O>
BoxRun start_box_run(const Algorithm& algorithm, P& problem, const Termination& termination, std::uint64_t seed,
                     O& observer, HorizonNeed need = {}, bool constraint_values = false) {
    // Braced initialisers run in order: start_run's checks come before any allocation.
    BoxRun run{start_run(algorithm, termination, seed, need, problem.dimension()),
               problem.lower(),
               problem.upper(),
               problem.dimension(),
               Matrix(static_cast<Eigen::Index>(problem.dimension()), static_cast<Eigen::Index>(algorithm.population)),
               std::vector<double>(static_cast<std::size_t>(algorithm.population)),
               std::vector<double>(static_cast<std::size_t>(algorithm.population), 0.0),
               {}};
    seed_noise(problem, seed);
    algorithm.init(problem, run.rng, run.x);
    std::vector<std::size_t> categorical;
    if constexpr (requires { algorithm.round_integers; })
        if (algorithm.round_integers) {
            run.discrete = Rounding(problem);
            categorical = categorical_coordinates(problem);
        }
    for (Eigen::Index i = 0; i < run.x.cols(); ++i) {
        const std::span<double> x = column(run.x, i);
        algorithm.bounds(x, run.lo, run.hi);
        for (const std::size_t c : categorical) x[c] = choice_of_start(x[c], run.lo[c], run.hi[c]);
        run.round(x);
    }
    if constexpr (ConstrainedProblem<P>) {
        if (constraint_values) {
            run.cx.assign(problem.constraint_counts().total() * run.fx.size(), 0.0);
            run.state.evaluate_columns(problem, run.x, run.fx, run.vx, run.cx);
        } else {
            run.state.evaluate_population(problem, run.x, run.fx, run.vx);
        }
    } else {
        (void)constraint_values;
        run.state.evaluate_population(problem, run.x, run.fx, run.vx);
    }
    run.state.end_iteration(observer, run.x, run.fx);
    return run;
}

}  // namespace pride

// The worked example of docs/adding-an-algorithm.md: a (1+1) evolution strategy registered as
// "example-es" from outside engine/, as a user's program would. tests/test_docs.cpp runs it, and
// holds each region between "// doc: NAME" and "// doc: end" equal to the doc's code block of that
// name, so the doc cannot drift from code that compiles.
// doc: algorithm
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "framework/bounds.hpp"
#include "framework/error.hpp"
#include "framework/initializer.hpp"
#include "framework/observer.hpp"
#include "framework/problem.hpp"
#include "framework/random.hpp"
#include "framework/result.hpp"
#include "framework/run_state.hpp"
#include "framework/termination.hpp"

namespace example {

// (1+1) evolution strategy with the 1/5 success rule.
//
//   Rechenberg, I. (1973). Evolutionsstrategie. Frommann-Holzboog (the 1/5 success rule).
//   Schwefel, H.-P. (1995). Evolution and Optimum Seeking. Wiley (adapting every few iterations,
//     factor 0.85).
//
// Per iteration (one evaluation each):
//   (1) y <- x + sigma (high - low) N(0, I), then the Bounds policy puts y back into the box
//   (2) x <- y if f(y) <= f(x) (a success)
//   (3) after every `window` iterations: sigma <- sigma / 0.85 if more than 1/5 of them were
//       successes, sigma * 0.85 if fewer
// Decided by this example where the papers are silent: sigma is relative to each coordinate's
// range and never above 1; ties count as successes.
template <class Bounds = pride::Clamp, class Init = pride::UniformInit>
class OnePlusOneEs {
  public:
    double sigma0 = 0.1;       // initial step, as a fraction of each coordinate's range
    std::int64_t window = 10;  // iterations between two step-size adaptations
    Bounds bounds{};
    Init init{};

    std::string name() const { return "example-es"; }

    void validate() const {
        pride::require(sigma0 > 0.0 && sigma0 <= 1.0, name(), "sigma0 must be in (0, 1]");
        pride::require(window >= 1, name(), "window must be >= 1");
    }

    template <pride::BoxProblem P, pride::Observer O = pride::NoObserver>
    pride::Result run(P problem, const pride::Termination& termination, std::uint64_t seed, O&& observer = O{}) const {
        validate();
        termination.validate(name());
        const std::size_t dim = problem.dimension();
        const auto lo = problem.lower();
        const auto hi = problem.upper();

        pride::Rng rng(seed);  // the run's own stream: no global generator
        pride::RunState state(termination, dim);
        pride::Matrix x(static_cast<Eigen::Index>(dim), 1), y(x.rows(), 1);  // allocated once per run
        std::vector<double> fx(1);

        init(problem, rng, x);  // the parent
        bounds(pride::column(x, 0), lo, hi);
        state.evaluate_columns(problem, x, fx);  // counted; +inf if the budget is already spent
        state.end_iteration(observer, x, fx);    // iteration 0

        double sigma = sigma0;
        std::int64_t trials = 0, successes = 0;
        while (!state.done()) {
            const auto xs = pride::column(x, 0);
            const auto ys = pride::column(y, 0);
            for (std::size_t d = 0; d < dim; ++d) ys[d] = xs[d] + sigma * (hi[d] - lo[d]) * rng.normal();  // (1)
            bounds(ys, lo, hi);
            const double fy = state.evaluate(problem, ys);  // sanitised: NaN and inf are +inf
            if (fy <= fx[0]) {                              // (2)
                x = y;
                fx[0] = fy;
                ++successes;
            }
            if (++trials == window) {  // (3)
                if (5 * successes > trials) sigma = std::min(sigma / 0.85, 1.0);
                if (5 * successes < trials) sigma *= 0.85;
                trials = successes = 0;
            }
            state.end_iteration(observer, x, fx);
        }
        return state.finish();
    }
};

}  // namespace example
// doc: end

// doc: registration
#include "engine/family.hpp"

namespace {

pride::engine::AlgorithmEntry example_es() {
    using namespace pride::engine;
    return box_algorithm(
        "example-es", "es", "(1+1) evolution strategy with the 1/5 success rule (docs/adding-an-algorithm.md)",
        {real("sigma0", 0.1, 0.0, 1.0, "initial step, as a fraction of each coordinate's range").open_below(),
         integer("window", 10, 1, 1000, "iterations between two step-size adaptations")},
        [](const Params& p) {
            example::OnePlusOneEs<> es;
            es.sigma0 = p.real("sigma0");
            es.window = p.integer("window");
            return es;
        });
}

// At start-up, before main: the algorithm is then in engine::algorithms() like the built-ins.
const pride::engine::Registration registration{example_es()};

}  // namespace
// doc: end

// doc: running
#include "engine/run.hpp"
#include "problems/continuous/functions.hpp"

// By name, as every front end runs it: the parameters are checked against their declarations, the
// problem is built once from its spec.
pride::engine::RunResult run_example_by_name() {
    const pride::engine::Problem sphere(pride::engine::ContinuousSpec{"sphere", 5});
    pride::engine::Budget budget;
    budget.evaluations = 1000;
    return pride::engine::run({"example-es", {}}, sphere, budget, /*seed=*/1);
}

// Typed, without the registry: on any box problem type, with an observer called once per
// iteration (here counting the iterations that improved the best value).
pride::Result run_example_directly(std::int64_t& improvements) {
    static const example::OnePlusOneEs<> es;  // one configured value; run() never changes it
    double previous = pride::kInf;
    return es.run(pride::continuous::Sphere(5), pride::max_evaluations(1000), 1, [&](const pride::IterationView& v) {
        if (v.best_f < previous) ++improvements;
        previous = v.best_f;
    });
}
// doc: end

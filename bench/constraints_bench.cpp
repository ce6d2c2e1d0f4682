// What handling constraints costs the framework per evaluation: each algorithm that takes
// constraints runs on the sphere (problems/continuous/functions.hpp: D = 30, [-5.12, 5.12]^D) and on the same sphere
// with one inequality that always holds (g = -1, free to compute), so that the two runs make the same comparisons and
// differ only by the constrained path (the constraint buffer, the violation, the handler's order,
// the first-feasible bookkeeping). Each run: exactly --evals evaluations, seed 1; the time per
// evaluation is the least of 7 timings (bench/best_time.hpp, the thread's CPU clock).
//
// stdout: CSV `algo,plain_ns,constrained_ns,ratio,same_best`; same_best says whether the two runs
// found the same best value (they make the same comparisons, so they should).
#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "algorithms/cmaes.hpp"
#include "algorithms/de.hpp"
#include "algorithms/pso.hpp"
#include "bench/best_time.hpp"
#include "framework/constraints.hpp"
#include "framework/termination.hpp"
#include "problems/continuous/functions.hpp"

namespace {

using namespace pride;

/// The sphere with one inequality that always holds.
struct HeldSphere : continuous::Sphere {
    using continuous::Sphere::Sphere;
    ConstraintCounts constraint_counts() const { return {1, 0}; }
    double evaluate_constrained(std::span<const double> x, std::span<double> c) const {
        c[0] = -1.0;
        return evaluate(x);
    }
    double violation(std::span<const double> c) const { return mean_violation(c, constraint_counts()); }
};
static_assert(ConstrainedProblem<HeldSphere>);

template <class A>
void measure(const std::string& name, const A& algorithm, std::size_t dim, std::int64_t evals) {
    Termination t;
    t.max_evaluations = evals;
    double plain_best = 0.0, held_best = 0.0;
    const double plain =
        bench::best_ns([&] { plain_best = algorithm.run(continuous::Sphere(dim), t, 1).best_f; }, evals);
    const double held = bench::best_ns([&] { held_best = algorithm.run(HeldSphere(dim), t, 1).best_f; }, evals);
    fmt::print("{},{:.2f},{:.2f},{:.3f},{}\n", name, plain, held, held / plain, plain_best == held_best);
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"The framework's cost per evaluation with and without constraints"};
    std::int64_t evals = 100'000;
    std::size_t dim = 30;
    app.add_option("--evals", evals, "evaluations per run")->check(CLI::Range(100, 10'000'000));
    app.add_option("--dim", dim, "the sphere's dimension")->check(CLI::Range(2, 1000));
    CLI11_PARSE(app, argc, argv);
    fmt::print("algo,plain_ns,constrained_ns,ratio,same_best\n");
    measure("de", De<>{}, dim, evals);
    Pso<> pso;
    measure("pso", pso, dim, evals);
    measure("cmaes", Cmaes<>{}, dim, evals);
    return 0;
}

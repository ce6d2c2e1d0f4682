// The continuous benchmark of issue 2: each algorithm on rastrigin, rosenbrock, ackley, griewank and
// schwefel (D = 30, pagmo's boxes), population 50, exactly 100,000 evaluations, seeds 1..10.
//
// stdout: CSV `algo,problem,dim,seed,fevals,best_f,wall_ms`; wall time runs from population set-up
// to the end of the run. Rows with algo `bare` time the same number of bare function evaluations
// (the minimum of five repetitions, on a population-sized set of points, as an algorithm sees them),
// so that framework cost per evaluation = (wall_ms - bare wall_ms) / fevals.
// stderr: a summary of that cost per algorithm (median over problems and seeds).
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "algorithms/ga.hpp"
#include "algorithms/nlopt.hpp"
#include "algorithms/pso.hpp"
#include "problems/continuous/functions.hpp"

#ifdef PRIDE_HAVE_PAGMO
#include <pagmo/algorithm.hpp>
#include <pagmo/algorithms/pso.hpp>
#include <pagmo/algorithms/sga.hpp>
#include <pagmo/population.hpp>
#include <pagmo/problem.hpp>
#include <pagmo/problems/ackley.hpp>
#include <pagmo/problems/griewank.hpp>
#include <pagmo/problems/rastrigin.hpp>
#include <pagmo/problems/rosenbrock.hpp>
#include <pagmo/problems/schwefel.hpp>
#endif

namespace {

using namespace pride;
using namespace pride::continuous;

struct Settings {
    std::int64_t dim = 30;
    std::int64_t pop = 50;
    std::int64_t evals = 100000;
    std::int64_t seeds = 10;
    std::vector<std::string> algos{"pso", "pso-constriction", "ga", "nlopt:LN_SBPLX", "nlopt:GN_CRS2_LM"};
    bool pagmo = true;
};

struct Row {
    std::string algo, problem;
    std::int64_t seed, fevals;
    double best_f, wall_ms;
};

std::vector<Row> rows;

void emit(Row r) {
    fmt::print("{},{},{},{},{},{:.17g},{:.3f}\n", r.algo, r.problem, 30, r.seed, r.fevals, r.best_f, r.wall_ms);
    std::fflush(stdout);
    rows.push_back(std::move(r));
}

/// Time of `evals` bare evaluations on a population-sized set of random points in the box.
template <class F>
double bare_ms(F f, const Settings& s) {
    Matrix points(static_cast<Eigen::Index>(s.dim), static_cast<Eigen::Index>(s.pop));
    Rng rng(12345);
    UniformInit{}(f, rng, points);
    double best = 1e300, sink = 0.0;
    for (int rep = 0; rep < 5; ++rep) {
        const auto start = Clock::now();
        for (std::int64_t done = 0; done < s.evals;) {
            for (Eigen::Index j = 0; j < points.cols() && done < s.evals; ++j, ++done) {
                // The barrier keeps each evaluation inside the timed region and un-hoisted, as in
                // Google Benchmark's DoNotOptimize.
                double v = f.evaluate(column(points, j));
                asm volatile("" : "+x"(v) : : "memory");
                sink += v;
            }
        }
        best = std::min(best, std::chrono::duration<double, std::milli>(Clock::now() - start).count());
    }
    if (sink == 42.0) std::fputs("", stderr);  // keeps the sum alive
    return best;
}

template <class F>
void bench_problem(const Settings& s) {
    const F f(static_cast<std::size_t>(s.dim));
    const std::string name(F::info.name);
    const Termination budget = max_evaluations(s.evals);
    for (const auto& algo : s.algos) {
        for (std::int64_t seed = 1; seed <= s.seeds; ++seed) {
            Result r;
            const auto useed = static_cast<std::uint64_t>(seed);
            if (algo == "pso") {
                Pso<> a;
                a.population = s.pop;
                r = a.run(f, budget, useed);
            } else if (algo == "pso-constriction") {
                Pso<ConstrictionVelocity> a;
                a.population = s.pop;
                r = a.run(f, budget, useed);
            } else if (algo == "ga") {
                Ga<> a;
                a.population = s.pop;
                r = a.run(f, budget, useed);
            } else {
                r = Nlopt(algo, s.pop).run(f, budget, useed);
            }
            emit({algo, name, seed, r.evaluations, r.best_f, r.wall_ms});
        }
    }
    emit({"bare", name, 0, s.evals, 0.0, bare_ms(f, s)});
}

#ifdef PRIDE_HAVE_PAGMO
template <class PagmoProblem>
void bench_pagmo(const std::string& name, const Settings& s) {
    const auto gens = static_cast<unsigned>((s.evals - s.pop) / s.pop);  // pop + gens * pop evaluations
    for (const std::string algo : {"pagmo-pso", "pagmo-sga"}) {
        for (std::int64_t seed = 1; seed <= s.seeds; ++seed) {
            const auto useed = static_cast<unsigned>(seed);
            pagmo::problem prob{PagmoProblem{static_cast<unsigned>(s.dim)}};
            // The same algorithms as ours: gbest PSO with constriction and vmax 0.2; a GA with
            // tournament 2, SBX 15 / 0.9 and polynomial mutation 20 / (1/D).
            pagmo::algorithm alg = algo == "pagmo-pso"
                                       ? pagmo::algorithm{pagmo::pso(gens, 0.7298, 2.05, 2.05, 0.2, 5u, 1u, 4u, false, useed)}
                                       : pagmo::algorithm{pagmo::sga(gens, 0.9, 15.0, 1.0 / static_cast<double>(s.dim), 20.0,
                                                                     2u, "sbx", "polynomial", "tournament", useed)};
            const auto start = Clock::now();
            pagmo::population pop{prob, static_cast<pagmo::population::size_type>(s.pop), useed};
            pop = alg.evolve(pop);
            const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
            emit({algo, name, seed, static_cast<std::int64_t>(pop.get_problem().get_fevals()), pop.champion_f()[0], ms});
        }
    }
}
#endif

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const auto n = v.size();
    return n == 0 ? 0.0 : (n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]));
}

void summarise() {
    std::map<std::string, double> bare;
    for (const auto& r : rows)
        if (r.algo == "bare") bare[r.problem] = r.wall_ms / static_cast<double>(r.fevals);
    std::map<std::string, std::vector<double>> cost_ns;
    std::map<std::string, std::map<std::string, std::vector<double>>> best;
    for (const auto& r : rows) {
        if (r.algo == "bare") continue;
        cost_ns[r.algo].push_back((r.wall_ms / static_cast<double>(r.fevals) - bare[r.problem]) * 1e6);
        best[r.algo][r.problem].push_back(r.best_f);
    }
    fmt::print(stderr, "\nframework cost per evaluation (median over problems and seeds; bare function time removed)\n");
    fmt::print(stderr, "{:<18} {:>12}   median best_f per problem\n", "algo", "ns/eval");
    for (const auto& [algo, costs] : cost_ns) {
        std::string medians;
        for (const auto& [problem, values] : best[algo]) medians += fmt::format("  {}={:.4g}", problem, median(values));
        fmt::print(stderr, "{:<18} {:>12.1f} {}\n", algo, median(costs), medians);
    }
    for (const auto& [problem, per_eval] : bare) fmt::print(stderr, "bare {:<12} {:>8.1f} ns/eval\n", problem, per_eval * 1e6);
}

}  // namespace

int main(int argc, char** argv) {
    Settings s;
    CLI::App app{"continuous benchmark: CSV of runs on stdout, summary on stderr"};
    app.add_option("--seeds", s.seeds, "seeds 1..N (default 10)")->check(CLI::Range(1, 1000));
    app.add_option("--evals", s.evals, "evaluations per run (default 100000)")->check(CLI::Range(100, 100000000));
    app.add_option("--algos", s.algos, "algorithms (default: pso pso-constriction ga nlopt:LN_SBPLX nlopt:GN_CRS2_LM)")
        ->delimiter(',');
    app.add_flag("!--no-pagmo", s.pagmo, "skip pagmo2 even when it was found at build time");
    CLI11_PARSE(app, argc, argv);
    try {
        fmt::print("algo,problem,dim,seed,fevals,best_f,wall_ms\n");
        bench_problem<Rastrigin>(s);
        bench_problem<Rosenbrock>(s);
        bench_problem<Ackley>(s);
        bench_problem<Griewank>(s);
        bench_problem<Schwefel>(s);
#ifdef PRIDE_HAVE_PAGMO
        if (s.pagmo) {
            bench_pagmo<pagmo::rastrigin>("rastrigin", s);
            bench_pagmo<pagmo::rosenbrock>("rosenbrock", s);
            bench_pagmo<pagmo::ackley>("ackley", s);
            bench_pagmo<pagmo::griewank>("griewank", s);
            bench_pagmo<pagmo::schwefel>("schwefel", s);
        }
#endif
        summarise();
    } catch (const std::exception& e) {
        fmt::print(stderr, "continuous_bench: {}\n", e.what());
        return 2;
    }
    return 0;
}

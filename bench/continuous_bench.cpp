// The continuous benchmark: each algorithm on rastrigin, rosenbrock, ackley, griewank and
// schwefel (D = 30 unless --dims names others, pagmo's boxes), population 50, exactly 100,000
// evaluations, seeds 1..10. pagmo2's counterparts of the algorithms asked for run beside them with
// the same population and budget (de/jde against pagmo's de/sade and cmaes against
// pagmo's cmaes): pso and pso-constriction -> pso, ga and ga-plus -> sga, de -> de (variant 7,
// rand/1/bin), jde -> sade (variant 7, jDE adaptation), cmaes -> cmaes. An algorithm the registry
// does not have (cmaes before it lands) is skipped with a line on stderr, and so is its pair.
//
// stdout: CSV `algo,problem,dim,seed,fevals,best_f,wall_ms`; wall time runs from population set-up
// to the end of the run. After each run a row `ALGO/bare` gives the time of the same evaluations
// done bare: the run is repeated with the same seed (runs are deterministic, so it evaluates the
// same points) while the points are recorded, and the recorded points are then evaluated again,
// timed in population-sized chunks that are already in cache. The exact points matter: the cost of
// cos() and sin() depends on the argument, so points drawn elsewhere in the box would misstate the
// function's share. Framework cost per evaluation = (wall_ms - bare wall_ms) / fevals.
// stderr: a summary of that cost per algorithm (median over problems and seeds).
#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <map>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "engine/registry.hpp"
#include "engine/run.hpp"
#include "framework/random.hpp"
#include "problems/continuous/catalog.hpp"
#include "problems/continuous/cec/functions.hpp"
#include "problems/continuous/extras.hpp"
#include "problems/continuous/functions.hpp"
#include "problems/continuous/yao.hpp"

#ifdef PRIDE_HAVE_PAGMO
#include <pagmo/algorithm.hpp>
#include <pagmo/algorithms/cmaes.hpp>
#include <pagmo/algorithms/de.hpp>
#include <pagmo/algorithms/pso.hpp>
#include <pagmo/algorithms/sade.hpp>
#include <pagmo/algorithms/sga.hpp>
#include <pagmo/population.hpp>
#include <pagmo/problem.hpp>
#include <pagmo/problems/ackley.hpp>
#include <pagmo/problems/griewank.hpp>
#include <pagmo/problems/rastrigin.hpp>
#include <pagmo/problems/rosenbrock.hpp>
#include <pagmo/problems/schwefel.hpp>
#include "bench/pagmo_recording.hpp"
#endif

namespace {

using namespace pride;
using namespace pride::continuous;

struct Settings {
    std::vector<std::int64_t> dims{30};  // the usual D; 10 and 100 by --dims
    std::int64_t pop = 50;
    std::int64_t evals = 100000;
    std::int64_t seeds = 10;
    std::vector<std::string> algos{
        "pso", "pso-constriction", "ga", "ga-plus", "lso", "ilso", "nlopt:LN_SBPLX", "nlopt:GN_CRS2_LM"};
    bool pagmo = true;
};

struct Row {
    std::string algo, problem;
    std::int64_t dim, seed, fevals;
    double best_f, wall_ms;
};

std::vector<Row> rows;

void emit(Row r) {
    fmt::print("{},{},{},{},{},{},{:.3f}\n", r.algo, r.problem, r.dim, r.seed, r.fevals,
               std::isnan(r.best_f) ? std::string() : fmt::format("{:.17g}", r.best_f), r.wall_ms);
    std::fflush(stdout);
    rows.push_back(std::move(r));
}

/// The time, in ms, of evaluating `points` (concatenated, `dim` each) bare, in chunks of `chunk`
/// points: each chunk is read once untimed so that the timing sees it in cache, as the algorithm's
/// own evaluations did.
template <class F>
double bare_ms(F f, const std::vector<double>& points, std::size_t dim, std::size_t chunk) {
    double total = 0.0, sink = 0.0;
    const std::size_t n = points.size() / dim;
    for (std::size_t first = 0; first < n; first += chunk) {
        const std::size_t last = std::min(n, first + chunk);
        for (std::size_t k = first * dim; k < last * dim; ++k) sink += points[k];  // warm the cache
        const auto start = Clock::now();
        for (std::size_t j = first; j < last; ++j) {
            // The barrier keeps each evaluation inside the timed region, as Google Benchmark's
            // DoNotOptimize does.
            double v = f.evaluate(std::span<const double>(points.data() + j * dim, dim));
            asm volatile("" : "+x"(v) : : "memory");
            sink += v;
        }
        total += std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    }
    if (sink == 42.0) std::fputs("", stderr);  // keeps the sums alive
    return total;
}

/// One run through the engine, as every front end runs: the registry's entry, the run function,
/// and inside it the fully typed loop of the algorithm on the problem.
engine::RunResult run_algorithm(const std::string& algo, const engine::Problem& problem, const Settings& s,
                                std::uint64_t seed) {
    engine::AlgorithmSpec a{algo, {}};
    if (engine::algorithms().at(algo).param("pop")) a.params.set("pop", static_cast<double>(s.pop));
    // CMA-ES's own stopping criteria off, so that its runs spend the budget as pagmo's do
    // (tolerances 0 there too).
    if (algo == "cmaes") {
        a.params.set("tol_fun", 0.0);
        a.params.set("tol_x", 0.0);
    }
    engine::Budget budget;
    budget.evaluations = s.evals;
    return engine::run(a, problem, budget, seed);
}

template <class F>
void bench_problem(const Settings& s, std::int64_t dim) {
    const F f(static_cast<std::size_t>(dim));
    const std::string name(F::info.name);
    const engine::Problem problem(engine::ContinuousSpec{name, dim});
    std::vector<double> points;
    points.reserve(static_cast<std::size_t>(s.evals * dim));
    // The same function as a callback that records every point it evaluates (for the second,
    // untimed run): the run takes the same decisions, so it evaluates the same points.
    engine::CallbackSpec recording{name,
                                   std::vector<double>(f.lower().begin(), f.lower().end()),
                                   std::vector<double>(f.upper().begin(), f.upper().end()),
                                   [&](std::span<const double> x) {
                                       points.insert(points.end(), x.begin(), x.end());
                                       return f.evaluate(x);
                                   },
                                   {}};
    const engine::Problem recorded(recording);
    for (const auto& algo : s.algos) {
        for (std::int64_t seed = 1; seed <= s.seeds; ++seed) {
            const auto useed = static_cast<std::uint64_t>(seed);
            const auto r = run_algorithm(algo, problem, s, useed);
            emit({algo, name, dim, seed, r.evaluations, r.best_f, r.wall_ms});
            points.clear();
            run_algorithm(algo, recorded, s, useed);
            emit({algo + "/bare", name, dim, seed, r.evaluations, std::nan(""),
                  bare_ms(f, points, f.dimension(), static_cast<std::size_t>(s.pop))});
        }
    }
}

#ifdef PRIDE_HAVE_PAGMO
/// pagmo's counterparts of the algorithms asked for, in the order of the pairs.
std::vector<std::string> pagmo_pairs(const std::vector<std::string>& algos) {
    auto asked = [&](std::initializer_list<const char*> names) {
        for (const char* n : names)
            if (std::find(algos.begin(), algos.end(), n) != algos.end()) return true;
        return false;
    };
    std::vector<std::string> out;
    if (asked({"pso", "pso-constriction"})) out.push_back("pagmo-pso");
    if (asked({"ga", "ga-plus"})) out.push_back("pagmo-sga");
    if (asked({"de"})) out.push_back("pagmo-de");
    if (asked({"jde"})) out.push_back("pagmo-sade");
    if (asked({"cmaes"})) out.push_back("pagmo-cmaes");
    return out;
}

template <class PagmoProblem, class F>
void bench_pagmo(const Settings& s, std::int64_t dim) {
    const F f(static_cast<std::size_t>(dim));
    const std::string name(F::info.name);
    const auto gens = static_cast<unsigned>((s.evals - s.pop) / s.pop);  // pop + gens * pop evaluations
    std::vector<double> points;
    points.reserve(static_cast<std::size_t>(s.evals * dim));
    for (const std::string& algo : pagmo_pairs(s.algos)) {
        for (std::int64_t seed = 1; seed <= s.seeds; ++seed) {
            const auto useed = static_cast<unsigned>(seed);
            // The same algorithms as ours: gbest PSO with constriction and vmax 0.2; a GA with
            // tournament 2, SBX 15 / 0.9 and polynomial mutation 20 / (1/D); DE rand/1/bin with
            // F 0.5 and CR 0.9 (pride's de defaults); jDE's self-adaptation on rand/1/bin; CMA-ES
            // (Hansen's 2006 review, no active update) clamped into the box. The tolerances are 0:
            // every run spends its budget.
            auto make_algorithm = [&] {
                if (algo == "pagmo-pso")
                    return pagmo::algorithm{pagmo::pso(gens, 0.7298, 2.05, 2.05, 0.2, 5u, 1u, 4u, false, useed)};
                if (algo == "pagmo-sga")
                    return pagmo::algorithm{pagmo::sga(gens, 0.9, 15.0, 1.0 / static_cast<double>(dim), 20.0, 2u, "sbx",
                                                       "polynomial", "tournament", useed)};
                if (algo == "pagmo-de") return pagmo::algorithm{pagmo::de(gens, 0.5, 0.9, 7u, 0.0, 0.0, useed)};
                if (algo == "pagmo-sade") return pagmo::algorithm{pagmo::sade(gens, 7u, 1u, 0.0, 0.0, false, useed)};
                // sigma0 0.3 of the box's width (pagmo scales D by the width; pride's cmaes default).
                return pagmo::algorithm{pagmo::cmaes(gens, -1, -1, -1, -1, 0.3, 0.0, 0.0, false, true, useed)};
            };
            auto run = [&](pagmo::problem prob) {
                pagmo::algorithm alg = make_algorithm();
                const auto start = Clock::now();
                pagmo::population pop{std::move(prob), static_cast<pagmo::population::size_type>(s.pop), useed};
                pop = alg.evolve(pop);
                const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
                return std::make_tuple(ms, static_cast<std::int64_t>(pop.get_problem().get_fevals()),
                                       pop.champion_f()[0]);
            };
            const auto [ms, fevals, best] = run(pagmo::problem{PagmoProblem{static_cast<unsigned>(dim)}});
            emit({algo, name, dim, seed, fevals, best, ms});
            points.clear();
            run(pagmo::problem{
                pride::bench::PagmoRecording<PagmoProblem>{PagmoProblem{static_cast<unsigned>(dim)}, &points}});
            emit({algo + "/bare", name, dim, seed, fevals, std::nan(""),
                  bare_ms(f, points, f.dimension(), static_cast<std::size_t>(s.pop))});
        }
    }
}
#endif

// --cost: what one evaluation costs by each route, ns per evaluation, population 50 in cache:
// the typed class called directly (the typed hot loop's baseline), the catalog's Function point by
// point (one dispatch per evaluation) and by batch (one dispatch per population; the function's
// batch form where it has one), for instance 0 and for instance 1 (shift and rotation: one
// matrix-vector product more). The best of 7 timings of about 20 ms each.
constexpr Eigen::Index kCostPopulation = 50;

template <class Pass>
double best_ns(Pass&& pass) {
    // Passes enough for about 20 ms per timing (at least one), found from one timed pass.
    auto start = Clock::now();
    pass();
    const double one = std::chrono::duration<double, std::nano>(Clock::now() - start).count();
    const long passes = std::max(1L, static_cast<long>(2e7 / std::max(one, 1.0)));
    double best = 1e300;
    for (int r = 0; r < 7; ++r) {
        start = Clock::now();
        for (long k = 0; k < passes; ++k) pass();
        const double ns = std::chrono::duration<double, std::nano>(Clock::now() - start).count();
        best = std::min(best, ns / static_cast<double>(passes * kCostPopulation));
    }
    return best;
}

Matrix uniform_points(std::span<const double> lo, std::span<const double> hi, std::uint64_t seed) {
    Rng rng(seed);
    Matrix x(static_cast<Eigen::Index>(lo.size()), kCostPopulation);
    for (Eigen::Index j = 0; j < x.cols(); ++j)
        for (Eigen::Index i = 0; i < x.rows(); ++i)
            x(i, j) = rng.uniform(lo[static_cast<std::size_t>(i)], hi[static_cast<std::size_t>(i)]);
    return x;
}

/// The catalog's two routes on the points x: Function::evaluate point by point, and
/// Function::evaluate_batch on them all; ns per evaluation.
std::pair<double, double> catalog_routes_ns(continuous::Function& f, const Matrix& x) {
    std::vector<double> values(static_cast<std::size_t>(x.cols()));
    double sink = 0.0;
    const double scalar = best_ns([&] {
        for (Eigen::Index j = 0; j < x.cols(); ++j) {
            double v = f.evaluate(column(x, j));
            asm volatile("" : "+x"(v) : : "memory");
            sink += v;
        }
    });
    const double batch = best_ns([&] {
        f.evaluate_batch(x, values);
        asm volatile("" : : "r"(values.data()) : "memory");
        sink += values[0];
    });
    if (sink == 42.0) std::fputs("", stderr);
    return {scalar, batch};
}

/// One CSV row per (function, D, instance): typed_ns (instance 0 with a typed class only),
/// scalar_ns, batch_ns.
template <class Typed = void>
void cost_row(const std::string& name, std::int64_t dim) {
    for (const std::int64_t instance : {0, 1}) {
        auto f = continuous::make_function(name, dim, name.starts_with("bbob") ? instance + 1 : instance);
        const Matrix x = uniform_points(f.lower(), f.upper(), 7);
        double sink = 0.0;
        std::string typed = "";
        if constexpr (!std::is_void_v<Typed>) {
            if (instance == 0) {
                Typed t(static_cast<std::size_t>(dim));
                typed = fmt::format("{:.2f}", best_ns([&] {
                                        for (Eigen::Index j = 0; j < x.cols(); ++j) {
                                            double v = t.evaluate(column(x, j));
                                            asm volatile("" : "+x"(v) : : "memory");
                                            sink += v;
                                        }
                                    }));
            }
        }
        const auto [scalar, batch] = catalog_routes_ns(f, x);
        fmt::print("{},{},{},{},{:.2f},{:.2f}\n", name, dim, f.instance(), typed, scalar, batch);
        if (sink == 42.0) std::fputs("", stderr);
    }
}

void evaluation_cost() {
    fmt::print("function,dim,instance,typed_ns,scalar_ns,batch_ns\n");
    for (const std::int64_t dim : {10, 40}) {
        cost_row<Sphere>("sphere", dim);
        cost_row<Ellipsoid>("ellipsoid", dim);
        cost_row<Schwefel221>("schwefel-2.21", dim);
        cost_row<Rastrigin>("rastrigin", dim);
        cost_row<Rosenbrock>("rosenbrock", dim);
        cost_row("bbob-f1", dim);
        cost_row("bbob-f10", dim);
        cost_row("bbob-f15", dim);
    }
}

// --cost-cec: the same routes for every CEC function and dimension (problems/continuous/cec/), on
// the official data the environment names (PRIDE_CEC2017_DATA, PRIDE_CEC2022_DATA); a suite
// without its data is skipped with a line on stderr. D = 2 is left out (not a competition size).
void cec_cost() {
    fmt::print("function,dim,scalar_ns,batch_ns\n");
    for (const auto suite : {continuous::cec::Suite::y2017, continuous::cec::Suite::y2022}) {
        const std::string variable(continuous::cec::data_variable(suite));
        if (!std::getenv(variable.c_str())) {
            fmt::print(stderr, "{}: skipped, {} is not set\n", continuous::cec::suite_name(suite), variable);
            continue;
        }
        for (int k = 1; k <= continuous::cec::size(suite); ++k)
            for (const std::size_t dim : continuous::cec::dimensions(suite, k)) {
                if (dim == 2) continue;
                auto f =
                    continuous::make_function(continuous::cec::info(suite, k).name, static_cast<std::int64_t>(dim));
                const auto [scalar, batch] = catalog_routes_ns(f, uniform_points(f.lower(), f.upper(), 7));
                fmt::print("{},{},{:.1f},{:.1f}\n", f.name(), dim, scalar, batch);
            }
    }
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const auto n = v.size();
    return n == 0 ? 0.0 : (n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]));
}

void summarise() {
    // Each run row is followed by its bare row. Grouped by (algo, D).
    using Key = std::pair<std::string, std::int64_t>;
    std::map<Key, std::vector<double>> cost_ns;
    std::map<Key, std::map<std::string, std::vector<double>>> best;
    std::map<Key, std::vector<double>> bare_ns;
    for (std::size_t k = 0; k + 1 < rows.size(); k += 2) {
        const Row& run = rows[k];
        const Row& bare = rows[k + 1];
        const auto evals = static_cast<double>(run.fevals);
        cost_ns[{run.algo, run.dim}].push_back((run.wall_ms - bare.wall_ms) / evals * 1e6);
        bare_ns[{run.problem, run.dim}].push_back(bare.wall_ms / evals * 1e6);
        best[{run.algo, run.dim}][run.problem].push_back(run.best_f);
    }
    fmt::print(stderr,
               "\nframework cost per evaluation (median over problems and seeds; bare function time removed)\n");
    fmt::print(stderr, "{:<18} {:>4} {:>12}   median best_f per problem\n", "algo", "D", "ns/eval");
    for (const auto& [key, costs] : cost_ns) {
        std::string medians;
        for (const auto& [problem, values] : best[key]) medians += fmt::format("  {}={:.4g}", problem, median(values));
        fmt::print(stderr, "{:<18} {:>4} {:>12.1f} {}\n", key.first, key.second, median(costs), medians);
    }
    for (const auto& [key, ns] : bare_ns)
        fmt::print(stderr, "bare {:<12} D={:<4} {:>8.1f} ns/eval (median over the points of every run)\n", key.first,
                   key.second, median(ns));
}

}  // namespace

int main(int argc, char** argv) {
    Settings s;
    CLI::App app{"continuous benchmark: CSV of runs on stdout, summary on stderr"};
    app.add_option("--seeds", s.seeds, "seeds 1..N (default 10)")->check(CLI::Range(1, 1000));
    app.add_option("--evals", s.evals, "evaluations per run (default 100000)")->check(CLI::Range(100, 100000000));
    app.add_option("--algos", s.algos,
                   "algorithms (default: pso pso-constriction ga ga-plus lso ilso nlopt:LN_SBPLX nlopt:GN_CRS2_LM)")
        ->delimiter(',');
    app.add_option("--dims", s.dims, "dimensions (default 30: 10,30,100)")
        ->delimiter(',')
        ->check(CLI::Range(1, 100000));
    app.add_flag("!--no-pagmo", s.pagmo,
                 "skip pagmo2 even when it was found at build time (else each algorithm's pagmo counterpart runs: "
                 "pso, sga, de, sade, cmaes)");
    bool cost = false;
    app.add_flag("--cost", cost,
                 "instead: the cost of one evaluation by each route (typed, scalar, batch), D 10 and 40");
    bool cec = false;
    app.add_flag("--cost-cec", cec,
                 "instead: the cost of one evaluation of every CEC 2017 and 2022 function (official data from "
                 "PRIDE_CEC2017_DATA, PRIDE_CEC2022_DATA)");
    CLI11_PARSE(app, argc, argv);
    try {
        if (cost) {
            evaluation_cost();
            return 0;
        }
        if (cec) {
            cec_cost();
            return 0;
        }
        // An algorithm the registry lacks (cmaes before it lands) is skipped, with its pagmo pair.
        std::erase_if(s.algos, [](const std::string& algo) {
            const bool missing = engine::algorithms().find(algo) == nullptr;
            if (missing) fmt::print(stderr, "{}: skipped, not in the registry (nor its pagmo pair)\n", algo);
            return missing;
        });
        fmt::print("algo,problem,dim,seed,fevals,best_f,wall_ms\n");
        for (const std::int64_t dim : s.dims) {
            bench_problem<Rastrigin>(s, dim);
            bench_problem<Rosenbrock>(s, dim);
            bench_problem<Ackley>(s, dim);
            bench_problem<Griewank>(s, dim);
            bench_problem<Schwefel>(s, dim);
        }
#ifdef PRIDE_HAVE_PAGMO
        if (s.pagmo)
            for (const std::int64_t dim : s.dims) {
                bench_pagmo<pagmo::rastrigin, Rastrigin>(s, dim);
                bench_pagmo<pagmo::rosenbrock, Rosenbrock>(s, dim);
                bench_pagmo<pagmo::ackley, Ackley>(s, dim);
                bench_pagmo<pagmo::griewank, Griewank>(s, dim);
                bench_pagmo<pagmo::schwefel, Schwefel>(s, dim);
            }
#endif
        summarise();
    } catch (const std::exception& e) {
        fmt::print(stderr, "continuous_bench: {}\n", e.what());
        return 2;
    }
    return 0;
}

// The multi-objective benchmark of issue 28: pride's NSGA-II and MOEA/D beside pagmo2's nsga2 and
// moead (when pagmo was found at build time), and pride's SMS-EMOA and NSGA-III (M = 3) beside
// them, on ZDT1-4, 6 (n = 30, 30, 30, 10, 10) and DTLZ1, 2 (M = 3, the papers' k). The pairs share
// their settings: NSGA-II population 100, SBX eta_c 20 with p_c 0.9, polynomial mutation eta_m 20
// with p_m 1/n (Deb et al. 2002, sec. V); MOEA/D pagmo's defaults (DE form, T 20, delta 0.9, n_r 2,
// Tchebycheff, lattice weights: 100 subproblems at M = 2, 91 at M = 3). Exactly --evals
// evaluations for pride (pagmo: its population + gens x population, up to --evals), seeds
// 1..--seeds. Each side runs on its own implementation of the problem.
//
// stdout: CSV `algo,problem,seed,fevals,wall_ms,bare_ms,points,hv_ratio,igd_plus`. wall_ms runs
// from the population's set-up to the end of the run; bare_ms is the time of the same evaluations
// done bare (the run repeated with the same seed while the points are recorded, the points then
// evaluated again in population-sized chunks), so framework cost = (wall_ms - bare_ms) / fevals.
// Quality, of the run's final non-dominated points: hv_ratio = HV(result) / HV(reference front),
// both with the reference point 1.1 x the reference front's largest value per objective (the front's
// ideal point is 0 on these problems); igd_plus = IGD+ to the reference front (Ishibuchi et al.
// 2015). The reference fronts: problems/multiobjective/fronts.hpp, 1000 points (DTLZ: the lattice
// of at most 1000 points).
// stderr: per (algo, problem), the medians over the seeds.
#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/moead.hpp"
#include "algorithms/nsga2.hpp"
#include "algorithms/nsga3.hpp"
#include "algorithms/smsemoa.hpp"
#include "framework/pareto/dominance.hpp"
#include "framework/pareto/hypervolume.hpp"
#include "framework/pareto/indicators.hpp"
#include "framework/pareto/reference_directions.hpp"
#include "problems/multiobjective/dtlz.hpp"
#include "problems/multiobjective/fronts.hpp"
#include "problems/multiobjective/zdt.hpp"

#ifdef PRIDE_HAVE_PAGMO
#include <pagmo/algorithm.hpp>
#include <pagmo/algorithms/moead.hpp>
#include <pagmo/algorithms/nsga2.hpp>
#include <pagmo/population.hpp>
#include <pagmo/problem.hpp>
#include <pagmo/problems/dtlz.hpp>
#include <pagmo/problems/zdt.hpp>
#include <pagmo/utils/multi_objective.hpp>
#endif

namespace {

using namespace pride;
using Clock = std::chrono::steady_clock;
constexpr std::int64_t kPopulation = 100;

struct Settings {
    std::int64_t evals = 25000;
    std::int64_t seeds = 10;
    bool pagmo = true;
    std::vector<std::string> algos{"nsga2", "moead", "smsemoa", "nsga3"};
    bool wanted(const std::string& a) const { return std::find(algos.begin(), algos.end(), a) != algos.end(); }
};

struct Row {
    std::string algo, problem;
    std::int64_t seed = 0, fevals = 0;
    double wall_ms = 0.0, bare_ms = 0.0;
    Eigen::Index points = 0;
    double hv_ratio = 0.0, igd_plus = 0.0;
};

std::vector<Row> rows;

/// The reference front of a problem and its hypervolume, with the bench's reference point.
struct Reference {
    Matrix front;
    std::vector<double> point;
    double hv = 0.0;
};

Reference reference_of(const Matrix& front) {
    Reference r{front, std::vector<double>(static_cast<std::size_t>(front.rows())), 0.0};
    for (Eigen::Index i = 0; i < front.rows(); ++i)
        r.point[static_cast<std::size_t>(i)] = 1.1 * front.row(i).maxCoeff();
    r.hv = pareto::hypervolume(front, r.point);
    return r;
}

/// A problem that records the points it evaluates (the second, untimed run).
template <class P>
struct Recording {
    P inner;
    std::vector<double>* points = nullptr;
    std::size_t dimension() const { return inner.dimension(); }
    std::span<const double> lower() const { return inner.lower(); }
    std::span<const double> upper() const { return inner.upper(); }
    std::size_t objectives() const { return inner.objectives(); }
    void evaluate(std::span<const double> x, std::span<double> f) {
        points->insert(points->end(), x.begin(), x.end());
        inner.evaluate(x, f);
    }
};

/// The time, in ms, of evaluating `points` (`dim` each) with `evaluate`, in chunks of a population
/// read once untimed first (in cache, as the run's own evaluations were).
template <class Evaluate>
double bare_ms(Evaluate evaluate, const std::vector<double>& points, std::size_t dim) {
    double total = 0.0, sink = 0.0;
    const std::size_t n = points.size() / dim, chunk = static_cast<std::size_t>(kPopulation);
    for (std::size_t first = 0; first < n; first += chunk) {
        const std::size_t last = std::min(n, first + chunk);
        for (std::size_t k = first * dim; k < last * dim; ++k) sink += points[k];
        const auto start = Clock::now();
        for (std::size_t j = first; j < last; ++j) {
            double v = evaluate(points.data() + j * dim);
            asm volatile("" : "+x"(v) : : "memory");
            sink += v;
        }
        total += std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    }
    if (sink == 42.0) std::fputs("", stderr);
    return total;
}

/// Quality of a set of objective vectors (columns) against the reference front.
std::pair<double, double> quality(const Matrix& f, const Reference& ref) {
    return {pareto::hypervolume(f, ref.point) / ref.hv, pareto::igd_plus(f, ref.front)};
}

template <class A, class P>
void bench_pride(const Settings& s, const std::string& algo, const A& algorithm, const std::string& name,
                 const P& problem, const Reference& ref) {
    Termination t;
    t.max_evaluations = s.evals;
    std::vector<double> points;
    for (std::int64_t seed = 1; seed <= s.seeds; ++seed) {
        const auto start = Clock::now();
        const MultiObjectiveResult r = algorithm.run(problem, t, static_cast<std::uint64_t>(seed));
        const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
        points.clear();
        (void)algorithm.run(Recording<P>{problem, &points}, t, static_cast<std::uint64_t>(seed));
        P copy = problem;
        std::vector<double> fx(problem.objectives());
        const double bare = bare_ms(
            [&](const double* x) {
                copy.evaluate(std::span<const double>(x, problem.dimension()), std::span<double>(fx));
                return fx[0] + fx.back();
            },
            points, problem.dimension());
        const auto [hv, igd] = quality(r.f, ref);
        rows.push_back({algo, name, seed, r.evaluations, ms, bare, r.f.cols(), hv, igd});
    }
}

/// Every pride algorithm on one problem: NSGA-II, MOEA/D (its DE form, pagmo's defaults),
/// SMS-EMOA, and at M = 3 NSGA-III on the lattice H = 12 (91 directions, N = 92).
template <class P>
void bench_pride_all(const Settings& s, const std::string& name, const P& problem, const Reference& ref) {
    if (s.wanted("nsga2")) bench_pride(s, "nsga2", Nsga2<>{}, name, problem, ref);
    if (s.wanted("moead")) bench_pride(s, "moead", Moead<>{}, name, problem, ref);
    if (s.wanted("smsemoa")) bench_pride(s, "smsemoa", SmsEmoa<>{}, name, problem, ref);
    if (s.wanted("nsga3") && problem.objectives() == 3)
        bench_pride(s, "nsga3", make_nsga3(pareto::simplex_lattice(3, 12)), name, problem, ref);
}

#ifdef PRIDE_HAVE_PAGMO
template <class PagmoProblem>
struct PagmoRecording {
    PagmoProblem inner;
    std::vector<double>* points = nullptr;
    pagmo::vector_double fitness(const pagmo::vector_double& x) const {
        points->insert(points->end(), x.begin(), x.end());
        return inner.fitness(x);
    }
    std::pair<pagmo::vector_double, pagmo::vector_double> get_bounds() const { return inner.get_bounds(); }
    pagmo::vector_double::size_type get_nobj() const { return inner.get_nobj(); }
};

/// pagmo's nsga2 (population 100) or moead (grid weights: its population is the lattice's size,
/// 100 at M = 2, 91 at M = 3, as pride's moead takes) with pride's settings, the same budget.
template <class PagmoProblem>
void bench_pagmo(const Settings& s, const std::string& algo, const std::string& name, const PagmoProblem& problem,
                 std::size_t dim, const Reference& ref) {
    const std::int64_t pop = algo == "pagmo-moead" && problem.get_nobj() == 3 ? 91 : kPopulation;
    const auto gens = static_cast<unsigned>((s.evals - pop) / pop);
    std::vector<double> points;
    for (std::int64_t seed = 1; seed <= s.seeds; ++seed) {
        const auto useed = static_cast<unsigned>(seed);
        auto run = [&](pagmo::problem prob) {
            pagmo::algorithm alg =
                algo == "pagmo-moead"
                    ? pagmo::algorithm{pagmo::moead(gens, "grid", "tchebycheff", 20u, 1.0, 0.5, 20.0, 0.9, 2u, true,
                                                    useed)}
                    : pagmo::algorithm{pagmo::nsga2(gens, 0.9, 20.0, 1.0 / static_cast<double>(dim), 20.0, useed)};
            const auto start = Clock::now();
            pagmo::population population{std::move(prob), static_cast<pagmo::population::size_type>(pop), useed};
            population = alg.evolve(population);
            const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
            return std::make_pair(ms, population);
        };
        const auto [ms, population] = run(pagmo::problem{problem});
        points.clear();
        (void)run(pagmo::problem{PagmoRecording<PagmoProblem>{problem, &points}});
        const double bare = bare_ms(
            [&](const double* x) {
                const auto f = problem.fitness(pagmo::vector_double(x, x + dim));
                return f[0] + f.back();
            },
            points, dim);
        const auto fs = population.get_f();
        const auto front = std::get<0>(pagmo::fast_non_dominated_sorting(fs))[0];
        Matrix f(static_cast<Eigen::Index>(fs[0].size()), static_cast<Eigen::Index>(front.size()));
        for (std::size_t k = 0; k < front.size(); ++k)
            for (std::size_t i = 0; i < fs[0].size(); ++i)
                f(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)) = fs[front[k]][i];
        const auto [hv, igd] = quality(f, ref);
        rows.push_back({algo, name, seed, static_cast<std::int64_t>(population.get_problem().get_fevals()), ms, bare,
                        f.cols(), hv, igd});
    }
}

template <class PagmoProblem>
void bench_pagmo_all(const Settings& s, const std::string& name, const PagmoProblem& problem, std::size_t dim,
                     const Reference& ref) {
    if (s.wanted("nsga2")) bench_pagmo(s, "pagmo-nsga2", name, problem, dim, ref);
    if (s.wanted("moead")) bench_pagmo(s, "pagmo-moead", name, problem, dim, ref);
}
#endif

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

int main(int argc, char** argv) {
    Settings s;
    CLI::App app{"multi-objective benchmark: CSV of runs on stdout, medians on stderr"};
    app.add_option("--evals", s.evals, "evaluations per run (default 25000)")->check(CLI::Range(200, 100'000'000));
    app.add_option("--seeds", s.seeds, "seeds 1..N (default 10)")->check(CLI::Range(1, 1000));
    app.add_flag("--no-pagmo{false}", s.pagmo, "skip pagmo2 even when it was found at build time");
    app.add_option("--algos", s.algos,
                   "algorithms (default: nsga2 moead smsemoa nsga3; pagmo's nsga2, moead beside theirs)")
        ->delimiter(',')
        ->check(CLI::IsMember({"nsga2", "moead", "smsemoa", "nsga3"}));
    CLI11_PARSE(app, argc, argv);

    using namespace pride::multiobjective;
    const auto two = [](std::string_view name) { return reference_of(reference_front(name, 2, 1000)); };
    const auto three = [](std::string_view name) { return reference_of(reference_front(name, 3, 1000)); };
    const Reference z1 = two("zdt1"), z2 = two("zdt2"), z3 = two("zdt3"), z4 = two("zdt4"), z6 = two("zdt6");
    const Reference d1 = three("dtlz1"), d2 = three("dtlz2");
    bench_pride_all(s, "zdt1", Zdt1(30), z1);
    bench_pride_all(s, "zdt2", Zdt2(30), z2);
    bench_pride_all(s, "zdt3", Zdt3(30), z3);
    bench_pride_all(s, "zdt4", Zdt4(10), z4);
    bench_pride_all(s, "zdt6", Zdt6(10), z6);
    bench_pride_all(s, "dtlz1", Dtlz1(3), d1);
    bench_pride_all(s, "dtlz2", Dtlz2(3), d2);
#ifdef PRIDE_HAVE_PAGMO
    if (s.pagmo) {
        bench_pagmo_all(s, "zdt1", pagmo::zdt(1, 30), 30, z1);
        bench_pagmo_all(s, "zdt2", pagmo::zdt(2, 30), 30, z2);
        bench_pagmo_all(s, "zdt3", pagmo::zdt(3, 30), 30, z3);
        bench_pagmo_all(s, "zdt4", pagmo::zdt(4, 10), 10, z4);
        bench_pagmo_all(s, "zdt6", pagmo::zdt(6, 10), 10, z6);
        bench_pagmo_all(s, "dtlz1", pagmo::dtlz(1, 7, 3), 7, d1);
        bench_pagmo_all(s, "dtlz2", pagmo::dtlz(2, 12, 3), 12, d2);
    }
#endif
    fmt::print("algo,problem,seed,fevals,wall_ms,bare_ms,points,hv_ratio,igd_plus\n");
    std::map<std::pair<std::string, std::string>, std::vector<const Row*>> groups;
    for (const Row& r : rows) {
        fmt::print("{},{},{},{},{:.3f},{:.3f},{},{:.6f},{:.6g}\n", r.algo, r.problem, r.seed, r.fevals, r.wall_ms,
                   r.bare_ms, r.points, r.hv_ratio, r.igd_plus);
        groups[{r.problem, r.algo}].push_back(&r);
    }
    fmt::print(stderr, "{:<8} {:<12} {:>12} {:>10} {:>10} {:>8}\n", "problem", "algo", "framework ns", "HV ratio",
               "IGD+", "points");
    for (const auto& [key, group] : groups) {
        std::vector<double> ns, hv, igd, pts;
        for (const Row* r : group) {
            ns.push_back((r->wall_ms - r->bare_ms) / static_cast<double>(r->fevals) * 1e6);
            hv.push_back(r->hv_ratio);
            igd.push_back(r->igd_plus);
            pts.push_back(static_cast<double>(r->points));
        }
        fmt::print(stderr, "{:<8} {:<12} {:>12.0f} {:>10.4f} {:>10.4g} {:>8.0f}\n", key.first, key.second, median(ns),
                   median(hv), median(igd), median(pts));
    }
    return 0;
}

#pragma once
// pride's multi-objective algorithms for bench/mo_bench (mo_bench.cpp says what is measured): the
// runner, included by mo_bench_zdt.cpp and mo_bench_dtlz.cpp, one translation unit per suite so that
// each compiles within the project's bound.
#include <span>
#include <string>
#include <vector>

#include "algorithms/moead.hpp"
#include "algorithms/nsga2.hpp"
#include "algorithms/nsga3.hpp"
#include "algorithms/smsemoa.hpp"
#include "bench/mo_bench.hpp"
#include "framework/pareto/reference_directions.hpp"

namespace pride::mo_bench {

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

}  // namespace pride::mo_bench

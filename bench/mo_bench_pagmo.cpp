// pagmo2's nsga2 and moead for bench/mo_bench (see mo_bench.cpp), with pride's settings.
#include <pagmo/algorithm.hpp>
#include <pagmo/algorithms/moead.hpp>
#include <pagmo/algorithms/nsga2.hpp>
#include <pagmo/population.hpp>
#include <pagmo/problem.hpp>
#include <pagmo/problems/dtlz.hpp>
#include <pagmo/problems/zdt.hpp>
#include <pagmo/utils/multi_objective.hpp>

#include <string>
#include <tuple>
#include <vector>

#include "bench/mo_bench.hpp"
#include "bench/pagmo_recording.hpp"

namespace pride::mo_bench {
namespace {

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
        (void)run(pagmo::problem{bench::PagmoRecording<PagmoProblem>{problem, &points}});
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

}  // namespace

void bench_pagmo_all_problems(const Settings& s, const References& r) {
    bench_pagmo_all(s, "zdt1", pagmo::zdt(1, 30), 30, r.zdt1);
    bench_pagmo_all(s, "zdt2", pagmo::zdt(2, 30), 30, r.zdt2);
    bench_pagmo_all(s, "zdt3", pagmo::zdt(3, 30), 30, r.zdt3);
    bench_pagmo_all(s, "zdt4", pagmo::zdt(4, 10), 10, r.zdt4);
    bench_pagmo_all(s, "zdt6", pagmo::zdt(6, 10), 10, r.zdt6);
    bench_pagmo_all(s, "dtlz1", pagmo::dtlz(1, 7, 3), 7, r.dtlz1);
    bench_pagmo_all(s, "dtlz2", pagmo::dtlz(2, 12, 3), 12, r.dtlz2);
}

}  // namespace pride::mo_bench

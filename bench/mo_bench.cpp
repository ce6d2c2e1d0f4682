// The multi-objective benchmark: pride's NSGA-II and MOEA/D beside pagmo2's nsga2 and
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
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "bench/mo_bench.hpp"
#include "problems/multiobjective/fronts.hpp"

namespace {

using namespace pride::mo_bench;

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

    using pride::multiobjective::reference_front;
    const auto two = [](std::string_view name) { return reference_of(reference_front(name, 2, 1000)); };
    const auto three = [](std::string_view name) { return reference_of(reference_front(name, 3, 1000)); };
    const References refs{two("zdt1"), two("zdt2"),    two("zdt3"),   two("zdt4"),
                          two("zdt6"), three("dtlz1"), three("dtlz2")};
    bench_pride_zdt(s, refs);
    bench_pride_dtlz(s, refs);
#ifdef PRIDE_HAVE_PAGMO
    if (s.pagmo) bench_pagmo_all_problems(s, refs);
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
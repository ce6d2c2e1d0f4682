// The real-coded GA's operators alone, and the typed GA and PSO loops on a cheap function (issue
// 15): where continuous_bench subtracts a function's time from a whole run (and is noisy by the
// function's share), this times what the framework itself does, each figure the least of many
// repetitions. Prints CSV `what,dim,ns` (per call for an operator, per evaluation for a run).
//   sbx: SbxCrossover::Prepared::cross (eta 15, every pair crossed) on two parents of --dim (30)
//   polynomial-mutation: PolynomialMutation (eta 20, pm 1/D) on one child
//   pso / ga / iaga / icga / woa / hs / hswoa on sphere: the typed Pso<>, Ga<> and the Ga of iaga
//     (adaptive pc and pm) and icga (the catastrophe hook), Woa<>, HarmonySearch<> and the Woa of
//     hswoa (balance factor and harmony second step), registry defaults, for 100,000 evaluations:
//     their ratios to pso's figure are the measure of "within 2x of PSO", with sphere's few ns included
#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <vector>

#include "algorithms/ga.hpp"
#include "algorithms/hs.hpp"
#include "algorithms/pso.hpp"
#include "algorithms/woa.hpp"
#include "bench/best_time.hpp"
#include "problems/continuous/functions.hpp"

namespace {

using namespace pride;

using pride::bench::least_ns;

/// 64 random points in [-5.12, 5.12]^dim (the operators' parents).
std::vector<std::vector<double>> parents(std::size_t dim, Rng& rng) {
    std::vector<std::vector<double>> pool(64, std::vector<double>(dim));
    for (auto& x : pool)
        for (double& v : x) v = rng.uniform(-5.12, 5.12);
    return pool;
}

}  // namespace

int main(int argc, char** argv) {
    std::size_t dim = 30;
    int rounds = 200;
    CLI::App app{"the GA's operators, and the typed GA and PSO on sphere: CSV what,dim,ns"};
    app.add_option("--dim", dim, "coordinates (default 30)")->check(CLI::Range(1, 10000));
    app.add_option("--rounds", rounds, "repetitions; the least is printed (default 200)")->check(CLI::Range(1, 100000));
    CLI11_PARSE(app, argc, argv);

    Rng rng(7);
    const std::vector<double> lo(dim, -5.12), hi(dim, 5.12);
    const auto pool = parents(dim, rng);
    std::vector<double> a(dim), b(dim);
    double sink = 0.0;
    constexpr int kCalls = 2000;
    fmt::print("what,dim,ns\n");

    const auto sbx = SbxCrossover{15.0, 1.0}.prepare(dim);
    fmt::print("sbx,{},{:.1f}\n", dim, least_ns(rounds, kCalls, [&] {
                   for (int k = 0; k < kCalls; ++k) {
                       a = pool[static_cast<std::size_t>(k) % 64];
                       b = pool[static_cast<std::size_t>(k * 7 + 3) % 64];
                       sbx.cross(a, b, lo, hi, rng);
                       sink += a[0];
                   }
               }));
    const auto mutation = PolynomialMutation{}.prepare(dim);
    fmt::print("polynomial-mutation,{},{:.1f}\n", dim, least_ns(rounds, kCalls, [&] {
                   for (int k = 0; k < kCalls; ++k) {
                       a = pool[static_cast<std::size_t>(k) % 64];
                       mutation(a, lo, hi, rng);
                       sink += a[0];
                   }
               }));
    // Whole runs: fewer repetitions (each is 100,000 evaluations); seeds 1-3 in turn.
    const int runs = std::max(1, rounds / 13);
    constexpr std::int64_t kEvals = 100000;
    std::uint64_t seed = 0;
    const auto on_sphere = [&](const char* name, const auto& algorithm) {
        fmt::print("{} on sphere,{},{:.1f}\n", name, dim, least_ns(runs, kEvals, [&] {
                       sink += algorithm.run(continuous::Sphere(dim), max_evaluations(kEvals), 1 + seed++ % 3).best_f;
                   }));
    };
    on_sphere("pso", Pso<>{});
    on_sphere("ga", Ga<>{});
    on_sphere("iaga", Ga<TournamentSelection, AdaptiveSbxCrossover, AdaptivePolynomialMutation>{});
    on_sphere("icga", Ga<TournamentSelection, SbxCrossover, PolynomialMutation, Clamp, UniformInit, ElitistReplacement,
                         CatastropheHook>{});
    on_sphere("woa", Woa<>{});
    on_sphere("hs", HarmonySearch<>{});
    on_sphere("hswoa", Woa<PerWhaleDraws, BalanceMode, HarmonySecondStep>{});
    if (sink == 42.0) fmt::print(stderr, "\n");  // keeps the work
    return 0;
}

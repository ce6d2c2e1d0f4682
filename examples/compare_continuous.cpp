// The main job of the README: PSO, GA, LSO, ILSO and two NLopt algorithms compared on rastrigin,
// shifted rastrigin and shifted rosenbrock (D = 30, 100,000 evaluations, seeds 1..5), as a table.
// Rastrigin with and without the shift shows what docs/results/lso-continuous.md explains: the
// lion swarm's moves scale positions, so its results depend on where the optimum lies. It uses the library
// directly, as a researcher's own experiment program would: every run is a fully typed template
// instantiation (algorithm x problem), so the figures are those of the real hot loop.
#include <fmt/format.h>

#include <algorithm>
#include <numeric>
#include <string>
#include <vector>

#include "algorithms/ga.hpp"
#include "algorithms/lso.hpp"
#include "algorithms/nlopt.hpp"
#include "algorithms/pso.hpp"
#include "problems/continuous/functions.hpp"
#include "problems/continuous/shifted.hpp"

namespace {

using namespace pride;
using namespace pride::continuous;

constexpr std::size_t kDim = 30;
constexpr std::int64_t kEvaluations = 100000;
constexpr std::uint64_t kSeeds = 5;

struct Summary {
    std::string problem, algorithm;
    std::vector<double> best;
    double wall_ms = 0.0;
    std::int64_t evaluations = 0;
};

template <class Problem, class Algorithm>
Summary compare(const Problem& problem, const Algorithm& algorithm) {
    Summary s{std::string(problem.name()), algorithm.name(), {}, 0.0, 0};
    for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) {
        const Result r = algorithm.run(problem, max_evaluations(kEvaluations), seed);
        s.best.push_back(r.best_f);
        s.wall_ms += r.wall_ms / kSeeds;
        s.evaluations += r.evaluations / static_cast<std::int64_t>(kSeeds);
    }
    std::sort(s.best.begin(), s.best.end());
    return s;
}

template <class Problem>
void compare_all(std::vector<Summary>& out) {
    const Problem problem(kDim);
    out.push_back(compare(problem, Pso<>{}));
    out.push_back(compare(problem, Ga<>{}));
    out.push_back(compare(problem, LsoAlgorithm{}));
    out.push_back(compare(problem, make_ilso()));
    out.push_back(compare(problem, Nlopt("LN_SBPLX")));
    out.push_back(compare(problem, Nlopt("GN_CRS2_LM")));
}

}  // namespace

int main() {
    std::vector<Summary> rows;
    compare_all<Rastrigin>(rows);
    compare_all<Shifted<Rastrigin>>(rows);
    compare_all<Shifted<Rosenbrock>>(rows);

    fmt::print("D = {}, {} evaluations per run, seeds 1..{}, optimum value 0 everywhere\n\n", kDim, kEvaluations,
               kSeeds);
    fmt::print("| {:<19} | {:<16} | {:>10} | {:>10} | {:>10} | {:>10} | {:>8} |\n", "problem", "algorithm", "min",
               "median", "mean", "max", "ms/run");
    fmt::print("|{:-<21}|{:-<18}|{:->12}|{:->12}|{:->12}|{:->12}|{:->10}|\n", "", "", "", "", "", "", "");
    for (const auto& s : rows) {
        const double mean = std::accumulate(s.best.begin(), s.best.end(), 0.0) / static_cast<double>(s.best.size());
        fmt::print("| {:<19} | {:<16} | {:>10.4g} | {:>10.4g} | {:>10.4g} | {:>10.4g} | {:>8.1f} |\n", s.problem,
                   s.algorithm, s.best.front(), s.best[s.best.size() / 2], mean, s.best.back(), s.wall_ms);
    }
    return 0;
}

// The main job of the README: PSO, GA, LSO, ILSO and two NLopt algorithms compared on rastrigin,
// shifted rastrigin and shifted rosenbrock (D = 30, 100,000 evaluations, seeds 1..5), as a table.
// Rastrigin with and without the shift shows what docs/results/lso-continuous.md explains: the
// lion swarm's moves scale positions, so its results depend on where the optimum lies. It uses the
// runtime library (engine/run.hpp) as a researcher's own experiment program would: problems and
// algorithms by name, with their parameters; inside each run the loop is fully typed.
#include <fmt/format.h>

#include <algorithm>
#include <numeric>
#include <string>
#include <vector>

#include "engine/run.hpp"

namespace {

namespace engine = pride::engine;

constexpr std::int64_t kDim = 30;
constexpr std::int64_t kEvaluations = 100000;
constexpr std::uint64_t kSeeds = 5;

struct Summary {
    std::string problem, algorithm;
    std::vector<double> best;
    double wall_ms = 0.0;
    std::int64_t evaluations = 0;
};

Summary compare(const std::string& problem_name, const std::string& algorithm) {
    const engine::Problem problem(engine::ContinuousSpec{problem_name, kDim});
    engine::Budget budget;
    budget.evaluations = kEvaluations;
    Summary s{problem_name, algorithm, {}, 0.0, 0};
    for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) {
        const engine::RunResult r = engine::run({algorithm, {}}, problem, budget, seed);
        s.best.push_back(r.best_f);
        s.wall_ms += r.wall_ms / kSeeds;
        s.evaluations += r.evaluations / static_cast<std::int64_t>(kSeeds);
    }
    std::sort(s.best.begin(), s.best.end());
    return s;
}

}  // namespace

int main() {
    std::vector<Summary> rows;
    for (const char* problem : {"rastrigin", "shifted-rastrigin", "shifted-rosenbrock"})
        for (const char* algorithm : {"pso", "ga", "lso", "ilso", "nlopt:LN_SBPLX", "nlopt:GN_CRS2_LM"})
            rows.push_back(compare(problem, algorithm));

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

#include "cli/algorithms.hpp"

#include <variant>

#include "cli/algorithm_factory.hpp"

namespace pride::cli {

std::vector<AlgorithmInfo> list_algorithms() {
    std::vector<AlgorithmInfo> out{
        {"pso",
         "global-best particle swarm, inertia 0.9 -> 0.4, c1 = c2 = 2, vmax 0.2 (params: pop w_start w_end c1 c2 "
         "vmax)"},
        {"pso-constriction",
         "particle swarm with Clerc-Kennedy constriction chi 0.7298, c 2.05 (params: pop chi c vmax)"},
        {"ga",
         "real-coded GA: tournament 2, SBX 15 / 0.9, polynomial mutation 20 / (1/D), elitism 1 (params: pop elitism "
         "tournament eta_c pc eta_m pm)"},
        {"ga-plus",
         "the same GA with (mu + lambda) reinsertion: best N of parents and children, as pagmo2's sga (params: pop "
         "tournament eta_c pc eta_m pm)"},
        {"lso",
         "lion swarm (file 000 eqs. 1-9): king, lionesses, cubs; N 20, beta 0.2, step r*(mean high - mean low) with r "
         "~ U(0,1) per run (params: pop beta step cub_first cub_second gamma_per_coordinate)"},
        {"ilso",
         "improved lion swarm (file 000 eqs. 10-12): LSO with inertia 0.99 -> 0.35 (quadratic), cub threshold 3/10, "
         "starting from the problem's suggestions (rough-set rule walks on grids) (params: pop beta step w_max w_min "
         "cub_first cub_second gamma_per_coordinate)"},
        {"astar", "grids only (pride path): A* with the octile heuristic, the shortest path by length"},
        {"exact", "grids only (pride path): the exact optimum of an additive objective, over (cell, last direction)"},
    };
    for (const auto& name : nlopt_derivative_free_names()) {
        const auto a = nlopt_algorithm_from_string(name.c_str());
        out.push_back({"nlopt:" + name, std::string("NLopt: ") + nlopt_algorithm_name(a) + " (params: pop restart)"});
    }
    return out;
}

ContinuousRunner make_algorithm(std::string_view name, const ParamMap& params) {
    require(name != "astar" && name != "exact", "--algo", std::string(name) + " works on grids only: use 'pride path'");
    with_algorithm(name, params, [](const auto&) { return 0; });  // validates name and parameters now
    return [name = std::string(name), params](const continuous::AnyProblem& problem, const Termination& termination,
                                              std::uint64_t seed) {
        return with_algorithm(name, params, [&](const auto& algorithm) {
            return std::visit([&](const auto& p) { return algorithm.run(p, termination, seed); }, problem);
        });
    };
}

}  // namespace pride::cli

// NLopt's derivative-free algorithms (algorithms/nlopt.hpp) as baselines: one entry per algorithm
// of this NLopt build, named nlopt:NAME with NLopt's own name.
#include "algorithms/nlopt.hpp"

#include "engine/family.hpp"

namespace pride::engine {

void register_nlopt(AlgorithmRegistry& registry) {
    for (const auto& nlopt_name : nlopt_derivative_free_names()) {
        const std::string name = "nlopt:" + nlopt_name;
        auto e = box_algorithm(
            name, "nlopt",
            std::string("NLopt: ") +
                nlopt_algorithm_name(static_cast<nlopt_algorithm>(nlopt_algorithm_index(nlopt_name))),
            {population_param(50, 1, "evaluations per recorded iteration (NLopt has no iterations)"),
             flag("restart", true, "restart from a new uniform point when NLopt stops before the budget is spent")},
            [name](const Params& p) {
                Nlopt a{name};
                a.record_every = p.integer("pop");
                a.restart = p.flag("restart");
                return a;
            });
        e.memory = [](const Params&, std::size_t dimension) { return 8.0 * 16.0 * static_cast<double>(dimension); };
        registry.add(std::move(e));
    }
}

}  // namespace pride::engine

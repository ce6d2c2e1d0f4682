// Harmony search (algorithms/hs.hpp), continuous form.
#include "algorithms/hs.hpp"

#include "engine/family.hpp"

namespace pride::engine {

void register_hs(AlgorithmRegistry& registry) {
    auto e = box_algorithm(
        "hs", "hs", "harmony search (Geem et al. 2001), HMS 30, HMCR 0.9, PAR 0.3, BW 0.01 of the range",
        {population_param(30, 1, "harmony memory size (HMS)"),
         real("hmcr", 0.9, 0.0, 1.0, "harmony memory considering rate"),
         real("par", 0.3, 0.0, 1.0, "pitch adjusting rate"),
         real("bw", 0.01, 0.0, 1.0, "bandwidth as a fraction of each coordinate's range"), walk_init_param(false)},
        [](const Params& p) {
            HarmonySearch<Clamp, SelectableInit> a;
            a.population = p.integer("pop");
            a.rates = {p.real("hmcr"), p.real("par"), p.real("bw")};
            a.init.suggestions = p.flag("walk_init");
            return a;
        });
    e.memory = population_memory(1);
    registry.add(std::move(e));
}

}  // namespace pride::engine

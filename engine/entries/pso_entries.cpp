// The particle swarm family (algorithms/pso.hpp): pso (inertia weight) and pso-constriction, two
// configurations of one instantiation (the velocity rule is chosen once per iteration).
#include "algorithms/pso.hpp"

#include "engine/family.hpp"

namespace pride::engine {
namespace {

using Family = Pso<SelectableVelocity, RangeVelocityClamp, Clamp, SelectableInit>;

Family configure(const Params& p) {
    Family a;
    a.population = p.integer("pop");
    a.init.suggestions = p.flag("walk_init");
    a.round_integers = p.choice("discrete") == "round";
    a.velocity_clamp.fraction = p.real("vmax");
    return a;
}

ParamSpec vmax() {
    return real("vmax", 0.2, 0.0, 1.0, "velocity limit as a fraction of each coordinate's range").open_below();
}

}  // namespace

void register_pso(AlgorithmRegistry& registry) {
    const auto configure_pso = [](const Params& p) {
        Family a = configure(p);
        InertiaVelocity<LinearInertia> v;
        v.inertia.start = p.real("w_start");
        v.inertia.end = p.real("w_end");
        v.c1 = p.real("c1");
        v.c2 = p.real("c2");
        a.velocity = v;
        return a;
    };
    auto pso = box_algorithm(
        "pso", "pso", "global-best particle swarm, inertia 0.9 -> 0.4, c1 = c2 = 2, vmax 0.2",
        {population_param(50, 2), real("w_start", 0.9, 0.0, 1.5, "inertia weight at the first iteration"),
         real("w_end", 0.4, 0.0, 1.5, "inertia weight at the last iteration"),
         real("c1", 2.0, 0.0, 10.0, "cognitive coefficient (towards the personal best)"),
         real("c2", 2.0, 0.0, 10.0, "social coefficient (towards the global best)"), vmax(), walk_init_param(false),
         integers_param("the particles' integer coordinates (rounded positions)")},
        configure_pso);
    add_constrained_runner(pso, configure_pso);
    pso.memory = population_memory(3);  // positions, velocities, personal bests
    registry.add(std::move(pso));

    const auto configure_constriction = [](const Params& p) {
        Family a = configure(p);
        a.id = "pso-constriction";
        ConstrictionVelocity v;
        v.chi = p.real("chi");
        v.c = p.real("c");
        a.velocity = v;
        return a;
    };
    auto constriction = box_algorithm(
        "pso-constriction", "pso", "particle swarm with Clerc-Kennedy constriction chi 0.7298, c 2.05",
        {population_param(50, 2), real("chi", 0.7298, 0.0, 1.0, "constriction factor").open_below().open_above(),
         real("c", 2.05, 0.0, 10.0, "acceleration coefficient (both attractions)").open_below(), vmax(),
         walk_init_param(false), integers_param("the particles' integer coordinates (rounded positions)")},
        configure_constriction);
    add_constrained_runner(constriction, configure_constriction);
    constriction.memory = population_memory(3);
    registry.add(std::move(constriction));
}

}  // namespace pride::engine

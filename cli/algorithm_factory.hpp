#pragma once
// Names and named parameters to configured algorithm objects, for the command line. The result
// is handed to a callback as its concrete type, so the caller instantiates the run for its own
// problem type (continuous or grid): type erasure happens once per run, never per evaluation.
#include <string>
#include <string_view>

#include "algorithms/ga.hpp"
#include "algorithms/lso.hpp"
#include "algorithms/nlopt.hpp"
#include "algorithms/pso.hpp"
#include "framework/error.hpp"
#include "framework/params.hpp"

namespace pride::cli {

namespace detail {
template <class G>
void set_ga_operators(G& a, const ParamMap& params) {
    a.population = params.get_int("pop", a.population, a.id);
    a.selection.size = params.get_int("tournament", a.selection.size, a.id);
    a.crossover.eta = params.get("eta_c", a.crossover.eta);
    a.crossover.probability = params.get("pc", a.crossover.probability);
    a.mutation.eta = params.get("eta_m", a.mutation.eta);
    a.mutation.probability = params.get("pm", a.mutation.probability);
}

template <class A, class F>
decltype(auto) finish(A& a, const ParamMap& params, F&& f) {
    params.check_all_used(a.name());
    a.validate();
    return f(a);
}
}  // namespace detail

/// The box algorithms by name, each with the parameters it reads (see list_algorithms()).
template <class F>
decltype(auto) with_algorithm(std::string_view name, const ParamMap& params, F&& f) {
    if (name.rfind("nlopt:", 0) == 0) {
        Nlopt a{std::string(name)};
        a.record_every = params.get_int("pop", a.record_every, a.name());
        a.restart = params.get_int("restart", 1, a.name()) != 0;
        return detail::finish(a, params, f);
    }
    // The command line's box algorithms take their initialiser at run time: uniform in the box, or
    // (`walk_init=1`, pride path --init walk|rules) the problem's suggested starting points: on
    // grids, genotypes read off the walks the problem offers (rule walks unless told random). ILSO
    // takes them unless told otherwise (pride path --init uniform); the others do not.
    const bool walk_init = params.get_int("walk_init", name == "ilso" ? 1 : 0, std::string(name)) != 0;
    if (name == "pso") {
        Pso<InertiaVelocity<LinearInertia>, RangeVelocityClamp, Clamp, SelectableInit> a;
        a.init.suggestions = walk_init;
        a.population = params.get_int("pop", a.population, a.id);
        a.velocity.inertia.start = params.get("w_start", a.velocity.inertia.start);
        a.velocity.inertia.end = params.get("w_end", a.velocity.inertia.end);
        a.velocity.c1 = params.get("c1", a.velocity.c1);
        a.velocity.c2 = params.get("c2", a.velocity.c2);
        a.velocity_clamp.fraction = params.get("vmax", a.velocity_clamp.fraction);
        return detail::finish(a, params, f);
    }
    if (name == "pso-constriction") {
        Pso<ConstrictionVelocity, RangeVelocityClamp, Clamp, SelectableInit> a;
        a.id = "pso-constriction";
        a.init.suggestions = walk_init;
        a.population = params.get_int("pop", a.population, a.id);
        a.velocity.chi = params.get("chi", a.velocity.chi);
        a.velocity.c = params.get("c", a.velocity.c);
        a.velocity_clamp.fraction = params.get("vmax", a.velocity_clamp.fraction);
        return detail::finish(a, params, f);
    }
    if (name == "ga") {
        Ga<TournamentSelection, SbxCrossover, PolynomialMutation, Clamp, SelectableInit> a;
        a.init.suggestions = walk_init;
        detail::set_ga_operators(a, params);
        a.replacement.elitism = params.get_int("elitism", a.replacement.elitism, a.id);
        return detail::finish(a, params, f);
    }
    if (name == "ga-plus") {
        Ga<TournamentSelection, SbxCrossover, PolynomialMutation, Clamp, SelectableInit, PlusReplacement> a;
        a.id = "ga-plus";
        a.init.suggestions = walk_init;
        detail::set_ga_operators(a, params);
        return detail::finish(a, params, f);
    }
    if (name == "lso" || name == "ilso") {
        auto set_lion = [&](auto& a) {
            a.init.suggestions = walk_init;
            a.population = params.get_int("pop", a.population, a.id);
            a.beta = params.get("beta", a.beta);
            if (params.contains("step")) a.step_factor = params.get("step", 0.0);
            a.cubs.first = params.get("cub_first", a.cubs.first);
            a.cubs.second = params.get("cub_second", a.cubs.second);
            a.gamma_per_coordinate = params.get_int("gamma_per_coordinate", 0, a.id) != 0;
        };
        if (name == "lso") {
            Lso<UnitWeight, LsoCubs, Clamp, SelectableInit> a;
            set_lion(a);
            return detail::finish(a, params, f);
        }
        auto a = make_ilso<Clamp, SelectableInit>();
        set_lion(a);
        a.weight.start = params.get("w_max", a.weight.start);
        a.weight.end = params.get("w_min", a.weight.end);
        return detail::finish(a, params, f);
    }
    throw InputError("--algo: unknown algorithm '" + std::string(name) + "' (see 'pride list')");
}

/// The algorithms on chains (`--encoding chain`) by name: the GA with the chain operators.
template <class F>
decltype(auto) with_chain_algorithm(std::string_view name, const ParamMap& params, F&& f) {
    auto set = [&](auto& a) {
        a.population = params.get_int("pop", a.population, a.id);
        a.selection.size = params.get_int("tournament", a.selection.size, a.id);
        a.crossover.probability = params.get("pc", a.crossover.probability);
        a.mutation.probability = params.get("pm", a.mutation.probability);
    };
    if (name == "ga") {
        ChainGa a;
        set(a);
        a.replacement.elitism = params.get_int("elitism", a.replacement.elitism, a.id);
        return detail::finish(a, params, f);
    }
    if (name == "ga-plus") {
        Ga<TournamentSelection, ChainCrossover, ChainMutation, Clamp, UniformInit, PlusReplacement> a;
        a.id = "ga-plus";
        set(a);
        return detail::finish(a, params, f);
    }
    throw InputError("--algo: " + std::string(name) + " does not work on chains; --encoding chain takes ga or ga-plus");
}

}  // namespace pride::cli

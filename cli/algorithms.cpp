#include "cli/algorithms.hpp"

#include <variant>

#include "algorithms/ga.hpp"
#include "algorithms/nlopt.hpp"
#include "algorithms/pso.hpp"
#include "framework/registry.hpp"

namespace pride::cli {
namespace {

template <class A>
ContinuousRunner wrap(A algorithm, const ParamMap& params) {
    params.check_all_used(algorithm.name());
    algorithm.validate();
    return [algorithm](const continuous::AnyProblem& problem, const Termination& termination, std::uint64_t seed) {
        return std::visit([&](const auto& p) { return algorithm.run(p, termination, seed); }, problem);
    };
}

ContinuousRunner make_pso(const ParamMap& params) {
    Pso<> a;
    a.population = params.get_int("pop", a.population, "pso");
    a.velocity.inertia.start = params.get("w_start", a.velocity.inertia.start);
    a.velocity.inertia.end = params.get("w_end", a.velocity.inertia.end);
    a.velocity.c1 = params.get("c1", a.velocity.c1);
    a.velocity.c2 = params.get("c2", a.velocity.c2);
    a.velocity_clamp.fraction = params.get("vmax", a.velocity_clamp.fraction);
    return wrap(a, params);
}

ContinuousRunner make_pso_constriction(const ParamMap& params) {
    Pso<ConstrictionVelocity> a;
    a.id = "pso-constriction";
    a.population = params.get_int("pop", a.population, a.id);
    a.velocity.chi = params.get("chi", a.velocity.chi);
    a.velocity.c = params.get("c", a.velocity.c);
    a.velocity_clamp.fraction = params.get("vmax", a.velocity_clamp.fraction);
    return wrap(a, params);
}

template <class G>
void set_ga_operators(G& a, const ParamMap& params) {
    a.population = params.get_int("pop", a.population, a.id);
    a.selection.size = params.get_int("tournament", a.selection.size, a.id);
    a.crossover.eta = params.get("eta_c", a.crossover.eta);
    a.crossover.probability = params.get("pc", a.crossover.probability);
    a.mutation.eta = params.get("eta_m", a.mutation.eta);
    a.mutation.probability = params.get("pm", a.mutation.probability);
}

ContinuousRunner make_ga(const ParamMap& params) {
    Ga<> a;
    set_ga_operators(a, params);
    a.replacement.elitism = params.get_int("elitism", a.replacement.elitism, a.id);
    return wrap(a, params);
}

ContinuousRunner make_ga_plus(const ParamMap& params) {
    Ga<TournamentSelection, SbxCrossover, PolynomialMutation, Clamp, UniformInit, PlusReplacement> a;
    a.id = "ga-plus";
    set_ga_operators(a, params);
    return wrap(a, params);
}

struct Builtin {
    ContinuousRunner (*make)(const ParamMap&);
};

const Registry<Builtin>& builtins() {
    static const Registry<Builtin> r = [] {
        Registry<Builtin> reg;
        reg.add("pso", "global-best particle swarm, inertia 0.9 -> 0.4, c1 = c2 = 2, vmax 0.2 (params: pop w_start w_end c1 c2 vmax)",
                {&make_pso});
        reg.add("pso-constriction", "particle swarm with Clerc-Kennedy constriction chi 0.7298, c 2.05 (params: pop chi c vmax)",
                {&make_pso_constriction});
        reg.add("ga", "real-coded GA: tournament 2, SBX 15 / 0.9, polynomial mutation 20 / (1/D), elitism 1 (params: pop elitism tournament eta_c pc eta_m pm)",
                {&make_ga});
        reg.add("ga-plus", "the same GA with (mu + lambda) reinsertion: best N of parents and children, as pagmo2's sga (params: pop tournament eta_c pc eta_m pm)",
                {&make_ga_plus});
        return reg;
    }();
    return r;
}

}  // namespace

std::vector<AlgorithmInfo> list_algorithms() {
    std::vector<AlgorithmInfo> out;
    for (const auto& item : builtins().items()) out.push_back({item.name, item.summary});
    for (const auto& name : nlopt_derivative_free_names()) {
        const auto a = nlopt_algorithm_from_string(name.c_str());
        out.push_back({"nlopt:" + name, std::string("NLopt: ") + nlopt_algorithm_name(a) + " (params: pop restart)"});
    }
    return out;
}

ContinuousRunner make_algorithm(std::string_view name, const ParamMap& params) {
    if (name.rfind("nlopt:", 0) == 0) {
        Nlopt a{std::string(name)};
        a.record_every = params.get_int("pop", a.record_every, a.name());
        a.restart = params.get_int("restart", 1, a.name()) != 0;
        return wrap(a, params);
    }
    const auto* item = builtins().find(name);
    require(item != nullptr, "--algo", "unknown algorithm '" + std::string(name) + "' (see 'pride list')");
    return item->entry.make(params);
}

}  // namespace pride::cli

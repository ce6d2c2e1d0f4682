// The genetic algorithm family (algorithms/ga.hpp): ga (elitist generational replacement) and
// ga-plus ((mu + lambda) replacement), two configurations of one instantiation on boxes and one on
// chains (the replacement is chosen once per generation).
#include "algorithms/ga.hpp"

#include "engine/family.hpp"

namespace pride::engine {
namespace {

using BoxFamily =
    Ga<TournamentSelection, SbxCrossover, PolynomialMutation, Clamp, SelectableInit, SelectableReplacement>;
using ChainFamily = Ga<TournamentSelection, ChainCrossover, ChainMutation, Clamp, UniformInit, SelectableReplacement>;

SelectableReplacement replacement(const Params& p, bool plus) {
    if (plus) return PlusReplacement{};
    ElitistReplacement r;
    r.elitism = p.integer("elitism");
    return r;
}

template <class G>
void common(G& a, const Params& p, bool plus) {
    a.id = plus ? "ga-plus" : "ga";
    a.population = p.integer("pop");
    a.replacement = replacement(p, plus);
    a.selection.size = p.integer("tournament");
    a.crossover.probability = p.real("pc");
}

BoxFamily configure_box(const Params& p, bool plus) {
    BoxFamily a;
    common(a, p, plus);
    a.init.suggestions = p.flag("walk_init");
    a.crossover.eta = p.real("eta_c");
    a.mutation.eta = p.real("eta_m");
    if (const auto pm = p.optional("pm")) a.mutation.probability = *pm;  // else 1/D
    return a;
}

ChainFamily configure_chain(const Params& p, bool plus) {
    ChainFamily a;
    common(a, p, plus);
    if (const auto pm = p.optional("pm")) a.mutation.probability = *pm;  // else 0.1, IQGA's Pm
    return a;
}

std::vector<ParamSpec> params(bool plus) {
    std::vector<ParamSpec> v{population_param(50, 2)};
    if (!plus) v.push_back(integer("elitism", 1, 0, 100'000'000, "best parents kept unchanged, fewer than pop"));
    v.push_back(integer("tournament", 2, 1, 100'000'000, "tournament size of parent selection"));
    v.push_back(real("eta_c", 15.0, 0.0, 1000.0, "SBX distribution index").only_on_boxes());
    v.push_back(real("pc", 0.9, 0.0, 1.0, "crossover probability per pair"));
    v.push_back(real("eta_m", 20.0, 0.0, 1000.0, "polynomial mutation distribution index").only_on_boxes());
    v.push_back(real("pm", 0.0, 0.0, 1.0,
                     "mutation probability: per gene on boxes (default 1/D), per child on chains "
                     "(default 0.1)")
                    .no_default());
    v.push_back(walk_init_param(false).only_on_boxes());
    return v;
}

void add(AlgorithmRegistry& registry, bool plus, std::string summary) {
    auto e = box_algorithm(plus ? "ga-plus" : "ga", "ga", std::move(summary), params(plus),
                           [plus](const Params& p) { return configure_box(p, plus); });
    add_chain_runner(e, [plus](const Params& p) { return configure_chain(p, plus); });
    e.memory = population_memory(plus ? 4 : 3);  // parents, next generation, children
    registry.add(std::move(e));
}

}  // namespace

void register_ga(AlgorithmRegistry& registry) {
    add(registry, false,
        "real-coded GA: tournament 2, SBX 15 / 0.9, polynomial mutation 20 / (1/D), elitism 1; on chains: crossover "
        "at a common cell, segment mutation");
    add(registry, true,
        "the same GA with (mu + lambda) reinsertion: best N of parents and children, as pagmo2's sga; on chains too");
}

}  // namespace pride::engine

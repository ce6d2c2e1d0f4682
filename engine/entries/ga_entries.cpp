// The genetic algorithm family (algorithms/ga.hpp): ga (elitist generational replacement) and
// ga-plus ((mu + lambda) replacement), two configurations of one instantiation on boxes and one on
// chains (the replacement is chosen once per generation), both also on boxes with constraints
// (`constraints`: deb, epsilon, penalty, apm); and the variants as policies of the same
// skeleton: iaga (Srinivas and Patnaik's adaptive pc and pm), icga (the catastrophe hook) on boxes
// and chains, ga-q (Q-learning choice among three box mutations) on boxes, iqga (Zhang et al.'s (2025) IQGA:
// region selection, elite crossover, Q-learning among three mutations) on chains only.
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

/// What every GA variant on boxes sets alike: where it starts, SBX's and the mutation's indices.
template <class G>
void box_operators(G& a, const Params& p) {
    a.init.suggestions = p.flag("walk_init");
    typed_operators(a, p);
    a.crossover.eta = p.real("eta_c");
    a.mutation.eta = p.real("eta_m");
}

BoxFamily configure_box(const Params& p, bool plus) {
    BoxFamily a;
    common(a, p, plus);
    box_operators(a, p);
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
    v.push_back(integers_param("the children's integer coordinates"));
    for (auto& c : categorical_params()) v.push_back(std::move(c));
    return v;
}

// --- iaga: adaptive pc and pm (algorithms/parts/ga/adaptive_rates.hpp) ---

using IagaBox = Ga<TournamentSelection, AdaptiveSbxCrossover, AdaptivePolynomialMutation, Clamp, SelectableInit>;
using IagaChain = Ga<TournamentSelection, AdaptiveChainCrossover, AdaptiveChainMutation>;

template <class G>
void iaga_common(G& a, const Params& p) {
    a.id = "iaga";
    a.population = p.integer("pop");
    a.replacement.elitism = p.integer("elitism");
    a.selection.size = p.integer("tournament");
    a.crossover.probability = {p.real("k1"), p.real("k3")};
    a.mutation.probability = {p.real("k2"), p.real("k4"), p.real("pm_min")};
}

std::vector<ParamSpec> iaga_params() {
    return with_categorical(
        {population_param(50, 2), integer("elitism", 1, 0, 100'000'000, "best parents kept unchanged, fewer than pop"),
         integer("tournament", 2, 1, 100'000'000, "tournament size of parent selection"),
         real("eta_c", 15.0, 0.0, 1000.0, "SBX distribution index").only_on_boxes(),
         real("eta_m", 20.0, 0.0, 1000.0, "polynomial mutation distribution index").only_on_boxes(),
         real("k1", 1.0, 0.0, 1.0, "pc = k1 (f' - best)/(mean - best) for a pair at least average (Srinivas-Patnaik)"),
         real("k2", 0.5, 0.0, 1.0, "pm = k2 (f - best)/(mean - best) for a member at least average"),
         real("k3", 1.0, 0.0, 1.0, "pc for a pair worse than average"),
         real("k4", 0.5, 0.0, 1.0, "pm for a member worse than average (per gene on boxes, per child on chains)"),
         real("pm_min", 0.005, 0.0, 1.0, "least pm of any member (Srinivas-Patnaik's default mutation rate)"),
         walk_init_param(false).only_on_boxes(), integers_param("the children's integer coordinates")});
}

void add_iaga(AlgorithmRegistry& registry) {
    auto e = box_algorithm("iaga", "ga",
                           "GA with Srinivas and Patnaik's adaptive crossover and mutation probabilities (IAGA of "
                           "Zhang et al. (2025)): SBX / polynomial mutation on boxes, chain operators on chains",
                           iaga_params(), [](const Params& p) {
                               IagaBox a;
                               iaga_common(a, p);
                               box_operators(a, p);
                               return a;
                           });
    add_chain_runner(e, [](const Params& p) {
        IagaChain a;
        iaga_common(a, p);
        return a;
    });
    e.memory = population_memory(3);
    e.native_encoding = "chain";  // Zhang et al. (2025) compare them with IQGA on paths
    registry.add(std::move(e));
}

// --- icga: the catastrophe hook (algorithms/parts/ga/catastrophe.hpp) ---

using IcgaBox = Ga<TournamentSelection, SbxCrossover, PolynomialMutation, Clamp, SelectableInit, ElitistReplacement,
                   CatastropheHook>;
using IcgaChain =
    Ga<TournamentSelection, ChainCrossover, ChainMutation, Clamp, UniformInit, ElitistReplacement, CatastropheHook>;

template <class G>
void icga_common(G& a, const Params& p) {
    a.id = "icga";
    a.population = p.integer("pop");
    a.replacement.elitism = p.integer("elitism");
    a.selection.size = p.integer("tournament");
    a.crossover.probability = p.real("pc");
    if (const auto pm = p.optional("pm")) a.mutation.probability = *pm;
    a.hook.k = p.integer("k");
    a.hook.elite = p.integer("elite");
}

void add_icga(AlgorithmRegistry& registry) {
    auto v = params(false);
    v.insert(v.end() - 1,
             integer("k", 10, 1, 1'000'000'000, "generations without improvement of the best before a catastrophe"));
    v.insert(v.end() - 1, integer("elite", 1, 0, 100'000'000, "best members a catastrophe keeps, fewer than pop"));
    auto e = box_algorithm(
        "icga", "ga",
        "GA with a catastrophe (ICGA of Zhang et al. (2025)): after k generations without improvement all "
        "but the elite are re-seeded; on chains too",
        std::move(v), [](const Params& p) {
            IcgaBox a;
            icga_common(a, p);
            box_operators(a, p);
            return a;
        });
    add_chain_runner(e, [](const Params& p) {
        IcgaChain a;
        icga_common(a, p);
        return a;
    });
    e.memory = population_memory(4);  // parents, next generation, children, re-seeded members
    e.native_encoding = "chain";      // Zhang et al. (2025) compare them with IQGA on paths
    registry.add(std::move(e));
}

// --- ga-q: Q-learning choice among box mutations (algorithms/parts/iqga/q_learning.hpp) ---

using GaQBox = Ga<TournamentSelection, SbxCrossover,
                  QLearningMutation<PolynomialMutation, UniformMutation, GaussianMutation>, Clamp, SelectableInit>;

void add_ga_q(AlgorithmRegistry& registry) {
    std::vector<ParamSpec> v{
        population_param(50, 2),
        integer("elitism", 1, 0, 100'000'000, "best parents kept unchanged, fewer than pop"),
        integer("tournament", 2, 1, 100'000'000, "tournament size of parent selection"),
        real("eta_c", 15.0, 0.0, 1000.0, "SBX distribution index"),
        real("pc", 0.9, 0.0, 1.0, "crossover probability per pair"),
        real("eta_m", 20.0, 0.0, 1000.0, "polynomial mutation distribution index"),
        real("sigma", 0.1, 0.0, 1.0, "Gaussian mutation step, a fraction of each coordinate's range").open_below(),
        real("pm", 0.0, 0.0, 1.0, "per-gene probability of the chosen mutation (default 1/D)").no_default(),
        real("epsilon", 0.1, 0.0, 1.0, "Q-learning: probability of a random action"),
        real("alpha", 0.1, 0.0, 1.0, "Q-learning: learning rate"),
        real("gamma", 0.9, 0.0, 1.0, "Q-learning: discount factor"),
        walk_init_param(false),
        integers_param("the children's integer coordinates")};
    for (auto& c : categorical_params()) v.push_back(std::move(c));
    auto e =
        box_algorithm("ga-q", "ga",
                      "GA whose mutation is polynomial, uniform or Gaussian by probabilities (0.6/0.2/0.2 in "
                      "some order) that Q-learning chooses once per generation (Zhang et al. 2025, eq. 19); boxes only",
                      std::move(v), [](const Params& p) {
                          GaQBox a;
                          a.id = "ga-q";
                          a.population = p.integer("pop");
                          a.replacement.elitism = p.integer("elitism");
                          a.selection.size = p.integer("tournament");
                          a.init.suggestions = p.flag("walk_init");
                          typed_operators(a, p);
                          a.crossover.eta = p.real("eta_c");
                          a.crossover.probability = p.real("pc");
                          auto& [polynomial, uniform, gaussian] = a.mutation.operators;
                          polynomial.eta = p.real("eta_m");
                          gaussian.sigma = p.real("sigma");
                          if (const auto pm = p.optional("pm"))
                              polynomial.probability = uniform.probability = gaussian.probability = *pm;
                          a.mutation.learning = {p.real("epsilon"), p.real("alpha"), p.real("gamma")};
                          return a;
                      });
    e.memory = population_memory(3);
    registry.add(std::move(e));
}

// --- iqga: Zhang et al.'s (2025) IQGA on chains (algorithms/parts/iqga/operators.hpp) ---

IqgaGa configure_iqga(const Params& p) {
    IqgaGa a;
    a.id = "iqga";
    a.population = p.integer("pop");
    a.replacement.elitism = 1;  // the best path so far is always kept (section 2.3)
    a.selection.elite = a.crossover.elite = p.integer("elite");
    a.crossover.probability = p.real("pc");
    a.mutation.probability = p.real("pm");
    a.mutation.learning = {p.real("epsilon"), p.real("alpha"), p.real("gamma")};
    // The ablations of docs/results/zhang2025.md: each flag removes one of Zhang et al.'s (2025) changes.
    a.selection.regions = p.flag("regions");
    a.selection.pairing = a.crossover.elite_only = p.flag("elite_crossover");
    if (!p.flag("qlearning")) a.mutation.actions = {{1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0}};  // one fixed action
    return a;
}

void add_iqga(AlgorithmRegistry& registry) {
    AlgorithmEntry e;
    e.name = "iqga";
    e.family = "ga";
    e.summary =
        "Zhang et al.'s (2025) IQGA on chains: SITP initial paths, region tournaments with SA acceptance (eqs. 14-18), "
        "elite "
        "two-point crossover, three mutations chosen by Q-learning (eq. 19); N = 40 on grids";
    e.params = {
        population_param(40, 2, "population size (on grids 40 unless given, as Zhang et al. (2025))"),
        integer("elite", 20, 1, 100'000'000, "elite of the crossover pairing: the min(elite, pop/2) best"),
        real("pc", 0.9, 0.0, 1.0, "crossover probability per pair with an elite member"),
        real("pm", 0.1, 0.0, 1.0, "mutation probability per child"),
        real("epsilon", 0.1, 0.0, 1.0, "Q-learning: probability of a random action"),
        real("alpha", 0.1, 0.0, 1.0, "Q-learning: learning rate"),
        real("gamma", 0.9, 0.0, 1.0, "Q-learning: discount factor"),
        flag("sitp", true,
             "initial chains from SITP walks (Zhang et al. 2025, section 2.2); the grid spec's init sets it"),
        flag("regions", true,
             "region-partitioned tournaments (eqs. 14-16); false: all N tournaments over the whole population"),
        flag("elite_crossover", true,
             "elite pairing rule and elite-only crossover (section 2.4.2); false: any pair, crossed with pc"),
        flag("qlearning", true, "Q-learning chooses the mutation probabilities (eq. 19); false: fixed 1/3 each")};
    for (auto& spec : chain_space_params({})) e.params.push_back(std::move(spec));
    e.grid_population = 40;
    add_runner<ChainTarget>(e, Kind::chain, [](const RunRequest& r, const ChainTarget& target) {
        const auto algorithm = configure_iqga(r.params);
        return std::visit(
            [&](const auto& problem) -> ChainResult {
                auto space = problem;
                configure_space(space, r.params);
                if (r.params.flag("sitp")) space.set_init(grid::Walks::sitp);
                return algorithm.run(std::move(space), r.termination, r.seed);
            },
            target.problem);
    });
    e.memory = population_memory(4);  // parents, next generation, children, the mating pool
    registry.add(std::move(e));
}

// --- ga-sga: ga-plus with pagmo2's polynomial mutation (mutation.hpp) ---

using SgaBox = Ga<TournamentSelection, SbxCrossover, SimplePolynomialMutation, Clamp, SelectableInit, PlusReplacement>;

std::vector<ParamSpec> sga_params() {
    return with_categorical({population_param(50, 2),
                             integer("tournament", 2, 1, 100'000'000, "tournament size of parent selection"),
                             real("eta_c", 15.0, 0.0, 1000.0, "SBX distribution index"),
                             real("pc", 0.9, 0.0, 1.0, "crossover probability per pair"),
                             real("eta_m", 20.0, 0.0, 1000.0, "polynomial mutation distribution index"),
                             real("pm", 0.0, 0.0, 1.0, "mutation probability per gene (default 1/D)").no_default(),
                             walk_init_param(false), integers_param("the children's integer coordinates")});
}

void add_ga_sga(AlgorithmRegistry& registry) {
    auto e = box_algorithm("ga-sga", "ga",
                           "ga-plus with the simple polynomial mutation of pagmo2's sga (steps a fraction of the "
                           "distance to the face moved towards); boxes only",
                           sga_params(), [](const Params& p) {
                               SgaBox a;
                               a.id = "ga-sga";
                               a.population = p.integer("pop");
                               a.selection.size = p.integer("tournament");
                               a.crossover.probability = p.real("pc");
                               box_operators(a, p);
                               if (const auto pm = p.optional("pm")) a.mutation.probability = *pm;  // else 1/D
                               return a;
                           });
    e.memory = population_memory(4);
    registry.add(std::move(e));
}

void add(AlgorithmRegistry& registry, bool plus, std::string summary) {
    auto e = box_algorithm(plus ? "ga-plus" : "ga", "ga", std::move(summary), params(plus),
                           [plus](const Params& p) { return configure_box(p, plus); });
    add_chain_runner(e, [plus](const Params& p) { return configure_chain(p, plus); });
    // Boxes with constraints: Deb's tournament and elitism, the epsilon level, a static penalty, or APM.
    add_constrained_runner(
        e, [plus](const Params& p) { return configure_box(p, plus); }, true);
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
    add_iaga(registry);
    add_icga(registry);
    add_ga_q(registry);
    add_iqga(registry);
    add_ga_sga(registry);
}

}  // namespace pride::engine

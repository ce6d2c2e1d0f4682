// The differential evolution family (algorithms/de.hpp): de (Storn and Price's strategies), jde,
// jade, shade, lshade and jso, six configurations of one instantiation (the policies are chosen
// once per generation); and colshade (algorithms/colshade.hpp), L-SHADE's constrained descendant
// with its own selection and tolerances. `pop` 0 is each paper's rule for N_init; the memory estimate applies it.
#include "algorithms/colshade.hpp"
#include "algorithms/de.hpp"

#include <string>
#include <utility>
#include <vector>

#include "engine/family.hpp"

namespace pride::engine {
namespace {

using Family = De<de::SelectableMutation, de::SelectableControl, de::SelectableRepair, de::SelectableSize,
                  de::SelectableReduction, SelectableInit>;

ParamSpec pop(const std::string& rule) {
    return population_param(0, 0, "initial population size; 0: the paper's rule, " + rule);
}

ParamSpec bounds() {
    return choice("bounds", {"midpoint", "clamp"}, "midpoint",
                  "a trial coordinate outside the box: halfway between the target's and the bound (JADE), or "
                  "the nearest bound");
}

ParamSpec archive_rate(double value) {
    return real("archive_rate", value, 0.0, 100.0, "archive size |A| as a multiple of the population size N");
}

ParamSpec memory(std::int64_t value, std::int64_t min) {
    return integer("memory", value, min, 1'000'000, "success-history memory size H");
}

ParamSpec n_min() {
    return integer("n_min", 4, 4, 1'000'000'000, "population size at the end of the linear reduction (N_min)");
}

/// What every entry shares: the name, the population rule, the bounds and the initial points.
Family common(const std::string& id, const Params& p, de::SelectableSize size) {
    Family a;
    a.id = id;
    a.population = p.integer("pop");
    a.size = std::move(size);
    if (p.choice("bounds") == "clamp") a.repair = de::ClampRepair{};
    a.init.suggestions = p.flag("walk_init");
    a.round_integers = p.choice("discrete") == "round";
    return a;
}

template <class Configure>
void add(AlgorithmRegistry& registry, const std::string& name, const std::string& summary,
         std::vector<ParamSpec> params, Configure configure) {
    params.push_back(bounds());
    params.push_back(walk_init_param(false));
    params.push_back(integers_param("the trials' integer coordinates"));
    auto e = box_algorithm(name, "de", summary, std::move(params), configure);
    add_constrained_runner(e, configure);
    // The population and the trials, the archive (each entry's own size), the per-individual
    // vectors: with pop 0, at the paper's N_init for the dimension.
    e.memory = [configure](const Params& p, std::size_t dimension) { return configure(p).memory_bytes(dimension); };
    registry.add(std::move(e));
}

Family configure_de(const Params& p) {
    Family a = common("de", p, de::PerDimensionSize{10.0});
    const std::string& strategy = p.choice("strategy");
    if (strategy == "best-1-bin")
        a.mutation = de::BestOne{};
    else if (strategy == "current-to-best-1-bin")
        a.mutation = de::CurrentToBestOne{};
    else if (strategy == "rand-2-bin")
        a.mutation = de::RandTwo{};
    a.control = de::FixedControl{p.real("f"), p.real("cr")};
    return a;
}

Family configure_jde(const Params& p) {
    Family a = common("jde", p, de::ConstantSize{100});
    de::JdeControl c;
    c.tau1 = p.real("tau1");
    c.tau2 = p.real("tau2");
    c.f_lower = p.real("f_lower");
    c.f_upper = p.real("f_upper");
    a.control = c;
    return a;
}

Family configure_jade(const Params& p) {
    Family a = common("jade", p, de::ConstantSize{100});
    a.mutation = de::CurrentToPBest<de::FixedRate>{{p.real("p")}};
    a.control = de::JadeControl{p.real("c")};
    a.archive.rate = p.flag("archive") ? 1.0 : 0.0;
    a.archive.trim_after_generation = true;
    a.ties_replace = false;
    return a;
}

Family configure_shade(const Params& p) {
    Family a = common("shade", p, de::ConstantSize{100});
    a.mutation = de::CurrentToPBest<de::UniformRate>{{p.real("p_max")}};
    de::ShadeControl c;
    c.memory = p.integer("memory");
    a.control = c;
    a.archive.rate = p.real("archive_rate");
    return a;
}

Family configure_lshade(const Params& p) {
    Family a = common("lshade", p, de::PerDimensionSize{18.0});
    const bool code = p.choice("reading") == "code";
    a.mutation = de::CurrentToPBest<de::FixedRate>{{p.real("p")}};
    de::LshadeControl c;
    c.memory = p.integer("memory");
    c.sticky_terminal = !code;
    a.control = c;
    a.archive.rate = p.real("archive_rate");
    a.archive.stores_trial = code;
    a.archive.floor_on_resize = code;
    a.reduction = de::LinearReduction{p.integer("n_min")};
    return a;
}

Family configure_jso(const Params& p) {
    Family a = common("jso", p, de::LogSqrtSize{25.0});
    de::CurrentToPBest<de::LinearRate> m;
    m.rate = {p.real("p_max"), p.real("p_min")};
    m.pbest_not_target_before = 0.5;
    a.mutation = m;
    de::JsoControl c;
    c.memory = p.integer("memory");
    a.control = c;
    a.archive.rate = p.real("archive_rate");
    a.archive.floor_on_resize = true;  // (int)(1 N): the same as round
    a.reduction = de::LinearReduction{p.integer("n_min")};
    return a;
}

Colshade<SelectableInit> configure_colshade(const Params& p) {
    Colshade<SelectableInit> a;
    a.population = p.integer("pop");
    a.n_min = p.integer("n_min");
    a.memory = p.integer("memory");
    a.p = p.real("p");
    a.archive_rate = p.real("archive_rate");
    a.levy_start = p.real("p_levy");
    a.dynamic_tolerance = p.flag("dynamic");
    a.cut = p.real("cut");
    a.paper_reading = p.choice("reading") == "paper";
    a.init.suggestions = p.flag("walk_init");
    return a;
}

void register_colshade(AlgorithmRegistry& registry) {
    auto e = box_algorithm(
        "colshade", "de",
        "COLSHADE (Gurrola-Ramos et al. 2020): L-SHADE with an adaptive Levy-flight mutation, Deb's rules and a "
        "dynamic tolerance on equalities, 18 D -> 4",
        {pop("ceil(18 D)"), n_min(), memory(6, 1),
         real("p", 0.11, 0.0, 1.0, "share of the best from which x_pbest is drawn").open_below(), archive_rate(2.6),
         real("p_levy", 0.5, 0.0, 1.0, "the initial probability of the Levy-flight mutation"),
         flag("dynamic", true,
              "equality tolerances start at the population's largest |h_j| and fall to 1e-4 (0: 1e-4 throughout)")
             .only_with_constraints(),
         real("cut", 0.6, 0.0, 1.0, "share of the budget after which the equality tolerances are 1e-4")
             .only_with_constraints(),
         choice("reading", {"code", "paper"}, "code",
                "where the paper and the authors' submitted code differ: the code, or the paper (tolerance falls "
                "when 0.2 N meet it, eq. 10's third case between epsilon-feasible points, F clipped to F_crit, "
                "no terminal CR)"),
         walk_init_param(false)},
        configure_colshade);
    add_runner<ConstrainedBoxTarget>(
        e, Kind::constrained_box, [](const RunRequest& r, const ConstrainedBoxTarget& target) -> Result {
            const auto algorithm = configure_colshade(r.params);
            const ForwardingObserver forward{r.observer};
            return std::visit(
                [&](const auto& problem) -> Result { return algorithm.run(problem, r.termination, r.seed, forward); },
                target.problem);
        });
    e.memory = [](const Params& p, std::size_t dimension) { return configure_colshade(p).memory_bytes(dimension); };
    registry.add(std::move(e));
}

}  // namespace

void register_de(AlgorithmRegistry& registry) {
    add(registry, "de", "differential evolution (Storn and Price 1997), rand/1/bin by default, F 0.5, CR 0.9, NP 10 D",
        {pop("10 D (Storn and Price: 5 D to 10 D)"),
         choice("strategy", {"rand-1-bin", "best-1-bin", "current-to-best-1-bin", "rand-2-bin"}, "rand-1-bin",
                "mutation strategy DE/x/y/bin: rand/1, best/1, current-to-best/1 or rand/2"),
         real("f", 0.5, 0.0, 2.0, "differential weight F").open_below(),
         real("cr", 0.9, 0.0, 1.0, "crossover rate CR")},
        configure_de);
    add(registry, "jde", "jDE (Brest et al. 2006): rand/1/bin with self-adapting F and CR, tau1 = tau2 = 0.1, NP 100",
        {pop("100"), real("tau1", 0.1, 0.0, 1.0, "probability of drawing a new F_i"),
         real("tau2", 0.1, 0.0, 1.0, "probability of drawing a new CR_i"),
         real("f_lower", 0.1, 0.0, 2.0, "F_l: a new F_i is U[F_l, F_l + F_u)").open_below(),
         real("f_upper", 0.9, 0.0, 2.0, "F_u (F_l + F_u <= 2)")},
        configure_jde);
    add(registry, "jade",
        "JADE (Zhang and Sanderson 2009): current-to-pbest/1 with archive, p 0.05, c 0.1, mu_CR = mu_F = 0.5, NP 100",
        {pop("100"), real("p", 0.05, 0.0, 1.0, "share of the best from which x_pbest is drawn").open_below(),
         real("c", 0.1, 0.0, 1.0, "learning rate of mu_CR and mu_F"),
         flag("archive", true, "keep the replaced targets as donors (|A| = N); 0: JADE without archive")},
        configure_jade);
    add(registry, "shade",
        "SHADE (Tanabe and Fukunaga 2013): current-to-pbest/1, success-history memory H 100, p in [2/N, 0.2], NP 100",
        {pop("100"), memory(100, 1),
         real("p_max", 0.2, 0.0, 1.0, "p_i ~ U[2/N, p_max]: share of the best for x_pbest").open_below(),
         archive_rate(1.0)},
        configure_shade);
    add(registry, "lshade",
        "L-SHADE (Tanabe and Fukunaga 2014, Tanabe's code): SHADE with linear population reduction 18 D -> 4, H 6",
        {pop("round(18 D)"), n_min(), memory(6, 1),
         real("p", 0.11, 0.0, 1.0, "share of the best from which x_pbest is drawn").open_below(), archive_rate(2.6),
         choice("reading", {"code", "paper"}, "code",
                "where paper and Tanabe's code (version 1.0, CEC 2022) differ: the code (archives the trial, "
                "|A| truncated, terminal CR reset) or the paper")},
        configure_lshade);
    add(registry, "jso",
        "jSO (Brest et al. 2017): L-SHADE with current-to-pBest-w/1 and F, CR, p schedules, N 25 ln(D) sqrt(D) -> 4",
        {pop("round(25 ln(D) sqrt(D)), at least 4"), n_min(), memory(5, 2),
         real("p_max", 0.25, 0.0, 1.0, "p at the start, falling linearly to p_min").open_below(),
         real("p_min", 0.125, 0.0, 1.0, "p at the end of the budget").open_below(), archive_rate(1.0)},
        configure_jso);
    register_colshade(registry);
}

}  // namespace pride::engine

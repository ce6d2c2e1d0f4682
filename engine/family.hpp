#pragma once
// What an algorithm family's registration file (engine/entries/*.cpp) uses to turn a typed
// algorithm into registry entries: an entry's runner visits the target once and calls the
// algorithm's typed run(), so every (algorithm type, problem type) pair is instantiated in that one
// file. Include this only from registration files: it pulls in every problem type.
#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "engine/registry.hpp"
#include "engine/target.hpp"
#include "framework/constraint_order.hpp"

namespace pride::engine {

/// The standard parameter of population algorithms.
inline ParamSpec population_param(std::int64_t default_value, std::int64_t min, std::string doc = "population size") {
    return integer("pop", default_value, min, 1'000'000'000'000, std::move(doc));  // memory is checked apart
}

/// Start from the problem's suggested points (grids: feasible walks) instead of uniform ones.
inline ParamSpec walk_init_param(bool default_value) {
    return flag("walk_init", default_value,
                "start from the problem's suggestions (grids: feasible walks, as the grid spec's init sets it)");
}

/// The typed space's rounding operator (framework/variables.hpp) on a problem with integer or
/// categorical variables: `what` put on their values, or the coordinates searched as reals that
/// the problem rounds when it evaluates them. Named `discrete`, not `integers`: Python's
/// `integers=` declares a function's integer coordinates.
inline ParamSpec integers_param(const std::string& what) {
    return choice("discrete", {"round", "relax"}, "round",
                  "integer and categorical variables (bbob-mixint, functions given types): " + what +
                      " rounded to their values, or searched as reals the problem rounds")
        .only_on_boxes();
}

/// The GA family's operators on categorical variables (algorithms/parts/variation/categorical.hpp).
inline std::vector<ParamSpec> categorical_params() {
    return {real("cat_swap", 0.45, 0.0, 1.0,
                 "categorical variables: probability that the two children exchange one (uniform crossover; "
                 "pymoo's mixed-variable GA: 0.9 per pair x 0.5)")
                .only_on_boxes(),
            real("cat_reset", 0.5, 0.0, 1.0,
                 "categorical variables: probability that a child's one is drawn anew among its choices (random "
                 "resetting, as pymoo's)")
                .only_on_boxes()};
}

/// `params` and the categorical ones.
inline std::vector<ParamSpec> with_categorical(std::vector<ParamSpec> params) {
    for (auto& c : categorical_params()) params.push_back(std::move(c));
    return params;
}

/// What `discrete`, `cat_swap` and `cat_reset` set on an algorithm with categorical rates.
template <class A>
void typed_operators(A& a, const Params& p) {
    a.round_integers = p.choice("discrete") == "round";
    a.categorical = {p.real("cat_swap"), p.real("cat_reset")};
}

/// Memory of a population algorithm holding `matrices` population-sized matrices of points (and a
/// few vectors): 8 bytes per number.
inline auto population_memory(double matrices) {
    return [matrices](const Params& p, std::size_t dimension) {
        const double pop = static_cast<double>(p.integer("pop"));
        const double dim = static_cast<double>(dimension);
        return 8.0 * (matrices * pop * dim + 4.0 * pop + 8.0 * dim);
    };
}

/// Adds a kind of run to an entry: `run(request, target)`, on the target's alternative T, returns
/// that kind's result. The entry's runner becomes one that runs T itself and hands any other kind
/// to the runner it had, so an entry of several kinds is still one runner (one std::function call
/// and one visit per run).
template <class T, class Run>
void add_runner(AlgorithmEntry& e, Kind kind, Run run) {
    e.kinds.add(kind);
    e.run = [previous = std::move(e.run), run = std::move(run)](const RunRequest& request,
                                                                const Target& target) -> Outcome {
        if (const T* own = std::get_if<T>(&target)) return Outcome(run(request, *own));
        if (!previous) throw std::logic_error("a target of a kind the entry does not declare");
        return previous(request, target);
    };
}

/// Calls the engine's observer when there is one (box_algorithm's runners).
struct ForwardingObserver {
    const BoxObserver* observer = nullptr;
    void operator()(const IterationView& view) const {
        if (observer && *observer) (*observer)(view);
    }
};

/// An entry that runs on boxes: `configure(params)` returns the configured typed algorithm.
template <class Configure>
AlgorithmEntry box_algorithm(std::string name, std::string family, std::string summary, std::vector<ParamSpec> params,
                             Configure configure) {
    AlgorithmEntry e;
    e.name = std::move(name);
    e.family = std::move(family);
    e.summary = std::move(summary);
    e.params = std::move(params);
    // One typed run per (algorithm, problem type), observed or not: the observer is tested once
    // per iteration.
    add_runner<BoxTarget>(e, Kind::box, [configure](const RunRequest& r, const BoxTarget& target) -> Result {
        const auto algorithm = configure(r.params);
        const ForwardingObserver forward{r.observer};
        return std::visit(
            [&](const auto& problem) -> Result { return algorithm.run(problem, r.termination, r.seed, forward); },
            target.problem);
    });
    return e;
}

/// The handlers of constraints an algorithm that compares pairs of points offers
/// (framework/constraint_order.hpp), as parameters refused on problems without constraints;
/// `apm`: the algorithm offers Barbosa and Lemonge's adaptive penalty too (it ranks a population).
inline std::vector<ParamSpec> constraint_params(bool apm = false) {
    std::vector<std::string> handlers{"deb", "epsilon", "penalty"};
    std::string doc =
        "how points compare under constraints: Deb's (2000) feasibility rules, Takahama and Sakai's (2006) "
        "epsilon level, or the static penalty f + penalty v";
    if (apm) {
        handlers.push_back("apm");
        doc =
            "how points compare under constraints: Deb's (2000) feasibility rules, Takahama and Sakai's (2006) "
            "epsilon level, the static penalty f + penalty v, or Barbosa and Lemonge's adaptive penalty "
            "recomputed from the population each generation";
    }
    return {choice("constraints", std::move(handlers), "deb", std::move(doc)).only_with_constraints(),
            real("epsilon_cp", 100.0, 0.0, 1e6, "how fast the epsilon level falls, (1 - t / Tc)^cp")
                .open_below()
                .only_with_constraints(),
            integer("epsilon_tc", 1000, 1, 1'000'000'000'000, "the iteration from which the epsilon level is 0")
                .only_with_constraints(),
            real("epsilon_theta", 0.2, 0.0, 1.0,
                 "the initial epsilon level: the violation of the (theta N)-th point of the initial population")
                .open_below()
                .only_with_constraints(),
            real("penalty", 1e6, 0.0, 1e300, "r of the static penalty f + r v").only_with_constraints()};
}

/// The handler the parameters of constraint_params() name.
inline ConstraintHandling constraint_handling(const Params& p) {
    ConstraintHandling h;
    const std::string& name = p.choice("constraints");
    h.handler = name == "epsilon"              ? ConstraintHandling::Handler::epsilon
                : name == "penalty"            ? ConstraintHandling::Handler::penalty
                : name == "apm"                ? ConstraintHandling::Handler::apm
                : name == "stochastic-ranking" ? ConstraintHandling::Handler::stochastic_ranking
                                               : ConstraintHandling::Handler::deb;
    h.epsilon.cp = p.real("epsilon_cp");
    h.epsilon.tc = p.integer("epsilon_tc");
    h.epsilon.theta = p.real("epsilon_theta");
    h.penalty = p.real("penalty");
    return h;
}

/// Adds running on boxes with constraints to an entry whose algorithm compares through its
/// `constraints` (ConstraintHandling): `configure(params)` returns the typed algorithm; the entry
/// gets the handlers' parameters (with `apm` among them when the algorithm offers it).
template <class Configure>
void add_constrained_runner(AlgorithmEntry& e, Configure configure, bool apm = false) {
    for (auto& spec : constraint_params(apm)) e.params.push_back(std::move(spec));
    add_runner<ConstrainedBoxTarget>(
        e, Kind::constrained_box, [configure](const RunRequest& r, const ConstrainedBoxTarget& target) -> Result {
            auto algorithm = configure(r.params);
            algorithm.constraints = constraint_handling(r.params);
            const ForwardingObserver forward{r.observer};
            return std::visit(
                [&](const auto& problem) -> Result { return algorithm.run(problem, r.termination, r.seed, forward); },
                target.problem);
        });
}

/// An algorithm's defaults for the settings of the chain space it plans on (its paper's).
struct ChainSpaceDefaults {
    std::string shortcut = "none";         // none, line, elbow
    std::string walks = "octile";          // eq10, octile
    std::string sitp_score = "objective";  // objective, length (multi-objective spaces: length only)
};

/// The chain space's settings (problems/grid/chain.hpp) as parameters of an algorithm that plans
/// on chains: the same names, choices and meaning for every such algorithm, refused on boxes.
inline std::vector<ParamSpec> chain_space_params(const ChainSpaceDefaults& d) {
    return {
        choice("shortcut", {"none", "line", "elbow"}, d.shortcut,
               "the chain space's shortcut on every chain an operator makes, at no evaluation: line of sight "
               "(Cai and Du 2021), or one-turn elbows first (this project's)")
            .only_on_chains(),
        flag("shortcut_keep", false,
             "keep a shortcut only when the objective does not rise (two counted evaluations per changed chain)")
            .only_on_chains(),
        choice(
            "walks", {"eq10", "octile"}, d.walks,
            "random walks' roulette: Cai and Du's (2021) eq. 10 (D - distance to the goal) or exp(-2 x octile change)")
            .only_on_chains(),
        choice(
            "sitp_column", {"random", "midpoint"}, "random",
            "SITP's transition column: random between start and goal (Zhang et al.'s (2025) text) or eq. 3's midpoint")
            .only_on_chains(),
        choice("sitp_score", {"objective", "length"}, d.sitp_score,
               "SITP keeps the best of N/8 walks by the objective (counted evaluations) or by length")
            .only_on_chains()};
}

/// A run's copy of the chain space with the algorithm's settings.
template <class Space>
void configure_space(Space& space, const Params& p) {
    const std::string& shortcut = p.choice("shortcut");
    space.set_shortcut(shortcut == "line"    ? grid::Shortcut::line
                       : shortcut == "elbow" ? grid::Shortcut::elbow
                                             : grid::Shortcut::none,
                       p.flag("shortcut_keep"));
    space.set_walks(p.choice("walks") == "eq10" ? grid::GoalBias::eq10 : grid::GoalBias::octile_exp);
    space.set_sitp(p.choice("sitp_column") == "midpoint",
                   p.choice("sitp_score") == "length" ? grid::SitpScore::length : grid::SitpScore::objective);
}

/// Adds running on chains to an entry: `configure(params)` returns the typed algorithm for chains;
/// the entry gets the chain space's settings as parameters, with `defaults`.
template <class Configure>
void add_chain_runner(AlgorithmEntry& e, Configure configure, const ChainSpaceDefaults& defaults = {}) {
    for (auto& spec : chain_space_params(defaults)) e.params.push_back(std::move(spec));
    add_runner<ChainTarget>(e, Kind::chain, [configure](const RunRequest& r, const ChainTarget& target) {
        const auto algorithm = configure(r.params);
        return std::visit(
            [&](const auto& problem) -> ChainResult {
                auto space = problem;
                configure_space(space, r.params);
                return algorithm.run(std::move(space), r.termination, r.seed);
            },
            target.problem);
    });
}

}  // namespace pride::engine

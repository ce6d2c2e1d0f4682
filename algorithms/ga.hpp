#pragma once
// Genetic algorithm: real-coded on boxes, and on chains (grid paths) through the same skeleton.
//
//   Deb, K. and Agrawal, R. B. (1995). Simulated binary crossover for continuous search space.
//     Complex Systems 9, 115-148.
//   Deb, K. and Goyal, M. (1996). A combined genetic adaptive search (GeneAS) for engineering
//     design. Computer Science and Informatics 26(4), 30-45 (polynomial mutation).
//
// One generation, one loop for points and chains (Ga::generations; what differs, storage,
// initialisation, copies, the operators' signatures and evaluation, sits in a population adapter,
// algorithms/parts/ga/population.hpp):
//   (1) as many children as the Replacement policy asks for (N - elitism for the project's elitist
//       replacement): two parents by the Selection policy, two children (copies of the parents) by
//       the Crossover policy, each child through the Mutation policy and, for points, the Bounds
//       policy;
//   (2) the children are evaluated in order;
//   (3) the Replacement policy forms the next population from parents and children (elitist: the
//       `elitism` best parents, unchanged and not re-evaluated, then the children; plus: the best N
//       of parents and children, as pagmo2's sga);
//   before (1), operators whose prepared form offers begin_generation(context, rng) are told a
//   generation begins (generation_context.hpp; the Q-learning choice of q_learning.hpp learns and
//   chooses there; nothing for the others): the crossover, the mutation, then the selection (whose
//   prepared form, one per run, may build a mating pool there: IQGA's, iqga_operators.hpp; a
//   Selection declaring `uses_regions` finds the members' regions in the context, on chain spaces
//   with regions, and a Mutation declaring `uses_best_length` the length of the best member, on
//   chain spaces with lengths); the Selection is asked for parents two at a time, a pair per call pair;
//   after (3), the GenerationContext (generation_context.hpp: iteration, horizon, best / mean / worst of
//   the population, best so far, generations without improvement) is brought up to date, the Hook
//   policy is called with it, the population and the Rng (generation_hook.hpp; by default it does
//   nothing; after any other hook the population is described again, as the hook may have
//   changed it), and the generation is recorded. Selection, Crossover, Mutation and Replacement
//   policies whose call accepts a trailing context get it; the others are called as they always were.
// The initial population: for points, the Init policy then the Bounds policy (run_setup.hpp); for
// chains, the problem's random chains. Both are evaluated in order and recorded as iteration 0.
// Variants as policies: IAGA's adaptive pc and pm (adaptive_rates.hpp), ICGA's catastrophe
// (catastrophe.hpp, a hook), Q-learning choice among mutation operators (q_learning.hpp), IQGA's
// region selection, elite crossover and Q-learning mutations on chains (iqga_operators.hpp; IqgaGa).
// Defaults (docs/algorithms.md): tournament of 2, SBX eta 15 with probability 0.9,
// polynomial mutation eta 20 with probability 1/D per gene, elitist replacement with elitism 1.
// On a problem with constraints (framework/constraints.hpp; `constraints`, the box GA with the
// tournament) every comparison of two members is the configured handler's order on (f, v)
// (framework/constraint_order.hpp), the same policies the DE family ranks by:
//   deb: Deb's (2000) feasibility rules, as that paper applies them to a GA: in the tournament of
//     (1) (Deb's binary tournament: a feasible member beats an infeasible one, two feasible ones
//     compare by f, two infeasible ones by v), and in (3), the elite of the elitist replacement and
//     the best N of the plus replacement;
//   epsilon: Takahama and Sakai's (2006) epsilon level (eq. 3-5), generation t of the loop being
//     the level's t + 1 (0: the initial population, as in the DE family); penalty: f + r v;
//   apm: Barbosa and Lemonge's adaptive penalty as Lemonge and Barbosa (2004, eq. 2-4) apply it to
//     a GA: each generation, before (1), the penalised values F of the current population are
//     recomputed from its own mean f and mean violation of each constraint
//     (algorithms/parts/common/adaptive_penalty.hpp), and the tournament and the elite compare F.
// Runarsson and Yao's (2000) stochastic ranking is not offered: it orders a population for a
// rank-based selection, and this GA's parent selection is a tournament, which compares two members
// at a time. Without constraints the run is the same, bit for bit, as before constraints existed.
// Integer variables (framework/variables.hpp), which the papers do not treat: with
// `round_integers` each child's integer coordinates are rounded after SBX and the mutation (the
// rounding repair pymoo's mixed-variable GA gives its integer variables), the initial population too;
// categorical coordinates keep their values through SBX and the mutation and get uniform crossover
// and random resetting instead, as pymoo's mixed-variable GA gives its Choice variables
// (algorithms/parts/variation/categorical.hpp, `categorical`; where pride differs from pymoo: its
// tournament selection, not pymoo's random one, and p_m = 1/D over all the real-coded
// coordinates, where pymoo takes 1 / (the number of variables of each type)).
// Decided by this project where the papers are silent: Deb's tournament is used without the
// niching its paper adds among feasible members (sigma_share; a distance per comparison) and
// without its mutation of infeasible members; under apm the plus replacement (absent from the
// paper) ranks parents and children by F computed over that pool of 2N, the elitist replacement
// ranks the parents by the F the tournament saw; the budget's unevaluated children (+inf, +inf)
// take no part in APM's means. When an odd number of children is asked for,
// the second child of the last pair is dropped; when the budget ends inside a generation the
// children not evaluated get fitness +inf, the generation is recorded, and the run stops.
#include <algorithm>
#include <cstdint>
#include <numeric>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "algorithms/parts/ga/adaptive_rates.hpp"
#include "algorithms/parts/ga/catastrophe.hpp"
#include "algorithms/parts/ga/generation_context.hpp"
#include "algorithms/parts/ga/generation_hook.hpp"
#include "algorithms/parts/ga/population.hpp"
#include "algorithms/parts/ga/replacement.hpp"
#include "algorithms/parts/ga/selection.hpp"
#include "algorithms/parts/iqga/operators.hpp"
#include "algorithms/parts/iqga/q_learning.hpp"
#include "algorithms/parts/variation/categorical.hpp"
#include "algorithms/parts/variation/chain_operators.hpp"
#include "algorithms/parts/variation/crossover.hpp"
#include "algorithms/parts/variation/mutation.hpp"
#include "framework/bounds.hpp"
#include "framework/chain.hpp"
#include "framework/constraint_order.hpp"
#include "framework/initializer.hpp"
#include "framework/observer.hpp"
#include "framework/problem.hpp"
#include "framework/random.hpp"
#include "framework/result.hpp"
#include "framework/run_state.hpp"
#include "framework/termination.hpp"
#include "framework/visit_policy.hpp"

namespace pride {

template <class Selection = TournamentSelection, class Crossover = SbxCrossover, class Mutation = PolynomialMutation,
          class Bounds = Clamp, class Init = UniformInit, class Replacement = ElitistReplacement,
          class Hook = NoGenerationHook>
class Ga {
  public:
    std::string id = "ga";  // the name in messages and results ("ga-plus" for that variant)
    std::int64_t population = 50;
    Replacement replacement{};
    Selection selection{};
    Crossover crossover{};
    Mutation mutation{};
    Bounds bounds{};
    Init init{};
    Hook hook{};
    ConstraintHandling constraints{};  // constrained problems only (deb, epsilon, penalty, apm)
    bool round_integers = true;        // integer coordinates: children rounded (framework/variables.hpp)
    CategoricalRates categorical{};    // categorical coordinates (with round_integers): categorical.hpp

    std::string name() const { return id; }

    void validate() const {
        require(population >= 2, name(), "population must be >= 2, got " + std::to_string(population));
        replacement.validate(name(), population);
        selection.validate(name());
        crossover.validate(name());
        mutation.validate(name());
        if constexpr (requires { hook.validate(name(), population); })
            hook.validate(name(), population);
        else if constexpr (requires { hook.validate(name()); })
            hook.validate(name());
        constraints.validate(name(), true, false);
        categorical.validate(name());
    }

    /// Real-coded, on the box of a BoxProblem.
    template <BoxProblem P, Observer O = NoObserver>
    Result run(P problem, const Termination& termination, std::uint64_t seed, O&& observer = O{}) const {
        BoxPopulation<Ga, P> population(*this, problem, termination, seed, observer);
        return generations(population, observer);
    }

    /// On chains (framework/chain.hpp), with chain operator policies (ChainCrossover, ChainMutation).
    template <ChainProblem P, class O = NoObserver>
    BasicResult<typename P::chain_type> run(P problem, const Termination& termination, std::uint64_t seed,
                                            O&& observer = O{}) const requires
        PreparedOperatorOn<Crossover, P&, typename P::chain_type&, typename P::chain_type&, Rng&> &&
        PreparedOperatorOn<Mutation, P&, typename P::chain_type&, Rng&> {
        ChainPopulation<Ga, P> population(*this, problem, termination, seed, observer);
        return generations(population, observer);
    }

  private:
    /// The generation loop, for points and chains alike (the adapter holds what differs).
    template <class Population, class O>
    auto generations(Population& pop, O& observer) const {
        Rng& rng = pop.rng();
        auto& state = pop.state();
        const std::size_t n = pop.size(), kids = pop.offspring();
        std::vector<std::size_t> chosen(n);
        ReplacementScratch scratch;
        GenerationContext context;
        context.horizon = pop.horizon();
        context.describe(0, pop.fitness(), state.best());
        // The selection's prepared form (detail::prepared; the policy itself unless it offers
        // prepare), one per run, so that a selection may keep per-generation state (a mating pool).
        auto&& select = detail::prepared(selection, 0);
        // Constrained problems only: the handler's order, and the values it compares (f, or APM's F).
        constexpr bool constrained = Population::constrained;
        [[maybe_unused]] ConstraintOrder by(constraints);
        [[maybe_unused]] const bool apm = constraints.handler == ConstraintHandling::Handler::apm;
        [[maybe_unused]] std::vector<double> keys, pool_keys;
        if constexpr (constrained) by.start(pop.violations());

        for (std::int64_t t = 0; !state.done(); ++t) {
            const std::span<const double> fx = pop.fitness();
            // Operators that learn between generations (nothing for most).
            if constexpr (requires { Selection::uses_regions; }) context.regions = pop.regions();
            if constexpr (requires { Mutation::uses_best_length; }) context.best_length = pop.best_length();
            pop.begin_generation(context);
            detail::begin_generation(select, context, rng);
            [[maybe_unused]] std::span<const double> fsel = fx;
            if constexpr (constrained) {
                by.generation(t + 1);
                if (apm) {
                    pop.penalise(false, keys);
                    fsel = keys;
                }
            }
            // Two parents by the Selection policy, under constraints by the handler's order.
            const auto parent = [&] {
                if constexpr (constrained)
                    return select(by, fsel, pop.violations(), rng);
                else
                    return with_context(select, context, fx, rng);
            };
            for (std::size_t k = 0; k < kids; k += 2) {  // (1)
                const std::size_t a = parent();
                const std::size_t b = parent();
                auto&& first = pop.child(k);
                auto&& second = k + 1 < kids ? pop.child(k + 1) : pop.spare();
                pop.copy(a, first);
                pop.copy(b, second);
                context.parents = {a, b};
                pop.cross(first, second, context);
                context.child = 0;
                pop.mutate(first, context);
                context.child = 1;
                pop.mutate(second, context);
                pop.repair(first);
                pop.repair(second);
            }
            pop.evaluate_children();      // (2); +inf past the budget
            if constexpr (constrained) {  // (3) by the handler's order
                visit_policy(replacement, [&](const auto& r) {
                    std::span<const double> fp = fsel, fc = pop.children_fitness();
                    if (apm && std::decay_t<decltype(r)>::ranks_children) {
                        pop.penalise(true, pool_keys);
                        fp = std::span<const double>(pool_keys).first(n);
                        fc = std::span<const double>(pool_keys).subspan(n);
                    }
                    r(by, fp, pop.violations(), fc, pop.children_violations(), chosen, scratch);
                });
            } else {
                with_context(replacement, context, fx, pop.children_fitness(), chosen, scratch);  // (3)
            }
            for (std::size_t k = 0; k < n; ++k) pop.take(k, chosen[k]);
            pop.advance();
            context.describe(t + 1, pop.fitness(), state.best());
            hook(std::as_const(context), pop, rng);
            // A hook may have renewed members: the next generation's operators see them as they are.
            if constexpr (!std::is_same_v<Hook, NoGenerationHook>) context.describe(t + 1, pop.fitness(), state.best());
            pop.end_iteration(observer);
        }
        return pop.finish();
    }
};

/// The GA on chains (grid paths, ...): the same skeleton with the chain operator policies.
using ChainGa = Ga<TournamentSelection, ChainCrossover, ChainMutation>;

/// Zhang et al.'s (2025) IQGA on chain spaces with regions, two-point crossover and numbered mutations
/// (iqga_operators.hpp); elitist replacement with elitism 1. Its initial chains are the problem's
/// (on grids: SITP walks when the space is set so, as the registry entry iqga does by default).
using IqgaGa = Ga<RegionTournamentSelection, EliteCrossover, IqgaMutation>;

}  // namespace pride

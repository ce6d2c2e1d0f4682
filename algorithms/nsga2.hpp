#pragma once
// NSGA-II on boxes and on chains.
//
//   Deb, K., Pratap, A., Agarwal, S. and Meyarivan, T. (2002). A fast and elitist multiobjective
//     genetic algorithm: NSGA-II. IEEE Transactions on Evolutionary Computation 6(2), 182-197.
//
// The paper numbers no equations; its sections are cited instead. One generation t (sec. III-C):
//   (1) the offspring Q_t, N of them: parents by binary tournament on the crowded-comparison
//       operator <_n (sec. III-B: the lower front rank wins, then the larger crowding distance),
//       two children per pair by the Crossover policy (SBX), each then through the Mutation policy
//       (polynomial); sec. V's settings: p_c = 0.9, eta_c = 20, p_m = 1/n, eta_m = 20;
//   (2) Q_t evaluated;
//   (3) R_t = P_t u Q_t sorted into fronts (sec. III-A, framework/pareto/sorting.hpp); P_{t+1}
//       takes whole fronts in order while they fit, then the members of the first front that does
//       not fit with the largest crowding distances (the Survival policy: CrowdingSurvival; NSGA-III's
//       reference directions are the other policy of this skeleton); each member of P_{t+1} keeps
//       its rank and crowding distance for the tournaments of (1).
// The initial population: uniform in the box (on chains: the space's random chains), evaluated,
// ranked and crowded, recorded as iteration 0.
// On chains (grid paths) the skeleton is the same and only the variation differs: the
// chain operators as policies (Nsga2<ChainCrossover, ChainMutationChoice>: crossover at a common
// cell with p_c = 0.9, then per child, with probability p_m, one of the GA's and IQGA's mutations;
// algorithms/parts/variation/chain_operators.hpp). The paper's p_m = 1/n per variable has no chain form;
// decided by this project: p_m per child (the registry's default says which value).
// The result: the non-dominated members of the final population.
// Typed spaces (framework/variables.hpp), which the paper does not treat: with `round_integers`
// every member's integer and categorical coordinates are on their values (the initial ones, and
// the children after the variation), and the categorical coordinates get uniform crossover and
// random resetting instead of SBX and the mutation (categorical.hpp): the operators of pymoo's
// mixed-variable GA, which pymoo runs as NSGA-II with its RankAndCrowding survival. Where pride
// differs from that: NSGA-II's crowded tournament here, pymoo's random mating there; p_m = 1/n over
// all the real-coded coordinates, pymoo's 1 / (the number of variables of each type); no
// elimination of duplicates (pymoo's MixedVariableDuplicateElimination).
//
// Where the paper is silent this follows Deb's reference code (nsga2-gnu, revision 1.1.6), as
// pagmo2 does: the parents of the N children come from two random permutations of the population,
// each read four at a time (two tournaments, one pair, two children), so every member enters
// exactly two tournaments and N must be a multiple of 4; a tournament whose two entrants tie on
// <_n is decided by a fair coin. The code's tournament asks first which entrant dominates the
// other and only then compares crowding distances, where the paper compares ranks: `tournament =
// Tournament::code` is that reading (the two differ when neither entrant dominates the other but
// their ranks differ). Decided by this project: ties in crowding distance when a front is cut go
// to the lower index in R_t (parents before children), so that one seed gives one result; when
// the budget ends inside a generation, the children not evaluated have +inf in every objective.
#include <algorithm>
#include <concepts>
#include <cstdint>
#include <numeric>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "algorithms/parts/variation/categorical.hpp"
#include "algorithms/parts/variation/chain_operators.hpp"
#include "algorithms/parts/variation/crossover.hpp"
#include "algorithms/parts/variation/mutation.hpp"
#include "framework/error.hpp"
#include "framework/mo_run_state.hpp"
#include "framework/multi_objective.hpp"
#include "framework/observer.hpp"
#include "framework/pareto/constrained_sorting.hpp"
#include "framework/pareto/dominance.hpp"
#include "framework/pareto/sorting.hpp"
#include "framework/random.hpp"
#include "framework/termination.hpp"
#include "framework/variables.hpp"

namespace pride {

namespace nsga {

/// Each member's place for the tournaments: its front (0 = non-dominated) and crowding distance.
struct Standing {
    std::vector<std::size_t> rank;
    std::vector<double> crowding;
};

/// Buffers a survival step reuses from generation to generation.
struct SurvivalScratch {
    pareto::SortScratch sort;
    pareto::ConstrainedSortScratch ranking;
    std::vector<std::size_t> rank, by_front, front_start, members;
    std::vector<double> distance;
    std::vector<std::pair<double, std::size_t>> cut;
};

/// (3) NSGA-II's survival: whole fronts in order, the last one cut by crowding distance, largest
/// first (sec. III-C). Writes the `keep` survivors' columns of `f` into `chosen` and their
/// standing into `out`.
struct CrowdingSurvival {
    static constexpr const char* name = "crowding";
    static constexpr const char* algorithm = "nsga2";
    /// The tournaments compare the standing (a survival with no ranking of its own says false).
    static constexpr bool ranked_mating = true;
    void operator()(const Matrix& f, std::span<const double> v, std::size_t keep, std::vector<std::size_t>& chosen,
                    Standing& out, SurvivalScratch& s, Rng&) const {
        const auto n = static_cast<std::size_t>(f.cols());
        s.rank.resize(n);
        const std::size_t fronts = pareto::constrained_sort(f, v, std::span<std::size_t>(s.rank), s.ranking);
        // The members of each front, in index order (a counting sort on the rank).
        s.front_start.assign(fronts + 1, 0);
        for (const std::size_t r : s.rank) ++s.front_start[r + 1];
        for (std::size_t k = 0; k < fronts; ++k) s.front_start[k + 1] += s.front_start[k];
        s.by_front.resize(n);
        s.members.assign(s.front_start.begin(), s.front_start.end() - 1);  // next free slot per front
        for (std::size_t i = 0; i < n; ++i) s.by_front[s.members[s.rank[i]]++] = i;

        chosen.clear();
        out.rank.clear();
        out.crowding.clear();
        for (std::size_t k = 0; k < fronts && chosen.size() < keep; ++k) {
            const auto front = std::span<const std::size_t>(s.by_front)
                                   .subspan(s.front_start[k], s.front_start[k + 1] - s.front_start[k]);
            s.distance.resize(front.size());
            // A front of points not evaluated or with non-finite values (+inf in every objective,
            // mo_run_state.hpp: such points are only equal to each other) is not spread: 0 each.
            if (f.col(static_cast<Eigen::Index>(front[0])).allFinite())
                pareto::crowding_distance(f, front, std::span<double>(s.distance), s.sort);
            else
                std::fill(s.distance.begin(), s.distance.end(), 0.0);
            if (chosen.size() + front.size() <= keep) {
                for (std::size_t j = 0; j < front.size(); ++j) {
                    chosen.push_back(front[j]);
                    out.rank.push_back(k);
                    out.crowding.push_back(s.distance[j]);
                }
                continue;
            }
            s.cut.clear();
            for (std::size_t j = 0; j < front.size(); ++j) s.cut.emplace_back(s.distance[j], front[j]);
            const std::size_t take = keep - chosen.size();
            std::partial_sort(s.cut.begin(), s.cut.begin() + static_cast<std::ptrdiff_t>(take), s.cut.end(),
                              [](const auto& a, const auto& b) {
                                  return a.first > b.first || (a.first == b.first && a.second < b.second);
                              });
            for (std::size_t j = 0; j < take; ++j) {
                chosen.push_back(s.cut[j].second);
                out.rank.push_back(k);
                out.crowding.push_back(s.cut[j].first);
            }
        }
    }
};

/// The paper's settings of its operators on boxes (sec. V: eta_c = 20, p_c = 0.9; eta_m = 20,
/// p_m = 1/n, written as p_m < 0); other policies (on chains) keep their own defaults.
template <class Operator>
Operator default_operator() {
    if constexpr (std::is_same_v<Operator, SbxCrossover>)
        return SbxCrossover{20.0, 0.9};
    else if constexpr (std::is_same_v<Operator, PolynomialMutation>)
        return PolynomialMutation{20.0, -1.0};
    else
        return Operator{};
}

/// Which tournament decides between two entrants (see the header comment).
enum class Tournament { paper, code };

}  // namespace nsga

template <class Crossover = SbxCrossover, class Mutation = PolynomialMutation, class Survival = nsga::CrowdingSurvival>
struct Nsga2 {
    std::int64_t population = 100;  // N, a multiple of 4
    Crossover crossover = nsga::default_operator<Crossover>();
    Mutation mutation = nsga::default_operator<Mutation>();
    Survival survival{};
    nsga::Tournament tournament = nsga::Tournament::paper;
    bool round_integers = true;      // typed spaces: integer and categorical coordinates on their values
    CategoricalRates categorical{};  // and the categorical operators (categorical.hpp)

    /// nsga2, or nsga3 with NSGA-III's survival (algorithms/nsga3.hpp).
    static std::string name() { return Survival::algorithm; }

    void validate() const {
        require(population >= 4 && population <= 10'000'000 && population % 4 == 0, name(),
                "population must be a multiple of 4 in [4, 10000000] (two children per two tournaments), got " +
                    std::to_string(population));
        crossover.validate(name());
        mutation.validate(name());
        categorical.validate(name());
    }

    /// On boxes: SBX and polynomial mutation (the Crossover and Mutation policies' defaults).
    template <MultiObjectiveProblem P, class O = NoObserver>
    MultiObjectiveResult run(P problem, const Termination& termination, std::uint64_t seed, O&& observer = O{}) const {
        auto start = begin(problem, termination, seed);
        BoxPopulation<P> population(problem, static_cast<std::size_t>(this->population), crossover, mutation);
        if (round_integers) population.typed(categorical);
        return generations(population, start, observer);
    }

    /// On chains (grid paths, framework/multi_objective.hpp's MultiObjectiveChainProblem): the same
    /// generation with the chain policies (ChainCrossover: crossover at a common cell;
    /// ChainMutationChoice: the GA's and IQGA's mutations), from the space's random chains (random
    /// or SITP walks, as the space is set).
    template <MultiObjectiveChainProblem P, class O = NoObserver>
    BasicMultiObjectiveResult<std::vector<typename P::chain_type>> run(P problem, const Termination& termination,
                                                                       std::uint64_t seed, O&& observer = O{})
        const requires std::invocable<const Crossover&, P&, typename P::chain_type&, typename P::chain_type&, Rng&> &&
        std::invocable<const Mutation&, P&, typename P::chain_type&, Rng&> {
        auto start = begin(problem, termination, seed);
        ChainPopulation<P> population{problem, crossover, mutation, static_cast<std::size_t>(this->population)};
        return generations(population, start, observer);
    }

  private:
    /// One run's generations, whatever the members are (sec. III-C; BoxPopulation, ChainPopulation):
    /// R_t's 2N members, parents in the first N and children in the last N.
    template <class Population, class O>
    auto generations(Population& pop, MultiObjectiveStart& start, O& observer) const {
        Rng& rng = start.rng;
        MultiObjectiveRunState& state = start.state;
        const std::size_t n = pop.n;
        const auto mrows = static_cast<Eigen::Index>(start.objectives), cols = static_cast<Eigen::Index>(n);
        Matrix fr(mrows, 2 * cols), fnext(mrows, cols), fq(mrows, cols);
        // Violations beside the values (constraints only; empty otherwise): R_t's in vr, P_{t+1}'s in vnext.
        std::vector<double> vr(Population::constrained ? 2 * n : 0), vnext(Population::constrained ? n : 0);
        const auto children_v = vr.empty() ? std::span<double>() : std::span<double>(vr).subspan(n);
        pop.initialise(rng, state, fnext, std::span<double>(vnext));
        fr.leftCols(cols) = fnext;
        std::copy(vnext.begin(), vnext.end(), vr.begin());
        Generation g(n);
        g.rank_initial(*this, fnext, vnext, rng);
        pop.keep_parents();
        state.end_iteration(observer, pop.next, fnext);
        while (!state.done()) {
            // (1)
            g.mate(*this, fr, vr, rng,
                   [&](std::size_t a, std::size_t b, std::size_t child) { pop.breed(a, b, child, rng); });
            // (2)
            pop.evaluate_children(state, fq, children_v);
            fr.rightCols(cols) = fq;
            // (3)
            g.survive(*this, fr, vr, fnext, vnext, rng);
            pop.keep(g.chosen);
            fr.leftCols(cols) = fnext;
            std::copy(vnext.begin(), vnext.end(), vr.begin());
            state.end_iteration(observer, pop.next, fnext);
        }
        const auto front = g.first_front();
        return state.finish(pop.next, fnext, front, vnext);
    }

    /// Points of a box as matrix columns: R_t in `r`, P_{t+1} in `next`.
    template <class P>
    struct BoxPopulation {
        static constexpr bool constrained = ConstrainedMultiObjectiveProblem<P>;
        P& problem;
        std::size_t n, dim;
        Eigen::Index cols;
        std::span<const double> lo, hi;
        Matrix r, next;
        decltype(std::declval<const Crossover&>().prepare(std::size_t{})) cross;
        decltype(std::declval<const Mutation&>().prepare(std::size_t{})) mutate;

        BoxPopulation(P& p, std::size_t size, const Crossover& crossover, const Mutation& mutation)
            : problem(p),
              n(size),
              dim(p.dimension()),
              cols(static_cast<Eigen::Index>(size)),
              lo(p.lower()),
              hi(p.upper()),
              r(static_cast<Eigen::Index>(dim), 2 * cols),
              next(static_cast<Eigen::Index>(dim), cols),
              cross(crossover.prepare(dim)),
              mutate(mutation.prepare(dim)) {}

        Rounding discrete{};                // the typed space's rounding operator (empty: none)
        CategoricalVariation categories{};  // empty unless typed with categorical coordinates
        std::vector<std::size_t> categorical_index;

        /// The population in the problem's types (integer and categorical coordinates).
        void typed(CategoricalRates rates) {
            discrete = Rounding(problem);
            categories = CategoricalVariation(problem, rates);
            categorical_index = categorical_coordinates(problem);
        }

        void initialise(Rng& rng, MultiObjectiveRunState& state, Matrix& f, std::span<double> v) {
            for (Eigen::Index j = 0; j < cols; ++j) {
                for (std::size_t i = 0; i < dim; ++i) r(static_cast<Eigen::Index>(i), j) = rng.uniform(lo[i], hi[i]);
                const std::span<double> x = column(r, j);
                for (const std::size_t c : categorical_index) x[c] = choice_of_start(x[c], lo[c], hi[c]);
                discrete(x, lo, hi);
            }
            evaluate(state, r.leftCols(cols), f, v);
        }
        void evaluate(MultiObjectiveRunState& state, MatrixView points, Matrix& f, std::span<double> v) {
            if constexpr (constrained)
                state.evaluate_columns(problem, points, f, v);
            else
                state.evaluate_columns(problem, points, f);
        }
        void keep_parents() { next = r.leftCols(cols); }
        void breed(std::size_t a, std::size_t b, std::size_t child, Rng& rng) {
            const auto c1 = cols + static_cast<Eigen::Index>(child), c2 = c1 + 1;
            r.col(c1) = r.col(static_cast<Eigen::Index>(a));
            r.col(c2) = r.col(static_cast<Eigen::Index>(b));
            const std::span<double> x1 = column(r, c1), x2 = column(r, c2);
            categories.cross(x1, x2, rng, [&] { cross(x1, x2, lo, hi, rng); });
            categories.mutate(x1, rng, [&] { mutate(x1, lo, hi, rng); });
            categories.mutate(x2, rng, [&] { mutate(x2, lo, hi, rng); });
            discrete(x1, lo, hi);
            discrete(x2, lo, hi);
        }
        void evaluate_children(MultiObjectiveRunState& state, Matrix& f, std::span<double> v) {
            evaluate(state, r.rightCols(cols), f, v);
        }
        void keep(const std::vector<std::size_t>& chosen) {
            for (std::size_t k = 0; k < n; ++k)
                next.col(static_cast<Eigen::Index>(k)) = r.col(static_cast<Eigen::Index>(chosen[k]));
            r.leftCols(cols) = next;
        }
    };

    /// Cell chains: R_t in `r`, P_{t+1} in `next`; assignments keep each chain's storage, so no
    /// allocation once the run is warmed up.
    template <class P>
    struct ChainPopulation {
        using Chain = typename P::chain_type;
        static constexpr bool constrained = false;
        P& problem;
        const Crossover& crossover;
        const Mutation& mutation;
        std::size_t n;
        std::vector<Chain> r = std::vector<Chain>(2 * n), next = std::vector<Chain>(n);

        void initialise(Rng& rng, MultiObjectiveRunState& state, Matrix& f, std::span<double>) {
            for (std::size_t j = 0; j < n; ++j) problem.random_chain(rng, r[j]);
            state.evaluate_chains(problem, std::span<const Chain>(r).first(n), f);
        }
        void keep_parents() { std::copy(r.begin(), r.begin() + static_cast<std::ptrdiff_t>(n), next.begin()); }
        void breed(std::size_t a, std::size_t b, std::size_t child, Rng& rng) {
            Chain& c1 = r[n + child];
            Chain& c2 = r[n + child + 1];
            c1 = r[a];
            c2 = r[b];
            crossover(problem, c1, c2, rng);
            mutation(problem, c1, rng);
            mutation(problem, c2, rng);
        }
        void evaluate_children(MultiObjectiveRunState& state, Matrix& f, std::span<double>) {
            state.evaluate_chains(problem, std::span<const Chain>(r).subspan(n, n), f);
        }
        void keep(const std::vector<std::size_t>& chosen) {
            for (std::size_t k = 0; k < n; ++k) next[k] = r[chosen[k]];
            for (std::size_t k = 0; k < n; ++k) r[k] = next[k];
        }
    };

    /// Every check of the parameters and the stopping rules, then the run's generator and guard.
    template <class P>
    MultiObjectiveStart begin(P& problem, const Termination& termination, std::uint64_t seed) const {
        validate();
        auto start = start_multiobjective_run(name(), problem, termination, seed);
        if constexpr (requires { survival.validate(start.objectives, name()); })
            survival.validate(start.objectives, name());
        return start;
    }

    /// What a generation keeps besides the population, the same on boxes and chains: the standing
    /// for the tournaments, the permutations, the survivors and the survival's buffers.
    struct Generation {
        std::size_t n;
        nsga::Standing standing;
        nsga::SurvivalScratch scratch;
        std::vector<std::size_t> chosen, perm;
        explicit Generation(std::size_t size) : n(size), perm(size) {}

        /// The initial population's standing, in its own order (every member survives; the
        /// survival lists them by front).
        void rank_initial(const Nsga2& a, const Matrix& f0, std::span<const double> v0, Rng& rng) {
            a.survival(f0, v0, n, chosen, standing, scratch, rng);
            nsga::Standing ordered{std::vector<std::size_t>(n), std::vector<double>(n)};
            for (std::size_t k = 0; k < n; ++k) {
                ordered.rank[chosen[k]] = standing.rank[k];
                ordered.crowding[chosen[k]] = standing.crowding[k];
            }
            standing = std::move(ordered);
        }

        /// (1) two permutations, four entrants at a time: two tournaments, then breed(a, b, child)
        /// makes children `child` and `child + 1` (counted from 0) of parents a and b.
        template <class Breed>
        void mate(const Nsga2& a, const Matrix& fr, std::span<const double> vr, Rng& rng, Breed&& breed) {
            std::size_t child = 0;
            for (int pass = 0; pass < 2; ++pass) {
                std::iota(perm.begin(), perm.end(), std::size_t{0});
                for (std::size_t i = n; i > 1; --i)
                    std::swap(perm[i - 1], perm[static_cast<std::size_t>(rng.below(i))]);
                for (std::size_t i = 0; i + 3 < n; i += 4) {
                    const std::size_t p1 = a.winner(perm[i], perm[i + 1], fr, vr, standing, rng);
                    const std::size_t p2 = a.winner(perm[i + 2], perm[i + 3], fr, vr, standing, rng);
                    breed(p1, p2, child);
                    child += 2;
                }
            }
        }

        /// (3) the survivors of R_t into `chosen` (indices into R_t), their values into fnext.
        void survive(const Nsga2& a, const Matrix& fr, std::span<const double> vr, Matrix& fnext,
                     std::span<double> vnext, Rng& rng) {
            a.survival(fr, vr, n, chosen, standing, scratch, rng);
            for (std::size_t k = 0; k < n; ++k)
                fnext.col(static_cast<Eigen::Index>(k)) = fr.col(static_cast<Eigen::Index>(chosen[k]));
            if (!vr.empty())
                for (std::size_t k = 0; k < n; ++k) vnext[k] = vr[chosen[k]];
        }

        /// The members of the first front, in population order.
        std::vector<std::size_t> first_front() const {
            std::vector<std::size_t> front;
            for (std::size_t k = 0; k < n; ++k)
                if (standing.rank[k] == 0) front.push_back(k);
            return front;
        }
    };

    /// The winner of a binary tournament between members a and b of the population.
    /// `v`: the members' violations (empty without constraints).
    std::size_t winner(std::size_t a, std::size_t b, const Matrix& f, std::span<const double> v,
                       const nsga::Standing& s, Rng& rng) const {
        if constexpr (!Survival::ranked_mating) {
            // Jain and Deb's (2014, part II) constrained tournament: the lesser violation wins (a
            // feasible entrant over an infeasible one); two feasible entrants, or equal violations,
            // a fair coin as without constraints.
            if (!v.empty() && v[a] != v[b]) return v[a] < v[b] ? a : b;
            return rng.uniform() <= 0.5 ? a : b;
        }
        if (tournament == nsga::Tournament::code) {
            const auto fa = pareto::point(f, static_cast<Eigen::Index>(a));
            const auto fb = pareto::point(f, static_cast<Eigen::Index>(b));
            const double va = v.empty() ? 0.0 : v[a], vb = v.empty() ? 0.0 : v[b];
            if (pareto::constrained_dominates(fa, va, fb, vb)) return a;
            if (pareto::constrained_dominates(fb, vb, fa, va)) return b;
        } else {
            if (s.rank[a] != s.rank[b]) return s.rank[a] < s.rank[b] ? a : b;
        }
        if (s.crowding[a] != s.crowding[b]) return s.crowding[a] > s.crowding[b] ? a : b;
        return rng.uniform() <= 0.5 ? a : b;
    }
};

}  // namespace pride

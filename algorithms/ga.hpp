#pragma once
// Genetic algorithm: real-coded on boxes, and on chains (grid paths) through the same skeleton.
//
//   Deb, K. and Agrawal, R. B. (1995). Simulated binary crossover for continuous search space.
//     Complex Systems 9, 115-148.
//   Deb, K. and Goyal, M. (1996). A combined genetic adaptive search (GeneAS) for engineering
//     design. Computer Science and Informatics 26(4), 30-45 (polynomial mutation).
//
// One generation:
//   (1) as many children as the Replacement policy asks for (N - elitism for the spec's elitist
//       replacement): two parents by the Selection policy, two children by the Crossover policy,
//       each child through the Mutation policy and the Bounds policy;
//   (2) the children are evaluated in order;
//   (3) the Replacement policy forms the next population from parents and children (elitist: the
//       `elitism` best parents, unchanged and not re-evaluated, then the children; plus: the best N
//       of parents and children, as pagmo2's sga).
// Spec defaults (shared/spec/algorithms.md): tournament of 2, SBX eta 15 with probability 0.9,
// polynomial mutation eta 20 with probability 1/D per gene, elitist replacement with elitism 1.
// Decided by this project where the spec is silent: when an odd number of children is asked for,
// the second child of the last pair is dropped; when the budget ends inside a generation the
// children not evaluated get fitness +inf, the generation is recorded, and the run stops.
#include <algorithm>
#include <cstdint>
#include <numeric>
#include <span>
#include <string>
#include <vector>

#include "algorithms/parts/chain_operators.hpp"
#include "algorithms/parts/crossover.hpp"
#include "algorithms/parts/mutation.hpp"
#include "algorithms/parts/replacement.hpp"
#include "algorithms/parts/selection.hpp"
#include "framework/bounds.hpp"
#include "framework/chain.hpp"
#include "framework/initializer.hpp"
#include "framework/observer.hpp"
#include "framework/problem.hpp"
#include "framework/random.hpp"
#include "framework/result.hpp"
#include "framework/run_state.hpp"
#include "framework/termination.hpp"

namespace pride {

template <class Selection = TournamentSelection, class Crossover = SbxCrossover, class Mutation = PolynomialMutation,
          class Bounds = Clamp, class Init = UniformInit, class Replacement = ElitistReplacement>
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

    std::string name() const { return id; }

    void validate() const {
        require(population >= 2, name(), "population must be >= 2, got " + std::to_string(population));
        replacement.validate(name(), population);
        selection.validate(name());
        crossover.validate(name());
        mutation.validate(name());
    }

    template <BoxProblem P, Observer O = NoObserver>
    Result run(P problem, const Termination& termination, std::uint64_t seed, O&& observer = O{}) const {
        validate();
        termination.validate(name());
        const auto n = static_cast<Eigen::Index>(population);
        const auto kids = static_cast<Eigen::Index>(replacement.offspring(population));
        const std::size_t dim = problem.dimension();
        const auto lo = problem.lower();
        const auto hi = problem.upper();

        Rng rng(seed);
        RunState state(termination, dim);
        const auto rows = static_cast<Eigen::Index>(dim);
        Matrix x(rows, n), next(rows, n), y(rows, kids), spare(rows, 1);
        std::vector<double> fx(static_cast<std::size_t>(n)), fnext(fx.size()), fy(static_cast<std::size_t>(kids));
        std::vector<std::size_t> chosen(static_cast<std::size_t>(n));
        ReplacementScratch scratch;

        const auto& cross = prepared(crossover, dim);
        const auto& mutate = prepared(mutation, dim);

        init(problem, rng, x);
        for (Eigen::Index i = 0; i < n; ++i) bounds(column(x, i), lo, hi);
        state.evaluate_columns(problem, x, fx);
        state.end_iteration(observer, x, fx);

        while (!state.done()) {
            for (Eigen::Index k = 0; k < kids; k += 2) {  // (1)
                const auto a = static_cast<Eigen::Index>(selection(fx, rng));
                const auto b = static_cast<Eigen::Index>(selection(fx, rng));
                y.col(k) = x.col(a);
                auto child2 = k + 1 < kids ? column(y, k + 1) : column(spare, 0);
                std::copy_n(x.col(b).data(), dim, child2.data());
                cross(column(y, k), child2, lo, hi, rng);
                mutate(column(y, k), lo, hi, rng);
                mutate(child2, lo, hi, rng);
                bounds(column(y, k), lo, hi);
                bounds(child2, lo, hi);
            }
            state.evaluate_columns(problem, y, fy);  // (2); +inf past the budget
            replacement(fx, fy, chosen, scratch);    // (3)
            for (Eigen::Index k = 0; k < n; ++k) {
                const auto from = static_cast<Eigen::Index>(chosen[static_cast<std::size_t>(k)]);
                next.col(k) = from < n ? x.col(from) : y.col(from - n);
                fnext[static_cast<std::size_t>(k)] =
                    from < n ? fx[static_cast<std::size_t>(from)] : fy[static_cast<std::size_t>(from - n)];
            }
            std::swap(x, next);
            std::swap(fx, fnext);
            state.end_iteration(observer, x, fx);
        }
        return state.finish();
    }

    /// The same generation on chains (framework/chain.hpp), with chain operator policies
    /// (ChainCrossover, ChainMutation): (1) selection, then the problem's crossover and mutation;
    /// (2) evaluation; (3) replacement. The initial population is the problem's random chains;
    /// Bounds and Init do not apply.
    template <ChainProblem P, class O = NoObserver>
    BasicResult<typename P::chain_type> run(P problem, const Termination& termination, std::uint64_t seed,
                                            O&& observer = O{}) const requires
        requires(const Crossover& c, const Mutation& m, P& p, typename P::chain_type& a, Rng& r) {
        c(p, a, a, r);
        m(p, a, r);
    }
    {
        using Chain = typename P::chain_type;
        validate();
        termination.validate(name());
        const auto n = static_cast<std::size_t>(population);
        const auto kids = static_cast<std::size_t>(replacement.offspring(population));
        Rng rng(seed);
        BasicRunState<Chain> state(termination);
        std::vector<Chain> x(n), next(n), y(kids);
        Chain spare;
        std::vector<double> fx(n, kInf), fnext(n), fy(kids);
        std::vector<std::size_t> chosen(n);
        ReplacementScratch scratch;

        for (auto& c : x) problem.random_chain(rng, c);
        for (std::size_t i = 0; i < n && !state.exhausted(); ++i) fx[i] = state.evaluate(problem, x[i]);
        state.end_iteration(observer, x, fx);

        while (!state.done()) {
            for (std::size_t k = 0; k < kids; k += 2) {  // (1)
                const std::size_t a = selection(fx, rng), b = selection(fx, rng);
                Chain& child2 = k + 1 < kids ? y[k + 1] : spare;
                y[k] = x[a];
                child2 = x[b];
                crossover(problem, y[k], child2, rng);
                mutation(problem, y[k], rng);
                mutation(problem, child2, rng);
            }
            for (std::size_t k = 0; k < kids; ++k)  // (2); +inf past the budget
                fy[k] = state.exhausted() ? kInf : state.evaluate(problem, y[k]);
            replacement(fx, fy, chosen, scratch);  // (3)
            for (std::size_t k = 0; k < n; ++k) {
                next[k] = chosen[k] < n ? x[chosen[k]] : y[chosen[k] - n];
                fnext[k] = chosen[k] < n ? fx[chosen[k]] : fy[chosen[k] - n];
            }
            std::swap(x, next);
            std::swap(fx, fnext);
            state.end_iteration(observer, x, fx);
        }
        return state.finish();
    }

  private:
    /// An operator policy may offer prepare(dim), its constants worked out once per run; the
    /// result lives as long as the run (lifetime extension of the temporary bound to a const&).
    template <class Op>
    static decltype(auto) prepared(const Op& op, std::size_t dim) {
        if constexpr (requires { op.prepare(dim); })
            return op.prepare(dim);
        else
            return (op);
    }
};

/// The GA on chains (grid paths, ...): the same skeleton with the chain operator policies.
using ChainGa = Ga<TournamentSelection, ChainCrossover, ChainMutation>;

}  // namespace pride

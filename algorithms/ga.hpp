#pragma once
// Real-coded genetic algorithm, generational with elitism.
//
//   Deb, K. and Agrawal, R. B. (1995). Simulated binary crossover for continuous search space.
//     Complex Systems 9, 115-148.
//   Deb, K. and Goyal, M. (1996). A combined genetic adaptive search (GeneAS) for engineering
//     design. Computer Science and Informatics 26(4), 30-45 (polynomial mutation).
//
// One generation:
//   (1) the `elitism` best members of the population pass on unchanged (and are not re-evaluated);
//   (2) until the new population is full: two parents by the Selection policy, two children by the
//       Crossover policy, each child through the Mutation policy and the Bounds policy;
//   (3) children are evaluated in order; the new population replaces the old.
// Spec defaults (shared/spec/algorithms.md): tournament of 2, SBX eta 15 with probability 0.9,
// polynomial mutation eta 20 with probability 1/D per gene, elitism 1.
// Decided by this project where the spec is silent: when an odd number of places is left the
// second child of the last pair is dropped; when the budget ends inside a generation the children
// not evaluated are discarded (their fitness shown as +inf) and the run stops.
#include <algorithm>
#include <cstdint>
#include <numeric>
#include <span>
#include <string>
#include <vector>

#include "algorithms/parts/crossover.hpp"
#include "algorithms/parts/mutation.hpp"
#include "algorithms/parts/selection.hpp"
#include "framework/bounds.hpp"
#include "framework/initializer.hpp"
#include "framework/observer.hpp"
#include "framework/problem.hpp"
#include "framework/random.hpp"
#include "framework/result.hpp"
#include "framework/run_state.hpp"
#include "framework/termination.hpp"

namespace pride {

template <class Selection = TournamentSelection, class Crossover = SbxCrossover, class Mutation = PolynomialMutation,
          class Bounds = Clamp, class Init = UniformInit>
class Ga {
public:
    std::int64_t population = 50;
    std::int64_t elitism = 1;
    Selection selection{};
    Crossover crossover{};
    Mutation mutation{};
    Bounds bounds{};
    Init init{};

    std::string name() const { return "ga"; }

    void validate() const {
        require(population >= 2, name(), "population must be >= 2, got " + std::to_string(population));
        require(elitism >= 0 && elitism < population, name(),
                "elitism must be in [0, population), got " + std::to_string(elitism));
        selection.validate(name());
        crossover.validate(name());
        mutation.validate(name());
    }

    template <BoxProblem P, Observer O = NoObserver>
    Result run(P problem, const Termination& termination, std::uint64_t seed, O&& observer = O{}) const {
        validate();
        termination.validate(name());
        const auto n = static_cast<Eigen::Index>(population);
        const auto elites = static_cast<Eigen::Index>(elitism);
        const std::size_t dim = problem.dimension();
        const auto lo = problem.lower();
        const auto hi = problem.upper();

        Rng rng(seed);
        RunState state(termination, dim);
        Matrix x(static_cast<Eigen::Index>(dim), n), y(x.rows(), n), spare(x.rows(), 1);
        std::vector<double> fx(static_cast<std::size_t>(n)), fy(fx.size());
        std::vector<std::size_t> order(fx.size());

        const auto& cross = prepared(crossover, dim);
        const auto& mutate = prepared(mutation, dim);

        init(problem, rng, x);
        for (Eigen::Index i = 0; i < n; ++i) bounds(column(x, i), lo, hi);
        state.evaluate_columns(problem, x, fx);
        state.end_iteration(observer, x, fx);

        while (!state.done()) {
            // (1) elites: a stable partial sort keeps the earlier member on ties.
            std::iota(order.begin(), order.end(), std::size_t{0});
            std::partial_sort(order.begin(), order.begin() + elites, order.end(),
                              [&](std::size_t a, std::size_t b) { return fx[a] < fx[b] || (fx[a] == fx[b] && a < b); });
            for (Eigen::Index e = 0; e < elites; ++e) {
                y.col(e) = x.col(static_cast<Eigen::Index>(order[static_cast<std::size_t>(e)]));
                fy[static_cast<std::size_t>(e)] = fx[order[static_cast<std::size_t>(e)]];
            }
            // (2) offspring
            for (Eigen::Index k = elites; k < n; k += 2) {
                const auto a = static_cast<Eigen::Index>(selection(fx, rng));
                const auto b = static_cast<Eigen::Index>(selection(fx, rng));
                const Eigen::Index second = k + 1 < n ? k + 1 : -1;
                y.col(k) = x.col(a);
                auto child2 = second >= 0 ? column(y, second) : column(spare, 0);
                std::copy_n(x.col(b).data(), dim, child2.data());
                cross(column(y, k), child2, lo, hi, rng);
                mutate(column(y, k), lo, hi, rng);
                mutate(child2, lo, hi, rng);
                bounds(column(y, k), lo, hi);
                bounds(child2, lo, hi);
            }
            // (3) evaluation and replacement
            const Eigen::Index evaluated = elites + evaluate_offspring(problem, state, y, elites, fy);
            if (evaluated < n) {  // budget spent inside the generation: record it and stop
                std::fill(fy.begin() + evaluated, fy.end(), kInf);
                state.end_iteration(observer, y, fy);
                break;
            }
            std::swap(x, y);
            std::swap(fx, fy);
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

    template <class P>
    static Eigen::Index evaluate_offspring(P& problem, RunState& state, const Matrix& y, Eigen::Index first,
                                           std::vector<double>& fy) {
        Eigen::Index done = 0;
        for (Eigen::Index k = first; k < y.cols() && !state.exhausted(); ++k, ++done)
            fy[static_cast<std::size_t>(k)] = state.evaluate(problem, column(y, k));
        return done;
    }
};

}  // namespace pride

#pragma once
// The chain concept: problems whose solutions are variable-length chains (cell chains on a grid,
// say) searched with discrete operators rather than through a box. The operators belong to the
// problem (the path space), so an algorithm on chains still contains no grid code: it only calls
//   random_chain(rng, c)   a random feasible chain into c;
//   crossover(a, b, rng)   a and b become two children; false when they cannot be crossed;
//   mutate(c, rng)         a changed, still feasible, chain;
//   evaluate(c)            the value to minimise.
// The operators are non-const so that a problem may keep scratch; each run owns its copy.
#include <concepts>
#include <cstddef>
#include <utility>

#include "framework/random.hpp"

namespace pride {

/// The three operators alone, what operator policies need (a space of several objectives has them
/// and evaluates otherwise: framework/multi_objective.hpp).
template <class P>
concept ChainOperators = std::copy_constructible<P> &&
    requires(P& p, Rng& rng, typename P::chain_type& a, typename P::chain_type& b) {
    typename P::chain_type;
    { p.random_chain(rng, a) } -> std::same_as<void>;
    { p.crossover(a, b, rng) } -> std::same_as<bool>;
    { p.mutate(a, rng) } -> std::same_as<void>;
};

template <class P>
concept ChainProblem = ChainOperators<P> && requires(const typename P::chain_type& a, P& p) {
    { p.evaluate(a) } -> std::convertible_to<double>;
};

}  // namespace pride

namespace pride {

// Optional capabilities of a chain problem, for algorithms that need more than the four operators
// above (Zhang et al.'s (2025) IQGA). An algorithm asks for them through these concepts (`if constexpr
// (NumberedMutations<P>)`, or as a requirement), never through a problem's types.

/// Several numbered mutation operators, so that a policy can pick operator k (IQGA's Q-learning
/// actions order three of them). `badness` in [0, 1] says how bad the chain is in its population
/// (Zhang et al. 2025, eq. 20's B: 0 the best, 1 the worst); operators that ignore it may; 0 when unknown.
template <class P>
concept NumberedMutations = ChainOperators<P> &&
    requires(P& p, const P& cp, Rng& rng, typename P::chain_type& a, std::size_t k, double badness) {
    { cp.mutation_count() } -> std::convertible_to<std::size_t>;
    { p.mutate(k, a, rng) } -> std::same_as<void>;
    { p.mutate(k, a, rng, badness) } -> std::same_as<void>;
};

/// Chains fall into numbered regions of the search space, 0..region_count() - 1 (IQGA's
/// region-partitioned selection, eqs. 14-16) of Zhang et al. (2025).
template <class P>
concept RegionOf = ChainProblem<P> && requires(const P& cp, const typename P::chain_type& a) {
    { cp.region_count() } -> std::convertible_to<std::size_t>;
    { cp.region(a) } -> std::convertible_to<std::size_t>;
};

/// A crossover at two cut points that swaps the parts between them (Zhang et al. 2025, fig. 7); false, the
/// parents left as they were, when the two cannot be crossed.
template <class P>
concept TwoPointCrossover = ChainProblem<P> &&
    requires(P& p, Rng& rng, typename P::chain_type& a, typename P::chain_type& b) {
    { p.crossover_two_point(a, b, rng) } -> std::same_as<bool>;
};

/// The length of a chain (on grids: the path's length, eq. 8) of Zhang et al. (2025), for operators whose choices
/// follow the best path's length rather than its value (IQGA's Q-learning states).
template <class P>
concept ChainLength = ChainProblem<P> && requires(const P& cp, const typename P::chain_type& a) {
    { cp.length(a) } -> std::convertible_to<double>;
};

/// The part of a chain between positions i < j (both kept) made anew; false, the chain unchanged,
/// when it cannot be (positions out of range or not ordered).
template <class P>
concept SegmentRegeneration = ChainProblem<P> && requires(P& p, Rng& rng, typename P::chain_type& a, std::size_t i) {
    { p.regenerate(a, i, i, rng) } -> std::same_as<bool>;
};

}  // namespace pride

namespace pride {

/// Moving one chain towards another (Cai and Du's (2021) whale moves on grids): `a` takes a share `w` in
/// [0, 1] of `b`'s course (0 barely, 1 as much as the space allows), stays feasible, and `b` may be
/// `a` itself (a perturbation of `a`'s own course).
template <class P>
concept TowardMoves = ChainProblem<P> &&
    requires(P& p, Rng& rng, typename P::chain_type& a, const typename P::chain_type& b, double w) {
    { p.toward(a, b, w, rng) } -> std::same_as<void>;
};

/// A chain made shorter in place and kept feasible (on grids: Cai and Du's (2021) line-of-sight shortcut),
/// for algorithms that shorten every chain they make.
template <class P>
concept Shortening = ChainProblem<P> && requires(P& p, typename P::chain_type& a) {
    { p.shorten(a) } -> std::same_as<void>;
};

}  // namespace pride

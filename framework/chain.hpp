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
#include <utility>

#include "framework/random.hpp"

namespace pride {

template <class P>
concept ChainProblem = std::copy_constructible<P> &&
    requires(P& p, const P& cp, Rng& rng, typename P::chain_type& a, typename P::chain_type& b) {
    typename P::chain_type;
    { p.random_chain(rng, a) } -> std::same_as<void>;
    { p.crossover(a, b, rng) } -> std::same_as<bool>;
    { p.mutate(a, rng) } -> std::same_as<void>;
    { p.evaluate(std::as_const(a)) } -> std::convertible_to<double>;
};

}  // namespace pride

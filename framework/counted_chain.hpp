#pragma once
// The counted route to a chain problem's objective. Some chain operators score candidates with
// the objective while they build a chain (Zhang et al.'s (2025) SITP keeps the best of N/8 walks per segment
// by it); every such call is an evaluation like any other (docs/architecture.md: "every
// call, of a whole solution or a partial one, is counted and bounded by the budget"). A chain
// space offers those operators in a scored form, `op(..., score)`, whose last argument is the
// only way they may reach the objective; CountedChains is the chain problem an algorithm's
// operators see: every operator forwarded, the scored forms given a score bound to the run's
// evaluation guard. The space's unscored forms refuse to score by the objective (a logic_error),
// so an operator that would call it outside the budget fails loudly instead of spending silently.
#include <cstddef>
#include <utility>

#include "framework/chain.hpp"
#include "framework/random.hpp"

namespace pride {

/// The score a chain operator gets: one counted evaluation per call (the value of a partial
/// chain: not a solution, so never the best), +inf without a call once the budget is spent.
template <class P, class State>
class ChainScore {
  public:
    ChainScore(const P& problem, State& state) noexcept : problem_(&problem), state_(&state) {}
    double operator()(const typename P::chain_type& c) const { return state_->evaluate_partial(*problem_, c); }

  private:
    const P* problem_;
    State* state_;
};

/// A chain problem seen through the run's evaluation guard `state` (a BasicRunState): made for
/// each operator call, so it holds two pointers for the length of that call only.
template <ChainProblem P, class State>
class CountedChains {
  public:
    using chain_type = typename P::chain_type;

    CountedChains(P& problem, State& state) noexcept : p_(&problem), s_(&state) {}

    // The four operators of ChainProblem.
    void random_chain(Rng& rng, chain_type& c) {
        if constexpr (requires { p_->random_chain(rng, c, score()); })
            p_->random_chain(rng, c, score());
        else
            p_->random_chain(rng, c);
    }
    bool crossover(chain_type& a, chain_type& b, Rng& rng) {
        if constexpr (requires { p_->crossover(a, b, rng, score()); })
            return p_->crossover(a, b, rng, score());
        else
            return p_->crossover(a, b, rng);
    }
    void mutate(chain_type& c, Rng& rng) {
        if constexpr (requires { p_->mutate(c, rng, score()); })
            p_->mutate(c, rng, score());
        else
            p_->mutate(c, rng);
    }
    double evaluate(const chain_type& c) const { return p_->evaluate(c); }

    // The optional capabilities, offered exactly when the problem offers them.
    std::size_t mutation_count() const requires NumberedMutations<P> { return p_->mutation_count(); }
    void mutate(std::size_t k, chain_type& c, Rng& rng, double badness = 0.0) requires NumberedMutations<P> {
        if constexpr (requires { p_->mutate(k, c, rng, badness, score()); })
            p_->mutate(k, c, rng, badness, score());
        else
            p_->mutate(k, c, rng, badness);
    }
    std::size_t region_count() const requires RegionOf<P> { return p_->region_count(); }
    std::size_t region(const chain_type& c) const requires RegionOf<P> { return p_->region(c); }
    bool crossover_two_point(chain_type& a, chain_type& b, Rng& rng) requires TwoPointCrossover<P> {
        if constexpr (requires { p_->crossover_two_point(a, b, rng, score()); })
            return p_->crossover_two_point(a, b, rng, score());
        else
            return p_->crossover_two_point(a, b, rng);
    }
    double length(const chain_type& c) const requires ChainLength<P> { return p_->length(c); }
    bool regenerate(chain_type& c, std::size_t i, std::size_t j, Rng& rng) requires SegmentRegeneration<P> {
        if constexpr (requires { p_->regenerate(c, i, j, rng, score()); })
            return p_->regenerate(c, i, j, rng, score());
        else
            return p_->regenerate(c, i, j, rng);
    }
    void toward(chain_type& a, const chain_type& b, double w, Rng& rng) requires TowardMoves<P> {
        if constexpr (requires { p_->toward(a, b, w, rng, score()); })
            p_->toward(a, b, w, rng, score());
        else
            p_->toward(a, b, w, rng);
    }
    void shorten(chain_type& c) requires Shortening<P> {
        if constexpr (requires { p_->shorten(c, score()); })
            p_->shorten(c, score());
        else
            p_->shorten(c);
    }

  private:
    ChainScore<P, State> score() const noexcept { return {*p_, *s_}; }
    P* p_;
    State* s_;
};

}  // namespace pride

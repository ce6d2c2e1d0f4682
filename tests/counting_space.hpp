#pragma once
// A chain space seen from outside: every call of its objective counted (whole chains through
// evaluate, and the partial ones its operators score, which reach it through the score the run
// gives them: ChainScore calls this wrapper's evaluate), every operator and capability forwarded
// in both forms, scored and unscored. The count must equal the run's `evaluations`.
#include <cstddef>
#include <cstdint>
#include <memory>

#include "framework/chain.hpp"
#include "framework/random.hpp"

namespace pride::test {

template <class Space>
struct CountingSpace {
    Space space;
    std::shared_ptr<std::int64_t> count = std::make_shared<std::int64_t>(0);
    using chain_type = typename Space::chain_type;

    double evaluate(const chain_type& c) const {
        ++*count;
        return space.evaluate(c);
    }
    template <class... Score>
    void random_chain(Rng& rng, chain_type& out, Score&&... score) {
        space.random_chain(rng, out, score...);
    }
    template <class... Score>
    bool crossover(chain_type& a, chain_type& b, Rng& rng, Score&&... score) {
        return space.crossover(a, b, rng, score...);
    }
    template <class... Score>
    void mutate(chain_type& c, Rng& rng, Score&&... score) {
        space.mutate(c, rng, score...);
    }
    std::size_t region_count() const requires RegionOf<Space> { return space.region_count(); }
    std::size_t region(const chain_type& c) const requires RegionOf<Space> { return space.region(c); }
    template <class... Score>
    bool crossover_two_point(chain_type& a, chain_type& b, Rng& rng,
                             Score&&... score) requires TwoPointCrossover<Space> {
        return space.crossover_two_point(a, b, rng, score...);
    }
    std::size_t mutation_count() const requires NumberedMutations<Space> { return space.mutation_count(); }
    void mutate(std::size_t k, chain_type& c, Rng& rng, double badness = 0.0) requires NumberedMutations<Space> {
        space.mutate(k, c, rng, badness);
    }
    template <class Score>
    void mutate(std::size_t k, chain_type& c, Rng& rng, double badness,
                Score&& score) requires NumberedMutations<Space> {
        space.mutate(k, c, rng, badness, score);
    }
    double length(const chain_type& c) const requires ChainLength<Space> { return space.length(c); }
    template <class... Score>
    bool regenerate(chain_type& c, std::size_t i, std::size_t j, Rng& rng,
                    Score&&... score) requires SegmentRegeneration<Space> {
        return space.regenerate(c, i, j, rng, score...);
    }
    template <class... Score>
    void toward(chain_type& c, const chain_type& t, double w, Rng& rng, Score&&... score) requires TowardMoves<Space> {
        space.toward(c, t, w, rng, score...);
    }
    template <class... Score>
    void shorten(chain_type& c, Score&&... score) requires Shortening<Space> {
        space.shorten(c, score...);
    }
};

}  // namespace pride::test

namespace pride::test {

/// The objective of a chain space as the score its operators take, for tests that call an operator
/// by itself, outside a run (no budget to count against).
template <class Space>
auto uncounted_score(const Space& space) {
    return [&space](const typename Space::chain_type& c) { return space.evaluate(c); };
}

}  // namespace pride::test

#pragma once
// The GA's per-generation hook, in the spirit of ParadisEO's eoCheckpoint: a policy called once a
// generation, after replacement, with the generation's context (generation_context.hpp), the
// population and the run's Rng, before the generation is recorded. Variants that act on the whole
// population between generations are written as hooks, not as changes to the loop: ICGA's
// catastrophe, say, renews all but the elite when context.stagnation reaches a multiple of k.
//
// The population a hook is given (algorithms/parts/ga/population.hpp) offers, for points and
// chains alike: size(); fitness(), the current members' values; individual(i); and renew(indices,
// rng), which replaces those members by new ones from the run's initialisation (the Init and
// Bounds policies for points, the problem's random chains for chains) and evaluates them in order
// through the run's evaluation guard (+inf past the budget). A hook that offers validate(where) is
// checked with the GA's parameters.
#include "algorithms/parts/ga/generation_context.hpp"
#include "framework/random.hpp"

namespace pride {

/// The default: nothing, at no cost (an empty inline call).
struct NoGenerationHook {
    template <class Population>
    void operator()(const GenerationContext&, Population&, Rng&) const noexcept {}
};

}  // namespace pride

#pragma once
// Initialisers: how a population's first positions are drawn. Policies of every algorithm.
#include <cstddef>

#include "framework/problem.hpp"
#include "framework/random.hpp"

namespace pride {

/// Uniform in the box, column by column, coordinate by coordinate (a fixed draw order, so the
/// population depends on the seed alone).
struct UniformInit {
    template <BoxProblem P>
    void operator()(const P& p, Rng& rng, Matrix& pop) const {
        const auto lo = p.lower();
        const auto hi = p.upper();
        for (Eigen::Index j = 0; j < pop.cols(); ++j)
            for (Eigen::Index i = 0; i < pop.rows(); ++i)
                pop(i, j) = rng.uniform(lo[static_cast<std::size_t>(i)], hi[static_cast<std::size_t>(i)]);
    }
};

/// The problem's own starting points when it offers them (SuggestsStartingPoints), otherwise
/// uniform in the box. ILSO's rough-set initialisation on grids reaches algorithms this way.
struct SuggestedInit {
    template <BoxProblem P>
    void operator()(const P& p, Rng& rng, Matrix& pop) const {
        if constexpr (SuggestsStartingPoints<P>)
            p.starting_points(rng, pop);
        else
            UniformInit{}(p, rng, pop);
    }
};

/// Uniform, or the problem's suggestions when `suggestions` is set and the problem offers them:
/// the same choice as SuggestedInit, but made at run time (the command line's --init walk).
struct SelectableInit {
    bool suggestions = false;
    template <BoxProblem P>
    void operator()(const P& p, Rng& rng, Matrix& pop) const {
        if constexpr (SuggestsStartingPoints<P>) {
            if (suggestions) {
                p.starting_points(rng, pop);
                return;
            }
        }
        UniformInit{}(p, rng, pop);
    }
};

}  // namespace pride

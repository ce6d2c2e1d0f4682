#pragma once
// NSGA-III (Deb and Jain 2014): the NSGA-II skeleton (algorithms/nsga2.hpp) with the survival by
// reference directions (algorithms/parts/nsga3/survival.hpp), and the paper's settings. Where the
// paper is silent this project decided in those two headers (degenerate hyperplanes, ties, p_m).
#include <cstdint>
#include <utility>

#include "algorithms/nsga2.hpp"
#include "algorithms/parts/nsga3/survival.hpp"

namespace pride {

template <class Crossover = SbxCrossover, class Mutation = PolynomialMutation>
using Nsga3 = Nsga2<Crossover, Mutation, nsga::ReferenceDirectionSurvival>;

/// NSGA-III on the reference directions `directions` (M rows, one column each) with the paper's
/// settings (sec. V-A, Table I-II): N the smallest multiple of 4 not below the number of
/// directions, SBX with eta_c = 30 and p_c = 1, polynomial mutation with eta_m = 20 and p_m = 1/n.
inline Nsga3<> make_nsga3(Matrix directions) {
    Nsga3<> a;
    a.population = (static_cast<std::int64_t>(directions.cols()) + 3) / 4 * 4;
    a.crossover = SbxCrossover{30.0, 1.0};
    a.mutation = PolynomialMutation{20.0, -1.0};
    a.survival.directions = std::move(directions);
    return a;
}

}  // namespace pride

#pragma once
// Observers: a callback at the end of every iteration with read access to the population, for
// logs and plots of where a swarm searched. The default observer does nothing and costs nothing.
#include <concepts>
#include <cstdint>
#include <span>

#include "framework/problem.hpp"

namespace pride {

/// What an observer sees. `Best` is the best solution so far (a span for box algorithms, a chain
/// for chain algorithms); `Population` the individuals as the algorithm moved them.
template <class Best, class Population>
struct BasicIterationView {
    std::int64_t iteration;  // 0 = the initial population
    std::int64_t evaluations;
    double best_f;
    Best best_x;
    const Population& population;     // box algorithms: one column per individual
    std::span<const double> fitness;  // of those individuals (+inf where not evaluated)
};

using IterationView = BasicIterationView<std::span<const double>, Matrix>;

/// An observer of box algorithms; chain algorithms call theirs with their own view type.
template <class O>
concept Observer = std::invocable<O&, const IterationView&>;

struct NoObserver {
    template <class View>
    void operator()(const View&) const noexcept {}
};

}  // namespace pride

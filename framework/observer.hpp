#pragma once
// Observers: a callback at the end of every iteration with read access to the population, for
// logs and plots of where a swarm searched. The default observer does nothing and costs nothing.
#include <concepts>
#include <cstdint>
#include <span>

#include "framework/problem.hpp"

namespace pride {

struct IterationView {
    std::int64_t iteration;  // 0 = the initial population
    std::int64_t evaluations;
    double best_f;
    std::span<const double> best_x;
    const Matrix& population;         // one column per individual, as the algorithm moved them
    std::span<const double> fitness;  // of those columns (+inf where not evaluated)
};

template <class O>
concept Observer = std::invocable<O&, const IterationView&>;

struct NoObserver {
    void operator()(const IterationView&) const noexcept {}
};

}  // namespace pride

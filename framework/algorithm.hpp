#pragma once
// The algorithm concept: an algorithm is a value (its parameters and policies, validated when it
// is built) with a run() that takes its own copy of a problem, the stopping rules and a seed.
#include <concepts>
#include <cstdint>
#include <string>

#include "framework/observer.hpp"
#include "framework/problem.hpp"
#include "framework/result.hpp"
#include "framework/termination.hpp"

namespace pride {

template <class A, class P>
concept AlgorithmFor = BoxProblem<P> &&
    requires(const A& a, P p, const Termination& t, std::uint64_t seed, NoObserver& observer) {
    { a.name() } -> std::convertible_to<std::string>;
    { a.run(p, t, seed, observer) } -> std::same_as<Result>;
};

}  // namespace pride

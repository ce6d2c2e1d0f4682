#pragma once
// What a GA generation knows of itself, for operators whose rates adapt as the run goes (Srinivas
// and Patnaik's adaptive pc and pm read the population's best, mean and worst fitness) and for the
// per-generation hook (a catastrophe after k generations without improvement). The GA keeps one
// context per run and brings it up to date once per generation, so it costs O(N) per generation and
// nothing per evaluation. A policy sees it only if it asks: one whose call also accepts a trailing
// `const GenerationContext&` gets it (with_context), every other policy is called as before.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <type_traits>
#include <utility>

#include "framework/one_of.hpp"

namespace pride {

struct GenerationContext {
    /// Generations completed: t while generation t (0-based) is being made, t + 1 in the hook after
    /// its replacement (the same count as the run's iterations).
    std::int64_t iteration = 0;
    std::optional<std::int64_t> horizon;  // T (Termination::horizon), when a limit gives it
    // Of the current population (the parents while a generation is made); members not evaluated
    // because the budget ran out count as +inf. mean is kept within [best, worst] against rounding.
    double best = std::numeric_limits<double>::infinity();
    double mean = std::numeric_limits<double>::infinity();
    double worst = std::numeric_limits<double>::infinity();
    double best_so_far = std::numeric_limits<double>::infinity();  // the best value the run ever evaluated
    std::int64_t stagnation = 0;                                   // generations since best_so_far last improved
    std::span<const double> fitness;                               // the current population's, by index
    // While a pair is varied: the parents (indices into `fitness`), the children starting as copies
    // of parents[0] and parents[1]; and, while one child is mutated, which (0 or 1). For operators
    // whose rates depend on the individuals' own fitness (IAGA's f' and f).
    std::array<std::size_t, 2> parents{};
    std::size_t child = 0;
    // The region of each current member (framework/chain.hpp's RegionOf), by index; filled only for
    // a Selection policy that declares `uses_regions` and a chain space that has regions, else empty.
    std::span<const std::size_t> regions;
    // The length of the population's best member (the first of the smallest values) when the
    // population is of a chain space with lengths (framework/chain.hpp's ChainLength), else empty;
    // for a Q-learning whose states follow the best path's length (IQGA).
    std::optional<double> best_length;

    /// Describes the population `f` after `completed` generations, `best_ever` the run's best:
    /// the stagnation count restarts when best_ever improved on the last description's, and grows
    /// by one when a later generation did not improve it (0 for the initial population). The same
    /// generation may be described again (after a hook changed the population): then it only
    /// restarts, on an improvement.
    void describe(std::int64_t completed, std::span<const double> f, double best_ever) {
        if (completed == 0 || best_ever < best_so_far)
            stagnation = 0;
        else if (completed > iteration)
            ++stagnation;
        iteration = completed;
        best_so_far = best_ever;
        fitness = f;
        best = worst = f.empty() ? std::numeric_limits<double>::infinity() : f[0];
        double sum = 0.0;
        for (const double v : f) {
            best = std::min(best, v);
            worst = std::max(worst, v);
            sum += v;
        }
        mean = f.empty() ? best : std::clamp(sum / static_cast<double>(f.size()), best, worst);
    }
};

namespace detail {
template <class... P>
std::true_type derives_one_of(const OneOf<P...>*);
std::false_type derives_one_of(const void*);
}  // namespace detail

/// A OneOf policy (framework/one_of.hpp): each alternative is asked on its own.
template <class T>
concept OneOfPolicy = decltype(detail::derives_one_of(static_cast<const T*>(nullptr)))::value;

namespace detail {
template <class Op, class... Args>
struct callable_with_or_without_context
    : std::bool_constant<std::is_invocable_v<const Op&, Args...> ||
                         std::is_invocable_v<const Op&, Args..., const GenerationContext&>> {};
template <class... P, class... Args>
struct callable_with_or_without_context<OneOf<P...>, Args...>
    : std::bool_constant<(callable_with_or_without_context<P, Args...>::value && ...)> {};
}  // namespace detail

/// A policy with_context can call on `args` (every alternative of a OneOf).
template <class Op, class... Args>
concept OperatorOn = detail::callable_with_or_without_context<Op, Args...>::value;

/// op(args..., context) when the policy takes the context, op(args...) otherwise; for a OneOf, the
/// same question for the alternative it holds.
template <class Op, class... Args>
decltype(auto) with_context(const Op& op, const GenerationContext& context, Args&&... args) {
    if constexpr (OneOfPolicy<Op>)
        return op.visit(
            [&](const auto& alternative) -> decltype(auto) { return with_context(alternative, context, args...); });
    else if constexpr (requires { op(std::forward<Args>(args)..., context); })
        return op(std::forward<Args>(args)..., context);
    else
        return op(std::forward<Args>(args)...);
}

namespace detail {
/// An operator policy may offer prepare(dim), its constants worked out once per run (dim 0 on
/// chains), the prepared value then owned by the run; otherwise it is used as it is (a reference
/// to it). A prepared value may also offer begin_generation(const GenerationContext&, Rng&),
/// called once at the start of every generation, before its first selection, with the context of
/// the parents and the run's Rng: per-run state that learns from generation to generation (the
/// Q-learning operator choice of q_learning.hpp) lives there.
template <class Op>
decltype(auto) prepared(const Op& op, std::size_t dim) {
    if constexpr (requires { op.prepare(dim); })
        return op.prepare(dim);
    else
        return (op);
}
template <class Op>
using Prepared = decltype(prepared(std::declval<const Op&>(), std::size_t{}));
}  // namespace detail

/// A policy whose prepared form (detail::prepared) with_context can call on `args`.
template <class Op, class... Args>
concept PreparedOperatorOn = OperatorOn<std::remove_cvref_t<detail::Prepared<Op>>, Args...>;

}  // namespace pride

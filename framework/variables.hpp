#pragma once
// The type of each variable of a box problem: real (any value in [lower, upper]), integer (the
// integers lower, lower + 1, ..., upper) or categorical (one of upper - lower + 1 unordered
// choices, numbered lower ... upper, lower = 0). Points stay vectors of doubles: an algorithm
// that knows the types keeps its integer and categorical coordinates on their values; one that
// does not sees a box, and the problem rounds what it gets as its definition says.
#include <algorithm>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <span>
#include <string_view>

#include "framework/problem.hpp"

namespace pride {

enum class VariableType : unsigned char { real, integer, categorical };

/// "real", "integer", "categorical".
constexpr std::string_view type_name(VariableType t) noexcept {
    return t == VariableType::integer ? "integer" : t == VariableType::categorical ? "categorical" : "real";
}

/// A box problem that declares its variables' types (all real when it does not).
template <class P>
concept TypedVariables = BoxProblem<P> && requires(const P& p, std::size_t i) {
    { p.variable_type(i) } -> std::same_as<VariableType>;
};

/// The type of variable i of `p`: its declaration, or real.
template <BoxProblem P>
VariableType variable_type(const P& p, std::size_t i) {
    if constexpr (TypedVariables<P>)
        return p.variable_type(i);
    else
        return VariableType::real;
}

/// Whether some variable of `p` is not real.
template <BoxProblem P>
bool has_discrete_variables(const P& p) {
    if constexpr (TypedVariables<P>) {
        for (std::size_t i = 0; i < p.dimension(); ++i)
            if (p.variable_type(i) != VariableType::real) return true;
    }
    return false;
}

/// x with its integer and categorical coordinates put on their values, as a problem that takes
/// real values rounds them (COCO's rule: half-way cases up, then clamped to the bounds): the point
/// a result reports, in the problem's types, with the same f.
template <BoxProblem P>
void round_to_types(const P& p, std::span<double> x) {
    if constexpr (TypedVariables<P>) {
        for (std::size_t i = 0; i < x.size() && i < p.dimension(); ++i)
            if (p.variable_type(i) != VariableType::real)
                x[i] = std::clamp(std::floor(x[i] + 0.5), p.lower()[i], p.upper()[i]);
    }
}

}  // namespace pride

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
#include <vector>

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

/// A value of an integer or categorical coordinate put on its values, as a problem that takes real
/// values rounds it (COCO's rule: half-way cases up, then clamped to the bounds).
inline double round_to_value(double v, double lo, double hi) noexcept {
    return std::clamp(std::floor(v + 0.5), lo, hi);
}

/// x with its integer and categorical coordinates put on their values: the point a result
/// reports, in the problem's types, with the same f.
template <BoxProblem P>
void round_to_types(const P& p, std::span<double> x) {
    if constexpr (TypedVariables<P>) {
        for (std::size_t i = 0; i < x.size() && i < p.dimension(); ++i)
            if (p.variable_type(i) != VariableType::real) x[i] = round_to_value(x[i], p.lower()[i], p.upper()[i]);
    }
}

/// The coordinates of `p` that are not real, in order (computed once per run).
template <BoxProblem P>
std::vector<std::size_t> discrete_coordinates(const P& p) {
    std::vector<std::size_t> out;
    if constexpr (TypedVariables<P>) {
        for (std::size_t i = 0; i < p.dimension(); ++i)
            if (p.variable_type(i) != VariableType::real) out.push_back(i);
    }
    return out;
}

/// The rounding operator of a typed space: coordinates `which` of x put on their values. Every
/// box algorithm may apply it to the points it makes (`round_integers`), so that its population
/// holds values of the problem's types (rounded positions, rounded trials, rounded children).
inline void round_coordinates(std::span<double> x, std::span<const std::size_t> which, std::span<const double> lo,
                              std::span<const double> hi) noexcept {
    for (const std::size_t i : which) x[i] = round_to_value(x[i], lo[i], hi[i]);
}

}  // namespace pride

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
#include <cstdint>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "framework/problem.hpp"

namespace pride {

enum class VariableType : unsigned char { real, integer, categorical };

/// "real", "integer", "categorical".
constexpr std::string_view type_name(VariableType t) noexcept {
    return t == VariableType::integer ? "integer" : t == VariableType::categorical ? "categorical" : "real";
}

/// A problem on a box, of one objective or several: what the types are declared over.
template <class P>
concept Boxed = requires(const P& cp) {
    { cp.dimension() } -> std::convertible_to<std::size_t>;
    { cp.lower() } -> std::convertible_to<std::span<const double>>;
    { cp.upper() } -> std::convertible_to<std::span<const double>>;
};

/// A box problem that declares its variables' types (all real when it does not).
template <class P>
concept TypedVariables = Boxed<P> && requires(const P& p, std::size_t i) {
    { p.variable_type(i) } -> std::same_as<VariableType>;
};

/// The type of variable i of `p`: its declaration, or real.
template <Boxed P>
VariableType variable_type(const P& p, std::size_t i) {
    if constexpr (TypedVariables<P>)
        return p.variable_type(i);
    else
        return VariableType::real;
}

/// Whether some variable of `p` is not real.
template <Boxed P>
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
template <Boxed P>
void round_to_types(const P& p, std::span<double> x) {
    if constexpr (TypedVariables<P>) {
        for (std::size_t i = 0; i < x.size() && i < p.dimension(); ++i)
            if (p.variable_type(i) != VariableType::real) x[i] = round_to_value(x[i], p.lower()[i], p.upper()[i]);
    }
}

/// The coordinates of `p` that are not real, in order (computed once per run).
template <Boxed P>
std::vector<std::size_t> discrete_coordinates(const P& p) {
    std::vector<std::size_t> out;
    if constexpr (TypedVariables<P>) {
        for (std::size_t i = 0; i < p.dimension(); ++i)
            if (p.variable_type(i) != VariableType::real) out.push_back(i);
    }
    return out;
}

/// The coordinates of `p` that are categorical, in order (computed once per run).
template <Boxed P>
std::vector<std::size_t> categorical_coordinates(const P& p) {
    std::vector<std::size_t> out;
    if constexpr (TypedVariables<P>) {
        for (std::size_t i = 0; i < p.dimension(); ++i)
            if (p.variable_type(i) == VariableType::categorical) out.push_back(i);
    }
    return out;
}

/// A starting value v in [lo, hi] of a categorical coordinate made one of its k = hi - lo + 1
/// choices by cutting the range in k equal parts: a uniform start then draws every choice alike
/// (rounding would give the first and the last half the chance of the others).
inline double choice_of_start(double v, double lo, double hi) noexcept {
    const double k = hi - lo + 1.0;
    const double part = std::floor((v - lo) / (hi - lo) * k);
    return part >= 0.0 ? lo + std::min(part, k - 1.0) : lo;  // below the range or NaN: the first
}

/// The rounding operator of a typed space: the integer and categorical coordinates of a point put
/// on their values. Every box algorithm may apply it to the points it makes (`round_integers`),
/// so that its population holds values of the problem's types (rounded positions, rounded trials,
/// rounded children). Equal to round_to_value on every finite value (clamping first and rounding
/// after gives the same on integer bounds); NaN becomes the lower bound. The coordinates are kept
/// as runs of consecutive indices, and rounded without std::floor (a library call without SSE4.1)
/// where the bounds allow, so that the loop vectorises: it runs once per point made.
class Rounding {
  public:
    Rounding() = default;
    template <class P>
    requires(!std::same_as<P, Rounding> && Boxed<P>)  // not a copy: the check would recurse
        explicit Rounding(const P& p) {
        const auto which = discrete_coordinates(p);
        for (std::size_t k = 0; k < which.size(); ++k) {
            if (k == 0 || which[k] != which[k - 1] + 1)
                runs_.push_back({which[k], which[k] + 1});
            else
                runs_.back().second = which[k] + 1;
            small_ = small_ && std::abs(p.lower()[which[k]]) < kSmall && std::abs(p.upper()[which[k]]) < kSmall;
        }
    }

    bool empty() const noexcept { return runs_.empty(); }

    void operator()(std::span<double> x, std::span<const double> lo, std::span<const double> hi) const noexcept {
        for (const auto& [begin, end] : runs_) {
            if (!small_) {
                for (std::size_t i = begin; i < end; ++i)
                    x[i] = round_to_value(x[i] >= lo[i] ? x[i] : lo[i], lo[i], hi[i]);
                continue;
            }
            std::size_t i = begin;
#if defined(__SSE2__)
            // Two at a time: max(x, lo) gives lo for NaN (MAXPD returns its second operand then).
            const __m128d half = _mm_set1_pd(0.5), magic = _mm_set1_pd(kMagic), one = _mm_set1_pd(1.0);
            for (; i + 2 <= end; i += 2) {
                const __m128d v =
                    _mm_min_pd(_mm_max_pd(_mm_loadu_pd(&x[i]), _mm_loadu_pd(&lo[i])), _mm_loadu_pd(&hi[i]));
                const __m128d t = _mm_add_pd(v, half);
                const __m128d nearest = _mm_sub_pd(_mm_add_pd(t, magic), magic);
                _mm_storeu_pd(&x[i], _mm_sub_pd(nearest, _mm_and_pd(_mm_cmpgt_pd(nearest, t), one)));
            }
#endif
            for (; i < end; ++i) {
                double v = x[i] >= lo[i] ? x[i] : lo[i];
                v = v > hi[i] ? hi[i] : v;
                const double t = v + 0.5;
                // t rounded to the nearest integer by the float adder (|t| < 2^51), then floor(t).
                const double nearest = (t + kMagic) - kMagic;
                x[i] = floor_from_nearest(nearest, t);
            }
        }
    }

  private:
    /// floor(t) from t's nearest integer: one less when that is above t. Without a branch, whose
    /// outcome would be a coin toss (GCC turns the plain expression back into one).
    static double floor_from_nearest(double nearest, double t) noexcept {
#if defined(__SSE2__)
        const __m128d n = _mm_set_sd(nearest);
        const __m128d above = _mm_and_pd(_mm_cmpgt_sd(n, _mm_set_sd(t)), _mm_set_sd(1.0));
        return _mm_cvtsd_f64(_mm_sub_sd(n, above));
#else
        return nearest > t ? nearest - 1.0 : nearest;
#endif
    }

    static constexpr double kSmall = 1e15;                   // bounds below 2^51 in magnitude, with room for + 0.5
    static constexpr double kMagic = 6755399441055744.0;     // 2^52 + 2^51
    std::vector<std::pair<std::size_t, std::size_t>> runs_;  // [begin, end) of consecutive discrete coordinates
    bool small_ = true;
};

}  // namespace pride

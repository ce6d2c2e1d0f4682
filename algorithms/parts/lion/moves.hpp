#pragma once
// The moves of the lion swarm (Wan and Gao 2022, section 1.1 and 2.3; Liu, Yang and Zhou 2018), one
// function per equation and no randomness inside: the caller draws gamma, q and the partners and
// passes them in, so each equation can be checked by hand on fixed draws (tests/test_lso.cpp).
// Positions are spans of equal length; `out` may not alias an input.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>

namespace pride::lion {

/// Eqs. (1)-(2): nLeader = ceil(N beta), kept within 2 <= nLeader <= N/2 (N >= 4).
inline std::int64_t leaders(std::int64_t n, double beta) {
    auto k = static_cast<std::int64_t>(std::ceil(static_cast<double>(n) * beta));
    if (k > n / 2) k = n / 2;
    if (k < 2) k = 2;
    return k;
}

/// Eq. (5): the largest step, r (mean(high) - mean(low)); r ~ U(0,1) once per run, or 0.1 in the
/// original LSO.
inline double step(double r, std::span<const double> low, std::span<const double> high) {
    double lo = 0.0, hi = 0.0;
    for (std::size_t d = 0; d < low.size(); ++d) {
        lo += low[d];
        hi += high[d];
    }
    const auto n = static_cast<double>(low.size());
    return r * (hi / n - lo / n);
}

/// Eq. (6) as the project's decision reads it: alpha_f = step exp(-30 (t/T)^10), t = 1..T (see lso.hpp).
inline double alpha_f(double step, std::int64_t t, std::int64_t horizon) {
    const double ratio = static_cast<double>(t) / static_cast<double>(horizon);
    return step * std::exp(-30.0 * std::pow(ratio, 10));
}

/// Eq. (7): alpha_c = step (T - t) / T.
inline double alpha_c(double step, std::int64_t t, std::int64_t horizon) {
    return step * static_cast<double>(horizon - t) / static_cast<double>(horizon);
}

/// ||p - g||, the king's range in eq. (3).
inline double distance(std::span<const double> p, std::span<const double> g) {
    double squared = 0.0;
    for (std::size_t d = 0; d < g.size(); ++d) squared += (p[d] - g[d]) * (p[d] - g[d]);
    return std::sqrt(squared);
}

/// Eq. (3), the king: x = g (1 + gamma ||p_i - g||).
inline void king(std::span<const double> g, std::span<const double> p_i, double gamma, std::span<double> out) {
    const double factor = 1.0 + gamma * distance(p_i, g);
    for (std::size_t d = 0; d < g.size(); ++d) out[d] = g[d] * factor;
}

/// Eq. (4) with w = 1, eq. (11) with the inertia weight w: x = w (p_i + p_c)/2 (1 + alpha_f gamma).
/// Eq. (9) with w = 1 and eq. (12) have the same form, x = w (a + p_i)/2 (1 + alpha_c gamma), with
/// a = g, p_m or g_bar by the branch: one function serves all four.
inline void midpoint_move(std::span<const double> a, std::span<const double> b, double alpha, double gamma, double w,
                          std::span<double> out) {
    const double factor = w * 0.5 * (1.0 + alpha * gamma);
    for (std::size_t d = 0; d < a.size(); ++d) out[d] = (a[d] + b[d]) * factor;
}

/// The same moves with one gamma per coordinate (Lso::gamma_per_coordinate, not Wan and Gao's (2022) reading):
/// x_d = g_d (1 + gamma_d ||p_i - g||) and x_d = w (a_d + b_d)/2 (1 + alpha gamma_d).
inline void king(std::span<const double> g, std::span<const double> p_i, std::span<const double> gamma,
                 std::span<double> out) {
    const double range = distance(p_i, g);
    for (std::size_t d = 0; d < g.size(); ++d) out[d] = g[d] * (1.0 + gamma[d] * range);
}
inline void midpoint_move(std::span<const double> a, std::span<const double> b, double alpha,
                          std::span<const double> gamma, double w, std::span<double> out) {
    for (std::size_t d = 0; d < a.size(); ++d) out[d] = (a[d] + b[d]) * (w * 0.5 * (1.0 + alpha * gamma[d]));
}

/// Eq. (8): the point opposite the king, g_bar = low + high - g (per coordinate).
inline void opposite(std::span<const double> low, std::span<const double> high, std::span<const double> g,
                     std::span<double> out) {
    for (std::size_t d = 0; d < g.size(); ++d) out[d] = low[d] + high[d] - g[d];
}

/// Which target a cub follows (eqs. 9 and 12): q < first: the king; first <= q < second: a lioness;
/// otherwise the point opposite the king.
enum class CubTarget { king, lioness, opposite };
inline CubTarget cub_target(double q, double first, double second) {
    if (q < first) return CubTarget::king;
    if (q < second) return CubTarget::lioness;
    return CubTarget::opposite;
}

}  // namespace pride::lion

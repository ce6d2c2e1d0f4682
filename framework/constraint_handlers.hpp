#pragma once
// The field's handlers of constraints, as the comparisons and rankings an algorithm makes of
// (f, v) pairs, v a point's violation (framework/constraints.hpp), wherever its paper compares two
// values or ranks a population:
//
//   Deb (2000), "An efficient constraint handling method for genetic algorithms", the feasibility
//   rules of its tournament: a feasible point beats an infeasible one, two feasible points compare
//   by f, two infeasible ones by v.
//   Takahama and Sakai (2006), "Constrained optimization by the epsilon constrained differential
//   evolution with gradient-based mutation and feasible elites": the epsilon-level comparison
//   (eq. 3: by f when both violations are <= epsilon or equal, else by v) and its level's schedule
//   (eq. 4-5: epsilon(0) the violation of the theta-th point of the initial population,
//   epsilon(t) = epsilon(0) (1 - t / Tc)^cp for 0 < t < Tc, 0 from Tc on).
//   Runarsson and Yao (2000), "Stochastic ranking for constrained evolutionary optimization":
//   fig. 1's bubble-sort, P_f = 0.45, at most N sweeps of the population.
//   A static penalty, f + r v, and Barbosa and Lemonge's (2003) adaptive penalty method (APM; eq.
//   in Lemonge and Barbosa 2004, "An adaptive penalty scheme for genetic algorithms in structural
//   optimization", eq. 2-4), as baselines.
//
// Decisions left open by the papers: v is the suite's violation (CEC's mean, not Deb's sum nor
// Runarsson and Yao's sum of squares, so that every handler compares the same numbers); equal
// (f, v) pairs are not better than each other; Takahama and Sakai's theta-th point is counted from
// 1 among the violations sorted increasingly (theta = 0.2 N, at least the first point).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "framework/problem.hpp"
#include "framework/random.hpp"

namespace pride::constraints {

/// Deb's (2000) feasibility rules: true when (fa, va) is better than (fb, vb).
inline bool deb_better(double fa, double va, double fb, double vb) noexcept {
    const bool feasible_a = va == 0.0, feasible_b = vb == 0.0;
    if (feasible_a && feasible_b) return fa < fb;
    if (feasible_a != feasible_b) return feasible_a;
    return va < vb;
}

/// Takahama and Sakai's (2006) epsilon-level comparison (eq. 3) at level `epsilon`: Deb's rules
/// once epsilon is 0.
inline bool epsilon_better(double fa, double va, double fb, double vb, double epsilon) noexcept {
    if ((va <= epsilon && vb <= epsilon) || va == vb) return fa < fb;
    return va < vb;
}

/// Takahama and Sakai's (2006) schedule of the epsilon level (eq. 4-5).
struct EpsilonSchedule {
    double cp = 100.0;       // how fast the level falls
    std::int64_t tc = 1000;  // the generation from which the level is 0
    double theta = 0.2;      // epsilon(0): the violation of the (theta N)-th point, sorted
    double initial = 0.0;    // epsilon(0), set by start()

    /// epsilon(0) from the initial population's violations.
    void start(std::span<const double> violations) {
        if (violations.empty()) {
            initial = 0.0;
            return;
        }
        std::vector<double> sorted(violations.begin(), violations.end());
        const auto n = static_cast<double>(sorted.size());
        const auto k = std::max<std::size_t>(1, static_cast<std::size_t>(std::floor(theta * n)));
        std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(k - 1), sorted.end());
        initial = sorted[k - 1];
    }
    /// epsilon(t), t the generation (0: the initial population).
    double level(std::int64_t t) const noexcept {
        if (t <= 0) return initial;
        if (t >= tc) return 0.0;
        return initial * std::pow(1.0 - static_cast<double>(t) / static_cast<double>(tc), cp);
    }
};

/// Runarsson and Yao's (2000) stochastic ranking (fig. 1): reorders `order` (indices into f and v)
/// best first, by bubble-sort sweeps in which two neighbours compare by f when both are feasible
/// or with probability pf, else by v; at most `sweeps` sweeps (the paper's N: the population's
/// size), fewer once a sweep swaps nothing. One uniform draw per comparison. `order`: any
/// random-access range of integer indices (a vector or a span).
template <class Indices>
void stochastic_rank(Indices&& order, std::span<const double> f, std::span<const double> v, double pf,
                     std::size_t sweeps, Rng& rng) {
    const auto size = static_cast<std::size_t>(order.size());
    if (size < 2) return;
    for (std::size_t i = 0; i < sweeps; ++i) {
        bool swapped = false;
        for (std::size_t j = 0; j + 1 < size; ++j) {
            const auto a = static_cast<std::size_t>(order[j]), b = static_cast<std::size_t>(order[j + 1]);
            const double u = rng.uniform();
            const bool by_f = (v[a] == 0.0 && v[b] == 0.0) || u < pf;
            if (by_f ? f[a] > f[b] : v[a] > v[b]) {
                std::swap(order[j], order[j + 1]);
                swapped = true;
            }
        }
        if (!swapped) break;
    }
}

/// A static penalty: f + r v.
inline double static_penalty(double f, double v, double r) noexcept {
    return v == 0.0 ? f : f + r * v;
}

/// Barbosa and Lemonge's adaptive penalty (APM): the penalised values of a population, from its
/// objective values `f` (one per point) and its constraints' violations `violations` (one row per
/// constraint, one column per point: inequality_violation or equality_violation). With <f> the mean of f
/// and <v_j> the mean violation of constraint j over the population,
///   k_j = |<f>| <v_j> / sum_l <v_l>^2,
///   F(x) = f(x) if x is feasible, else max(f(x), <f>) + sum_j k_j v_j(x).
inline void adaptive_penalty(std::span<const double> f, const Matrix& violations, std::span<double> out) {
    const auto n = static_cast<Eigen::Index>(f.size());
    if (n == 0) return;
    double mean_f = 0.0;
    for (const double x : f) mean_f += x;
    mean_f /= static_cast<double>(n);
    const Eigen::VectorXd mean_v = violations.rowwise().mean();
    const double norm = mean_v.squaredNorm();
    Eigen::VectorXd k = Eigen::VectorXd::Zero(violations.rows());
    if (norm > 0.0) k = (std::abs(mean_f) / norm) * mean_v;
    for (Eigen::Index j = 0; j < n; ++j) {
        const auto i = static_cast<std::size_t>(j);
        const bool feasible = (violations.col(j).array() == 0.0).all();
        out[i] = feasible ? f[i] : std::max(f[i], mean_f) + k.dot(violations.col(j));
    }
}

}  // namespace pride::constraints

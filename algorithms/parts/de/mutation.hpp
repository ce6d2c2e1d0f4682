#pragma once
// Differential evolution's mutation strategies and its binomial crossover (algorithms/de.hpp),
// each strategy a small policy type: which donors it draws (`pick`) and the mutant it makes of them
// (`mutant`), with no randomness in the latter, so that tests can check each on scripted draws.
//
//   Storn, R. and Price, K. (1997). Differential evolution - a simple and efficient heuristic for
//     global optimization over continuous spaces. J. Global Optimization 11, 341-359.
//   Zhang, J. and Sanderson, A. C. (2009). JADE: adaptive differential evolution with optional
//     external archive. IEEE TEC 13(5), 945-958 (current-to-pbest/1 with the archive).
//   Tanabe, R. and Fukunaga, A. (2013). Success-history based parameter adaptation for differential
//     evolution. Proc. IEEE CEC, 71-78 (SHADE: p_i ~ U[2/N, p_max] per individual).
//   Brest, J., Maucec, M. S. and Boskovic, B. (2017). Single objective real-parameter optimization:
//     algorithm jSO. Proc. IEEE CEC, 1311-1318 (current-to-pBest-w/1: F_w on the pbest term).
//
// The mutant v_i of target x_i, with F (and F_w) the individual's factors (de_control.hpp):
//   (M1) rand/1:            v = x_r1 + F (x_r2 - x_r3)                   (Storn and Price 1997)
//   (M2) best/1:            v = x_best + F (x_r1 - x_r2)                 (Storn and Price 1997)
//   (M3) current-to-best/1: v = x_i + F (x_best - x_i) + F (x_r1 - x_r2) (Storn and Price 1997's
//                           second variant, with lambda = F)
//   (M4) rand/2:            v = x_r1 + F ((x_r2 - x_r3) + (x_r4 - x_r5)) (Storn and Price 1997)
//   (M5) current-to-pbest/1 with archive:
//                           v = x_i + F_w (x_pbest - x_i) + F (x_r1 - x~_r2)
//        (JADE; F_w = F but in jSO), x_pbest drawn from the best max(2, round(p N)) of the
//        population, x~_r2 from the population and the archive together (P u A).
//   (C)  binomial crossover: j_rand ~ U{0..D-1}; u_j = v_j if U(0,1) < CR or j = j_rand, else x_ij
//        (Storn and Price 1997; U(0,1) < CR rather than <=: the same in distribution).
//   (R)  bound handling of the trial u (JADE's, and Tanabe's code's): u_j < low_j becomes
//        (low_j + x_ij) / 2, u_j > high_j becomes (high_j + x_ij) / 2 (`MidpointRepair`); or the
//        nearest face (`ClampRepair`). Coordinates u takes from x are inside already, so repairing
//        u after the crossover is repairing v before it.
// The donors r1, r2, ... are drawn by rejection in this order, each distinct from the target and
// from those drawn before it; x_best (the best of the population, ties to the lower index) and
// x_pbest may be the target or a donor (as in the papers and Tanabe's code).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include "algorithms/parts/common/branchless.hpp"
#include "framework/error.hpp"
#include "framework/one_of.hpp"
#include "framework/problem.hpp"

namespace pride::de {

/// How much of the evaluation budget a generation starts with: the schedules of L-SHADE and jSO
/// run over nfes / max_nfes (max_nfes = the evaluation limit; 0 when there is none, and then no
/// schedule is asked for: De refuses such runs when a policy needs one).
struct Spent {
    std::int64_t evaluations = 0;
    std::int64_t limit = 0;
    /// nfes < share max_nfes, computed as the papers' code does.
    bool before(double share) const noexcept {
        return static_cast<double>(evaluations) < share * static_cast<double>(limit);
    }
    double fraction() const noexcept {
        return limit > 0 ? static_cast<double>(evaluations) / static_cast<double>(limit) : 0.0;
    }
};

/// The population as a strategy sees it in one generation.
struct Generation {
    const Matrix& x;  // one column per individual
    // The individuals by value, best first (ties: lower index); only the strategy's ranked()
    // leading entries are set.
    std::span<const std::size_t> order;
    const Matrix* archive = nullptr;  // the archive's first `archived` columns (current-to-pbest)
    std::size_t archived = 0;
    Spent spent{};

    std::size_t size() const noexcept { return static_cast<std::size_t>(x.cols()); }
    /// Member k of P u A: the population's k, or the archive's k - size().
    const double* member(std::size_t k) const noexcept {
        const std::size_t n = size();
        return k < n ? x.col(static_cast<Eigen::Index>(k)).data()
                     : archive->col(static_cast<Eigen::Index>(k - n)).data();
    }
};

/// The donors of one mutant: `best` (best/1, current-to-best/1, current-to-pbest/1) and r[0..4]
/// (r[1] of current-to-pbest/1 indexes P u A).
struct Donors {
    std::size_t best = 0;
    std::array<std::size_t, 5> r{};
};

namespace detail {

/// A draw below `n` distinct from the `k` values given (rejection, as in the papers' code).
template <class Draw>
std::size_t distinct(Draw& u, std::size_t n, std::span<const std::size_t> taken) {
    for (;;) {
        const auto r = static_cast<std::size_t>(u.below(n));
        if (std::find(taken.begin(), taken.end(), r) == taken.end()) return r;
    }
}

/// r[0..k-1] from the population, distinct from the target i and from each other.
template <class Draw>
void draw_distinct(Draw& u, std::size_t n, std::size_t i, std::size_t k, Donors& d) {
    std::array<std::size_t, 6> taken{i};
    for (std::size_t m = 0; m < k; ++m) {
        d.r[m] = distinct(u, n, std::span<const std::size_t>(taken.data(), m + 1));
        taken[m + 1] = d.r[m];
    }
}

inline const double* col(const Matrix& x, std::size_t k) noexcept {
    return x.col(static_cast<Eigen::Index>(k)).data();
}

/// The donors of best/1 and current-to-best/1: x_best and two others, distinct from the target.
template <class Draw>
Donors best_and_two(const Generation& g, std::size_t i, Draw& u) {
    Donors d;
    d.best = g.order[0];
    draw_distinct(u, g.size(), i, 2, d);
    return d;
}

}  // namespace detail

/// (M1) DE/rand/1.
struct RandOne {
    static constexpr bool scheduled = false;
    static constexpr const char* name = "rand/1/bin";
    static constexpr std::int64_t min_population = 4;  // the target and three donors
    /// How many leading entries of Generation::order pick() reads (the rest is not ranked).
    static std::size_t ranked(std::size_t, Spent) noexcept { return 0; }
    void validate(const std::string&) const {}
    template <class Draw>
    Donors pick(const Generation& g, std::size_t i, Draw& u) const {
        Donors d;
        detail::draw_distinct(u, g.size(), i, 3, d);
        return d;
    }
    void mutant(const Generation& g, std::size_t, const Donors& d, double f, double, std::span<double> v) const {
        const double *a = detail::col(g.x, d.r[0]), *b = detail::col(g.x, d.r[1]), *c = detail::col(g.x, d.r[2]);
        for (std::size_t j = 0; j < v.size(); ++j) v[j] = a[j] + f * (b[j] - c[j]);
    }
};

/// (M2) DE/best/1.
struct BestOne {
    static constexpr bool scheduled = false;
    static constexpr const char* name = "best/1/bin";
    static constexpr std::int64_t min_population = 3;
    static std::size_t ranked(std::size_t, Spent) noexcept { return 1; }
    void validate(const std::string&) const {}
    template <class Draw>
    Donors pick(const Generation& g, std::size_t i, Draw& u) const {
        return detail::best_and_two(g, i, u);
    }
    void mutant(const Generation& g, std::size_t, const Donors& d, double f, double, std::span<double> v) const {
        const double *a = detail::col(g.x, d.best), *b = detail::col(g.x, d.r[0]), *c = detail::col(g.x, d.r[1]);
        for (std::size_t j = 0; j < v.size(); ++j) v[j] = a[j] + f * (b[j] - c[j]);
    }
};

/// (M3) DE/current-to-best/1.
struct CurrentToBestOne {
    static constexpr bool scheduled = false;
    static constexpr const char* name = "current-to-best/1/bin";
    static constexpr std::int64_t min_population = 3;
    static std::size_t ranked(std::size_t, Spent) noexcept { return 1; }
    void validate(const std::string&) const {}
    template <class Draw>
    Donors pick(const Generation& g, std::size_t i, Draw& u) const {
        return detail::best_and_two(g, i, u);
    }
    void mutant(const Generation& g, std::size_t i, const Donors& d, double f, double, std::span<double> v) const {
        const double *x = detail::col(g.x, i), *best = detail::col(g.x, d.best);
        const double *b = detail::col(g.x, d.r[0]), *c = detail::col(g.x, d.r[1]);
        for (std::size_t j = 0; j < v.size(); ++j) v[j] = x[j] + f * (best[j] - x[j]) + f * (b[j] - c[j]);
    }
};

/// (M4) DE/rand/2.
struct RandTwo {
    static constexpr bool scheduled = false;
    static constexpr const char* name = "rand/2/bin";
    static constexpr std::int64_t min_population = 6;  // the target and five donors
    static std::size_t ranked(std::size_t, Spent) noexcept { return 0; }
    void validate(const std::string&) const {}
    template <class Draw>
    Donors pick(const Generation& g, std::size_t i, Draw& u) const {
        Donors d;
        detail::draw_distinct(u, g.size(), i, 5, d);
        return d;
    }
    void mutant(const Generation& g, std::size_t, const Donors& d, double f, double, std::span<double> v) const {
        const double *a = detail::col(g.x, d.r[0]), *b = detail::col(g.x, d.r[1]), *c = detail::col(g.x, d.r[2]);
        const double *e = detail::col(g.x, d.r[3]), *h = detail::col(g.x, d.r[4]);
        for (std::size_t j = 0; j < v.size(); ++j) v[j] = a[j] + f * ((b[j] - c[j]) + (e[j] - h[j]));
    }
};

/// How many of the best individuals x_pbest is drawn from: max(2, round(p N)), at most N.
inline std::size_t pbest_count(double p, std::size_t n) noexcept {
    const auto k = static_cast<std::size_t>(std::max(2.0, std::round(p * static_cast<double>(n))));
    return std::min(k, n);
}

/// p fixed (JADE 0.05, L-SHADE 0.11).
struct FixedRate {
    static constexpr bool scheduled = false;
    double p = 0.05;
    template <class Draw>
    double operator()(std::size_t, Spent, Draw&) const noexcept {
        return p;
    }
    double largest(std::size_t, Spent) const noexcept { return p; }
    void validate(const std::string& who) const {
        require(p > 0.0 && p <= 1.0, who, "p must be in (0, 1], got " + std::to_string(p));
    }
};

/// p_i ~ U[2/N, p_max] per individual (SHADE).
struct UniformRate {
    static constexpr bool scheduled = false;
    double p_max = 0.2;
    template <class Draw>
    double operator()(std::size_t n, Spent, Draw& u) const {
        const double p_min = 2.0 / static_cast<double>(n);
        return p_min + (std::max(p_min, p_max) - p_min) * u.uniform();
    }
    double largest(std::size_t n, Spent) const noexcept { return std::max(2.0 / static_cast<double>(n), p_max); }
    void validate(const std::string& who) const {
        require(p_max > 0.0 && p_max <= 1.0, who, "p_max must be in (0, 1], got " + std::to_string(p_max));
    }
};

/// p from `start` to `end` linearly over the evaluation budget (jSO: 0.25 -> 0.125).
struct LinearRate {
    static constexpr bool scheduled = true;
    double start = 0.25;
    double end = 0.125;
    template <class Draw>
    double operator()(std::size_t, Spent spent, Draw&) const noexcept {
        return start + (end - start) * spent.fraction();
    }
    double largest(std::size_t, Spent spent) const noexcept { return start + (end - start) * spent.fraction(); }
    void validate(const std::string& who) const {
        require(start > 0.0 && start <= 1.0, who, "p_max must be in (0, 1], got " + std::to_string(start));
        require(end > 0.0 && end <= start, who,
                "p_min must be in (0, p_max], got " + std::to_string(end) + " with p_max " + std::to_string(start));
    }
};

/// (M5) current-to-pbest/1 with the archive (JADE, SHADE, L-SHADE), current-to-pBest-w/1 with
/// the control's F_w (jSO). `pbest_not_target_before`: while nfes < that share of the budget,
/// x_pbest is drawn again when it is the target (the jSO code's rule, from iL-SHADE; 0: never).
template <class Rate = FixedRate>
struct CurrentToPBest {
    static constexpr const char* name = "current-to-pbest/1/bin";
    static constexpr std::int64_t min_population = 4;
    static constexpr bool scheduled = Rate::scheduled;
    Rate rate{};
    double pbest_not_target_before = 0.0;
    void validate(const std::string& who) const {
        rate.validate(who);
        require(pbest_not_target_before >= 0.0 && pbest_not_target_before <= 1.0, who,
                "the share of the budget with x_pbest distinct from the target must be in [0, 1]");
    }
    /// The largest top a draw of p can give (pbest_count is monotone in p).
    std::size_t ranked(std::size_t n, Spent spent) const noexcept { return pbest_count(rate.largest(n, spent), n); }
    template <class Draw>
    Donors pick(const Generation& g, std::size_t i, Draw& u) const {
        const std::size_t n = g.size();
        const std::size_t top = pbest_count(rate(n, g.spent, u), n);
        Donors d;
        do {
            d.best = g.order[static_cast<std::size_t>(u.below(top))];
        } while (d.best == i && g.spent.before(pbest_not_target_before));
        const std::size_t target[] = {i};
        d.r[0] = detail::distinct(u, n, target);
        const std::size_t taken[] = {i, d.r[0]};
        d.r[1] = detail::distinct(u, n + g.archived, taken);
        return d;
    }
    void mutant(const Generation& g, std::size_t i, const Donors& d, double f, double fw, std::span<double> v) const {
        const double *x = detail::col(g.x, i), *best = detail::col(g.x, d.best);
        const double *b = detail::col(g.x, d.r[0]), *c = g.member(d.r[1]);
        for (std::size_t j = 0; j < v.size(); ++j) v[j] = x[j] + fw * (best[j] - x[j]) + f * (b[j] - c[j]);
    }
};

/// (C) The binomial crossover of target x and mutant v into u. The D coins are drawn in bulk into
/// `out` first (Rng::fill_uniform: the same draws as D uniform() calls, the generator's state in
/// registers), then each coordinate is a select, not a jump: with CR near 0.5 a jump would be
/// mispredicted every other coordinate.
template <class Draw>
void binomial_crossover(std::span<const double> x, std::span<const double> v, double cr, Draw& u,
                        std::span<double> out) {
    const auto j_rand = static_cast<std::size_t>(u.below(x.size()));
    if constexpr (requires { u.fill_uniform(out); })
        u.fill_uniform(out);
    else
        for (double& coin : out) coin = u.uniform();
    for (std::size_t j = 0; j < x.size(); ++j)
        out[j] = pride::detail::select((out[j] < cr) | (j == j_rand), v[j], x[j]);
}

/// (R) JADE's bound handling: a coordinate below its lower bound goes halfway between the bound
/// and the target's coordinate, one above its upper bound likewise (NaN goes the lower way).
struct MidpointRepair {
    static constexpr const char* name = "midpoint";
    void operator()(std::span<double> u, std::span<const double> target, std::span<const double> lo,
                    std::span<const double> hi) const noexcept {
        for (std::size_t j = 0; j < u.size(); ++j) {
            if (!(u[j] >= lo[j]))
                u[j] = 0.5 * lo[j] + 0.5 * target[j];
            else if (u[j] > hi[j])
                u[j] = 0.5 * hi[j] + 0.5 * target[j];
        }
    }
};

/// The framework's Clamp (framework/bounds.hpp): the nearest face of the box.
struct ClampRepair {
    static constexpr const char* name = "clamp";
    void operator()(std::span<double> u, std::span<const double>, std::span<const double> lo,
                    std::span<const double> hi) const noexcept {
        for (std::size_t j = 0; j < u.size(); ++j) u[j] = std::max(lo[j], std::min(u[j], hi[j]));
    }
};

/// One trial vector: the strategy's donors and mutant (into `scratch`), then the crossover with
/// the target, into `out`.
template <class Strategy, class Draw>
void make_trial(const Strategy& strategy, const Generation& g, std::size_t i, double f, double cr, double fw, Draw& u,
                std::span<double> scratch, std::span<double> out) {
    const Donors d = strategy.pick(g, i, u);
    strategy.mutant(g, i, d, f, fw, scratch);
    const auto target = std::span<const double>(detail::col(g.x, i), scratch.size());
    binomial_crossover(target, std::span<const double>(scratch), cr, u, out);
}

/// The strategies of the registry's entries, chosen at run time (once per generation).
using SelectableMutation = OneOf<RandOne, BestOne, CurrentToBestOne, RandTwo, CurrentToPBest<FixedRate>,
                                 CurrentToPBest<UniformRate>, CurrentToPBest<LinearRate>>;
using SelectableRepair = OneOf<MidpointRepair, ClampRepair>;

}  // namespace pride::de

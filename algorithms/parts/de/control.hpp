#pragma once
// Differential evolution's parameter control (algorithms/de.hpp): where each individual's F, CR
// (and jSO's F_w) come from, and what a generation's successes teach. Each rule a small policy
// type; the means are plain functions, so that tests check the memory updates on hand-computed
// numbers.
//
//   Storn, R. and Price, K. (1997). J. Global Optimization 11, 341-359 (F and CR fixed).
//   Brest, J., Greiner, S., Boskovic, B., Mernik, M. and Zumer, V. (2006). Self-adapting control
//     parameters in differential evolution: a comparative study on numerical benchmark problems.
//     IEEE TEC 10(6), 646-657 (jDE).
//   Zhang, J. and Sanderson, A. C. (2009). JADE: adaptive differential evolution with optional
//     external archive. IEEE TEC 13(5), 945-958.
//   Tanabe, R. and Fukunaga, A. (2013). Success-history based parameter adaptation for differential
//     evolution. Proc. IEEE CEC, 71-78 (SHADE).
//   Tanabe, R. and Fukunaga, A. (2014). Improving the search performance of SHADE using linear
//     population size reduction. Proc. IEEE CEC, 1658-1665 (L-SHADE), and Tanabe's code as the
//     CEC 2022 competition distributes it (lshade.cpp, version 1.0).
//   Brest, J., Maucec, M. S. and Boskovic, B. (2017). Single objective real-parameter optimization:
//     algorithm jSO. Proc. IEEE CEC, 1311-1318.
//
// Per individual i, before its trial vector (randn: normal, randc: Cauchy, both with scale 0.1):
//   (P1) fixed:   F_i = F, CR_i = CR                                               (Storn and Price)
//   (P2) jDE:     F_i <- F_l + U(0,1) F_u if U(0,1) < tau1, else F_i (the draw order: the test,
//                 then the value); CR_i <- U(0,1) if U(0,1) < tau2, else CR_i; both kept with
//                 the vector only when its trial replaces it; F_i = 0.5, CR_i = 0.9 at the
//                 start (Tanabe's jDE code)                                         (Brest et al. 2006)
//   (P3) JADE:    CR_i = randn(mu_CR) clipped to [0, 1]; F_i = randc(mu_F), drawn again while
//                 <= 0, 1 if above 1                                               (Zhang and Sanderson)
//   (P4) SHADE, L-SHADE, jSO: a slot r ~ U{0..H-1} of the memory; CR_i = randn(M_CR,r) clipped to
//                 [0, 1], or 0 when M_CR,r is the terminal value (L-SHADE, jSO); F_i = randc(M_F,r)
//                 as in (P3)                                                       (Tanabe and Fukunaga)
//   (P5) jSO:     the last slot reads M_F = M_CR = 0.9; CR_i <- max(CR_i, 0.7) while nfes < 0.25
//                 max_nfes, max(CR_i, 0.6) while nfes < 0.5 max_nfes; F_i <- min(F_i, 0.7) while
//                 nfes < 0.6 max_nfes; F_w = 0.7 F_i (nfes < 0.2 max_nfes), 0.8 F_i (< 0.4),
//                 1.2 F_i otherwise                                                (Brest et al. 2017)
// After the generation's selection, with S_F, S_CR the parameters of the trials strictly better
// than their targets and the weights w_k = |f(u_k) - f(x_k)| / sum_l |f(u_l) - f(x_l)|:
//   (U1) JADE:    mu_CR <- (1 - c) mu_CR + c mean_A(S_CR); mu_F <- (1 - c) mu_F + c mean_L(S_F),
//                 mean_L(S) = sum S^2 / sum S (the Lehmer mean)                    (Zhang and Sanderson)
//   (U2) SHADE:   M_CR,k <- mean_WA(S_CR) = sum w S_CR; M_F,k <- mean_WL(S_F) = sum w S_F^2 /
//                 sum w S_F; k <- k + 1 mod H                                      (Tanabe and Fukunaga 2013)
//   (U3) L-SHADE: M_F,k <- mean_WL(S_F); M_CR,k <- mean_WL(S_CR), or the terminal value when
//                 sum w S_CR = 0 (every successful CR is 0); k <- k + 1 mod H      (Tanabe and Fukunaga 2014)
//   (U4) jSO:     M_F,k <- (mean_WL(S_F) + M_F,k) / 2; M_CR,k <- (mean_WL(S_CR) + M_CR,k) / 2, the
//                 terminal value taking the place of the mean as in (U3)           (Brest et al. 2017)
//   No update when S is empty (SHADE and L-SHADE say so; for JADE this project decides it: its
//   means of an empty set are undefined).
// Decided by this project where the papers are silent: the terminal value is held as -1 (Tanabe's
// code; jSO's halving then averages -1 with the old value, as Brest's code does, and any negative
// M_CR reads as terminal); infinite gains (a target worth +inf replaced by a finite trial) share
// the weight equally and the finite ones get none, the limit of the weights as those gains grow.
// Where L-SHADE's paper and code differ the code is followed unless `sticky_terminal` is set: the
// code tests `memory_cr[k] == -1` after resetting the slot to 0, so a terminal slot is
// overwritten by the next update; the paper keeps it terminal. jSO's update cycles over all H
// slots, the fixed last one included (Brest's code: the value written there is never read).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <span>
#include <string>
#include <vector>

#include "algorithms/parts/de/mutation.hpp"
#include "framework/error.hpp"
#include "framework/one_of.hpp"

namespace pride::de {

/// M_CR's terminal value (L-SHADE's bottom symbol), as Tanabe's code holds it.
inline constexpr double kTerminal = -1.0;

/// One individual's parameters for its trial vector.
struct Parameters {
    double f = 0.5;
    double cr = 0.9;
    double fw = 0.5;  // the factor of the pbest term (jSO's F_w; F otherwise)
};

/// What the control keeps over a run: per individual (jDE), or the memory (JADE: one slot holding
/// mu_F and mu_CR; the SHADE family: H slots and the next slot to write).
struct Adaptation {
    std::vector<double> f, cr;
    std::vector<double> memory_f, memory_cr;
    std::size_t next = 0;
};

/// The parameters of one generation's successful trials, and their gains |f(u) - f(x)|.
struct Successes {
    std::vector<double> f, cr, gain;
    explicit Successes(std::size_t capacity = 0) {
        f.reserve(capacity);
        cr.reserve(capacity);
        gain.reserve(capacity);
    }
    void add(double fi, double cri, double g) {
        f.push_back(fi);
        cr.push_back(cri);
        gain.push_back(g);
    }
    void clear() noexcept {
        f.clear();
        cr.clear();
        gain.clear();
    }
    bool empty() const noexcept { return f.empty(); }
    std::size_t size() const noexcept { return f.size(); }
};

/// sum_k w_k s_k^2 and sum_k w_k s_k with w_k = gain_k / sum(gain) (infinite gains: equal shares
/// among them, none for the finite ones).
struct WeightedSums {
    double squares = 0.0;
    double values = 0.0;
};

inline WeightedSums weighted_sums(std::span<const double> s, std::span<const double> gain) {
    double total = 0.0;
    std::size_t infinite = 0;
    for (const double g : gain)
        if (std::isinf(g))
            ++infinite;
        else
            total += g;
    WeightedSums out;
    for (std::size_t k = 0; k < s.size(); ++k) {
        const double w =
            infinite > 0 ? (std::isinf(gain[k]) ? 1.0 / static_cast<double>(infinite) : 0.0) : gain[k] / total;
        out.squares += w * s[k] * s[k];
        out.values += w * s[k];
    }
    return out;
}

/// mean_WL(S) = sum w S^2 / sum w S (SHADE's weighted Lehmer mean).
inline double weighted_lehmer_mean(std::span<const double> s, std::span<const double> gain) {
    const WeightedSums sums = weighted_sums(s, gain);
    return sums.squares / sums.values;
}

/// mean_WA(S) = sum w S (SHADE's weighted arithmetic mean).
inline double weighted_arithmetic_mean(std::span<const double> s, std::span<const double> gain) {
    return weighted_sums(s, gain).values;
}

/// mean_L(S) = sum S^2 / sum S (JADE's Lehmer mean).
inline double lehmer_mean(std::span<const double> s) {
    double squares = 0.0, values = 0.0;
    for (const double v : s) {
        squares += v * v;
        values += v;
    }
    return squares / values;
}

/// mean_A(S) (JADE's arithmetic mean).
inline double arithmetic_mean(std::span<const double> s) {
    double sum = 0.0;
    for (const double v : s) sum += v;
    return sum / static_cast<double>(s.size());
}

namespace detail {

/// randn(mu, 0.1) clipped to [0, 1], or 0 for the terminal value (any negative mu).
template <class Draw>
double normal_cr(double mu, Draw& u) {
    if (mu < 0.0) return 0.0;
    const double cr = mu + 0.1 * u.normal();
    return cr > 1.0 ? 1.0 : (cr < 0.0 ? 0.0 : cr);
}

/// randc(mu, 0.1), drawn again while <= 0, 1 if above 1.
template <class Draw>
double cauchy_f(double mu, Draw& u) {
    double f = 0.0;
    do f = mu + 0.1 * std::tan(std::numbers::pi * (u.uniform() - 0.5));
    while (!(f > 0.0));
    return std::min(f, 1.0);
}

inline void require_memory_size(std::int64_t h, std::int64_t least, const std::string& who) {
    require(h >= least && h <= 1'000'000, who,
            "memory must be in [" + std::to_string(least) + ", 1000000], got " + std::to_string(h));
}

inline void require_unit(double v, const std::string& what, const std::string& who, bool zero_allowed) {
    require((zero_allowed ? v >= 0.0 : v > 0.0) && v <= 1.0, who,
            what + " must be in " + (zero_allowed ? "[0, 1]" : "(0, 1]") + ", got " + std::to_string(v));
}

/// The memory's H slots, each (f0, cr0).
inline void start_memory(Adaptation& a, std::int64_t h, double f0, double cr0) {
    a.memory_f.assign(static_cast<std::size_t>(h), f0);
    a.memory_cr.assign(static_cast<std::size_t>(h), cr0);
    a.next = 0;
}

inline void advance(Adaptation& a) {
    a.next = (a.next + 1) % a.memory_f.size();
}

/// (P4): a slot r ~ U{0..H-1}, then CR_i and F_i from its values.
template <class Draw>
Parameters memory_sample(const Adaptation& a, Draw& u) {
    const auto r = static_cast<std::size_t>(u.below(a.memory_f.size()));
    Parameters p;
    p.cr = normal_cr(a.memory_cr[r], u);
    p.f = cauchy_f(a.memory_f[r], u);
    p.fw = p.f;
    return p;
}

}  // namespace detail

/// (P1) F and CR fixed (Storn and Price 1997).
struct FixedControl {
    static constexpr bool scheduled = false;
    double f = 0.5;
    double cr = 0.9;
    void validate(const std::string& who) const {
        require(f > 0.0 && f <= 2.0, who, "F must be in (0, 2], got " + std::to_string(f));
        detail::require_unit(cr, "CR", who, true);
    }
    void start(Adaptation&, std::size_t) const {}
    template <class Draw>
    Parameters sample(const Adaptation&, std::size_t, Spent, Draw&) const {
        return {f, cr, f};
    }
    void keep(Adaptation&, std::size_t, const Parameters&) const {}
    void update(Adaptation&, const Successes&) const {}
    std::int64_t memory_slots() const { return 0; }
};

/// (P2) jDE's self-adapting F_i and CR_i (Brest et al. 2006).
struct JdeControl {
    static constexpr bool scheduled = false;
    double tau1 = 0.1;     // the probability of a new F_i
    double tau2 = 0.1;     // the probability of a new CR_i
    double f_lower = 0.1;  // F_l
    double f_upper = 0.9;  // F_u: a new F_i is U[F_l, F_l + F_u)
    double f_init = 0.5;   // every F_i at the start
    double cr_init = 0.9;  // every CR_i at the start
    void validate(const std::string& who) const {
        detail::require_unit(tau1, "tau1", who, true);
        detail::require_unit(tau2, "tau2", who, true);
        require(f_lower > 0.0 && f_lower <= 2.0, who, "F_l must be in (0, 2], got " + std::to_string(f_lower));
        require(f_upper >= 0.0 && f_lower + f_upper <= 2.0, who,
                "F_u must be in [0, 2 - F_l], got " + std::to_string(f_upper) + " with F_l " + std::to_string(f_lower));
        require(f_init > 0.0 && f_init <= 2.0, who, "the initial F must be in (0, 2], got " + std::to_string(f_init));
        detail::require_unit(cr_init, "the initial CR", who, true);
    }
    void start(Adaptation& a, std::size_t n) const {
        a.f.assign(n, f_init);
        a.cr.assign(n, cr_init);
    }
    template <class Draw>
    Parameters sample(const Adaptation& a, std::size_t i, Spent, Draw& u) const {
        Parameters p;
        p.f = u.uniform() < tau1 ? f_lower + u.uniform() * f_upper : a.f[i];
        p.cr = u.uniform() < tau2 ? u.uniform() : a.cr[i];
        p.fw = p.f;
        return p;
    }
    void keep(Adaptation& a, std::size_t i, const Parameters& p) const {
        a.f[i] = p.f;
        a.cr[i] = p.cr;
    }
    void update(Adaptation&, const Successes&) const {}
    std::int64_t memory_slots() const { return 0; }
};

/// (P3), (U1) JADE's mu_F and mu_CR (Zhang and Sanderson 2009).
struct JadeControl {
    static constexpr bool scheduled = false;
    double c = 0.1;  // the learning rate
    double mu_f = 0.5;
    double mu_cr = 0.5;
    void validate(const std::string& who) const {
        detail::require_unit(c, "c", who, true);
        detail::require_unit(mu_f, "the initial mu_F", who, false);
        detail::require_unit(mu_cr, "the initial mu_CR", who, true);
    }
    void start(Adaptation& a, std::size_t) const { detail::start_memory(a, 1, mu_f, mu_cr); }
    template <class Draw>
    Parameters sample(const Adaptation& a, std::size_t, Spent, Draw& u) const {
        Parameters p;
        p.cr = detail::normal_cr(a.memory_cr[0], u);
        p.f = detail::cauchy_f(a.memory_f[0], u);
        p.fw = p.f;
        return p;
    }
    void keep(Adaptation&, std::size_t, const Parameters&) const {}
    void update(Adaptation& a, const Successes& s) const {
        if (s.empty()) return;
        a.memory_cr[0] = (1.0 - c) * a.memory_cr[0] + c * arithmetic_mean(s.cr);
        a.memory_f[0] = (1.0 - c) * a.memory_f[0] + c * lehmer_mean(s.f);
    }
    std::int64_t memory_slots() const { return 1; }
};

/// (P4) The success-history memory of SHADE and L-SHADE: H slots (default `H`), sampled alike;
/// each adds its own update, (U2) or (U3).
template <std::int64_t H>
struct HistoryMemory {
    static constexpr bool scheduled = false;
    std::int64_t memory = H;
    double f_init = 0.5;
    double cr_init = 0.5;
    void validate(const std::string& who) const {
        detail::require_memory_size(memory, 1, who);
        detail::require_unit(f_init, "the initial M_F", who, false);
        detail::require_unit(cr_init, "the initial M_CR", who, true);
    }
    void start(Adaptation& a, std::size_t) const { detail::start_memory(a, memory, f_init, cr_init); }
    template <class Draw>
    Parameters sample(const Adaptation& a, std::size_t, Spent, Draw& u) const {
        return detail::memory_sample(a, u);
    }
    void keep(Adaptation&, std::size_t, const Parameters&) const {}
    std::int64_t memory_slots() const { return memory; }
};

/// (P4), (U2) SHADE's success-history memory (Tanabe and Fukunaga 2013), H = 100.
struct ShadeControl : HistoryMemory<100> {
    void update(Adaptation& a, const Successes& s) const {
        if (s.empty()) return;
        a.memory_cr[a.next] = weighted_arithmetic_mean(s.cr, s.gain);
        a.memory_f[a.next] = weighted_lehmer_mean(s.f, s.gain);
        detail::advance(a);
    }
};

/// (P4), (U3) L-SHADE's memory, H = 6: weighted Lehmer means for both, and the terminal value
/// (Tanabe and Fukunaga 2014). `sticky_terminal`: the paper's reading (a terminal slot stays
/// terminal); unset, Tanabe's code.
struct LshadeControl : HistoryMemory<6> {
    bool sticky_terminal = false;
    void update(Adaptation& a, const Successes& s) const {
        if (s.empty()) return;
        const WeightedSums cr = weighted_sums(s.cr, s.gain);
        const bool terminal = cr.values == 0.0 || (sticky_terminal && a.memory_cr[a.next] < 0.0);
        a.memory_f[a.next] = weighted_lehmer_mean(s.f, s.gain);
        a.memory_cr[a.next] = terminal ? kTerminal : cr.squares / cr.values;
        detail::advance(a);
    }
};

/// (P4), (P5), (U4) jSO's memory and its rules over the budget (Brest et al. 2017).
struct JsoControl {
    static constexpr bool scheduled = true;
    std::int64_t memory = 5;  // H, the last slot fixed
    double f_init = 0.3;
    double cr_init = 0.8;
    double fixed = 0.9;  // M_F and M_CR of the last slot
    void validate(const std::string& who) const {
        detail::require_memory_size(memory, 2, who);
        detail::require_unit(f_init, "the initial M_F", who, false);
        detail::require_unit(cr_init, "the initial M_CR", who, true);
        detail::require_unit(fixed, "the last slot's M_F and M_CR", who, false);
    }
    void start(Adaptation& a, std::size_t) const { detail::start_memory(a, memory, f_init, cr_init); }
    template <class Draw>
    Parameters sample(const Adaptation& a, std::size_t, Spent spent, Draw& u) const {
        const std::size_t h = a.memory_f.size();
        const auto r = static_cast<std::size_t>(u.below(h));
        const bool last = r == h - 1;
        Parameters p;
        p.cr = detail::normal_cr(last ? fixed : a.memory_cr[r], u);
        if (spent.before(0.25)) p.cr = std::max(p.cr, 0.7);
        if (spent.before(0.5)) p.cr = std::max(p.cr, 0.6);
        p.f = detail::cauchy_f(last ? fixed : a.memory_f[r], u);
        if (spent.before(0.6)) p.f = std::min(p.f, 0.7);
        p.fw = p.f * (spent.before(0.2) ? 0.7 : spent.before(0.4) ? 0.8 : 1.2);
        return p;
    }
    void keep(Adaptation&, std::size_t, const Parameters&) const {}
    void update(Adaptation& a, const Successes& s) const {
        if (s.empty()) return;
        const WeightedSums cr = weighted_sums(s.cr, s.gain);
        const double mean_cr = cr.values == 0.0 ? kTerminal : cr.squares / cr.values;
        a.memory_f[a.next] = (weighted_lehmer_mean(s.f, s.gain) + a.memory_f[a.next]) / 2.0;
        a.memory_cr[a.next] = (mean_cr + a.memory_cr[a.next]) / 2.0;
        detail::advance(a);
    }
    std::int64_t memory_slots() const { return memory; }
};

/// The controls of the registry's entries, chosen at run time (once per generation).
using SelectableControl = OneOf<FixedControl, JdeControl, JadeControl, ShadeControl, LshadeControl, JsoControl>;

}  // namespace pride::de

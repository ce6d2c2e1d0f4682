#pragma once
// The whale optimisation algorithm (WOA) and HS-WOA: one skeleton, three policies.
//
//   Mirjalili, S. and Lewis, A. (2016). The whale optimization algorithm. Advances in Engineering
//     Software 95, 51-67, and the authors' reference code WOA.m (Cai and Du 2021, eqs. 1-7).
//   Cai and Du (2021) (harmony-search-based balanced WOA, HS-WOA): eq. 8 and the harmony second step
//     (section 2.1), the balance factor and the reconstruction (eq. 9, section 2.2).
//   Geem, Z. W., Kim, J. H. and Loganathan, G. V. (2001). A new heuristic optimization algorithm:
//     harmony search. Simulation 76(2), 60-68 (the improvisation).
//
// The initial pod (run_setup.hpp): positions by the Init policy, then the Bounds policy, evaluated
// and recorded as iteration 0; the leader X* = the best evaluated whale. Iteration t = 0..T-1:
//   a = 2 - 2t/T, a2 = -1 - t/T (whale::a, whale::a2). Per whale i: r1, r2, r, p ~ U(0,1) (the
//   Draws policy: once per whale as WOA.m does, or r1, r2, p per coordinate), and with the balance
//   mode one more draw q (explore when q < balance); A = 2 a r1 - a (eq. 3), C = 2 r2 (eq. 4),
//   l = (a2 - 1) r + 1, b = 1. Per coordinate d the Mode policy picks the move:
//     convergence (WOA): p < 0.5 and |A| >= 1: search (eqs. 6-7) relative to a whale drawn anew
//       for each coordinate; p < 0.5 and |A| < 1: encircle X* (eqs. 1-2); p >= 0.5: spiral (eq. 5);
//     balance (HS-WOA): explore: search (eqs. 6-7); else p < 0.5: encircle, p >= 0.5: spiral.
//   Positions are replaced (no greedy selection); then the Bounds policy; the pod is evaluated in
//   one batch and X* updated from the evaluations.
//   SecondStep harmony (Cai and Du 2021, section 2.1): each whale moves by eq. 8 (towards X* by a U(0,1)
//   fraction if f_i < f_avg, towards a random whale otherwise), Bounds, the pod is evaluated; then
//   N improvisations from the pod (HMCR, PAR, BW), each evaluated and replacing the current worst
//   whale when strictly better.
//   Balance mode, at the end of the iteration (eq. 9): whale::balance_step; on stagnation the
//   pod is rebuilt: 20 % kept by tournament (the best among them), the rest uniform in the box,
//   evaluated.
// On chains (grid paths, the chain encoding) the same loop runs on whale::ChainPod
// (whale_pods.hpp): the whales are the space's chains (on grids random walks with backtracking,
// shortened by the line-of-sight shortcut), and each move of eqs. 1-8 moves a whale towards its
// target through the space's TowardMoves capability; the improvisation and the reconstruction are
// chain operations too. whale_pods.hpp says how each equation's factor becomes a share of the
// target's course (the papers leave that open).
// Decided by this project where the papers are open: as in WOA.m, whales move one
// after another in place, so a random whale drawn for whale i may already have moved this
// iteration (and is not yet clamped: clamping is applied to the whole pod before evaluation); the
// random whale may be whale i itself; per-coordinate draws keep r and q per whale; eq. 8 uses one
// U(0,1) fraction per whale, X* the leader (best evaluated so far), and its moves are evaluated
// before the improvisations (so an HS-WOA iteration costs 3N evaluations, the horizon T counts
// them); the balance factor's "improvement" is a strictly better leader over the iteration; T is
// the iteration limit or the iterations the budget allows (reconstructions are not foreseen, so
// a may end above 0); when the budget ends inside an iteration the rest of it is not evaluated.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <span>
#include <string>
#include <vector>

#include "algorithms/parts/common/run_setup.hpp"
#include "algorithms/parts/whale/moves.hpp"
#include "algorithms/parts/whale/pods.hpp"
#include "framework/bounds.hpp"
#include "framework/chain.hpp"
#include "framework/error.hpp"
#include "framework/initializer.hpp"
#include "framework/observer.hpp"
#include "framework/one_of.hpp"
#include "framework/problem.hpp"
#include "framework/random.hpp"
#include "framework/result.hpp"
#include "framework/run_state.hpp"
#include "framework/termination.hpp"
#include "framework/visit_policy.hpp"

namespace pride {

/// Draws: A, C and p once per whale and iteration (WOA.m).
struct PerWhaleDraws {
    static constexpr bool per_coordinate = false;
    void validate(const std::string&) const {}
};
/// Draws: r1, r2 and p anew for every coordinate (the vector reading of the paper's notation).
struct PerCoordinateDraws {
    static constexpr bool per_coordinate = true;
    void validate(const std::string&) const {}
};
using SelectableWhaleDraws = OneOf<PerWhaleDraws, PerCoordinateDraws>;

/// Mode: WOA's convergence factor chooses between exploration and exploitation through |A|.
struct ConvergenceMode {
    static constexpr bool balanced = false;
    WhaleMove operator()(double A, double p, bool /*explore*/) const noexcept {
        if (p < 0.5) return std::abs(A) >= 1.0 ? WhaleMove::search : WhaleMove::encircle;
        return WhaleMove::spiral;
    }
    void validate(const std::string&) const {}
};

/// Mode: Cai and Du's (2021) balance factor (eq. 9) chooses exploration with probability `balance`.
struct BalanceMode {
    static constexpr bool balanced = true;
    double start = 0.8;    // the balance at the start and after a reconstruction
    std::int64_t thr = 2;  // iterations without improvement before a switch
    double keep = 0.2;     // share of the pod kept by the reconstruction
    WhaleMove operator()(double /*A*/, double p, bool explore) const noexcept {
        if (explore) return WhaleMove::search;
        return p < 0.5 ? WhaleMove::encircle : WhaleMove::spiral;
    }
    void validate(const std::string& who) const {
        require(start >= 0.0 && start <= 1.0, who, "balance must be in [0, 1], got " + std::to_string(start));
        require(thr >= 0, who, "thr must be >= 0, got " + std::to_string(thr));
        require(keep > 0.0 && keep <= 1.0, who, "keep must be in (0, 1], got " + std::to_string(keep));
    }
};
using SelectableWhaleMode = OneOf<ConvergenceMode, BalanceMode>;

/// SecondStep: none (WOA).
struct NoSecondStep {
    static constexpr std::int64_t evaluations_per_whale = 0;
    void validate(const std::string&) const {}
};
/// SecondStep: eq. 8 then harmony improvisations (Cai and Du 2021, section 2.1).
struct HarmonySecondStep {
    static constexpr std::int64_t evaluations_per_whale = 2;
    whale::HarmonyRates rates{0.8, 0.3, 0.01};
    void validate(const std::string& who) const {
        require(rates.hmcr >= 0.0 && rates.hmcr <= 1.0, who, "hmcr must be in [0, 1]");
        require(rates.par >= 0.0 && rates.par <= 1.0, who, "par must be in [0, 1]");
        require(rates.bw >= 0.0 && rates.bw <= 1.0, who, "bw must be in [0, 1]");
    }
};
using SelectableSecondStep = OneOf<NoSecondStep, HarmonySecondStep>;

template <class Draws = PerWhaleDraws, class Mode = ConvergenceMode, class SecondStep = NoSecondStep,
          class Bounds = Clamp, class Init = UniformInit>
class Woa {
  public:
    std::string id = "woa";  // the name in messages and results
    std::int64_t population = 30;
    double b = 1.0;  // the spiral's shape constant of eq. 5
    Draws draws{};
    Mode mode{};
    SecondStep second_step{};
    Bounds bounds{};
    Init init{};

    std::string name() const { return id; }

    void validate() const {
        require(population >= 2, name(), "population must be >= 2, got " + std::to_string(population));
        require(std::isfinite(b), name(), "b must be finite");
        draws.validate(name());
        mode.validate(name());
        second_step.validate(name());
    }

    /// On the box of a BoxProblem.
    template <BoxProblem P, Observer O = NoObserver>
    Result run(P problem, const Termination& termination, std::uint64_t seed, O&& observer = O{}) const {
        whale::BoxPod<Woa, P> pod(*this, problem, termination, seed, observer, horizon_need());
        return iterations(pod, observer);
    }

    /// On chains with TowardMoves (framework/chain.hpp; whale_pods.hpp says how the equations act
    /// on chains). The draws are per whale: PerCoordinateDraws has no meaning on chains.
    template <TowardMoves P, class O = NoObserver>
    BasicResult<typename P::chain_type> run(P problem, const Termination& termination, std::uint64_t seed,
                                            O&& observer = O{}) const {
        visit_policy(draws, [&](const auto& d) {
            require(!std::decay_t<decltype(d)>::per_coordinate, name(),
                    "per-coordinate draws have no meaning on chains");
        });
        whale::ChainPod<Woa, P> pod(*this, problem, termination, seed, observer, horizon_need());
        return iterations(pod, observer);
    }

    std::int64_t evaluations_per_whale() const {
        std::int64_t e = 0;
        visit_policy(second_step, [&](const auto& s) { e = s.evaluations_per_whale; });
        return e;
    }

    /// One WOA sweep (eqs. 1-7) over the pod, in place, with the run's draws; public so that tests
    /// can replay it with scripted draws.
    template <class D, class M, class Draw>
    void sweep(const D&, const M& m, Matrix& x, std::span<const double> leader, double a, double a2, double balance,
               Draw& u) const {
        const auto n = x.cols();
        const auto un = static_cast<std::uint64_t>(n);
        const auto dim = static_cast<std::size_t>(x.rows());
        for (Eigen::Index i = 0; i < n; ++i) {
            double* xi = x.col(i).data();
            auto move = [&](std::size_t d, double A, double C, double p, double spiral, bool explore) {
                switch (m(A, p, explore)) {
                    case WhaleMove::search: {
                        const auto other = static_cast<Eigen::Index>(u.below(un));  // anew per coordinate
                        xi[d] = whale::search(xi[d], x(static_cast<Eigen::Index>(d), other), A, C);  // (6)-(7)
                        break;
                    }
                    case WhaleMove::encircle:
                        xi[d] = whale::encircle(xi[d], leader[d], A, C);
                        break;  // (1)-(2)
                    case WhaleMove::spiral:
                        xi[d] = whale::spiral(xi[d], leader[d], spiral);
                        break;  // (5)
                }
            };
            if constexpr (!D::per_coordinate) {
                const double A = whale::coefficient_a(a, u.uniform());  // (3)
                const double C = whale::coefficient_c(u.uniform());     // (4)
                const double spiral = whale::spiral_factor(whale::l(a2, u.uniform()), b);
                const double p = u.uniform();
                const bool explore = M::balanced && u.uniform() < balance;
                for (std::size_t d = 0; d < dim; ++d) move(d, A, C, p, spiral, explore);
            } else {
                const double spiral = whale::spiral_factor(whale::l(a2, u.uniform()), b);
                const bool explore = M::balanced && u.uniform() < balance;
                for (std::size_t d = 0; d < dim; ++d) {
                    const double A = whale::coefficient_a(a, u.uniform());
                    const double C = whale::coefficient_c(u.uniform());
                    const double p = u.uniform();
                    move(d, A, C, p, spiral, explore);
                }
            }
        }
    }

  private:
    HorizonNeed horizon_need() const { return {population * (1 + evaluations_per_whale()), "for its schedule of a"}; }

    /// The iteration loop, for boxes and chains alike (the pod holds what differs).
    template <class Pod, class O>
    auto iterations(Pod& pod, O& observer) const {
        Rng& rng = pod.rng();
        auto& state = pod.state();
        const std::int64_t horizon = pod.horizon();
        const std::size_t n = pod.size();
        whale::BalanceState balance;
        visit_policy(mode, [&](const auto& m) {
            if constexpr (std::decay_t<decltype(m)>::balanced) balance.balance = m.start;
        });
        std::vector<std::size_t> order(n);

        for (std::int64_t t = 0; !state.done(); ++t) {
            const double before = pod.leader_f();
            const double a = whale::a(t, horizon), a2 = whale::a2(t, horizon);
            visit_policy(draws, [&](const auto& dp) {
                visit_policy(mode, [&](const auto& m) { pod.sweep(dp, m, a, a2, balance.balance); });
            });
            pod.evaluate_pod();
            visit_policy(second_step, [&](const auto& s) {
                // From the type: clang 14 refuses `s.evaluations_per_whale` (a reference) here.
                if constexpr (std::remove_cvref_t<decltype(s)>::evaluations_per_whale > 0) {
                    if (state.exhausted()) return;
                    // Eq. 8: towards X* if better than the average, towards a random whale otherwise.
                    const auto fx = pod.fitness();
                    double avg = 0.0;
                    for (double f : fx) avg += f;
                    avg /= static_cast<double>(n);
                    for (std::size_t i = 0; i < n; ++i) {
                        const bool good = fx[i] < avg;
                        const std::size_t other = good ? 0 : static_cast<std::size_t>(rng.below(n));
                        pod.toward(i, good, other, rng.uniform());
                    }
                    pod.evaluate_pod();
                    // Improvisations from the pod (the harmony memory), each replacing the worst.
                    for (std::size_t k = 0; k < n && !state.exhausted(); ++k) pod.improvise(s.rates);
                }
            });
            visit_policy(mode, [&](const auto& m) {
                if constexpr (std::decay_t<decltype(m)>::balanced) {
                    if (!whale::balance_step(balance, pod.leader_f() < before, m.start, m.thr) || state.exhausted())
                        return;
                    // Reconstruction: keep 20 % by tournament (the best among them), renew the rest.
                    const auto keep = static_cast<std::size_t>(
                        std::clamp<double>(std::round(m.keep * static_cast<double>(n)), 1.0, static_cast<double>(n)));
                    whale::tournament_keep(pod.fitness(), keep, rng, std::span<std::size_t>(order));
                    pod.rebuild(order, keep);
                }
            });
            pod.end_iteration(observer);
        }
        return pod.finish();
    }
};

}  // namespace pride

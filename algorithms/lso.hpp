#pragma once
// Lion swarm optimisation (LSO) and its improved form ILSO: one skeleton, two sets of policies.
//
//   Liu, S., Yang, Y. and Zhou, Y. (2018). A swarm intelligence algorithm: lion swarm optimization.
//     Pattern Recognition and Artificial Intelligence 31(5), 431-441 (LSO).
//   Wan, R. and Gao, Y. (2022). Robot path planning based on rough set reduction and lion swarm
//     optimization. J. Zhengzhou Univ. (Nat. Sci.) 54(2), 32-38 (Wan and Gao 2022: eqs. 1-12, ILSO).
//
// N lions; nLeader = ceil(N beta) within [2, N/2] (eqs. 1-2). The initial pride (run_setup.hpp,
// shared with PSO and the GA): positions by the Init policy, then the Bounds policy, evaluated and
// recorded as iteration 0; p = x; then r of eq. (5). Each iteration t = 1..T:
//   (a) rank the lions by the fitness of their personal bests p: the best is the king, the next
//       nLeader - 1 are lionesses, the rest cubs; g = the king's p;
//   (b) king (eq. 3): x = g (1 + gamma ||p_i - g||);
//   (c) lioness (eq. 4; ILSO eq. 11 multiplies by w): x = w (p_i + p_c)/2 (1 + alpha_f gamma), p_c the
//       p of another lioness drawn at random;
//   (d) cub (eq. 9; ILSO eq. 12 multiplies by w), q ~ U(0,1): q < first: x = w (g + p_i)/2 (1 + alpha_c
//       gamma); first <= q < 2/3: the same around (p_m + p_i)/2, p_m the p of a random lioness;
//       else around (g_bar + p_i)/2, g_bar = low + high - g (eq. 8);
//   (e) the Bounds policy puts x back into the box; all N new positions are evaluated; p_i <- x_i
//       when f(x_i) < f(p_i) (greedy).
// step = r (mean(high) - mean(low)) (eq. 5), alpha_f = step exp(-30 (t/T)^10) (eq. 6), alpha_c =
// step (T - t)/T (eq. 7), w from the Weight policy (UnitWeight: LSO; QuadraticInertia: eq. 10).
// ILSO = Weight QuadraticInertia (0.99 -> 0.35), cub thresholds 3/10 and 2/3 (eq. 12), and an
// initialiser that takes the problem's starting points (rough-set rule walks on grids).
//
// Decided by this project where Wan and Gao (2022) are open: eq. (6) is read as exp(-30 (t/T)^10)
// (the printed exp(-30t/T)^10 vanishes after 2 % of the run, against the paper's own text);
// beta = 0.2 fixed (the paper draws it at random); r of eq. 5 drawn once per run (`step` sets a
// fixed factor instead, 0.1 in the original LSO); gamma is one N(0,1) draw per lion per iteration,
// for every role; t counts the iterations that move, 1..T, so w reaches w_min and alpha_c reaches 0
// on the last one; moves are synchronous (all from the p of the previous iteration); with a single
// lioness (nLeader = 2) her partner is the king; g_bar of eq. (8) is low + high - g per coordinate
// (the project's decision; the paper's overlined low and high, means over the coordinates as in eq. 5, give the
// same point on a cubic box and differ on others); T is the iteration limit or the iterations the
// evaluation budget allows, and when the budget ends inside an iteration the lions left over are
// not evaluated and keep their personal bests. As stated, the king's p_i is g, so eq. (3) puts the
// king back on g, and g is evaluated again (1/N of the budget): kept as written.
#include <algorithm>
#include <cstdint>
#include <numeric>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/parts/common/run_setup.hpp"
#include "algorithms/parts/lion/moves.hpp"
#include "algorithms/parts/swarm/inertia.hpp"
#include "framework/bounds.hpp"
#include "framework/initializer.hpp"
#include "framework/observer.hpp"
#include "framework/problem.hpp"
#include "framework/random.hpp"
#include "framework/result.hpp"
#include "framework/run_state.hpp"
#include "framework/termination.hpp"

namespace pride {

/// The cubs' thresholds of eq. (9): LSO's 1/3 and 2/3.
struct LsoCubs {
    double first = 1.0 / 3.0;
    double second = 2.0 / 3.0;
};
/// ILSO's eq. (12): 3/10 and 2/3.
struct IlsoCubs {
    double first = 0.3;
    double second = 2.0 / 3.0;
};

template <class Weight = UnitWeight, class Cubs = LsoCubs, class Bounds = Clamp, class Init = UniformInit>
class Lso {
  public:
    std::string id = "lso";  // the name in messages and results ("ilso" for that set of policies)
    std::int64_t population = 20;
    double beta = 0.2;                  // share of adult lions, eqs. (1)-(2)
    std::optional<double> step_factor;  // eq. (5): r fixed instead of drawn (0.1: original LSO)
    // One gamma per coordinate instead of one per lion: not Wan and Gao's (2022) reading (every move then
    // scales a whole vector along one ray); an option to measure what that reading costs.
    bool gamma_per_coordinate = false;
    Weight weight{};
    Cubs cubs{};
    Bounds bounds{};
    Init init{};

    std::string name() const { return id; }

    void validate() const {
        require(population >= 4, name(),
                "population must be >= 4 (a king, a lioness, a cub), got " + std::to_string(population));
        require(beta > 0.0 && beta < 1.0, name(), "beta must be in (0, 1), got " + std::to_string(beta));
        if (step_factor)
            require(*step_factor > 0.0 && *step_factor <= 1.0, name(),
                    "step must be in (0, 1], got " + std::to_string(*step_factor));
        require(cubs.first > 0.0 && cubs.first <= cubs.second && cubs.second < 1.0, name(),
                "cub thresholds must satisfy 0 < first <= second < 1, got " + std::to_string(cubs.first) + " and " +
                    std::to_string(cubs.second));
        weight.validate(name());
    }

    template <BoxProblem P, Observer O = NoObserver>
    Result run(P problem, const Termination& termination, std::uint64_t seed, O&& observer = O{}) const {
        // Checks, the initial pride (Init, then Bounds) evaluated and recorded as iteration 0.
        auto run = start_box_run(*this, problem, termination, seed, observer, {population, "(T of eqs. 6, 7 and 10)"});
        const std::int64_t horizon = *run.horizon;
        const auto lo = run.lo, hi = run.hi;
        const std::size_t dim = run.dim;
        Rng& rng = run.rng;
        RunState& state = run.state;
        Matrix& x = run.x;
        std::vector<double>& fx = run.fx;
        const auto n = x.cols();
        const std::int64_t leaders = lion::leaders(population, beta);  // (1), (2)
        const auto lionesses = leaders - 1;

        Matrix p = x;
        std::vector<double> fp = fx, g(dim), g_bar(dim);
        std::vector<Eigen::Index> order(static_cast<std::size_t>(n));
        std::vector<double> gammas(gamma_per_coordinate ? dim : 0);
        // gamma of eqs. 3, 4 and 9: one N(0,1) draw per lion, or one per coordinate (option).
        auto move = [&](auto&& scalar_move, auto&& vector_move) {
            if (gamma_per_coordinate) {
                for (double& v : gammas) v = rng.normal();
                vector_move(std::span<const double>(gammas));
            } else {
                scalar_move(rng.normal());
            }
        };

        const double step = lion::step(step_factor ? *step_factor : rng.uniform(), lo, hi);  // (5)

        for (std::int64_t t = 1; !state.done(); ++t) {
            // (a) roles by the personal bests; ties by index, so the ranking is the seed's alone.
            std::iota(order.begin(), order.end(), Eigen::Index{0});
            std::sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) {
                const auto fa = fp[static_cast<std::size_t>(a)], fb = fp[static_cast<std::size_t>(b)];
                return fa < fb || (fa == fb && a < b);
            });
            const Eigen::Index king = order[0];
            std::copy_n(p.col(king).data(), dim, g.begin());
            lion::opposite(lo, hi, g, g_bar);                   // (8)
            const double w = weight(t - 1, horizon);            // (10)
            const double af = lion::alpha_f(step, t, horizon);  // (6)
            const double ac = lion::alpha_c(step, t, horizon);  // (7)
            auto lioness = [&](std::int64_t k) { return column(p, order[static_cast<std::size_t>(1 + k)]); };

            for (std::size_t r = 0; r < order.size(); ++r) {
                const Eigen::Index i = order[r];
                const auto pi = column(std::as_const(p), i);
                const auto xi = column(x, i);
                if (r == 0) {
                    move([&](double gamma) { lion::king(g, pi, gamma, xi); },
                         [&](std::span<const double> gamma) { lion::king(g, pi, gamma, xi); });  // (3)
                } else if (static_cast<std::int64_t>(r) < leaders) {
                    const auto self = static_cast<std::int64_t>(r) - 1;
                    std::span<const double> partner = g;  // a single lioness hunts with the king
                    if (lionesses > 1) {
                        auto c = static_cast<std::int64_t>(rng.below(static_cast<std::uint64_t>(lionesses - 1)));
                        partner = lioness(c >= self ? c + 1 : c);  // another lioness
                    }
                    move([&](double gamma) { lion::midpoint_move(pi, partner, af, gamma, w, xi); },
                         [&](std::span<const double> gamma) {
                             lion::midpoint_move(pi, partner, af, gamma, w, xi);
                         });  // (4), (11)
                } else {
                    std::span<const double> target = g_bar;
                    switch (lion::cub_target(rng.uniform(), cubs.first, cubs.second)) {  // (9), (12)
                        case lion::CubTarget::king:
                            target = g;
                            break;
                        case lion::CubTarget::lioness:
                            target =
                                lioness(static_cast<std::int64_t>(rng.below(static_cast<std::uint64_t>(lionesses))));
                            break;
                        case lion::CubTarget::opposite:
                            break;
                    }
                    move([&](double gamma) { lion::midpoint_move(target, pi, ac, gamma, w, xi); },
                         [&](std::span<const double> gamma) { lion::midpoint_move(target, pi, ac, gamma, w, xi); });
                }
                bounds(xi, lo, hi);
            }
            // (e) evaluate, then the greedy personal bests; lions past the budget get +inf and keep p.
            state.evaluate_columns(problem, x, fx);
            for (Eigen::Index i = 0; i < n; ++i) {
                const auto ui = static_cast<std::size_t>(i);
                if (fx[ui] < fp[ui]) {
                    p.col(i) = x.col(i);
                    fp[ui] = fx[ui];
                }
            }
            state.end_iteration(observer, x, fx);
        }
        return state.finish();
    }
};

/// LSO as section 1.1 of Wan and Gao (2022) states it.
using LsoAlgorithm = Lso<UnitWeight, LsoCubs, Clamp, UniformInit>;

/// ILSO (Wan and Gao 2022, section 2.3): the same skeleton with the inertia weight of eq. (10), the cub
/// thresholds of eq. (12) and the problem's starting points (rough-set rule walks on grids).
template <class Bounds = Clamp, class Init = SuggestedInit>
Lso<QuadraticInertia, IlsoCubs, Bounds, Init> make_ilso() {
    Lso<QuadraticInertia, IlsoCubs, Bounds, Init> a;
    a.id = "ilso";
    return a;
}

}  // namespace pride

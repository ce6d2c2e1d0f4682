#pragma once
// The whale pods: what differs between whales in a box and whales on chains, behind one interface,
// so that Woa (woa.hpp) has one iteration loop for both. A pod owns the run (Rng and state, from
// run_setup.hpp), the whales, their fitness and the leader X*, and knows how to make and evaluate
// the initial pod, sweep it (eqs. 1-7), move a whale by eq. 8, improvise one harmony and rebuild
// the pod from the whales the tournament kept.
//
// Boxes: the whales are the columns of a matrix and move coordinate by coordinate (Woa::sweep).
// Chains: the whales are the problem's chains and every move is the space's TowardMoves
// capability (framework/chain.hpp): a whale takes a share of its target's course. The share is
// decided here where the papers are silent on how eqs. 1-8 map onto paths: for the encircling and the
// search (eqs. 1-2, 6-7) 1 / (1 + |A|), for the spiral (eq. 5) 1 / (1 + |e^{bl} cos(2 pi l)|) (the
// closer the equation puts the whale to its target, the larger the share; C has no part), for
// eq. 8 its U(0,1) fraction r. A harmony on chains is a memory member (HMCR), pitch-adjusted (PAR)
// by a perturbation of a share BW of its own course, or else a new random chain; a member taken
// as it is (no pitch adjustment) is a copy whose value is known, so it is not evaluated again.
// Shortcuts are the space's (its `shortcut` setting, applied inside its operators), not the pod's.
// Every operator is called through CountedChains (framework/counted_chain.hpp), so whatever an
// operator scores is counted in the run's budget.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "algorithms/parts/common/run_setup.hpp"
#include "algorithms/parts/whale/moves.hpp"
#include "framework/chain.hpp"
#include "framework/counted_chain.hpp"
#include "framework/problem.hpp"
#include "framework/random.hpp"
#include "framework/result.hpp"
#include "framework/run_state.hpp"
#include "framework/termination.hpp"

namespace pride::whale {

/// Whales in the box of a BoxProblem. `Algorithm`: the Woa, for its policies and sweep.
template <class Algorithm, BoxProblem P>
class BoxPod {
  public:
    template <class O>
    BoxPod(const Algorithm& woa, P& problem, const Termination& termination, std::uint64_t seed, O& observer,
           HorizonNeed need)
        : woa_(woa),
          problem_(problem),
          run_(start_box_run(woa, problem, termination, seed, observer, need)),
          leader_(run_.dim),
          y_(run_.dim),
          kept_(run_.x.rows(), run_.x.cols()),
          kept_f_(run_.fx.size()) {
        const auto best = std::min_element(run_.fx.begin(), run_.fx.end()) - run_.fx.begin();
        const auto xb = column(std::as_const(run_.x), best);
        std::copy(xb.begin(), xb.end(), leader_.begin());
        leader_f_ = run_.fx[static_cast<std::size_t>(best)];
    }

    Rng& rng() noexcept { return run_.rng; }
    RunState& state() noexcept { return run_.state; }
    std::int64_t horizon() const noexcept { return *run_.horizon; }
    std::size_t size() const noexcept { return run_.fx.size(); }
    std::span<const double> fitness() const noexcept { return run_.fx; }
    double leader_f() const noexcept { return leader_f_; }

    template <class D, class M>
    void sweep(const D& d, const M& m, double a, double a2, double balance) {
        // From a local copy of the run's Rng, put back afterwards (the same draws): its state can
        // stay in registers, where the member's is loaded and stored at every draw.
        Rng rng = run_.rng;
        woa_.sweep(d, m, run_.x, leader_, a, a2, balance, rng);
        run_.rng = rng;
    }
    void evaluate_pod() {
        for (Eigen::Index i = 0; i < run_.x.cols(); ++i) woa_.bounds(column(run_.x, i), run_.lo, run_.hi);
        consider_pod(0, run_.state.evaluate_columns(problem_, run_.x, run_.fx));
        worst_ = kUnknown;
    }
    /// Eq. 8: whale i towards X* (to_leader) or towards whale `other`, by the fraction r.
    void toward(std::size_t i, bool to_leader, std::size_t other, double r) {
        double* xi = run_.x.col(index(i)).data();
        const double* target = to_leader ? leader_.data() : run_.x.col(index(other)).data();
        for (std::size_t d = 0; d < run_.dim; ++d) xi[d] = whale::toward(xi[d], target[d], r);
    }
    /// One improvisation from the pod, evaluated; it replaces the worst whale when strictly better.
    /// The worst whale is looked for only when the fitness has changed since (as in hs.hpp).
    void improvise(const HarmonyRates& rates) {
        whale::improvise(run_.x, run_.lo, run_.hi, rates, run_.rng, std::span<double>(y_));
        woa_.bounds(std::span<double>(y_), run_.lo, run_.hi);
        const double f = run_.state.evaluate(problem_, std::span<const double>(y_));
        consider(y_, f);
        if (worst_ == kUnknown) worst_ = worst(run_.fx);
        if (f < run_.fx[worst_]) {
            std::copy(y_.begin(), y_.end(), run_.x.col(index(worst_)).data());
            run_.fx[worst_] = f;
            worst_ = kUnknown;
        }
    }
    /// The whales order[0..keep) first, the rest uniform in the box, then Bounds; those evaluated.
    void rebuild(std::span<const std::size_t> order, std::size_t keep) {
        Matrix& x = run_.x;
        const auto n = x.cols();
        for (std::size_t j = 0; j < keep; ++j) {
            kept_.col(index(j)) = x.col(index(order[j]));
            kept_f_[j] = run_.fx[order[j]];
        }
        const auto k = index(keep);
        x.leftCols(k) = kept_.leftCols(k);
        std::copy_n(kept_f_.begin(), keep, run_.fx.begin());
        for (Eigen::Index i = k; i < n; ++i)
            for (std::size_t d = 0; d < run_.dim; ++d) x(index(d), i) = run_.rng.uniform(run_.lo[d], run_.hi[d]);
        for (Eigen::Index i = k; i < n; ++i) woa_.bounds(column(x, i), run_.lo, run_.hi);
        const auto done =
            run_.state.evaluate_columns(problem_, x.rightCols(n - k), std::span<double>(run_.fx).subspan(keep));
        consider_pod(k, done);
        worst_ = kUnknown;
    }
    template <class O>
    void end_iteration(O& observer) {
        run_.state.end_iteration(observer, run_.x, run_.fx);
    }
    Result finish() { return run_.state.finish(); }

  private:
    static Eigen::Index index(std::size_t i) noexcept { return static_cast<Eigen::Index>(i); }
    void consider(std::span<const double> xi, double f) {
        if (f < leader_f_) {
            leader_f_ = f;
            std::copy(xi.begin(), xi.end(), leader_.begin());
        }
    }
    void consider_pod(Eigen::Index from, Eigen::Index count) {
        for (Eigen::Index i = from; i < from + count; ++i)
            consider(column(std::as_const(run_.x), i), run_.fx[static_cast<std::size_t>(i)]);
    }

    static constexpr std::size_t kUnknown = static_cast<std::size_t>(-1);

    const Algorithm& woa_;
    P& problem_;
    BoxRun run_;
    std::vector<double> leader_, y_;
    double leader_f_ = kInf;
    std::size_t worst_ = kUnknown;  // the worst whale, kUnknown once the fitness has changed
    Matrix kept_;                   // the reconstruction's copy of the kept whales
    std::vector<double> kept_f_;
};

/// The share of its target's course a whale on a chain takes for a move whose equation scales the
/// distance by `factor` (A for eqs. 1-2 and 6-7, the spiral's factor for eq. 5).
inline double chain_share(double factor) noexcept {
    return 1.0 / (1.0 + std::abs(factor));
}

/// Whales on the chains of a ChainProblem with TowardMoves.
template <class Algorithm, TowardMoves P>
class ChainPod {
  public:
    using Chain = typename P::chain_type;

    /// The initial pod: N random chains (shortened), made first, then evaluated in order.
    template <class O>
    ChainPod(const Algorithm& woa, P& problem, const Termination& termination, std::uint64_t seed, O& observer,
             HorizonNeed need)
        : problem_(problem),
          run_(start_run<Chain>(woa, termination, seed, need)),
          b_(woa.b),
          x_(static_cast<std::size_t>(woa.population)),
          fx_(x_.size(), kInf),
          kept_(x_.size()),
          kept_f_(x_.size()) {
        for (auto& c : x_) fresh(c);
        evaluate_from(0);
        run_.state.end_iteration(observer, x_, fx_);
    }

    Rng& rng() noexcept { return run_.rng; }
    BasicRunState<Chain>& state() noexcept { return run_.state; }
    std::int64_t horizon() const noexcept { return *run_.horizon; }
    std::size_t size() const noexcept { return x_.size(); }
    std::span<const double> fitness() const noexcept { return fx_; }
    double leader_f() const noexcept { return leader_f_; }

    /// Eqs. 1-7 with one set of draws per whale, in the box sweep's order (A, C, l, p, and q with
    /// the balance mode); whales move one after another in place, as on boxes.
    template <class D, class M>
    void sweep(const D&, const M& m, double a, double a2, double balance) {
        Rng& u = run_.rng;
        const auto un = static_cast<std::uint64_t>(x_.size());
        for (std::size_t i = 0; i < x_.size(); ++i) {
            const double A = coefficient_a(a, u.uniform());  // (3)
            (void)coefficient_c(u.uniform());                // (4): drawn as on boxes, no part on chains
            const double spiral = spiral_factor(l(a2, u.uniform()), b_);
            const double p = u.uniform();
            const bool explore = M::balanced && u.uniform() < balance;
            switch (m(A, p, explore)) {
                case WhaleMove::search:
                    move(x_[i], x_[static_cast<std::size_t>(u.below(un))], chain_share(A));  // (6)-(7)
                    break;
                case WhaleMove::encircle:
                    move(x_[i], leader_, chain_share(A));  // (1)-(2)
                    break;
                case WhaleMove::spiral:
                    move(x_[i], leader_, chain_share(spiral));  // (5)
                    break;
            }
        }
    }
    void evaluate_pod() { evaluate_from(0); }
    void toward(std::size_t i, bool to_leader, std::size_t other, double r) {
        move(x_[i], to_leader ? leader_ : x_[other], r);  // (8)
    }
    void improvise(const HarmonyRates& rates) {
        Rng& u = run_.rng;
        std::optional<double> known;  // a member taken as it is: its value
        if (u.uniform() < rates.hmcr) {
            const auto k = static_cast<std::size_t>(u.below(x_.size()));
            y_ = x_[k];
            if (u.uniform() < rates.par)
                move(y_, y_, rates.bw);
            else
                known = fx_[k];
        } else {
            fresh(y_);
        }
        if (!known && run_.state.exhausted()) return;
        const double f = known ? *known : run_.state.evaluate(problem_, y_);
        consider(y_, f);
        const std::size_t w = worst(fx_);
        if (f < fx_[w]) {
            std::swap(x_[w], y_);
            fx_[w] = f;
        }
    }
    void rebuild(std::span<const std::size_t> order, std::size_t keep) {
        for (std::size_t j = 0; j < keep; ++j) {
            std::swap(kept_[j], x_[order[j]]);
            kept_f_[j] = fx_[order[j]];
        }
        for (std::size_t j = 0; j < keep; ++j) {
            std::swap(x_[j], kept_[j]);
            fx_[j] = kept_f_[j];
        }
        for (std::size_t i = keep; i < x_.size(); ++i) fresh(x_[i]);
        evaluate_from(keep);
    }
    template <class O>
    void end_iteration(O& observer) {
        run_.state.end_iteration(observer, x_, fx_);
    }
    BasicResult<Chain> finish() { return run_.state.finish(); }

  private:
    CountedChains<P, BasicRunState<Chain>> counted() noexcept { return {problem_, run_.state}; }
    void fresh(Chain& c) { counted().random_chain(run_.rng, c); }
    void move(Chain& c, const Chain& target, double share) { counted().toward(c, target, share, run_.rng); }
    void consider(const Chain& c, double f) {
        if (f < leader_f_) {
            leader_f_ = f;
            leader_ = c;
        }
    }
    /// Evaluates whales from..N in order while the budget lasts; +inf past it.
    void evaluate_from(std::size_t from) {
        for (std::size_t i = from; i < x_.size(); ++i) {
            if (run_.state.exhausted()) {
                fx_[i] = kInf;
                continue;
            }
            fx_[i] = run_.state.evaluate(problem_, x_[i]);
            consider(x_[i], fx_[i]);
        }
    }

    P& problem_;
    RunStart<Chain> run_;
    double b_;
    std::vector<Chain> x_;
    std::vector<double> fx_;
    Chain leader_, y_;
    double leader_f_ = kInf;
    std::vector<Chain> kept_;
    std::vector<double> kept_f_;
};

}  // namespace pride::whale

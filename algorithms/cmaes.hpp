#pragma once
// CMA-ES: the covariance matrix adaptation evolution strategy, with restarts and a separable form.
//
//   Hansen, N. (2016). The CMA Evolution Strategy: A Tutorial. arXiv:1604.00772: the algorithm of
//     its appendix A, eqs. (38)-(47), with the default strategy parameters of its table 1,
//     eqs. (48)-(58) (cma_strategy.hpp), the active (negative) weights included.
//   Ros, R. and Hansen, N. (2008). A simple modification in CMA-ES achieving linear time and space
//     complexity. PPSN X, 296-305 (sep-CMA-ES: C diagonal, c_1 and c_mu times (n + 2) / 3).
//   Auger and Hansen (2005), Hansen (2009): restarts and stopping criteria (cma_restarts.hpp,
//     cma_stopping.hpp).
//
// One run from a mean m (the Init policy's point), step sigma_0 and C = diag((high - low)^2), so that
// sigma is a share of each coordinate's range; per generation g = 0, 1, ...:
//   (38)-(40) z_k ~ N(0, I), y_k = B D z_k, x_k = m + sigma y_k, k = 1..lambda (the Boundary policy
//             may draw again or repair, below); the lambda points are evaluated as one batch
//   (41) <y>_w = sum_{i<=mu} w_i y_{i:lambda}             (ranked by f, or by the penalised value)
//   (42) m <- m + c_m sigma <y>_w
//   (43) p_s <- (1 - c_s) p_s + sqrt(c_s (2 - c_s) mu_eff) C^(-1/2) <y>_w
//   (44) sigma <- sigma exp(c_s / d_s (||p_s|| / E||N(0, I)|| - 1))
//   (45) p_c <- (1 - c_c) p_c + h_s sqrt(c_c (2 - c_c) mu_eff) <y>_w, h_s = 1 when
//        ||p_s|| / sqrt(1 - (1 - c_s)^(2 (g + 1))) < (1.4 + 2 / (n + 1)) E||N(0, I)||, else 0
//   (46) w_i° = w_i if w_i >= 0, else w_i n / ||C^(-1/2) y_{i:lambda}||^2
//   (47) C <- (1 + c_1 delta(h_s) - c_1 - c_mu sum_j w_j) C + c_1 p_c p_c^T
//             + c_mu sum_i w_i° y_{i:lambda} y_{i:lambda}^T,  delta(h_s) = (1 - h_s) c_c (2 - c_c)
//   then B, D from C's eigendecomposition (Eigen's SelfAdjointEigenSolver) every
//   max(1, floor(1 / (10 n (c_1 + c_mu)))) generations, as the tutorial advises (section B.2), and
//   the stopping criteria of cma_stopping.hpp. Separable: C is its diagonal, B = I.
// Boundary policies (the tutorial's appendix B.3 names them): Resample draws an infeasible x_k
// again, up to `tries` times, then clamps it (python3-cmaes does the same); ClampRepair evaluates
// the clamped point and uses it in the update; Penalty evaluates the clamped point x^r and ranks by
// f(x^r) + weight ||(x - x^r) / (high - low)||^2, the unrepaired x in the update.
// On a problem with constraints (framework/constraints.hpp) the lambda points of (41) rank by the
// configured handler's order on (f, v) (`constraints`: Deb's feasibility rules by default, the
// epsilon level, whose generation t is the run's iteration, or a static penalty;
// framework/constraint_order.hpp), or by Runarsson and Yao's (2000) stochastic ranking (fig. 1:
// the bubble-sort whose neighbours compare by f when both are feasible or with probability P_f,
// else by v; P_f = 0.45 by default, `constraints.pf`), which ranks the lambda offspring for the
// (mu, lambda) selection as it ranks them in that paper's evolution strategy, or, with
// `augmented_lagrangian`, by f plus the penalty of
// Atamna, Auger and Hansen's (2016, 2017) augmented Lagrangian (augmented_lagrangian.hpp), whose
// coefficients are updated after each generation and start afresh with each run of a restart
// sequence. The run's best point is Deb's best over the true (f, v) either way; without
// constraints the run is the same, bit for bit, as before constraints were handled.
// Integer variables (framework/variables.hpp): with `margin`, CMA-ES with margin (Hamano, Saito,
// Nomura, Shirakawa 2022; parts/cma/margin.hpp) encodes them and bounds their marginal
// probabilities; without it they are real coordinates, which the problem rounds. `unit_covariance`
// and `centre_start` give the start Optuna's CmaEsSampler uses (mean at the centre, C = I with
// sigma0 a share of the smallest range), for comparisons with it.
// Decided by this project where the tutorial is open: stochastic ranking sweeps at most lambda
// times (Runarsson and Yao's N, their number of individuals ranked), from the points in the
// order they were drawn, with one draw of the run's Rng per comparison, taken after the
// generation's samples (so one seed gives one run), and ranks f plus the Penalty boundary's term
// when that boundary is chosen; C starts as diag((high - low)^2) (the
// tutorial's C = I on the box scaled to unit ranges), sigma_0 = 0.3 of that by default (the
// tutorial asks for about a quarter to a third of the search interval); the mean is not evaluated;
// when the budget ends inside a generation, the rest of it is not evaluated and no update follows;
// values are ranked by (value, index), ties in index order; a run without restarts ends at its
// first stopping criterion, before the budget; eigenvalues below zero or not finite count as
// ConditionCov; under the augmented Lagrangian, Stagnation, EqualFunVals and MaxIter are off (its
// ranked values move with its coefficients, and a new run would start its multipliers afresh).
#include <algorithm>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "algorithms/parts/cma/augmented_lagrangian.hpp"
#include "algorithms/parts/cma/restarts.hpp"
#include "algorithms/parts/cma/search.hpp"
#include "algorithms/parts/cma/stopping.hpp"
#include "algorithms/parts/common/run_setup.hpp"
#include "framework/constraint_order.hpp"
#include "framework/constraints.hpp"
#include "framework/error.hpp"
#include "framework/initializer.hpp"
#include "framework/observer.hpp"
#include "framework/one_of.hpp"
#include "framework/problem.hpp"
#include "framework/random.hpp"
#include "framework/result.hpp"
#include "framework/run_state.hpp"
#include "framework/termination.hpp"
#include "framework/variables.hpp"

namespace pride {
namespace cma {

/// Covariance: the full matrix (CMA-ES).
struct FullCovariance {
    static constexpr bool separable = false;
};
/// Covariance: its diagonal only (sep-CMA-ES, Ros and Hansen 2008), O(n) per sample.
struct DiagonalCovariance {
    static constexpr bool separable = true;
};

using SelectableRestarts = OneOf<NoRestarts, Ipop, Bipop>;

/// What one run of a restart sequence was and why it ended (Stop::none: the budget, an iteration
/// limit, the target or the wall time ended it).
struct RunLog {
    std::int64_t lambda = 0;
    Regime regime = Regime::single;
    double sigma0 = 0.0;
    std::int64_t evaluations = 0;
    Stop stop = Stop::none;
    std::vector<double> multipliers;  // the augmented Lagrangian's lam_i at the run's end
};

}  // namespace cma

template <class Covariance = cma::FullCovariance, class Restarts = cma::SelectableRestarts,
          class Boundary = cma::SelectableBoundary, class Init = UniformInit>
class Cmaes {
  public:
    std::string id = "cmaes";     // the name in messages and results
    std::int64_t population = 0;  // lambda of the first run; 0: eq. (48)'s 4 + floor(3 ln n)
    double sigma0 = 0.3;          // initial step as a share of each coordinate's range
    bool active = true;           // the negative weights of eq. (53)
    cma::Tolerances tolerances{};
    Restarts restarts{};
    Boundary boundary{};
    Init init{};
    ConstraintHandling constraints{};   // constrained problems only: the order the points rank by
    bool augmented_lagrangian = false;  // constrained problems only: rank by f + the AL's penalty
    cma::AlSettings al{};               // its parameters
    bool margin = false;                // CMA-ES with margin on integer variables (margin.hpp)
    double margin_alpha = 0.0;          // its alpha; 0: 1 / (n lambda)
    bool unit_covariance = false;       // C starts as (min range)^2 I instead of diag(range^2)
    bool centre_start = false;          // each run's mean starts at the box's centre, not at Init's point

    std::string name() const { return id; }

    void validate() const {
        require(population == 0 || (population >= 2 && population <= 1'000'000), name(),
                "population must be 0 (the default 4 + floor(3 ln D)) or in [2, 1000000], got " +
                    std::to_string(population));
        require(sigma0 > 0.0 && sigma0 <= 10.0, name(), "sigma0 must be in (0, 10], got " + std::to_string(sigma0));
        tolerances.validate(name());
        restarts.validate(name());
        boundary.validate(name());
        constraints.validate(name(), false, true);
        al.validate(name());
        require(margin_alpha >= 0.0 && margin_alpha < 0.5, name(),
                "margin alpha must be in [0, 0.5), got " + std::to_string(margin_alpha));
    }

    /// The first run's lambda in dimension n.
    std::int64_t first_lambda(std::size_t n) const { return population > 0 ? population : cma::default_lambda(n); }

    template <BoxProblem P, Observer O = NoObserver>
    Result run(P problem, const Termination& termination, std::uint64_t seed, O&& observer = O{}) const {
        return run_logged(std::move(problem), termination, seed, observer, nullptr);
    }

    /// run(), and into `log` (when given) one entry per CMA-ES run of the restart sequence.
    template <BoxProblem P, Observer O = NoObserver>
    Result run_logged(P problem, const Termination& termination, std::uint64_t seed, O&& observer,
                      std::vector<cma::RunLog>* log) const {
        auto start = start_run(*this, termination, seed, {}, problem.dimension());
        const std::size_t n = problem.dimension();
        require(n >= 1, name(), "needs a dimension of at least 1");
        seed_noise(problem, seed);
        Rng& rng = start.rng;
        RunState& state = start.state;
        cma::Search<Covariance::separable> search(problem.lower(), problem.upper());
        Matrix mean(static_cast<Eigen::Index>(n), 1);
        auto sequence = visit_policy(restarts, [&](const auto& r) { return AnySequence(r.sequence(first_lambda(n))); });
        cma::RunPlan plan;
        std::vector<std::size_t> integers;  // the margin's coordinates
        if (margin)
            for (std::size_t i = 0; i < n; ++i) {
                const VariableType type = variable_type(problem, i);
                // Hamano et al. (2022) treat integer (and binary) variables; unordered choices are
                // CatCMA's (Hamano et al. 2024), another algorithm.
                require(type != VariableType::categorical, name(),
                        "the margin takes integer and real variables; variable " + std::to_string(i) +
                            " is categorical (the GA family and NSGA-II vary unordered choices)");
                if (type == VariableType::integer) integers.push_back(i);
            }
        constexpr bool constrained = ConstrainedProblem<P>;
        [[maybe_unused]] auto order = order_for<P>(constraints);
        [[maybe_unused]] const bool lagrangian = constrained && augmented_lagrangian;
        // Constrained problems only: the points' violations, constraint values and penalised values.
        std::vector<double> violations, values_g, penalties, fitness;
        cma::AugmentedLagrangian lagrange;
        [[maybe_unused]] std::size_t k = 0;
        cma::Tolerances al_tolerances = tolerances;
        al_tolerances.stagnation = false;
        al_tolerances.equal_fun_values = false;
        al_tolerances.max_iter = false;
        if constexpr (constrained) k = problem.constraint_counts().total();
        // The first generation is iteration 0 (the initial population of other algorithms): it is
        // sampled and evaluated under any limit but the evaluations', so that an iteration limit
        // of k gives k + 1 generations.
        bool first = true;
        auto go_on = [&] { return first ? !state.exhausted() : !state.done(); };
        while (go_on() && sequence.next(rng, plan)) {
            const std::int64_t before = state.progress().evaluations;
            // The mean: one point of the Init policy (or the centre), for the first run and every restart.
            if (centre_start) {
                for (std::size_t i = 0; i < n; ++i)
                    mean(static_cast<Eigen::Index>(i), 0) = 0.5 * (problem.lower()[i] + problem.upper()[i]);
            } else {
                init(problem, rng, mean);
            }
            // Only the points the budget allows are drawn (a last run of a huge lambda needs no
            // more memory than its evaluations); a generation short of lambda ends the run.
            const auto columns = static_cast<Eigen::Index>(std::min(plan.lambda, state.remaining()));
            search.begin(column(mean, 0), sigma0 * plan.sigma_factor, plan.lambda, columns, active, unit_covariance);
            if (!integers.empty()) search.use_margin(integers, margin_alpha);
            if constexpr (constrained) {
                const auto c = static_cast<std::size_t>(columns);
                violations.resize(c);
                if (lagrangian) {
                    values_g.resize(c * k), penalties.resize(c), fitness.resize(c);
                    lagrange.reset(n, problem.constraint_counts(), al);
                }
            }
            cma::Stop stop = cma::Stop::none;
            while (go_on()) {
                // A run with its own limit (BIPOP's small runs) starts only the generations it allows.
                if (state.progress().evaluations - before + plan.lambda > plan.max_evaluations) {
                    stop = cma::Stop::run_budget;
                    break;
                }
                search.sample(rng, boundary);
                if constexpr (constrained) {
                    const auto evaluated =
                        state.evaluate_columns(problem, search.Xeval(), search.values(), violations,
                                               lagrangian ? std::span<double>(values_g) : std::span<double>());
                    state.end_iteration(observer, search.Xeval(), search.values());
                    if (first)
                        order.start(std::span<const double>(violations).first(static_cast<std::size_t>(evaluated)));
                    else
                        order.generation(state.iteration());
                    first = false;
                    if (evaluated < plan.lambda) break;
                    if (lagrangian) {
                        const auto f = search.values();
                        for (std::size_t j = 0; j < penalties.size(); ++j) {
                            penalties[j] = lagrange.penalty(std::span<const double>(values_g).subspan(j * k, k));
                            fitness[j] = f[j] + penalties[j];
                        }
                        stop = search.update(boundary, al_tolerances, PlainOrder{}, {}, penalties);
                        lagrange.end_generation(f, values_g, fitness);
                    } else {
                        stop = search.update(boundary, tolerances, order, violations, {}, &rng);
                    }
                } else {
                    const auto evaluated = state.evaluate_columns(problem, search.Xeval(), search.values());
                    state.end_iteration(observer, search.Xeval(), search.values());
                    first = false;
                    if (evaluated < plan.lambda) break;  // the budget ended inside the generation: no update
                    stop = search.update(boundary, tolerances);
                }
                if (stop != cma::Stop::none) break;
            }
            const std::int64_t used = state.progress().evaluations - before;
            sequence.used(used);
            if (log) log->push_back({plan.lambda, plan.regime, sigma0 * plan.sigma_factor, used, stop, {}});
            if (log && lagrangian) log->back().multipliers = lagrange.multipliers();
        }
        return state.finish();
    }

  private:
    /// Either restart policy's sequence behind one type (the restart scheme is chosen per run).
    struct AnySequence {
        std::variant<cma::NoRestarts::Sequence, cma::Ipop::Sequence, cma::Bipop::Sequence> s;
        template <class S>
        explicit AnySequence(S seq) : s(std::move(seq)) {}
        bool next(Rng& rng, cma::RunPlan& plan) {
            return std::visit([&](auto& q) { return q.next(rng, plan); }, s);
        }
        void used(std::int64_t e) {
            std::visit([&](auto& q) { q.used(e); }, s);
        }
    };
};

}  // namespace pride

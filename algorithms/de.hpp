#pragma once
// Differential evolution: one skeleton for DE, jDE, JADE, SHADE, L-SHADE and jSO, the variable
// parts policies (algorithms/parts/de/mutation.hpp, de_control.hpp, de_population.hpp,
// de_archive.hpp; their comments hold the equations (M1)-(M5), (C), (R), (P1)-(P5), (U1)-(U4),
// (S1)-(S3), (L) with their papers).
//
//   Storn, R. and Price, K. (1997). Differential evolution - a simple and efficient heuristic for
//     global optimization over continuous spaces. J. Global Optimization 11, 341-359.
//   Brest, J., Greiner, S., Boskovic, B., Mernik, M. and Zumer, V. (2006). Self-adapting control
//     parameters in differential evolution. IEEE TEC 10(6), 646-657 (jDE).
//   Zhang, J. and Sanderson, A. C. (2009). JADE: adaptive differential evolution with optional
//     external archive. IEEE TEC 13(5), 945-958.
//   Tanabe, R. and Fukunaga, A. (2013). Success-history based parameter adaptation for differential
//     evolution. Proc. IEEE CEC, 71-78 (SHADE).
//   Tanabe, R. and Fukunaga, A. (2014). Improving the search performance of SHADE using linear
//     population size reduction. Proc. IEEE CEC, 1658-1665 (L-SHADE), and Tanabe's C++ code as the
//     CEC 2022 competition distributes it (lshade.cpp, search_algorithm.cpp, de.h: version 1.0).
//   Brest, J., Maucec, M. S. and Boskovic, B. (2017). Single objective real-parameter optimization:
//     algorithm jSO. Proc. IEEE CEC, 1311-1318.
//
// The initial population (run_setup.hpp): N_init = `population`, or the Size rule (S1)-(S3) when
// it is 0; drawn by the Init policy, evaluated, recorded as iteration 0. Each generation G:
//   (1) rank the population by value (best first, ties to the lower index), as far as the strategy reads;
//   (2) per individual i: F_i, CR_i, F_w,i from the Control policy (P1)-(P5);
//   (3) per individual i: the trial u_i = the Mutation policy's mutant (M1)-(M5) crossed with x_i
//       (C), then the Repair policy (R); every trial is made from the population of step (1)
//       (a synchronous generation);
//   (4) the N trials are evaluated in one batch (RunState::evaluate_columns: what the budget does
//       not allow gets +inf, takes no part in (5), and the run ends);
//   (5) selection, i in order: f(u_i) < f(x_i): a success (F_i, CR_i and |f(u_i) - f(x_i)| go to
//       S_F, S_CR and the gains; x_i, or u_i under `stores_trial`, to the archive) and u_i replaces
//       x_i; f(u_i) = f(x_i): u_i replaces x_i without a success when `ties_replace` (SHADE,
//       L-SHADE, jSO, and this project's DE and jDE), x_i stays otherwise (JADE); the Control keeps
//       a replaced individual's F_i, CR_i (jDE);
//   (6) JADE's archive trim; the Control's memory update (U1)-(U4) from S_F, S_CR;
//   (7) the Reduction policy (L): the worst individuals are removed, the archive resized;
//   (8) the population (its current N columns) is recorded and shown to the observer.
// On a problem with constraints (framework/constraints.hpp) every comparison above, "by value" in
// (1), f(u_i) < f(x_i) and f(u_i) = f(x_i) in (5) and "the worst" in (7), is the order of the
// configured handler (framework/constraint_order.hpp: Deb's rules by default, the epsilon level
// of generation G, or a static penalty), and the gains of (5) are combine_gains()'s, after
// COLSHADE (Gurrola-Ramos et al. 2020); without constraints the run is the same, bit for bit, as
// before constraints existed.
// Integer variables (framework/variables.hpp), which the papers do not treat: with
// `round_integers` each trial's integer coordinates are rounded after the Repair policy (the
// common rounding of the mutant: a crossed coordinate is the mutant's or the integer target's),
// the initial population too.
// Decided by this project where the papers are silent: DE's NP rule is 10 D (Storn and Price
// recommend 5 D to 10 D); ties replace in DE and jDE (Storn's and Tanabe's codes take u when
// f(u) <= f(x)), not in JADE (its pseudo-code keeps x_i when f(x_i) <= f(u_i)); the bound
// handling is JADE's midpoint for every entry by default (de and jde's papers name none; Tanabe's
// jDE code uses the midpoint too; `ClampRepair` is the alternative); jDE starts from F_i = 0.5,
// CR_i = 0.9 (as Tanabe's jDE code); jSO's N_init = round(25 ln D sqrt D) is at least 4 (D = 1 gives 0); a schedule
// over the budget (LPSR, jSO's p, F and CR rules) runs over nfes / max_nfes, max_nfes the
// evaluation limit, so a run without one is refused; draws come from the run's Rng in a fixed
// order (bit identity with the papers' codes and their rand() is not sought, equality in
// distribution is). Where L-SHADE's paper and Tanabe's code (version 1.0, the CEC 2022 oracle)
// differ, the entry `lshade` follows the code by default (`reading=paper` for the paper): see
// de_archive.hpp (archived vector, |A| after a reduction) and de_control.hpp (the terminal value).
// The code also counts an error below 1e-8 as 0 (the CEC rule), which turns near-ties into ties:
// not followed (the algorithm does not know f*; with the CEC 2022 driver's optimum = 0 it never
// fires anyway). p_num = max(2, round(p N)) throughout (the code
// applies the floor of 2 only after a reduction; the same for N_init >= 14 at p = 0.11).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "algorithms/parts/common/run_setup.hpp"
#include "algorithms/parts/de/archive.hpp"
#include "algorithms/parts/de/control.hpp"
#include "algorithms/parts/de/mutation.hpp"
#include "algorithms/parts/de/population.hpp"
#include "framework/bounds.hpp"
#include "framework/constraint_order.hpp"
#include "framework/error.hpp"
#include "framework/initializer.hpp"
#include "framework/observer.hpp"
#include "framework/problem.hpp"
#include "framework/random.hpp"
#include "framework/result.hpp"
#include "framework/run_state.hpp"
#include "framework/termination.hpp"
#include "framework/visit_policy.hpp"

namespace pride {
namespace de {

/// What start_box_run needs to draw the initial population of N_init (run_setup.hpp).
template <class Init>
struct Start {
    std::string id;
    std::int64_t population;
    Init init;
    Clamp bounds{};  // Init draws inside the box; this only guards the problem's own suggestions
    bool round_integers = true;
    std::string name() const { return id; }
    void validate() const {}
};

/// The first `leading` entries of `order` <- those of 0, 1, ..., k - 1 (k its size) ordered by
/// value, best first, ties to the lower index (a total order: the same entries whether the whole
/// is sorted or only its head, which is all a strategy reads: none for rand/1, one for best/1).
inline void rank(std::span<const double> f, std::span<std::size_t> order, std::size_t leading) {
    rank_by(PlainOrder{}, f, {}, order, leading);
}

/// rank() under a constraint order (framework/constraint_order.hpp): by (f, v) as the handler
/// compares them, ties to the lower index.
template <class Order>
void rank(const Order& by, std::span<const double> f, std::span<const double> v, std::span<std::size_t> order,
          std::size_t leading) {
    rank_by(by, f, v, order, leading);
}

/// The index of the first of the worst individuals by `by` (by value: the first of the largest).
template <class Order>
std::size_t worst_index(const Order& by, std::span<const double> f, std::span<const double> v) {
    if constexpr (std::is_same_v<Order, PlainOrder>) {
        return static_cast<std::size_t>(std::max_element(f.begin(), f.end()) - f.begin());
    } else {
        std::size_t worst = 0;
        for (std::size_t i = 1; i < f.size(); ++i)
            if (by.better(f[worst], v[worst], f[i], v[i])) worst = i;
        return worst;
    }
}

/// Under constraints, the gains that weight the successful parameters (control.hpp's weighted
/// means): each success's fall of f and fall of the violation, each divided by the largest of
/// its kind in the generation, summed (Gurrola-Ramos, Hernandez-Aguirre, Dalmau-Cedeno 2020,
/// COLSHADE's selection), so a success in feasibility weighs as much as one in value. A fall
/// of +inf counts 1 and the finite ones of its kind 0 (the limit as it grows).
inline void combine_gains(std::span<double> df, std::span<const double> dv) {
    const auto largest = [](auto values) {
        double m = 0.0;
        for (const double d : values) m = std::max(m, d);
        return m;
    };
    const double mf = largest(std::span<const double>(df)), mv = largest(dv);
    const auto share = [](double d, double m) {
        if (m <= 0.0) return 0.0;
        if (std::isinf(m)) return std::isinf(d) ? 1.0 : 0.0;
        return d / m;
    };
    for (std::size_t k = 0; k < df.size(); ++k) df[k] = share(df[k], mf) + share(dv[k], mv);
}

/// Removes the `count` worst individuals (worst_index), one at a time, as Tanabe's code; the
/// others keep their order. Per-individual control values and violations go with them.
template <class Order>
void remove_worst(const Order& by, Matrix& x, std::vector<double>& fx, std::vector<double>& vx, Adaptation& a,
                  std::size_t count) {
    auto n = static_cast<Eigen::Index>(fx.size());
    for (std::size_t k = 0; k < count; ++k) {
        const auto worst = static_cast<Eigen::Index>(worst_index(by, fx, vx));
        for (Eigen::Index c = worst; c + 1 < n; ++c) x.col(c) = x.col(c + 1);
        fx.erase(fx.begin() + worst);
        vx.erase(vx.begin() + worst);
        if (!a.f.empty()) {
            a.f.erase(a.f.begin() + worst);
            a.cr.erase(a.cr.begin() + worst);
        }
        --n;
    }
    x.conservativeResize(Eigen::NoChange, n);  // once per reduction
}

}  // namespace de

template <class Mutation = de::RandOne, class Control = de::FixedControl, class Repair = de::MidpointRepair,
          class Size = de::PerDimensionSize, class Reduction = de::FixedPopulation, class Init = UniformInit>
class De {
  public:
    std::string id = "de";        // the name in messages and results
    std::int64_t population = 0;  // N_init; 0: the Size policy's rule (the paper's)
    bool ties_replace = true;     // f(u) = f(x): u replaces x (without a success)
    Mutation mutation{};
    Control control{};
    de::ArchiveRules archive{};
    Repair repair{};
    Size size{};
    Reduction reduction{};
    Init init{};
    ConstraintHandling constraints{};  // constrained problems only
    bool round_integers = true;        // integer coordinates: trials rounded (framework/variables.hpp)

    std::string name() const { return id; }

    /// The smallest N_init the mutation and the reduction work with.
    std::int64_t min_population() const {
        std::int64_t least = 0;
        visit_policy(mutation, [&](const auto& m) { least = std::decay_t<decltype(m)>::min_population; });
        visit_policy(reduction, [&](const auto& r) { least = std::max(least, r.min_population()); });
        return least;
    }

    void validate() const {
        std::int64_t by_strategy = 0, by_reduction = 0;
        std::string strategy;
        visit_policy(mutation, [&](const auto& m) {
            by_strategy = std::decay_t<decltype(m)>::min_population;
            strategy = std::decay_t<decltype(m)>::name;
        });
        visit_policy(reduction, [&](const auto& r) { by_reduction = r.min_population(); });
        require(population >= 0, name(),
                "pop must be 0 (the paper's rule) or positive, got " + std::to_string(population));
        require(population == 0 || population >= by_strategy, name(),
                "pop must be 0 (the paper's rule) or >= " + std::to_string(by_strategy) + " for " + strategy +
                    ", got " + std::to_string(population));
        require(by_reduction == 0 || by_reduction >= by_strategy, name(),
                "n_min must be >= " + std::to_string(by_strategy) + " for " + strategy + ", got " +
                    std::to_string(by_reduction));
        require(population == 0 || population >= by_reduction, name(),
                "pop must be 0 (the paper's rule) or >= n_min = " + std::to_string(by_reduction) +
                    " (the population size reduction's floor), got " + std::to_string(population));
        visit_policy(mutation, [&](const auto& m) { m.validate(name()); });
        visit_policy(control, [&](const auto& c) { c.validate(name()); });
        visit_policy(reduction, [&](const auto& r) { r.validate(name()); });
        archive.validate(name());
        constraints.validate(name());
    }

    /// N_init on a problem of dimension `dim`: `population`, or the Size rule when it is 0.
    std::int64_t initial_population(std::size_t dim) const {
        if (population > 0) return population;
        std::int64_t n = 0;
        visit_policy(size, [&](const auto& s) { n = s(dim); });
        return std::max(n, min_population());
    }

    /// True when a policy runs a schedule over the evaluation budget (LPSR, jSO's rules).
    bool needs_evaluation_limit() const {
        bool scheduled = false;
        auto check = [&](const auto& p) { scheduled = scheduled || std::decay_t<decltype(p)>::scheduled; };
        visit_policy(mutation, check);
        visit_policy(control, check);
        visit_policy(reduction, check);
        return scheduled;
    }

    /// Bytes a run allocates in dimension `dim`: the population and the trials, the archive, and
    /// the per-individual and per-slot vectors.
    double memory_bytes(std::size_t dim) const {
        const auto n = static_cast<double>(initial_population(dim));
        const auto a = static_cast<double>(archive.storage(static_cast<std::size_t>(initial_population(dim))));
        std::int64_t slots = 0;
        visit_policy(control, [&](const auto& c) { slots = c.memory_slots(); });
        const double d = static_cast<double>(dim);
        return 8.0 * ((2.0 * n + a) * d + 12.0 * n + 2.0 * static_cast<double>(slots) + 4.0 * d);
    }

    template <BoxProblem P, Observer O = NoObserver>
    Result run(P problem, const Termination& termination, std::uint64_t seed, O&& observer = O{}) const {
        validate();
        termination.validate(name());
        if (needs_evaluation_limit())
            require(termination.max_evaluations.has_value(), name(),
                    "needs an evaluation limit: its population size reduction and schedules run over the "
                    "evaluation budget");
        const std::int64_t n_init = initial_population(problem.dimension());
        // Checks, the initial population (Init) evaluated and recorded as iteration 0.
        auto run =
            start_box_run(de::Start<Init>{id, n_init, init, {}, round_integers}, problem, termination, seed, observer);
        const auto lo = run.lo, hi = run.hi;
        const std::size_t dim = run.dim;
        Rng& rng = run.rng;
        RunState& state = run.state;
        Matrix& x = run.x;
        std::vector<double>& fx = run.fx;
        std::vector<double>& vx = run.vx;
        const auto n0 = static_cast<std::size_t>(n_init);
        auto by = order_for<P>(constraints);
        by.start(vx);
        constexpr bool constrained = ConstrainedProblem<P>;

        // Allocated once per run: trials, their values and parameters, the order, the archive.
        Matrix u(x.rows(), x.cols());
        std::vector<double> fu(n0), vu(n0), scratch(dim), fall_v;
        if constexpr (constrained) fall_v.reserve(n0);
        std::vector<de::Parameters> params(n0);
        std::vector<std::size_t> order(n0);
        std::vector<char> replaced(n0);
        de::Archive archived(dim, n0, archive);
        de::Adaptation adaptation;
        visit_policy(control, [&](const auto& c) { c.start(adaptation, n0); });
        de::Successes successes(n0);
        const std::int64_t limit = termination.max_evaluations.value_or(0);

        std::size_t n = n0;
        for (std::int64_t generation = 1; !state.done(); ++generation) {
            by.generation(generation);
            const de::Spent spent{state.progress().evaluations, limit};
            const auto order_n = std::span<std::size_t>(order).first(n);
            std::size_t leading = 0;
            visit_policy(mutation, [&](const auto& m) { leading = m.ranked(n, spent); });
            de::rank(by, fx, vx, order_n, leading);  // (1)
            // The draws of (2) and (3) come from a local copy of the generator, put back after:
            // its state stays in registers (the same draws in the same order).
            Rng local = rng;
            visit_policy(control, [&](const auto& c) {  // (2)
                for (std::size_t i = 0; i < n; ++i) params[i] = c.sample(adaptation, i, spent, local);
            });
            const de::Generation g{x, order_n, &archived.members(), archived.size(), spent};
            visit_policy(mutation, [&](const auto& m) {  // (3)
                for (std::size_t i = 0; i < n; ++i) {
                    const auto& p = params[i];
                    de::make_trial(m, g, i, p.f, p.cr, p.fw, local, std::span<double>(scratch),
                                   column(u, static_cast<Eigen::Index>(i)));
                }
            });
            rng = local;
            visit_policy(repair, [&](const auto& r) {
                for (std::size_t i = 0; i < n; ++i) {
                    const auto k = static_cast<Eigen::Index>(i);
                    r(column(u, k), column(std::as_const(x), k), lo, hi);
                    if (!run.discrete.empty()) run.round(column(u, k));  // rounded trials
                }
            });
            const auto evaluated = static_cast<std::size_t>(state.evaluate_population(
                problem, u.leftCols(static_cast<Eigen::Index>(n)), std::span<double>(fu).first(n),
                std::span<double>(vu).first(n)));  // (4)
            successes.clear();
            if constexpr (constrained) fall_v.clear();
            for (std::size_t i = 0; i < evaluated; ++i) {  // (5)
                const auto k = static_cast<Eigen::Index>(i);
                const bool better = by.better(fu[i], vu[i], fx[i], vx[i]);
                if (better) {
                    if constexpr (constrained) {
                        successes.add(params[i].f, params[i].cr, std::max(fx[i] - fu[i], 0.0));
                        fall_v.push_back(std::max(vx[i] - vu[i], 0.0));
                    } else {
                        successes.add(params[i].f, params[i].cr, fx[i] - fu[i]);
                    }
                    archived.add(archive.stores_trial ? column(std::as_const(u), k) : column(std::as_const(x), k), rng);
                }
                bool tie = false;
                if constexpr (constrained)
                    tie = !better && !by.better(fx[i], vx[i], fu[i], vu[i]);
                else
                    tie = fu[i] == fx[i];
                replaced[i] = better || (ties_replace && tie);
                if (replaced[i]) {
                    x.col(k) = u.col(k);
                    fx[i] = fu[i];
                    vx[i] = vu[i];
                }
            }
            if constexpr (constrained) de::combine_gains(successes.gain, fall_v);
            visit_policy(control, [&](const auto& c) {  // jDE's F_i, CR_i go with the vector
                for (std::size_t i = 0; i < evaluated; ++i)
                    if (replaced[i]) c.keep(adaptation, i, params[i]);
            });
            archived.end_generation(rng);  // (6)
            visit_policy(control, [&](const auto& c) { c.update(adaptation, successes); });
            const de::Spent after{state.progress().evaluations, limit};  // (7)
            std::size_t next = n;
            visit_policy(reduction, [&](const auto& r) { next = r.next(n, n0, after); });
            if (next < n) {
                de::remove_worst(by, x, fx, vx, adaptation, n - next);
                n = next;
                archived.resize(n, rng);
            }
            state.end_iteration(observer, x, fx);  // (8)
        }
        return state.finish();
    }
};

}  // namespace pride

#pragma once
// SMS-EMOA on boxes.
//
//   Beume, N., Naujoks, B. and Emmerich, M. (2007). SMS-EMOA: Multiobjective selection based on
//     dominated hypervolume. European Journal of Operational Research 181(3), 1653-1669.
//
// Cited by the paper's Algorithm 1 (SMS-EMOA), Algorithm 2 (Reduce) and its exclusive
// contribution Delta_S(s, R) = S(R) - S(R \ {s}) (their numbers in the paper's text not checked
// here). A steady-state (mu + 1) EA; one step t:
//   (1) one child q: two distinct parents drawn uniformly from P_t (the paper's random selection),
//       SBX then polynomial mutation (Crossover and Mutation policies, as in pride::Nsga2);
//   (2) q evaluated;
//   (3) Reduce(P_t u {q}): the mu + 1 points sorted into fronts R_1..R_v
//       (framework/pareto/sorting.hpp); the member of the worst front R_v with the least
//       Delta_S(s, R_v), exact (framework/pareto/hypervolume.hpp), is removed.
// The initial population: mu points uniform in the box, evaluated. The result: the non-dominated
// members of the final population.
//
// Decided by this project, where the paper leaves it open:
// - reference point of Delta_S: per objective the largest value in R_v plus `reference_offset`
//   (default 1), recomputed at every step ("the worst front's nadir plus 1", the usual reading;
//   whether the paper's text says so was not checked here). R_v's own nadir rather than the whole
//   population's: Delta_S is taken within R_v, and a far point would only inflate the ends'
//   boxes. It depends on the objectives' scale;
// - the two ends of a two-objective R_v: measured against that reference point like every other
//   member (`extremes = Extremes::by_reference`, one rule for every M); `Extremes::kept` gives
//   them an infinite contribution instead, the variant that always keeps the front's extent;
// - R_v with one member: it is removed (nothing to measure); R_v of points whose evaluation failed
//   (+inf in every objective, mo_run_state.hpp, so always the worst front): they all contribute 0;
// - ties (equal contributions, equal points, the failed points above): the lowest column goes, the
//   child being column mu, after the population; one seed then gives one result, bit for bit;
// - the child is SBX's first child (the second is dropped: SBX swaps the children's coordinates
//   with probability 1/2 each and the parents come in random order, so either is as likely);
// - iterations: a "generation" of mu children is one iteration of the run state (its history and
//   observer call), the last one shorter when the evaluation budget ends inside it; an observer
//   called per child would see the same population, one member changed, mu times over. The wall
//   time and the stop flag are read before every step too (a generation of a large mu takes
//   minutes), so a generation they end is shorter, as one the evaluation budget ends;
// - operators: eta_c = 20, p_c = 0.9, eta_m = 20, p_m = 1/n, as pride::Nsga2 (NSGA-II's sec. V),
//   so that the two differ only in selection when compared.
// With constraints (framework/multi_objective.hpp's ConstrainedMultiObjectiveProblem): the fronts
// of (3) and of the result are constrained domination's (Deb et al. 2002, sec. VI-A), and a worst
// front of infeasible points loses its lowest column (decided by this project: the paper has no
// constraints; it is how the usual constrained SMS-EMOA codes reduce).
// Cost of a step at M = 2: the O(mu log mu) sort into fronts and Delta_S of R_v from its sorted
// neighbours, O(|R_v| log |R_v|); at M >= 3 Deb's O(M mu^2) sort and, per member of R_v, WFG's
// exclusive hypervolume (the 3-D sweep at M = 3). No allocation per step once the buffers have
// grown to size.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <span>
#include <string>
#include <vector>

#include "algorithms/parts/variation/crossover.hpp"
#include "algorithms/parts/variation/mutation.hpp"
#include "framework/error.hpp"
#include "framework/mo_run_state.hpp"
#include "framework/multi_objective.hpp"
#include "framework/observer.hpp"
#include "framework/pareto/constrained_sorting.hpp"
#include "framework/pareto/hypervolume.hpp"
#include "framework/pareto/sorting.hpp"
#include "framework/random.hpp"
#include "framework/termination.hpp"

namespace pride {

namespace sms {

/// How the two ends of a two-objective worst front are measured (see the header comment).
enum class Extremes { by_reference, kept };

/// Buffers Reduce reuses from step to step; after it, what it saw (for tests and observers).
struct Scratch {
    pareto::SortScratch sort;
    pareto::ConstrainedSortScratch ranking;
    std::vector<std::size_t> rank;
    std::vector<std::size_t> worst;    // R_v's columns, increasing
    std::vector<double> contribution;  // Delta_S of worst[k]; empty when none was computed
    std::vector<double> reference;     // the reference point used
    std::vector<std::size_t> order;    // M = 2: positions in `worst` by (f1, f2, column)
    std::vector<double> flat;          // M != 2: R_v's values, M apart
    pareto::detail::WfgScratch wfg;
};

namespace detail {

/// Delta_S of the mutually non-dominated points worst[0..k) at M = 2: sorted by f1 (so f2
/// decreasing), point t alone covers [f1_t, f1_{t+1}) x [f2_t, f2_{t-1}) (the ends reaching r);
/// a point equal to a neighbour covers nothing alone. The product is the one
/// pareto::contributions() forms, so the values are its own, bit for bit.
inline void contributions_2d(const MatrixView& f, Extremes extremes, Scratch& s) {
    const std::size_t k = s.worst.size();
    s.order.resize(k);
    std::iota(s.order.begin(), s.order.end(), std::size_t{0});
    const auto at = [&](std::size_t t, Eigen::Index i) { return f(i, static_cast<Eigen::Index>(s.worst[t])); };
    std::sort(s.order.begin(), s.order.end(), [&](std::size_t a, std::size_t b) {
        if (at(a, 0) != at(b, 0)) return at(a, 0) < at(b, 0);
        if (at(a, 1) != at(b, 1)) return at(a, 1) < at(b, 1);
        return a < b;
    });
    const auto equal = [&](std::size_t a, std::size_t b) { return at(a, 0) == at(b, 0) && at(a, 1) == at(b, 1); };
    for (std::size_t t = 0; t < k; ++t) {
        const std::size_t p = s.order[t];
        double& c = s.contribution[p];
        if ((t > 0 && equal(s.order[t - 1], p)) || (t + 1 < k && equal(s.order[t + 1], p))) {
            c = 0.0;
        } else if (extremes == Extremes::kept && (t == 0 || t + 1 == k)) {
            c = std::numeric_limits<double>::infinity();
        } else {
            const double right = t + 1 < k ? at(s.order[t + 1], 0) : s.reference[0];
            const double top = t > 0 ? at(s.order[t - 1], 1) : s.reference[1];
            c = (right - at(p, 0)) * (top - at(p, 1));
        }
    }
}

/// Delta_S of worst[0..k) at any M, as pareto::contributions() computes it (WFG's exclhv:
/// the point's box less the hypervolume of its limit set), in buffers kept between steps.
inline void contributions_any(const MatrixView& f, Scratch& s) {
    const std::size_t k = s.worst.size(), m = static_cast<std::size_t>(f.rows());
    s.flat.resize(k * m);
    for (std::size_t t = 0; t < k; ++t)
        for (std::size_t i = 0; i < m; ++i)
            s.flat[t * m + i] = f(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(s.worst[t]));
    s.wfg.prepare(k, m, 3);
    double* limit = s.wfg.limit[m].data();
    double* w = s.wfg.candidate[m].data();
    const double* ref = s.reference.data();
    for (std::size_t t = 0; t < k; ++t) {
        const double* p = s.flat.data() + t * m;
        std::size_t count = 0;
        bool covered = false;  // an equal point: p alone covers nothing
        for (std::size_t j = 0; j < k && !covered; ++j) {
            if (j == t) continue;
            const double* q = s.flat.data() + j * m;
            for (std::size_t i = 0; i < m; ++i) w[i] = std::max(p[i], q[i]);
            covered = pareto::detail::weakly_dominates_flat(q, p, m);
            count = pareto::detail::add_nondominated(limit, count, w, m, m);
        }
        s.contribution[t] = covered ? 0.0
                                    : std::max(0.0, pareto::detail::box_volume(p, m, ref) -
                                                        pareto::detail::hypervolume_flat(limit, count, m, ref, s.wfg));
    }
}

}  // namespace detail

/// Algorithm 2 (Reduce) on the columns of f (M rows, no NaN: the run state has made failed points
/// +inf): returns the column to remove. Fills s.worst, s.reference and s.contribution. With
/// constraints (`violation`: one per column; empty without), the fronts are constrained
/// domination's (framework/pareto/constrained_sorting.hpp) and a worst front of infeasible points
/// (one violation) loses its lowest column: hypervolume measures objectives, not violations.
inline std::size_t reduce(const MatrixView& f, std::span<const double> violation, double reference_offset,
                          Extremes extremes, Scratch& s) {
    const auto n = static_cast<std::size_t>(f.cols());
    const auto m = static_cast<std::size_t>(f.rows());
    if (n == 0) throw InputError("sms::reduce", "there is no point to remove");  // no message built per step
    s.rank.resize(n);
    const std::size_t fronts = pareto::constrained_sort(f, violation, std::span<std::size_t>(s.rank), s.ranking);
    s.worst.clear();
    for (std::size_t i = 0; i < n; ++i)
        if (s.rank[i] + 1 == fronts) s.worst.push_back(i);
    s.contribution.clear();
    s.reference.clear();
    const auto first = static_cast<Eigen::Index>(s.worst.front());
    // One member: removed. Failed points (+inf, equal to each other only): the lowest column.
    if (s.worst.size() == 1 || !f.col(first).allFinite() || (!violation.empty() && violation[s.worst.front()] != 0.0))
        return s.worst.front();
    for (std::size_t i = 0; i < m; ++i) {
        double worst = -std::numeric_limits<double>::infinity();
        for (const std::size_t j : s.worst)
            worst = std::max(worst, f(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)));
        // Every member must strictly dominate r to be measured: an offset lost to rounding next to
        // a large value becomes one ulp; r stays finite.
        double r = worst + reference_offset;
        if (!(r > worst)) r = std::nextafter(worst, std::numeric_limits<double>::infinity());
        s.reference.push_back(std::min(r, std::numeric_limits<double>::max()));
    }
    s.contribution.resize(s.worst.size());
    if (m == 2)
        detail::contributions_2d(f, extremes, s);
    else
        detail::contributions_any(f, s);
    std::size_t least = 0;  // strict <: the lowest column wins a tie
    for (std::size_t k = 1; k < s.worst.size(); ++k)
        if (s.contribution[k] < s.contribution[least]) least = k;
    return s.worst[least];
}

}  // namespace sms

template <class Crossover = SbxCrossover, class Mutation = PolynomialMutation>
struct SmsEmoa {
    std::int64_t population = 100;  // mu
    Crossover crossover{20.0, 0.9};
    Mutation mutation{20.0, -1.0};  // p_m < 0: 1/n
    double reference_offset = 1.0;  // r = the worst front's worst values + this
    sms::Extremes extremes = sms::Extremes::by_reference;

    static std::string name() { return "smsemoa"; }

    void validate() const {
        require(
            population >= 2 && population <= 10'000'000, name(),
            "population must be in [2, 10000000] (two distinct parents per child), got " + std::to_string(population));
        require(reference_offset > 0.0 && reference_offset <= std::numeric_limits<double>::max(), name(),
                "reference_offset must be finite and > 0, got " + std::to_string(reference_offset));
        crossover.validate(name());
        mutation.validate(name());
    }

    template <MultiObjectiveProblem P, class O = NoObserver>
    MultiObjectiveResult run(P problem, const Termination& termination, std::uint64_t seed, O&& observer = O{}) const {
        validate();
        auto start = start_multiobjective_run(name(), problem, termination, seed);
        const std::size_t m = start.objectives;
        Rng& rng = start.rng;
        MultiObjectiveRunState& state = start.state;
        require(extremes == sms::Extremes::by_reference || m == 2, name(),
                "extremes = kept is defined for two objectives, the problem has " + std::to_string(m));
        const std::size_t dim = problem.dimension();
        const auto n = static_cast<std::size_t>(population);
        const auto rows = static_cast<Eigen::Index>(dim), mrows = static_cast<Eigen::Index>(m);
        const auto cols = static_cast<Eigen::Index>(n);
        const auto lo = problem.lower(), hi = problem.upper();

        // The population in x; f has its values and, in column mu, the child's (P_t u {q}); v their
        // violations (constraints only; empty otherwise).
        Matrix x(rows, cols), f(mrows, cols + 1), values(mrows, cols);
        Matrix child(rows, 1), mate(rows, 1), fchild(mrows, 1);
        constexpr bool constrained = ConstrainedMultiObjectiveProblem<P>;
        std::vector<double> v(constrained ? n + 1 : 0);
        const auto evaluate = [&](MatrixView points, Matrix& out, std::span<double> violation) {
            if constexpr (constrained)
                state.evaluate_columns(problem, points, out, violation);
            else
                state.evaluate_columns(problem, points, out);
        };
        for (Eigen::Index j = 0; j < cols; ++j)
            for (std::size_t i = 0; i < dim; ++i) x(static_cast<Eigen::Index>(i), j) = rng.uniform(lo[i], hi[i]);
        evaluate(x, values, constrained ? std::span<double>(v).first(n) : std::span<double>());
        f.leftCols(cols) = values;
        state.end_iteration(observer, x, values);

        const auto cross = crossover.prepare(dim);
        const auto mutate = mutation.prepare(dim);
        sms::Scratch scratch;
        while (!state.done()) {
            // Every rule is read before each step, not once per generation: a generation of mu
            // steps, each O(mu log mu) or more, took minutes for mu = 100000 past --wall-ms.
            for (std::size_t t = 0; t < n && !state.done(); ++t) {
                // (1)
                const auto a = static_cast<Eigen::Index>(rng.below(n));
                auto b = static_cast<Eigen::Index>(rng.below(n - 1));
                if (b >= a) ++b;
                child.col(0) = x.col(a);
                mate.col(0) = x.col(b);
                cross(column(child, 0), column(mate, 0), lo, hi, rng);
                mutate(column(child, 0), lo, hi, rng);
                // (2)
                evaluate(child, fchild, constrained ? std::span<double>(v).subspan(n) : std::span<double>());
                f.col(cols) = fchild.col(0);
                // (3): the child takes the place of the member removed, unless it is removed itself.
                const auto out = static_cast<Eigen::Index>(sms::reduce(f, v, reference_offset, extremes, scratch));
                if (out != cols) {
                    x.col(out) = child.col(0);
                    f.col(out) = f.col(cols);
                    if constexpr (constrained) v[static_cast<std::size_t>(out)] = v[n];
                }
            }
            values = f.leftCols(cols);
            state.end_iteration(observer, x, values);
        }
        scratch.rank.resize(n);
        const auto population_v = constrained ? std::span<const double>(v).first(n) : std::span<const double>();
        pareto::constrained_sort(values, population_v, std::span<std::size_t>(scratch.rank), scratch.ranking);
        std::vector<std::size_t> front;
        for (std::size_t k = 0; k < n; ++k)
            if (scratch.rank[k] == 0) front.push_back(k);
        return state.finish(x, values, front, population_v);
    }
};

}  // namespace pride

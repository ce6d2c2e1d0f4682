#pragma once
// COLSHADE: L-SHADE for constrained problems with an adaptive Levy-flight mutation and a dynamic
// tolerance on the equality constraints.
//
//   Gurrola-Ramos, J., Hernandez-Aguirre, A. and Dalmau-Cedeno, O. (2020). COLSHADE for
//     real-world single-objective constrained optimization problems. Proc. IEEE CEC 2020
//     (an entrant of the CEC 2020 real-world constrained competition, Kumar et al. 2020).
//
// The steps below follow the authors' MATLAB code as submitted to the competition ("CEC E-24586
// codes and results.zip" in P-N-Suganthan/2020-RW-Constrained-Optimisation: colshade.m,
// get_cx_params.m, crossover.m, deb_tournament.m, get_tolerance.m, update_memory.m, sort_pop.m),
// read for its behaviour; an audit found no step that differs. Where the paper (E-24586-Final.pdf
// there) differs, the code is followed by default and the paper is `paper_reading`: the paper
// updates the tolerance (its eq. 9) only when p_G = 0.2 N individuals meet it (counted per
// equality, as the code tests each equality) and with exponent 1 / (FEs_eps - FEs); its
// tournament's third case (eq. 10) asks both points to meet the tolerance; it clips F to F_crit
// (Algorithm 2, line 2) where the code draws again; its CR (eq. 4) is 0 while M_CR is 0 and has no
// terminal value (a memory slot whose successes all had CR = 0 holds 0, and later successes raise
// it again). The best individual's rule in (S7) is the code's in both readings (the paper exempts
// it from the first case only, which would let an epsilon-feasible trial replace a feasible best).
// The step labels (S1)-(S10) are this file's, not the paper's numbers. The
// parts shared with L-SHADE (Tanabe and Fukunaga 2014) are algorithms/parts/de/'s: the archive, the
// weighted Lehmer mean.
//
// A point's violation inside the algorithm is svc(x; eps) = sum_i max(g_i, 0) + sum_j max(|h_j| -
// eps_j, 0), with one tolerance eps_j per equality constraint; svc_abs is svc at eps_j = 1e-4
// (`tolerance`). The run's reported violation is the problem's (CEC's mean), computed apart.
//   (S0) N_init = ceil(18 D) uniform points, evaluated, sorted by svc(x; 0); then eps_j =
//        max(max_i |h_j(x_i)|, 1e-4) (dynamic tolerance) or 1e-4, and the population sorted by
//        svc_abs: ascending, the feasible head by f (a stable sort).
// Each generation, with N the current size and fes the evaluations spent:
//   (S1) svc under eps. While fes < 0.6 max_fes (`cut_off`), for each equality j that some
//        individual meets within eps_j: eps_j <- max(eps_j (1e-4 / eps_j)^(N / (cut - fes)), 1e-4)
//        (the fall that reaches 1e-4 at the cut); from the cut on, eps_j = 1e-4.
//   (S2) per individual: Levy with probability p_levy, otherwise current-to-pbest/1; a slot r of
//        that kind's memory (H = 6 slots each, M_F and M_CR starting at 0.5); CR = M_CR,r +
//        N(0, 0.1) (0 when M_CR,r is terminal), F = M_F,r + Cauchy(0, 0.1) drawn again while F <=
//        F_crit = sqrt((1 - CR / 2) / N) (CR before clipping), then CR clipped to [0, 1], F <= 1.
//   (S3) current-to-pbest/1: v = x_i + F (x_pbest - x_i) + F (x_r1 - x_r2), x_pbest among the
//        ceil(0.11 N) first (the sorted best), r1 != i from the population, r2 != i, r1 from the
//        population and the archive. Levy: v_j = x_i,j + F L_j (x_pbest,j - x_i,j), L_j = 0.01 /
//        z^2 with z standard normal, drawn per coordinate (the stable law of index 1/2, skewness 1,
//        scale 0.01 the code draws: Levy's distribution with location 0).
//   (S4) a coordinate above its bound becomes (1 - b) hi + b x_i,j, below it (1 - b) lo + b x_i,j,
//        b = 0.1 U(0, 1).
//   (S5) binomial crossover with CR (j_rand always from v); (S6) the N trials evaluated.
//   (S7) selection: for the best individual (i = 0 after sorting), the trial replaces it when its
//        svc_abs is smaller, or both are feasible at 1e-4 and its f is smaller; for the others,
//        when its svc is smaller, or both svc are 0 and its f is smaller, or (while some eps_j >
//        1e-4) its svc_abs is smaller. The falls of f and of svc are divided by the largest of
//        their kind and summed into each success's weight; the replaced targets go to the archive.
//   (S8) each kind's memory slot <- the weighted Lehmer means of its successes' F and CR (CR
//        terminal when the slot was or the largest CR is 0); the slot index advances when the kind
//        had a success. p_levy <- 0.25 p_levy + 0.75 (Levy's weight / all weights), within
//        [0.001, 0.999].
//   (S9) sorted as in (S0); (S10) N <- round(4 + (1 - fes / max_fes) (N_init - 4)) keeping the
//        best; the archive cut at random to round(2.6 N).
// Decided by this project where the code is silent or differs: the last generation evaluates only
// what the budget allows (the code stops when a whole generation no longer fits: comparisons here
// are at equal evaluations); a mutant coordinate that is NaN (z = 0 in the Levy draw with x_pbest =
// x_i) keeps the target's value; a fall of +inf (a trial with a finite violation replacing an
// infinite one) takes its kind's whole share (the code divides inf by inf and drops the success),
// and a kind whose weights are all 0 weights its successes equally; draws follow one generator in
// a fixed order (equality in distribution with the code, not in bits). Without constraints the run
// is L-SHADE with the Levy mutation beside current-to-pbest/1.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>
#include <numeric>
#include <span>
#include <string>
#include <vector>

#include "algorithms/de.hpp"
#include "algorithms/parts/common/run_setup.hpp"
#include "algorithms/parts/de/archive.hpp"
#include "algorithms/parts/de/control.hpp"
#include "framework/constraints.hpp"
#include "framework/error.hpp"
#include "framework/initializer.hpp"
#include "framework/observer.hpp"
#include "framework/problem.hpp"
#include "framework/random.hpp"
#include "framework/result.hpp"
#include "framework/run_state.hpp"
#include "framework/termination.hpp"

namespace pride {
namespace colshade {

/// svc: the sum of max(g_i, 0) over the m inequalities and of max(|h_j| - eps_j, 0) over the
/// equalities that follow them in `c`; +inf when a value is NaN.
inline double violation_sum(std::span<const double> c, std::size_t m, std::span<const double> eps) noexcept {
    double sum = 0.0;
    for (std::size_t i = 0; i < m; ++i) {
        if (std::isnan(c[i])) return std::numeric_limits<double>::infinity();
        sum += std::max(c[i], 0.0);
    }
    for (std::size_t j = 0; j < eps.size(); ++j) {
        const double h = c[m + j];
        if (std::isnan(h)) return std::numeric_limits<double>::infinity();
        sum += std::max(std::abs(h) - eps[j], 0.0);
    }
    return sum;
}

/// (S1)'s fall of the tolerances met by some individual: eps_j (final / eps_j)^(n / left), at
/// least `final`; `met[j]` says whether some individual meets equality j within eps_j.
inline void shrink_tolerances(std::span<double> eps, std::span<const char> met, double final, double n,
                              double left) noexcept {
    for (std::size_t j = 0; j < eps.size(); ++j) {
        if (met[j]) eps[j] *= std::pow(final / eps[j], n / left);
        eps[j] = std::max(eps[j], final);
    }
}

/// Levy's distribution with location 0 and scale c: c / z^2, z standard normal.
inline double levy(Rng& rng, double c) noexcept {
    const double z = rng.normal();
    return c / (z * z);
}

/// The order of (S0) and (S9): by svc_abs, then, among the points with svc_abs = 0, by f; stable.
inline void sort_order(std::span<const double> svc_abs, std::span<const double> f, std::vector<std::size_t>& order) {
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        if (svc_abs[a] != svc_abs[b]) return svc_abs[a] < svc_abs[b];
        return svc_abs[a] == 0.0 && f[a] < f[b];
    });
}

}  // namespace colshade

template <class Init = UniformInit>
class Colshade {
  public:
    std::string id = "colshade";
    std::int64_t population = 0;            // N_init; 0: ceil(18 D)
    std::int64_t n_min = 4;                 // N at the end of the linear reduction
    double archive_rate = 2.6;              // |A| = round(2.6 N)
    double p = 0.11;                        // x_pbest among the ceil(p N) best
    std::int64_t memory = 6;                // H, each kind's memory
    double levy_start = 0.5;                // p_levy at the start
    double momentum = 0.25;                 // (S8)
    double levy_floor = 1e-3;               // p_levy in [floor, 1 - floor]
    double levy_scale = 0.01;               // c of L = c / z^2
    bool dynamic_tolerance = true;          // (S1); false: eps_j = `tolerance` throughout
    double cut = 0.6;                       // share of the budget after which eps_j = `tolerance`
    double tolerance = kEqualityTolerance;  // the final tolerance of the equalities
    bool paper_reading = false;             // the paper's eq. 4, 9, 10 and F clip instead of the code's
    double feasible_share = 0.2;            // paper reading: p_G / N, the share that must meet eps_j
    Init init{};

    std::string name() const { return id; }

    void validate() const {
        require(population == 0 || population >= 4, name(),
                "pop must be 0 (ceil(18 D)) or >= 4, got " + std::to_string(population));
        require(n_min >= 4 && n_min <= 1'000'000'000, name(),
                "n_min must be in [4, 1000000000], got " + std::to_string(n_min));
        require(population == 0 || population >= n_min, name(),
                "pop must be 0 or >= n_min = " + std::to_string(n_min) + ", got " + std::to_string(population));
        require(archive_rate >= 0.0 && archive_rate <= 100.0, name(),
                "archive_rate must be in [0, 100], got " + std::to_string(archive_rate));
        require(p > 0.0 && p <= 1.0, name(), "p must be in (0, 1], got " + std::to_string(p));
        de::detail::require_memory_size(memory, 1, name());
        require(levy_start >= 0.0 && levy_start <= 1.0, name(),
                "p_levy must be in [0, 1], got " + std::to_string(levy_start));
        require(momentum >= 0.0 && momentum <= 1.0, name(),
                "momentum must be in [0, 1], got " + std::to_string(momentum));
        require(levy_floor >= 0.0 && levy_floor <= 0.5, name(),
                "levy_floor must be in [0, 0.5], got " + std::to_string(levy_floor));
        require(std::isfinite(levy_scale) && levy_scale > 0.0, name(),
                "levy_scale must be a finite number > 0, got " + std::to_string(levy_scale));
        require(cut >= 0.0 && cut <= 1.0, name(), "cut must be in [0, 1], got " + std::to_string(cut));
        require(std::isfinite(tolerance) && tolerance >= 0.0, name(),
                "tolerance must be a finite number >= 0, got " + std::to_string(tolerance));
        require(feasible_share >= 0.0 && feasible_share <= 1.0, name(),
                "feasible_share must be in [0, 1], got " + std::to_string(feasible_share));
    }

    /// N_init on a problem of dimension `dim`.
    std::int64_t initial_population(std::size_t dim) const {
        if (population > 0) return population;
        return std::max<std::int64_t>(static_cast<std::int64_t>(std::ceil(18.0 * static_cast<double>(dim))), n_min);
    }

    /// Bytes a run allocates: population, trials, sorting copy and archive; the constraint values
    /// of population, trials and copy; the per-individual vectors.
    double memory_bytes(std::size_t dim, std::size_t constraints = 0) const {
        const auto n = static_cast<double>(initial_population(dim));
        const double d = static_cast<double>(dim), k = static_cast<double>(constraints);
        return 8.0 * ((3.0 + archive_rate + 1.0) * n * d + 3.0 * n * k + 16.0 * n + 4.0 * static_cast<double>(memory));
    }

    template <BoxProblem P, Observer O = NoObserver>
    Result run(P problem, const Termination& termination, std::uint64_t seed, O&& observer = O{}) const {
        validate();
        termination.validate(name());
        require(termination.max_evaluations.has_value(), name(),
                "needs an evaluation limit: its population size reduction and tolerances run over the evaluation "
                "budget");
        const std::size_t dim = problem.dimension();
        const auto n0 = static_cast<std::size_t>(initial_population(dim));
        auto start = start_run(de::Start<Init>{id, static_cast<std::int64_t>(n0), init}, termination, seed, {}, dim);
        Rng& rng = start.rng;
        RunState& state = start.state;
        const auto lo = problem.lower(), hi = problem.upper();
        ConstraintCounts counts{};
        if constexpr (ConstrainedProblem<P>) counts = problem.constraint_counts();
        const std::size_t m = counts.inequalities, q = counts.equalities, k = counts.total();
        const double max_fes = static_cast<double>(*termination.max_evaluations);
        const double cut_fes = cut * max_fes;

        // Allocated once per run.
        const auto rows = static_cast<Eigen::Index>(dim);
        Matrix x(rows, static_cast<Eigen::Index>(n0)), u(rows, static_cast<Eigen::Index>(n0)),
            sorted(rows, static_cast<Eigen::Index>(n0));
        std::vector<double> fx(n0), vx(n0), cx(k * n0), fu(n0), vu(n0), cu(k * n0), cs(k * n0);
        std::vector<double> svc(n0), svc_abs(n0), su(n0), su_abs(n0), fall_f(n0), fall_v(n0), moved(n0);
        std::vector<double> eps(q, tolerance), final_eps(q, tolerance), zero(q, 0.0), mutant(dim);
        std::vector<std::size_t> order(n0);
        std::vector<char> levy_kind(n0), met(q);
        std::vector<de::Parameters> params(n0);
        de::ArchiveRules rules;
        rules.rate = archive_rate;
        rules.trim_after_generation = true;  // the replaced targets are all added, then cut
        de::Archive archived(dim, n0, rules);
        struct Memory {
            std::vector<double> f, cr;
            std::size_t next = 0;
        };
        Memory pbest_memory{std::vector<double>(static_cast<std::size_t>(memory), 0.5),
                            std::vector<double>(static_cast<std::size_t>(memory), 0.5)},
            levy_memory = pbest_memory;
        de::Successes pbest_successes(n0), levy_successes(n0);
        double p_levy = levy_start;

        const auto evaluate = [&](MatrixView points, std::span<double> f, std::span<double> v,
                                  std::span<double> c) -> std::size_t {
            if constexpr (ConstrainedProblem<P>) {
                return static_cast<std::size_t>(state.evaluate_columns(problem, points, f, v, c));
            } else {
                (void)v;
                (void)c;
                return static_cast<std::size_t>(state.evaluate_columns(problem, points, f));
            }
        };
        const auto constraints_of = [&](std::vector<double>& c, std::size_t i) {
            return std::span<const double>(c).subspan(i * k, k);
        };
        const auto violations = [&](std::vector<double>& c, std::size_t n, std::span<const double> e,
                                    std::vector<double>& out) {
            for (std::size_t i = 0; i < n; ++i) out[i] = colshade::violation_sum(constraints_of(c, i), m, e);
        };
        // Puts the population in (S0)'s order, with everything that goes with an individual.
        const auto sort_population = [&](std::size_t n, std::span<const double> key) {
            order.resize(n);
            colshade::sort_order(key, std::span<const double>(fx).first(n), order);
            for (std::size_t j = 0; j < n; ++j)
                sorted.col(static_cast<Eigen::Index>(j)) = x.col(static_cast<Eigen::Index>(order[j]));
            x.leftCols(static_cast<Eigen::Index>(n)) = sorted.leftCols(static_cast<Eigen::Index>(n));
            const auto permute = [&](std::vector<double>& values) {
                for (std::size_t j = 0; j < n; ++j) moved[j] = values[order[j]];
                std::copy_n(moved.begin(), n, values.begin());
            };
            permute(fx);
            permute(vx);
            permute(svc);
            permute(svc_abs);
            for (std::size_t j = 0; j < n; ++j)
                std::copy_n(cx.begin() + static_cast<std::ptrdiff_t>(order[j] * k), k,
                            cs.begin() + static_cast<std::ptrdiff_t>(j * k));
            std::copy_n(cs.begin(), n * k, cx.begin());
        };

        // (S0)
        seed_noise(problem, seed);
        init(problem, rng, x);
        evaluate(x, fx, vx, cx);
        std::size_t n = n0;
        violations(cx, n, zero, svc);
        std::copy_n(svc.begin(), n, svc_abs.begin());
        sort_population(n, svc);
        if (dynamic_tolerance)
            for (std::size_t j = 0; j < q; ++j) {
                double largest = tolerance;
                for (std::size_t i = 0; i < n; ++i) {
                    const double h = std::abs(cx[i * k + m + j]);
                    if (h > largest) largest = h;  // NaN is passed over, as MATLAB's max does
                }
                eps[j] = largest;
            }
        violations(cx, n, eps, svc);
        violations(cx, n, final_eps, svc_abs);
        sort_population(n, svc_abs);
        state.end_iteration(observer, x, std::span<const double>(fx).first(n));

        const auto loose = [&] { return std::any_of(eps.begin(), eps.end(), [&](double e) { return e > tolerance; }); };
        while (!state.done()) {
            const auto fes = static_cast<double>(state.progress().evaluations);
            // (S1)
            violations(cx, n, eps, svc);
            if (q > 0 && dynamic_tolerance) {
                bool any_met = false;
                // The code: some individual meets eps_j; the paper: p_G = 0.2 N of them.
                const double needed = paper_reading ? feasible_share * static_cast<double>(n) : 1.0;
                for (std::size_t j = 0; j < q; ++j) {
                    std::size_t meeting = 0;
                    for (std::size_t i = 0; i < n; ++i)
                        if (std::abs(cx[i * k + m + j]) - eps[j] <= 0.0) ++meeting;
                    met[j] = meeting > 0 && static_cast<double>(meeting) >= needed ? 1 : 0;
                    any_met = any_met || met[j];
                }
                if (any_met && loose() && fes < cut_fes) {
                    colshade::shrink_tolerances(eps, met, tolerance, paper_reading ? 1.0 : static_cast<double>(n),
                                                cut_fes - fes);
                    violations(cx, n, eps, svc);
                }
                if (fes >= cut_fes && loose()) {
                    std::fill(eps.begin(), eps.end(), tolerance);
                    violations(cx, n, eps, svc);
                }
            }
            // (S2)-(S5)
            const auto best_count = static_cast<std::uint64_t>(std::max(1.0, std::ceil(p * static_cast<double>(n))));
            const std::size_t archive_size = archived.size();
            for (std::size_t i = 0; i < n; ++i) {
                const bool levy = rng.uniform() <= p_levy;
                levy_kind[i] = levy ? 1 : 0;
                const Memory& mem = levy ? levy_memory : pbest_memory;
                const auto r = static_cast<std::size_t>(rng.below(static_cast<std::uint64_t>(memory)));
                const bool cr_zero = paper_reading ? !(mem.cr[r] > 0.0) : mem.cr[r] < 0.0;
                double cr = cr_zero ? 0.0 : mem.cr[r] + 0.1 * rng.normal();
                const double critical = std::sqrt(std::max(0.0, 1.0 - cr / 2.0) / static_cast<double>(n));
                double f = 0.0;
                if (paper_reading) {
                    f = mem.f[r] + 0.1 * std::tan(std::numbers::pi * (rng.uniform() - 0.5));
                    if (!(f > critical)) f = critical;
                } else {
                    while (!(f > critical)) f = mem.f[r] + 0.1 * std::tan(std::numbers::pi * (rng.uniform() - 0.5));
                }
                cr = std::clamp(cr, 0.0, 1.0);
                f = std::min(f, 1.0);
                params[i] = {f, cr, f};

                const auto pb = static_cast<Eigen::Index>(rng.below(best_count));
                const auto xi = x.col(static_cast<Eigen::Index>(i));
                const auto xp = x.col(pb);
                if (levy) {
                    for (std::size_t d = 0; d < dim; ++d) {
                        const auto e = static_cast<Eigen::Index>(d);
                        mutant[d] = xi(e) + f * colshade::levy(rng, levy_scale) * (xp(e) - xi(e));
                    }
                } else {
                    std::size_t r1 = 0, r2 = 0;
                    do r1 = static_cast<std::size_t>(rng.below(n));
                    while (r1 == i);
                    do r2 = static_cast<std::size_t>(rng.below(n + archive_size));
                    while (r2 == i || r2 == r1);
                    const double* x1 = x.col(static_cast<Eigen::Index>(r1)).data();
                    const double* x2 =
                        r2 < n ? x.col(static_cast<Eigen::Index>(r2)).data() : archived.member(r2 - n).data();
                    for (std::size_t d = 0; d < dim; ++d) {
                        const auto e = static_cast<Eigen::Index>(d);
                        mutant[d] = xi(e) + f * (xp(e) - xi(e)) + f * (x1[d] - x2[d]);
                    }
                }
                for (std::size_t d = 0; d < dim; ++d) {  // (S4)
                    const double target = xi(static_cast<Eigen::Index>(d));
                    if (std::isnan(mutant[d])) {
                        mutant[d] = target;
                    } else if (mutant[d] > hi[d]) {
                        const double b = 0.1 * rng.uniform();
                        mutant[d] = (1.0 - b) * hi[d] + b * target;
                    } else if (mutant[d] < lo[d]) {
                        const double b = 0.1 * rng.uniform();
                        mutant[d] = (1.0 - b) * lo[d] + b * target;
                    }
                }
                de::binomial_crossover(std::span<const double>(xi.data(), dim), std::span<const double>(mutant), cr,
                                       rng, column(u, static_cast<Eigen::Index>(i)));
            }
            // (S6)
            const std::size_t evaluated = evaluate(u.leftCols(static_cast<Eigen::Index>(n)),
                                                   std::span<double>(fu).first(n), std::span<double>(vu).first(n), cu);
            violations(cu, evaluated, eps, su);
            violations(cu, evaluated, final_eps, su_abs);
            // (S7)
            const bool loose_now = loose();
            double largest_f = 0.0, largest_v = 0.0;
            for (std::size_t i = 0; i < evaluated; ++i) {
                fall_f[i] = fall_v[i] = 0.0;
                if (i == 0) {
                    if (su_abs[i] < svc_abs[i])
                        fall_v[i] = svc_abs[i] - su_abs[i];
                    else if (su_abs[i] == 0.0 && svc_abs[i] == 0.0 && fu[i] < fx[i])
                        fall_f[i] = fx[i] - fu[i];
                } else if (su[i] < svc[i]) {
                    fall_v[i] = svc[i] - su[i];
                } else if (su[i] == 0.0 && svc[i] == 0.0 && fu[i] < fx[i]) {
                    fall_f[i] = fx[i] - fu[i];
                } else if ((paper_reading ? su[i] == 0.0 && svc[i] == 0.0 : loose_now) && su_abs[i] < svc_abs[i]) {
                    fall_v[i] = svc_abs[i] - su_abs[i];
                }
                largest_f = std::max(largest_f, fall_f[i]);
                largest_v = std::max(largest_v, fall_v[i]);
            }
            const auto share = [](double d, double largest) {
                if (largest <= 0.0) return 0.0;
                if (std::isinf(largest)) return std::isinf(d) ? 1.0 : 0.0;
                return d / largest;
            };
            pbest_successes.clear();
            levy_successes.clear();
            double levy_weight = 0.0, pbest_weight = 0.0;
            for (std::size_t i = 0; i < evaluated; ++i) {
                if (!(fall_f[i] > 0.0 || fall_v[i] > 0.0)) continue;
                const double w = share(fall_f[i], largest_f) + share(fall_v[i], largest_v);
                auto& successes = levy_kind[i] ? levy_successes : pbest_successes;
                successes.add(params[i].f, params[i].cr, w);
                (levy_kind[i] ? levy_weight : pbest_weight) += w;
                const auto c = static_cast<Eigen::Index>(i);
                archived.add(column(std::as_const(x), c), rng);
                x.col(c) = u.col(c);
                fx[i] = fu[i];
                vx[i] = vu[i];
                svc[i] = su[i];
                svc_abs[i] = su_abs[i];
                std::copy_n(cu.begin() + static_cast<std::ptrdiff_t>(i * k), k,
                            cx.begin() + static_cast<std::ptrdiff_t>(i * k));
            }
            // (S8)
            const auto update = [&](Memory& mem, de::Successes& s) {
                if (s.empty()) return;
                if (std::all_of(s.gain.begin(), s.gain.end(), [](double g) { return g == 0.0; }))
                    std::fill(s.gain.begin(), s.gain.end(), 1.0);
                const bool all_zero = *std::max_element(s.cr.begin(), s.cr.end()) == 0.0;
                if (paper_reading)
                    mem.cr[mem.next] = all_zero ? 0.0 : de::weighted_lehmer_mean(s.cr, s.gain);
                else
                    mem.cr[mem.next] =
                        mem.cr[mem.next] < 0.0 || all_zero ? -1.0 : de::weighted_lehmer_mean(s.cr, s.gain);
                mem.f[mem.next] = de::weighted_lehmer_mean(s.f, s.gain);
                mem.next = (mem.next + 1) % mem.f.size();
            };
            update(pbest_memory, pbest_successes);
            update(levy_memory, levy_successes);
            if (levy_weight + pbest_weight > 0.0) {
                p_levy = momentum * p_levy + (1.0 - momentum) * (levy_weight / (levy_weight + pbest_weight));
                p_levy = std::clamp(p_levy, levy_floor, 1.0 - levy_floor);
            }
            // (S9), (S10)
            sort_population(n, svc_abs);
            const double spent = static_cast<double>(state.progress().evaluations);
            const auto next = static_cast<std::size_t>(
                std::max(static_cast<double>(n_min),
                         std::round(static_cast<double>(n_min) +
                                    (1.0 - spent / max_fes) * (static_cast<double>(n0) - static_cast<double>(n_min)))));
            if (next < n) {
                n = next;
                x.conservativeResize(Eigen::NoChange, static_cast<Eigen::Index>(n));
            }
            archived.resize(n, rng);
            state.end_iteration(observer, x, std::span<const double>(fx).first(n));
        }
        return state.finish();
    }
};

}  // namespace pride

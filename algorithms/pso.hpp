#pragma once
// Particle swarm optimisation, global-best form.
//
//   Kennedy, J. and Eberhart, R. (1995). Particle swarm optimization. Proc. ICNN'95, 1942-1948.
//   Shi, Y. and Eberhart, R. (1998). A modified particle swarm optimizer. Proc. IEEE CEC, 69-73
//     (the inertia weight).
//   Clerc, M. and Kennedy, J. (2002). The particle swarm - explosion, stability, and convergence in
//     a multidimensional complex space. IEEE TEC 6(1), 58-73 (the constriction factor).
//
// The initial swarm (run_setup.hpp, shared with the GA and LSO): positions by the Init policy, put in
// the box by the Bounds policy, evaluated and recorded as iteration 0; then the velocities, particle
// by particle; p = x; g = the best p.
// Per iteration t, for each particle i and coordinate d, with r1, r2 ~ U(0,1) drawn per coordinate
// (both from one generator step, 32 bits each: see Rng::fill_uniform_pairs):
//   (1) v_id <- a v_id + b1 r1 (p_id - x_id) + b2 r2 (g_d - x_id)   (a, b1, b2 from the Velocity policy:
//       w(t), c1, c2 for the inertia form; chi, chi c, chi c for the constriction form)
//   (2) v_id <- clamp(v_id, -vmax_d, vmax_d)                          (VelocityClamp policy)
//   (3) x_id <- x_id + v_id, then the Bounds policy puts x back into the box
//   (4) p_i <- x_i if f(x_i) < f(p_i);  g <- the best p after the whole sweep (synchronous update)
// On a constrained problem (framework/constraints.hpp) the comparisons of (4) and the choice of g
// are the configured handler's (`constraints`: Deb's feasibility rules, the default, as Deb (2000)
// applies them to selection and as the constrained PSO literature to p and g; the epsilon level;
// a static penalty), on (f, v) pairs; the epsilon level's generation is the iteration.
// Defaults (docs/algorithms.md): w 0.9 -> 0.4 linearly, c1 = c2 = 2, vmax = 0.2 (high - low),
// clamping to the box.
// Integer variables (framework/variables.hpp), which the papers do not treat: with
// `round_integers` the positions are rounded on those coordinates after each move (rounded
// positions, the common treatment; the velocities stay real), the initial swarm too.
// Decided by this project where the papers are silent: initial velocities are U(-vmax, vmax);
// w(t) runs over the horizon T = the iteration limit, or the iterations the evaluation budget
// allows, reaching w_end on the last one; when the budget ends inside a sweep the remaining
// particles do not move; the constriction variant keeps the velocity clamp (Eberhart and Shi 2000
// found constriction with a clamp better than either alone; Clerc and Kennedy need none).
#include <algorithm>
#include <cstdint>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "algorithms/parts/common/run_setup.hpp"
#include "algorithms/parts/swarm/velocity.hpp"
#include "framework/bounds.hpp"
#include "framework/constraint_order.hpp"
#include "framework/initializer.hpp"
#include "framework/observer.hpp"
#include "framework/problem.hpp"
#include "framework/random.hpp"
#include "framework/result.hpp"
#include "framework/run_state.hpp"
#include "framework/termination.hpp"

namespace pride {
namespace detail {

/// Eqs. (1)-(3) for the coordinates of one particle two at a time (SSE2), returning how many were
/// moved (the rest, an odd last one, the caller moves). Bit-identical to the scalar loop: each lane
/// performs the scalar loop's operations in its order, no contraction; r1 and r2 are the high and
/// low 32 bits of one step each, converted exactly (2^52 + k, less 2^52, times 2^-32); the clamps
/// are minpd/maxpd with std::min and std::max's operand order (and so their NaN rule); with
/// `clamp`, the Clamp policy's max(lo, min(x, hi)) follows on each coordinate. Always inlined, so
/// that the caller's local generator stays in registers.
template <bool clamp>
[[gnu::always_inline]] inline std::size_t move_pairs(
    [[maybe_unused]] Rng& rng, [[maybe_unused]] double a, [[maybe_unused]] double b1, [[maybe_unused]] double b2,
    [[maybe_unused]] double* x, [[maybe_unused]] double* v, [[maybe_unused]] const double* p,
    [[maybe_unused]] const double* g, [[maybe_unused]] const double* vmax, [[maybe_unused]] const double* lo,
    [[maybe_unused]] const double* hi, [[maybe_unused]] std::size_t dim) noexcept {
#if defined(__SSE2__)
    const __m128i low32 = _mm_set1_epi64x(0xFFFFFFFF), magic = _mm_set1_epi64x(0x4330000000000000);
    const __m128d two52 = _mm_set1_pd(0x1.0p52), scale = _mm_set1_pd(0x1.0p-32), sign = _mm_set1_pd(-0.0);
    const __m128d av = _mm_set1_pd(a), b1v = _mm_set1_pd(b1), b2v = _mm_set1_pd(b2);
    std::size_t d = 0;
    for (; d + 2 <= dim; d += 2) {
        const auto first = static_cast<long long>(rng()), second = static_cast<long long>(rng());
        const __m128i bits = _mm_set_epi64x(second, first);
        const __m128d r1 =
            _mm_mul_pd(_mm_sub_pd(_mm_castsi128_pd(_mm_or_si128(_mm_srli_epi64(bits, 32), magic)), two52), scale);
        const __m128d r2 =
            _mm_mul_pd(_mm_sub_pd(_mm_castsi128_pd(_mm_or_si128(_mm_and_si128(bits, low32), magic)), two52), scale);
        const __m128d xd = _mm_loadu_pd(x + d), limit = _mm_loadu_pd(vmax + d);
        const __m128d vd = _mm_add_pd(_mm_add_pd(_mm_mul_pd(av, _mm_loadu_pd(v + d)),
                                                 _mm_mul_pd(_mm_mul_pd(b1v, r1), _mm_sub_pd(_mm_loadu_pd(p + d), xd))),
                                      _mm_mul_pd(_mm_mul_pd(b2v, r2), _mm_sub_pd(_mm_loadu_pd(g + d), xd)));  // (1)
        // (2): std::max(-vmax, std::min(vd, vmax))
        const __m128d vn = _mm_max_pd(_mm_min_pd(limit, vd), _mm_xor_pd(limit, sign));
        _mm_storeu_pd(v + d, vn);
        __m128d xn = _mm_add_pd(xd, vn);  // (3)
        if constexpr (clamp) xn = _mm_max_pd(_mm_min_pd(_mm_loadu_pd(hi + d), xn), _mm_loadu_pd(lo + d));
        _mm_storeu_pd(x + d, xn);
    }
    return d;
#else
    return 0;
#endif
}

}  // namespace detail

template <class Velocity = InertiaVelocity<LinearInertia>, class VelocityClamp = RangeVelocityClamp,
          class Bounds = Clamp, class Init = UniformInit>
class Pso {
  public:
    std::string id = "pso";  // the name in messages and results ("pso-constriction" for that variant)
    std::int64_t population = 50;
    Velocity velocity{};
    VelocityClamp velocity_clamp{};
    Bounds bounds{};
    Init init{};
    ConstraintHandling constraints{};  // constrained problems only
    bool round_integers = true;        // integer coordinates: rounded positions (framework/variables.hpp)

    std::string name() const { return id; }

    void validate() const {
        require(population >= 2, name(), "population must be >= 2, got " + std::to_string(population));
        velocity.validate(name());
        velocity_clamp.validate(name());
        constraints.validate(name());
    }

    template <BoxProblem P, Observer O = NoObserver>
    Result run(P problem, const Termination& termination, std::uint64_t seed, O&& observer = O{}) const {
        // Checks, the initial swarm (Init, then Bounds) evaluated and recorded as iteration 0.
        auto run = start_box_run(*this, problem, termination, seed, observer, {population, "for its inertia schedule"});
        const std::int64_t horizon = *run.horizon;
        const auto lo = run.lo, hi = run.hi;
        const std::size_t dim = run.dim;
        Rng& rng = run.rng;
        RunState& state = run.state;
        Matrix& x = run.x;
        std::vector<double>& fx = run.fx;
        std::vector<double>& vx = run.vx;
        const auto n = x.cols();
        auto order = order_for<P>(constraints);
        order.start(vx);

        Matrix v(x.rows(), n), p = x;
        std::vector<double> fp = fx, vp = vx, vmax(dim), g(dim);
        for (std::size_t d = 0; d < dim; ++d) vmax[d] = velocity_clamp.limit(lo[d], hi[d]);
        for (Eigen::Index i = 0; i < n; ++i)
            for (std::size_t d = 0; d < dim; ++d) v(static_cast<Eigen::Index>(d), i) = rng.uniform(-vmax[d], vmax[d]);
        auto refresh_global_best = [&] {
            const auto best = column(p, static_cast<Eigen::Index>(best_index(order, fp, vp)));
            std::copy(best.begin(), best.end(), g.begin());
        };
        refresh_global_best();

        for (std::int64_t t = 0; !state.done(); ++t) {
            const auto [a, b1, b2] = velocity(t, horizon);
            order.generation(t + 1);
            // Every particle moves (1)-(3), then the swarm is evaluated in one batch; g is fixed
            // within an iteration, so this is the same run as evaluating particle by particle.
            const auto moving = std::min<Eigen::Index>(n, static_cast<Eigen::Index>(state.remaining()));
            // Drawn from a local copy of the generator, put back after the sweep: its state stays
            // in registers (the same draws in the same order).
            Rng local = rng;
            for (Eigen::Index i = 0; i < moving; ++i) {
                double* xi = x.col(i).data();
                double* vi = v.col(i).data();
                const double* pi = p.col(i).data();
                constexpr bool clamp = std::is_same_v<Bounds, Clamp>;
                std::size_t d = detail::move_pairs<clamp>(local, a, b1, b2, xi, vi, pi, g.data(), vmax.data(),
                                                          lo.data(), hi.data(), dim);
                for (; d < dim; ++d) {
                    // r1, r2 from the high and low 32 bits of one step, as Rng::fill_uniform_pairs.
                    const std::uint64_t bits = local();
                    const double r1 = Rng::high_unit(bits), r2 = Rng::low_unit(bits);
                    const double vd = a * vi[d] + b1 * r1 * (pi[d] - xi[d]) + b2 * r2 * (g[d] - xi[d]);  // (1)
                    vi[d] = std::max(-vmax[d], std::min(vd, vmax[d]));                     // (2), branch-free
                    xi[d] += vi[d];                                                        // (3)
                    if constexpr (clamp) xi[d] = std::max(lo[d], std::min(xi[d], hi[d]));  // Clamp's own formula
                }
                if constexpr (!clamp) bounds(column(x, i), lo, hi);
                if (!run.discrete.empty()) run.round(column(x, i));
            }
            rng = local;
            state.evaluate_population(problem, x.leftCols(moving),
                                      std::span<double>(fx).first(static_cast<std::size_t>(moving)),
                                      std::span<double>(vx).first(static_cast<std::size_t>(moving)));
            for (Eigen::Index i = 0; i < moving; ++i) {
                const auto ui = static_cast<std::size_t>(i);
                if (order.better(fx[ui], vx[ui], fp[ui], vp[ui])) {  // (4)
                    p.col(i) = x.col(i);
                    fp[ui] = fx[ui];
                    vp[ui] = vx[ui];
                }
            }
            refresh_global_best();
            state.end_iteration(observer, x, fx);
        }
        return state.finish();
    }
};

}  // namespace pride

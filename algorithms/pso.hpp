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
// Spec defaults (shared/spec/algorithms.md): w 0.9 -> 0.4 linearly, c1 = c2 = 2, vmax = 0.2 (high - low),
// clamping to the box.
// Decided by this project where the papers are silent: initial velocities are U(-vmax, vmax);
// w(t) runs over the horizon T = the iteration limit, or the iterations the evaluation budget
// allows, reaching w_end on the last one; when the budget ends inside a sweep the remaining
// particles do not move; the constriction variant keeps the velocity clamp (Eberhart and Shi 2000
// found constriction with a clamp better than either alone; Clerc and Kennedy need none).
#include <algorithm>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/parts/run_setup.hpp"
#include "algorithms/parts/velocity.hpp"
#include "framework/bounds.hpp"
#include "framework/initializer.hpp"
#include "framework/observer.hpp"
#include "framework/problem.hpp"
#include "framework/random.hpp"
#include "framework/result.hpp"
#include "framework/run_state.hpp"
#include "framework/termination.hpp"

namespace pride {

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

    std::string name() const { return id; }

    void validate() const {
        require(population >= 2, name(), "population must be >= 2, got " + std::to_string(population));
        velocity.validate(name());
        velocity_clamp.validate(name());
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
        const auto n = x.cols();

        Matrix v(x.rows(), n), p = x;
        std::vector<double> fp = fx, vmax(dim), g(dim), r1(dim), r2(dim);
        for (std::size_t d = 0; d < dim; ++d) vmax[d] = velocity_clamp.limit(lo[d], hi[d]);
        for (Eigen::Index i = 0; i < n; ++i)
            for (std::size_t d = 0; d < dim; ++d) v(static_cast<Eigen::Index>(d), i) = rng.uniform(-vmax[d], vmax[d]);
        auto refresh_global_best = [&] {
            const auto best = column(p, std::min_element(fp.begin(), fp.end()) - fp.begin());
            std::copy(best.begin(), best.end(), g.begin());
        };
        refresh_global_best();

        for (std::int64_t t = 0; !state.done(); ++t) {
            const auto [a, b1, b2] = velocity(t, horizon);
            // Every particle moves (1)-(3), then the swarm is evaluated in one batch; g is fixed
            // within an iteration, so this is the same run as evaluating particle by particle.
            const auto moving = std::min<Eigen::Index>(n, static_cast<Eigen::Index>(state.remaining()));
            for (Eigen::Index i = 0; i < moving; ++i) {
                double* xi = x.col(i).data();
                double* vi = v.col(i).data();
                const double* pi = p.col(i).data();
                rng.fill_uniform_pairs(r1, r2);
                for (std::size_t d = 0; d < dim; ++d) {
                    const double vd = a * vi[d] + b1 * r1[d] * (pi[d] - xi[d]) + b2 * r2[d] * (g[d] - xi[d]);  // (1)
                    vi[d] = std::max(-vmax[d], std::min(vd, vmax[d]));  // (2), branch-free
                    xi[d] += vi[d];                                     // (3)
                }
                bounds(column(x, i), lo, hi);
            }
            state.evaluate_columns(problem, x.leftCols(moving),
                                   std::span<double>(fx).first(static_cast<std::size_t>(moving)));
            for (Eigen::Index i = 0; i < moving; ++i) {
                const auto ui = static_cast<std::size_t>(i);
                if (fx[ui] < fp[ui]) {  // (4)
                    p.col(i) = x.col(i);
                    fp[ui] = fx[ui];
                }
            }
            refresh_global_best();
            state.end_iteration(observer, x, fx);
        }
        return state.finish();
    }
};

}  // namespace pride

#pragma once
// Any NLopt algorithm (Johnson, The NLopt nonlinear-optimization package,
// https://github.com/stevengj/nlopt) by its NLopt name, on any box problem, as a baseline.
//
// Mapping to the framework: the evaluation limit becomes maxeval and is also enforced by the
// evaluation guard (the objective stops NLopt before an evaluation past the budget); a target
// value becomes stopval; wall time becomes maxtime; the seed seeds NLopt's generator
// (nlopt_srand) and draws the starting point. NLopt has no iterations: one "iteration" here is a
// block of `record_every` evaluations, so histories are comparable with population algorithms of
// that size.
// Decided by this project: the starting point is uniform in the box (drawn from the seed), so
// that local algorithms differ between seeds; when NLopt stops on its own before any limit of the
// run (it converged, possibly to a local minimum), it is restarted from a new uniform point, so a
// baseline always spends the budget it is compared under (`restart = false` runs NLopt once);
// algorithms that need a local optimiser (MLSL, AUGLAG) get LN_SBPLX; gradient-based algorithms
// (LD_*, GD_*) are refused, since problems here give no gradients.
// Non-finite values (NaN, +-inf) reach NLopt as a finite plateau just above the worst finite
// value seen (+inf before any): the run state still ranks them worst, but NLopt's models (NEWUOA,
// BOBYQA) looped without end on NaN and -inf, so they never see them.
#include <nlopt.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "framework/error.hpp"
#include "framework/observer.hpp"
#include "framework/problem.hpp"
#include "framework/random.hpp"
#include "framework/result.hpp"
#include "framework/run_state.hpp"
#include "framework/termination.hpp"

namespace pride {

/// NLopt names its gradient-based algorithms LD_* and GD_*.
inline bool nlopt_needs_gradient(const std::string& name) {
    return name.size() > 3 && name[1] == 'D' && name[2] == '_';
}

/// NLopt's algorithm of that name, or -1. Not nlopt_algorithm_from_string: it answers an unknown
/// name with (nlopt_algorithm)-1, a value outside the enumeration (undefined behaviour to load,
/// which clang's UBSan reports).
inline int nlopt_algorithm_index(const std::string& name) {
    for (int a = 0; a < NLOPT_NUM_ALGORITHMS; ++a)
        if (name == nlopt_algorithm_to_string(static_cast<nlopt_algorithm>(a))) return a;
    return -1;
}

/// Every NLopt algorithm of this NLopt build that needs no gradient, by NLopt's name ("LN_SBPLX",
/// "GN_CRS2_LM", ...); algorithms the build left out ("NOT COMPILED") are not listed.
inline std::vector<std::string> nlopt_derivative_free_names() {
    std::vector<std::string> names;
    for (int a = 0; a < NLOPT_NUM_ALGORITHMS; ++a) {
        const auto algorithm = static_cast<nlopt_algorithm>(a);
        const std::string name = nlopt_algorithm_to_string(algorithm);
        if (!nlopt_needs_gradient(name) &&
            std::string(nlopt_algorithm_name(algorithm)).find("NOT COMPILED") == std::string::npos)
            names.push_back(name);
    }
    return names;
}

class Nlopt {
  public:
    /// `algorithm`: NLopt's name, with or without the "nlopt:" prefix.
    explicit Nlopt(std::string algorithm, std::int64_t record_every = 50) : record_every(record_every) {
        if (algorithm.rfind("nlopt:", 0) == 0) algorithm.erase(0, 6);
        algorithm_ = algorithm;
        validate();
    }

    std::int64_t record_every;
    bool restart = true;

    std::string name() const { return "nlopt:" + algorithm_; }

    void validate() const {
        const int index = nlopt_algorithm_index(algorithm_);
        require(index >= 0, "algo", "unknown NLopt algorithm '" + algorithm_ + "'");
        const auto a = static_cast<nlopt_algorithm>(index);
        require(std::string(nlopt_algorithm_name(a)).find("NOT COMPILED") == std::string::npos, name(),
                "is not compiled into this NLopt build");
        require(!nlopt_needs_gradient(algorithm_), name(),
                "needs gradients, which pride's problems do not provide; use an LN_ or GN_ algorithm");
        require(record_every >= 1, name(), "pop (evaluations per recorded iteration) must be >= 1");
    }

    template <BoxProblem P, Observer O = NoObserver>
    Result run(P problem, const Termination& termination, std::uint64_t seed, O&& observer = O{}) const {
        validate();
        termination.validate(name());
        const std::size_t dim = problem.dimension();
        const auto lo = problem.lower();
        const auto hi = problem.upper();
        Rng rng(seed);
        std::vector<double> x0(dim);
        for (std::size_t d = 0; d < dim; ++d) x0[d] = rng.uniform(lo[d], hi[d]);
        nlopt::srand(static_cast<unsigned long>(seed));
        seed_noise(problem, seed);

        RunState state(termination, dim);
        Matrix current(static_cast<Eigen::Index>(dim), 1);  // what the observer sees: the last point
        double current_f = kInf;
        auto record = [&] { state.end_iteration(observer, current, std::span<const double>(&current_f, 1)); };
        std::int64_t limit = std::numeric_limits<std::int64_t>::max();
        if (termination.max_evaluations) limit = *termination.max_evaluations;
        if (termination.max_iterations && *termination.max_iterations < limit / record_every - 1)
            limit = std::min(limit, (*termination.max_iterations + 1) * record_every);
        // Inside NLopt only the target and the wall clock are checked per evaluation; evaluation
        // and iteration limits are `limit`.
        Termination per_evaluation = termination;
        per_evaluation.max_evaluations.reset();
        per_evaluation.max_iterations.reset();

        struct Context {
            P* problem;
            RunState* state;
            Matrix* current;
            double* current_f;
            std::int64_t limit;
            std::int64_t record_every;
            decltype(record)* record_iteration;
            const Termination* termination;
            double best_finite = kInf, worst_finite = -kInf;
        } context{&problem, &state, &current, &current_f, limit, record_every, &record, &per_evaluation};

        auto objective = [](unsigned n, const double* x, double*, void* data) -> double {
            auto& c = *static_cast<Context*>(data);
            if (c.state->exhausted() || c.state->progress().evaluations >= c.limit ||
                (c.state->progress().evaluations > 0 && c.termination->done(c.state->progress())))
                throw nlopt::forced_stop();
            const std::span<const double> point(x, n);
            const double f = c.state->evaluate(*c.problem, point);
            std::copy(point.begin(), point.end(), c.current->data());
            *c.current_f = f;
            if (c.state->progress().evaluations % c.record_every == 0) (*c.record_iteration)();
            if (std::isfinite(f)) {
                c.best_finite = std::min(c.best_finite, f);
                c.worst_finite = std::max(c.worst_finite, f);
                return f;
            }
            if (!std::isfinite(c.worst_finite)) return kInf;
            return c.worst_finite + (c.worst_finite - c.best_finite) + 1.0;
        };
        const std::vector<double> lower(lo.begin(), lo.end()), upper(hi.begin(), hi.end());
        while (true) {
            nlopt::opt opt = make_optimiser(dim);
            opt.set_lower_bounds(lower);
            opt.set_upper_bounds(upper);
            opt.set_min_objective(objective, &context);
            const std::int64_t left = limit - state.progress().evaluations;
            if (left < std::numeric_limits<int>::max()) opt.set_maxeval(static_cast<int>(left));
            if (termination.target) opt.set_stopval(*termination.target);
            if (termination.wall_time) {
                const auto spent = Clock::now() - state.progress().start;
                opt.set_maxtime(std::chrono::duration<double>(*termination.wall_time - spent).count());
            }
            double fmin = kInf;
            bool stopped_by_us = false;
            const std::int64_t evaluations_before = state.progress().evaluations;
            try {
                opt.optimize(x0, fmin);
            } catch (const nlopt::forced_stop&) {
                stopped_by_us = true;
            } catch (const nlopt::roundoff_limited&) {
            } catch (const std::invalid_argument& e) {
                throw InputError(name() + ": NLopt refused the problem: " + e.what());
            }
            const bool limit_reached =
                stopped_by_us || state.progress().evaluations >= limit || termination.done(state.progress());
            // A start that NLopt left without evaluating anything would be drawn again for ever.
            if (limit_reached || !restart || state.progress().evaluations == evaluations_before) break;
            for (std::size_t d = 0; d < dim; ++d) x0[d] = rng.uniform(lo[d], hi[d]);
        }
        if (state.progress().evaluations % record_every != 0 || state.progress().evaluations == 0) record();
        return state.finish();
    }

  private:
    nlopt::opt make_optimiser(std::size_t dim) const {
        nlopt::opt opt(algorithm_.c_str(), static_cast<unsigned>(dim));
        if (algorithm_.find("MLSL") != std::string::npos || algorithm_.find("AUGLAG") != std::string::npos) {
            nlopt::opt local(nlopt::LN_SBPLX, static_cast<unsigned>(dim));
            local.set_xtol_rel(1e-10);
            opt.set_local_optimizer(local);
        }
        return opt;
    }

    std::string algorithm_;
};

}  // namespace pride

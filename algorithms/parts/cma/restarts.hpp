#pragma once
// Restart policies around one CMA-ES run: what the next run's population size and initial step
// are, and when there is no next run.
//
//   Auger, A. and Hansen, N. (2005). A restart CMA evolution strategy with increasing population
//     size. Proc. IEEE CEC 2005, 1769-1776 (IPOP: lambda times 2 at each restart).
//   Hansen, N. (2009). Benchmarking a BI-population CMA-ES on the BBOB-2009 function testbed.
//     GECCO 2009 workshop (BIPOP: after a first run with the default lambda, two interlaced restart
//     regimes; large: lambda_l = 2^i lambda_def, sigma_0 unchanged; small:
//     lambda_s = floor(lambda_def (lambda_l / (2 lambda_def))^(U^2)), sigma_0 = sigma_def 10^(-2U),
//     a run at most half the evaluations of the last large run; each restart in the regime that
//     has used fewer evaluations).
// Decided by this project where the papers are open: the first run is booked to neither regime
// (as DEAP's BIPOP example does), so the second run is a large one (2 lambda_def); lambda_l in
// lambda_s is the large regime's next lambda, 2^(i + 1) lambda_def after i large runs besides the
// first, so lambda_s lies in [lambda_def, the last large run's lambda] (pycma and DEAP compute the
// same);
// ties between the regimes' evaluations go to the large one; the two U are two draws; a small run
// starts a generation only while the run stays within half the last large run's evaluations, and
// runs at least one generation; lambda stops growing at 2^9 lambda_def (where pycma's default of 9
// restarts ends), which bounds memory. pycma differs in two points, kept as `pycma_budget`: it
// books the first run to the small regime, and bounds a small run by half of all the large
// regime's evaluations instead of the last large run's (pycma also caps a small run at the first
// run's MaxIter; here each run has its own).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "framework/error.hpp"
#include "framework/random.hpp"

namespace pride::cma {

/// One run of a restart sequence.
enum class Regime { single, first, large, small };

inline const char* regime_name(Regime r) {
    switch (r) {
        case Regime::single:
            return "single";
        case Regime::first:
            return "first";
        case Regime::large:
            return "large";
        case Regime::small:
            return "small";
    }
    return "?";
}

struct RunPlan {
    std::int64_t lambda = 0;
    double sigma_factor = 1.0;  // the run's sigma_0 is this times the user's
    std::int64_t max_evaluations = std::numeric_limits<std::int64_t>::max();  // the run's own limit
    Regime regime = Regime::single;  // BIPOP's regime of the run (single for the other schemes)
};

/// The population cap of the restart schemes: 2^kMaxDoublings lambda_def (memory is estimated
/// from it).
inline constexpr int kMaxDoublings = 9;

/// No restart: one run, ended by its stopping criteria or the budget.
struct NoRestarts {
    static constexpr const char* name = "none";
    void validate(const std::string&) const {}
    struct Sequence {
        std::int64_t lambda_default;
        bool started = false;
        bool next(Rng&, RunPlan& plan) {
            if (started) return false;
            started = true;
            plan = {lambda_default, 1.0, std::numeric_limits<std::int64_t>::max(), Regime::single};
            return true;
        }
        void used(std::int64_t) {}
    };
    Sequence sequence(std::int64_t lambda_default) const { return {lambda_default}; }
    static double max_lambda_factor() { return 1.0; }
};

/// IPOP: restart with lambda multiplied by `factor` (2 in the paper) until the budget ends.
struct Ipop {
    static constexpr const char* name = "ipop";
    double factor = 2.0;
    void validate(const std::string& who) const {
        require(factor >= 1.0 && factor <= 4.0, who, "factor must be in [1, 4], got " + std::to_string(factor));
    }
    struct Sequence {
        std::int64_t lambda_default;
        double factor;
        std::int64_t runs = 0;
        bool next(Rng&, RunPlan& plan) {
            const double grown =
                std::min(static_cast<double>(lambda_default) * std::pow(factor, static_cast<double>(runs)),
                         std::ldexp(static_cast<double>(lambda_default), kMaxDoublings));
            ++runs;
            plan = {static_cast<std::int64_t>(std::floor(grown)), 1.0, std::numeric_limits<std::int64_t>::max(),
                    Regime::single};
            return true;
        }
        void used(std::int64_t) {}
    };
    Sequence sequence(std::int64_t lambda_default) const { return {lambda_default, factor}; }
    static double max_lambda_factor() { return std::ldexp(1.0, kMaxDoublings); }
};

/// BIPOP: the large regime doubles lambda; the small one draws a smaller lambda and sigma_0.
struct Bipop {
    static constexpr const char* name = "bipop";
    bool pycma_budget = false;  // pycma's bookkeeping (see above) instead of the paper's
    void validate(const std::string&) const {}
    struct Sequence {
        std::int64_t lambda_default;
        bool pycma_budget = false;
        std::int64_t runs = 0;        // runs started
        std::int64_t large_runs = 0;  // large-regime runs started, the first run not counted
        std::int64_t large_used = 0, small_used = 0, last_large_used = 0;
        Regime regime = Regime::first;  // the current run's
        bool next(Rng& rng, RunPlan& plan) {
            const auto unlimited = std::numeric_limits<std::int64_t>::max();
            if (runs++ == 0) {
                regime = Regime::first;
                plan = {lambda_default, 1.0, unlimited, regime};
            } else if (small_used >= large_used) {
                regime = Regime::large;
                ++large_runs;
                plan = {lambda_large(large_runs), 1.0, unlimited, regime};
            } else {
                regime = Regime::small;
                const double u1 = rng.uniform(), u2 = rng.uniform();
                const double ratio =
                    0.5 * static_cast<double>(lambda_large(large_runs + 1)) / static_cast<double>(lambda_default);
                const auto lambda =
                    std::max<std::int64_t>(2, static_cast<std::int64_t>(std::floor(static_cast<double>(lambda_default) *
                                                                                   std::pow(ratio, u1 * u1))));
                const std::int64_t allowed = (pycma_budget ? large_used : last_large_used) / 2;
                plan = {lambda, std::pow(10.0, -2.0 * u2), std::max(lambda, allowed - allowed % lambda), regime};
            }
            return true;
        }
        void used(std::int64_t evaluations) {
            if (regime == Regime::large) {
                large_used += evaluations;
                last_large_used = evaluations;
            } else if (regime == Regime::small || pycma_budget) {
                small_used += evaluations;
            }
        }
        /// 2^i lambda_def, i at most kMaxDoublings.
        std::int64_t lambda_large(std::int64_t i) const {
            return lambda_default << std::min<std::int64_t>(i, kMaxDoublings);
        }
    };
    Sequence sequence(std::int64_t lambda_default) const { return {lambda_default, pycma_budget}; }
    static double max_lambda_factor() { return std::ldexp(1.0, kMaxDoublings); }
};

}  // namespace pride::cma

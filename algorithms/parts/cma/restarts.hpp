#pragma once
// Restart policies around one CMA-ES run: what the next run's population size and initial step
// are, and when there is no next run.
//
//   Auger, A. and Hansen, N. (2005). A restart CMA evolution strategy with increasing population
//     size. Proc. IEEE CEC 2005, 1769-1776 (IPOP: lambda times 2 at each restart).
//   Hansen, N. (2009). Benchmarking a BI-population CMA-ES on the BBOB-2009 function testbed.
//     GECCO 2009 workshop (BIPOP: a large regime, IPOP, and a small regime with
//     lambda_s = floor(lambda_def (lambda_l / (2 lambda_def))^(U^2)), sigma_s = sigma_0 10^(-2U),
//     each restart in the regime that has used fewer evaluations).
// Decided by this project where the papers are open: the first run (default lambda) counts as the
// large regime's first run (as pycma's BIPOP does), so the second run is a small one; lambda_l is
// the last large run's lambda; the two U of the small regime are two draws; a small run also stops
// once the small regime's evaluations would exceed the large regime's (its share of the budget);
// lambda stops growing at 2^9 lambda_def (where pycma's default of 9 restarts ends), which bounds
// memory.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "framework/error.hpp"
#include "framework/random.hpp"

namespace pride::cma {

/// One run of a restart sequence.
struct RunPlan {
    std::int64_t lambda = 0;
    double sigma_factor = 1.0;  // the run's sigma_0 is this times the user's
    std::int64_t max_evaluations = std::numeric_limits<std::int64_t>::max();  // the run's own limit
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
            plan = {lambda_default, 1.0, std::numeric_limits<std::int64_t>::max()};
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
            plan = {static_cast<std::int64_t>(std::floor(grown)), 1.0, std::numeric_limits<std::int64_t>::max()};
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
    void validate(const std::string&) const {}
    struct Sequence {
        std::int64_t lambda_default;
        std::int64_t large_runs = 0;  // large-regime runs started (the first run is one)
        std::int64_t lambda_large = 0;
        std::int64_t large_used = 0, small_used = 0;
        bool small = false;  // the current run's regime
        bool next(Rng& rng, RunPlan& plan) {
            if (large_runs == 0 || small_used >= large_used) {
                small = false;
                lambda_large = lambda_default << std::min<std::int64_t>(large_runs, kMaxDoublings);
                ++large_runs;
                plan = {lambda_large, 1.0, std::numeric_limits<std::int64_t>::max()};
            } else {
                small = true;
                const double u1 = rng.uniform(), u2 = rng.uniform();
                const double ratio = 0.5 * static_cast<double>(lambda_large) / static_cast<double>(lambda_default);
                const auto lambda_small = static_cast<std::int64_t>(
                    std::floor(static_cast<double>(lambda_default) * std::pow(ratio, u1 * u1)));
                plan = {std::max<std::int64_t>(2, lambda_small), std::pow(10.0, -2.0 * u2), large_used - small_used};
            }
            return true;
        }
        void used(std::int64_t evaluations) { (small ? small_used : large_used) += evaluations; }
    };
    Sequence sequence(std::int64_t lambda_default) const { return {lambda_default}; }
    static double max_lambda_factor() { return std::ldexp(1.0, kMaxDoublings); }
};

}  // namespace pride::cma

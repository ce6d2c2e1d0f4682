#pragma once
// What check() and run() both establish before a run (engine/run_checks.cpp): the entry, the
// parameters as the run sees them and checked against the problem's space, the stopping rules,
// and the memory the run needs. Inside the engine only.
#include "engine/prepared.hpp"
#include "engine/registry.hpp"
#include "engine/run.hpp"
#include "engine/specs.hpp"

namespace pride::engine {

struct CheckedRun {
    const AlgorithmEntry* entry = nullptr;
    RunRequest request;  // its parameters and stopping rules; the seed and observer are the run's
};

/// InputError naming what is wrong (one objective).
CheckedRun checked_run(const AlgorithmSpec& algorithm, const Prepared& p, const Budget& budget);

/// The checks and the run of a problem of several objectives (engine/multiobjective.cpp).
void check_several(const AlgorithmSpec& algorithm, const Prepared& p, const Budget& budget);
RunResult run_several(const AlgorithmSpec& algorithm, const Prepared& p, const Budget& budget, std::uint64_t seed);

}  // namespace pride::engine

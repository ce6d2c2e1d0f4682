#pragma once
// What an algorithm family's registration file (engine/algorithms/*.cpp) uses to turn a typed
// algorithm into registry entries: the runners visit the target once and call the algorithm's
// typed run(), so every (algorithm type, problem type) pair is instantiated in that one file.
// Include this only from registration files: it pulls in every problem type.
#include <cstddef>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "engine/registry.hpp"
#include "engine/targets.hpp"

namespace pride::engine {

/// The standard parameter of population algorithms.
inline ParamSpec population_param(std::int64_t default_value, std::int64_t min, std::string doc = "population size") {
    return integer("pop", default_value, min, 1'000'000'000'000, std::move(doc));  // memory is checked apart
}

/// Start from the problem's suggested points (grids: feasible walks) instead of uniform ones.
inline ParamSpec walk_init_param(bool default_value) {
    return flag("walk_init", default_value,
                "start from the problem's suggestions (grids: feasible walks, as the grid spec's init sets it)");
}

/// Memory of a population algorithm holding `matrices` population-sized matrices of points (and a
/// few vectors): 8 bytes per number.
inline auto population_memory(double matrices) {
    return [matrices](const Params& p, std::size_t dimension) {
        const double pop = static_cast<double>(p.integer("pop"));
        const double dim = static_cast<double>(dimension);
        return 8.0 * (matrices * pop * dim + 4.0 * pop + 8.0 * dim);
    };
}

/// Calls the engine's observer when there is one (box_algorithm's runners).
struct ForwardingObserver {
    const BoxObserver* observer = nullptr;
    void operator()(const IterationView& view) const {
        if (observer && *observer) (*observer)(view);
    }
};

/// An entry that runs on boxes: `configure(params)` returns the configured typed algorithm.
template <class Configure>
AlgorithmEntry box_algorithm(std::string name, std::string family, std::string summary, std::vector<ParamSpec> params,
                             Configure configure) {
    AlgorithmEntry e;
    e.name = std::move(name);
    e.family = std::move(family);
    e.summary = std::move(summary);
    e.params = std::move(params);
    // One typed run per (algorithm, problem type), observed or not: the observer is tested once
    // per iteration.
    auto runner = [configure](const Params& p, const BoxTarget& target, const Termination& termination,
                              std::uint64_t seed, const BoxObserver* observer) -> Result {
        const auto algorithm = configure(p);
        ForwardingObserver forward{observer};
        return std::visit(
            [&](const auto& problem) -> Result { return algorithm.run(problem, termination, seed, forward); },
            target.problem);
    };
    e.run_box = [runner](const Params& p, const BoxTarget& target, const Termination& termination, std::uint64_t seed) {
        return runner(p, target, termination, seed, nullptr);
    };
    e.run_box_observed = [runner](const Params& p, const BoxTarget& target, const Termination& termination,
                                  std::uint64_t seed, const BoxObserver& observer) {
        return runner(p, target, termination, seed, &observer);
    };
    return e;
}

/// Adds running on chains to an entry: `configure(params)` returns the typed algorithm for chains.
template <class Configure>
void add_chain_runner(AlgorithmEntry& e, Configure configure) {
    e.run_chain = [configure](const Params& p, const ChainTarget& target, const Termination& termination,
                              std::uint64_t seed) -> ChainResult {
        const auto algorithm = configure(p);
        return std::visit([&](const auto& problem) -> ChainResult { return algorithm.run(problem, termination, seed); },
                          target.problem);
    };
}

}  // namespace pride::engine

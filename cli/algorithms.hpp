#pragma once
// The algorithm registry of the command line: a name and named parameters become a runner for
// continuous problems. Type erasure happens once per run (std::function, std::visit), never per
// evaluation: inside a runner the algorithm and the problem are concrete types.
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "framework/params.hpp"
#include "framework/result.hpp"
#include "framework/termination.hpp"
#include "problems/continuous/catalog.hpp"

namespace pride::cli {

using ContinuousRunner = std::function<Result(const continuous::AnyProblem&, const Termination&, std::uint64_t seed)>;

struct AlgorithmInfo {
    std::string name;
    std::string summary;
};

/// Every algorithm name the command line accepts, with a few words each (NLopt's included).
std::vector<AlgorithmInfo> list_algorithms();

/// The runner for `name` ("pso", "ga", "nlopt:LN_SBPLX", ...) with its parameters; InputError for
/// an unknown name, an unknown parameter or a value out of range.
ContinuousRunner make_algorithm(std::string_view name, const ParamMap& params);

}  // namespace pride::cli

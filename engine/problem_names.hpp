#pragma once
// The message for a problem's name that none of the registries knows.
#include <string>

namespace pride::engine {

/// "unknown problem 'NAME'", with the registered problems' names close to it (the catalog's, the
/// constrained suites' and the multi-objective ones: framework/close_names.hpp), for InputError.
std::string unknown_problem(const std::string& name);

}  // namespace pride::engine

#pragma once
// Which variables of a continuous::Function are integer, for the code that will give algorithms
// typed variables: a function of COCO's bbob-mixint suite has its first k variables integer
// (their values lower()[i] .. upper()[i]); every other function has none.
#include <cstddef>

#include "problems/continuous/function.hpp"

namespace pride::continuous {

/// k: variables 0 .. k-1 of `f` are integer, the others continuous (0 for all but bbob-mixint).
/// f.evaluate() takes real values on them too, and rounds them as the suite's definition says
/// (bbob_mixint.hpp).
std::size_t integer_variables(const Function& f) noexcept;

}  // namespace pride::continuous

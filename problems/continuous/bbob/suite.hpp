#pragma once
// The 24 noiseless BBOB functions of COCO's `bbob` suite (Hansen, Finck, Ros, Auger 2009,
// "Real-parameter black-box optimization benchmarking 2009: noiseless functions definitions",
// INRIA RR-6829), each a class FN(dim, instance) whose values equal COCO's (numbbo/coco-experiment,
// code-experiments/src/f_*.c) for the same function, dimension and instance.
#include <tuple>

#include "problems/continuous/bbob/ill_conditioned.hpp"
#include "problems/continuous/bbob/moderate.hpp"
#include "problems/continuous/bbob/multimodal.hpp"
#include "problems/continuous/bbob/separable.hpp"
#include "problems/continuous/bbob/weak_structure.hpp"

namespace pride::continuous::bbob {

using All = std::tuple<F1, F2, F3, F4, F5, F6, F7, F8, F9, F10, F11, F12, F13, F14, F15, F16, F17, F18, F19, F20, F21,
                       F22, F23, F24>;

}  // namespace pride::continuous::bbob

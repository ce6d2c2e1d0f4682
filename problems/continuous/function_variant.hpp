#pragma once
// Internal to problems/continuous (function.cpp, catalog.cpp): the variant of every function class
// behind continuous::Function. Adding a function class means adding it here (Scalable when it has
// instances, else beside the fixed ones) and registering it in catalog.cpp.
#include <cstdint>
#include <span>
#include <string>
#include <tuple>
#include <variant>

#include "problems/continuous/bbob/suite.hpp"
#include "problems/continuous/bbob_mixint/bbob_mixint.hpp"
#include "problems/continuous/cec/functions.hpp"
#include "problems/continuous/extras.hpp"
#include "problems/continuous/function.hpp"
#include "problems/continuous/functions.hpp"
#include "problems/continuous/transformed.hpp"
#include "problems/continuous/yao.hpp"
#include "problems/continuous/yao_fixed.hpp"

namespace pride::continuous {
namespace detail {

template <class... F>
using WithInstances = std::variant<F..., Transformed<F>...>;

// Scalable functions appear plain and transformed (instances k >= 1, shifted-*); fixed-dimension
// ones (Yao's F14-F23), BBOB's and bbob-mixint's (which build their own instances) and CEC's (one
// class for each suite's functions, numbered) plain only.
using Scalable =
    WithInstances<Sphere, Rastrigin, Rosenbrock, Ackley, Griewank, Schwefel, Schwefel222, Schwefel12, Schwefel221, Step,
                  QuarticNoise, Schwefel226, Penalized1, Penalized2, Ellipsoid, Levy, Zakharov, StyblinskiTang>;

template <class V, class... More>
struct Append;
template <class... A, class... More>
struct Append<std::variant<A...>, More...> {
    using type = std::variant<A..., More...>;
};

template <class V, class Tuple>
struct AppendTuple;
template <class V, class... T>
struct AppendTuple<V, std::tuple<T...>> : Append<V, T...> {};

using Any = AppendTuple<Append<Scalable, ShekelFoxholes, Kowalik, SixHumpCamel, Branin, GoldsteinPrice, Hartman3,
                               Hartman6, Shekel5, Shekel7, Shekel10, cec::CecFunction, bbob_mixint::Problem>::type,
                        bbob::All>::type;

}  // namespace detail

struct Function::Impl {
    detail::Any function;
    std::string name;
    std::int64_t instance = 0;
};

}  // namespace pride::continuous

#pragma once
// What the tests of the multi-objective algorithms share: ZDT1 with its calls counted, and an
// evaluation budget.
#include <cstdint>
#include <memory>
#include <span>

#include "framework/multi_objective.hpp"
#include "framework/termination.hpp"
#include "problems/multiobjective/zdt.hpp"

namespace pride::test {

/// ZDT1 (problems/multiobjective/zdt.hpp) whose calls are counted (copies share the counter).
struct CountedZdt1 {
    multiobjective::Zdt1 zdt1;
    std::shared_ptr<std::int64_t> calls = std::make_shared<std::int64_t>(0);
    explicit CountedZdt1(std::size_t n) : zdt1(n) {}
    std::size_t dimension() const { return zdt1.dimension(); }
    std::span<const double> lower() const { return zdt1.lower(); }
    std::span<const double> upper() const { return zdt1.upper(); }
    std::size_t objectives() const { return 2; }
    void evaluate(std::span<const double> x, std::span<double> f) {
        ++*calls;
        zdt1.evaluate(x, f);
    }
};
static_assert(MultiObjectiveProblem<CountedZdt1>);

/// A budget of exactly n evaluations.
inline Termination evaluations(std::int64_t n) {
    Termination t;
    t.max_evaluations = n;
    return t;
}

}  // namespace pride::test

#pragma once
// A pagmo2 problem that records the points it evaluates, for the benchmarks' second, untimed run
// (continuous_bench, mo_bench): the recorded points are then timed bare. Built with pagmo only.
#include <pagmo/types.hpp>

#include <utility>
#include <vector>

namespace pride::bench {

template <class PagmoProblem>
struct PagmoRecording {
    PagmoProblem inner;
    std::vector<double>* points = nullptr;
    pagmo::vector_double fitness(const pagmo::vector_double& x) const {
        points->insert(points->end(), x.begin(), x.end());
        return inner.fitness(x);
    }
    std::pair<pagmo::vector_double, pagmo::vector_double> get_bounds() const { return inner.get_bounds(); }
    // Only for multi-objective problems: pagmo then sees no get_nobj and takes one objective.
    pagmo::vector_double::size_type get_nobj() const requires requires(const PagmoProblem& p) { p.get_nobj(); }
    { return inner.get_nobj(); }
};

}  // namespace pride::bench

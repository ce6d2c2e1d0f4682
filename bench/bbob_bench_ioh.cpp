// bbob_bench's IOHexperimenter reference (bbob_bench_references.hpp): its BBOB classes called as a
// user calls them, problem(x) on a std::vector (which includes its per-call bookkeeping).
#include "bench/bbob_bench_references.hpp"

#ifdef PRIDE_HAVE_IOH
#include <iostream>  // the headers use std::cout and fmt without including them
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "bench/best_time.hpp"
#include "ioh/problem/bbob.hpp"
#endif

namespace pride::bench {

double ioh_ns(int function, int instance, int dim, const double* points, long count, double* values) {
#ifdef PRIDE_HAVE_IOH
    auto problem = ioh::problem::ProblemRegistry<ioh::problem::BBOB>::instance().create(function, instance, dim);
    std::vector<std::vector<double>> xs(static_cast<std::size_t>(count));
    for (long j = 0; j < count; ++j) xs[static_cast<std::size_t>(j)].assign(points + j * dim, points + (j + 1) * dim);
    const auto pass = [&] {
        for (long j = 0; j < count; ++j) values[j] = (*problem)(xs[static_cast<std::size_t>(j)]);
        asm volatile("" : : "r"(values) : "memory");
    };
    const double ns = best_ns(pass, count);  // its last pass leaves the values
    return ns;
#else
    (void)function, (void)instance, (void)dim, (void)points, (void)count, (void)values;
    return 0.0;
#endif
}

}  // namespace pride::bench

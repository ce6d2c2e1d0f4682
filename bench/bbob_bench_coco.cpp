// bbob_bench's COCO reference (bbob_bench_references.hpp): coco_evaluate_function on the points.
#include "bench/bbob_bench_references.hpp"

#ifdef PRIDE_HAVE_COCO
#include <string>

#include "bench/best_time.hpp"
extern "C" {
#include "coco.h"
}
#endif

namespace pride::bench {

double coco_ns(int function, int instance, int dim, const double* points, long count, double* values) {
#ifdef PRIDE_HAVE_COCO
    coco_set_log_level("error");  // its info lines would go to stdout, into the CSV
    const std::string options = "dimensions: " + std::to_string(dim) +
                                " function_indices: " + std::to_string(function) +
                                " instance_indices: " + std::to_string(instance);
    coco_suite_t* suite = coco_suite("bbob", "", options.c_str());
    coco_problem_t* problem = coco_suite_get_next_problem(suite, nullptr);
    const auto pass = [&] {
        for (long j = 0; j < count; ++j) coco_evaluate_function(problem, points + j * dim, values + j);
        asm volatile("" : : "r"(values) : "memory");
    };
    const double ns = best_ns(pass, count);  // its last pass leaves the values
    coco_suite_free(suite);
    return ns;
#else
    (void)function, (void)instance, (void)dim, (void)points, (void)count, (void)values;
    return 0.0;
#endif
}

}  // namespace pride::bench

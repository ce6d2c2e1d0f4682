#pragma once
// bbob_bench's references, each in its own translation unit: COCO's coco.h defines macros and
// IOHexperimenter's headers need C++17 and fmt's runtime format strings, so neither may share a
// unit with pride. Each evaluates `count` points of dimension `dim` (column after column from
// `points`) into `values`, and returns the least ns per evaluation of 7 timings (best_time.hpp),
// or 0 when the build was not given that reference's sources.

namespace pride::bench {

double coco_ns(int function, int instance, int dim, const double* points, long count, double* values);
double ioh_ns(int function, int instance, int dim, const double* points, long count, double* values);

}  // namespace pride::bench

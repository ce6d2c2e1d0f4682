#pragma once
// Batch evaluation of the sum-like functions: the points are the columns of a column-major matrix,
// and a function's scalar loop runs over the rows of one column. Here the loop runs row by row over
// all columns at once, one accumulator per column, so each column sees exactly the operations of
// the scalar loop in the same order (values are bit-identical to evaluate()).
//
// That rarely pays (bench/batch_bench.cpp): the row is a strided read, and the out-of-order core
// already overlaps the scalar chains of consecutive columns, while bit identity forbids the
// reordering within a column that would let the scalar loop vectorise. Only the functions where it
// measured faster use it (Schwefel 2.21, the ellipsoid).
#include <Eigen/Core>
#include <span>

#include "framework/problem.hpp"

namespace pride::continuous {

/// values[j] = init, then step(acc, row, i) for every row i in order, where acc is the array of
/// the columns' accumulators (values itself) and row the array of the columns' i-th coordinates.
template <class Step>
void accumulate_rows(MatrixView points, std::span<double> values, double init, Step step) {
    Eigen::Map<Eigen::ArrayXd> acc(values.data(), points.cols());
    acc.setConstant(init);
    for (Eigen::Index i = 0; i < points.rows(); ++i) step(acc, points.row(i).transpose().array(), i);
}

}  // namespace pride::continuous

#pragma once
// Inside the CEC 2006 suite: each problem's entry of the suite's table (cec2006_table.cpp), which
// Problem's constructor reads.
#include <cstddef>
#include <span>
#include <string_view>

namespace pride::continuous::cec2006::detail {

struct Spec {
    std::string_view name;
    std::size_t inequalities, equalities;
    double best_value;
    std::span<const double> lower, upper, best_point;
};

/// Problem `number`'s entry; InputError("problem", ...) unless 1 <= number <= 24.
const Spec& spec(int number);

}  // namespace pride::continuous::cec2006::detail

#pragma once
// The order in which reports and pages list problems, functions and ids: natural order, where a run
// of digits compares by its value, so that f2 comes before f10, g2 before g10 and RC2 before RC10
// (plain string order would put f10 first). Every listing of the reports (experiment/report/,
// experiment/html/) sorts by this one comparison.
#include <string>
#include <string_view>

namespace pride::report {

/// Negative, zero or positive as a comes before, with or after b in natural order: the strings are
/// compared piece by piece, a run of digits against a run of digits by its value (leading zeros
/// ignored; at equal values the shorter run first), anything else byte by byte. Zero only for equal
/// strings ("f01" and "f1" differ: f1 first), so that it orders map keys as equality does.
int natural_compare(std::string_view a, std::string_view b);

/// natural_compare as a strict weak order, for std::map, std::set and std::sort.
struct NaturalLess {
    using is_transparent = void;
    bool operator()(std::string_view a, std::string_view b) const { return natural_compare(a, b) < 0; }
};

}  // namespace pride::report

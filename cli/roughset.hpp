#pragma once
// pride roughset: reduce a decision table (a CSV file, or Wan and Gao's (2022) grid table) and print its
// consistency, positive region, core, reducts and minimal rules (docs/cli.md).
#include <iosfwd>
#include <string>

namespace pride::cli {

struct RoughsetOptions {
    std::string table;  // CSV path; empty with `grid`
    bool grid = false;  // Wan and Gao's (2022) grid decision table (problems/grid/rough_rules.hpp)
    bool json = false;
};

/// Exit status 0; InputError for a missing or bad table, or neither/both of TABLE and --grid.
int roughset_command(const RoughsetOptions& o, std::ostream& out);

}  // namespace pride::cli

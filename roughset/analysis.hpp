#pragma once
// The whole analysis of a decision table that `pride roughset` prints and the Python module
// returns: consistency, dependency, core, reducts, and minimal certain rules on one reduct.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "roughset/decision_table.hpp"
#include "roughset/rules.hpp"

namespace pride::roughset {

/// Minimal rules cost about 2^|B| partitions of the distinct rows; beyond this many row-subset
/// steps they are not attempted (minutes of work, thousands of rules).
inline constexpr double max_rule_steps = 1 << 28;

struct Analysis {
    Attributes C, D;  // the table's condition and decision attributes
    std::size_t rows = 0;
    bool consistent = false;
    std::size_t positive = 0;  // |POS_C(D)|
    double gamma = 1.0;
    Attributes core;
    bool exhaustive = false;          // whether reducts were searched exhaustively
    std::vector<Attributes> reducts;  // all of them when exhaustive, else {quick}
    Attributes quick;
    Attributes used;  // the attributes the rules are computed on
    std::string why;  // why those
    std::optional<std::vector<Rule>> rules;
    std::string no_rules;  // why they were not computed, when rules is nullopt
};

/// Rules computed elsewhere (the grid rule book's), reported instead of computing them.
struct GivenRules {
    Attributes reduct;
    std::vector<Rule> rules;
    std::string why;
};

/// The analysis of t with its last column as the decision. The rules are computed on the only
/// reduct, or the first of the smallest ones, or (over max_exhaustive_attributes conditions) the
/// QuickReduct result; when that is over the limits, rules is nullopt and no_rules says why.
Analysis analyse(const DecisionTable& t, std::optional<GivenRules> given = {});

}  // namespace pride::roughset

#pragma once
// Certain decision rules from the positive region, minimised value by value (Pawlak 1991,
// chapter 6): value cores, value reducts, and a small covering set of minimal rules.
#include <cstddef>
#include <vector>

#include "roughset/decision_table.hpp"

namespace pride::roughset {

struct Condition {
    std::size_t attribute;
    int value;
    friend bool operator==(const Condition&, const Condition&) = default;
    friend auto operator<=>(const Condition&, const Condition&) = default;
};

/// IF every condition THEN D = decision. decision: one code per attribute of D, in D's order;
/// conditions sorted by attribute; support: every object of the table that the conditions match
/// (all of them in the positive region, all with this decision).
struct Rule {
    std::vector<Condition> conditions;
    std::vector<int> decision;
    Objects support;
};

/// Whether object `row` has every value the rule's conditions ask for.
bool matches(const DecisionTable& t, const Rule& rule, std::size_t row);

/// Per object: the attributes of B whose value cannot be dropped from the object's rule without
/// making it inconsistent (Pawlak's value core = intersection of the value reducts); empty for
/// objects outside POS_B(D). InputError when |B| > 16.
std::vector<Attributes> value_cores(const DecisionTable& t, const Attributes& B, const Attributes& D);

/// Per object: every minimal subset R of B such that all objects with the object's values on R
/// have its values on D; ordered by size, then lexicographically; empty for objects outside
/// POS_B(D). InputError when |B| > 16.
std::vector<std::vector<Attributes>> value_reducts(const DecisionTable& t, const Attributes& B, const Attributes& D);

/// A small set of certain rules covering POS_B(D): the candidates are the value reducts of the
/// objects left after dropping duplicate rows on B; covering POS with fewest rules is NP-hard, so
/// a greedy cover picks the candidate covering most uncovered objects (ties: fewer conditions,
/// then the smaller (attribute, value) list), then rules the others cover are dropped, last picked
/// first. Ordered by support (smallest first object first). Deterministic. InputError when |B| > 16.
std::vector<Rule> minimal_rules(const DecisionTable& t, const Attributes& B, const Attributes& D);

}  // namespace pride::roughset

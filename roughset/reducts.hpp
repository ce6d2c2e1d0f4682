#pragma once
// Core and reducts relative to a decision. The absolute (information-system) reducts of B are the
// relative ones with D = B, since IND(R) = IND(B) iff gamma_R(B) = 1.
#include <cstddef>
#include <vector>

#include "roughset/decision_table.hpp"

namespace pride::roughset {

/// Above this many condition attributes reducts() refuses (2^|C| subsets) and quick_reduct is the tool.
inline constexpr std::size_t max_exhaustive_attributes = 16;

/// The attributes a of C with gamma_{C-{a}}(D) < gamma_C(D); equals the intersection of all reducts.
Attributes core(const DecisionTable& t, const Attributes& C, const Attributes& D);

/// Every minimal R of C with gamma_R(D) = gamma_C(D), ordered by size, then lexicographically by
/// column index. Exhaustive; InputError when |C| > max_exhaustive_attributes.
std::vector<Attributes> reducts(const DecisionTable& t, const Attributes& C, const Attributes& D);

/// QuickReduct (Chouchoulas and Shen 2001): from the empty set, add the attribute that raises gamma
/// the most (ties: the lowest index) until gamma_C(D) is reached; then drop each attribute, last
/// added first, that is not needed, so the result is a reduct (not necessarily a smallest one).
/// Any number of attributes; sorted ascending.
Attributes quick_reduct(const DecisionTable& t, const Attributes& C, const Attributes& D);

}  // namespace pride::roughset

#pragma once
// Indiscernibility, approximations and the positive region (Pawlak 1991, chapters 2-4).
// Partitions are computed by hashing the rows' codes on B: O(|U| |B|), never pairwise.
#include "roughset/decision_table.hpp"

namespace pride::roughset {

/// U/IND(B): objects with equal values on every attribute of B. B empty: one class, U.
Classes indiscernibility(const DecisionTable& t, const Attributes& B);

/// B_*(X): union of the B-classes contained in X (X sorted, 0-based).
Objects lower_approximation(const DecisionTable& t, const Attributes& B, const Objects& X);
/// B^*(X): union of the B-classes that meet X.
Objects upper_approximation(const DecisionTable& t, const Attributes& B, const Objects& X);
/// B^*(X) - B_*(X).
Objects boundary(const DecisionTable& t, const Attributes& B, const Objects& X);

/// POS_C(D): union of the lower approximations of the D-classes, i.e. the objects whose C-class
/// has a single value on D.
Objects positive_region(const DecisionTable& t, const Attributes& C, const Attributes& D);
/// gamma_C(D) = |POS_C(D)| / |U| (1 for an empty table).
double dependency(const DecisionTable& t, const Attributes& C, const Attributes& D);
/// gamma_C(D) == 1: equal values on C imply equal values on D.
bool consistent(const DecisionTable& t, const Attributes& C, const Attributes& D);

}  // namespace pride::roughset

#pragma once
// The whole rough-set module: decision tables, CSV input, approximations, reducts and rules.
#include "framework/roughset/approximation.hpp"
#include "framework/roughset/csv.hpp"
#include "framework/roughset/decision_table.hpp"
#include "framework/roughset/reducts.hpp"
#include "framework/roughset/rules.hpp"

#pragma once
// The whole rough-set module: decision tables, CSV input, approximations, reducts and rules.
#include "roughset/analysis.hpp"
#include "roughset/approximation.hpp"
#include "roughset/csv.hpp"
#include "roughset/decision_table.hpp"
#include "roughset/reducts.hpp"
#include "roughset/rules.hpp"

#pragma once
// Reading numbers the user typed, strictly; writing them as JSON is the engine's (engine/json.hpp).
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "engine/json.hpp"

namespace pride::cli {

/// A finite double written in full ("1", "-2.5e3"); InputError naming `where` otherwise.
double parse_finite(std::string_view text, const std::string& where);

/// An integer written in full ("12", "-3", "+4"; not "1e3" or "12.0") in [min, max]; InputError
/// naming `where` and the range otherwise. The caller converts: the range says the type it fits.
void check_integer(std::string_view text, std::int64_t min, std::uint64_t max, const std::string& where);

/// "v1,v2,..." with optional spaces around each value; InputError naming `where` for an empty
/// list, an empty value or a value that is not a finite number.
std::vector<double> parse_point(std::string_view text, const std::string& where);

using engine::json_array;
using engine::json_cells;
using engine::json_integers;
using engine::json_number;
using engine::json_string;

}  // namespace pride::cli

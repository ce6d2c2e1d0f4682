#pragma once
// Reading numbers the user typed, strictly, and writing numbers as JSON.
#include <string>
#include <string_view>
#include <vector>

namespace pride::cli {

/// A finite double written in full ("1", "-2.5e3"); InputError naming `where` otherwise.
double parse_finite(std::string_view text, const std::string& where);

/// "v1,v2,..." with optional spaces around each value; InputError naming `where` for an empty
/// list, an empty value or a value that is not a finite number.
std::vector<double> parse_point(std::string_view text, const std::string& where);

/// Shortest text that reads back as the same double; JSON has no inf or NaN, so those are null.
std::string json_number(double v);

/// [v1, v2, ...] with json_number each.
std::string json_array(const std::vector<double>& values);

/// A JSON string literal with the necessary escapes.
std::string json_string(std::string_view s);

}  // namespace pride::cli

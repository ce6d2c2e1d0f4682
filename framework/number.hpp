#pragma once
// The one grammar of a number given as text, on the command line, in `--param NAME=VALUE` and in
// points read from stdin: an optional sign, decimal digits with an optional fraction, an optional
// decimal exponent. No spaces inside a value (a list's items may have spaces around them), no hex
// (0x1p3), no inf or nan. A value below the smallest double gives the nearest one (0 or a
// subnormal), as strtod and Python's float() do; one beyond the largest is an error.
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>
#include <string_view>

namespace pride {

enum class NumberText { ok, not_a_number, too_large };

/// Reads `text` (all of it) into `out` by the grammar above.
inline NumberText parse_decimal(std::string_view text, double& out) {
    std::size_t i = 0;
    const auto digits = [&] {
        const std::size_t from = i;
        while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) ++i;
        return i - from;
    };
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
    std::size_t mantissa = digits();
    if (i < text.size() && text[i] == '.') {
        ++i;
        mantissa += digits();
    }
    if (mantissa == 0) return NumberText::not_a_number;
    if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
        ++i;
        if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
        if (digits() == 0) return NumberText::not_a_number;
    }
    if (i != text.size()) return NumberText::not_a_number;
    const std::string_view unsigned_text = text.front() == '+' ? text.substr(1) : text;  // from_chars takes no '+'
    const auto [ptr, ec] = std::from_chars(unsigned_text.data(), unsigned_text.data() + unsigned_text.size(), out);
    if (ec == std::errc::result_out_of_range) {
        // Beyond the range one way or the other: strtod gives inf for an overflow, the nearest
        // double for an underflow.
        const double v = std::strtod(std::string(text).c_str(), nullptr);
        if (!std::isfinite(v)) return NumberText::too_large;
        out = v;
        return NumberText::ok;
    }
    return ec == std::errc() && ptr == unsigned_text.data() + unsigned_text.size() ? NumberText::ok
                                                                                   : NumberText::not_a_number;
}

/// The message for a value parse_decimal refused.
inline std::string number_problem(std::string_view text, NumberText what) {
    return what == NumberText::too_large ? "'" + std::string(text) + "' is beyond the largest finite number"
                                         : "'" + std::string(text) + "' is not a finite number";
}

}  // namespace pride

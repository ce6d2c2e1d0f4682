#pragma once
// How the text reports write a cell (report.cpp's tables, cec.cpp's CEC tables): numbers for
// reading and for reading back, and text made safe for a CSV field or a markdown cell.
#include <fmt/format.h>

#include <cmath>
#include <string>

namespace pride::report::cells {

/// For reading: 6 significant digits, as every table.
inline std::string num(double v) {
    return std::isfinite(v) ? fmt::format("{:.6g}", v) : "inf";
}

/// For reading back: the shortest form that parses to the same double.
inline std::string exact(double v) {
    return std::isfinite(v) ? fmt::format("{}", v) : "inf";
}

/// A CSV field, quoted as RFC 4180 says when it holds a comma, a quote or a line break.
inline std::string csv(const std::string& s) {
    if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
    std::string out = "\"";
    for (const char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

/// Text for a markdown table cell: a | would start a new column.
inline std::string markdown(const std::string& s) {
    std::string out;
    for (const char c : s) out += c == '|' ? std::string("\\|") : std::string(1, c);
    return out;
}

}  // namespace pride::report::cells

#include "cli/numbers.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>

#include "framework/error.hpp"

namespace pride::cli {

namespace {
std::string_view trim(std::string_view s) {
    const auto first = s.find_first_not_of(" \t\r");
    if (first == std::string_view::npos) return {};
    const auto last = s.find_last_not_of(" \t\r");
    return s.substr(first, last - first + 1);
}
}  // namespace

double parse_finite(std::string_view text, const std::string& where) {
    const std::string_view t = trim(text);
    double v = 0.0;
    const char* begin = t.data();
    const char* end = t.data() + t.size();
    if (!t.empty() && *begin == '+') ++begin;  // from_chars refuses a leading '+'
    const auto [ptr, ec] = std::from_chars(begin, end, v);
    require(!t.empty() && ec == std::errc() && ptr == end && std::isfinite(v), where,
            "'" + std::string(t) + "' is not a finite number");
    return v;
}

std::vector<double> parse_point(std::string_view text, const std::string& where) {
    require(!trim(text).empty(), where, "no coordinates given");
    std::vector<double> point;
    std::size_t start = 0;
    for (std::size_t k = 1;; ++k) {
        const auto comma = text.find(',', start);
        const std::string_view token = text.substr(start, comma == std::string_view::npos ? text.npos : comma - start);
        require(!trim(token).empty(), where, "coordinate " + std::to_string(k) + " is empty");
        point.push_back(parse_finite(token, where + " coordinate " + std::to_string(k)));
        if (comma == std::string_view::npos) break;
        start = comma + 1;
    }
    return point;
}

}  // namespace pride::cli

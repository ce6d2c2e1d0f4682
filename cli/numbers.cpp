#include "cli/numbers.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>

#include "framework/error.hpp"
#include "framework/number.hpp"

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
    double v = 0.0;
    const NumberText read = parse_decimal(text, v);
    require(read == NumberText::ok, where, number_problem(text, read));
    return v;
}

void check_integer(std::string_view text, std::int64_t min, std::uint64_t max, const std::string& where) {
    const std::string_view t = text;  // no spaces: the grammar of framework/number.hpp
    const std::string range = fmt::format("[{}, {}]", min, max);
    const bool negative = !t.empty() && t.front() == '-';
    const std::string_view digits = !t.empty() && (t.front() == '-' || t.front() == '+') ? t.substr(1) : t;
    std::uint64_t magnitude = 0;
    const auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), magnitude);
    const bool integer = !digits.empty() && digits.front() >= '0' && digits.front() <= '9' &&
                         ptr == digits.data() + digits.size() &&
                         (ec == std::errc() || ec == std::errc::result_out_of_range);
    require(integer, where, fmt::format("must be an integer in {}, got '{}'", range, t));
    // |min| as an unsigned number without overflowing at INT64_MIN.
    const std::uint64_t below = min < 0 ? static_cast<std::uint64_t>(-(min + 1)) + 1 : 0;
    const bool in_range = ec == std::errc() &&
                          (negative ? min < 0 && magnitude <= below
                                    : magnitude <= max && (min <= 0 || magnitude >= static_cast<std::uint64_t>(min)));
    require(in_range, where, fmt::format("must be an integer in {}, got {}", range, t));
}

std::vector<double> parse_point(std::string_view text, const std::string& where) {
    require(!trim(text).empty(), where, "no coordinates given");
    std::vector<double> point;
    std::size_t start = 0;
    for (std::size_t k = 1;; ++k) {
        const auto comma = text.find(',', start);
        const std::string_view token = text.substr(start, comma == std::string_view::npos ? text.npos : comma - start);
        require(!trim(token).empty(), where, "coordinate " + std::to_string(k) + " is empty");
        point.push_back(parse_finite(trim(token), where + " coordinate " + std::to_string(k)));
        if (comma == std::string_view::npos) break;
        start = comma + 1;
    }
    return point;
}

}  // namespace pride::cli

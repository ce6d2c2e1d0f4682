#include "cli/flags.hpp"

#include <fmt/format.h>

#include <cmath>
#include <map>

#include "cli/numbers.hpp"
#include "framework/error_place.hpp"
#include "framework/utf8.hpp"

namespace pride::cli {

std::string user_message(const InputError& e) {
    static const std::map<std::string, std::string, std::less<>> flags{{"parameter", "--param"},
                                                                       {"dim", "--dim"},
                                                                       {"problem", "--problem"},
                                                                       {"algo", "--algo"},
                                                                       {"start", "--start"},
                                                                       {"goal", "--goal"},
                                                                       {"objective", "--objective"},
                                                                       {"encoding", "--encoding"},
                                                                       {"connector", "--connector"},
                                                                       {"init", "--init"},
                                                                       {"waypoints", "--waypoints"},
                                                                       {"weights", "--weights"},
                                                                       {"lambda", "--lambda"},
                                                                       {"inflate", "--inflate"},
                                                                       {"iterations", "--iters"},
                                                                       {"evaluations", "--evals"},
                                                                       {"corner_cutting", "--corner-cutting"},
                                                                       {"wall_ms", "--wall-ms"},
                                                                       {"target", "--target"},
                                                                       {"oracle", "--oracle"},
                                                                       {"seed", "--seed"},
                                                                       {"map", "--map"},
                                                                       {"jobs", "--jobs"},
                                                                       {"threads", "--threads"},
                                                                       {"instance", "--instance"},
                                                                       {"objectives", "--objectives"},
                                                                       {"html", "--html"}};
    return printable(renamed_message(e, flags).value_or(e.what()));
}

std::string printable(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c >= 0x20 && c < 0x7F) {
            out += text[i++];
        } else if (c == '\n' || c == '\r' || c == '\t') {
            out += c == '\n' ? "\\n" : c == '\r' ? "\\r" : "\\t";
            ++i;
        } else if (const std::size_t n = c >= 0x80 ? utf8_length(text, i) : 0) {
            out.append(text.substr(i, n));
            i += n;
        } else {
            out += fmt::format("\\x{:02x}", c);
            ++i;
        }
    }
    return out;
}

CLI::Validator integer_in(std::int64_t min, std::uint64_t max) {
    return CLI::Validator(
        [min, max](std::string& value) {
            try {
                check_integer(value, min, max, "");
            } catch (const InputError& e) {
                return e.detail();
            }
            return std::string();
        },
        "");
}

CLI::Validator finite_in(double min, double max) {
    return CLI::Validator(
        [min, max](std::string& value) {
            const bool bounded = std::isfinite(min) || std::isfinite(max);
            const std::string range = bounded ? fmt::format(" in [{}, {}]", min, max) : "";
            double v = 0.0;
            try {
                v = parse_finite(value, "");
            } catch (const InputError&) {
                return fmt::format("must be a finite number{}, got '{}'", range, value);
            }
            if (v < min || v > max) return fmt::format("must be{}, got {}", range, value);
            return std::string();
        },
        "");
}

CLI::Validator a_path() {
    return CLI::Validator(
        [](std::string& value) { return value.empty() ? std::string("expected a path, got ''") : ""; }, "");
}

}  // namespace pride::cli

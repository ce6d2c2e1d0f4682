#include "engine/json.hpp"

#include <fmt/format.h>

#include <cmath>

namespace pride::engine {

std::string json_number(double v) {
    return std::isfinite(v) ? fmt::format("{}", v) : "null";
}

std::string json_array(const std::vector<double>& values) {
    std::string out = "[";
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (i) out += ", ";
        out += json_number(values[i]);
    }
    return out + "]";
}

std::string json_string(std::string_view s) {
    std::string out = "\"";
    for (const char c : s) {
        switch (c) {
            case '"':
                out += "\\\"";
                break;
            case '\\':
                out += "\\\\";
                break;
            case '\n':
                out += "\\n";
                break;
            case '\t':
                out += "\\t";
                break;
            default:
                if (static_cast<unsigned char>(c) < 0x20)
                    out += fmt::format("\\u{:04x}", static_cast<unsigned>(c));
                else
                    out += c;
        }
    }
    return out + "\"";
}

std::string json_integers(const std::vector<std::int64_t>& v) {
    std::string s = "[";
    for (std::size_t i = 0; i < v.size(); ++i) s += fmt::format("{}{}", i ? ", " : "", v[i]);
    return s + "]";
}

std::string json_cells(const grid::Path& path) {
    std::string s = "[";
    for (std::size_t i = 0; i < path.size(); ++i) s += fmt::format("{}[{},{}]", i ? "," : "", path[i].x, path[i].y);
    return s + "]";
}

}  // namespace pride::engine

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

std::string json_polyline(const grid::Polyline& line) {
    std::string out = "[";
    for (std::size_t i = 0; i < line.size(); ++i)
        out += (i ? ", [" : "[") + json_number(line[i].x) + ", " + json_number(line[i].y) + "]";
    return out + "]";
}

std::string json_path_metrics(const GridOutcome& run, bool gaps, const std::optional<grid::WorldFrame>& frame) {
    const auto optional = [](const std::optional<double>& v) { return v ? json_number(*v) : std::string("null"); };
    const grid::PolylineMetrics& m = run.metrics;
    std::string out = "{\"length\": " + json_number(m.length) + ", \"turns\": " + std::to_string(m.turns) +
                      ", \"total_turn_deg\": " + json_number(m.total_turn_deg) +
                      ", \"max_turn_deg\": " + json_number(m.max_turn_deg) +
                      ", \"angle_over_length\": " + json_number(m.angle_over_length) +
                      ", \"max_curvature\": " + json_number(m.max_curvature) +
                      ", \"min_clearance\": " + optional(m.min_clearance) +
                      ", \"mean_clearance\": " + optional(m.mean_clearance);
    if (gaps)
        out += ", \"shortest_grid_length\": " + optional(run.shortest_grid_length) +
               ", \"shortest_any_angle_length\": " + optional(run.shortest_any_angle_length) +
               ", \"grid_gap\": " + optional(run.grid_gap) + ", \"any_angle_gap\": " + optional(run.any_angle_gap);
    if (frame) {
        const auto metres = [&](const std::optional<double>& v) {
            return optional(v ? std::optional(*v * frame->resolution) : std::nullopt);
        };
        out += ", \"length_m\": " + metres(m.length) + ", \"min_clearance_m\": " + metres(m.min_clearance) +
               ", \"mean_clearance_m\": " + metres(m.mean_clearance);
    }
    return out + "}";
}

}  // namespace pride::engine

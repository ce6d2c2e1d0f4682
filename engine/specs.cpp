#include "engine/specs.hpp"

#include <fmt/format.h>

#include "framework/error.hpp"

namespace pride::engine {

grid::Cell world_cell(const grid::GridMap& map, double x, double y, const std::string& where,
                      const std::string& instead) {
    const auto& f = map.frame();
    require(f.has_value(), where,
            "the map " + map.name() +
                " has no world frame (only a ROS map_server YAML map has a resolution and origin): give " + instead);
    const auto cell = map.cell_at({x, y});
    require(
        cell.has_value(), where,
        fmt::format("the point ({}, {}) is outside the map: x in [{:.10g}, {:.10g}), y in [{:.10g}, {:.10g}) metres", x,
                    y, f->origin_x, f->origin_x + map.width() * f->resolution, f->origin_y,
                    f->origin_y + map.height() * f->resolution));
    require(
        map.free(*cell), where,
        fmt::format("the point ({}, {}) is in cell ({},{}), a blocked cell of {}", x, y, cell->x, cell->y, map.name()));
    return *cell;
}

InputError endpoint_error(const InputError& e, const std::string& start, const std::string& goal) {
    const std::string& name = e.where() == "start" ? start : e.where() == "goal" ? goal : std::string();
    return name.empty() ? e : InputError(name, e.detail());
}

std::shared_ptr<const grid::GridMap> load_map(const std::string& file, std::int64_t inflate,
                                              const grid::MapReadOptions& options) {
    require(inflate >= 0 && inflate <= 1000, "inflate", "must be in [0, 1000], got " + std::to_string(inflate));
    grid::GridMap loaded = grid::read_map(file, options);
    if (inflate > 0) loaded = loaded.inflated(static_cast<int>(inflate));
    return std::make_shared<const grid::GridMap>(std::move(loaded));
}

}  // namespace pride::engine

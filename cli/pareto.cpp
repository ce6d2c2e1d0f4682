#include "cli/pareto.hpp"

#include <fmt/format.h>

#include <memory>
#include <ostream>
#include <vector>

#include "cli/draw.hpp"
#include "cli/grid_commands.hpp"
#include "cli/numbers.hpp"
#include "engine/run.hpp"
#include "framework/error.hpp"
#include "problems/grid/grid_problem.hpp"
#include "problems/grid/objectives.hpp"
#include "problems/grid/pareto.hpp"

namespace pride::cli {

int pareto_command(const ParetoOptions& o, std::ostream& out) {
    const grid::Criteria criteria = grid::parse_criteria(o.objectives);
    std::vector<std::string> names;  // as given, with angle spelled angle_penalty
    for (std::size_t begin = 0; begin <= o.objectives.size();) {
        const std::size_t comma = std::min(o.objectives.find(',', begin), o.objectives.size());
        const std::string name = o.objectives.substr(begin, comma - begin);
        names.push_back(name == "angle" ? "angle_penalty" : name);
        begin = comma + 1;
    }
    const auto map = engine::load_map(o.map, o.inflate);
    const grid::Cell start = parse_cell(o.start, "--start"), goal = parse_cell(o.goal, "--goal");
    // The checks of `pride path`: inside, free, and the goal reachable (one line, exit 2).
    const grid::GridProblem<grid::LengthObjective> checked(map, start, goal, {}, o.corner_cutting);

    grid::ParetoOptions options;
    options.corner_cutting = o.corner_cutting;
    const auto front = grid::pareto_front(*map, start, goal, criteria, options);

    std::vector<std::pair<std::string, PictureFormat>> pictures;
    if (!o.svg.empty()) pictures.emplace_back(o.svg, PictureFormat::svg);
    if (!o.png.empty()) pictures.emplace_back(o.png, PictureFormat::png);
    std::vector<grid::Path> paths;
    for (const auto& p : front) paths.push_back(p.path);
    write_pictures(pictures, [&](const std::string& file, const std::string& shown_as, PictureFormat format) {
        draw_grid_paths(*map, start, goal, paths, file, shown_as, format);
    });

    std::string text;
    if (o.json) {
        std::string list, points;
        for (const auto& n : names) list += (list.empty() ? "" : ", ") + json_string(n);
        for (const auto& p : front)
            points += fmt::format("{}{{\"length\": {}, \"turns\": {}, \"angle_penalty\": {}, \"path\": {}}}",
                                  points.empty() ? "" : ", ", json_number(p.length), p.turns, p.angle_penalty,
                                  json_cells(p.path));
        text = fmt::format("{{\"objectives\": [{}], \"front\": [{}]}}\n", list, points);
    } else {
        text = "length turns angle_penalty\n";
        for (const auto& p : front) text += fmt::format("{:.10g} {} {}\n", p.length, p.turns, p.angle_penalty);
    }
    out << text;
    return 0;
}

}  // namespace pride::cli

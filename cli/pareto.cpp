#include "cli/pareto.hpp"

#include <fmt/format.h>

#include <memory>
#include <ostream>
#include <vector>

#include "cli/grid_commands.hpp"
#include "cli/numbers.hpp"
#include "cli/output.hpp"
#include "engine/run.hpp"
#include "experiment/html/draw.hpp"
#include "experiment/html/figure.hpp"
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
    grid::MapReadOptions read;
    read.unknown_free = o.unknown_free;
    const auto map = engine::load_map(o.map, o.inflate, read);
    const grid::Cell start = parse_cell(o.start, "--start"), goal = parse_cell(o.goal, "--goal");
    // The checks of `pride path`: inside, free, and the goal reachable (one line, exit 2).
    const grid::GridProblem<grid::LengthObjective> checked(map, start, goal, {}, o.corner_cutting);

    grid::ParetoOptions options;
    options.corner_cutting = o.corner_cutting;
    options.max_labels =
        std::min(options.max_labels, grid::label_limit(map->size(), engine::available_memory(), map->name()));
    const auto front = grid::pareto_front(*map, start, goal, criteria, options);

    std::vector<std::pair<std::string, html::PictureFormat>> pictures;
    if (!o.svg.empty()) pictures.emplace_back(o.svg, html::PictureFormat::svg);
    if (!o.png.empty()) pictures.emplace_back(o.png, html::PictureFormat::png);
    std::vector<grid::Path> paths;
    std::vector<std::string> labels;  // the point's objectives, as asked for
    for (const auto& p : front) {
        paths.push_back(p.path);
        std::string words;
        for (const auto& n : names)
            words +=
                (words.empty() ? "" : ", ") + (n == "length"      ? fmt::format("length {:.6g}", p.length)
                                               : n == "turns"     ? fmt::format("turns {}", p.turns)
                                               : n == "clearance" ? fmt::format("clearance {}", p.clearance)
                                                                  : fmt::format("angle penalty {}", p.angle_penalty));
        labels.push_back(words);
    }
    OutputFiles files;  // committed once the front was printed
    html::write_pictures(pictures, files, [&](OutputFiles::File& file, html::PictureFormat format) {
        html::draw_grid_paths(*map, start, goal, paths, labels, file, format);
    });

    if (!o.plot.empty()) {
        const auto value = [](const grid::FrontPoint& p, const std::string& n) -> double {
            return n == "length" ? p.length : n == "turns" ? p.turns : n == "clearance" ? p.clearance : p.angle_penalty;
        };
        std::vector<double> x, y;
        for (const auto& p : front) {
            x.push_back(value(p, names[0]));
            y.push_back(value(p, names[1]));
        }
        html::Figure fig("exact Pareto front", html::Axis{names[0], html::Scale::linear, std::nullopt, std::nullopt},
                         html::Axis{names[1], html::Scale::linear, std::nullopt, std::nullopt});
        if (names.size() > 2)
            fig.subtitle(fmt::format("objectives 1 and 2 of {}: {} and {}", names.size(), names[0], names[1]));
        fig.markers(x, y, html::series_colour(0), fmt::format("{} points", front.size()), html::Marker::circle);
        fig.write(files.create(o.plot));
    }

    // Clearance (with the default bands) is shown only when asked for, so that the other fronts
    // print as they always did.
    std::string text;
    if (o.json) {
        std::string list, points;
        for (const auto& n : names) list += (list.empty() ? "" : ", ") + json_string(n);
        for (const auto& p : front)
            points += fmt::format("{}{{\"length\": {}, \"turns\": {}, \"angle_penalty\": {}, {}\"path\": {}}}",
                                  points.empty() ? "" : ", ", json_number(p.length), p.turns, p.angle_penalty,
                                  criteria.clearance ? fmt::format("\"clearance\": {}, ", p.clearance) : "",
                                  json_cells(p.path));
        text = fmt::format("{{\"objectives\": [{}], \"front\": [{}]}}\n", list, points);
    } else {
        text = criteria.clearance ? "length turns angle_penalty clearance\n" : "length turns angle_penalty\n";
        for (const auto& p : front)
            text += criteria.clearance
                        ? fmt::format("{:.10g} {} {} {}\n", p.length, p.turns, p.angle_penalty, p.clearance)
                        : fmt::format("{:.10g} {} {}\n", p.length, p.turns, p.angle_penalty);
    }
    print_then_commit(out, text, files);
    return 0;
}

}  // namespace pride::cli

#include "cli/grid_commands.hpp"

#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <map>
#include <memory>
#include <ostream>
#include <tuple>

#include "cli/commands.hpp"
#include "cli/numbers.hpp"
#include "cli/output.hpp"
#include "engine/planner_settings.hpp"
#include "engine/registry.hpp"
#include "engine/run.hpp"
#include "engine/scenarios.hpp"
#include "experiment/html/draw.hpp"
#include "framework/error.hpp"
#include "problems/grid/grid_problem.hpp"
#include "problems/grid/map_io.hpp"
#include "problems/grid/planners/astar.hpp"

namespace pride::cli {
namespace {

using namespace pride::grid;

/// The spec of `pride path`'s options (names checked, the map not read yet).
engine::GridSpec grid_spec(const PathOptions& o) {
    engine::GridSpec g;
    g.objective = o.objective.empty() ? engine::default_grid_objective(o.algo) : o.objective;
    g.encoding = o.encoding;
    g.connector = o.connector;
    g.init = o.init;
    if (o.waypoints) {
        // A count the run would ignore is refused: only the free encoding has waypoints.
        const engine::AlgorithmEntry* entry = engine::algorithms().find(o.algo);
        const std::string encoding = !o.encoding.empty()            ? o.encoding
                                     : entry && !entry->whole_map() ? entry->native_encoding
                                                                    : "";
        if (entry || !o.encoding.empty())
            require(encoding == "free", "--waypoints",
                    encoding.empty()
                        ? o.algo + " plans on the whole map, it has no waypoints"
                        : "only the free encoding has waypoints; this run plans on " + encoding +
                              (o.encoding.empty() ? " (" + o.algo + "'s own; --encoding free to use them)" : ""));
        g.waypoints = *o.waypoints;
    }
    g.corner_cutting = o.corner_cutting;
    g.oracle = o.oracle;
    g.path_gaps = o.gaps;
    if (o.weights) g.weights = parse_point(*o.weights, "--weights");
    g.lambda = o.lambda;
    return g;
}

}  // namespace

Cell parse_cell(const std::string& text, const std::string& where) {
    const auto comma = text.find(',');
    require(comma != std::string::npos, where, "expected X,Y, got '" + text + "'");
    const double x = parse_finite(std::string_view(text).substr(0, comma), where + " X");
    const double y = parse_finite(std::string_view(text).substr(comma + 1), where + " Y");
    require(x == std::floor(x) && y == std::floor(y) && std::abs(x) < 1e9 && std::abs(y) < 1e9, where,
            "expected integer coordinates, got '" + text + "'");
    return {static_cast<int>(x), static_cast<int>(y)};
}

Cell parse_world_cell(const std::string& text, const GridMap& map, const std::string& where) {
    const auto comma = text.find(',');
    require(comma != std::string::npos, where, "expected X,Y in metres, got '" + text + "'");
    const double x = parse_finite(std::string_view(text).substr(0, comma), where + " X");
    const double y = parse_finite(std::string_view(text).substr(comma + 1), where + " Y");
    return engine::world_cell(map, x, y, where, "a cell with " + where.substr(0, where.find("-world")));
}

std::string json_world_path(const GridMap& map, const Polyline& path) {
    std::string out = "[";
    for (std::size_t i = 0; i < path.size(); ++i) {
        const WorldPoint p = map.world(path[i].x, path[i].y);
        out +=
            fmt::format("{}[{}, {}]", i ? ", " : "", json_number(printed_world(p.x)), json_number(printed_world(p.y)));
    }
    return out + "]";
}

engine::RunResult plan_path(const PathOptions& o, engine::GridSpec* spec_out) {
    engine::GridSpec spec = grid_spec(o);
    engine::check_grid_names(spec);
    require(!o.start.empty() || !o.start_world.empty(), "--start",
            "give the start: --start X,Y (a cell) or --start-world X,Y (metres)");
    require(!o.goal.empty() || !o.goal_world.empty(), "--goal",
            "give the goal: --goal X,Y (a cell) or --goal-world X,Y (metres)");
    grid::MapReadOptions read;
    read.unknown_free = o.unknown_free;
    spec.map = engine::load_map(o.map, o.inflate, read);
    spec.start = o.start_world.empty() ? parse_cell(o.start, "--start")
                                       : parse_world_cell(o.start_world, *spec.map, "--start-world");
    spec.goal =
        o.goal_world.empty() ? parse_cell(o.goal, "--goal") : parse_world_cell(o.goal_world, *spec.map, "--goal-world");
    std::optional<engine::Problem> problem;
    try {
        problem.emplace(spec);
    } catch (const InputError& e) {
        // The goal unreachable from a world point's cell: named by the option that gave it.
        throw engine::endpoint_error(e, o.start_world.empty() ? "" : "--start-world",
                                     o.goal_world.empty() ? "" : "--goal-world");
    }
    const engine::AlgorithmSpec algorithm{o.algo, parse_params(o.params, o.pop)};
    engine::refuse_unused_planner_settings(algorithm, spec, o.budget);
    engine::check(algorithm, *problem, o.budget);
    if (spec_out) *spec_out = spec;
    return engine::run(algorithm, *problem, o.budget, o.seed);
}

std::pair<std::string, std::string> picture_labels(const PathOptions& o, const engine::GridSpec& spec,
                                                   const engine::GridOutcome& run) {
    std::string path = fmt::format("{} ({}): {} {:.6g}", o.algo, run.encoding, spec.objective, run.value);
    std::string optimal =
        run.optimum ? fmt::format("exact optimum: {} {:.6g}", spec.objective, *run.optimum) : "exact optimum";
    if (const auto& frame = spec.map->frame()) {
        // The lengths in metres beside those in cells.
        if (run.feasible) path += ", " + html::length_words(run.metrics.length, *frame);
        if (run.optimum && !run.optimal_path.empty())
            optimal += ", " + html::length_words(metrics(run.optimal_path).length, *frame);
    }
    return {path, optimal};
}

int path_command(const PathOptions& o, std::ostream& out) {
    engine::GridSpec spec;
    const engine::RunResult r = plan_path(o, &spec);
    const engine::GridOutcome& run = *r.grid;
    const PathMetrics m = metrics(run.path);
    // A polyline planner's path (Theta*, the any-angle path) is no chain of cells.
    const bool polyline_only = run.path.empty() && !run.polyline.empty();
    // A map with a world frame: lengths in metres beside those in cells.
    const std::optional<WorldFrame>& frame = spec.map->frame();
    const auto length_m = [&](double cells) {
        return frame ? fmt::format("length_m        {:.10g}\n", cells * frame->resolution) : std::string();
    };

    std::optional<double> gap;
    if (run.optimum && run.feasible) {
        // The oracle sums step and turn costs in another order than the metrics do: values that
        // agree to 1e-9 (relative) are the same optimum, and the gap is exactly 0.
        const double scale = std::max(1.0, std::abs(*run.optimum));
        // Relative to |optimum|, so that a worse value has a positive gap when the optimum is negative
        // (iqga); for every other objective the optimum is >= 0 and this is (value - optimum) / optimum.
        gap = std::abs(run.value - *run.optimum) <= 1e-9 * scale ? 0.0
                                                                 : (run.value - *run.optimum) / std::abs(*run.optimum);
    }
    // The pictures first: drawn to temporary files, and renamed into place only once the text
    // below was printed, so a failure of either leaves no picture (framework/output_files.hpp).
    std::vector<std::pair<std::string, html::PictureFormat>> pictures;
    if (!o.svg.empty()) pictures.emplace_back(o.svg, html::PictureFormat::svg);
    if (!o.png.empty()) pictures.emplace_back(o.png, html::PictureFormat::png);
    OutputFiles files;
    html::write_pictures(pictures, files, [&](OutputFiles::File& file, html::PictureFormat format) {
        html::PathLabels labels;
        std::tie(labels.path, labels.optimal) = picture_labels(o, spec, run);
        html::draw_grid(*spec.map, spec.start, spec.goal, run.feasible ? &run.polyline : nullptr,
                        o.oracle ? &run.optimal_path : nullptr, labels, file, format);
    });

    if (o.json) {
        // A chain's metrics (path.hpp); a polyline planner's path has no cells: null.
        const std::string chain_metrics =
            polyline_only ? "null"
                          : fmt::format(
                                "{{\"cells\": {}, \"length\": {}, \"turns\": {}, \"turn_angle_deg\": {}, "
                                "\"angle_penalty\": {}{}}}",
                                m.cells, json_number(m.length), m.turns, m.turn_angle_deg, m.angle_penalty,
                                frame ? ", \"length_m\": " + json_number(m.length * frame->resolution) : "");
        std::string text = fmt::format(
            "{{\"algo\": {}, \"objective\": {}, \"encoding\": {}, \"seed\": {}, \"feasible\": {}, \"path\": {}, "
            "\"metrics\": {}, \"objective_value\": {}, \"evaluations\": {}, \"iterations\": {}, \"wall_ms\": {}, "
            "\"history\": {}",
            json_string(o.algo), json_string(spec.objective), json_string(run.encoding), o.seed,
            run.feasible ? "true" : "false", json_cells(run.path), chain_metrics,
            run.feasible ? json_number(run.value) : "null", r.evaluations, r.iterations, json_number(r.wall_ms),
            json_array(r.history));
        text += ", \"polyline\": " + engine::json_polyline(run.polyline);
        if (run.feasible) text += ", \"path_metrics\": " + engine::json_path_metrics(run, o.gaps, frame);
        if (spec.map->frame()) text += ", \"path_world\": " + json_world_path(*spec.map, run.polyline);
        if (o.oracle)
            text += fmt::format(", \"optimum\": {{\"objective_value\": {}, \"gap\": {}}}",
                                run.optimum ? json_number(*run.optimum) : "null", gap ? json_number(*gap) : "null");
        print_then_commit(out, text + "}\n", files);
        return 0;
    }
    std::string text = fmt::format(
        "algo            {}\nobjective       {}\nencoding        {}\nseed            {}\n"
        "feasible        {}\n",
        o.algo, spec.objective, run.encoding, o.seed, run.feasible ? "yes" : "no");
    if (run.feasible && polyline_only)
        text += fmt::format(
            "objective_value {:.10g}\nvertices        {}\nlength          {:.10g}\n{}turns           {}\n", run.value,
            run.polyline.size(), run.metrics.length, length_m(run.metrics.length), run.metrics.turns);
    else if (run.feasible)
        text += fmt::format(
            "objective_value {:.10g}\ncells           {}\nlength          {:.10g}\n{}turns           {}\n"
            "turn_angle_deg  {}\nangle_penalty   {}\n",
            run.value, m.cells, m.length, length_m(m.length), m.turns, m.turn_angle_deg, m.angle_penalty);
    if (run.feasible) {
        const PolylineMetrics& pm = run.metrics;
        const auto clearance = [](const std::optional<double>& v) { return v ? fmt::format("{:.6g}", *v) : "-"; };
        text += fmt::format(
            "total_turn_deg  {:.6g}\nmax_turn_deg    {:.6g}\nangle_over_len  {:.6g}\nmax_curvature   {:.6g}\n"
            "min_clearance   {}\nmean_clearance  {}\n",
            pm.total_turn_deg, pm.max_turn_deg, pm.angle_over_length, pm.max_curvature, clearance(pm.min_clearance),
            clearance(pm.mean_clearance));
    }
    if (o.oracle)
        text += fmt::format("optimum         {:.10g}\ngap             {}\n", *run.optimum,
                            gap ? fmt::format("{:.6g}", *gap) : "-");
    if (o.gaps) {
        const auto number = [](const std::optional<double>& v) { return v ? fmt::format("{:.10g}", *v) : "-"; };
        text += fmt::format("grid_shortest   {}\ngrid_gap        {}\nany_angle_short {}\nany_angle_gap   {}\n",
                            number(run.shortest_grid_length), number(run.grid_gap),
                            number(run.shortest_any_angle_length), number(run.any_angle_gap));
    }
    text += fmt::format("evaluations     {}\niterations      {}\nwall_ms         {:.3f}\n", r.evaluations, r.iterations,
                        r.wall_ms);
    if (!run.path.empty() || run.polyline.empty())
        text += fmt::format("path            {}\n", json_cells(run.path));
    else
        text += fmt::format("polyline        {}\n", engine::json_polyline(run.polyline));
    if (spec.map->frame()) text += "path_world      " + json_world_path(*spec.map, run.polyline) + "\n";
    print_then_commit(out, text, files);
    return 0;
}

int scen_command(const ScenOptions& o, std::ostream& out) {
    const engine::ScenarioCheck c = engine::check_scenarios(o.file, o.map_dir);
    if (o.json)
        out << fmt::format("{{\"checked\": {}, \"differ\": {}, \"max_diff\": {}, \"expansions_per_s\": {}}}\n",
                           c.checked, c.differ, json_number(c.max_diff), json_number(c.expansions_per_s));
    else
        out << fmt::format(
            "checked           {}\ndiffer            {} (by more than 1e-6)\nmax_diff          {:.3g}\n"
            "expansions_per_s  {:.4g}\n",
            c.checked, c.differ, c.max_diff, c.expansions_per_s);
    return 0;
}

}  // namespace pride::cli

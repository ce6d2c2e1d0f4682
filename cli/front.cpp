#include "cli/front.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <ostream>
#include <utility>

#include "cli/commands.hpp"
#include "cli/grid_commands.hpp"
#include "cli/numbers.hpp"
#include "cli/output.hpp"
#include "engine/multiobjective.hpp"
#include "engine/run.hpp"
#include "experiment/html/draw.hpp"
#include "experiment/html/figure.hpp"
#include "framework/error.hpp"

namespace pride::cli {
namespace {

engine::ProblemSpec problem_spec(const FrontOptions& o) {
    const bool grid = !o.map.empty();
    require(grid != !o.problem.empty(), "problem", "give either --problem or --map (with --start and --goal)");
    if (!grid) {
        require(o.start.empty() && o.goal.empty() && o.encoding.empty() && o.init.empty() && !o.waypoints &&
                    o.inflate == 0 && !o.unknown_free && !o.corner_cutting && o.connector == "repair" &&
                    o.svg.empty() && o.png.empty(),
                "problem",
                o.problem +
                    " is not a grid: --start, --goal, --encoding, --init, --connector, --waypoints, --unknown-free, "
                    "--inflate, --corner-cutting, --svg and --png are for --map");
        require(engine::is_multiobjective_problem(o.problem), "problem",
                "unknown multi-objective problem '" + o.problem + "' (" + engine::multiobjective_problem_names() +
                    "; single-objective problems run with pride run)");
        engine::ContinuousSpec s{o.problem, o.dim.value_or(0), std::nullopt, 0};
        if (!o.objectives.empty()) {
            std::int64_t m = 0;
            const auto* end = o.objectives.data() + o.objectives.size();
            const auto [ptr, ec] = std::from_chars(o.objectives.data(), end, m);
            require(ec == std::errc{} && ptr == end && m >= 1, "objectives",
                    "expected the number of objectives M of " + o.problem + ", got '" + o.objectives + "'");
            s.objectives = m;
        }
        return s;
    }
    require(!o.dim, "dim", "a grid's dimension is its encoding's");
    require(!o.start.empty() && !o.goal.empty(), "map", "a grid needs --start and --goal");
    require(!o.waypoints || o.encoding == "free", "waypoints", "only for the free encoding");
    engine::GridSpec s;
    grid::MapReadOptions read;
    read.unknown_free = o.unknown_free;
    s.map = engine::load_map(o.map, o.inflate, read);
    s.start = parse_cell(o.start, "--start");
    s.goal = parse_cell(o.goal, "--goal");
    s.encoding = o.encoding;
    s.init = o.init;
    s.connector = o.connector;
    s.waypoints = o.waypoints.value_or(3);
    s.corner_cutting = o.corner_cutting;
    s.objectives = o.objectives.empty() ? "length,turns" : o.objectives;
    return s;
}

}  // namespace

int front_command(const FrontOptions& o, std::ostream& out) {
    const engine::ProblemSpec spec = problem_spec(o);
    const engine::Problem problem(spec);
    const engine::AlgorithmSpec algorithm{o.algo, parse_params(o.params, o.pop)};
    engine::check(algorithm, problem, o.budget);
    if (!o.no_reference) engine::check_quality(problem);
    const engine::RunResult r = engine::run(algorithm, problem, o.budget, o.seed);
    const engine::Front& front = *r.front;
    std::optional<engine::FrontQuality> q;
    if (!o.no_reference) q = engine::quality(problem, front.f, front.violation);

    const auto names = problem.objective_names();
    const bool grid = problem.is_grid();
    std::vector<std::pair<std::string, html::PictureFormat>> pictures;
    if (!o.svg.empty()) pictures.emplace_back(o.svg, html::PictureFormat::svg);
    if (!o.png.empty()) pictures.emplace_back(o.png, html::PictureFormat::png);
    OutputFiles files;  // committed once the front was printed
    if (grid) {
        const auto& g = std::get<engine::GridSpec>(spec);
        std::vector<std::string> labels;
        for (Eigen::Index j = 0; j < front.f.cols(); ++j) {
            std::string words;
            for (std::size_t i = 0; i < names.size(); ++i)
                words +=
                    fmt::format("{}{} {:.6g}", i == 0 ? "" : ", ", names[i], front.f(static_cast<Eigen::Index>(i), j));
            labels.push_back(words);
        }
        html::write_pictures(pictures, files, [&](OutputFiles::File& file, html::PictureFormat format) {
            html::draw_grid_paths(*g.map, g.start, g.goal, front.paths, labels, file, format);
        });
    }

    if (!o.plot.empty()) {
        // The reference front is drawn even with --no-reference only when it is known already: the
        // plot's own reason to compute it is the comparison, which --no-reference declines.
        const auto where = grid ? std::string("grid") : problem.name();
        html::Figure fig(r.algorithm + " on " + where,
                         html::Axis{names[0], html::Scale::linear, std::nullopt, std::nullopt},
                         html::Axis{names[1], html::Scale::linear, std::nullopt, std::nullopt});
        if (names.size() > 2)
            fig.subtitle(fmt::format("objectives 1 and 2 of {}: {} and {}", names.size(), names[0], names[1]));
        const auto row = [](const Matrix& m, Eigen::Index i) {
            return std::vector<double>(m.row(i).begin(), m.row(i).end());
        };
        if (q) {
            const Matrix& reference = problem.reference_front();
            fig.markers(row(reference, 0), row(reference, 1), html::Rgb{0.6, 0.6, 0.6},
                        grid ? "exact front" : "reference front", html::Marker::circle);
        }
        fig.markers(row(front.f, 0), row(front.f, 1), html::series_colour(0), r.algorithm, html::Marker::cross);
        fig.write(files.create(o.plot));
    }

    std::string text;
    const std::string where =
        grid ? "grid" : fmt::format("{} (n = {}, M = {})", problem.name(), problem.dimension(), problem.objectives());
    if (o.json) {
        std::string list;
        for (const auto& n : names) list += (list.empty() ? "" : ", ") + json_string(n);
        std::string quality = "null";
        if (q)
            quality = fmt::format(
                "{{\"hypervolume\": {}, \"reference_hypervolume\": {}, \"hypervolume_ratio\": {}, \"igd_plus\": {}, "
                "\"ideal\": {}, \"nadir\": {}, \"reference_point\": 1.1, \"reference_size\": {}{}}}",
                json_number(q->hypervolume), json_number(q->reference_hypervolume), json_number(q->hypervolume_ratio),
                json_number(q->igd_plus), json_array(q->ideal), json_array(q->nadir), q->reference_size,
                q->exact_found ? fmt::format(", \"exact_found\": {}", *q->exact_found) : "");
        text = fmt::format(
            "{{\"algo\": {}, \"problem\": {}, \"dim\": {}, \"objectives\": [{}], \"seed\": {}, \"evaluations\": {}, "
            "\"iterations\": {}, \"wall_ms\": {}, \"front\": {}, \"quality\": {}{}}}\n",
            json_string(r.algorithm), json_string(problem.name()), problem.dimension(), list, o.seed, r.evaluations,
            r.iterations, json_number(r.wall_ms), engine::front_json(front), quality,
            front.violation.empty() ? ""
                                    : fmt::format(", \"first_feasible\": {}",
                                                  r.first_feasible ? std::to_string(*r.first_feasible) : "null"));
    } else {
        text = fmt::format(
            "algo         {}\nproblem      {}\nseed         {}\nevaluations  {}\niterations   {}\nwall_ms      {:.3f}\n"
            "points       {} non-dominated\n",
            r.algorithm, where, o.seed, r.evaluations, r.iterations, r.wall_ms, front.f.cols());
        if (!front.violation.empty()) {
            const auto feasible = std::count(front.violation.begin(), front.violation.end(), 0.0);
            text += fmt::format("feasible     {} of {} points{}\n", feasible, front.violation.size(),
                                r.first_feasible ? fmt::format("; the first found at evaluation {}", *r.first_feasible)
                                                 : "; none found");
        }
        if (q) {
            text += fmt::format(
                "hypervolume  {:.6g} of the reference front's {:.6g} (ratio {:.4f}; normalised, "
                "reference point 1.1)\nigd+         {:.6g}\n",
                q->hypervolume, q->reference_hypervolume, q->hypervolume_ratio, q->igd_plus);
            if (q->exact_found)
                text += fmt::format("exact front  {} of its {} points found\n", *q->exact_found, q->reference_size);
        }
        for (std::size_t i = 0; i < names.size(); ++i) text += (i == 0 ? "" : " ") + names[i];
        text += grid ? " legal\n" : front.violation.empty() ? "\n" : " violation\n";
        for (Eigen::Index j = 0; j < front.f.cols(); ++j) {
            for (Eigen::Index i = 0; i < front.f.rows(); ++i)
                text += fmt::format("{}{:.10g}", i == 0 ? "" : " ", front.f(i, j));
            if (!grid && !front.violation.empty())
                text += fmt::format(" {:.10g}", front.violation[static_cast<std::size_t>(j)]);
            text += grid ? (front.feasible[static_cast<std::size_t>(j)] ? " yes\n" : " no\n") : "\n";
        }
    }
    print_then_commit(out, text, files);
    return 0;
}

}  // namespace pride::cli

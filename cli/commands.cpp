#include "cli/commands.hpp"

#include <fmt/format.h>

#include <chrono>
#include <istream>
#include <map>
#include <ostream>
#include <variant>

#include "cli/algorithms.hpp"
#include "cli/numbers.hpp"
#include "framework/error.hpp"
#include "framework/params.hpp"
#include "problems/continuous/catalog.hpp"

namespace pride::cli {

int run_command(const RunOptions& o, std::ostream& out) {
    require(o.dim >= 1, "--dim", "dimension must be >= 1, got " + std::to_string(o.dim));
    const auto problem = continuous::make_problem(o.problem, o.dim);
    ParamMap params;
    for (const auto& p : o.params) params.set_from_string(p);
    if (o.pop) params.set("pop", static_cast<double>(*o.pop));
    const auto runner = make_algorithm(o.algo, params);

    Termination t;
    if (o.iters) {
        require(*o.iters >= 0, "--iters", "must be >= 0, got " + std::to_string(*o.iters));
        t = t | max_iterations(*o.iters);
    }
    if (o.evals || !o.iters) {
        // Without a limit the budget is 10,000 evaluations per dimension, the CEC convention.
        const std::int64_t evals = o.evals.value_or(10000 * o.dim);
        require(evals >= 1, "--evals", "must be >= 1, got " + std::to_string(evals));
        t = t | max_evaluations(evals);
    }
    if (o.target) t = t | target_value(*o.target);
    if (o.wall_ms) {
        require(*o.wall_ms > 0, "--wall-ms", "must be > 0");
        // A limit beyond what the clock can count (about 292 years) is no limit.
        const double longest = std::chrono::duration<double, std::milli>(Clock::duration::max()).count();
        if (*o.wall_ms < longest)
            t = t | wall_time(std::chrono::duration_cast<Clock::duration>(
                        std::chrono::duration<double, std::milli>(*o.wall_ms)));
    }

    require(o.seed >= 0, "--seed", "must be >= 0, got " + std::to_string(o.seed));
    const Result r = runner(problem, t, static_cast<std::uint64_t>(o.seed));
    if (o.json) {
        out << fmt::format(
            "{{\"algo\": {}, \"problem\": {}, \"dim\": {}, \"seed\": {}, \"best_f\": {}, \"best_x\": {}, "
            "\"evaluations\": {}, \"wall_ms\": {}, \"history\": {}}}\n",
            json_string(o.algo), json_string(o.problem), o.dim, o.seed, json_number(r.best_f), json_array(r.best_x),
            r.evaluations, json_number(r.wall_ms), json_array(r.history));
    } else {
        out << fmt::format(
            "algo         {}\nproblem      {} (D = {})\nseed         {}\nbest_f       {:.17g}\n"
            "evaluations  {}\niterations   {}\nwall_ms      {:.3f}\nbest_x       {}\n",
            o.algo, o.problem, o.dim, o.seed, r.best_f, r.evaluations, r.iterations, r.wall_ms, json_array(r.best_x));
    }
    return 0;
}

int eval_command(const EvalOptions& o, std::istream& in, std::ostream& out) {
    std::vector<std::vector<double>> points;
    if (o.x == "-") {
        std::string line;
        for (std::size_t n = 1; std::getline(in, line); ++n) {
            if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
            points.push_back(parse_point(line, "stdin line " + std::to_string(n)));
            require(points.back().size() == points.front().size(), "stdin line " + std::to_string(n),
                    "expected " + std::to_string(points.front().size()) + " coordinates like the first point, got " +
                        std::to_string(points.back().size()));
        }
        require(!points.empty(), "stdin", "no points given");
    } else {
        points.push_back(parse_point(o.x, "--x"));
    }
    const std::size_t dim = points.front().size();
    if (o.dim)
        require(static_cast<std::int64_t>(dim) == *o.dim, o.x == "-" ? "stdin" : "--x",
                "expected " + std::to_string(*o.dim) + " coordinates (--dim), got " + std::to_string(dim));
    auto problem = continuous::make_problem(o.problem, static_cast<std::int64_t>(dim), o.x == "-" ? "stdin" : "--x");
    std::string text;
    for (const auto& x : points)
        text += fmt::format("{:.17g}\n", std::visit([&](auto& p) { return p.evaluate(x); }, problem));
    out << text;
    return 0;
}

int list_command(bool json, std::ostream& out) {
    struct Section {
        std::string title;
        std::vector<AlgorithmInfo> items;
    };
    std::vector<Section> sections;
    sections.push_back({"algorithms", list_algorithms()});
    Section problems{"problems", {}};
    for (const auto& item : continuous::catalog().items())
        problems.items.push_back({item.name, item.summary + " (dim >= " + std::to_string(item.entry.min_dim) + ")"});
    sections.push_back(problems);
    sections.push_back(
        {"encodings",
         {{"identity", "the genotype is the solution (every continuous problem)"},
          {"line", "grids: one gene per row (or column) between start and goal, the waypoint's cross coordinate"},
          {"free", "grids: 2K genes, K waypoints (x, y) anywhere on the map (--waypoints K, default 3)"},
          {"chain",
           "grids: the cell chain itself, with crossover at a common cell and segment-regenerating mutation (ga, "
           "ga-plus)"}}});
    sections.push_back(
        {"connectors",
         {{"repair", "grids (line, free): a blocked join becomes the shortest legal detour (A* in a growing window)"},
          {"penalty", "grids (line, free): the straight cell line; each violation costs M >= 10 W H"}}});
    sections.push_back(
        {"objectives",
         {{"value", "continuous problems: the function value itself, minimised"},
          {"cells", "grids: number of cells, start and goal included (file 000 eq. 13)"},
          {"length", "grids: sum of step lengths, 1 or sqrt(2) (file 002 eq. 8)"},
          {"weighted", "grids: w_len length + w_turn turns + w_angle angle_penalty (--weights, default 1,1,0.1)"},
          {"iqga", "grids: -(1/length + 1/angle_penalty + 1/turns) (file 002 eq. 12)"},
          {"hswoa", "grids: length + lambda turns (file 003; --lambda, default 1)"}}});

    std::string text;
    if (json) {
        text = "{";
        for (std::size_t s = 0; s < sections.size(); ++s) {
            text += (s ? ", " : "") + json_string(sections[s].title) + ": [";
            for (std::size_t i = 0; i < sections[s].items.size(); ++i)
                text += fmt::format("{}{{\"name\": {}, \"summary\": {}}}", i ? ", " : "",
                                    json_string(sections[s].items[i].name), json_string(sections[s].items[i].summary));
            text += "]";
        }
        text += "}\n";
    } else {
        for (const auto& s : sections) {
            text += s.title + ":\n";
            for (const auto& item : s.items) text += fmt::format("  {:<22} {}\n", item.name, item.summary);
        }
    }
    out << text;
    return 0;
}

}  // namespace pride::cli

#include "cli/grid_commands.hpp"

#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <map>
#include <memory>
#include <ostream>

#include "cli/algorithm_factory.hpp"
#include "cli/draw.hpp"
#include "cli/numbers.hpp"
#include "framework/encoding.hpp"
#include "framework/error.hpp"
#include "framework/params.hpp"
#include "problems/grid/astar.hpp"
#include "problems/grid/chain.hpp"
#include "problems/grid/encodings.hpp"
#include "problems/grid/grid_problem.hpp"
#include "problems/grid/map_io.hpp"
#include "problems/grid/objectives.hpp"
#include "problems/grid/oracle.hpp"

namespace pride::cli {
namespace {

using namespace pride::grid;

Cell parse_cell(const std::string& text, const std::string& where) {
    const auto comma = text.find(',');
    require(comma != std::string::npos, where, "expected X,Y, got '" + text + "'");
    const double x = parse_finite(std::string_view(text).substr(0, comma), where + " X");
    const double y = parse_finite(std::string_view(text).substr(comma + 1), where + " Y");
    require(x == std::floor(x) && y == std::floor(y) && std::abs(x) < 1e9 && std::abs(y) < 1e9, where,
            "expected integer coordinates, got '" + text + "'");
    return {static_cast<int>(x), static_cast<int>(y)};
}

std::string json_path(const Path& path) {
    std::string s = "[";
    for (std::size_t i = 0; i < path.size(); ++i) s += fmt::format("{}[{},{}]", i ? "," : "", path[i].x, path[i].y);
    return s + "]";
}

Termination grid_termination(const PathOptions& o) {
    Termination t;
    if (o.iters) {
        require(*o.iters >= 0, "--iters", "must be >= 0, got " + std::to_string(*o.iters));
        t = t | max_iterations(*o.iters);
    }
    if (o.evals) {
        require(*o.evals >= 1, "--evals", "must be >= 1, got " + std::to_string(*o.evals));
        t = t | max_evaluations(*o.evals);
    }
    if (!o.iters && !o.evals) t = max_iterations(50);  // the papers' T = 50
    return t;
}

/// What a run of an algorithm (box or chain) found: the candidate path is the result only when it
/// is legal (grid.md: an infeasible candidate is never returned as a result).
template <class Objective, class R>
void record(PathRun& run, const GridProblem<Objective>& problem, const Path& candidate, bool no_violations,
            const R& r) {
    run.feasible =
        no_violations &&
        path_violation(problem.map(), candidate, problem.start(), problem.goal(), problem.corner_cutting()).empty();
    if (run.feasible) {
        run.path = candidate;
        run.value = problem.evaluate(candidate);
    }
    run.evaluations = r.evaluations;
    run.iterations = r.iterations;
    run.wall_ms = r.wall_ms;
    run.history = r.history;
    run.history_evaluations = r.history_evaluations;
}

/// The algorithm's parameters: --param, with the population of --pop (else --param pop, else the
/// papers' N = 20).
ParamMap grid_params(const PathOptions& o) {
    ParamMap params;
    for (const auto& p : o.params) params.set_from_string(p);
    if (o.pop || !params.contains("pop")) params.set("pop", static_cast<double>(o.pop.value_or(20)));
    return params;
}

/// A box algorithm through an encoding with a connector.
template <class Objective, class Encoding>
void run_encoded(const PathOptions& o, const GridProblem<Objective>& problem, Encoding encoding, PathRun& run) {
    ParamMap params = grid_params(o);
    GridProblem<Objective> suggesting = problem;
    if (!o.init.empty()) {
        require(o.init == "uniform" || o.algo.rfind("nlopt:", 0) != 0, "--init " + o.init,
                "NLopt algorithms start from one uniform point");
        if (o.algo.rfind("nlopt:", 0) != 0) params.set("walk_init", o.init == "uniform" ? 0.0 : 1.0);
    }
    suggesting.set_walks(o.init == "walk" ? Walks::random : Walks::rules);
    const Termination termination = grid_termination(o);
    Encoded<GridProblem<Objective>, Encoding> encoded(std::move(suggesting), std::move(encoding));
    const Result r = with_algorithm(o.algo, params, [&](const auto& algorithm) {
        return algorithm.run(encoded, termination, static_cast<std::uint64_t>(o.seed));
    });
    const DecodedPath& best = encoded.decode(r.best_x);
    record(run, problem, best.path, best.violations == 0, r);
}

template <class Objective, template <class> class Encoding>
void run_with_connector(const PathOptions& o, const GridProblem<Objective>& problem, PathRun& run, auto make) {
    if (o.connector == "repair")
        run_encoded(o, problem, make.template operator()<Encoding<RepairConnector>>(), run);
    else if (o.connector == "penalty")
        run_encoded(o, problem, make.template operator()<Encoding<PenaltyConnector>>(), run);
    else
        throw InputError("--connector: unknown connector '" + o.connector + "' (penalty or repair)");
}

template <class Objective>
PathRun run_path(const PathOptions& o, const std::shared_ptr<const GridMap>& map, Objective objective) {
    const GridProblem<Objective> problem(map, parse_cell(o.start, "--start"), parse_cell(o.goal, "--goal"), objective,
                                         o.corner_cutting);
    PathRun run;
    const auto start = Clock::now();  // for astar and exact, whose wall time is their own
    if (o.oracle || o.algo == "exact") {
        if constexpr (Objective::additive) {
            Oracle oracle;
            run.optimum = oracle.solve(problem.map(), problem.start(), problem.goal(), objective, &run.optimal_path,
                                       o.corner_cutting);
        } else {
            throw InputError(std::string(o.algo == "exact" ? "--algo exact" : "--oracle") + ": the " +
                             std::string(Objective::name) +
                             " objective is not a sum of step and turn costs, so it has no exact oracle");
        }
    }
    if (o.algo == "exact") {
        run.path = run.optimal_path;
        run.feasible = true;
        run.value = problem.evaluate(run.path);
    } else if (o.algo == "astar") {
        AStar astar;
        astar.search(problem.map(), problem.start(), problem.goal(), &run.path, nullptr, o.corner_cutting);
        run.feasible = true;
        run.value = problem.evaluate(run.path);
        run.evaluations = astar.expansions();
    } else if (o.encoding == "line") {
        run.encoding = "line";
        run_with_connector<Objective, LineEncoding>(o, problem, run, [&]<class E>() { return E(problem); });
    } else if (o.encoding == "free") {
        run.encoding = "free";
        require(o.waypoints >= 1 && o.waypoints <= 1000, "--waypoints", "must be in [1, 1000]");
        run_with_connector<Objective, FreeEncoding>(
            o, problem, run, [&]<class E>() { return E(problem, static_cast<int>(o.waypoints)); });
    } else if (o.encoding == "chain") {
        run.encoding = "chain";
        require(o.connector == "repair", "--connector", "chains need no connector: every operator keeps them legal");
        const auto r = with_chain_algorithm(o.algo, grid_params(o), [&](const auto& algorithm) {
            return algorithm.run(ChainSpace<Objective>(problem), grid_termination(o),
                                 static_cast<std::uint64_t>(o.seed));
        });
        record(run, problem, r.best_x, true, r);
    } else {
        throw InputError("--encoding: unknown encoding '" + o.encoding + "' (line, free or chain)");
    }
    if (o.algo == "astar" || o.algo == "exact")
        run.wall_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    return run;
}

PathRun dispatch_objective(const PathOptions& o, const std::shared_ptr<const GridMap>& map) {
    if (o.objective == "cells") return run_path(o, map, CellsObjective{});
    if (o.objective == "length") return run_path(o, map, LengthObjective{});
    if (o.objective == "weighted") {
        WeightedObjective w;
        if (o.weights) {
            const auto v = parse_point(*o.weights, "--weights");
            require(v.size() == 3, "--weights", "expected L,T,A (three weights), got " + std::to_string(v.size()));
            w.w_len = v[0];
            w.w_turn = v[1];
            w.w_angle = v[2];
        }
        w.validate();
        return run_path(o, map, w);
    }
    if (o.objective == "hswoa") {
        HswoaObjective h;
        h.lambda = o.lambda.value_or(h.lambda);
        h.validate();
        return run_path(o, map, h);
    }
    if (o.objective == "iqga") return run_path(o, map, IqgaObjective{});
    throw InputError("--objective: unknown objective '" + o.objective + "' (cells, length, weighted, iqga or hswoa)");
}

}  // namespace

void check_path_options(const PathOptions& o) {
    const bool box_algorithm = o.algo != "astar" && o.algo != "exact";
    const bool additive = o.objective != "iqga";
    require(o.objective == "cells" || o.objective == "length" || o.objective == "weighted" || o.objective == "iqga" ||
                o.objective == "hswoa",
            "--objective", "unknown objective '" + o.objective + "' (cells, length, weighted, iqga or hswoa)");
    require(o.encoding == "line" || o.encoding == "free" || o.encoding == "chain", "--encoding",
            "unknown encoding '" + o.encoding + "' (line, free or chain)");
    require(o.connector == "repair" || o.connector == "penalty", "--connector",
            "unknown connector '" + o.connector + "' (penalty or repair)");
    require(o.encoding != "chain" || o.connector == "repair", "--connector",
            "chains need no connector: every operator keeps them legal");
    require(o.waypoints >= 1 && o.waypoints <= 1000, "--waypoints", "must be in [1, 1000]");
    const bool walks = o.init == "walk" || o.init == "rules";
    require(o.init.empty() || o.init == "uniform" || walks, "--init",
            "expected uniform, walk or rules, got '" + o.init + "'");
    require(!walks || o.encoding == "line" || o.encoding == "free", "--init " + o.init,
            "only for the line and free encodings (chains always start from walks)");
    require(!walks || o.algo.rfind("nlopt:", 0) != 0, "--init " + o.init,
            "NLopt algorithms start from one uniform point");
    require(additive || (o.algo != "exact" && !o.oracle), o.algo == "exact" ? "--algo exact" : "--oracle",
            "the iqga objective is not a sum of step and turn costs, so it has no exact oracle");
    require(box_algorithm || o.params.empty(), "--param", o.algo + " takes no parameters");
    require(!o.weights || o.objective == "weighted", "--weights", "only for --objective weighted");
    require(!o.lambda || o.objective == "hswoa", "--lambda", "only for --objective hswoa");
    require(o.seed >= 0, "--seed", "must be >= 0, got " + std::to_string(o.seed));
    require(o.inflate >= 0 && o.inflate <= 1000, "--inflate", "must be in [0, 1000], got " + std::to_string(o.inflate));
}

namespace {
std::shared_ptr<const GridMap> load_for(const PathOptions& o) {
    check_path_options(o);
    GridMap loaded = read_map(o.map);
    if (o.inflate > 0) loaded = loaded.inflated(static_cast<int>(o.inflate));
    return std::make_shared<const GridMap>(std::move(loaded));
}
}  // namespace

PathRun plan_path(const PathOptions& o) {
    return dispatch_objective(o, load_for(o));
}

int path_command(const PathOptions& o, std::ostream& out) {
    const auto map = load_for(o);
    const PathRun run = dispatch_objective(o, map);
    const Cell start = parse_cell(o.start, "--start"), goal = parse_cell(o.goal, "--goal");
    const PathMetrics m = metrics(run.path);

    std::optional<double> gap;
    if (run.optimum && run.feasible) {
        // The oracle sums step and turn costs in another order than the metrics do: values that
        // agree to 1e-9 (relative) are the same optimum, and the gap is exactly 0.
        const double scale = std::max(1.0, std::abs(*run.optimum));
        gap = std::abs(run.value - *run.optimum) <= 1e-9 * scale ? 0.0 : (run.value - *run.optimum) / *run.optimum;
    }
    // The pictures first: they are the only output that can fail now. Both are drawn to temporary
    // files and renamed only when both succeeded, so a failure leaves no picture and prints nothing.
    std::vector<std::pair<std::string, PictureFormat>> pictures;
    if (!o.svg.empty()) pictures.emplace_back(o.svg, PictureFormat::svg);
    if (!o.png.empty()) pictures.emplace_back(o.png, PictureFormat::png);
    std::error_code ec;
    try {
        for (const auto& [file, format] : pictures)
            draw_grid(*map, start, goal, run.feasible ? &run.path : nullptr, o.oracle ? &run.optimal_path : nullptr,
                      file + ".part", file, format);
        for (const auto& [file, format] : pictures) {
            std::filesystem::rename(file + ".part", file, ec);
            if (ec) throw InputError(file + ": cannot write the picture: " + ec.message());
        }
    } catch (...) {
        for (const auto& [file, format] : pictures) std::filesystem::remove(file + ".part", ec);
        throw;
    }

    if (o.json) {
        std::string text = fmt::format(
            "{{\"algo\": {}, \"objective\": {}, \"encoding\": {}, \"seed\": {}, \"feasible\": {}, \"path\": {}, "
            "\"metrics\": {{\"cells\": {}, \"length\": {}, \"turns\": {}, \"turn_angle_deg\": {}, \"angle_penalty\": "
            "{}}}, "
            "\"objective_value\": {}, \"evaluations\": {}, \"iterations\": {}, \"wall_ms\": {}, \"history\": {}",
            json_string(o.algo), json_string(o.objective), json_string(run.encoding), o.seed,
            run.feasible ? "true" : "false", json_path(run.path), m.cells, json_number(m.length), m.turns,
            m.turn_angle_deg, m.angle_penalty, run.feasible ? json_number(run.value) : "null", run.evaluations,
            run.iterations, json_number(run.wall_ms), json_array(run.history));
        if (o.oracle)
            text += fmt::format(", \"optimum\": {{\"objective_value\": {}, \"gap\": {}}}",
                                run.optimum ? json_number(*run.optimum) : "null", gap ? json_number(*gap) : "null");
        out << text << "}\n";
        return 0;
    }
    std::string text = fmt::format(
        "algo            {}\nobjective       {}\nencoding        {}\nseed            {}\n"
        "feasible        {}\n",
        o.algo, o.objective, run.encoding, o.seed, run.feasible ? "yes" : "no");
    if (run.feasible)
        text += fmt::format(
            "objective_value {:.10g}\ncells           {}\nlength          {:.10g}\nturns           {}\n"
            "turn_angle_deg  {}\nangle_penalty   {}\n",
            run.value, m.cells, m.length, m.turns, m.turn_angle_deg, m.angle_penalty);
    if (o.oracle)
        text += fmt::format("optimum         {:.10g}\ngap             {}\n", *run.optimum,
                            gap ? fmt::format("{:.6g}", *gap) : "-");
    text += fmt::format("evaluations     {}\niterations      {}\nwall_ms         {:.3f}\npath            {}\n",
                        run.evaluations, run.iterations, run.wall_ms, json_path(run.path));
    out << text;
    return 0;
}

int scen_command(const ScenOptions& o, std::ostream& out) {
    const auto entries = read_scenario(o.file);
    const std::filesystem::path dir =
        o.map_dir.empty() ? std::filesystem::path(o.file).parent_path() : std::filesystem::path(o.map_dir);
    std::map<std::string, GridMap> maps;
    AStar astar;
    std::size_t differ = 0;
    double max_diff = 0.0, seconds = 0.0;
    for (const auto& e : entries) {
        const std::string where = o.file + ":" + std::to_string(e.line);
        auto it = maps.find(e.map);
        if (it == maps.end()) {
            try {
                it = maps.emplace(e.map, read_map((dir / e.map).string())).first;
            } catch (const InputError& error) {
                throw InputError(where + ": " + error.what());
            }
        }
        const GridMap& map = it->second;
        require(map.width() == e.width && map.height() == e.height, where,
                fmt::format("the scenario says {}x{}, but {} is {}x{}", e.width, e.height, e.map, map.width(),
                            map.height()));
        require(map.free(e.start), where, "the start " + to_string(e.start) + " is blocked on " + e.map);
        require(map.free(e.goal), where, "the goal " + to_string(e.goal) + " is blocked on " + e.map);
        const auto t0 = Clock::now();
        const double length = astar.search(map, e.start, e.goal);
        seconds += std::chrono::duration<double>(Clock::now() - t0).count();
        const double diff = length < 0 ? std::numeric_limits<double>::infinity() : std::abs(length - e.optimal);
        if (diff > 1e-6) ++differ;
        max_diff = std::max(max_diff, diff);
    }
    const double rate = seconds > 0 ? static_cast<double>(astar.expansions()) / seconds : 0.0;
    if (o.json)
        out << fmt::format("{{\"checked\": {}, \"differ\": {}, \"max_diff\": {}, \"expansions_per_s\": {}}}\n",
                           entries.size(), differ, json_number(max_diff), json_number(rate));
    else
        out << fmt::format(
            "checked           {}\ndiffer            {} (by more than 1e-6)\nmax_diff          {:.3g}\n"
            "expansions_per_s  {:.4g}\n",
            entries.size(), differ, max_diff, rate);
    return 0;
}

}  // namespace pride::cli

#include "experiment/campaign/run_one.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/json.hpp"
#include "engine/registry.hpp"
#include "problems/continuous/cec/suites.hpp"

namespace pride::campaign {

using engine::AlgorithmEntry;
using engine::algorithms;
using engine::Budget;
using engine::Front;
using engine::front_json;
using engine::FrontQuality;
using engine::GridSpec;
using engine::json_array;
using engine::json_cells;
using engine::json_integers;
using engine::json_number;
using engine::json_path_metrics;
using engine::json_polyline;
using engine::json_string;
using engine::Problem;
using engine::quality;
using engine::run;
using engine::RunResult;

Budget problem_budget(const Budget& budget, const CampaignProblem& p) {
    Budget b = budget;
    if (p.evaluations) b.evaluations = p.evaluations;
    return b;
}

namespace {
/// A trace as RunRecord keeps it: [e0, f0, e1, f1, ...], null for +inf.
std::string json_trace(const std::vector<TracePoint>& trace) {
    std::string text = "[";
    for (const auto& t : trace)
        text += fmt::format("{}{}, {}", text.size() > 1 ? ", " : "", t.evaluations, json_number(t.best));
    return text + "]";
}
}  // namespace

namespace {

/// A multi-objective run as stored: its value is the hypervolume gap 1 - HV / HV_ref (0 for a set
/// as good as the reference front; engine/multiobjective.hpp's normalisation), its solution the
/// whole front with its indicators: {"objectives": [...], "hypervolume_ratio", "igd_plus",
/// "exact_found" (grids), "front": [{"f": [...], "x": [...]} or, on grids, {"f", "legal", "path"}]}.
RunRecord run_multiobjective(const CampaignProblem& p, const CampaignAlgorithm& a, const Budget& budget,
                             std::int64_t seed, RunRecord r) {
    const Problem& problem = *p.problem;
    const RunResult result = run(a.spec, problem, problem_budget(budget, p), static_cast<std::uint64_t>(seed));
    const Front& front = *result.front;
    const FrontQuality q = quality(problem, front.f, front.violation);
    const bool grid = problem.is_grid();
    std::string names;
    for (const auto& n : problem.objective_names()) names += (names.empty() ? "" : ", ") + json_string(n);
    r.solution = fmt::format(
        "{{\"objectives\": [{}], \"hypervolume_ratio\": {}, \"igd_plus\": {}, \"exact_found\": {}, \"front\": {}}}",
        names, json_number(q.hypervolume_ratio), json_number(q.igd_plus),
        q.exact_found ? std::to_string(*q.exact_found) : std::string("null"), front_json(front));
    r.best = 1.0 - q.hypervolume_ratio;
    // Feasible: a point found (on grids, a legal path; with constraints, a feasible point).
    r.feasible = grid ? std::any_of(front.feasible.begin(), front.feasible.end(), [](char c) { return c != 0; })
                 : !front.violation.empty() ? std::count(front.violation.begin(), front.violation.end(), 0.0) > 0
                                            : front.f.cols() > 0;
    r.evaluations = result.evaluations;
    r.iterations = result.iterations;
    r.wall_ms = result.wall_ms;
    // One point of history: the run's value after its last iteration.
    r.history = json_array({r.best});
    r.history_evaluations = json_integers({result.evaluations});
    if (grid) r.encoding = std::get<GridSpec>(p.spec).encoding.empty() ? "line" : std::get<GridSpec>(p.spec).encoding;
    return r;
}

}  // namespace

RunRecord run_one(const CampaignProblem& p, const CampaignAlgorithm& a, const Budget& budget, std::int64_t seed) {
    RunRecord r;
    r.problem = p.id;
    r.algorithm = a.id;
    r.seed = seed;
    if (p.is_multiobjective()) return run_multiobjective(p, a, budget, seed, std::move(r));
    const std::optional<double> optimum = p.problem->optimum_value();
    Budget with_targets = problem_budget(budget, p);
    if (optimum)
        for (const double precision : coco_precisions()) with_targets.recorded_targets.push_back(*optimum + precision);
    // A whole-map planner has no evaluation budget: its work (A*'s expansions, Theta*'s) is not
    // bounded by the campaign's, so no budget is recorded beside it.
    const AlgorithmEntry* entry = algorithms().find(a.spec.name);
    if (!entry || entry->evaluates()) r.max_evaluations = with_targets.evaluations;
    if (optimum && with_targets.evaluations)
        with_targets.recorded_evaluations = continuous::cec::recorded_evaluations(
            *with_targets.evaluations, static_cast<std::int64_t>(std::max<std::size_t>(p.problem->dimension(), 1)));
    const RunResult result = run(a.spec, *p.problem, with_targets, static_cast<std::uint64_t>(seed));
    if (result.grid) {
        r.feasible = result.grid->feasible;
        r.best = r.feasible ? result.grid->value : std::numeric_limits<double>::infinity();
        // The 8-connected optimum is no optimum of a polyline (shorter ones exist): a polyline
        // planner's run records none, so that reports compare it by its path gaps instead.
        if (!entry || !entry->plans_polylines) r.optimum = result.grid->optimum;
        r.solution = json_cells(result.grid->path);
        r.encoding = result.grid->encoding;
        if (r.feasible) {
            const auto* g = std::get_if<GridSpec>(&p.spec);
            r.path_metrics =
                json_path_metrics(*result.grid, g && g->path_gaps, g && g->map ? g->map->frame() : std::nullopt);
            if (result.grid->path.empty()) r.polyline = json_polyline(result.grid->polyline);
        }
    } else {
        r.best = result.best_f;
        // With constraints, best_f is the least violating point's f while no point is feasible:
        // feasible only by the violation, which the store keeps beside it.
        r.feasible = std::isfinite(result.best_f) && (!result.best_violation || *result.best_violation == 0.0);
        r.best_violation = result.best_violation;
        r.first_feasible = result.first_feasible;
        r.solution = json_array(result.best_x);
    }
    r.evaluations = result.evaluations;
    r.iterations = result.iterations;
    r.wall_ms = result.wall_ms;
    r.history = json_array(result.history);
    r.history_evaluations = json_integers(result.history_evaluations);
    r.trace_targets = json_trace(result.trace_targets);
    r.trace_evaluations = json_trace(result.trace_evaluations);
    r.checkpoints = json_trace(result.checkpoints);
    if (optimum) {
        r.target_hits = "[";
        for (std::size_t k = 0; k < coco_precisions().size(); ++k)
            r.target_hits += (k ? ", " : "") + (k < result.target_hits.size() ? std::to_string(result.target_hits[k])
                                                                              : std::string("null"));
        r.target_hits += "]";
    }
    return r;
}

}  // namespace pride::campaign

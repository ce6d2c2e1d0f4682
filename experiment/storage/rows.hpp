#pragma once
// What a store's writer takes: the campaign, its problems and algorithms as the rows it records
// (built by the campaign: campaign/identity.hpp, store_rows), and each finished run. The store
// knows nothing of how they were made.
#include <cstdint>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

namespace pride::storage {

/// The key of a run in a store: (problem id, algorithm id, seed).
using RunKey = std::tuple<std::string, std::string, std::int64_t>;

/// One finished run, as stored.
struct RunRecord {
    std::string problem, algorithm;
    std::int64_t seed = 0;
    bool feasible = true;
    double best = 0.0;
    std::int64_t evaluations = 0, iterations = 0;
    double wall_ms = 0.0;
    std::optional<double> optimum;  // grid problems: the exact optimum (additive objectives)
    std::string solution;           // JSON: the best point, or the path as [[x,y],...]
    std::string history;            // JSON: best value after each iteration
    std::string history_evaluations;
    // JSON: one entry per coco_precisions() value, the evaluations after which best <= f_opt +
    // precision first held, or null; "[]" for problems without a known optimum.
    std::string target_hits = "[]";
    std::string encoding;  // grid runs: what the run planned on (line, free, chain; none for A*, exact)
    // JSON [e0, f0, e1, f1, ...]: (evaluations, best so far) at COCO's target triggers and at its
    // evaluation triggers (RunResult::trace_targets, trace_evaluations), null for +inf.
    std::string trace_targets = "[]", trace_evaluations = "[]";
    // The run's evaluation budget (MaxFES; empty under an iteration budget alone) and, for problems
    // with a known optimum, JSON [e0, f0, e1, f1, ...]: the best value so far after each of the
    // CEC reports' checkpoints of that budget (problems/continuous/cec/suites.hpp: recorded_evaluations).
    std::optional<std::int64_t> max_evaluations;
    std::string checkpoints = "[]";
    // Grid runs that found a path: its metrics (engine::json_path_metrics; with the problem's
    // path_gaps, its gaps too), and, for a polyline planner (Theta*, the any-angle path), whose
    // `solution` holds no cells, its polyline as [[x, y], ...]. Empty: NULL in the store.
    std::string path_metrics, polyline;
    // Problems with constraints (RunResult::best_violation, first_feasible): the best point's
    // violation, 0 when it is feasible (`best` is then the best feasible f, else the least violating
    // point's f and `feasible` is false), and the evaluation that first found a feasible point
    // (empty: none). Empty for problems without constraints: NULL in the store.
    std::optional<double> best_violation;
    std::optional<std::int64_t> first_feasible;
};

/// A problem as recorded, for reports and plots (a map's path made absolute).
struct ProblemRow {
    std::string id;
    std::string type;             // "grid", the catalog function's name, or a user problem's name
    std::int64_t dim = 0;         // grids: 2, the plane
    std::string map;              // absolute; empty without a map file
    std::string start, goal;      // grids: "x,y"
    std::int64_t instance = 0;    // 0 for a multi-objective problem, which has none
    std::optional<double> f_opt;  // the known optimum; none for a multi-objective problem
    std::string suite;            // the catalog's suite ("bbob", "cec2017", ...) or empty
    std::int64_t fid = 0;         // its number in that suite
    std::string definition;       // campaign::problem_definition
    std::string digest;           // campaign::problem_digest
};

/// An algorithm as recorded.
struct AlgorithmRow {
    std::string id;
    std::string type;          // its registered name
    bool evaluates = true;     // its runs count evaluations (a whole-map planner's do not)
    bool reproducible = true;  // one seed gives one result
    std::string definition;    // campaign::algorithm_definition
};

/// A campaign as recorded: its name and text (a store never mixes two campaigns), its report
/// target, the target precisions its runs record (JSON), its budget's definition and its rows.
struct CampaignRows {
    std::string name, text;
    std::optional<double> target, target_precision;
    std::string precisions;
    std::string budget;
    std::vector<ProblemRow> problems;
    std::vector<AlgorithmRow> algorithms;
};

}  // namespace pride::storage

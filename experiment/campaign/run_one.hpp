#pragma once
// One run of a prepared campaign, as the store records it.
#include <cstdint>
#include <optional>
#include <string>

#include "experiment/campaign/campaign.hpp"

namespace pride::campaign {

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
};

/// Runs one (problem, algorithm, seed) of a prepared campaign; the same inputs give the same
/// record (bar wall_ms), whatever thread or rank runs it.
RunRecord run_one(const CampaignProblem& p, const CampaignAlgorithm& a, const engine::Budget& budget,
                  std::int64_t seed);

/// The budget of one problem's runs: the campaign's, with its evaluations per dimension resolved.
engine::Budget problem_budget(const engine::Budget& budget, const CampaignProblem& p);

}  // namespace pride::campaign

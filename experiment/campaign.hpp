#pragma once
// Campaigns as data: problems, algorithms, seeds and a budget, built from structs (the TOML file
// of `pride bench` is one front end: campaign_toml.hpp) and run on a thread pool or over MPI ranks
// into an SQLite store (store.hpp) that commits finished runs as they come, so an interrupted
// campaign resumes with no run lost or run twice.
#include <atomic>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/run.hpp"
#include "engine/specs.hpp"

namespace pride::engine {

struct CampaignProblem {
    std::string id;
    ProblemSpec spec;      // ContinuousSpec or GridSpec; a grid's map may be left empty...
    std::string map_file;  // ... and named here (read once per (file, inflate) by prepare())
    std::int64_t inflate = 0;
    int line = 0;                            // where it stands in the campaign file (0: not from a file)
    std::string suite;                       // "bbob", "classic" when it came from a suite, else empty
    std::shared_ptr<const Problem> problem;  // built by prepare()
    // The evaluations of each run when the campaign budgets per dimension (set by prepare()).
    std::optional<std::int64_t> evaluations;
};

/// COCO's 51 target precisions: a continuous problem with a known optimum f_opt records in every
/// run the evaluations after which the best value first reached f_opt + 10^k, k = 2, 1.8, ...,
/// -8 (Hansen et al. 2022, "COCO: performance assessment", the runtime ECDFs' targets; cocopp's
/// 10**np.arange(2, -8.1, -0.2)).
inline const std::vector<double>& coco_precisions() {
    static const std::vector<double> p = [] {
        std::vector<double> v;
        for (int k = 0; k <= 50; ++k) v.push_back(std::pow(10.0, (10 - k) / 5.0));
        return v;
    }();
    return p;
}

struct CampaignAlgorithm {
    std::string id;
    AlgorithmSpec spec;
    int line = 0;
};

struct Campaign {
    std::string file;  // for messages; empty when built in code
    std::string text;  // stored with the results, so a store never mixes two campaigns; empty:
                       // prepare() writes a canonical description
    std::string name;
    std::int64_t seeds = 0;  // seeds 1..seeds
    Budget budget;           // evaluations and/or iterations
    // Or evaluations per dimension: each continuous problem's runs get this times its dimension
    // (COCO's budgets; excludes budget.evaluations; grids have no dimension and refuse it).
    std::optional<std::int64_t> evaluations_per_dim;
    std::optional<double> target;  // a threshold for reports (evaluations to reach it); runs do not stop there
    // The same as a precision: the threshold f_opt + precision of each problem with a known
    // optimum (the other problems have none). At most one of target and target_precision.
    std::optional<double> target_precision;
    std::vector<CampaignProblem> problems;
    std::vector<CampaignAlgorithm> algorithms;
};

/// What identifies a campaign's runs beside their seeds (a campaign grows by seeds, problems and
/// algorithms; these must not change under a stored id): its budget, each problem's definition
/// (function, dimension and instance, or map, ends and grid settings) and each algorithm's
/// (registered name and parameters), as canonical one-line texts.
std::string budget_definition(const Campaign& c);
std::string problem_definition(const CampaignProblem& p);
std::string algorithm_definition(const CampaignAlgorithm& a);

/// Checks the campaign and builds every problem once (each map read once): a missing or duplicate
/// id, a bad problem, an unknown algorithm, a bad parameter, an algorithm that cannot run on a
/// problem, or a run that would not fit in memory is an InputError naming the file and line (or
/// the id), so a campaign that starts will not fail half-way on its input.
void prepare(Campaign& campaign);

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
};

/// Runs one (problem, algorithm, seed) of a prepared campaign; the same inputs give the same
/// record (bar wall_ms), whatever thread or rank runs it.
RunRecord run_one(const CampaignProblem& p, const CampaignAlgorithm& a, const Budget& budget, std::int64_t seed);

struct BenchSummary {
    std::size_t stored = 0;   // runs stored by this call
    std::size_t already = 0;  // runs of the campaign the store held before
    std::size_t total = 0;    // runs of the campaign
    std::size_t others = 0;   // runs left to another pride bench that is running them on the same store
    int ranks = 1;            // MPI ranks (1: threads only; 0: an MPI rank other than 0, which reports nothing)
};

/// Called from the storing thread after each stored batch: (runs in the store, runs in all, seconds).
using Progress = std::function<void(std::size_t done, std::size_t total, double seconds)>;

/// A campaign stopped by a signal (SIGINT, SIGTERM): what the store holds, and which signal.
struct Interrupted : std::runtime_error {
    Interrupted(std::size_t in_store, std::size_t total, int signal)
        : std::runtime_error("interrupted"), in_store(in_store), total(total), signal(signal) {}
    std::size_t in_store, total;
    int signal;
};

/// How a caller stops a campaign: `signal` is polled (every few milliseconds) by the storing
/// thread; once it is non-zero, the finished runs are committed, the claims of the running ones
/// dropped, the store closed, and `on_stop` called with what the store holds. `on_stop` may end
/// the process (the command line does, abandoning the running runs); when it returns, the
/// running runs are waited for (not stored) and Interrupted is thrown.
struct Stop {
    const std::atomic<int>* signal = nullptr;
    std::function<void(const Interrupted&)> on_stop;
};

/// Runs every (problem, algorithm, seed) not yet in `store` on `jobs` threads (or, under mpirun
/// in an MPI build, over the ranks) and commits finished runs in batches. Several processes may
/// run one campaign on one store at once: each takes runs the others have not (claims in the
/// store). The campaign must be prepared. Store errors (a read-only or full file system, a store
/// deleted meanwhile) are InputErrors naming the file.
BenchSummary run_campaign(const Campaign& campaign, const std::string& store, std::int64_t jobs,
                          const Progress& progress = {}, const Stop& stop = {});

/// The number of processes mpirun (Open MPI, or a PMI launcher) started, or 1 outside mpirun.
int launched_ranks();

}  // namespace pride::engine

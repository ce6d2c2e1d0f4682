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

#include "engine/multiobjective.hpp"
#include "engine/run.hpp"
#include "engine/specs.hpp"

namespace pride::engine {

struct CampaignProblem {
    std::string id;
    ProblemSpec spec;      // ContinuousSpec or GridSpec; a grid's map may be left empty...
    std::string map_file;  // ... and named here (read once per (file, inflate) by prepare())
    std::int64_t inflate = 0;
    bool unknown_free = false;               // a map_server map's unknown cells read as free (grid::MapReadOptions)
    bool path_gaps = false;                  // each run records its gaps to the shortest grid and any-angle lengths
    int line = 0;                            // where it stands in the campaign file (0: not from a file)
    std::string suite;                       // "bbob", "classic" when it came from a suite, else empty
    std::shared_ptr<const Problem> problem;  // built by prepare()
    // The evaluations of each run when the campaign budgets per dimension (set by prepare()).
    std::optional<std::int64_t> evaluations;
    std::string digest;  // problem_digest(), set by prepare()
    // A problem of several objectives (engine/multiobjective.hpp) when set: its objectives (a
    // grid's criteria, "length,turns,clearance"; a catalog problem's M, "3", or "" for the
    // default), `spec` holding the rest (a ContinuousSpec naming zdt1..dtlz7 with its dim, 0 for
    // the paper's; a GridSpec with the map, ends and encoding). prepare() builds `multiobjective`
    // instead of `problem`; each run stores its front and, as its value, the hypervolume gap.
    std::optional<std::string> objectives;
    std::shared_ptr<const MoProblem> multiobjective;
    bool is_multiobjective() const { return objectives.has_value(); }
    /// The dimension of the box its algorithms search (once prepared).
    std::size_t dimension() const { return multiobjective ? multiobjective->dimension() : problem->dimension(); }
};

/// A multi-objective problem's spec from its campaign entry (the map of a grid as loaded).
MoProblemSpec multiobjective_spec(const CampaignProblem& p);

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

/// What a store records of a prepared problem beside its definition, so that a resume or a merge
/// on another problem under the same id is refused: "map sha256:HEX; settings sha256:HEX" for a
/// grid (the map's size and cells as the runs see them, inflated; not its path, so a map moved
/// or given in code is the same map), "settings sha256:HEX" otherwise. The settings are every
/// field that defines the problem: a grid's start, goal, objective, weights, lambda, inflate,
/// corner cutting, encoding, connector, init and waypoints; a function's name, dimension and
/// instance; a Python function's id, bounds and f_opt. Python code (a function, a path objective,
/// a step cost) cannot be identified: only that there is one.
std::string problem_digest(const CampaignProblem& p);

/// What differs between two problem digests, for messages: "has another map than the stored
/// one (...)" or "has other settings than the stored ones (...)".
std::string digest_difference(const std::string& stored, const std::string& now);

/// A name as a store keeps it (the campaign's name, problem and algorithm ids): an empty one, a
/// NUL (SQLite would cut the name there) or another control character (printed raw on a
/// terminal) gives what is wrong, else an empty string.
inline constexpr std::size_t kMaxNameBytes = 100;
std::string name_problem(const std::string& name);

/// At most this many problems in one campaign (COCO's largest suites have a few thousand): a short
/// instance list or suite must not start hours of building (each problem takes about 12 kB and
/// 80 us to build before its rotation: a 6.9 MB file asked for a million).
inline constexpr std::size_t max_campaign_problems = 100'000;

/// The memory a problem takes once prepare() has built it, estimated from its spec before any of
/// it is: a built problem's tables (about 11 kB measured; 16 kB counted with its CampaignProblem
/// and id), a continuous instance's vectors and rotation (8 dim and 2 dim^2 doubles); a grid's
/// map is counted once per file by load_map.
double problem_memory(const ProblemSpec& spec);

/// The memory one run of a campaign takes in the lists made before any starts (its task, its key
/// with both ids, its place in the set of stored keys), for ids of these lengths.
double run_list_memory(std::size_t problem_id_length, std::size_t algorithm_id_length);

/// The CEC suites' rules where the campaign leaves them open (docs/campaigns.md, "The CEC
/// suites"; prepare() applies them first, data-free): without an evaluation budget (evaluations
/// or evaluations_per_dim), each problem of a CEC suite (cec2017-fN, cec2022-fN, from a [[suite]]
/// or a [[problem]]) runs its suite's MaxFES (CampaignProblem::evaluations; with iterations too,
/// whichever ends first), and a campaign without any budget must hold CEC problems only; without
/// seeds (0), a campaign of one CEC suite's problems runs the competition's number of runs (51
/// for cec2017, 30 for cec2022, seeds 1..N), any other is refused. InputError naming the file.
void apply_suite_rules(Campaign& campaign);

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

#pragma once
// A campaign store (the SQLite file `pride bench` writes, docs/campaigns.md) read back and checked:
// every value the reports and exports use, typed. A store that cannot be used is bad input, never
// an internal error: InputError "STORE: not a campaign store (...)" for a file that is none, and
// DamagedStore "STORE: damaged store: WHERE: WHAT" for one whose tables, columns or values are not
// what pride bench writes. It lives beside the schema, not in report/, as the campaign and pride
// merge check a store with it (check_store) before they trust one, and report/ reads with it.
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "experiment/storage/published.hpp"
#include "framework/coco_trace.hpp"
#include "framework/error.hpp"

struct sqlite3;

namespace pride::storage {

/// Refuses, in one line, a store beside which SQLite's own files (PATH-journal, PATH-wal,
/// PATH-shm) exist as anything but regular files (after links): SQLite opens them without
/// looking, and waits forever on a FIFO there, or writes into a device. Every opening of a store
/// (read_only_uri, the writer, merge) calls it first. InputError "PATH-journal: not a regular
/// file (a FIFO): ...".
void check_store_files(const std::string& path);

/// InputError unless `path` is a regular file to read a store from: "PATH: no such store", or
/// "PATH: not a regular file (a FIFO): ..." for what is there but is no file (before: a FIFO was
/// "no such store").
void require_store_file(const std::string& path);

/// The SQLite URI that opens the store at `path` for reading without writing anything beside it:
/// "file:PATH?mode=ro", or, where that cannot read it (a read-only folder or file system, where a
/// store in WAL mode cannot get its -shm file), "file:PATH?immutable=1" when nothing of the store
/// is outside the file (no -wal or -journal file with content, as after its last writer closed
/// it). InputError "PATH: cannot read the store (REASON)" otherwise, saying what to do.
std::string read_only_uri(const std::string& path);

/// The store at `path` opened as read_only_uri says (the caller closes it), checked readable.
sqlite3* open_read_only(const std::string& path);

/// A store whose contents are not what pride bench writes (missing tables or columns, values of
/// the wrong kind, malformed JSON); an InputError, so the command line exits 2.
class DamagedStore : public InputError {
  public:
    DamagedStore(const std::string& store, const std::string& what) : InputError(store + ": damaged store: " + what) {}
};

struct StoredRun {
    std::string problem, algorithm;
    std::int64_t seed = 0;
    std::optional<double> best;  // empty: no feasible value found
    std::int64_t evaluations = 0;
    std::optional<std::int64_t> iterations;  // empty for a store without the column
    double wall_ms = 0;
    std::optional<double> optimum;  // grid problems: the exact optimum
    // A box run's best point (its solution; NaN where the store has null, a coordinate not
    // finite); empty for grid runs (a path), multi-objective runs (a front) and published runs.
    std::vector<double> best_x;
    // The best value after each iteration (+inf before the first feasible one) and, where
    // recorded, the evaluations spent by then (empty, or one per history value).
    std::vector<double> history;
    std::vector<std::int64_t> history_evaluations;
    // One entry per precision of CampaignStore::precisions, in its order: the evaluations after
    // which best - f_opt <= precision first held, empty where never. Empty when the run records
    // no hits (column absent, NULL or []).
    std::vector<std::optional<std::int64_t>> target_hits;
    std::string encoding;  // grid runs: what the run planned on; empty for boxes and older stores
    // COCO's trace (framework/coco_trace.hpp): (evaluations, best so far, +inf before a finite
    // value) at its target and at its evaluation triggers; empty for runs stored before it. On a
    // constrained problem the best of COCO's logged value (framework/run_state.hpp), ending at
    // the run's last evaluation.
    std::vector<TracePoint> trace_targets, trace_evaluations;
    // The run's evaluation budget (MaxFES), and (evaluations, best so far) at the CEC reports'
    // checkpoints of it (experiment/report/cec.hpp), for problems with a known f_opt: empty for runs
    // stored before store schema 4 and for runs under an iteration budget alone.
    std::optional<std::int64_t> max_evaluations;
    // A multi-objective run (its solution is a front, an object, where other runs store a point
    // or a path): its value is the hypervolume gap (experiment/campaign.hpp).
    bool front = false;
    std::optional<double> igd_plus;           // a front's IGD+ (normalised as the hypervolume gap)
    std::optional<std::int64_t> exact_found;  // a grid front's points of the exact front
    std::string front_json;                   // the front as stored (engine::front_json), or empty
    std::vector<TracePoint> checkpoints;
    // A grid run's path metrics (runs.path_metrics, store schema 5: problems/grid/polyline.hpp, in
    // kPathMetricNames' order, each empty where the JSON has null or lacks it); empty for other runs
    // and runs stored before.
    std::vector<std::optional<double>> path_metrics;
    // A constrained problem's run (runs.best_violation, first_feasible, store schema 6): its best
    // point's violation (0: feasible; +inf when no point had a finite one) and the evaluation that
    // first found a feasible point (empty: none). A run whose best is infeasible has no `best` (no
    // feasible value: every table and analysis of values leaves it out, as a grid run without a
    // path) and keeps its least violating point's f in `infeasible_f`. All empty for problems
    // without constraints and for runs stored before.
    std::optional<double> best_violation;
    std::optional<std::int64_t> first_feasible;
    std::optional<double> infeasible_f;
};

/// The keys of runs.path_metrics the report reads, in StoredRun::path_metrics' order. length_m,
/// the length in metres, is there only for maps with a world frame (and runs stored since).
inline constexpr const char* kPathMetricNames[] = {
    "length",        "turns",          "total_turn_deg", "angle_over_length", "max_curvature",
    "min_clearance", "mean_clearance", "grid_gap",       "any_angle_gap",     "length_m"};
/// The index of length_m in kPathMetricNames.
inline constexpr std::size_t kPathLengthMetres = 9;

struct StoredProblem {
    std::string id;
    std::int64_t dim = 0;
    std::optional<std::string> function;  // the registered function name (bbob-f3, rastrigin, grid)
    std::int64_t instance = 0;            // 0: the function as defined; bbob: COCO's instance id >= 1
    std::optional<double> f_opt;          // the known optimum value
    std::optional<std::string> suite;     // bbob, bbob-constrained, classic, ...
    std::optional<std::int64_t> fid;      // the function's number in its suite (bbob f1..f24: 1..24)
};

struct CampaignStore {
    std::string name;
    std::optional<double> target;            // [budget] target; stores from before targets have none
    std::optional<double> target_precision;  // [budget] precision: f_opt + it, per problem
    // The target precisions (f - f_opt) the runs' target_hits refer to; empty optional for a
    // campaign that records none (NULL, or a store from before them).
    std::optional<std::vector<double>> precisions;
    // In the campaign's order; empty optional for stores from before the problems table.
    std::optional<std::vector<StoredProblem>> problems;
    std::vector<StoredRun> runs;  // ordered by problem, algorithm, seed
    // The ids of the campaign's algorithms that evaluate no objective (whole-map planners: A*,
    // exact), from its algorithms table; empty for stores from before it.
    std::set<std::string> whole_map_algorithms;
    // The ids of those registered as not reproducible (AlgorithmEntry::reproducible: OMPL's
    // planners): a run of theirs found in two stores is the same run by its definition.
    std::set<std::string> unreproducible_algorithms;
    // The published algorithms (published.hpp, store schema 7: runs read from their authors' files,
    // never run by pride), by id, with their provenance; empty for stores without.
    std::map<std::string, PublishedSource> published;
};

/// Reads and checks the whole store at `path` (read-only). Throws InputError when the file is
/// missing or not a campaign store, DamagedStore when its contents are damaged.
CampaignStore read_store(const std::string& path);

/// The checks of read_store (the very same code, the runs read and dropped one by one) followed by
/// SQLite's quick_check of every page, for what trusts a store before writing to it or from it
/// (pride bench, Python's Campaign.run, pride merge): the same InputError or DamagedStore as
/// read_store. An SQLite file without any table (a store being created) passes.
void check_store(const std::string& path);

}  // namespace pride::storage

#pragma once
// The version of the campaign store's schema, kept in SQLite's user_version: pride bench writes
// it when it creates or migrates a store (adding the columns a store from before lacks), and
// pride bench, report and export refuse a store that a newer pride wrote, rather than misread it.
//   0: stores from before the version was recorded (migrated on the next pride bench)
//   1: runs.encoding, campaign.target_precision, campaign.budget and the problems' and
//      algorithms' definitions
//   2: runs.trace_targets and runs.trace_evaluations, COCO's trace of each run
//   3: problems.digest, SHA-256 digests of each problem's map and settings; NULL in a
//      store migrated from before, filled from the campaign of its first resume
//   4: runs.max_evaluations and runs.checkpoints, each run's evaluation budget and its best values
//      at the CEC reports' checkpoints; NULL and '[]' for runs stored before
//   5: runs.path_metrics and runs.polyline, every grid path's metrics and a polyline planner's
//      polyline, NULL for other runs and runs stored before; algorithms.reproducible,
//      0 for algorithms whose runs are compared by definition (OMPL's), 1 before
//   6: runs.best_violation and runs.first_feasible, a constrained problem's run: its best point's
//      violation (0: feasible) and the evaluation that first found a feasible point; NULL for
//      problems without constraints and for runs stored before
//   7: table published, the provenance of published runs (published.hpp: source, SHA-256,
//      citation, format); empty in a store migrated from before
// Keys added inside a JSON column need no version: runs.path_metrics' length_m, min_clearance_m
// and mean_clearance_m (maps with a world frame) are absent from the runs stored before, which
// the report tells apart (reader.hpp: kPathMetricNames).
namespace pride::storage {

inline constexpr int schema_version = 7;

}  // namespace pride::storage

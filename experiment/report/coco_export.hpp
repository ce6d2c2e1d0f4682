#pragma once
// A campaign store as COCO's data files (`pride export STORE --coco DIR`), which cocopp
// post-processes as it does COCO's own experiments (docs/analysis.md). Written as COCO's bbob
// logger writes them (numbbo/coco-experiment, src/logger_bbob.c, data format "bbob-new2"):
//   DIR/ALG/bbobexp_f<fid>.info                   per function: a block per dimension
//   DIR/ALG/data_f<fid>/bbobexp_f<fid>_DIM<d>.dat   one block per run, at COCO's target triggers
//   DIR/ALG/data_f<fid>/bbobexp_f<fid>_DIM<d>.tdat  one block per run, at its evaluation triggers
// from each run's COCO trace (framework/coco_trace.hpp), its last line at the run's last
// evaluation. Each run is one entry "instance:evaluations|final precision" of its .info line, in
// the order of its blocks (runs of an instance by seed): cocopp reads several runs of an
// instance as repetitions of it, as in COCO's 2009 data (3 runs of instances 1-5).
// A store's runs of one suite: bbob, or bbob-constrained, whose lines give the f evaluations and
// the constraint evaluations (equal: a pride evaluation is one of each) and COCO's logged value
// max(f, f_opt) + sum g_i+ (docs/constraints.md). What COCO writes and a run cannot know is left
// out: the x columns (COCO writes them below 7-D; runs keep no points along the way), "measured
// fitness" is the best value (on a triggered line COCO's current value, which a trace does not
// keep) and so is the fifth column (COCO's single-digit constraint values; cocopp reads neither).
#include <cstddef>
#include <string>

namespace pride {
class OutputFiles;
}

namespace pride::report {

struct CocoExportSummary {
    std::size_t files = 0;       // .info, .dat and .tdat files written
    std::size_t algorithms = 0;  // folders
    std::size_t runs = 0;        // runs written
    std::size_t skipped = 0;     // runs on problems outside COCO's suites (not COCO's data)
    std::string suite;           // the suite written: bbob or bbob-constrained
    std::string folder;
};

/// Writes the runs of the store at `store` on COCO's bbob or bbob-constrained suite under
/// `folder` (created if need be), one folder per algorithm; runs on other problems are counted in
/// `skipped`. InputError when the store is missing, damaged, holds no run of either suite or runs
/// of both, when a run has no COCO trace (stored before pride kept one: run the campaign again
/// into a new store), or when a file cannot be written; then nothing of the export is left
/// (framework/output_files.hpp).
CocoExportSummary export_coco(const std::string& store, const std::string& folder);
/// The same files, written to `files` and left for the caller to commit.
CocoExportSummary export_coco(const std::string& store, const std::string& folder, OutputFiles& files);

}  // namespace pride::report

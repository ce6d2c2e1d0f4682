#pragma once
// A campaign store as COCO's bbob data files (`pride export STORE --coco DIR`), which cocopp
// post-processes as it does COCO's own experiments (docs/analysis.md). Written as COCO's bbob
// logger writes them (numbbo/coco-experiment, src/logger_bbob.c, data format "bbob-new2"):
//   DIR/ALG/bbobexp_f<fid>.info                   per function: a block per dimension
//   DIR/ALG/data_f<fid>/bbobexp_f<fid>_DIM<d>.dat   one block per run, at COCO's target triggers
//   DIR/ALG/data_f<fid>/bbobexp_f<fid>_DIM<d>.tdat  one block per run, at its evaluation triggers
// from each run's COCO trace (framework/coco_trace.hpp), its last line at the run's last
// evaluation. What COCO writes and a run cannot know is left out: the x columns (COCO writes
// them below 7-D; runs keep no points along the way), and "measured fitness" is the best value
// (on a triggered line COCO's current value, which a trace does not keep; cocopp reads neither).
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
    std::size_t skipped = 0;     // runs on problems outside the bbob suite (not COCO's data)
    std::string folder;
};

/// Writes the bbob runs of the store at `store` under `folder` (created if need be), one folder
/// per algorithm. InputError when the store is missing, damaged or holds no bbob run, when a
/// bbob run has no COCO trace (stored before pride kept one: run the campaign again into a new
/// store), or when a file cannot be written; then nothing of the export is left
/// (framework/output_files.hpp).
CocoExportSummary export_coco(const std::string& store, const std::string& folder);
/// The same files, written to `files` and left for the caller to commit.
CocoExportSummary export_coco(const std::string& store, const std::string& folder, OutputFiles& files);

}  // namespace pride::report

#pragma once
// A campaign store as IOHprofiler files (the COCO-style `.info` and `.dat` files IOHanalyzer
// reads; docs/campaigns.md, `pride export`): one folder per algorithm (its id as a safe, unique
// file name), one `.info` file and one
// `.dat` file per problem it ran on.
#include <cstddef>
#include <string>

namespace pride {
class OutputFiles;
}

namespace pride::report {

struct ExportSummary {
    std::size_t files = 0;  // .info and .dat files written
    std::size_t algorithms = 0;
    std::string folder;
};

/// Writes the store at `store` under `folder` (created if need be). InputError when the store is
/// missing, not a campaign store, damaged (DamagedStore) or empty, or when a file cannot be written;
/// then nothing of the export is left (framework/output_files.hpp).
ExportSummary export_ioh(const std::string& store, const std::string& folder);
/// The same files, written to `files` and left for the caller to commit (the command line commits
/// them once its summary was printed).
ExportSummary export_ioh(const std::string& store, const std::string& folder, OutputFiles& files);

}  // namespace pride::report

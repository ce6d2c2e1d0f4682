#pragma once
// A campaign store as IOHprofiler files (the COCO-style `.info` and `.dat` files IOHanalyzer
// reads; docs/campaigns.md, `pride export`): one folder per algorithm (its id as a safe, unique
// file name), one `.info` file and one
// `.dat` file per problem it ran on.
#include <cstddef>
#include <cstdint>
#include <string>

namespace pride {
class OutputFiles;
}
namespace pride::storage {
struct StoredProblem;
}

namespace pride::report {

/// The IOHprofiler function a store's problem is written as (and read back from, ioh_import.hpp).
struct IohFunction {
    std::int64_t id = 0;    // funcId
    std::string name;       // funcName
    std::string suite;      // the .info header's suite
    bool in_suite = false;  // runs named by instance (IOH's suites) rather than by seed
};

/// `p`, the problem at `position` (0, 1, ...) in its store: BBOB's f1-f24 by IOHexperimenter's fid
/// and name, other suites' functions by disjoint ids, any other problem by its place in the campaign.
IohFunction ioh_function(const storage::StoredProblem& p, std::size_t position);

/// `name` as a .info file's double quotes hold it (a quote or line break written as '_').
std::string ioh_quoted(const std::string& name);

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

#pragma once
// IOHprofiler files read as published runs (`pride import STORE --ioh FOLDER --name NAME`): one
// algorithm's folder as `pride export --ioh` writes it (ioh_export.hpp), in IOHprofiler's .info
// format (IOHexperimenter's Analyzer v1 and its FlatFile columns, as IOHanalyzer reads them):
//   IOHprofiler_f<id>_<name>.info  per function, per dimension: a header line ("suite = "BBOB",
//                                  funcId = 1, funcName = "Sphere", DIM = 2, maximization = "F",
//                                  algId = "pso", ..."), a comment line ("%"), and a data line
//                                  naming a .dat file followed by one "number:evaluations|best f"
//                                  per run, in the order of the runs' blocks in that file;
//   data_f<id>_<name>/IOHprofiler_f<id>_DIM<d>.dat
//                                  per run a block: a header line of quoted column names
//                                  ("function evaluation" "current f(x)" "best-so-far f(x)" ...),
//                                  then one line per improvement: evaluations, then the values.
// The runs are of the store's own problems, named as the export names them (ioh_function): a suite's
// function by its id, dimension and instance (the run's number; its runs there are trials 1, 2, ...
// in the files' order), any other problem by its place in the campaign and its name (the run's
// number is its seed). Each run keeps its rows as its history; its runtimes to the store's target
// precisions are the first rows whose best-so-far f(x) - f_opt is within them (rows are written at
// iterations: a runtime is that of the iteration that reached the target), its evaluations and final
// value the .info line's. Problems without a known optimum get no runtimes (as pride's own runs).
#include <string>
#include <vector>

#include "experiment/report/published_files.hpp"
#include "experiment/storage/published.hpp"

namespace pride::report {

/// The runs of the IOH folder `folder` (every .info file under it), on the problems of the store at
/// `store`. InputError naming the file and line for a malformed line, a value that is no number, an
/// evaluation count that decreases, a .dat whose runs do not match its .info line, two algorithms
/// (algId) in one folder, a maximised function, or a function, dimension or instance the store has
/// not; naming the folder or store when either is missing.
storage::PublishedSet read_ioh(const std::string& store, const std::string& folder,
                               const PublishedImportOptions& options);

/// read_ioh's runs added to the store at `store` in one transaction: storage::Writer::import_published,
/// its refusals included (an algorithm of that name there already, other target precisions).
storage::ImportSummary import_ioh(const std::string& store, const std::string& folder,
                                  const PublishedImportOptions& options, const std::vector<double>& precisions,
                                  const std::string& precisions_json);

}  // namespace pride::report

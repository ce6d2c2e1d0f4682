#pragma once
// The CEC 2017 bound-constrained competition's entrants' result files read as published runs
// (`pride import STORE --cec2017 FOLDER --name NAME`): one entrant's folder, one file per function
// and dimension, as the competition asked for them (Awad, Ali, Liang, Qu, Suganthan 2016, "Problem
// Definitions and Evaluation Criteria for the CEC 2017 Special Session and Competition on Single
// Objective Real-Parameter Numerical Optimization", section 2.2, quoted in cec.hpp):
//   NAME_F_D.txt   (.dat and .csv too; NAME_D_F where the folder's names show it, as
//                  IDEbestNsize's do: its second numbers run over 1-30) 14 rows, the checkpoints
//                  (0.01, 0.02, 0.03, 0.05, 0.1, 0.2, ..., 0.9, 1.0) x MaxFES with MaxFES = 10000 D,
//                  of one error f - f* per run (51 runs), separated by blanks, tabs or commas. A row
//                  may start with a label giving its evaluations ("Function error values when FEs =
//                  1000", as MOS's files do, below a header line "NAME.csv , Run 1, ..."), which must
//                  be the checkpoint's.
// Each run (column) becomes one published run on the function cecYYYY-fF in D dimensions, as pride's
// CEC 2017 campaigns store it (problems/continuous/cec: f* = 100 F, no instance): its budget MaxFES,
// its evaluations MaxFES, its best value f* + the last row's error, and its 14 checkpoints (the
// store's `checkpoints`, which `pride report --format cec` reads; also its trace). The files give no
// runtime to a target (a checkpoint bounds one), so the runs store none: the ERT and ECDFs leave them
// out. Errors are kept as written; the CEC report counts those below 1e-8 as 0.
#include <string>
#include <vector>

#include "experiment/report/published_files.hpp"
#include "experiment/storage/published.hpp"

namespace pride::report {

/// The runs of one entrant's folder (its files NAME_F_D.*, not its subfolders). InputError naming the
/// file and line for a row that is not 14 x one error per run (a value that is no finite number >= 0,
/// a count of runs unlike the first row's, a run whose error rises, a label of other evaluations),
/// for files of two entrants or of a function and dimension the suite does not define, and naming the
/// folder when it holds no such file (listing its folders, where an entrant's results are in several).
storage::PublishedSet read_cec2017(const std::string& folder, const PublishedImportOptions& options);

/// read_cec2017's runs added to the store at `store` (created when absent), in one transaction:
/// storage::Writer::import_published, its refusals included (a store's problem of the same function
/// and dimension with another f* among them).
storage::ImportSummary import_cec2017(const std::string& store, const std::string& folder,
                                      const PublishedImportOptions& options, const std::vector<double>& precisions,
                                      const std::string& precisions_json);

}  // namespace pride::report

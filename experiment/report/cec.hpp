#pragma once
// The CEC competitions' way of reporting, for `pride report --format cec`: per problem
// and algorithm, the error f - f* of the best value so far at the end of the runs and at the
// checkpoints the suite's technical report prescribes, as best / worst / median / mean / std over
// the runs, errors below 1e-8 taken as 0. MaxFES is each run's evaluation budget.
//
// CEC 2017 (Awad, Ali, Liang, Qu, Suganthan 2016, "Problem Definitions and Evaluation Criteria for
// the CEC 2017 Special Session and Competition on Single Objective Real-Parameter Numerical
// Optimization", section 2.2 "Results Record"):
//   "1) Record function error value (Fi(x)-Fi(x*)) after (0.01, 0.02, 0.03, 0.05, 0.1, 0.2, 0.3,
//   0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0)*MaxFES for each run. In this case, 14 error values are
//   recorded for each function for each run. Sort the error values achieved after MaxFES in 51
//   runs from the smallest (best) to the largest (worst) and present the best, worst, mean, median
//   and standard variance values of function error values for the 51 runs.
//   Please Notice: Error value smaller than 10-8 will be taken as zero."
// CEC 2022 (Kumar, Price, Mohamed, Hadi, Suganthan 2021, "Problem Definitions and Evaluation
// Criteria for the CEC 2022 Special Session and Competition on Single Objective Bound Constrained
// Numerical Optimization", section 2.2 "Results Record"):
//   "1) For each run, record the function error value (Fi(x) - Fi(x*)) after
//   floor(D^(k/5-3) MaxFES) function evaluations (k = 0, 1, 2, 3, ..., 15). If a trial terminates
//   by reaching an error value of 10^-8 before reaching MaxFES, then record 10^-8 for the
//   remaining entries. [...] 3) Sort the error values achieved after MaxFES in 30 runs from the
//   smallest (best) to the largest (worst) and present the best, worst, mean, median and standard
//   variance values of function error values for the 30 runs."
//
// Where pride decides:
// - Errors below 1e-8 are 0 for both suites (the 2017 rule, kept for both so that they compare); the 2022 report's
//   "record 10^-8" would print such errors as 1e-8 instead. Runs do not stop at 1e-8 (a campaign
//   spends its budget): since the best value so far never rises, every later checkpoint is below
//   1e-8 too, so the tables are those of runs that stopped.
// - A checkpoint is at least 1 evaluation (a tiny MaxFES would floor it to 0); the 2017 ones are
//   floor(fraction x MaxFES), exact in integers (10000 D is a multiple of 100).
// - "Standard variance" is the sample standard deviation (n - 1), as MATLAB's std and the rest of
//   pride's reports compute it; the median of an even count is the mean of the middle two.
// - A run that ended before a checkpoint (a stopping rule, an algorithm that converged) has there
//   the best value it ended with: its best so far.
// - Problems other than cec2022's (another suite's, or any function with a known f*) take the
//   CEC 2017 checkpoints.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "experiment/storage/reader.hpp"
#include "problems/continuous/cec/suites.hpp"

namespace pride::report::cec {

// The checkpoints are the suites' (problems/continuous/cec/suites.hpp), which campaigns record too.
using continuous::cec::Checkpoint;

/// Errors below this are taken as 0.
inline constexpr double zero_below = 1e-8;

/// An error as the CEC reports count it: f - f*, 0 below 1e-8 (negative rounding included).
double error_of(double f, double f_opt);

/// The statistics of the runs' errors at one checkpoint.
struct Errors {
    double best = 0, worst = 0, median = 0, mean = 0, std = 0;  // std: sample (n - 1); inf if one is
};

struct CheckpointErrors {
    Checkpoint checkpoint;
    Errors errors;
};

/// One (problem, algorithm) in the CEC table.
struct Row {
    std::string problem, algorithm;
    std::string function;  // the registered function, as stored (cec2017-f3, bbob-f1, ...)
    std::string suite;     // as stored: cec2017, cec2022, bbob, classic, or empty
    std::int64_t dim = 0;
    double f_opt = 0;
    std::int64_t max_evaluations = 0;  // MaxFES: the runs' evaluation budget
    std::size_t runs = 0;
    std::vector<CheckpointErrors> checkpoints;  // in order; the last one is at MaxFES
};

struct Table {
    std::string campaign;
    std::vector<Row> rows;  // in the campaign's order of problems, then by algorithm
    // What the table leaves out, one sentence each (problems without a known f*).
    std::vector<std::string> notes;
};

/// The CEC table of the runs of `store` on problems with a known f*. InputError naming the store
/// when no run is on such a problem, and naming the run when one has no evaluation budget or was
/// stored without its checkpoints (before store schema 4), or when the runs of one (problem,
/// algorithm) had different budgets.
Table make_table(const storage::CampaignStore& store, const std::string& name);

/// A heading, what the numbers are, the errors at MaxFES as one table (the reports' "Results"
/// tables), then one table per problem and algorithm with every checkpoint; 6 significant digits.
std::string render_markdown(const Table& table);

/// problem,function,suite,dim,f_opt,algorithm,max_evaluations,runs,checkpoint,evaluations,best,
/// worst,median,mean,std: one line per checkpoint, numbers as the double they are.
std::string render_csv(const Table& table);

}  // namespace pride::report::cec

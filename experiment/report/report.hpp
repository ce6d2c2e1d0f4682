#pragma once
// The comparison report of a campaign store (docs/campaigns.md, `pride report`): per problem and
// algorithm the statistics of the final best values, the algorithm with the lowest median marked
// best, Holm-corrected Wilcoxon rank-sum p-values against it, and Friedman's ranks over the
// problems; as data, and rendered as markdown, CSV (every number as the double it is) or LaTeX.
// Problems that are instances of a function (BBOB, bbob-constrained, a function's seeded instances
// k >= 1) are compared as COCO compares them: per function and dimension, the runs of all its
// instances and seeds one sample per algorithm (FunctionRow), and Friedman ranks functions.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "experiment/report/coco.hpp"
#include "experiment/report/critical_difference.hpp"
#include "experiment/report/statistics.hpp"
#include "experiment/storage/reader.hpp"

namespace pride::report {

/// One (problem, algorithm): its runs' final best values (+inf for a run without a feasible one).
struct ReportRow {
    std::string problem, algorithm;
    std::size_t runs = 0;
    double min = 0, mean = 0, std = 0, median = 0, max = 0;  // std: sample (n - 1); +inf if a value is
    double mean_wall_ms = 0, mean_evaluations = 0;
    std::optional<double> optimum;   // grid problems: the exact optimum, and then
    std::optional<double> mean_gap;  // the mean of (value - optimum) / |optimum| (0 at the optimum);
                                     // precision rows: the mean precision f - f_opt
    std::optional<double> success;   // the share of runs at the optimum (precision rows: f - f_opt <= 1e-8)
    // Continuous problems with a known optimum f_opt: min ... max are precisions f - f_opt
    // (`precision`), unless the report is raw (ReportOptions::raw).
    std::optional<double> f_opt;
    bool precision = false;
    bool best = false;             // the lowest median of the problem (ties: the lowest mean)
    std::optional<double> p_holm;  // against the best; empty for the best itself
    std::optional<double> a12;     // Vargha-Delaney A against the best: P(this run better), ties half
    // An instance of a function (StoredProblem::instance >= 1): its runs are tested per function
    // (ReportData::functions, this function's rows), so p_holm and a12 are empty here. Empty for a
    // problem compared on its own.
    std::string function;
    // With a campaign target: the runs whose best reached it, and their mean evaluations to do so.
    std::size_t reached_target = 0;
    std::optional<double> mean_evaluations_to_target;
    // Problems with constraints: the runs whose best is feasible. min to max, mean, std and gap are
    // then over them alone; best, p_holm, a12 and Friedman's ranks compare all runs by Deb's order
    // (deb_order_text). Empty for problems without constraints.
    std::optional<std::size_t> feasible_runs;
};

/// A problem with constraints, per algorithm: how often and how soon its runs found a feasible point.
struct FeasibilityRow {
    std::string problem, algorithm;
    std::size_t runs = 0, feasible = 0;           // runs, and those whose best is feasible
    std::optional<double> median_first_feasible;  // over the runs that found a feasible point
    std::optional<double> median_violation;       // over the runs whose best is infeasible
};

/// What the report says of problems with constraints, after its table's first paragraph.
std::string deb_order_text();
/// The sentence before the feasibility table.
std::string feasibility_heading();

/// The runs cell of a row: "N", or with constraints "N (F feasible)".
std::string runs_cell(const ReportRow& r);
/// A feasibility row's cells: problem, algorithm, runs, "F (P %)" feasible, median first feasible
/// evaluation, median violation ("-" where there is none).
std::vector<std::string> feasibility_cells(const FeasibilityRow& f);

/// A function of a suite with instances, per dimension and algorithm: its runs over all the
/// instances and seeds, one sample (COCO's view: instances are repetitions). The values are
/// precisions f - f_opt (also under ReportOptions::raw; the values f where f_opt is unknown), a run
/// without a feasible point +inf.
struct FunctionRow {
    std::string function;  // the problem's function (bbob-f3, bbob-constrained-f12, rastrigin)
    std::int64_t dim = 0;
    std::string algorithm;
    std::size_t runs = 0, instances = 0;            // runs over all its instances, and the instances
    double median = 0, p10 = 0, p90 = 0, mean = 0;  // percentiles as cocopp's (coco::percentile)
    bool precision = true;                          // false: the values f (an instance without a known f_opt)
    std::size_t solved = 0;                         // runs with f - f_opt <= solved_precision (COCO's final target)
    std::optional<std::size_t> feasible_runs;       // with constraints: runs whose best is feasible
    bool best = false;                              // the lowest median (with constraints: of the Deb ranks)
    std::optional<double> p_holm;                   // rank-sum against the best, Holm over the function's algorithms
    std::optional<double> a12;                      // Vargha-Delaney A against the best
};

/// Friedman's test over the problems, on the median values of the algorithms run on all of them.
/// A function with instances is one block (its median over all instances and seeds), each other
/// problem one block.
struct FriedmanSummary {
    std::vector<std::string> algorithms;
    std::size_t problems = 0;            // the blocks ranked: problems compared on their own and functions
    std::size_t functions = 0;           // of them, functions (and dimensions) pooled over their instances
    stats::FriedmanTest test;            // average_ranks in the order of `algorithms`
    std::vector<stats::RankPair> pairs;  // every pair's post-hoc test (Demsar 2006), Holm-corrected
    // Nemenyi's critical difference at alpha 0.05 and the groups of algorithms whose average ranks
    // differ by less (the bars of Demsar's CD diagram); indices into `algorithms`.
    stats::CriticalDifference critical_difference;
};

/// How a report reads the runs.
struct ReportOptions {
    bool raw = false;  // the values f as run, also where f_opt is known (default: precisions f - f_opt)
};

/// COCO's final target precision: a run whose f - f_opt is at most this has solved the problem.
inline constexpr double solved_precision = 1e-8;

/// A problem of several objectives, per algorithm: what its runs' fronts reached (medians).
struct FrontRow {
    std::string problem, algorithm;
    std::size_t runs = 0;
    double hypervolume_ratio = 0;       // median of 1 - the hypervolume gap
    double igd_plus = 0;                // median IGD+
    std::optional<double> exact_found;  // grids: median points of the exact front found
    bool best = false;                  // the lowest median IGD+ of the problem (ties: the first)
    std::optional<double> p_holm;       // IGD+ against the best's, rank-sum, Holm over the problem
};

/// Grid problems, per algorithm: the paths its runs found, scored alike whoever planned them
/// (problems/grid/polyline.hpp): medians over the runs that found one.
struct PathRow {
    std::string problem, algorithm;
    std::size_t runs = 0, found = 0;
    // Medians in kPathMetricNames' order (empty where no run recorded the metric), and of wall_ms.
    std::vector<std::optional<double>> medians;
    /// The medians in the tables' column order: length_m beside length when `metres` (some row
    /// of the table has it: a map with a world frame), else left out.
    std::vector<std::optional<double>> columns(bool metres) const;
    double median_wall_ms = 0;
};

/// Whether some row has a median length in metres (its map has a world frame): the tables of
/// paths then show a column "length (m)" after "length".
bool paths_in_metres(const std::vector<PathRow>& rows);

struct ReportData {
    std::string campaign;
    std::optional<double> target;
    std::optional<double> target_precision;  // [budget] precision: the target is f_opt + it per problem
    bool raw = false;
    std::vector<ReportRow> rows;  // sorted by problem (natural_order.hpp), then algorithm
    // Functions with instances: sorted by function (natural order), dimension, algorithm.
    std::vector<FunctionRow> functions;
    std::optional<FriedmanSummary> friedman;  // with two algorithms on two problems or more
    // With the campaign's target precisions: ERT per function, dimension and algorithm, and the
    // ECDF curves (experiment/report/coco.hpp); rendered after the table.
    std::optional<coco::Analysis> coco;
    // What the reader must know before comparing the rows, one sentence each: problems whose
    // compared runs used evaluation counts more than 5 % apart, and the whole-map planners exempt
    // from that comparison (they evaluate no objective). Rendered after the table.
    std::vector<std::string> notes;
    // Problems of several objectives (their runs store fronts): rendered after the notes.
    std::vector<FrontRow> fronts;
    // Grid problems whose runs recorded path metrics (store schema 5): rendered after the fronts.
    std::vector<PathRow> paths;
    // Problems with constraints (their runs record violations, store schema 6): rendered after
    // the main table, before its notes.
    std::vector<FeasibilityRow> feasibility;
};

/// The report of the runs of `store` (no rows when it holds none).
ReportData make_report(const storage::CampaignStore& store, const ReportOptions& options = {});
/// make_report(read_store(path)); InputError when the store holds no runs yet.
ReportData load_report(const std::string& path, const ReportOptions& options = {});
/// Several stores read as one (a campaign run in parts; one store: read_store): their runs
/// together, a run found in several kept once when equal; InputError naming the stores when they
/// cannot be read as one (other target precisions or report targets, a problem id of two
/// definitions, a run that differs) or hold no runs.
storage::CampaignStore read_stores(const std::vector<std::string>& paths);
/// The report of several stores read as one (a campaign run in parts): their runs together, a run
/// found in several kept once when equal; InputError naming the stores when they cannot be read
/// as one (other target precisions or report targets, a problem id of two definitions, a run
/// that differs).
ReportData load_report(const std::vector<std::string>& paths, const ReportOptions& options = {});

/// The sentence before the table of functions with instances (ReportData::functions).
std::string functions_heading(const ReportData& report);
/// A function row's cells: function, D, algorithm, runs (with constraints "N (F feasible)"),
/// instances, median, 10th and 90th percentiles, mean, solved "k/N", p (Holm) ("best" for the best),
/// A12.
std::vector<std::string> function_cells(const FunctionRow& f);
/// What Friedman ranked, after "Friedman average ranks over ": "24 functions (1 = best; ...)".
std::string friedman_blocks_text(const FriedmanSummary& f);

std::string render_markdown(const ReportData& report);
/// A header line, then one line per row; each number in the shortest form that reads back as
/// the same double ("inf" when infinite), fields quoted as RFC 4180 says.
std::string render_csv(const ReportData& report);
/// The ERT of every function, dimension, algorithm and precision (report.coco) as CSV, numbers
/// as render_csv writes them: function,dim,algorithm,precision,ert,successes,runs,ert_p10,ert_p50,
/// ert_p90 (the percentiles of the ERT over bootstrap resamples, coco::ErtRow::ert_interval); the header
/// alone without an analysis.
std::string render_ert_csv(const ReportData& report);
/// The table of functions (report.functions) as CSV, numbers as render_csv writes them:
/// function,dim,algorithm,runs,instances,median,p10,p90,mean,measure,solved,feasible_runs,best,
/// p_holm_vs_best,a12_vs_best (measure: precision, or value where f_opt is unknown; solved and
/// feasible_runs empty where they do not apply); the header alone for a store without instances.
std::string render_functions_csv(const ReportData& report);
/// A `tabular` with the markdown's columns, then Friedman's ranks as a comment.
std::string render_latex(const ReportData& report);

/// The precisions an ERT table shows (every rendering, the HTML page's too): of COCO's 1e1, 1e-1,
/// 1e-3, 1e-5, 1e-7, 1e-8 those the campaign records, else all of the campaign's; as indices into
/// `precisions`.
std::vector<std::size_t> shown_precisions(const std::vector<double>& precisions);
/// A precision as a column title: 1e-3 for a power of ten, else 6 significant digits.
std::string precision_label(double p);

}  // namespace pride::report

#pragma once
// The CEC 2020 real-world constrained competition's tables and ranking (Kumar, Wu, Ali,
// Mallipeddi, Suganthan, Das 2020, "Guidelines for Real-World Single-Objective Constrained
// Optimisation Competition"), for `pride report --format cec2020rw` and Python's
// pride.cec2020rw_score:
// - Section 3.1: per problem, the best, median, mean, worst and standard deviation of f and of
//   the violation nu (eq. 2, the mean of the violations) over the runs, sorted as its footnote
//   says: feasible solutions first by f, then infeasible ones by nu; and FR (eq. 3), the share of
//   runs that found a feasible point.
// - Section 4: PM_i = 0.5 sum_j w_j A^best_ij + 0.3 sum_j w_j A^mean_ij + 0.2 sum_j w_j A^median_ij
//   (eq. 4) with the weights w_j of eq. 5 by dimension; A is the adjusted value (eq. 6: f when
//   feasible, else the worst feasible f among the algorithms' solutions of that kind on problem j,
//   or 0 when none is feasible, plus nu), normalised over the algorithms (eq. 7-9). Lower is better.
//
// The organisers' ranking script (Score.m, in "Code used For Ranking.zip" of the competition's
// repository P-N-Suganthan/2020-RW-Constrained-Optimisation) computes the same, and pride's scoring of
// the published workbooks equals its output (Scoring.txt) in every printed digit when the runs are
// taken in the workbooks' order (docs/results/cec2020rw.md). What pride decides where the guidelines
// are silent, each as the script does:
// - The "mean solution" is the mean f and the mean nu of the runs.
// - The "best" and "median" solutions are the first run and the one at floor((n - 1) / 2) (the 13th of
//   25) in the footnote's order (Order::guidelines, the default), or in the order given
//   (Order::given: the script takes rows 1 and 13 of each workbook, which their authors sorted,
//   nearly always as the footnote says).
// - A solution is feasible when nu = 0 exactly (eq. 2 already counts an equality within 1e-4 as met).
// - A problem on which every algorithm has the same adjusted value adds 0 (eq. 7 would divide 0 by 0;
//   the script divides by 1e-8).
// - No result: one entrant's workbook holds the text "nan" where it has none (the script reads NaN)
//   and 12345 as the violation of two of those. A NaN is what MATLAB makes of it: a mean over a NaN
//   is NaN; a NaN nu is infeasible; a NaN f is left out of the worst feasible f; an adjusted value
//   that is NaN is left out of the minimum and maximum and scores 1, the worst. (The script scores
//   1 only for that entrant, the only one with NaNs; pride does for any.) In the footnote's order a
//   run with a NaN comes last.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace pride::report::cec2020rw {

/// A run's final best point: its f and its violation nu (0 when feasible).
struct Outcome {
    double f = 0;
    double violation = 0;
};

/// The guidelines' order: feasible before infeasible, feasible by f, infeasible by nu; a run with a
/// NaN after all others.
bool precedes(const Outcome& a, const Outcome& b);

/// Which runs are the best and the median: the footnote's order, or the order given.
enum class Order { guidelines, given };

/// Section 3.1's statistics of one algorithm's runs on one problem.
struct Summary {
    Outcome best, median, mean, worst;
    double std_f = 0, std_violation = 0;  // sample standard deviations (n - 1), as MATLAB's std; 0 for one run
    double feasible_rate = 0;             // FR, eq. 3
    std::size_t runs = 0;
};

/// The statistics of `runs`: InputError naming `what` when there are none, or when an f or a
/// violation is infinite or a violation is negative (NaN is allowed: no result).
Summary summarise(std::span<const Outcome> runs, const std::string& what, Order order = Order::guidelines);

/// Eq. 5: the weight of a problem of `dim` variables (0.008 up to 10, 0.016 up to 30, 0.024 up
/// to 50, 0.032 up to 150, 0.040 above).
double weight(std::int64_t dim);

/// One algorithm's score: the three weighted sums of eq. 4 and PM itself.
struct Score {
    double best = 0, mean = 0, median = 0, total = 0;
};

/// Eq. 4-9 over the algorithms of `summaries` (summaries[a][j]: algorithm a on problem j, every
/// algorithm on the same problems, `dims[j]` the dimension of problem j). InputError when the
/// shapes disagree.
std::vector<Score> score(const std::vector<std::vector<Summary>>& summaries, std::span<const std::int64_t> dims);

/// The competition's ranks of `scores`: 1 for the lowest PM; equal PMs share the better rank.
std::vector<int> ranks(const std::vector<Score>& scores);

}  // namespace pride::report::cec2020rw

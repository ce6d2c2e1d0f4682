#pragma once
// The CEC 2017 bound-constrained competition's score, as the organisers ranked the entrants
// (Awad, Ali, Liang, Qu, Suganthan; the ranking presented with the results,
// "Bound-Constrained-Comparisons.pdf" in P-N-Suganthan/CEC2017-BoundContrained), for Python's
// pride.cec2017_score:
//   SE = sum_D w_D sum_i ef_i,D and SR = sum_D w_D sum_i rank_i,D, w = 0.1, 0.2, 0.3, 0.4 for
//   D = 10, 30, 50, 100 (F2 left out: "unstable");
//   Score1 = 50 (1 - (SE - SE_min) / SE), Score2 = 50 (1 - (SR - SR_min) / SR), Score = the sum.
// Where the slides are silent, pride decides: ef is an algorithm's mean error at MaxFES over its
// runs (errors below 1e-8 as 0: the report's rule); rank_i,D ranks the algorithms by ef on F_i in
// D, 1 the lowest, ties sharing their mean rank. With these, the thirteen entrants' Score1 equals the
// slides' to their five digits; Score2 does not (within 11 %: the slides do not say what was
// ranked; docs/import.md).
#include <cstdint>
#include <span>
#include <vector>

namespace pride::report::cec2017 {

/// One (function, dimension) of the table.
struct Cell {
    int function = 0;
    std::int64_t dim = 0;
};

/// The weight w_D of a dimension: 0.1, 0.2, 0.3, 0.4 for 10, 30, 50, 100; InputError otherwise.
double weight(std::int64_t dim);

/// One algorithm's score.
struct Score {
    double se = 0, sr = 0;          // the weighted sums of mean errors and of ranks
    double score1 = 0, score2 = 0;  // each out of 50
    double total = 0;               // Score1 + Score2, out of 100; higher is better
    int rank = 0;                   // 1 for the highest total; equal totals share the better rank
};

/// The scores of the algorithms whose mean errors are means[a][c] on cells[c]. InputError when
/// a row's length differs from the cells', a mean error is negative or not finite, or there are
/// no algorithms or cells.
std::vector<Score> score(const std::vector<std::vector<double>>& means, std::span<const Cell> cells);

}  // namespace pride::report::cec2017

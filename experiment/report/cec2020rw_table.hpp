#pragma once
// `pride report --format cec2020rw` (and cec2020rw-csv): a store's runs on the CEC 2020
// real-world problems (cec2020rw-rcNN) as the competition presents and ranks them
// (experiment/report/cec2020rw_score.hpp): per problem and algorithm, the guidelines' Table 1 at
// MaxFEs (best, median, mean, worst and std of f and of the violation; FR), then the algorithms'
// scores (eq. 4) over the problems every algorithm ran.
#include <cstdint>
#include <string>
#include <vector>

#include "experiment/report/cec2020rw_score.hpp"
#include "experiment/storage/reader.hpp"

namespace pride::report::cec2020rw {

struct Row {
    std::string problem, algorithm, function;
    std::int64_t dim = 0;
    Summary summary;
};

struct Table {
    std::string campaign;
    std::vector<Row> rows;                // in the campaign's order of problems, then by algorithm
    std::vector<std::string> algorithms;  // in the store's order
    std::vector<Score> scores;            // one per algorithm, over `scored` problems
    std::vector<int> ranks;
    std::vector<std::string> scored;  // the problems every algorithm ran
    std::vector<std::string> notes;   // what the table leaves out, one sentence each
};

/// The table of `store`'s runs on cec2020rw problems. InputError naming the store when it has none,
/// and naming the run when one has no finite violation (no point with finite values).
Table make_table(const storage::CampaignStore& store, const std::string& name);

/// A heading, Table 1 per problem and algorithm, the scores; 6 significant digits.
std::string render_markdown(const Table& table);

/// problem,function,dim,algorithm,runs,best_f,best_violation,median_f,median_violation,mean_f,
/// mean_violation,worst_f,worst_violation,std_f,std_violation,feasible_rate: one line per row,
/// numbers as the double they are; then a blank line and algorithm,score_best,score_mean,
/// score_median,pm,rank,problems.
std::string render_csv(const Table& table);

}  // namespace pride::report::cec2020rw

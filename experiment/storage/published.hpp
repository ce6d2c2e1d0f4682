#pragma once
// Published runs in a store: another author's results, read from the files they published (COCO's
// data sets: experiment/report/coco_import.hpp; the CEC 2017 entrants' result files:
// experiment/report/cec2017_import.hpp; IOHprofiler files: experiment/report/ioh_import.hpp), kept beside the runs
// pride made so that one report compares both. They are read-only rows: their algorithm's id is "published:NAME", a
// prefix no campaign's algorithm or problem may take (campaign/prepare.cpp refuses it); a campaign never runs them
// (they are none of its runs) and never changes them; the table `published` (store schema 7) keeps their provenance:
// the source file, its SHA-256, a citation, the format it was read from.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace pride::storage {

/// The id prefix of every published algorithm.
inline constexpr const char* kPublishedPrefix = "published:";

/// Where a published algorithm's runs come from (one row of table `published`).
struct PublishedSource {
    std::string algorithm;  // "published:NAME"
    std::string format;     // "coco-bbob", "cec2017", "iohprofiler"
    std::string source;     // the file or folder name it was read from (no path)
    std::string sha256;     // of the source file; of a folder, of its files (coco_import.hpp)
    std::string citation;
};

/// A point of a published run: (evaluations, best value minus the optimum so far).
struct PublishedPoint {
    std::int64_t evaluations = 0;
    double precision = 0;
};

/// One published run, as its files give it.
struct PublishedRun {
    std::string suite;                            // "bbob", "cec2017"
    std::int64_t fid = 0, dim = 0, instance = 0;  // instance 0: a CEC function, which has none
    std::int64_t trial = 0;                       // 1, 2, ...: the repeats of one instance, in the files' order
    double f_opt = 0;                             // as the run's data gives it
    std::int64_t evaluations = 0;
    double final_precision = 0;  // best - f_opt at the end
    // Where the best value improved at COCO's target triggers (.dat) and at its evaluation triggers
    // (.tdat), each with evaluations increasing.
    std::vector<PublishedPoint> targets, values;
    // Whether `targets` give the runtimes to the store's target precisions (COCO's .dat lines). A
    // CEC file records errors at checkpoints only, which bound a runtime without giving it: its runs
    // store none (target_hits "[]"), so the ERT and ECDFs leave them out.
    bool runtimes = true;
    // The CEC files' protocol: the evaluation budget (MaxFES) and the best f - f_opt after each of
    // its checkpoints (the store's `checkpoints`, read by `pride report --format cec`); COCO's data
    // sets record neither.
    std::optional<std::int64_t> max_evaluations;
    std::vector<PublishedPoint> checkpoints;
    // The store's problem the run is of, when its files name the store's own problems (IOH files
    // written by `pride export --ioh`, ioh_import.hpp): used as it is, never added; f_opt is then
    // the problem's (0 where it has none, and `runtimes` false). Else the problem is found, or
    // added, by suite, fid, dim and instance.
    std::optional<std::string> problem;
    // The best value after each iteration and the evaluations by then, as IOH's .dat files give
    // them (the store's `history`); empty for the other formats.
    std::vector<double> history;
    std::vector<std::int64_t> history_evaluations;
    std::string where;  // the file and line the run starts at, for messages
};

struct PublishedSet {
    PublishedSource source;
    std::vector<PublishedRun> runs;
};

/// What an import added.
struct ImportSummary {
    std::size_t runs = 0, problems_matched = 0, problems_added = 0;
};

}  // namespace pride::storage

#pragma once
// COCO-style analysis of a campaign that records target hits (docs/analysis.md): the expected
// running time (ERT) per function, dimension, algorithm and target precision, and the empirical
// cumulative distribution (ECDF) of runtimes over (run, target) pairs per algorithm, over the
// whole campaign and per BBOB function group.
//
// Definitions as in N. Hansen, A. Auger, D. Brockhoff, D. Tusar, T. Tusar, "COCO: Performance
// assessment", arXiv:1605.03560 (2016); the ERT is K. Price's (1997) "expected number of
// function evaluations" as used by A. Auger and N. Hansen (CEC 2005).
//
// The pure functions ert() and ecdf() take plain data; analyse() builds both from a store.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "experiment/storage/reader.hpp"

namespace pride::report::coco {

/// One run's record against one target: what ert() and ecdf() need.
struct TargetRun {
    std::int64_t evaluations = 0;     // all evaluations of the run
    std::optional<std::int64_t> hit;  // evaluations until best - f_opt <= precision first held
    std::int64_t dim = 1;             // the problem's dimension (ecdf() divides by it)
};

/// The 10th, 50th and 90th percentiles of a sample (experiment/report/bootstrap.hpp).
struct Percentiles {
    double p10 = 0, p50 = 0, p90 = 0;
};

struct Ert {
    double value = 0;  // +inf when no run succeeded
    std::size_t successes = 0, runs = 0;
};

/// ERT = (sum over the runs of the evaluations until the target was reached, or of all the
/// run's evaluations for a run that did not reach it) / (the number of runs that reached it);
/// +inf when none did (and when there are no runs).
Ert ert(const std::vector<TargetRun>& runs);

/// The ECDF of the runtimes of (run, target) pairs as a step function of
/// x = log10(evaluations / dimension): y[k] is the fraction of all pairs (reached or not) whose
/// target was reached within 10^x[k] * dimension evaluations; x increasing, y increasing (one
/// point per distinct runtime), constant between points and 0 before x[0].
struct Ecdf {
    std::vector<double> x, y;
    std::size_t pairs = 0;
    double max_budget = 0;  // log10 of the largest evaluations / dimension of the runs (-inf: none)
};

/// COCO's ECDF (Hansen et al. 2016, section "Empirical Cumulative Distribution Functions"):
/// the fraction of (run, target) pairs whose target was hit within a budget of b * dim
/// evaluations, as a function of log10(b). Pairs never reached count in the denominator.
Ecdf ecdf(const std::vector<TargetRun>& pairs);

/// COCO's five BBOB function groups, by fid: separable (f1-f5), moderate (low or moderate
/// conditioning, f6-f9), ill-conditioned (high conditioning and unimodal, f10-f14), multimodal
/// (adequate global structure, f15-f19), weakly-structured (weak global structure, f20-f24);
/// empty for another fid.
std::optional<std::string> bbob_group(std::int64_t fid);
/// The group's title as COCO words it ("separable functions f1-f5", ...).
std::string bbob_group_title(const std::string& group);

/// The ERT of one (function, dimension, algorithm): one entry per precision of the campaign,
/// over the runs of every instance of the function in that dimension (COCO treats instances as
/// runs).
struct ErtRow {
    std::string function;              // the problem's function, else its id
    std::optional<std::int64_t> fid;   // its number in its suite
    std::optional<std::string> suite;  // bbob, classic
    std::int64_t dim = 0;
    std::string algorithm;
    std::size_t runs = 0, instances = 0;
    std::vector<Ert> ert;  // per precision
    // Per precision: the 10th, 50th and 90th percentiles of the ERT over bootstrap resamples of
    // the runs (ert_confidence, bootstrap.hpp; kErtResamples of them), +inf where none succeeded.
    std::vector<Percentiles> ert_interval;
};

/// The bootstrap resamples behind ErtRow::ert_interval and the simulated restarts of each pair
/// behind EcdfCurve::restarts (cocopp draws 30 in its defaults, 10^4 for final figures).
inline constexpr std::size_t kErtResamples = 1000;
inline constexpr std::size_t kRestartSamples = 100;

/// One ECDF line: an algorithm over the (run, precision) pairs of a group of functions.
struct EcdfCurve {
    std::string group;  // "all", or a BBOB group (bbob_group)
    std::string algorithm;
    std::vector<std::int64_t> dims;  // the dimensions its pairs come from, increasing
    Ecdf ecdf;
    // COCO's ECDF with simulated restarts (ecdf_simulated_restarts, bootstrap.hpp): kRestartSamples
    // runtimes per (function, dimension, precision), runs of one function's instances pooled.
    Ecdf restarts;
};

struct Analysis {
    std::vector<double> precisions;
    std::vector<ErtRow> erts;           // by suite fid (then name), dimension, algorithm
    std::vector<EcdfCurve> curves;      // "all" first, then the BBOB groups in order; by algorithm
    std::size_t runs_without_hits = 0;  // left out: their rows record no target hits
};

/// The analysis of `store`; empty when the campaign records no precisions (NULL, absent or
/// []), when the store has no problems table, or when no run records hits (pride bench records
/// none for problems without a known optimum, grids). Runs without recorded hits are left out
/// (and counted).
std::optional<Analysis> analyse(const storage::CampaignStore& store);

/// The ECDF curves as JSON for scripts/plot_ecdf.py:
/// {"campaign": ..., "precisions": [...], "groups": [{"group", "title", "dims": [...],
///  "curves": [{"algorithm", "pairs", "max_budget", "x": [...], "y": [...]}]}]}.
std::string ecdf_json(const std::string& campaign, const Analysis& analysis);

}  // namespace pride::report::coco

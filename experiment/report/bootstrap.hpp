#pragma once
// COCO's simulated restarts and what is built on them (docs/analysis.md, "Simulated restarts"):
// runtimes of simulated restarts for one target, their percentiles beside the ERT (the spread
// cocopp's ERT tables print), a bootstrap interval of the ERT itself, and the runtime ECDF with
// simulated restarts (cocopp's pprldmany figures).
//
// Definitions: N. Hansen, A. Auger, D. Brockhoff, D. Tusar, T. Tusar, "COCO: Performance
// assessment", arXiv:1605.03560 (2016), sections "Runtime computation" (restarts and simulated
// restarts), "Averaging runtime" and "Empirical distribution functions"; journal version: N. Hansen, A. Auger, D.
// Brockhoff, T. Tusar, "Anytime performance assessment in blackbox optimization benchmarking", IEEE Trans. Evol.
// Comput. 26(6):1293-1305 (2022). The sampling follows cocopp's reference code (toolsstats.drawSP,
// DataSet.evals_with_simulated_restarts, compall/pprldmany.py), checked against it statistically in
// tests/test_bootstrap.cpp. Every function takes its seed: the same seed gives the same numbers bit for bit
// (framework/random.hpp's generator, not numpy's).
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "experiment/report/coco.hpp"

namespace pride::report::coco {

/// The smallest multiple of `runs` that is at least `wanted` (and at least `runs`): cocopp's
/// DataSet.bootstrap_sample_size, so that the first draws of simulated_runtimes() take every run
/// equally often. `wanted` when `runs` is 0.
std::size_t balanced_sample_size(std::size_t wanted, std::size_t runs);

/// `samples` runtimes of simulated restarts on one target, sorted ascending; empty when no run
/// reached the target (or there are none). One simulated runtime: draw runs uniformly with
/// replacement until one that reached the target is drawn; it is the sum of the evaluations of
/// the unsuccessful runs drawn plus the successful run's hit. Its expected value is the ERT
/// (ert()). As cocopp does, the first run of each simulated runtime is drawn without replacement
/// in blocks of runs.size() (a fresh permutation per block), which lowers the variance: with
/// every run successful and `samples` a multiple of the runs, each hit appears equally often.
/// Empty too when `samples` is 0.
std::vector<double> simulated_runtimes(const std::vector<TargetRun>& runs, std::size_t samples, std::uint64_t seed);

/// The p-th percentile (p in [0, 100]) of `sorted` (ascending, +inf allowed, no NaN) as cocopp's
/// toolsstats.prctile computes it: Hazen's (R. J. Hyndman, Y. Fan, "Sample quantiles in
/// statistical packages", Am. Stat. 50(4), 1996, definition 5), linear interpolation at the position
/// p/100 * n - 1/2 (0-based), clamped to the first and last values; numpy's
/// percentile(method="hazen"). An interpolation touching +inf is +inf; NaN when `sorted` is empty.
double percentile(std::span<const double> sorted, double p);

/// The 10th, 50th and 90th percentiles of a distribution, as cocopp's tables use them; +inf when
/// it is not defined (no run reached the target).

/// The ERT of one target with the spread of its simulated restarts, as cocopp's ERT tables
/// (pptable.py) show it: `runtimes` are the 10th, 50th and 90th percentiles of `samples`
/// simulated runtimes (drawSP); the tables print (p90 - p10) / 2 beside the ERT. This is the
/// spread of the runtime of a restarted algorithm, not a confidence interval of the ERT (see
/// ert_confidence()).
struct ErtSpread {
    Ert ert;                  // exact, as ert()
    Percentiles runtimes;     // +inf each when no run reached the target
    std::size_t samples = 0;  // simulated runtimes drawn (0 when none reached it)
    double half_range() const { return (runtimes.p90 - runtimes.p10) / 2; }
};
ErtSpread ert_spread(const std::vector<TargetRun>& runs, std::size_t samples, std::uint64_t seed);

/// A percentile bootstrap interval of the ERT (B. Efron, R. Tibshirani, "An introduction to the
/// bootstrap", 1993, ch. 13): the 10th, 50th and 90th percentiles of the ERTs of `resamples`
/// resamples of the runs (runs.size() runs drawn uniformly with replacement), cocopp's
/// toolsstats.draw(data, [10, 50, 90], func=sp). A resample in which no run reached the target
/// has an infinite ERT, so p90 is +inf when such resamples are over a tenth of them. [p10, p90]
/// is an 80 % interval; +inf each when there are no runs.
Percentiles ert_confidence(const std::vector<TargetRun>& runs, std::size_t resamples, std::uint64_t seed);

/// COCO's runtime ECDF with simulated restarts (compall/pprldmany.py): `pairs` holds one entry
/// per (problem, target) pair, the runs of every instance on it (one dimension per pair); each
/// pair contributes `samples_per_pair` simulated runtimes divided by its dimension, or as many
/// unreached entries when none of its runs reached the target (or it has no runs). Returned as
/// ecdf() returns the plain ECDF: y is the fraction of all pairs * samples_per_pair entries
/// reached within 10^x * dimension evaluations. Unlike ecdf(), the runtimes go past the largest
/// budget (max_budget, as ecdf() sets it), as restarts would; cocopp draws its curves only up to
/// its x limit. Pair k draws from the stream (seed, k), so a pair's runtimes do not depend on the
/// others. With every run successful, the same number of runs in every pair and samples_per_pair
/// a multiple of it, the curve is exactly ecdf() of all the runs.
Ecdf ecdf_simulated_restarts(const std::vector<std::vector<TargetRun>>& pairs, std::size_t samples_per_pair,
                             std::uint64_t seed);

}  // namespace pride::report::coco

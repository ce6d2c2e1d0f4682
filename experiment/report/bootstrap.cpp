#include "experiment/report/bootstrap.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <utility>

#include "framework/error.hpp"
#include "framework/random.hpp"

namespace pride::report::coco {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// What one run costs a restarted algorithm: its hit when it reached the target, else all of it.
double cost(const TargetRun& r) {
    return static_cast<double>(r.hit ? *r.hit : r.evaluations);
}

/// The percentiles 10, 50 and 90 of ascending values (+inf each when there are none).
Percentiles percentiles(std::span<const double> sorted) {
    if (sorted.empty()) return {kInfinity, kInfinity, kInfinity};
    return {percentile(sorted, 10), percentile(sorted, 50), percentile(sorted, 90)};
}

/// Fisher-Yates (Knuth, TAOCP vol. 2, algorithm 3.4.2 P) with the run's own generator.
void shuffle(std::vector<std::size_t>& v, Rng& rng) {
    for (std::size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[rng.below(i)]);
}

}  // namespace

std::size_t balanced_sample_size(std::size_t wanted, std::size_t runs) {
    if (runs == 0) return wanted;
    return std::max<std::size_t>(1, (wanted + runs - 1) / runs) * runs;
}

std::vector<double> simulated_runtimes(const std::vector<TargetRun>& runs, std::size_t samples, std::uint64_t seed) {
    const std::size_t n = runs.size();
    if (std::none_of(runs.begin(), runs.end(), [](const TargetRun& r) { return r.hit.has_value(); })) return {};
    Rng rng(seed);
    std::vector<std::size_t> first(n);
    std::iota(first.begin(), first.end(), std::size_t{0});
    std::vector<double> out;
    out.reserve(samples);
    for (std::size_t s = 0; s < samples; ++s) {
        // cocopp draws the first run without replacement, block by block (randint_derandomized);
        // the restarts after an unsuccessful run with replacement.
        if (s % n == 0) shuffle(first, rng);
        std::size_t i = first[s % n];
        double runtime = 0;
        while (!runs[i].hit) {
            runtime += static_cast<double>(runs[i].evaluations);
            i = rng.below(n);
        }
        out.push_back(runtime + static_cast<double>(*runs[i].hit));
    }
    std::sort(out.begin(), out.end());
    return out;
}

double percentile(std::span<const double> sorted, double p) {
    const std::size_t n = sorted.size();
    if (n == 0) return std::numeric_limits<double>::quiet_NaN();
    // Hazen: the k-th of n values (0-based) sits at the fraction (k + 1/2) / n.
    const double i = p / 100.0 * static_cast<double>(n) - 0.5;
    if (i <= 0) return sorted.front();
    if (i >= static_cast<double>(n - 1)) return sorted.back();
    const auto low = static_cast<std::size_t>(std::floor(i));
    const double w = i - static_cast<double>(low);
    if (w == 0) return sorted[low];  // no 0 * inf
    return (1 - w) * sorted[low] + w * sorted[low + 1];
}

ErtSpread ert_spread(const std::vector<TargetRun>& runs, std::size_t samples, std::uint64_t seed) {
    ErtSpread out;
    out.ert = ert(runs);
    const std::vector<double> simulated = simulated_runtimes(runs, samples, seed);
    out.samples = simulated.size();
    out.runtimes = percentiles(simulated);
    return out;
}

Percentiles ert_confidence(const std::vector<TargetRun>& runs, std::size_t resamples, std::uint64_t seed) {
    const std::size_t n = runs.size();
    if (n == 0) return {kInfinity, kInfinity, kInfinity};
    Rng rng(seed);
    std::vector<double> erts;
    erts.reserve(resamples);
    for (std::size_t b = 0; b < resamples; ++b) {
        double spent = 0;
        std::size_t successes = 0;
        for (std::size_t j = 0; j < n; ++j) {
            const TargetRun& r = runs[rng.below(n)];
            spent += cost(r);
            successes += r.hit ? 1 : 0;
        }
        erts.push_back(successes ? spent / static_cast<double>(successes) : kInfinity);
    }
    std::sort(erts.begin(), erts.end());
    return percentiles(erts);
}

Ecdf ecdf_simulated_restarts(const std::vector<std::vector<TargetRun>>& pairs, std::size_t samples_per_pair,
                             std::uint64_t seed) {
    Ecdf out;
    out.pairs = pairs.size();
    out.max_budget = -kInfinity;
    std::vector<double> reached;  // simulated runtimes / dimension of every pair
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        const std::vector<TargetRun>& runs = pairs[k];
        if (runs.empty()) continue;  // no data: samples_per_pair unreached entries
        const std::int64_t dim = runs.front().dim;
        for (const TargetRun& r : runs) {
            require(r.dim == dim, "ECDF with simulated restarts",
                    "the runs of one (problem, target) pair must share their dimension");
            out.max_budget = std::max(out.max_budget, std::log10(static_cast<double>(r.evaluations) /
                                                                 static_cast<double>(std::max<std::int64_t>(dim, 1))));
        }
        // Stream k of the seed: a pair's runtimes are the same whatever the other pairs are.
        Rng stream(seed, k);
        const std::vector<double> simulated = simulated_runtimes(runs, samples_per_pair, stream());
        for (const double t : simulated) reached.push_back(t / static_cast<double>(std::max<std::int64_t>(dim, 1)));
    }
    const double total = static_cast<double>(pairs.size() * samples_per_pair);
    std::sort(reached.begin(), reached.end());
    for (std::size_t j = 0; j < reached.size(); ++j) {
        if (j + 1 < reached.size() && reached[j + 1] == reached[j]) continue;  // one point per runtime
        out.x.push_back(std::log10(reached[j]));
        out.y.push_back(static_cast<double>(j + 1) / total);
    }
    return out;
}

}  // namespace pride::report::coco

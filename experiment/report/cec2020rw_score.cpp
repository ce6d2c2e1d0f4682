#include "experiment/report/cec2020rw_score.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "experiment/report/statistics.hpp"
#include "framework/error.hpp"

namespace pride::report::cec2020rw {
namespace {

enum class Kind { best, mean, median };

const Outcome& of(const Summary& s, Kind k) {
    return k == Kind::best ? s.best : k == Kind::mean ? s.mean : s.median;
}

/// sum_j w_j A^kind_ij (eq. 6-9) for every algorithm i, NaNs as MATLAB treats them (the header says).
std::vector<double> weighted_sum(const std::vector<std::vector<Summary>>& summaries, std::span<const std::int64_t> dims,
                                 Kind kind) {
    std::vector<double> sums(summaries.size(), 0.0), adjusted(summaries.size());
    for (std::size_t j = 0; j < dims.size(); ++j) {
        // Eq. 6's f^{F,kind}_{worst,j}: the worst feasible f among the algorithms' solutions (NaN when
        // every feasible one has a NaN f); without any feasible solution the violations alone count.
        bool any = false;
        double worst = std::numeric_limits<double>::quiet_NaN();
        for (const auto& row : summaries) {
            const Outcome& o = of(row[j], kind);
            if (o.violation != 0.0) continue;
            any = true;
            if (!std::isnan(o.f)) worst = std::isnan(worst) ? o.f : std::max(worst, o.f);
        }
        bool seen = false;
        double lo = 0.0, hi = 0.0;
        for (std::size_t i = 0; i < summaries.size(); ++i) {
            const Outcome& o = of(summaries[i][j], kind);
            adjusted[i] = !any ? o.violation : o.violation == 0.0 ? o.f : worst + o.violation;
            if (std::isnan(adjusted[i])) continue;
            lo = seen ? std::min(lo, adjusted[i]) : adjusted[i];
            hi = seen ? std::max(hi, adjusted[i]) : adjusted[i];
            seen = true;
        }
        for (std::size_t i = 0; i < summaries.size(); ++i) {
            const double normalised = std::isnan(adjusted[i]) ? 1.0 : hi == lo ? 0.0 : (adjusted[i] - lo) / (hi - lo);
            sums[i] += weight(dims[j]) * normalised;
        }
    }
    return sums;
}

}  // namespace

bool precedes(const Outcome& a, const Outcome& b) {
    const bool ra = !std::isnan(a.f) && !std::isnan(a.violation), rb = !std::isnan(b.f) && !std::isnan(b.violation);
    if (ra != rb) return ra;
    if (!ra) return false;
    const bool fa = a.violation == 0.0, fb = b.violation == 0.0;
    if (fa != fb) return fa;
    return fa ? a.f < b.f : a.violation < b.violation;
}

Summary summarise(std::span<const Outcome> runs, const std::string& what, Order order) {
    require(!runs.empty(), what, "no runs");
    for (const Outcome& o : runs)
        require(!std::isinf(o.f) && !std::isinf(o.violation) && !(o.violation < 0.0), what,
                fmt::format("a run's f {} and violation {}: expected finite numbers (NaN for no result), the "
                            "violation >= 0",
                            o.f, o.violation));
    std::vector<Outcome> sorted(runs.begin(), runs.end());
    if (order == Order::guidelines) std::stable_sort(sorted.begin(), sorted.end(), precedes);
    std::vector<double> f, v;
    for (const Outcome& o : runs) f.push_back(o.f), v.push_back(o.violation);
    Summary s;
    s.runs = runs.size();
    s.best = sorted.front();
    s.worst = sorted.back();
    s.median = sorted[(sorted.size() - 1) / 2];
    s.mean = {stats::mean_of(f), stats::mean_of(v)};
    s.std_f = runs.size() > 1 ? stats::sample_std(f) : 0.0;
    s.std_violation = runs.size() > 1 ? stats::sample_std(v) : 0.0;
    s.feasible_rate = static_cast<double>(std::count(v.begin(), v.end(), 0.0)) / static_cast<double>(runs.size());
    return s;
}

double weight(std::int64_t dim) {
    return dim <= 10 ? 0.008 : dim <= 30 ? 0.016 : dim <= 50 ? 0.024 : dim <= 150 ? 0.032 : 0.040;
}

std::vector<Score> score(const std::vector<std::vector<Summary>>& summaries, std::span<const std::int64_t> dims) {
    for (std::size_t i = 0; i < summaries.size(); ++i)
        require(summaries[i].size() == dims.size(), "scores",
                fmt::format("algorithm {} has {} problems where the dimensions name {}", i + 1, summaries[i].size(),
                            dims.size()));
    const auto best = weighted_sum(summaries, dims, Kind::best);
    const auto mean = weighted_sum(summaries, dims, Kind::mean);
    const auto median = weighted_sum(summaries, dims, Kind::median);
    std::vector<Score> out(summaries.size());
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = {best[i], mean[i], median[i], 0.5 * best[i] + 0.3 * mean[i] + 0.2 * median[i]};
    return out;
}

std::vector<int> ranks(const std::vector<Score>& scores) {
    std::vector<int> out;
    for (const Score& s : scores)
        out.push_back(1 + static_cast<int>(std::count_if(scores.begin(), scores.end(),
                                                         [&](const Score& t) { return t.total < s.total; })));
    return out;
}

}  // namespace pride::report::cec2020rw

#include "experiment/report/cec2017_score.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "framework/error.hpp"

namespace pride::report::cec2017 {

double weight(std::int64_t dim) {
    switch (dim) {
        case 10:
            return 0.1;
        case 30:
            return 0.2;
        case 50:
            return 0.3;
        case 100:
            return 0.4;
        default:
            throw InputError("dims", fmt::format("the CEC 2017 score weighs D = 10, 30, 50 and 100, got {}", dim));
    }
}

std::vector<Score> score(const std::vector<std::vector<double>>& means, std::span<const Cell> cells) {
    require(!means.empty(), "results", "no algorithms");
    require(!cells.empty(), "results", "no functions and dimensions");
    for (std::size_t a = 0; a < means.size(); ++a) {
        require(means[a].size() == cells.size(), "results",
                fmt::format("algorithm {} has {} mean errors for {} cells", a + 1, means[a].size(), cells.size()));
        for (std::size_t c = 0; c < cells.size(); ++c)
            require(std::isfinite(means[a][c]) && means[a][c] >= 0.0, "results",
                    fmt::format("algorithm {}, F{} at D = {}: a mean error must be a finite number >= 0, got {}", a + 1,
                                cells[c].function, cells[c].dim, means[a][c]));
    }
    std::vector<Score> out(means.size());
    std::vector<std::size_t> order(means.size());
    for (std::size_t c = 0; c < cells.size(); ++c) {
        const double w = weight(cells[c].dim);
        for (std::size_t a = 0; a < means.size(); ++a) out[a].se += w * means[a][c];
        // Ranks by mean error, ties sharing the mean of the ranks they span.
        std::iota(order.begin(), order.end(), std::size_t{0});
        std::stable_sort(order.begin(), order.end(),
                         [&](std::size_t x, std::size_t y) { return means[x][c] < means[y][c]; });
        for (std::size_t i = 0; i < order.size();) {
            std::size_t j = i;
            while (j + 1 < order.size() && means[order[j + 1]][c] == means[order[i]][c]) ++j;
            const double rank = 0.5 * static_cast<double>(i + j) + 1.0;
            for (std::size_t k = i; k <= j; ++k) out[order[k]].sr += w * rank;
            i = j + 1;
        }
    }
    double se_min = out[0].se, sr_min = out[0].sr;
    for (const Score& s : out) se_min = std::min(se_min, s.se), sr_min = std::min(sr_min, s.sr);
    for (Score& s : out) {
        // An algorithm with no error anywhere has SE = 0 = SE_min: the best Score1.
        s.score1 = s.se > 0.0 ? 50.0 * (1.0 - (s.se - se_min) / s.se) : 50.0;
        s.score2 = 50.0 * (1.0 - (s.sr - sr_min) / s.sr);
        s.total = s.score1 + s.score2;
    }
    for (Score& s : out)
        s.rank = 1 + static_cast<int>(
                         std::count_if(out.begin(), out.end(), [&](const Score& t) { return t.total > s.total; }));
    return out;
}

}  // namespace pride::report::cec2017

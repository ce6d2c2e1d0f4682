#include "problems/continuous/cec/suites.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace pride::continuous::cec {

std::vector<Checkpoint> checkpoints_2017(std::int64_t max_evaluations) {
    std::vector<Checkpoint> out;
    for (const int percent : {1, 2, 3, 5, 10, 20, 30, 40, 50, 60, 70, 80, 90, 100}) {
        // floor(MaxFES p / 100) without overflow: MaxFES = 100 q + r gives q p + floor(r p / 100).
        const std::int64_t e = max_evaluations / 100 * percent + max_evaluations % 100 * percent / 100;
        out.push_back(
            {percent == 100 ? std::string("1.0") : fmt::format("{:g}", percent / 100.0), std::max<std::int64_t>(1, e)});
    }
    return out;
}

std::vector<Checkpoint> checkpoints_2022(std::int64_t max_evaluations, std::int64_t dim) {
    std::vector<Checkpoint> out;
    for (int k = 0; k <= 15; ++k) {
        std::int64_t e = 0;
        if (k % 5 == 0) {
            // D^(k/5 - 3) is 1 / D^(3 - k/5): the floor is integer division, exact (floor(floor(a / b) /
            // c) = floor(a / (b c))).
            e = max_evaluations;
            for (int i = k / 5; i < 3; ++i) e /= dim;
        } else {
            // An irrational factor: long double (64-bit mantissa) leaves no integer in doubt.
            e = static_cast<std::int64_t>(
                std::floor(std::pow(static_cast<long double>(dim), static_cast<long double>(k) / 5.0L - 3.0L) *
                           static_cast<long double>(max_evaluations)));
        }
        out.push_back({fmt::format("k={}", k), std::max<std::int64_t>(1, e)});
    }
    return out;
}

std::vector<Checkpoint> checkpoints(std::string_view suite, std::int64_t max_evaluations, std::int64_t dim) {
    return suite == "cec2022" ? checkpoints_2022(max_evaluations, dim) : checkpoints_2017(max_evaluations);
}

std::vector<std::int64_t> recorded_evaluations(std::int64_t max_evaluations, std::int64_t dim) {
    std::set<std::int64_t> all;
    for (const auto& c : checkpoints_2017(max_evaluations)) all.insert(c.evaluations);
    for (const auto& c : checkpoints_2022(max_evaluations, dim)) all.insert(c.evaluations);
    return {all.begin(), all.end()};
}

}  // namespace pride::continuous::cec

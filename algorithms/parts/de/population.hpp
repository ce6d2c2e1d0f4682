#pragma once
// Differential evolution's population size (algorithms/de.hpp): the papers' rules for the initial
// size N_init (used when `population` is 0) and L-SHADE's linear population size reduction, each a
// small policy type.
//
//   Storn, R. and Price, K. (1997). J. Global Optimization 11, 341-359 (NP = 10 D, the top of
//     their 5 D .. 10 D).
//   Tanabe, R. and Fukunaga, A. (2014). Improving the search performance of SHADE using linear
//     population size reduction. Proc. IEEE CEC, 1658-1665 (N_init = round(18 D), N_min = 4, LPSR).
//   Brest, J., Maucec, M. S. and Boskovic, B. (2017). Algorithm jSO. Proc. IEEE CEC, 1311-1318
//     (N_init = round(25 ln(D) sqrt(D)), N_min = 4).
//
//   (S1) ConstantSize:     N_init = n (jDE, JADE, SHADE: 100)
//   (S2) PerDimensionSize: N_init = round(factor D) (DE: 10 D; L-SHADE: 18 D)
//   (S3) LogSqrtSize:      N_init = round(factor ln(D) sqrt(D)) (jSO: 25), at least 4 (D = 1 gives 0)
//   (L)  LinearReduction, after each generation (after the memory update, as paper and code):
//        N_{G+1} = round((N_min - N_init) / max_nfes * nfes + N_init); when N_{G+1} < N_G the
//        N_G - max(N_{G+1}, N_min) worst individuals are removed one at a time, each the first
//        (lowest index) of the worst values (Tanabe's code); the others keep their order.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "algorithms/parts/de/mutation.hpp"
#include "framework/error.hpp"
#include "framework/one_of.hpp"

namespace pride::de {

/// (S1) A fixed initial size.
struct ConstantSize {
    std::int64_t n = 100;
    std::int64_t operator()(std::size_t) const noexcept { return n; }
};

/// (S2) round(factor D).
struct PerDimensionSize {
    double factor = 10.0;
    std::int64_t operator()(std::size_t dim) const noexcept {
        return static_cast<std::int64_t>(std::round(factor * static_cast<double>(dim)));
    }
};

/// (S3) round(factor ln(D) sqrt(D)), at least 4.
struct LogSqrtSize {
    double factor = 25.0;
    std::int64_t operator()(std::size_t dim) const noexcept {
        const double d = static_cast<double>(dim);
        return std::max<std::int64_t>(4, static_cast<std::int64_t>(std::round(factor * std::log(d) * std::sqrt(d))));
    }
};

/// No reduction: N stays N_init.
struct FixedPopulation {
    static constexpr bool scheduled = false;
    std::int64_t min_population() const noexcept { return 0; }
    std::size_t next(std::size_t n, std::size_t, Spent) const noexcept { return n; }
    void validate(const std::string&) const {}
};

/// (L) L-SHADE's linear population size reduction (LPSR).
struct LinearReduction {
    static constexpr bool scheduled = true;
    std::int64_t n_min = 4;  // N_min
    std::int64_t min_population() const noexcept { return n_min; }
    /// The size for the next generation, from the current n and N_init after `spent`.
    std::size_t next(std::size_t n, std::size_t n_init, Spent spent) const noexcept {
        const double init = static_cast<double>(n_init), least = static_cast<double>(n_min);
        const double plan = std::round(
            (least - init) / static_cast<double>(spent.limit) * static_cast<double>(spent.evaluations) + init);
        if (!(static_cast<double>(n) > plan)) return n;
        return static_cast<std::size_t>(std::max(plan, least));
    }
    void validate(const std::string& who) const {
        require(n_min >= 4 && n_min <= 1'000'000'000, who,
                "n_min must be in [4, 1000000000], got " + std::to_string(n_min));
    }
};

using SelectableSize = OneOf<ConstantSize, PerDimensionSize, LogSqrtSize>;
using SelectableReduction = OneOf<FixedPopulation, LinearReduction>;

}  // namespace pride::de

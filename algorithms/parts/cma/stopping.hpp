#pragma once
// The stopping criteria of one CMA-ES run, as Hansen (2009, BBOB workshop, section 2) and Auger and
// Hansen (2005) name them; a restart policy starts the next run when one holds.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "framework/error.hpp"

namespace pride::cma {

enum class Stop {
    none,
    tol_fun,           // range of the recent best values and of the generation's values < tol_fun
    tol_x,             // sigma max(|p_c,i|, sqrt(C_ii)) < tol_x sigma_0,i in every coordinate
    no_effect_axis,    // m + 0.1 sigma sqrt(lambda_i) b_i == m, i = g mod n
    no_effect_coord,   // m_i + 0.2 sigma sqrt(C_ii) == m_i for some i
    condition_cov,     // cond(C) > condition (or C lost definiteness)
    stagnation,        // the medians of the recent best and median values no better than earlier ones
    tol_x_up,          // sigma max(D) grew by more than tol_x_up from its start
    run_budget,        // the restart policy's share of evaluations for this run is spent (BIPOP small)
    max_iter,          // 100 + 50 (n + 3)^2 / sqrt(lambda) generations
    equal_fun_values,  // the best and the k-th best value equal in more than 1/3 of the last n generations
};

inline const char* stop_name(Stop s) {
    switch (s) {
        case Stop::none:
            return "none";
        case Stop::tol_fun:
            return "TolFun";
        case Stop::tol_x:
            return "TolX";
        case Stop::no_effect_axis:
            return "NoEffectAxis";
        case Stop::no_effect_coord:
            return "NoEffectCoord";
        case Stop::condition_cov:
            return "ConditionCov";
        case Stop::stagnation:
            return "Stagnation";
        case Stop::tol_x_up:
            return "TolXUp";
        case Stop::run_budget:
            return "RunBudget";
        case Stop::max_iter:
            return "MaxIter";
        case Stop::equal_fun_values:
            return "EqualFunVals";
    }
    return "?";
}

/// The thresholds (Hansen 2009's values by default).
struct Tolerances {
    double fun = 1e-12;
    double x = 1e-12;  // relative to sigma_0 in each coordinate
    double x_up = 1e4;
    double condition = 1e14;
    // Off under the augmented Lagrangian, whose ranked values move with its coefficients (pycma's
    // ConstrainedFitnessAL example sets tolstagnation 0).
    bool stagnation = true;
    bool max_iter = true;          // off under the augmented Lagrangian too: a new run would start
    bool equal_fun_values = true;  // its multipliers afresh, and its ranked values move
    void validate(const std::string& who) const {
        require(fun >= 0.0 && std::isfinite(fun), who, "tol_fun must be finite and >= 0");
        require(x >= 0.0 && std::isfinite(x), who, "tol_x must be finite and >= 0");
        require(x_up > 1.0, who, "tol_x_up must be > 1");
        require(condition > 1.0, who, "condition must be > 1");
    }
};

/// The function-value histories TolFun and Stagnation read, with their own buffers.
class ValueHistory {
  public:
    /// n: dimension, lambda: population of this run.
    void reset(std::size_t n, std::int64_t lambda) {
        const double ratio = 30.0 * static_cast<double>(n) / static_cast<double>(lambda);
        tolfun_window_ = 10 + static_cast<std::size_t>(std::ceil(ratio));
        stagnation_min_ = 120 + static_cast<std::size_t>(std::ceil(ratio));
        const double l = static_cast<double>(lambda);
        max_iter_ = 100.0 + 50.0 * std::pow(static_cast<double>(n) + 3.0, 2.0) / std::sqrt(l);
        kth_ = 1 + static_cast<std::size_t>(std::ceil(0.1 + l / 4.0));
        n_ = n;
        best_.clear();
        median_.clear();
        equal_.clear();
    }

    /// After generation g (best and median of its values, sorted ascending in `sorted`).
    void record(const std::vector<double>& sorted, std::size_t count) {
        best_.push_back(sorted[0]);
        median_.push_back(median_of_sorted(sorted, count));
        last_range_ = sorted[count - 1] - sorted[0];
        equal_.push_back(count >= kth_ && sorted[0] == sorted[kth_ - 1]);
    }

    /// TolFun (Hansen 2009): the range of the best values of the last 10 + ceil(30 n / lambda)
    /// generations and of all values of the last generation is below `tol`.
    bool tol_fun(double tol) const {
        if (best_.size() < tolfun_window_) return false;
        const auto first = best_.end() - static_cast<std::ptrdiff_t>(tolfun_window_);
        const auto [lo, hi] = std::minmax_element(first, best_.end());
        return *hi - *lo < tol && last_range_ < tol;
    }

    /// Stagnation (Hansen 2009): over the last 20 % of the generations, but at least
    /// 120 + 30 n / lambda and at most 20,000, the median of the most recent 30 % of the best
    /// values, and of the median values, is no better than the median of the first 30 %.
    bool stagnation(std::vector<double>& scratch) const {
        const std::size_t g = best_.size();
        if (g < stagnation_min_) return false;
        const std::size_t window =
            std::min<std::size_t>(20000, std::max(stagnation_min_, static_cast<std::size_t>(std::ceil(0.2 * g))));
        const std::size_t part = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(0.3 * window)));
        auto median_of = [&](const std::vector<double>& h, std::size_t begin) {
            scratch.assign(h.begin() + static_cast<std::ptrdiff_t>(begin),
                           h.begin() + static_cast<std::ptrdiff_t>(begin + part));
            std::sort(scratch.begin(), scratch.end());
            return median_of_sorted(scratch, part);
        };
        const std::size_t early = g - window, late = g - part;
        return median_of(best_, late) >= median_of(best_, early) &&
               median_of(median_, late) >= median_of(median_, early);
    }

    /// MaxIter (Hansen 2009): 100 + 50 (n + 3)^2 / sqrt(lambda) generations are done.
    bool max_iter() const { return static_cast<double>(best_.size()) >= max_iter_; }

    /// EqualFunVals (Hansen 2009): in more than a third of the last n generations the best value
    /// equals the k-th best, k = 1 + ceil(0.1 + lambda / 4) (the k of cmaes.m's flat-fitness test;
    /// DEAP's example compares with the ceil(0.1 + lambda / 4)-th). Decided by this project: it
    /// waits for n generations.
    bool equal_fun_values() const {
        if (equal_.size() < n_) return false;
        const auto hits = std::count(equal_.end() - static_cast<std::ptrdiff_t>(n_), equal_.end(), char{1});
        return 3 * static_cast<std::size_t>(hits) > n_;
    }

    std::size_t generations() const { return best_.size(); }

  private:
    static double median_of_sorted(const std::vector<double>& v, std::size_t count) {
        return count % 2 ? v[count / 2] : 0.5 * (v[count / 2 - 1] + v[count / 2]);
    }

    std::size_t tolfun_window_ = 0, stagnation_min_ = 0, kth_ = 2, n_ = 1;
    double max_iter_ = 0.0;
    std::vector<double> best_, median_;
    std::vector<char> equal_;  // per generation: the best value equals the k-th best
    double last_range_ = 0.0;
};

}  // namespace pride::cma

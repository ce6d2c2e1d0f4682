#pragma once
// Barbosa and Lemonge's adaptive penalty method (APM; Lemonge and Barbosa 2004, eq. 2-4;
// constraints::adaptive_penalty) on a population as an algorithm keeps it: each member's value f,
// violation v and its m + p constraint values (RunState::evaluate_columns' `constraints`, member
// after member). The penalised values are recomputed from the whole population each time they are
// asked for, as the paper recomputes them each generation.
//
// Decided by this project where the paper is silent: v_j(x), constraint j's violation, is the
// problem's own measure of a point whose other constraints are 0 (the suite's violation, CEC's
// mean or COCO's sum, of that constraint alone; APM's values do not change when every v_j is
// scaled alike, so the mean's 1 / (m + p) is immaterial), so a point is feasible for APM exactly
// when the problem says so; a member whose f or v is not finite (not evaluated before the budget
// ended, or a NaN) takes no part in the means and gets +inf.
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

#include "framework/constraint_handlers.hpp"
#include "framework/constraints.hpp"
#include "framework/problem.hpp"
#include "framework/run_state.hpp"

namespace pride {

/// APM's penalised values of a population, with its scratch (allocated once for a population size).
class AdaptivePenalty {
  public:
    /// out[i] <- F(x_i) for the n = f.size() members; `c` holds m + p values per member.
    template <ConstrainedProblem P>
    void operator()(const P& problem, std::span<const double> f, std::span<const double> v, std::span<const double> c,
                    std::span<double> out) {
        const std::size_t k = problem.constraint_counts().total();
        members_.clear();
        for (std::size_t i = 0; i < f.size(); ++i) {
            if (std::isfinite(f[i]) && std::isfinite(v[i]))
                members_.push_back(i);
            else
                out[i] = kInf;
        }
        const auto n = static_cast<Eigen::Index>(members_.size());
        if (violations_.rows() != static_cast<Eigen::Index>(k) || violations_.cols() != n)
            violations_.resize(static_cast<Eigen::Index>(k), n);
        values_.resize(members_.size());
        penalised_.resize(members_.size());
        one_.assign(k, 0.0);
        for (std::size_t j = 0; j < members_.size(); ++j) {
            const std::size_t i = members_[j];
            values_[j] = f[i];
            for (std::size_t q = 0; q < k; ++q) {
                one_[q] = c[i * k + q];
                violations_(static_cast<Eigen::Index>(q), static_cast<Eigen::Index>(j)) = problem.violation(one_);
                one_[q] = 0.0;
            }
        }
        constraints::adaptive_penalty(values_, violations_, penalised_);
        for (std::size_t j = 0; j < members_.size(); ++j)
            out[members_[j]] = std::isnan(penalised_[j]) ? kInf : penalised_[j];  // an overflow's inf * 0
    }

  private:
    std::vector<std::size_t> members_;
    std::vector<double> values_, penalised_, one_;
    Matrix violations_;
};

}  // namespace pride

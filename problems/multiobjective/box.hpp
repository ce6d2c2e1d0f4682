#pragma once
// What every multi-objective box problem here shares: its box, its number of
// objectives, and the limits on their sizes. Each problem is then one small class adding its
// formula (zdt.hpp, dtlz.hpp); fronts.hpp samples their analytic Pareto fronts.
#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "framework/error.hpp"

namespace pride::multiobjective {

/// The largest number of variables of a problem (its bounds take 16 bytes a variable).
inline constexpr std::size_t kMaxVariables = 1'000'000;
/// The largest number of objectives (DTLZ is defined for any M; many-objective studies use up to 15).
inline constexpr std::size_t kMaxObjectives = 10'000;

class MultiObjectiveBox {
  public:
    /// `n` variables in [lo, hi] each, `objectives` objectives; `where` names the problem in errors.
    /// The size is checked before anything is allocated.
    MultiObjectiveBox(std::string_view where, std::size_t n, std::size_t min_n, double lo, double hi,
                      std::size_t objectives)
        : objectives_(objectives) {
        require(n >= min_n, std::string(where),
                "needs n >= " + std::to_string(min_n) + " variables, got " + std::to_string(n));
        require(n <= kMaxVariables, std::string(where),
                "is built up to n = " + std::to_string(kMaxVariables) + " variables, got " + std::to_string(n));
        lower_.assign(n, lo);
        upper_.assign(n, hi);
    }

    std::size_t dimension() const noexcept { return lower_.size(); }
    std::span<const double> lower() const noexcept { return lower_; }
    std::span<const double> upper() const noexcept { return upper_; }
    std::size_t objectives() const noexcept { return objectives_; }

  protected:
    /// A box that differs in one coordinate (ZDT4's x1).
    void set_bounds(std::size_t i, double lo, double hi) {
        lower_[i] = lo;
        upper_[i] = hi;
    }

  private:
    std::vector<double> lower_;
    std::vector<double> upper_;
    std::size_t objectives_;
};

}  // namespace pride::multiobjective

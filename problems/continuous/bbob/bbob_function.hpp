#pragma once
// What the 24 BBOB function classes share: the box [-5, 5]^D, the instance number, COCO's x_opt
// and f_opt. Each class adds its transformations (built once, in its constructor) and evaluate().
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "problems/continuous/bbob/instance.hpp"
#include "problems/continuous/box_function.hpp"

namespace pride::continuous::bbob {

/// info's optimum fields: x_opt and f_opt depend on the instance (optimum_point(), optimum_value()).
inline constexpr double unknown = std::numeric_limits<double>::quiet_NaN();

/// Base of F1-F24: checks dim >= 2 and instance >= 1 (InputError where "bbob-fN") before building
/// anything, then holds the instance's seed, f_opt and x_opt. Values only, so copies are independent.
class BbobFunction : public BoxFunction {
  public:
    /// COCO's best parameter (for f5 the corner, for f8/f9/f19/f20/f21/f22/f24 its own formula).
    std::vector<double> optimum_point() const { return x_opt_; }
    /// f_opt, the value COCO reports as the optimum.
    double optimum_value() const noexcept { return f_opt_; }
    std::int64_t instance() const noexcept { return instance_; }

  protected:
    BbobFunction(std::size_t dim, std::int64_t instance, const FunctionInfo& info, int id)
        : BoxFunction(checked(dim, instance, info), info),
          instance_(instance),
          seed_(instance_seed(id, instance)),
          f_opt_(compute_fopt(id, instance)) {}

    std::int64_t instance_;
    std::int64_t seed_;  // COCO's rseed
    double f_opt_;
    std::vector<double> x_opt_;

  private:
    static std::size_t checked(std::size_t dim, std::int64_t instance, const FunctionInfo& info) {
        check_arguments(info.name, dim, instance);
        return dim;
    }
};

}  // namespace pride::continuous::bbob

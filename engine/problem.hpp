#pragma once
// A problem built once from its spec: a campaign builds each once (maps parsed once, reachability
// and encodings' tables computed once) and copies it into every run, so runs never share state.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "engine/specs.hpp"

namespace pride::engine {

struct Prepared;  // engine/prepared.hpp

/// A problem ready to run: every check of its spec done, every table built.
class Problem {
  public:
    /// Throws InputError naming the field of the spec that is wrong.
    explicit Problem(const ProblemSpec& spec);

    bool is_grid() const;
    /// A grid problem whose objective is a sum of step and turn costs (the oracle's objectives).
    bool additive() const;
    /// A grid problem whose objective has an exact optimum: every additive one (the oracle) and
    /// iqga (over the 3-D Pareto front).
    bool has_optimum() const;
    /// The same grid problem with the exact optimum computed beside every run (GridSpec::oracle),
    /// without building it again; InputError when the objective has none.
    Problem with_oracle() const;
    /// The dimension of the box an algorithm searches (grids: of the encoding's genotype; chains: 0).
    std::size_t dimension() const;
    const ProblemSpec& spec() const;
    /// The problem's display name: the function, "grid" or the callback's name.
    std::string name() const;
    /// A continuous function's instance (0: as defined; BBOB: COCO's, from 1); 0 for others.
    std::int64_t instance() const;
    /// A continuous function's known minimum at this instance and dimension (for targets).
    std::optional<double> optimum_value() const;

    const Prepared& prepared() const { return *prepared_; }
    /// What a run of `algorithm` plans on: on a grid, the encoding, connector and init the run
    /// names, else the problem's, else the algorithm's native encoding (built once per plan and
    /// shared by the problem's copies); the problem itself otherwise. InputError for a space the
    /// algorithm cannot use.
    std::shared_ptr<const Prepared> planned_for(const AlgorithmSpec& algorithm) const;

  private:
    struct Variants;
    explicit Problem(std::shared_ptr<const Prepared> prepared);
    std::shared_ptr<const Prepared> prepared_;
    std::shared_ptr<Variants> variants_;
};

}  // namespace pride::engine

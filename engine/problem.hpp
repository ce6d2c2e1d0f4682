#pragma once
// A problem built once from its spec: a campaign builds each once (maps parsed once, reachability
// and encodings' tables computed once) and copies it into every run, so runs never share state.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/grid_names.hpp"
#include "engine/specs.hpp"
#include "problems/grid/path.hpp"

namespace pride::engine {

struct Prepared;  // engine/prepared.hpp

/// A problem ready to run: every check of its spec done, every table built.
class Problem {
  public:
    /// Throws InputError naming the field of the spec that is wrong.
    explicit Problem(const ProblemSpec& spec);

    bool is_grid() const;
    /// A grid searched on cell chains (the chain encoding); dimension() is then 0.
    bool is_chain() const;
    /// M: 1, or the number of objectives of a problem of several (ContinuousSpec::objectives,
    /// GridSpec::objectives, CallbackSpec::objectives).
    std::size_t objectives() const;
    /// f1, f2, ... for boxes; the criteria's names (length, turns, angle_penalty, clearance) on grids;
    /// empty for one objective.
    std::vector<std::string> objective_names() const;
    /// The reference front of a problem of several objectives (M rows, one column per point),
    /// computed once and shared by copies: the analytic front sampled with at most
    /// reference_points points (catalog problems), or the grid's exact front (ParetoSearch).
    /// InputError for a callback or one objective (none), and when a grid's front does not fit in
    /// memory.
    const Matrix& reference_front() const;
    static constexpr std::size_t reference_points = 1000;
    /// On grids, the exact front's paths, in the columns' order (after reference_front()).
    const std::vector<grid::Path>& reference_paths() const;
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
    /// The problem's display name: the function (a catalog problem of several objectives: as the
    /// catalog names it), "grid" or the callback's name.
    std::string name() const;
    /// A continuous function's instance (0: as defined; BBOB and bbob-constrained: COCO's, from 1); 0
    /// for others.
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

/// The constrained suites' problems by name (CEC 2006, CEC 2020 real-world, COCO's
/// bbob-constrained), each with its constraint counts and dimension, for listings.
const std::vector<NamedItem>& constrained_problems();

}  // namespace pride::engine

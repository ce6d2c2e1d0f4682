#pragma once
// Multi-objective runs: problems with M objectives by name (ZDT, DTLZ), grids with two
// to four criteria searched through the line or free encoding, and a user's function returning M
// values; the multi-objective algorithms of the one registry (engine/registry.hpp,
// Kind::multiobjective); a run's non-dominated set, with its paths on grids; and its quality
// against the problem's reference front (the analytic front sampled, or a grid's exact front).
//
// Indicators are computed on normalised objectives: each objective o maps to (o - ideal) /
// (nadir - ideal), ideal and nadir those of the reference front (a range of 0 counts as 1); the
// hypervolume's reference point is 1.1 in every normalised objective (nadir + 10 % of the range,
// the usual choice: Ishibuchi et al. 2018, "How to specify a reference point in hypervolume
// calculation"), points beyond it contribute nothing; IGD+ (Ishibuchi et al. 2015) is measured
// from the reference front to the set.
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "engine/specs.hpp"
#include "framework/problem.hpp"
#include "problems/grid/path.hpp"

namespace pride::engine {

/// A catalog problem (problems/multiobjective/catalog.hpp): zdt1..zdt6, dtlz1..dtlz7.
struct MoBenchmarkSpec {
    std::string problem;
    std::int64_t dim = 0;         // n; 0: the paper's default
    std::int64_t objectives = 0;  // M; 0: the default (2 for ZDT, 3 for DTLZ)
};

/// A grid searched for several criteria: the map, start and goal, the encoding (line, the
/// default, free, or chain with init walk or sitp), connector, waypoints and corner cutting of
/// `grid` (its objective, weights and oracle are single-objective settings and must be left alone).
struct MoGridSpec {
    GridSpec grid;
    std::string objectives = "length,turns";  // two to four of length, turns, angle, clearance
    std::int64_t clearance_bands = 3;         // B of clearance.hpp
    std::int64_t clearance_width = 1;         // w of clearance.hpp
};

/// A user's function of M objectives on a box: type erasure at this edge only. `batch`, when set,
/// fills the M rows of `values` for every column of `points` in one call and is used instead of
/// `scalar`.
struct MoCallbackSpec {
    std::string name = "callback";
    std::vector<double> lower, upper;
    std::int64_t objectives = 2;
    std::function<void(std::span<const double>, std::span<double>)> scalar;
    std::function<void(MatrixView, Matrix&)> batch;
};

using MoProblemSpec = std::variant<MoBenchmarkSpec, MoGridSpec, MoCallbackSpec>;

/// True when `name` is one of the multi-objective catalog's problems.
bool is_multiobjective_problem(const std::string& name);

struct MoPrepared;  // engine/multiobjective.cpp

/// A multi-objective problem ready to run: built once, copied into every run.
class MoProblem {
  public:
    /// InputError naming the field that is wrong.
    explicit MoProblem(const MoProblemSpec& spec);

    std::string name() const;
    bool is_grid() const;
    /// A grid searched on cell chains (the chain encoding): no box, dimension() is 0.
    bool is_chain() const;
    std::size_t dimension() const;
    std::size_t objectives() const;
    /// f1, f2, ... for boxes; the criteria's names (length, turns, angle_penalty, clearance) on grids.
    std::vector<std::string> objective_names() const;
    /// The reference front (M rows, one column per point), computed once and shared by copies: the
    /// analytic front sampled with at most reference_points points (catalog problems), or the
    /// grid's exact front (ParetoSearch). InputError for a callback (it has none) and when a
    /// grid's front does not fit in memory.
    const Matrix& reference_front() const;
    static constexpr std::size_t reference_points = 1000;
    /// On grids, the exact front's paths, in the columns' order (after reference_front()).
    const std::vector<grid::Path>& reference_paths() const;

    const MoPrepared& prepared() const { return *prepared_; }

  private:
    std::shared_ptr<MoPrepared> prepared_;
};

struct MoRunResult {
    std::string algorithm;
    Matrix f;                       // the non-dominated set's objective values: M rows, one column per point
    Matrix x;                       // their points (grids: genotypes; none on chains)
    std::vector<grid::Path> paths;  // grids: the path of each point
    std::vector<char> feasible;     // grids: whether it is a legal path (no violation)
    std::int64_t evaluations = 0;
    std::int64_t iterations = 0;
    double wall_ms = 0.0;
    std::vector<std::int64_t> history_evaluations;
};

/// The set of a run as a JSON array, one object per point in the result's order: {"f": [...],
/// "x": [...]}, or on grids {"f": [...], "legal": true, "path": [[x, y], ...]} (pride front --json,
/// campaign stores).
std::string front_json(const MoRunResult& r);

/// Every check a run would make, without running: the name, that it is a multi-objective
/// algorithm, its parameters, the budget. InputError naming what is wrong.
void check(const AlgorithmSpec& algorithm, const MoProblem& problem, const Budget& budget);

/// Runs once; the same inputs give the same result, bit for bit (bar wall_ms). A budget without
/// evaluations or iterations gets 10,000 evaluations per variable (grids: 50 iterations).
MoRunResult run(const AlgorithmSpec& algorithm, const MoProblem& problem, const Budget& budget, std::uint64_t seed);

/// A set's quality against the problem's reference front (the header's normalisation).
struct MoQuality {
    std::vector<double> ideal, nadir;         // of the reference front, per objective
    double hypervolume = 0.0;                 // of the set, normalised, reference point 1.1
    double reference_hypervolume = 0.0;       // of the reference front, the same way
    double hypervolume_ratio = 0.0;           // hypervolume / reference_hypervolume
    double igd_plus = 0.0;                    // normalised
    std::optional<std::int64_t> exact_found;  // grids: points of the exact front the set holds
    std::int64_t reference_size = 0;
};

/// InputError("problem", ...) for a problem without a reference front (a callback).
MoQuality quality(const MoProblem& problem, const Matrix& f);

/// Before any run that will be measured: InputError("objectives", ...) when a catalog problem's
/// reference front is beyond an exact hypervolume's bound in its number of objectives
/// (pareto::exact_hypervolume_points), so that nothing runs, and no store is written, for a
/// quality that cannot be computed. Grids (whose exact front is found, not sampled) pass.
void check_quality(const MoProblem& problem);

}  // namespace pride::engine

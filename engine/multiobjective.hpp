#pragma once
// Problems of several objectives are Problems like the others (engine/problem.hpp): a catalog
// problem by name (ZDT, DTLZ: ContinuousSpec), a grid with two to four criteria searched through
// the line, free or chain encoding (GridSpec::objectives), or a user's function returning M values
// (CallbackSpec::objectives). run() (engine/run.hpp) runs the registry's multi-objective
// algorithms (Kind::multiobjective) on them and gives the non-dominated set (RunResult::front),
// with its paths on grids. Here: the set's quality against the problem's reference front (the
// analytic front sampled, or a grid's exact front), and the set as JSON.
//
// Indicators are computed on normalised objectives: each objective o maps to (o - ideal) /
// (nadir - ideal), ideal and nadir those of the reference front (a range of 0 counts as 1); the
// hypervolume's reference point is 1.1 in every normalised objective (nadir + 10 % of the range,
// the usual choice: Ishibuchi et al. 2018, "How to specify a reference point in hypervolume
// calculation"), points beyond it contribute nothing; IGD+ (Ishibuchi et al. 2015) is measured
// from the reference front to the set.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "engine/problem.hpp"
#include "engine/run.hpp"
#include "framework/problem.hpp"

namespace pride::engine {

/// True when `name` is one of the multi-objective catalog's problems.
bool is_multiobjective_problem(const std::string& name);

/// The set of a run as a JSON array, one object per point in the set's order: {"f": [...],
/// "x": [...]}, or on grids {"f": [...], "legal": true, "path": [[x, y], ...]} (pride front --json,
/// campaign stores).
std::string front_json(const Front& front);

/// A set's quality against the problem's reference front (the header's normalisation).
struct FrontQuality {
    std::vector<double> ideal, nadir;         // of the reference front, per objective
    double hypervolume = 0.0;                 // of the set, normalised, reference point 1.1
    double reference_hypervolume = 0.0;       // of the reference front, the same way
    double hypervolume_ratio = 0.0;           // hypervolume / reference_hypervolume
    double igd_plus = 0.0;                    // normalised
    std::optional<std::int64_t> exact_found;  // grids: points of the exact front the set holds
    std::int64_t reference_size = 0;
};

/// InputError("problem", ...) for a problem without a reference front (a callback, one objective).
/// With constraints (`violation`: one per column of f), only the feasible points count: a set
/// with none has hypervolume 0 and an infinite IGD+.
FrontQuality quality(const Problem& problem, const Matrix& f, std::span<const double> violation = {});

/// The multi-objective catalogs' names, comma-separated (for messages).
std::string multiobjective_problem_names();

/// Before any run that will be measured: InputError("objectives", ...) when a catalog problem's
/// reference front is beyond an exact hypervolume's bound in its number of objectives
/// (pareto::exact_hypervolume_points), so that nothing runs, and no store is written, for a
/// quality that cannot be computed. Grids (whose exact front is found, not sampled) pass.
void check_quality(const Problem& problem);

}  // namespace pride::engine

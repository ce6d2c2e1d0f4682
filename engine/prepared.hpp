#pragma once
// A problem as the engine holds it once prepared (engine/problem.cpp): its spec and the targets its
// runs receive. Inside the engine only; front ends hold a Problem.
#include <cstddef>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "engine/specs.hpp"
#include "engine/target.hpp"
#include "framework/error.hpp"

namespace pride::engine {

/// The reference front of a problem of several objectives (M rows, one column per point), made at
/// first use and shared by the problem's copies: the analytic front sampled, or a grid's exact
/// front with its paths.
struct ReferenceFront {
    std::once_flag once;
    Matrix values;
    std::vector<grid::Path> paths;
    std::optional<InputError> error;
};

struct Prepared {
    ProblemSpec spec;
    std::string name;
    std::size_t dimension = 0;
    // What algorithms that evaluate search: a BoxTarget or a ChainTarget (none on a grid whose
    // encoding is chosen per run, or could not be built).
    std::optional<Target> searched;
    // A grid problem itself (a GridTarget): what whole-map algorithms plan on, and what scores the
    // path of every grid run.
    std::optional<Target> whole_grid;
    // Why the grid's encoding could not be built: only runs through it fail; A* and the exact
    // optimum need no encoding.
    std::optional<InputError> encoding_error;

    // Several objectives: their names (f1, f2, ..., or a grid's criteria), the grid's criteria and
    // clearance field, and the reference front; empty for one objective.
    std::vector<std::string> objective_names;
    grid::Criteria criteria{};
    std::shared_ptr<const grid::MapClearance> clearance;
    std::shared_ptr<ReferenceFront> front;

    std::size_t objectives() const { return objective_names.empty() ? 1 : objective_names.size(); }
    const BoxTarget* box() const { return searched ? std::get_if<BoxTarget>(&*searched) : nullptr; }
    const ChainTarget* chain() const { return searched ? std::get_if<ChainTarget>(&*searched) : nullptr; }
    const GridTarget* grid() const { return whole_grid ? std::get_if<GridTarget>(&*whole_grid) : nullptr; }
    const ConstrainedBoxTarget* constrained() const {
        return searched ? std::get_if<ConstrainedBoxTarget>(&*searched) : nullptr;
    }
    const MoBoxTarget* mo_box() const { return searched ? std::get_if<MoBoxTarget>(&*searched) : nullptr; }
    const MoChainTarget* mo_chain() const { return searched ? std::get_if<MoChainTarget>(&*searched) : nullptr; }
    /// Searched on cell chains (the chain encoding), with one objective or several.
    bool on_chains() const { return chain() != nullptr || mo_chain() != nullptr; }
};

/// A continuous function's known minimum at its instance, or a callback's f_opt: the reference of
/// a run's COCO trace.
std::optional<double> optimum_of(const Prepared& p);

/// The checks of a continuous problem's size, before any of it is allocated.
void require_problem_memory(const ContinuousSpec& c);

/// The most constraints of each kind a problem declares.
inline constexpr std::int64_t kMaxConstraints = 1'000'000;

/// The number k of a CEC 2006 problem's name, cec2006-g01 .. cec2006-g24.
std::optional<int> cec2006_number(const std::string& name);
/// The number k of a CEC 2020 real-world problem's name, cec2020rw-rc01 .. cec2020rw-rc57.
std::optional<int> cec2020rw_number(const std::string& name);
/// The number N of a bbob-constrained function's name, bbob-constrained-f1 .. -f54; InputError
/// ("problem", ...) for another number after that prefix.
std::optional<int> bbob_constrained_number(const std::string& name);

/// Whether a callback declares constraints (checked: counts in range, a function for them).
bool has_constraints(const CallbackSpec& cb);

/// Why the grid spec's objective has no exact optimum (for messages).
std::string no_optimum(const GridSpec& g);

// Problems of several objectives (engine/multiobjective.cpp).

/// True for a spec of several objectives: a catalog problem of several (zdt1..dtlz7), a grid with
/// criteria, a callback of M >= 2.
bool several_objectives(const ProblemSpec& spec);
/// Fills `out` (its spec set) with the targets of a problem of several objectives; InputError naming
/// the field that is wrong.
void prepare_several(Prepared& out);
/// The reference front of `p` (InputError for a callback, or a grid's front beyond memory).
const ReferenceFront& reference_front_of(const Prepared& p);

}  // namespace pride::engine

#pragma once
// A problem as the engine holds it once prepared (engine/problem.cpp): its spec and the targets its
// runs receive. Inside the engine only; front ends hold a Problem.
#include <cstddef>
#include <optional>
#include <string>
#include <variant>

#include "engine/specs.hpp"
#include "engine/target.hpp"
#include "framework/error.hpp"

namespace pride::engine {

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

    const BoxTarget* box() const { return searched ? std::get_if<BoxTarget>(&*searched) : nullptr; }
    const ChainTarget* chain() const { return searched ? std::get_if<ChainTarget>(&*searched) : nullptr; }
    const GridTarget* grid() const { return whole_grid ? std::get_if<GridTarget>(&*whole_grid) : nullptr; }
};

/// A continuous function's known minimum at its instance, or a callback's f_opt: the reference of
/// a run's COCO trace.
std::optional<double> optimum_of(const Prepared& p);

/// The checks of a continuous problem's size, before any of it is allocated.
void require_problem_memory(const ContinuousSpec& c);

/// Why the grid spec's objective has no exact optimum (for messages).
std::string no_optimum(const GridSpec& g);

}  // namespace pride::engine

#pragma once
// The grid objectives that are not linear in a path's metrics, as one type, so that every
// algorithm is compiled once for all of them: Zhang et al.'s (2025) iqga, or a user's objective on paths
// (GridSpec::path_objective: from Python, a callable on the path's cells). Type erasure stays at
// this edge: one call of the user's function per evaluation, one predictable branch for iqga.
#include <cmath>
#include <functional>
#include <memory>
#include <string>

#include "framework/error.hpp"

#include "problems/grid/map.hpp"
#include "problems/grid/objectives.hpp"
#include "problems/grid/path.hpp"

namespace pride::engine {

/// A user's objective on legal paths, and optionally its per-step form: the cost of a step in
/// direction d (0..7, as map.hpp numbers them) after a step in direction `previous` (-1 for the
/// first step), >= 0, such that the value of a path is the sum of its steps' costs. With it the
/// exact optimum (`exact`, --oracle) searches over those costs; without it there is none.
struct UserPathObjective {
    std::function<double(const grid::Path&)> value;
    std::function<double(int previous, int direction)> step_cost;
};

struct OtherObjective {
    static constexpr bool additive = false;         // iqga is not; a user's may be (has_steps)
    std::shared_ptr<const UserPathObjective> user;  // empty: iqga

    static OtherObjective iqga() { return {}; }
    double of_path(const grid::Path& path) const {
        return user ? user->value(path) : grid::IqgaObjective{}(grid::metrics(path));
    }
    /// A user's objective with its per-step form: the oracle applies (UserSteps).
    bool has_steps() const noexcept { return user && user->step_cost; }
};

/// The per-step form of a user's objective, as the oracle searches it (oracle.hpp: edge_cost).
struct UserSteps {
    static constexpr bool additive = true;
    const UserPathObjective* user = nullptr;
    double start_cost() const noexcept { return 0.0; }
    double edge_cost(int previous, int direction) const {
        const double c = user->step_cost(previous, direction);
        require(std::isfinite(c) && c >= 0.0, "step_cost",
                "must be a finite number >= 0, got " + std::to_string(c) + " for a step in direction " +
                    std::to_string(direction) + " after " + std::to_string(previous));
        return c;
    }
    /// The value of a legal path as the sum of its steps' costs: what whole-map planners report,
    /// so that they never call the user's objective (every call of it is some run's evaluation).
    double of_path(const grid::Path& path) const {
        double sum = start_cost();
        int previous = -1;
        for (std::size_t i = 1; i < path.size(); ++i) {
            const int d = grid::direction(path[i - 1], path[i]);
            sum += edge_cost(previous, d);
            previous = d;
        }
        return sum;
    }
};

}  // namespace pride::engine

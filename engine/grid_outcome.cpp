#include "engine/grid_outcome.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <optional>
#include <utility>

#include "engine/target.hpp"
#include "framework/error.hpp"
#include "problems/grid/pareto.hpp"
#include "problems/grid/planners/any_angle.hpp"
#include "problems/grid/planners/astar.hpp"
#include "problems/grid/planners/oracle.hpp"

namespace pride::engine {

namespace {

/// The reported value of a whole-map planner's path (not an evaluation: GridProblem::result_value);
/// for a user's objective with per-step costs, their sum, so that the user's function is called
/// by evaluations only (without them, once here).
double grid_value(const GridTarget& target, const grid::Path& path) {
    if (const auto* g = std::get_if<grid::GridProblem<OtherObjective>>(&target.problem))
        if (g->objective().has_steps()) return UserSteps{g->objective().user.get()}.of_path(path);
    return std::visit([&](const auto& g) { return g.result_value(path); }, target.problem);
}

/// A run that beats the exact optimum of a user's objective shows that its per-step costs and its
/// value disagree (the two must agree on every path; checking that with a call of the objective
/// would be a call outside every run's budget).
void check_user_optimum(const GridTarget& target, const GridOutcome& o) {
    const auto* g = std::get_if<grid::GridProblem<OtherObjective>>(&target.problem);
    if (!g || !g->objective().user || !o.optimum || *o.optimum < 0.0 || !o.feasible) return;
    require(o.value >= *o.optimum - 1e-9 * std::max(1.0, std::abs(*o.optimum)), "step_cost",
            fmt::format("the per-step costs give an optimum of {}, but a run found a path the objective values at "
                        "{}: the two must agree on every path",
                        *o.optimum, o.value));
}

}  // namespace

void record_path(GridOutcome& o, const GridTarget& target, const grid::Path& candidate, bool no_violations,
                 double value) {
    std::visit(
        [&](const auto& g) {
            o.feasible = no_violations &&
                         grid::path_violation(g.map(), candidate, g.start(), g.goal(), g.corner_cutting()).empty();
        },
        target.problem);
    if (o.feasible) {
        o.path = candidate;
        o.value = value;
    }
}

namespace {

/// Why a polyline (centre convention) is not a free path from the start's centre to the goal's,
/// or "" when it is: every segment passes any_angle.hpp's test.
std::string polyline_violation(const GridTarget& target, const grid::Polyline& line,
                               const std::vector<grid::Point>& plane) {
    return std::visit(
        [&](const auto& g) -> std::string {
            // The planner's own points when it gave them (x - 0.5 + 0.5 need not give x back).
            const bool own = plane.size() == line.size();
            const auto at = [&](std::size_t i) {
                return own ? plane[i] : grid::Point{line[i].x + 0.5, line[i].y + 0.5};
            };
            if (!(line.front() == grid::PathPoint{double(g.start().x), double(g.start().y)}))
                return "the polyline does not begin at the start";
            if (!(line.back() == grid::PathPoint{double(g.goal().x), double(g.goal().y)}))
                return "the polyline does not end at the goal";
            for (std::size_t i = 1; i < line.size(); ++i)
                if (!grid::segment_is_free(g.map(), at(i - 1), at(i)))
                    return "segment " + std::to_string(i) + " is not free";
            return {};
        },
        target.problem);
}

/// The metrics every path gets, whoever planned it (problems/grid/polyline.hpp), and with `gaps`
/// its gaps to the problem's shortest grid and any-angle lengths (each computed once per problem).
void score_path(GridOutcome& o, const GridTarget& target, bool gaps) {
    if (!o.feasible) return;
    if (o.polyline.empty()) o.polyline = grid::polyline_of(o.path);
    PathScoring& s = *target.scoring;
    std::visit(
        [&](const auto& g) {
            std::call_once(s.scorer_once, [&] { s.scorer.emplace(g.map()); });
            o.metrics = s.scorer->score(o.polyline);
            if (!gaps) return;
            std::call_once(s.lengths_once, [&] {
                grid::AStar astar;
                s.grid_length = astar.search(g.map(), g.start(), g.goal(), nullptr, nullptr, g.corner_cutting());
                grid::AnyAngleOracle oracle(g.map());
                s.any_angle_length = oracle.solve(g.start(), g.goal());
            });
        },
        target.problem);
    if (!gaps) return;
    const double length = o.metrics.length;
    // A length equal to the shortest to 1e-9 (relative) is the optimum: its gap is exactly 0.
    const auto gap = [&](double shortest) -> std::optional<double> {
        if (shortest < 0.0) return std::nullopt;
        if (std::abs(length - shortest) <= 1e-9 * std::max(1.0, shortest)) return 0.0;
        return shortest > 0.0 ? std::optional<double>(length / shortest - 1.0) : std::nullopt;
    };
    if (s.grid_length >= 0.0) o.shortest_grid_length = s.grid_length;
    if (s.any_angle_length >= 0.0) o.shortest_any_angle_length = s.any_angle_length;
    o.grid_gap = gap(s.grid_length);
    o.any_angle_gap = gap(s.any_angle_length);
}

}  // namespace

double record_solution(GridOutcome& o, const GridTarget& target, GridSolution& s, bool polylines) {
    if (polylines) {
        // Checked as a chain is: a polyline that leaves the free plane is never a result.
        o.feasible = !s.polyline.empty() && polyline_violation(target, s.polyline, s.plane).empty();
        if (o.feasible) {
            o.polyline = std::move(s.polyline);
            for (std::size_t i = 1; i < o.polyline.size(); ++i)
                o.value += std::hypot(o.polyline[i].x - o.polyline[i - 1].x, o.polyline[i].y - o.polyline[i - 1].y);
            // Start = goal: the one-vertex polyline is also the one-cell path, given as A* gives it.
            if (o.polyline.size() == 1)
                o.path = std::visit([](const auto& g) { return grid::Path{g.start()}; }, target.problem);
        }
        return o.feasible ? o.value : std::numeric_limits<double>::infinity();
    }
    o.feasible = true;
    o.path = std::move(s.path);
    o.value = grid_value(target, o.path);
    return o.value;
}

void score_outcome(GridOutcome& o, const GridTarget& target, bool gaps) {
    check_user_optimum(target, o);
    score_path(o, target, gaps);
}

double grid_optimum(const GridTarget& target, grid::Path* out) {
    if (!target.additive()) {
        const auto& g = std::get<grid::GridProblem<OtherObjective>>(target.problem);
        if (g.objective().user) {  // a user's objective: the oracle on its per-step costs
            require(g.objective().has_steps(), "objective",
                    "a user's objective without per-step costs (step_cost) has no exact optimum");
            grid::Oracle oracle;
            grid::Path path;
            const double optimum = oracle.solve(g.map(), g.start(), g.goal(), UserSteps{g.objective().user.get()},
                                                &path, g.corner_cutting());
            // Not checked here against the objective (a call outside every budget): runs that beat
            // it are refused (check_user_optimum).
            if (out && optimum >= 0.0) *out = std::move(path);
            return optimum;
        }
        FrontOptimum& cached = *target.front_optimum;
        std::call_once(cached.once, [&] {
            cached.value = grid::iqga_optimum(g.map(), g.start(), g.goal(), g.corner_cutting(), &cached.path);
        });
        if (!cached.value) return -1.0;
        if (out) *out = cached.path;
        return *cached.value;
    }
    return std::visit(
        [&](const auto& gp) {
            double optimum = -1.0;
            if constexpr (std::decay_t<decltype(gp.objective())>::additive) {
                grid::Oracle oracle;
                optimum = oracle.solve(gp.map(), gp.start(), gp.goal(), gp.objective(), out, gp.corner_cutting());
            }
            return optimum;
        },
        target.problem);
}

}  // namespace pride::engine

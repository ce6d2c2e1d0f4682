#include "engine/run.hpp"

#include <fmt/format.h>
#include <sys/resource.h>
#include <unistd.h>
#include <map>
#include <mutex>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

#include "engine/multiobjective.hpp"
#include "engine/registry.hpp"
#include "engine/targets.hpp"
#include "framework/error.hpp"
#include "framework/parallel.hpp"
#include "problems/grid/map_io.hpp"
#include "problems/grid/pareto.hpp"
#include "problems/grid/planners/any_angle.hpp"
#include "problems/grid/planners/astar.hpp"
#include "problems/grid/planners/oracle.hpp"

namespace pride::engine {

struct Prepared {
    ProblemSpec spec;
    std::string name;
    std::size_t dimension = 0;
    std::optional<BoxTarget> box;
    std::optional<ChainTarget> chain;
    std::optional<GridTarget> grid;
    // Why the grid's encoding could not be built: only runs through it fail; A* and the exact
    // optimum need no encoding.
    std::optional<InputError> encoding_error;
};

// ---------------------------------------------------------------------------------------------
// Names

const std::vector<NamedItem>& grid_objectives() {
    static const std::vector<NamedItem> items{
        {"cells", "grids: number of cells, start and goal included (Wan and Gao 2022, eq. 13)"},
        {"length", "grids: sum of step lengths, 1 or sqrt(2) (Zhang et al. 2025, eq. 8)"},
        {"weighted", "grids: w_len length + w_turn turns + w_angle angle_penalty (--weights, default 1,1,0.1)"},
        {"iqga", "grids: -(1/length + 1/angle_penalty + 1/turns) (Zhang et al. 2025, eq. 12)"},
        {"hswoa", "grids: length + lambda turns (Cai and Du 2021; --lambda, default 1)"}};
    return items;
}

const std::vector<NamedItem>& grid_encodings() {
    static const std::vector<NamedItem> items{
        {"line", "grids: one gene per row (or column) between start and goal, the waypoint's cross coordinate"},
        {"free", "grids: 2K genes, K waypoints (x, y) anywhere on the map (--waypoints K, default 3)"},
        {"chain",
         "grids: the cell chain itself, with crossover at a common cell and segment-regenerating mutation (ga, "
         "ga-plus)"}};
    return items;
}

const std::vector<NamedItem>& grid_connectors() {
    static const std::vector<NamedItem> items{
        {"repair", "grids (line, free): a blocked join becomes the shortest legal detour (A* in a growing window)"},
        {"penalty", "grids (line, free): the straight cell line; each violation costs M >= 10 W H"}};
    return items;
}

const std::vector<NamedItem>& grid_inits() {
    static const std::vector<NamedItem> items{
        {"uniform", "uniform genotypes in the box"},
        {"walk", "genotypes read off goal-biased random walks with taboo list"},
        {"rules", "genotypes read off Wan and Gao's (2022) rough-set rule walks"},
        {"sitp", "genotypes or chains from Zhang et al.'s (2025) SITP walks (eqs. 3-7)"}};
    return items;
}

namespace {

bool known(const std::vector<NamedItem>& items, const std::string& name) {
    for (const auto& i : items)
        if (i.name == name) return true;
    return false;
}

std::string choices(const std::vector<NamedItem>& items) {
    std::string s;
    for (std::size_t i = 0; i < items.size(); ++i)
        s += (i == 0 ? "" : i + 1 == items.size() ? " or " : ", ") + items[i].name;
    return s;
}

// ---------------------------------------------------------------------------------------------
// Preparing problems

}  // namespace

void check_grid_names(const GridSpec& g) {
    // "user": a user's objective on paths, given as GridSpec::path_objective (Python: a callable).
    require(g.objective == "user" || known(grid_objectives(), g.objective), "objective",
            "unknown objective '" + g.objective + "' (" + choices(grid_objectives()) + ")");
    require((g.objective == "user") == (g.path_objective && g.path_objective->value), "objective",
            g.objective == "user" ? "user needs the objective's function (a callable on paths)"
                                  : "a function on paths comes with the objective user, not " + g.objective);
    // No encoding: each run plans on its algorithm's own, or its native one (planned_grid).
    require(g.encoding.empty() || known(grid_encodings(), g.encoding), "encoding",
            "unknown encoding '" + g.encoding + "' (" + choices(grid_encodings()) + ")");
    require(known(grid_connectors(), g.connector), "connector",
            "unknown connector '" + g.connector + "' (" + choices(grid_connectors()) + ")");
    require(g.encoding != "chain" || g.connector == "repair", "connector",
            "chains need no connector: every operator keeps them legal");
    require(g.waypoints >= 1 && g.waypoints <= 1000, "waypoints",
            "must be in [1, 1000], got " + std::to_string(g.waypoints));
    require(g.init.empty() || known(grid_inits(), g.init), "init",
            "expected uniform, walk, rules or sitp, got '" + g.init + "'");
    require(g.init != "rules" || g.encoding != "chain", "init " + g.init,
            "only for the line and free encodings (chains start from random walks, or SITP walks with init sitp)");
    require(g.weights.empty() || g.objective == "weighted", "weights", "only for the weighted objective");
    require(!g.lambda || g.objective == "hswoa", "lambda", "only for the hswoa objective");
}

namespace {

void check_grid_spec(const GridSpec& g) {
    check_grid_names(g);
    require(g.map != nullptr, "map", "no map given");
}

grid::LinearObjective linear_objective(const GridSpec& g) {
    if (g.objective == "cells") return grid::LinearObjective::of(grid::CellsObjective{});
    if (g.objective == "length") return grid::LinearObjective::of(grid::LengthObjective{});
    if (g.objective == "weighted") {
        grid::WeightedObjective w;
        if (!g.weights.empty()) {
            require(g.weights.size() == 3, "weights",
                    "expected L,T,A (three weights), got " + std::to_string(g.weights.size()));
            for (const double w : g.weights)
                require(std::isfinite(w) && w >= 0 && w <= max_weight, "weights",
                        fmt::format("each weight must be a finite number in [0, {}], got {}", max_weight, w));
            w.w_len = g.weights[0];
            w.w_turn = g.weights[1];
            w.w_angle = g.weights[2];
        }
        w.validate();
        return grid::LinearObjective::of(w);
    }
    grid::HswoaObjective h;
    h.lambda = g.lambda.value_or(h.lambda);
    require(std::isfinite(h.lambda) && h.lambda >= 0 && h.lambda <= max_weight, "lambda",
            fmt::format("must be a finite number in [0, {}], got {}", max_weight, h.lambda));
    h.validate();
    return grid::LinearObjective::of(h);
}

/// Why the objective has no exact optimum.
std::string no_optimum(const GridSpec& g) {
    return g.objective == "user" ? "the user objective has no per-step costs (step_cost)"
                                 : "the " + g.objective + " objective is not a sum of step and turn costs";
}

void require_oracle(const GridSpec& g, const GridTarget& target) {
    require(target.has_optimum(), "oracle", no_optimum(g) + ", so it has no exact oracle");
}

template <class Objective>
void prepare_grid(Prepared& out, const GridSpec& g, Objective objective) {
    grid::GridProblem<Objective> problem(g.map, g.start, g.goal, objective, g.corner_cutting);
    problem.count_calls(g.objective_calls);
    out.grid = GridTarget{problem};
    if (g.oracle) require_oracle(g, *out.grid);
    if (g.encoding.empty()) return;  // planned per run (planned_grid): A* and exact need none
    try {
        if (g.encoding == "chain") {
            grid::ChainSpace<Objective> space(problem);
            if (g.init == "sitp") space.set_init(grid::Walks::sitp);
            out.chain = ChainTarget{std::move(space)};
            return;
        }
        const grid::SelectableConnector connector(g.connector == "repair" ? grid::SelectableConnector::Kind::repair
                                                                          : grid::SelectableConnector::Kind::penalty);
        // The problem's suggestions come from rule walks unless random or SITP walks are asked for.
        grid::GridProblem<Objective> suggesting = problem;
        suggesting.set_walks(g.init == "walk"   ? grid::Walks::random
                             : g.init == "sitp" ? grid::Walks::sitp
                                                : grid::Walks::rules);
        if (g.encoding == "line") {
            grid::LineEncoding<grid::SelectableConnector> e(problem, connector);
            out.dimension = e.dimension(problem);
            out.box = BoxTarget{GridLine<Objective>(std::move(suggesting), std::move(e))};
        } else {
            grid::FreeEncoding<grid::SelectableConnector> e(problem, static_cast<int>(g.waypoints), connector);
            out.dimension = e.dimension(problem);
            out.box = BoxTarget{GridFree<Objective>(std::move(suggesting), std::move(e))};
        }
    } catch (const InputError& e) {
        out.encoding_error = e;
    }
}

/// The checks of a continuous problem's size, before any of it is allocated.
void require_problem_memory(const ContinuousSpec& c) {
    const auto* item = continuous::catalog().find(c.function);
    require(item != nullptr || !is_multiobjective_problem(c.function), "problem",
            c.function + " has several objectives: its runs are multi-objective ones (pride front, pride.front)");
    require(item != nullptr, "problem", "unknown problem '" + c.function + "'");
    require(c.dim >= 1 && c.dim <= max_budget, "dim",
            fmt::format("must be an integer in [1, {}], got {}", max_budget, c.dim));
    // Bounds, an optimum and scratch vectors per coordinate, and a rotation (dim^2) for an
    // instance that has one.
    const double n = static_cast<double>(c.dim);
    const bool rotated = c.instance.value_or(continuous::default_instance(item->entry)) != 0;
    require_memory(8.0 * (8.0 * n + (rotated ? 2.0 * n * n : 0.0)), "dim",
                   fmt::format("{} in dimension {}", c.function, c.dim));
}

std::shared_ptr<const Prepared> prepare(const ProblemSpec& spec) {
    auto out = std::make_shared<Prepared>();
    out->spec = spec;
    if (const auto* c = std::get_if<ContinuousSpec>(&spec)) {
        require_problem_memory(*c);
        out->name = c->function;
        out->dimension = static_cast<std::size_t>(c->dim);
        out->box = BoxTarget{continuous::make_function(c->function, c->dim, c->instance)};
    } else if (const auto* g = std::get_if<GridSpec>(&spec)) {
        check_grid_spec(*g);
        out->name = "grid";
        if (g->objective == "user")
            prepare_grid(*out, *g, OtherObjective{g->path_objective});
        else if (g->objective == "iqga")
            prepare_grid(*out, *g, OtherObjective::iqga());
        else
            prepare_grid(*out, *g, linear_objective(*g));
    } else {
        const auto& cb = std::get<CallbackSpec>(spec);
        require(!cb.f_opt || std::isfinite(*cb.f_opt), "f_opt", "must be a finite number");
        out->name = cb.name;
        out->dimension = cb.lower.size();
        out->box = BoxTarget{CallbackProblem(cb.name, cb.lower, cb.upper, cb.scalar, cb.batch, cb.thread_safe)};
    }
    return out;
}

/// A grid problem's variant planned on another encoding, connector or init (Problem::planned_for):
/// the same grid target (its tables and its cached optimum), the encoding's target built anew.
void prepare_plan(Prepared& v, const GridSpec& plan) {
    check_grid_spec(plan);
    const GridTarget grid = *v.grid;
    if (plan.objective == "user")
        prepare_grid(v, plan, OtherObjective{plan.path_objective});
    else if (plan.objective == "iqga")
        prepare_grid(v, plan, OtherObjective::iqga());
    else
        prepare_grid(v, plan, linear_objective(plan));
    v.grid = grid;
}

// ---------------------------------------------------------------------------------------------
// Running

/// The parameters as the run sees them: the user's, plus what the problem decides (on grids the
/// papers' N = 20 unless a population is given, AlgorithmEntry::grid_population: 40 for iqga; the
/// grid spec's init sets walk_init, and on chains the `sitp` flag of an entry that has one: SITP
/// walks unless the spec asks for other initial chains).
ParamValues effective_params(const AlgorithmEntry& entry, const Prepared& p, const ParamValues& given) {
    ParamValues v = given;
    const auto* g = std::get_if<GridSpec>(&p.spec);
    if (!g || entry.whole_map()) return v;
    if (entry.param("pop") && !v.contains("pop")) v.set("pop", static_cast<double>(entry.grid_population));
    if (!g->init.empty() && g->encoding == "chain" && entry.param("sitp") && !v.contains("sitp"))
        v.set("sitp", g->init == "sitp" ? 1.0 : 0.0);
    if (!g->init.empty() && g->encoding != "chain") {
        if (entry.param("walk_init"))
            v.set("walk_init", g->init == "uniform" ? 0.0 : 1.0);
        else
            require(g->init == "uniform", "init " + g->init, entry.name + " starts from one uniform point");
    }
    return v;
}

/// Checks that the algorithm runs on the problem's space; returns the checked parameters.
Params checked(const AlgorithmEntry& entry, const Prepared& p, const AlgorithmSpec& a) {
    require(!entry.multiobjective(), "algo",
            entry.name + " is a multi-objective algorithm; " + p.name +
                " has one objective (its problems: zdt1-zdt6, dtlz1-dtlz7, grids with several objectives)");
    const Params params(entry.name, entry.params, effective_params(entry, p, a.params));
    const auto* g = std::get_if<GridSpec>(&p.spec);
    auto refuse_chain_settings = [&](const std::string& space) {
        for (const auto& spec : entry.params)
            require(!spec.chain_only || !params.given(spec.name), entry.name,
                    spec.name + " is a setting of the chain space (the chain encoding); it has no meaning on " + space);
    };
    if (!g) {
        require(static_cast<bool>(entry.run_box), "algo", entry.name + " works on grid problems only");
        refuse_chain_settings("a box");
        for (const auto& spec : entry.params)
            require(!spec.grid_only || !params.given(spec.name), entry.name,
                    spec.name + " says how a grid is planned on; it has no meaning on " + p.name);
        return params;
    }
    if (entry.whole_map()) {
        require(!entry.needs_optimum || p.grid->has_optimum(), "objective",
                no_optimum(*g) + ", so " + entry.name + " has no optimum to find");
        require(!entry.plans_polylines || g->objective == "length", "objective",
                entry.name + " plans polylines, whose value is their length: it runs on the length objective, not " +
                    g->objective);
        // Its polylines never pass between two blocked cells that touch at a corner: a setting it
        // cannot honour is refused, never ignored.
        require(!entry.plans_polylines || !g->corner_cutting, "corner_cutting",
                entry.name +
                    " plans polylines in the free plane, which has no corner cutting (leave it off, or plan "
                    "with astar)");
        return params;
    }
    if (p.encoding_error) throw *p.encoding_error;
    if (g->encoding == "chain") {
        if (!entry.run_chain) {
            std::string on_chains;
            for (const auto& e : algorithms().entries())
                if (e.run_chain) on_chains += (on_chains.empty() ? "" : ", ") + e.name;
            throw InputError("encoding chain",
                             entry.name + " does not run on chains; the chain encoding takes " + on_chains);
        }
        for (const auto& spec : entry.params)
            require(!spec.box_only || !params.given(spec.name), entry.name,
                    spec.name + " has no meaning on chains (the chain encoding)");
    } else {
        require(static_cast<bool>(entry.run_box), "algo", entry.name + " does not run on a box");
        refuse_chain_settings("the " + g->encoding + " encoding");
    }
    return params;
}

/// One part of what a run allocates, named as the message names it when the whole is too much.
struct MemoryPart {
    double bytes = 0.0;
    std::string where, what;
};

/// What a run will allocate, checked against the machine's memory before anything is: the
/// algorithm's own (its entry's estimate), the history (one value and one count per iteration the
/// budget allows) and, on grids, per cell of the map: the oracle's states when the run computes
/// the optimum (9 per cell, 20 bytes each: g, parent, two stamps), A*'s records (16 bytes), and
/// the decode scratch of each copy of a line or free encoding (the loop-free chain 24, the repair
/// connector's A* 16, a walk's marks 4; one copy per thread). The oracle and the run come one after
/// the other, so the larger of the two counts. Too much names the largest part.
void check_run_memory(const AlgorithmEntry& entry, const Params& params, const Prepared& p,
                      const Termination& termination, std::int64_t threads) {
    std::vector<MemoryPart> parts;
    double cells = 0.0;
    std::string map_size;
    if (p.grid)
        std::visit(
            [&](const auto& g) {
                cells = static_cast<double>(g.map().size());
                map_size = fmt::format("{} x {}", g.map().width(), g.map().height());
            },
            p.grid->problem);
    MemoryPart run;
    if (entry.whole_map()) {
        if (entry.memory)
            run = {entry.memory(params, static_cast<std::size_t>(cells)), entry.name,
                   fmt::format("{} on a {} map", entry.name, map_size)};
    } else {
        // A chain holds no cell twice (every operator cuts loops), so the map's cells bound its length.
        const std::size_t dimension = p.chain ? static_cast<std::size_t>(cells) + 8 : p.dimension;  // + a vector's own
        const std::string where =
            p.chain ? fmt::format("on chains of up to {} cells", dimension) : fmt::format("in dimension {}", dimension);
        run.where = entry.name;
        run.what = entry.param("pop") ? fmt::format("a run with population {} {}", params.integer("pop"), where)
                                      : fmt::format("a run {}", where);
        if (entry.memory) run.bytes = entry.memory(params, dimension);
        if (p.grid && !p.chain) {
            run.bytes += 44.0 * cells * static_cast<double>(threads);
            run.what += fmt::format(" on a {} map", map_size);
        }
        const auto pop = entry.param("pop") ? params.integer("pop") : 1;
        if (const auto t = termination.horizon(pop, pop))
            parts.push_back({16.0 * static_cast<double>(*t + 1),
                             termination.max_iterations ? "iterations" : "evaluations",
                             fmt::format("the history of {} iterations", *t)});
    }
    const auto& g = p.grid ? &std::get<GridSpec>(p.spec) : nullptr;
    if (g && (g->oracle || entry.needs_optimum) && p.grid->additive_or_steps()) {
        const MemoryPart oracle{180.0 * cells, g->oracle ? "oracle" : entry.name,
                                fmt::format("the exact optimum on a {} map", map_size)};
        if (oracle.bytes > run.bytes) run = oracle;
    }
    if (g)  // the path scorer's distance field, and with path_gaps A*'s and the any-angle oracle's arrays
        parts.push_back({(8.0 + (g->path_gaps ? 56.0 : 0.0)) * cells, g->path_gaps ? "path_gaps" : "map",
                         fmt::format("scoring the paths{} on a {} map",
                                     g->path_gaps ? " and their shortest lengths" : "", map_size)});
    parts.push_back(std::move(run));
    // The run's own part is blamed first when it alone is too much (a default budget grows the
    // history with the dimension the user chose), then the history (a huge --iters), else the
    // largest part.
    std::reverse(parts.begin(), parts.end());
    const double have = available_memory();
    double total = 0.0;
    const MemoryPart* largest = &parts.front();
    for (const MemoryPart& part : parts) total += part.bytes;
    for (const MemoryPart& part : parts)
        if (part.bytes > have) {
            largest = &part;
            break;
        } else if (part.bytes > largest->bytes) {
            largest = &part;
        }
    require(total <= have, largest->where,
            fmt::format(
                "{} needs about {}{} of memory, more than the {} this machine has", largest->what,
                format_bytes(largest->bytes),
                largest->bytes < 0.99 * total ? fmt::format(" ({} with the rest of the run)", format_bytes(total)) : "",
                format_bytes(have)));
}

template <class R>
void copy_run(RunResult& out, R&& r) {
    out.best_f = r.best_f;
    out.evaluations = r.evaluations;
    out.iterations = r.iterations;
    out.wall_ms = r.wall_ms;
    out.history = std::move(r.history);
    out.history_evaluations = std::move(r.history_evaluations);
    out.target_hits = std::move(r.target_hits);
    out.trace_targets = std::move(r.trace_targets);
    out.trace_evaluations = std::move(r.trace_evaluations);
    out.checkpoints = std::move(r.checkpoints);
}

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

/// The candidate is the result only when it is legal (grid.md: an infeasible candidate is never
/// returned as a result). `value` is its objective, known from the run's own evaluation: the
/// objective is not called again to report it (a user counting its calls sees the run's only).
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

/// The prepared variants of one grid problem, by how a run plans on it (encoding, connector,
/// init), shared by the problem's copies and built once each.
struct Problem::Variants {
    std::mutex mutex;
    std::map<std::string, std::shared_ptr<const Prepared>> by_plan;
};

Problem::Problem(const ProblemSpec& spec) : Problem(prepare(spec)) {}
Problem::Problem(std::shared_ptr<const Prepared> prepared)
    : prepared_(std::move(prepared)), variants_(std::make_shared<Variants>()) {}

namespace {

/// The grid a run of `entry` plans on: the encoding, connector and init the run names (its
/// parameters), else the problem's, else the algorithm's native encoding (its paper's space).
/// A space the algorithm cannot use is refused, naming the ones it can.
GridSpec planned_grid(const AlgorithmEntry& entry, const GridSpec& g, const ParamValues& given) {
    GridSpec out = g;
    if (entry.whole_map()) return out;
    auto named = [&](const char* key) -> const std::string* {
        const auto it = given.names().find(key);
        if (it == given.names().end()) return nullptr;
        // A name among no choice is refused here; an encoding the algorithm cannot use, below,
        // with the ones it can.
        const bool encoding = std::string_view(key) == "encoding" && known(grid_encodings(), it->second);
        if (const ParamSpec* spec = entry.param(key); spec && !encoding) spec->choice_index(it->second, entry.name);
        return &it->second;
    };
    const std::string* encoding = named("encoding");
    if (encoding) out.encoding = *encoding;
    if (out.encoding.empty()) out.encoding = entry.native_encoding;
    if (const std::string* c = named("connector")) out.connector = *c;
    if (const std::string* i = named("init")) out.init = *i;
    if (out.encoding == "chain") out.connector = "repair";  // chains need none: the problem's is for line and free
    const auto can = entry.encodings();
    if (std::find(can.begin(), can.end(), out.encoding) == can.end()) {
        std::string list;
        for (std::size_t k = 0; k < can.size(); ++k)
            list += (k == 0 ? "" : k + 1 == can.size() ? " or " : ", ") + can[k];
        throw InputError("encoding " + out.encoding, entry.name + " runs on " + list + ", not on " + out.encoding +
                                                         ": name no encoding (" + entry.name + "'s own is " +
                                                         entry.native_encoding + ") or choose another algorithm");
    }
    return out;
}

}  // namespace

std::shared_ptr<const Prepared> Problem::planned_for(const AlgorithmSpec& algorithm) const {
    const auto* g = std::get_if<GridSpec>(&prepared_->spec);
    if (!g) return prepared_;
    const AlgorithmEntry& entry = algorithms().at(algorithm.name);
    const GridSpec plan = planned_grid(entry, *g, algorithm.params);
    if (plan.encoding == g->encoding && plan.connector == g->connector && plan.init == g->init) return prepared_;
    const std::string key = plan.encoding + "|" + plan.connector + "|" + plan.init;
    const std::lock_guard lock(variants_->mutex);
    auto& variant = variants_->by_plan[key];
    if (!variant) {
        auto v = std::make_shared<Prepared>(*prepared_);
        v->spec = plan;
        v->box.reset();
        v->chain.reset();
        v->encoding_error.reset();
        v->dimension = 0;
        prepare_plan(*v, plan);
        variant = std::move(v);
    }
    return variant;
}

bool Problem::is_grid() const {
    return prepared_->grid.has_value();
}
bool Problem::additive() const {
    return prepared_->grid && prepared_->grid->additive();
}
bool Problem::has_optimum() const {
    return prepared_->grid && prepared_->grid->has_optimum();
}
Problem Problem::with_oracle() const {
    const auto* g = std::get_if<GridSpec>(&prepared_->spec);
    require(g != nullptr, "oracle", "only grid problems have an exact optimum");
    require_oracle(*g, *prepared_->grid);
    auto copy = std::make_shared<Prepared>(*prepared_);  // the targets share their tables
    std::get<GridSpec>(copy->spec).oracle = true;
    return Problem(std::move(copy));
}
std::size_t Problem::dimension() const {
    return prepared_->dimension;
}
const ProblemSpec& Problem::spec() const {
    return prepared_->spec;
}
std::string Problem::name() const {
    return prepared_->name;
}
std::int64_t Problem::instance() const {
    const auto* f = prepared_->box ? std::get_if<continuous::Function>(&prepared_->box->problem) : nullptr;
    return f ? f->instance() : 0;
}
namespace {
std::optional<double> optimum_of(const Prepared& p) {
    if (const auto* cb = std::get_if<CallbackSpec>(&p.spec)) return cb->f_opt;
    const auto* f = p.box ? std::get_if<continuous::Function>(&p.box->problem) : nullptr;
    if (!f) return std::nullopt;
    const double v = f->optimum_value();
    return std::isfinite(v) ? std::optional<double>(v) : std::nullopt;
}
}  // namespace

std::optional<double> Problem::optimum_value() const {
    return optimum_of(*prepared_);
}

Termination Budget::termination(std::size_t dimension, bool grid) const {
    Termination t;
    if (iterations) {
        require(*iterations >= 0 && *iterations <= max_budget, "iterations",
                fmt::format("must be in [0, {}], got {}", max_budget, *iterations));
        t = t | max_iterations(*iterations);
    }
    if (evaluations) {
        require(*evaluations >= 1 && *evaluations <= max_budget, "evaluations",
                fmt::format("must be in [1, {}], got {}", max_budget, *evaluations));
        t = t | max_evaluations(*evaluations);
    }
    if (!evaluations && !iterations) {
        if (grid)
            t = max_iterations(50);  // the papers' T = 50
        else
            t = max_evaluations(static_cast<std::int64_t>(10000 * std::max<std::size_t>(dimension, 1)));
    }
    if (target) {
        require(std::isfinite(*target), "target", fmt::format("must be a finite number, got {}", *target));
        t = t | target_value(*target);
    }
    if (wall_ms) {
        require(std::isfinite(*wall_ms), "wall_ms", fmt::format("must be a finite number, got {}", *wall_ms));
        require(*wall_ms > 0, "wall_ms", fmt::format("must be > 0, got {}", *wall_ms));
        // A limit beyond what the clock can count (about 292 years) is no limit.
        const double longest = std::chrono::duration<double, std::milli>(Clock::duration::max()).count();
        if (*wall_ms < longest)
            t = t | wall_time(std::chrono::duration_cast<Clock::duration>(
                        std::chrono::duration<double, std::milli>(*wall_ms)));
    }
    t.recorded_targets = recorded_targets;
    for (std::size_t i = 0; i < recorded_evaluations.size(); ++i)
        require(recorded_evaluations[i] >= 1 && (i == 0 || recorded_evaluations[i] > recorded_evaluations[i - 1]),
                "recorded_evaluations", "must be evaluation counts >= 1, increasing");
    t.recorded_evaluations = recorded_evaluations;
    t.stop = stop;
    return t;
}

namespace {
/// What check() and run() both establish before a run: the entry, its checked parameters and the
/// stopping rules, with the memory the run needs checked.
struct CheckedRun {
    const AlgorithmEntry& entry;
    Params params;
    Termination termination;
};

/// The largest Budget::threads: far more than a population's slices are worth.
constexpr std::int64_t kMaxThreads = 256;

void check_threads(const Prepared& p, const Budget& budget) {
    require(budget.threads >= 1 && budget.threads <= kMaxThreads, "threads",
            fmt::format("must be in [1, {}], got {}", kMaxThreads, budget.threads));
    if (budget.threads == 1 || !p.box) return;
    if (const auto* cb = std::get_if<CallbackProblem>(&p.box->problem))
        require(cb->thread_safe(), "threads",
                fmt::format("the function '{}' is not marked thread-safe (CallbackSpec::thread_safe), so it runs on "
                            "one thread only; Python functions always do",
                            cb->name()));
}

/// The box a run with Budget::threads > 1 searches: the prepared target's problem behind a
/// ParallelBatch (framework/parallel.hpp), erased into a CallbackProblem so that no algorithm is
/// compiled twice; one std::function call per slice of a batch. Empty when the run stays on one
/// thread: one thread asked for, or a continuous function (its noise is drawn in evaluation order,
/// and an evaluation costs less than waking a thread).
std::optional<BoxTarget> threaded_box(const BoxTarget& target, const std::string& name, std::int64_t threads) {
    if (threads <= 1) return std::nullopt;
    return std::visit(
        [&](const auto& problem) -> std::optional<BoxTarget> {
            using P = std::decay_t<decltype(problem)>;
            if constexpr (Reseedable<P> || std::is_same_v<P, continuous::Function>) {
                return std::nullopt;
            } else {
                ParallelBatch<P> parallel(problem, static_cast<std::size_t>(threads));
                CallbackProblem::Starts starts;
                if constexpr (SuggestsStartingPoints<P>)
                    starts = [parallel](Rng& rng, Matrix& out) { parallel.first().starting_points(rng, out); };
                const auto lo = problem.lower(), hi = problem.upper();
                return BoxTarget{CallbackProblem(
                    name, std::vector<double>(lo.begin(), lo.end()), std::vector<double>(hi.begin(), hi.end()),
                    [parallel](std::span<const double> x) mutable { return parallel.evaluate(x); },
                    [parallel](MatrixView points, std::span<double> values) mutable {
                        parallel.evaluate_batch(points, values);
                    },
                    true, std::move(starts))};
            }
        },
        target.problem);
}

CheckedRun checked_run(const AlgorithmSpec& algorithm, const Prepared& p, const Budget& budget) {
    check_threads(p, budget);
    const AlgorithmEntry& entry = algorithms().at(algorithm.name);
    CheckedRun c{entry, checked(entry, p, algorithm), budget.termination(p.dimension, p.grid.has_value())};
    c.termination.optimum = optimum_of(p);  // the reference of the run's COCO trace
    // A sampling planner counts validity checks, not iterations: it needs a budget of them (or of
    // time), never the grids' default of 50 iterations.
    if (entry.sample_grid) {
        require(c.termination.max_evaluations || c.termination.wall_time, "evaluations",
                entry.name + " needs an evaluation budget (its state and motion validity checks: --evals N)");
        // Its tree or roadmap grows by up to one state per check: about 256 bytes each with OMPL's
        // nearest-neighbour structure, checked before anything is allocated.
        if (c.termination.max_evaluations)
            require_memory(256.0 * static_cast<double>(*c.termination.max_evaluations), "evaluations",
                           fmt::format("{} with {} validity checks", entry.name, *c.termination.max_evaluations));
    }
    check_run_memory(entry, c.params, p, c.termination, budget.threads);
    return c;
}
}  // namespace

void check(const AlgorithmSpec& algorithm, const Problem& problem, const Budget& budget) {
    checked_run(algorithm, *problem.planned_for(algorithm), budget);
}

void check_before_building(const AlgorithmSpec& algorithm, const ProblemSpec& spec, std::int64_t dimension,
                           const Budget& budget) {
    Prepared p;
    p.spec = spec;
    if (const auto* c = std::get_if<ContinuousSpec>(&spec)) {
        require_problem_memory(*c);
        p.name = c->function;
        dimension = c->dim;
    } else if (const auto* cb = std::get_if<CallbackSpec>(&spec)) {
        require(dimension >= 1 && dimension <= max_budget, "dim",
                fmt::format("must be an integer in [1, {}], got {}", max_budget, dimension));
        // The bounds, held three times once built (the spec, its prepared copy, the problem's).
        require_memory(48.0 * static_cast<double>(dimension), "dim",
                       fmt::format("{} in dimension {}", cb->name, dimension));
        p.name = cb->name;
    } else {
        return;  // grids: their size is the map's, checked as it is read
    }
    p.dimension = static_cast<std::size_t>(dimension);
    checked_run(algorithm, p, budget);
}

namespace {
/// A box run, observed when `observer` is given: its stop flag joins the stopping rules.
Result run_box(const AlgorithmEntry& entry, const Params& params, const BoxTarget& target,
               const Termination& termination, std::uint64_t seed, const IterationObserver* observer) {
    if (!observer) return entry.run_box(params, target, termination, seed);
    require(static_cast<bool>(entry.run_box_observed), "observer", entry.name + " cannot be observed");
    auto stop = std::make_shared<std::atomic<bool>>(false);
    Termination observed = termination;
    observed.stop = stop;
    // The observer's flag replaces the budget's (Budget::stop), which is read here instead.
    const BoxObserver forward = [&](const IterationView& view) {
        const bool asked = termination.stop && termination.stop->load(std::memory_order_relaxed);
        if (!(*observer)(view) || asked) stop->store(true, std::memory_order_relaxed);
    };
    return entry.run_box_observed(params, target, observed, seed, forward);
}

RunResult run_observed(const AlgorithmSpec& algorithm, const Problem& problem, const Budget& budget, std::uint64_t seed,
                       const IterationObserver* observer) {
    const std::shared_ptr<const Prepared> planned = problem.planned_for(algorithm);
    const Prepared& p = *planned;
    const auto [entry, params, termination] = checked_run(algorithm, p, budget);

    RunResult out;
    out.algorithm = entry.name;
    if (observer && p.grid)
        require(!entry.whole_map() && !p.chain, "observer",
                "only box runs are observed (" + entry.name +
                    (entry.whole_map() ? " solves the whole map)" : " runs on chains)"));
    // Made only for a run on the box (its threads start here and end with the run).
    // The bindings captured by name: clang 14 (the fuzz build) cannot capture structured bindings.
    auto box_run = [&, &entry = entry, &params = params, &termination = termination] {
        const auto threaded = threaded_box(*p.box, p.name, budget.threads);
        return run_box(entry, params, threaded ? *threaded : *p.box, termination, seed, observer);
    };
    if (!p.grid) {
        Result r = box_run();
        copy_run(out, r);
        out.best_x = std::move(r.best_x);
        return out;
    }

    const auto& g = std::get<GridSpec>(p.spec);
    GridOutcome o;
    auto start = Clock::now();  // `exact`'s wall time includes the oracle: it is its search
    if (g.oracle || entry.needs_optimum) o.optimum = grid_optimum(*p.grid, &o.optimal_path);
    if (entry.whole_map()) {
        if (!entry.needs_optimum) start = Clock::now();  // the planner's own time, not the oracle's
        // An entry that returns the exact optimum (needs_optimum) would search again for the path
        // just found (the same function of the same inputs: the same path): 120 s instead of
        // 60 s on an 8000 x 8000 map.
        GridSolution s;
        if (entry.needs_optimum && o.optimum && *o.optimum >= 0.0)
            s.path = o.optimal_path;
        else if (entry.sample_grid)
            s = entry.sample_grid(params, *p.grid, termination, seed);
        else
            s = entry.solve_grid(*p.grid);
        if (entry.plans_polylines) {
            // Checked as a chain is: a polyline that leaves the free plane is never a result.
            o.feasible = !s.polyline.empty() && polyline_violation(*p.grid, s.polyline, s.plane).empty();
            if (o.feasible) {
                o.polyline = std::move(s.polyline);
                for (std::size_t i = 1; i < o.polyline.size(); ++i)
                    o.value += std::hypot(o.polyline[i].x - o.polyline[i - 1].x, o.polyline[i].y - o.polyline[i - 1].y);
            }
            out.best_f = o.feasible ? o.value : std::numeric_limits<double>::infinity();
        } else {
            o.feasible = true;
            o.path = std::move(s.path);
            o.value = grid_value(*p.grid, o.path);
            out.best_f = o.value;
        }
        out.evaluations = s.work;
        out.wall_ms =
            s.planning_ms ? *s.planning_ms : std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    } else if (p.chain) {
        o.encoding = "chain";
        ChainResult r = entry.run_chain(params, *p.chain, termination, seed);
        record_path(o, *p.grid, r.best_x, true, r.best_f);
        copy_run(out, r);
    } else {
        o.encoding = g.encoding;
        Result r = box_run();
        std::visit(
            [&](const auto& target) {
                using Target = std::decay_t<decltype(target)>;
                if constexpr (requires(Target & t) { t.decode(std::span<const double>{}).violations; }) {
                    auto fresh = target;  // decoding uses scratch; the prepared problem stays untouched
                    const grid::DecodedPath& best = fresh.decode(r.best_x);
                    record_path(o, *p.grid, best.path, best.violations == 0, r.best_f);
                }
            },
            p.box->problem);
        copy_run(out, r);
        out.best_x = std::move(r.best_x);
    }
    check_user_optimum(*p.grid, o);
    score_path(o, *p.grid, g.path_gaps);
    out.grid = std::move(o);
    return out;
}
}  // namespace

RunResult run(const AlgorithmSpec& algorithm, const Problem& problem, const Budget& budget, std::uint64_t seed) {
    return run_observed(algorithm, problem, budget, seed, nullptr);
}

RunResult run(const AlgorithmSpec& algorithm, const Problem& problem, const Budget& budget, std::uint64_t seed,
              const IterationObserver& observer) {
    return run_observed(algorithm, problem, budget, seed, &observer);
}

grid::Cell world_cell(const grid::GridMap& map, double x, double y, const std::string& where,
                      const std::string& instead) {
    const auto& f = map.frame();
    require(f.has_value(), where,
            "the map " + map.name() +
                " has no world frame (only a ROS map_server YAML map has a resolution and origin): give " + instead);
    const auto cell = map.cell_at({x, y});
    require(
        cell.has_value(), where,
        fmt::format("the point ({}, {}) is outside the map: x in [{:.10g}, {:.10g}), y in [{:.10g}, {:.10g}) metres", x,
                    y, f->origin_x, f->origin_x + map.width() * f->resolution, f->origin_y,
                    f->origin_y + map.height() * f->resolution));
    return *cell;
}

std::shared_ptr<const grid::GridMap> load_map(const std::string& file, std::int64_t inflate,
                                              const grid::MapReadOptions& options) {
    require(inflate >= 0 && inflate <= 1000, "inflate", "must be in [0, 1000], got " + std::to_string(inflate));
    grid::GridMap loaded = grid::read_map(file, options);
    if (inflate > 0) loaded = loaded.inflated(static_cast<int>(inflate));
    return std::make_shared<const grid::GridMap>(std::move(loaded));
}

}  // namespace pride::engine

#include "engine/run_checks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "engine/registry.hpp"
#include "engine/run.hpp"
#include "framework/error.hpp"
#include "framework/memory.hpp"

namespace pride::engine {

namespace {

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
    const bool constrained = p.constrained() != nullptr;
    for (const auto& spec : entry.params)
        require(!spec.constrained_only || !params.given(spec.name) || constrained, entry.name,
                spec.name + " says how constraints are handled; " + p.name + " has none");
    auto refuse_chain_settings = [&](const std::string& space) {
        for (const auto& spec : entry.params)
            require(!spec.chain_only || !params.given(spec.name), entry.name,
                    spec.name + " is a setting of the chain space (the chain encoding); it has no meaning on " + space);
    };
    if (!g) {
        if (constrained && !entry.runs(Kind::constrained_box)) {
            std::string names;
            for (const auto& e : algorithms().entries())
                if (e.runs(Kind::constrained_box)) names += (names.empty() ? "" : ", ") + e.name;
            throw InputError("algo", entry.name + " does not handle constraints; " + p.name +
                                         " has some (the algorithms that do: " + names + ")");
        }
        require(constrained || entry.runs(Kind::box), "algo", entry.name + " works on grid problems only");
        refuse_chain_settings("a box");
        for (const auto& spec : entry.params)
            require(!spec.grid_only || !params.given(spec.name), entry.name,
                    spec.name + " says how a grid is planned on; it has no meaning on " + p.name);
        return params;
    }
    if (entry.whole_map()) {
        require(!entry.needs_optimum || p.grid()->has_optimum(), "objective",
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
        if (!entry.runs(Kind::chain)) {
            std::string on_chains;
            for (const auto& e : algorithms().entries())
                if (e.runs(Kind::chain)) on_chains += (on_chains.empty() ? "" : ", ") + e.name;
            throw InputError("encoding chain",
                             entry.name + " does not run on chains; the chain encoding takes " + on_chains);
        }
        for (const auto& spec : entry.params)
            require(!spec.box_only || !params.given(spec.name), entry.name,
                    spec.name + " has no meaning on chains (the chain encoding)");
    } else {
        require(entry.runs(Kind::box), "algo", entry.name + " does not run on a box");
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
    if (p.grid())
        std::visit(
            [&](const auto& g) {
                cells = static_cast<double>(g.map().size());
                map_size = fmt::format("{} x {}", g.map().width(), g.map().height());
            },
            p.grid()->problem);
    MemoryPart run;
    if (entry.whole_map()) {
        if (entry.memory)
            run = {entry.memory(params, static_cast<std::size_t>(cells)), entry.name,
                   fmt::format("{} on a {} map", entry.name, map_size)};
    } else {
        // A chain holds no cell twice (every operator cuts loops), so the map's cells bound its length.
        const std::size_t dimension =
            p.chain() ? static_cast<std::size_t>(cells) + 8 : p.dimension;  // + a vector's own
        const std::string where = p.chain() ? fmt::format("on chains of up to {} cells", dimension)
                                            : fmt::format("in dimension {}", dimension);
        run.where = entry.name;
        run.what = entry.param("pop") ? fmt::format("a run with population {} {}", params.integer("pop"), where)
                                      : fmt::format("a run {}", where);
        if (entry.memory) run.bytes = entry.memory(params, dimension);
        if (p.grid() && !p.chain()) {
            run.bytes += 44.0 * cells * static_cast<double>(threads);
            run.what += fmt::format(" on a {} map", map_size);
        }
        const auto pop = entry.param("pop") ? params.integer("pop") : 1;
        if (const auto t = termination.horizon(pop, pop))
            parts.push_back({16.0 * static_cast<double>(*t + 1),
                             termination.max_iterations ? "iterations" : "evaluations",
                             fmt::format("the history of {} iterations", *t)});
    }
    const auto* g = p.grid() ? &std::get<GridSpec>(p.spec) : nullptr;
    if (g && (g->oracle || entry.needs_optimum) && p.grid()->additive_or_steps()) {
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

/// The largest Budget::threads: far more than a population's slices are worth.
constexpr std::int64_t kMaxThreads = 256;

void check_threads(const Prepared& p, const Budget& budget) {
    require(budget.threads >= 1 && budget.threads <= kMaxThreads, "threads",
            fmt::format("must be in [1, {}], got {}", kMaxThreads, budget.threads));
    require(budget.threads == 1 || !p.constrained(), "threads",
            "a problem with constraints is evaluated on one thread");
    if (budget.threads == 1 || !p.box()) return;
    if (const auto* cb = std::get_if<CallbackProblem>(&p.box()->problem))
        require(cb->thread_safe(), "threads",
                fmt::format("the function '{}' is not marked thread-safe (CallbackSpec::thread_safe), so it runs on "
                            "one thread only; Python functions always do",
                            cb->name()));
}

}  // namespace

CheckedRun checked_run(const AlgorithmSpec& algorithm, const Prepared& p, const Budget& budget) {
    check_threads(p, budget);
    const AlgorithmEntry& entry = algorithms().at(algorithm.name);
    CheckedRun c{&entry, {checked(entry, p, algorithm), budget.termination(p.dimension, p.grid() != nullptr)}};
    RunRequest& r = c.request;
    r.termination.optimum = optimum_of(p);  // the reference of the run's COCO trace
    // A sampling planner counts validity checks, not iterations: it needs a budget of them (or of
    // time), never the grids' default of 50 iterations.
    if (entry.runs(Kind::sampled_grid)) {
        require(r.termination.max_evaluations || r.termination.wall_time, "evaluations",
                entry.name + " needs an evaluation budget (its state and motion validity checks: --evals N)");
        // Its tree or roadmap grows by up to one state per check: about 256 bytes each with OMPL's
        // nearest-neighbour structure, checked before anything is allocated.
        if (r.termination.max_evaluations)
            require_memory(256.0 * static_cast<double>(*r.termination.max_evaluations), "evaluations",
                           fmt::format("{} with {} validity checks", entry.name, *r.termination.max_evaluations));
    }
    check_run_memory(entry, r.params, p, r.termination, budget.threads);
    return c;
}

void check(const AlgorithmSpec& algorithm, const Problem& problem, const Budget& budget) {
    const std::shared_ptr<const Prepared> planned = problem.planned_for(algorithm);
    if (planned->objectives() > 1)
        check_several(algorithm, *planned, budget);
    else
        checked_run(algorithm, *planned, budget);
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

}  // namespace pride::engine

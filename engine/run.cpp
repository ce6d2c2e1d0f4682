#include "engine/run.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <memory>
#include <optional>
#include <span>
#include <type_traits>
#include <utility>

#include "engine/prepared.hpp"
#include "engine/registry.hpp"
#include "engine/run_checks.hpp"
#include "framework/error.hpp"
#include "framework/parallel.hpp"
#include "framework/variables.hpp"

namespace pride::engine {

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

/// The box a run with Budget::threads > 1 searches: the prepared target's problem behind a
/// ParallelBatch (framework/parallel.hpp), erased into a CallbackProblem so that no algorithm is
/// compiled twice; one std::function call per slice of a batch. Empty when the run stays on one
/// thread: one thread asked for, or a continuous function (its noise is drawn in evaluation order,
/// and an evaluation costs less than waking a thread).
std::optional<Target> threaded_box(const BoxTarget& target, const std::string& name, std::int64_t threads) {
    if (threads <= 1) return std::nullopt;
    return std::visit(
        [&](const auto& problem) -> std::optional<Target> {
            using P = std::decay_t<decltype(problem)>;
            if constexpr (Reseedable<P> || std::is_same_v<P, continuous::Function>) {
                return std::nullopt;
            } else {
                ParallelBatch<P> parallel(problem, static_cast<std::size_t>(threads));
                CallbackProblem::Starts starts;
                if constexpr (SuggestsStartingPoints<P>)
                    starts = [parallel](Rng& rng, Matrix& out) { parallel.first().starting_points(rng, out); };
                const auto lo = problem.lower(), hi = problem.upper();
                // The types too, so that a run on threads is the run on one thread.
                std::vector<VariableType> types;
                for (std::size_t i = 0; i < problem.dimension(); ++i) types.push_back(variable_type(problem, i));
                return Target(BoxTarget{CallbackProblem(
                    name, std::vector<double>(lo.begin(), lo.end()), std::vector<double>(hi.begin(), hi.end()),
                    [parallel](std::span<const double> x) mutable { return parallel.evaluate(x); },
                    [parallel](MatrixView points, std::span<double> values) mutable {
                        parallel.evaluate_batch(points, values);
                    },
                    true, std::move(starts), std::move(types))});
            }
        },
        target.problem);
}

/// Runs `request` on `target`; with an observer, a box run observed: its stop flag joins the
/// stopping rules.
Outcome run_target(const AlgorithmEntry& entry, RunRequest request, const Target& target,
                   const IterationObserver* observer) {
    if (!observer) return entry.run(request, target);
    auto stop = std::make_shared<std::atomic<bool>>(false);
    const std::shared_ptr<const std::atomic<bool>> asked = request.termination.stop;
    request.termination.stop = stop;
    // The observer's flag replaces the budget's (Budget::stop), which is read here instead.
    const BoxObserver forward = [&](const IterationView& view) {
        const bool stopping = asked && asked->load(std::memory_order_relaxed);
        if (!(*observer)(view) || stopping) stop->store(true, std::memory_order_relaxed);
    };
    request.observer = &forward;
    return entry.run(request, target);
}

RunResult run_observed(const AlgorithmSpec& algorithm, const Problem& problem, const Budget& budget, std::uint64_t seed,
                       const IterationObserver* observer) {
    const std::shared_ptr<const Prepared> planned = problem.planned_for(algorithm);
    const Prepared& p = *planned;
    if (p.objectives() > 1) {
        require(!observer, "observer", "only runs of one objective are observed");
        return run_several(algorithm, p, budget, seed);
    }
    CheckedRun checked = checked_run(algorithm, p, budget);
    const AlgorithmEntry& entry = *checked.entry;
    RunRequest& request = checked.request;
    request.seed = seed;

    RunResult out;
    out.algorithm = entry.name;
    if (observer && p.grid())
        require(!entry.whole_map() && !p.chain(), "observer",
                "only box runs are observed (" + entry.name +
                    (entry.whole_map() ? " solves the whole map)" : " runs on chains)"));
    // Made only for a run on the box (its threads start here and end with the run).
    auto box_run = [&] {
        if (p.constrained()) return std::get<Result>(run_target(entry, request, *p.searched, observer));
        const auto threaded = threaded_box(*p.box(), p.name, budget.threads);
        return std::get<Result>(run_target(entry, request, threaded ? *threaded : *p.searched, observer));
    };
    if (!p.grid()) {
        Result r = box_run();
        copy_run(out, r);
        out.best_x = std::move(r.best_x);
        // Integer and categorical coordinates reported in their types.
        if (const BoxTarget* box = p.box())
            std::visit([&](const auto& problem) { round_to_types(problem, out.best_x); }, box->problem);
        if (const ConstrainedBoxTarget* c = p.constrained())
            std::visit([&](const auto& problem) { round_to_types(problem, out.best_x); }, c->problem);
        if (p.constrained()) {
            out.best_violation = r.best_violation;
            out.first_feasible = r.first_feasible;
        }
        return out;
    }

    const auto& g = std::get<GridSpec>(p.spec);
    const GridTarget& grid = *p.grid();
    GridOutcome o;
    auto start = Clock::now();  // `exact`'s wall time includes the oracle: it is its search
    if (g.oracle || entry.needs_optimum) o.optimum = grid_optimum(grid, &o.optimal_path);
    if (entry.whole_map()) {
        if (!entry.needs_optimum) start = Clock::now();  // the planner's own time, not the oracle's
        // An entry that returns the exact optimum (needs_optimum) would search again for the path
        // just found (the same function of the same inputs: the same path): 120 s instead of
        // 60 s on an 8000 x 8000 map.
        GridSolution s;
        if (entry.needs_optimum && o.optimum && *o.optimum >= 0.0)
            s.path = o.optimal_path;
        else
            s = std::get<GridSolution>(entry.run(request, *p.whole_grid));
        out.best_f = record_solution(o, grid, s, entry.plans_polylines);
        out.evaluations = s.work;
        out.wall_ms =
            s.planning_ms ? *s.planning_ms : std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    } else if (p.chain()) {
        o.encoding = "chain";
        ChainResult r = std::get<ChainResult>(entry.run(request, *p.searched));
        record_path(o, grid, r.best_x, true, r.best_f);
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
                    record_path(o, grid, best.path, best.violations == 0, r.best_f);
                }
            },
            p.box()->problem);
        copy_run(out, r);
        out.best_x = std::move(r.best_x);
    }
    score_outcome(o, grid, g.path_gaps);
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

}  // namespace pride::engine

#include "engine/multiobjective.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <mutex>

#include "engine/grid_names.hpp"
#include "engine/grid_plan.hpp"
#include "engine/json.hpp"
#include "engine/prepared.hpp"
#include "engine/registry.hpp"
#include "engine/run.hpp"
#include "engine/run_checks.hpp"
#include "engine/target.hpp"
#include "framework/error.hpp"
#include "framework/memory.hpp"
#include "framework/pareto/dominance.hpp"
#include "framework/pareto/hypervolume.hpp"
#include "framework/pareto/indicators.hpp"
#include "problems/grid/pareto.hpp"
#include "problems/multiobjective/re/fronts.hpp"

namespace pride::engine {

bool is_multiobjective_problem(const std::string& name) {
    return multiobjective::find_problem(name) != nullptr || multiobjective::find_constrained_problem(name) != nullptr ||
           multiobjective::re::find_problem(name) != nullptr;
}

std::string multiobjective_problem_names() {
    std::string names = multiobjective::problem_names();
    for (const auto& e : multiobjective::kConstrainedCatalog) names += ", " + std::string(e.name);
    for (const auto& e : multiobjective::re::kCatalog) names += ", " + std::string(e.name);
    return names;
}

namespace {

/// An RE problem's approximated front, Tanabe and Ishibuchi's, read from $PRIDE_DATA/re-fronts (the
/// project does not ship others' data); the CRE problems have none published.
Matrix re_front(const multiobjective::re::Problem& p) {
    const std::string name(p.name());
    require(p.constraint_counts().total() == 0, "problem",
            name +
                " has no published reference front (the suite publishes the RE problems' only); run it "
                "without the reference front");
    const char* data = std::getenv("PRIDE_DATA");
    require(data != nullptr && *data != 0, "problem",
            name +
                "'s reference front is Tanabe and Ishibuchi's approximated front, which pride does not ship: set "
                "PRIDE_DATA to a folder holding re-fronts/ (their reproblems repository's "
                "approximated_Pareto_fronts), or run without the reference front");
    return multiobjective::re::read_re_front(std::filesystem::path(data) / "re-fronts", name);
}

std::int64_t checked_count(std::int64_t v, std::int64_t lo, std::int64_t hi, const char* where) {
    require(v >= lo && v <= hi, where, fmt::format("must be an integer in [{}, {}], got {}", lo, hi, v));
    return v;
}

void prepare_benchmark(Prepared& out, const ContinuousSpec& s) {
    require(!s.instance, "instance", s.function + " has no instances");
    checked_count(s.dim, 0, static_cast<std::int64_t>(multiobjective::kMaxVariables), "dim");
    checked_count(s.objectives, 0, static_cast<std::int64_t>(multiobjective::kMaxObjectives), "objectives");
    if (const auto* e = multiobjective::re::find_problem(s.function)) {
        require(s.dim == 0 || s.dim == static_cast<std::int64_t>(e->variables), "dim",
                fmt::format("{} has {} variables, got {}", e->name, e->variables, s.dim));
        require(s.objectives == 0 || s.objectives == static_cast<std::int64_t>(e->objectives), "objectives",
                fmt::format("{} has {} objectives, got {}", e->name, e->objectives, s.objectives));
        multiobjective::re::Problem p(s.function);
        out.name = std::string(p.name());
        for (std::size_t i = 1; i <= p.objectives(); ++i) out.objective_names.push_back(fmt::format("f{}", i));
        out.searched.emplace(std::in_place_type<MoBoxTarget>, MoBoxTarget{std::move(p)});
        return;
    }
    if (multiobjective::find_constrained_problem(s.function)) {
        multiobjective::ConstrainedBenchmark b(s.function, static_cast<std::size_t>(s.dim),
                                               static_cast<std::size_t>(s.objectives));
        out.name = std::string(b.name());
        for (std::size_t i = 1; i <= b.objectives(); ++i) out.objective_names.push_back(fmt::format("f{}", i));
        out.searched.emplace(std::in_place_type<MoBoxTarget>, MoBoxTarget{std::move(b)});
        return;
    }
    multiobjective::Benchmark b(s.function, static_cast<std::size_t>(s.dim), static_cast<std::size_t>(s.objectives));
    out.name = std::string(b.name());
    for (std::size_t i = 1; i <= b.objectives(); ++i) out.objective_names.push_back(fmt::format("f{}", i));
    out.searched.emplace(std::in_place_type<MoBoxTarget>, MoBoxTarget{std::move(b)});
}

void prepare_grid(Prepared& out, const GridSpec& g) {
    check_grid_names(g);
    require(g.map != nullptr, "map", "no map given");
    require(g.objective == "cells" && g.weights.empty() && !g.lambda && !g.path_objective, "objective",
            "a multi-objective grid problem takes its criteria from objectives, not a single objective");
    require(!g.oracle, "oracle", "a multi-objective grid problem's reference is its exact front");
    if (g.encoding == "chain")
        require(g.init.empty() || g.init == "walk" || g.init == "sitp", "init",
                "chains start from random walks (walk) or Zhang et al.'s (2025) SITP walks (sitp), got " + g.init);
    else
        require(g.init.empty() || g.init == "uniform", "init",
                "the multi-objective algorithms start from uniform points on line and free, got " + g.init);
    out.criteria = grid::parse_criteria(g.objectives);
    grid::ClearanceParams cp;
    cp.bands = static_cast<int>(checked_count(g.clearance_bands, 1, 63, "clearance_bands"));
    cp.band_width = static_cast<int>(checked_count(g.clearance_width, 1, 1'000'000, "clearance_width"));
    grid::PathCriteria criteria(*g.map, out.criteria, cp);
    out.clearance = criteria.clearance();
    out.objective_names = grid::criteria_names(out.criteria);
    out.name = "grid";
    const grid::GridProblem<grid::CellsObjective> problem(g.map, g.start, g.goal, {}, g.corner_cutting);
    std::visit(
        [&](auto&& plan) {
            using Plan = std::decay_t<decltype(plan)>;
            if constexpr (std::is_same_v<Plan, grid::ChainSpace<grid::CellsObjective>>) {
                MoGridChain p(std::move(plan), std::move(criteria));
                p.count_calls(g.objective_calls);
                out.searched.emplace(std::in_place_type<MoChainTarget>, MoChainTarget{std::move(p)});
            } else {
                using Paths = std::conditional_t<std::is_same_v<Plan, LinePlan>, MoGridLine, MoGridFree>;
                Paths p(problem, std::move(plan), std::move(criteria));
                p.count_calls(g.objective_calls);
                out.searched.emplace(std::in_place_type<MoBoxTarget>, MoBoxTarget{std::move(p)});
            }
        },
        plan_grid(g, problem));
}

void prepare_callback(Prepared& out, const CallbackSpec& s) {
    require(!s.lower.empty(), "bounds", "the box has no coordinate");
    require(s.lower.size() == s.upper.size(), "bounds",
            fmt::format("lower has {} coordinates, upper {}", s.lower.size(), s.upper.size()));
    for (std::size_t i = 0; i < s.lower.size(); ++i)
        require(std::isfinite(s.lower[i]) && std::isfinite(s.upper[i]) && s.lower[i] <= s.upper[i], "bounds",
                fmt::format("coordinate {} must have finite bounds with lower <= upper", i));
    checked_count(s.objectives, 1, static_cast<std::int64_t>(multiobjective::kMaxObjectives), "objectives");
    require(static_cast<bool>(s.values) || static_cast<bool>(s.values_batch), "function",
            fmt::format("no function of {} objectives given", s.objectives));
    require(!s.f_opt, "f_opt", "a function of several objectives has no single minimum");
    require(s.inequalities == 0 && s.equalities == 0 && !s.constrained, "constraints",
            "a function of several objectives takes no constraints");
    out.name = s.name;
    for (std::int64_t i = 1; i <= s.objectives; ++i) out.objective_names.push_back(fmt::format("f{}", i));
    out.searched.emplace(std::in_place_type<MoBoxTarget>,
                         MoBoxTarget{MoCallbackProblem(s.name, s.lower, s.upper, static_cast<std::size_t>(s.objectives),
                                                       s.values, s.values_batch, s.types)});
}

/// The grid's exact front over the same criteria (ParetoSearch within the machine's memory).
void exact_front(const Prepared& p, ReferenceFront& out) {
    const auto& g = std::get<GridSpec>(p.spec);
    const grid::GridMap& map = *g.map;
    grid::ParetoOptions options;
    options.corner_cutting = g.corner_cutting;
    options.max_labels = grid::label_limit(map.size(), available_memory(), map.name());
    const grid::MapClearance clearance = p.clearance ? *p.clearance : grid::MapClearance(map);
    const auto front = grid::pareto_front(map, clearance, g.start, g.goal, p.criteria, options);
    const auto m = static_cast<Eigen::Index>(p.criteria.count());
    out.values.resize(m, static_cast<Eigen::Index>(front.size()));
    for (std::size_t j = 0; j < front.size(); ++j) {
        const auto& q = front[j];
        Eigen::Index k = 0;
        const auto c = static_cast<Eigen::Index>(j);
        if (p.criteria.length) out.values(k++, c) = q.steps.value();  // as PathCriteria's
        if (p.criteria.turns) out.values(k++, c) = q.turns;
        if (p.criteria.angle_penalty) out.values(k++, c) = q.angle_penalty;
        if (p.criteria.clearance) out.values(k++, c) = q.clearance;
        out.paths.push_back(q.path);
    }
}

}  // namespace

bool several_objectives(const ProblemSpec& spec) {
    if (const auto* c = std::get_if<ContinuousSpec>(&spec)) return is_multiobjective_problem(c->function);
    if (const auto* g = std::get_if<GridSpec>(&spec)) return !g->objectives.empty();
    return std::get<CallbackSpec>(spec).objectives != 1;
}

void prepare_several(Prepared& out) {
    if (const auto* c = std::get_if<ContinuousSpec>(&out.spec))
        prepare_benchmark(out, *c);
    else if (const auto* g = std::get_if<GridSpec>(&out.spec))
        prepare_grid(out, *g);
    else
        prepare_callback(out, std::get<CallbackSpec>(out.spec));
    out.dimension = out.mo_box() ? std::visit([](const auto& p) { return p.dimension(); }, out.mo_box()->problem) : 0;
    out.front = std::make_shared<ReferenceFront>();
}

const ReferenceFront& reference_front_of(const Prepared& p) {
    require(p.front != nullptr, "problem", p.name + " has one objective: it has no reference front");
    require(!std::holds_alternative<CallbackSpec>(p.spec), "problem",
            p.name + " is a user's function: it has no reference front");
    ReferenceFront& front = *p.front;
    std::call_once(front.once, [&] {
        try {
            const auto* box = p.mo_box();
            if (const auto* b = box ? std::get_if<multiobjective::Benchmark>(&box->problem) : nullptr)
                front.values = b->reference_front(Problem::reference_points);
            else if (const auto* c = box ? std::get_if<multiobjective::ConstrainedBenchmark>(&box->problem) : nullptr)
                front.values = c->reference_front(Problem::reference_points);
            else if (const auto* re = box ? std::get_if<multiobjective::re::Problem>(&box->problem) : nullptr)
                front.values = re_front(*re);
            else
                exact_front(p, front);
        } catch (const InputError& e) {
            front.error = e;
        }
    });
    if (front.error) throw *front.error;
    return front;
}

namespace {

const AlgorithmEntry& multiobjective_entry(const AlgorithmSpec& algorithm, const Prepared& p) {
    const AlgorithmEntry& entry = algorithms().at(algorithm.name);
    if (!entry.multiobjective()) {
        std::string names;
        for (const auto& e : algorithms().entries())
            if (e.multiobjective()) names += (names.empty() ? "" : ", ") + e.name;
        throw InputError("algo", entry.name + " optimises one objective; " + p.name + " has " +
                                     std::to_string(p.objectives()) + " (multi-objective algorithms: " + names + ")");
    }
    if (p.mo_chain() && !entry.runs(Kind::multiobjective_chain)) {
        std::string names;
        for (const auto& e : algorithms().entries())
            if (e.runs(Kind::multiobjective_chain)) names += (names.empty() ? "" : ", ") + e.name;
        throw InputError("algo", entry.name + " has no chain operators; the chain encoding takes " + names);
    }
    return entry;
}

/// Parameters of one space given on another (SBX's index on chains, a chain setting on a box).
void check_space_params(const AlgorithmEntry& entry, const Params& params, const Prepared& p) {
    const bool chain = p.mo_chain() != nullptr;
    for (const auto& spec : entry.params) {
        if (!params.given(spec.name)) continue;
        require(!spec.chain_only || chain, entry.name,
                spec.name + " is a setting of chains; " + p.name + " is not searched on chains");
        require(!spec.box_only || !chain, entry.name, spec.name + " has no meaning on chains");
    }
}

Termination mo_termination(const Prepared& p, const Budget& budget) {
    require(!budget.target, "target", "a multi-objective run has no single value to reach");
    require(budget.recorded_targets.empty() && budget.recorded_evaluations.empty(), "budget",
            "multi-objective runs record no targets or checkpoints");
    require(budget.threads == 1, "threads", "multi-objective runs evaluate on one thread");
    return budget.termination(p.dimension, std::holds_alternative<GridSpec>(p.spec));
}

/// What a run allocates, checked before it does: about six population-sized matrices of points
/// and of values (parents, children, the merged set, their copies).
void check_memory(const Params& params, const Prepared& p) {
    const double pop = std::max(100.0, static_cast<double>(params.integer("pop")));
    // A chain counted as twice the map's perimeter in cells, two integers each (one double's
    // bytes): a loop-free chain may have as many cells as the map, but counting that would refuse
    // runs on large maps whose paths cover a small part of them.
    double genes = static_cast<double>(p.dimension);
    if (p.mo_chain()) {
        const grid::GridMap& map = *std::get<GridSpec>(p.spec).map;
        genes = 4.0 * static_cast<double>(map.width() + map.height());
    }
    const double per = genes + static_cast<double>(p.objectives());
    require_memory(8.0 * 6.0 * pop * per, "pop",
                   fmt::format("a population of {} in dimension {}", params.integer("pop"), p.dimension));
}

/// What check() and run() both refuse before anything is allocated: a run that would not fit in
/// memory, or parameters the entry cannot honour in this many objectives.
void check_run_size(const AlgorithmEntry& entry, const Params& params, const Prepared& p) {
    check_memory(params, p);
    if (entry.check_objectives) entry.check_objectives(params, p.objectives());
}

/// The members a run's result lists: distinct objective vectors only (the first point of each, in
/// the population's order), in lexicographic order of their objectives.
std::vector<std::size_t> listed(const Matrix& f) {
    auto keep = pareto::nondominated(f);
    std::stable_sort(keep.begin(), keep.end(), [&](std::size_t a, std::size_t b) {
        return pareto::detail::lexicographically_before(f, static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b));
    });
    return keep;
}

/// A run's record with the members listed() keeps (their indices into the run's result in `keep`)
/// and their values; their points or paths are for the caller.
template <class Result>
RunResult listed_run(const AlgorithmEntry& entry, Result& r, std::vector<std::size_t>& keep) {
    RunResult out;
    out.algorithm = entry.name;
    out.best_f = std::numeric_limits<double>::quiet_NaN();
    out.evaluations = r.evaluations;
    out.iterations = r.iterations;
    out.wall_ms = r.wall_ms;
    out.history_evaluations = std::move(r.history_evaluations);
    keep = listed(r.f);
    Front& front = out.front.emplace();
    front.f.resize(r.f.rows(), static_cast<Eigen::Index>(keep.size()));
    for (std::size_t k = 0; k < keep.size(); ++k)
        front.f.col(static_cast<Eigen::Index>(k)) = r.f.col(static_cast<Eigen::Index>(keep[k]));
    if (!r.violation.empty()) {
        for (const std::size_t k : keep) front.violation.push_back(r.violation[k]);
        out.first_feasible = r.first_feasible;
        // The set's least violation: 0 when it is feasible (constrained domination's first front
        // is feasible whenever a feasible point survived).
        out.best_violation = *std::min_element(front.violation.begin(), front.violation.end());
    }
    return out;
}

struct CheckedSeveral {
    const AlgorithmEntry* entry = nullptr;
    RunRequest request;
};

CheckedSeveral checked_several(const AlgorithmSpec& algorithm, const Prepared& p, const Budget& budget) {
    const AlgorithmEntry& entry = multiobjective_entry(algorithm, p);
    const Params params(entry.name, entry.params, algorithm.params);
    check_space_params(entry, params, p);
    CheckedSeveral c{&entry, {params, mo_termination(p, budget)}};
    c.request.termination.validate(entry.name);
    check_run_size(entry, params, p);
    return c;
}

}  // namespace

void check_several(const AlgorithmSpec& algorithm, const Prepared& p, const Budget& budget) {
    checked_several(algorithm, p, budget);
}

RunResult run_several(const AlgorithmSpec& algorithm, const Prepared& p, const Budget& budget, std::uint64_t seed) {
    CheckedSeveral c = checked_several(algorithm, p, budget);
    const AlgorithmEntry& entry = *c.entry;
    c.request.seed = seed;
    const Target& target = *p.searched;
    std::vector<std::size_t> keep;
    if (p.mo_chain()) {
        MoChainResult r = std::get<MoChainResult>(entry.run(c.request, target));
        RunResult out = listed_run(entry, r, keep);
        for (const std::size_t i : keep) {
            out.front->paths.push_back(std::move(r.x[i]));
            out.front->feasible.push_back(1);  // the chain operators make legal chains only
        }
        return out;
    }
    MultiObjectiveResult r = std::get<MultiObjectiveResult>(entry.run(c.request, target));
    RunResult out = listed_run(entry, r, keep);
    Front& front = *out.front;
    front.x.resize(r.x.rows(), static_cast<Eigen::Index>(keep.size()));
    for (std::size_t k = 0; k < keep.size(); ++k)
        front.x.col(static_cast<Eigen::Index>(k)) = r.x.col(static_cast<Eigen::Index>(keep[k]));
    std::visit(
        [&](const auto& problem) {
            using T = std::decay_t<decltype(problem)>;
            if constexpr (std::is_same_v<T, MoGridLine> || std::is_same_v<T, MoGridFree>) {
                T decoder = problem;
                for (Eigen::Index j = 0; j < front.x.cols(); ++j) {
                    auto [path, legal] = decoder.path(column(std::as_const(front.x), j));
                    front.paths.push_back(std::move(path));
                    front.feasible.push_back(legal ? 1 : 0);
                }
            } else if constexpr (TypedVariables<T>) {  // integer coordinates reported as integers
                for (Eigen::Index j = 0; j < front.x.cols(); ++j)
                    round_to_types(problem, std::span<double>(front.x.col(j).data(), front.x.col(j).size()));
            }
        },
        p.mo_box()->problem);
    return out;
}

std::string front_json(const Front& r) {
    const auto column = [](const Matrix& m, Eigen::Index j) {
        return json_array(std::vector<double>(m.col(j).data(), m.col(j).data() + m.rows()));
    };
    const bool grid = !r.paths.empty();
    std::string points;
    for (Eigen::Index j = 0; j < r.f.cols(); ++j) {
        points += points.empty() ? "" : ", ";
        const auto k = static_cast<std::size_t>(j);
        points += grid
                      ? fmt::format("{{\"f\": {}, \"legal\": {}, \"path\": {}}}", column(r.f, j),
                                    r.feasible[k] ? "true" : "false", json_cells(r.paths[k]))
                      : fmt::format(
                            "{{\"f\": {}, \"x\": {}{}}}", column(r.f, j), column(r.x, j),
                            r.violation.empty() ? "" : fmt::format(", \"violation\": {}", json_number(r.violation[k])));
    }
    return "[" + points + "]";
}

void check_quality(const Problem& problem) {
    if (problem.objectives() < 2 || !std::holds_alternative<ContinuousSpec>(problem.spec())) return;
    const std::size_t m = problem.objectives(), most = pareto::exact_hypervolume_points(m);
    // Built here, once for every run of the problem: a front that cannot be had (data not given,
    // none published) is refused before anything runs.
    const auto points = static_cast<std::size_t>(problem.reference_front().cols());
    if (m <= 3) return;
    require(points <= most, "objectives",
            fmt::format("{} objectives: the hypervolume of the reference front ({} points) is beyond what is computed "
                        "exactly in {} objectives ({} points at most); give fewer objectives, or run without the "
                        "reference front",
                        m, points, m, most));
}

FrontQuality quality(const Problem& problem, const Matrix& all, std::span<const double> violation) {
    const Matrix& front = problem.reference_front();
    Matrix feasible_only;
    if (!violation.empty()) {
        require(violation.size() == static_cast<std::size_t>(all.cols()), "front",
                fmt::format("{} violations for {} points", violation.size(), all.cols()));
        feasible_only.resize(all.rows(),
                             static_cast<Eigen::Index>(std::count(violation.begin(), violation.end(), 0.0)));
        Eigen::Index k = 0;
        for (Eigen::Index j = 0; j < all.cols(); ++j)
            if (violation[static_cast<std::size_t>(j)] == 0.0) feasible_only.col(k++) = all.col(j);
    }
    const Matrix& f = violation.empty() ? all : feasible_only;
    require(front.cols() > 0, "problem", "the reference front is empty (the goal cannot be reached)");
    require(f.rows() == front.rows(), "front",
            fmt::format("the set has {} objectives, the problem {}", f.rows(), front.rows()));
    FrontQuality q;
    const auto m = front.rows();
    const Eigen::VectorXd ideal = front.rowwise().minCoeff(), nadir = front.rowwise().maxCoeff();
    Eigen::VectorXd range = nadir - ideal;
    for (Eigen::Index i = 0; i < m; ++i)
        if (!(range[i] > 0.0)) range[i] = 1.0;
    const auto normalise = [&](const Matrix& a) {
        return Matrix((a.colwise() - ideal).array().colwise() / range.array());
    };
    const Matrix nf = normalise(front), ns = normalise(f);
    const std::vector<double> ref(static_cast<std::size_t>(m), 1.1);
    q.ideal.assign(ideal.data(), ideal.data() + m);
    q.nadir.assign(nadir.data(), nadir.data() + m);
    q.reference_size = front.cols();
    q.reference_hypervolume = pareto::hypervolume(nf, ref);
    if (f.cols() > 0) {
        q.hypervolume = pareto::hypervolume(ns, ref);
        q.igd_plus = pareto::igd_plus(ns, nf);
    } else {
        q.igd_plus = std::numeric_limits<double>::infinity();
    }
    q.hypervolume_ratio = q.reference_hypervolume > 0.0 ? q.hypervolume / q.reference_hypervolume : 0.0;
    if (problem.is_grid()) {
        std::int64_t found = 0;
        for (Eigen::Index j = 0; j < front.cols(); ++j)
            for (Eigen::Index k = 0; k < f.cols(); ++k)
                if (f.col(k) == front.col(j)) {
                    ++found;
                    break;
                }
        q.exact_found = found;
    }
    return q;
}

}  // namespace pride::engine

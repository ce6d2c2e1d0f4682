#include "engine/problem.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>

#include "engine/grid_names.hpp"
#include "engine/grid_plan.hpp"
#include "engine/multiobjective.hpp"
#include "engine/prepared.hpp"
#include "engine/problem_names.hpp"
#include "engine/registry.hpp"
#include "framework/close_names.hpp"
#include "framework/error.hpp"
#include "framework/memory.hpp"

namespace pride::engine {

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

}  // namespace

std::string no_optimum(const GridSpec& g) {
    return g.objective == "user" ? "the user objective has no per-step costs (step_cost)"
                                 : "the " + g.objective + " objective is not a sum of step and turn costs";
}

namespace {

void require_oracle(const GridSpec& g, const GridTarget& target) {
    require(target.has_optimum(), "oracle", no_optimum(g) + ", so it has no exact oracle");
}

template <class Objective>
void prepare_grid(Prepared& out, const GridSpec& g, Objective objective) {
    grid::GridProblem<Objective> problem(g.map, g.start, g.goal, objective, g.corner_cutting);
    problem.count_calls(g.objective_calls);
    out.whole_grid.emplace(std::in_place_type<GridTarget>, GridTarget{problem});
    if (g.oracle) require_oracle(g, *out.grid());
    if (g.encoding.empty()) return;  // planned per run (planned_grid): A* and exact need none
    try {
        std::visit(
            [&](auto&& plan) {
                using Plan = std::decay_t<decltype(plan)>;
                if constexpr (std::is_same_v<Plan, grid::ChainSpace<Objective>>) {
                    out.searched.emplace(std::in_place_type<ChainTarget>, ChainTarget{std::move(plan)});
                } else {
                    grid::GridProblem<Objective> suggesting = problem;
                    suggesting.set_walks(suggested_walks(g));
                    out.dimension = plan.dimension(problem);
                    using Box =
                        std::conditional_t<std::is_same_v<Plan, LinePlan>, GridLine<Objective>, GridFree<Objective>>;
                    out.searched.emplace(std::in_place_type<BoxTarget>,
                                         BoxTarget{Box(std::move(suggesting), std::move(plan))});
                }
            },
            plan_grid(g, problem));
    } catch (const InputError& e) {
        out.encoding_error = e;
    }
}

}  // namespace

/// The checks of a continuous problem's size, before any of it is allocated.
void require_problem_memory(const ContinuousSpec& c) {
    const auto* item = continuous::catalog().find(c.function);
    require(item != nullptr || !is_multiobjective_problem(c.function), "problem",
            c.function + " has several objectives: its runs are multi-objective ones (pride front, pride.front)");
    // Close names only for a name that is unknown: looking for them costs as much as building a problem.
    if (item == nullptr) throw InputError("problem", unknown_problem(c.function));
    require(c.dim >= 1 && c.dim <= max_budget, "dim",
            fmt::format("must be an integer in [1, {}], got {}", max_budget, c.dim));
    // Bounds, an optimum and scratch vectors per coordinate, and a rotation (dim^2) for an
    // instance that has one.
    const double n = static_cast<double>(c.dim);
    const bool rotated = c.instance.value_or(continuous::default_instance(item->entry)) != 0;
    require_memory(8.0 * (8.0 * n + (rotated ? 2.0 * n * n : 0.0)), "dim",
                   fmt::format("{} in dimension {}", c.function, c.dim));
}

bool has_constraints(const CallbackSpec& cb) {
    for (const auto& [count, where] :
         {std::pair{cb.inequalities, "inequalities"}, std::pair{cb.equalities, "equalities"}})
        require(count >= 0 && count <= kMaxConstraints, where,
                fmt::format("must be an integer in [0, {}], got {}", kMaxConstraints, count));
    const bool any = cb.inequalities + cb.equalities > 0;
    require(any || !cb.constrained, "constraints",
            "a constrained function is given, but no inequalities or equalities");
    require(!any || static_cast<bool>(cb.constrained), "constraints",
            "inequalities or equalities are declared, but no function returning them (constrained)");
    return any;
}

namespace {

/// k from `prefix` followed by two digits, 01 to `count`.
std::optional<int> two_digit_number(const std::string& name, std::string_view prefix, int count) {
    if (!name.starts_with(prefix) || name.size() != prefix.size() + 2) return std::nullopt;
    const char a = name[prefix.size()], b = name[prefix.size() + 1];
    if (a < '0' || a > '9' || b < '0' || b > '9') return std::nullopt;
    const int k = (a - '0') * 10 + (b - '0');
    if (k < 1 || k > count) return std::nullopt;
    return k;
}

}  // namespace

std::optional<int> cec2006_number(const std::string& name) {
    return two_digit_number(name, "cec2006-g", continuous::cec2006::kProblems);
}

std::optional<int> cec2020rw_number(const std::string& name) {
    return two_digit_number(name, "cec2020rw-rc", continuous::cec2020rw::kProblems);
}

std::optional<int> bbob_constrained_number(const std::string& name) {
    const std::string_view prefix = continuous::bbob_constrained::kPrefix;
    if (!name.starts_with(prefix)) return std::nullopt;
    const std::string digits = name.substr(prefix.size());
    const bool number = !digits.empty() && digits.size() <= 2 && digits[0] != '0' &&
                        std::all_of(digits.begin(), digits.end(), [](char d) { return d >= '0' && d <= '9'; });
    const int k = number ? std::stoi(digits) : 0;
    require(k >= 1 && k <= continuous::bbob_constrained::kFunctions, "problem",
            fmt::format("unknown problem '{}': the bbob-constrained functions are {}1 to {}{}", name, prefix, prefix,
                        continuous::bbob_constrained::kFunctions));
    return k;
}

const std::vector<NamedItem>& constrained_problems() {
    static const std::vector<NamedItem> items = [] {
        std::vector<NamedItem> out;
        const auto counts = [](const ConstraintCounts& c) {
            return fmt::format("{} inequalit{}, {} equalit{}", c.inequalities, c.inequalities == 1 ? "y" : "ies",
                               c.equalities, c.equalities == 1 ? "y" : "ies");
        };
        for (int k = 1; k <= 24; ++k) {
            const continuous::cec2006::Problem p(k);
            out.push_back({fmt::format("cec2006-g{:02}", k),
                           fmt::format("CEC 2006 g{:02} (Liang et al. 2006): {}; best known {} (dim = {})", k,
                                       counts(p.constraint_counts()), p.best_known_value(), p.dimension())});
        }
        for (int k = 1; k <= continuous::cec2020rw::kProblems; ++k) {
            const continuous::cec2020rw::Problem p(k);
            out.push_back({fmt::format("cec2020rw-rc{:02}", k),
                           fmt::format("CEC 2020 real-world RC{:02} (Kumar et al. 2020): {}; best known {} (dim = {})",
                                       k, counts(p.constraint_counts()), p.best_known_value(), p.dimension())});
        }
        // COCO's order: nine objectives, each with six numbers m of active linear constraints.
        static constexpr const char* objectives[] = {
            "sphere",     "separable ellipsoid", "linear slope",        "rotated ellipsoid", "discus",
            "bent cigar", "different powers",    "separable Rastrigin", "rotated Rastrigin"};
        static constexpr const char* actives[] = {"1", "2", "6", "6 + floor(D/2)", "6 + D", "6 + 3D"};
        for (int n = 1; n <= continuous::bbob_constrained::kFunctions; ++n)
            out.push_back({fmt::format("{}{}", continuous::bbob_constrained::kPrefix, n),
                           fmt::format("COCO bbob-constrained: {} with m = {} active linear constraints and floor(m/2) "
                                       "inactive ones; COCO's instances (dim 2 to 40; the suite's 2, 3, 5, 10, 20, 40)",
                                       objectives[(n - 1) / 6], actives[(n - 1) % 6])});
        return out;
    }();
    return items;
}

std::string unknown_problem(const std::string& name) {
    std::vector<std::string> names;
    for (const auto& item : continuous::catalog().items()) names.push_back(item.name);
    for (const auto& item : constrained_problems()) names.push_back(item.name);
    const std::string several = multiobjective_problem_names();
    for (std::size_t at = 0; at < several.size();) {
        const std::size_t comma = std::min(several.find(", ", at), several.size());
        names.push_back(several.substr(at, comma - at));
        at = comma + 2;
    }
    return "unknown problem '" + name + "'" + did_you_mean(name, names);
}

namespace {

/// A function of COCO's bbob-constrained suite: dimension 2 to 40, instance 1 when none is given.
void prepare_bbob_constrained(Prepared& out, const ContinuousSpec& c, int number) {
    using continuous::bbob_constrained::kMaxDimension;
    require(c.dim >= 2 && c.dim <= static_cast<std::int64_t>(kMaxDimension), "dim",
            fmt::format("{} takes a dimension from 2 to {} (the suite's: 2, 3, 5, 10, 20, 40), got {}", c.function,
                        kMaxDimension, c.dim));
    require(c.objectives == 0 || c.objectives == 1, "objectives",
            fmt::format("{} has one objective, got {}", c.function, c.objectives));
    continuous::bbob_constrained::Problem problem(number, static_cast<std::size_t>(c.dim), c.instance.value_or(1));
    out.name = c.function;
    out.dimension = problem.dimension();
    out.searched.emplace(std::in_place_type<ConstrainedBoxTarget>, ConstrainedBoxTarget{std::move(problem)});
}

/// A problem of a constrained suite (CEC 2006, CEC 2020 real-world): its own dimension, no instance.
template <class SuiteProblem>
void prepare_constrained_suite(Prepared& out, const ContinuousSpec& c, int number) {
    SuiteProblem problem(number);
    require(c.dim == static_cast<std::int64_t>(problem.dimension()), "dim",
            fmt::format("{} has dimension {}, got {}", c.function, problem.dimension(), c.dim));
    require(!c.instance, "instance", c.function + " has no instances");
    require(c.objectives == 0 || c.objectives == 1, "objectives",
            fmt::format("{} has one objective, got {}", c.function, c.objectives));
    out.name = c.function;
    out.dimension = problem.dimension();
    out.searched.emplace(std::in_place_type<ConstrainedBoxTarget>, ConstrainedBoxTarget{problem});
}

std::shared_ptr<const Prepared> prepare(const ProblemSpec& spec) {
    auto out = std::make_shared<Prepared>();
    out->spec = spec;
    const auto* continuous = std::get_if<ContinuousSpec>(&spec);
    if (several_objectives(spec)) {
        prepare_several(*out);
    } else if (const auto number = continuous ? cec2006_number(continuous->function) : std::nullopt) {
        prepare_constrained_suite<continuous::cec2006::Problem>(*out, *continuous, *number);
    } else if (const auto rc = continuous ? cec2020rw_number(continuous->function) : std::nullopt) {
        prepare_constrained_suite<continuous::cec2020rw::Problem>(*out, *continuous, *rc);
    } else if (const auto k = continuous ? bbob_constrained_number(continuous->function) : std::nullopt) {
        prepare_bbob_constrained(*out, *continuous, *k);
    } else if (const auto* c = continuous) {
        require_problem_memory(*c);
        require(c->objectives == 0 || c->objectives == 1, "objectives",
                fmt::format("{} has one objective, got {}", c->function, c->objectives));
        out->name = c->function;
        out->dimension = static_cast<std::size_t>(c->dim);
        out->searched.emplace(std::in_place_type<BoxTarget>,
                              BoxTarget{continuous::make_function(c->function, c->dim, c->instance)});
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
        if (has_constraints(cb)) {
            out->searched.emplace(
                std::in_place_type<ConstrainedBoxTarget>,
                ConstrainedBoxTarget{ConstrainedCallbackProblem(
                    cb.name, cb.lower, cb.upper,
                    {static_cast<std::size_t>(cb.inequalities), static_cast<std::size_t>(cb.equalities)}, cb.tolerance,
                    cb.constrained, cb.types)});
        } else {
            out->searched.emplace(std::in_place_type<BoxTarget>,
                                  BoxTarget{CallbackProblem(cb.name, cb.lower, cb.upper, cb.scalar, cb.batch,
                                                            cb.thread_safe, {}, cb.types)});
        }
    }
    return out;
}

/// A grid problem's variant planned on another encoding, connector or init (Problem::planned_for):
/// the same grid target (its tables and its cached optimum), the encoding's target built anew.
void prepare_plan(Prepared& v, const GridSpec& plan) {
    check_grid_spec(plan);
    const std::optional<Target> grid = v.whole_grid;
    if (plan.objective == "user")
        prepare_grid(v, plan, OtherObjective{plan.path_objective});
    else if (plan.objective == "iqga")
        prepare_grid(v, plan, OtherObjective::iqga());
    else
        prepare_grid(v, plan, linear_objective(plan));
    v.whole_grid = grid;
}

}  // namespace

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
        const bool encoding = std::string_view(key) == "encoding" && named_in(grid_encodings(), it->second);
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
    // Several objectives are searched on the spec's encoding, whatever the algorithm.
    if (!g || prepared_->objectives() > 1) return prepared_;
    const AlgorithmEntry& entry = algorithms().at(algorithm.name);
    const GridSpec plan = planned_grid(entry, *g, algorithm.params);
    if (plan.encoding == g->encoding && plan.connector == g->connector && plan.init == g->init) return prepared_;
    const std::string key = plan.encoding + "|" + plan.connector + "|" + plan.init;
    const std::lock_guard lock(variants_->mutex);
    auto& variant = variants_->by_plan[key];
    if (!variant) {
        auto v = std::make_shared<Prepared>(*prepared_);
        v->spec = plan;
        v->searched.reset();
        v->encoding_error.reset();
        v->dimension = 0;
        prepare_plan(*v, plan);
        variant = std::move(v);
    }
    return variant;
}

bool Problem::is_grid() const {
    return std::holds_alternative<GridSpec>(prepared_->spec);
}
bool Problem::is_chain() const {
    return prepared_->on_chains();
}
std::size_t Problem::objectives() const {
    return prepared_->objectives();
}
std::vector<std::string> Problem::objective_names() const {
    return prepared_->objective_names;
}
const Matrix& Problem::reference_front() const {
    return reference_front_of(*prepared_).values;
}
const std::vector<grid::Path>& Problem::reference_paths() const {
    return reference_front_of(*prepared_).paths;
}
bool Problem::additive() const {
    return prepared_->grid() && prepared_->grid()->additive();
}
bool Problem::has_optimum() const {
    return prepared_->grid() && prepared_->grid()->has_optimum();
}
Problem Problem::with_oracle() const {
    const auto* g = std::get_if<GridSpec>(&prepared_->spec);
    require(g != nullptr, "oracle", "only grid problems have an exact optimum");
    require(prepared_->grid() != nullptr, "oracle",
            "a grid problem of several objectives is measured against its exact front, not an optimum");
    require_oracle(*g, *prepared_->grid());
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
namespace {
const continuous::bbob_constrained::Problem* bbob_constrained_of(const Prepared& p) {
    return p.constrained() ? std::get_if<continuous::bbob_constrained::Problem>(&p.constrained()->problem) : nullptr;
}
}  // namespace

std::int64_t Problem::instance() const {
    if (const auto* c = bbob_constrained_of(*prepared_)) return c->instance();
    const auto* f = prepared_->box() ? std::get_if<continuous::Function>(&prepared_->box()->problem) : nullptr;
    return f ? f->instance() : 0;
}
std::optional<double> optimum_of(const Prepared& p) {
    if (const auto* cb = std::get_if<CallbackSpec>(&p.spec)) return cb->f_opt;
    if (const auto* c = bbob_constrained_of(p)) return c->optimum_value();  // f(x*), COCO's best value
    const auto* f = p.box() ? std::get_if<continuous::Function>(&p.box()->problem) : nullptr;
    if (!f) return std::nullopt;
    const double v = f->optimum_value();
    return std::isfinite(v) ? std::optional<double>(v) : std::nullopt;
}

std::optional<double> Problem::optimum_value() const {
    return optimum_of(*prepared_);
}

}  // namespace pride::engine

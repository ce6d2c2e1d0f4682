#include "experiment/campaign/prepare.hpp"
#include "experiment/campaign/protocol.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <functional>
#include <map>
#include <set>
#include <tuple>

#include "engine/json.hpp"
#include "engine/planner_settings.hpp"
#include "engine/prepared.hpp"
#include "engine/registry.hpp"
#include "experiment/campaign/identity.hpp"
#include "experiment/campaign/run_one.hpp"
#include "experiment/storage/file_name.hpp"
#include "experiment/storage/published.hpp"
#include "framework/error.hpp"
#include "problems/continuous/catalog.hpp"
#include "problems/continuous/cec/suites.hpp"

namespace pride::campaign {

using engine::check;
using engine::check_grid_names;
using engine::check_quality;
using engine::ContinuousSpec;
using engine::GridSpec;
using engine::load_map;
using engine::max_budget;
using engine::Problem;
using engine::ProblemSpec;
using storage::file_name;
namespace {

std::string where_of(const Campaign& c, int line, const std::string& what) {
    if (!c.file.empty() && line > 0) return fmt::format("{}:{}", c.file, line);
    return (c.file.empty() ? std::string("campaign") : c.file) + ": " + what;
}

/// An error already placed at its key (start_world, goal_world), passed on as it is.
struct PlacedError : InputError {
    using InputError::InputError;
};

/// The cells of a grid problem's world points (CampaignProblem::start_world, goal_world), on its
/// map; errors at the key's line, naming the key.
void place_world_ends(const Campaign& c, CampaignProblem& p, GridSpec& g) {
    const auto place = [&](const CampaignProblem::WorldEnd& end, const char* key, const char* cell_key,
                           grid::Cell& cell) {
        if (!end.point) return;
        try {
            cell =
                engine::world_cell(*g.map, end.point->x, end.point->y, key, std::string("'") + cell_key + "' (a cell)");
        } catch (const InputError& e) {
            throw PlacedError(where_of(c, end.line, "problem '" + p.id + "'"), "problem '" + p.id + "': " + e.what());
        }
    };
    place(p.start_world, "start_world", "start", g.start);
    place(p.goal_world, "goal_world", "goal", g.goal);
}

/// A grid problem built from its spec; the ends' errors (the goal unreachable) at a world key's line
/// when the end came from one.
std::shared_ptr<const Problem> build_grid(const Campaign& c, const CampaignProblem& p, const ProblemSpec& spec,
                                          bool with_oracle, bool& oracle) {
    try {
        Problem problem(spec);
        if (with_oracle && problem.has_optimum()) {
            problem = problem.with_oracle();
            oracle = true;
        }
        return std::make_shared<const Problem>(std::move(problem));
    } catch (const InputError& e) {
        const CampaignProblem::WorldEnd* end = e.where() == "start"  ? &p.start_world
                                               : e.where() == "goal" ? &p.goal_world
                                                                     : nullptr;
        if (!end || !end->point) throw;
        throw PlacedError(where_of(c, end->line, "problem '" + p.id + "'"),
                          "problem '" + p.id + "': " + e.where() + "_world: " + e.detail());
    }
}

/// The campaign's settings that no algorithm of it uses, refused as `pride path` refuses them for
/// one planner (engine/planner_settings.hpp), at the [[problem]] or [budget] key that gives them.
/// A campaign with an algorithm that plans through an encoding shares its problems' settings and
/// its budget with the planners beside it, which take them without using them.
void refuse_unused_planner_settings(const Campaign& c) {
    if (!planners_only(c)) return;
    const bool python = c.file.empty();
    bool evaluates = false;  // OMPL's planners count their validity checks
    for (const auto& a : c.algorithms) evaluates = evaluates || engine::algorithms().find(a.spec.name)->evaluates();
    const engine::AlgorithmSpec& first = c.algorithms.front().spec;
    const std::string every =
        c.algorithms.size() == 1 ? std::string() : " (every algorithm of this campaign plans on the whole map)";
    for (const auto& p : c.problems) {
        const auto* g = std::get_if<GridSpec>(&p.spec);
        if (!g) continue;
        try {
            engine::refuse_unused_planner_settings(first, *g, engine::Budget{});
        } catch (const InputError& e) {
            const std::string entry = "problem '" + p.id + "'";
            throw InputError(python || p.line <= 0 ? entry : fmt::format("{}:{}: {}", c.file, p.line, entry),
                             e.what() + every);
        }
    }
    const auto refuse_budget = [&](engine::Budget b, int line) {
        engine::PlannerSettingNames names;
        names.evaluations = python ? "evals" : "[budget] evaluations";
        names.iterations = python ? "iters" : "[budget] iterations";
        names.threads = "threads";
        try {
            engine::refuse_unused_planner_settings(first, GridSpec{}, b, names);
        } catch (const InputError& e) {
            if (python || line <= 0) throw InputError(e.what() + every);
            throw InputError(fmt::format("{}:{}", c.file, line), e.what() + every);
        }
    };
    if (c.budget.evaluations && !evaluates) {
        engine::Budget b;
        b.evaluations = c.budget.evaluations;
        refuse_budget(b, c.evaluations_line);
    }
    if (c.budget.iterations) {
        engine::Budget b;
        b.iterations = c.budget.iterations;
        refuse_budget(b, c.iterations_line);
    }
    if (c.budget.threads != 1) {
        engine::Budget b;
        b.threads = c.budget.threads;
        refuse_budget(b, c.threads_line);
    }
}

/// The CEC suite of a problem's function by the catalog (cec2017-fN and cec2022-fN, from a
/// [[suite]] or a [[problem]] alike), or nullptr.
const continuous::cec::SuiteRules* cec_rules_of(const ContinuousSpec& f) {
    if (f.function.rfind("cec2020rw-rc", 0) == 0) return continuous::cec::suite_rules("cec2020rw");
    const auto* item = continuous::catalog().find(f.function);
    return item ? continuous::cec::suite_rules(item->entry.suite) : nullptr;
}

}  // namespace

bool planners_only(const Campaign& c) {
    if (c.algorithms.empty()) return false;
    for (const auto& a : c.algorithms) {
        const engine::AlgorithmEntry* entry = engine::algorithms().find(a.spec.name);
        if (!entry || !entry->whole_map()) return false;
    }
    return true;
}

ProblemSpec problem_spec(const CampaignProblem& p) {
    ProblemSpec spec = p.spec;
    if (!p.objectives) return spec;
    if (auto* g = std::get_if<GridSpec>(&spec)) {
        g->objectives = *p.objectives;
    } else if (!p.objectives->empty()) {
        const std::string& m = *p.objectives;
        require(m.find_first_not_of("0123456789") == std::string::npos && m.size() <= 6, "objectives",
                "expected the number of objectives M, got '" + m + "'");
        std::get<ContinuousSpec>(spec).objectives = std::stoll(m);
    }
    return spec;
}

double problem_memory(const ProblemSpec& spec) {
    constexpr double built = 16e3;
    if (const auto* f = std::get_if<ContinuousSpec>(&spec)) {
        const auto* item = continuous::catalog().find(f->function);
        const double n = std::max(0.0, static_cast<double>(f->dim));
        const bool rotated = item && f->instance.value_or(continuous::default_instance(item->entry)) != 0 &&
                             item->entry.instances != continuous::Instances::none;
        return built + 8.0 * (8.0 * n + (rotated ? 2.0 * n * n : 0.0));
    }
    return built;
}

double run_list_memory(std::size_t problem_id_length, std::size_t algorithm_id_length) {
    // A task (24 bytes), its number (8), its key (72) and the key's node in the set of stored
    // keys (72 + 48), each key's ids on the heap beyond 15 characters (with malloc's overhead).
    const auto heap = [](std::size_t n) { return n > 15 ? 2.0 * (static_cast<double>(n) + 32.0) : 0.0; };
    return 224.0 + heap(problem_id_length) + heap(algorithm_id_length);
}

void apply_suite_rules(Campaign& c) {
    const std::string file = c.file.empty() ? std::string("campaign") : c.file;
    std::set<std::string_view> suites;
    const CampaignProblem* other = nullptr;      // the first problem of no CEC suite
    const CampaignProblem* no_budget = nullptr;  // the first problem without a default budget
    for (const auto& p : c.problems) {
        const auto* f = std::get_if<ContinuousSpec>(&p.spec);
        const continuous::cec::SuiteRules* rules = f ? cec_rules_of(*f) : nullptr;
        if (rules)
            suites.insert(rules->name);
        else if (!other)
            other = &p;
        if (!no_budget && !(rules && continuous::cec::default_evaluations(rules->name, f->dim))) no_budget = &p;
    }
    if (c.seeds < 1) {
        require(c.seeds == 0 && !other && suites.size() == 1, file,
                suites.empty() ? std::string("missing key 'seeds'")
                               : "missing key 'seeds': only a campaign of one CEC suite's problems has a default (51 "
                                 "runs for cec2017, 30 for cec2022, 25 for cec2020rw)");
        c.seeds = continuous::cec::suite_rules(*suites.begin())->runs;
    }
    // Planners alone need no budget: they search the whole map once (and refuse one they would not use).
    if (no_budget && !planners_only(c) && !c.budget.evaluations && !c.budget.iterations && !c.evaluations_per_dim)
        throw InputError(file, suites.empty() ? std::string("missing [budget] with 'evaluations', "
                                                            "'evaluations_per_dim' or 'iterations'")
                                              : "missing [budget] with 'evaluations', 'evaluations_per_dim' or "
                                                "'iterations': only the CEC suites' problems have a default budget "
                                                "(CEC 2022's at D = 10 and 20), and problem '" +
                                                    no_budget->id + "' has none");
    // The CEC suites' MaxFES, where the campaign gives no evaluation budget.
    if (!c.budget.evaluations && !c.evaluations_per_dim)
        for (auto& p : c.problems)
            if (const auto* f = std::get_if<ContinuousSpec>(&p.spec))
                if (const continuous::cec::SuiteRules* rules = cec_rules_of(*f))
                    p.evaluations = continuous::cec::default_evaluations(rules->name, f->dim);
}

void prepare(Campaign& c) {
    const std::string file = c.file.empty() ? std::string("campaign") : c.file;
    require(!c.name.empty(), file, "missing key 'name'");
    require(!c.problems.empty() || c.seeds >= 1, file, "missing key 'seeds'");
    require(!c.problems.empty() || c.budget.evaluations || c.budget.iterations || c.evaluations_per_dim, file,
            "missing [budget] with 'evaluations', 'evaluations_per_dim' or 'iterations'");
    require(!(c.budget.evaluations && c.evaluations_per_dim), file,
            "[budget]: give evaluations or evaluations_per_dim, not both");
    require(!c.problems.empty(), file, "no [[problem]]");
    apply_protocol(c);
    apply_suite_rules(c);
    require(c.seeds >= 1 && c.seeds <= max_campaign_seeds, file, "seeds " + seeds_range_message(c.seeds));
    if (!c.seed_list.empty()) {
        // A campaign built in code states its seeds as the file does: distinct, in range, and as many as it says.
        require(
            c.seed_list.size() == static_cast<std::size_t>(c.seeds), file,
            fmt::format("seeds: {} runs per problem and algorithm, but {} seeds listed", c.seeds, c.seed_list.size()));
        // Up to a million seeds: no message made, nor node allocated, per seed (a range of a
        // million took seconds so).
        for (const std::int64_t s : c.seed_list)
            if (s < 1 || s > max_campaign_seeds) throw InputError(file, "seeds: a seed " + seeds_range_message(s));
        // Ranges come in increasing order, and are then distinct without a sort.
        if (!std::is_sorted(c.seed_list.begin(), c.seed_list.end(), std::less_equal<>())) {
            std::vector<std::int64_t> sorted = c.seed_list;
            std::sort(sorted.begin(), sorted.end());
            if (const auto twice = std::adjacent_find(sorted.begin(), sorted.end()); twice != sorted.end())
                throw InputError(file, fmt::format("seeds: seed {} is listed twice", *twice));
        }
    }
    require(!c.algorithms.empty(), file, "no [[algorithm]]");
    require(c.problems.size() <= max_campaign_problems, file,
            fmt::format("{} problems; a campaign has at most {}", c.problems.size(), max_campaign_problems));
    // Every problem is built, and the list of runs made (a task and a stored key per run), before
    // any run starts: both are checked here, before either is (128 bytes a run was less
    // than a key with its two ids takes, and the problems' own 12 kB each were not counted).
    std::size_t problem_id = 0, algorithm_id = 0;
    double built = 0.0;
    for (const auto& p : c.problems) {
        problem_id = std::max(problem_id, p.id.size());
        // A problem too large alone is refused as it is built, by the engine's check naming its
        // dimension; the sum is of the others.
        if (const double bytes = problem_memory(p.spec); bytes <= available_memory()) built += bytes;
    }
    for (const auto& a : c.algorithms) algorithm_id = std::max(algorithm_id, a.id.size());
    const double runs = static_cast<double>(c.problems.size()) * static_cast<double>(c.algorithms.size()) *
                        static_cast<double>(c.seeds);
    const double listed = runs * run_list_memory(problem_id, algorithm_id);
    require(built + listed <= available_memory(), file,
            fmt::format("{} problems and their {} runs ({} algorithms x {} seeds each) need about {} of memory "
                        "({} for the problems, {} to list the runs), more than the {} this machine has",
                        c.problems.size(), runs, c.algorithms.size(), c.seeds, format_bytes(built + listed),
                        format_bytes(built), format_bytes(listed), format_bytes(available_memory())));
    // Names as the store keeps and the summaries print them: one root for the campaign
    // files and Python; the name itself is not shown (it may hold the very character refused).
    if (const std::string why = name_problem(c.name); !why.empty()) throw InputError(file, "name " + why);
    for (const auto& p : c.problems)
        if (const std::string why = name_problem(p.id); !why.empty())
            throw InputError(where_of(c, p.line, "problem"), "problem id " + why);
    for (const auto& a : c.algorithms)
        if (const std::string why = name_problem(a.id); !why.empty())
            throw InputError(where_of(c, a.line, "algorithm"), "algorithm id " + why);
    // "published:" marks the runs a store holds from others' files (storage/published.hpp), never
    // a campaign's: its runs could otherwise be taken for the published ones, or the reverse.
    for (const auto& p : c.problems)
        if (p.id.rfind(storage::kPublishedPrefix, 0) == 0)
            throw InputError(where_of(c, p.line, "problem"), "problem id '" + p.id +
                                                                 "': ids starting with 'published:' are kept for "
                                                                 "published runs (pride import)");
    for (const auto& a : c.algorithms)
        if (a.id.rfind(storage::kPublishedPrefix, 0) == 0)
            throw InputError(where_of(c, a.line, "algorithm"), "algorithm id '" + a.id +
                                                                   "': ids starting with 'published:' are kept for "
                                                                   "published runs (pride import)");
    std::set<std::string> ids;
    for (const auto& p : c.problems)
        if (!ids.insert(p.id).second)
            throw InputError(where_of(c, p.line, "problem '" + p.id + "'"), "duplicate problem id '" + p.id + "'");
    ids.clear();
    for (const auto& a : c.algorithms)
        if (!ids.insert(a.id).second)
            throw InputError(where_of(c, a.line, "algorithm '" + a.id + "'"), "duplicate algorithm id '" + a.id + "'");
    // Ids that would name the same file (figures, exports), also on a file system that ignores case.
    const auto same_file = [&](const auto& items, const char* kind) {
        std::map<std::string, std::string> seen;  // lower-case file name -> id
        for (const auto& item : items) {
            std::string name = file_name(item.id);
            for (char& ch : name) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
            const auto [it, fresh] = seen.emplace(name, item.id);
            if (!fresh)
                throw InputError(where_of(c, item.line, std::string(kind) + " '" + item.id + "'"),
                                 fmt::format("{} ids '{}' and '{}' would name the same file ('{}'); rename one", kind,
                                             it->second, item.id, file_name(item.id)));
        }
    };
    same_file(c.problems, "problem");
    same_file(c.algorithms, "algorithm");

    // Each map is read once, whatever number of problems use it.
    std::map<std::tuple<std::string, std::int64_t, bool>, std::shared_ptr<const grid::GridMap>> maps;
    for (auto& p : c.problems) {
        const std::string where = where_of(c, p.line, "problem '" + p.id + "'");
        try {
            if (auto* g = std::get_if<GridSpec>(&p.spec)) {
                check_grid_names(*g);
                if (!g->map) {
                    auto& m = maps[{p.map_file, p.inflate, p.unknown_free}];
                    grid::MapReadOptions read;
                    read.unknown_free = p.unknown_free;
                    read.named_in_file = true;  // a campaign's maps are files, never standard input
                    if (!m) m = load_map(p.map_file, p.inflate, read);
                    g->map = m;
                }
                place_world_ends(c, p, *g);
                // The exact optimum beside every run whose objective has one, for gaps in reports.
                g->oracle = false;
                g->path_gaps = p.path_gaps;
                bool oracle = false;
                p.problem = p.is_multiobjective() ? build_grid(c, p, problem_spec(p), false, oracle)
                                                  : build_grid(c, p, p.spec, true, oracle);
                g->oracle = oracle;
            } else {
                // With constraints, each run's row records its best point's violation and first feasible
                // evaluation (store schema 6), and reports rank runs by Deb's order.
                p.problem = std::make_shared<const Problem>(problem_spec(p));
            }
            if (c.evaluations_per_dim) {
                require(!std::holds_alternative<GridSpec>(p.spec), "evaluations_per_dim",
                        "a grid problem has no dimension; give the campaign an absolute budget (evaluations)");
                const double n = static_cast<double>(*c.evaluations_per_dim) * static_cast<double>(p.dimension());
                require(n <= static_cast<double>(max_budget), "evaluations_per_dim",
                        fmt::format("{} x {} dimensions is more than {} evaluations", *c.evaluations_per_dim,
                                    p.dimension(), max_budget));
                p.evaluations = *c.evaluations_per_dim * static_cast<std::int64_t>(p.dimension());
            }
        } catch (const PlacedError&) {
            throw;
        } catch (const InputError& e) {
            throw InputError(where, "problem '" + p.id + "': " + e.what());
        }
    }
    // Each map hashed once, whatever number of problems use it.
    std::map<const grid::GridMap*, std::string> map_digests;
    for (auto& p : c.problems) {
        const auto* g = std::get_if<GridSpec>(&p.spec);
        if (!g || !g->map) {
            p.digest = problem_digest(p);
            continue;
        }
        auto& m = map_digests[g->map.get()];
        if (m.empty()) m = map_digest(*g->map);
        p.digest = compose_digest(m, p);
    }
    // A quality every run of a problem records must be computable before anything runs.
    for (const auto& p : c.problems) {
        if (!p.is_multiobjective()) continue;
        try {
            check_quality(*p.problem);
        } catch (const InputError& e) {
            throw InputError(where_of(c, p.line, "problem '" + p.id + "'"), e.what());
        }
    }
    for (const auto& a : c.algorithms) {
        const std::string where = where_of(c, a.line, "algorithm '" + a.id + "'");
        for (const auto& p : c.problems) {
            try {
                check(a.spec, *p.problem, problem_budget(c.budget, p));
            } catch (const InputError& e) {
                throw InputError(where, "algorithm '" + a.id + "' on problem '" + p.id + "': " + e.what());
            }
        }
    }
    refuse_unused_planner_settings(c);
    if (c.text.empty()) c.text = campaign_text(c);
}

}  // namespace pride::campaign

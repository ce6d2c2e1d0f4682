#include "experiment/campaign/identity.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <filesystem>
#include <string>
#include <string_view>
#include <variant>

#include "engine/json.hpp"
#include "engine/registry.hpp"
#include "experiment/storage/digest.hpp"
#include "problems/continuous/bbob_constrained/bbob_constrained.hpp"
#include "problems/continuous/catalog.hpp"
#include "problems/continuous/cec/functions.hpp"

namespace pride::campaign {

using engine::CallbackSpec;
using engine::ContinuousSpec;
using engine::GridSpec;
using engine::json_array;
using engine::json_number;
using engine::json_string;

/// A canonical text of a campaign built in code, so that a store is never mixed with another's.
std::string campaign_text(const Campaign& c) {
    // A count as before; listed seeds as their list (the runs of seed 5 are one run either way:
    // a store grows, and stores merge, across the two).
    std::string s =
        fmt::format("name = {}\nseeds = {}\n", json_string(c.name),
                    c.seed_list.empty() ? std::to_string(c.seeds) : fmt::format("[{}]", fmt::join(c.seed_list, ", ")));
    if (c.budget.evaluations) s += fmt::format("evaluations = {}\n", *c.budget.evaluations);
    if (c.budget.iterations) s += fmt::format("iterations = {}\n", *c.budget.iterations);
    if (c.evaluations_per_dim) s += fmt::format("evaluations_per_dim = {}\n", *c.evaluations_per_dim);
    if (c.target) s += fmt::format("target = {}\n", json_number(*c.target));
    if (c.target_precision) s += fmt::format("precision = {}\n", json_number(*c.target_precision));
    for (const auto& p : c.problems) {
        s += "problem " + json_string(p.id) + ": ";
        if (const auto* f = std::get_if<ContinuousSpec>(&p.spec)) {
            s += fmt::format("{} {}", f->function, f->dim);
            if (f->instance) s += fmt::format(" instance {}", *f->instance);  // absent: texts as before instances
        }
        if (const auto* g = std::get_if<GridSpec>(&p.spec))
            s += fmt::format("grid {} {} ({},{}) ({},{}) {} {} {} {} {} {} {}", json_string(p.map_file), p.inflate,
                             g->start.x, g->start.y, g->goal.x, g->goal.y, g->objective, g->encoding, g->connector,
                             g->waypoints, g->init, g->corner_cutting, json_array(g->weights));
        if (p.unknown_free) s += " unknown_free";
        if (p.path_gaps) s += " path_gaps";
        if (const auto* g = std::get_if<GridSpec>(&p.spec); g && g->lambda) s += " lambda " + json_number(*g->lambda);
        s += "\n";
    }
    for (const auto& a : c.algorithms) {
        s += "algorithm " + json_string(a.id) + ": " + a.spec.name;
        for (const auto& [k, v] : a.spec.params.values()) s += " " + k + "=" + json_number(v);
        for (const auto& [k, v] : a.spec.params.names()) s += " " + k + "=" + json_string(v);
        s += "\n";
    }
    return s;
}

std::string budget_definition(const Campaign& c) {
    std::string s;
    if (c.budget.evaluations) s += fmt::format("evaluations = {}; ", *c.budget.evaluations);
    if (c.evaluations_per_dim) s += fmt::format("evaluations_per_dim = {}; ", *c.evaluations_per_dim);
    if (c.budget.iterations) s += fmt::format("iterations = {}; ", *c.budget.iterations);
    // No evaluation budget given: the CEC problems run their suites' MaxFES (prepare()).
    if (!c.budget.evaluations && !c.evaluations_per_dim &&
        std::any_of(c.problems.begin(), c.problems.end(), [](const CampaignProblem& p) { return p.evaluations; }))
        s += "evaluations by the CEC suites' rules; ";
    return s.empty() ? s : s.substr(0, s.size() - 2);
}

std::string problem_definition(const CampaignProblem& p) {
    if (p.is_multiobjective()) {
        const auto* f = std::get_if<ContinuousSpec>(&p.spec);
        CampaignProblem plain = p;
        plain.objectives.reset();
        const std::string objectives = p.objectives->empty() ? "(default)" : *p.objectives;
        return f ? fmt::format("{} dim {} objectives {}", f->function,
                               f->dim == 0 ? std::string("(default)") : std::to_string(f->dim), objectives)
                 : problem_definition(plain) + " objectives " + objectives;
    }
    if (const auto* f = std::get_if<ContinuousSpec>(&p.spec))
        return fmt::format("{} dim {} instance {}", f->function, f->dim,
                           p.problem ? p.problem->instance() : f->instance.value_or(0));
    if (const auto* g = std::get_if<GridSpec>(&p.spec)) {
        const std::string map =
            p.map_file.empty() ? std::string("(a map given in code)") : std::filesystem::absolute(p.map_file).string();
        std::string s = fmt::format(
            "grid {} inflate {} start ({},{}) goal ({},{}) objective {} encoding {} connector {} waypoints {} init {} "
            "corner_cutting {} weights {}",
            json_string(map), p.inflate, g->start.x, g->start.y, g->goal.x, g->goal.y, g->objective,
            g->encoding.empty() ? "(native)" : g->encoding, g->connector, g->waypoints,
            g->init.empty() ? "(default)" : g->init, g->corner_cutting, json_array(g->weights));
        if (g->lambda) s += " lambda " + json_number(*g->lambda);
        // Only when set, so that the definitions of earlier stores stay as they were written.
        if (p.unknown_free) s += " unknown_free true";
        if (p.path_gaps) s += " path_gaps true";  // what its runs record (only when set, as above)
        return s;
    }
    return "function (a callback: known by its id alone)";
}

std::string map_digest(const grid::GridMap& m) {
    storage::Sha256 h;
    h.field("grid map v1");
    const std::int64_t size[2] = {m.width(), m.height()};
    h.add(size, sizeof size);
    unsigned char chunk[4096];
    std::size_t used = 0;
    for (std::size_t i = 0; i < m.size(); ++i) {
        chunk[used++] = m.free_index(i) ? 0 : 1;
        if (used == sizeof chunk) {
            h.add(chunk, used);
            used = 0;
        }
    }
    h.add(chunk, used);
    return h.hex();
}

namespace {

std::string settings_digest(const CampaignProblem& p) {
    storage::Sha256 h;
    const auto number = [&](double v) { h.field(json_number(v)); };
    if (p.is_multiobjective()) h.field("objectives v1").field(*p.objectives);
    if (const auto* f = std::get_if<ContinuousSpec>(&p.spec)) {
        h.field("function v1").field(f->function).field(std::to_string(f->dim));
        h.field(std::to_string(p.problem ? p.problem->instance() : f->instance.value_or(0)));
        // A CEC function is also its data, which the user names (PRIDE_CEC2017_DATA): another folder
        // or an edited file makes another problem.
        const auto* item = continuous::catalog().find(f->function);
        if (item && item->entry.suite.starts_with("cec"))
            h.field(fmt::format("cec data {:016x}", continuous::cec::data_fingerprint(
                                                        item->entry.suite == "cec2017" ? continuous::cec::Suite::y2017
                                                                                       : continuous::cec::Suite::y2022,
                                                        item->entry.number, static_cast<std::size_t>(f->dim))));
    } else if (const auto* g = std::get_if<GridSpec>(&p.spec)) {
        h.field("grid v1").field(std::to_string(p.inflate));
        if (p.unknown_free) h.field("unknown cells free");  // only when set: earlier digests unchanged
        h.field(fmt::format("{},{} {},{}", g->start.x, g->start.y, g->goal.x, g->goal.y));
        h.field(g->objective).field(g->encoding).field(g->connector).field(std::to_string(g->waypoints));
        h.field(g->init).field(g->corner_cutting ? "corner cutting" : "no corner cutting");
        h.field(std::to_string(g->weights.size()));
        for (const double w : g->weights) number(w);
        h.field(g->lambda ? json_number(*g->lambda) : "no lambda");
        // A Python objective is known only as being one (and whether it has its per-step form).
        h.field(!g->path_objective             ? "no user objective"
                : g->path_objective->step_cost ? "a user objective with step costs"
                                               : "a user objective");
    } else if (const auto* b = std::get_if<CallbackSpec>(&p.spec)) {
        h.field("callback v1").field(b->name).field(std::to_string(b->lower.size()));
        for (const double v : b->lower) number(v);
        for (const double v : b->upper) number(v);
        h.field(b->f_opt ? json_number(*b->f_opt) : "no f_opt");
        // Its constraints' counts and tolerance make another problem (only when it has them: the
        // digests of callbacks without constraints stay as they were).
        if (b->constrained)
            h.field(fmt::format("constraints {} {} {}", b->inequalities, b->equalities, json_number(b->tolerance)));
    }
    return h.hex();
}

}  // namespace

std::string compose_digest(const std::string& map_hex, const CampaignProblem& p) {
    return (map_hex.empty() ? std::string() : "map sha256:" + map_hex + "; ") + "settings sha256:" + settings_digest(p);
}

std::string problem_digest(const CampaignProblem& p) {
    const auto* g = std::get_if<GridSpec>(&p.spec);
    return compose_digest(g && g->map ? map_digest(*g->map) : std::string(), p);
}

std::string name_problem(const std::string& name) {
    if (name.empty()) return "must not be empty";
    // Reports and exports name files and folders after ids, a figure after a problem and an
    // algorithm together: two ids of 100 bytes and their suffixes stay within the 255 bytes of a
    // file name, so that a stored run can always be reported.
    if (name.size() > kMaxNameBytes)
        return fmt::format("must be at most {} bytes long (it has {}): reports and exports name files after it",
                           kMaxNameBytes, name.size());
    for (std::size_t i = 0; i < name.size(); ++i) {
        const auto u = static_cast<unsigned char>(name[i]);
        // C0 controls and DEL, and C1 controls (U+0080-U+009F, two bytes in UTF-8): a terminal
        // acts on them (ESC starts a control sequence) rather than showing them.
        const bool c1 = u == 0xc2 && i + 1 < name.size() && static_cast<unsigned char>(name[i + 1]) >= 0x80 &&
                        static_cast<unsigned char>(name[i + 1]) <= 0x9f;
        if (u == 0) return fmt::format("must not contain a NUL character (U+0000 at byte {})", i + 1);
        if (u < 0x20 || u == 0x7f || c1)
            return fmt::format("must not contain control characters (U+{:04X} at byte {})",
                               c1 ? static_cast<unsigned char>(name[i + 1]) : u, i + 1);
    }
    return "";
}

std::string algorithm_definition(const CampaignAlgorithm& a) {
    std::string s = a.spec.name;
    for (const auto& [k, v] : a.spec.params.values()) s += " " + k + "=" + json_number(v);
    for (const auto& [k, v] : a.spec.params.names()) s += " " + k + "=" + json_string(v);
    return s;
}

storage::CampaignRows store_rows(const Campaign& c) {
    storage::CampaignRows rows;
    rows.name = c.name;
    rows.text = c.text;
    rows.target = c.target;
    rows.target_precision = c.target_precision;
    rows.precisions = json_array(coco_precisions());
    rows.budget = budget_definition(c);
    rows.problems.reserve(c.problems.size());
    for (const auto& p : c.problems) {
        storage::ProblemRow& r = rows.problems.emplace_back();
        const auto* g = std::get_if<GridSpec>(&p.spec);
        const auto* f = std::get_if<ContinuousSpec>(&p.spec);
        r.id = p.id;
        r.type = g ? "grid" : f ? f->function : p.problem->name();
        r.dim = g ? 2 : static_cast<std::int64_t>(p.dimension());
        r.map = p.map_file.empty() ? "" : std::filesystem::absolute(p.map_file).string();
        if (g) {
            r.start = fmt::format("{},{}", g->start.x, g->start.y);
            r.goal = fmt::format("{},{}", g->goal.x, g->goal.y);
        }
        // A multi-objective problem has no instance and no single optimum (its runs' values are
        // hypervolume gaps: 0 is the reference front).
        r.instance = p.problem ? p.problem->instance() : 0;
        r.f_opt = p.problem ? p.problem->optimum_value() : std::nullopt;
        if (const auto* item = f ? continuous::catalog().find(f->function) : nullptr;
            item && !item->entry.suite.empty()) {
            r.suite = item->entry.suite;
            r.fid = item->entry.number;
        } else if (const std::string_view prefix = continuous::bbob_constrained::kPrefix;
                   f && f->function.starts_with(prefix)) {
            // Not in the box catalog (constrained): its number follows the prefix, checked when it was built.
            r.suite = "bbob-constrained";
            r.fid = std::stoll(f->function.substr(prefix.size()));
        }
        r.definition = problem_definition(p);
        r.digest = p.digest;
    }
    rows.algorithms.reserve(c.algorithms.size());
    for (const auto& a : c.algorithms) {
        storage::AlgorithmRow& r = rows.algorithms.emplace_back();
        const engine::AlgorithmEntry* entry = engine::algorithms().find(a.spec.name);
        r.id = a.id;
        r.type = a.spec.name;
        r.evaluates = !entry || entry->evaluates();
        r.reproducible = !entry || entry->reproducible;
        r.definition = algorithm_definition(a);
    }
    return rows;
}

}  // namespace pride::campaign

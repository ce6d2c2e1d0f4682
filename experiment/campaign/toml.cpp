#include "experiment/campaign/toml.hpp"
#include "experiment/campaign/identity.hpp"
#include "experiment/campaign/prepare.hpp"
#include "experiment/campaign/protocol.hpp"
#include "experiment/campaign/toml_mixint.hpp"
#include "experiment/campaign/toml_nodes.hpp"
#include "experiment/campaign/toml_seeds.hpp"

#include <fmt/format.h>

#include <toml++/toml.h>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>

#include "engine/planner_settings.hpp"
#include "engine/registry.hpp"
#include "engine/run.hpp"
#include "framework/error.hpp"
#include "framework/memory.hpp"
#include "framework/read_file.hpp"
#include "problems/continuous/bbob_constrained/bbob_constrained.hpp"
#include "problems/continuous/catalog.hpp"
#include "problems/continuous/cec/suites.hpp"
#include "problems/continuous/cec2020rw/cec2020rw.hpp"

namespace pride::campaign {

using engine::AlgorithmEntry;
using engine::algorithms;
using engine::ContinuousSpec;
using engine::GridSpec;
using engine::is_multiobjective_problem;
using engine::max_budget;
using engine::ParamSpec;
using engine::ParamType;
namespace {

using namespace toml_nodes;

CampaignProblem read_problem(const std::string& file, const toml::table& t, const std::filesystem::path& folder,
                             std::vector<std::int64_t>& instances) {
    CampaignProblem p;
    p.line = static_cast<int>(t.source().begin.line);
    const std::string where = fmt::format("{}:{}", file, p.line);
    p.id = need_name(file, t, "id", where);
    const std::string type = need_string(file, t, "type", where);
    const bool grid = type == "grid";
    // zdt1..dtlz7: several objectives (engine/multiobjective.hpp), with `objectives` M for DTLZ.
    const bool several = is_multiobjective_problem(type);
    GridSpec g;
    ContinuousSpec f{type, 0};
    static const std::set<std::string> continuous_keys{"id", "type", "dim", "instance"};
    static const std::set<std::string> multiobjective_keys{"id", "type", "dim", "objectives"};
    static const std::set<std::string> grid_keys{"id",        "type",        "map",       "start",      "goal",
                                                 "objective", "encoding",    "connector", "init",       "waypoints",
                                                 "inflate",   "weights",     "lambda",    "objectives", "unknown_free",
                                                 "path_gaps", "start_world", "goal_world"};
    for (auto&& [key, value] : t) {
        const std::string k(key.str());
        if (!(grid ? grid_keys : several ? multiobjective_keys : continuous_keys).count(k))
            fail(at(file, value), "unknown key '" + k + "' in a " +
                                      (grid      ? "grid"
                                       : several ? "multi-objective"
                                                 : "continuous") +
                                      " [[problem]]");
        if (k == "objectives") {
            // A grid's criteria (a list of names, or one comma-separated string); DTLZ's M.
            if (grid) {
                std::string list;
                if (const toml::array* a = value.as_array()) {
                    for (const auto& item : *a) {
                        if (!item.is_string()) fail(at(file, item), "'objectives' must list names such as \"length\"");
                        list += (list.empty() ? "" : ",") + std::string(*item.as_string());
                    }
                } else {
                    list = need_string(file, t, k, where);
                }
                p.objectives = list;
            } else {
                p.objectives = std::to_string(need_integer(file, value, k));
            }
        }
        if (k == "dim") f.dim = need_integer(file, value, k);
        if (k == "instance")
            instances = value.is_array() ? need_integers(file, value, k) : std::vector{need_integer(file, value, k)};
        if (k == "map") {
            if (!value.is_string()) fail(at(file, value), "'map' must be a string");
            // Relative to the campaign file's folder when the file is there, else to the working folder.
            const std::filesystem::path m(std::string(**value.as_string()));
            p.map_file = (m.is_relative() && std::filesystem::exists(folder / m)) ? (folder / m).string() : m.string();
        }
        if (k == "start") g.start = need_cell(file, value, k);
        if (k == "goal") g.goal = need_cell(file, value, k);
        // World points become cells in prepare(), once the map and its frame are read.
        if (k == "start_world" || k == "goal_world") {
            const std::string cell_key = k == "start_world" ? "start" : "goal";
            if (t.get(cell_key))
                fail(at(file, value), "give '" + cell_key + "' (a cell) or '" + k + "' (metres), not both");
            CampaignProblem::WorldEnd& end = k == "start_world" ? p.start_world : p.goal_world;
            end.point = need_point(file, value, k);
            end.line = static_cast<int>(value.source().begin.line);
        }
        if (k == "objective") g.objective = need_string(file, t, k, where);
        if (k == "encoding") g.encoding = need_string(file, t, k, where);
        if (k == "connector") g.connector = need_string(file, t, k, where);
        if (k == "init") g.init = need_string(file, t, k, where);
        if (k == "waypoints") g.waypoints = need_integer(file, value, k);
        if (k == "inflate") p.inflate = need_integer(file, value, k);
        if (k == "unknown_free" || k == "path_gaps") {
            if (!value.is_boolean()) fail(at(file, value), "'" + k + "' must be true or false");
            (k == "unknown_free" ? p.unknown_free : p.path_gaps) = **value.as_boolean();
        }
        if (k == "lambda") g.lambda = need_number(file, value, k);
        if (k == "weights") {
            const toml::array* a = value.as_array();
            if (!a || a->size() != 3) fail(at(file, value), "'weights' must be [w_len, w_turn, w_angle]");
            g.weights = {need_number(file, (*a)[0], k), need_number(file, (*a)[1], k), need_number(file, (*a)[2], k)};
        }
    }
    if (grid) {
        if (p.map_file.empty()) fail(where, "a grid [[problem]] needs 'map'");
        if (!t.get("start") && !t.get("start_world"))
            fail(where, "a grid [[problem]] needs 'start' (a cell) or 'start_world' (metres)");
        if (!t.get("goal") && !t.get("goal_world"))
            fail(where, "a grid [[problem]] needs 'goal' (a cell) or 'goal_world' (metres)");
        if (p.objectives && t.get("objective"))
            fail(at(file, *t.get("objective")), "a grid with 'objectives' (several) takes no 'objective' (one)");
        p.spec = g;
    } else if (several) {
        if (!p.objectives) p.objectives = "";  // the problem's default M
        p.spec = f;                            // dim 0: the paper's n
    } else {
        if (!t.get("dim")) fail(where, "missing key 'dim'");
        p.spec = f;
    }
    return p;
}

/// The problems the file has asked for so far, counted before each table expands (a
/// 6.9 MB instance list or a 15 KB suite asked for hundreds of thousands of problems, 12 kB each,
/// and met std::bad_alloc after gigabytes): a table that would pass max_campaign_problems or the
/// memory of the problems built (problem_memory) is refused at its key, before it expands.
struct Expansion {
    std::size_t problems = 0;
    double bytes = 0.0;

    void add(std::size_t n, double memory, const std::string& where, const std::string& what) {
        if (problems + n > max_campaign_problems)
            fail(where, fmt::format("{} {} problems ({} in the campaign with those before); a campaign has at most "
                                    "{}",
                                    what, n, problems + n, max_campaign_problems));
        // One problem too large alone is the engine's to refuse, naming its dimension.
        if (n > 1 && bytes + memory > available_memory())
            fail(where, fmt::format("{} {} problems, which need about {} of memory once built ({} with those "
                                    "before), more than the {} this machine has",
                                    what, n, format_bytes(memory), format_bytes(bytes + memory),
                                    format_bytes(available_memory())));
        problems += n;
        if (memory <= available_memory()) bytes += memory;
    }
};

/// A continuous [[problem]] with `instance = [k1, k2, ...]` is one problem per instance, "ID-iK".
void add_problem(std::vector<CampaignProblem>& out, const std::string& file, const toml::table& t,
                 const std::filesystem::path& folder, Expansion& expansion) {
    std::vector<std::int64_t> instances;
    CampaignProblem p = read_problem(file, t, folder, instances);
    const toml::node* given = t.get("instance");
    if (!given) {
        expansion.add(1, problem_memory(p.spec), fmt::format("{}:{}", file, p.line), "this [[problem]] is");
        out.push_back(std::move(p));
        return;
    }
    if (instances.empty()) fail(at(file, *given), "'instance' must not be an empty list");
    double memory = 0.0;
    for (const std::int64_t k : instances) {
        ContinuousSpec f = std::get<ContinuousSpec>(p.spec);
        f.instance = k;
        memory += problem_memory(f);
    }
    expansion.add(instances.size(), memory, at_column(file, *given), "'instance' lists");
    const bool list = given->is_array();
    for (const std::int64_t k : instances) {
        CampaignProblem q = p;
        std::get<ContinuousSpec>(q.spec).instance = k;
        if (list) q.id += "-i" + std::to_string(k);
        out.push_back(std::move(q));
    }
}

/// [[suite]] name = "cec2017" (F1-F30) or "cec2022" (F1-F12), with `functions` (default: all) and
/// `dimensions`: one problem per (function, dimension), "PREFIX-fN-dD" on cecYYYY-fN. CEC functions
/// have no instances (the key is refused), and a dimension the official data does not cover for
/// a function is refused at the key, naming both (problems/continuous/cec/suites.hpp), before any data is read.
void add_cec_suite(std::vector<CampaignProblem>& out, const std::string& file, const toml::table& t,
                   const continuous::cec::SuiteRules& rules, Expansion& expansion) {
    const int line = static_cast<int>(t.source().begin.line);
    const std::string where = fmt::format("{}:{}", file, line);
    const std::string name(rules.name);
    if (const auto* n = t.get("instances"))
        fail(at_column(file, *n),
             fmt::format("'instances': {} has no instances (each function is defined once per dimension, by the "
                         "official data); leave the key out",
                         name));
    const std::string prefix = t.get("id") ? need_name(file, t, "id", where) : name;
    std::vector<std::int64_t> functions, dimensions;
    for (std::int64_t f = 1; f <= rules.functions; ++f) functions.push_back(f);
    if (const auto* n = t.get("functions")) functions = need_integers(file, *n, "functions");
    if (const auto* n = t.get("dimensions"))
        dimensions = need_integers(file, *n, "dimensions");
    else
        fail(where, "a [[suite]] needs 'dimensions' (a list of integers)");
    if (functions.empty() || dimensions.empty()) fail(where, "the lists of a [[suite]] must not be empty");
    for (const std::int64_t f : functions)
        if (f < 1 || f > rules.functions)
            fail(at_column(file, *t.get("functions")),
                 fmt::format("function {} is not in the {} suite (1-{})", f, name, rules.functions));
    // Each dimension once, in the order given.
    std::vector<std::int64_t> dims;
    for (const std::int64_t d : dimensions)
        if (std::find(dims.begin(), dims.end(), d) == dims.end()) dims.push_back(d);
    for (const std::int64_t f : functions) {
        // The dimensions of the official data (the catalog's), checked before any data is read.
        const auto* item = continuous::catalog().find(name + "-f" + std::to_string(f));
        if (!item) fail(where, fmt::format("{}-f{} is not in this pride's catalog", name, f));
        const auto& have = item->entry.dims;
        for (const std::int64_t d : dims)
            if (d < 1 || std::find(have.begin(), have.end(), static_cast<std::size_t>(d)) == have.end()) {
                std::string list;
                for (const std::size_t h : have) list += (list.empty() ? "" : ", ") + std::to_string(h);
                fail(at_column(file, *t.get("dimensions")),
                     fmt::format("{}-f{} has no official data in dimension {} (the official code and data define "
                                 "it in {} only); leave {} out of 'dimensions', or F{} out of 'functions'",
                                 name, f, d, list, d, f));
            }
    }
    {
        double memory = 0.0;
        for (const std::int64_t f : functions)
            for (const std::int64_t d : dims)
                memory += problem_memory(ContinuousSpec{name + "-f" + std::to_string(f), d});
        const bool longer = t.get("functions") && t.get("functions")->as_array() &&
                            t.get("functions")->as_array()->size() > t.get("dimensions")->as_array()->size();
        const char* key = longer ? "functions" : "dimensions";
        expansion.add(functions.size() * dims.size(), memory, at_column(file, *t.get(key)),
                      fmt::format("'{}': this [[suite]] expands to {} functions x {} dimensions, or", key,
                                  functions.size(), dims.size()));
    }
    for (const std::int64_t f : functions)
        for (const std::int64_t d : dims) {
            CampaignProblem p;
            p.line = line;
            p.suite = name;
            p.id = fmt::format("{}-f{}-d{}", prefix, f, d);
            p.spec = ContinuousSpec{name + "-f" + std::to_string(f), d};
            out.push_back(std::move(p));
        }
}

/// [[suite]] name = "cec2020rw": the CEC 2020 real-world constrained problems RC01-RC57, with
/// `functions` (default: all 57); each problem has its
/// own dimension (the key `dimensions` is refused) and no instances. Ids "PREFIX-rcNN".
void add_rw_suite(std::vector<CampaignProblem>& out, const std::string& file, const toml::table& t,
                  Expansion& expansion) {
    namespace rw = continuous::cec2020rw;
    const int line = static_cast<int>(t.source().begin.line);
    const std::string where = fmt::format("{}:{}", file, line);
    for (const char* key : {"instances", "dimensions"})
        if (const auto* n = t.get(key))
            fail(at_column(file, *n), fmt::format("'{}': each cec2020rw problem has one dimension of its own and no "
                                                  "instances; leave the key out",
                                                  key));
    const std::string prefix = t.get("id") ? need_name(file, t, "id", where) : std::string("cec2020rw");
    std::vector<std::int64_t> functions;
    for (int k = 1; k <= rw::kProblems; ++k) functions.push_back(k);
    if (const auto* n = t.get("functions")) functions = need_integers(file, *n, "functions");
    if (functions.empty()) fail(where, "the lists of a [[suite]] must not be empty");
    for (const std::int64_t f : functions)
        if (f < 1 || f > rw::kProblems)
            fail(at_column(file, *t.get("functions")),
                 fmt::format("problem {} is not in the cec2020rw suite (1-{})", f, rw::kProblems));
    double memory = 0.0;
    std::vector<std::int64_t> dims;
    for (const std::int64_t f : functions) {
        dims.push_back(static_cast<std::int64_t>(rw::Problem(static_cast<int>(f)).dimension()));
        memory += problem_memory(ContinuousSpec{fmt::format("cec2020rw-rc{:02}", f), dims.back()});
    }
    expansion.add(functions.size(), memory, t.get("functions") ? at_column(file, *t.get("functions")) : where,
                  "this [[suite]] expands to");
    for (std::size_t i = 0; i < functions.size(); ++i) {
        CampaignProblem p;
        p.line = line;
        p.suite = "cec2020rw";
        p.id = fmt::format("{}-rc{:02}", prefix, functions[i]);
        p.spec = ContinuousSpec{fmt::format("cec2020rw-rc{:02}", functions[i]), dims[i]};
        out.push_back(std::move(p));
    }
}

/// [[suite]] name = "bbob-constrained": COCO's constrained suite (functions 1-54, default all;
/// instances from 1, default 1-5 as bbob's; dimensions 2-40, the suite's own being 2, 3, 5, 10,
/// 20, 40), one problem per (function, instance, dimension), "PREFIX-fN-iK-dD" on
/// bbob-constrained-fN.
void add_bbob_constrained_suite(std::vector<CampaignProblem>& out, const std::string& file, const toml::table& t,
                                Expansion& expansion) {
    namespace bc = continuous::bbob_constrained;
    const int line = static_cast<int>(t.source().begin.line);
    const std::string where = fmt::format("{}:{}", file, line);
    const std::string name = "bbob-constrained";
    const std::string prefix = t.get("id") ? need_name(file, t, "id", where) : name;
    const auto [functions, instances, dimensions, dims] = read_suite_lists(file, t, name, bc::kFunctions);
    for (const std::int64_t d : dimensions)
        if (d < 2 || d > static_cast<std::int64_t>(bc::kMaxDimension))
            fail(at(file, *t.get("dimensions")),
                 fmt::format("dimension {}: the {} functions take a dimension from 2 to {} (the suite's: 2, 3, 5, "
                             "10, 20, 40)",
                             d, name, bc::kMaxDimension));
    {
        // A rotation, and up to 6 + 3D active constraints and half as many inactive ones, of D values each.
        double memory = 0.0;
        for (const std::int64_t d : dims) {
            const double n = static_cast<double>(d);
            memory +=
                static_cast<double>(functions.size() * instances.size()) * (16e3 + 8.0 * (20.0 * n * n + 8.0 * n));
        }
        const char* key = longest_list(t);
        expansion.add(functions.size() * instances.size() * dims.size(), memory, at_column(file, *t.get(key)),
                      fmt::format("'{}': this [[suite]] expands to {} functions x {} instances x {} dimensions, or",
                                  key, functions.size(), instances.size(), dims.size()));
    }
    for (const std::int64_t f : functions)
        for (const std::int64_t d : dims)
            for (const std::int64_t k : instances) {
                CampaignProblem p;
                p.line = line;
                p.suite = name;
                p.id = fmt::format("{}-f{}-i{}-d{}", prefix, f, k, d);
                p.spec = ContinuousSpec{fmt::format("{}{}", bc::kPrefix, f), d, k};
                out.push_back(std::move(p));
            }
}

/// [[suite]]: name = "bbob" (functions 1-24, instances from 1) or "classic" (Yao et al. 1999's
/// F1-F23, instance 0 as defined), with `functions`, `instances` and `dimensions` lists; one
/// problem per (function, instance, dimension), "PREFIX-fN-iK-dD" (fixed-dimension functions: their
/// own dimension and instance 0 only).
void add_suite(std::vector<CampaignProblem>& out, const std::string& file, const toml::table& t, Expansion& expansion) {
    const int line = static_cast<int>(t.source().begin.line);
    const std::string where = fmt::format("{}:{}", file, line);
    static const std::set<std::string> keys{"name", "id", "functions", "instances", "dimensions"};
    for (auto&& [key, value] : t)
        if (!keys.count(std::string(key.str())))
            fail(at(file, value), "unknown key '" + std::string(key.str()) +
                                      "' in a [[suite]] (name, id, functions, instances, dimensions)");
    const std::string name = need_string(file, t, "name", where);
    if (name == "cec2020rw") {
        add_rw_suite(out, file, t, expansion);
        return;
    }
    if (name == "bbob-constrained") {
        add_bbob_constrained_suite(out, file, t, expansion);
        return;
    }
    if (name == "bbob-mixint") {
        add_bbob_mixint_suite(out, file, t,
                              [&](std::size_t n, double memory, const std::string& at, const std::string& what) {
                                  expansion.add(n, memory, at, what);
                              });
        return;
    }
    if (continuous::cec::suite_rules(name)) {
        add_cec_suite(out, file, t, *continuous::cec::suite_rules(name), expansion);
        return;
    }
    if (name != "bbob" && name != "classic")
        fail(where, "unknown suite '" + name +
                        "' (bbob, bbob-constrained, bbob-mixint, classic, cec2017, cec2022, cec2020rw)");
    const bool bbob = name == "bbob";
    const std::string prefix = t.get("id") ? need_name(file, t, "id", where) : name;
    std::vector<std::int64_t> functions, instances, dimensions;
    for (std::int64_t f = 1; f <= (bbob ? 24 : 23); ++f) functions.push_back(f);
    instances = bbob ? std::vector<std::int64_t>{1, 2, 3, 4, 5} : std::vector<std::int64_t>{0};
    if (const auto* n = t.get("functions")) functions = need_integers(file, *n, "functions");
    if (const auto* n = t.get("instances")) instances = need_integers(file, *n, "instances");
    if (const auto* n = t.get("dimensions"))
        dimensions = need_integers(file, *n, "dimensions");
    else
        fail(where, "a [[suite]] needs 'dimensions' (a list of integers)");
    for (auto* list : {&functions, &instances, &dimensions})
        if (list->empty()) fail(where, "the lists of a [[suite]] must not be empty");
    for (const std::int64_t f : functions)
        if (f < 1 || f > (bbob ? 24 : 23))
            fail(at(file, *t.get("functions")),
                 fmt::format("function {} is not in the {} suite (1-{})", f, name, bbob ? 24 : 23));
    {
        // What the suite expands to, counted before any of it is made.
        std::size_t n = 0;
        double memory = 0.0;
        for (const std::int64_t f : functions) {
            const std::string function = (bbob ? "bbob-f" : "yao-f") + std::to_string(f);
            const auto& entry = continuous::catalog().find(function)->entry;
            const bool single = entry.instances == continuous::Instances::none;
            std::set<std::int64_t> seen;
            for (const std::int64_t d : dimensions) {
                const std::int64_t dim = entry.fixed_dim ? static_cast<std::int64_t>(entry.fixed_dim) : d;
                if (!seen.insert(dim).second) continue;
                const std::size_t k = single ? 1 : instances.size();
                n += k;
                memory += static_cast<double>(k) * problem_memory(ContinuousSpec{function, dim, single ? 0 : 1});
            }
        }
        // Blamed on the longest list the table gives.
        const char* key = "dimensions";
        for (const char* other : {"instances", "functions"})
            if (const auto* node = t.get(other);
                node && node->as_array() && node->as_array()->size() > t.get(key)->as_array()->size())
                key = other;
        expansion.add(n, memory, at_column(file, *t.get(key)),
                      fmt::format("'{}': this [[suite]] expands to {} functions x {} instances x {} dimensions, "
                                  "or",
                                  key, functions.size(), instances.size(), dimensions.size()));
    }
    for (const std::int64_t f : functions) {
        const std::string function = (bbob ? "bbob-f" : "yao-f") + std::to_string(f);
        const auto& entry = continuous::catalog().find(function)->entry;
        const auto fixed = entry.fixed_dim;
        // Fixed-dimension functions (Yao's F14-F23) have one instance: they run once, at instance 0,
        // when the list asks for it; a list without it is refused, never run at an instance it
        // does not name (instances = [1] ran instance 0 and said nothing).
        const bool single = entry.instances == continuous::Instances::none;
        if (single && std::find(instances.begin(), instances.end(), 0) == instances.end())
            fail(at_column(file, *t.get("instances")),
                 fmt::format("'instances' has no instance 0, the only instance of {} (a fixed-dimension function); "
                             "add 0 to 'instances', or leave F14-F23 out of 'functions'",
                             function));
        const std::vector<std::int64_t> own_instances = single ? std::vector<std::int64_t>{0} : instances;
        std::set<std::int64_t> seen;
        for (const std::int64_t d : dimensions) {
            const std::int64_t dim = fixed ? static_cast<std::int64_t>(fixed) : d;
            if (!seen.insert(dim).second) continue;
            for (const std::int64_t k : own_instances) {
                CampaignProblem p;
                p.line = line;
                p.suite = name;
                p.id = fmt::format("{}-f{}-i{}-d{}", prefix, f, k, dim);
                p.spec = ContinuousSpec{function, dim, k};
                out.push_back(std::move(p));
            }
        }
    }
}

CampaignAlgorithm read_algorithm(const std::string& file, const toml::table& t) {
    CampaignAlgorithm a;
    a.line = static_cast<int>(t.source().begin.line);
    const std::string where = fmt::format("{}:{}", file, a.line);
    a.id = need_name(file, t, "id", where);
    a.spec.name = need_string(file, t, "type", where);
    for (auto&& [key, value] : t) {
        const std::string k(key.str());
        if (k == "id" || k == "type") continue;
        // A name is a value only for a choice parameter; every other value is a number (a name
        // given to a number is refused here, where the file's line and column are known).
        const AlgorithmEntry* entry = algorithms().find(a.spec.name);
        const ParamSpec* spec = entry ? entry->param(k) : nullptr;
        // How an algorithm plans through an encoding, named for a whole-map planner: refused at the
        // key in pride path's words (it was "'encoding' must be a number").
        if (entry && entry->whole_map() && !spec) {
            GridSpec g;
            if (k == "encoding") g.encoding = "line";
            if (k == "init") g.init = "uniform";
            if (k == "connector") g.connector = "penalty";
            if (k == "waypoints") g.waypoints = 4;
            try {
                engine::refuse_unused_planner_settings(a.spec, g, engine::Budget{});
            } catch (const InputError& e) {
                fail(at_column(file, value), e.what());
            }
        }
        if (value.is_string() && spec && spec->type == ParamType::choice)
            a.spec.params.set_name(k, std::string(**value.as_string()));
        else
            a.spec.params.set(k, need_number(file, value, k));
    }
    return a;
}

}  // namespace

Campaign read_campaign(const std::string& path) {
    Campaign c = parse_campaign(path);
    prepare(c);
    return c;
}

Campaign parse_campaign(const std::string& path) {
    Campaign c;
    c.file = path;
    // Read under a cap (framework/read_file.hpp): `pride bench /dev/zero` is refused, not read forever.
    std::error_code ec;
    require(!std::filesystem::is_directory(path, ec), path, "is a folder, not a campaign file");
    c.text = read_capped_file(path, std::size_t{16} << 20, "campaign");
    toml::table root;
    if (std::error_code ec; std::filesystem::is_directory(path, ec))
        throw InputError(path + ": is a folder, not a campaign file");
    try {
        root = toml::parse(c.text, path);
    } catch (const toml::parse_error& e) {
        // toml++'s words up to the first quote: what it quotes after is text of the file, and a
        // file that is no TOML (a path a scenario or a user named by mistake) is never shown.
        std::string_view words = e.description();
        words = words.substr(0, words.find('\''));
        const auto trim = [&] {
            while (!words.empty() && (words.back() == ' ' || words.back() == ',' || words.back() == ':'))
                words.remove_suffix(1);
        };
        trim();
        for (const std::string_view cut : {std::string_view("saw"), std::string_view("expected")})
            if (words.ends_with(cut)) {
                words.remove_suffix(cut.size());
                trim();
            }
        // An integer toml++ cannot hold (seeds = 18446744073709551615, a seed --seed takes): the
        // range a campaign file can hold, said once here for every key.
        const std::string range = words.find("integer") != std::string_view::npos
                                      ? " (a campaign file's integers lie in [-9223372036854775808, "
                                        "9223372036854775807])"
                                      : "";
        throw InputError(fmt::format("{}:{}:{}: not valid TOML: {}{}", path, e.source().begin.line,
                                     e.source().begin.column, words, range));
    }
    const auto folder = std::filesystem::path(path).parent_path();
    bool suites_read = false;
    Expansion expansion;
    for (auto&& [key, value] : root) {
        const std::string k(key.str());
        if (k == "name") {
            if (!value.is_string()) fail(at(path, value), "'name' must be a string");
            c.name = std::string(**value.as_string());
            if (const std::string why = name_problem(c.name); !why.empty())
                fail(at_column(path, value), "'name' " + why);
        } else if (k == "seeds") {
            read_seeds(c, path, value);
        } else if (k == "budget") {
            const toml::table* b = value.as_table();
            if (!b) fail(at(path, value), "'budget' must be a table");
            for (auto&& [bk, bv] : *b) {
                const std::string kk(bk.str());
                if (kk == "evaluations") {
                    c.evaluations_line = static_cast<int>(bv.source().begin.line);
                    c.budget.evaluations = need_integer(path, bv, kk);
                    if (*c.budget.evaluations < 1 || *c.budget.evaluations > max_budget)
                        fail(at(path, bv), fmt::format("'evaluations' must be in [1, {}], got {}", max_budget,
                                                       *c.budget.evaluations));
                } else if (kk == "iterations") {
                    c.iterations_line = static_cast<int>(bv.source().begin.line);
                    c.budget.iterations = need_integer(path, bv, kk);
                    if (*c.budget.iterations < 0 || *c.budget.iterations > max_budget)
                        fail(at(path, bv),
                             fmt::format("'iterations' must be in [0, {}], got {}", max_budget, *c.budget.iterations));
                } else if (kk == "target") {
                    c.target = need_number(path, bv, kk);
                    if (!std::isfinite(*c.target))
                        fail(at(path, bv), fmt::format("'target' must be a finite number, got {}", *c.target));
                } else if (kk == "evaluations_per_dim") {
                    c.evaluations_per_dim = need_integer(path, bv, kk);
                    if (*c.evaluations_per_dim < 1 || *c.evaluations_per_dim > max_budget)
                        fail(at(path, bv), fmt::format("'evaluations_per_dim' must be in [1, {}], got {}", max_budget,
                                                       *c.evaluations_per_dim));
                } else if (kk == "precision") {
                    c.target_precision = need_number(path, bv, kk);
                    if (!std::isfinite(*c.target_precision) || *c.target_precision <= 0)
                        fail(at(path, bv), fmt::format("'precision' must be a finite number > 0 (a target f_opt + "
                                                       "precision), got {}",
                                                       *c.target_precision));
                } else {
                    fail(at(path, bv),
                         "unknown key '" + kk +
                             "' in [budget] (evaluations, evaluations_per_dim, iterations, target, precision)");
                }
            }
            if (c.budget.evaluations && c.evaluations_per_dim)
                fail(at(path, value), "[budget]: give evaluations or evaluations_per_dim, not both");
            if (c.target && c.target_precision)
                fail(at(path, value),
                     "[budget]: give target (an absolute value) or precision (f_opt + precision), "
                     "not both");
        } else if (k == "protocol") {
            if (!value.is_string()) fail(at(path, value), "'protocol' must be a string");
            c.protocol = std::string(**value.as_string());
            c.protocol_line = static_cast<int>(value.source().begin.line);
            if (!is_protocol(c.protocol))
                fail(at_column(path, value), "unknown protocol '" + c.protocol + "' (" + protocol_names + ")");
        } else if (k == "threads") {  // evaluation threads per run (Budget::threads; results unchanged)
            c.threads_line = static_cast<int>(value.source().begin.line);
            c.budget.threads = need_integer(path, value, k);
            if (c.budget.threads < 1 || c.budget.threads > 256) fail(at(path, value), "'threads' must be in [1, 256]");
        } else if (k == "suite") {
            const toml::array* a = value.as_array();
            if (!a || !a->is_array_of_tables()) fail(at(path, value), "'suite' must be [[suite]] tables");
            for (const toml::node& n : *a) add_suite(c.problems, path, *n.as_table(), expansion);
            suites_read = true;
        } else if (k == "problem" || k == "algorithm") {
            const toml::array* a = value.as_array();
            if (!a || !a->is_array_of_tables()) fail(at(path, value), "'" + k + "' must be [[" + k + "]] tables");
            for (const toml::node& n : *a) {
                if (k == "problem")
                    add_problem(c.problems, path, *n.as_table(), folder, expansion);
                else
                    c.algorithms.push_back(read_algorithm(path, *n.as_table()));
            }
        } else {
            fail(at(path, value),
                 "unknown key '" + k + "' (name, seeds, budget, threads, protocol, problem, suite, algorithm)");
        }
    }
    // toml++ visits keys in name order; problems and suites run in the order the file gives them.
    if (suites_read)
        std::stable_sort(c.problems.begin(), c.problems.end(),
                         [](const CampaignProblem& a, const CampaignProblem& b) { return a.line < b.line; });
    return c;
}

}  // namespace pride::campaign

#include "cli/commands.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <istream>
#include <ostream>
#include <span>
#include <string_view>
#include <variant>

#include "cli/numbers.hpp"
#include "engine/problem.hpp"
#include "engine/registry.hpp"
#include "engine/run.hpp"
#include "framework/error.hpp"
#include "problems/continuous/catalog.hpp"
#include "problems/multiobjective/catalog.hpp"
#include "problems/multiobjective/constrained.hpp"
#include "problems/multiobjective/re/re.hpp"

namespace pride::cli {

engine::ParamValues parse_params(const std::vector<std::string>& assignments, const std::optional<std::string>& pop) {
    engine::ParamValues params;
    for (const auto& p : assignments) params.set_from_string(p);
    // --pop is checked against the algorithm's own range (engine::ParamSpec::check), so that it
    // gets the message a campaign's or Python's pop gets. An integer written in full is its value;
    // anything else (1e3, 2.5, abc) is handed on as text, which the check refuses with that range.
    if (pop) {
        const std::string_view t = *pop;
        const std::string_view digits = !t.empty() && (t[0] == '-' || t[0] == '+') ? t.substr(1) : t;
        const bool whole =
            !digits.empty() && std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
        if (whole)
            params.set("pop", std::strtod(pop->c_str(), nullptr));
        else
            params.set_name("pop", *pop);
    }
    return params;
}

int run_command(const RunOptions& o, std::ostream& out) {
    const engine::Problem problem(engine::ContinuousSpec{o.problem, o.dim, o.instance});
    const std::int64_t instance = problem.instance();
    const engine::AlgorithmSpec algorithm{o.algo, parse_params(o.params, o.pop)};
    engine::check(algorithm, problem, o.budget);
    const engine::RunResult r = engine::run(algorithm, problem, o.budget, o.seed);
    // Problems with constraints: the best point's violation and the first feasible evaluation.
    const std::string first_feasible = r.first_feasible ? std::to_string(*r.first_feasible) : "null";
    if (o.json) {
        const std::string constrained = r.best_violation
                                            ? fmt::format(", \"best_violation\": {}, \"first_feasible\": {}",
                                                          json_number(*r.best_violation), first_feasible)
                                            : "";
        out << fmt::format(
            "{{\"algo\": {}, \"problem\": {}, \"dim\": {}, \"instance\": {}, \"seed\": {}, \"best_f\": {}{}, "
            "\"best_x\": {}, \"evaluations\": {}, \"wall_ms\": {}, \"history\": {}}}\n",
            json_string(o.algo), json_string(o.problem), o.dim, instance, o.seed, json_number(r.best_f), constrained,
            json_array(r.best_x), r.evaluations, json_number(r.wall_ms), json_array(r.history));
    } else {
        const std::string constrained =
            r.best_violation ? fmt::format("violation    {:.17g}\nfeasible at  {}\n", *r.best_violation,
                                           r.first_feasible ? first_feasible + " evaluations" : std::string("never"))
                             : "";
        out << fmt::format(
            "algo         {}\nproblem      {} (D = {}, instance {})\nseed         {}\nbest_f       {:.17g}\n{}"
            "evaluations  {}\niterations   {}\nwall_ms      {:.3f}\nbest_x       {}\n",
            o.algo, o.problem, o.dim, instance, o.seed, r.best_f, constrained, r.evaluations, r.iterations, r.wall_ms,
            json_array(r.best_x));
    }
    return 0;
}

int eval_command(const EvalOptions& o, std::istream& in, std::ostream& out) {
    // Every point, flat (one allocation whatever their number): `dim` coordinates each.
    std::vector<double> coords;
    std::size_t dim = 0;
    if (o.x == "-") {
        // Read in chunks under a cap, and a NUL byte refused at once: `--x - < /dev/zero` is bad
        // input, not an endless read.
        constexpr std::size_t max_bytes = std::size_t{64} << 20;
        std::string all;
        std::size_t lines_before = 1;
        char buffer[1 << 16];
        while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
            const auto n = static_cast<std::size_t>(in.gcount());
            if (const void* nul = std::memchr(buffer, 0, n)) {
                const auto at = static_cast<std::size_t>(static_cast<const char*>(nul) - buffer);
                const auto line = lines_before + static_cast<std::size_t>(std::count(buffer, buffer + at, '\n'));
                throw InputError("stdin line " + std::to_string(line), "NUL byte: binary input, not points");
            }
            require(n <= max_bytes - all.size(), "stdin", "more than 64 MiB of points");
            lines_before += static_cast<std::size_t>(std::count(buffer, buffer + n, '\n'));
            all.append(buffer, n);
        }
        const std::string_view text(all);
        std::size_t start = 0;
        for (std::size_t n = 1; start < text.size(); ++n) {
            const std::size_t end = std::min(text.find('\n', start), text.size());
            const std::string_view line = text.substr(start, end - start);
            start = end + 1;
            if (line.find_first_not_of(" \t\r") == std::string_view::npos) continue;
            const std::vector<double> x = parse_point(line, "stdin line " + std::to_string(n));
            if (coords.empty()) dim = x.size();
            require(x.size() == dim, "stdin line " + std::to_string(n),
                    "expected " + std::to_string(dim) + " coordinates like the first point, got " +
                        std::to_string(x.size()));
            coords.insert(coords.end(), x.begin(), x.end());
        }
        require(!coords.empty(), "stdin", "no points given");
    } else {
        coords = parse_point(o.x, "--x");
        dim = coords.size();
    }
    if (o.dim)
        require(*o.dim >= 1, "dim", fmt::format("must be an integer in [1, {}], got {}", engine::max_budget, *o.dim));
    if (o.dim)
        require(static_cast<std::int64_t>(dim) == *o.dim, o.x == "-" ? "stdin" : "--x",
                "expected " + std::to_string(*o.dim) + " coordinates (--dim), got " + std::to_string(dim));
    auto problem =
        continuous::make_function(o.problem, static_cast<std::int64_t>(dim), o.instance, o.x == "-" ? "stdin" : "--x");
    problem.reseed(o.seed);
    // Written in pieces once every point is read and checked: nothing is printed for bad input.
    std::string text;
    for (std::size_t i = 0; i < coords.size(); i += dim) {
        text += fmt::format("{:.17g}\n", problem.evaluate(std::span<const double>(coords.data() + i, dim)));
        if (text.size() > (1 << 16)) {
            out << text;
            text.clear();
        }
    }
    out << text;
    return 0;
}

namespace {

std::string json_param(const engine::ParamSpec& p) {
    // A choice parameter's default is its name, and its names are listed.
    std::string choices;
    for (const auto& c : p.choices) choices += (choices.empty() ? "" : ", ") + json_string(c);
    const std::string default_value = !p.default_value                      ? "null"
                                      : p.type == engine::ParamType::choice ? json_string(p.default_text())
                                                                            : json_number(*p.default_value);
    return fmt::format(
        "{{\"name\": {}, \"type\": {}, \"default\": {}, \"min\": {}, \"max\": {}, \"min_open\": {}, \"max_open\": {}, "
        "\"range\": {}, \"doc\": {}{}}}",
        json_string(p.name), json_string(engine::to_string(p.type)), default_value, json_number(p.min),
        json_number(p.max), p.min_open ? "true" : "false", p.max_open ? "true" : "false", json_string(p.range()),
        json_string(p.doc), p.choices.empty() ? "" : ", \"choices\": [" + choices + "]");
}

/// Text for a markdown table cell: a '|' would end the cell.
std::string md_cell(const std::string& text) {
    std::string out;
    for (const char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
    return out;
}

bool same_params(const std::vector<engine::ParamSpec>& a, const std::vector<engine::ParamSpec>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].name != b[i].name || a[i].type != b[i].type || a[i].default_value != b[i].default_value ||
            a[i].range() != b[i].range() || a[i].doc != b[i].doc || a[i].box_only != b[i].box_only ||
            a[i].chain_only != b[i].chain_only)
            return false;
    return true;
}

/// The parameter table heading of algorithms[i, end): their names, or "nlopt:NAME" for a family.
std::string markdown_heading(const std::vector<engine::AlgorithmEntry>& algorithms, std::size_t i, std::size_t end) {
    const std::string prefix = algorithms[i].family + ":";
    bool one_family = end - i > 3;
    for (std::size_t k = i; k < end && one_family; ++k) one_family = algorithms[k].name.rfind(prefix, 0) == 0;
    if (one_family) return fmt::format("`{}NAME` (each of the {} above)", prefix, end - i);
    std::string heading;
    for (std::size_t k = i; k < end; ++k) heading += (k > i ? ", `" : "`") + algorithms[k].name + "`";
    return heading;
}

/// The algorithm and parameter tables of docs/cli.md (between its "generated by: pride list
/// --markdown" markers). Consecutive algorithms with the same parameters share one table, so the
/// NLopt algorithms get one.
std::string markdown_algorithms(const std::vector<engine::AlgorithmEntry>& algorithms) {
    std::string text = "### Algorithms\n\n| algorithm | runs on | what it is |\n|---|---|---|\n";
    for (const auto& a : algorithms) {
        text += fmt::format("| `{}` | {} | {} |\n", a.name, fmt::join(a.spaces(), ", "), md_cell(a.summary));
    }
    text += "\n### Parameters\n";
    for (std::size_t i = 0, end = 0; i < algorithms.size(); i = end) {
        end = i + 1;
        while (end < algorithms.size() && same_params(algorithms[end].params, algorithms[i].params)) ++end;
        text += "\n#### " + markdown_heading(algorithms, i, end) + "\n\n";
        if (algorithms[i].params.empty()) {
            text += "No parameters.\n";
            continue;
        }
        text += "| parameter | type | default | range | meaning |\n|---|---|---|---|---|\n";
        for (const auto& p : algorithms[i].params)
            text += fmt::format("| `{}` | {} | {} | {} | {} |\n", p.name, engine::to_string(p.type), p.default_text(),
                                p.range(), md_cell(p.doc));
    }
    return text;
}

/// A problem's dimensions, instances and suite, for `pride list --json`.
std::string problem_facts(const continuous::CatalogEntry& e) {
    static constexpr const char* instances[] = {"transform", "none", "coco"};
    return fmt::format(
        ", \"min_dim\": {}, \"fixed_dim\": {}, \"instances\": {}, \"default_instance\": {}, "
        "\"suite\": {}, \"number\": {}, \"dims\": {}",
        e.min_dim, e.fixed_dim ? std::to_string(e.fixed_dim) : "null",
        json_string(instances[static_cast<int>(e.instances)]), continuous::default_instance(e),
        e.suite.empty() ? "null" : json_string(e.suite), e.suite.empty() ? "null" : std::to_string(e.number),
        e.dims.empty() ? "null" : "[" + fmt::format("{}", fmt::join(e.dims, ", ")) + "]");
}

struct Section {
    std::string title;
    std::vector<engine::NamedItem> items;
};

}  // namespace

int list_command(ListFormat format, std::ostream& out) {
    std::vector<Section> sections;
    Section problems{"problems", {}};
    for (const auto& item : continuous::catalog().items()) {
        std::string dims;
        for (const std::size_t d : item.entry.dims) dims += (dims.empty() ? "" : ", ") + std::to_string(d);
        problems.items.push_back(
            {item.name,
             item.summary + (!dims.empty()          ? " (dim in " + dims + ")"
                             : item.entry.fixed_dim ? " (dim = " + std::to_string(item.entry.fixed_dim) + ")"
                                                    : " (dim >= " + std::to_string(item.entry.min_dim) + ")")});
    }
    sections.push_back(problems);
    sections.push_back({"constrained_problems", engine::constrained_problems()});
    Section several{"multiobjective_problems", {}};
    for (const auto& e : multiobjective::kCatalog)
        several.items.push_back({std::string(e.name), std::string(e.summary) + " (pride front)"});
    for (const auto& e : multiobjective::kConstrainedCatalog)
        several.items.push_back({std::string(e.name), std::string(e.summary) + " (pride front; constrained)"});
    for (const auto& e : multiobjective::re::kCatalog)
        several.items.push_back(
            {std::string(e.name), fmt::format("Tanabe and Ishibuchi (2020), {}; n = {}, M = {} (pride front)",
                                              e.summary, e.variables, e.objectives)});
    sections.push_back(several);
    sections.push_back({"encodings", {{"identity", "the genotype is the solution (every continuous problem)"}}});
    for (const auto& e : engine::grid_encodings()) sections.back().items.push_back(e);
    sections.push_back({"connectors", engine::grid_connectors()});
    sections.push_back({"objectives", {{"value", "continuous problems: the function value itself, minimised"}}});
    for (const auto& e : engine::grid_objectives()) sections.back().items.push_back(e);

    const auto& algorithms = engine::algorithms().entries();
    std::string text;
    if (format == ListFormat::markdown) {
        text = markdown_algorithms(algorithms);
        for (auto s : sections) {
            s.title[0] = static_cast<char>(s.title[0] - 'a' + 'A');
            std::replace(s.title.begin(), s.title.end(), '_', ' ');
            text += fmt::format("\n### {}\n\n| name | what it is |\n|---|---|\n", s.title);
            for (const auto& item : s.items) text += fmt::format("| `{}` | {} |\n", item.name, md_cell(item.summary));
        }
    } else if (format == ListFormat::json) {
        text = "{\"algorithms\": [";
        for (std::size_t i = 0; i < algorithms.size(); ++i) {
            const auto& a = algorithms[i];
            std::string spaces, params;
            for (const auto& s : a.spaces()) spaces += (spaces.empty() ? "" : ", ") + json_string(s);
            for (const auto& p : a.params) params += (params.empty() ? "" : ", ") + json_param(p);
            text += fmt::format(
                "{}{{\"name\": {}, \"family\": {}, \"summary\": {}, \"spaces\": [{}], \"params\": [{}]}}",
                i ? ", " : "", json_string(a.name), json_string(a.family), json_string(a.summary), spaces, params);
        }
        text += "]";
        for (const auto& s : sections) {
            text += ", " + json_string(s.title) + ": [";
            for (std::size_t i = 0; i < s.items.size(); ++i) {
                text += fmt::format("{}{{\"name\": {}, \"summary\": {}", i ? ", " : "", json_string(s.items[i].name),
                                    json_string(s.items[i].summary));
                if (const auto* f = s.title == "problems" ? continuous::catalog().find(s.items[i].name) : nullptr)
                    text += problem_facts(f->entry);
                text += "}";
            }
            text += "]";
        }
        text += "}\n";
    } else {
        text = "algorithms:\n";
        for (const auto& a : algorithms) {
            std::string params;
            for (const auto& p : a.params) params += (params.empty() ? "" : " ") + p.name;
            text += fmt::format("  {:<22} {} [{}]{}\n", a.name, a.summary, fmt::join(a.spaces(), ", "),
                                params.empty() ? "" : " (params: " + params + ")");
        }
        for (const auto& s : sections) {
            text += s.title + ":\n";
            for (const auto& item : s.items) text += fmt::format("  {:<22} {}\n", item.name, item.summary);
        }
    }
    out << text;
    return 0;
}

}  // namespace pride::cli

#include "experiment/report/ioh_import.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <sstream>
#include <tuple>

#include "experiment/report/ioh_export.hpp"
#include "experiment/storage/reader.hpp"
#include "framework/error.hpp"

namespace pride::report {
namespace {

namespace fs = std::filesystem;
using published_files::count;
using published_files::number;
using published_files::read_lines;
using published_files::trim;

/// The store's problems as the export names them: (funcId, DIM) -> its function and problems.
struct IohCell {
    IohFunction fn;
    std::map<std::int64_t, const storage::StoredProblem*> by_instance;  // a suite's function
    const storage::StoredProblem* problem = nullptr;                    // any other problem
};

/// "key = value" pairs of a .info header line, a value either double-quoted (commas inside it
/// kept) or up to the next comma.
std::map<std::string, std::string> ioh_header_fields(const std::string& line) {
    std::map<std::string, std::string> out;
    std::size_t at = 0;
    while (at < line.size()) {
        const auto eq = line.find('=', at);
        if (eq == std::string::npos) break;
        const std::string key = trim(line.substr(at, eq - at));
        std::size_t v = line.find_first_not_of(" \t", eq + 1);
        std::string value;
        if (v != std::string::npos && line[v] == '"') {
            const auto close = line.find('"', v + 1);
            value = line.substr(v + 1, close == std::string::npos ? std::string::npos : close - v - 1);
            v = close == std::string::npos ? line.size() : close + 1;
        } else {
            const auto comma = line.find(',', v == std::string::npos ? line.size() : v);
            value = v == std::string::npos ? "" : trim(line.substr(v, comma == std::string::npos ? comma : comma - v));
            v = comma == std::string::npos ? line.size() : comma;
        }
        out[key] = value;
        const auto comma = line.find(',', v);
        at = comma == std::string::npos ? line.size() : comma + 1;
    }
    return out;
}

/// A row of a .dat block: evaluations and the best-so-far f(x) (none: "None", no value yet).
struct IohRow {
    std::int64_t evaluations = 0;
    std::optional<double> best;
    std::size_t line = 0;
};

/// One run's block of a .dat file: its header's line and its rows.
struct IohBlock {
    std::size_t line = 0;
    std::vector<IohRow> rows;
};

/// The blocks of a .dat file: each starts with a header line of quoted column names, of which
/// "function evaluation" and "best-so-far f(x)" are read; every row has as many columns as it names.
std::vector<IohBlock> read_ioh_blocks(const fs::path& file, const std::string& what) {
    const auto lines = read_lines(file, what);
    std::vector<IohBlock> blocks;
    std::size_t columns = 0, best_column = 0;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string line = trim(lines[i]);
        const std::string where = fmt::format("{}:{}", file.string(), i + 1);
        if (line.empty()) continue;
        if (line[0] == '"') {
            std::vector<std::string> names;
            for (std::size_t at = 0; (at = line.find('"', at)) != std::string::npos;) {
                const auto close = line.find('"', at + 1);
                if (close == std::string::npos) throw InputError(where, "expected a closing '\"' in the header line");
                names.push_back(line.substr(at + 1, close - at - 1));
                at = close + 1;
            }
            const auto best = std::find(names.begin(), names.end(), "best-so-far f(x)");
            if (names.empty() || names.front() != "function evaluation" || best == names.end())
                throw InputError(where,
                                 "expected a header line naming the columns \"function evaluation\" and "
                                 "\"best-so-far f(x)\"");
            columns = names.size();
            best_column = static_cast<std::size_t>(best - names.begin());
            blocks.push_back({i + 1, {}});
            continue;
        }
        if (blocks.empty())
            throw InputError(where, "expected a header line of column names (\"function evaluation\" ...) first");
        std::istringstream in(line);
        std::vector<std::string> tokens;
        for (std::string t; in >> t;) tokens.push_back(t);
        if (tokens.size() != columns)
            throw InputError(where, fmt::format("expected {} columns, as the header line at {} names, got {} (a "
                                                "truncated file?)",
                                                columns, blocks.back().line, tokens.size()));
        const auto evaluations = count(tokens[0], 1);
        if (!evaluations)
            throw InputError(where,
                             "expected a count of evaluations (at least 1) in column 1, got '" + tokens[0] + "'");
        auto& rows = blocks.back().rows;
        if (!rows.empty() && *evaluations < rows.back().evaluations)
            throw InputError(where, fmt::format("expected evaluations that never decrease, got {} after {}",
                                                *evaluations, rows.back().evaluations));
        const std::string& token = tokens[best_column];
        std::optional<double> best;
        if (token != "None") {  // IOHexperimenter's text for no value
            best = number(token);
            if (!best || !std::isfinite(*best))
                throw InputError(where, fmt::format("expected best-so-far f(x), a finite number or None, in column {}, "
                                                    "got '{}'",
                                                    best_column + 1, token));
        }
        rows.push_back({*evaluations, best, i + 1});
    }
    return blocks;
}

}  // namespace

storage::PublishedSet read_ioh(const std::string& store_path, const std::string& folder,
                               const PublishedImportOptions& options) {
    published_files::check_options(options);
    std::error_code ec;
    require(fs::is_directory(folder, ec), folder,
            fs::exists(folder, ec) ? "not a folder (give the folder of an algorithm's .info files)" : "no such folder");
    std::vector<fs::path> infos;
    for (const auto& e : fs::recursive_directory_iterator(folder))
        if (e.is_regular_file() && e.path().extension() == ".info") infos.push_back(e.path());
    std::sort(infos.begin(), infos.end());
    require(!infos.empty(), folder, "holds no .info file (not an IOHprofiler folder as pride export --ioh writes)");

    const storage::CampaignStore store = storage::read_store(store_path);
    require(store.problems && !store.problems->empty(), store_path,
            "holds no campaign's problems (run pride bench first: IOH files are read onto the store's problems)");
    std::map<std::pair<std::int64_t, std::int64_t>, IohCell> functions;  // (funcId, DIM)
    for (std::size_t k = 0; k < store.problems->size(); ++k) {
        const storage::StoredProblem& p = (*store.problems)[k];
        IohCell& f = functions[{ioh_function(p, k).id, p.dim}];
        f.fn = ioh_function(p, k);
        if (f.fn.in_suite)
            f.by_instance.emplace(p.instance, &p);
        else
            f.problem = &p;
    }

    storage::PublishedSet set;
    set.source.algorithm = storage::kPublishedPrefix + options.name;
    set.source.format = "iohprofiler";
    set.source.source = options.source.value_or(published_files::folder_name(folder));
    set.source.citation = options.citation;
    std::optional<std::pair<std::string, std::string>> algorithm;       // (algId, where)
    std::map<std::pair<std::int64_t, std::int64_t>, std::string> seen;  // (funcId, DIM) -> where
    std::map<std::string, std::int64_t> trials;                         // problem -> runs so far
    for (const fs::path& info : infos) {
        const auto lines = read_lines(info, "an .info file");
        const IohCell* current = nullptr;
        std::int64_t dim = 0;
        for (std::size_t i = 0; i < lines.size(); ++i) {
            const std::string line = trim(lines[i]);
            const std::string where = fmt::format("{}:{}", info.string(), i + 1);
            if (line.empty() || line[0] == '%') continue;
            if (line.find("funcId") != std::string::npos) {
                const auto f = ioh_header_fields(line);
                const auto field = [&](const char* key) { return f.count(key) ? f.at(key) : std::string(); };
                const auto id = count(field("funcId"), 0);
                const auto d = count(field("DIM"), 1);
                if (!id) throw InputError(where, "expected 'funcId = N' with N a function number");
                if (!d) throw InputError(where, "expected 'DIM = D' with D at least 1");
                if (field("maximization") == "T")
                    throw InputError(where,
                                     "maximization = \"T\": pride minimises, and imports minimised functions only");
                const std::string alg = field("algId");
                if (alg.empty()) throw InputError(where, "expected 'algId = \"...\"', the algorithm that ran");
                if (!algorithm)
                    algorithm.emplace(alg, where);
                else if (alg != algorithm->first)
                    throw InputError(where, fmt::format("names the algorithm '{}', {} names '{}': import one "
                                                        "algorithm's folder at a time",
                                                        alg, algorithm->second, algorithm->first));
                const auto it = functions.find({*id, *d});
                if (it == functions.end() || field("suite") != ioh_quoted(it->second.fn.suite) ||
                    field("funcName") != ioh_quoted(it->second.fn.name))
                    throw InputError(
                        where, fmt::format("suite '{}' funcId {} ('{}') in {}-D is none of the store's problems{} "
                                           "(IOH files are read onto the problems of the campaign they were "
                                           "exported from)",
                                           field("suite"), *id, field("funcName"), *d,
                                           it == functions.end()
                                               ? ""
                                               : fmt::format(": its funcId {} in {}-D is suite '{}' "
                                                             "'{}'",
                                                             *id, *d, it->second.fn.suite, it->second.fn.name)));
                if (const auto [s, added] = seen.emplace(std::pair{*id, *d}, where); !added)
                    throw InputError(where, fmt::format("funcId {} in {}-D again, as at {}", *id, *d, s->second));
                current = &it->second;
                dim = *d;
                continue;
            }
            if (!current)
                throw InputError(where, "expected a header line ('suite = ..., funcId = ..., DIM = ...') first");
            // The data line: the .dat file, then its runs.
            std::vector<std::string> parts;
            std::istringstream in(line);
            for (std::string part; std::getline(in, part, ',');) parts.push_back(trim(part));
            if (parts.size() < 2 || parts.front().find(':') != std::string::npos)
                throw InputError(where,
                                 "expected a data line: the .dat file, then its runs as "
                                 "'number:evaluations|best f(x)'");
            struct Listed {
                const storage::StoredProblem* problem;
                std::int64_t number, evaluations;
                double best;
            };
            std::vector<Listed> listed;
            for (std::size_t k = 1; k < parts.size(); ++k) {
                const std::string& elem = parts[k];
                const auto colon = elem.find(':'), bar = elem.find('|');
                const auto n = colon == std::string::npos ? std::nullopt : count(elem.substr(0, colon), 0);
                const auto e = bar == std::string::npos || bar < colon
                                   ? std::nullopt
                                   : count(elem.substr(colon + 1, bar - colon - 1), 0);
                const auto b = bar == std::string::npos ? std::nullopt : number(elem.substr(bar + 1));
                if (!n || !e || !b || !std::isfinite(*b))
                    throw InputError(where,
                                     "expected a run as 'number:evaluations|best f(x)' (a finite best: pride "
                                     "imports runs that found a value), got '" +
                                         elem + "'");
                const Listed run{current->problem, *n, *e, *b};
                listed.push_back(run);
                if (current->fn.in_suite) {
                    const auto at = current->by_instance.find(run.number);
                    if (at == current->by_instance.end())
                        throw InputError(where, fmt::format("'{}': instance {} of funcId {} in {}-D is none of the "
                                                            "store's problems",
                                                            elem, run.number, current->fn.id, dim));
                    listed.back().problem = at->second;
                }
            }
            std::string file = parts.front();
            std::replace(file.begin(), file.end(), '\\', '/');
            const fs::path dat = info.parent_path() / file;
            const auto blocks = read_ioh_blocks(dat, "named at " + where);
            if (blocks.size() != listed.size())
                throw InputError(dat.string(), fmt::format("holds {} runs, {} lists {} (a truncated file?)",
                                                           blocks.size(), where, listed.size()));
            for (std::size_t k = 0; k < listed.size(); ++k) {
                const Listed& l = listed[k];
                const IohBlock& b = blocks[k];
                storage::PublishedRun r;
                r.problem = l.problem->id;
                r.suite = l.problem->suite.value_or("");
                r.fid = l.problem->fid.value_or(0);
                r.dim = l.problem->dim;
                r.instance = l.problem->instance;
                r.trial = current->fn.in_suite ? ++trials[l.problem->id] : l.number;
                // Without a known optimum the values are kept as they are (precisions from 0), and
                // no runtime is derived, as for pride's own runs there.
                r.runtimes = l.problem->f_opt.has_value();
                r.f_opt = l.problem->f_opt.value_or(0.0);
                r.evaluations = l.evaluations;
                r.final_precision = l.best - r.f_opt;
                r.where = fmt::format("{}:{}", dat.string(), b.line);
                for (const IohRow& row : b.rows) {
                    if (row.evaluations > l.evaluations)
                        throw InputError(fmt::format("{}:{}", dat.string(), row.line),
                                         fmt::format("a row at {} evaluations, beyond the run's {} ({})",
                                                     row.evaluations, l.evaluations, where));
                    if (!row.best) continue;
                    r.history.push_back(*row.best);
                    r.history_evaluations.push_back(row.evaluations);
                    // The best so far never rises; a row at the same evaluations replaces the last.
                    const double v = r.values.empty() ? *row.best - r.f_opt
                                                      : std::min(*row.best - r.f_opt, r.values.back().precision);
                    if (!r.values.empty() && r.values.back().evaluations == row.evaluations)
                        r.values.back().precision = v;
                    else
                        r.values.push_back({row.evaluations, v});
                }
                r.targets = r.values;
                set.runs.push_back(std::move(r));
            }
        }
    }
    require(!set.runs.empty(), folder, "holds no run (its .info files list none)");
    set.source.sha256 = options.sha256.value_or(published_files::folder_sha256(folder));
    return set;
}

storage::ImportSummary import_ioh(const std::string& store, const std::string& folder,
                                  const PublishedImportOptions& options, const std::vector<double>& precisions,
                                  const std::string& precisions_json) {
    // Everything read and checked before the store is opened for writing: bad files leave no trace.
    return published_files::add_to_store(store, read_ioh(store, folder, options), precisions, precisions_json);
}

}  // namespace pride::report

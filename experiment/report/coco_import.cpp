#include "experiment/report/coco_import.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>
#include <tuple>

#include "framework/error.hpp"

namespace pride::report {
namespace {

namespace fs = std::filesystem;
using published_files::count;
using published_files::number;
using published_files::read_lines;
using published_files::trim;

std::vector<std::string> split(const std::string& s, char by) {
    std::vector<std::string> out;
    std::string part;
    std::istringstream in(s);
    while (std::getline(in, part, by)) out.push_back(part);
    return out;
}

/// One run's block of a .dat or .tdat file.
struct Block {
    std::optional<double> f_opt;  // from its header ("Fopt (3.59e+01)")
    std::vector<storage::PublishedPoint> points;
    std::size_t line = 0;   // of its first data line
    std::int64_t last = 0;  // the evaluations of its last line
};

/// The blocks of a .dat or .tdat file as cocopp's readalign.split cuts them: a line starting with
/// '%' after data lines starts the next run.
std::vector<Block> read_blocks(const fs::path& file, const std::string& what) {
    const auto lines = read_lines(file, what);
    std::vector<Block> blocks;
    Block current;
    bool data = false;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string& line = lines[i];
        const std::string where = fmt::format("{}:{}", file.string(), i + 1);
        if (trim(line).empty()) continue;
        if (line[0] == '%') {
            if (data) {
                blocks.push_back(std::move(current));
                current = Block{};
                data = false;
            }
            if (const auto at = line.find("Fopt ("); at != std::string::npos) {
                const auto close = line.find(')', at);
                const auto v =
                    close == std::string::npos ? std::nullopt : number(trim(line.substr(at + 6, close - at - 6)));
                if (!v || !std::isfinite(*v)) throw InputError(where, "expected a number in 'Fopt (...)'");
                current.f_opt = *v;
            }
            continue;
        }
        std::istringstream in(line);
        std::vector<std::string> tokens;
        for (std::string t; in >> t;) tokens.push_back(t);
        if (tokens.size() < 3)
            throw InputError(where, fmt::format("expected evaluations, f - f_opt and best f - f_opt (3 columns or "
                                                "more), got {}",
                                                tokens.size()));
        const auto evaluations = count(tokens[0], 1);
        if (!evaluations)
            throw InputError(where,
                             "expected a count of evaluations (at least 1) in column 1, got '" + tokens[0] + "'");
        const auto best = number(tokens[2]);
        if (!best || std::isnan(*best))
            throw InputError(where, "expected best f - f_opt, a number, in column 3, got '" + tokens[2] + "'");
        if (!data) current.line = i + 1;
        data = true;
        current.last = std::max(current.last, *evaluations);
        auto& points = current.points;
        if (!points.empty() && *evaluations < points.back().evaluations)
            throw InputError(where, fmt::format("expected evaluations that never decrease, got {} after {}",
                                                *evaluations, points.back().evaluations));
        if (std::isinf(*best)) continue;  // nothing reached yet (the trace's +inf before a value)
        // The best so far never increases; a line at the same evaluations replaces the one before.
        const double value = points.empty() ? *best : std::min(*best, points.back().precision);
        if (!points.empty() && points.back().evaluations == *evaluations)
            points.back().precision = value;
        else
            points.push_back({*evaluations, value});
    }
    if (data) blocks.push_back(std::move(current));
    return blocks;
}

/// "key = value" pairs of an .info header line, values unquoted.
std::map<std::string, std::string> header_fields(const std::string& line) {
    std::map<std::string, std::string> out;
    for (const std::string& part : split(line, ',')) {
        const auto eq = part.find('=');
        if (eq == std::string::npos) continue;
        std::string value = trim(part.substr(eq + 1));
        if (value.size() >= 2 && (value.front() == '\'' || value.front() == '"') && value.back() == value.front())
            value = value.substr(1, value.size() - 2);
        out[trim(part.substr(0, eq))] = value;
    }
    return out;
}

}  // namespace

storage::PublishedSet read_coco(const std::string& folder, const CocoImportOptions& options) {
    published_files::check_options(options);
    std::error_code ec;
    require(fs::is_directory(folder, ec), folder,
            fs::exists(folder, ec) ? "not a folder (extract a .tgz first: pride reads the folder of .info files)"
                                   : "no such folder");
    std::vector<fs::path> infos;
    for (const auto& e : fs::recursive_directory_iterator(folder))
        if (e.is_regular_file() && e.path().extension() == ".info") infos.push_back(e.path());
    std::sort(infos.begin(), infos.end());
    require(!infos.empty(), folder, "holds no .info file (not a COCO data set)");

    storage::PublishedSet set;
    set.source.algorithm = storage::kPublishedPrefix + options.name;
    set.source.format = "coco-bbob";
    set.source.source = options.source.value_or(published_files::folder_name(folder));
    set.source.citation = options.citation;
    std::map<std::tuple<std::int64_t, std::int64_t, std::int64_t>, std::int64_t> trials;  // (fid, dim, instance)
    for (const fs::path& info : infos) {
        const auto lines = read_lines(info, "an .info file");
        std::optional<std::pair<std::int64_t, std::int64_t>> current;  // (fid, dim) of the last header
        for (std::size_t i = 0; i < lines.size(); ++i) {
            const std::string line = trim(lines[i]);
            const std::string where = fmt::format("{}:{}", info.string(), i + 1);
            if (line.empty() || line[0] == '%') continue;
            if (line.find("funcId") != std::string::npos) {
                const auto f = header_fields(line);
                if (const auto s = f.find("suite"); s != f.end() && s->second != "bbob")
                    throw InputError(where, "suite '" + s->second + "': pride imports COCO's bbob data sets only");
                const auto fid = f.count("funcId") ? count(f.at("funcId"), 1) : std::nullopt;
                const auto dim = f.count("DIM") ? count(f.at("DIM"), 2) : std::nullopt;
                if (!fid) throw InputError(where, "expected 'funcId = N' with N a bbob function number");
                if (!dim) throw InputError(where, "expected 'DIM = D' with D at least 2");
                const std::int64_t function = fid.value_or(0);
                if (function > 24)
                    throw InputError(where, "funcId = " + std::to_string(function) +
                                                ": pride imports the noiseless bbob functions f1-f24 only");
                current.emplace(function, dim.value_or(0));
                continue;
            }
            if (!current) throw InputError(where, "expected a header line ('funcId = ..., DIM = ...') first");
            const auto [fid, dim] = *current;
            // The data line: data files, each followed by its runs.
            struct Group {
                std::string file;
                std::vector<std::tuple<std::int64_t, std::int64_t>> runs;  // (instance, evaluations)
            };
            std::vector<Group> groups;
            for (const std::string& raw : split(line, ',')) {
                const std::string elem = trim(raw);
                if (elem.empty() || elem.find('=') != std::string::npos) continue;
                const auto colon = elem.find(':');
                if (colon == std::string::npos) {
                    if (count(elem, 0))
                        throw InputError(where, "run of instance " + elem +
                                                    " was not finished (no ':evaluations|f'); cocopp warns, pride "
                                                    "imports finished runs only");
                    std::string file = elem;
                    std::replace(file.begin(), file.end(), '\\', '/');  // written on Windows in 2009
                    groups.push_back({file, {}});
                    continue;
                }
                if (groups.empty()) throw InputError(where, "expected a data file name before the runs");
                const auto bar = elem.find('|', colon);
                const auto instance = count(elem.substr(0, colon), 1);
                const auto evaluations =
                    bar == std::string::npos ? std::nullopt : count(elem.substr(colon + 1, bar - colon - 1), 0);
                if (!instance || !evaluations || !number(elem.substr(bar + 1)))
                    throw InputError(where,
                                     "expected a run as 'instance:evaluations|final f - f_target', got '" + elem + "'");
                groups.back().runs.emplace_back(*instance, *evaluations);
            }
            if (groups.empty()) throw InputError(where, "expected a data line naming a .dat file and its runs");
            for (const Group& g : groups) {
                fs::path dat = info.parent_path() / g.file;
                dat.replace_extension(".dat");
                fs::path tdat = dat;
                tdat.replace_extension(".tdat");
                const auto targets = read_blocks(dat, "named at " + where);
                std::error_code e2;
                const auto values = fs::exists(tdat, e2) ? read_blocks(tdat, "") : std::vector<Block>{};
                if (targets.size() != g.runs.size())
                    throw InputError(dat.string(),
                                     fmt::format("holds {} runs, {} lists {}", targets.size(), where, g.runs.size()));
                if (!values.empty() && values.size() != g.runs.size())
                    throw InputError(tdat.string(),
                                     fmt::format("holds {} runs, {} lists {}", values.size(), where, g.runs.size()));
                for (std::size_t k = 0; k < g.runs.size(); ++k) {
                    const Block& b = targets[k];
                    const std::string run_where = fmt::format("{}:{}", dat.string(), b.line);
                    if (!b.f_opt) throw InputError(run_where, "the run's header gives no 'Fopt (...)' (its optimum)");
                    storage::PublishedRun r;
                    r.suite = "bbob";
                    r.fid = fid;
                    r.dim = dim;
                    r.instance = std::get<0>(g.runs[k]);
                    r.trial = ++trials[{fid, dim, r.instance}];
                    r.f_opt = *b.f_opt;
                    r.targets = b.points;
                    if (!values.empty()) r.values = values[k].points;
                    if (r.targets.empty()) throw InputError(run_where, "the run reached no finite value");
                    r.evaluations = b.last;
                    r.final_precision = r.targets.back().precision;
                    if (!values.empty()) {
                        r.evaluations = std::max(r.evaluations, values[k].last);
                        if (!r.values.empty())
                            r.final_precision = std::min(r.final_precision, r.values.back().precision);
                    }
                    r.where = run_where;
                    set.runs.push_back(std::move(r));
                }
            }
        }
    }
    require(!set.runs.empty(), folder, "holds no run (its .info files list none)");
    set.source.sha256 = options.sha256.value_or(published_files::folder_sha256(folder));
    return set;
}

storage::ImportSummary import_coco(const std::string& store, const std::string& folder,
                                   const CocoImportOptions& options, const std::vector<double>& precisions,
                                   const std::string& precisions_json) {
    // Everything read and checked before the store is opened: a bad data set leaves no trace.
    return published_files::add_to_store(store, read_coco(folder, options), precisions, precisions_json);
}

}  // namespace pride::report

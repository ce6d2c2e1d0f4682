#include "experiment/report/cec2017_import.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "framework/error.hpp"
#include "problems/continuous/cec/functions.hpp"
#include "problems/continuous/cec/suites.hpp"

namespace pride::report {
namespace {

namespace fs = std::filesystem;
using published_files::number;
using published_files::trim;

constexpr int kCheckpoints = 14;  // (0.01, 0.02, 0.03, 0.05, 0.1, 0.2, ..., 1.0) x MaxFES

/// A result file's name: NAME_A_B with its two numbers.
struct Named {
    fs::path path;
    std::string algorithm;
    std::int64_t a = 0, b = 0;
};

bool competition_dimension(std::int64_t d) {
    return d == 10 || d == 30 || d == 50 || d == 100;
}

/// A line's fields: comma-separated where it has a comma (DES's, MOS's files; a trailing comma
/// ends no field), else blank-separated.
std::vector<std::string> fields(const std::string& line) {
    std::vector<std::string> out;
    if (line.find(',') != std::string::npos) {
        std::istringstream in(line);
        for (std::string part; std::getline(in, part, ',');) out.push_back(trim(part));
        if (!out.empty() && out.back().empty()) out.pop_back();
    } else {
        std::istringstream in(line);
        for (std::string t; in >> t;) out.push_back(t);
    }
    return out;
}

/// The evaluations a row's label gives ("Function error values when FEs = 1000"), or none.
std::optional<std::int64_t> label_evaluations(const std::string& label) {
    static const std::regex fes(R"(FEs\s*=\s*([0-9]+)\s*$)");
    std::smatch m;
    if (!std::regex_search(label, m, fes)) return std::nullopt;
    return std::stoll(m[1].str());
}

/// MOS's header line: a name, then "Run 1", "Run 2", ... one per column.
bool is_header(const std::vector<std::string>& tokens) {
    if (tokens.size() < 2) return false;
    for (std::size_t k = 1; k < tokens.size(); ++k)
        if (tokens[k] != "Run " + std::to_string(k)) return false;
    return true;
}

/// One file's runs, appended to `out`.
void read_file(const Named& f, std::int64_t fid, std::int64_t dim, std::vector<storage::PublishedRun>& out) {
    const std::string file = f.path.string();
    const auto lines = published_files::read_lines(f.path, "a CEC 2017 result file");
    const std::int64_t max_evaluations = *continuous::cec::default_evaluations("cec2017", dim);
    const auto checkpoints = continuous::cec::checkpoints_2017(max_evaluations);
    std::vector<std::vector<double>> rows;  // [checkpoint][run]
    std::size_t first_line = 0, last_line = 0;
    bool labelled = false;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string where = fmt::format("{}:{}", file, i + 1);
        if (trim(lines[i]).empty()) continue;
        std::vector<std::string> tokens = fields(lines[i]);
        const bool labelled_row = !tokens.empty() && !number(tokens.front());
        if (labelled_row && rows.empty() && !labelled && is_header(tokens)) {
            labelled = true;  // "NAME.csv , Run 1, Run 2, ...": the rows below are labelled
            continue;
        }
        if (rows.size() == kCheckpoints)
            throw InputError(where, fmt::format("expected {} rows, one per CEC 2017 checkpoint ((0.01, 0.02, 0.03, "
                                                "0.05, 0.1, 0.2, ..., 1.0) x MaxFES), got more",
                                                kCheckpoints));
        const auto& checkpoint = checkpoints[rows.size()];
        if (labelled && !labelled_row)
            throw InputError(where,
                             "expected a label 'FEs = N' in column 1 (as the header line's 'Run 1, ...' says), "
                             "got '" +
                                 tokens.front() + "'");
        if (labelled_row) {
            const auto at = label_evaluations(tokens.front());
            if (!at)
                throw InputError(where, "expected an error f - f* (a number) or a label 'FEs = N' in column 1, got '" +
                                            tokens.front() + "'");
            if (*at != checkpoint.evaluations)
                throw InputError(where, fmt::format("labelled FEs = {}, the CEC 2017 checkpoint {} x MaxFES of {}-D "
                                                    "(MaxFES = 10000 D) is {} evaluations",
                                                    *at, checkpoint.label, dim, checkpoint.evaluations));
            tokens.erase(tokens.begin());
        }
        std::vector<double> row;
        for (std::size_t k = 0; k < tokens.size(); ++k) {
            const auto v = number(tokens[k]);
            if (!v || !std::isfinite(*v) || *v < 0)
                throw InputError(where, fmt::format("run {}: expected an error f - f* (a finite number >= 0), got '{}'",
                                                    k + 1, tokens[k]));
            row.push_back(*v);
        }
        if (row.empty()) throw InputError(where, "expected the runs' errors, got none");
        if (!rows.empty() && row.size() != rows.front().size())
            throw InputError(where,
                             fmt::format("holds {} runs' errors, the first row {}", row.size(), rows.front().size()));
        if (!rows.empty())
            for (std::size_t k = 0; k < row.size(); ++k)
                if (row[k] > rows.back()[k])
                    throw InputError(where, fmt::format("run {}: the error rises from {} to {}, but a checkpoint "
                                                        "records the best error so far",
                                                        k + 1, rows.back()[k], row[k]));
        if (rows.empty()) first_line = i + 1;
        last_line = i + 1;
        rows.push_back(std::move(row));
    }
    if (rows.size() != kCheckpoints)
        throw InputError(rows.empty() ? file : fmt::format("{}:{}", file, last_line),
                         fmt::format("expected {} rows, one per CEC 2017 checkpoint ((0.01, 0.02, 0.03, 0.05, 0.1, "
                                     "0.2, ..., 1.0) x MaxFES), got {}",
                                     kCheckpoints, rows.size()));
    const double f_opt = continuous::cec::bias(continuous::cec::Suite::y2017, static_cast<int>(fid));
    for (std::size_t k = 0; k < rows.front().size(); ++k) {
        storage::PublishedRun r;
        r.suite = "cec2017";
        r.fid = fid;
        r.dim = dim;
        r.instance = 0;
        r.trial = static_cast<std::int64_t>(k) + 1;
        r.f_opt = f_opt;
        r.runtimes = false;
        r.max_evaluations = max_evaluations;
        r.evaluations = max_evaluations;
        for (int c = 0; c < kCheckpoints; ++c) r.checkpoints.push_back({checkpoints[c].evaluations, rows[c][k]});
        r.values = r.checkpoints;
        r.final_precision = rows.back()[k];
        r.where = fmt::format("{}:{}", file, first_line);
        out.push_back(std::move(r));
    }
}

}  // namespace

storage::PublishedSet read_cec2017(const std::string& folder, const PublishedImportOptions& options) {
    published_files::check_options(options);
    std::error_code ec;
    require(
        fs::is_directory(folder, ec), folder,
        fs::exists(folder, ec) ? "not a folder (give one entrant's folder of NAME_F_D.txt files)" : "no such folder");
    static const std::regex name(R"((.+)_([0-9]+)_([0-9]+)\.(txt|dat|csv))");
    std::vector<Named> files;
    std::vector<std::string> subfolders;
    for (const auto& e : fs::directory_iterator(folder)) {
        const std::string file = e.path().filename().string();
        std::smatch m;
        if (e.is_directory())
            subfolders.push_back(file);
        else if (e.is_regular_file() && std::regex_match(file, m, name) && m[2].length() < 6 && m[3].length() < 6)
            files.push_back({e.path(), m[1].str(), std::stoll(m[2].str()), std::stoll(m[3].str())});
    }
    std::sort(files.begin(), files.end(), [](const Named& x, const Named& y) { return x.path < y.path; });
    std::sort(subfolders.begin(), subfolders.end());
    if (files.empty()) {
        std::string list;
        for (const auto& s : subfolders) list += (list.empty() ? "" : ", ") + s;
        throw InputError(folder, "holds no CEC 2017 result file (NAME_F_D.txt, one per function and dimension)" +
                                     (list.empty() ? std::string() : "; import its folders one by one: " + list));
    }
    for (const Named& f : files)
        if (f.algorithm != files.front().algorithm)
            throw InputError(f.path.string(), "is a file of '" + f.algorithm + "', " + files.front().path.string() +
                                                  " one of '" + files.front().algorithm +
                                                  "': import one entrant's folder at a time");
    // NAME_F_D as the competition asked, or NAME_D_F where the names show it: the second numbers
    // go beyond the competition's dimensions and the first stay within them.
    const bool a_dims =
        std::all_of(files.begin(), files.end(), [](const Named& f) { return competition_dimension(f.a); });
    const bool b_dims =
        std::all_of(files.begin(), files.end(), [](const Named& f) { return competition_dimension(f.b); });
    const bool dim_first = a_dims && !b_dims;
    storage::PublishedSet set;
    set.source.algorithm = storage::kPublishedPrefix + options.name;
    set.source.format = "cec2017";
    set.source.source = options.source.value_or(published_files::folder_name(folder));
    set.source.citation = options.citation;
    std::map<std::pair<std::int64_t, std::int64_t>, std::string> seen;  // (function, dimension) -> file
    const auto suite = continuous::cec::Suite::y2017;
    for (const Named& f : files) {
        const std::int64_t fid = dim_first ? f.b : f.a, dim = dim_first ? f.a : f.b;
        const std::string file = f.path.string();
        if (fid < 1 || fid > continuous::cec::size(suite))
            throw InputError(file, fmt::format("names function {} ({}_{}_{}: NAME_F_D), CEC 2017's are 1-{}", fid,
                                               f.algorithm, f.a, f.b, continuous::cec::size(suite)));
        const auto dims = continuous::cec::dimensions(suite, static_cast<int>(fid));
        if (std::find(dims.begin(), dims.end(), static_cast<std::size_t>(dim)) == dims.end()) {
            std::string list;
            for (const std::size_t d : dims) list += (list.empty() ? "" : ", ") + std::to_string(d);
            throw InputError(file, fmt::format("names F{} in dimension {} ({}_{}_{}: NAME_{}), which CEC 2017 "
                                               "defines in {} only",
                                               fid, dim, f.algorithm, f.a, f.b, dim_first ? "D_F" : "F_D", list));
        }
        if (const auto [it, added] = seen.emplace(std::pair{fid, dim}, file); !added)
            throw InputError(file, fmt::format("holds F{} in {}-D, as {} does", fid, dim, it->second));
        read_file(f, fid, dim, set.runs);
    }
    set.source.sha256 = options.sha256.value_or(published_files::folder_sha256(folder));
    return set;
}

storage::ImportSummary import_cec2017(const std::string& store, const std::string& folder,
                                      const PublishedImportOptions& options, const std::vector<double>& precisions,
                                      const std::string& precisions_json) {
    // Everything read and checked before the store is opened: a bad file leaves no trace.
    return published_files::add_to_store(store, read_cec2017(folder, options), precisions, precisions_json);
}

}  // namespace pride::report

#include "cli/export.hpp"

#include <fmt/format.h>
#include <sqlite3.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <ostream>
#include <sstream>
#include <vector>

#include "framework/error.hpp"

namespace pride::cli {
namespace {

std::vector<double> numbers(const std::string& json) {  // "[1, 2.5, null]" -> 1, 2.5, inf
    std::vector<double> out;
    std::string text = json;
    for (char& c : text)
        if (c == '[' || c == ']' || c == ',') c = ' ';
    std::istringstream in(text);
    for (std::string token; in >> token;)
        out.push_back(token == "null" ? std::numeric_limits<double>::infinity() : std::stod(token));
    return out;
}

std::string safe(const std::string& name) {
    std::string s = name;
    for (char& c : s)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '.') c = '_';
    return s;
}

struct Run {
    std::int64_t seed, evaluations;
    double best;
    std::vector<double> history, history_evaluations;
};

}  // namespace

int export_command(const ExportOptions& o, std::ostream& out) {
    require(!o.ioh.empty(), "--ioh", "name the folder to write");
    require(std::filesystem::is_regular_file(o.store), o.store, "no such store");
    sqlite3* db = nullptr;
    if (sqlite3_open_v2(o.store.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) != SQLITE_OK) {
        sqlite3_close(db);
        throw InputError(o.store + ": cannot open the store");
    }
    auto query = [&](const char* sql, auto&& row) {
        sqlite3_stmt* s = nullptr;
        if (sqlite3_prepare_v2(db, sql, -1, &s, nullptr) != SQLITE_OK) {
            const std::string why = sqlite3_errmsg(db);
            sqlite3_close(db);
            throw InputError(o.store + ": not a campaign store (" + why + ")");
        }
        while (sqlite3_step(s) == SQLITE_ROW) row(s);
        sqlite3_finalize(s);
    };
    auto text = [](sqlite3_stmt* s, int i) {
        return std::string(reinterpret_cast<const char*>(sqlite3_column_text(s, i)));
    };
    std::string campaign;
    query("SELECT name FROM campaign WHERE id = 1", [&](sqlite3_stmt* s) { campaign = text(s, 0); });
    std::vector<std::pair<std::string, std::int64_t>> problems;  // in campaign order: the function ids
    query("SELECT id, dim FROM problems ORDER BY rowid",
          [&](sqlite3_stmt* s) { problems.emplace_back(text(s, 0), sqlite3_column_int64(s, 1)); });
    std::map<std::string, std::map<std::string, std::vector<Run>>> runs;  // algorithm -> problem -> runs
    query(
        "SELECT algorithm, problem, seed, evaluations, best, history, history_evaluations FROM runs "
        "ORDER BY algorithm, problem, seed",
        [&](sqlite3_stmt* s) {
            runs[text(s, 0)][text(s, 1)].push_back({sqlite3_column_int64(s, 2), sqlite3_column_int64(s, 3),
                                                    sqlite3_column_type(s, 4) == SQLITE_NULL
                                                        ? std::numeric_limits<double>::infinity()
                                                        : sqlite3_column_double(s, 4),
                                                    numbers(text(s, 5)), numbers(text(s, 6))});
        });
    sqlite3_close(db);
    require(!runs.empty(), o.store, "holds no runs yet (run pride bench first)");

    std::size_t files = 0;
    for (const auto& [algorithm, by_problem] : runs) {
        const std::filesystem::path folder = std::filesystem::path(o.ioh) / safe(algorithm);
        std::error_code ec;
        std::filesystem::create_directories(folder, ec);
        require(!ec, "--ioh", folder.string() + ": cannot create the folder");
        for (std::size_t f = 0; f < problems.size(); ++f) {
            const auto& [problem, dim] = problems[f];
            const auto it = by_problem.find(problem);
            if (it == by_problem.end()) continue;
            const std::string id = std::to_string(f + 1), name = safe(problem);
            const std::string data_folder = "data_f" + id + "_" + name;
            const std::string dat = "IOHprofiler_f" + id + "_DIM" + std::to_string(dim) + ".dat";
            std::filesystem::create_directories(folder / data_folder, ec);
            std::ofstream d(folder / data_folder / dat);
            std::string runs_line;
            for (const Run& r : it->second) {
                // One block per run: the best value after each iteration, at its evaluation count.
                d << "\"function evaluation\" \"current f(x)\" \"best-so-far f(x)\"\n";
                for (std::size_t k = 0; k < r.history.size() && k < r.history_evaluations.size(); ++k)
                    d << fmt::format("{} {:.17g} {:.17g}\n", static_cast<std::int64_t>(r.history_evaluations[k]),
                                     r.history[k], r.history[k]);
                runs_line += fmt::format(", {}:{}|{:.17g}", r.seed, r.evaluations, r.best);
            }
            std::ofstream info(folder / ("IOHprofiler_f" + id + "_" + name + ".info"));
            info << fmt::format(
                "suite = 'pride', funcId = {}, funcName = '{}', DIM = {}, maximization = 'F', algId = "
                "'{}', algInfo = 'campaign {}'\n%\n{}/{}{}\n",
                id, problem, dim, algorithm, campaign, data_folder, dat, runs_line);
            require(d.good() && info.good(), "--ioh", folder.string() + ": cannot write the files");
            files += 2;
        }
    }
    out << fmt::format("{} IOHprofiler files written under {}\n", files, o.ioh);
    return 0;
}

}  // namespace pride::cli

#include "experiment/html/page_store.hpp"

#include <sqlite3.h>

#include <cmath>
#include <regex>

#include <fmt/format.h>

#include "experiment/storage/reader.hpp"
#include "framework/error.hpp"

namespace pride::html {
namespace {

class Reader {
  public:
    explicit Reader(const std::string& path) : path_(path), db_(storage::open_read_only(path)) {}
    ~Reader() { sqlite3_close(db_); }
    Reader(const Reader&) = delete;
    Reader& operator=(const Reader&) = delete;

    /// A statement; SQLite's reason as bad input when it cannot be prepared or stepped.
    class Statement {
      public:
        Statement(const Reader& r, const std::string& sql) : r_(r) {
            if (sqlite3_prepare_v2(r.db_, sql.c_str(), -1, &s_, nullptr) != SQLITE_OK) r.fail("");
        }
        ~Statement() { sqlite3_finalize(s_); }
        Statement(const Statement&) = delete;
        Statement& operator=(const Statement&) = delete;
        /// The next row; false at the end. `where` names the row for a failure (malformed JSON).
        bool step(const std::string& where = "") {
            const int rc = sqlite3_step(s_);
            if (rc == SQLITE_ROW) return true;
            if (rc != SQLITE_DONE) r_.fail(where);
            return false;
        }
        sqlite3_stmt* get() const { return s_; }
        std::string text(int i) const {
            const auto* t = sqlite3_column_text(s_, i);
            return t ? reinterpret_cast<const char*>(t) : std::string();
        }
        bool null(int i) const { return sqlite3_column_type(s_, i) == SQLITE_NULL; }

      private:
        const Reader& r_;
        sqlite3_stmt* s_ = nullptr;
    };

    [[noreturn]] void fail(const std::string& where) const {
        const std::string why = sqlite3_errmsg(db_);
        if (!where.empty()) throw storage::DamagedStore(path_, where + ": " + why);
        throw InputError(path_ + ": cannot read the store (" + why + ")");
    }
    bool has_table(const std::string& table) const {
        Statement s(*this, "SELECT 1 FROM sqlite_master WHERE type = 'table' AND name = '" + table + "'");
        return s.step();
    }
    bool has_column(const std::string& table, const std::string& column) const {
        Statement s(*this, "SELECT 1 FROM pragma_table_info('" + table + "') WHERE name = '" + column + "'");
        return s.step();
    }
    const std::string& path() const { return path_; }

  private:
    std::string path_;
    sqlite3* db_ = nullptr;
};

grid::Cell parse_cell(const std::string& text, const std::string& store, const std::string& where) {
    static const std::regex cell(R"((-?\d{1,9}),(-?\d{1,9}))");
    std::smatch m;
    if (!std::regex_match(text, m, cell))
        throw storage::DamagedStore(store, where + ": expected x,y, got '" + text + "'");
    return {std::stoi(m[1].str()), std::stoi(m[2].str())};
}

/// The front of a multi-objective run read from its solution, or in `out.error` why it cannot be:
/// SQLite's JSON functions read it (the report's store reader reads its indicators the same way),
/// each form checked before a value is taken, so that no form of solution makes SQLite fail.
void read_front(const Reader& db, const std::string& solution, StoredFront& out) {
    const auto bound = [&](Reader::Statement& s) {
        sqlite3_bind_text(s.get(), 1, solution.c_str(), -1, SQLITE_TRANSIENT);
    };
    const std::string row = fmt::format("runs row (problem '{}', algorithm '{}', seed {}), column solution",
                                        out.problem, out.algorithm, out.seed);
    const auto number = [](const std::string& type) { return type == "real" || type == "integer"; };
    {
        Reader::Statement s(db,
                            "SELECT json_valid(?1), CASE WHEN json_valid(?1) THEN json_type(?1, '$.objectives') END, "
                            "CASE WHEN json_valid(?1) THEN json_type(?1, '$.front') END, CASE WHEN json_valid(?1) "
                            "THEN json_type(?1, '$.hypervolume_ratio') END, CASE WHEN json_valid(?1) THEN "
                            "json_extract(?1, '$.hypervolume_ratio') END");
        bound(s);
        s.step(row);
        if (sqlite3_column_int(s.get(), 0) != 1) {
            out.error = "not valid JSON";
            return;
        }
        if (s.text(1) != "array" || s.text(2) != "array" || !number(s.text(3))) {
            out.error = "expected an object with objectives (a list of names), hypervolume_ratio and front (a list)";
            return;
        }
        out.hypervolume_ratio = sqlite3_column_double(s.get(), 4);
    }
    {
        Reader::Statement s(db, "SELECT type, value FROM json_each(?1, '$.objectives') ORDER BY key");
        bound(s);
        while (s.step(row)) {
            if (s.text(0) != "text") {
                out.error = "an objective's name is not a string";
                return;
            }
            out.objectives.push_back(s.text(1));
        }
        if (out.objectives.size() < 2) {
            out.error = fmt::format("expected two objectives or more, got {}", out.objectives.size());
            return;
        }
    }
    const auto m = static_cast<Eigen::Index>(out.objectives.size());
    std::size_t points = 0, grid = 0;
    {
        Reader::Statement s(db,
                            "SELECT type, CASE WHEN type = 'object' THEN json_type(value, '$.f') END, CASE WHEN type "
                            "= 'object' THEN json_array_length(value, '$.f') END, CASE WHEN type = 'object' THEN "
                            "json_type(value, '$.path') END, CASE WHEN type = 'object' THEN json_type(value, "
                            "'$.legal') END FROM json_each(?1, '$.front') ORDER BY key");
        bound(s);
        while (s.step(row)) {
            if (s.text(0) != "object" || s.text(1) != "array" || sqlite3_column_int64(s.get(), 2) != m) {
                out.error = fmt::format("point {}: expected an object with f, a list of {} values", points, m);
                return;
            }
            if (!s.null(3)) {
                if (s.text(3) != "array" || (s.text(4) != "true" && s.text(4) != "false")) {
                    out.error =
                        fmt::format("point {}: expected path, a list of cells, and legal, true or false", points);
                    return;
                }
                out.legal.push_back(s.text(4) == "true" ? 1 : 0);
                ++grid;
            }
            ++points;
        }
    }
    if (grid != 0 && grid != points) {
        out.error = "some points have a path and some none";
        return;
    }
    out.f.resize(m, static_cast<Eigen::Index>(points));
    {
        Reader::Statement s(db,
                            "SELECT p.key, f.key, f.type, f.value FROM json_each(?1, '$.front') AS p, "
                            "json_each(p.value, '$.f') AS f ORDER BY p.key, f.key");
        bound(s);
        while (s.step(row)) {
            const auto j = sqlite3_column_int64(s.get(), 0), i = sqlite3_column_int64(s.get(), 1);
            const double v = sqlite3_column_double(s.get(), 3);
            if (!number(s.text(2)) || std::isnan(v)) {
                out.error = fmt::format("point {}: objective {} is not a number", j, i);
                return;
            }
            out.f(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = v;
        }
    }
    if (grid == 0) return;
    out.paths.resize(points);
    Reader::Statement s(db,
                        "SELECT p.key, c.type, CASE WHEN c.type = 'array' THEN json_array_length(c.value) END, CASE "
                        "WHEN c.type = 'array' THEN json_type(c.value, '$[0]') END, CASE WHEN c.type = 'array' THEN "
                        "json_type(c.value, '$[1]') END, CASE WHEN c.type = 'array' THEN json_extract(c.value, "
                        "'$[0]') END, CASE WHEN c.type = 'array' THEN json_extract(c.value, '$[1]') END FROM "
                        "json_each(?1, '$.front') AS p, json_each(p.value, '$.path') AS c ORDER BY p.key, c.key");
    bound(s);
    while (s.step(row)) {
        const auto j = static_cast<std::size_t>(sqlite3_column_int64(s.get(), 0));
        const std::int64_t x = sqlite3_column_int64(s.get(), 5), y = sqlite3_column_int64(s.get(), 6);
        if (s.text(1) != "array" || sqlite3_column_int64(s.get(), 2) != 2 || s.text(3) != "integer" ||
            s.text(4) != "integer" || x < -(1 << 30) || x > (1 << 30) || y < -(1 << 30) || y > (1 << 30)) {
            out.error = fmt::format("point {}: expected path, a list of [x, y] cells", j);
            out.paths.clear();
            return;
        }
        out.paths[j].push_back({static_cast<int>(x), static_cast<int>(y)});
    }
}

}  // namespace

/// Calls each(x, y) for every [x, y] of a JSON list, read by SQLite's JSON functions: integers
/// (cells) or any numbers (points), each within 1e9; else DamagedStore naming `where`.
template <class Each>
void for_each_pair(Reader& db, const std::string& json, const std::string& path, const std::string& where,
                   const char* what, bool integers, Each each) {
    Reader::Statement pairs(db,
                            "SELECT json_type(value), json_array_length(value), json_type(value, '$[0]'), "
                            "json_type(value, '$[1]'), json_extract(value, '$[0]'), json_extract(value, '$[1]') "
                            "FROM json_each(?1)");
    sqlite3_bind_text(pairs.get(), 1, json.c_str(), -1, SQLITE_TRANSIENT);
    const auto ok_type = [&](const std::string& type) { return type == "integer" || (!integers && type == "real"); };
    while (pairs.step(where)) {
        const double x = sqlite3_column_double(pairs.get(), 4), y = sqlite3_column_double(pairs.get(), 5);
        if (pairs.text(0) != "array" || sqlite3_column_int64(pairs.get(), 1) != 2 || !ok_type(pairs.text(2)) ||
            !ok_type(pairs.text(3)) || !(std::abs(x) <= 1e9 && std::abs(y) <= 1e9))
            throw storage::DamagedStore(path, where + ": expected a JSON list of [x, y] " + what);
        each(x, y);
    }
}

PageStore read_page_store(const std::string& path) {
    Reader db(path);
    PageStore out;
    {
        Reader::Statement s(db, "SELECT text FROM campaign WHERE id = 1");
        if (s.step()) out.text = s.text(0);
    }
    // Multi-objective runs: their solution is an object (as read_store tells them apart).
    {
        Reader::Statement fronts(
            db,
            "SELECT problem, algorithm, seed, solution FROM runs WHERE substr(solution, 1, 1) = '{' "
            "ORDER BY problem, algorithm, seed");
        while (fronts.step()) {
            StoredFront f;
            f.problem = fronts.text(0);
            f.algorithm = fronts.text(1);
            f.seed = sqlite3_column_int64(fronts.get(), 2);
            read_front(db, fronts.text(3), f);
            out.fronts.push_back(std::move(f));
        }
    }
    // Stores from before the problems table are reported too: without pictures of grids.
    if (!db.has_table("problems")) return out;
    const bool definitions = db.has_column("problems", "definition");
    {
        Reader::Statement s(db, std::string("SELECT id, map, start, goal, ") + (definitions ? "definition" : "NULL") +
                                    " FROM problems WHERE type = 'grid' ORDER BY rowid");
        while (s.step()) {
            GridProblemInfo g;
            g.id = s.text(0);
            g.map = s.text(1);
            const std::string row = "problems row '" + g.id + "'";
            g.start = parse_cell(s.text(2), path, row + ", column start");
            g.goal = parse_cell(s.text(3), path, row + ", column goal");
            // The definition pride bench writes (experiment/campaign.cpp, problem_definition):
            // "grid MAP inflate N start (x,y) goal (x,y) objective ... corner_cutting true ...".
            const std::string definition = s.text(4);
            std::smatch m;
            if (std::regex_search(definition, m, std::regex(R"( inflate (\d{1,9}) )"))) g.inflate = std::stoll(m[1]);
            g.corner_cutting = definition.find(" corner_cutting true") != std::string::npos;
            g.unknown_free = definition.find(" unknown_free true") != std::string::npos;
            out.grids.push_back(g);
        }
    }
    // runs.polyline: a polyline planner's path (store schema 5), NULL for chains and older stores.
    const std::string polyline = db.has_column("runs", "polyline") ? "r.polyline" : "NULL";
    Reader::Statement best(db,
                           "SELECT r.problem, r.algorithm, r.seed, r.best, r.optimum, r.solution, " + polyline +
                               " FROM runs r JOIN problems p ON p.id = r.problem WHERE p.type = 'grid' AND r.feasible "
                               "= 1 AND r.best IS NOT NULL AND coalesce(substr(r.solution, 1, 1), '') <> '{' ORDER BY "
                               "r.problem, r.algorithm, r.best, r.seed");
    while (best.step()) {
        BestPath b;
        b.problem = best.text(0);
        b.algorithm = best.text(1);
        if (!out.best_paths.empty() && out.best_paths.back().problem == b.problem &&
            out.best_paths.back().algorithm == b.algorithm)
            continue;  // a worse run of the same algorithm
        b.seed = sqlite3_column_int64(best.get(), 2);
        b.value = sqlite3_column_double(best.get(), 3);
        if (!best.null(4)) b.optimum = sqlite3_column_double(best.get(), 4);
        const std::string row =
            fmt::format("runs row (problem '{}', algorithm '{}', seed {}), column ", b.problem, b.algorithm, b.seed);
        // The path, a JSON list of [x, y] cells, and a polyline planner's polyline, of [x, y] points.
        for_each_pair(db, best.text(5), path, row + "solution", "cells", true, [&](double x, double y) {
            b.path.push_back({static_cast<int>(x), static_cast<int>(y)});
        });
        if (!best.null(6))
            for_each_pair(db, best.text(6), path, row + "polyline", "points", false, [&](double x, double y) {
                b.polyline.push_back({x, y});
            });
        out.best_paths.push_back(std::move(b));
    }
    return out;
}

}  // namespace pride::html

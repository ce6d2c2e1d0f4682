#pragma once
// The SQLite store of a campaign as run_campaign writes it (internal to engine/campaign.cpp; the
// report code reads it): the campaign
// itself, its problems, and one row per finished run, each committed in a transaction of its own.
#include <sqlite3.h>

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <set>
#include <string>
#include <tuple>

#include "engine/campaign.hpp"
#include "engine/json.hpp"
#include "framework/error.hpp"
#include "problems/continuous/catalog.hpp"

namespace pride::engine {

class Store {
  public:
    explicit Store(const std::string& path) : path_(path) {
        if (sqlite3_open_v2(path.c_str(), &db_, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_FULLMUTEX,
                            nullptr) != SQLITE_OK) {
            const std::string why = db_ ? sqlite3_errmsg(db_) : "out of memory";
            sqlite3_close(db_);
            db_ = nullptr;
            throw InputError(path + ": cannot open the store: " + why);
        }
        sqlite3_busy_timeout(db_, 10000);
        // Never take over another application's database: a store has a campaign table or no table.
        bool foreign = false;
        try {
            sqlite3_stmt* s = prepare(
                "SELECT (SELECT COUNT(*) FROM sqlite_master WHERE type = 'table'), "
                "(SELECT COUNT(*) FROM sqlite_master WHERE type = 'table' AND name = 'campaign')");
            if (sqlite3_step(s) == SQLITE_ROW) foreign = sqlite3_column_int(s, 0) > 0 && sqlite3_column_int(s, 1) == 0;
            sqlite3_finalize(s);
        } catch (...) {  // not a database at all
            sqlite3_close(db_);
            db_ = nullptr;
            throw;
        }
        if (foreign) {
            sqlite3_close(db_);
            db_ = nullptr;
            throw InputError(
                path + ": is not a pride store (an SQLite database with other tables); choose another store file");
        }
        exec("PRAGMA journal_mode=WAL");
        exec("PRAGMA synchronous=NORMAL");
        exec(
            "CREATE TABLE IF NOT EXISTS campaign (id INTEGER PRIMARY KEY CHECK (id = 1), name TEXT NOT NULL, "
            "text TEXT NOT NULL, target REAL)");
        exec(
            "CREATE TABLE IF NOT EXISTS runs (problem TEXT NOT NULL, algorithm TEXT NOT NULL, seed INTEGER NOT NULL, "
            "feasible INTEGER NOT NULL, best REAL, evaluations INTEGER NOT NULL, iterations INTEGER NOT NULL, "
            "wall_ms REAL NOT NULL, optimum REAL, solution TEXT NOT NULL, history TEXT NOT NULL, "
            "history_evaluations TEXT NOT NULL, UNIQUE (problem, algorithm, seed))");
        exec(
            "CREATE TABLE IF NOT EXISTS problems (id TEXT PRIMARY KEY, type TEXT NOT NULL, dim INTEGER NOT NULL, "
            "map TEXT, start TEXT, goal TEXT)");
        // Columns added with the suites (issue 10); a store from before gains them, empty.
        add_column("campaign", "precisions", "TEXT");
        add_column("problems", "function", "TEXT");
        add_column("problems", "instance", "INTEGER NOT NULL DEFAULT 0");
        add_column("problems", "f_opt", "REAL");
        add_column("problems", "suite", "TEXT");
        add_column("problems", "fid", "INTEGER");
        add_column("runs", "target_hits", "TEXT NOT NULL DEFAULT '[]'");
    }
    ~Store() { sqlite3_close(db_); }
    Store(const Store&) = delete;
    Store& operator=(const Store&) = delete;

    /// Records the campaign, or checks that the store holds this very campaign.
    void claim(const Campaign& c) {
        sqlite3_stmt* s = prepare("SELECT name, text FROM campaign WHERE id = 1");
        const int rc = sqlite3_step(s);
        if (rc == SQLITE_ROW) {
            const std::string name = reinterpret_cast<const char*>(sqlite3_column_text(s, 0));
            const std::string text = reinterpret_cast<const char*>(sqlite3_column_text(s, 1));
            sqlite3_finalize(s);
            if (text != c.text)
                throw InputError(path_ + ": holds the results of another campaign ('" + name +
                                 "', or an edited version of this file); choose another store file");
            return;
        }
        sqlite3_finalize(s);
        exec("BEGIN");
        s = prepare("INSERT INTO campaign (id, name, text, target, precisions) VALUES (1, ?, ?, ?, ?)");
        sqlite3_bind_text(s, 1, c.name.c_str(), -1, SQLITE_TRANSIENT);
        sqlite3_bind_text(s, 2, c.text.c_str(), -1, SQLITE_TRANSIENT);
        if (c.target)
            sqlite3_bind_double(s, 3, *c.target);
        else
            sqlite3_bind_null(s, 3);
        const std::string precisions = json_array(coco_precisions());
        sqlite3_bind_text(s, 4, precisions.c_str(), -1, SQLITE_TRANSIENT);
        step_done(s);
        // The problems as resolved here (map paths made absolute), for reports and plots.
        for (const auto& p : c.problems) {
            s = prepare(
                "INSERT INTO problems (id, type, dim, map, start, goal, function, instance, f_opt, suite, fid) "
                "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
            const std::string map = p.map_file.empty() ? "" : std::filesystem::absolute(p.map_file).string();
            const auto* g = std::get_if<GridSpec>(&p.spec);
            const auto* f = std::get_if<ContinuousSpec>(&p.spec);
            const std::string type = g ? "grid" : f ? f->function : p.problem->name();
            const std::string start = g ? fmt::format("{},{}", g->start.x, g->start.y) : "";
            const std::string goal = g ? fmt::format("{},{}", g->goal.x, g->goal.y) : "";
            sqlite3_bind_text(s, 1, p.id.c_str(), -1, SQLITE_TRANSIENT);
            sqlite3_bind_text(s, 2, type.c_str(), -1, SQLITE_TRANSIENT);
            sqlite3_bind_int64(s, 3, g ? 2 : static_cast<std::int64_t>(p.problem->dimension()));  // grids: the plane
            sqlite3_bind_text(s, 4, map.c_str(), -1, SQLITE_TRANSIENT);
            sqlite3_bind_text(s, 5, start.c_str(), -1, SQLITE_TRANSIENT);
            sqlite3_bind_text(s, 6, goal.c_str(), -1, SQLITE_TRANSIENT);
            sqlite3_bind_text(s, 7, type.c_str(), -1, SQLITE_TRANSIENT);
            sqlite3_bind_int64(s, 8, p.problem->instance());
            if (const auto f_opt = p.problem->optimum_value())
                sqlite3_bind_double(s, 9, *f_opt);
            else
                sqlite3_bind_null(s, 9);
            const auto* item = f ? continuous::catalog().find(f->function) : nullptr;
            const std::string suite = item ? item->entry.suite : "";
            if (suite.empty()) {
                sqlite3_bind_null(s, 10);
                sqlite3_bind_null(s, 11);
            } else {
                sqlite3_bind_text(s, 10, suite.c_str(), -1, SQLITE_TRANSIENT);
                sqlite3_bind_int64(s, 11, item->entry.number);
            }
            step_done(s);
        }
        exec("COMMIT");
    }

    std::set<std::tuple<std::string, std::string, std::int64_t>> done() {
        std::set<std::tuple<std::string, std::string, std::int64_t>> keys;
        sqlite3_stmt* s = prepare("SELECT problem, algorithm, seed FROM runs");
        while (sqlite3_step(s) == SQLITE_ROW)
            keys.emplace(reinterpret_cast<const char*>(sqlite3_column_text(s, 0)),
                         reinterpret_cast<const char*>(sqlite3_column_text(s, 1)), sqlite3_column_int64(s, 2));
        sqlite3_finalize(s);
        return keys;
    }

    /// One run, in a transaction of its own: once this returns, a kill cannot lose it.
    void insert(const RunRecord& r) {
        sqlite3_stmt* s = prepare(
            "INSERT INTO runs (problem, algorithm, seed, feasible, best, evaluations, iterations, wall_ms, optimum, "
            "solution, history, history_evaluations, target_hits) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
        sqlite3_bind_text(s, 1, r.problem.c_str(), -1, SQLITE_TRANSIENT);
        sqlite3_bind_text(s, 2, r.algorithm.c_str(), -1, SQLITE_TRANSIENT);
        sqlite3_bind_int64(s, 3, r.seed);
        sqlite3_bind_int(s, 4, r.feasible ? 1 : 0);
        if (std::isfinite(r.best))
            sqlite3_bind_double(s, 5, r.best);
        else
            sqlite3_bind_null(s, 5);
        sqlite3_bind_int64(s, 6, r.evaluations);
        sqlite3_bind_int64(s, 7, r.iterations);
        sqlite3_bind_double(s, 8, r.wall_ms);
        if (r.optimum)
            sqlite3_bind_double(s, 9, *r.optimum);
        else
            sqlite3_bind_null(s, 9);
        sqlite3_bind_text(s, 10, r.solution.c_str(), -1, SQLITE_TRANSIENT);
        sqlite3_bind_text(s, 11, r.history.c_str(), -1, SQLITE_TRANSIENT);
        sqlite3_bind_text(s, 12, r.history_evaluations.c_str(), -1, SQLITE_TRANSIENT);
        sqlite3_bind_text(s, 13, r.target_hits.c_str(), -1, SQLITE_TRANSIENT);
        step_done(s);  // autocommit: the statement is its own transaction
    }

  private:
    void add_column(const std::string& table, const std::string& column, const std::string& type) {
        sqlite3_stmt* s = prepare(("SELECT 1 FROM pragma_table_info('" + table + "') WHERE name = ?").c_str());
        sqlite3_bind_text(s, 1, column.c_str(), -1, SQLITE_TRANSIENT);
        const bool present = sqlite3_step(s) == SQLITE_ROW;
        sqlite3_finalize(s);
        if (!present) exec(("ALTER TABLE " + table + " ADD COLUMN " + column + " " + type).c_str());
    }

    void exec(const char* sql) {
        char* message = nullptr;
        if (sqlite3_exec(db_, sql, nullptr, nullptr, &message) != SQLITE_OK) {
            const std::string why = message ? message : sqlite3_errmsg(db_);
            sqlite3_free(message);
            throw InputError(path_ + ": " + why);
        }
    }
    sqlite3_stmt* prepare(const char* sql) {
        sqlite3_stmt* s = nullptr;
        if (sqlite3_prepare_v2(db_, sql, -1, &s, nullptr) != SQLITE_OK)
            throw InputError(path_ + ": " + sqlite3_errmsg(db_));
        return s;
    }
    void step_done(sqlite3_stmt* s) {
        const int rc = sqlite3_step(s);
        sqlite3_finalize(s);
        if (rc != SQLITE_DONE) throw InputError(path_ + ": " + sqlite3_errmsg(db_));
    }

    std::string path_;
    sqlite3* db_ = nullptr;
};

}  // namespace pride::engine

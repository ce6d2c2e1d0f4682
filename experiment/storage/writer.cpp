#include "experiment/storage/writer.hpp"

#include <signal.h>
#include <sqlite3.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <thread>

#include "experiment/storage/reader.hpp"
#include "experiment/storage/schema.hpp"
#include "framework/error.hpp"

namespace pride::storage {
namespace {

/// This process, as it stands in a store's claims: "PID:START" with START the process's start
/// time (so a later process that reuses the number is not taken for it).
std::string process_token(long pid) {
    std::ifstream f("/proc/" + std::to_string(pid) + "/stat");
    std::string stat((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    std::string start = "0";
    const auto close = stat.rfind(')');  // the command name may hold spaces: count fields after it
    if (close != std::string::npos) {
        std::istringstream rest(stat.substr(close + 2));
        std::string field;
        for (int i = 3; i <= 22 && rest >> field; ++i)
            if (i == 22) start = field;
    }
    return std::to_string(pid) + ":" + start;
}

/// Is the process of a claim's token still running? (A token of an unknown form counts as alive:
/// its runs are never taken over by mistake.)
bool token_alive(const std::string& token) {
    const auto colon = token.find(':');
    if (colon == std::string::npos) return true;
    long pid = 0;
    try {
        pid = std::stol(token.substr(0, colon));
    } catch (...) {
        return true;
    }
    if (pid <= 0) return true;
    if (::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) return false;
    if (!std::filesystem::exists("/proc/self/stat")) return true;  // no /proc: the pid alone decides
    return process_token(pid) == token;
}

}  // namespace

Writer::Writer(const std::string& path) : path_(path), token_(process_token(::getpid())) {
    const bool existed = std::filesystem::exists(path);
    // Before SQLite opens anything: on a device (/dev/null) it would create its journal beside it.
    if (existed && !std::filesystem::is_regular_file(path))
        throw InputError(path + ": cannot be the store: " +
                         (std::filesystem::is_directory(path) ? "it is a folder" : "not a regular file") +
                         "; nothing was changed");
    // A FIFO where SQLite keeps its journal would hang the writer at its first transaction.
    check_store_files(path);
    // A store is checked as pride report checks it (storage/reader.hpp: check_store, the same
    // code) before anything is trusted or written: resuming on a truncated or bit-flipped store
    // would take its damaged rows for stored runs and report success.
    if (existed) {
        try {
            check_store(path);
        } catch (const InputError& e) {
            throw InputError(std::string(e.what()) + "; nothing was run (run the campaign into another store)");
        }
    }
    if (!existed) {  // SQLite's own message would give the errno of its last try, not the reason
        const auto parent = std::filesystem::path(path).parent_path();
        if (::access(parent.empty() ? "." : parent.c_str(), W_OK) != 0 && errno != ENOENT)
            throw InputError(path + ": cannot create the store: " + std::strerror(errno));
    }
    if (sqlite3_open_v2(path.c_str(), &db_, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_FULLMUTEX,
                        nullptr) != SQLITE_OK) {
        const std::string why = db_ ? reason() : "out of memory";
        sqlite3_close(db_);
        db_ = nullptr;
        throw InputError(path + ": cannot " + (existed ? "open" : "create") + " the store: " + why);
    }
    sqlite3_busy_timeout(db_, 30000);  // another pride bench on the same store holds it briefly
    // SQLite opens a file it may not write read-only: refused here, before any work is done.
    if (sqlite3_db_readonly(db_, "main") == 1) {
        const int e = errno;
        sqlite3_close(db_);
        db_ = nullptr;
        throw InputError(path + ": cannot write the store (" +
                         (e == EROFS || e == EACCES || e == EPERM ? std::strerror(e) : "it is read-only") +
                         "); nothing was changed");
    }
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
        throw InputError(path +
                         ": is not a pride store (an SQLite database with other tables); choose another store file");
    }
    if (const int version = user_version(); version > storage::schema_version) {
        sqlite3_close(db_);
        db_ = nullptr;
        throw InputError(
            fmt::format("{}: was written by a newer pride (store schema {}; this pride knows 0 to "
                        "{}); use that pride, or another store file",
                        path, version, storage::schema_version));
    }
    // A new store is made without waiting for the disk (five syncs, 15-30 ms that every
    // campaign paid before its first run): a kill cannot hurt it either way, and a power cut
    // meanwhile would lose a store that holds nothing yet. Runs are then written with
    // synchronous=NORMAL, as before.
    if (!existed) exec("PRAGMA synchronous=OFF");
    journal_wal();
    // The schema in one transaction: two processes opening one new store create it once.
    exec("BEGIN IMMEDIATE");
    try {
        exec(
            "CREATE TABLE IF NOT EXISTS campaign (id INTEGER PRIMARY KEY CHECK (id = 1), name TEXT NOT NULL, "
            "text TEXT NOT NULL, target REAL)");
        exec(
            "CREATE TABLE IF NOT EXISTS runs (problem TEXT NOT NULL, algorithm TEXT NOT NULL, seed INTEGER NOT "
            "NULL, feasible INTEGER NOT NULL, best REAL, evaluations INTEGER NOT NULL, iterations INTEGER NOT "
            "NULL, wall_ms REAL NOT NULL, optimum REAL, solution TEXT NOT NULL, history TEXT NOT NULL, "
            "history_evaluations TEXT NOT NULL, UNIQUE (problem, algorithm, seed))");
        exec(
            "CREATE TABLE IF NOT EXISTS problems (id TEXT PRIMARY KEY, type TEXT NOT NULL, dim INTEGER NOT NULL, "
            "map TEXT, start TEXT, goal TEXT)");
        // The campaign's algorithms: their registered type, and whether they evaluate
        // the objective (whole-map planners such as A* do not), for the equal-evaluation check
        // of reports. Stores from before it have none, and their reports check every algorithm.
        exec(
            "CREATE TABLE IF NOT EXISTS algorithms (id TEXT PRIMARY KEY, type TEXT NOT NULL, evaluates INTEGER NOT "
            "NULL)");
        // The runs a pride bench has taken and not yet stored, so that two processes on one
        // store share the work; the claims of a process that died are taken over.
        exec(
            "CREATE TABLE IF NOT EXISTS claims (problem TEXT NOT NULL, algorithm TEXT NOT NULL, seed INTEGER NOT "
            "NULL, owner TEXT NOT NULL, UNIQUE (problem, algorithm, seed))");
        // Published runs' provenance (published.hpp): the source they were read from, its
        // SHA-256, a citation; stores from before have none.
        exec(
            "CREATE TABLE IF NOT EXISTS published (algorithm TEXT PRIMARY KEY, format TEXT NOT NULL, source TEXT NOT "
            "NULL, sha256 TEXT NOT NULL, citation TEXT NOT NULL)");
        // Columns added with the suites; a store from before gains them, empty.
        add_column("campaign", "precisions", "TEXT");
        add_column("campaign", "target_precision", "REAL");  // [budget] precision
        // What identifies the runs (a campaign grows by seeds, problems and
        // algorithms): the budget, and each problem's and algorithm's definition. NULL in
        // stores from before, which then take only their own campaign file.
        add_column("campaign", "budget", "TEXT");
        add_column("problems", "definition", "TEXT");
        add_column("algorithms", "definition", "TEXT");
        // What each problem is beyond its definition's text (a map edited between an
        // interrupted campaign and its resume): SHA-256 digests of its content, compared on
        // every resume. NULL in stores from before, filled on their next resume.
        add_column("problems", "digest", "TEXT");
        // Written only when it changes: a store that needs nothing is not touched (its bytes stay).
        if (user_version() != storage::schema_version)
            exec(fmt::format("PRAGMA user_version = {}", storage::schema_version).c_str());
        add_column("problems", "function", "TEXT");
        add_column("problems", "instance", "INTEGER NOT NULL DEFAULT 0");
        add_column("problems", "f_opt", "REAL");
        add_column("problems", "suite", "TEXT");
        add_column("problems", "fid", "INTEGER");
        add_column("runs", "target_hits", "TEXT NOT NULL DEFAULT '[]'");
        // What a grid run planned on (one campaign may mix encodings); '' for boxes
        // and for runs stored before it.
        add_column("runs", "encoding", "TEXT NOT NULL DEFAULT ''");
        // COCO's trace of each run (what its .dat and .tdat files hold); '[]' for runs
        // stored before it.
        add_column("runs", "trace_targets", "TEXT NOT NULL DEFAULT '[]'");
        add_column("runs", "trace_evaluations", "TEXT NOT NULL DEFAULT '[]'");
        // The run's evaluation budget and its best values at the CEC reports' checkpoints; NULL and
        // '[]' for runs stored before them.
        add_column("runs", "max_evaluations", "INTEGER");
        add_column("runs", "checkpoints", "TEXT NOT NULL DEFAULT '[]'");
        // Every grid path's metrics, whoever planned it, and a polyline planner's polyline; NULL for
        // other runs and for runs stored before them.
        add_column("runs", "path_metrics", "TEXT");
        // 0 for an algorithm registered as not reproducible (AlgorithmEntry::reproducible):
        // merges and reports of several stores compare its runs by definition, not values.
        add_column("algorithms", "reproducible", "INTEGER NOT NULL DEFAULT 1");
        add_column("runs", "polyline", "TEXT");
        // A constrained problem's run: its best point's violation and its first feasible
        // evaluation; NULL for problems without constraints and for runs stored before.
        add_column("runs", "best_violation", "REAL");
        add_column("runs", "first_feasible", "INTEGER");
        exec("COMMIT");
        exec("PRAGMA synchronous=NORMAL");
    } catch (...) {
        rollback();
        sqlite3_close(db_);
        db_ = nullptr;
        throw;
    }
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0) {
        device_ = st.st_dev;
        inode_ = st.st_ino;
    }
}

Writer::~Writer() {
    if (!db_) return;
    sqlite3_finalize(insert_);
    sqlite3_finalize(unclaim_);
    sqlite3_finalize(claim_);
    sqlite3_finalize(held_);
    try {
        release();
    } catch (...) {  // a store that cannot be written keeps its claims; the next process takes them over
    }
    sqlite3_close(db_);
}

void Writer::claim(const CampaignRows& c) {
    exec("BEGIN IMMEDIATE");
    try {
        sqlite3_stmt* s =
            prepare("SELECT name, text, (SELECT COUNT(*) FROM runs), precisions FROM campaign WHERE id = 1");
        const int rc = sqlite3_step(s);
        if (rc == SQLITE_ROW) {
            const std::string name = reinterpret_cast<const char*>(sqlite3_column_text(s, 0));
            const std::string text = reinterpret_cast<const char*>(sqlite3_column_text(s, 1));
            const std::int64_t runs = sqlite3_column_int64(s, 2);
            const std::optional<std::string> precisions =
                sqlite3_column_type(s, 3) == SQLITE_NULL
                    ? std::nullopt
                    : std::optional<std::string>(reinterpret_cast<const char*>(sqlite3_column_text(s, 3)));
            sqlite3_finalize(s);
            // Every run of a store records hits of the same targets (pride went from COCO's
            // 11 precisions to its 51): new runs cannot join runs that recorded others. A store
            // from before precisions (its runs record none) takes today's.
            if (!precisions) {
                sqlite3_stmt* u = prepare("UPDATE campaign SET precisions = ? WHERE id = 1");
                sqlite3_bind_text(u, 1, c.precisions.c_str(), -1, SQLITE_TRANSIENT);
                step_done(u, "cannot write the store");
            } else if ((runs > 0 || live_claims() > 0) && *precisions != c.precisions)
                throw InputError(path_ + ": its runs record the target precisions " + *precisions +
                                 ", this pride records COCO's 51 (10^2 ... 10^-8); report it as it is, or run the "
                                 "campaign into a new store");
            if (text == c.text) {
                // The same file may name an edited map, and Python's campaigns describe a Grid
                // given in code by its settings alone: the content is compared all the same.
                check_digests(c);
                fill_definitions(c);  // a store from before definitions, resumed with its own file
                exec("COMMIT");
                return;
            }
            if (runs > 0 || live_claims() > 0) {
                grow(c, name);
                exec("COMMIT");
                return;
            }
            exec("DELETE FROM campaign; DELETE FROM problems; DELETE FROM algorithms; DELETE FROM claims");
        } else {
            sqlite3_finalize(s);
            if (rc != SQLITE_DONE) fail("cannot read the store");
        }
        record(c);
        exec("COMMIT");
    } catch (...) {
        rollback();
        throw;
    }
}

std::set<RunKey> Writer::done() {
    std::set<RunKey> keys;
    sqlite3_stmt* s = prepare("SELECT problem, algorithm, seed FROM runs");
    int rc;
    while ((rc = sqlite3_step(s)) == SQLITE_ROW)
        keys.emplace(reinterpret_cast<const char*>(sqlite3_column_text(s, 0)),
                     reinterpret_cast<const char*>(sqlite3_column_text(s, 1)), sqlite3_column_int64(s, 2));
    sqlite3_finalize(s);
    if (rc != SQLITE_DONE) fail("cannot read the store");
    return keys;
}

std::vector<std::size_t> Writer::take(const std::vector<RunKey>& keys, std::size_t& from, std::size_t wanted,
                                      std::vector<std::size_t>& busy) {
    std::vector<std::size_t> taken;
    exec("BEGIN IMMEDIATE");
    try {
        sqlite3_stmt* s = cached(
            claim_,
            "INSERT OR IGNORE INTO claims (problem, algorithm, seed, owner) SELECT ?1, ?2, ?3, ?4 WHERE NOT EXISTS "
            "(SELECT 1 FROM runs WHERE problem = ?1 AND algorithm = ?2 AND seed = ?3)");
        sqlite3_stmt* held =
            cached(held_, "SELECT 1 FROM claims WHERE problem = ?1 AND algorithm = ?2 AND seed = ?3 AND owner <> ?4");
        for (; from < keys.size() && taken.size() < wanted; ++from) {
            const auto& [p, a, seed] = keys[from];
            for (sqlite3_stmt* q : {s, held}) {
                sqlite3_reset(q);
                sqlite3_bind_text(q, 1, p.c_str(), -1, SQLITE_STATIC);  // the keys outlive the steps
                sqlite3_bind_text(q, 2, a.c_str(), -1, SQLITE_STATIC);
                sqlite3_bind_int64(q, 3, seed);
                sqlite3_bind_text(q, 4, token_.c_str(), -1, SQLITE_STATIC);
            }
            const int rc = sqlite3_step(s);
            if (rc != SQLITE_DONE) fail("cannot write the store");
            if (sqlite3_changes(db_) == 1) {
                taken.push_back(from);
            } else if (sqlite3_step(held) == SQLITE_ROW) {
                busy.push_back(from);
            }
        }
        sqlite3_reset(s);
        sqlite3_reset(held);
        exec("COMMIT");
    } catch (...) {
        sqlite3_reset(claim_);  // no statement left running across the rollback
        sqlite3_reset(held_);
        rollback();
        throw;
    }
    return taken;
}

bool Writer::drop_dead_claims() {
    std::vector<std::string> owners;
    sqlite3_stmt* s = prepare("SELECT DISTINCT owner FROM claims");
    while (sqlite3_step(s) == SQLITE_ROW) owners.emplace_back(reinterpret_cast<const char*>(sqlite3_column_text(s, 0)));
    sqlite3_finalize(s);
    bool dropped = false;
    for (const auto& owner : owners) {
        if (owner == token_ || token_alive(owner)) continue;
        s = prepare("DELETE FROM claims WHERE owner = ?");
        sqlite3_bind_text(s, 1, owner.c_str(), -1, SQLITE_TRANSIENT);
        step_done(s, "cannot write the store");
        dropped = true;
    }
    return dropped;
}

std::size_t Writer::insert(const std::vector<RunRecord>& records) {
    if (records.empty()) return 0;
    check_same_file();
    std::size_t added = 0;
    exec("BEGIN IMMEDIATE");
    try {
        for (const RunRecord& r : records) added += insert_one(r);
        exec("COMMIT");
    } catch (...) {
        rollback();
        throw;
    }
    check_same_file();
    return added;
}

void Writer::release() {
    sqlite3_stmt* s = prepare("DELETE FROM claims WHERE owner = ?");
    sqlite3_bind_text(s, 1, token_.c_str(), -1, SQLITE_TRANSIENT);
    step_done(s, "cannot write the store");
}

std::size_t Writer::count() {
    sqlite3_stmt* s = prepare("SELECT COUNT(*) FROM runs");
    const int rc = sqlite3_step(s);
    const std::int64_t n = rc == SQLITE_ROW ? sqlite3_column_int64(s, 0) : 0;
    sqlite3_finalize(s);
    return static_cast<std::size_t>(n);
}

void Writer::check_same_file() const {
    struct stat st {};
    if (inode_ == 0) return;
    if (::stat(path_.c_str(), &st) != 0 || st.st_dev != device_ || st.st_ino != inode_)
        throw InputError(path_ +
                         ": the store was deleted or replaced while pride bench ran; the runs of this call "
                         "went with it (run the same command again to compute them)");
}

std::int64_t Writer::live_claims() {
    drop_dead_claims();
    sqlite3_stmt* s = prepare("SELECT COUNT(*) FROM claims WHERE owner <> ?");
    sqlite3_bind_text(s, 1, token_.c_str(), -1, SQLITE_TRANSIENT);
    const std::int64_t n = sqlite3_step(s) == SQLITE_ROW ? sqlite3_column_int64(s, 0) : 0;
    sqlite3_finalize(s);
    return n;
}

int Writer::user_version() {
    sqlite3_stmt* s = prepare("PRAGMA user_version");
    const int v = sqlite3_step(s) == SQLITE_ROW ? sqlite3_column_int(s, 0) : 0;
    sqlite3_finalize(s);
    return v;
}

void Writer::bind_optional(sqlite3_stmt* s, int i, const std::optional<double>& v) {
    if (v)
        sqlite3_bind_double(s, i, *v);
    else
        sqlite3_bind_null(s, i);
}

sqlite3_stmt* Writer::cached(sqlite3_stmt*& s, const char* sql) {
    if (!s) s = prepare(sql);
    sqlite3_reset(s);
    sqlite3_clear_bindings(s);
    return s;
}

void Writer::step_cached(sqlite3_stmt* s, const char* doing) {
    const int rc = sqlite3_step(s);
    sqlite3_reset(s);
    if (rc != SQLITE_DONE) fail(doing);
}

std::size_t Writer::insert_one(const RunRecord& r) {
    sqlite3_stmt* s = cached(
        insert_,
        "INSERT OR IGNORE INTO runs (problem, algorithm, seed, feasible, best, evaluations, iterations, wall_ms, "
        "optimum, solution, history, history_evaluations, target_hits, encoding, trace_targets, trace_evaluations, "
        "max_evaluations, checkpoints, path_metrics, polyline, best_violation, first_feasible) "
        "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
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
    bind_optional(s, 9, r.optimum);
    // SQLITE_STATIC: the record outlives the step (no copy of the long JSON texts).
    sqlite3_bind_text(s, 10, r.solution.c_str(), -1, SQLITE_STATIC);
    sqlite3_bind_text(s, 11, r.history.c_str(), -1, SQLITE_STATIC);
    sqlite3_bind_text(s, 12, r.history_evaluations.c_str(), -1, SQLITE_STATIC);
    sqlite3_bind_text(s, 13, r.target_hits.c_str(), -1, SQLITE_STATIC);
    sqlite3_bind_text(s, 14, r.encoding.c_str(), -1, SQLITE_STATIC);
    sqlite3_bind_text(s, 15, r.trace_targets.c_str(), -1, SQLITE_STATIC);
    sqlite3_bind_text(s, 16, r.trace_evaluations.c_str(), -1, SQLITE_STATIC);
    if (r.max_evaluations)
        sqlite3_bind_int64(s, 17, *r.max_evaluations);
    else
        sqlite3_bind_null(s, 17);
    sqlite3_bind_text(s, 18, r.checkpoints.c_str(), -1, SQLITE_STATIC);
    for (const auto& [column, text] : {std::pair{19, &r.path_metrics}, std::pair{20, &r.polyline}})
        if (text->empty())
            sqlite3_bind_null(s, column);
        else
            sqlite3_bind_text(s, column, text->c_str(), -1, SQLITE_STATIC);
    bind_optional(s, 21, r.best_violation);
    if (r.first_feasible)
        sqlite3_bind_int64(s, 22, *r.first_feasible);
    else
        sqlite3_bind_null(s, 22);
    step_cached(s, "cannot write the store");
    const std::size_t added = static_cast<std::size_t>(sqlite3_changes(db_));
    s = cached(unclaim_, "DELETE FROM claims WHERE problem = ? AND algorithm = ? AND seed = ?");
    sqlite3_bind_text(s, 1, r.problem.c_str(), -1, SQLITE_STATIC);
    sqlite3_bind_text(s, 2, r.algorithm.c_str(), -1, SQLITE_STATIC);
    sqlite3_bind_int64(s, 3, r.seed);
    step_cached(s, "cannot write the store");
    return added;
}

void Writer::add_column(const std::string& table, const std::string& column, const std::string& type) {
    sqlite3_stmt* s = prepare(("SELECT 1 FROM pragma_table_info('" + table + "') WHERE name = ?").c_str());
    sqlite3_bind_text(s, 1, column.c_str(), -1, SQLITE_TRANSIENT);
    const bool present = sqlite3_step(s) == SQLITE_ROW;
    sqlite3_finalize(s);
    if (!present) exec(("ALTER TABLE " + table + " ADD COLUMN " + column + " " + type).c_str());
}

std::string Writer::reason() const {
    std::string why = sqlite3_errmsg(db_);
    const int e = sqlite3_system_errno(db_);
    const int code = sqlite3_errcode(db_) & 0xff;
    if (e != 0 && (code == SQLITE_IOERR || code == SQLITE_CANTOPEN || code == SQLITE_FULL))
        why += std::string(" (") + std::strerror(e) + ")";
    return why;
}

void Writer::journal_wal() {
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    for (;;) {
        std::string mode;
        sqlite3_stmt* s = nullptr;
        if (sqlite3_prepare_v2(db_, "PRAGMA journal_mode=WAL", -1, &s, nullptr) == SQLITE_OK &&
            sqlite3_step(s) == SQLITE_ROW)
            if (const unsigned char* text = sqlite3_column_text(s, 0)) mode = reinterpret_cast<const char*>(text);
        sqlite3_finalize(s);
        if (mode == "wal") return;
        if (std::chrono::steady_clock::now() > until)
            throw InputError(path_ + ": cannot write the store: it stays in journal mode '" + mode +
                             "' (another process keeps it open)");
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
}

void Writer::exec(const char* sql) {
    char* message = nullptr;
    if (sqlite3_exec(db_, sql, nullptr, nullptr, &message) != SQLITE_OK) {
        sqlite3_free(message);
        fail("cannot write the store");
    }
}

sqlite3_stmt* Writer::prepare(const char* sql) {
    sqlite3_stmt* s = nullptr;
    if (sqlite3_prepare_v2(db_, sql, -1, &s, nullptr) != SQLITE_OK) {
        sqlite3_finalize(s);
        fail("cannot read the store");
    }
    return s;
}

void Writer::step_done(sqlite3_stmt* s, const char* doing) {
    const int rc = sqlite3_step(s);
    sqlite3_finalize(s);
    if (rc != SQLITE_DONE) fail(doing);
}

void Writer::fail(const std::string& doing) const {
    throw InputError(path_ + ": " + doing + ": " + reason());
}

void Writer::rollback() noexcept {
    sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
}

}  // namespace pride::storage

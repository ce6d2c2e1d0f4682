#include "cli/campaign.hpp"

#include <fmt/format.h>
#include <sqlite3.h>
#include <unistd.h>

#include <toml++/toml.h>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <deque>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <mutex>
#include <ostream>
#include <set>
#include <thread>
#include <tuple>

#include "cli/algorithm_factory.hpp"
#include "cli/algorithms.hpp"
#include "cli/grid_commands.hpp"
#include "cli/numbers.hpp"
#include "framework/error.hpp"
#include "framework/params.hpp"
#include "problems/continuous/catalog.hpp"

#ifdef PRIDE_HAVE_MPI
#include <mpi.h>
#endif

namespace pride::cli {
namespace {

// ---------------------------------------------------------------------------------------------
// Reading the campaign file

std::string at(const std::string& file, const toml::node& node) {
    return fmt::format("{}:{}", file, node.source().begin.line);
}

[[noreturn]] void fail(const std::string& where, const std::string& what) {
    throw InputError(where + ": " + what);
}

std::string need_string(const std::string& file, const toml::table& t, std::string_view key, const std::string& where) {
    const toml::node* n = t.get(key);
    if (!n) fail(where, "missing key '" + std::string(key) + "'");
    if (!n->is_string()) fail(at(file, *n), "'" + std::string(key) + "' must be a string");
    return std::string(**n->as_string());
}

std::int64_t need_integer(const std::string& file, const toml::node& n, std::string_view key) {
    if (!n.is_integer()) fail(at(file, n), "'" + std::string(key) + "' must be an integer");
    return **n.as_integer();
}

double need_number(const std::string& file, const toml::node& n, std::string_view key) {
    if (n.is_integer()) return static_cast<double>(**n.as_integer());
    if (!n.is_floating_point()) fail(at(file, n), "'" + std::string(key) + "' must be a number");
    return **n.as_floating_point();
}

/// [x, y] with integers, as "x,y" for the grid's cell parser.
std::string need_cell(const std::string& file, const toml::node& n, std::string_view key) {
    const toml::array* a = n.as_array();
    if (!a || a->size() != 2 || !(*a)[0].is_integer() || !(*a)[1].is_integer())
        fail(at(file, n), "'" + std::string(key) + "' must be [x, y] with two integers");
    return fmt::format("{},{}", **(*a)[0].as_integer(), **(*a)[1].as_integer());
}

ProblemSpec read_problem(const std::string& file, const toml::table& t, const std::filesystem::path& folder) {
    ProblemSpec p;
    p.line = static_cast<int>(t.source().begin.line);
    const std::string where = fmt::format("{}:{}", file, p.line);
    p.id = need_string(file, t, "id", where);
    p.type = need_string(file, t, "type", where);
    const bool grid = p.type == "grid";
    static const std::set<std::string> continuous_keys{"id", "type", "dim"};
    static const std::set<std::string> grid_keys{"id",        "type",     "map",       "start", "goal",
                                                 "objective", "encoding", "connector", "init",  "waypoints",
                                                 "inflate",   "weights",  "lambda"};
    for (auto&& [key, value] : t) {
        const std::string k(key.str());
        if (!(grid ? grid_keys : continuous_keys).count(k))
            fail(at(file, value), "unknown key '" + k + "' in a " + (grid ? "grid" : "continuous") + " [[problem]]");
        if (k == "dim") p.dim = need_integer(file, value, k);
        if (k == "map") {
            if (!value.is_string()) fail(at(file, value), "'map' must be a string");
            // Relative to the campaign file's folder when the file is there, else to the working folder.
            const std::filesystem::path m(std::string(**value.as_string()));
            p.map = (m.is_relative() && std::filesystem::exists(folder / m)) ? (folder / m).string() : m.string();
        }
        if (k == "start") p.start = need_cell(file, value, k);
        if (k == "goal") p.goal = need_cell(file, value, k);
        if (k == "objective") p.objective = need_string(file, t, k, where);
        if (k == "encoding") p.encoding = need_string(file, t, k, where);
        if (k == "connector") p.connector = need_string(file, t, k, where);
        if (k == "init") p.init = need_string(file, t, k, where);
        if (k == "waypoints") p.waypoints = need_integer(file, value, k);
        if (k == "inflate") p.inflate = need_integer(file, value, k);
        if (k == "lambda") p.lambda = need_number(file, value, k);
        if (k == "weights") {
            const toml::array* a = value.as_array();
            if (!a || a->size() != 3) fail(at(file, value), "'weights' must be [w_len, w_turn, w_angle]");
            p.weights = fmt::format("{},{},{}", need_number(file, (*a)[0], k), need_number(file, (*a)[1], k),
                                    need_number(file, (*a)[2], k));
        }
    }
    if (grid) {
        if (p.map.empty()) fail(where, "a grid [[problem]] needs 'map'");
        if (p.start.empty() || p.goal.empty()) fail(where, "a grid [[problem]] needs 'start' and 'goal'");
    } else if (!t.get("dim")) {
        fail(where, "missing key 'dim'");
    }
    return p;
}

AlgorithmSpec read_algorithm(const std::string& file, const toml::table& t) {
    AlgorithmSpec a;
    a.line = static_cast<int>(t.source().begin.line);
    const std::string where = fmt::format("{}:{}", file, a.line);
    a.id = need_string(file, t, "id", where);
    a.type = need_string(file, t, "type", where);
    for (auto&& [key, value] : t) {
        const std::string k(key.str());
        if (k == "id" || k == "type") continue;
        a.params.push_back(fmt::format("{}={}", k, need_number(file, value, k)));
    }
    return a;
}

PathOptions grid_options(const Campaign& c, const ProblemSpec& p, const AlgorithmSpec& a, std::int64_t seed) {
    PathOptions o;
    o.map = p.map;
    o.start = p.start;
    o.goal = p.goal;
    o.algo = a.type;
    o.objective = p.objective;
    o.encoding = p.encoding;
    o.connector = p.connector;
    o.init = p.init;
    o.waypoints = p.waypoints;
    o.inflate = p.inflate;
    o.weights = p.weights;
    o.lambda = p.lambda;
    o.seed = seed;
    o.iters = c.iterations;
    o.evals = c.evaluations;
    o.params = a.params;
    return o;
}

Termination continuous_termination(const Campaign& c) {
    Termination t;
    if (c.evaluations) t = t | max_evaluations(*c.evaluations);
    if (c.iterations) t = t | max_iterations(*c.iterations);
    return t;
}

ParamMap params_of(const AlgorithmSpec& a) {
    ParamMap params;
    for (const auto& s : a.params) params.set_from_string(s);
    return params;
}

std::string json_cells(const grid::Path& path) {
    std::string s = "[";
    for (std::size_t i = 0; i < path.size(); ++i) s += fmt::format("{}[{},{}]", i ? "," : "", path[i].x, path[i].y);
    return s + "]";
}

std::string json_integers(const std::vector<std::int64_t>& v) {
    std::string s = "[";
    for (std::size_t i = 0; i < v.size(); ++i) s += fmt::format("{}{}", i ? ", " : "", v[i]);
    return s + "]";
}

}  // namespace

Campaign read_campaign(const std::string& path) {
    Campaign c;
    c.file = path;
    toml::table root;
    try {
        root = toml::parse_file(path);
    } catch (const toml::parse_error& e) {
        throw InputError(
            fmt::format("{}:{}:{}: {}", path, e.source().begin.line, e.source().begin.column, e.description()));
    }
    {
        std::ifstream in(path, std::ios::binary);
        c.text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    const auto folder = std::filesystem::path(path).parent_path();
    for (auto&& [key, value] : root) {
        const std::string k(key.str());
        if (k == "name") {
            if (!value.is_string()) fail(at(path, value), "'name' must be a string");
            c.name = std::string(**value.as_string());
        } else if (k == "seeds") {
            c.seeds = need_integer(path, value, k);
            if (c.seeds < 1) fail(at(path, value), "'seeds' must be >= 1");
        } else if (k == "budget") {
            const toml::table* b = value.as_table();
            if (!b) fail(at(path, value), "'budget' must be a table");
            for (auto&& [bk, bv] : *b) {
                const std::string kk(bk.str());
                if (kk == "evaluations") {
                    c.evaluations = need_integer(path, bv, kk);
                    if (*c.evaluations < 1) fail(at(path, bv), "'evaluations' must be >= 1");
                } else if (kk == "iterations") {
                    c.iterations = need_integer(path, bv, kk);
                    if (*c.iterations < 0) fail(at(path, bv), "'iterations' must be >= 0");
                } else if (kk == "target") {
                    c.target = need_number(path, bv, kk);
                } else {
                    fail(at(path, bv), "unknown key '" + kk + "' in [budget] (evaluations, iterations, target)");
                }
            }
        } else if (k == "problem" || k == "algorithm") {
            const toml::array* a = value.as_array();
            if (!a || !a->is_array_of_tables()) fail(at(path, value), "'" + k + "' must be [[" + k + "]] tables");
            for (const toml::node& n : *a) {
                if (k == "problem")
                    c.problems.push_back(read_problem(path, *n.as_table(), folder));
                else
                    c.algorithms.push_back(read_algorithm(path, *n.as_table()));
            }
        } else {
            fail(at(path, value), "unknown key '" + k + "' (name, seeds, budget, problem, algorithm)");
        }
    }
    if (c.name.empty()) fail(path, "missing key 'name'");
    if (c.seeds < 1) fail(path, "missing key 'seeds'");
    if (!c.evaluations && !c.iterations) fail(path, "missing [budget] with 'evaluations' or 'iterations'");
    if (c.problems.empty()) fail(path, "no [[problem]]");
    if (c.algorithms.empty()) fail(path, "no [[algorithm]]");
    std::set<std::string> ids;
    for (const auto& p : c.problems)
        if (!ids.insert(p.id).second) fail(fmt::format("{}:{}", path, p.line), "duplicate problem id '" + p.id + "'");
    ids.clear();
    for (const auto& a : c.algorithms)
        if (!ids.insert(a.id).second) fail(fmt::format("{}:{}", path, a.line), "duplicate algorithm id '" + a.id + "'");

    // Build every problem and algorithm once: bad input fails now, not half-way through the runs.
    for (const auto& p : c.problems) {
        const std::string where = fmt::format("{}:{}", path, p.line);
        try {
            if (p.type == "grid") {
                PathOptions o = grid_options(c, p, AlgorithmSpec{"", "astar", {}, 0}, 1);
                plan_path(o);  // checks the map, start, goal and options
            } else {
                continuous::make_problem(p.type, p.dim);
            }
        } catch (const InputError& e) {
            throw InputError(where + ": problem '" + p.id + "': " + e.what());
        }
    }
    for (const auto& a : c.algorithms) {
        const std::string where = fmt::format("{}:{}", path, a.line);
        try {
            const ParamMap params = params_of(a);
            for (const auto& p : c.problems) {
                const bool grid = p.type == "grid";
                if (a.type == "astar" || a.type == "exact") {
                    require(grid, "algorithm '" + a.id + "'",
                            a.type + " works on grid problems only (problem '" + p.id + "')");
                    require(a.params.empty(), "algorithm '" + a.id + "'",
                            a.type + " takes no parameters, got '" +
                                (a.params.empty() ? "" : a.params.front().substr(0, a.params.front().find('='))) + "'");
                } else if (grid && p.encoding == "chain") {
                    with_chain_algorithm(a.type, params, [](const auto&) { return 0; });
                } else {
                    with_algorithm(a.type, params, [](const auto&) { return 0; });
                }
                if (grid) {  // what only a run of this pair would otherwise find out
                    PathOptions o = grid_options(c, p, a, 1);
                    o.oracle = o.objective != "iqga";
                    try {
                        check_path_options(o);
                    } catch (const InputError& e) {
                        throw InputError("problem '" + p.id + "': " + e.what());
                    }
                }
            }
        } catch (const InputError& e) {
            throw InputError(where + ": " + e.what());
        }
    }
    return c;
}

RunRecord run_one(const Campaign& c, const ProblemSpec& p, const AlgorithmSpec& a, std::int64_t seed) {
    RunRecord r;
    r.problem = p.id;
    r.algorithm = a.id;
    r.seed = seed;
    if (p.type == "grid") {
        PathOptions o = grid_options(c, p, a, seed);
        o.oracle = o.objective != "iqga";  // the exact optimum, beside each run, for gaps in reports
        const PathRun run = plan_path(o);
        r.feasible = run.feasible;
        r.best = run.feasible ? run.value : std::numeric_limits<double>::infinity();
        r.evaluations = run.evaluations;
        r.iterations = run.iterations;
        r.wall_ms = run.wall_ms;
        r.optimum = run.optimum;
        r.solution = json_cells(run.path);
        r.history = json_array(run.history);
        r.history_evaluations = json_integers(run.history_evaluations);
        return r;
    }
    const auto problem = continuous::make_problem(p.type, p.dim);
    const auto runner = make_algorithm(a.type, params_of(a));
    const Result result = runner(problem, continuous_termination(c), static_cast<std::uint64_t>(seed));
    r.best = result.best_f;
    r.feasible = std::isfinite(result.best_f);
    r.evaluations = result.evaluations;
    r.iterations = result.iterations;
    r.wall_ms = result.wall_ms;
    r.solution = json_array(result.best_x);
    r.history = json_array(result.history);
    r.history_evaluations = json_integers(result.history_evaluations);
    return r;
}

// ---------------------------------------------------------------------------------------------
// The store

namespace {

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
            throw InputError(path + ": is not a pride store (an SQLite database with other tables); use another --out");
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
                                 "', or an edited version of this file); use another --out");
            return;
        }
        sqlite3_finalize(s);
        exec("BEGIN");
        s = prepare("INSERT INTO campaign (id, name, text, target) VALUES (1, ?, ?, ?)");
        sqlite3_bind_text(s, 1, c.name.c_str(), -1, SQLITE_TRANSIENT);
        sqlite3_bind_text(s, 2, c.text.c_str(), -1, SQLITE_TRANSIENT);
        if (c.target)
            sqlite3_bind_double(s, 3, *c.target);
        else
            sqlite3_bind_null(s, 3);
        step_done(s);
        // The problems as resolved here (map paths made absolute), for reports and plots.
        for (const auto& p : c.problems) {
            s = prepare("INSERT INTO problems (id, type, dim, map, start, goal) VALUES (?, ?, ?, ?, ?, ?)");
            const std::string map = p.map.empty() ? "" : std::filesystem::absolute(p.map).string();
            sqlite3_bind_text(s, 1, p.id.c_str(), -1, SQLITE_TRANSIENT);
            sqlite3_bind_text(s, 2, p.type.c_str(), -1, SQLITE_TRANSIENT);
            sqlite3_bind_int64(s, 3, p.type == "grid" ? 2 : p.dim);  // grids: the plane
            sqlite3_bind_text(s, 4, map.c_str(), -1, SQLITE_TRANSIENT);
            sqlite3_bind_text(s, 5, p.start.c_str(), -1, SQLITE_TRANSIENT);
            sqlite3_bind_text(s, 6, p.goal.c_str(), -1, SQLITE_TRANSIENT);
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
            "solution, history, history_evaluations) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
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
        step_done(s);  // autocommit: the statement is its own transaction
    }

  private:
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

struct Task {
    const ProblemSpec* problem;
    const AlgorithmSpec* algorithm;
    std::int64_t seed;
};

}  // namespace

namespace {

/// Every (problem, algorithm, seed) of the campaign, in a fixed order that every process shares.
std::vector<Task> all_tasks(const Campaign& c) {
    std::vector<Task> tasks;
    for (const auto& p : c.problems)
        for (const auto& a : c.algorithms)
            for (std::int64_t seed = 1; seed <= c.seeds; ++seed) tasks.push_back({&p, &a, seed});
    return tasks;
}

std::string default_store(const BenchOptions& o) {
    return o.out.empty() ? std::filesystem::path(o.config).replace_extension(".sqlite").string() : o.out;
}

#ifdef PRIDE_HAVE_MPI
// Runs spread over MPI ranks: rank 0 owns the store and hands out task numbers; the other ranks
// run them and send the records back. Values equal those of a threaded run: a run depends only
// on its task.
constexpr int kTagResult = 1, kTagTask = 2;
constexpr char kSep = '\x1f';

std::string serialise(const RunRecord& r) {
    return fmt::format("{1}{0}{2}{0}{3}{0}{4}{0}{5:.17g}{0}{6}{0}{7}{0}{8:.17g}{0}{9}{0}{10}{0}{11}{0}{12}", kSep,
                       r.problem, r.algorithm, r.seed, r.feasible ? 1 : 0, r.best, r.evaluations, r.iterations,
                       r.wall_ms, r.optimum ? fmt::format("{:.17g}", *r.optimum) : "", r.solution, r.history,
                       r.history_evaluations);
}

RunRecord deserialise(const std::string& text) {
    std::vector<std::string> f;
    for (std::size_t start = 0;;) {
        const std::size_t end = text.find(kSep, start);
        f.push_back(text.substr(start, end == std::string::npos ? std::string::npos : end - start));
        if (end == std::string::npos) break;
        start = end + 1;
    }
    if (f.size() != 12) throw std::runtime_error("MPI: a malformed run record");
    RunRecord r;
    r.problem = f[0];
    r.algorithm = f[1];
    r.seed = std::stoll(f[2]);
    r.feasible = f[3] == "1";
    r.best = std::stod(f[4]);
    r.evaluations = std::stoll(f[5]);
    r.iterations = std::stoll(f[6]);
    r.wall_ms = std::stod(f[7]);
    if (!f[8].empty()) r.optimum = std::stod(f[8]);
    r.solution = f[9];
    r.history = f[10];
    r.history_evaluations = f[11];
    return r;
}

int bench_mpi(const BenchOptions& o, std::ostream& out, const Campaign& c, int rank, int size) {
    const std::vector<Task> tasks = all_tasks(c);
    if (rank != 0) {
        std::string payload;  // empty: "ready"; "!..." a failure; else a record
        for (;;) {
            MPI_Send(payload.data(), static_cast<int>(payload.size()), MPI_CHAR, 0, kTagResult, MPI_COMM_WORLD);
            long long index = -1;
            MPI_Recv(&index, 1, MPI_LONG_LONG, 0, kTagTask, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            if (index < 0) return 0;
            try {
                const Task& t = tasks[static_cast<std::size_t>(index)];
                payload = serialise(run_one(c, *t.problem, *t.algorithm, t.seed));
            } catch (const std::exception& e) {
                payload = std::string("!") + e.what();
            }
        }
    }
    std::exception_ptr failure;
    std::vector<long long> pending;
    std::size_t already = 0, stored = 0;
    std::optional<Store> store;
    const std::string store_path = default_store(o);
    try {
        store.emplace(store_path);
        store->claim(c);
        const auto done = store->done();
        already = done.size();
        for (std::size_t i = tasks.size(); i-- > 0;)
            if (!done.count({tasks[i].problem->id, tasks[i].algorithm->id, tasks[i].seed}))
                pending.push_back(static_cast<long long>(i));  // taken from the back: in task order
    } catch (...) {
        failure = std::current_exception();
    }
    for (int active = size - 1; active > 0;) {
        MPI_Status status;
        MPI_Probe(MPI_ANY_SOURCE, kTagResult, MPI_COMM_WORLD, &status);
        int length = 0;
        MPI_Get_count(&status, MPI_CHAR, &length);
        std::string payload(static_cast<std::size_t>(length), '\0');
        MPI_Recv(payload.data(), length, MPI_CHAR, status.MPI_SOURCE, kTagResult, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        if (!payload.empty() && !failure) {
            try {
                if (payload.front() == '!') throw InputError(payload.substr(1));
                store->insert(deserialise(payload));
                ++stored;
            } catch (...) {
                failure = std::current_exception();
            }
        }
        long long next = -1;
        if (!failure && !pending.empty()) {
            next = pending.back();
            pending.pop_back();
        }
        MPI_Send(&next, 1, MPI_LONG_LONG, status.MPI_SOURCE, kTagTask, MPI_COMM_WORLD);
        if (next < 0) --active;
    }
    if (failure) std::rethrow_exception(failure);
    out << fmt::format("{}: {} runs stored in {} ({} were there already, {} in all; {} MPI ranks)\n", c.name, stored,
                       store_path, already, tasks.size(), size);
    return 0;
}
#endif

}  // namespace

/// The number of processes mpirun (Open MPI, or a PMI launcher) started, or 1 outside mpirun.
int launched_ranks() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"})
        if (const char* v = std::getenv(name)) return std::max(1, std::atoi(v));
    return 1;
}

int bench_command(const BenchOptions& o, std::ostream& out) {
#ifdef PRIDE_HAVE_MPI
    if (launched_ranks() > 1) {  // MPI only under mpirun: a plain run needs no MPI runtime
        int initialised = 0;
        MPI_Initialized(&initialised);
        if (!initialised) MPI_Init(nullptr, nullptr);
        struct Finalise {
            ~Finalise() {
                int finalised = 0;
                MPI_Finalized(&finalised);
                if (!finalised) MPI_Finalize();
            }
        } finalise;
        int rank = 0, size = 1;
        MPI_Comm_rank(MPI_COMM_WORLD, &rank);
        MPI_Comm_size(MPI_COMM_WORLD, &size);
        if (size > 1) {
            const Campaign c = read_campaign(o.config);  // every rank reads and checks it: the same verdict
            return bench_mpi(o, out, c, rank, size);
        }
    }
#else
    require(launched_ranks() == 1, "pride bench",
            "this pride was built without MPI (configure with -DPRIDE_MPI=ON); under mpirun every rank would "
            "run the whole campaign");
#endif
    const Campaign c = read_campaign(o.config);
    const std::string store_path = default_store(o);
    const std::int64_t jobs = o.jobs.value_or(std::max(1u, std::thread::hardware_concurrency()));
    require(jobs >= 1 && jobs <= 1024, "--jobs", "must be in [1, 1024], got " + std::to_string(jobs));
    Store store(store_path);
    store.claim(c);
    const auto done = store.done();

    std::vector<Task> tasks = all_tasks(c);
    const std::size_t total = tasks.size();
    std::erase_if(tasks, [&](const Task& t) { return done.count({t.problem->id, t.algorithm->id, t.seed}) != 0; });

    std::mutex mutex;
    std::condition_variable ready;
    std::deque<RunRecord> finished;
    std::exception_ptr failure;
    std::atomic<std::size_t> next{0};
    std::atomic<bool> stop{false};
    auto worker = [&] {
        for (std::size_t i; !stop && (i = next++) < tasks.size();) {
            try {
                RunRecord r = run_one(c, *tasks[i].problem, *tasks[i].algorithm, tasks[i].seed);
                const std::lock_guard lock(mutex);
                finished.push_back(std::move(r));
            } catch (...) {
                const std::lock_guard lock(mutex);
                if (!failure) failure = std::current_exception();
                stop = true;
            }
            ready.notify_one();
        }
    };
    std::vector<std::thread> pool;
    for (std::int64_t j = 0; j < std::min<std::int64_t>(jobs, static_cast<std::int64_t>(tasks.size())); ++j)
        pool.emplace_back(worker);

    const bool show_progress = isatty(STDERR_FILENO) != 0;
    const auto start = std::chrono::steady_clock::now();
    std::size_t stored = 0;
    try {
        while (stored < tasks.size()) {
            std::unique_lock lock(mutex);
            ready.wait(lock, [&] { return !finished.empty() || failure; });
            if (failure && finished.empty()) break;
            RunRecord r = std::move(finished.front());
            finished.pop_front();
            lock.unlock();
            store.insert(r);  // the main thread alone writes: one transaction per run
            ++stored;
            if (show_progress) {
                const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                const double left = elapsed / static_cast<double>(stored) * static_cast<double>(tasks.size() - stored);
                fmt::print(stderr, "\r{}/{} runs, {:.0f} s elapsed, about {:.0f} s left   ", done.size() + stored,
                           total, elapsed, left);
            }
        }
    } catch (...) {
        stop = true;
        for (auto& t : pool) t.join();
        throw;
    }
    stop = true;
    for (auto& t : pool) t.join();
    if (show_progress) fmt::print(stderr, "\n");
    if (failure) std::rethrow_exception(failure);
    out << fmt::format("{}: {} runs stored in {} ({} were there already, {} in all)\n", c.name, stored, store_path,
                       done.size(), total);
    return 0;
}

}  // namespace pride::cli

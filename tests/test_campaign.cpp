// Tests of `pride bench` (docs/cli.md, cli/campaign.hpp) through the real executable: every
// campaign-file error (exit 2, one line naming the file, the line and the key, no store created);
// --jobs 1 and --jobs 2 storing the same values; resuming after a real SIGKILL with no run lost or
// run twice; re-running a finished campaign; refusing a store made from another campaign file. The
// stores are read here with SQLite's own C API, read-only.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sqlite3.h>
#include <sys/wait.h>
#include <unistd.h>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <tuple>
#include <utility>
#include <vector>

#include "json_reader.hpp"
#include "tests/test_support.hpp"

extern char** environ;

namespace {

namespace fs = std::filesystem;
using pride::test::check_input_error;
using pride::test::json_numbers;
using pride::test::slurp;
using pride::test::TempDir;
using namespace std::chrono_literals;
using pride::test::JsonValue;
using pride::test::parse_json;
using Clock = std::chrono::steady_clock;

// ---------------------------------------------------------------------------------------------
// Files and processes

fs::path bundled_map() {
    return fs::path(PRIDE_SOURCE_DIR) / "examples" / "maps" / "wan2022-10x10.map";
}
fs::path bundled_campaigns() {
    return fs::path(PRIDE_SOURCE_DIR) / "examples" / "campaigns";
}

/// `pride ARGS...` started with posix_spawn (no shell), stdin from /dev/null, stdout and stderr to
/// files. The destructor kills and reaps a child still running, so a failed check never leaves one.
class Child {
  public:
    Child(const std::vector<std::string>& args, const std::string& out, const std::string& err,
          const std::string& cwd = "") {
        std::vector<std::string> argv_strings{PRIDE_EXE};
        argv_strings.insert(argv_strings.end(), args.begin(), args.end());
        std::vector<char*> argv;
        for (auto& s : argv_strings) argv.push_back(s.data());
        argv.push_back(nullptr);
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
        posix_spawn_file_actions_addopen(&actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        posix_spawn_file_actions_addopen(&actions, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (!cwd.empty()) posix_spawn_file_actions_addchdir_np(&actions, cwd.c_str());
        const int rc = posix_spawn(&pid_, PRIDE_EXE, &actions, nullptr, argv.data(), environ);
        posix_spawn_file_actions_destroy(&actions);
        if (rc != 0) throw std::runtime_error("posix_spawn failed");
    }
    ~Child() {
        if (running()) kill_now();
    }
    Child(const Child&) = delete;
    Child& operator=(const Child&) = delete;

    /// Has it not exited yet? (reaps it when it has)
    bool running() {
        if (reaped_) return false;
        int status = 0;
        const pid_t r = waitpid(pid_, &status, WNOHANG);
        if (r == 0) return true;
        reaped_ = true;
        status_ = r == pid_ ? status : -1;
        return false;
    }
    /// SIGKILL, then reap.
    void kill_now() {
        if (reaped_) return;
        ::kill(pid_, SIGKILL);
        int status = 0;
        while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
        }
        reaped_ = true;
        status_ = status;
    }
    void send(int signal) { ::kill(pid_, signal); }
    /// Waits for the child to exit by itself; kills it after `limit` and returns false.
    bool wait_for(Clock::duration limit) {
        const auto deadline = Clock::now() + limit;
        while (running()) {
            if (Clock::now() > deadline) {
                kill_now();
                return false;
            }
            std::this_thread::sleep_for(2ms);
        }
        return true;
    }
    /// The exit status, or -1 when it did not exit normally.
    int exit_status() const { return reaped_ && WIFEXITED(status_) ? WEXITSTATUS(status_) : -1; }
    bool killed_by_sigkill() const { return reaped_ && WIFSIGNALED(status_) && WTERMSIG(status_) == SIGKILL; }

  private:
    pid_t pid_ = -1;
    bool reaped_ = false;
    int status_ = 0;
};

struct Outcome {
    int status = -1;
    std::string out, err;
};

/// Runs `pride ARGS...` to its end, within a generous bound (a hang is a failure, never a hang).
Outcome run(const std::vector<std::string>& args, Clock::duration limit = 120s, const std::string& cwd = "") {
    const TempDir io;
    Child child(args, io.file("out"), io.file("err"), cwd);
    const bool finished = child.wait_for(limit);
    Outcome o;
    o.status = child.exit_status();
    o.out = slurp(io.file("out"));
    o.err = slurp(io.file("err"));
    if (!finished) FAIL("pride did not finish within the time limit; stderr: " << o.err);
    return o;
}

std::string replace(std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    if (at == std::string::npos) throw std::logic_error("test bug: '" + from + "' is not in the text");
    return text.replace(at, from.size(), to);
}

std::string join(const std::vector<std::string>& args) {
    std::string s = "pride";
    for (const auto& a : args) s += " " + a;
    return s;
}

// ---------------------------------------------------------------------------------------------
// Reading the stores (read-only)

/// A connection that never writes. `live`: read-only, for a store that pride may be writing or was
/// killed writing (it leaves the journal as it finds it; note that a read-only connection creates
/// the -wal and -shm files when they are missing, and leaves them). Otherwise opened read-write
/// (never created) on a store that pride has closed: closing removes the empty journal again, so the
/// folder's listing stays what pride left.
class Db {
  public:
    /// ok() is false when the file is not there or cannot be opened.
    explicit Db(const std::string& path, bool live = false) {
        const int flags = live ? SQLITE_OPEN_READONLY : SQLITE_OPEN_READWRITE;
        if (sqlite3_open_v2(path.c_str(), &db_, flags, nullptr) != SQLITE_OK) {
            sqlite3_close(db_);
            db_ = nullptr;
            return;
        }
        sqlite3_busy_timeout(db_, 5000);
    }
    ~Db() { sqlite3_close(db_); }
    Db(const Db&) = delete;
    Db& operator=(const Db&) = delete;
    bool ok() const { return db_ != nullptr; }

    /// Every row of `sql`, each value as text tagged by its type ("i:", "r:" with 17 digits, "t:",
    /// "null"); nullopt when the query fails (no table yet, say).
    std::optional<std::vector<std::vector<std::string>>> query(const std::string& sql) {
        if (!db_) return std::nullopt;
        sqlite3_stmt* s = nullptr;
        if (sqlite3_prepare_v2(db_, sql.c_str(), -1, &s, nullptr) != SQLITE_OK) {
            sqlite3_finalize(s);
            return std::nullopt;
        }
        std::vector<std::vector<std::string>> rows;
        int rc;
        while ((rc = sqlite3_step(s)) == SQLITE_ROW) {
            std::vector<std::string> row;
            for (int i = 0; i < sqlite3_column_count(s); ++i) {
                switch (sqlite3_column_type(s, i)) {
                    case SQLITE_INTEGER:
                        row.push_back("i:" + std::to_string(sqlite3_column_int64(s, i)));
                        break;
                    case SQLITE_FLOAT: {
                        char buffer[64];
                        std::snprintf(buffer, sizeof buffer, "r:%.17g", sqlite3_column_double(s, i));
                        row.emplace_back(buffer);
                        break;
                    }
                    case SQLITE_NULL:
                        row.emplace_back("null");
                        break;
                    default:
                        row.push_back("t:" + std::string(reinterpret_cast<const char*>(sqlite3_column_text(s, i))));
                }
            }
            rows.push_back(std::move(row));
        }
        sqlite3_finalize(s);
        if (rc != SQLITE_DONE) return std::nullopt;
        return rows;
    }

  private:
    sqlite3* db_ = nullptr;
};

/// The number of stored runs, or -1 while the store or its table does not exist yet.
long long count_runs(const std::string& store) {
    if (!fs::exists(store)) return -1;
    Db db(store, true);
    const auto rows = db.query("SELECT count(*) FROM runs");
    if (!rows || rows->size() != 1) return -1;
    return std::stoll((*rows)[0][0].substr(2));
}

const char* const kColumnsButWall =
    "problem, algorithm, seed, feasible, best, evaluations, iterations, optimum, solution, history, "
    "history_evaluations";

/// Every stored run, ordered by key: every column but wall_ms (or all of them).
std::vector<std::vector<std::string>> runs_of(const std::string& store, bool with_wall_ms = false) {
    Db db(store);
    REQUIRE(db.ok());
    const std::string columns = with_wall_ms ? std::string(kColumnsButWall) + ", wall_ms" : kColumnsButWall;
    const auto rows = db.query("SELECT " + columns + " FROM runs ORDER BY problem, algorithm, seed");
    REQUIRE(rows);
    return *rows;
}

void check_same_runs(const std::vector<std::vector<std::string>>& a, const std::vector<std::vector<std::string>>& b) {
    REQUIRE(a.size() == b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        INFO("row " << i);
        CHECK(a[i] == b[i]);
    }
}

/// The distinct (problem, algorithm, seed) keys stored, to be compared with the row count.
std::size_t distinct_keys(const std::string& store, bool live = false) {
    Db db(store, live);
    const auto rows = db.query("SELECT DISTINCT problem, algorithm, seed FROM runs");
    REQUIRE(rows);
    return rows->size();
}

std::string text_of(const std::string& tagged) {
    REQUIRE(tagged.rfind("t:", 0) == 0);
    return tagged.substr(2);
}
double real_of(const std::string& tagged) {
    REQUIRE((tagged.rfind("r:", 0) == 0 || tagged.rfind("i:", 0) == 0));
    return std::stod(tagged.substr(2));
}
long long integer_of(const std::string& tagged) {
    REQUIRE(tagged.rfind("i:", 0) == 0);
    return std::stoll(tagged.substr(2));
}

// ---------------------------------------------------------------------------------------------
// The grid, read and solved here independently of the library (docs/grid.md)

struct Cell {
    int x, y;
    bool operator==(const Cell&) const = default;
};

struct Map {
    int width = 0, height = 0;
    std::vector<std::string> rows;
    bool free(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height && rows[y][x] == '.'; }
};

Map read_movingai(const fs::path& file) {
    std::ifstream in(file);
    REQUIRE(in);
    Map m;
    std::string word;
    while (in >> word && word != "map") {
        if (word == "height") in >> m.height;
        if (word == "width") in >> m.width;
    }
    std::string line;
    std::getline(in, line);
    for (int y = 0; y < m.height; ++y) {
        REQUIRE(std::getline(in, line));
        REQUIRE(static_cast<int>(line.size()) >= m.width);
        m.rows.push_back(line.substr(0, static_cast<std::size_t>(m.width)));
    }
    return m;
}

/// A legal 8-connected step without corner cutting.
bool legal_step(const Map& m, Cell a, Cell b) {
    const int dx = b.x - a.x, dy = b.y - a.y;
    if (std::abs(dx) > 1 || std::abs(dy) > 1 || (dx == 0 && dy == 0) || !m.free(b.x, b.y)) return false;
    return dx == 0 || dy == 0 || (m.free(a.x + dx, a.y) && m.free(a.x, a.y + dy));
}

/// Shortest path cost from start to goal by Dijkstra, steps costing `straight` and `diagonal`.
double shortest(const Map& m, Cell start, Cell goal, double straight, double diagonal) {
    const double inf = std::numeric_limits<double>::infinity();
    std::vector<double> dist(static_cast<std::size_t>(m.width * m.height), inf);
    std::vector<bool> settled(dist.size(), false);
    auto index = [&](Cell c) { return static_cast<std::size_t>(c.y * m.width + c.x); };
    dist[index(start)] = 0.0;
    for (;;) {  // O(V^2): the maps here are tiny
        std::size_t best = dist.size();
        for (std::size_t i = 0; i < dist.size(); ++i)
            if (!settled[i] && dist[i] < inf && (best == dist.size() || dist[i] < dist[best])) best = i;
        if (best == dist.size()) return inf;
        settled[best] = true;
        const Cell c{static_cast<int>(best) % m.width, static_cast<int>(best) / m.width};
        if (c == goal) return dist[best];
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const Cell n{c.x + dx, c.y + dy};
                if (!legal_step(m, c, n)) continue;
                const double d = dist[best] + (dx != 0 && dy != 0 ? diagonal : straight);
                if (d < dist[index(n)]) dist[index(n)] = d;
            }
    }
}

std::vector<Cell> path_of(const std::string& json) {
    const JsonValue v = parse_json(json);
    REQUIRE(v.kind == JsonValue::Kind::array);
    std::vector<Cell> path;
    for (const auto& item : v.items) {
        const auto xy = json_numbers(item);
        REQUIRE(xy.size() == 2);
        path.push_back({static_cast<int>(xy[0]), static_cast<int>(xy[1])});
    }
    return path;
}

// ---------------------------------------------------------------------------------------------
// Campaign files

// Line numbers matter: the error tests name them.
const std::string kContinuous =
    "name = \"e\"\n"       // 1
    "seeds = 2\n"          // 2
    "[budget]\n"           // 3
    "evaluations = 100\n"  // 4
    "[[problem]]\n"        // 5
    "id = \"s\"\n"         // 6
    "type = \"sphere\"\n"  // 7
    "dim = 2\n"            // 8
    "[[algorithm]]\n"      // 9
    "id = \"p\"\n"         // 10
    "type = \"pso\"\n";    // 11

/// `text` with every @MAP@ replaced by the bundled map's path.
std::string with_map(std::string text) {
    const std::string map = bundled_map().string();
    for (std::size_t at; (at = text.find("@MAP@")) != std::string::npos;) text.replace(at, 5, map);
    return text;
}

std::string grid_base() {
    return with_map(
        "name = \"g\"\n"     // 1
        "seeds = 1\n"        // 2
        "[budget]\n"         // 3
        "iterations = 5\n"   // 4
        "[[problem]]\n"      // 5
        "id = \"g1\"\n"      // 6
        "type = \"grid\"\n"  // 7
        "map = '@MAP@'\n"    // 8
        "start = [0, 0]\n"   // 9
        "goal = [9, 9]\n"    // 10
        "[[algorithm]]\n"    // 11
        "id = \"a\"\n"       // 12
        "type = \"ga\"\n");  // 13
}

/// `pride bench FILE [extra]` on `text` fails with one line naming each of `words` (FILE stands for
/// the campaign file's path), and leaves the folder as it was: no store, no journal.
void expect_campaign_error(const std::string& text, std::vector<std::string> words,
                           const std::vector<std::string>& extra = {}) {
    const TempDir dir;
    const std::string file = dir.write("c.toml", text);
    std::vector<std::string> args{"bench", file};
    args.insert(args.end(), extra.begin(), extra.end());
    for (auto& w : words)
        if (w.rfind("FILE", 0) == 0) w = file + w.substr(4);
    INFO(join(args));
    INFO("campaign file:\n" << text);
    const Outcome r = run(args, 120s, dir.path().string());
    check_input_error(r, words);
    CHECK(dir.entries() == std::vector<std::string>{"c.toml"});
}

// A continuous campaign: 2 problems x 4 algorithms (NLopt's SBPLX and CRS2 among them) x 3 seeds.
const std::string kSmallContinuous =
    "# a small continuous campaign\n"
    "name = \"small continuous\"\n"
    "seeds = 3\n"
    "[budget]\n"
    "evaluations = 2000\n"
    "[[problem]]\n"
    "id = \"sphere-4\"\n"
    "type = \"sphere\"\n"
    "dim = 4\n"
    "[[problem]]\n"
    "id = \"rastrigin-3\"\n"
    "type = \"shifted-rastrigin\"\n"
    "dim = 3\n"
    "[[algorithm]]\n"
    "id = \"pso\"\n"
    "type = \"pso\"\n"
    "pop = 12\n"
    "[[algorithm]]\n"
    "id = \"ga\"\n"
    "type = \"ga\"\n"
    "pop = 12\n"
    "[[algorithm]]\n"
    "id = \"sbplx\"\n"
    "type = \"nlopt:LN_SBPLX\"\n"
    "[[algorithm]]\n"
    "id = \"crs2\"\n"
    "type = \"nlopt:GN_CRS2_LM\"\n";
constexpr std::size_t kSmallContinuousRuns = 2 * 4 * 3;

// A grid campaign on the bundled 10x10 map: the line encoding under `cells`, the chain encoding
// under `length`; two GAs and the exact optimum; 3 seeds.
std::string small_grid() {
    return with_map(
        "name = \"small grid\"\n"
        "seeds = 3\n"
        "[budget]\n"
        "iterations = 15\n"
        "[[problem]]\n"
        "id = \"line-cells\"\n"
        "type = \"grid\"\n"
        "map = '@MAP@'\n"
        "start = [0, 0]\n"
        "goal = [9, 9]\n"
        "objective = \"cells\"\n"
        "encoding = \"line\"\n"
        "[[problem]]\n"
        "id = \"chain-length\"\n"
        "type = \"grid\"\n"
        "map = '@MAP@'\n"
        "start = [0, 9]\n"
        "goal = [9, 0]\n"
        "objective = \"length\"\n"
        "encoding = \"chain\"\n"
        "[[algorithm]]\n"
        "id = \"ga\"\n"
        "type = \"ga\"\n"
        "pop = 10\n"
        "[[algorithm]]\n"
        "id = \"ga-plus\"\n"
        "type = \"ga-plus\"\n"
        "pop = 10\n"
        "[[algorithm]]\n"
        "id = \"exact\"\n"
        "type = \"exact\"\n");
}
constexpr std::size_t kSmallGridRuns = 2 * 3 * 3;

// Big enough to take about a second: 2 problems x 3 algorithms x 30 seeds = 180 runs.
const std::string kResume =
    "name = \"resume\"\n"
    "seeds = 30\n"
    "[budget]\n"
    "evaluations = 40000\n"
    "[[problem]]\n"
    "id = \"sphere-10\"\n"
    "type = \"sphere\"\n"
    "dim = 10\n"
    "[[problem]]\n"
    "id = \"rastrigin-10\"\n"
    "type = \"shifted-rastrigin\"\n"
    "dim = 10\n"
    "[[algorithm]]\n"
    "id = \"pso\"\n"
    "type = \"pso\"\n"
    "pop = 20\n"
    "[[algorithm]]\n"
    "id = \"ga\"\n"
    "type = \"ga\"\n"
    "pop = 20\n"
    "[[algorithm]]\n"
    "id = \"sbplx\"\n"
    "type = \"nlopt:LN_SBPLX\"\n";
constexpr long long kResumeRuns = 2 * 3 * 30;

/// Runs a campaign to its end; checks the summary line and returns it.
std::string bench_ok(const std::vector<std::string>& args, const std::string& cwd = "") {
    INFO(join(args));
    const Outcome r = run(args, 120s, cwd);
    INFO("stderr: " << r.err);
    REQUIRE(r.status == 0);
    CHECK(r.err.empty());
    CHECK(std::count(r.out.begin(), r.out.end(), '\n') == 1);
    return r.out;
}

/// "N runs stored in STORE (K were there already, T in all)".
void check_summary(const std::string& out, long long stored, long long there, long long total,
                   const std::string& store) {
    INFO("stdout: " << out);
    CHECK(out.find(": " + std::to_string(stored) + " runs stored in " + store + " (") != std::string::npos);
    CHECK(out.find("(" + std::to_string(there) + " were there already, " + std::to_string(total) + " in all)") !=
          std::string::npos);
}

/// Starts `pride bench` into `store`, waits until at least `at_least` runs are stored, kills it with
/// SIGKILL; returns the number of runs the killed store holds. The child must still be running
/// when the threshold is reached (the campaign is sized for that), and everything is bounded.
long long bench_and_kill(const std::string& config, const std::string& store, long long at_least, const TempDir& io) {
    Child child({"bench", config, "--jobs", "2", "--out", store}, io.file("kill-out"), io.file("kill-err"));
    const auto deadline = Clock::now() + 120s;
    long long seen = -1;
    while ((seen = count_runs(store)) < at_least) {
        if (!child.running()) {
            INFO("stderr: " << slurp(io.file("kill-err")));
            FAIL("pride bench ended (status " << child.exit_status() << ") before " << at_least << " runs were stored; "
                                              << seen << " were");
        }
        if (Clock::now() > deadline) FAIL("no " << at_least << " runs stored within 120 s; " << seen << " were");
        std::this_thread::sleep_for(1ms);
    }
    child.kill_now();
    CHECK(child.killed_by_sigkill());
    const long long left = count_runs(store);
    INFO("killed after " << seen << " runs were seen; the store holds " << left);
    CHECK(left >= at_least);
    REQUIRE(left < kResumeRuns);  // killed half-way: the rest is for the resumed run
    CHECK(static_cast<long long>(distinct_keys(store, true)) == left);
    return left;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// 1. Errors in the campaign file

TEST_CASE("bench: the base campaign files of the error tests are valid", "[cli][bench]") {
    // Guards the error tests below: each differs from one of these by the one mistake it checks.
    for (const auto& text : {kContinuous, grid_base()}) {
        const TempDir dir;
        const std::string file = dir.write("c.toml", text);
        bench_ok({"bench", file, "--jobs", "1"}, dir.path().string());
        CHECK(count_runs(dir.file("c.sqlite")) >= 1);
    }
}

TEST_CASE("bench: TOML syntax errors name the file, line and column", "[cli][bench][errors]") {
    expect_campaign_error(replace(kContinuous, "seeds = 2", "seeds = = 2"), {"FILE:2:9:"});
    expect_campaign_error(replace(kContinuous, "type = \"pso\"\n", "type = \"pso\n"), {"FILE:11:"});
    expect_campaign_error(replace(kContinuous, "seeds = 2\n", "seeds = 2\nseeds = 3\n"), {"FILE:3:"});
}

TEST_CASE("bench: unknown keys name the file, line and key", "[cli][bench][errors]") {
    expect_campaign_error(replace(kContinuous, "seeds = 2\n", "seeds = 2\ncolour = \"red\"\n"),
                          {"FILE:3:", "'colour'"});
    expect_campaign_error(replace(kContinuous, "evaluations = 100\n", "evaluations = 100\nevals = 5\n"),
                          {"FILE:5:", "'evals'", "budget"});
    expect_campaign_error(replace(kContinuous, "dim = 2\n", "dim = 2\nstart = [0, 0]\n"),
                          {"FILE:9:", "'start'", "continuous"});
    expect_campaign_error(replace(grid_base(), "goal = [9, 9]\n", "goal = [9, 9]\ndim = 2\n"),
                          {"FILE:11:", "'dim'", "grid"});
    expect_campaign_error(replace(grid_base(), "goal = [9, 9]\n", "goal = [9, 9]\nencodnig = \"chain\"\n"),
                          {"FILE:11:", "'encodnig'", "grid"});
}

TEST_CASE("bench: missing keys are named", "[cli][bench][errors]") {
    expect_campaign_error(replace(kContinuous, "name = \"e\"\n", ""), {"FILE", "'name'"});
    expect_campaign_error(replace(kContinuous, "seeds = 2\n", ""), {"FILE", "'seeds'"});
    expect_campaign_error(replace(kContinuous, "[budget]\nevaluations = 100\n", ""), {"FILE", "budget"});
    expect_campaign_error(replace(kContinuous, "evaluations = 100\n", ""), {"FILE", "budget"});
    expect_campaign_error(replace(kContinuous, "[[problem]]\nid = \"s\"\ntype = \"sphere\"\ndim = 2\n", ""),
                          {"FILE", "problem"});
    expect_campaign_error(replace(kContinuous, "[[algorithm]]\nid = \"p\"\ntype = \"pso\"\n", ""),
                          {"FILE", "algorithm"});
    expect_campaign_error(replace(kContinuous, "dim = 2\n", ""), {"FILE:5:", "'dim'"});
    expect_campaign_error(replace(kContinuous, "id = \"s\"\n", ""), {"FILE:5:", "'id'"});
    expect_campaign_error(replace(kContinuous, "type = \"sphere\"\n", ""), {"FILE:5:", "'type'"});
    expect_campaign_error(replace(kContinuous, "id = \"p\"\n", ""), {"FILE:9:", "'id'"});
    expect_campaign_error(replace(kContinuous, "type = \"pso\"\n", ""), {"FILE:9:", "'type'"});
    expect_campaign_error(replace(grid_base(), "goal = [9, 9]\n", ""), {"FILE:5:", "goal"});
    expect_campaign_error(replace(grid_base(), "map = '", "# map = '"), {"FILE:5:", "map"});
}

TEST_CASE("bench: out-of-range and mistyped values name the file, line and key", "[cli][bench][errors]") {
    expect_campaign_error(replace(kContinuous, "seeds = 2", "seeds = 0"), {"FILE:2:", "'seeds'"});
    expect_campaign_error(replace(kContinuous, "seeds = 2", "seeds = -3"), {"FILE:2:", "'seeds'"});
    expect_campaign_error(replace(kContinuous, "evaluations = 100", "evaluations = 0"), {"FILE:4:", "'evaluations'"});
    expect_campaign_error(replace(kContinuous, "dim = 2", "dim = 0"), {"FILE:5:", "'s'", "dim"});
    // a string, or a fraction, where a number (an integer) is needed
    expect_campaign_error(replace(kContinuous, "seeds = 2", "seeds = \"2\""), {"FILE:2:", "'seeds'"});
    expect_campaign_error(replace(kContinuous, "evaluations = 100", "evaluations = \"100\""),
                          {"FILE:4:", "'evaluations'"});
    expect_campaign_error(replace(kContinuous, "evaluations = 100", "evaluations = 100.5"),
                          {"FILE:4:", "'evaluations'"});
    expect_campaign_error(replace(kContinuous, "dim = 2", "dim = \"2\""), {"FILE:8:", "'dim'"});
    expect_campaign_error(kContinuous + "pop = \"20\"\n", {"FILE:12:", "'pop'"});
    expect_campaign_error(replace(kContinuous, "name = \"e\"", "name = 3"), {"FILE:1:", "'name'"});
    expect_campaign_error(replace(grid_base(), "start = [0, 0]", "start = \"0,0\""), {"FILE:9:", "'start'"});
    expect_campaign_error(replace(grid_base(), "iterations = 5\n", "iterations = 5\n[[budget]]\n"), {"FILE"});
}

TEST_CASE("bench: duplicate ids name the second one's line", "[cli][bench][errors]") {
    expect_campaign_error(kContinuous + "[[problem]]\nid = \"s\"\ntype = \"sphere\"\ndim = 3\n",
                          {"FILE:12:", "'s'", "problem"});
    expect_campaign_error(kContinuous + "[[algorithm]]\nid = \"p\"\ntype = \"ga\"\n", {"FILE:12:", "'p'", "algorithm"});
}

TEST_CASE("bench: unknown problems, algorithms and parameters are named", "[cli][bench][errors]") {
    expect_campaign_error(replace(kContinuous, "\"sphere\"", "\"nosuchproblem\""), {"FILE:5:", "'s'", "nosuchproblem"});
    expect_campaign_error(replace(kContinuous, "\"pso\"", "\"nosuchalgo\""), {"FILE:9:", "nosuchalgo"});
    expect_campaign_error(replace(kContinuous, "\"pso\"", "\"nlopt:LN_NOSUCH\""), {"FILE:9:", "LN_NOSUCH"});
    expect_campaign_error(kContinuous + "wibble = 3\n", {"FILE:9:", "'wibble'"});
    expect_campaign_error(kContinuous + "pop = 0\n", {"FILE:9:", "pop"});
}

TEST_CASE("bench: bad grid problems are named with their line", "[cli][bench][errors]") {
    expect_campaign_error(replace(grid_base(), "wan2022-10x10.map", "nosuchmap-10x10.map"),
                          {"FILE:5:", "'g1'", "nosuchmap-10x10.map"});
    // (5, 1) is an obstacle of wan2022-10x10.map
    expect_campaign_error(replace(grid_base(), "start = [0, 0]", "start = [5, 1]"),
                          {"FILE:5:", "'g1'", "start", "(5,1)"});
    expect_campaign_error(replace(grid_base(), "goal = [9, 9]", "goal = [10, 9]"), {"FILE:5:", "'g1'", "goal"});
    expect_campaign_error(replace(grid_base(), "goal = [9, 9]\n", "goal = [9, 9]\nobjective = \"nosuchobj\"\n"),
                          {"FILE:5:", "'g1'", "nosuchobj"});
}

TEST_CASE("bench: algorithms on problems they cannot solve are refused up front", "[cli][bench][errors]") {
    // astar plans on grids only
    expect_campaign_error(replace(kContinuous, "\"pso\"", "\"astar\""), {"FILE:9:", "astar", "'s'"});
    expect_campaign_error(replace(kContinuous, "\"pso\"", "\"exact\""), {"FILE:9:", "exact", "'s'"});
    // pso has no chain operators; the check covers every problem, not only the first
    const std::string chain = replace(replace(grid_base(), "goal = [9, 9]\n", "goal = [9, 9]\nencoding = \"chain\"\n"),
                                      "type = \"ga\"", "type = \"pso\"");
    expect_campaign_error(chain, {"FILE:12:", "pso", "chain"});
    const std::string line_then_chain =
        replace(grid_base(), "[[algorithm]]\n",
                "[[problem]]\nid = \"g2\"\ntype = \"grid\"\nmap = '" + bundled_map().string() +
                    "'\nstart = [0, 0]\ngoal = [9, 9]\nencoding = \"chain\"\n[[algorithm]]\n");
    expect_campaign_error(replace(line_then_chain, "type = \"ga\"", "type = \"pso\""), {"FILE:18:", "pso", "chain"});
}

TEST_CASE("bench: --jobs 0 and an impossible store are refused before anything is written", "[cli][bench][errors]") {
    expect_campaign_error(kContinuous, {"--jobs"}, {"--jobs", "0"});
    expect_campaign_error(kContinuous, {"--jobs"}, {"--jobs", "-2"});
    const TempDir dir;
    const std::string file = dir.write("c.toml", kContinuous);
    const Outcome r = run({"bench", file, "--jobs", "0", "--out", dir.file("s.sqlite")});
    check_input_error(r, {"--jobs"});
    CHECK(dir.entries() == std::vector<std::string>{"c.toml"});
    // a store that cannot be created is named too
    const std::string nowhere = dir.file("no-such-folder/s.sqlite");
    check_input_error(run({"bench", file, "--jobs", "1", "--out", nowhere}), {nowhere});
    CHECK(dir.entries() == std::vector<std::string>{"c.toml"});
}

TEST_CASE("bench: the bundled example campaigns are valid", "[cli][bench]") {
    // --jobs 0 is checked after the whole campaign file: the error names --jobs, not the file.
    const TempDir dir;
    for (const char* name : {"continuous.toml", "grid.toml"}) {
        const std::string file = (bundled_campaigns() / name).string();
        INFO(file);
        const Outcome r = run({"bench", file, "--jobs", "0", "--out", dir.file("s.sqlite")});
        check_input_error(r, {"--jobs"});
        CHECK(r.err.find(name) == std::string::npos);
    }
    CHECK(dir.entries().empty());
}

// ---------------------------------------------------------------------------------------------
// 2. --jobs 1 and --jobs 2 store the same values

TEST_CASE("bench: --jobs 1 and --jobs 2 store the same continuous runs", "[cli][bench]") {
    const TempDir dir;
    const std::string file = dir.write("c.toml", kSmallContinuous);
    check_summary(bench_ok({"bench", file, "--jobs", "1", "--out", dir.file("one.sqlite")}), kSmallContinuousRuns, 0,
                  kSmallContinuousRuns, dir.file("one.sqlite"));
    check_summary(bench_ok({"bench", file, "--jobs", "2", "--out", dir.file("two.sqlite")}), kSmallContinuousRuns, 0,
                  kSmallContinuousRuns, dir.file("two.sqlite"));
    const auto one = runs_of(dir.file("one.sqlite"));
    const auto two = runs_of(dir.file("two.sqlite"));
    REQUIRE(one.size() == kSmallContinuousRuns);
    check_same_runs(one, two);
    CHECK(distinct_keys(dir.file("one.sqlite")) == kSmallContinuousRuns);

    // The rows themselves: problem, algorithm, seed, feasible, best, evaluations, iterations,
    // optimum, solution, history, history_evaluations.
    for (const auto& row : one) {
        INFO(row[0] << " " << row[1] << " " << row[2]);
        const std::string problem = text_of(row[0]);
        CHECK(integer_of(row[3]) == 1);
        const double best = real_of(row[4]);
        CHECK(std::isfinite(best));
        CHECK(best >= 0.0);  // both problems have their minimum 0
        const long long evaluations = integer_of(row[5]);
        const long long iterations = integer_of(row[6]);
        CHECK(evaluations >= 1);
        CHECK(evaluations <= 2000);
        CHECK(row[7] == "null");  // no optimum for continuous problems
        const auto x = json_numbers(parse_json(text_of(row[8])));
        CHECK(x.size() == (problem == "sphere-4" ? 4u : 3u));
        if (problem == "sphere-4") {
            double f = 0.0;
            for (const double v : x) f += v * v;
            CHECK(std::abs(f - best) <= 1e-12 * std::max(1.0, std::abs(best)));
        }
        const auto history = json_numbers(parse_json(text_of(row[9])));
        const auto history_evaluations = json_numbers(parse_json(text_of(row[10])));
        CHECK(history.size() == static_cast<std::size_t>(iterations) + 1);
        REQUIRE(history_evaluations.size() == history.size());
        REQUIRE(!history.empty());
        CHECK(history.back() == best);
        CHECK(history_evaluations.back() == static_cast<double>(evaluations));
        for (std::size_t i = 1; i < history.size(); ++i) {
            CHECK(history[i] <= history[i - 1]);
            CHECK(history_evaluations[i] > history_evaluations[i - 1]);
        }
    }
}

TEST_CASE("bench: --jobs 1 and --jobs 2 store the same grid runs, with legal paths and the optimum",
          "[cli][bench][grid]") {
    const TempDir dir;
    const std::string file = dir.write("g.toml", small_grid());
    check_summary(bench_ok({"bench", file, "--jobs", "1", "--out", dir.file("one.sqlite")}), kSmallGridRuns, 0,
                  kSmallGridRuns, dir.file("one.sqlite"));
    check_summary(bench_ok({"bench", file, "--jobs", "2", "--out", dir.file("two.sqlite")}), kSmallGridRuns, 0,
                  kSmallGridRuns, dir.file("two.sqlite"));
    const auto one = runs_of(dir.file("one.sqlite"));
    check_same_runs(one, runs_of(dir.file("two.sqlite")));
    REQUIRE(one.size() == kSmallGridRuns);
    CHECK(distinct_keys(dir.file("one.sqlite")) == kSmallGridRuns);

    const Map map = read_movingai(bundled_map());
    const double optimal_cells = shortest(map, {0, 0}, {9, 9}, 1.0, 1.0) + 1.0;
    const double optimal_length = shortest(map, {0, 9}, {9, 0}, 1.0, std::sqrt(2.0));
    REQUIRE(std::isfinite(optimal_cells));
    REQUIRE(std::isfinite(optimal_length));
    std::size_t feasible_runs = 0;
    for (const auto& row : one) {
        INFO(row[0] << " " << row[1] << " " << row[2] << " " << row[8]);
        const bool cells = text_of(row[0]) == "line-cells";
        const Cell start = cells ? Cell{0, 0} : Cell{0, 9};
        const Cell goal = cells ? Cell{9, 9} : Cell{9, 0};
        const double optimum = cells ? optimal_cells : optimal_length;
        CHECK(std::abs(real_of(row[7]) - optimum) <= 1e-9);

        const auto path = path_of(text_of(row[8]));
        REQUIRE(path.size() >= 2);
        CHECK(path.front() == start);
        CHECK(path.back() == goal);
        const bool feasible = integer_of(row[3]) == 1;
        bool legal = true;
        double length = 0.0;
        for (std::size_t i = 1; i < path.size(); ++i) {
            legal = legal && legal_step(map, path[i - 1], path[i]);
            length += (path[i].x != path[i - 1].x && path[i].y != path[i - 1].y) ? std::sqrt(2.0) : 1.0;
        }
        CHECK(map.free(start.x, start.y));
        CHECK(legal == feasible);
        if (!feasible) {
            CHECK(row[4] == "null");
            continue;
        }
        ++feasible_runs;
        const double best = real_of(row[4]);
        CHECK(std::abs(best - (cells ? static_cast<double>(path.size()) : length)) <= 1e-9);
        CHECK(best >= optimum - 1e-9);
        if (text_of(row[1]) == "exact") CHECK(std::abs(best - optimum) <= 1e-9);
        const auto history = json_numbers(parse_json(text_of(row[9])));
        if (text_of(row[1]) == "exact") {
            CHECK(integer_of(row[6]) == 0);  // no iterations: the history may be empty
            if (history.empty()) continue;
        }
        REQUIRE(!history.empty());
        CHECK(history.back() == best);
        for (std::size_t i = 1; i < history.size(); ++i) CHECK(history[i] <= history[i - 1]);
        // Either not recorded ("[]"), or one count per history entry, the last being the total.
        const auto history_evaluations = json_numbers(parse_json(text_of(row[10])));
        if (!history_evaluations.empty()) {
            REQUIRE(history_evaluations.size() == history.size());
            CHECK(history_evaluations.back() == static_cast<double>(integer_of(row[5])));
            for (std::size_t i = 1; i < history_evaluations.size(); ++i)
                CHECK(history_evaluations[i] > history_evaluations[i - 1]);
        }
    }
    CHECK(feasible_runs >= kSmallGridRuns / 2);  // repair and chains keep nearly every run feasible
}

// ---------------------------------------------------------------------------------------------
// 3. Resuming after SIGKILL

TEST_CASE("bench: a campaign killed with SIGKILL resumes with no run lost or run twice", "[cli][bench][resume]") {
    const TempDir dir;
    const std::string config = dir.write("r.toml", kResume);
    const std::string reference_store = dir.file("reference.sqlite");
    check_summary(bench_ok({"bench", config, "--jobs", "2", "--out", reference_store}), kResumeRuns, 0, kResumeRuns,
                  reference_store);
    const auto reference = runs_of(reference_store);
    REQUIRE(static_cast<long long>(reference.size()) == kResumeRuns);

    {
        INFO("killed early, resumed to the end");
        const std::string store = dir.file("early.sqlite");
        const long long left = bench_and_kill(config, store, 3, dir);
        check_summary(bench_ok({"bench", config, "--jobs", "2", "--out", store}), kResumeRuns - left, left, kResumeRuns,
                      store);
        check_same_runs(runs_of(store), reference);
        CHECK(count_runs(store) == kResumeRuns);
        CHECK(static_cast<long long>(distinct_keys(store)) == kResumeRuns);
    }
    {
        INFO("killed half-way, killed again while resuming, resumed to the end");
        const std::string store = dir.file("late.sqlite");
        const long long first = bench_and_kill(config, store, kResumeRuns / 2, dir);
        const long long second = bench_and_kill(config, store, std::max(first + 5, kResumeRuns * 3 / 4), dir);
        CHECK(second > first);
        check_summary(bench_ok({"bench", config, "--jobs", "1", "--out", store}), kResumeRuns - second, second,
                      kResumeRuns, store);
        check_same_runs(runs_of(store), reference);
        CHECK(count_runs(store) == kResumeRuns);
        CHECK(static_cast<long long>(distinct_keys(store)) == kResumeRuns);
    }
}

// ---------------------------------------------------------------------------------------------
// 4. Finished campaigns, and stores of other campaigns

TEST_CASE("bench: re-running a finished campaign stores nothing and says so", "[cli][bench]") {
    const TempDir dir;
    const std::string config = dir.write("c.toml", kSmallContinuous);
    const std::string store = dir.file("c.sqlite");  // the default: CONFIG's name with .sqlite, here
    check_summary(bench_ok({"bench", config, "--jobs", "2"}, dir.path().string()), kSmallContinuousRuns, 0,
                  kSmallContinuousRuns, "c.sqlite");
    const auto before = runs_of(store, true);
    const std::string bytes = slurp(store);
    const auto entries = dir.entries();
    CHECK(entries == std::vector<std::string>{"c.sqlite", "c.toml"});

    const std::string out = bench_ok({"bench", config, "--jobs", "2", "--out", store});
    check_summary(out, 0, kSmallContinuousRuns, kSmallContinuousRuns, store);
    check_same_runs(runs_of(store, true), before);  // wall_ms included: no row was rewritten
    CHECK(slurp(store) == bytes);
    CHECK(dir.entries() == entries);
}

TEST_CASE("bench: a store of another campaign is refused and left untouched", "[cli][bench][errors]") {
    const TempDir dir;
    const std::string config = dir.write("c.toml", kSmallContinuous);
    const std::string store = dir.file("c.sqlite");
    bench_ok({"bench", config, "--jobs", "2", "--out", store});
    const auto before = runs_of(store, true);
    const std::string bytes = slurp(store);

    // What changes a stored run's definition, or the campaign, is refused, naming it.
    const std::vector<std::tuple<std::string, std::string, std::string>> others{
        {"another budget", replace(kSmallContinuous, "evaluations = 2000", "evaluations = 2001"),
         "the budget 'evaluations = 2000', this campaign 'evaluations = 2001'"},
        {"a problem redefined", replace(kSmallContinuous, "dim = 4", "dim = 5"),
         "problem 'sphere-4' is stored as sphere dim 4 instance 0, here it is sphere dim 5 instance 0"},
        {"an algorithm redefined",
         replace(kSmallContinuous, "pop = 12\n[[algorithm]]\nid = \"ga\"", "pop = 13\n[[algorithm]]\nid = \"ga\""),
         "algorithm 'pso' is stored as pso pop=12, here it is pso pop=13"},
        {"another campaign", kContinuous, "another campaign"},
    };
    for (const auto& [what, text, words] : others) {
        INFO(what);
        const std::string other = dir.write("other.toml", text);
        const auto entries = dir.entries();
        const Outcome r = run({"bench", other, "--jobs", "2", "--out", store});
        check_input_error(r, {store, words});
        CHECK(slurp(store) == bytes);
        CHECK(dir.entries() == entries);  // no journal left behind either
        check_same_runs(runs_of(store, true), before);
    }

    // A file that is not a store at all is refused too, and kept as it was.
    const std::string not_a_store = dir.write("notes.sqlite", "these are my notes, not a database\n");
    check_input_error(run({"bench", config, "--jobs", "1", "--out", not_a_store}), {not_a_store});
    CHECK(slurp(not_a_store) == "these are my notes, not a database\n");

    // The campaign itself still finds its store intact: nothing to do.
    check_summary(bench_ok({"bench", config, "--jobs", "1", "--out", store}), 0, kSmallContinuousRuns,
                  kSmallContinuousRuns, store);
}

TEST_CASE("bench: a campaign grows by seeds, algorithms and problems, and only the new runs run", "[cli][bench]") {
    const TempDir dir;
    const std::string store = dir.file("c.sqlite");
    const std::string base =
        "name = \"grow\"\nseeds = 2\n[budget]\nevaluations = 300\n"
        "[[problem]]\nid = \"s\"\ntype = \"sphere\"\ndim = 3\n"
        "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\npop = 10\n";
    check_summary(bench_ok({"bench", dir.write("a.toml", base), "--jobs", "1", "--out", store}), 2, 0, 2, store);
    const auto before = runs_of(store, true);  // wall times included: rows never rewritten
    // A comment, three seeds, one more algorithm and one more problem: 3 x 2 x 2 runs, 2 stored.
    const std::string grown = "# grown\n" + replace(base, "seeds = 2", "seeds = 3") +
                              "[[algorithm]]\nid = \"ga\"\ntype = \"ga\"\npop = 10\n"
                              "[[problem]]\nid = \"r\"\ntype = \"rastrigin\"\ndim = 2\ninstance = 1\n";
    check_summary(bench_ok({"bench", dir.write("b.toml", grown), "--jobs", "2", "--out", store}), 10, 2, 12, store);
    const auto after = runs_of(store, true);
    REQUIRE(after.size() == 12);
    for (const auto& row : before) CHECK(std::find(after.begin(), after.end(), row) != after.end());
    // The grown store equals a fresh run of the grown campaign (bar wall times).
    const std::string fresh = dir.file("fresh.sqlite");
    bench_ok({"bench", dir.file("b.toml"), "--jobs", "1", "--out", fresh});
    check_same_runs(runs_of(store), runs_of(fresh));
    // Back to the first file: nothing to run, nothing lost.
    check_summary(bench_ok({"bench", dir.file("a.toml"), "--jobs", "1", "--out", store}), 0, 2, 2, store);
    CHECK(runs_of(store).size() == 12);
    // The problems and algorithms the growth added are recorded with their definitions.
    Db db(store);
    const auto defined = db.query("SELECT id, definition FROM algorithms ORDER BY id");
    REQUIRE(defined);
    CHECK(*defined == std::vector<std::vector<std::string>>{{"t:ga", "t:ga pop=10"}, {"t:pso", "t:pso pop=10"}});
}

TEST_CASE("bench: a store from before definitions grows after one resume with its own file", "[cli][bench]") {
    const TempDir dir;
    const std::string store = dir.file("c.sqlite");
    const std::string base =
        "name = \"old\"\nseeds = 1\n[budget]\nevaluations = 100\n"
        "[[problem]]\nid = \"s\"\ntype = \"sphere\"\ndim = 2\n"
        "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\npop = 10\n";
    const std::string a = dir.write("a.toml", base);
    bench_ok({"bench", a, "--jobs", "1", "--out", store});
    {  // as a store written before definitions were kept
        Db db(store);
        REQUIRE(
            db.query("UPDATE campaign SET budget = NULL; UPDATE problems SET definition = NULL; "
                     "UPDATE algorithms SET definition = NULL"));
    }
    const std::string grown = dir.write("b.toml", replace(base, "seeds = 1", "seeds = 2"));
    check_input_error(run({"bench", grown, "--jobs", "1", "--out", store}), {store, "before campaigns could grow"});
    check_summary(bench_ok({"bench", a, "--jobs", "1", "--out", store}), 0, 1, 1, store);  // fills them in
    check_summary(bench_ok({"bench", grown, "--jobs", "1", "--out", store}), 1, 1, 2, store);
}

TEST_CASE("bench: grid options that only a run would reject are refused up front", "[cli][bench][errors]") {
    const std::string g = grid_base();
    auto with = [&](const std::string& lines) { return replace(g, "goal = [9, 9]\n", "goal = [9, 9]\n" + lines); };
    expect_campaign_error(with("encoding = \"nosuch\"\n"), {"FILE:5:", "'g1'", "nosuch"});
    expect_campaign_error(with("encoding = \"chain\"\nconnector = \"penalty\"\n"), {"FILE:5:", "'g1'", "connector"});
    expect_campaign_error(with("encoding = \"free\"\nwaypoints = 0\n"), {"FILE:5:", "'g1'", "waypoints"});
    expect_campaign_error(replace(with("init = \"walk\"\n"), "type = \"ga\"", "type = \"nlopt:LN_SBPLX\""),
                          {"FILE:", "walk"});
    expect_campaign_error(replace(g + "wibble = 3\n", "type = \"ga\"", "type = \"exact\""), {"FILE:11:", "'wibble'"});
    expect_campaign_error(g + "[[algorithm]]\nid = \"b\"\ntype = \"astar\"\npop = 20\n", {"FILE:14:", "pop"});
}

TEST_CASE("bench: an SQLite database that is not a pride store is refused and left untouched", "[cli][bench][errors]") {
    const TempDir dir;
    const std::string config = dir.write("c.toml", kContinuous);
    const std::string foreign = dir.file("notes.db");
    {
        sqlite3* db = nullptr;
        REQUIRE(sqlite3_open(foreign.c_str(), &db) == SQLITE_OK);
        REQUIRE(sqlite3_exec(db, "CREATE TABLE notes (t TEXT); INSERT INTO notes VALUES ('hello')", nullptr, nullptr,
                             nullptr) == SQLITE_OK);
        sqlite3_close(db);
    }
    const std::string bytes = slurp(foreign);
    check_input_error(run({"bench", config, "--jobs", "1", "--out", foreign}), {foreign});
    CHECK(slurp(foreign) == bytes);
    CHECK(dir.entries() == std::vector<std::string>{"c.toml", "notes.db"});
}

// ---------------------------------------------------------------------------------------------
// 5. Campaigns under faults: signals, two processes on one store, read-only and full
// file systems, a store deleted meanwhile, a store of a campaign that stored nothing

namespace {

/// Waits (bounded) until `store` holds at least `at_least` runs while `child` runs.
void wait_for_runs(Child& child, const std::string& store, long long at_least, const std::string& err) {
    const auto deadline = Clock::now() + 120s;
    long long seen = -1;
    while ((seen = count_runs(store)) < at_least) {
        if (!child.running()) {
            INFO("stderr: " << slurp(err));
            FAIL("pride bench ended (status " << child.exit_status() << ") before " << at_least << " runs were stored");
        }
        if (Clock::now() > deadline) FAIL("no " << at_least << " runs stored within 120 s; " << seen << " were");
        std::this_thread::sleep_for(1ms);
    }
}

long long claims_left(const std::string& store) {
    Db db(store);
    const auto rows = db.query("SELECT count(*) FROM claims");
    REQUIRE(rows);
    return integer_of((*rows)[0][0]);
}

/// "NAME: N runs stored in ..." -> N
long long stored_of(const std::string& out) {
    const auto colon = out.find(": ");
    REQUIRE(colon != std::string::npos);
    return std::stoll(out.substr(colon + 2));
}

/// Can this process make a user and mount namespace (unshare -rm) for a tmpfs of its own?
bool can_unshare() {
    return std::system("unshare -rm sh -c 'mount -t tmpfs -o size=64k none /mnt' >/dev/null 2>&1") == 0;
}

std::string sh_quote(const std::string& s) {
    return "'" + s + "'";
}

}  // namespace

TEST_CASE("bench: SIGINT and SIGTERM commit the finished runs, say how to resume, exit 130 and 143",
          "[cli][bench][resume][faults]") {
    const TempDir dir;
    const std::string config = dir.write("r.toml", kResume);
    const std::string reference_store = dir.file("reference.sqlite");
    bench_ok({"bench", config, "--jobs", "2", "--out", reference_store});
    const auto reference = runs_of(reference_store);
    for (const auto& [signal, name, status] :
         {std::tuple{SIGINT, "SIGINT", 130}, std::tuple{SIGTERM, "SIGTERM", 143}}) {
        INFO(name);
        const std::string store = dir.file(std::string(name) + ".sqlite");
        long long left = 0;
        {
            Child child({"bench", config, "--jobs", "2", "--out", store}, dir.file("sig-out"), dir.file("sig-err"));
            wait_for_runs(child, store, 10, dir.file("sig-err"));  // event-driven: 10 runs are in the store
            child.send(signal);
            REQUIRE(child.wait_for(60s));
            CHECK(child.exit_status() == status);
            left = count_runs(store);
            const std::string err = slurp(dir.file("sig-err"));
            INFO("stderr: " << err);
            CHECK(std::count(err.begin(), err.end(), '\n') == 1);
            CHECK(err.find(std::string("interrupted by ") + name) != std::string::npos);
            CHECK(err.find(": " + std::to_string(left) + " of " + std::to_string(kResumeRuns) + " runs are stored in " +
                           store) != std::string::npos);
            CHECK(err.find("run the same command again to resume") != std::string::npos);
            CHECK(slurp(dir.file("sig-out")).empty());
        }
        CHECK(left >= 10);
        REQUIRE(left < kResumeRuns);
        CHECK(static_cast<long long>(distinct_keys(store)) == left);
        CHECK(claims_left(store) == 0);  // the abandoned runs were handed back
        {
            Db db(store);
            const auto ok = db.query("PRAGMA integrity_check");
            REQUIRE(ok);
            CHECK((*ok)[0][0] == "t:ok");
        }
        check_summary(bench_ok({"bench", config, "--jobs", "2", "--out", store}), kResumeRuns - left, left, kResumeRuns,
                      store);
        check_same_runs(runs_of(store), reference);
    }
}

TEST_CASE("bench: two processes on one store share its runs, none lost or stored twice", "[cli][bench][faults]") {
    const TempDir dir;
    const std::string config = dir.write("r.toml", kResume);
    const std::string reference_store = dir.file("reference.sqlite");
    bench_ok({"bench", config, "--jobs", "2", "--out", reference_store});
    const auto reference = runs_of(reference_store);
    for (const bool together : {true, false}) {
        INFO((together ? "started at once on a new store" : "the second started once the first stored 5 runs"));
        const std::string store = dir.file(together ? "together.sqlite" : "later.sqlite");
        Child a({"bench", config, "--jobs", "1", "--out", store}, dir.file("a-out"), dir.file("a-err"));
        if (!together) wait_for_runs(a, store, 5, dir.file("a-err"));
        Child b({"bench", config, "--jobs", "1", "--out", store}, dir.file("b-out"), dir.file("b-err"));
        REQUIRE(a.wait_for(120s));
        REQUIRE(b.wait_for(120s));
        const std::string out_a = slurp(dir.file("a-out")), out_b = slurp(dir.file("b-out"));
        INFO("a: " << out_a << slurp(dir.file("a-err")) << "b: " << out_b << slurp(dir.file("b-err")));
        CHECK(a.exit_status() == 0);
        CHECK(b.exit_status() == 0);
        CHECK(slurp(dir.file("a-err")).empty());
        CHECK(slurp(dir.file("b-err")).empty());
        CHECK(count_runs(store) == kResumeRuns);
        CHECK(static_cast<long long>(distinct_keys(store)) == kResumeRuns);
        CHECK(stored_of(out_a) + stored_of(out_b) == kResumeRuns);  // each run stored by one of them
        if (!together) {
            // The second took runs the first had not: 175 runs remained when it started.
            CHECK(stored_of(out_a) > 0);
            CHECK(stored_of(out_b) > 0);
        }
        CHECK(claims_left(store) == 0);
        check_same_runs(runs_of(store), reference);
    }
}

TEST_CASE("bench: a store deleted while it runs is an error naming it, never a success", "[cli][bench][faults]") {
    const TempDir dir;
    const std::string config = dir.write("r.toml", kResume);
    const std::string store = dir.file("gone.sqlite");
    Child child({"bench", config, "--jobs", "2", "--out", store}, dir.file("out"), dir.file("err"));
    wait_for_runs(child, store, 3, dir.file("err"));
    for (const char* suffix : {"", "-wal", "-shm"}) fs::remove(store + suffix);
    REQUIRE(child.wait_for(120s));
    const Outcome r{child.exit_status(), slurp(dir.file("out")), slurp(dir.file("err"))};
    check_input_error(r, {store, "deleted or replaced"});
}

TEST_CASE("bench: a store of a campaign that stored no run takes the corrected campaign", "[cli][bench][faults]") {
    const TempDir dir;
    const std::string first = dir.write("c.toml", kSmallContinuous);
    const std::string store = dir.file("s.sqlite");
    bench_ok({"bench", first, "--jobs", "1", "--out", store});
    {  // as a campaign that failed (or was stopped) before its first run leaves it
        sqlite3* db = nullptr;
        REQUIRE(sqlite3_open(store.c_str(), &db) == SQLITE_OK);
        REQUIRE(sqlite3_exec(db, "DELETE FROM runs", nullptr, nullptr, nullptr) == SQLITE_OK);
        sqlite3_close(db);
    }
    const std::string corrected =
        dir.write("d.toml", replace(kSmallContinuous, "evaluations = 2000", "evaluations = 2001"));
    check_summary(bench_ok({"bench", corrected, "--jobs", "1", "--out", store}), kSmallContinuousRuns, 0,
                  kSmallContinuousRuns, store);
    // Once it holds runs, another budget is refused again.
    check_input_error(run({"bench", first, "--jobs", "1", "--out", store}), {store, "the budget"});
}

TEST_CASE("bench: a folder or a device as the campaign file is one clear line", "[cli][bench][faults]") {
    const TempDir dir;
    check_input_error(run({"bench", dir.path().string()}, 120s, dir.path().string()),
                      {dir.path().string(), "is a folder"});
    check_input_error(run({"bench", "/dev/zero"}, 120s, dir.path().string()), {"/dev/zero", "not a regular file"});
    CHECK(dir.entries().empty());
}

TEST_CASE("bench: a read-only or full file system is an error naming the store, nothing stored is lost",
          "[cli][bench][faults]") {
    if (!can_unshare()) {
        WARN("skipped: no user and mount namespace here (unshare -rm) for a read-only or small file system");
        return;
    }
    const TempDir dir;
    const std::string config = dir.write("r.toml", kResume);
    const std::string small = dir.write("c.toml", kSmallContinuous);
    {
        INFO("read-only: a bind mount of the store's folder, remounted read-only in a namespace of its own");
        fs::create_directories(dir.path() / "ro");
        const std::string store = dir.file("ro/s.sqlite");
        bench_ok({"bench", small, "--jobs", "1", "--out", store});
        const std::string bytes = slurp(store);
        const auto entries = fs::directory_iterator(dir.path() / "ro");
        (void)entries;
        const std::string ro = dir.file("ro");
        for (const std::string& target : {store, dir.file("ro/new.sqlite")}) {
            const std::string script = "mount --bind " + sh_quote(ro) + " " + sh_quote(ro) +
                                       " && mount -o remount,bind,ro " + sh_quote(ro) + " && " + sh_quote(PRIDE_EXE) +
                                       " bench " + sh_quote(config) + " --jobs 1 --out " + sh_quote(target) + " >" +
                                       sh_quote(dir.file("ro-out")) + " 2>" + sh_quote(dir.file("ro-err")) +
                                       "; echo $? >" + sh_quote(dir.file("ro-rc"));
            REQUIRE(std::system(("unshare -rm sh -c " + sh_quote(script)).c_str()) == 0);
            const Outcome r{std::stoi(slurp(dir.file("ro-rc"))), slurp(dir.file("ro-out")), slurp(dir.file("ro-err"))};
            check_input_error(r, {target, "store", "Read-only file system"});
        }
        CHECK(slurp(store) == bytes);
        CHECK(!fs::exists(dir.file("ro/new.sqlite")));
    }
    {
        // 4 MiB: about half of the 8 MB this campaign stores, so that several commits (one per 16 runs
        // or 20 ms, about 0.7 MB) land before the file system fills.
        INFO("full: a 4 MiB tmpfs; the store, the message and a copy are taken before the namespace ends");
        fs::create_directories(dir.path() / "full");
        fs::create_directories(dir.path() / "copy");
        const std::string full = dir.file("full"), store = dir.file("full/s.sqlite");
        const std::string script = "mount -t tmpfs -o size=4m none " + sh_quote(full) + " && " + sh_quote(PRIDE_EXE) +
                                   " bench " + sh_quote(config) + " --jobs 2 --out " + sh_quote(store) + " >" +
                                   sh_quote(dir.file("full-out")) + " 2>" + sh_quote(dir.file("full-err")) +
                                   "; echo $? >" + sh_quote(dir.file("full-rc")) + "; cp " + sh_quote(full) + "/* " +
                                   sh_quote(dir.file("copy"));
        REQUIRE(std::system(("unshare -rm sh -c " + sh_quote(script)).c_str()) == 0);
        const Outcome r{std::stoi(slurp(dir.file("full-rc"))), slurp(dir.file("full-out")),
                        slurp(dir.file("full-err"))};
        check_input_error(r, {store, "full", "runs are stored and kept", "resume"});
        // What the message says is stored is there, intact.
        const std::string copy = dir.file("copy/s.sqlite");
        REQUIRE(fs::exists(copy));
        Db db(copy);
        const auto ok = db.query("PRAGMA integrity_check");
        REQUIRE(ok);
        CHECK((*ok)[0][0] == "t:ok");
        const long long kept = count_runs(copy);
        INFO("stderr: " << r.err);
        CHECK(kept > 0);
        CHECK(kept < kResumeRuns);
        CHECK(r.err.find("(" + std::to_string(kept) + " runs are stored and kept") != std::string::npos);
    }
}

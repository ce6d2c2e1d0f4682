#include "experiment/storage/reader.hpp"

#include <fmt/format.h>
#include <sqlite3.h>
#include <sys/stat.h>

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <string_view>
#include <type_traits>

#include "experiment/storage/schema.hpp"

namespace pride::storage {
namespace {

/// Text for a message: `text` quoted, or an excerpt around character `at` when it is long (a
/// history holds thousands of numbers).
std::string excerpt(std::string_view text, std::size_t at) {
    constexpr std::size_t half = 24;
    if (text.size() <= 2 * half) return "'" + std::string(text) + "'";
    const std::size_t from = at > half ? at - half : 0, to = std::min(text.size(), from + 2 * half);
    return "'" + std::string(from > 0 ? "..." : "") + std::string(text.substr(from, to - from)) +
           (to < text.size() ? "..." : "") + "'";
}

template <class T>
struct Value {  // the number type of a list element
    using type = T;
};
template <class T>
struct Value<std::optional<T>> {
    using type = T;
};

/// The numbers of a JSON list such as "[1, 2.5e-3, null]" as pride bench writes it; `null` only
/// when `T` is double (+inf: no feasible value yet) or an optional (empty: never). On failure,
/// the character at fault.
template <class T>
bool parse_list(std::string_view text, std::vector<T>& out, std::size_t& at) {
    using V = typename Value<T>::type;
    constexpr bool nullable = std::is_floating_point_v<T> || !std::is_same_v<T, V>;
    std::size_t& i = at;
    i = 0;
    const auto skip = [&] {
        while (i < text.size() && (text[i] == ' ' || text[i] == '\t' || text[i] == '\n' || text[i] == '\r')) ++i;
    };
    const auto at_end = [&] {
        skip();
        return i == text.size();
    };
    skip();
    if (i == text.size() || text[i] != '[') return false;
    ++i;
    skip();
    if (i < text.size() && text[i] == ']') {
        ++i;
        return at_end();
    }
    for (;;) {
        skip();
        if (nullable && text.substr(i, 4) == "null") {
            if constexpr (std::is_floating_point_v<T>)
                out.push_back(std::numeric_limits<T>::infinity());
            else
                out.push_back(T{});
            i += 4;
        } else {
            // from_chars alone would take "inf" and "nan": a JSON number starts with a digit.
            const std::size_t start = i;
            if (i < text.size() && text[i] == '-') ++i;
            if (i == text.size() || text[i] < '0' || text[i] > '9') return false;
            V v{};
            const auto [end, ec] = std::from_chars(text.data() + start, text.data() + text.size(), v);
            if (ec != std::errc()) return false;  // out of range included
            out.push_back(v);
            i = static_cast<std::size_t>(end - text.data());
        }
        skip();
        if (i < text.size() && text[i] == ',') {
            ++i;
            continue;
        }
        if (i < text.size() && text[i] == ']') {
            ++i;
            return at_end();
        }
        return false;
    }
}

/// The store's connection, read-only; closed at the end of the scope.
class Connection {
  public:
    explicit Connection(const std::string& path) : path_(path), db_(open_read_only(path)) {}
    ~Connection() { sqlite3_close(db_); }
    Connection(const Connection&) = delete;
    Connection& operator=(const Connection&) = delete;

    /// The failure of the last call as bad input: a file that is no database, one that is
    /// corrupt, or one that cannot be read.
    [[noreturn]] void fail() const {
        const std::string why = sqlite3_errmsg(db_);
        switch (sqlite3_errcode(db_) & 0xff) {
            case SQLITE_NOTADB:
                throw InputError(path_ + ": not a campaign store (" + why + ")");
            case SQLITE_CORRUPT:
                throw DamagedStore(path_, why);
            default:
                throw InputError(path_ + ": cannot read the store (" + why + ")");
        }
    }
    sqlite3* get() const { return db_; }
    const std::string& path() const { return path_; }

  private:
    std::string path_;
    sqlite3* db_ = nullptr;
};

/// One query's rows, each value checked against the kind pride bench writes; `where` names the
/// row in messages.
class Query {
  public:
    Query(const Connection& db, const char* sql) : db_(db) {
        if (sqlite3_prepare_v2(db.get(), sql, -1, &s_, nullptr) != SQLITE_OK) db.fail();
    }
    ~Query() { sqlite3_finalize(s_); }
    Query(const Query&) = delete;
    Query& operator=(const Query&) = delete;

    void bind(int i, const std::string& text) { sqlite3_bind_text(s_, i, text.c_str(), -1, SQLITE_TRANSIENT); }
    /// The next row; false at the end. A corrupt page found on the way is an error, not the end.
    bool next() {
        const int rc = sqlite3_step(s_);
        if (rc == SQLITE_ROW) return true;
        if (rc != SQLITE_DONE) db_.fail();
        return false;
    }

    std::string where;

    std::string text(int i, const char* column) const {
        if (sqlite3_column_type(s_, i) != SQLITE_TEXT) fail(column, "expected text, got " + value(i));
        return raw_text(i);
    }
    double number(int i, const char* column) const {
        const int type = sqlite3_column_type(s_, i);
        if (type == SQLITE_INTEGER) return static_cast<double>(sqlite3_column_int64(s_, i));
        if (type != SQLITE_FLOAT) fail(column, "expected a number, got " + value(i));
        const double v = sqlite3_column_double(s_, i);
        // pride bench stores no infinity or NaN (NULL stands for "none").
        if (!std::isfinite(v)) fail(column, "expected a finite number, got " + value(i));
        return v;
    }
    /// A REAL or INTEGER as it is, infinities included (a violation with no finite value).
    double raw_double(int i, const char* column) const {
        const int type = sqlite3_column_type(s_, i);
        if (type == SQLITE_INTEGER) return static_cast<double>(sqlite3_column_int64(s_, i));
        if (type != SQLITE_FLOAT) fail(column, "expected a number, got " + value(i));
        return sqlite3_column_double(s_, i);
    }
    std::optional<double> optional_number(int i, const char* column) const {
        if (sqlite3_column_type(s_, i) == SQLITE_NULL) return std::nullopt;
        return number(i, column);
    }
    std::optional<std::string> optional_text(int i, const char* column) const {
        if (sqlite3_column_type(s_, i) == SQLITE_NULL) return std::nullopt;
        return text(i, column);
    }
    std::optional<std::int64_t> optional_integer(int i, const char* column, std::int64_t min) const {
        if (sqlite3_column_type(s_, i) == SQLITE_NULL) return std::nullopt;
        return integer(i, column, min);
    }
    bool is_null(int i) const { return sqlite3_column_type(s_, i) == SQLITE_NULL; }
    std::int64_t integer(int i, const char* column, std::int64_t min) const {
        if (sqlite3_column_type(s_, i) != SQLITE_INTEGER) fail(column, "expected an integer, got " + value(i));
        const std::int64_t v = sqlite3_column_int64(s_, i);
        if (v < min) fail(column, fmt::format("expected an integer of at least {}, got {}", min, v));
        return v;
    }
    /// A JSON list of numbers (of counts when `T` is std::int64_t, of counts or nulls when it is
    /// an optional).
    template <class T>
    std::vector<T> list(int i, const char* column) const {
        const char* expected = std::is_floating_point_v<T>       ? "a JSON list of numbers"
                               : std::is_same_v<T, std::int64_t> ? "a JSON list of counts"
                                                                 : "a JSON list of counts or nulls";
        if (sqlite3_column_type(s_, i) != SQLITE_TEXT)
            fail(column, fmt::format("expected {}, got {}", expected, value(i)));
        const std::string json = raw_text(i);
        std::vector<T> out;
        std::size_t at = 0;
        if (!parse_list(json, out, at))
            fail(column,
                 fmt::format("expected {}, got {} (wrong at character {})", expected, excerpt(json, at), at + 1));
        if constexpr (std::is_integral_v<T>)
            for (const T v : out)
                if (v < 0) fail(column, fmt::format("expected {}, got the negative count {}", expected, v));
        if constexpr (!std::is_same_v<T, typename Value<T>::type>)
            for (const T& v : out)
                if (v && *v < 1) fail(column, fmt::format("expected {}, got the count {} (at least 1)", expected, *v));
        return out;
    }
    [[noreturn]] void fail(const char* column, const std::string& what) const {
        throw DamagedStore(db_.path(), where + ", column " + column + ": " + what);
    }

  private:
    std::string raw_text(int i) const {
        const auto* p = reinterpret_cast<const char*>(sqlite3_column_text(s_, i));
        return p ? std::string(p, static_cast<std::size_t>(sqlite3_column_bytes(s_, i))) : std::string();
    }
    /// A stored value as a message shows it.
    std::string value(int i) const {
        switch (sqlite3_column_type(s_, i)) {
            case SQLITE_NULL:
                return "NULL";
            case SQLITE_INTEGER:
                return std::to_string(sqlite3_column_int64(s_, i));
            case SQLITE_FLOAT:
                return fmt::format("{}", sqlite3_column_double(s_, i));
            case SQLITE_TEXT:
                return "the text " + excerpt(raw_text(i), 0);
            default:
                return "a blob";
        }
    }

    const Connection& db_;
    sqlite3_stmt* s_ = nullptr;
};

/// The first column of every row of `sql` (table or column names).
std::set<std::string> names(const Connection& db, const char* sql, const std::string& bound = "") {
    Query q(db, sql);
    if (!bound.empty()) q.bind(1, bound);
    q.where = bound.empty() ? "the schema" : "the schema of table " + bound;
    std::set<std::string> out;
    while (q.next()) out.insert(q.text(0, "name"));
    return out;
}

/// A store file shorter than its header says (cut short by a full disk or a careless copy):
/// SQLite would report it as malformed somewhere later, or not at all for the pages never read.
/// The header's page count holds only when its "version valid for" number equals the change
/// counter, and without a write-ahead log (which may hold pages not yet in the file).
void check_length(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    unsigned char h[100] = {};
    if (!f.read(reinterpret_cast<char*>(h), sizeof h)) return;  // too short for a header: SQLite says so
    if (std::string(reinterpret_cast<char*>(h), 16) != std::string("SQLite format 3\0", 16)) return;
    const auto be32 = [&](int at) {
        return (std::uint64_t{h[at]} << 24) | (std::uint64_t{h[at + 1]} << 16) | (std::uint64_t{h[at + 2]} << 8) |
               std::uint64_t{h[at + 3]};
    };
    std::uint64_t page = (std::uint64_t{h[16]} << 8) | h[17];
    if (page == 1) page = 65536;
    const std::uint64_t pages = be32(28);
    std::error_code ec;
    const auto wal = std::filesystem::file_size(path + "-wal", ec);
    if (be32(24) != be32(92) || pages == 0 || (!ec && wal > 0)) return;
    const auto size = std::filesystem::file_size(path, ec);
    if (!ec && size < page * pages)
        throw DamagedStore(path, fmt::format("the file is truncated: {} bytes, where its header gives {} pages of {} "
                                             "bytes ({} bytes)",
                                             size, pages, page, page * pages));
}

/// `path` as an SQLite URI file name: bytes outside the unreserved set percent-encoded (a '?' or '#'
/// in a name would end the path), and "file://" before an absolute path (so that "//x" is no host).
std::string uri_of(const std::string& path) {
    std::string out = path.rfind('/', 0) == 0 ? "file://" : "file:";
    for (const char c : path) {
        const auto u = static_cast<unsigned char>(c);
        if (std::isalnum(u) || c == '/' || c == '-' || c == '.' || c == '_' || c == '~')
            out += c;
        else
            out += fmt::format("%{:02X}", u);
    }
    return out;
}

/// Whether `file` exists with content (a -wal or -journal file that holds what the store lacks).
bool holds_content(const std::string& file) {
    std::error_code ec;
    return std::filesystem::exists(file, ec) && std::filesystem::file_size(file, ec) > 0 && !ec;
}

/// The store opened with `uri` and its schema read (which is where a WAL store without its -shm
/// fails), or null with SQLite's reason in `why`.
sqlite3* try_open(const std::string& uri, std::string& why) {
    sqlite3* db = nullptr;
    int rc = sqlite3_open_v2(uri.c_str(), &db, SQLITE_OPEN_READONLY | SQLITE_OPEN_URI, nullptr);
    // A pride bench on the same store may hold it for a moment (its schema being created, a
    // change of journal mode): wait for it as pride bench itself does, rather than fail.
    if (rc == SQLITE_OK) sqlite3_busy_timeout(db, 30000);
    if (rc == SQLITE_OK) rc = sqlite3_exec(db, "SELECT count(*) FROM sqlite_master", nullptr, nullptr, nullptr);
    if (rc == SQLITE_OK) return db;
    why = db ? sqlite3_errmsg(db) : "out of memory";
    // Not a database, or a corrupt one, is said by the reader's own checks: keep the connection.
    const int primary = db ? (sqlite3_extended_errcode(db) & 0xff) : SQLITE_NOMEM;
    if (primary == SQLITE_NOTADB || primary == SQLITE_CORRUPT) return db;
    sqlite3_close(db);
    return nullptr;
}

}  // namespace

namespace {

/// What is at `st` when it is no regular file, in a message's words.
const char* kind_of(const struct stat& st, bool dangling) {
    return dangling               ? "a link to nothing"
           : S_ISFIFO(st.st_mode) ? "a FIFO"
           : S_ISDIR(st.st_mode)  ? "a folder"
           : S_ISCHR(st.st_mode)  ? "a character device"
           : S_ISBLK(st.st_mode)  ? "a block device"
           : S_ISSOCK(st.st_mode) ? "a socket"
                                  : "not a file";
}

}  // namespace

void check_store_files(const std::string& path) {
    for (const char* suffix : {"-journal", "-wal", "-shm"}) {
        const std::string file = path + suffix;
        struct stat link {};
        if (::lstat(file.c_str(), &link) != 0) continue;  // absent: SQLite makes it when it needs one
        struct stat st {};
        const bool dangling = ::stat(file.c_str(), &st) != 0;
        if (!dangling && S_ISREG(st.st_mode)) continue;
        throw InputError(file + ": not a regular file (" + kind_of(st, dangling) +
                         "): SQLite keeps the store's journal there; remove it to use the store");
    }
}

void require_store_file(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode)) return;
    struct stat link {};
    require(::lstat(path.c_str(), &link) == 0, path, "no such store");
    const bool dangling = ::stat(path.c_str(), &st) != 0;
    throw InputError(path + ": not a regular file (" + kind_of(st, dangling) + "): a store is an SQLite file");
}

std::string read_only_uri(const std::string& path) {
    check_store_files(path);
    std::string why;
    const std::string ro = uri_of(path) + "?mode=ro";
    if (sqlite3* db = try_open(ro, why)) {
        sqlite3_close(db);
        return ro;
    }
    if (holds_content(path + "-wal") || holds_content(path + "-journal"))
        throw InputError(path + ": cannot read the store (" + why + "): its changes in " + path +
                         (holds_content(path + "-wal") ? "-wal" : "-journal") +
                         " are not in the file yet, and SQLite cannot open them here (a read-only folder or file "
                         "system); open the store once where its folder can be written, or copy it with that file "
                         "to such a folder");
    // Nothing outside the file: it is the whole store, read as a file that does not change.
    const std::string immutable = uri_of(path) + "?immutable=1";
    if (sqlite3* db = try_open(immutable, why)) {
        sqlite3_close(db);
        return immutable;
    }
    throw InputError(path + ": cannot read the store (" + why + ")");
}

sqlite3* open_read_only(const std::string& path) {
    const std::string uri = read_only_uri(path);
    std::string why;
    if (sqlite3* db = try_open(uri, why)) return db;
    throw InputError(path + ": cannot read the store (" + why + ")");
}

namespace {
/// A trace column, [e0, f0, e1, f1, ...] (null: +inf): evaluations whole, increasing, within the
/// run's; the best values never increasing. NULL reads as no trace.
std::vector<TracePoint> trace(const Query& q, int i, const char* column, std::int64_t run_evaluations) {
    std::vector<TracePoint> out;
    if (q.is_null(i)) return out;
    const auto flat = q.list<double>(i, column);
    if (flat.size() % 2 != 0)
        q.fail(column, fmt::format("expected pairs of evaluations and values, got {} numbers", flat.size()));
    for (std::size_t k = 0; k < flat.size(); k += 2) {
        const double e = flat[k];
        if (!(e >= 1 && e <= static_cast<double>(run_evaluations) && e == std::floor(e)))
            q.fail(column, fmt::format("expected evaluations in [1, {}] (the run's), got {}", run_evaluations, e));
        const TracePoint t{static_cast<std::int64_t>(e), flat[k + 1]};
        if (!out.empty() && (t.evaluations <= out.back().evaluations || t.best > out.back().best))
            q.fail(column, fmt::format("expected increasing evaluations and values that never increase, got ({}, {}) "
                                       "after ({}, {})",
                                       t.evaluations, t.best, out.back().evaluations, out.back().best));
        out.push_back(t);
    }
    return out;
}
}  // namespace

namespace {
/// A constrained problem's run: its violation (at least 0; +inf when no point had a finite one) and
/// first feasible evaluation (within the run's, present exactly when its best is feasible), read
/// from columns `i` and `i + 1`; an infeasible best moved from `best` to `infeasible_f`.
void constrained(const Query& q, int i, StoredRun& r) {
    if (q.is_null(i)) {
        if (!q.is_null(i + 1))
            q.fail("first_feasible", "expected NULL where best_violation is NULL (a problem without constraints)");
        return;
    }
    const double v = q.raw_double(i, "best_violation");
    if (!(v >= 0)) q.fail("best_violation", fmt::format("expected a violation of at least 0, got {}", v));
    r.best_violation = v;
    r.first_feasible = q.optional_integer(i + 1, "first_feasible", 1);
    if (r.first_feasible && *r.first_feasible > r.evaluations)
        q.fail("first_feasible",
               fmt::format("expected at most the run's {} evaluations, got {}", r.evaluations, *r.first_feasible));
    if ((v == 0) != r.first_feasible.has_value())
        q.fail("first_feasible", v == 0 ? std::string("expected the evaluation that found the feasible best, got NULL")
                                        : fmt::format("expected NULL for a run whose best is infeasible (violation "
                                                      "{}), got {}",
                                                      v, *r.first_feasible));
    if (v > 0) {
        r.infeasible_f = r.best;
        r.best.reset();
    }
}

/// read_store, and check_store with `keep_runs` false (its runs checked, not kept: a store of any
/// size is checked in the memory of one run).
CampaignStore read_checked(const std::string& path, bool keep_runs) {
    require_store_file(path);
    check_length(path);
    const Connection db(path);
    const auto tables = names(db, "SELECT name FROM sqlite_master WHERE type = 'table'");
    if (!keep_runs && tables.empty()) return {};
    if (!tables.count("campaign") && !tables.count("runs"))
        throw InputError(path + ": not a campaign store (it has no campaign and no runs table)");
    {
        Query q(db, "PRAGMA user_version");
        q.where = "the store's schema version";
        const std::int64_t version =
            q.next() ? q.integer(0, "user_version", std::numeric_limits<std::int64_t>::min()) : 0;
        if (version > storage::schema_version)
            throw InputError(
                fmt::format("{}: was written by a newer pride (store schema {}; this pride knows 0 to {}); "
                            "use that pride",
                            path, version, storage::schema_version));
    }
    for (const char* table : {"campaign", "runs"})
        if (!tables.count(table)) throw DamagedStore(path, fmt::format("it has no table {}", table));
    const auto columns = [&](const char* table, std::initializer_list<const char*> wanted) {
        const auto have = names(db, "SELECT name FROM pragma_table_info(?)", table);
        for (const char* c : wanted)
            if (!have.count(c)) throw DamagedStore(path, fmt::format("table {} has no column {}", table, c));
        return have;
    };
    const auto campaign_columns = columns("campaign", {"id", "name"});
    const bool has_target = campaign_columns.count("target") > 0;
    const bool has_precisions = campaign_columns.count("precisions") > 0;
    const bool has_target_precision = campaign_columns.count("target_precision") > 0;
    const auto run_columns = columns("runs", {"problem", "algorithm", "seed", "best", "evaluations", "wall_ms",
                                              "optimum", "history", "history_evaluations"});
    const bool has_hits = run_columns.count("target_hits") > 0;
    // Stores written before the problems table existed are still read: the report needs none of
    // it; the IOH export asks for it.
    const bool has_problems = tables.count("problems") > 0;
    std::set<std::string> problem_columns;
    if (has_problems) problem_columns = columns("problems", {"id", "dim"});
    // A column of the suite extension, or NULL in a store from before it.
    const auto optional_column = [](const std::set<std::string>& have, const char* c) {
        return have.count(c) ? std::string(c) : std::string("NULL");
    };

    CampaignStore store;
    if (tables.count("algorithms")) {
        const auto algorithm_columns = columns("algorithms", {"id", "evaluates"});
        Query q(db, fmt::format("SELECT rowid, id, evaluates, {} FROM algorithms ORDER BY rowid",
                                optional_column(algorithm_columns, "reproducible"))
                        .c_str());
        while (q.next()) {
            q.where = fmt::format("algorithms row with rowid {}",
                                  q.integer(0, "rowid", std::numeric_limits<std::int64_t>::min()));
            const std::string id = q.text(1, "id");
            if (q.integer(2, "evaluates", 0) == 0) store.whole_map_algorithms.insert(id);
            if (q.optional_integer(3, "reproducible", 0) == 0) store.unreproducible_algorithms.insert(id);
        }
    }
    if (tables.count("published")) {
        columns("published", {"algorithm", "format", "source", "sha256", "citation"});
        Query q(db, "SELECT algorithm, format, source, sha256, citation FROM published ORDER BY algorithm");
        while (q.next()) {
            q.where = "the published row";
            PublishedSource p;
            p.algorithm = q.text(0, "algorithm");
            q.where = fmt::format("published row '{}'", p.algorithm);
            if (p.algorithm.rfind(kPublishedPrefix, 0) != 0)
                q.fail("algorithm", fmt::format("expected an id starting with '{}'", kPublishedPrefix));
            p.format = q.text(1, "format");
            p.source = q.text(2, "source");
            p.sha256 = q.text(3, "sha256");
            p.citation = q.text(4, "citation");
            store.published.emplace(p.algorithm, std::move(p));
        }
    }
    {
        Query q(db,
                fmt::format("SELECT name, {}, {}, {} FROM campaign WHERE id = 1", has_target ? "target" : "NULL",
                            has_precisions ? "precisions" : "NULL", has_target_precision ? "target_precision" : "NULL")
                    .c_str());
        q.where = "the campaign row";
        if (!q.next()) throw DamagedStore(path, "table campaign has no row with id 1");
        store.name = q.text(0, "name");
        store.target = q.optional_number(1, "target");
        store.target_precision = q.optional_number(3, "target_precision");
        if (store.target_precision && !(*store.target_precision > 0))
            q.fail("target_precision", fmt::format("expected a number > 0, got {}", *store.target_precision));
        if (!q.is_null(2)) {
            // A JSON list of finite numbers, each at least 0 (null would read as +inf).
            auto precisions = q.list<double>(2, "precisions");
            for (const double p : precisions)
                if (!std::isfinite(p) || p < 0)
                    q.fail("precisions", fmt::format("expected a JSON list of numbers of at least 0, got {}", p));
            store.precisions = std::move(precisions);
        }
    }
    std::set<std::string> problem_ids;
    if (has_problems) {
        const std::string sql =
            fmt::format("SELECT rowid, id, dim, {}, {}, {}, {}, {} FROM problems ORDER BY rowid",
                        optional_column(problem_columns, "function"), optional_column(problem_columns, "instance"),
                        optional_column(problem_columns, "f_opt"), optional_column(problem_columns, "suite"),
                        optional_column(problem_columns, "fid"));
        Query q(db, sql.c_str());
        store.problems.emplace();
        while (q.next()) {
            q.where = fmt::format("problems row with rowid {}",
                                  q.integer(0, "rowid", std::numeric_limits<std::int64_t>::min()));
            StoredProblem p;
            p.id = q.text(1, "id");
            q.where = fmt::format("problems row '{}'", p.id);
            p.dim = q.integer(2, "dim", 1);
            p.function = q.optional_text(3, "function");
            p.instance = q.optional_integer(4, "instance", 0).value_or(0);
            p.f_opt = q.optional_number(5, "f_opt");
            p.suite = q.optional_text(6, "suite");
            p.fid = q.optional_integer(7, "fid", 1);
            problem_ids.insert(p.id);
            store.problems->push_back(std::move(p));
        }
    }
    // The path metrics by SQLite's JSON functions, NULL where absent (a store from before them, a
    // run without a path) or not valid JSON.
    std::string path_metrics;
    const std::string metrics_column = optional_column(run_columns, "path_metrics");
    for (const char* key : kPathMetricNames)
        path_metrics +=
            fmt::format(", CASE WHEN json_valid({0}) THEN json_extract({0}, '$.{1}') END", metrics_column, key);
    Query q(db, fmt::format(
                    "SELECT rowid, problem, algorithm, seed, best, evaluations, wall_ms, optimum, history, "
                    "history_evaluations, {}, {}, {}, {}, {}, {}, substr(solution, 1, 1) = '{{', "
                    // A front's indicators, by SQLite's JSON functions; NULL for a solution that is not
                    // valid JSON (a damaged or hand-made store), which then has no row of fronts.
                    "CASE WHEN substr(solution, 1, 1) = '{{' AND json_valid(solution) THEN json_extract(solution, "
                    "'$.igd_plus') END, CASE WHEN substr(solution, 1, 1) = '{{' AND json_valid(solution) THEN "
                    "json_extract(solution, '$.exact_found') END, CASE WHEN substr(solution, 1, 1) = '{{' AND "
                    "json_valid(solution) THEN json_extract(solution, '$.front') END{}, {}, {}, {}, "
                    // A box run's best point: a list of numbers (null for a coordinate not finite);
                    // a path is a list of lists, a front an object.
                    "CASE WHEN substr(solution, 1, 1) = '[' AND json_valid(solution) AND json_type(solution, '$[0]') "
                    "IN ('integer', 'real', 'null') THEN solution END FROM runs ORDER BY problem, algorithm, seed",
                    has_hits ? "target_hits" : "NULL", optional_column(run_columns, "encoding"),
                    optional_column(run_columns, "trace_targets"), optional_column(run_columns, "trace_evaluations"),
                    optional_column(run_columns, "max_evaluations"), optional_column(run_columns, "checkpoints"),
                    path_metrics, optional_column(run_columns, "best_violation"),
                    optional_column(run_columns, "first_feasible"), optional_column(run_columns, "iterations"))
                    .c_str());
    while (q.next()) {
        // Named by rowid until its key is read, then by the key.
        constexpr auto any = std::numeric_limits<std::int64_t>::min();
        q.where = fmt::format("runs row with rowid {}", q.integer(0, "rowid", any));
        StoredRun r;
        r.problem = q.text(1, "problem");
        r.algorithm = q.text(2, "algorithm");
        r.seed = q.integer(3, "seed", any);
        q.where = fmt::format("runs row (problem '{}', algorithm '{}', seed {})", r.problem, r.algorithm, r.seed);
        r.best = q.optional_number(4, "best");
        r.evaluations = q.integer(5, "evaluations", 0);
        r.wall_ms = q.number(6, "wall_ms");
        r.optimum = q.optional_number(7, "optimum");
        r.history = q.list<double>(8, "history");
        r.history_evaluations = q.list<std::int64_t>(9, "history_evaluations");
        if (!r.history_evaluations.empty() && r.history_evaluations.size() != r.history.size())
            q.fail("history_evaluations", fmt::format("expected one count per value of history ({}), got {}",
                                                      r.history.size(), r.history_evaluations.size()));
        if (!q.is_null(10)) {
            r.target_hits = q.list<std::optional<std::int64_t>>(10, "target_hits");
            const std::size_t wanted = store.precisions ? store.precisions->size() : 0;
            if (!r.target_hits.empty() && r.target_hits.size() != wanted)
                q.fail("target_hits", store.precisions
                                          ? fmt::format("expected one entry per precision of the campaign ({}), got {}",
                                                        wanted, r.target_hits.size())
                                          : fmt::format("expected no entries (the campaign records no precisions), "
                                                        "got {}",
                                                        r.target_hits.size()));
            for (const auto& hit : r.target_hits)
                if (hit && *hit > r.evaluations)
                    q.fail("target_hits",
                           fmt::format("expected at most the run's {} evaluations, got {}", r.evaluations, *hit));
        }
        if (!q.is_null(11)) r.encoding = q.text(11, "encoding");
        r.trace_targets = trace(q, 12, "trace_targets", r.evaluations);
        r.trace_evaluations = trace(q, 13, "trace_evaluations", r.evaluations);
        r.max_evaluations = q.optional_integer(14, "max_evaluations", 1);
        // Whole-map planners' work is no evaluation (stores before they recorded no budget for them).
        if (r.max_evaluations && *r.max_evaluations < r.evaluations && !store.whole_map_algorithms.count(r.algorithm))
            q.fail("max_evaluations", fmt::format("expected at least the run's {} evaluations, got {}", r.evaluations,
                                                  *r.max_evaluations));
        r.checkpoints = trace(q, 15, "checkpoints", r.evaluations);
        r.front = q.integer(16, "solution", 0) == 1;
        if (r.front) {
            r.igd_plus = q.optional_number(17, "solution: igd_plus");
            r.exact_found = q.optional_integer(18, "solution: exact_found", 0);
            if (!q.is_null(19)) r.front_json = q.text(19, "solution: front");
        }
        if (metrics_column != "NULL") {
            r.path_metrics.resize(std::size(kPathMetricNames));
            bool any = false;
            for (std::size_t k = 0; k < r.path_metrics.size(); ++k) {
                r.path_metrics[k] = q.optional_number(20 + static_cast<int>(k),
                                                      (std::string("path_metrics: ") + kPathMetricNames[k]).c_str());
                any = any || r.path_metrics[k].has_value();
            }
            if (!any) r.path_metrics.clear();
        }
        constexpr int violation_column = 20 + static_cast<int>(std::size(kPathMetricNames));
        constrained(q, violation_column, r);
        r.iterations = q.optional_integer(violation_column + 2, "iterations", 0);
        if (!q.is_null(violation_column + 3)) {
            r.best_x = q.list<double>(violation_column + 3, "solution");
            for (double& x : r.best_x)
                if (std::isinf(x)) x = std::numeric_limits<double>::quiet_NaN();  // null: not finite
        }
        // The analysis of target hits (experiment/report/coco.hpp) needs each run's function and
        // dimension; a store without the problems table gets no analysis.
        if (store.precisions && has_problems && !problem_ids.count(r.problem))
            q.fail("problem", fmt::format("'{}' is not in table problems (the analysis of target hits needs its "
                                          "function and dimension)",
                                          r.problem));
        if (keep_runs) store.runs.push_back(std::move(r));
    }
    if (!keep_runs) {
        // Pages the queries above never read (free pages, the claims, an index's inner pages):
        // a damaged one would fail some later write, or a lookup would miss a stored run.
        Query check(db, "PRAGMA quick_check(1)");
        check.where = "SQLite's quick_check";
        if (check.next()) {
            const std::string verdict = check.text(0, "quick_check");
            if (verdict != "ok") throw DamagedStore(path, "SQLite's quick_check: " + verdict);
        }
    }
    return store;
}

}  // namespace

CampaignStore read_store(const std::string& path) {
    return read_checked(path, true);
}

void check_store(const std::string& path) {
    read_checked(path, false);
}

}  // namespace pride::storage

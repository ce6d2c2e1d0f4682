#include "experiment/storage/merge.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sqlite3.h>
#include <stdio.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <map>
#include <optional>
#include <set>

#include "experiment/storage/digest.hpp"
#include "experiment/storage/reader.hpp"
#include "experiment/storage/schema.hpp"
#include "framework/error.hpp"

namespace pride::storage {
namespace {

/// One SQLite connection, closed on every path.
class Db {
  public:
    /// `name` is the store as the user named it, for messages; `file` what SQLite opens.
    Db(const std::string& file, int flags, const std::string& name) : path_(name) {
        if (sqlite3_open_v2(file.c_str(), &db_, flags, nullptr) != SQLITE_OK) {
            const std::string why = db_ ? sqlite3_errmsg(db_) : "out of memory";
            sqlite3_close(db_);
            throw InputError(name + ": cannot open the store: " + why);
        }
        sqlite3_busy_timeout(db_, 30000);
    }
    ~Db() { sqlite3_close(db_); }
    Db(const Db&) = delete;
    Db& operator=(const Db&) = delete;

    void exec(const std::string& sql) {
        char* error = nullptr;
        if (sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, &error) != SQLITE_OK) {
            const std::string why = error ? error : sqlite3_errmsg(db_);
            sqlite3_free(error);
            throw InputError(path_ + ": " + why);
        }
    }
    /// Rows of text (NULL as nullopt).
    std::vector<std::vector<std::optional<std::string>>> rows(const std::string& sql) {
        sqlite3_stmt* s = nullptr;
        if (sqlite3_prepare_v2(db_, sql.c_str(), -1, &s, nullptr) != SQLITE_OK)
            throw InputError(path_ + ": " + sqlite3_errmsg(db_));
        std::vector<std::vector<std::optional<std::string>>> out;
        int rc;
        while ((rc = sqlite3_step(s)) == SQLITE_ROW) {
            auto& row = out.emplace_back();
            for (int i = 0; i < sqlite3_column_count(s); ++i)
                row.push_back(
                    sqlite3_column_type(s, i) == SQLITE_NULL
                        ? std::nullopt
                        : std::optional<std::string>(reinterpret_cast<const char*>(sqlite3_column_text(s, i))));
        }
        sqlite3_finalize(s);
        if (rc != SQLITE_DONE) throw InputError(path_ + ": " + sqlite3_errmsg(db_));
        return out;
    }
    sqlite3* get() { return db_; }

  private:
    std::string path_;
    sqlite3* db_ = nullptr;
};

/// The merged store until it is whole: a new hidden file beside `out`
/// (".NAME.pride-merge-PID-N.tmp"), created exclusively, so never a file that was there before;
/// removed with SQLite's files beside it unless committed, which renames it to `out` without
/// replacing anything found there meanwhile.
class Temporary {
  public:
    explicit Temporary(const std::string& out) : out_(out) {
        namespace fs = std::filesystem;
        const fs::path target(out);
        fs::path folder = target.parent_path();
        if (folder.empty()) folder = ".";
        for (unsigned n = 0;; ++n) {
            path_ =
                (folder / fmt::format(".{}.pride-merge-{}-{}.tmp", target.filename().string(), ::getpid(), n)).string();
            const int fd = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0666);
            if (fd >= 0) {
                ::close(fd);
                break;
            }
            // A folder the user cannot write is the user's error: one line, exit 2.
            if (errno != EEXIST || n >= 1000)
                throw InputError(out + ": cannot write the merged store: " + std::strerror(errno));
        }
        try {
            check_store_files(path_);  // nothing planted where SQLite will keep its journal
        } catch (...) {
            std::error_code ec;
            fs::remove(path_, ec);
            throw;
        }
    }
    ~Temporary() {
        if (!committed_) remove();
    }
    Temporary(const Temporary&) = delete;
    Temporary& operator=(const Temporary&) = delete;

    /// The file as SQLite opens it with SQLITE_OPEN_URI: a plain name, never read as a URI.
    std::string sqlite_name() const { return path_.rfind('/', 0) == 0 ? path_ : "./" + path_; }

    void remove() const {
        std::error_code ec;
        for (const char* suffix : {"-journal", "-wal", "-shm", ""}) std::filesystem::remove(path_ + suffix, ec);
    }

    /// Renamed to `out`, refused (and removed) when `out` has appeared meanwhile.
    void commit() {
        int rc = ::renameat2(AT_FDCWD, path_.c_str(), AT_FDCWD, out_.c_str(), RENAME_NOREPLACE);
        if (rc != 0 && (errno == EINVAL || errno == ENOSYS)) {  // a file system without it: a hard link
            rc = ::link(path_.c_str(), out_.c_str());
            if (rc == 0) ::unlink(path_.c_str());
        }
        if (rc != 0) {
            const int e = errno;
            remove();
            throw InputError(
                out_ + ": cannot write the store: " +
                (e == EEXIST ? std::string("it was made meanwhile by another program") : std::strerror(e)));
        }
        committed_ = true;
        std::error_code ec;
        for (const char* suffix : {"-journal", "-wal", "-shm"}) std::filesystem::remove(path_ + suffix, ec);
    }

  private:
    std::string out_, path_;
    bool committed_ = false;
};

std::string text(const std::optional<std::string>& v) {
    return v.value_or("NULL");
}

std::string quoted(const std::string& s) {
    std::string out = "'";
    for (const char c : s) out += c == '\'' ? std::string("''") : std::string(1, c);
    return out + "'";
}

/// The columns of `table` in schema `schema` (main, or an attached input), in order.
std::vector<std::string> columns(Db& db, const std::string& schema, const std::string& table) {
    std::vector<std::string> out;
    for (const auto& row : db.rows("SELECT name FROM " + schema + ".pragma_table_info(" + quoted(table) + ")"))
        out.push_back(*row[0]);
    return out;
}

std::string joined(const std::vector<std::string>& names, const std::string& prefix = "") {
    std::string s;
    for (const auto& n : names) s += (s.empty() ? "" : ", ") + prefix + n;
    return s;
}

}  // namespace

MergeSummary merge_stores(const std::vector<std::string>& inputs, const std::string& out) {
    require(inputs.size() >= 2, "merge", "give two stores or more to merge");
    {
        std::error_code ec;
        require(std::filesystem::symlink_status(out, ec).type() == std::filesystem::file_type::not_found, out,
                "exists already; merge writes a new store (choose another --out)");
    }
    for (const auto& in : inputs) require_store_file(in);
    // One file named twice (under the same name or another: a link, another path) would count its
    // runs twice.
    std::map<std::pair<dev_t, ino_t>, std::string> seen;
    for (const auto& in : inputs) {
        struct stat st {};
        if (::stat(in.c_str(), &st) != 0) throw InputError(in + ": cannot read the store: " + std::strerror(errno));
        const auto [it, fresh] = seen.emplace(std::pair{st.st_dev, st.st_ino}, in);
        if (!fresh)
            throw InputError(in == it->second ? in + ": named twice; give each store once"
                                              : in + ": the same file as " + it->second + "; give each store once");
    }
    // Each input checked as pride report checks it (the same code), then at the current schema
    // (pride bench migrates a store when it opens it): a damaged input is never copied on. Each is
    // opened read-only as report opens it (storage::read_only_uri), so a store in a read-only
    // folder merges as it reports.
    for (const auto& in : inputs) check_store(in);
    std::vector<std::string> uris;
    for (const auto& in : inputs) {
        uris.push_back(read_only_uri(in));
        Db db(uris.back(), SQLITE_OPEN_READONLY | SQLITE_OPEN_URI, in);
        const auto v = db.rows("PRAGMA user_version");
        const int version = v.empty() ? 0 : std::stoi(*v[0][0]);
        if (db.rows("SELECT 1 FROM sqlite_master WHERE type = 'table' AND name = 'campaign'").empty())
            throw InputError(in + ": not a campaign store (it has no campaign table)");
        require(version == schema_version, in,
                fmt::format("has store schema {}, merge reads schema {} (run its campaign with pride bench once to "
                            "migrate it{})",
                            version, schema_version, version > schema_version ? "; or use the newer pride" : ""));
    }
    // The store is written to a new hidden file beside `out`, made here and nowhere else
    // (O_EXCL), and renamed to `out` only when whole: no file the user did not name as the output
    // is ever removed or written, whatever lies beside it.
    Temporary part(out);
    MergeSummary summary;
    try {
        {
            // The first input, copied whole (SQLite's backup: a consistent copy, WAL included).
            Db source(uris[0], SQLITE_OPEN_READONLY | SQLITE_OPEN_URI, inputs[0]);
            Db target(part.sqlite_name(), SQLITE_OPEN_READWRITE | SQLITE_OPEN_URI, out);
            sqlite3_backup* b = sqlite3_backup_init(target.get(), "main", source.get(), "main");
            if (!b) throw InputError(out + ": cannot write the store: " + sqlite3_errmsg(target.get()));
            const int rc = sqlite3_backup_step(b, -1);
            sqlite3_backup_finish(b);
            if (rc != SQLITE_DONE) throw InputError(out + ": cannot write the store: " + sqlite3_errstr(rc));
        }
        Db db(part.sqlite_name(), SQLITE_OPEN_READWRITE | SQLITE_OPEN_URI, out);
        db.exec("DELETE FROM claims");  // runs another process had taken: not results
        const auto campaign = db.rows("SELECT budget, precisions FROM campaign WHERE id = 1");
        require(!campaign.empty(), inputs[0], "has no campaign row");
        const auto run_columns = columns(db, "main", "runs");
        std::vector<std::string> compared;  // every column of a run but its key and its wall time
        for (const auto& c : run_columns)
            if (c != "problem" && c != "algorithm" && c != "seed" && c != "wall_ms") compared.push_back(c);
        std::set<std::string> keys_seen;
        for (const auto& row : db.rows("SELECT problem, algorithm, seed FROM runs"))
            keys_seen.insert(*row[0] + '\x1f' + *row[1] + '\x1f' + *row[2]);
        for (std::size_t k = 1; k < inputs.size(); ++k) {
            const std::string& in = inputs[k];
            const std::string& uri = uris[k];
            db.exec("ATTACH DATABASE " + quoted(uri) + " AS b");
            try {
                const auto other = db.rows("SELECT budget, precisions FROM b.campaign WHERE id = 1");
                require(!other.empty(), in, "has no campaign row");
                if (other[0][0] != campaign[0][0])
                    throw InputError(
                        fmt::format("{}: its runs have the budget '{}', those of {} '{}'; runs of "
                                    "different budgets are not merged",
                                    in, text(other[0][0]), inputs[0], text(campaign[0][0])));
                if (other[0][1] != campaign[0][1])
                    throw InputError(fmt::format("{}: records the target precisions {}, {} records {}", in,
                                                 text(other[0][1]), inputs[0], text(campaign[0][1])));
                for (const char* table : {"problems", "algorithms"}) {
                    const auto differ = db.rows(fmt::format(
                        "SELECT o.id, o.definition, m.definition FROM b.{0} o JOIN main.{0} m ON o.id = m.id "
                        "WHERE o.definition IS NOT m.definition OR o.definition IS NULL LIMIT 1",
                        table));
                    if (!differ.empty())
                        throw InputError(
                            fmt::format("{}: {} '{}' is defined as {} there and as {} in {}; stores "
                                        "whose runs differ in definition are not merged",
                                        in, table == std::string("problems") ? "problem" : "algorithm",
                                        text(differ[0][0]), text(differ[0][1]), text(differ[0][2]), inputs[0]));
                    // The same definition may name maps whose content differs (edited between
                    // the campaigns, or given in code): the digests (schema 3) must agree too.
                    if (table == std::string("problems")) {
                        const auto other_content = db.rows(
                            "SELECT o.id, o.digest, m.digest FROM b.problems o JOIN main.problems m ON o.id = m.id "
                            "WHERE o.digest IS NOT NULL AND m.digest IS NOT NULL AND o.digest <> m.digest LIMIT 1");
                        if (!other_content.empty())
                            throw InputError(fmt::format(
                                "{}: problem '{}' {} in {}; stores whose runs are of different problems are not "
                                "merged",
                                in, text(other_content[0][0]),
                                digest_difference(*other_content[0][2], *other_content[0][1]), inputs[0]));
                    }
                    const auto cols = columns(db, "main", table);
                    db.exec(
                        fmt::format("INSERT INTO main.{0} ({1}) SELECT {1} FROM b.{0} WHERE id NOT IN (SELECT id "
                                    "FROM main.{0})",
                                    table, joined(cols)));
                }
                // Published algorithms (published.hpp): one id, one source; their algorithms' rows,
                // whose definitions name the source's SHA-256, were compared above.
                {
                    const auto differ = db.rows(
                        "SELECT o.algorithm, o.source, o.sha256, m.source, m.sha256 FROM b.published o JOIN "
                        "main.published m ON o.algorithm = m.algorithm WHERE o.sha256 <> m.sha256 OR o.citation <> "
                        "m.citation OR o.format <> m.format LIMIT 1");
                    if (!differ.empty())
                        throw InputError(fmt::format(
                            "{}: published algorithm '{}' comes from {} (SHA-256 {}) there and from {} (SHA-256 {}) "
                            "in {}; stores whose published runs differ are not merged",
                            in, text(differ[0][0]), text(differ[0][1]), text(differ[0][2]), text(differ[0][3]),
                            text(differ[0][4]), inputs[0]));
                    db.exec(
                        "INSERT INTO main.published (algorithm, format, source, sha256, citation) SELECT algorithm, "
                        "format, source, sha256, citation FROM b.published WHERE algorithm NOT IN (SELECT algorithm "
                        "FROM main.published)");
                }
                // A run in both must be the same run: every column but the wall time, bit for bit;
                // a run of an algorithm registered as not reproducible (AlgorithmEntry::reproducible:
                // OMPL's planners) by its definition alone, its values kept from the first store.
                std::string unequal;
                for (const auto& c : compared)
                    unequal += (unequal.empty() ? "" : " OR ") + ("o." + c + " IS NOT m." + c);
                const auto algorithm_columns = columns(db, "main", "algorithms");
                if (std::find(algorithm_columns.begin(), algorithm_columns.end(), "reproducible") !=
                    algorithm_columns.end())
                    unequal = "(" + unequal +
                              ") AND o.algorithm NOT IN (SELECT id FROM main.algorithms WHERE reproducible = 0)";
                const auto differ = db.rows(
                    "SELECT o.problem, o.algorithm, o.seed FROM b.runs o JOIN main.runs m ON "
                    "o.problem = m.problem AND o.algorithm = m.algorithm AND o.seed = m.seed "
                    "WHERE " +
                    unequal + " ORDER BY o.problem, o.algorithm, o.seed LIMIT 1");
                if (!differ.empty())
                    throw InputError(
                        fmt::format("{}: run (problem '{}', algorithm '{}', seed {}) differs from the "
                                    "same run in {}; stores whose runs differ are not merged",
                                    in, text(differ[0][0]), text(differ[0][1]), text(differ[0][2]), inputs[0]));
                for (const auto& row : db.rows("SELECT problem, algorithm, seed FROM b.runs"))
                    if (!keys_seen.insert(*row[0] + '\x1f' + *row[1] + '\x1f' + *row[2]).second) ++summary.shared;
                db.exec(
                    fmt::format("INSERT INTO main.runs ({0}) SELECT {1} FROM b.runs o WHERE NOT EXISTS (SELECT 1 "
                                "FROM main.runs m WHERE m.problem = o.problem AND m.algorithm = o.algorithm AND "
                                "m.seed = o.seed)",
                                joined(run_columns), joined(run_columns, "o.")));
            } catch (...) {
                db.exec("DETACH DATABASE b");
                throw;
            }
            db.exec("DETACH DATABASE b");
        }
        summary.runs = keys_seen.size();
        db.exec("PRAGMA wal_checkpoint(TRUNCATE)");
    } catch (...) {
        part.remove();
        throw;
    }
    part.commit();
    return summary;
}

}  // namespace pride::storage

#pragma once
// The SQLite store as a campaign writes it: the campaign itself, its problems and algorithms, one
// row per finished run (committed in batches: a finished run is never lost once its batch
// returns), and the claims by which several processes on one store share its runs. The reader
// (reader.hpp) reads it back.
#include <sys/types.h>

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "experiment/storage/published.hpp"
#include "experiment/storage/rows.hpp"

struct sqlite3;
struct sqlite3_stmt;

namespace pride::storage {

class Writer {
  public:
    explicit Writer(const std::string& path);
    ~Writer();
    Writer(const Writer&) = delete;
    Writer& operator=(const Writer&) = delete;

    const std::string& path() const { return path_; }

    /// Records the campaign, or checks that the store holds this very campaign. A store that
    /// holds no run yet (a campaign that failed before its first) takes the new campaign.
    void claim(const CampaignRows& c);

    std::set<RunKey> done();

    /// Takes, in one transaction, the first runs of `keys[from...]` that are neither stored nor
    /// taken by another live process, up to `wanted`; returns the positions taken and sets `from`
    /// past the last one looked at. Positions that another live process holds go to `busy`.
    std::vector<std::size_t> take(const std::vector<RunKey>& keys, std::size_t& from, std::size_t wanted,
                                  std::vector<std::size_t>& busy);

    /// Drops the claims of processes that are no longer running; true when there were any.
    bool drop_dead_claims();

    /// Finished runs in one transaction with the release of their claims: once this returns, a
    /// kill cannot lose them. A run another process stored meanwhile (same inputs, same values)
    /// is kept once. Returns the number of rows added.
    std::size_t insert(const std::vector<RunRecord>& records);
    std::size_t insert(const RunRecord& r) { return insert(std::vector<RunRecord>{r}); }

    /// The claims of this process, dropped (runs it took and will not finish).
    void release();

    std::size_t count();

    /// Published runs (published.hpp) added in one transaction, or nothing: refused when the store
    /// holds the algorithm already, when a run's problem (suite, function, dimension, instance) is
    /// stored with another optimum (another instance: not the same protocol), or when the store's
    /// campaign records target precisions other than `precisions` (JSON). A run's problem is the
    /// store's own where it has it (or the one the run names, PublishedRun::problem), else a problem
    /// row of its own ("published:bbob-f6-i3-d20"). A store without a campaign gets one named
    /// "published runs", which no campaign grows.
    ImportSummary import_published(const PublishedSet& set, const std::vector<double>& precisions,
                                   const std::string& precisions_json);

    /// Throws when the store's file is gone or replaced (deleted while a campaign ran: SQLite
    /// would go on writing into the unlinked file, and every result would be lost unseen).
    void check_same_file() const;

  private:
    std::int64_t live_claims();

    /// import_published's body, inside its transaction.
    ImportSummary add_published(const PublishedSet& set, const std::vector<double>& precisions,
                                const std::string& precisions_json);

    int user_version();

    /// The stored definitions of one table's ids (NULL: a store from before definitions).
    std::map<std::string, std::optional<std::string>> definitions(const char* table);

    /// A store that holds runs takes a campaign that only adds to it: the same name and budget,
    /// every stored problem and algorithm id defined as before; new seeds, problems and algorithms
    /// are new runs. The campaign's text and report target become the new file's; the problems
    /// and algorithms it adds are recorded. Anything else is refused, naming what differs.
    void grow(const CampaignRows& c, const std::string& stored_name);

    /// Every problem of `c` stored under its id with another digest (problem_digest: its map's
    /// cells and size, its settings) is refused, naming the id and what differs: the runs
    /// stored are of another problem. A NULL digest (a store from before them) is not compared.
    void check_digests(const CampaignRows& c);

    /// The digests of this campaign's problems, recorded where the store has none (a store from
    /// before them: its problems are taken as they are now, an edit made before cannot be seen).
    /// Nothing is written when none is missing.
    void fill_digests(const CampaignRows& c);

    /// A store written before definitions were kept, resumed with its very campaign: the
    /// definitions are this campaign's, recorded where missing, so that it can grow from now on.
    /// Nothing is written when none is missing (the store's bytes stay).
    void fill_definitions(const CampaignRows& c);

    static void bind_optional(sqlite3_stmt* s, int i, const std::optional<double>& v);

    void record(const CampaignRows& c);

    void record_algorithm(const AlgorithmRow& a);

    /// A problem as resolved here (map paths made absolute), for reports and plots.
    void record_problem(const ProblemRow& p);

    /// A statement prepared once (the ones run per stored run), reset for its next use.
    sqlite3_stmt* cached(sqlite3_stmt*& s, const char* sql);
    void step_cached(sqlite3_stmt* s, const char* doing);

    std::size_t insert_one(const RunRecord& r);

    void add_column(const std::string& table, const std::string& column, const std::string& type);

    /// SQLite's reason, with the system's where it has one ("disk I/O error: No space left on device").
    std::string reason() const;
    [[noreturn]] void fail(const std::string& doing) const;

    void rollback() noexcept;

    /// Switches the store to WAL and makes sure it is: while another process reads the file (the
    /// check of a second bench starting at once, a pride report), SQLite leaves the journal as it
    /// was without waiting and says so only in the mode it returns, and a store left in rollback
    /// mode fails its writers at once with "database is locked" when two write together. Readers
    /// come and go: the switch is retried for up to the busy timeout.
    void journal_wal();

    void exec(const char* sql);
    sqlite3_stmt* prepare(const char* sql);
    void step_done(sqlite3_stmt* s, const char* doing);

    std::string path_;
    std::string token_;
    sqlite3* db_ = nullptr;
    sqlite3_stmt* insert_ = nullptr;  // cached()
    sqlite3_stmt* unclaim_ = nullptr;
    sqlite3_stmt* claim_ = nullptr;  // take()'s two
    sqlite3_stmt* held_ = nullptr;
    dev_t device_ = 0;
    ino_t inode_ = 0;
};

}  // namespace pride::storage

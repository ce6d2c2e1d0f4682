// The Writer's published runs (published.hpp): another author's runs added beside a campaign's, in
// one transaction, on the store's own problems where it has them.
#include <sqlite3.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <tuple>

#include "experiment/storage/writer.hpp"
#include "framework/error.hpp"

namespace pride::storage {
namespace {

std::string column_text(sqlite3_stmt* s, int i) {
    const auto* p = reinterpret_cast<const char*>(sqlite3_column_text(s, i));
    return p ? p : "";
}

/// JSON [e0, f0, e1, f1, ...] of a published trace, its precisions made values again.
std::string trace_json(const std::vector<PublishedPoint>& points, double f_opt) {
    std::string out = "[";
    for (const auto& p : points)
        out += fmt::format("{}{}, {}", out.size() > 1 ? ", " : "", p.evaluations, f_opt + p.precision);
    return out + "]";
}

}  // namespace

ImportSummary Writer::import_published(const PublishedSet& set, const std::vector<double>& precisions,
                                       const std::string& precisions_json) {
    check_same_file();
    exec("BEGIN IMMEDIATE");
    try {
        const ImportSummary summary = add_published(set, precisions, precisions_json);
        exec("COMMIT");
        return summary;
    } catch (...) {
        rollback();
        throw;
    }
}

ImportSummary Writer::add_published(const PublishedSet& set, const std::vector<double>& precisions,
                                    const std::string& precisions_json) {
    const PublishedSource& src = set.source;
    require(
        src.algorithm.rfind(kPublishedPrefix, 0) == 0 && src.algorithm.size() > std::string(kPublishedPrefix).size(),
        "import", "a published algorithm's id is published:NAME, got '" + src.algorithm + "'");
    require(!set.runs.empty(), src.source, "holds no run to import");
    {
        sqlite3_stmt* s = prepare(
            "SELECT (SELECT COUNT(*) FROM algorithms WHERE id = ?1) + (SELECT COUNT(*) FROM runs WHERE algorithm = "
            "?1), (SELECT source || ' (SHA-256 ' || sha256 || ')' FROM published WHERE algorithm = ?1)");
        sqlite3_bind_text(s, 1, src.algorithm.c_str(), -1, SQLITE_TRANSIENT);
        const bool held = sqlite3_step(s) == SQLITE_ROW && sqlite3_column_int64(s, 0) > 0;
        const std::string from = column_text(s, 1);
        sqlite3_finalize(s);
        if (held)
            throw InputError(path_ + ": holds the algorithm '" + src.algorithm + "' already" +
                             (from.empty() ? "" : ", imported from " + from) +
                             "; import under another --name, or into another store; nothing was imported");
    }
    {
        sqlite3_stmt* s = prepare("SELECT precisions FROM campaign WHERE id = 1");
        const int rc = sqlite3_step(s);
        const bool has_campaign = rc == SQLITE_ROW;
        const std::optional<std::string> stored = has_campaign && sqlite3_column_type(s, 0) != SQLITE_NULL
                                                      ? std::optional<std::string>(column_text(s, 0))
                                                      : std::nullopt;
        sqlite3_finalize(s);
        if (!has_campaign) {
            // No campaign yet: one of published runs only, which a campaign file never grows
            // (its name and text are no campaign's).
            sqlite3_stmt* u = prepare(
                "INSERT INTO campaign (id, name, text, target, precisions, target_precision, budget) VALUES (1, "
                "'published runs', '', NULL, ?, NULL, 'published runs only')");
            sqlite3_bind_text(u, 1, precisions_json.c_str(), -1, SQLITE_TRANSIENT);
            step_done(u, "cannot write the store");
        } else if (stored != precisions_json &&
                   std::any_of(set.runs.begin(), set.runs.end(), [](const PublishedRun& r) { return r.runtimes; })) {
            // Runs without runtimes (CEC files) record no target precisions: any store takes them.
            throw InputError(path_ + ": its runs record the target precisions " + stored.value_or("(none)") +
                             ", published runs are read at COCO's 51 (10^2 ... 10^-8); import into a new store; "
                             "nothing was imported");
        }
    }
    ImportSummary summary;
    // (suite, fid, dim, instance) -> the problem's id and optimum, the store's or a new one.
    std::map<std::tuple<std::string, std::int64_t, std::int64_t, std::int64_t>, std::pair<std::string, double>> ids;
    // The same for runs that name the store's problem (PublishedRun::problem), by its id.
    std::map<std::string, std::pair<std::string, double>> named;
    std::vector<RunRecord> records;
    records.reserve(set.runs.size());
    for (const PublishedRun& run : set.runs) {
        const auto key = std::tuple{run.suite, run.fid, run.dim, run.instance};
        auto it = ids.find(key);
        const std::pair<std::string, double>* to = nullptr;
        if (run.problem) {
            // The store's own problem, as the reader of the run's files found it there.
            auto [n, added] = named.emplace(*run.problem, std::pair{*run.problem, run.f_opt});
            summary.problems_matched += added;
            to = &n->second;
        } else if (it == ids.end()) {
            sqlite3_stmt* s = prepare(
                "SELECT id, f_opt FROM problems WHERE suite = ? AND fid = ? AND dim = ? AND instance = ? AND f_opt "
                "IS NOT NULL ORDER BY rowid LIMIT 1");
            sqlite3_bind_text(s, 1, run.suite.c_str(), -1, SQLITE_TRANSIENT);
            sqlite3_bind_int64(s, 2, run.fid);
            sqlite3_bind_int64(s, 3, run.dim);
            sqlite3_bind_int64(s, 4, run.instance);
            std::optional<std::pair<std::string, double>> found;
            if (sqlite3_step(s) == SQLITE_ROW) found.emplace(column_text(s, 0), sqlite3_column_double(s, 1));
            sqlite3_finalize(s);
            if (found) {
                // The same instance has the same optimum: another one means another instance
                // generator (another protocol), whose runs are not the store's problem's.
                if (std::abs(found->second - run.f_opt) > 1e-9 * std::max(1.0, std::abs(found->second)))
                    throw InputError(
                        run.where,
                        fmt::format("{} f{} instance {} in {}-D has f_opt {} here, {} in the store's "
                                    "problem '{}' (another instance: not the same protocol); nothing "
                                    "was imported",
                                    run.suite, run.fid, run.instance, run.dim, run.f_opt, found->second, found->first));
                ++summary.problems_matched;
            } else {
                ProblemRow p;
                // Named as a campaign names its problems: a CEC function has no instance (0).
                p.id = run.instance == 0 ? fmt::format("{}{}-f{}-d{}", kPublishedPrefix, run.suite, run.fid, run.dim)
                                         : fmt::format("{}{}-f{}-i{}-d{}", kPublishedPrefix, run.suite, run.fid,
                                                       run.instance, run.dim);
                p.type = fmt::format("{}-f{}", run.suite, run.fid);
                p.dim = run.dim;
                p.instance = run.instance;
                p.f_opt = run.f_opt;
                p.suite = run.suite;
                p.fid = run.fid;
                p.definition = run.instance == 0
                                   ? fmt::format("published {} f{}, dimension {}", run.suite, run.fid, run.dim)
                                   : fmt::format("published {} f{}, dimension {}, instance {}", run.suite, run.fid,
                                                 run.dim, run.instance);
                p.digest = "published";
                record_problem(p);
                found.emplace(p.id, run.f_opt);
                ++summary.problems_added;
            }
            it = ids.emplace(key, *found).first;
        }
        const auto& [problem, f_opt] = to ? *to : it->second;
        RunRecord& r = records.emplace_back();
        r.problem = problem;
        r.algorithm = src.algorithm;
        r.seed = run.trial;
        r.best = f_opt + run.final_precision;
        r.evaluations = run.evaluations;
        r.solution = "[]";
        r.history = "[";
        r.history_evaluations = "[";
        for (std::size_t k = 0; k < run.history.size() && k < run.history_evaluations.size(); ++k) {
            r.history += fmt::format("{}{:.17g}", k ? ", " : "", run.history[k]);
            r.history_evaluations += fmt::format("{}{}", k ? ", " : "", run.history_evaluations[k]);
        }
        r.history += "]";
        r.history_evaluations += "]";
        r.max_evaluations = run.max_evaluations;
        r.checkpoints = trace_json(run.checkpoints, f_opt);
        r.trace_targets = trace_json(run.targets, f_opt);
        r.trace_evaluations = trace_json(run.values, f_opt);
        if (!run.runtimes) continue;  // target_hits "[]": no runtimes known
        // COCO's runtime to each target: the first .dat line whose best is within it (as cocopp's
        // DataSet.detEvals reads the same lines).
        std::string hits = "[";
        for (std::size_t k = 0; k < precisions.size(); ++k) {
            std::optional<std::int64_t> hit;
            for (const auto& p : run.targets)
                if (p.precision <= precisions[k]) {
                    hit = p.evaluations;
                    break;
                }
            hits += (k ? ", " : "") + (hit ? std::to_string(*hit) : std::string("null"));
        }
        r.target_hits = hits + "]";
    }
    {
        AlgorithmRow a;
        a.id = src.algorithm;
        a.type = "published";
        // What identifies the runs: their source's content and its citation (a merge of two stores
        // with one name for two sources is refused by it).
        a.definition =
            fmt::format("published {} {} sha256 {} cited as {}", src.format, src.source, src.sha256, src.citation);
        record_algorithm(a);
        sqlite3_stmt* s =
            prepare("INSERT INTO published (algorithm, format, source, sha256, citation) VALUES (?, ?, ?, ?, ?)");
        int i = 1;
        for (const std::string* v : {&src.algorithm, &src.format, &src.source, &src.sha256, &src.citation})
            sqlite3_bind_text(s, i++, v->c_str(), -1, SQLITE_TRANSIENT);
        step_done(s, "cannot write the store");
    }
    for (const RunRecord& r : records) {
        if (insert_one(r) != 1)
            throw InputError(path_ + ": run (problem '" + r.problem + "', algorithm '" + r.algorithm + "', trial " +
                             std::to_string(r.seed) + ") is given twice; nothing was imported");
        ++summary.runs;
    }
    return summary;
}

}  // namespace pride::storage

// The Writer's rows of the campaign itself (writer.hpp): its definition, problems and algorithms
// recorded in a new store; in a store that holds runs, the same campaign grown (new seeds, problems
// and algorithms only), its problems' digests checked, and what an older store lacks filled in.
#include <sqlite3.h>

#include <algorithm>
#include <string>

#include "experiment/storage/digest.hpp"
#include "experiment/storage/writer.hpp"
#include "framework/error.hpp"

namespace pride::storage {

std::map<std::string, std::optional<std::string>> Writer::definitions(const char* table) {
    std::map<std::string, std::optional<std::string>> out;
    sqlite3_stmt* s = prepare((std::string("SELECT id, definition FROM ") + table).c_str());
    while (sqlite3_step(s) == SQLITE_ROW)
        out[reinterpret_cast<const char*>(sqlite3_column_text(s, 0))] =
            sqlite3_column_type(s, 1) == SQLITE_NULL
                ? std::nullopt
                : std::optional<std::string>(reinterpret_cast<const char*>(sqlite3_column_text(s, 1)));
    sqlite3_finalize(s);
    return out;
}

void Writer::grow(const CampaignRows& c, const std::string& stored_name) {
    const std::string refuse = "; a campaign grows by seeds, problems and algorithms only (choose another store file)";
    if (stored_name != c.name)
        throw InputError(path_ + ": holds the results of another campaign ('" + stored_name + "', not '" + c.name +
                         "'); choose another store file");
    sqlite3_stmt* s = prepare("SELECT budget FROM campaign WHERE id = 1");
    std::optional<std::string> budget;
    if (sqlite3_step(s) == SQLITE_ROW && sqlite3_column_type(s, 0) != SQLITE_NULL)
        budget = reinterpret_cast<const char*>(sqlite3_column_text(s, 0));
    sqlite3_finalize(s);
    const auto problems = definitions("problems"), algorithms = definitions("algorithms");
    const bool old = !budget ||
                     std::any_of(problems.begin(), problems.end(), [](const auto& p) { return !p.second; }) ||
                     std::any_of(algorithms.begin(), algorithms.end(), [](const auto& a) { return !a.second; });
    if (old)
        throw InputError(path_ + ": holds the results of another campaign ('" + stored_name +
                         "', or an edited version of this file; the store was written before campaigns could "
                         "grow); choose another store file");
    if (*budget != c.budget)
        throw InputError(path_ + ": its runs have the budget '" + *budget + "', this campaign '" + c.budget + "'" +
                         refuse);
    for (const auto& p : c.problems)
        if (const auto it = problems.find(p.id); it != problems.end() && *it->second != p.definition)
            throw InputError(path_ + ": problem '" + p.id + "' is stored as " + *it->second + ", here it is " +
                             p.definition + refuse);
    for (const auto& a : c.algorithms)
        if (const auto it = algorithms.find(a.id); it != algorithms.end() && *it->second != a.definition)
            throw InputError(path_ + ": algorithm '" + a.id + "' is stored as " + *it->second + ", here it is " +
                             a.definition + refuse);
    check_digests(c);
    fill_digests(c);
    s = prepare("UPDATE campaign SET text = ?, target = ?, target_precision = ? WHERE id = 1");
    sqlite3_bind_text(s, 1, c.text.c_str(), -1, SQLITE_TRANSIENT);
    bind_optional(s, 2, c.target);
    bind_optional(s, 3, c.target_precision);
    step_done(s, "cannot write the store");
    for (const auto& a : c.algorithms)
        if (!algorithms.count(a.id)) record_algorithm(a);
    for (const auto& p : c.problems)
        if (!problems.count(p.id)) record_problem(p);
}

void Writer::check_digests(const CampaignRows& c) {
    std::map<std::string, std::string> stored;
    sqlite3_stmt* s = prepare("SELECT id, digest FROM problems WHERE digest IS NOT NULL");
    int rc;
    while ((rc = sqlite3_step(s)) == SQLITE_ROW)
        stored[reinterpret_cast<const char*>(sqlite3_column_text(s, 0))] =
            reinterpret_cast<const char*>(sqlite3_column_text(s, 1));
    sqlite3_finalize(s);
    if (rc != SQLITE_DONE) fail("cannot read the store");
    for (const auto& p : c.problems)
        if (const auto it = stored.find(p.id); it != stored.end() && it->second != p.digest)
            throw InputError(path_ + ": problem '" + p.id + "' " + digest_difference(it->second, p.digest) +
                             "; a store never mixes the runs of two problems under one id (give the problem "
                             "another id, or choose another store file)");
}

void Writer::fill_digests(const CampaignRows& c) {
    sqlite3_stmt* s = prepare("SELECT COUNT(*) FROM problems WHERE digest IS NULL");
    const bool missing = sqlite3_step(s) == SQLITE_ROW && sqlite3_column_int64(s, 0) > 0;
    sqlite3_finalize(s);
    if (!missing) return;
    for (const auto& p : c.problems) {
        sqlite3_stmt* u = prepare("UPDATE problems SET digest = ? WHERE id = ? AND digest IS NULL");
        sqlite3_bind_text(u, 1, p.digest.c_str(), -1, SQLITE_TRANSIENT);
        sqlite3_bind_text(u, 2, p.id.c_str(), -1, SQLITE_TRANSIENT);
        step_done(u, "cannot write the store");
    }
}

void Writer::fill_definitions(const CampaignRows& c) {
    sqlite3_stmt* s = prepare(
        "SELECT (SELECT COUNT(*) FROM campaign WHERE budget IS NULL) + (SELECT COUNT(*) FROM problems WHERE "
        "definition IS NULL) + (SELECT COUNT(*) FROM algorithms WHERE definition IS NULL)");
    const bool missing = sqlite3_step(s) == SQLITE_ROW && sqlite3_column_int64(s, 0) > 0;
    sqlite3_finalize(s);
    fill_digests(c);
    if (!missing) return;
    s = prepare("UPDATE campaign SET budget = ? WHERE budget IS NULL");
    sqlite3_bind_text(s, 1, c.budget.c_str(), -1, SQLITE_TRANSIENT);
    step_done(s, "cannot write the store");
    const auto define = [&](const char* table, const std::string& id, const std::string& definition) {
        sqlite3_stmt* u = prepare(
            (std::string("UPDATE ") + table + " SET definition = ? WHERE id = ? AND definition IS NULL").c_str());
        sqlite3_bind_text(u, 1, definition.c_str(), -1, SQLITE_TRANSIENT);
        sqlite3_bind_text(u, 2, id.c_str(), -1, SQLITE_TRANSIENT);
        step_done(u, "cannot write the store");
    };
    for (const auto& p : c.problems) define("problems", p.id, p.definition);
    for (const auto& a : c.algorithms) define("algorithms", a.id, a.definition);
}

void Writer::record(const CampaignRows& c) {
    sqlite3_stmt* s = prepare(
        "INSERT INTO campaign (id, name, text, target, precisions, target_precision, budget) "
        "VALUES (1, ?, ?, ?, ?, ?, ?)");
    sqlite3_bind_text(s, 1, c.name.c_str(), -1, SQLITE_TRANSIENT);
    sqlite3_bind_text(s, 2, c.text.c_str(), -1, SQLITE_TRANSIENT);
    bind_optional(s, 3, c.target);
    sqlite3_bind_text(s, 4, c.precisions.c_str(), -1, SQLITE_TRANSIENT);
    bind_optional(s, 5, c.target_precision);
    sqlite3_bind_text(s, 6, c.budget.c_str(), -1, SQLITE_TRANSIENT);
    step_done(s, "cannot write the store");
    for (const auto& a : c.algorithms) record_algorithm(a);
    for (const auto& p : c.problems) record_problem(p);
}

void Writer::record_algorithm(const AlgorithmRow& a) {
    sqlite3_stmt* s =
        prepare("INSERT INTO algorithms (id, type, evaluates, definition, reproducible) VALUES (?, ?, ?, ?, ?)");
    sqlite3_bind_text(s, 1, a.id.c_str(), -1, SQLITE_TRANSIENT);
    sqlite3_bind_text(s, 2, a.type.c_str(), -1, SQLITE_TRANSIENT);
    sqlite3_bind_int(s, 3, a.evaluates ? 1 : 0);
    sqlite3_bind_text(s, 4, a.definition.c_str(), -1, SQLITE_TRANSIENT);
    sqlite3_bind_int(s, 5, a.reproducible ? 1 : 0);
    step_done(s, "cannot write the store");
}

void Writer::record_problem(const ProblemRow& p) {
    sqlite3_stmt* s = prepare(
        "INSERT INTO problems (id, type, dim, map, start, goal, function, instance, f_opt, suite, fid, "
        "definition, digest) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
    sqlite3_bind_text(s, 1, p.id.c_str(), -1, SQLITE_TRANSIENT);
    sqlite3_bind_text(s, 2, p.type.c_str(), -1, SQLITE_TRANSIENT);
    sqlite3_bind_int64(s, 3, p.dim);
    sqlite3_bind_text(s, 4, p.map.c_str(), -1, SQLITE_TRANSIENT);
    sqlite3_bind_text(s, 5, p.start.c_str(), -1, SQLITE_TRANSIENT);
    sqlite3_bind_text(s, 6, p.goal.c_str(), -1, SQLITE_TRANSIENT);
    sqlite3_bind_text(s, 7, p.type.c_str(), -1, SQLITE_TRANSIENT);
    sqlite3_bind_int64(s, 8, p.instance);
    bind_optional(s, 9, p.f_opt);
    if (p.suite.empty()) {
        sqlite3_bind_null(s, 10);
        sqlite3_bind_null(s, 11);
    } else {
        sqlite3_bind_text(s, 10, p.suite.c_str(), -1, SQLITE_TRANSIENT);
        sqlite3_bind_int64(s, 11, p.fid);
    }
    sqlite3_bind_text(s, 12, p.definition.c_str(), -1, SQLITE_TRANSIENT);
    sqlite3_bind_text(s, 13, p.digest.c_str(), -1, SQLITE_TRANSIENT);
    step_done(s, "cannot write the store");
}

}  // namespace pride::storage

// Campaigns on problems with constraints: each run's row records its best violation and first
// feasible evaluation (store schema 6) equal to what engine::run gives for the same seed; reports
// add a feasibility table and compare runs by Deb's order; older stores migrate, merges keep the
// columns, and a damaged row is refused naming the column.
#include <sqlite3.h>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "engine/problem.hpp"
#include "engine/run.hpp"
#include "experiment/campaign/identity.hpp"
#include "experiment/report/report.hpp"
#include "experiment/storage/reader.hpp"
#include "experiment/storage/schema.hpp"
#include "tests/cli_runner.hpp"
#include "tests/test_support.hpp"

using Catch::Matchers::Contains;
using pride::test::run_pride;
using pride::test::TempDir;
namespace engine = pride::engine;
namespace storage = pride::storage;
namespace report = pride::report;

namespace {

constexpr std::int64_t kEvaluations = 300;
constexpr int kSeeds = 4;

/// g06 (2-D, two inequality constraints, a thin feasible crescent) under de and pso (both with
/// Deb's rules, their default: a `constraints` parameter would be refused on sphere), and sphere
/// beside it (no constraints: its rows keep NULL). At 300 evaluations de ends feasible on seeds 1,
/// 3 and 4, infeasible on 2, and pso infeasible on all four, so the report has both to order.
std::string campaign(int seeds) {
    return "name = \"con\"\nseeds = " + std::to_string(seeds) +
           "\n[budget]\nevaluations = " + std::to_string(kEvaluations) +
           "\n[[problem]]\nid = \"g06\"\ntype = \"cec2006-g06\"\ndim = 2\n"
           "[[problem]]\nid = \"s\"\ntype = \"sphere\"\ndim = 2\n"
           "[[algorithm]]\nid = \"de\"\ntype = \"de\"\npop = 10\n"
           "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\npop = 10\n";
}

void exec_sql(const std::string& store, const std::string& sql) {
    sqlite3* db = nullptr;
    REQUIRE(sqlite3_open(store.c_str(), &db) == SQLITE_OK);
    char* error = nullptr;
    const int rc = sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &error);
    INFO((error ? error : ""));
    sqlite3_free(error);
    sqlite3_close(db);
    REQUIRE(rc == SQLITE_OK);
}

std::string scalar(const std::string& store, const std::string& sql) {
    sqlite3* db = nullptr;
    REQUIRE(sqlite3_open_v2(store.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK);
    sqlite3_stmt* s = nullptr;
    REQUIRE(sqlite3_prepare_v2(db, sql.c_str(), -1, &s, nullptr) == SQLITE_OK);
    std::string out;
    if (sqlite3_step(s) == SQLITE_ROW && sqlite3_column_type(s, 0) != SQLITE_NULL)
        out = reinterpret_cast<const char*>(sqlite3_column_text(s, 0));
    sqlite3_finalize(s);
    sqlite3_close(db);
    return out;
}

/// A bench of `seeds` seeds into `store`.
void bench(const TempDir& dir, int seeds, const std::string& store) {
    const std::string toml = dir.write("c" + std::to_string(seeds) + ".toml", campaign(seeds));
    const auto r = run_pride("bench '" + toml + "' --out '" + store + "'");
    INFO(r.err);
    REQUIRE(r.status == 0);
}

engine::AlgorithmSpec spec_of(const std::string& algorithm) {
    engine::ParamValues params;
    params.set("pop", 10.0);
    return {algorithm, params};
}

}  // namespace

TEST_CASE("pride bench on a constrained problem: each row's violation and first feasible evaluation are engine::run's",
          "[constraints][campaign][store]") {
    const TempDir dir;
    const std::string store = dir.file("c.sqlite");
    bench(dir, kSeeds, store);
    CHECK(scalar(store, "PRAGMA user_version") == std::to_string(storage::schema_version));
    const storage::CampaignStore s = storage::read_store(store);
    REQUIRE(s.runs.size() == 2u * 2u * kSeeds);
    const engine::Problem g06(engine::ContinuousSpec{"cec2006-g06", 2});
    engine::Budget budget;
    budget.evaluations = kEvaluations;
    std::size_t feasible = 0, infeasible = 0;
    for (const storage::StoredRun& r : s.runs) {
        INFO(r.problem << " " << r.algorithm << " seed " << r.seed);
        if (r.problem == "s") {  // no constraints: NULL, as before
            CHECK_FALSE(r.best_violation);
            CHECK_FALSE(r.first_feasible);
            CHECK(r.best);
            continue;
        }
        const auto want = engine::run(spec_of(r.algorithm), g06, budget, static_cast<std::uint64_t>(r.seed));
        REQUIRE(want.best_violation);
        REQUIRE(r.best_violation);
        CHECK(*r.best_violation == *want.best_violation);
        CHECK(r.first_feasible == want.first_feasible);
        if (*want.best_violation == 0.0) {
            ++feasible;
            REQUIRE(r.best);
            CHECK(*r.best == want.best_f);
            CHECK_FALSE(r.infeasible_f);
        } else {
            ++infeasible;
            CHECK_FALSE(r.best);  // an infeasible best is no value of the tables
            REQUIRE(r.infeasible_f);
            CHECK(*r.infeasible_f == want.best_f);
        }
        // The target hits count only feasible points. The COCO trace holds COCO's logged value
        // (framework/run_state.hpp): g06's optimum is not known to the run, so an infeasible point
        // counts as 1e10 + its violation until the first feasible one; the trace ends at the
        // run's last evaluation.
        for (const auto& t : r.trace_targets)
            if (!r.first_feasible || t.evaluations < *r.first_feasible) CHECK(t.best > 1e10);
        REQUIRE(!r.trace_targets.empty());
        CHECK(r.trace_targets.back().evaluations == r.evaluations);
        for (const auto& hit : r.target_hits)
            if (hit) CHECK((r.first_feasible && *hit >= *r.first_feasible));
        for (std::size_t k = 0; k < r.history.size(); ++k)
            if (std::isfinite(r.history[k])) CHECK((r.first_feasible && r.history_evaluations[k] >= *r.first_feasible));
    }
    // The budget is chosen so that both kinds occur (the report's order has something to order).
    CHECK(feasible > 0);
    CHECK(infeasible > 0);
    // The `feasible` column follows the violation, not the finiteness of f.
    CHECK(scalar(store, "SELECT COUNT(*) FROM runs WHERE problem = 'g06' AND feasible <> (best_violation = 0)") == "0");
    CHECK(scalar(store,
                 "SELECT COUNT(*) FROM runs WHERE problem = 's' AND (best_violation IS NOT NULL OR "
                 "first_feasible IS NOT NULL)") == "0");
}

TEST_CASE("pride run and pride bench agree on a constrained run", "[constraints][campaign][store]") {
    const TempDir dir;
    const std::string store = dir.file("c.sqlite");
    bench(dir, 1, store);
    const auto run = run_pride("run --algo de --problem cec2006-g06 --dim 2 --evals " + std::to_string(kEvaluations) +
                               " --seed 1 --param pop=10 --json");
    INFO(run.err);
    REQUIRE(run.status == 0);
    const storage::CampaignStore s = storage::read_store(store);
    const auto stored = std::find_if(s.runs.begin(), s.runs.end(), [](const storage::StoredRun& r) {
        return r.problem == "g06" && r.algorithm == "de" && r.seed == 1;
    });
    REQUIRE(stored != s.runs.end());
    REQUIRE(stored->best_violation);
    const auto json = pride::test::parse_json(run.out);
    CHECK(json.at("best_violation").number == *stored->best_violation);
    CHECK(json.at("best_f").number == stored->best.value_or(stored->infeasible_f.value_or(0.0)));
    if (!stored->first_feasible)
        CHECK(json.at("first_feasible").kind == pride::test::JsonValue::Kind::null);
    else
        CHECK(json.at("first_feasible").number == static_cast<double>(*stored->first_feasible));
}

TEST_CASE("pride report on a constrained problem: the feasibility table and Deb's order", "[constraints][report]") {
    const TempDir dir;
    const std::string store = dir.file("c.sqlite");
    bench(dir, kSeeds, store);
    const auto md = run_pride("report '" + store + "'");
    INFO(md.err);
    REQUIRE(md.status == 0);
    CHECK_THAT(md.out, Contains("runs are compared by Deb's order (Deb 2000)"));
    CHECK_THAT(md.out, Contains("Feasibility, per problem with constraints and algorithm"));
    CHECK_THAT(md.out,
               Contains("| problem | algorithm | runs | feasible | median first feasible | median violation |"));
    // The rows agree with the store's columns.
    const storage::CampaignStore s = storage::read_store(store);
    const report::ReportData data = report::make_report(s);
    REQUIRE(data.feasibility.size() == 2);  // g06 only; sphere has none
    for (const report::FeasibilityRow& f : data.feasibility) {
        INFO(f.algorithm);
        CHECK(f.problem == "g06");
        CHECK(f.runs == static_cast<std::size_t>(kSeeds));
        const std::string feasible =
            scalar(store, "SELECT COUNT(*) FROM runs WHERE problem = 'g06' AND best_violation = 0 AND algorithm = '" +
                              f.algorithm + "'");
        CHECK(std::to_string(f.feasible) == feasible);
        CHECK_THAT(md.out, Contains("| g06 | " + f.algorithm + " | " + std::to_string(kSeeds) + " | " + feasible));
    }
    for (const report::ReportRow& r : data.rows) {
        INFO(r.problem << " " << r.algorithm);
        CHECK(r.feasible_runs.has_value() == (r.problem == "g06"));
    }
    // CSV: the three columns at the end; HTML: the same table.
    const auto csv = run_pride("report '" + store + "' --format csv");
    REQUIRE(csv.status == 0);
    CHECK_THAT(csv.out, Contains(",feasible_runs,median_first_feasible,median_violation\n"));
    const auto html = run_pride("report '" + store + "' --html '" + dir.file("html") + "'");
    INFO(html.err);
    REQUIRE(html.status == 0);
    const std::string page = pride::test::slurp(dir.file("html/index.html"));
    CHECK_THAT(page, Contains("<th class=\"n\">median first feasible</th>"));
    CHECK_THAT(page, Contains("Deb&#39;s order"));
}

TEST_CASE("report: runs of a constrained problem are ranked by Deb's order, values over feasible runs",
          "[constraints][report]") {
    // A: every run feasible at f = 10. B: one feasible run at f = 5, three infeasible whose least
    // violating points have f = -100 (lower than any feasible value). By f alone B would be best;
    // by Deb's order A is (three of B's runs are behind all of A's).
    storage::CampaignStore s;
    s.name = "deb";
    const auto add = [&](const std::string& algorithm, std::int64_t seed, double f, double violation,
                         std::optional<std::int64_t> first) {
        storage::StoredRun r;
        r.problem = "p";
        r.algorithm = algorithm;
        r.seed = seed;
        r.evaluations = 100;
        r.best_violation = violation;
        r.first_feasible = first;
        if (violation == 0)
            r.best = f;
        else
            r.infeasible_f = f;
        r.history = {r.best.value_or(std::numeric_limits<double>::infinity())};
        s.runs.push_back(r);
    };
    for (std::int64_t seed = 1; seed <= 4; ++seed) add("A", seed, 10.0, 0.0, 10 * seed);
    add("B", 1, 5.0, 0.0, 40);
    add("B", 2, -100.0, 0.5, std::nullopt);
    add("B", 3, -100.0, 0.25, std::nullopt);
    add("B", 4, -100.0, 1.0, std::nullopt);
    const report::ReportData r = report::make_report(s);
    REQUIRE(r.rows.size() == 2);
    const report::ReportRow& a = r.rows[0];
    const report::ReportRow& b = r.rows[1];
    CHECK(a.best);
    CHECK_FALSE(b.best);
    CHECK(a.feasible_runs == std::size_t{4});
    CHECK(b.feasible_runs == std::size_t{1});
    // Over the feasible runs only.
    CHECK(b.min == 5.0);
    CHECK(b.mean == 5.0);
    CHECK(b.median == 5.0);
    CHECK(a.mean == 10.0);
    // A12 of B against A: B's feasible run (f = 5) beats all four of A's; its infeasible ones lose.
    REQUIRE(b.a12);
    CHECK(*b.a12 == Approx(4.0 / 16.0));
    REQUIRE(r.feasibility.size() == 2);
    CHECK(r.feasibility[0].feasible == 4);
    CHECK(*r.feasibility[0].median_first_feasible == 25.0);  // of 10, 20, 30, 40
    CHECK_FALSE(r.feasibility[0].median_violation);
    CHECK(r.feasibility[1].feasible == 1);
    CHECK(*r.feasibility[1].median_first_feasible == 40.0);
    CHECK(*r.feasibility[1].median_violation == 0.5);
    const std::string md = report::render_markdown(r);
    CHECK_THAT(md, Contains("| p | A | 4 (4 feasible) |"));
    CHECK_THAT(md, Contains("| p | B | 4 (1 feasible) | 5 |"));
    CHECK_THAT(md, Contains("| p | B | 4 | 1 (25 %) | 40 | 0.5 |"));
    // No feasible run at all: the value columns say so.
    storage::CampaignStore none = s;
    none.runs.erase(none.runs.begin() + 4);  // B's feasible run
    const report::ReportData n = report::make_report(none);
    CHECK(n.rows[1].feasible_runs == std::size_t{0});
    CHECK_THAT(report::render_markdown(n), Contains("| p | B | 3 (0 feasible) | - | - | - | - | - |"));
}

TEST_CASE("store schema 6: a store of schema 5 reports, migrates on its next bench, and merges then",
          "[constraints][store][schema]") {
    const TempDir dir;
    const std::string store = dir.file("c.sqlite");
    bench(dir, 2, store);
    // As pride wrote it before: no violation columns (their runs then had no constrained problem).
    exec_sql(store,
             "DELETE FROM runs WHERE problem = 'g06'; ALTER TABLE runs DROP COLUMN best_violation; ALTER TABLE runs "
             "DROP COLUMN first_feasible; PRAGMA user_version = 5");
    const auto old_report = run_pride("report '" + store + "'");
    INFO(old_report.err);
    CHECK(old_report.status == 0);
    CHECK_THAT(old_report.out, !Contains("Feasibility"));
    // merge reads the current schema only, and says how to migrate.
    const std::string copy = dir.file("copy.sqlite");
    std::filesystem::copy_file(store, copy);
    pride::test::expect_input_error(
        "merge '" + store + "' '" + copy + "' --out '" + dir.file("m.sqlite") + "'",
        {"has store schema 5, merge reads schema " + std::to_string(storage::schema_version)});
    // The next bench adds the columns (NULL for the runs stored before) and the missing runs.
    bench(dir, 2, store);
    CHECK(scalar(store, "PRAGMA user_version") == std::to_string(storage::schema_version));
    CHECK(scalar(store, "SELECT COUNT(*) FROM runs WHERE problem = 's' AND best_violation IS NULL") == "4");
    CHECK(scalar(store, "SELECT COUNT(*) FROM runs WHERE problem = 'g06' AND best_violation IS NOT NULL") == "4");
    CHECK(storage::read_store(store).runs.size() == 8);
}

TEST_CASE("pride merge keeps the violation columns, and refuses runs that differ in them", "[constraints][store]") {
    const TempDir dir;
    const std::string a = dir.file("a.sqlite"), b = dir.file("b.sqlite");
    bench(dir, 2, a);
    bench(dir, 3, b);
    const std::string merged = dir.file("m.sqlite");
    const auto m = run_pride("merge '" + a + "' '" + b + "' --out '" + merged + "'");
    INFO(m.err);
    REQUIRE(m.status == 0);
    const std::string columns =
        "SELECT group_concat(problem || algorithm || seed || ':' || quote(best_violation) || "
        "quote(first_feasible), ';') FROM (SELECT * FROM runs ORDER BY problem, algorithm, seed)";
    CHECK(scalar(merged, columns) == scalar(b, columns));
    CHECK(scalar(merged, "SELECT COUNT(*) FROM runs WHERE problem = 'g06' AND best_violation IS NOT NULL") == "6");
    // A run whose violation differs is another run: refused, naming it.
    exec_sql(b,
             "UPDATE runs SET first_feasible = NULL, best_violation = 7 WHERE problem = 'g06' AND algorithm = "
             "'de' AND seed = 1");
    pride::test::expect_input_error("merge '" + a + "' '" + b + "' --out '" + dir.file("m2.sqlite") + "'",
                                    {"run (problem 'g06', algorithm 'de', seed 1) differs"});
}

TEST_CASE("a damaged violation column is refused in one line naming it", "[constraints][store]") {
    const TempDir dir;
    const std::string store = dir.file("c.sqlite");
    bench(dir, 1, store);
    const std::string where = "WHERE problem = 'g06' AND algorithm = 'de' AND seed = 1";
    const std::string backup = dir.file("backup.sqlite");
    std::filesystem::copy_file(store, backup);
    const auto damaged = [&](const std::string& sql, const std::vector<std::string>& words) {
        std::filesystem::copy_file(backup, store, std::filesystem::copy_options::overwrite_existing);
        exec_sql(store, sql);
        pride::test::expect_input_error("report '" + store + "'", words);
    };
    damaged("UPDATE runs SET best_violation = -1 " + where,
            {"damaged store", "best_violation", "expected a violation of at least 0, got -1"});
    damaged("UPDATE runs SET best_violation = 'x' " + where, {"damaged store", "best_violation", "expected a number"});
    damaged("UPDATE runs SET best_violation = 0, first_feasible = 100000 " + where,
            {"first_feasible", "expected at most the run's 300 evaluations"});
    damaged("UPDATE runs SET best_violation = 0, first_feasible = NULL " + where,
            {"first_feasible", "expected the evaluation that found the feasible best, got NULL"});
    damaged("UPDATE runs SET best_violation = 0.5, first_feasible = 3 " + where,
            {"first_feasible", "expected NULL for a run whose best is infeasible"});
    damaged("UPDATE runs SET first_feasible = 3 WHERE problem = 's' AND algorithm = 'de' AND seed = 1",
            {"first_feasible", "expected NULL where best_violation is NULL"});
    // A violation no point had finite (+inf) is a value, not damage.
    std::filesystem::copy_file(backup, store, std::filesystem::copy_options::overwrite_existing);
    exec_sql(store, "UPDATE runs SET best_violation = 9e999, first_feasible = NULL " + where);
    CHECK(run_pride("report '" + store + "'").status == 0);
}

TEST_CASE("pride bench: an algorithm that does not handle constraints is refused naming it",
          "[constraints][campaign]") {
    const TempDir dir;
    const std::string toml = dir.write("c.toml",
                                       "name = \"c\"\nseeds = 1\n[budget]\nevaluations = 100\n"
                                       "[[problem]]\nid = \"g06\"\ntype = \"cec2006-g06\"\ndim = 2\n"
                                       "[[algorithm]]\nid = \"harmony\"\ntype = \"hs\"\n");
    pride::test::expect_input_error("bench '" + toml + "' --out '" + dir.file("c.sqlite") + "'",
                                    {"algorithm 'harmony' on problem 'g06'", "does not handle constraints"});
    CHECK(dir.entries() == std::vector<std::string>{"c.toml"});
    // A handler the algorithm does not have is refused as any other parameter value.
    const std::string bad = dir.write("d.toml",
                                      "name = \"c\"\nseeds = 1\n[budget]\nevaluations = 100\n"
                                      "[[problem]]\nid = \"g06\"\ntype = \"cec2006-g06\"\ndim = 2\n"
                                      "[[algorithm]]\nid = \"de\"\ntype = \"de\"\nconstraints = \"nope\"\n");
    pride::test::expect_input_error("bench '" + bad + "' --out '" + dir.file("d.sqlite") + "'", {"constraints"});
}

TEST_CASE("a callback's constraints are part of its problem digest", "[constraints][store]") {
    // A Python campaign names its function by id alone: the digest is what tells an edit.
    pride::campaign::CampaignProblem p;
    p.id = "c";
    engine::CallbackSpec b;
    b.name = "disc";
    b.lower = {-1.0, -1.0};
    b.upper = {1.0, 1.0};
    b.scalar = [](std::span<const double> x) { return x[0]; };
    p.spec = b;
    const std::string plain = pride::campaign::problem_digest(p);
    b.tolerance = 1e-6;  // no constraints: the tolerance is no part of it
    p.spec = b;
    CHECK(pride::campaign::problem_digest(p) == plain);
    b.inequalities = 1;
    b.constrained = [](std::span<const double> x, std::span<double> g) {
        g[0] = x[0] * x[0] + x[1] * x[1] - 0.25;
        return x[0];
    };
    p.spec = b;
    const std::string one = pride::campaign::problem_digest(p);
    CHECK(one != plain);
    b.tolerance = 1e-4;
    p.spec = b;
    CHECK(pride::campaign::problem_digest(p) != one);
    b.equalities = 1;
    p.spec = b;
    CHECK(pride::campaign::problem_digest(p) != one);
}

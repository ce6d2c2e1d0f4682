// COCO-style analysis (experiment/report/coco.hpp, docs/analysis.md): ERT and runtime ECDFs worked by
// hand; stores with the suite columns (campaign.precisions; problems.function, instance, f_opt,
// suite, fid; runs.target_hits) written here with sqlite3 and read back, rendered by `pride
// report` (md, csv, latex) and plotted by `pride report --plots`; stores without them; the
// damaged-store messages of the new columns; and the IOH export of bbob problems by fid and
// instance.
#include <sqlite3.h>
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "experiment/report/coco.hpp"
#include "experiment/report/report.hpp"
#include "experiment/storage/reader.hpp"
#include "tests/cli_runner.hpp"
#include "tests/test_support.hpp"

namespace {

namespace coco = pride::report::coco;
using Catch::Matchers::WithinRel;
using pride::test::check_input_error;
using pride::test::run_pride;
using pride::test::slurp;
using pride::test::TempDir;
constexpr double inf = std::numeric_limits<double>::infinity();

std::string quote(const std::string& s) {
    return "'" + s + "'";
}

void exec(sqlite3* db, const std::string& sql) {
    char* message = nullptr;
    const int rc = sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &message);
    INFO(sql << ": " << (message ? message : ""));
    sqlite3_free(message);
    REQUIRE(rc == SQLITE_OK);
}

/// A store with pride bench's tables; with `suite`, the columns of the suite extension and
/// target hits. Precisions 10, 1, 0.1; algorithms a and b on two instances of bbob-f1 (2-D),
/// one of bbob-f20 (2-D) and on a classic rastrigin (3-D, not in a suite numbering).
std::string suite_store(const TempDir& dir, const std::string& name, bool suite = true) {
    const std::string path = dir.file(name + ".sqlite");
    sqlite3* db = nullptr;
    REQUIRE(sqlite3_open(path.c_str(), &db) == SQLITE_OK);
    exec(db, std::string("CREATE TABLE campaign (id INTEGER PRIMARY KEY CHECK (id = 1), name TEXT NOT NULL, "
                         "text TEXT NOT NULL, target REAL") +
                 (suite ? ", precisions TEXT)" : ")"));
    exec(db,
         std::string("CREATE TABLE runs (problem TEXT NOT NULL, algorithm TEXT NOT NULL, seed INTEGER NOT NULL, "
                     "feasible INTEGER NOT NULL, best REAL, evaluations INTEGER NOT NULL, iterations INTEGER NOT NULL, "
                     "wall_ms REAL NOT NULL, optimum REAL, solution TEXT NOT NULL, history TEXT NOT NULL, "
                     "history_evaluations TEXT NOT NULL, ") +
             (suite ? "target_hits TEXT, " : "") + "UNIQUE (problem, algorithm, seed))");
    exec(db, std::string("CREATE TABLE problems (id TEXT PRIMARY KEY, type TEXT NOT NULL, dim INTEGER NOT NULL, "
                         "map TEXT, start TEXT, goal TEXT") +
                 (suite ? ", function TEXT, instance INTEGER, f_opt REAL, suite TEXT, fid INTEGER)" : ")"));
    if (suite) {
        exec(db, "INSERT INTO campaign VALUES (1, 'suite', 'name = \"suite\"', NULL, '[10, 1, 0.1]')");
        exec(db,
             "INSERT INTO problems VALUES "
             "('f1-i1', 'bbob-f1', 2, '', '', '', 'bbob-f1', 1, 79.48, 'bbob', 1), "
             "('f1-i2', 'bbob-f1', 2, '', '', '', 'bbob-f1', 2, -209.88, 'bbob', 1), "
             "('f20-i1', 'bbob-f20', 2, '', '', '', 'bbob-f20', 1, 2.5, 'bbob', 20), "
             "('ras3', 'rastrigin', 3, '', '', '', 'rastrigin', 0, 0, 'classic', NULL)");
    } else {
        exec(db, "INSERT INTO campaign VALUES (1, 'suite', 'name = \"suite\"', NULL)");
        exec(db,
             "INSERT INTO problems VALUES ('f1-i1', 'bbob-f1', 2, '', '', ''), ('f1-i2', 'bbob-f1', 2, '', '', ''), "
             "('f20-i1', 'bbob-f20', 2, '', '', ''), ('ras3', 'rastrigin', 3, '', '', '')");
    }
    struct Run {
        const char *problem, *algorithm;
        int seed, evaluations;
        const char* hits;  // nullptr: NULL
        const char *history, *history_evaluations;
        double best;
    };
    const std::vector<Run> runs = {
        {"f1-i1", "a", 1, 100, "[10, 40, null]", "[85, 79.5]", "[50, 100]", 79.5},
        {"f1-i1", "a", 2, 100, "[20, null, null]", "[85, 82]", "[50, 100]", 82},
        {"f1-i2", "a", 1, 100, "[5, 30, 50]", "[-200, -209.8]", "[50, 100]", -209.8},
        {"f1-i2", "a", 2, 100, "[null, null, null]", "[0, -150]", "[50, 100]", -150},
        {"f1-i1", "b", 1, 100, "[null, null, null]", "[300, 200]", "[50, 100]", 200},
        {"f1-i1", "b", 2, 100, "[null, null, null]", "[300, 200]", "[50, 100]", 200},
        {"f1-i2", "b", 1, 100, "[null, null, null]", "[300, 200]", "[50, 100]", 200},
        {"f1-i2", "b", 2, 100, "[null, null, null]", "[300, 200]", "[50, 100]", 200},
        {"f20-i1", "a", 1, 100, "[100, null, null]", "[20, 12]", "[50, 100]", 12},
        {"f20-i1", "a", 2, 100, "[60, 90, 100]", "[12, 2.55]", "[50, 100]", 2.55},
        {"f20-i1", "b", 1, 100, "[50, 80, null]", "[12, 3]", "[50, 100]", 3},
        {"f20-i1", "b", 2, 100, nullptr, "[12, 3]", "[50, 100]", 3},  // records no hits
        {"ras3", "a", 1, 300, "[3, 6, 9]", "[null, 0.05]", "[150, 300]", 0.05},
        {"ras3", "b", 1, 300, "[null, null, null]", "[40, 30]", "[150, 300]", 30},
    };
    for (const Run& r : runs)
        exec(db, fmt::format("INSERT INTO runs (problem, algorithm, seed, feasible, best, evaluations, iterations, "
                             "wall_ms, optimum, solution, history, history_evaluations{}) VALUES ('{}', '{}', {}, 1, "
                             "{}, {}, 2, 1.5, NULL, '[0, 0]', '{}', '{}'{})",
                             suite ? ", target_hits" : "", r.problem, r.algorithm, r.seed, r.best, r.evaluations,
                             r.history, r.history_evaluations,
                             suite ? (r.hits ? fmt::format(", '{}'", r.hits) : std::string(", NULL")) : ""));
    sqlite3_close(db);
    return path;
}

/// A copy of `store` named `name`, changed by `sql`.
std::string tampered(const TempDir& dir, const std::string& store, const std::string& name, const std::string& sql) {
    const std::string copy = dir.file(name + ".sqlite");
    std::filesystem::copy_file(store, copy, std::filesystem::copy_options::overwrite_existing);
    sqlite3* db = nullptr;
    REQUIRE(sqlite3_open(copy.c_str(), &db) == SQLITE_OK);
    exec(db, sql);
    sqlite3_close(db);
    return copy;
}

const coco::ErtRow& row(const coco::Analysis& a, const std::string& function, const std::string& algorithm) {
    for (const auto& r : a.erts)
        if (r.function == function && r.algorithm == algorithm) return r;
    FAIL("no ERT row " << function << " " << algorithm);
    throw std::logic_error("unreachable");
}

const coco::EcdfCurve& curve(const coco::Analysis& a, const std::string& group, const std::string& algorithm) {
    for (const auto& c : a.curves)
        if (c.group == group && c.algorithm == algorithm) return c;
    FAIL("no ECDF curve " << group << " " << algorithm);
    throw std::logic_error("unreachable");
}

void check_steps(const coco::Ecdf& e, const std::vector<double>& runtimes, const std::vector<double>& fractions) {
    REQUIRE(e.x.size() == runtimes.size());
    REQUIRE(e.y.size() == fractions.size());
    for (std::size_t k = 0; k < runtimes.size(); ++k) {
        INFO("step " << k);
        CHECK_THAT(e.x[k], WithinRel(std::log10(runtimes[k]), 1e-12));
        CHECK_THAT(e.y[k], WithinRel(fractions[k], 1e-12));
    }
}

}  // namespace

TEST_CASE("coco: ERT and ECDF worked by hand", "[report][coco]") {
    // Three runs of a 2-D problem against three targets (hits in evaluations, - never):
    //   A: 100 evaluations, hits 10, 40, -
    //   B: 200 evaluations, hits 20, -, -
    //   C:  50 evaluations, hits  5, 30, 50
    const std::vector<std::vector<coco::TargetRun>> per_target = {
        {{100, 10, 2}, {200, 20, 2}, {50, 5, 2}},
        {{100, 40, 2}, {200, std::nullopt, 2}, {50, 30, 2}},
        {{100, std::nullopt, 2}, {200, std::nullopt, 2}, {50, 50, 2}},
    };
    // Target 1: (10 + 20 + 5) / 3 = 35 / 3; target 2: (40 + 200 + 30) / 2 = 135;
    // target 3: (100 + 200 + 50) / 1 = 350.
    const coco::Ert e1 = coco::ert(per_target[0]), e2 = coco::ert(per_target[1]), e3 = coco::ert(per_target[2]);
    CHECK_THAT(e1.value, WithinRel(35.0 / 3.0, 1e-15));
    CHECK(e1.successes == 3);
    CHECK(e1.runs == 3);
    CHECK(e2.value == 135.0);
    CHECK(e2.successes == 2);
    CHECK(e3.value == 350.0);
    CHECK(e3.successes == 1);
    // No success: inf; no runs: inf and 0/0.
    const coco::Ert none = coco::ert({{100, std::nullopt, 2}, {70, std::nullopt, 2}});
    CHECK(none.value == inf);
    CHECK(none.successes == 0);
    CHECK(none.runs == 2);
    CHECK(coco::ert({}).value == inf);

    // The ECDF of the 9 (run, target) pairs: 6 reached, at 10, 20, 5, 40, 30, 50 evaluations,
    // / 2 (the dimension) = 2.5, 5, 10, 15, 20, 25: steps of 1/9 at log10 of each.
    std::vector<coco::TargetRun> pairs;
    for (const auto& t : per_target) pairs.insert(pairs.end(), t.begin(), t.end());
    const coco::Ecdf e = coco::ecdf(pairs);
    CHECK(e.pairs == 9);
    check_steps(e, {2.5, 5, 10, 15, 20, 25}, {1 / 9.0, 2 / 9.0, 3 / 9.0, 4 / 9.0, 5 / 9.0, 6 / 9.0});
    CHECK_THAT(e.max_budget, WithinRel(std::log10(100.0), 1e-12));  // 200 evaluations / 2
    // Equal runtimes make one step; dimensions differ per pair: 30/3 = 10 = 20/2, 4/1 = 4.
    const coco::Ecdf ties = coco::ecdf({{30, 30, 3}, {40, 20, 2}, {10, 4, 1}, {10, std::nullopt, 1}});
    check_steps(ties, {4, 10}, {0.25, 0.75});
    CHECK(coco::ecdf({}).x.empty());

    CHECK(coco::bbob_group(1) == "separable");
    CHECK(coco::bbob_group(5) == "separable");
    CHECK(coco::bbob_group(6) == "moderate");
    CHECK(coco::bbob_group(9) == "moderate");
    CHECK(coco::bbob_group(10) == "ill-conditioned");
    CHECK(coco::bbob_group(14) == "ill-conditioned");
    CHECK(coco::bbob_group(15) == "multimodal");
    CHECK(coco::bbob_group(19) == "multimodal");
    CHECK(coco::bbob_group(20) == "weakly-structured");
    CHECK(coco::bbob_group(24) == "weakly-structured");
    CHECK(!coco::bbob_group(0));
    CHECK(!coco::bbob_group(25));
}

TEST_CASE("coco: a store with the suite columns read back, analysed and reported", "[report][coco]") {
    TempDir dir("pride-coco");
    const std::string store = suite_store(dir, "suite");
    const auto s = pride::storage::read_store(store);
    REQUIRE(s.precisions);
    CHECK(*s.precisions == std::vector<double>{10, 1, 0.1});
    REQUIRE(s.problems);
    REQUIRE(s.problems->size() == 4);
    const auto& p2 = (*s.problems)[1];
    CHECK(p2.id == "f1-i2");
    CHECK(p2.function == "bbob-f1");
    CHECK(p2.instance == 2);
    CHECK(p2.f_opt == -209.88);
    CHECK(p2.suite == "bbob");
    CHECK(p2.fid == 1);
    const auto& p4 = (*s.problems)[3];
    CHECK(p4.suite == "classic");
    CHECK(!p4.fid);
    CHECK(p4.instance == 0);
    // Runs ordered by problem, algorithm, seed: f1-i1 a 1 first.
    REQUIRE(s.runs.size() == 14);
    CHECK(s.runs[0].target_hits == std::vector<std::optional<std::int64_t>>{10, 40, std::nullopt});
    for (const auto& r : s.runs)
        if (r.problem == "f20-i1" && r.algorithm == "b" && r.seed == 2) CHECK(r.target_hits.empty());

    const auto report = pride::report::load_report(store);
    REQUIRE(report.coco);
    const coco::Analysis& a = *report.coco;
    CHECK(a.runs_without_hits == 1);
    REQUIRE(a.erts.size() == 6);  // bbob-f1, bbob-f20 (by fid), rastrigin; a and b each
    CHECK(a.erts[0].function == "bbob-f1");
    CHECK(a.erts[2].function == "bbob-f20");
    CHECK(a.erts[4].function == "rastrigin");
    // a on bbob-f1, 2-D, over both instances (4 runs of 100 evaluations):
    //   10:  (10 + 20 + 5 + 100) / 3 = 45;  1: (40 + 100 + 30 + 100) / 2 = 135;
    //   0.1: (100 + 100 + 50 + 100) / 1 = 350.
    const auto& a1 = row(a, "bbob-f1", "a");
    CHECK(a1.dim == 2);
    CHECK(a1.runs == 4);
    CHECK(a1.instances == 2);
    CHECK(a1.ert[0].value == 45);
    CHECK(a1.ert[0].successes == 3);
    CHECK(a1.ert[1].value == 135);
    CHECK(a1.ert[2].value == 350);
    CHECK(a1.ert[2].successes == 1);
    const auto& b1 = row(a, "bbob-f1", "b");
    for (const auto& e : b1.ert) CHECK(e.value == inf);
    // a on bbob-f20: 10: (100 + 60) / 2 = 80; 1: (100 + 90) / 1 = 190; 0.1: (100 + 100) / 1 = 200.
    const auto& a20 = row(a, "bbob-f20", "a");
    CHECK(a20.ert[0].value == 80);
    CHECK(a20.ert[1].value == 190);
    CHECK(a20.ert[2].value == 200);
    // b on bbob-f20: its second run records no hits: 50 / 1, 80 / 1, inf (0 of 1 run).
    const auto& b20 = row(a, "bbob-f20", "b");
    CHECK(b20.runs == 1);
    CHECK(b20.ert[0].value == 50);
    CHECK(b20.ert[1].value == 80);
    CHECK(b20.ert[2].value == inf);
    const auto& ar = row(a, "rastrigin", "a");
    CHECK(ar.dim == 3);
    CHECK(ar.ert[2].value == 9);

    // ECDF of a over everything: 4 * 3 + 2 * 3 + 3 = 21 pairs; reached, in evaluations / dim:
    //   bbob-f1 (2-D): 10, 40, 20, 5, 30, 50 -> 5, 20, 10, 2.5, 15, 25
    //   bbob-f20 (2-D): 100, 60, 90, 100 -> 50, 30, 45, 50
    //   rastrigin (3-D): 3, 6, 9 -> 1, 2, 3
    // sorted 1, 2, 2.5, 3, 5, 10, 15, 20, 25, 30, 45, 50, 50: 12 steps, the last of two pairs.
    const auto& all_a = curve(a, "all", "a");
    CHECK(all_a.ecdf.pairs == 21);
    CHECK(all_a.dims == std::vector<std::int64_t>{2, 3});
    check_steps(all_a.ecdf, {1, 2, 2.5, 3, 5, 10, 15, 20, 25, 30, 45, 50},
                {1 / 21.0, 2 / 21.0, 3 / 21.0, 4 / 21.0, 5 / 21.0, 6 / 21.0, 7 / 21.0, 8 / 21.0, 9 / 21.0, 10 / 21.0,
                 11 / 21.0, 13 / 21.0});
    CHECK_THAT(all_a.ecdf.max_budget, WithinRel(2.0, 1e-12));  // rastrigin: 300 / 3 = 10^2
    // Separable (f1 only): 12 pairs, 6 reached.
    const auto& sep_a = curve(a, "separable", "a");
    CHECK(sep_a.ecdf.pairs == 12);
    check_steps(sep_a.ecdf, {2.5, 5, 10, 15, 20, 25}, {1 / 12.0, 2 / 12.0, 3 / 12.0, 4 / 12.0, 5 / 12.0, 6 / 12.0});
    // Weak global structure (f20): 6 pairs, reached at 30, 45, 50, 50.
    check_steps(curve(a, "weakly-structured", "a").ecdf, {30, 45, 50}, {1 / 6.0, 2 / 6.0, 4 / 6.0});
    // b: 12 + 3 + 3 = 18 pairs (its run without hits left out), reached at 50 / 2 and 80 / 2.
    const auto& all_b = curve(a, "all", "b");
    CHECK(all_b.ecdf.pairs == 18);
    check_steps(all_b.ecdf, {25, 40}, {1 / 18.0, 2 / 18.0});
    for (const auto& c : a.curves) CHECK(c.group != "moderate");  // no f6-f9 here
    CHECK(a.curves.front().group == "all");

    const std::string json = coco::ecdf_json(report.campaign, a);
    CHECK(json.find("\"group\": \"separable\", \"title\": \"separable functions f1-f5\", \"dims\": [2]") !=
          std::string::npos);

    // The rendered tables.
    const auto md = run_pride("report " + quote(store));
    REQUIRE(md.status == 0);
    CHECK(md.out.find("## Expected running time (ERT)") != std::string::npos);
    CHECK(md.out.find("### bbob-f1, 2-D (2 instances)") != std::string::npos);
    CHECK(md.out.find("| algorithm | ERT 1e1 | ERT 1e-1 | #succ |") != std::string::npos);
    // ERTs with the 10th and 90th percentiles of their bootstrap in brackets; inf without.
    CHECK(md.out.find("| a | 45 [") != std::string::npos);
    CHECK(md.out.find("] | 350 [") != std::string::npos);
    CHECK(md.out.find("] | 1/4 |") != std::string::npos);
    CHECK(md.out.find("| b | inf | inf | 0/4 |") != std::string::npos);
    CHECK(md.out.find("### rastrigin, 3-D (1 instance)") != std::string::npos);
    CHECK(md.out.find("1 runs record no target hits") != std::string::npos);
    // The main CSV stays one table; the ERT is its own CSV.
    const auto csv = run_pride("report " + quote(store) + " --format csv");
    REQUIRE(csv.status == 0);
    CHECK(csv.out.find("\n\n") == std::string::npos);
    CHECK(csv.out.find("ert") == std::string::npos);
    const auto ert_csv = run_pride("report " + quote(store) + " --format ert-csv");
    REQUIRE(ert_csv.status == 0);
    CHECK(ert_csv.out.rfind("function,dim,algorithm,precision,ert,successes,runs,ert_p10,ert_p50,ert_p90\n", 0) == 0);
    CHECK(ert_csv.out.find("\nbbob-f1,2,a,10,45,3,4,") != std::string::npos);
    CHECK(ert_csv.out.find("\nbbob-f1,2,a,1,135,2,4,") != std::string::npos);
    CHECK(ert_csv.out.find("\nbbob-f1,2,a,0.1,350,1,4,") != std::string::npos);
    CHECK(ert_csv.out.find("\nbbob-f20,2,b,0.1,inf,0,1,inf,inf,inf\n") != std::string::npos);
    CHECK(std::count(ert_csv.out.begin(), ert_csv.out.end(), '\n') == 1 + 6 * 3);  // 6 rows x 3 precisions
    const auto latex = run_pride("report " + quote(store) + " --format latex");
    REQUIRE(latex.status == 0);
    CHECK(latex.out.find("% bbob-f20, 2-D (1 instance)\n\\begin{tabular}{lrrr}") != std::string::npos);
    CHECK(latex.out.find("a & 80 [") != std::string::npos);
    CHECK(latex.out.find("] & 200 [") != std::string::npos);

    // Precisions in another order: the columns follow COCO's order, #succ the smallest precision.
    // The hits stay as they are: for a on bbob-f1 the ERT at 10 is now the second entry's, 135;
    // at 0.1 the first entry's, 45, reached by 3 of the 4 runs.
    const std::string unordered = dir.file("unordered.sqlite");
    std::filesystem::copy_file(store, unordered);
    {
        sqlite3* db = nullptr;
        REQUIRE(sqlite3_open(unordered.c_str(), &db) == SQLITE_OK);
        exec(db, "UPDATE campaign SET precisions = '[0.1, 10, 1]'");
        sqlite3_close(db);
    }
    const auto u = run_pride("report " + quote(unordered));
    REQUIRE(u.status == 0);
    CHECK(u.out.find("the smallest precision (1e-1)") != std::string::npos);
    CHECK(u.out.find("| a | 135 [") != std::string::npos);
    CHECK(u.out.find("] | 45 [") != std::string::npos);
    CHECK(u.out.find("] | 3/4 |") != std::string::npos);
}

TEST_CASE("coco: stores without the suite columns, or with them NULL, read as before", "[report][coco]") {
    TempDir dir("pride-coco-old");
    const std::string old = suite_store(dir, "old", false);
    const auto s = pride::storage::read_store(old);
    CHECK(!s.precisions);
    REQUIRE(s.problems);
    for (const auto& p : *s.problems) {
        CHECK(!p.function);
        CHECK(p.instance == 0);
        CHECK(!p.f_opt);
        CHECK(!p.suite);
        CHECK(!p.fid);
    }
    for (const auto& r : s.runs) CHECK(r.target_hits.empty());
    CHECK(!pride::report::load_report(old).coco);
    const auto md = run_pride("report " + quote(old));
    REQUIRE(md.status == 0);
    CHECK(md.out.find("Expected running time") == std::string::npos);
    const auto csv = run_pride("report " + quote(old) + " --format csv");
    REQUIRE(csv.status == 0);
    CHECK(csv.out.find("\n\n") == std::string::npos);  // one table only
    check_input_error(run_pride("report " + quote(old) + " --format ert-csv"),
                      {"--format ert-csv", "records no target hits"});

    // A new store of a campaign without targets: the columns NULL, or hits [].
    const std::string store = suite_store(dir, "suite");
    const std::string none = tampered(dir, store, "none",
                                      "UPDATE campaign SET precisions = NULL; UPDATE runs SET target_hits = NULL; "
                                      "UPDATE problems SET function = NULL, instance = NULL, suite = NULL, fid = NULL");
    const auto n = pride::storage::read_store(none);
    CHECK(!n.precisions);
    CHECK((*n.problems)[0].instance == 0);
    CHECK(!pride::report::load_report(none).coco);
    const std::string empty =
        tampered(dir, store, "empty", "UPDATE campaign SET precisions = NULL; UPDATE runs SET target_hits = '[]'");
    CHECK(!pride::report::load_report(empty).coco);
    CHECK(run_pride("report " + quote(empty)).out.find("Expected running time") == std::string::npos);
    const std::string no_precisions = tampered(
        dir, store, "no-precisions", "UPDATE campaign SET precisions = '[]'; UPDATE runs SET target_hits = '[]'");
    CHECK(pride::storage::read_store(no_precisions).precisions->empty());
    CHECK(!pride::report::load_report(no_precisions).coco);
    // Hits [] in a campaign with precisions: the runs are left out of the analysis.
    const std::string some = tampered(dir, store, "some", "UPDATE runs SET target_hits = '[]' WHERE algorithm = 'b'");
    const auto a = pride::report::load_report(some).coco;
    REQUIRE(a);
    CHECK(a->runs_without_hits == 7);
    CHECK(a->erts.size() == 3);
    // Precisions but no run with hits (pride bench on grids, no known optimum): no ERT section.
    const std::string grids = tampered(dir, store, "grids", "UPDATE runs SET target_hits = '[]'");
    CHECK(pride::storage::read_store(grids).precisions);
    CHECK(!pride::report::load_report(grids).coco);
    CHECK(run_pride("report " + quote(grids)).out.find("Expected running time") == std::string::npos);
}

TEST_CASE("coco: damaged suite columns are bad input naming the run and the column", "[report][coco][damaged]") {
    TempDir dir("pride-coco-damaged");
    const std::string store = suite_store(dir, "suite");
    const std::string run = "runs row (problem 'f1-i1', algorithm 'a', seed 1)";
    const std::string where = " WHERE problem = 'f1-i1' AND algorithm = 'a' AND seed = 1";
    struct Case {
        std::string name, sql, message;  // the whole message after "STORE: damaged store: "
    };
    const std::vector<Case> cases = {
        {"hits-short", "UPDATE runs SET target_hits = '[10, 40]'" + where,
         run + ", column target_hits: expected one entry per precision of the campaign (3), got 2"},
        {"hits-long", "UPDATE runs SET target_hits = '[10, 40, 50, 60]'" + where,
         run + ", column target_hits: expected one entry per precision of the campaign (3), got 4"},
        {"hits-fraction", "UPDATE runs SET target_hits = '[10.5, 40, null]'" + where,
         run + ", column target_hits: expected a JSON list of counts or nulls, got '[10.5, 40, null]' (wrong at "
               "character 4)"},
        {"hits-text", "UPDATE runs SET target_hits = '[\"10\", 40, null]'" + where,
         run + ", column target_hits: expected a JSON list of counts or nulls, got '[\"10\", 40, null]' (wrong at "
               "character 2)"},
        {"hits-zero", "UPDATE runs SET target_hits = '[0, 40, null]'" + where,
         run + ", column target_hits: expected a JSON list of counts or nulls, got the count 0 (at least 1)"},
        {"hits-beyond", "UPDATE runs SET target_hits = '[10, 101, null]'" + where,
         run + ", column target_hits: expected at most the run's 100 evaluations, got 101"},
        // A TEXT column turns a number into text; a blob stays one.
        {"hits-blob", "UPDATE runs SET target_hits = x'05'" + where,
         run + ", column target_hits: expected a JSON list of counts or nulls, got a blob"},
        {"hits-without-precisions", "UPDATE campaign SET precisions = NULL",
         "runs row (problem 'f1-i1', algorithm 'a', seed 1), column target_hits: expected no entries (the campaign "
         "records no precisions), got 3"},
        {"precisions-text", "UPDATE campaign SET precisions = '[\"a\"]'",
         "the campaign row, column precisions: expected a JSON list of numbers, got '[\"a\"]' (wrong at character "
         "2)"},
        {"precisions-object", "UPDATE campaign SET precisions = '{\"a\": 1}'",
         "the campaign row, column precisions: expected a JSON list of numbers, got '{\"a\": 1}' (wrong at "
         "character 1)"},
        {"precisions-null", "UPDATE campaign SET precisions = '[10, null, 0.1]'",
         "the campaign row, column precisions: expected a JSON list of numbers of at least 0, got inf"},
        {"precisions-negative", "UPDATE campaign SET precisions = '[10, -1, 0.1]'",
         "the campaign row, column precisions: expected a JSON list of numbers of at least 0, got -1"},
        {"precisions-number", "UPDATE campaign SET precisions = 10",
         "the campaign row, column precisions: expected a JSON list of numbers, got '10' (wrong at character 1)"},
        {"precisions-blob", "UPDATE campaign SET precisions = x'00'",
         "the campaign row, column precisions: expected a JSON list of numbers, got a blob"},
        {"fid-text", "UPDATE problems SET fid = 'one' WHERE id = 'f1-i1'",
         "problems row 'f1-i1', column fid: expected an integer, got the text 'one'"},
        {"instance-negative", "UPDATE problems SET instance = -1 WHERE id = 'f1-i1'",
         "problems row 'f1-i1', column instance: expected an integer of at least 0, got -1"},
        {"f-opt-text", "UPDATE problems SET f_opt = 'low' WHERE id = 'f1-i1'",
         "problems row 'f1-i1', column f_opt: expected a number, got the text 'low'"},
        {"suite-blob", "UPDATE problems SET suite = x'00' WHERE id = 'f1-i1'",
         "problems row 'f1-i1', column suite: expected text, got a blob"},
        {"function-blob", "UPDATE problems SET function = x'00' WHERE id = 'f1-i1'",
         "problems row 'f1-i1', column function: expected text, got a blob"},
        {"no-problem-row", "DELETE FROM problems WHERE id = 'ras3'",
         "runs row (problem 'ras3', algorithm 'a', seed 1), column problem: 'ras3' is not in table problems (the "
         "analysis of target hits needs its function and dimension)"},
    };
    for (const Case& c : cases) {
        INFO(c.name);
        const std::string path = tampered(dir, store, c.name, c.sql);
        CHECK(pride::test::input_error_message([&] { pride::storage::read_store(path); }) ==
              path + ": damaged store: " + c.message);
        check_input_error(run_pride("report " + quote(path)), {path + ": damaged store: " + c.message});
        const std::string out = dir.file(c.name + "-ioh");
        check_input_error(run_pride("export " + quote(path) + " --ioh " + quote(out)), {c.message});
        CHECK(!std::filesystem::exists(out));
    }
    CHECK_THROWS_AS(pride::storage::read_store(dir.file("hits-short.sqlite")), pride::storage::DamagedStore);
    // Without the problems table (as before it existed) the store is reported, with no analysis.
    const std::string no_problems = tampered(dir, store, "no-problems", "DROP TABLE problems");
    CHECK(!pride::report::load_report(no_problems).coco);
    CHECK(run_pride("report " + quote(no_problems)).status == 0);
}

TEST_CASE("coco: the IOH export names bbob problems by fid and instance", "[report][coco][export]") {
    TempDir dir("pride-coco-ioh");
    const std::string store = suite_store(dir, "suite");
    const std::string out = dir.file("ioh");
    const auto r = run_pride("export " + quote(store) + " --ioh " + quote(out));
    INFO(r.err);
    REQUIRE(r.status == 0);
    // Per algorithm: bbob-f1 (one .info, one .dat: both instances), bbob-f20, ras3 (f4: its place).
    CHECK(r.out == "12 IOHprofiler files written under " + out + "\n");
    const std::filesystem::path a = std::filesystem::path(out) / "a";
    // BBOB functions by IOHexperimenter's names and ids.
    const std::string info = slurp(a / "IOHprofiler_f1_Sphere.info");
    CHECK(info ==
          "suite = \"BBOB\", funcId = 1, funcName = \"Sphere\", DIM = 2, maximization = \"F\", algId = \"a\", "
          "algInfo = \"campaign suite\"\n%\ndata_f1_Sphere/IOHprofiler_f1_DIM2.dat, 1:100|79.5, 1:100|82, "
          "2:100|-209.80000000000001, 2:100|-150\n");
    const std::string dat = slurp(a / "data_f1_Sphere" / "IOHprofiler_f1_DIM2.dat");
    const std::string header =
        "\"function evaluation\" \"current f(x)\" \"best-so-far f(x)\" \"current af(x)+b\" \"best af(x)+b\"\n";
    CHECK(dat.rfind(header + "50 85 85 85 85\n100 79.5 79.5 79.5 79.5\n" + header, 0) == 0);
    std::size_t blocks = 0;
    for (auto at = dat.find(header); at != std::string::npos; at = dat.find(header, at + 1)) ++blocks;
    CHECK(blocks == 4);  // 2 instances x 2 seeds
    CHECK(slurp(a / "IOHprofiler_f20_Schwefel.info").find("funcId = 20, funcName = \"Schwefel\", DIM = 2") !=
          std::string::npos);
    CHECK(std::filesystem::exists(a / "data_f20_Schwefel" / "IOHprofiler_f20_DIM2.dat"));
    // Outside a suite: 1000 + its place in the campaign (never a BBOB id), runs by seed; the rows
    // start at the first feasible value (IOHanalyzer reads every row as a value reached).
    CHECK(slurp(a / "IOHprofiler_f1004_ras3.info")
              .rfind("suite = \"pride\", funcId = 1004, funcName = \"ras3\", DIM = 3", 0) == 0);
    CHECK(slurp(a / "data_f1004_ras3" / "IOHprofiler_f1004_DIM3.dat") ==
          header + "300 0.050000000000000003 0.050000000000000003 0.050000000000000003 0.050000000000000003\n");
    CHECK(!std::filesystem::exists(a / "IOHprofiler_f2_f1-i2.info"));
}

TEST_CASE("coco: --plots writes the ECDF figures of the suite and its groups", "[report][coco][plots]") {
    TempDir dir("pride-coco-plots");
    const std::string store = suite_store(dir, "suite");
    const std::string figures = dir.file("figures");
    const auto r = run_pride("report " + quote(store) + " --plots " + quote(figures));
    if (r.status == 2 && r.err.find("matplotlib") != std::string::npos)
        FAIL("python3-matplotlib is missing: scripts/deps.sh installs it");
    INFO(r.err);
    REQUIRE(r.status == 0);
    for (const char* stem : {"ecdf_all", "ecdf_separable", "ecdf_weakly-structured"}) {
        INFO(stem);
        const std::string png = slurp(std::filesystem::path(figures) / (std::string(stem) + ".png"));
        CHECK(png.rfind("\x89PNG\r\n\x1a\n", 0) == 0);
        CHECK(std::filesystem::file_size(std::filesystem::path(figures) / (std::string(stem) + ".svg")) > 1000);
    }
    CHECK(!std::filesystem::exists(std::filesystem::path(figures) / "ecdf_moderate.png"));
    CHECK(std::filesystem::exists(std::filesystem::path(figures) / "f1-i1-convergence.png"));
    // A store without precisions: no ECDF figures.
    const std::string old = suite_store(dir, "old", false);
    const std::string old_figures = dir.file("old-figures");
    REQUIRE(run_pride("report " + quote(old) + " --plots " + quote(old_figures)).status == 0);
    CHECK(!std::filesystem::exists(std::filesystem::path(old_figures) / "ecdf_all.png"));
}

TEST_CASE("coco: a store written by pride bench, read back and checked against its histories",
          "[report][coco][bench]") {
    TempDir dir("pride-coco-bench");
    const std::string config = dir.write("c.toml",
                                         "name = \"coco-bench\"\nseeds = 3\n[budget]\nevaluations = 3000\n"
                                         "[[problem]]\nid = \"sphere4\"\ntype = \"sphere\"\ndim = 4\n"
                                         "[[problem]]\nid = \"grid\"\ntype = \"grid\"\nmap = \"" +
                                             std::string(PRIDE_SOURCE_DIR) +
                                             "/examples/maps/wan2022-10x10.map\"\nstart = [0, 0]\ngoal = [9, 9]\n"
                                             "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\npop = 10\n"
                                             "[[algorithm]]\nid = \"ga\"\ntype = \"ga\"\npop = 10\n");
    const std::string store = dir.file("c.sqlite");
    const auto bench = run_pride("bench " + quote(config) + " --jobs 2 --out " + quote(store));
    INFO(bench.out << bench.err);
    REQUIRE(bench.status == 0);
    const auto s = pride::storage::read_store(store);
    REQUIRE(s.precisions);
    // COCO's 51 targets 10^2, 10^1.8, ..., 10^-8 (every fifth a power of ten, exactly).
    REQUIRE(s.precisions->size() == 51);
    for (std::size_t k = 0; k < 51; ++k)
        CHECK_THAT((*s.precisions)[k], WithinRel(std::pow(10.0, 2.0 - 0.2 * static_cast<double>(k)), 1e-14));
    for (std::size_t k = 0; k < 51; k += 5)
        CHECK((*s.precisions)[k] == std::stod("1e" + std::to_string(2 - int(k) / 5)));
    constexpr std::size_t n = 51;
    const auto& sphere = (*s.problems)[0];
    REQUIRE(sphere.f_opt);
    std::map<std::string, std::vector<std::vector<coco::TargetRun>>> by_algorithm;  // sphere runs, per precision
    for (const auto& r : s.runs) {
        if (r.problem == "grid") {
            CHECK(r.target_hits.empty());  // no known optimum: no hits
            continue;
        }
        REQUIRE(r.target_hits.size() == n);
        auto& per = by_algorithm[r.algorithm];
        per.resize(n);
        // COCO's trace: its target triggers (20 per decade) include the 51 targets (5 per decade),
        // so the first trace point at or below a target is the exact hit.
        REQUIRE(!r.trace_targets.empty());
        CHECK(r.trace_targets.front().evaluations == 1);
        CHECK(r.trace_targets.back().best >= *r.best);  // improvements within a trigger are not kept
        REQUIRE(!r.trace_evaluations.empty());
        CHECK(r.trace_evaluations.front().evaluations == 1);
        for (std::size_t k = 0; k < n; ++k) {
            std::optional<std::int64_t> traced;
            for (const auto& t : r.trace_targets)
                if (t.best <= *sphere.f_opt + (*s.precisions)[k]) {
                    traced = t.evaluations;
                    break;
                }
            CHECK(traced == r.target_hits[k]);
        }
        for (std::size_t k = 0; k < n; ++k) {
            INFO(r.algorithm << " seed " << r.seed << " precision " << (*s.precisions)[k]);
            per[k].push_back({r.evaluations, r.target_hits[k], sphere.dim});
            // The exact hit lies within the first iteration whose best value reached the target.
            std::optional<std::size_t> first;
            for (std::size_t i = 0; i < r.history.size() && !first; ++i)
                if (r.history[i] - *sphere.f_opt <= (*s.precisions)[k]) first = i;
            CHECK(bool(first) == bool(r.target_hits[k]));
            if (first && r.target_hits[k]) {
                CHECK(*r.target_hits[k] <= r.history_evaluations[*first]);
                if (*first > 0) CHECK(*r.target_hits[k] > r.history_evaluations[*first - 1]);
            }
        }
    }
    REQUIRE(by_algorithm.size() == 2);
    const auto report = pride::report::load_report(store);
    REQUIRE(report.coco);
    CHECK(report.coco->runs_without_hits == 6);  // the grid's
    REQUIRE(report.coco->erts.size() == 2);
    for (const auto& row : report.coco->erts) {
        CHECK(row.function == "sphere");
        CHECK(row.dim == 4);
        CHECK(row.runs == 3);
        for (std::size_t k = 0; k < n; ++k) {
            const coco::Ert e = coco::ert(by_algorithm.at(row.algorithm)[k]);
            CHECK(row.ert[k].value == e.value);
            CHECK(row.ert[k].successes == e.successes);
        }
    }
    const auto md = run_pride("report " + quote(store));
    REQUIRE(md.status == 0);
    CHECK(md.out.find("### sphere, 4-D (1 instance)") != std::string::npos);
    CHECK(md.out.find("| algorithm | ERT 1e1 | ERT 1e-1 | ERT 1e-3 | ERT 1e-5 | ERT 1e-7 | ERT 1e-8 | #succ |") !=
          std::string::npos);
    const auto ert_csv = run_pride("report " + quote(store) + " --format ert-csv");
    REQUIRE(ert_csv.status == 0);
    CHECK(std::count(ert_csv.out.begin(), ert_csv.out.end(), '\n') == 1 + 2 * 51);
}

TEST_CASE("coco: a bbob [[suite]] campaign from pride bench to tables, figures and IOH files",
          "[report][coco][bench]") {
    TempDir dir("pride-coco-suite");
    const std::string config = dir.write("s.toml",
                                         "name = \"bbob-small\"\nseeds = 2\n[budget]\nevaluations = 400\n"
                                         "[[suite]]\nname = \"bbob\"\nfunctions = [1, 20]\ninstances = [1, 2]\n"
                                         "dimensions = [2]\n"
                                         "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\npop = 10\n");
    const std::string store = dir.file("s.sqlite");
    const auto bench = run_pride("bench " + quote(config) + " --jobs 2 --out " + quote(store));
    INFO(bench.out << bench.err);
    REQUIRE(bench.status == 0);
    const auto s = pride::storage::read_store(store);
    REQUIRE(s.problems->size() == 4);
    for (const auto& p : *s.problems) {
        CHECK(p.suite == "bbob");
        CHECK(p.f_opt);
        CHECK((p.fid == 1 || p.fid == 20));
        CHECK(p.function == fmt::format("bbob-f{}", *p.fid));
        CHECK((p.instance == 1 || p.instance == 2));
    }
    const auto report = pride::report::load_report(store);
    REQUIRE(report.coco);
    REQUIRE(report.coco->erts.size() == 2);
    CHECK(report.coco->erts[0].function == "bbob-f1");
    CHECK(report.coco->erts[0].instances == 2);
    CHECK(report.coco->erts[0].runs == 4);  // 2 instances x 2 seeds
    CHECK(report.coco->erts[1].function == "bbob-f20");
    const auto md = run_pride("report " + quote(store) + " --plots " + quote(dir.file("figures")));
    REQUIRE(md.status == 0);
    CHECK(md.out.find("### bbob-f1, 2-D (2 instances)") != std::string::npos);
    CHECK(md.out.find("### bbob-f20, 2-D (2 instances)") != std::string::npos);
    for (const char* stem : {"ecdf_all", "ecdf_separable", "ecdf_weakly-structured"})
        CHECK(std::filesystem::exists(dir.path() / "figures" / (std::string(stem) + ".png")));

    // IOH: one function per fid, the runs of both instances in one data file, named by instance.
    const std::string out = dir.file("ioh");
    REQUIRE(run_pride("export " + quote(store) + " --ioh " + quote(out)).status == 0);
    const std::filesystem::path a = std::filesystem::path(out) / "pso";
    const std::string info = slurp(a / "IOHprofiler_f20_Schwefel.info");
    CHECK(info.rfind("suite = \"BBOB\", funcId = 20, funcName = \"Schwefel\", DIM = 2, maximization = \"F\", "
                     "algId = \"pso\", algInfo = \"campaign bbob-small\"\n%\n"
                     "data_f20_Schwefel/IOHprofiler_f20_DIM2.dat, 1:400|",
                     0) == 0);
    CHECK(info.find(", 2:400|") != std::string::npos);
    CHECK(std::count(info.begin(), info.end(), ':') == 4);
    const std::string dat = slurp(a / "data_f20_Schwefel" / "IOHprofiler_f20_DIM2.dat");
    std::size_t blocks = 0;
    for (auto at = dat.find("\"function evaluation\""); at != std::string::npos;
         at = dat.find("\"function evaluation\"", at + 1))
        ++blocks;
    CHECK(blocks == 4);
    CHECK(std::filesystem::exists(a / "IOHprofiler_f1_Sphere.info"));
    CHECK(std::distance(std::filesystem::directory_iterator(a), std::filesystem::directory_iterator()) == 4);
}

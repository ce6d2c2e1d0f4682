// Campaign stores read back by experiment/report: the CSV of `pride report` holds every number as the
// double it is (checked against the store read here with sqlite3, and against the library's
// ReportData), and a damaged store (malformed JSON, values of the wrong kind, missing tables or
// columns, corrupt pages) is bad input for `pride report` and `pride export`: exit 2, one line.
#include <sqlite3.h>
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "experiment/report/report.hpp"
#include "experiment/storage/reader.hpp"
#include "tests/cli_runner.hpp"
#include "tests/test_support.hpp"

namespace {

using pride::test::check_input_error;
using pride::test::lines_of;
using pride::test::run_pride;
using pride::test::TempDir;

constexpr double inf = std::numeric_limits<double>::infinity();

std::string quote(const std::string& s) {
    return "'" + s + "'";
}

/// A tiny campaign with a target, a grid problem (an optimum) and continuous ones (values with
/// all 17 digits), run by pride bench; its store.
std::string bench_store(const TempDir& dir) {
    const std::string map = std::string(PRIDE_SOURCE_DIR) + "/examples/maps/wan2022-10x10.map";
    const std::string config = dir.write("tiny.toml",
                                         "name = \"tiny\"\nseeds = 3\n[budget]\niterations = 8\ntarget = 14\n"
                                         "[[problem]]\nid = \"sphere\"\ntype = \"sphere\"\ndim = 3\n"
                                         "[[problem]]\nid = \"rastrigin\"\ntype = \"shifted-rastrigin\"\ndim = 2\n"
                                         "[[problem]]\nid = \"grid\"\ntype = \"grid\"\nmap = \"" +
                                             map +
                                             "\"\nstart = [0, 0]\ngoal = [9, 9]\n"
                                             "[[algorithm]]\nid = \"ga\"\ntype = \"ga\"\npop = 10\n"
                                             "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\npop = 10\n");
    const std::string store = dir.file("tiny.sqlite");
    const auto bench = run_pride("bench " + quote(config) + " --jobs 2 --out " + quote(store));
    INFO("bench: " << bench.out << bench.err);
    REQUIRE(bench.status == 0);
    return store;
}

void exec(sqlite3* db, const std::string& sql) {
    char* message = nullptr;
    const int rc = sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &message);
    INFO(sql << ": " << (message ? message : ""));
    sqlite3_free(message);
    REQUIRE(rc == SQLITE_OK);
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

/// A CSV cell holds exactly `expected`: empty for none, "inf", or a number that reads back as it.
void check_exact(const std::string& column, const std::string& cell, const std::optional<double>& expected) {
    INFO(column << ": '" << cell << "', expected " << (expected ? fmt::format("{:.17g}", *expected) : "none"));
    if (!expected) {
        CHECK(cell.empty());
        return;
    }
    if (std::isinf(*expected)) {
        CHECK(cell == "inf");
        return;
    }
    char* end = nullptr;
    const double v = std::strtod(cell.c_str(), &end);
    CHECK(!cell.empty());
    CHECK(*end == '\0');
    CHECK(v == *expected);
}

std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> out(1);
    for (const char c : line)
        if (c == ',')
            out.emplace_back();
        else
            out.back() += c;
    return out;
}

}  // namespace

TEST_CASE("report: csv numbers read back as the stored doubles", "[report][csv][precision]") {
    TempDir dir("pride-precision");
    const std::string store = bench_store(dir);
    const auto r = run_pride("report " + quote(store) + " --format csv");
    INFO(r.err);
    REQUIRE(r.status == 0);
    const auto lines = lines_of(r.out);
    REQUIRE(lines.size() == 7);  // the header and 3 problems x 2 algorithms
    CHECK(lines[0] ==
          "problem,algorithm,runs,min,mean,std,median,max,mean_wall_ms,mean_evaluations,optimum,mean_gap,success,"
          "p_holm_vs_best,is_best,f_opt,measure,a12_vs_best,target,reached_target,mean_evaluations_to_target");

    // The store, read here: per (problem, algorithm) the best values (+inf for NULL) and
    // evaluations in seed order, and the optimum.
    struct Stored {
        std::vector<double> best;
        double evaluations = 0;
        std::optional<double> optimum;
    };
    std::map<std::pair<std::string, std::string>, Stored> stored;
    std::optional<double> target;
    {
        sqlite3* db = nullptr;
        REQUIRE(sqlite3_open_v2(store.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK);
        sqlite3_stmt* s = nullptr;
        REQUIRE(sqlite3_prepare_v2(db, "SELECT target FROM campaign", -1, &s, nullptr) == SQLITE_OK);
        REQUIRE(sqlite3_step(s) == SQLITE_ROW);
        target = sqlite3_column_double(s, 0);
        sqlite3_finalize(s);
        REQUIRE(sqlite3_prepare_v2(db,
                                   "SELECT problem, algorithm, best, evaluations, optimum FROM runs "
                                   "ORDER BY problem, algorithm, seed",
                                   -1, &s, nullptr) == SQLITE_OK);
        while (sqlite3_step(s) == SQLITE_ROW) {
            Stored& c = stored[{reinterpret_cast<const char*>(sqlite3_column_text(s, 0)),
                                reinterpret_cast<const char*>(sqlite3_column_text(s, 1))}];
            c.best.push_back(sqlite3_column_type(s, 2) == SQLITE_NULL ? inf : sqlite3_column_double(s, 2));
            c.evaluations += static_cast<double>(sqlite3_column_int64(s, 3));
            if (sqlite3_column_type(s, 4) != SQLITE_NULL) c.optimum = sqlite3_column_double(s, 4);
        }
        sqlite3_finalize(s);
        sqlite3_close(db);
    }
    REQUIRE(stored.size() == 6);

    // And the same store through the library: the CSV carries its doubles bit for bit.
    const pride::report::ReportData data = pride::report::load_report(store);
    REQUIRE(data.rows.size() == 6);
    REQUIRE(data.target == target);
    std::size_t longer = 0;  // cells with more than the 6 significant digits of the markdown
    for (std::size_t i = 0; i < data.rows.size(); ++i) {
        const auto c = split(lines[i + 1]);
        const pride::report::ReportRow& row = data.rows[i];
        INFO(lines[i + 1]);
        REQUIRE(c.size() == 21);
        CHECK(c[0] == row.problem);
        CHECK(c[1] == row.algorithm);
        const Stored& s = stored.at({row.problem, row.algorithm});
        REQUIRE(s.best.size() == 3);
        CHECK(c[2] == "3");
        // What the store holds itself: min, max, the median of three, the optimum, the target.
        std::vector<double> sorted = s.best;
        std::sort(sorted.begin(), sorted.end());
        check_exact("min", c[3], sorted[0]);
        check_exact("median", c[6], sorted[1]);
        check_exact("max", c[7], sorted[2]);
        check_exact("optimum", c[10], s.optimum);
        check_exact("target", c[18], target);
        // Means of the stored values, summed in seed order.
        check_exact("mean", c[4], (s.best[0] + s.best[1] + s.best[2]) / 3);
        check_exact("mean_evaluations", c[9], s.evaluations / 3);
        // Every number against the library's report.
        check_exact("min", c[3], row.min);
        check_exact("mean", c[4], row.mean);
        check_exact("std", c[5], row.std);
        check_exact("median", c[6], row.median);
        check_exact("max", c[7], row.max);
        check_exact("mean_wall_ms", c[8], row.mean_wall_ms);
        check_exact("mean_evaluations", c[9], row.mean_evaluations);
        check_exact("optimum", c[10], row.optimum);
        check_exact("mean_gap", c[11], row.mean_gap);
        check_exact("success", c[12], row.success);
        check_exact("p_holm_vs_best", c[13], row.p_holm);
        CHECK(c[14] == (row.best ? "1" : "0"));
        check_exact("f_opt", c[15], row.f_opt);
        CHECK(c[16] == (row.precision ? "precision" : "value"));
        check_exact("a12_vs_best", c[17], row.a12);
        CHECK(c[19] == std::to_string(row.reached_target));
        check_exact("mean_evaluations_to_target", c[20], row.mean_evaluations_to_target);
        for (const double v : {row.min, row.mean, row.std, row.median, row.max, row.mean_wall_ms})
            if (std::isfinite(v) && fmt::format("{}", v) != fmt::format("{:.6g}", v)) ++longer;
    }
    CHECK(longer > 0);                      // else this test would not tell full precision from 6 digits
    CHECK(data.rows[0].problem == "grid");  // the grid rows have an optimum
    CHECK(data.rows[0].optimum);
}

TEST_CASE("report, export: a damaged store is bad input, one line naming what and where", "[report][export][damaged]") {
    TempDir dir("pride-damaged");
    const std::string store = bench_store(dir);
    const std::string row = "runs row (problem 'sphere', algorithm 'pso', seed 2)";
    const std::string where = " WHERE problem = 'sphere' AND algorithm = 'pso' AND seed = 2";
    struct Case {
        std::string name, sql;
        std::vector<std::string> words;  // besides the store and "damaged store"
        bool report = true, exporting = true;
    };
    // Tables recreated without their NOT NULL constraints, to hold NULL where pride bench never does.
    const std::string loose_runs =
        "CREATE TABLE loose AS SELECT * FROM runs; DROP TABLE runs; ALTER TABLE loose RENAME TO runs; ";
    const std::string loose_campaign =
        "CREATE TABLE loose AS SELECT * FROM campaign; DROP TABLE campaign; ALTER TABLE loose RENAME TO campaign; ";
    const std::vector<Case> cases = {
        // Malformed histories: not a JSON list of numbers.
        {"history-x", "UPDATE runs SET history = '[1, x]'" + where, {row, "column history", "'[1, x]'"}},
        {"history-string", "UPDATE runs SET history = '\"abc\"'" + where, {row, "column history", "\"abc\""}},
        {"history-open", "UPDATE runs SET history = '[1, 2'" + where, {row, "column history"}},
        {"history-empty", "UPDATE runs SET history = ''" + where, {row, "column history"}},
        {"history-object", "UPDATE runs SET history = '{\"a\": 1}'" + where, {row, "column history"}},
        {"history-nested", "UPDATE runs SET history = '[[1], 2]'" + where, {row, "column history"}},
        {"history-commas", "UPDATE runs SET history = '[1,, 2]'" + where, {row, "column history"}},
        {"history-nan", "UPDATE runs SET history = '[1, NaN]'" + where, {row, "column history", "NaN"}},
        {"history-inf", "UPDATE runs SET history = '[1, inf]'" + where, {row, "column history"}},
        {"history-overflow", "UPDATE runs SET history = '[1e999]'" + where, {row, "column history"}},
        {"history-trailing", "UPDATE runs SET history = '[1] 2'" + where, {row, "column history"}},
        {"history-number", "UPDATE runs SET history = 5" + where, {row, "column history"}},
        {"history-blob", "UPDATE runs SET history = x'00ff'" + where, {row, "column history", "blob"}},
        // Malformed evaluation counts.
        {"evaluations-x",
         "UPDATE runs SET history_evaluations = '[10, x]'" + where,
         {row, "column history_evaluations", "[10, x]"}},
        {"evaluations-fraction",
         "UPDATE runs SET history_evaluations = '[10.5]'" + where,
         {row, "column history_evaluations"}},
        {"evaluations-null",
         "UPDATE runs SET history_evaluations = '[null]'" + where,
         {row, "column history_evaluations"}},
        {"evaluations-negative",
         "UPDATE runs SET history_evaluations = '[-10' || substr(history_evaluations, instr(history_evaluations, "
         "','))" +
             where,
         {row, "column history_evaluations", "negative"}},
        {"evaluations-short",
         "UPDATE runs SET history_evaluations = '[10]'" + where,
         {row, "column history_evaluations", "history"}},
        // Values of the wrong kind where numbers belong.
        {"best-nan", "UPDATE runs SET best = 'NaN'" + where, {row, "column best", "NaN"}},
        {"best-text", "UPDATE runs SET best = 'abc'" + where, {row, "column best", "abc"}},
        {"best-infinite", "UPDATE runs SET best = 9e999" + where, {row, "column best", "finite"}},
        {"wall-text", "UPDATE runs SET wall_ms = 'slow'" + where, {row, "column wall_ms", "slow"}},
        {"evaluations-text", "UPDATE runs SET evaluations = 'many'" + where, {row, "column evaluations", "many"}},
        {"evaluations-real", "UPDATE runs SET evaluations = 2.5" + where, {row, "column evaluations", "2.5"}},
        {"optimum-text",
         "UPDATE runs SET optimum = 'x' WHERE problem = 'grid' AND algorithm = 'ga' AND seed = 1",
         {"runs row (problem 'grid', algorithm 'ga', seed 1)", "column optimum"}},
        {"seed-text", "UPDATE runs SET seed = 'two'" + where, {"runs row", "column seed", "two"}},
        {"problem-null", loose_runs + "UPDATE runs SET problem = NULL" + where, {"runs row", "column problem", "NULL"}},
        {"target-text", "UPDATE campaign SET target = 'low'", {"campaign", "column target", "low"}},
        {"name-null", loose_campaign + "UPDATE campaign SET name = NULL", {"campaign", "column name", "NULL"}},
        {"dim-text",
         "UPDATE problems SET dim = 'three' WHERE id = 'sphere'",
         {"problems row 'sphere'", "column dim", "three"}},
        // Missing tables, columns and rows.
        {"no-runs-table", "DROP TABLE runs", {"no table runs"}},
        {"no-campaign-table", "DROP TABLE campaign", {"no table campaign"}},
        // Stores from before the problems table are still reported; only the export needs it.
        {"no-problems-table", "DROP TABLE problems", {"no table problems"}, false, true},
        {"no-history-column", "ALTER TABLE runs DROP COLUMN history", {"table runs", "no column history"}},
        {"no-best-column", "ALTER TABLE runs DROP COLUMN best", {"table runs", "no column best"}},
        {"no-dim-column", "ALTER TABLE problems DROP COLUMN dim", {"table problems", "no column dim"}},
        {"no-campaign-row", "DELETE FROM campaign", {"table campaign", "no row"}},
    };
    for (const Case& c : cases) {
        const std::string path = tampered(dir, store, c.name, c.sql);
        std::vector<std::string> words = c.words;
        words.push_back(path + ": damaged store: ");
        if (c.report) {
            for (const char* format : {"md", "csv"}) {
                INFO(c.name << ": pride report --format " << format);
                check_input_error(run_pride("report " + quote(path) + " --format " + format), words);
            }
        } else {  // what the report does not read does not stop it
            INFO(c.name << ": pride report");
            CHECK(run_pride("report " + quote(path)).status == 0);
        }
        if (c.exporting) {
            INFO(c.name << ": pride export");
            const std::string out = dir.file(c.name + "-ioh");
            check_input_error(run_pride("export " + quote(path) + " --ioh " + quote(out)), words);
            CHECK(!std::filesystem::exists(out));  // nothing written from a damaged store
        }
    }

    // A store with corrupt pages: what SQLite finds is reported the same way.
    const std::string corrupt = dir.file("corrupt.sqlite");
    std::filesystem::copy_file(store, corrupt);
    {
        std::fstream f(corrupt, std::ios::in | std::ios::out | std::ios::binary);
        // Every page but the first (the schema): the tables' pages are garbage.
        const auto size = std::filesystem::file_size(corrupt);
        REQUIRE(size > 4096);
        f.seekp(4096);
        f << std::string(size - 4096, '\xff');
    }
    check_input_error(run_pride("report " + quote(corrupt)), {corrupt + ": damaged store: "});
    check_input_error(run_pride("export " + quote(corrupt) + " --ioh " + quote(dir.file("x"))),
                      {corrupt + ": damaged store: "});
    const std::string truncated = dir.file("truncated.sqlite");
    std::filesystem::copy_file(store, truncated);
    std::filesystem::resize_file(truncated, 8192);
    check_input_error(run_pride("report " + quote(truncated)), {truncated + ": damaged store: "});

    // The untouched store is fine, and the library throws a DamagedStore (an InputError).
    CHECK(run_pride("report " + quote(store)).status == 0);
    const std::string bad = dir.file("history-x.sqlite");
    CHECK_THROWS_AS(pride::report::load_report(bad), pride::storage::DamagedStore);
    CHECK(pride::test::input_error_message([&] { pride::storage::read_store(bad); }) ==
          bad + ": damaged store: " + row +
              ", column history: expected a JSON list of numbers, got '[1, x]' (wrong at character 5)");
}

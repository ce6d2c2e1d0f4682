// Campaign stores read back by engine/report: the CSV of `pride report` holds every number as the
// double it is (checked against the store read here with sqlite3, and against the library's
// ReportData).
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

#include "engine/report/report.hpp"
#include "engine/report/store.hpp"
#include "tests/cli_runner.hpp"
#include "tests/test_support.hpp"

namespace {

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
    const std::string map = std::string(PRIDE_SOURCE_DIR) + "/examples/maps/file000-10x10.map";
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
          "p_holm_vs_best,best,target,reached_target,mean_evaluations_to_target");

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
        REQUIRE(c.size() == 18);
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
        check_exact("target", c[15], target);
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
        CHECK(c[16] == std::to_string(row.reached_target));
        check_exact("mean_evaluations_to_target", c[17], row.mean_evaluations_to_target);
        for (const double v : {row.min, row.mean, row.std, row.median, row.max, row.mean_wall_ms})
            if (std::isfinite(v) && fmt::format("{}", v) != fmt::format("{:.6g}", v)) ++longer;
    }
    CHECK(longer > 0);                      // else this test would not tell full precision from 6 digits
    CHECK(data.rows[0].problem == "grid");  // the grid rows have an optimum
    CHECK(data.rows[0].optimum);
}

// Tests of `pride report STORE [--format md|csv|latex]` (cli/report.cpp over experiment/report/) as a
// user runs it: a store written here with sqlite3 (the schema of cli/campaign.cpp) and hand-chosen
// values, every CSV column checked against values computed independently below; the markdown and
// LaTeX tables; the errors; and `pride bench` followed by `pride report` end to end.
#include <sqlite3.h>
#include <catch2/catch.hpp>

#include <stdlib.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "cli_runner.hpp"
#include "tests/test_support.hpp"

using pride::test::lines_of;

namespace {

using pride::test::expect_input_error;
using pride::test::run_pride;
constexpr double inf = std::numeric_limits<double>::infinity();

/// A fresh folder under /tmp, removed with everything in it at the end of the test.
struct TempDir {
    std::string path;
    TempDir() {
        char name[] = "/tmp/pride-report-XXXXXX";
        if (!mkdtemp(name)) throw std::runtime_error("mkdtemp failed");
        path = name;
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(path, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    std::string operator/(const std::string& file) const { return path + "/" + file; }
};

std::string shell_quote(const std::string& s) {
    return "'" + s + "'";
}

std::vector<std::string> split(const std::string& s, const std::string& sep) {
    std::vector<std::string> out;
    std::size_t start = 0;
    for (;;) {
        const auto at = s.find(sep, start);
        if (at == std::string::npos) {
            out.push_back(s.substr(start));
            return out;
        }
        out.push_back(s.substr(start, at - start));
        start = at + sep.size();
    }
}

std::string g(const char* format, double v) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, format, v);
    return buffer;
}

// ---------------------------------------------------------------------------------------------
// The store

struct StoredRun {
    std::string problem, algorithm;
    int seed;
    std::optional<double> best;  // NULL: no feasible value
    long long evaluations;
    double wall_ms;
    std::optional<double> optimum;
};

void exec(sqlite3* db, const std::string& sql) {
    char* message = nullptr;
    if (sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &message) != SQLITE_OK) {
        const std::string why = message ? message : "?";
        sqlite3_free(message);
        throw std::runtime_error(sql + ": " + why);
    }
}

/// A store as `pride bench` writes it (the two tables of cli/campaign.cpp), holding `runs`.
void write_store(const std::string& path, const std::vector<StoredRun>& runs) {
    sqlite3* db = nullptr;
    REQUIRE(sqlite3_open(path.c_str(), &db) == SQLITE_OK);
    exec(db, "CREATE TABLE campaign (id INTEGER PRIMARY KEY CHECK (id = 1), name TEXT NOT NULL, text TEXT NOT NULL)");
    exec(db,
         "CREATE TABLE runs (problem TEXT NOT NULL, algorithm TEXT NOT NULL, seed INTEGER NOT NULL, "
         "feasible INTEGER NOT NULL, best REAL, evaluations INTEGER NOT NULL, iterations INTEGER NOT NULL, "
         "wall_ms REAL NOT NULL, optimum REAL, solution TEXT NOT NULL, history TEXT NOT NULL, "
         "history_evaluations TEXT NOT NULL, UNIQUE (problem, algorithm, seed))");
    exec(db, "INSERT INTO campaign (id, name, text) VALUES (1, 'hand-made', 'name = \"hand-made\"')");
    sqlite3_stmt* s = nullptr;
    REQUIRE(sqlite3_prepare_v2(db,
                               "INSERT INTO runs (problem, algorithm, seed, feasible, best, evaluations, iterations, "
                               "wall_ms, optimum, solution, history, history_evaluations) "
                               "VALUES (?, ?, ?, ?, ?, ?, 7, ?, ?, '[0.5]', '[9, 8]', '[10, 20]')",
                               -1, &s, nullptr) == SQLITE_OK);
    for (const auto& r : runs) {
        sqlite3_reset(s);
        sqlite3_bind_text(s, 1, r.problem.c_str(), -1, SQLITE_TRANSIENT);
        sqlite3_bind_text(s, 2, r.algorithm.c_str(), -1, SQLITE_TRANSIENT);
        sqlite3_bind_int(s, 3, r.seed);
        sqlite3_bind_int(s, 4, r.best ? 1 : 0);
        if (r.best)
            sqlite3_bind_double(s, 5, *r.best);
        else
            sqlite3_bind_null(s, 5);
        sqlite3_bind_int64(s, 6, r.evaluations);
        sqlite3_bind_double(s, 7, r.wall_ms);
        if (r.optimum)
            sqlite3_bind_double(s, 8, *r.optimum);
        else
            sqlite3_bind_null(s, 8);
        REQUIRE(sqlite3_step(s) == SQLITE_DONE);
    }
    sqlite3_finalize(s);
    sqlite3_close(db);
}

// 3 problems x 3 algorithms x 5 seeds. Inserted in an order other than the report's (which sorts
// by problem, algorithm), with values chosen so that:
//  - rastrigin: ga and pso share the median 3 and the value 3; pso wins on the mean (2.8 < 3);
//  - sphere: one run of ga is infeasible (NULL best, +inf), so its mean, std and max are inf;
//    pso's five runs are equal (std 0); Holm's monotone step lifts ga's p to pso's;
//  - grid10 (optimum 12 on every row, as grid runs store it): nlopt_sbplx is at the optimum every
//    time; ga and nlopt_sbplx tie on the median, nlopt_sbplx wins on the mean; one pso run is
//    12 * (1 + 1e-11), at the optimum up to rounding; pso's raw p (0.025) is below 0.05 but its
//    Holm-corrected p (0.051) is not.
const std::vector<StoredRun> kRuns = {
    // problem, algorithm, seed, best, evaluations, wall_ms, optimum
    {"rastrigin", "pso", 1, 3.0, 1000, 2.5, {}},
    {"rastrigin", "pso", 2, 2.5, 1000, 3.5, {}},
    {"rastrigin", "pso", 3, 5.0, 1000, 2.0, {}},
    {"rastrigin", "pso", 4, 3.0, 1000, 4.0, {}},
    {"rastrigin", "pso", 5, 0.5, 1000, 3.0, {}},
    {"rastrigin", "ga", 1, 3.0, 1000, 1.0, {}},
    {"rastrigin", "ga", 2, 1.0, 1010, 1.5, {}},
    {"rastrigin", "ga", 3, 2.0, 1020, 2.0, {}},
    {"rastrigin", "ga", 4, 5.0, 1030, 2.5, {}},
    {"rastrigin", "ga", 5, 4.0, 1040, 3.0, {}},
    {"rastrigin", "nlopt_sbplx", 1, 10.0, 900, 0.25, {}},
    {"rastrigin", "nlopt_sbplx", 2, 12.0, 950, 0.5, {}},
    {"rastrigin", "nlopt_sbplx", 3, 11.0, 1000, 0.75, {}},
    {"rastrigin", "nlopt_sbplx", 4, 10.0, 1000, 1.0, {}},
    {"rastrigin", "nlopt_sbplx", 5, 14.0, 1000, 1.25, {}},
    {"sphere", "ga", 1, 1e-3, 2000, 10.0, {}},
    {"sphere", "ga", 2, 2e-3, 2000, 11.0, {}},
    {"sphere", "ga", 3, {}, 2000, 12.0, {}},
    {"sphere", "ga", 4, 5e-4, 2000, 13.0, {}},
    {"sphere", "ga", 5, 1e-3, 2000, 14.0, {}},
    {"sphere", "nlopt_sbplx", 1, 1e-6, 300, 0.1, {}},
    {"sphere", "nlopt_sbplx", 2, 2e-6, 400, 0.2, {}},
    {"sphere", "nlopt_sbplx", 3, 3e-6, 500, 0.3, {}},
    {"sphere", "nlopt_sbplx", 4, 4e-6, 600, 0.4, {}},
    {"sphere", "nlopt_sbplx", 5, 5e-6, 700, 0.5, {}},
    {"sphere", "pso", 1, 1e-4, 2000, 5.0, {}},
    {"sphere", "pso", 2, 1e-4, 2000, 5.0, {}},
    {"sphere", "pso", 3, 1e-4, 2000, 5.0, {}},
    {"sphere", "pso", 4, 1e-4, 2000, 5.0, {}},
    {"sphere", "pso", 5, 1e-4, 2000, 5.0, {}},
    {"grid10", "ga", 1, 12.0, 440, 0.8, 12.0},
    {"grid10", "ga", 2, 12.0, 440, 0.9, 12.0},
    {"grid10", "ga", 3, 14.0, 440, 1.0, 12.0},
    {"grid10", "ga", 4, 13.0, 440, 1.1, 12.0},
    {"grid10", "ga", 5, 12.0, 440, 1.2, 12.0},
    {"grid10", "nlopt_sbplx", 1, 12.0, 100, 0.05, 12.0},
    {"grid10", "nlopt_sbplx", 2, 12.0, 110, 0.05, 12.0},
    {"grid10", "nlopt_sbplx", 3, 12.0, 120, 0.05, 12.0},
    {"grid10", "nlopt_sbplx", 4, 12.0, 130, 0.05, 12.0},
    {"grid10", "nlopt_sbplx", 5, 12.0, 140, 0.05, 12.0},
    {"grid10", "pso", 1, 15.0, 420, 2.0, 12.0},
    {"grid10", "pso", 2, 12.0, 420, 2.0, 12.0},
    {"grid10", "pso", 3, 18.0, 420, 2.0, 12.0},
    {"grid10", "pso", 4, 12.0 * (1 + 1e-11), 420, 2.0, 12.0},
    {"grid10", "pso", 5, 13.5, 420, 2.0, 12.0},
};

// ---------------------------------------------------------------------------------------------
// The expected report, computed here independently of experiment/report/report.cpp and
// experiment/report/statistics.hpp

double mean(const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x;
    return s / static_cast<double>(v.size());
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 == 1 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

/// Sample standard deviation (n - 1); infinite when a value is.
double sample_std(const std::vector<double>& v) {
    for (double x : v)
        if (!std::isfinite(x)) return inf;
    const double m = mean(v);
    double s = 0;
    for (double x : v) s += (x - m) * (x - m);
    return std::sqrt(s / static_cast<double>(v.size() - 1));
}

/// Mann-Whitney U, two-sided, normal approximation with the tie and continuity corrections (as
/// scipy.stats.mannwhitneyu(x, y, method="asymptotic")), written from the textbook formulas: the
/// midrank of v in the pooled sample is (#values below v) + (#values equal to v + 1) / 2.
double mann_whitney_p(const std::vector<double>& x, const std::vector<double>& y) {
    std::vector<double> pooled = x;
    pooled.insert(pooled.end(), y.begin(), y.end());
    auto count = [&](double v, bool below) {
        return static_cast<double>(
            std::count_if(pooled.begin(), pooled.end(), [&](double w) { return below ? w < v : w == v; }));
    };
    double r1 = 0;
    for (double v : x) r1 += count(v, true) + (count(v, false) + 1) / 2;
    const double n1 = static_cast<double>(x.size()), n2 = static_cast<double>(y.size()), n = n1 + n2;
    const double u1 = r1 - n1 * (n1 + 1) / 2;
    double ties = 0;  // sum of t^3 - t over the groups of equal values
    for (std::size_t i = 0; i < pooled.size(); ++i) {
        const bool first = std::find(pooled.begin(), pooled.begin() + static_cast<std::ptrdiff_t>(i), pooled[i]) ==
                           pooled.begin() + static_cast<std::ptrdiff_t>(i);
        const double t = count(pooled[i], false);
        if (first) ties += t * t * t - t;
    }
    const double variance = n1 * n2 / 12 * ((n + 1) - ties / (n * (n - 1)));
    if (variance <= 0) return 1.0;
    const double z = (std::max(u1, n1 * n2 - u1) - n1 * n2 / 2 - 0.5) / std::sqrt(variance);
    return std::min(1.0, std::erfc(z / std::sqrt(2.0)));  // 2 * (1 - Phi(z))
}

/// Holm's step-down adjustment, in the input order.
std::vector<double> holm(const std::vector<double>& p) {
    std::vector<std::size_t> order(p.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return p[a] < p[b]; });
    std::vector<double> out(p.size());
    double running = 0;
    for (std::size_t k = 0; k < order.size(); ++k) {
        running = std::max(running, std::min(1.0, static_cast<double>(p.size() - k) * p[order[k]]));
        out[order[k]] = running;
    }
    return out;
}

struct Expected {
    std::string problem, algorithm;
    std::size_t runs = 0;
    double min = 0, mean = 0, std = 0, median = 0, max = 0, wall = 0, evaluations = 0;
    std::optional<double> optimum, gap, success, p_holm;
    bool best = false;
};

/// One row per (problem, algorithm), sorted by problem then algorithm.
std::vector<Expected> expected_report(const std::vector<StoredRun>& runs) {
    std::map<std::string, std::map<std::string, std::vector<const StoredRun*>>> cells;
    for (const auto& r : runs) cells[r.problem][r.algorithm].push_back(&r);
    std::vector<Expected> rows;
    for (const auto& [problem, by_algorithm] : cells) {
        std::map<std::string, std::vector<double>> values;
        for (const auto& [algorithm, list] : by_algorithm)
            for (const StoredRun* r : list) values[algorithm].push_back(r->best.value_or(inf));
        std::string best;
        for (const auto& [algorithm, v] : values)
            if (best.empty() || median(v) < median(values[best]) ||
                (median(v) == median(values[best]) && mean(v) < mean(values[best])))
                best = algorithm;
        std::vector<double> p;
        std::vector<std::size_t> tested;
        for (const auto& [algorithm, list] : by_algorithm) {
            const std::vector<double>& v = values[algorithm];
            Expected e;
            e.problem = problem;
            e.algorithm = algorithm;
            e.runs = v.size();
            e.min = *std::min_element(v.begin(), v.end());
            e.max = *std::max_element(v.begin(), v.end());
            e.mean = mean(v);
            e.std = sample_std(v);
            e.median = median(v);
            std::vector<double> wall, evaluations;
            for (const StoredRun* r : list) {
                wall.push_back(r->wall_ms);
                evaluations.push_back(static_cast<double>(r->evaluations));
            }
            e.wall = mean(wall);
            e.evaluations = mean(evaluations);
            e.best = algorithm == best;
            if (list.front()->optimum) {
                const double opt = *list.front()->optimum;
                e.optimum = opt;
                double gap = 0, at = 0;
                for (double x : v) {
                    if (std::abs(x - opt) <= 1e-9 * std::abs(opt))
                        ++at;
                    else
                        gap += (x - opt) / std::abs(opt);
                }
                e.gap = gap / static_cast<double>(v.size());
                e.success = at / static_cast<double>(v.size());
            }
            if (!e.best) {
                p.push_back(mann_whitney_p(v, values[best]));
                tested.push_back(rows.size());
            }
            rows.push_back(e);
        }
        const auto adjusted = holm(p);
        for (std::size_t i = 0; i < tested.size(); ++i) rows[tested[i]].p_holm = adjusted[i];
    }
    return rows;
}

/// A number printed by the report: "inf" when infinite, else within 6 significant digits (all that
/// a markdown cell holds; the CSV holds more).
void check_number(const std::string& column, const std::string& cell, double expected) {
    INFO(column << ": '" << cell << "', expected " << g("%.17g", expected));
    if (!std::isfinite(expected)) {
        CHECK(cell == "inf");
        return;
    }
    char* end = nullptr;
    const double v = std::strtod(cell.c_str(), &end);
    CHECK(!cell.empty());
    CHECK(*end == '\0');
    CHECK(v == Approx(expected).epsilon(1e-5).margin(1e-300));
}

/// A CSV number: the whole cell parses to within 1e-12 (relative) of `expected`, which carries
/// its own rounding (hand and scipy values); the CSV carries every digit of the report's double.
void check_close(const std::string& cell, double expected) {
    INFO("'" << cell << "', expected " << g("%.17g", expected));
    char* end = nullptr;
    const double v = std::strtod(cell.c_str(), &end);
    CHECK(!cell.empty());
    CHECK(*end == '\0');
    CHECK(std::abs(v - expected) <= 1e-12 * std::abs(expected));
}

void check_optional(const std::string& column, const std::string& cell, const std::optional<double>& expected) {
    INFO(column);
    if (expected)
        check_number(column, cell, *expected);
    else
        CHECK(cell.empty());
}

std::string report(const std::string& store, const std::string& format) {
    const auto r = run_pride("report " + shell_quote(store) + " --format " + format);
    INFO("stderr: " << r.err);
    REQUIRE(r.status == 0);
    CHECK(r.err.empty());
    return r.out;
}

const std::vector<std::string> kCsvHeader = {"problem",      "algorithm",
                                             "runs",         "min",
                                             "mean",         "std",
                                             "median",       "max",
                                             "mean_wall_ms", "mean_evaluations",
                                             "optimum",      "mean_gap",
                                             "success",      "p_holm_vs_best",
                                             "is_best",      "f_opt",
                                             "measure",      "a12_vs_best"};

/// The CSV as rows of cells (the header checked and dropped).
std::vector<std::vector<std::string>> parse_csv(const std::string& text) {
    REQUIRE(!text.empty());
    CHECK(text.back() == '\n');
    const auto lines = lines_of(text);
    REQUIRE(!lines.empty());
    CHECK(split(lines[0], ",") == kCsvHeader);
    std::vector<std::vector<std::string>> rows;
    for (std::size_t i = 1; i < lines.size(); ++i) {
        INFO("line " << i << ": " << lines[i]);
        rows.push_back(split(lines[i], ","));
        REQUIRE(rows.back().size() == kCsvHeader.size());
    }
    return rows;
}

/// The rows of a markdown or LaTeX table: the lines that start with `start`, split at `sep`.
std::vector<std::vector<std::string>> table_rows(const std::vector<std::string>& lines, const std::string& sep) {
    std::vector<std::vector<std::string>> rows;
    for (const auto& line : lines) {
        if (sep == " | " && line.rfind("| ", 0) == 0 && line.size() >= 2 && line.substr(line.size() - 2) == " |")
            rows.push_back(split(line.substr(2, line.size() - 4), sep));
        if (sep == " & " && line.size() >= 3 && line.substr(line.size() - 3) == " \\\\")
            rows.push_back(split(line.substr(0, line.size() - 3), sep));
    }
    return rows;
}

const std::vector<std::string> kTableHeader = {"problem", "algorithm", "runs", "min",     "mean",     "std", "median",
                                               "max",     "mean ms",   "gap",  "optimal", "p (Holm)", "A12"};

}  // namespace

// ---------------------------------------------------------------------------------------------
// The independent statistics above, on the cases worked by hand

TEST_CASE("report: the test's own Mann-Whitney and Holm agree with hand computations", "[report]") {
    // rastrigin, nlopt_sbplx {10,12,11,10,14} against the best, pso {3,2.5,5,3,0.5}: every value of
    // nlopt_sbplx is above every value of pso, so U1 = 25 (the larger of U1 and U2 = 0). Ties in
    // the pooled 10 values: 3 twice and 10 twice, sum(t^3 - t) = 6 + 6 = 12. Variance
    // n1 n2 / 12 ((n + 1) - 12 / (n (n - 1))) = 25/12 (11 - 12/90) = 22.638888...;
    // z = (25 - 12.5 - 0.5) / sqrt(22.6389) = 12 / 4.758034 = 2.522050; p = erfc(z / sqrt 2) = 0.011667.
    const std::vector<double> pso{3, 2.5, 5, 3, 0.5}, nlopt{10, 12, 11, 10, 14}, ga{3, 1, 2, 5, 4};
    CHECK(mann_whitney_p(nlopt, pso) == Approx(0.011667312343319398).epsilon(1e-9));
    // rastrigin, ga {3,1,2,5,4} against pso. Pooled, sorted: 0.5p 1g 2g 2.5p 3g 3p 3p 4g 5g 5p, midranks
    // 1 2 3 4 6 6 6 8 9.5 9.5; ga's rank sum 2 + 3 + 6 + 8 + 9.5 = 28.5, U1 = 28.5 - 15 = 13.5,
    // U2 = 11.5. Ties: 3 three times (24), 5 twice (6): 30. Variance 25/12 (11 - 30/90) = 22.2222;
    // z = (13.5 - 12.5 - 0.5) / 4.714045 = 0.106066; p = 0.915530.
    CHECK(mann_whitney_p(ga, pso) == Approx(0.9155299733767719).epsilon(1e-9));
    // Holm over {0.9155, 0.011667}: 2 * 0.011667 = 0.023335 and max(0.023335, 1 * 0.9155) = 0.9155.
    const auto h = holm({0.9155299733767719, 0.011667312343319398});
    CHECK(h[0] == Approx(0.9155299733767719).epsilon(1e-12));
    CHECK(h[1] == Approx(0.023334624686638796).epsilon(1e-12));
    // sphere: p(pso) = 0.0074950 (x2 = 0.014990) is smaller than p(ga) = 0.011925, so Holm lifts
    // ga's adjusted p to 0.014990 (the running maximum), not 0.011925.
    const auto lifted = holm({0.011925233593017606, 0.007494957516935249});
    CHECK(lifted[0] == Approx(0.014989915033870498).epsilon(1e-12));
    CHECK(lifted[1] == Approx(0.014989915033870498).epsilon(1e-12));
    // All values equal: no evidence, p = 1.
    CHECK(mann_whitney_p({12, 12, 12}, {12, 12}) == 1.0);
}

// ---------------------------------------------------------------------------------------------
// CSV: every column against the independent computation

TEST_CASE("report: csv columns equal values computed independently", "[report][csv]") {
    TempDir dir;
    const std::string store = dir / "hand.sqlite";
    write_store(store, kRuns);
    const auto rows = parse_csv(report(store, "csv"));
    const auto expected = expected_report(kRuns);
    REQUIRE(expected.size() == 9);
    REQUIRE(rows.size() == expected.size());
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const auto& c = rows[i];
        const Expected& e = expected[i];
        INFO("row " << i + 1 << ": " << e.problem << ", " << e.algorithm);
        CHECK(c[0] == e.problem);
        CHECK(c[1] == e.algorithm);
        CHECK(c[2] == std::to_string(e.runs));
        check_number("min", c[3], e.min);
        check_number("mean", c[4], e.mean);
        check_number("std", c[5], e.std);
        check_number("median", c[6], e.median);
        check_number("max", c[7], e.max);
        check_number("mean_wall_ms", c[8], e.wall);
        check_number("mean_evaluations", c[9], e.evaluations);
        check_optional("optimum", c[10], e.optimum);
        check_optional("mean_gap", c[11], e.gap);
        check_optional("success", c[12], e.success);
        check_optional("p_holm_vs_best", c[13], e.p_holm);
        CHECK(c[14] == (e.best ? "1" : "0"));
    }

    // The same values, hand-computed, for a few cells (order: grid10, rastrigin, sphere; then ga,
    // nlopt_sbplx, pso).
    auto row = [&](const std::string& p, const std::string& a) {
        for (const auto& r : rows)
            if (r[0] == p && r[1] == a) return r;
        FAIL("no row " << p << ", " << a);
        return std::vector<std::string>{};
    };
    // grid10 ga {12,12,14,13,12}, optimum 12: mean 12.6, std sqrt(3.2/4), gaps 0,0,2/12,1/12,0 -> 0.05; 3 of 5 at it.
    auto r = row("grid10", "ga");
    CHECK(r == std::vector<std::string>{"grid10", "ga", "5", "12", "12.6", r[5], "12", "14", "1", "440", "12", "0.05",
                                        "0.6", r[13], "0", "", "value", "0.3"});
    check_close(r[5], std::sqrt(0.8));
    check_close(r[13], 0.17971249487899985);
    // grid10 pso {15,12,18,12(1+1e-11),13.5}: median 13.5, mean 14.1 + 2.4e-11 (the CSV keeps every
    // digit); gaps 3/12, 0, 6/12, 0, 1.5/12 -> 0.175; 2 of 5.
    // U1 = 22.5 against nlopt_sbplx's five 12s: p = 0.025370, Holm x2 = 0.050740 (and ga's 0.1797 stays).
    r = row("grid10", "pso");
    CHECK(r[6] == "13.5");
    check_close(r[4], 14.1 + 12e-11 / 5);
    CHECK(r[4] != "14.1");
    CHECK(r[11] == "0.175");
    CHECK(r[12] == "0.4");
    check_close(r[13], 2 * 0.02536985982205372);
    r = row("grid10", "nlopt_sbplx");
    CHECK(r == std::vector<std::string>{"grid10", "nlopt_sbplx", "5", "12", "12", "0", "12", "12", "0.05", "120", "12",
                                        "0", "1", "", "1", "", "value", ""});
    // rastrigin: pso is best (median 3 like ga, mean 2.8 < 3).
    CHECK(row("rastrigin", "pso")[14] == "1");
    CHECK(row("rastrigin", "ga")[14] == "0");
    check_close(row("rastrigin", "ga")[13], 0.9155299733767719);
    check_close(row("rastrigin", "nlopt_sbplx")[13], 0.023334624686638796);
    check_close(row("rastrigin", "nlopt_sbplx")[5], std::sqrt(11.2 / 4));
    // sphere ga with one infeasible run: min 5e-4, median 1e-3, mean, std and max infinite.
    r = row("sphere", "ga");
    CHECK(r[3] == "0.0005");
    CHECK(r[4] == "inf");
    CHECK(r[6] == "0.001");
    CHECK(r[7] == "inf");
    CHECK(r[10].empty());
    check_close(r[13], 0.014989915033870498);
    CHECK(row("sphere", "pso")[5] == "0");
    CHECK(row("sphere", "nlopt_sbplx")[14] == "1");
}

// ---------------------------------------------------------------------------------------------
// Markdown

TEST_CASE("report: md table with best and star markers and the Friedman ranks", "[report][md]") {
    TempDir dir;
    const std::string store = dir / "hand.sqlite";
    write_store(store, kRuns);
    const std::string text = report(store, "md");
    INFO(text);
    CHECK(text.find("`hand-made`") != std::string::npos);  // the campaign's name
    const auto lines = lines_of(text);
    const auto rows = table_rows(lines, " | ");
    REQUIRE(rows.size() == 10);  // header and 9 rows
    CHECK(rows[0] == kTableHeader);
    CHECK(std::count(lines.begin(), lines.end(), "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|") ==
          1);

    const auto expected = expected_report(kRuns);
    for (std::size_t i = 0; i < expected.size(); ++i) {
        const auto& c = rows[i + 1];
        const Expected& e = expected[i];
        INFO(e.problem << ", " << e.algorithm);
        REQUIRE(c.size() == kTableHeader.size());
        CHECK(c[0] == e.problem);
        CHECK(c[1] == e.algorithm);
        CHECK(c[2] == "5");
        check_number("min", c[3], e.min);
        check_number("mean", c[4], e.mean);
        check_number("std", c[5], e.std);
        check_number("median", c[6], e.median);
        check_number("max", c[7], e.max);
        CHECK(c[8] == g("%.3f", e.wall));
        CHECK(c[9] == (e.gap ? g("%.2f %%", 100 * *e.gap) : "-"));
        CHECK(c[10] == (e.success ? g("%.0f %%", 100 * *e.success) : "-"));
        if (e.best) {
            CHECK(c[11] == "best");
            CHECK(c[12] == "-");
        } else {
            REQUIRE(e.p_holm);
            CHECK(c[11] == g("%.3g", *e.p_holm) + (*e.p_holm < 0.05 ? "*" : ""));
        }
    }
    // By hand: the markers of each problem.
    auto p_of = [&](const std::string& p, const std::string& a) {
        for (std::size_t i = 1; i < rows.size(); ++i)
            if (rows[i][0] == p && rows[i][1] == a) return rows[i][11];
        return std::string("(missing)");
    };
    CHECK(p_of("grid10", "nlopt_sbplx") == "best");
    CHECK(p_of("grid10", "ga") == "0.18");
    // A12 of grid10 ga {12,12,14,13,12} against nlopt_sbplx's five 12s: no pair better, 3 x 5 ties
    // at half: 7.5 / 25.
    for (std::size_t i = 1; i < rows.size(); ++i)
        if (rows[i][0] == "grid10" && rows[i][1] == "ga") CHECK(rows[i][12] == "0.30");
    CHECK(p_of("grid10", "pso") == "0.0507");  // raw 0.0254 < 0.05, Holm-corrected not: no star
    CHECK(p_of("rastrigin", "pso") == "best");
    CHECK(p_of("rastrigin", "ga") == "0.916");
    CHECK(p_of("rastrigin", "nlopt_sbplx") == "0.0233*");
    CHECK(p_of("sphere", "nlopt_sbplx") == "best");
    CHECK(p_of("sphere", "ga") == "0.015*");
    CHECK(p_of("sphere", "pso") == "0.015*");
    CHECK(rows[1][9] == "5.00 %");  // grid10 ga
    CHECK(rows[1][10] == "60 %");
    CHECK(rows[4][9] == "-");  // rastrigin ga

    // Friedman on the medians (rows: problems; columns: ga, nlopt_sbplx, pso):
    //   grid10     12 (1.5)   12 (1.5)   13.5 (3)
    //   rastrigin  3 (1.5)    11 (3)     3 (1.5)
    //   sphere     1e-3 (3)   3e-6 (1)   1e-4 (2)
    // average ranks 6/3 = 2, 5.5/3 = 1.8333, 6.5/3 = 2.1667. Chi-squared: 12/(n k (k+1)) sum R^2 -
    // 3 n (k+1) = (36 + 30.25 + 42.25)/3 - 36 = 1/6, tie correction 1 - 12/(k (k^2-1) n) = 1 - 12/72
    // = 5/6, so 0.2; with 2 degrees of freedom p = exp(-0.2 / 2) = 0.904837.
    const std::string friedman =
        "Friedman average ranks over 3 problems (1 = best; median values): ga 2, nlopt_sbplx 1.83, pso 2.17; "
        "chi-squared 0.2, p = 0.905";
    CHECK(std::count(lines.begin(), lines.end(), friedman) == 1);
    // The pairs: se = sqrt(3 x 4 / (6 x 3)) = 0.8165; |z| = 0.204, 0.204, 0.408 (p = 0.838, 0.838,
    // 0.683), all Holm-corrected to 1.
    CHECK(std::count(lines.begin(), lines.end(),
                     "Pairs (z-test on the average ranks, Holm over 3 pairs; Demsar 2006): ga vs nlopt_sbplx p = 1; "
                     "ga vs pso p = 1; nlopt_sbplx vs pso p = 1") == 1);
}

// ---------------------------------------------------------------------------------------------
// LaTeX

TEST_CASE("report: latex tabular with escaped percent and underscore", "[report][latex]") {
    TempDir dir;
    const std::string store = dir / "hand.sqlite";
    write_store(store, kRuns);
    const std::string text = report(store, "latex");
    INFO(text);
    const auto lines = lines_of(text);
    REQUIRE(lines.size() >= 14);
    CHECK(lines[0] == "\\begin{tabular}{llrrrrrrrrrrr}");
    CHECK(lines[1] == "\\hline");
    const auto end = std::find(lines.begin(), lines.end(), "\\end{tabular}");
    REQUIRE(end != lines.end());
    CHECK(*(end - 1) == "\\hline");
    const std::vector<std::string> table(lines.begin(), end);
    const auto rows = table_rows(table, " & ");
    REQUIRE(rows.size() == 10);
    CHECK(rows[0] == kTableHeader);
    for (std::size_t i = 1; i < rows.size(); ++i) CHECK(rows[i].size() == kTableHeader.size());
    // Every % and _ inside the table is escaped; algorithm ids and percentages show it.
    for (const auto& line : table)
        for (std::size_t k = 0; k < line.size(); ++k)
            if (line[k] == '%' || line[k] == '_') {
                INFO(line);
                CHECK(k > 0);
                CHECK(line[k - 1] == '\\');
            }
    CHECK(rows[1] == std::vector<std::string>{"grid10", "ga", "5", "12", "12.6", g("%.6g", std::sqrt(0.8)), "12", "14",
                                              "1.000", "5.00 \\%", "60 \\%", "0.18", "0.30"});
    CHECK(rows[2][1] == "nlopt\\_sbplx");
    CHECK(rows[2][11] == "best");
    CHECK(rows[5][1] == "nlopt\\_sbplx");
    CHECK(rows[5][11] == "0.0233*");
    CHECK(text.find("nlopt\\_sbplx") != std::string::npos);
    // After the tabular, the Friedman ranks as a LaTeX comment.
    bool comment = false;
    for (auto it = end + 1; it != lines.end(); ++it)
        if (it->rfind("% Friedman average ranks over 3 problems", 0) == 0) comment = true;
    CHECK(comment);
}

// ---------------------------------------------------------------------------------------------
// Errors

TEST_CASE("report: bad stores and formats exit 2 with one line", "[report][errors]") {
    TempDir dir;
    expect_input_error("report " + shell_quote(dir / "missing.sqlite"), {"missing.sqlite"});
    expect_input_error("report " + shell_quote(dir / "missing.sqlite") + " --format csv", {"missing.sqlite"});
    expect_input_error("report " + shell_quote(dir.path), {dir.path});  // a folder

    const std::string text = dir / "notes.sqlite";
    {
        std::ofstream f(text);
        for (int i = 0; i < 40; ++i) f << "this is not an SQLite database, only text, line " << i << "\n";
    }
    expect_input_error("report " + shell_quote(text), {"notes.sqlite"});
    const std::string small = dir / "small.sqlite";
    std::ofstream(small) << "hello\n";
    expect_input_error("report " + shell_quote(small), {"small.sqlite"});
    const std::string empty = dir / "empty.sqlite";
    { std::ofstream f(empty); }  // 0 bytes: an empty SQLite database without the tables
    expect_input_error("report " + shell_quote(empty), {"empty.sqlite"});

    const std::string no_runs = dir / "no-runs.sqlite";
    write_store(no_runs, {});
    expect_input_error("report " + shell_quote(no_runs), {"no-runs.sqlite"});
    expect_input_error("report " + shell_quote(no_runs) + " --format csv", {"no runs"});

    const std::string good = dir / "good.sqlite";
    write_store(good, kRuns);
    expect_input_error("report " + shell_quote(good) + " --format html", {"--format"});
    expect_input_error("report " + shell_quote(good) + " --format ''", {"--format"});
    expect_input_error("report " + shell_quote(good) + " --format CSV", {"--format"});
    expect_input_error("report " + shell_quote(good) + " --format", {"format"});  // no value
    expect_input_error("report", {"store"});                                      // no store
    // And the good store is fine with the default format.
    const auto r = run_pride("report " + shell_quote(good));
    CHECK(r.status == 0);
    CHECK(r.out.find("| problem | algorithm |") != std::string::npos);
}

// ---------------------------------------------------------------------------------------------
// End to end: pride bench, then pride report

TEST_CASE("report: pride bench then pride report on a tiny campaign", "[report][bench]") {
    TempDir dir;
    const std::string config = dir / "tiny.toml";
    std::ofstream(config) << "name = \"tiny\"\n"
                             "seeds = 3\n"
                             "[budget]\n"
                             "evaluations = 500\n"
                             "[[problem]]\nid = \"sphere_3\"\ntype = \"sphere\"\ndim = 3\n"
                             "[[problem]]\nid = \"rastrigin-3\"\ntype = \"shifted-rastrigin\"\ndim = 3\n"
                             "[[algorithm]]\nid = \"pso10\"\ntype = \"pso\"\npop = 10\n"
                             "[[algorithm]]\nid = \"ga_10\"\ntype = \"ga\"\npop = 10\n";
    const std::string store = dir / "tiny.sqlite";
    const auto bench = run_pride("bench " + shell_quote(config) + " --jobs 2 --out " + shell_quote(store));
    INFO("bench stdout: " << bench.out << "\nbench stderr: " << bench.err);
    REQUIRE(bench.status == 0);

    const auto rows = parse_csv(report(store, "csv"));
    REQUIRE(rows.size() == 4);
    std::set<std::pair<std::string, std::string>> seen;
    for (const auto& c : rows) {
        INFO(c[0] << ", " << c[1]);
        seen.emplace(c[0], c[1]);
        CHECK(c[2] == "3");
        // Continuous with f_opt = 0: no grid optimum; values are precisions, gap their mean and
        // optimal the share within 1e-8 of f_opt.
        CHECK(c[10].empty());
        CHECK(c[15] == "0");
        CHECK(c[16] == "precision");
        CHECK(std::strtod(c[11].c_str(), nullptr) == Approx(std::strtod(c[4].c_str(), nullptr)).epsilon(1e-12));
        const double solved = std::strtod(c[12].c_str(), nullptr);
        CHECK((solved >= 0 && solved <= 1));
        const double evaluations = std::strtod(c[9].c_str(), nullptr);
        CHECK(evaluations > 0);
        CHECK(evaluations <= 500);
        const double lo = std::strtod(c[3].c_str(), nullptr), md = std::strtod(c[6].c_str(), nullptr),
                     hi = std::strtod(c[7].c_str(), nullptr);
        CHECK(lo <= md);
        CHECK(md <= hi);
        CHECK(std::isfinite(hi));
    }
    const std::set<std::pair<std::string, std::string>> all{
        {"rastrigin-3", "ga_10"}, {"rastrigin-3", "pso10"}, {"sphere_3", "ga_10"}, {"sphere_3", "pso10"}};
    CHECK(seen == all);
    // One best per problem; the other algorithm has a p-value.
    for (const auto& problem : {"rastrigin-3", "sphere_3"}) {
        int best = 0, tested = 0;
        for (const auto& c : rows)
            if (c[0] == problem) {
                best += c[14] == "1";
                tested += !c[13].empty();
            }
        CHECK(best == 1);
        CHECK(tested == 1);
    }
    // The min column equals the store's MIN(best), read here with sqlite3.
    sqlite3* db = nullptr;
    REQUIRE(sqlite3_open_v2(store.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK);
    sqlite3_stmt* s = nullptr;
    REQUIRE(sqlite3_prepare_v2(db,
                               "SELECT problem, algorithm, COUNT(*), MIN(best), AVG(evaluations) FROM runs "
                               "GROUP BY problem, algorithm ORDER BY problem, algorithm",
                               -1, &s, nullptr) == SQLITE_OK);
    std::size_t i = 0;
    while (sqlite3_step(s) == SQLITE_ROW && i < rows.size()) {
        const auto& c = rows[i++];
        CHECK(c[0] == reinterpret_cast<const char*>(sqlite3_column_text(s, 0)));
        CHECK(c[1] == reinterpret_cast<const char*>(sqlite3_column_text(s, 1)));
        CHECK(sqlite3_column_int(s, 2) == 3);
        check_number("min", c[3], sqlite3_column_double(s, 3));
        check_number("mean_evaluations", c[9], sqlite3_column_double(s, 4));
    }
    CHECK(i == 4);
    sqlite3_finalize(s);
    sqlite3_close(db);

    const std::string md = report(store, "md");
    CHECK(md.find("Friedman average ranks over 2 problems") != std::string::npos);
    CHECK(std::count(md.begin(), md.end(), '\n') >= 6);
    const std::string tex = report(store, "latex");
    CHECK(tex.find("ga\\_10") != std::string::npos);
    CHECK(tex.find("sphere\\_3") != std::string::npos);
}

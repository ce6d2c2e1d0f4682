// Reports in precision: where a continuous problem's optimum f_opt is known, pride report
// gives f - f_opt (COCO's precision), its mean as the gap and the share within 1e-8 as optimal; --raw
// gives the values f; `[budget] precision` sets the target f_opt + precision per problem. Every
// figure is checked against the store's own values, computed here.
#include <sqlite3.h>
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "tests/cli_runner.hpp"
#include "tests/json_reader.hpp"
#include "tests/test_support.hpp"

namespace fs = std::filesystem;

namespace {

/// The CSV lines of `pride report STORE --format csv ARGS`, each split at commas, keyed by the header.
std::vector<std::map<std::string, std::string>> report_csv(const fs::path& store, const std::string& args = "") {
    const auto r = pride::test::run_pride("report '" + store.string() + "' --format csv" + args);
    INFO(r.err);
    REQUIRE(r.status == 0);
    std::istringstream in(r.out);
    std::string line;
    std::getline(in, line);
    std::vector<std::string> head;
    std::stringstream h(line);
    for (std::string c; std::getline(h, c, ',');) head.push_back(c);
    std::vector<std::map<std::string, std::string>> rows;
    while (std::getline(in, line)) {
        std::vector<std::string> f;
        std::stringstream cells(line);
        for (std::string c; std::getline(cells, c, ',');) f.push_back(c);
        if (line.back() == ',') f.push_back("");
        REQUIRE(f.size() == head.size());
        std::map<std::string, std::string> row;
        for (std::size_t i = 0; i < f.size(); ++i) row[head[i]] = f[i];
        rows.push_back(row);
    }
    return rows;
}

struct StoredRuns {
    std::vector<double> best;
    std::vector<std::optional<double>> hit;  // evaluations to reach f_opt + precision
};

}  // namespace

TEST_CASE("report: precisions f - f_opt where f_opt is known, raw values on request", "[report][precision]") {
    const pride::test::TempDir tmp("pride-precision-report");
    const fs::path& dir = tmp.path();
    std::ofstream(dir / "c.toml") << "name = \"precision\"\nseeds = 4\n[budget]\nevaluations = 600\nprecision = 1e-6\n"
                                     "[[problem]]\nid = \"f1\"\ntype = \"bbob-f1\"\ndim = 2\ninstance = 1\n"
                                     "[[problem]]\nid = \"f8\"\ntype = \"bbob-f8\"\ndim = 2\ninstance = 2\n"
                                     "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\npop = 20\n"
                                     "[[algorithm]]\nid = \"sbplx\"\ntype = \"nlopt:LN_SBPLX\"\n";
    const fs::path store = dir / "c.sqlite";
    REQUIRE(pride::test::run_pride("bench '" + (dir / "c.toml").string() + "' --jobs 2 --out '" + store.string() + "'")
                .status == 0);
    // The store's values, and COCO's f_opt of each problem (f1 instance 1: 79.48).
    std::map<std::string, double> f_opt;
    std::map<std::pair<std::string, std::string>, StoredRuns> stored;
    {
        sqlite3* db = nullptr;
        REQUIRE(sqlite3_open_v2(store.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK);
        sqlite3_stmt* q = nullptr;
        REQUIRE(sqlite3_prepare_v2(db, "SELECT id, f_opt FROM problems", -1, &q, nullptr) == SQLITE_OK);
        while (sqlite3_step(q) == SQLITE_ROW)
            f_opt[reinterpret_cast<const char*>(sqlite3_column_text(q, 0))] = sqlite3_column_double(q, 1);
        sqlite3_finalize(q);
        REQUIRE(sqlite3_prepare_v2(db,
                                   "SELECT problem, algorithm, best, history, history_evaluations FROM runs ORDER BY "
                                   "problem, algorithm, seed",
                                   -1, &q, nullptr) == SQLITE_OK);
        while (sqlite3_step(q) == SQLITE_ROW) {
            auto text = [&](int k) { return std::string(reinterpret_cast<const char*>(sqlite3_column_text(q, k))); };
            const std::string problem = text(0);
            StoredRuns& s = stored[{problem, text(1)}];
            s.best.push_back(sqlite3_column_double(q, 2));
            const auto history = pride::test::json_numbers(pride::test::parse_json(text(3)));
            const auto counts = pride::test::json_numbers(pride::test::parse_json(text(4)));
            std::optional<double> first;
            for (std::size_t k = 0; k < history.size() && !first; ++k)
                if (history[k] <= f_opt.at(problem) + 1e-6) first = counts[k];
            s.hit.push_back(first);
        }
        sqlite3_finalize(q);
        sqlite3_close(db);
    }
    REQUIRE(f_opt.at("f1") == 79.48);
    REQUIRE(stored.size() == 4);

    const auto rows = report_csv(store);
    REQUIRE(rows.size() == 4);
    bool some_solved = false, some_not = false;
    for (const auto& row : rows) {
        INFO(row.at("problem") << " " << row.at("algorithm"));
        const double opt = f_opt.at(row.at("problem"));
        const StoredRuns& s = stored.at({row.at("problem"), row.at("algorithm")});
        std::vector<double> precision;
        double sum = 0;
        int solved = 0;
        for (const double f : s.best) {
            precision.push_back(f - opt);
            sum += f - opt;
            solved += f - opt <= 1e-8;
        }
        CHECK(row.at("measure") == "precision");
        CHECK(std::stod(row.at("f_opt")) == opt);
        CHECK(std::stod(row.at("min")) == *std::min_element(precision.begin(), precision.end()));
        CHECK(std::stod(row.at("max")) == *std::max_element(precision.begin(), precision.end()));
        CHECK(std::stod(row.at("mean_gap")) == Approx(sum / 4).epsilon(1e-12));
        CHECK(std::stod(row.at("success")) == solved / 4.0);
        (solved ? some_solved : some_not) = true;
        CHECK(row.at("optimum").empty());  // the grid optimum column stays for grids
        // The target: f_opt + 1e-6, reached as the histories say.
        CHECK(std::stod(row.at("target")) == opt + 1e-6);
        CHECK(std::stod(row.at("target_precision")) == 1e-6);
        int reached = 0;
        double evaluations = 0;
        for (const auto& h : s.hit)
            if (h) ++reached, evaluations += *h;
        CHECK(std::stoi(row.at("reached_target")) == reached);
        if (reached) CHECK(std::stod(row.at("mean_evaluations_to_target")) == Approx(evaluations / reached));
    }
    CHECK(some_solved);  // subplex solves f1 to 1e-8: the optimal column is not vacuous
    CHECK(some_not);

    // --raw: the values as run.
    for (const auto& row : report_csv(store, " --raw")) {
        const StoredRuns& s = stored.at({row.at("problem"), row.at("algorithm")});
        CHECK(row.at("measure") == "value");
        CHECK(std::stod(row.at("min")) == *std::min_element(s.best.begin(), s.best.end()));
    }
    // The markdown names the measure and shows f_opt, never "79.48" as every value.
    const auto md = pride::test::run_pride("report '" + store.string() + "'");
    REQUIRE(md.status == 0);
    CHECK(md.out.find("min to max are precisions f - f_opt") != std::string::npos);
    CHECK(md.out.find("| f_opt |") != std::string::npos);
    CHECK(md.out.find("| 79.48 |") != std::string::npos);
    CHECK(md.out.find("Target: f_opt + 1e-06.") != std::string::npos);
    // The figures: precisions on a log axis, against evaluations (matplotlib's SVG keeps each
    // text as a comment beside its glyphs).
    const auto plots =
        pride::test::run_pride("report '" + store.string() + "' --plots '" + (dir / "figs").string() + "'");
    REQUIRE(plots.status == 0);
    const std::string svg = pride::test::slurp(dir / "figs" / "f8-convergence.svg");
    CHECK(svg.find("<!-- precision f - f_opt (median, IQR band) -->") != std::string::npos);
    CHECK(svg.find("<!-- evaluations -->") != std::string::npos);
    CHECK(svg.find("\\mathdefault{10^{") != std::string::npos);  // log ticks
    CHECK(pride::test::slurp(dir / "figs" / "f8-final.svg").find("<!-- final precision f - f_opt -->") !=
          std::string::npos);
}

TEST_CASE("report: a grid campaign with A* plots against evaluations, A* as a line", "[report][precision]") {
    const pride::test::TempDir tmp("pride-precision-grid");
    const fs::path& dir = tmp.path();
    std::ofstream(dir / "g.toml") << "name = \"g\"\nseeds = 2\n[budget]\nevaluations = 200\n"
                                     "[[problem]]\nid = \"g\"\ntype = \"grid\"\nmap = \""
                                  << PRIDE_SOURCE_DIR
                                  << "/examples/maps/wan2022-10x10.map\"\n"
                                     "start = [0, 0]\ngoal = [9, 9]\n"
                                     "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\n"
                                     "[[algorithm]]\nid = \"astar\"\ntype = \"astar\"\n";
    const fs::path store = dir / "g.sqlite";
    REQUIRE(pride::test::run_pride("bench '" + (dir / "g.toml").string() + "' --out '" + store.string() + "'").status ==
            0);
    REQUIRE(
        pride::test::run_pride("report '" + store.string() + "' --plots '" + (dir / "figs").string() + "'").status ==
        0);
    const std::string svg = pride::test::slurp(dir / "figs" / "g-convergence.svg");
    CHECK(svg.find("<!-- evaluations -->") != std::string::npos);  // was "iteration" with A* present
    CHECK(svg.find("<!-- astar (whole map) -->") != std::string::npos);
    CHECK(svg.find("<!-- best value (median, IQR band) -->") != std::string::npos);  // no f_opt: values
}

TEST_CASE("report: [budget] precision is checked where it is read", "[report][precision]") {
    const pride::test::TempDir tmp("pride-precision-toml");
    auto refused = [&](const std::string& budget) {
        const std::string file = tmp.write("c.toml", "name = \"p\"\nseeds = 1\n[budget]\nevaluations = 10\n" + budget +
                                                         "[[problem]]\nid = \"s\"\ntype = \"sphere\"\ndim = 2\n"
                                                         "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\n");
        const auto r = pride::test::run_pride("bench '" + file + "' --out '" + tmp.file("c.sqlite") + "'");
        CHECK(r.status == 2);
        return r.err;
    };
    CHECK_THAT(refused("precision = 0\n"), Catch::Contains("c.toml:5: 'precision' must be a finite number > 0"));
    CHECK_THAT(refused("precision = -1e-8\n"), Catch::Contains("'precision' must be a finite number > 0"));
    CHECK_THAT(refused("precision = \"1e-8\"\n"), Catch::Contains("precision"));
    CHECK_THAT(refused("target = 1\nprecision = 1e-8\n"),
               Catch::Contains("[budget]: give target (an absolute value) or precision (f_opt + precision), not both"));
}

TEST_CASE("campaign: evaluations_per_dim budgets each problem by its dimension", "[campaign][budget]") {
    const pride::test::TempDir tmp("pride-per-dim");
    const std::string problems =
        "[[problem]]\nid = \"s2\"\ntype = \"sphere\"\ndim = 2\n"
        "[[problem]]\nid = \"f3\"\ntype = \"bbob-f3\"\ndim = 5\n"
        "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\npop = 10\n";
    const std::string file =
        tmp.write("c.toml", "name = \"d\"\nseeds = 2\n[budget]\nevaluations_per_dim = 60\n" + problems);
    const auto r = pride::test::run_pride("bench '" + file + "' --out '" + tmp.file("c.sqlite") + "'");
    INFO(r.err);
    REQUIRE(r.status == 0);
    std::map<std::string, std::int64_t> evaluations;
    {
        sqlite3* db = nullptr;
        REQUIRE(sqlite3_open_v2(tmp.file("c.sqlite").c_str(), &db, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK);
        sqlite3_stmt* q = nullptr;
        REQUIRE(sqlite3_prepare_v2(db, "SELECT problem, evaluations FROM runs", -1, &q, nullptr) == SQLITE_OK);
        while (sqlite3_step(q) == SQLITE_ROW)
            evaluations[reinterpret_cast<const char*>(sqlite3_column_text(q, 0))] = sqlite3_column_int64(q, 1);
        sqlite3_finalize(q);
        sqlite3_close(db);
    }
    CHECK(evaluations == std::map<std::string, std::int64_t>{{"s2", 120}, {"f3", 300}});
    auto refused = [&](const std::string& text) {
        const std::string bad = tmp.write("bad.toml", text);
        const auto b = pride::test::run_pride("bench '" + bad + "' --out '" + tmp.file("bad.sqlite") + "'");
        CHECK(b.status == 2);
        return b.err;
    };
    CHECK_THAT(refused("name = \"d\"\nseeds = 1\n[budget]\nevaluations_per_dim = 10\nevaluations = 5\n" + problems),
               Catch::Contains("[budget]: give evaluations or evaluations_per_dim, not both"));
    CHECK_THAT(refused("name = \"d\"\nseeds = 1\n[budget]\nevaluations_per_dim = 0\n" + problems),
               Catch::Contains("bad.toml:4: 'evaluations_per_dim' must be in [1, 1000000000000000], got 0"));
    CHECK_THAT(refused("name = \"d\"\nseeds = 1\n[budget]\nevaluations_per_dim = 10\n"
                       "[[problem]]\nid = \"g\"\ntype = \"grid\"\nmap = \"" PRIDE_SOURCE_DIR
                       "/examples/maps/wan2022-10x10.map\"\nstart = [0, 0]\ngoal = [9, 9]\n"
                       "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\n"),
               Catch::Contains("problem 'g': evaluations_per_dim: a grid problem has no dimension"));
}

TEST_CASE("report: ERT pools a function's seeded instances, never its instance 0", "[report][precision]") {
    const pride::test::TempDir tmp("pride-pooling");
    const std::string file = tmp.write("c.toml",
                                       "name = \"pool\"\nseeds = 2\n[budget]\nevaluations = 200\n"
                                       "[[problem]]\nid = \"r0\"\ntype = \"rastrigin\"\ndim = 2\ninstance = 0\n"
                                       "[[problem]]\nid = \"r1\"\ntype = \"rastrigin\"\ndim = 2\ninstance = 1\n"
                                       "[[problem]]\nid = \"r2\"\ntype = \"rastrigin\"\ndim = 2\ninstance = 2\n"
                                       "[[problem]]\nid = \"b1\"\ntype = \"bbob-f3\"\ndim = 2\ninstance = 1\n"
                                       "[[problem]]\nid = \"b2\"\ntype = \"bbob-f3\"\ndim = 2\ninstance = 2\n"
                                       "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\npop = 10\n");
    REQUIRE(pride::test::run_pride("bench '" + file + "' --out '" + tmp.file("c.sqlite") + "'").status == 0);
    const auto r = pride::test::run_pride("report '" + tmp.file("c.sqlite") + "' --format ert-csv");
    REQUIRE(r.status == 0);
    std::map<std::string, std::string> runs;  // function -> runs, at the first precision
    std::istringstream in(r.out);
    std::string line;
    std::getline(in, line);
    while (std::getline(in, line)) {
        std::vector<std::string> f;
        std::stringstream cells(line);
        for (std::string c; std::getline(cells, c, ',');) f.push_back(c);
        REQUIRE(f.size() == 10);
        runs.emplace(f[0], f[6]);
    }
    CHECK(runs == std::map<std::string, std::string>{
                      {"rastrigin", "2"}, {"rastrigin (instances k >= 1)", "4"}, {"bbob-f3", "4"}});
}

TEST_CASE("campaign: ids that would name the same file are refused when the campaign is read", "[campaign]") {
    const pride::test::TempDir tmp("pride-file-names");
    auto refused = [&](const std::string& ids) {
        const std::string file = tmp.write("c.toml", "name = \"f\"\nseeds = 1\n[budget]\nevaluations = 10\n" + ids);
        const auto r = pride::test::run_pride("bench '" + file + "' --out '" + tmp.file("c.sqlite") + "'");
        CHECK(r.status == 2);
        CHECK(!fs::exists(tmp.file("c.sqlite")));
        return r.err;
    };
    const std::string pso = "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\n";
    CHECK_THAT(refused("[[problem]]\nid = \"x/y\"\ntype = \"sphere\"\ndim = 2\n"
                       "[[problem]]\nid = \"x_y\"\ntype = \"sphere\"\ndim = 3\n" +
                       pso),
               Catch::Contains("problem ids 'x/y' and 'x_y' would name the same file ('x_y'); rename one"));
    CHECK_THAT(refused("[[problem]]\nid = \"s\"\ntype = \"sphere\"\ndim = 2\n" + pso +
                       "[[algorithm]]\nid = \"PSO\"\ntype = \"pso\"\npop = 10\n"),
               Catch::Contains("algorithm ids 'pso' and 'PSO' would name the same file ('PSO')"));
}

// `pride report STORE --html DIR` on a multi-objective campaign: per problem the
// attainment surfaces of two objectives, each algorithm's median front against the reference
// front and, on grids, that front's paths on the map; the surfaces drawn are attainment.hpp's of
// the stored fronts; a damaged front is a note on the page. Also --plots' matplotlib figures of them.
#include <sqlite3.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "engine/multiobjective.hpp"
#include "experiment/campaign/identity.hpp"
#include "experiment/campaign/toml.hpp"
#include "experiment/html/front_figures.hpp"
#include "experiment/html/page_store.hpp"
#include "experiment/storage/reader.hpp"
#include "framework/pareto/attainment.hpp"
#include "tests/cli_runner.hpp"
#include "tests/json_reader.hpp"
#include "tests/sqlite_support.hpp"
#include "tests/test_support.hpp"

namespace fs = std::filesystem;
using namespace pride;
using test::run_pride;
using test::slurp;

namespace {

std::string quote(const std::string& s) {
    return "'" + s + "'";
}

/// Two objectives on a box and on a grid, three on a box; two algorithms, three seeds, tiny budgets.
std::string campaign_text() {
    const std::string map = std::string(PRIDE_SOURCE_DIR) + "/examples/maps/zhang2025-20x20.map";
    return "name = \"mo-html\"\nseeds = 3\n[budget]\nevaluations = 600\n"
           "[[problem]]\nid = \"zdt1\"\ntype = \"zdt1\"\ndim = 6\n"
           "[[problem]]\nid = \"dtlz2\"\ntype = \"dtlz2\"\nobjectives = 3\ndim = 6\n"
           "[[problem]]\nid = \"grid\"\ntype = \"grid\"\nmap = \"" +
           map +
           "\"\nstart = [0, 19]\ngoal = [19, 0]\nobjectives = [\"length\", \"turns\"]\nencoding = \"free\"\n"
           "[[algorithm]]\nid = \"nsga2\"\ntype = \"nsga2\"\npop = 20\n"
           "[[algorithm]]\nid = \"smsemoa\"\ntype = \"smsemoa\"\npop = 20\n";
}

struct Run {
    std::int64_t seed = 0;
    double hypervolume_ratio = 0;
    Matrix f;
};

/// The fronts one algorithm's runs stored on one problem, read here with the tests' own JSON
/// reader (not the page's).
std::vector<Run> stored_runs(const std::string& store, const std::string& problem, const std::string& algorithm) {
    sqlite3* db = nullptr;
    REQUIRE(sqlite3_open_v2(store.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK);
    sqlite3_stmt* s = nullptr;
    REQUIRE(sqlite3_prepare_v2(db,
                               "SELECT seed, solution FROM runs WHERE problem = ?1 AND algorithm = ?2 ORDER BY seed",
                               -1, &s, nullptr) == SQLITE_OK);
    sqlite3_bind_text(s, 1, problem.c_str(), -1, SQLITE_TRANSIENT);
    sqlite3_bind_text(s, 2, algorithm.c_str(), -1, SQLITE_TRANSIENT);
    std::vector<Run> out;
    while (sqlite3_step(s) == SQLITE_ROW) {
        Run r;
        r.seed = sqlite3_column_int64(s, 0);
        const auto doc = test::parse_json(reinterpret_cast<const char*>(sqlite3_column_text(s, 1)));
        r.hypervolume_ratio = doc.at("hypervolume_ratio").number;
        const auto& front = doc.at("front").items;
        const auto m = static_cast<Eigen::Index>(doc.at("objectives").items.size());
        r.f.resize(m, static_cast<Eigen::Index>(front.size()));
        for (std::size_t j = 0; j < front.size(); ++j)
            for (Eigen::Index i = 0; i < m; ++i)
                r.f(i, static_cast<Eigen::Index>(j)) = front[j].at("f").items[static_cast<std::size_t>(i)].number;
        out.push_back(std::move(r));
    }
    sqlite3_finalize(s);
    sqlite3_close(db);
    return out;
}

bool svg(const fs::path& file) {
    const std::string text = fs::exists(file) ? slurp(file) : std::string();
    return text.rfind("<?xml", 0) == 0 && text.find("<svg") != std::string::npos;
}

}  // namespace

TEST_CASE("report --html: attainment surfaces, median fronts and grid paths of multi-objective problems",
          "[report][html][multiobjective]") {
    const test::TempDir dir("pride-html-fronts");
    const std::string config = dir.write("mo.toml", campaign_text()), store = dir.file("mo.sqlite");
    const auto bench = run_pride("bench " + quote(config) + " --jobs 2 --out " + quote(store));
    INFO(bench.out << bench.err);
    REQUIRE(bench.status == 0);
    const fs::path out = dir.path() / "page";
    const auto r = run_pride("report " + quote(store) + " --html " + quote(out.string()));
    INFO(r.err);
    REQUIRE(r.status == 0);
    const std::string html = slurp(out / "index.html");

    // The figures of each problem: attainment for two objectives, fronts for all, paths on grids;
    // no convergence (a run stores its final front only).
    for (const char* name :
         {"attainment-zdt1.svg", "fronts-zdt1.svg", "final-zdt1.svg", "fronts-dtlz2.svg", "attainment-grid.svg",
          "fronts-grid.svg", "front-paths-grid-nsga2.svg", "front-paths-grid-smsemoa.svg"}) {
        INFO(name);
        CHECK(html.find("<img src=\"" + std::string(name) + "\"") != std::string::npos);
        CHECK(svg(out / name));
    }
    for (const char* name : {"attainment-dtlz2.svg", "convergence-zdt1.svg", "paths-grid.svg", "pareto-grid.svg"}) {
        INFO(name);
        CHECK(!fs::exists(out / name));
    }
    CHECK(html.find("No attainment surfaces: dtlz2 has 3 objectives") != std::string::npos);
    CHECK(html.find("k = ceil(q n)") != std::string::npos);
    CHECK(html.find("in objectives f1 and f2 of 3 (a projection)") != std::string::npos);
    CHECK(html.find("is left out") == std::string::npos);  // every front read
    CHECK(html.find("No reference front") == std::string::npos);
    // The markdown report's table of fronts, on the page too.
    CHECK(html.find("<th class=\"n\">HV ratio</th><th class=\"n\">IGD+</th><th class=\"n\">exact points</th>") !=
          std::string::npos);

    // What the page draws is attainment.hpp's surfaces of the stored fronts, and the median run's
    // front (by hypervolume ratio) with its seed named; the reference front is the campaign's.
    const storage::CampaignStore s = storage::read_store(store);
    const html::PageStore extra = html::read_page_store(store);
    const campaign::Campaign campaign = campaign::read_campaign(config);
    for (const std::string problem : {"zdt1", "grid", "dtlz2"}) {
        const html::ProblemFronts fronts = html::problem_fronts(extra, problem);
        REQUIRE(fronts.algorithms.size() == 2);
        const auto& p = *std::find_if(campaign.problems.begin(), campaign.problems.end(),
                                      [&](const campaign::CampaignProblem& q) { return q.id == problem; });
        CHECK(fronts.objectives == p.problem->objective_names());
        const engine::Problem rebuilt = html::stored_problem(s, extra, problem, fronts.objectives);
        CHECK(rebuilt.reference_front() == p.problem->reference_front());
        for (const html::AlgorithmFronts& a : fronts.algorithms) {
            INFO(problem << " " << a.algorithm);
            const std::vector<Run> runs = stored_runs(store, problem, a.algorithm);
            REQUIRE(runs.size() == 3);
            REQUIRE(a.runs.size() == 3);
            std::vector<Matrix> sets;
            for (const Run& run : runs) sets.push_back(run.f);
            if (problem == "dtlz2") {
                CHECK(a.surfaces.empty());
            } else {
                REQUIRE(a.surfaces.size() == 3);
                CHECK(a.k == std::vector<std::size_t>{1, 2, 3});  // ceil(3 q), q = 0.25, 0.5, 0.75
                for (std::size_t l = 0; l < 3; ++l) CHECK(a.surfaces[l] == pareto::attainment_surface(sets, a.k[l]));
            }
            std::vector<double> ratios;
            for (const Run& run : runs) ratios.push_back(run.hypervolume_ratio);
            std::sort(ratios.begin(), ratios.end());
            REQUIRE(a.median != nullptr);
            CHECK(a.median->hypervolume_ratio == ratios[1]);
            const Run& median =
                *std::find_if(runs.begin(), runs.end(), [&](const Run& x) { return x.seed == a.median->seed; });
            CHECK(median.f == a.median->f);
            CHECK(html.find(a.algorithm + ": seed " + std::to_string(a.median->seed)) != std::string::npos);
            if (problem == "grid") CHECK(a.median->paths.size() == static_cast<std::size_t>(median.f.cols()));
        }
    }
    // Every figure loads in a browser (headless Chromium, where installed: test_report_html.cpp).
    if (fs::exists("/usr/bin/chromium")) {
        std::size_t figures = 0;
        for (std::size_t at = html.find("<img src="); at != std::string::npos; at = html.find("<img src=", at + 1))
            ++figures;
        const int dumped = std::system(("timeout 120 /usr/bin/chromium --headless --no-sandbox --disable-gpu "
                                        "--user-data-dir=" +
                                        quote(dir.file("profile")) + " --dump-dom " +
                                        quote("file://" + (out / "index.html").string() + "?check") + " >" +
                                        quote(dir.file("dom")) + " 2>/dev/null")
                                           .c_str());
        REQUIRE(dumped == 0);
        CHECK(slurp(dir.file("dom")).find("data-figures=\"loaded " + std::to_string(figures) + "\"") !=
              std::string::npos);
    }

    // The matplotlib figures (--plots) of the same store: attainment for two objectives, fronts for all.
    const auto plots = run_pride("report " + quote(store) + " --plots " + quote(dir.file("plots")));
    if (plots.status == 2 && plots.err.find("matplotlib") != std::string::npos)
        FAIL("python3-matplotlib is missing: scripts/deps.sh installs it");
    INFO(plots.err);
    REQUIRE(plots.status == 0);
    for (const char* stem :
         {"zdt1-attainment", "zdt1-fronts", "zdt1-final", "dtlz2-fronts", "grid-attainment", "grid-fronts"}) {
        INFO(stem);
        CHECK(fs::exists(dir.path() / "plots" / (std::string(stem) + ".png")));
        CHECK(fs::exists(dir.path() / "plots" / (std::string(stem) + ".svg")));
    }
    CHECK(!fs::exists(dir.path() / "plots" / "dtlz2-attainment.png"));
    CHECK(!fs::exists(dir.path() / "plots" / "grid-paths.png"));

    // k = ceil(q n) at the edges.
    CHECK(html::attainment_k(0.25, 1) == 1);
    CHECK(html::attainment_k(0.75, 4) == 3);
    CHECK(html::attainment_k(0.5, 5) == 3);
}

TEST_CASE("report --html: a damaged multi-objective front is a note on the page, the others drawn",
          "[report][html][multiobjective]") {
    const test::TempDir dir("pride-html-fronts-bad");
    std::string text = campaign_text();
    text.replace(text.find("seeds = 3"), 9, "seeds = 2");
    const std::string config = dir.write("mo.toml", text), store = dir.file("mo.sqlite");
    REQUIRE(run_pride("bench " + quote(config) + " --out " + quote(store)).status == 0);
    const auto set = [&](const std::string& problem, const std::string& algorithm, int seed,
                         const std::string& solution) {
        test::exec_sql(store, "UPDATE runs SET solution = '" + solution + "' WHERE problem = '" + problem +
                                  "' AND algorithm = '" + algorithm + "' AND seed = " + std::to_string(seed));
    };
    set("zdt1", "nsga2", 1, "{not json");
    set("zdt1", "smsemoa", 2, R"({"objectives": ["f1", "f2"], "hypervolume_ratio": 0.5, "front": [{"f": [1]}]})");
    set("grid", "nsga2", 2,
        R"({"objectives": ["length", "turns"], "hypervolume_ratio": 0.5, "front": [{"f": [30, 2], "legal": true, )"
        R"("path": [[0, 19], [1, "a"]]}]})");
    set("grid", "smsemoa", 1, R"({"objectives": ["length", "turns"], "hypervolume_ratio": 0.5, "front": ["x"]})");
    set("dtlz2", "nsga2", 1, R"({"objectives": ["f1", "f2"], "hypervolume_ratio": 0.5, "front": []})");
    const fs::path out = dir.path() / "page";
    const auto r = run_pride("report " + quote(store) + " --html " + quote(out.string()));
    INFO(r.err);
    REQUIRE(r.status == 0);
    const std::string html = slurp(out / "index.html");
    for (const char* words :
         {"The front of nsga2, seed 1 is left out: its solution is damaged (not valid JSON).",
          "The front of smsemoa, seed 2 is left out: its solution is damaged (point 0: expected an object with f, a "
          "list of 2 values).",
          "The front of nsga2, seed 2 is left out: its solution is damaged (point 0: expected path, a list of [x, y] "
          "cells).",
          "The front of smsemoa, seed 1 is left out: its solution is damaged (point 0: expected an object with f",
          "The front of nsga2, seed 1 is left out: its objectives are f1, f2, those of the other runs f1, f2, f3."}) {
        INFO(words);
        CHECK(html.find(words) != std::string::npos);
    }
    // --plots refuses such a store in one line naming the run (it draws no figure of a store it
    // cannot read whole).
    const auto plots = run_pride("report " + quote(store) + " --plots " + quote(dir.file("plots")));
    if (plots.status == 2 && plots.err.find("matplotlib") != std::string::npos)
        FAIL("python3-matplotlib is missing: scripts/deps.sh installs it");
    INFO(plots.err);
    CHECK(plots.status == 2);
    CHECK(plots.err.find("damaged store: runs row (problem 'grid', algorithm 'smsemoa', seed 1), column solution") !=
          std::string::npos);

    // The runs left are drawn.
    for (const char* name : {"attainment-zdt1.svg", "fronts-zdt1.svg", "attainment-grid.svg",
                             "front-paths-grid-nsga2.svg", "front-paths-grid-smsemoa.svg", "fronts-dtlz2.svg"}) {
        INFO(name);
        CHECK(svg(out / name));
    }
}

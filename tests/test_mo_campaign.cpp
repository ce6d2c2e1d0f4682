// Multi-objective campaigns: problems of several objectives in campaign files, each
// run stored with its whole front and, as its value, its hypervolume gap; the stored record is
// the engine's run; the report says what the values are; bad entries are refused at their line.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <string>

#include "engine/multiobjective.hpp"
#include "experiment/campaign/identity.hpp"
#include "experiment/campaign/run.hpp"
#include "experiment/campaign/run_one.hpp"
#include "experiment/campaign/toml.hpp"
#include "experiment/report/report.hpp"
#include "tests/cli_runner.hpp"
#include "tests/json_reader.hpp"
#include "tests/sqlite_support.hpp"
#include "tests/test_support.hpp"

using namespace pride;

namespace {

const std::string kMaps = std::string(PRIDE_SOURCE_DIR) + "/examples/maps/";

std::string campaign_text(const std::string& extra_problem = "", const std::string& algorithms = "nsga2,smsemoa") {
    std::string text =
        "name = \"mo\"\nseeds = 2\n[budget]\nevaluations = 1500\n"
        "[[problem]]\nid = \"zdt2\"\ntype = \"zdt2\"\ndim = 12\n"
        "[[problem]]\nid = \"dtlz2\"\ntype = \"dtlz2\"\nobjectives = 3\n"
        "[[problem]]\nid = \"grid\"\ntype = \"grid\"\nmap = \"" +
        kMaps +
        "zhang2025-20x20.map\"\nstart = [0, 19]\ngoal = [19, 0]\n"
        "objectives = [\"length\", \"turns\", \"clearance\"]\nencoding = \"free\"\n" +
        extra_problem;
    std::size_t from = 0;
    while (from <= algorithms.size()) {
        const std::size_t comma = std::min(algorithms.find(',', from), algorithms.size());
        const std::string a = algorithms.substr(from, comma - from);
        text += "[[algorithm]]\nid = \"" + a + "\"\ntype = \"" + a + "\"\n";
        from = comma + 1;
    }
    return text;
}

}  // namespace

TEST_CASE("a multi-objective campaign stores each run's front and its hypervolume gap, as the engine runs it") {
    const test::TempDir dir("pride-mo-campaign");
    const std::string file = dir.write("mo.toml", campaign_text());
    campaign::Campaign c = campaign::read_campaign(file);
    REQUIRE(c.problems.size() == 3);
    for (const auto& p : c.problems) CHECK(p.is_multiobjective());
    CHECK(c.problems[1].problem->objectives() == 3);
    CHECK(c.problems[0].problem->dimension() == 12);
    const auto summary = campaign::run_campaign(c, dir.file("mo.sqlite"), 2);
    CHECK(summary.stored == 12);
    CHECK(campaign::run_campaign(c, dir.file("mo.sqlite"), 2).stored == 0);  // resumed: nothing left

    // The stored record is the engine's run: the same front, the value 1 - its hypervolume ratio.
    for (const auto& p : c.problems) {
        const campaign::RunRecord r = campaign::run_one(p, c.algorithms[1], c.budget, 2);
        const auto direct = engine::run(c.algorithms[1].spec, *p.problem, c.budget, 2);
        const auto q = engine::quality(*p.problem, direct.front->f);
        INFO(p.id);
        CHECK(r.best == 1.0 - q.hypervolume_ratio);
        CHECK(r.evaluations == 1500);
        const auto doc = test::parse_json(r.solution);
        CHECK(doc.at("hypervolume_ratio").number == q.hypervolume_ratio);
        const auto& front = doc.at("front").items;
        REQUIRE(front.size() == static_cast<std::size_t>(direct.front->f.cols()));
        for (std::size_t j = 0; j < front.size(); ++j)
            for (std::size_t i = 0; i < front[j].at("f").items.size(); ++i)
                CHECK(front[j].at("f").items[i].number ==
                      direct.front->f(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)));
        if (p.problem->is_grid()) {
            CHECK(doc.at("exact_found").kind == test::JsonValue::Kind::number);
            CHECK(front.front().has("path"));
        } else {
            CHECK(front.front().at("x").items.size() == p.problem->dimension());
        }
    }
    const auto report = report::load_report(dir.file("mo.sqlite"));
    CHECK(report.rows.size() == 6);
    REQUIRE_FALSE(report.notes.empty());
    CHECK(report.notes.back().find("hypervolume gaps") != std::string::npos);
    // The fronts' table: medians of what the runs stored, one row per (problem, algorithm).
    REQUIRE(report.fronts.size() == 6);
    for (const auto& row : report.fronts) {
        INFO(row.problem << " " << row.algorithm);
        const auto& p = *std::find_if(c.problems.begin(), c.problems.end(),
                                      [&](const campaign::CampaignProblem& q) { return q.id == row.problem; });
        const auto& a = *std::find_if(c.algorithms.begin(), c.algorithms.end(),
                                      [&](const campaign::CampaignAlgorithm& q) { return q.id == row.algorithm; });
        std::vector<double> igd, ratio;
        for (std::int64_t seed = 1; seed <= 2; ++seed) {
            const auto doc = test::parse_json(campaign::run_one(p, a, c.budget, seed).solution);
            igd.push_back(doc.at("igd_plus").number);
            ratio.push_back(doc.at("hypervolume_ratio").number);
        }
        CHECK(row.runs == 2);
        CHECK(row.igd_plus == Approx(0.5 * (igd[0] + igd[1])).epsilon(1e-12));
        CHECK(row.hypervolume_ratio == Approx(0.5 * (ratio[0] + ratio[1])).epsilon(1e-12));
        CHECK(row.exact_found.has_value() == p.problem->is_grid());
    }
    const auto text = test::run_pride("report " + dir.file("mo.sqlite"));
    CHECK(text.status == 0);
    CHECK(text.out.find("dtlz2, grid, zdt2 have several objectives") != std::string::npos);
    CHECK(text.out.find("| problem | algorithm | runs | HV ratio | IGD+ | exact points | p (Holm) |") !=
          std::string::npos);
    // A solution that is not valid JSON (a damaged or hand-made store) drops that run from the
    // fronts' table; the report still reads.
    test::exec_sql(
        dir.file("mo.sqlite"),
        "UPDATE runs SET solution = '{not json' WHERE problem = 'zdt2' AND algorithm = 'nsga2' AND seed = 1");
    const auto damaged = report::load_report(dir.file("mo.sqlite"));
    for (const auto& row : damaged.fronts)
        CHECK(row.runs == (row.problem == "zdt2" && row.algorithm == "nsga2" ? 1u : 2u));
}

TEST_CASE("multi-objective campaign entries are refused at their line when they do not fit") {
    const test::TempDir dir("pride-mo-campaign-errors");
    const auto refused = [&](const std::string& text, const std::vector<std::string>& words) {
        const std::string file = dir.write("bad.toml", text);
        const std::string message = test::input_error_message([&] { (void)campaign::read_campaign(file); });
        INFO(message);
        CHECK(message.find("bad.toml") != std::string::npos);
        for (const auto& w : words) CHECK(message.find(w) != std::string::npos);
    };
    refused(campaign_text("", "nsga2,pso"), {"pso", "one objective"});
    refused(campaign_text("[[problem]]\nid = \"s\"\ntype = \"sphere\"\ndim = 3\n", "nsga2"),
            {"nsga2", "multi-objective algorithm"});
    refused(campaign_text("[[problem]]\nid = \"z\"\ntype = \"zdt1\"\ninstance = 2\n"), {"unknown key 'instance'"});
    refused(campaign_text("[[problem]]\nid = \"z\"\ntype = \"zdt1\"\nobjectives = 3\n"), {"zdt1", "2 objectives"});
    refused(campaign_text("[[problem]]\nid = \"g2\"\ntype = \"grid\"\nmap = \"" + kMaps +
                          "zhang2025-20x20.map\"\nstart = [0, 19]\ngoal = [19, 0]\nobjectives = \"length,speed\"\n"),
            {"objectives", "speed"});
    refused(campaign_text("[[problem]]\nid = \"g2\"\ntype = \"grid\"\nmap = \"" + kMaps +
                          "zhang2025-20x20.map\"\nstart = [0, 19]\ngoal = [19, 0]\nobjectives = [\"length\", "
                          "\"turns\"]\nobjective = \"length\"\n"),
            {"objective"});
}

TEST_CASE("a multi-objective campaign on a constrained problem stores each point's violation") {
    const test::TempDir dir("pride-mo-campaign-constrained");
    const std::string file =
        dir.write("c.toml",
                  "name = \"c\"\nseeds = 1\n[budget]\nevaluations = 1200\n[[problem]]\nid = \"constr\"\ntype = "
                  "\"constr\"\n[[algorithm]]\nid = \"nsga2\"\ntype = \"nsga2\"\n");
    const campaign::Campaign c = campaign::read_campaign(file);
    const campaign::RunRecord r = campaign::run_one(c.problems[0], c.algorithms[0], c.budget, 1);
    const auto direct = engine::run(c.algorithms[0].spec, *c.problems[0].problem, c.budget, 1);
    const auto q = engine::quality(*c.problems[0].problem, direct.front->f, direct.front->violation);
    CHECK(r.best == 1.0 - q.hypervolume_ratio);
    CHECK(r.feasible);
    const auto doc = test::parse_json(r.solution);
    const auto& front = doc.at("front").items;
    REQUIRE(front.size() == direct.front->violation.size());
    for (std::size_t j = 0; j < front.size(); ++j) CHECK(front[j].at("violation").number == direct.front->violation[j]);
    // A problem whose front is not published is refused before anything runs.
    const std::string cre = dir.write("cre.toml",
                                      "name = \"c\"\nseeds = 1\n[budget]\nevaluations = 1200\n[[problem]]\nid = "
                                      "\"cre21\"\ntype = \"cre21\"\n[[algorithm]]\nid = \"nsga2\"\ntype = \"nsga2\"\n");
    const std::string message = test::input_error_message([&] { (void)campaign::read_campaign(cre); });
    CHECK_THAT(message, Catch::Matchers::Contains("cre.toml") &&
                            Catch::Matchers::Contains("cre21 has no published reference front"));
}

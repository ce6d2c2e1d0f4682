// OMPL's planners as registered algorithms (engine/entries/ompl_entries.cpp), when OMPL is built:
// seeded runs on the length objective whose validity checks are their evaluations, within the
// budget; free polylines no shorter than the exact any-angle path; refused without an evaluation
// budget; in pride path and campaigns; and merged and reported by definition (not reproducible).
// Without OMPL the entries do not exist and these cases check only that.
#include <catch2/catch.hpp>

#include <sqlite3.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "cli_runner.hpp"
#include "engine/registry.hpp"
#include "engine/run.hpp"
#include "framework/error.hpp"
#include "grid_support.hpp"
#include "problems/grid/planners/any_angle.hpp"
#include "test_support.hpp"

using namespace pride;
using Catch::Matchers::Contains;

namespace {

const char* const kPlanners[] = {"ompl:RRTstar", "ompl:InformedRRTstar", "ompl:BITstar", "ompl:PRMstar"};

bool ompl_built() {
    return engine::algorithms().find("ompl:RRTstar") != nullptr;
}

engine::Problem wall_problem() {
    engine::GridSpec g;
    g.map = std::make_shared<const grid::GridMap>(
        test::map_of({"..........", "..........", "....@.....", "....@.....", "....@.....", "....@.....", "....@.....",
                      "..........", "..........", ".........."}));
    g.start = {1, 4};
    g.goal = {8, 4};
    g.objective = "length";
    return engine::Problem(g);
}

engine::RunResult run_ompl(const std::string& name, const engine::Problem& problem, std::int64_t evaluations,
                           std::uint64_t seed) {
    engine::Budget budget;
    budget.evaluations = evaluations;
    return engine::run(engine::AlgorithmSpec{name, {}}, problem, budget, seed);
}

}  // namespace

TEST_CASE("ompl engine: the four planners are registered when OMPL is built", "[ompl][planners]") {
    if (!ompl_built()) {
        WARN("OMPL is not built (PRIDE_OMPL off): no ompl: algorithms");
        CHECK(engine::algorithms().find("ompl:BITstar") == nullptr);
        return;
    }
    for (const char* name : kPlanners) {
        const engine::AlgorithmEntry& e = engine::algorithms().at(name);
        CHECK(e.spaces() == std::vector<std::string>{"grid"});
        CHECK(e.evaluates());  // its validity checks
        CHECK(e.plans_polylines);
        CHECK_FALSE(e.reproducible);
        REQUIRE(e.param("simplify"));
    }
}

TEST_CASE("ompl engine: seeded runs within the budget, free and no shorter than the any-angle optimum",
          "[ompl][planners]") {
    if (!ompl_built()) return;
    const engine::Problem problem = wall_problem();
    const auto& g = std::get<engine::GridSpec>(problem.spec());
    grid::AnyAngleOracle oracle(*g.map);
    const double shortest = oracle.solve(g.start, g.goal);
    for (const char* name : kPlanners) {
        INFO(name);
        const auto a = run_ompl(name, problem, 4000, 3);
        const auto b = run_ompl(name, problem, 4000, 3);
        REQUIRE(a.grid->feasible);
        CHECK(a.evaluations <= 4000);
        CHECK(a.evaluations > 0);
        CHECK(a.best_f >= shortest - 1e-9);
        CHECK(a.grid->path.empty());
        for (std::size_t i = 1; i < a.grid->polyline.size(); ++i) {
            const auto& p = a.grid->polyline[i - 1];
            const auto& q = a.grid->polyline[i];
            CHECK(grid::segment_is_free(*g.map, grid::Point{p.x + 0.5, p.y + 0.5}, grid::Point{q.x + 0.5, q.y + 0.5}));
        }
        // One seed and an evaluation budget: the same run in this process.
        CHECK(a.grid->polyline == b.grid->polyline);
        CHECK(a.evaluations == b.evaluations);
    }
}

TEST_CASE("ompl engine: refused without an evaluation budget and on objectives other than length",
          "[ompl][planners][errors]") {
    if (!ompl_built()) return;
    const engine::Problem problem = wall_problem();
    engine::Budget none;
    CHECK_THROWS_WITH(engine::check(engine::AlgorithmSpec{"ompl:RRTstar", {}}, problem, none),
                      "evaluations: ompl:RRTstar needs an evaluation budget (its state and motion validity checks: "
                      "--evals N)");
    const std::string map = std::string(PRIDE_SOURCE_DIR) + "/examples/maps/wan2022-10x10.map";
    test::expect_input_error("path --map '" + map + "' --start 0,0 --goal 9,9 --algo ompl:BITstar --objective length",
                             {"--evals", "needs an evaluation budget"});
    test::expect_input_error(
        "path --map '" + map + "' --start 0,0 --goal 9,9 --algo ompl:BITstar --evals 100 --objective cells",
        {"--objective", "plans polylines"});
    const auto ok = test::run_pride("path --map '" + map +
                                    "' --start 0,0 --goal 9,9 --algo ompl:BITstar --objective length --evals 3000 "
                                    "--gaps --json");
    INFO(ok.err);
    REQUIRE(ok.status == 0);
    CHECK_THAT(ok.out, Contains("\"polyline\": [[0, 0], ") && Contains("\"any_angle_gap\": "));
}

TEST_CASE("ompl engine: merges and reports compare OMPL runs by definition, other runs by value",
          "[ompl][planners][merge]") {
    if (!ompl_built()) return;
    const test::TempDir dir;
    const std::string map = std::string(PRIDE_SOURCE_DIR) + "/examples/maps/wan2022-10x10.map";
    const std::string toml =
        dir.write("c.toml",
                  "name = \"o\"\nseeds = 1\n[budget]\nevaluations = 2000\n[[problem]]\nid = \"g\"\ntype = \"grid\"\n"
                  "map = \"" +
                      map +
                      "\"\nstart = [0, 0]\ngoal = [9, 9]\nobjective = \"length\"\n[[algorithm]]\nid = \"rrt\"\n"
                      "type = \"ompl:RRTstar\"\n[[algorithm]]\nid = \"astar\"\ntype = \"astar\"\n");
    const std::string a = dir.file("a.sqlite"), b = dir.file("b.sqlite");
    REQUIRE(test::run_pride("bench '" + toml + "' --out '" + a + "'").status == 0);
    std::filesystem::copy_file(a, b);
    const auto edit = [&](const char* sql) {
        sqlite3* db = nullptr;
        REQUIRE(sqlite3_open(b.c_str(), &db) == SQLITE_OK);
        REQUIRE(sqlite3_exec(db, sql, nullptr, nullptr, nullptr) == SQLITE_OK);
        sqlite3_close(db);
    };
    // Another OMPL result for the same (problem, algorithm, seed): the same run by definition.
    edit("UPDATE runs SET best = best + 1e-9 WHERE algorithm = 'rrt'");
    const auto merged = test::run_pride("merge '" + a + "' '" + b + "' --out '" + dir.file("m.sqlite") + "'");
    INFO(merged.err);
    CHECK(merged.status == 0);
    CHECK(test::run_pride("report '" + a + "' '" + b + "'").status == 0);
    // A* is reproducible: another value is another run, refused.
    edit("UPDATE runs SET best = best + 1e-9 WHERE algorithm = 'astar'");
    const auto refused = test::run_pride("merge '" + a + "' '" + b + "' --out '" + dir.file("n.sqlite") + "'");
    CHECK(refused.status == 2);
    CHECK_THAT(refused.err, Contains("algorithm 'astar', seed 1) differs"));
}

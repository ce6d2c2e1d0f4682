// Polyline planners in the engine (engine/entries/any_angle_entries.cpp) and the metrics every grid path
// gets (engine::run, problems/grid/polyline.hpp): theta-star, lazy-theta-star and any-angle-exact
// run by name on the length objective only; their polylines are free, between the exact any-angle
// length and A*'s; every chain's polyline is its cells with the chain's metrics; the gaps to the
// shortest grid and any-angle lengths; pride path's JSON and text; campaign stores and the report.
#include <catch2/catch.hpp>

#include <sqlite3.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "engine/family.hpp"
#include "engine/registry.hpp"
#include "engine/run.hpp"
#include "engine/target.hpp"
#include "experiment/html/page_store.hpp"
#include "framework/error.hpp"
#include "grid_support.hpp"
#include "json_reader.hpp"
#include "problems/grid/path.hpp"
#include "problems/grid/planners/any_angle.hpp"
#include "problems/grid/planners/astar.hpp"
#include "problems/grid/polyline.hpp"
#include "test_support.hpp"

using namespace pride;
using Catch::Matchers::Contains;

namespace {

engine::Problem problem_of(const test::GridInstance& in, const std::string& objective, bool gaps = false) {
    engine::GridSpec g;
    g.map = in.map;
    g.start = in.start;
    g.goal = in.goal;
    g.objective = objective;
    g.corner_cutting = in.corner_cutting;
    g.path_gaps = gaps;
    return engine::Problem(g);
}

engine::RunResult run_named(const std::string& algo, const engine::Problem& problem, std::int64_t evaluations = 0) {
    engine::Budget budget;
    if (evaluations) budget.evaluations = evaluations;
    return engine::run(engine::AlgorithmSpec{algo, {}}, problem, budget, 7);
}

/// Every segment free by any_angle.hpp's exact test (the polyline's points are cell centres or
/// grid points: centre convention, so + 0.5 gives the square convention).
bool polyline_free(const grid::GridMap& map, const grid::Polyline& line) {
    for (std::size_t i = 1; i < line.size(); ++i)
        if (!grid::segment_is_free(map, grid::Point{line[i - 1].x + 0.5, line[i - 1].y + 0.5},
                                   grid::Point{line[i].x + 0.5, line[i].y + 0.5}))
            return false;
    return true;
}

}  // namespace

TEST_CASE("polyline planners: registered, free polylines between the exact any-angle length and A*'s",
          "[polyline][planners]") {
    for (const char* name : {"theta-star", "lazy-theta-star", "any-angle-exact"}) {
        const engine::AlgorithmEntry& e = engine::algorithms().at(name);
        CHECK(e.plans_polylines);
        CHECK(e.spaces() == std::vector<std::string>{"grid"});
        CHECK_FALSE(e.evaluates());
    }
    int compared = 0;
    for (const test::GridInstance& in : test::random_instances(2029, 60)) {
        if (in.corner_cutting) continue;  // the any-angle rules forbid the squeeze corner cutting allows
        const engine::Problem problem = problem_of(in, "length", true);
        const auto astar = run_named("astar", problem);
        const auto exact = run_named("any-angle-exact", problem);
        REQUIRE(exact.grid->feasible);
        grid::AnyAngleOracle oracle(*in.map);
        const double shortest = oracle.solve(in.start, in.goal);
        CHECK(exact.best_f == Approx(shortest).epsilon(1e-12));
        CHECK(exact.grid->any_angle_gap == 0.0);
        for (const char* name : {"theta-star", "lazy-theta-star", "any-angle-exact"}) {
            const auto r = run_named(name, problem);
            INFO(name << " on " << in.map->name());
            const engine::GridOutcome& o = *r.grid;
            REQUIRE(o.feasible);
            CHECK(o.path.empty());  // no cells: the polyline is the path
            REQUIRE(o.polyline.size() >= 1);
            CHECK(o.polyline.front() == grid::PathPoint{double(in.start.x), double(in.start.y)});
            CHECK(o.polyline.back() == grid::PathPoint{double(in.goal.x), double(in.goal.y)});
            CHECK(polyline_free(*in.map, o.polyline));
            CHECK(o.value == r.best_f);
            CHECK(o.metrics.length == Approx(o.value).epsilon(1e-12));
            CHECK(o.value >= shortest - 1e-9);
            CHECK(o.value <= astar.best_f + 1e-9);
            REQUIRE(o.grid_gap);
            REQUIRE(o.any_angle_gap);
            CHECK(*o.grid_gap <= 1e-12);  // never longer than the grid's shortest
            CHECK(*o.any_angle_gap >= 0.0);
            CHECK(*o.shortest_grid_length == Approx(astar.best_f).epsilon(1e-12));
        }
        ++compared;
    }
    CHECK(compared > 30);
}

TEST_CASE("polyline planners: refused on objectives other than length, with a one-line reason",
          "[polyline][planners][errors]") {
    const test::GridInstance in = test::random_instances(5, 1).front();
    for (const char* objective : {"cells", "weighted", "iqga", "hswoa"}) {
        const engine::Problem problem = problem_of(in, objective);
        try {
            run_named("theta-star", problem);
            FAIL("theta-star ran on " << objective);
        } catch (const InputError& e) {
            CHECK(std::string(e.what()) == std::string("objective: theta-star plans polylines, whose value is their "
                                                       "length: it runs on the length objective, not ") +
                                               objective);
        }
    }
}

TEST_CASE("polyline planners: every grid run's polyline is its cells, scored as its chain", "[polyline][planners]") {
    for (const test::GridInstance& in : test::random_instances(31, 12)) {
        const engine::Problem problem = problem_of(in, "length", true);
        for (const char* name : {"astar", "jps", "exact", "ga", "iqga", "pso"}) {
            if (std::string(name) == "jps" && in.corner_cutting) continue;
            const auto r = run_named(name, problem, 400);
            const engine::GridOutcome& o = *r.grid;
            if (!o.feasible) {
                CHECK(o.polyline.empty());
                continue;
            }
            INFO(name << " on " << in.map->name());
            REQUIRE(o.polyline.size() == o.path.size());
            for (std::size_t i = 0; i < o.path.size(); ++i)
                CHECK(o.polyline[i] == grid::PathPoint{double(o.path[i].x), double(o.path[i].y)});
            const grid::PathMetrics chain = grid::metrics(o.path);
            CHECK(o.metrics.turns == chain.turns);
            CHECK(o.metrics.total_turn_deg == double(chain.turn_angle_deg));
            CHECK(o.metrics.length == Approx(chain.length).epsilon(1e-12));
            // Cells are free and no step cuts a corner (one that does touches it: clearance 0).
            if (o.metrics.min_clearance && !in.corner_cutting) CHECK(*o.metrics.min_clearance >= 0.5 - 1e-12);
            // The exact algorithms find the grid's shortest length: a gap of exactly 0.
            if (std::string(name) == "astar" || std::string(name) == "jps" || std::string(name) == "exact")
                CHECK(o.grid_gap == 0.0);
            CHECK(*o.grid_gap >= 0.0);
        }
    }
}

TEST_CASE("polyline planners: without path_gaps no gap is computed", "[polyline][planners]") {
    const test::GridInstance in = test::random_instances(8, 1).front();
    const auto r = run_named("theta-star", problem_of(in, "length"));
    CHECK_FALSE(r.grid->grid_gap);
    CHECK_FALSE(r.grid->any_angle_gap);
    CHECK_FALSE(r.grid->shortest_any_angle_length);
}

TEST_CASE("polyline planners: pride path prints the polyline, its metrics and gaps", "[polyline][planners][cli]") {
    const std::string map = std::string(PRIDE_SOURCE_DIR) + "/examples/maps/wan2022-10x10.map";
    const auto json = test::run_pride("path --map '" + map +
                                      "' --start 0,0 --goal 9,9 --algo theta-star --objective length --gaps --json");
    INFO(json.err);
    REQUIRE(json.status == 0);
    const test::JsonValue v = test::parse_json(json.out);
    CHECK(v.at("path").items.empty());
    CHECK(v.at("metrics").kind == test::JsonValue::Kind::null);
    const auto& line = v.at("polyline").items;
    REQUIRE(line.size() >= 2);
    CHECK(line.front().items[0].number == 0.0);
    CHECK(line.back().items[1].number == 9.0);
    const test::JsonValue& m = v.at("path_metrics");
    CHECK(m.keys() == std::vector<std::string>{"length", "turns", "total_turn_deg", "max_turn_deg", "angle_over_length",
                                               "max_curvature", "min_clearance", "mean_clearance",
                                               "shortest_grid_length", "shortest_any_angle_length", "grid_gap",
                                               "any_angle_gap"});
    CHECK(m.at("length").number == v.at("objective_value").number);
    CHECK(m.at("grid_gap").number < 0.0);  // shorter than any 8-connected path
    CHECK(m.at("any_angle_gap").number >= 0.0);
    // The text form names the polyline and its vertices, not cells.
    const auto text =
        test::run_pride("path --map '" + map + "' --start 0,0 --goal 9,9 --algo lazy-theta-star --objective length");
    REQUIRE(text.status == 0);
    CHECK_THAT(text.out, Contains("vertices        ") && Contains("polyline        [[0, 0], ") &&
                             Contains("max_curvature   ") && !Contains("cells           "));
    // A chain planner's JSON has both, the polyline being its cells.
    const auto chain =
        test::run_pride("path --map '" + map + "' --start 0,0 --goal 9,9 --algo astar --objective length --json");
    const test::JsonValue c = test::parse_json(chain.out);
    REQUIRE(c.at("polyline").items.size() == c.at("path").items.size());
    CHECK(c.at("path_metrics").at("turns").number == c.at("metrics").at("turns").number);
    CHECK_FALSE(c.at("path_metrics").has("grid_gap"));
    // Pictures of polylines are drawn.
    const test::TempDir dir;
    const auto drawn = test::run_pride("path --map '" + map +
                                       "' --start 0,0 --goal 9,9 --algo any-angle-exact --objective length --svg '" +
                                       dir.file("p.svg") + "'");
    REQUIRE(drawn.status == 0);
    CHECK_THAT(test::slurp(dir.file("p.svg")), Contains("<svg"));
    // Without --objective a polyline planner plans for length, its only objective; cells named is an error.
    const auto plain = test::run_pride("path --map '" + map + "' --start 0,0 --goal 9,9 --algo theta-star");
    REQUIRE(plain.status == 0);
    CHECK_THAT(plain.out, Contains("objective       length\n") && Contains("vertices        "));
    test::expect_input_error("path --map '" + map + "' --start 0,0 --goal 9,9 --algo theta-star --objective cells",
                             {"--objective", "theta-star plans polylines", "not cells"});
    const auto chain_default = test::run_pride("path --map '" + map + "' --start 0,0 --goal 9,9 --algo astar --json");
    REQUIRE(chain_default.status == 0);
    CHECK(test::parse_json(chain_default.out).at("objective").text == "cells");
}

TEST_CASE("polyline planners: a campaign stores every path's metrics and a polyline planner's polyline",
          "[polyline][planners][bench]") {
    const test::TempDir dir;
    const std::string map = std::string(PRIDE_SOURCE_DIR) + "/examples/maps/wan2022-10x10.map";
    const std::string toml =
        dir.write("c.toml",
                  "name = \"paths\"\nseeds = 2\n[budget]\nevaluations = 200\n[[problem]]\nid = \"g\"\ntype = "
                  "\"grid\"\nmap = \"" +
                      map +
                      "\"\nstart = [0, 0]\ngoal = [9, 9]\nobjective = \"length\"\npath_gaps = true\n"
                      "[[algorithm]]\nid = \"astar\"\ntype = \"astar\"\n[[algorithm]]\nid = \"theta\"\ntype = "
                      "\"theta-star\"\n[[algorithm]]\nid = \"ga\"\ntype = \"ga\"\n");
    const std::string store = dir.file("c.sqlite");
    const auto bench = test::run_pride("bench '" + toml + "' --out '" + store + "'");
    INFO(bench.err);
    REQUIRE(bench.status == 0);
    const auto query = [&](const std::string& sql) {
        std::string out;
        FILE* pipe = popen(("sqlite3 '" + store + "' \"" + sql + "\"").c_str(), "r");
        REQUIRE(pipe);
        char buffer[4096];
        while (fgets(buffer, sizeof buffer, pipe)) out += buffer;
        CHECK(pclose(pipe) == 0);
        return out;
    };
    CHECK(query("SELECT count(*) FROM runs WHERE path_metrics IS NOT NULL") == "6\n");
    CHECK(query("SELECT algorithm FROM runs WHERE polyline IS NOT NULL ORDER BY seed") == "theta\ntheta\n");
    CHECK(query("SELECT json_extract(path_metrics, '$.grid_gap') FROM runs WHERE algorithm = 'astar' LIMIT 1") ==
          "0\n");
    CHECK(query("SELECT definition FROM problems").find(" path_gaps true") != std::string::npos);
    const auto report = test::run_pride("report '" + store + "'");
    INFO(report.err);
    REQUIRE(report.status == 0);
    CHECK_THAT(report.out, Contains("Paths on grids, per algorithm") && Contains("| g | theta | 2/2 | 13.07 |") &&
                               Contains("| g | astar | 2/2 | 13.9 |"));
    // The HTML report: the same table, and the best paths drawn, the polyline planner's among them.
    const auto html = test::run_pride("report '" + store + "' --html '" + dir.file("html") + "'");
    INFO(html.err);
    REQUIRE(html.status == 0);
    const std::string page = test::slurp(dir.file("html/index.html"));
    CHECK_THAT(page, Contains("Paths on grids, per algorithm") && Contains("<td>theta</td><td class=\"n\">2/2</td>"));
    CHECK(std::filesystem::exists(dir.file("html/paths-g.svg")));
    // What the picture draws: each algorithm's best path, Theta*'s as its polyline (runs.polyline).
    const html::PageStore extra = html::read_page_store(store);
    REQUIRE(extra.best_paths.size() == 3);
    for (const html::BestPath& b : extra.best_paths) {
        INFO(b.algorithm);
        CHECK(b.path.empty() == (b.algorithm == "theta"));
        CHECK(b.polyline.empty() == (b.algorithm != "theta"));
    }
    // Damaged path columns are one-line errors naming the run and the column.
    const std::string damaged = dir.file("damaged.sqlite");
    std::filesystem::copy_file(store, damaged);
    const auto edit = [&](const char* sql) {
        sqlite3* db = nullptr;
        REQUIRE(sqlite3_open(damaged.c_str(), &db) == SQLITE_OK);
        CHECK(sqlite3_exec(db, sql, nullptr, nullptr, nullptr) == SQLITE_OK);
        sqlite3_close(db);
    };
    edit("UPDATE runs SET polyline = '[[1]]' WHERE algorithm = 'theta' AND seed = 1");
    test::expect_input_error("report '" + damaged + "' --html '" + dir.file("damaged-html") + "'",
                             {"algorithm 'theta', seed 1), column polyline: expected a JSON list of [x, y] points"});
    edit("UPDATE runs SET path_metrics = '{\"length\": \"x\"}' WHERE algorithm = 'astar' AND seed = 2");
    test::expect_input_error("report '" + damaged + "'", {"seed 2)", "path_metrics: length", "expected a number"});
    test::expect_input_error(
        "bench '" +
            dir.write("bad.toml",
                      test::slurp(toml).replace(test::slurp(toml).find("path_gaps = true"), 16, "path_gaps = 2")) +
            "' --out '" + dir.file("bad.sqlite") + "'",
        {"bad.toml:12", "'path_gaps' must be true or false"});
}

namespace {

// A polyline planner that cuts through the obstacles: straight from start to goal whatever lies
// between (what a faulty planner would return). The engine must never report it as a path.
const engine::Registration straight_line{[] {
    engine::AlgorithmEntry e;
    e.name = "test-straight-line";
    e.family = "test";
    e.summary = "tests only: the straight segment from start to goal, obstacles or not";
    e.plans_polylines = true;
    engine::add_runner<engine::GridTarget>(
        e, engine::Kind::grid, [](const engine::RunRequest&, const engine::GridTarget& target) {
            return std::visit(
                [](const auto& g) {
                    engine::GridSolution s;
                    s.polyline = {{double(g.start().x), double(g.start().y)}, {double(g.goal().x), double(g.goal().y)}};
                    return s;
                },
                target.problem);
        });
    return e;
}()};

}  // namespace

TEST_CASE("polyline planners: a polyline through an obstacle is never reported as a path", "[polyline][planners]") {
    engine::GridSpec g;
    g.map = std::make_shared<const grid::GridMap>(test::map_of({".....", "..@..", "....."}));
    g.start = {0, 1};
    g.goal = {4, 1};
    g.objective = "length";
    const auto blocked = run_named("test-straight-line", engine::Problem(g));
    CHECK_FALSE(blocked.grid->feasible);
    CHECK(blocked.grid->polyline.empty());
    CHECK(std::isinf(blocked.best_f));
    g.map = std::make_shared<const grid::GridMap>(test::map_of({".....", ".....", "....."}));
    const auto free = run_named("test-straight-line", engine::Problem(g));
    CHECK(free.grid->feasible);
    CHECK(free.best_f == 4.0);
}

TEST_CASE("polyline planners: whole-map work beyond a campaign's budget, and stores of schema 4, are reported",
          "[polyline][planners][bench]") {
    const test::TempDir dir;
    const std::string map = std::string(PRIDE_SOURCE_DIR) + "/examples/maps/zhang2025-20x20.map";
    const std::string toml =
        dir.write("w.toml",
                  "name = \"w\"\nseeds = 1\n[budget]\nevaluations = 5\n[[problem]]\nid = \"g\"\ntype = \"grid\"\n"
                  "map = \"" +
                      map +
                      "\"\nstart = [0, 19]\ngoal = [19, 0]\nobjective = \"length\"\n[[algorithm]]\nid = \"astar\"\n"
                      "type = \"astar\"\n[[algorithm]]\nid = \"theta\"\ntype = \"theta-star\"\n[[algorithm]]\nid = "
                      "\"exact\"\ntype = \"any-angle-exact\"\n[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\npop = 5\n");
    // (The PSO takes the budget: a campaign of planners alone refuses one they would not use.)
    const std::string store = dir.file("w.sqlite");
    REQUIRE(test::run_pride("bench '" + toml + "' --out '" + store + "'").status == 0);
    // Their work (expansions, segment tests) is far beyond 5 evaluations: no budget is recorded
    // beside it, and the report reads the store.
    const auto report = test::run_pride("report '" + store + "'");
    INFO(report.err);
    REQUIRE(report.status == 0);
    // Theta* records no 8-connected optimum: a polyline has no gap to it in the main table.
    CHECK_THAT(report.out, Contains("| g | theta | 1/1 |"));
    // A store of schema 4 (before the path columns) gains them on its next bench, and reports.
    const auto edit = [&](const char* sql) {
        sqlite3* db = nullptr;
        REQUIRE(sqlite3_open(store.c_str(), &db) == SQLITE_OK);
        CHECK(sqlite3_exec(db, sql, nullptr, nullptr, nullptr) == SQLITE_OK);
        sqlite3_close(db);
    };
    edit(
        "ALTER TABLE runs DROP COLUMN path_metrics; ALTER TABLE runs DROP COLUMN polyline; ALTER TABLE algorithms "
        "DROP COLUMN reproducible; PRAGMA user_version = 4");
    CHECK(test::run_pride("report '" + store + "'").status == 0);
    REQUIRE(test::run_pride("bench '" + toml + "' --out '" + store + "'").status == 0);
    const auto again = test::run_pride("report '" + store + "' --html '" + dir.file("html") + "'");
    INFO(again.err);
    CHECK(again.status == 0);
}

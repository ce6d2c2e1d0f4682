// Tests of world units on maps with a world frame (docs/grid.md, "World coordinates"): points on
// cell borders land in the cell the doc names, exactly; campaign files take start_world and
// goal_world and run what the equivalent cells run; every error about a world point names the world
// option or key (and its file and line); lengths are given in metres beside cells (pride path,
// Python's plan, campaign stores, the report's tables, the pictures' legends), the metres the
// cells times the resolution, and maps without a frame are unchanged.
#include <sqlite3.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cli/grid_commands.hpp"
#include "experiment/campaign/toml.hpp"
#include "experiment/html/draw.hpp"
#include "experiment/html/problem_figures.hpp"
#include "experiment/report/report.hpp"
#include "experiment/storage/reader.hpp"
#include "framework/error.hpp"
#include "problems/grid/map.hpp"
#include "problems/grid/map_io.hpp"
#include "tests/cli_runner.hpp"
#include "tests/json_reader.hpp"
#include "tests/test_support.hpp"

using namespace pride;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;
using grid::Cell;
using grid::GridMap;
using pride::test::expect_input_error;
using pride::test::input_error_message;
using pride::test::run_pride;
using pride::test::TempDir;

namespace {

constexpr int kWidth = 240, kHeight = 4;

/// A 240 x 4 map_server map, origin (-10, -10) m, 0.05 m per cell (nav2's sandbox frame): a wall at
/// column 100 over rows y = 0..2 (its gap at y = 3) and a full wall at column 235, so columns
/// 236..239 cannot be reached from the left. World x spans [-10, 2), y [-10, -9.8).
std::string world_map(const TempDir& dir) {
    std::string pgm = fmt::format("P2\n{} {}\n255\n", kWidth, kHeight);
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const bool blocked = (x == 100 && y <= 2) || x == 235;
            pgm += blocked ? "0 " : "254 ";
        }
        pgm += "\n";
    }
    dir.write("m.pgm", pgm);
    return dir.write("m.yaml", "image: m.pgm\nresolution: 0.05\norigin: [-10, -10, 0]\n");
}

/// The cell column of a map with the frame (0.05, -10, -10).
int column_of(const GridMap& m, double x) {
    const auto c = m.cell_at({x, -9.99});
    REQUIRE(c.has_value());
    return c->x;
}

/// Every row of `sql` on the store at `path`, each value as text ("null" for NULL).
std::vector<std::vector<std::string>> query(const std::string& path, const std::string& sql) {
    sqlite3* db = nullptr;
    REQUIRE(sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK);
    sqlite3_stmt* s = nullptr;
    INFO(sql);
    REQUIRE(sqlite3_prepare_v2(db, sql.c_str(), -1, &s, nullptr) == SQLITE_OK);
    std::vector<std::vector<std::string>> rows;
    while (sqlite3_step(s) == SQLITE_ROW) {
        std::vector<std::string> row;
        for (int i = 0; i < sqlite3_column_count(s); ++i) {
            const auto* text = sqlite3_column_text(s, i);
            row.emplace_back(text ? reinterpret_cast<const char*>(text) : "null");
        }
        rows.push_back(std::move(row));
    }
    sqlite3_finalize(s);
    sqlite3_close(db);
    return rows;
}

/// The campaign on the map of world_map(), its ends as `ends` (lines 9 and 10).
std::string world_campaign(const std::string& ends, const std::string& map = "m.yaml") {
    return "name = \"world\"\n"
           "seeds = 2\n"
           "[budget]\n"
           "evaluations = 400\n"
           "[[problem]]\n"
           "id = \"w\"\n"
           "type = \"grid\"\n"
           "map = \"" +
           map + "\"\n" + ends +
           "objective = \"length\"\n"
           "[[algorithm]]\n"
           "id = \"astar\"\n"
           "type = \"astar\"\n"
           "[[algorithm]]\n"
           "id = \"ga\"\n"
           "type = \"ga\"\n"
           "encoding = \"chain\"\n";
}

const std::string kWorldEnds = "start_world = [1.6, -9.9]\ngoal_world = [-9.95, -10]\n";
const std::string kCellEnds = "start = [232, 1]\ngoal = [1, 3]\n";

}  // namespace

TEST_CASE("world points: a point on a cell border lies in the cell after it, exactly", "[grid][map][world]") {
    GridMap m(kWidth, kHeight, std::vector<std::uint8_t>(kWidth * kHeight, 0), "m");
    m.set_frame({0.05, -10.0, -10.0});
    // The example of docs/grid.md: (1.6 + 10) / 0.05 is 232 in real numbers, the border between
    // columns 231 and 232, but 231.99999999999997 in floating point, which floor() put in 231.
    CHECK(std::floor((1.6 + 10.0) / 0.05) == 231.0);
    CHECK(grid::world_index(1.6, -10.0, 0.05) == 232.0);
    CHECK(column_of(m, 1.6) == 232);
    // Every border as a user writes it (the decimal number, read as a double): the cell after it.
    int floor_missed = 0;
    for (int k = 0; k < kWidth; ++k) {
        const double x = std::strtod(fmt::format("{:.10g}", -10.0 + k * 0.05).c_str(), nullptr);
        INFO("border " << k << " at x = " << x);
        CHECK(column_of(m, x) == k);
        floor_missed += std::floor((x + 10.0) / 0.05) != k;
        // A point a millionth of a cell before the border is in the cell before it.
        if (k > 0) CHECK(column_of(m, x - 0.05e-6) == k - 1);
        CHECK(column_of(m, x + 0.05e-6) == k);
    }
    CHECK(floor_missed > 50);  // the rounding that the rule corrects is common, not a corner case
    // y: rows counted from the top, the world's y axis up; a border belongs to the cell above it.
    for (int k = 0; k < kHeight; ++k) {
        const double y = std::strtod(fmt::format("{:.10g}", -10.0 + k * 0.05).c_str(), nullptr);
        const auto c = m.cell_at({-9.99, y});
        REQUIRE(c.has_value());
        CHECK(c->y == kHeight - 1 - k);
    }
    CHECK(m.cell_at({-9.99, -9.9})->y == 1);  // (-9.9 + 10) / 0.05 = 1.999999999999993
    // The map's far edges lie outside it (no cell beyond them); the origin's lines inside.
    CHECK_FALSE(m.cell_at({2.0, -9.9}).has_value());
    CHECK_FALSE(m.cell_at({0.0, -9.8}).has_value());
    CHECK(m.cell_at({-10.0, -10.0}) == std::optional<Cell>(Cell{0, kHeight - 1}));
    CHECK_FALSE(m.cell_at({-10.0 - 1e-6, -9.9}).has_value());
    // Other frames, other borders: resolution 0.1 from 0.3 (0.3 / 0.1 is 2.9999999999999996),
    // 0.025 from -51.225, 0.03 from 7.77; every border k lands in cell k.
    for (const auto& [res, origin] : {std::pair{0.1, 0.3}, std::pair{0.025, -51.225}, std::pair{0.03, 7.77}}) {
        GridMap f(200, 1, std::vector<std::uint8_t>(200, 0), "f");
        f.set_frame({res, origin, 0.0});
        for (int k = 0; k < 200; ++k) {
            const double x = std::strtod(fmt::format("{:.10g}", origin + k * res).c_str(), nullptr);
            INFO("resolution " << res << ", origin " << origin << ", border " << k << " at " << x);
            const auto c = f.cell_at({x, 0.5 * res});
            REQUIRE(c.has_value());
            CHECK(c->x == k);
        }
    }
    // The tolerance is 1e-9 of a cell: a point 1e-8 of a cell before a border stays before it.
    CHECK(grid::world_index(-10.0 + 0.05 * 7 - 0.05e-8, -10.0, 0.05) == 6.0);
    CHECK(std::isnan(grid::world_index(NAN, -10.0, 0.05)));
}

TEST_CASE("world points: pride path names --start-world and --goal-world in every error about them",
          "[grid][world][cli]") {
    const TempDir dir("world-cli");
    const std::string map = world_map(dir);
    const std::string path = "path --map '" + map + "' --algo astar ";
    // The border example: x = 1.6 is column 232.
    const auto r = run_pride(path + "--start-world 1.6,-9.9 --goal-world -9.95,-10 --json");
    INFO(r.err);
    REQUIRE(r.status == 0);
    const auto json = test::parse_json(r.out);
    const auto cells = json.at("path");
    CHECK(test::json_numbers(cells.items.front()) == std::vector<double>{232, 1});
    CHECK(test::json_numbers(cells.items.back()) == std::vector<double>{1, 3});
    expect_input_error(path + "--start-world -4.99,-9.85 --goal-world -9.95,-10",
                       {"--start-world: the point (-4.99, -9.85) is in cell (100,0), a blocked cell of"});
    expect_input_error(path + "--start-world 1.6,-9.9 --goal-world 1.9,-10",
                       {"pride: --goal-world: (238,3) cannot be reached from the start (232,1)"});
    expect_input_error(path + "--start-world 1.9,-10 --goal-world 1.6,-9.9",
                       {"pride: --goal-world: (232,1) cannot be reached from the start (238,3)"});
    expect_input_error(path + "--start-world 1.6,-9.8 --goal-world 1.6,-9.9", {"pride: --start-world:", "outside"});
    expect_input_error(path + "--start 232,1 --goal-world 2,-9.9", {"pride: --goal-world:", "outside"});
    // The cell options keep their names.
    expect_input_error(path + "--start 100,0 --goal-world -9.95,-10", {"pride: --start: (100,0) is a blocked cell"});
    expect_input_error(path + "--start-world 1.6,-9.9 --goal 238,3", {"pride: --goal: (238,3) cannot be reached"});
}

TEST_CASE("world points: lengths in metres beside cells in pride path's text, JSON and legend", "[grid][world][cli]") {
    const TempDir dir("world-metres");
    const std::string map = world_map(dir);
    const auto r = run_pride("path --map '" + map +
                             "' --start-world 1.6,-9.9 --goal-world -9.95,-10 --algo astar --objective length --json");
    REQUIRE(r.status == 0);
    const auto json = test::parse_json(r.out);
    const double length = json.at("metrics").at("length").number;
    CHECK(length > 231.0);
    CHECK(json.at("metrics").at("length_m").number == length * 0.05);
    const auto& pm = json.at("path_metrics");
    CHECK(pm.at("length_m").number == pm.at("length").number * 0.05);
    CHECK(pm.at("min_clearance_m").number == pm.at("min_clearance").number * 0.05);
    CHECK(pm.at("mean_clearance_m").number == pm.at("mean_clearance").number * 0.05);
    const auto text = run_pride("path --map '" + map + "' --start 232,1 --goal 1,3 --algo astar --objective length");
    REQUIRE(text.status == 0);
    CHECK_THAT(text.out,
               Contains(fmt::format("length          {:.10g}\nlength_m        {:.10g}\n", length, length * 0.05)));
    // The legend's words (the picture itself holds glyphs, not text).
    cli::PathOptions o;
    o.map = map;
    o.start_world = "1.6,-9.9";
    o.goal_world = "-9.95,-10";
    o.algo = "exact";
    o.objective = "length";
    o.oracle = true;
    engine::GridSpec spec;
    const engine::RunResult run = cli::plan_path(o, &spec);
    const auto [found, optimal] = cli::picture_labels(o, spec, *run.grid);
    const double exact = run.grid->metrics.length;
    const std::string words = html::length_words(exact, *spec.map->frame());
    CHECK(words == fmt::format("length {:.6g} cells = {:.6g} m", exact, exact * 0.05));
    CHECK_THAT(found, StartsWith("exact (none): length ") && Contains(words));
    CHECK_THAT(optimal, StartsWith("exact optimum: length ") && Contains(words));
    CHECK(html::length_words(23.4, grid::WorldFrame{0.05, 0, 0}) == "length 23.4 cells = 1.17 m");

    // A map without a frame: no metres anywhere.
    const std::string plain = std::string(PRIDE_SOURCE_DIR) + "/examples/maps/wan2022-10x10.map";
    const auto p = run_pride("path --map '" + plain + "' --start 0,0 --goal 9,9 --algo astar --json");
    REQUIRE(p.status == 0);
    CHECK_THAT(p.out, !Contains("_m\""));
    const auto pt = run_pride("path --map '" + plain + "' --start 0,0 --goal 9,9 --algo astar");
    CHECK_THAT(pt.out, !Contains("length_m"));
    o.map = plain;
    o.start_world.clear();
    o.goal_world.clear();
    o.start = "0,0";
    o.goal = "9,9";
    const engine::RunResult q = cli::plan_path(o, &spec);
    const auto [plain_found, plain_optimal] = cli::picture_labels(o, spec, *q.grid);
    CHECK_THAT(plain_found, !Contains("cells ="));
    CHECK_THAT(plain_optimal, !Contains("cells ="));
}

TEST_CASE("world points: a campaign's start_world and goal_world run what the equivalent cells run",
          "[grid][world][bench]") {
    const TempDir dir("world-bench");
    world_map(dir);
    const std::string world = dir.write("world.toml", world_campaign(kWorldEnds));
    const std::string cells = dir.write("cells.toml", world_campaign(kCellEnds));
    for (const auto& [file, store] : {std::pair{world, "w.sqlite"}, std::pair{cells, "c.sqlite"}}) {
        const auto r = run_pride("bench '" + file + "' --out '" + dir.file(store) + "' --jobs 1");
        INFO(r.err);
        REQUIRE(r.status == 0);
    }
    const std::string runs =
        "SELECT algorithm, seed, best, solution, path_metrics, optimum, evaluations FROM runs "
        "ORDER BY algorithm, seed";
    const auto w = query(dir.file("w.sqlite"), runs), c = query(dir.file("c.sqlite"), runs);
    REQUIRE(w.size() == 4);
    CHECK(w == c);
    const std::string problems = "SELECT start, goal, digest, definition FROM problems";
    CHECK(query(dir.file("w.sqlite"), problems) == query(dir.file("c.sqlite"), problems));
    CHECK(query(dir.file("w.sqlite"), "SELECT start, goal FROM problems") ==
          std::vector<std::vector<std::string>>{{"232,1", "1,3"}});
    // Metres = cells x resolution in every stored run (the store's path_metrics, as read back).
    const storage::CampaignStore s = storage::read_store(dir.file("w.sqlite"));
    REQUIRE(s.runs.size() == 4);
    for (const auto& run : s.runs) {
        REQUIRE(run.path_metrics.size() == std::size(storage::kPathMetricNames));
        REQUIRE(run.path_metrics[storage::kPathLengthMetres].has_value());
        CHECK(*run.path_metrics[storage::kPathLengthMetres] == *run.path_metrics[0] * 0.05);
    }
    for (const auto& row : query(dir.file("w.sqlite"),
                                 "SELECT json_extract(path_metrics, '$.length'), json_extract(path_metrics, "
                                 "'$.length_m'), json_extract(path_metrics, '$.min_clearance'), "
                                 "json_extract(path_metrics, '$.min_clearance_m') FROM runs"))
        CHECK(std::stod(row[1]) == Approx(std::stod(row[0]) * 0.05).epsilon(1e-14));
    // The report's tables of paths: a column of metres after the length, the median length times 0.05.
    const report::ReportData data = report::load_report(dir.file("w.sqlite"), {});
    REQUIRE(data.paths.size() == 2);
    CHECK(report::paths_in_metres(data.paths));
    for (const auto& row : data.paths) {
        const auto columns = row.columns(true);
        REQUIRE(columns.size() == std::size(storage::kPathMetricNames));
        REQUIRE(columns[0].has_value());
        REQUIRE(columns[1].has_value());
        CHECK(*columns[1] == Approx(*columns[0] * 0.05).epsilon(1e-14));
        CHECK(row.columns(false).size() == columns.size() - 1);
    }
    const auto md = run_pride("report '" + dir.file("w.sqlite") + "'");
    REQUIRE(md.status == 0);
    CHECK_THAT(md.out, Contains("| problem | algorithm | found | length | length (m) | turns |"));
    const auto astar =
        std::find_if(data.paths.begin(), data.paths.end(), [](const auto& r) { return r.algorithm == "astar"; });
    REQUIRE(astar != data.paths.end());
    CHECK_THAT(md.out, Contains(fmt::format("| w | astar | 2/2 | {:.4g} | {:.4g} |", *astar->medians[0],
                                            *astar->medians[storage::kPathLengthMetres])));
    const auto html = run_pride("report '" + dir.file("w.sqlite") + "' --html '" + dir.file("html") + "'");
    REQUIRE(html.status == 0);
    CHECK_THAT(test::slurp(dir.file("html/index.html")), Contains("<th class=\"n\">length (m)</th>"));
    // The cells' store says the same (its map has the frame); a map without one has no column.
    const auto plain = run_pride("report '" + dir.file("c.sqlite") + "'");
    CHECK_THAT(plain.out, Contains("| length | length (m) |"));
}

TEST_CASE("world points: a map without a frame keeps its report and legends as they were", "[grid][world][bench]") {
    const TempDir dir("world-plain");
    const std::string file =
        dir.write("plain.toml", world_campaign("start = [0, 0]\ngoal = [9, 9]\n",
                                               std::string(PRIDE_SOURCE_DIR) + "/examples/maps/wan2022-10x10.map"));
    REQUIRE(run_pride("bench '" + file + "' --out '" + dir.file("p.sqlite") + "' --jobs 1").status == 0);
    CHECK(query(dir.file("p.sqlite"),
                "SELECT count(*) FROM runs WHERE json_extract(path_metrics, '$.length_m') IS "
                "NOT NULL") == std::vector<std::vector<std::string>>{{"0"}});
    const report::ReportData data = report::load_report(dir.file("p.sqlite"), {});
    CHECK_FALSE(report::paths_in_metres(data.paths));
    const auto md = run_pride("report '" + dir.file("p.sqlite") + "'");
    CHECK_THAT(md.out, Contains("| problem | algorithm | found | length | turns |"));
    CHECK_THAT(md.out, !Contains("length (m)"));
    // The legend of an HTML best path: metres only with a frame.
    html::BestPath b;
    b.algorithm = "astar";
    b.value = 2.0;
    b.path = {{0, 0}, {1, 1}, {2, 1}};
    GridMap m(3, 2, std::vector<std::uint8_t>(6, 0), "m");
    CHECK(html::best_path_label(b, m) == "astar: 2 (seed 0)");
    m.set_frame({0.5, 0.0, 0.0});
    CHECK(html::best_path_label(b, m) == "astar: 2 (seed 0), " + html::length_words(1.0 + std::sqrt(2.0), *m.frame()));
    CHECK_THAT(html::best_path_label(b, m), Contains("= 1.20711 m"));
}

TEST_CASE("world points: a campaign's errors about them name the key, the file and its line", "[grid][world][bench]") {
    const TempDir dir("world-errors");
    world_map(dir);
    const auto error = [&](const std::string& ends, const std::string& map = "m.yaml") {
        const std::string file = dir.write("e.toml", world_campaign(ends, map));
        return input_error_message([&] { campaign::read_campaign(file); });
    };
    const std::string f = dir.file("e.toml");
    CHECK(error(kWorldEnds) == "<no InputError thrown>");
    CHECK(error("start_world = [1.6, -9.9]\nstart = [232, 1]\ngoal = [1, 3]\n") ==
          f + ":9: give 'start' (a cell) or 'start_world' (metres), not both");
    CHECK(error("start = [232, 1]\ngoal = [1, 3]\ngoal_world = [-9.95, -10]\n") ==
          f + ":11: give 'goal' (a cell) or 'goal_world' (metres), not both");
    CHECK(error("start_world = \"1.6,-9.9\"\ngoal = [1, 3]\n") ==
          f + ":9: 'start_world' must be [x, y] with two numbers (metres in the map's frame)");
    CHECK(error("start_world = [1.6]\ngoal = [1, 3]\n") ==
          f + ":9: 'start_world' must be [x, y] with two numbers (metres in the map's frame)");
    CHECK(error("start_world = [inf, 0]\ngoal = [1, 3]\n") == f + ":9: 'start_world' must be finite");
    CHECK(error("goal_world = [-9.95, -10]\n") == f + ":5: a grid [[problem]] needs 'start' (a cell) or "
                                                      "'start_world' (metres)");
    CHECK(error("start_world = [1.6, -9.9]\n") == f + ":5: a grid [[problem]] needs 'goal' (a cell) or "
                                                      "'goal_world' (metres)");
    const std::string plain = std::string(PRIDE_SOURCE_DIR) + "/examples/maps/wan2022-10x10.map";
    CHECK_THAT(error("start_world = [1, 1]\ngoal = [9, 9]\n", plain),
               StartsWith(f + ":9: problem 'w': start_world: the map ") &&
                   Contains("has no world frame (only a ROS map_server YAML map has a resolution and origin): give "
                            "'start' (a cell)"));
    CHECK(error("start_world = [1.6, -9.9]\ngoal_world = [-9.95, -9.8]\n") ==
          f + ":10: problem 'w': goal_world: the point (-9.95, -9.8) is outside the map: x in [-10, 2), y in [-10, "
              "-9.8) metres");
    CHECK_THAT(error("start_world = [-4.99, -9.85]\ngoal_world = [-9.95, -10]\n"),
               StartsWith(f + ":9: problem 'w': start_world: the point (-4.99, -9.85) is in cell (100,0), a blocked "
                              "cell of "));
    CHECK_THAT(error("start_world = [1.6, -9.9]\ngoal_world = [1.9, -10]\n"),
               StartsWith(f + ":10: problem 'w': goal_world: (238,3) cannot be reached from the start (232,1)"));
    // The cell keys keep their messages, at the problem's line.
    CHECK_THAT(error("start = [232, 1]\ngoal = [238, 3]\n"),
               StartsWith(f + ":5: problem 'w': goal: (238,3) cannot be reached"));
    // Through pride bench: one line, exit status 2.
    expect_input_error("bench '" +
                           dir.write("b.toml", world_campaign("start_world = [-4.99, -9.85]\ngoal = [1, 3]\n")) +
                           "' --out '" + dir.file("b.sqlite") + "'",
                       {dir.file("b.toml") + ":9: problem 'w': start_world:", "blocked"});
}

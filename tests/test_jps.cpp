// Jump Point Search (problems/grid/planners/jps.hpp) against A*: the same length on every line of the Moving
// AI scenario files and of the bundled maps' files, and on random maps; legal full cell chains;
// the same answer when the goal cannot be reached; bad input refused.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <string>

#include "cli_runner.hpp"
#include "framework/random.hpp"
#include "grid_support.hpp"
#include "json_reader.hpp"
#include "problems/grid/map_io.hpp"
#include "problems/grid/path.hpp"
#include "problems/grid/planners/astar.hpp"
#include "problems/grid/planners/jps.hpp"

using namespace pride;
using namespace pride::grid;

namespace {

/// JPS and A* on one query: equal lengths (to 1e-9), JPS's path legal and as long as it says.
void agree(const GridMap& map, Cell s, Cell g, AStar& astar, JumpPointSearch& jps) {
    Path pa, pj;
    const double la = astar.search(map, s, g, &pa);
    const double lj = jps.search(map, s, g, &pj);
    INFO(map.name() << " (" << s.x << "," << s.y << ") -> (" << g.x << "," << g.y << ")");
    if (la < 0.0) {
        CHECK(lj == -1.0);
        return;
    }
    REQUIRE(lj >= 0.0);
    CHECK(std::abs(lj - la) <= 1e-9);
    CHECK(path_violation(map, pj, s, g).empty());
    CHECK(std::abs(metrics(pj, false).length - lj) <= 1e-9);
}

}  // namespace

TEST_CASE("jps: the length of A* on every line of the Moving AI scenario files") {
    AStar astar;
    JumpPointSearch jps;
    std::int64_t queries = 0;
    const auto data = test::shared_data("movingai", "Moving AI maps and scenarios");
    if (!data) return;
    for (const auto& scen : test::movingai_scenarios(*data)) {
        const auto entries = read_scenario(scen.string());
        std::map<std::string, GridMap> maps;
        for (const auto& e : entries) {
            if (!maps.count(e.map)) maps.emplace(e.map, read_map((scen.parent_path() / e.map).string()));
            const GridMap& m = maps.at(e.map);
            agree(m, e.start, e.goal, astar, jps);
            // And the file's own optimum, as A* checks it (grid.md: below 1e-7).
            CHECK(std::abs(jps.search(m, e.start, e.goal) - e.optimal) < 1e-6);
            ++queries;
        }
    }
    CHECK(queries > 7000);
    // Pruning at work: far fewer expansions than A* over the same queries.
    CHECK(jps.expansions() * 2 < astar.expansions());
}

TEST_CASE("jps: the length of A* on the bundled maps and on random maps, reachable or not") {
    AStar astar;
    JumpPointSearch jps;
    for (const auto& inst : test::bundled_instances(std::string(PRIDE_SOURCE_DIR) + "/examples/maps"))
        agree(*inst.map, inst.start, inst.goal, astar, jps);
    Rng rng(2907);
    int unreachable = 0;
    for (int m = 0; m < 300; ++m) {
        const int w = 2 + test::below(rng, 40), h = 2 + test::below(rng, 40);
        std::vector<std::uint8_t> blocked(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
        const double density = 0.45 * rng.uniform();
        for (auto& b : blocked) b = rng.uniform() < density ? 1 : 0;
        const GridMap map(w, h, std::move(blocked), "random " + std::to_string(m));
        for (int q = 0; q < 20; ++q) {
            const Cell s{test::below(rng, w), test::below(rng, h)}, g{test::below(rng, w), test::below(rng, h)};
            if (!map.free(s) || !map.free(g)) continue;
            agree(map, s, g, astar, jps);
            unreachable += astar.search(map, s, g) < 0.0;
        }
    }
    CHECK(unreachable > 0);  // the unreachable case was exercised
}

TEST_CASE("jps: start equal to goal, hand-drawn forced neighbours, and bad input") {
    const GridMap map = test::map_of({
        ".....",
        ".@@@.",
        "...@.",
        ".@...",
    });
    JumpPointSearch jps;
    Path p;
    CHECK(jps.search(map, {0, 0}, {0, 0}, &p) == 0.0);
    CHECK(p == Path{{0, 0}});
    // Down the left column and east under the wall: (0,1) -> (1,2) would cut the corner of (1,1).
    CHECK(jps.search(map, {0, 0}, {2, 2}, &p) == Approx(4.0).epsilon(1e-12));
    CHECK(path_violation(map, p, {0, 0}, {2, 2}).empty());
    CHECK_THROWS_AS(jps.search(map, {1, 1}, {0, 0}), InputError);                 // blocked start
    CHECK_THROWS_AS(jps.search(map, {0, 0}, {9, 0}), InputError);                 // goal outside
    CHECK_THROWS_AS(jps.search(map, {0, 0}, {4, 3}, nullptr, true), InputError);  // corner cutting
}

TEST_CASE("jps: pride path --algo jps finds the length of astar with fewer expansions, refuses corner cutting") {
    const std::string where = std::string("path --map '") + PRIDE_SOURCE_DIR +
                              "/examples/maps/zhang2025-40x40.map' --start 1,38 --goal 38,1 --objective length --json";
    const auto jps = test::run_pride(where + " --algo jps");
    const auto astar = test::run_pride(where + " --algo astar");
    REQUIRE(jps.status == 0);
    REQUIRE(astar.status == 0);
    const auto j = test::parse_json(jps.out), a = test::parse_json(astar.out);
    CHECK(j.at("algo").text == "jps");
    CHECK(j.at("objective_value").number == Approx(56.42640687).epsilon(1e-9));
    CHECK(j.at("objective_value").number == a.at("objective_value").number);
    CHECK(j.at("evaluations").number < a.at("evaluations").number);
    const auto cut = test::run_pride(where + " --algo jps --corner-cutting");
    CHECK(cut.status != 0);
    CHECK(cut.err.find("corner cutting is not supported") != std::string::npos);
}

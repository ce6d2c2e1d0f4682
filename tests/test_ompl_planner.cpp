// The segment and point tests for any points (problems/grid/segment.cpp) against the exact
// half-lattice test, and OMPL's planners on the grid's plane (problems/grid/planners/ompl_planner.hpp, when
// built with OMPL): solved, free, no shorter than the exact optimum, within their budget, seeded
// runs reproducible in this process and in fresh ones.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "framework/random.hpp"
#include "grid_support.hpp"
#include "problems/grid/map_io.hpp"
#include "problems/grid/planners/any_angle.hpp"
#ifdef PRIDE_HAVE_OMPL
#include "problems/grid/planners/ompl_planner.hpp"
#endif

using namespace pride;
using namespace pride::grid;

namespace {

GridMap random_map(Rng& rng, int w, int h, double density) {
    std::vector<std::uint8_t> blocked(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
    for (auto& b : blocked) b = rng.uniform() < density ? 1 : 0;
    return GridMap(w, h, std::move(blocked), "random");
}

/// Each cell of `map` as a k x k block. The rules of any_angle.hpp are the same on both maps: a
/// refined grid point inside a block or on a block's side has no squeeze pattern, edges between
/// two blocked cells are the same, so a segment is free on one exactly when it is on the other.
GridMap refined(const GridMap& map, int k) {
    std::vector<std::uint8_t> blocked;
    for (int y = 0; y < map.height() * k; ++y)
        for (int x = 0; x < map.width() * k; ++x) blocked.push_back(map.free({x / k, y / k}) ? 0 : 1);
    return GridMap(map.width() * k, map.height() * k, std::move(blocked), "refined");
}

#ifdef PRIDE_HAVE_OMPL  // only the OMPL planners' cases use these two: unused (and warned of) without OMPL
/// p as a half-lattice point (a cell centre or a grid point), when it is one.
bool half_of(Point p, HalfPoint& h) {
    const double x = 2.0 * p.x, y = 2.0 * p.y;
    if (x != std::floor(x) || y != std::floor(y) || std::abs(x) > 1e9 || std::abs(y) > 1e9) return false;
    h = {static_cast<int>(x), static_cast<int>(y)};
    return ((h.x ^ h.y) & 1) == 0;
}

/// The exact half-lattice test where both ends allow it, the general one otherwise.
bool free_segment(const GridMap& map, Point a, Point b) {
    HalfPoint ha, hb;
    if (half_of(a, ha) && half_of(b, hb)) return segment_is_free(map, ha, hb);
    return segment_is_free(map, a, b);
}
#endif

}  // namespace

TEST_CASE("segment: any points agree with the half-lattice test on centres and grid points", "[ompl]") {
    Rng rng(3031);
    int free_count = 0, blocked_count = 0;
    for (int m = 0; m < 300; ++m) {
        const GridMap map = random_map(rng, 1 + test::below(rng, 9), 1 + test::below(rng, 9), 0.5 * rng.uniform());
        for (int q = 0; q < 60; ++q) {
            // Doubled coordinates from one cell outside the map to one beyond it, both of a parity.
            HalfPoint h[2];
            for (auto& p : h) {
                const int parity = test::below(rng, 2);
                p.x = 2 * (test::below(rng, map.width() + 3) - 1) + parity;
                p.y = 2 * (test::below(rng, map.height() + 3) - 1) + parity;
            }
            if (q % 10 == 0) h[1] = h[0];
            if (q % 10 == 1) {  // along a grid line or a column of centres
                h[1].x = h[0].x;
                if ((h[1].x ^ h[1].y) & 1) h[1].y ^= 1;
            }
            const bool exact = segment_is_free(map, h[0], h[1]);
            INFO("map " << m << " (" << h[0].x << "," << h[0].y << ") -> (" << h[1].x << "," << h[1].y << ") doubled\n"
                        << to_movingai(map));
            CHECK(segment_is_free(map, to_point(h[0]), to_point(h[1])) == exact);
            (exact ? free_count : blocked_count)++;
        }
    }
    CHECK(free_count > 2000);
    CHECK(blocked_count > 2000);
}

TEST_CASE("segment: points on a 1/8 lattice agree with the exact test on the map refined 8 times", "[ompl]") {
    Rng rng(4049);
    int free_count = 0;
    for (int m = 0; m < 120; ++m) {
        const GridMap map = random_map(rng, 1 + test::below(rng, 6), 1 + test::below(rng, 6), 0.45 * rng.uniform());
        const GridMap fine = refined(map, 8);
        for (int q = 0; q < 80; ++q) {
            int e[4];  // eighths of a cell, the map's own range plus a little outside
            e[0] = test::below(rng, 8 * map.width() + 3) - 1;
            e[1] = test::below(rng, 8 * map.height() + 3) - 1;
            e[2] = test::below(rng, 8 * map.width() + 3) - 1;
            e[3] = test::below(rng, 8 * map.height() + 3) - 1;
            const Point a{e[0] / 8.0, e[1] / 8.0}, b{e[2] / 8.0, e[3] / 8.0};
            const bool exact = segment_is_free(fine, HalfPoint{2 * e[0], 2 * e[1]}, HalfPoint{2 * e[2], 2 * e[3]});
            INFO("map " << m << " (" << a.x << "," << a.y << ") -> (" << b.x << "," << b.y << ")\n"
                        << to_movingai(map));
            CHECK(segment_is_free(map, a, b) == exact);
            if (exact) ++free_count;
            // point_is_free on the ends: a point of the lattice is free when a short segment from
            // it into a free direction can be, so compare with the refined map's cells around it.
            const bool around = fine.free({e[0] - 1, e[1] - 1}) || fine.free({e[0], e[1] - 1}) ||
                                fine.free({e[0] - 1, e[1]}) || fine.free({e[0], e[1]});
            CHECK(point_is_free(map, a) == (around && !is_squeeze_point(fine, e[0], e[1])));
        }
    }
    CHECK(free_count > 1000);
}

TEST_CASE("segment: exact near corners and squeeze points, conservative only for tiny coordinates", "[ompl]") {
    // (1,1) blocked: segments tangent at its corner (1,1) are free, a hair inside is blocked.
    const GridMap one = test::map_of({"...", ".@.", "..."});
    const double d = 0x1p-50;
    CHECK(segment_is_free(one, Point{0.375, 1.625}, Point{1.625, 0.375}));            // x + y = 2 touches (1,1)
    CHECK_FALSE(segment_is_free(one, Point{0.375, 1.625 + d}, Point{1.625, 0.375}));  // crosses x = 1 above y = 1
    CHECK(segment_is_free(one, Point{0.375, 1.625 - d}, Point{1.625, 0.375}));        // passes the corner outside
    // Along the blocked square's top edge (a free cell above it), and inside it by a hair.
    CHECK(segment_is_free(one, Point{0.1, 1.0}, Point{2.9, 1.0}));
    CHECK_FALSE(segment_is_free(one, Point{0.1, 1.0 + d}, Point{2.9, 1.0 + d}));
    // The squeeze point (1,1) between (0,0) and (1,1): through it is blocked, ending at it is not.
    const GridMap squeeze = test::map_of({"@.", ".@"});
    CHECK_FALSE(segment_is_free(squeeze, Point{0.3, 1.7}, Point{1.7, 0.3}));
    CHECK(segment_is_free(squeeze, Point{0.3, 1.7}, Point{1.0, 1.0}));
    CHECK_FALSE(point_is_free(squeeze, Point{1.0, 1.0}));
    CHECK(point_is_free(squeeze, Point{1.0, 0.5}));        // the edge between free (1,0) and blocked (0,0)
    CHECK_FALSE(point_is_free(squeeze, Point{0.5, 0.5}));  // inside (0,0)
    // Map borders: along them next to a free cell, not beyond; non-finite points are blocked.
    CHECK(segment_is_free(one, Point{0.0, 0.2}, Point{0.0, 2.7}));
    CHECK_FALSE(segment_is_free(one, Point{0.0, 0.2}, Point{-1e-300, 2.7}));
    CHECK_FALSE(segment_is_free(one, Point{0.5, 0.5}, Point{NAN, 0.5}));
    CHECK_FALSE(point_is_free(one, Point{3.0 + 1e-12, 1.0}));
    CHECK(point_is_free(one, Point{3.0, 3.0}));
    // Conservative: a coordinate below 2^-400 (not 0) makes any segment blocked.
    CHECK_FALSE(segment_is_free(one, Point{1e-130, 0.5}, Point{2.5, 0.5}));
    CHECK(segment_is_free(one, Point{0.0, 0.5}, Point{2.5, 0.5}));
    // A zero-length segment is free, as the half-lattice test says; the point itself may not be.
    CHECK(segment_is_free(one, Point{1.5, 1.5}, Point{1.5, 1.5}));
    CHECK_FALSE(point_is_free(one, Point{1.5, 1.5}));
}

#ifdef PRIDE_HAVE_OMPL

namespace {

const GridMap& open_map() {
    static const GridMap m(12, 12, std::vector<std::uint8_t>(144, 0), "open");
    return m;
}
const GridMap& wall_map() {  // a wall with a one-cell gap at its bottom
    static const GridMap m = test::map_of({
        "...............",
        ".......@.......",
        ".......@.......",
        ".......@.......",
        ".......@.......",
        ".......@.......",
        ".......@.......",
        ".......@.......",
        "...............",
        ".......@.......",
    });
    return m;
}
const GridMap& maze_map() {
    static const GridMap m = test::map_of({
        "...........",
        ".@@@@@@@@@.",
        ".@.......@.",
        ".@.@@@@@.@.",
        ".@.@...@.@.",
        ".@.@.@.@.@.",
        ".@...@.@.@.",
        ".@@@@@.@.@.",
        ".......@...",
        "@@@@@@@@@@.",
        "...........",
    });
    return m;
}

struct Task {
    const GridMap* map;
    Cell s, g;
};

std::vector<Task> tasks() {
    return {{&open_map(), {0, 11}, {11, 0}}, {&wall_map(), {1, 2}, {13, 2}}, {&maze_map(), {4, 4}, {0, 10}}};
}

OmplRequest request(const std::string& planner, std::int64_t checks, std::uint64_t seed = 1) {
    OmplRequest r;
    r.planner = planner;
    r.max_checks = checks;
    r.seed = seed;
    return r;
}

/// A budget that solves the task with seed 1. On the maze RRT* and Informed RRT* need ~10^5 checks
/// (0.3 s): they spend many motion checks per sample (rewiring). Elsewhere a few thousand do; on
/// the open map 10^5 would take seconds (every sample joins the tree, and rewiring grows with it),
/// as would 10^4 for OMPL 1.5's BIT*, whose time grows faster than its checks.
std::int64_t budget_for(const std::string& planner, const GridMap& map) {
    return &map == &maze_map() && planner != "BITstar" ? 100000 : 4000;
}

/// The polyline in hexadecimal floats, and the counts: equal strings, equal runs.
std::string fingerprint(const OmplOutcome& o) {
    std::ostringstream s;
    s << o.solved << ' ' << o.state_checks << ' ' << o.motion_checks;
    char buf[64];
    for (const Point& p : o.polyline) {
        std::snprintf(buf, sizeof buf, " %a,%a", p.x, p.y);
        s << buf;
    }
    return s.str();
}

void check_polyline(const GridMap& map, const Task& t, const OmplOutcome& o) {
    REQUIRE(o.polyline.size() >= 2);
    CHECK(o.polyline.front() == centre_point(t.s));
    CHECK(o.polyline.back() == centre_point(t.g));
    for (std::size_t i = 1; i < o.polyline.size(); ++i) CHECK(free_segment(map, o.polyline[i - 1], o.polyline[i]));
    for (const Point& p : o.polyline) CHECK(point_is_free(map, p));
}

}  // namespace

TEST_CASE("ompl: every planner solves the open, wall and maze maps with free polylines no shorter than the optimum",
          "[ompl]") {
    for (const auto& name : ompl_planner_names())
        for (const Task& t : tasks()) {
            AnyAngleOracle oracle(*t.map);
            const double optimum = oracle.solve(t.s, t.g);
            REQUIRE(optimum > 0.0);
            const std::int64_t budget = budget_for(name, *t.map);
            for (const bool simplify : {false, true}) {
                OmplRequest r = request(name, budget);
                r.simplify = simplify;
                const OmplOutcome o = plan_with_ompl(*t.map, t.s, t.g, r);
                INFO(name << " on " << t.map->name() << (simplify ? " simplified" : ""));
                REQUIRE(o.solved);
                check_polyline(*t.map, t, o);
                const double length = polyline_length(o.polyline);
                CHECK(length >= optimum - 1e-9);
                CHECK(o.first_solution_ms >= 0.0);
                CHECK(o.first_solution_ms <= o.planning_ms);
                // Planning and simplifying together stay within the budget.
                CHECK(o.state_checks + o.motion_checks + o.simplify_checks <= budget);
                if (simplify) {
                    // The planner had nine tenths of the budget: with those alone it plans the same
                    // path, which the simplifier only shortens.
                    CHECK(o.state_checks + o.motion_checks <= budget - budget / 10);
                    const OmplOutcome raw = plan_with_ompl(*t.map, t.s, t.g, request(name, budget - budget / 10));
                    CHECK(length <= polyline_length(raw.polyline) + 1e-9);
                    if (raw.polyline.size() > 2) CHECK(o.simplify_checks > 0);
                } else {
                    CHECK(o.simplify_checks == 0);
                }
            }
        }
}

TEST_CASE("ompl: near the optimum on simple maps: 0.1% on the open map, 2% around the wall with a generous budget",
          "[ompl]") {
    // Measured with seed 1: the open map's straight line exactly; around the wall 0.1-0.8% above
    // the optimum (RRT*, Informed RRT* and PRM* with 20000 checks, BIT* with 6000).
    for (const Task& t : {tasks()[0], tasks()[1]}) {
        const bool open = t.map == &open_map();
        const double optimum = AnyAngleOracle(*t.map).solve(t.s, t.g);
        for (const auto& name : ompl_planner_names()) {
            const std::int64_t budget = open ? 4000 : name == "BITstar" ? 6000 : 20000;
            const OmplOutcome o = plan_with_ompl(*t.map, t.s, t.g, request(name, budget));
            INFO(name << " on " << t.map->name() << ": " << polyline_length(o.polyline) << " against " << optimum);
            REQUIRE(o.solved);
            CHECK(polyline_length(o.polyline) <= (open ? 1.001 : 1.02) * optimum);
        }
    }
}

TEST_CASE("ompl: an unreachable goal is not solved, and the budget in checks is never exceeded", "[ompl]") {
    const GridMap closed = test::map_of({
        "....@....",
        "....@....",
        "....@....",
        "....@....",
    });
    for (const auto& name : ompl_planner_names()) {
        for (const std::int64_t budget : {1, 50, 3000}) {
            const OmplOutcome o = plan_with_ompl(closed, {0, 0}, {8, 3}, request(name, budget));
            INFO(name << " with " << budget << " checks");
            CHECK_FALSE(o.solved);
            CHECK(o.polyline.empty());
            CHECK(o.first_solution_ms == -1.0);
            CHECK(o.state_checks + o.motion_checks <= budget);
        }
        // A time limit alone ends too.
        OmplRequest timed;
        timed.planner = name;
        timed.time_limit_s = 0.05;
        const OmplOutcome o = plan_with_ompl(closed, {0, 0}, {8, 3}, timed);
        CHECK_FALSE(o.solved);
        CHECK(o.planning_ms < 2000.0);
        // Budgets exactly met on a solvable map too (the checkers stop counting at the budget).
        for (const std::int64_t budget : {10, 700, 5000}) {
            const OmplOutcome s = plan_with_ompl(maze_map(), {4, 4}, {0, 10}, request(name, budget));
            CHECK(s.state_checks + s.motion_checks <= budget);
        }
    }
}

TEST_CASE("ompl: bad requests are input errors naming the field", "[ompl]") {
    const GridMap& map = wall_map();
    const auto where = [&](const OmplRequest& r, Cell s, Cell g) {
        try {
            plan_with_ompl(map, s, g, r);
        } catch (const InputError& e) {
            return e.where() + ": " + e.detail();
        }
        return std::string("no error");
    };
    CHECK_THAT(where(request("RRTsharp", 100), {0, 0}, {1, 0}),
               Catch::StartsWith("planner: unknown OMPL planner 'RRTsharp'") && Catch::Contains("BITstar"));
    CHECK_THAT(where(request("RRTstar", 0), {0, 0}, {1, 0}), Catch::StartsWith("max_checks: a budget is needed"));
    CHECK_THAT(where(request("RRTstar", -5), {0, 0}, {1, 0}), Catch::StartsWith("max_checks: must be >= 0"));
    OmplRequest nan_time = request("RRTstar", 100);
    nan_time.time_limit_s = NAN;
    CHECK_THAT(where(nan_time, {0, 0}, {1, 0}), Catch::StartsWith("time_limit_s:"));
    CHECK_THAT(where(request("PRMstar", 100), {7, 1}, {1, 0}), Catch::StartsWith("start: (7,1) is blocked"));
    CHECK_THAT(where(request("PRMstar", 100), {0, 0}, {15, 0}),
               Catch::StartsWith("goal: (15,0) is blocked or outside"));
    // start == goal needs no planning.
    const OmplOutcome same = plan_with_ompl(map, {3, 3}, {3, 3}, request("BITstar", 10));
    CHECK(same.solved);
    CHECK(same.polyline == std::vector<Point>{{3.5, 3.5}});
}

namespace {
constexpr std::uint64_t kSeeds[] = {1, 77};
std::string all_fingerprints() {
    std::string out;
    for (const auto& name : ompl_planner_names())
        for (const std::uint64_t seed : kSeeds) {
            const OmplOutcome o = plan_with_ompl(wall_map(), {1, 2}, {13, 2}, request(name, 4000, seed));
            out += name + " " + std::to_string(seed) + " " + fingerprint(o) + "\n";
        }
    return out;
}
}  // namespace

// Run by the next test case in fresh processes: prints the fingerprints of seeded runs.
TEST_CASE("ompl: fingerprints of seeded runs", "[.ompl_fingerprints]") {
    std::printf("%s", all_fingerprints().c_str());
}

TEST_CASE("ompl: a seed and a budget in checks give the same run in this process and in fresh ones", "[ompl]") {
    // In this process, after other OMPL runs: each planner twice with the same seed.
    for (const auto& name : ompl_planner_names()) {
        const OmplOutcome a = plan_with_ompl(wall_map(), {1, 2}, {13, 2}, request(name, 4000, 9));
        const OmplOutcome b = plan_with_ompl(wall_map(), {1, 2}, {13, 2}, request(name, 4000, 9));
        const OmplOutcome c = plan_with_ompl(wall_map(), {1, 2}, {13, 2}, request(name, 4000, 10));
        INFO(name);
        CHECK(a.solved);
        CHECK(fingerprint(a) == fingerprint(b));
        CHECK(fingerprint(a) != fingerprint(c));  // the seed is used
    }
    // Two fresh processes (this test binary, the hidden case above) print what this one computes.
    const std::string here = all_fingerprints();
    const std::string exe = std::filesystem::read_symlink("/proc/self/exe").string();
    for (int run = 0; run < 2; ++run) {
        FILE* pipe = popen(("'" + exe + "' '[.ompl_fingerprints]' 2>/dev/null").c_str(), "r");
        REQUIRE(pipe != nullptr);
        std::string text;
        char buf[4096];
        while (std::fgets(buf, sizeof buf, pipe)) text += buf;
        CHECK(pclose(pipe) == 0);
        INFO(text);
        CHECK(text.find(here) != std::string::npos);  // Catch2 adds its own lines
    }
}

#endif  // PRIDE_HAVE_OMPL

// Tests of the exact Pareto fronts (problems/grid/pareto.hpp) and of what rests on them: the iqga
// optimum (the exact algorithm and the oracle with --objective iqga) and `pride pareto`.
//
// The reference is brute force written here, apart from the library: a depth-first enumeration of
// every simple cell path with grid.md's move rules (own legality test), its own metrics (angles
// from the step vectors, W(theta) from the angle in degrees, lengths as counts of orthogonal and
// diagonal steps compared as long doubles), its own non-dominated filter and its own iqga formula.
// The enumeration prunes a partial path only when an already complete path weakly dominates it
// (every metric only grows as a path grows, and the length strictly), and the iqga search only a
// partial path whose own iqga value is no better than the best (iqga never decreases as a path grows).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "cli_runner.hpp"
#include "json_reader.hpp"
#include "problems/grid/map_io.hpp"
#include "problems/grid/objectives.hpp"
#include "problems/grid/pareto.hpp"
#include "problems/grid/planners/astar.hpp"
#include "tests/grid_support.hpp"
#include "tests/test_support.hpp"

namespace {

using pride::test::angle_between;
using pride::test::w_of_degrees;

using namespace pride;
using grid::Cell;
using grid::Criteria;
using grid::GridMap;
using grid::Path;

// ---------------------------------------------------------------------------------------------
// Brute force

struct Cost {
    int straight = 0, diagonal = 0, turns = 0, angle = 0;
    long double length() const { return straight + diagonal * std::sqrt(2.0L); }
};

/// a weakly dominates b in the chosen criteria (lengths equal within 1e-9).
bool weakly_dominates(const Cost& a, const Cost& b, const Criteria& c) {
    if (c.length && a.length() > b.length() + 1e-9L) return false;
    if (c.turns && a.turns > b.turns) return false;
    if (c.angle_penalty && a.angle > b.angle) return false;
    return true;
}

/// The projection onto the chosen criteria, with lengths as step counts (exact, comparable).
using Key = std::tuple<long long, int, int>;  // length * 1e6 rounded, turns, angle (unchosen: 0)
Key key_of(const Cost& x, const Criteria& c) {
    return {c.length ? std::llround(x.length() * 1e6L) : 0, c.turns ? x.turns : 0, c.angle_penalty ? x.angle : 0};
}

struct Brute {
    const GridMap& map;
    Cell goal;
    bool cutting;
    Criteria criteria;
    std::vector<Cost> found;  // complete paths' costs, possibly dominated
    double best_iqga = 1e300;
    bool for_iqga = false;
    std::vector<char> on;
    Path chain;

    bool free(int x, int y) const {
        return x >= 0 && y >= 0 && x < map.width() && y < map.height() && map.free({x, y});
    }
    bool legal(Cell a, int dx, int dy) const {
        if (!free(a.x + dx, a.y + dy)) return false;
        if (dx != 0 && dy != 0 && !cutting) return free(a.x + dx, a.y) && free(a.x, a.y + dy);
        return true;
    }
    static double iqga(const Cost& c) {
        const double len = static_cast<double>(c.length());
        return -((len > 0 ? 1.0 / len : 2.0) + (c.angle > 0 ? 1.0 / c.angle : 0.2) +
                 (c.turns > 0 ? 1.0 / c.turns : 2.0));
    }
    void dfs(Cost cost, int pdx, int pdy) {
        const Cell c = chain.back();
        if (c == goal) {
            if (for_iqga)
                best_iqga = std::min(best_iqga, iqga(cost));
            else
                found.push_back(cost);
            return;
        }
        if (for_iqga) {
            if (iqga(cost) >= best_iqga) return;
        } else {
            for (const Cost& f : found)
                if (weakly_dominates(f, cost, criteria)) return;
        }
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                if ((dx == 0 && dy == 0) || !legal(c, dx, dy)) continue;
                const Cell n{c.x + dx, c.y + dy};
                const std::size_t i = static_cast<std::size_t>(n.y * map.width() + n.x);
                if (on[i]) continue;
                Cost next = cost;
                (dx != 0 && dy != 0 ? next.diagonal : next.straight) += 1;
                if (pdx != 0 || pdy != 0) {
                    const double theta = angle_between(pdx, pdy, dx, dy);
                    if (theta > 1e-9) ++next.turns;
                    next.angle += w_of_degrees(theta);
                }
                on[i] = 1;
                chain.push_back(n);
                dfs(next, dx, dy);
                chain.pop_back();
                on[i] = 0;
            }
    }
    void run(Cell s) {
        on.assign(map.size(), 0);
        on[static_cast<std::size_t>(s.y * map.width() + s.x)] = 1;
        chain = {s};
        dfs(Cost{}, 0, 0);
    }
};

/// The non-dominated projections of `costs` onto the criteria, as a sorted set of keys.
std::set<Key> non_dominated(const std::vector<Cost>& costs, const Criteria& c) {
    std::set<Key> out;
    for (const Cost& x : costs) {
        bool dominated = false;
        for (const Cost& y : costs)
            if (weakly_dominates(y, x, c) && !weakly_dominates(x, y, c)) dominated = true;
        if (!dominated) out.insert(key_of(x, c));
    }
    return out;
}

/// The metrics of a path, computed as the brute force does.
Cost cost_of(const Path& p) {
    Cost c;
    for (std::size_t i = 1; i < p.size(); ++i) {
        const int dx = p[i].x - p[i - 1].x, dy = p[i].y - p[i - 1].y;
        (dx != 0 && dy != 0 ? c.diagonal : c.straight) += 1;
        if (i >= 2) {
            const int px = p[i - 1].x - p[i - 2].x, py = p[i - 1].y - p[i - 2].y;
            const double theta = angle_between(px, py, dx, dy);
            if (theta > 1e-9) ++c.turns;
            c.angle += w_of_degrees(theta);
        }
    }
    return c;
}

/// Every step one of the 8 moves onto a free cell, no corner cut unless allowed, start and goal at the ends.
bool legal_path(const GridMap& map, const Path& p, Cell s, Cell g, bool cutting) {
    if (p.empty() || !(p.front() == s) || !(p.back() == g)) return false;
    Brute b{map, g, cutting, {}, {}, 0, false, {}, {}};
    if (!b.free(s.x, s.y)) return false;
    for (std::size_t i = 1; i < p.size(); ++i) {
        const int dx = p[i].x - p[i - 1].x, dy = p[i].y - p[i - 1].y;
        if (std::max(std::abs(dx), std::abs(dy)) != 1 || !b.legal(p[i - 1], dx, dy)) return false;
    }
    return true;
}

const Criteria kLT{true, true, false}, kLA{true, false, true}, kLTA{true, true, true};

GridMap random_map(Rng& rng, int w, int h, int percent) {
    std::vector<std::uint8_t> blocked(static_cast<std::size_t>(w * h));
    for (auto& b : blocked) b = test::below(rng, 100) < percent ? 1 : 0;
    return GridMap(w, h, std::move(blocked), "random");
}

Cell random_free(Rng& rng, const GridMap& m) {
    for (;;) {
        const Cell c{test::below(rng, m.width()), test::below(rng, m.height())};
        if (m.free(c)) return c;
    }
}

/// The library's front, checked point by point: sorted by length, each path legal with the
/// metrics it reports (as measured here), no point weakly dominating another in the criteria.
std::set<Key> checked_front(const GridMap& map, Cell s, Cell g, const Criteria& c, bool cutting,
                            bool heuristic = true) {
    grid::ParetoOptions o;
    o.corner_cutting = cutting;
    o.use_heuristic = heuristic;
    const auto front = grid::pareto_front(map, s, g, c, o);
    std::set<Key> keys;
    std::vector<Cost> costs;
    for (std::size_t i = 0; i < front.size(); ++i) {
        const auto& p = front[i];
        CHECK(legal_path(map, p.path, s, g, cutting));
        const Cost m = cost_of(p.path);
        CHECK(m.straight == p.steps.straight);
        CHECK(m.diagonal == p.steps.diagonal);
        CHECK(m.turns == p.turns);
        CHECK(m.angle == p.angle_penalty);
        CHECK(std::abs(static_cast<double>(m.length()) - p.length) < 1e-9);
        if (i > 0) CHECK(front[i - 1].length <= p.length + 1e-9);
        for (const Cost& other : costs) CHECK_FALSE(weakly_dominates(other, m, c));
        costs.push_back(m);
        keys.insert(key_of(m, c));
    }
    return keys;
}

}  // namespace

TEST_CASE("pareto: exact length comparisons", "[pareto]") {
    using grid::compare_lengths;
    CHECK(compare_lengths({3, 0}, {1, 1}) == 1);   // 3 > 1 + 1.414
    CHECK(compare_lengths({2, 0}, {0, 1}) == 1);   // 2 > 1.414
    CHECK(compare_lengths({1, 0}, {0, 1}) == -1);  // 1 < 1.414
    CHECK(compare_lengths({7, 5}, {7, 5}) == 0);
    CHECK(compare_lengths({0, 12}, {17, 0}) == -1);  // 16.97 < 17
    CHECK(compare_lengths({17, 0}, {0, 12}) == 1);
    CHECK(compare_lengths({0, 70}, {99, 0}) == -1);  // 98.995 < 99
    CHECK(compare_lengths({-1, 0}, {0, 0}) == -1);
    CHECK(compare_lengths({0, 29}, {41, 0}) == 1);  // 41.012 > 41
}

TEST_CASE("pareto: criteria lists", "[pareto]") {
    CHECK(grid::parse_criteria("length,turns") == kLT);
    CHECK(grid::parse_criteria("length,angle") == kLA);
    CHECK(grid::parse_criteria("angle,turns,length") == kLTA);
    CHECK(grid::parse_criteria("length,angle_penalty") == kLA);
    CHECK(grid::criteria_names(kLTA) == std::vector<std::string>{"length", "turns", "angle_penalty"});
    CHECK(test::input_error_message([] { grid::parse_criteria("length,speed"); }).find("unknown objective 'speed'") !=
          std::string::npos);
    CHECK(test::input_error_message([] { grid::parse_criteria("length,turns,length"); }).find("given twice") !=
          std::string::npos);
    CHECK(test::input_error_message([] { grid::parse_criteria(""); }).find("objectives") != std::string::npos);
    CHECK(test::input_error_message([] { grid::parse_criteria("length,"); }).find("unknown objective ''") !=
          std::string::npos);
}

TEST_CASE("pareto: on tiny random maps the fronts equal brute force's, and so does the iqga optimum",
          "[pareto][brute]") {
    Rng rng(20261201);
    int maps = 0, points = 0;
    for (int trial = 0; trial < 600; ++trial) {
        const int w = 4 + test::below(rng, 3), h = 4 + test::below(rng, 2);
        const GridMap map = random_map(rng, w, h, test::below(rng, 31));
        bool any_free = false;
        for (std::size_t i = 0; i < map.size(); ++i) any_free = any_free || map.free_index(i);
        if (!any_free) continue;
        const Cell s = random_free(rng, map), g = random_free(rng, map);
        const bool cutting = trial % 5 == 4;
        INFO("trial " << trial << " " << w << "x" << h << " s " << s.x << "," << s.y << " g " << g.x << "," << g.y
                      << " cutting " << cutting << "\n"
                      << grid::to_movingai(map));
        for (const Criteria& c : {kLT, kLA, kLTA}) {
            Brute b{map, g, cutting, c, {}, 0, false, {}, {}};
            b.run(s);
            const std::set<Key> expected = non_dominated(b.found, c);
            const std::set<Key> got = checked_front(map, s, g, c, cutting);
            CHECK(got == expected);
            if (trial % 3 == 0) CHECK(checked_front(map, s, g, c, cutting, false) == expected);  // plain Martins
            points += static_cast<int>(got.size());
        }
        Brute bi{map, g, cutting, kLTA, {}, 1e300, true, {}, {}};
        bi.run(s);
        Path best;
        const auto opt = grid::iqga_optimum(map, s, g, cutting, &best);
        if (bi.best_iqga == 1e300) {
            CHECK_FALSE(opt.has_value());
            grid::ParetoOptions o;
            o.corner_cutting = cutting;
            CHECK(grid::pareto_front(map, s, g, kLTA, o).empty());
        } else {
            REQUIRE(opt.has_value());
            CHECK(std::abs(*opt - bi.best_iqga) < 1e-12);
            CHECK(legal_path(map, best, s, g, cutting));
            CHECK(Brute::iqga(cost_of(best)) == Approx(*opt).epsilon(1e-12));
            CHECK(grid::IqgaObjective{}(grid::metrics(best)) == *opt);
        }
        ++maps;
    }
    CHECK(maps >= 550);
    CHECK(points > 1500);
}

TEST_CASE("pareto: the 2-D fronts are the non-dominated projections of the 3-D front, length extreme = A*",
          "[pareto]") {
    Rng rng(11);
    for (int trial = 0; trial < 60; ++trial) {
        const int w = 8 + test::below(rng, 17), h = 8 + test::below(rng, 17);
        const GridMap map = random_map(rng, w, h, test::below(rng, 31));
        bool any_free = false;
        for (std::size_t i = 0; i < map.size(); ++i) any_free = any_free || map.free_index(i);
        if (!any_free) continue;
        const Cell s = random_free(rng, map), g = random_free(rng, map);
        INFO("trial " << trial);
        const auto three = grid::pareto_front(map, s, g, kLTA);
        std::vector<Cost> costs;
        for (const auto& p : three) costs.push_back(cost_of(p.path));
        grid::AStar astar;
        const double shortest = astar.search(map, s, g);
        REQUIRE((shortest < 0) == three.empty());
        for (const Criteria& c : {kLT, kLA}) {
            const auto two = grid::pareto_front(map, s, g, c);
            std::set<Key> keys;
            for (const auto& p : two) keys.insert(key_of(cost_of(p.path), c));
            CHECK(keys == non_dominated(costs, c));
            if (shortest >= 0) {
                REQUIRE_FALSE(two.empty());
                CHECK(std::abs(two.front().length - shortest) < 1e-9);
            }
        }
        if (shortest >= 0) CHECK(std::abs(three.front().length - shortest) < 1e-9);
    }
}

TEST_CASE("pareto: one-criterion fronts and degenerate inputs", "[pareto]") {
    const GridMap map = test::map_of({"....", ".@@.", "...."});
    const auto len = grid::pareto_front(map, {0, 0}, {3, 2}, Criteria{true, false, false});
    REQUIRE(len.size() == 1);
    CHECK(len.front().length == 5.0);  // around the wall's end: no corner cutting
    const auto turns = grid::pareto_front(map, {0, 0}, {3, 0}, Criteria{false, true, false});
    REQUIRE(turns.size() == 1);
    CHECK(turns.front().turns == 0);
    CHECK(grid::pareto_front(map, {0, 0}, {1, 1}, kLTA).empty());  // blocked goal
    CHECK(grid::pareto_front(map, {0, 0}, {9, 9}, kLTA).empty());  // outside
    const auto same = grid::pareto_front(map, {2, 2}, {2, 2}, kLTA);
    REQUIRE(same.size() == 1);
    CHECK(same.front().path == Path{{2, 2}});
    const GridMap walled = test::map_of({"..@..", "..@..", "..@.."});
    CHECK(grid::pareto_front(walled, {0, 0}, {4, 0}, kLTA).empty());
    CHECK_FALSE(grid::iqga_optimum(walled, {0, 0}, {4, 0}).has_value());
    grid::ParetoOptions tight;
    tight.max_labels = 5;
    CHECK(test::input_error_message([&] {
              grid::pareto_front(map, {0, 0}, {3, 2}, kLTA, tight);
          }).find("more than 5 labels") != std::string::npos);
}

TEST_CASE("pareto: on the bundled maps every front is non-empty, legal and non-dominated", "[pareto]") {
    struct Case {
        const char* file;
        Cell s, g;
    };
    for (const Case& k : {Case{"wan2022-10x10.map", {0, 0}, {9, 9}}, Case{"wan2022-13x13.map", {0, 0}, {12, 12}},
                          Case{"zhang2025-20x20.map", {0, 19}, {19, 0}}, Case{"zhang2025-40x40.map", {1, 38}, {38, 1}},
                          Case{"cai2021-50x50.map", {0, 49}, {49, 0}}}) {
        INFO(k.file);
        const GridMap map = grid::read_map(std::string(PRIDE_SOURCE_DIR) + "/examples/maps/" + k.file);
        grid::AStar astar;
        const double shortest = astar.search(map, k.s, k.g);
        for (const Criteria& c : {kLT, kLA, kLTA}) {
            const std::set<Key> keys = checked_front(map, k.s, k.g, c, false);
            CHECK_FALSE(keys.empty());
            const auto front = grid::pareto_front(map, k.s, k.g, c);
            CHECK(std::abs(front.front().length - shortest) < 1e-9);
        }
        const auto iqga = grid::iqga_optimum(map, k.s, k.g);
        CHECK(iqga.has_value());
    }
}

// ---------------------------------------------------------------------------------------------
// The engine: the exact algorithm and the oracle with iqga

TEST_CASE("pareto: pride path --algo exact --objective iqga and --oracle give the front's iqga optimum",
          "[pareto][cli]") {
    const std::string map = std::string(PRIDE_SOURCE_DIR) + "/examples/maps/zhang2025-20x20.map";
    const GridMap m = grid::read_map(map);
    const auto expected = grid::iqga_optimum(m, {0, 19}, {19, 0});
    REQUIRE(expected.has_value());
    const auto exact = test::run_pride("path --map '" + map +
                                       "' --start 0,19 --goal 19,0 --algo exact --objective iqga --oracle --json");
    INFO(exact.err);
    REQUIRE(exact.status == 0);
    const auto j = test::parse_json(exact.out);
    CHECK(j.at("objective_value").number == Approx(*expected).epsilon(1e-15));
    CHECK(j.at("optimum").at("objective_value").number == Approx(*expected).epsilon(1e-15));
    CHECK(j.at("optimum").at("gap").number == 0.0);
    const auto ga = test::run_pride("path --map '" + map +
                                    "' --start 0,19 --goal 19,0 --algo ga --encoding chain --objective iqga --iters 5 "
                                    "--oracle --json");
    INFO(ga.err);
    REQUIRE(ga.status == 0);
    const auto g = test::parse_json(ga.out);
    CHECK(g.at("optimum").at("objective_value").number == Approx(*expected).epsilon(1e-15));
    REQUIRE(g.at("optimum").at("gap").is_number());
    CHECK(g.at("optimum").at("gap").number >= 0.0);  // relative to |optimum|: iqga's optimum is negative
    CHECK(g.at("objective_value").number >= *expected - 1e-12);
}

// ---------------------------------------------------------------------------------------------
// pride pareto

TEST_CASE("pareto: pride pareto prints the front as text and JSON and draws it", "[pareto][cli]") {
    const std::string map = std::string(PRIDE_SOURCE_DIR) + "/examples/maps/zhang2025-20x20.map";
    const GridMap m = grid::read_map(map);
    const auto front = grid::pareto_front(m, {0, 19}, {19, 0}, kLTA);
    const std::string args = "pareto --map '" + map + "' --start 0,19 --goal 19,0 --objectives length,angle,turns";
    const auto text = test::run_pride(args);
    INFO(text.err);
    REQUIRE(text.status == 0);
    const auto lines = test::lines_of(text.out);
    REQUIRE(lines.size() == front.size() + 1);  // a header, then one line per point
    CHECK(lines[0] == "length turns angle_penalty");
    const auto json_run = test::run_pride(args + " --json");
    REQUIRE(json_run.status == 0);
    const auto j = test::parse_json(json_run.out);
    CHECK(j.keys() == std::vector<std::string>{"objectives", "front"});
    REQUIRE(j.at("objectives").items.size() == 3);
    CHECK(j.at("objectives").items[0].text == "length");
    CHECK(j.at("objectives").items[1].text == "angle_penalty");
    CHECK(j.at("objectives").items[2].text == "turns");
    REQUIRE(j.at("front").items.size() == front.size());
    for (std::size_t i = 0; i < front.size(); ++i) {
        const auto& p = j.at("front").items[i];
        CHECK(p.keys() == std::vector<std::string>{"length", "turns", "angle_penalty", "path"});
        CHECK(p.at("length").number == front[i].length);
        CHECK(p.at("turns").number == front[i].turns);
        CHECK(p.at("angle_penalty").number == front[i].angle_penalty);
        Path path;
        for (const auto& c : p.at("path").items) path.push_back({int(c.items.at(0).number), int(c.items.at(1).number)});
        CHECK(path == front[i].path);
    }
    const auto two =
        test::run_pride("pareto --map '" + map + "' --start 0,19 --goal 19,0 --objectives length,turns --json");
    REQUIRE(two.status == 0);
    CHECK(test::parse_json(two.out).at("front").items.size() == grid::pareto_front(m, {0, 19}, {19, 0}, kLT).size());

    test::TempDir dir;
    const auto drawn = test::run_pride(args + " --png " + dir.file("f.png") + " --svg " + dir.file("f.svg"));
    INFO(drawn.err);
    REQUIRE(drawn.status == 0);
    CHECK(dir.entries() == std::vector<std::string>{"f.png", "f.svg"});
    CHECK(test::slurp(dir.file("f.png")).rfind("\x89PNG", 0) == 0);
    CHECK(test::slurp(dir.file("f.svg")).find("<svg") != std::string::npos);
}

TEST_CASE("pareto: pride pareto's --inflate and --corner-cutting are those of pride path", "[pareto][cli]") {
    test::TempDir dir;
    // 12 x 12, free but for a few cells well away from the corners (so that inflation by 1 keeps
    // start and goal free).
    std::vector<std::string> rows(12, std::string(12, '.'));
    for (const auto& [x, y] : std::vector<std::pair<int, int>>{{4, 4}, {5, 5}, {7, 3}, {3, 7}, {8, 8}, {6, 9}})
        rows[static_cast<std::size_t>(y)][static_cast<std::size_t>(x)] = '@';
    std::string text = "type octile\nheight 12\nwidth 12\nmap\n";
    for (const auto& r : rows) text += r + "\n";
    const std::string map = dir.write("m.map", text);
    const GridMap m = grid::read_map(map);
    grid::ParetoOptions cutting;
    cutting.corner_cutting = true;
    struct Case {
        std::string flags;
        GridMap map;
        grid::ParetoOptions options;
    };
    for (const Case& k : {Case{"--inflate 1", m.inflated(1), {}}, Case{"--corner-cutting", m, cutting}}) {
        INFO(k.flags);
        const auto front = grid::pareto_front(k.map, {0, 0}, {11, 11}, kLTA, k.options);
        if (k.flags == "--inflate 1") {  // the flag has an effect: the front differs from the plain map's
            const auto plain = grid::pareto_front(m, {0, 0}, {11, 11}, kLTA);
            bool differs = plain.size() != front.size();
            for (std::size_t i = 0; i < std::min(plain.size(), front.size()); ++i)
                differs = differs || plain[i].path != front[i].path;
            CHECK(differs);
        }
        const auto r = test::run_pride("pareto --map '" + map +
                                       "' --start 0,0 --goal 11,11 --objectives length,angle,turns --json " + k.flags);
        INFO(r.err);
        REQUIRE(r.status == 0);
        const auto j = test::parse_json(r.out);
        REQUIRE(j.at("front").items.size() == front.size());
        for (std::size_t i = 0; i < front.size(); ++i) {
            CHECK(j.at("front").items[i].at("length").number == front[i].length);
            CHECK(j.at("front").items[i].at("turns").number == front[i].turns);
            CHECK(j.at("front").items[i].at("angle_penalty").number == front[i].angle_penalty);
        }
    }
}

TEST_CASE("pareto: pride pareto's bad input: one line naming the flag, exit 2", "[pareto][cli]") {
    const std::string map = std::string(PRIDE_SOURCE_DIR) + "/examples/maps/zhang2025-20x20.map";
    const std::string base = "pareto --map '" + map + "' ";
    test::TempDir dir;
    const std::string walled = dir.write("walled.txt", "0 1 0\n0 1 0\n0 1 0\n");
    struct Bad {
        std::string args;
        std::vector<std::string> words;
    };
    for (const Bad& b : {
             Bad{base + "--start 0,19 --goal 19,0 --objectives length,speed", {"--objectives", "speed"}},
             Bad{base + "--start 0,19 --goal 19,0 --objectives length,turns,turns", {"--objectives", "twice"}},
             Bad{base + "--start 0,19 --goal 19,0 --objectives ''", {"--objectives"}},
             Bad{base + "--start 0,19 --goal 99,0 --objectives length,turns", {"--goal", "outside"}},
             Bad{base + "--start -1,19 --goal 19,0 --objectives length,turns", {"--start", "outside"}},
             Bad{base + "--start 0,1x --goal 19,0 --objectives length,turns", {"--start"}},
             Bad{"pareto --map '" + walled + "' --start 0,0 --goal 1,0 --objectives length,turns",
                 {"--goal", "blocked"}},
             Bad{"pareto --map '" + walled + "' --start 0,0 --goal 2,0 --objectives length,turns",
                 {"--goal", "cannot be reached"}},
             Bad{"pareto --map " + dir.file("none.map") + " --start 0,0 --goal 2,0 --objectives length,turns",
                 {"none.map"}},
             Bad{base + "--start 0,19 --goal 19,0 --objectives length,turns --png /nonexistent/dir/f.png",
                 {"/nonexistent/dir/f.png"}},
             Bad{base + "--start 0,19 --goal 19,0", {"--objectives"}},
         }) {
        INFO(b.args);
        test::check_input_error(test::run_pride(b.args), b.words);
    }
}

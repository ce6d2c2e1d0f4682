// The `line` and `free` decoders (LoopFreeChain fed by the connectors' segments) against
// the algorithm they replaced, kept here as the reference: the raw chain of every join stored as
// cells, then cut_loops over the whole of it. Same cells in the same order, same violations, same
// objective values to the bit, on random maps (dense ones, narrow ones, start and goal in corners)
// and random genotypes.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <unordered_map>
#include <utility>
#include <vector>

#include "framework/random.hpp"
#include "grid_support.hpp"
#include "problems/grid/connectors.hpp"
#include "problems/grid/encodings.hpp"
#include "problems/grid/objectives.hpp"
#include "problems/grid/path.hpp"
#include "problems/grid/planners/astar.hpp"

using namespace pride::grid;
using pride::Rng;
using pride::test::below;

namespace {
namespace reference {

struct PenaltyConnector {
    void join(const GridMap& map, Cell a, Cell b, Path& path, int& violations, bool corner_cutting) {
        const std::size_t first = path.size();
        append_line(a, b, path);
        violations += count_violations(map, path, first, corner_cutting);
    }
};

class RepairConnector {
  public:
    void join(const GridMap& map, Cell a, Cell b, Path& path, int& violations, bool corner_cutting) {
        if (line_is_free(map, a, b, corner_cutting)) {
            append_line(a, b, path);
            return;
        }
        const std::uint64_t key = (static_cast<std::uint64_t>(map.index(a)) << 32) | map.index(b);
        if (const auto hit = known_.find(key); hit != known_.end()) {
            path.insert(path.end(), detours_.begin() + static_cast<std::ptrdiff_t>(hit->second.first),
                        detours_.begin() + static_cast<std::ptrdiff_t>(hit->second.first + hit->second.second));
            return;
        }
        const std::size_t first = path.size();
        const int before = violations;
        search(map, a, b, path, violations, corner_cutting);
        if (violations != before) return;
        known_.emplace(key, std::make_pair(detours_.size(), path.size() - first));
        detours_.insert(detours_.end(), path.begin() + static_cast<std::ptrdiff_t>(first), path.end());
    }

  private:
    void search(const GridMap& map, Cell a, Cell b, Path& path, int& violations, bool corner_cutting) {
        for (int margin = 2;; margin *= 2) {
            const Window w{std::max(0, std::min(a.x, b.x) - margin), std::max(0, std::min(a.y, b.y) - margin),
                           std::min(map.width() - 1, std::max(a.x, b.x) + margin),
                           std::min(map.height() - 1, std::max(a.y, b.y) + margin)};
            if (astar_.search(map, a, b, &detour_, &w, corner_cutting) >= 0.0) {
                path.insert(path.end(), detour_.begin() + 1, detour_.end());
                return;
            }
            if (w.x0 == 0 && w.y0 == 0 && w.x1 == map.width() - 1 && w.y1 == map.height() - 1) break;
        }
        PenaltyConnector{}.join(map, a, b, path, violations, corner_cutting);
    }

    AStar astar_;
    Path detour_;
    std::unordered_map<std::uint64_t, std::pair<std::size_t, std::size_t>> known_;
    Path detours_;
};

/// join_waypoints as it was: the raw chain, then cut_loops, then the recount.
template <class Objective, class Connector, class Waypoint>
DecodedPath decode(const GridProblem<Objective>& p, int count, Waypoint&& waypoint, Connector& connector,
                   std::vector<std::int32_t>& seen) {
    DecodedPath out;
    out.path.push_back(p.start());
    Cell previous = p.start();
    for (int k = 0; k < count; ++k) {
        const Cell w = waypoint(k);
        connector.join(p.map(), previous, w, out.path, out.violations, p.corner_cutting());
        previous = w;
    }
    connector.join(p.map(), previous, p.goal(), out.path, out.violations, p.corner_cutting());
    // cut_loops itself is unchanged (the chain operators still use it), so the live one serves.
    cut_loops(out.path, p.map(), seen);
    if (out.violations > 0) out.violations = count_violations(p.map(), out.path, 1, p.corner_cutting());
    return out;
}

}  // namespace reference

/// A random map: `w` x `h`, each cell blocked with probability `density`.
std::shared_ptr<const GridMap> random_map(Rng& rng, int w, int h, double density) {
    std::vector<std::uint8_t> blocked(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
    for (auto& b : blocked) b = rng.uniform() < density ? 1 : 0;
    return std::make_shared<const GridMap>(w, h, std::move(blocked), "random");
}

/// Start and goal: in opposite corners (cleared if blocked) every third time, else random free
/// cells; false when the goal is not reachable.
bool end_points(Rng& rng, const GridMap& map, bool corner_cutting, int round, Cell& s, Cell& g) {
    const int w = map.width(), h = map.height();
    if (round % 3 == 0) {
        const int corner = below(rng, 4);
        s = {corner & 1 ? w - 1 : 0, corner & 2 ? h - 1 : 0};
        g = {w - 1 - s.x, h - 1 - s.y};
    } else {
        s = {below(rng, w), below(rng, h)};
        g = {below(rng, w), below(rng, h)};
    }
    if (!map.free(s) || !map.free(g) || s == g) return false;
    return reachable_from(map, s, corner_cutting)[map.index(g)] != 0;
}

/// Genotypes in the box, with now and then a gene on a bound, outside it or NaN.
std::vector<std::vector<double>> genotypes(Rng& rng, std::span<const double> lower, std::span<const double> upper,
                                           int n) {
    std::vector<std::vector<double>> out;
    for (int i = 0; i < n; ++i) {
        std::vector<double> x(lower.size());
        for (std::size_t j = 0; j < x.size(); ++j) {
            x[j] = rng.uniform(lower[j], upper[j]);
            const double u = rng.uniform();
            if (u < 0.03)
                x[j] = lower[j];
            else if (u < 0.06)
                x[j] = upper[j];
            else if (u < 0.07)
                x[j] = upper[j] + 3.0;
            else if (u < 0.08)
                x[j] = std::numeric_limits<double>::quiet_NaN();
        }
        out.push_back(std::move(x));
    }
    // Repeats (the second decode of a genotype meets only remembered detours), in another order.
    for (int i = 0; i < n / 2; ++i) out.push_back(out[static_cast<std::size_t>(below(rng, n))]);
    return out;
}

struct Counts {
    long decodes = 0, cells = 0, illegal = 0, problems = 0;
};

/// Every genotype decoded by `encoding` and by the reference with `connector`: the same chain,
/// cell for cell, the same violations and the same value under several objectives, to the bit.
template <class Encoding, class RefConnector, class Waypoint>
void compare(const GridProblem<LinearObjective>& problem, Encoding& encoding, RefConnector connector, int count,
             Waypoint&& waypoint, Rng& rng, Counts& counts) {
    std::vector<std::int32_t> seen;
    const GridProblem<IqgaObjective> iqga(problem.shared_map(), problem.start(), problem.goal(), {},
                                          problem.corner_cutting());
    const GridProblem<WeightedObjective> weighted(problem.shared_map(), problem.start(), problem.goal(),
                                                  {1.0, 0.7, 0.1}, problem.corner_cutting());
    for (const auto& x : genotypes(rng, encoding.lower(problem), encoding.upper(problem), 12)) {
        const DecodedPath expected = reference::decode(
            problem, count, [&](int k) { return waypoint(x, k); }, connector, seen);
        const DecodedPath& got = encoding.decode(problem, x);
        INFO("map " << problem.map().width() << "x" << problem.map().height() << " start (" << problem.start().x << ","
                    << problem.start().y << ") goal (" << problem.goal().x << "," << problem.goal().y
                    << ") corner cutting " << problem.corner_cutting());
        REQUIRE(got.path.size() == expected.path.size());
        for (std::size_t i = 0; i < got.path.size(); ++i) {
            INFO("cell " << i);
            REQUIRE(got.path[i] == expected.path[i]);
        }
        CHECK(got.violations == expected.violations);
        CHECK(problem.evaluate(got) == problem.evaluate(expected));
        CHECK(iqga.evaluate(got) == iqga.evaluate(expected));
        CHECK(weighted.evaluate(got) == weighted.evaluate(expected));
        ++counts.decodes;
        counts.cells += static_cast<long>(got.path.size());
        counts.illegal += got.violations > 0;
    }
}

/// One random instance: line and free encodings, each with the repair, penalty and run-time
/// selectable connectors, against the reference.
void compare_instance(const std::shared_ptr<const GridMap>& map, Cell s, Cell g, bool corner_cutting,
                      const LinearObjective& objective, Rng& rng, Counts& counts) {
    const GridProblem<LinearObjective> problem(map, s, g, objective, corner_cutting);
    ++counts.problems;
    const bool line_fits = std::max(std::abs(g.x - s.x), std::abs(g.y - s.y)) >= 2;
    if (line_fits) {
        LineEncoding<RepairConnector> repair(problem);
        const auto wp = [&](const std::vector<double>& x, int k) { return repair.waypoint(x, k); };
        const int count = static_cast<int>(repair.dimension(problem));
        compare(problem, repair, reference::RepairConnector{}, count, wp, rng, counts);
        LineEncoding<PenaltyConnector> penalty(problem);
        compare(problem, penalty, reference::PenaltyConnector{}, count, wp, rng, counts);
        LineEncoding<SelectableConnector> selectable(problem, SelectableConnector(SelectableConnector::Kind::repair));
        compare(problem, selectable, reference::RepairConnector{}, count, wp, rng, counts);
        LineEncoding<SelectableConnector> selectable_penalty(problem,
                                                             SelectableConnector(SelectableConnector::Kind::penalty));
        compare(problem, selectable_penalty, reference::PenaltyConnector{}, count, wp, rng, counts);
    }
    const int k = 1 + below(rng, 8);
    FreeEncoding<RepairConnector> repair(problem, k);
    const auto wp = [&](const std::vector<double>& x, int i) { return repair.waypoint(problem, x, i); };
    compare(problem, repair, reference::RepairConnector{}, k, wp, rng, counts);
    FreeEncoding<PenaltyConnector> penalty(problem, k);
    compare(problem, penalty, reference::PenaltyConnector{}, k, wp, rng, counts);
}

}  // namespace

TEST_CASE("line and free decoders give the reference decoder's chains on random maps", "[grid][encoding][decode]") {
    Rng rng(15015);
    Counts counts;
    const LinearObjective objectives[] = {LinearObjective::of(CellsObjective{}), LinearObjective::of(LengthObjective{}),
                                          LinearObjective::of(HswoaObjective{})};
    for (int round = 0; counts.problems < 240 && round < 20000; ++round) {
        // Mostly small maps, some one or two cells wide or high, densities up to 45 %.
        int w = 1 + below(rng, 30), h = 1 + below(rng, 30);
        if (round % 7 == 0) w = 1 + below(rng, 2);
        if (round % 11 == 0) h = 1 + below(rng, 2);
        const double density = round % 5 == 0 ? 0.3 + 0.15 * rng.uniform() : 0.3 * rng.uniform();
        const auto map = random_map(rng, w, h, density);
        const bool cc = round % 4 == 3;
        Cell s, g;
        if (!end_points(rng, *map, cc, round, s, g)) continue;
        compare_instance(map, s, g, cc, objectives[round % 3], rng, counts);
    }
    CHECK(counts.problems >= 240);
    CHECK(counts.decodes > 10000);
    CHECK(counts.illegal > 500);  // the penalty decoders meet blocked cells
}

TEST_CASE("line and free decoders give the reference decoder's chains on 100x100 maps", "[grid][encoding][decode]") {
    Rng rng(15016);
    Counts counts;
    for (const double density : {0.0, 0.2, 0.3, 0.4}) {
        for (int round = 0, found = 0; found < 2 && round < 200; ++round) {
            const auto map = random_map(rng, 100, 100, density);
            const bool cc = round % 2 == 1;
            Cell s, g;
            if (!end_points(rng, *map, cc, found == 0 ? 0 : 1, s, g)) continue;
            compare_instance(map, s, g, cc, LinearObjective::of(CellsObjective{}), rng, counts);
            ++found;
        }
    }
    CHECK(counts.problems == 8);
    CHECK(counts.cells > 10 * counts.decodes);
}

TEST_CASE("LoopFreeChain gives cut_loops' result on random chains of random segments", "[grid][path]") {
    // Segments are random walks, so they close loops with the chain in every way: back to the
    // start, over several segments, nested; every other round they may also revisit their own
    // cells (LoopFreeChain does not need segments without repeats), and some are empty.
    Rng rng(15017);
    LoopFreeChain reused;  // one chain for every round too: nothing of a round may leak into the next
    for (int round = 0; round < 600; ++round) {
        const int w = 3 + below(rng, 12), h = 1 + below(rng, 12);
        const GridMap map(w, h, std::vector<std::uint8_t>(static_cast<std::size_t>(w) * h, 0), "open");
        const bool repeats = round % 2 == 1;
        Cell c{below(rng, w), below(rng, h)};
        Path raw{c};
        LoopFreeChain chain;
        chain.begin(map, static_cast<std::uint32_t>(map.index(c)));
        reused.begin(map, static_cast<std::uint32_t>(map.index(c)));
        std::vector<std::int32_t> seen;
        for (int seg = 0, n = 1 + below(rng, 12); seg < n; ++seg) {
            std::vector<std::uint32_t> cells;
            std::vector<std::uint8_t> used(map.size(), 0);
            for (int step = 0, len = below(rng, 3 * w); step < len; ++step) {
                const int d = below(rng, 8);
                const Cell next{c.x + kDx[d], c.y + kDy[d]};
                if (!map.inside(next) || (!repeats && used[map.index(next)])) continue;
                used[map.index(next)] = 1;
                cells.push_back(static_cast<std::uint32_t>(map.index(next)));
                raw.push_back(next);
                c = next;
            }
            chain.append(cells);
            reused.append(cells);
        }
        cut_loops(raw, map, seen);
        Path got;
        chain.to_path(got);
        REQUIRE(got == raw);
        reused.to_path(got);
        REQUIRE(got == raw);
        // Reused for a second chain without clearing by hand.
        chain.begin(map, static_cast<std::uint32_t>(map.index(raw.back())));
        chain.to_path(got);
        CHECK(got == Path{raw.back()});
    }
}

TEST_CASE("LoopFreeChain: a chain that comes back to its start keeps only the start", "[grid][path]") {
    const GridMap map(4, 4, std::vector<std::uint8_t>(16, 0), "open");
    LoopFreeChain chain;
    chain.begin(map, 5);
    const std::vector<std::uint32_t> out{6, 10, 9}, back{5}, on{6, 7};
    chain.append(out);
    chain.append(back);
    Path got;
    chain.to_path(got);
    CHECK(got == Path{{1, 1}});
    chain.append(on);
    chain.to_path(got);  // to_path does not end the chain: appending goes on
    CHECK(got == (Path{{1, 1}, {2, 1}, {3, 1}}));
}

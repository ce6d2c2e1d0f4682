// The `line` encoding's snap table, built in linear time per line, against its definition: the
// reachable coordinate of the same line nearest to the rounded gene, ties to the one nearer the
// straight start-goal line, then to the lower coordinate (problems/grid/encodings.hpp).
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <vector>

#include "grid_support.hpp"
#include "problems/grid/encodings.hpp"
#include "problems/grid/objectives.hpp"

using namespace pride::grid;
using pride::test::random_instances;

namespace {

/// The snapped cross coordinate by the definition, searching the whole line.
int snapped(const GridProblem<CellsObjective>& p, bool rows, int line, double ideal, int c) {
    const int extent = rows ? p.map().width() : p.map().height();
    int best = -1;
    double best_key = std::numeric_limits<double>::infinity(), best_tie = best_key;
    for (int o = 0; o < extent; ++o) {
        if (!p.reachable(rows ? Cell{o, line} : Cell{line, o})) continue;
        const double key = std::abs(o - c), tie = std::abs(o - ideal);
        if (key < best_key || (key == best_key && tie < best_tie)) {
            best = o;
            best_key = key;
            best_tie = tie;
        }
    }
    return best;
}

}  // namespace

TEST_CASE("line encoding: every gene snaps to the nearest reachable cell of its line, as defined", "[grid][encoding]") {
    int lines = 0, ties = 0;
    for (const auto& in : random_instances(4711, 200)) {
        const Cell s = in.start, g = in.goal;
        const bool rows = std::abs(g.y - s.y) >= std::abs(g.x - s.x);
        const int from = rows ? s.y : s.x, to = rows ? g.y : g.x;
        if (std::abs(to - from) < 2) continue;
        const GridProblem<CellsObjective> problem(in.map, s, g, {}, in.corner_cutting);
        const LineEncoding<RepairConnector> line(problem);
        const int count = static_cast<int>(line.dimension(problem));
        const int step = to >= from ? 1 : -1, extent = rows ? in.map->width() : in.map->height();
        std::vector<double> genotype(static_cast<std::size_t>(count), 0.0);
        for (int k = 0; k < count; ++k) {
            const int at = from + step * (k + 1);
            const double ideal = rows ? s.x + static_cast<double>(at - from) / (to - from) * (g.x - s.x)
                                      : s.y + static_cast<double>(at - from) / (to - from) * (g.y - s.y);
            for (int c = 0; c < extent; ++c) {
                genotype[static_cast<std::size_t>(k)] = c;
                const int want = snapped(problem, rows, at, ideal, c);
                const Cell got = line.waypoint(genotype, k);
                REQUIRE(got == (rows ? Cell{want, at} : Cell{at, want}));
                // A tie in distance decided by the straight line or by the lower coordinate.
                ties += c - 1 >= 0 && c + 1 < extent && !problem.reachable(rows ? Cell{c, at} : Cell{at, c}) &&
                        problem.reachable(rows ? Cell{c - 1, at} : Cell{at, c - 1}) &&
                        problem.reachable(rows ? Cell{c + 1, at} : Cell{at, c + 1});
            }
            ++lines;
        }
    }
    CHECK(lines > 1000);
    CHECK(ties > 50);  // the tie rule is exercised, not only the plain nearest cell
}

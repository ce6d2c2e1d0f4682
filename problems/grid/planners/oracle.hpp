#pragma once
// The exact optimum of docs/grid.md ("Exact optimum (the oracle)") for every additive
// objective (cells, length, weighted, hswoa; not iqga): such an objective is
//     start_cost() + sum over steps of step_cost(d) + sum over turns of turn_cost(k)
// (objectives.hpp), so its optimum is a shortest path over the states (cell, direction of the last
// step), at most 9 * W * H of them (8 directions, plus "no step yet" for the start). Moves are the
// legal steps of map.hpp (8-connected, no corner cutting unless asked); a step in direction e from
// a state whose last direction is d != e adds turn_cost(turn_steps(d, e)).
//
// An objective may instead give the cost of each step from the previous direction, edge_cost(previous,
// d) with previous -1 for the first step (a user's per-step cost): the same search over the same
// states, with that cost on each edge.
//
// The search is A* over those states with a consistent heuristic that ignores turns (the cheapest
// way to cover the remaining dx, dy with the objective's cheapest orthogonal and diagonal steps),
// which is Dijkstra when `use_heuristic` is false; both return the same optimum. Flat arrays
// indexed by state, a binary heap with lazy deletion and generation stamps: one Oracle serves many
// queries on one map (or several, resizing once) and allocates nothing per node after its first
// query on the largest map.
//
// The optimum over walks (cells may repeat) equals the optimum over simple paths for these
// objectives with non-negative weights, so the oracle is the exact optimum of the chains the
// encodings produce (which cut loops): tests/test_grid_search.cpp gives the argument.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "problems/grid/map.hpp"
#include "problems/grid/path.hpp"
#include "problems/grid/search_arrays.hpp"

namespace pride::grid {

class Oracle {
  public:
    /// Guide the search towards the goal with a consistent lower bound (A*); false: plain Dijkstra.
    bool use_heuristic = true;

    /// The optimal value of `objective` over legal paths from s to g, or -1 when g cannot be
    /// reached (or s or g is outside or blocked). With `out`, an optimal path (s first, g last)
    /// replaces its contents; it is left untouched when there is none.
    ///
    /// Ties: the open list pops the smallest f = g + h first and, among equal f, the smallest
    /// state index (cell index * 9 + last direction, 8 = no step yet); a state keeps the first
    /// parent that reached it with its final cost (only a strictly smaller cost replaces it). The
    /// path returned is therefore a deterministic function of the map, s, g and the objective.
    template <class Objective>
    requires(Objective::additive) double solve(const GridMap& map, Cell s, Cell g, const Objective& objective,
                                               Path* out = nullptr, bool corner_cutting = false) {
        if (!map.free(s) || !map.free(g)) return -1.0;
        prepare(map.size());
        constexpr bool per_edge = requires {
            objective.edge_cost(-1, 0);
        };
        double step[8] = {}, turn[5] = {0.0, 0.0, 0.0, 0.0, 0.0}, edge[kDirs][8] = {};
        if constexpr (per_edge) {
            for (std::uint32_t last = 0; last < kDirs; ++last)
                for (int d = 0; d < 8; ++d)
                    edge[last][d] = objective.edge_cost(last == kNone ? -1 : static_cast<int>(last), d);
        } else {
            for (int d = 0; d < 8; ++d) step[d] = objective.step_cost(d);
            for (int k = 1; k <= 4; ++k) turn[k] = objective.turn_cost(k);
        }
        // Heuristic: orthogonal steps cost at least a, diagonal ones at least b; turns cost >= 0
        // (with per-edge costs: the least of each kind over every previous direction).
        double a = per_edge ? edge[0][0] : step[0], b = per_edge ? edge[0][1] : step[1];
        for (int d = 0; d < 8; ++d)
            for (std::uint32_t last = 0; last < (per_edge ? kDirs : 1); ++last) {
                const double c = per_edge ? edge[last][d] : step[d];
                (d % 2 == 0 ? a : b) = std::min(d % 2 == 0 ? a : b, c);
            }
        const double per_minor = std::min(b, 2.0 * a), per_excess = std::min(a, b);
        const bool guided = use_heuristic && per_minor > 0.0 && per_excess > 0.0;
        const auto h = [&](Cell c) {
            if (!guided) return 0.0;
            const int dx = std::abs(c.x - g.x), dy = std::abs(c.y - g.y);
            return per_minor * std::min(dx, dy) + per_excess * (std::max(dx, dy) - std::min(dx, dy));
        };

        const auto goal = static_cast<std::uint32_t>(map.index(g));
        const std::uint32_t start = static_cast<std::uint32_t>(map.index(s)) * kDirs + kNone;
        open(start, objective.start_cost(), objective.start_cost() + h(s), start);
        while (!heap_.empty()) {
            std::pop_heap(heap_.begin(), heap_.end(), Later{});
            const Node node = heap_.back();
            heap_.pop_back();
            if (arrays_.closed[node.state] == arrays_.generation) continue;  // a stale entry
            arrays_.closed[node.state] = arrays_.generation;
            ++expansions_;
            const std::uint32_t index = node.state / kDirs;
            const int last = static_cast<int>(node.state % kDirs);
            const double cost = arrays_.g[node.state];
            if (index == goal) {
                if (out) trace(map, start, node.state, *out);
                return cost;
            }
            const Cell c = map.cell(index);
            for (unsigned m = map.moves(index, corner_cutting); m != 0; m &= m - 1) {
                const int d = std::countr_zero(m);
                const auto ni = static_cast<std::uint32_t>(static_cast<std::ptrdiff_t>(index) + map.offset(d));
                const std::uint32_t next = ni * kDirs + static_cast<std::uint32_t>(d);
                if (arrays_.closed[next] == arrays_.generation) continue;
                double ng = 0.0;
                if constexpr (per_edge) {
                    ng = cost + edge[last][d];
                } else {
                    ng = cost + step[d];
                    if (last != kNone && last != d) ng += turn[turn_steps(last, d)];
                }
                if (arrays_.seen[next] == arrays_.generation && arrays_.g[next] <= ng) continue;
                open(next, ng, ng + h(Cell{c.x + kDx[d], c.y + kDy[d]}), node.state);
            }
        }
        return -1.0;
    }

    /// States expanded (taken off the open list) since construction.
    std::int64_t expansions() const noexcept { return expansions_; }

  private:
    static constexpr std::uint32_t kDirs = 9;  // 8 directions and "no step yet"
    static constexpr int kNone = 8;

    struct Node {
        double f;
        std::uint32_t state;
    };
    /// Heap order: smallest f first, then the smallest state index.
    struct Later {
        bool operator()(const Node& x, const Node& y) const noexcept {
            return x.f > y.f || (x.f == y.f && x.state > y.state);
        }
    };

    void prepare(std::size_t cells) {
        arrays_.prepare(cells * kDirs);
        heap_.clear();
    }

    void open(std::uint32_t state, double g, double f, std::uint32_t parent) {
        arrays_.seen[state] = arrays_.generation;
        arrays_.g[state] = g;
        arrays_.parent[state] = parent;
        heap_.push_back({f, state});
        std::push_heap(heap_.begin(), heap_.end(), Later{});
    }

    void trace(const GridMap& map, std::uint32_t start, std::uint32_t state, Path& out) const {
        out.clear();
        for (std::uint32_t i = state;; i = arrays_.parent[i]) {
            out.push_back(map.cell(i / kDirs));
            if (i == start) break;
        }
        std::reverse(out.begin(), out.end());
    }

    SearchArrays arrays_;
    std::vector<Node> heap_;
    std::int64_t expansions_ = 0;
};

}  // namespace pride::grid

#pragma once
// A* with the octile heuristic on a GridMap: 8-connected, step costs 1 and sqrt(2), no corner
// cutting by default (the rule behind the Moving AI optimal lengths). Flat arrays indexed by cell,
// a binary heap with lazy deletion, and generation stamps, so one AStar serves many queries on one
// map (or on several, resizing once) without clearing or allocating per node.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "problems/grid/map.hpp"
#include "problems/grid/path.hpp"

namespace pride::grid {

/// The octile distance: the shortest 8-connected length on an empty grid.
inline double octile(Cell a, Cell b) noexcept {
    const int dx = std::abs(a.x - b.x), dy = std::abs(a.y - b.y);
    return std::max(dx, dy) + (kSqrt2 - 1.0) * std::min(dx, dy);
}

/// A rectangle of cells, both corners included; searches may be confined to one.
struct Window {
    int x0, y0, x1, y1;
    bool contains(Cell c) const noexcept { return c.x >= x0 && c.x <= x1 && c.y >= y0 && c.y <= y1; }
};

class AStar {
public:
    /// The optimal length from s to g, or -1 when g cannot be reached (inside `window` when given).
    /// With `out`, the path itself (s first, g last) replaces its contents.
    double search(const GridMap& map, Cell s, Cell g, Path* out = nullptr, const Window* window = nullptr,
                  bool corner_cutting = false) {
        if (!map.free(s) || !map.free(g)) return -1.0;
        prepare(map.size());
        const Window all{0, 0, map.width() - 1, map.height() - 1};
        const Window w = window ? *window : all;
        if (!w.contains(s) || !w.contains(g)) return -1.0;
        const auto start = static_cast<std::uint32_t>(map.index(s));
        const auto goal = static_cast<std::uint32_t>(map.index(g));
        open(start, 0.0, octile(s, g), start);
        while (!heap_.empty()) {
            std::pop_heap(heap_.begin(), heap_.end(), Later{});
            const Node node = heap_.back();
            heap_.pop_back();
            if (closed_[node.index] == generation_) continue;  // a stale entry
            closed_[node.index] = generation_;
            ++expansions_;
            if (node.index == goal) {
                if (out) trace(map, start, goal, *out);
                return node.g;
            }
            const Cell c = map.cell(node.index);
            for (unsigned m = map.moves(node.index, corner_cutting); m != 0; m &= m - 1) {
                const int d = std::countr_zero(m);
                const Cell n{c.x + kDx[d], c.y + kDy[d]};
                if (window && !w.contains(n)) continue;
                const auto ni = static_cast<std::uint32_t>(static_cast<std::ptrdiff_t>(node.index) + map.offset(d));
                if (closed_[ni] == generation_) continue;
                const double ng = node.g + (is_diagonal(d) ? kSqrt2 : 1.0);
                if (seen_[ni] == generation_ && g_[ni] <= ng) continue;
                open(ni, ng, ng + octile(n, g), node.index);
            }
        }
        return -1.0;
    }

    /// Nodes expanded (taken off the open list) since construction.
    std::int64_t expansions() const noexcept { return expansions_; }

private:
    struct Node {
        double f;
        double g;
        std::uint32_t index;
    };
    /// Heap order: smallest f first; among equal f the larger g (deeper node) first, which
    /// expands fewer nodes on open ground.
    struct Later {
        bool operator()(const Node& a, const Node& b) const noexcept { return a.f > b.f || (a.f == b.f && a.g < b.g); }
    };

    void prepare(std::size_t cells) {
        if (g_.size() != cells) {
            g_.assign(cells, 0.0);
            parent_.assign(cells, 0);
            seen_.assign(cells, 0);
            closed_.assign(cells, 0);
            generation_ = 0;
        }
        if (++generation_ == 0) {  // wrapped: clear the stamps once every 2^32 queries
            std::fill(seen_.begin(), seen_.end(), 0);
            std::fill(closed_.begin(), closed_.end(), 0);
            generation_ = 1;
        }
        heap_.clear();
    }

    void open(std::uint32_t index, double g, double f, std::uint32_t parent) {
        seen_[index] = generation_;
        g_[index] = g;
        parent_[index] = parent;
        heap_.push_back({f, g, index});
        std::push_heap(heap_.begin(), heap_.end(), Later{});
    }

    void trace(const GridMap& map, std::uint32_t start, std::uint32_t goal, Path& out) const {
        out.clear();
        for (std::uint32_t i = goal;; i = parent_[i]) {
            out.push_back(map.cell(i));
            if (i == start) break;
        }
        std::reverse(out.begin(), out.end());
    }

    std::vector<double> g_;
    std::vector<std::uint32_t> parent_;
    std::vector<std::uint32_t> seen_, closed_;  // generation stamps
    std::uint32_t generation_ = 0;
    std::vector<Node> heap_;
    std::int64_t expansions_ = 0;
};

}  // namespace pride::grid

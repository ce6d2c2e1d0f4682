#pragma once
// Theta* (Nash, Daniel, Koenig and Felner 2007, "Theta*: Any-Angle Path Planning on Grids", AAAI)
// and Lazy Theta* (Nash, Koenig and Tovey 2010, "Lazy Theta*: Any-Angle Path Planning and Path
// Length Analysis in 3D", AAAI): A* on the 8-connected grid (legal steps of map.hpp, no corner
// cutting) in which a node may take its parent's parent as parent when that one sees it, so that
// paths are polylines between cell centres.
//
// Vertices are cell centres here, not the cell corners of Nash et al., and line of sight is the
// exact segment test of any_angle.hpp (segment_is_free between the two centres): a segment through
// no blocked square's interior, along no edge between two blocked cells, through no grid point
// between two diagonally touching blocked cells. Every legal grid step passes it, so a Theta*
// path is a free polyline, at least the exact any-angle length (AnyAngleOracle) and, with the
// Euclidean heuristic (consistent), at most A*'s length: each node's g is at most its best grid
// neighbour's g plus the step (the parent's parent is taken only when that is shorter).
//
// Theta* tests line of sight for each neighbour update (path 2 of the paper, from the expanded
// node's parent); Lazy Theta* assumes it when updating and tests it once per expansion (SetVertex),
// falling back to the best closed grid neighbour when the assumption was wrong. Both count their
// tests. Ties between equal f go to the larger g. Flat arrays with generation stamps and a binary
// heap reused across queries: no allocation per query once grown.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "framework/error.hpp"
#include "problems/grid/map.hpp"
#include "problems/grid/path.hpp"
#include "problems/grid/planners/any_angle.hpp"
#include "problems/grid/search_arrays.hpp"

namespace pride::grid {

class ThetaStar {
  public:
    /// `lazy`: Lazy Theta* (2010); otherwise Theta* (2007).
    explicit ThetaStar(bool lazy = false) : lazy_(lazy) {}

    /// The length of the polyline found from the centre of s to the centre of g, or -1 when g
    /// cannot be reached. With `out`, its vertices (cells whose centres are the polyline's points,
    /// s first, g last) replace its contents. s or g outside or blocked: InputError.
    double search(const GridMap& map, Cell s, Cell g, std::vector<Cell>* out = nullptr) {
        require(map.free(s), "start",
                "(" + std::to_string(s.x) + "," + std::to_string(s.y) + ") is blocked or outside");
        require(map.free(g), "goal", "(" + std::to_string(g.x) + "," + std::to_string(g.y) + ") is blocked or outside");
        arrays_.prepare(map.size());
        heap_.clear();
        const auto width = static_cast<std::uint32_t>(map.width());
        const auto cell_of = [width](std::uint32_t i) {
            const std::uint32_t y = i / width;
            return Cell{static_cast<int>(i - y * width), static_cast<int>(y)};
        };
        const auto dist = [](Cell a, Cell b) {  // sqrt, not hypot: exact on these integers, and faster
            const double dx = a.x - b.x, dy = a.y - b.y;
            return std::sqrt(dx * dx + dy * dy);
        };
        const auto sees = [&](Cell a, Cell b) {
            ++los_checks_;
            return segment_is_free(map, centre_of(a), centre_of(b));
        };
        Record* const rec = arrays_.records.data();
        const std::uint32_t open = arrays_.open, closed = arrays_.closed();
        const auto start = static_cast<std::uint32_t>(map.index(s)), goal = static_cast<std::uint32_t>(map.index(g));
        rec[start] = {0.0, start, open};
        push(dist(s, g), 0.0, start);
        std::ptrdiff_t offset[8];
        for (int d = 0; d < 8; ++d) offset[d] = map.offset(d);
        while (!heap_.empty()) {
            std::pop_heap(heap_.begin(), heap_.end(), After{});
            const Entry e = heap_.back();
            heap_.pop_back();
            const std::uint32_t x = e.index;
            if (rec[x].stamp == closed || e.g != rec[x].g) continue;  // stale
            const Cell cx = cell_of(x);
            if (lazy_ && rec[x].parent != x && !sees(cell_of(rec[x].parent), cx)) {
                // SetVertex: the assumed line of sight fails; the best closed grid neighbour instead
                // (one exists: the one that opened x).
                double best = std::numeric_limits<double>::infinity();
                std::uint32_t parent = x;
                for (unsigned m = map.moves(x); m != 0; m &= m - 1) {
                    const int d = std::countr_zero(m);
                    const auto n = static_cast<std::uint32_t>(static_cast<std::ptrdiff_t>(x) + offset[d]);
                    if (rec[n].stamp != closed) continue;
                    const double v = rec[n].g + (is_diagonal(d) ? kSqrt2 : 1.0);
                    if (v < best) best = v, parent = n;
                }
                rec[x].g = best;
                rec[x].parent = parent;
            }
            rec[x].stamp = closed;
            ++expansions_;
            if (x == goal) {
                if (out) trace(start, goal, cell_of, *out);
                return rec[x].g;
            }
            const std::uint32_t px = rec[x].parent;
            const Cell cp = cell_of(px);
            const double gp = rec[px].g, gx = rec[x].g;
            for (unsigned m = map.moves(x); m != 0; m &= m - 1) {
                const int d = std::countr_zero(m);
                const auto n = static_cast<std::uint32_t>(static_cast<std::ptrdiff_t>(x) + offset[d]);
                Record& r = rec[n];
                if (r.stamp == closed) continue;
                const bool seen = r.stamp == open;
                const Cell cn = cell_of(n);
                // Path 2 (from x's parent) first; Theta* tests its line of sight, Lazy Theta*
                // assumes it. The start is its own parent: its neighbours are plain grid steps.
                double ng;
                std::uint32_t parent;
                if (px != x && (lazy_ || sees(cp, cn))) {
                    ng = gp + dist(cp, cn);
                    parent = px;
                } else {
                    ng = gx + (is_diagonal(d) ? kSqrt2 : 1.0);
                    parent = x;
                }
                if (seen && r.g <= ng) continue;
                r = {ng, parent, open};
                push(ng + dist(cn, g), ng, n);
            }
        }
        return -1.0;
    }

    std::int64_t expansions() const noexcept { return expansions_; }
    /// Line-of-sight tests made since construction.
    std::int64_t los_checks() const noexcept { return los_checks_; }

  private:
    using Record = PackedSearchArrays::Record;
    struct Entry {
        double f, g;
        std::uint32_t index;
    };
    /// a is popped after b: larger f, or equal f and smaller g.
    struct After {
        bool operator()(const Entry& a, const Entry& b) const noexcept { return a.f != b.f ? a.f > b.f : a.g < b.g; }
    };
    void push(double f, double g, std::uint32_t index) {
        heap_.push_back({f, g, index});
        std::push_heap(heap_.begin(), heap_.end(), After{});
    }
    template <class CellOf>
    void trace(std::uint32_t start, std::uint32_t goal, const CellOf& cell_of, std::vector<Cell>& out) const {
        out.clear();
        for (std::uint32_t i = goal;; i = arrays_.records[i].parent) {
            out.push_back(cell_of(i));
            if (i == start) break;
        }
        std::reverse(out.begin(), out.end());
    }

    bool lazy_;
    PackedSearchArrays arrays_;
    std::vector<Entry> heap_;
    std::int64_t expansions_ = 0, los_checks_ = 0;
};

/// The polyline of a Theta* path: the centres of its cells.
inline std::vector<Point> centres(const std::vector<Cell>& cells) {
    std::vector<Point> out;
    out.reserve(cells.size());
    for (const Cell c : cells) out.push_back(centre_point(c));
    return out;
}

}  // namespace pride::grid

#pragma once
// Jump Point Search (Harabor and Grastien 2011, "Online Graph Pruning for Pathfinding on Grid
// Maps", AAAI): A* on the same 8-connected grid with octile costs, whose successors are only the
// jump points found by scanning straight and diagonal lines, so that of the many symmetric
// shortest paths only one canonical one (diagonal moves as early as possible) is searched.
//
// The grids here forbid corner cutting (a diagonal step needs both orthogonal cells free, map.hpp).
// The 2011 paper's pruning and forced-neighbour rules assume corner cutting; this file implements
// the variant without it, as Harabor and Grastien use it on the Moving AI benchmarks from 2014 on
// ("Improving Jump Point Search", ICAPS 2014, the rules of JPS without corner cutting):
//   - a diagonal move has no forced neighbours: its natural neighbours are the two orthogonal
//     components and the diagonal itself (any other neighbour is reached at most as cheaply by a
//     path that leaves the parent orthogonally);
//   - a straight move (direction d) into x has the forced neighbour x + s on a side s (d +- 90
//     degrees) when x + s is free and the cell behind it, x - d + s, is blocked: the parent could
//     not reach x + s diagonally. Then x + s and x + d + s (when that diagonal step is legal) are
//     successors of x besides x + d;
//   - a diagonal scan stops at x when a straight scan from x along either component finds a jump
//     point (or the goal); a scan stops at the goal.
// Decided here: the rule "the cell behind is blocked" is read from the legal-step masks of the map
// (GridMap::moves): side s is free from x but not from the cell before x. Corner cutting is not
// supported: search() refuses it (InputError). Ties between equal f go to the larger g, as in
// A* (astar.hpp), with a binary heap (JPS's open list is short; A*'s bucket queue assumes
// successors within one step, which jumps are not).
//
// The path returned is the full cell chain (each jump expanded into single steps): a legal Path
// of the same length as A*'s. Flat arrays and generation stamps (PackedSearchArrays), a heap
// vector reused across queries: no allocation per query once grown.
#include <algorithm>
#include <bit>
#include <cstdint>
#include <vector>

#include "framework/error.hpp"
#include "problems/grid/map.hpp"
#include "problems/grid/path.hpp"
#include "problems/grid/planners/astar.hpp"
#include "problems/grid/search_arrays.hpp"

namespace pride::grid {

class JumpPointSearch {
  public:
    /// The optimal length from s to g (the length A* returns), or -1 when g cannot be reached. With
    /// `out`, the path (s first, g last, one step per pair of cells) replaces its contents. Start or
    /// goal outside or blocked, or `corner_cutting`, throw InputError.
    double search(const GridMap& map, Cell s, Cell g, Path* out = nullptr, bool corner_cutting = false) {
        require(!corner_cutting, "jps",
                "jump point search here prunes by the no-corner-cutting rules; corner cutting is not supported");
        require(map.free(s), "start",
                "(" + std::to_string(s.x) + "," + std::to_string(s.y) + ") is blocked or outside");
        require(map.free(g), "goal", "(" + std::to_string(g.x) + "," + std::to_string(g.y) + ") is blocked or outside");
        arrays_.prepare(map.size());
        heap_.clear();
        map_ = &map;
        width_ = static_cast<std::uint32_t>(map.width());
        goal_ = static_cast<std::uint32_t>(map.index(g));
        for (int d = 0; d < 8; ++d) offset_[d] = map.offset(d);
        const auto start = static_cast<std::uint32_t>(map.index(s));
        Record* const rec = arrays_.records.data();
        rec[start] = {0.0, start, arrays_.open};
        push(key(octile(s, g), 0.0), start);
        const std::uint32_t closed = arrays_.closed();
        while (!heap_.empty()) {
            std::pop_heap(heap_.begin(), heap_.end(), After{});
            const std::uint32_t x = heap_.back().index;
            heap_.pop_back();
            if (rec[x].stamp == closed) continue;  // a stale entry
            rec[x].stamp = closed;
            ++expansions_;
            if (x == goal_) {
                if (out) trace(start, *out);
                return rec[x].g;
            }
            const Cell cx = cell_of(x);
            const std::uint32_t p = rec[x].parent;
            const unsigned moves = map.moves(x);
            unsigned dirs;  // the directions to scan from x (natural and forced neighbours)
            if (p == x) {
                dirs = moves;  // the start: every neighbour
            } else {
                const Cell cp = cell_of(p);
                const int d = direction(cx, Cell{cx.x + sign(cp.x, cx.x), cx.y + sign(cp.y, cx.y)});
                dirs = successors(x, d, moves);
            }
            for (; dirs != 0; dirs &= dirs - 1) {
                const int d = std::countr_zero(dirs);
                const std::uint32_t j = jump(static_cast<std::uint32_t>(x + offset_[d]), d);
                if (j == kNone) continue;
                Record& r = rec[j];
                if (r.stamp == closed) continue;
                const Cell cj = cell_of(j);
                const double ng = rec[x].g + octile(cx, cj);
                if (r.stamp == arrays_.open && r.g <= ng) continue;
                r = {ng, x, arrays_.open};
                push(key(ng + octile(cj, g), ng), j);
            }
        }
        return -1.0;
    }

    /// Jump points expanded (taken off the open list) since construction.
    std::int64_t expansions() const noexcept { return expansions_; }

  private:
    using Record = PackedSearchArrays::Record;
    static constexpr std::uint32_t kNone = 0xffffffffu;

    /// The open list's order: `a` is popped after `b` (std heap functions keep the greatest on top).
    struct After {
        bool operator()(const OpenNode& a, const OpenNode& b) const noexcept { return a.key > b.key; }
    };
    /// A*'s key (astar.hpp): f in units of 2^-20, then the larger g first among equal f.
    static std::uint64_t key(double f, double g) noexcept {
        const auto fq = round_half_up(f * 1048576.0);
        const auto gq = std::min<std::uint64_t>(round_half_up(g), (1u << kTieBits) - 1);
        return (fq << kTieBits) | ((1u << kTieBits) - 1 - gq);
    }
    void push(std::uint64_t k, std::uint32_t index) {
        heap_.push_back({k, index});
        std::push_heap(heap_.begin(), heap_.end(), After{});
    }
    static int sign(int from, int to) noexcept { return (to > from) - (to < from); }
    Cell cell_of(std::uint32_t i) const noexcept {
        const std::uint32_t y = i / width_;
        return {static_cast<int>(i - y * width_), static_cast<int>(y)};
    }

    /// The directions to scan from jump point x reached by a move in direction d (its legal steps:
    /// `moves`). Diagonal: the two components and the diagonal. Straight: ahead, and for each side
    /// whose cell is free from x but not from the cell behind x, that side and the diagonal towards it.
    unsigned successors(std::uint32_t x, int d, unsigned moves) const noexcept {
        unsigned want;
        if (is_diagonal(d)) {
            want = bit(d - 1) | bit(d) | bit(d + 1);
        } else {
            want = bit(d);
            const unsigned behind = map_->moves(static_cast<std::size_t>(x - offset_[d]));
            for (const int side : {d + 2, d + 6})
                if (forced(moves, behind, side)) want |= bit(side) | bit(side == d + 2 ? d + 1 : d + 7);
        }
        return want & moves;
    }
    static unsigned bit(int d) noexcept { return 1u << (d & 7); }
    /// Side s (a direction) of a straight move is forced at x: free from x, not from the cell behind.
    static bool forced(unsigned moves, unsigned behind, int s) noexcept {
        return ((moves >> (s & 7)) & 1u) != 0 && ((behind >> (s & 7)) & 1u) == 0;
    }

    /// The jump point reached by scanning from cell i (entered by a legal step in direction d), or kNone.
    std::uint32_t jump(std::uint32_t i, int d) const noexcept {
        return is_diagonal(d) ? jump_diagonal(i, d) : jump_straight(i, d);
    }
    std::uint32_t jump_straight(std::uint32_t i, int d) const noexcept {
        const std::ptrdiff_t step = offset_[d];
        const int left = d + 6, right = d + 2;
        unsigned behind = map_->moves(static_cast<std::size_t>(i - step));
        for (;;) {
            const unsigned m = map_->moves(i);
            if (i == goal_ || forced(m, behind, left) || forced(m, behind, right)) return i;
            if (((m >> d) & 1u) == 0) return kNone;
            behind = m;
            i = static_cast<std::uint32_t>(i + step);
        }
    }
    std::uint32_t jump_diagonal(std::uint32_t i, int d) const noexcept {
        const int a = (d + 7) & 7, b = (d + 1) & 7;  // the two orthogonal components
        for (;;) {
            if (i == goal_) return i;
            const unsigned m = map_->moves(i);
            if (((m >> a) & 1u) != 0 && jump_straight(static_cast<std::uint32_t>(i + offset_[a]), a) != kNone) return i;
            if (((m >> b) & 1u) != 0 && jump_straight(static_cast<std::uint32_t>(i + offset_[b]), b) != kNone) return i;
            if (((m >> d) & 1u) == 0) return kNone;
            i = static_cast<std::uint32_t>(i + offset_[d]);
        }
    }

    /// The cell chain from start to the goal: the jump points, each jump expanded into its steps.
    void trace(std::uint32_t start, Path& out) {
        points_.clear();
        for (std::uint32_t i = goal_;; i = arrays_.records[i].parent) {
            points_.push_back(i);
            if (i == start) break;
        }
        out.clear();
        Cell c = cell_of(start);
        out.push_back(c);
        for (std::size_t k = points_.size() - 1; k-- > 0;) {
            const Cell to = cell_of(points_[k]);
            const int sx = sign(c.x, to.x), sy = sign(c.y, to.y);
            while (!(c == to)) {
                c = {c.x + sx, c.y + sy};
                out.push_back(c);
            }
        }
    }

    PackedSearchArrays arrays_;
    std::vector<OpenNode> heap_;
    std::vector<std::uint32_t> points_;  // trace's scratch: the jump points, goal first
    const GridMap* map_ = nullptr;
    std::uint32_t width_ = 0, goal_ = 0;
    std::ptrdiff_t offset_[8] = {};
    std::int64_t expansions_ = 0;
};

}  // namespace pride::grid

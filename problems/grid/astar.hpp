#pragma once
// A* with the octile heuristic on a GridMap: 8-connected, step costs 1 and sqrt(2), no corner
// cutting by default (the rule behind the Moving AI optimal lengths). Flat arrays indexed by cell,
// a radix heap with lazy deletion, and generation stamps, so one AStar serves many queries on one
// map (or on several, resizing once) without clearing or allocating per node.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "problems/grid/map.hpp"
#include "problems/grid/path.hpp"
#include "problems/grid/search_arrays.hpp"

namespace pride::grid {

/// The octile distance: the shortest 8-connected length on an empty grid.
[[gnu::always_inline]] inline double octile(Cell a, Cell b) noexcept {
    const int dx = std::abs(a.x - b.x), dy = std::abs(a.y - b.y);
    return std::max(dx, dy) + (kSqrt2 - 1.0) * std::min(dx, dy);
}

/// std::llround(x) bit for bit for x == 0 and 0.5 <= x < 2^52 (f * 2^20 and g in A*'s keys are
/// 0 or at least 1), without the libm call: there x + 0.5 rounds, if at all, to no other integer
/// part, and truncation is floor. (Below 0.5 it is wrong only at 0.5 - 2^-54, which rounds to 1.)
[[gnu::always_inline]] inline std::uint64_t round_half_up(double x) noexcept {
    // Through int64_t: one cvttsd2si, where a direct conversion to uint64_t tests for 2^63 first.
    return static_cast<std::uint64_t>(static_cast<std::int64_t>(x + 0.5));
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
        open(start, 0.0, key(octile(s, g), 0.0), start);
        // Loop invariants in locals (the compiler cannot keep them in registers across the
        // vector stores otherwise): index offsets of the 8 steps, the goal, the stamps.
        const auto width = static_cast<std::uint32_t>(map.width());
        std::ptrdiff_t offsets[8];
        for (int d = 0; d < 8; ++d) offsets[d] = map.offset(d);
        Record* const rec = arrays_.records.data();
        const std::uint32_t seen = arrays_.open, closed = arrays_.closed();
        while (!heap_.empty() || !level_.empty()) {
            std::uint32_t index;
            std::uint64_t current;
            if (!level_.empty()) {  // nodes with the smallest f, found while expanding one: no heap work
                index = level_.back().index;
                current = level_.back().key;
                level_.pop_back();
            } else {
                const Node node = heap_.pop();
                index = node.index;
                current = node.key;
            }
            if (rec[index].stamp == closed) continue;  // a stale entry
            rec[index].stamp = closed;
            ++expansions_;
            const double gi = rec[index].g;
            if (index == goal) {
                if (out) trace(map, start, goal, *out);
                return gi;
            }
            // 32-bit division: indices fit in 32 bits (they are stored so), and it is the cheaper one.
            const std::uint32_t cy = index / width;
            const Cell c{static_cast<int>(index - cy * width), static_cast<int>(cy)};
            for (unsigned m = map.moves(index, corner_cutting); m != 0; m &= m - 1) {
                const int d = std::countr_zero(m);
                const Cell n{c.x + kDx[d], c.y + kDy[d]};
                if (window && !w.contains(n)) continue;
                const auto ni = static_cast<std::uint32_t>(static_cast<std::ptrdiff_t>(index) + offsets[d]);
                Record& r = rec[ni];
                if (r.stamp == closed) continue;
                const double ng = gi + (is_diagonal(d) ? kSqrt2 : 1.0);
                if (r.stamp == seen && r.g <= ng) continue;
                const std::uint64_t k = key(ng + octile(n, g), ng);
                r.stamp = seen;
                r.g = ng;
                r.parent = index;
                // Same f as the node expanded (or, by rounding, a hair below it: a consistent
                // heuristic never truly lowers f): expanded next, without heap work.
                if ((k >> kTieBits) <= (current >> kTieBits))
                    level_.push_back({k, ni});
                else
                    heap_.push({k, ni});
            }
        }
        return -1.0;
    }

    /// Nodes expanded (taken off the open list) since construction.
    std::int64_t expansions() const noexcept { return expansions_; }

  private:
    /// The priority as one integer: f in units of 2^-20 above kTieBits bits that put the larger g
    /// first among equal f (deeper nodes first expand fewer nodes on open ground). Distinct octile
    /// lengths a + b sqrt(2) on maps below a few thousand cells a side differ by far more than
    /// 2^-20, so the order by f is exact; f must stay below 2^25.
    static constexpr int kTieBits = 19;
    static std::uint64_t key(double f, double g) noexcept {
        const auto fq = round_half_up(f * 1048576.0);
        const auto gq = std::min<std::uint64_t>(round_half_up(g), (1u << kTieBits) - 1);
        return (fq << kTieBits) | ((1u << kTieBits) - 1 - gq);
    }
    struct Node {
        std::uint64_t key;
        std::uint32_t index;
    };

    /// A radix heap (Ahuja, Mehlhorn, Orlin and Tarjan 1990): for monotone integer keys, which A*
    /// with a consistent heuristic pops here (equal-f nodes bypass it through level_), pushes are
    /// O(1) and each node moves down at most 64 buckets.
    class RadixHeap {
      public:
        bool empty() const noexcept { return size_ == 0; }
        void clear() noexcept {
            buckets_[0].clear();
            for (std::uint64_t m = used_; m != 0; m &= m - 1) buckets_[1 + std::countr_zero(m)].clear();
            used_ = 0;
            last_ = 0;
            size_ = 0;
        }
        [[gnu::always_inline]] void push(Node n) {
            const std::size_t b = bucket(n.key);
            buckets_[b].push_back(n);
            if (b > 0) used_ |= std::uint64_t{1} << (b - 1);
            ++size_;
        }
        Node pop() {
            if (buckets_[0].empty()) {  // refill bucket 0 from the first non-empty bucket
                const std::size_t i = 1 + static_cast<std::size_t>(std::countr_zero(used_));
                std::uint64_t least = buckets_[i].front().key;
                for (const Node& n : buckets_[i]) least = std::min(least, n.key);
                last_ = least;
                used_ &= ~(std::uint64_t{1} << (i - 1));
                for (const Node& n : buckets_[i]) push_moved(n);
                buckets_[i].clear();
            }
            const Node n = buckets_[0].back();
            buckets_[0].pop_back();
            --size_;
            return n;
        }

      private:
        std::size_t bucket(std::uint64_t key) const noexcept {
            return key == last_ ? 0 : 64 - static_cast<std::size_t>(std::countl_zero(key ^ last_));
        }
        void push_moved(Node n) {
            const std::size_t b = bucket(n.key);
            buckets_[b].push_back(n);
            if (b > 0) used_ |= std::uint64_t{1} << (b - 1);
        }
        std::vector<Node> buckets_[65];
        std::uint64_t used_ = 0;  // bit b - 1: bucket b (1..64) holds nodes
        std::uint64_t last_ = 0;
        std::size_t size_ = 0;
    };

    void prepare(std::size_t cells) {
        arrays_.prepare(cells);
        heap_.clear();
        level_.clear();
    }

    void open(std::uint32_t index, double g, std::uint64_t key, std::uint32_t parent) {
        arrays_.records[index] = {g, parent, arrays_.open};
        heap_.push({key, index});
    }

    void trace(const GridMap& map, std::uint32_t start, std::uint32_t goal, Path& out) const {
        out.clear();
        for (std::uint32_t i = goal;; i = arrays_.records[i].parent) {
            out.push_back(map.cell(i));
            if (i == start) break;
        }
        std::reverse(out.begin(), out.end());
    }

    using Record = PackedSearchArrays::Record;
    PackedSearchArrays arrays_;
    RadixHeap heap_;
    std::vector<Node> level_;  // nodes with the f of the node being expanded, taken before the heap
    std::int64_t expansions_ = 0;
};

}  // namespace pride::grid

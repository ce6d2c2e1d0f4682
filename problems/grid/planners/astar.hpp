#pragma once
// A* with the octile heuristic on a GridMap: 8-connected, step costs 1 and sqrt(2), no corner
// cutting by default (the rule behind the Moving AI optimal lengths). Flat arrays indexed by cell,
// a bucket queue on f with lazy deletion (OpenList), and generation stamps, so one AStar serves many queries on one
// map (or on several, resizing once) without clearing or allocating per node.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <iterator>
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

/// Bits of an A* key below f (they order equal f by g, larger g first).
inline constexpr int kTieBits = 19;

/// An entry of A*'s open list: its priority key, its cell and the order of its push.
struct OpenNode {
    std::uint64_t key;
    std::uint32_t index;
    std::uint32_t seq = 0;  // set by OpenList::push: ties between equal keys go to the later push
};

/// A*'s open list: pops the least key and, among equal keys, the node pushed last, for any
/// sequence of keys (this order is A*'s tie-breaking, and the results depend on it bit for bit).
///
/// A bucket queue on f: bucket a holds the keys with key >> kShift == a (f in steps of 2^-6), in a
/// ring of kSlots buckets from the cursor `lo_` (no nonempty bucket lies below it). A consistent
/// heuristic keeps the open f within 2 sqrt(2) of the least, so the ring (4 units of f) holds them
/// all and a node is stored once and never moved, where the radix heap before it moved each node
/// about 7 times. Only the cursor's bucket is kept sorted (key descending, then push order, so its
/// back is the next node); a bucket is sorted when the cursor reaches it, and a push into the
/// cursor's bucket is inserted in place (a key below the last pop too). A key in a bucket below
/// the cursor (in A*: when the list ran empty, the cursor restarts at the next push, and the
/// equal-f stack's nodes push lower keys after it) moves the cursor down when the ring's limit
/// allows, and otherwise rebuilds the ring below it from all nodes in push order (on the small
/// scenario files up to 5 % of the instructions; none on the large ones). Keys beyond the ring
/// (which a consistent heuristic never makes) wait in `overflow_` in push order; the ring stops
/// advancing meanwhile, so that no bucket receives a key before an older overflowed one.
class OpenList {
  public:
    static constexpr int kShift = kTieBits + 14;  // bucket of a key: f in units of 2^-6
    static constexpr std::size_t kSlots = 256;

    bool empty() const noexcept { return size_ == 0; }
    std::size_t size() const noexcept { return size_; }
    void clear() noexcept {
        empty_buckets([](const Bucket&) {});
        overflow_.clear();
        size_ = 0;
        seq_ = 0;
    }
    [[gnu::always_inline]] void push(OpenNode n) {
        n.seq = seq_++;
        if (size_++ == 0) {  // empty: the ring starts at this key's bucket
            lo_ = n.key >> kShift;
            limit_ = lo_ + kSlots;
        }
        place(n);
    }
    OpenNode pop() {
        Bucket* b = &slots_[lo_ & kMask];
        if (b->empty()) b = advance();
        const OpenNode n = b->back();
        b->pop_back();
        if (b->empty()) bits_[(lo_ & kMask) / 64] &= ~(std::uint64_t{1} << (lo_ & 63));
        --size_;
        return n;
    }
    /// Times the exact fallbacks ran (for the tests): keys overflowed, rebuilds below the ring.
    std::size_t overflowed() const noexcept { return overflowed_; }
    std::size_t rebuilds() const noexcept { return rebuilds_; }

  private:
    /// One bucket: a vector used up to `size`, so that the push is a store (std::vector's
    /// push_back was a call per node: its growth path kept it out of line).
    struct Bucket {
        std::vector<OpenNode> nodes;
        std::size_t size = 0;
        bool empty() const noexcept { return size == 0; }
        OpenNode* begin() noexcept { return nodes.data(); }
        OpenNode* end() noexcept { return nodes.data() + size; }
        [[gnu::always_inline]] void push_back(const OpenNode& n) {
            if (size == nodes.size()) [[unlikely]]
                grow();
            nodes[size++] = n;
        }
        [[gnu::noinline]] void grow() { nodes.resize(std::max<std::size_t>(16, 2 * nodes.size())); }
        OpenNode& back() noexcept { return nodes[size - 1]; }
        void pop_back() noexcept { --size; }
        void clear() noexcept { size = 0; }
    };
    static constexpr std::size_t kMask = kSlots - 1, kWords = kSlots / 64;
    /// a is popped after b; a type, so that std::sort inlines it (a function pointer it called).
    struct Before {
        bool operator()(const OpenNode& a, const OpenNode& b) const noexcept {
            return a.key != b.key ? a.key > b.key : a.seq < b.seq;
        }
    };
    [[gnu::always_inline]] void place(const OpenNode& n) {
        const std::uint64_t a = n.key >> kShift;
        if (a > lo_ && a < limit_) [[likely]] {
            slots_[a & kMask].push_back(n);
            mark(a);
        } else {
            place_rare(n, a);
        }
    }
    void place_rare(const OpenNode& n, std::uint64_t a) {
        if (a >= limit_) {
            overflow_.push_back(n);
            ++overflowed_;
            return;
        }
        if (a < lo_) {
            if (limit_ - a > kSlots) {
                rebuild(n, a);
                return;
            }
            lo_ = a;  // every bucket below the old cursor is empty, this one too
        }
        // The cursor's bucket: n in its place, after every key at least its own (n is the latest
        // push). Found by bisection: on open ground the bucket holds thousands of nodes.
        Bucket& b = slots_[a & kMask];
        const auto at = static_cast<std::size_t>(
            std::partition_point(b.begin(), b.end(), [&](const OpenNode& o) { return o.key >= n.key; }) - b.begin());
        b.push_back(n);
        std::copy_backward(b.begin() + at, b.end() - 1, b.end());
        b.begin()[at] = n;
        mark(a);
    }
    /// The cursor's bucket is empty: move to the next nonempty one (refilling the ring from the
    /// overflow when it is empty) and sort it.
    Bucket* advance() {
        const std::size_t d = next_distance(lo_ & kMask);
        if (d < kSlots) {
            lo_ += d;
            if (overflow_.empty()) limit_ = lo_ + kSlots;
        } else {  // the ring is empty; the overflow is not (size_ > 0)
            std::uint64_t least = overflow_.front().key;
            for (const OpenNode& n : overflow_) least = std::min(least, n.key);
            lo_ = least >> kShift;
            limit_ = lo_ + kSlots;
            std::vector<OpenNode> waiting;
            waiting.swap(overflow_);
            for (const OpenNode& n : waiting) place(n);  // in push order; the cursor's bucket in order
        }
        Bucket& b = slots_[lo_ & kMask];
        sort(b);
        return &b;
    }
    /// Into the cursor's order (key descending, then push order). The insertion sort compares keys
    /// only: it is stable, and a bucket holds equal keys in push order (nodes are appended in push
    /// order, to a bucket that is either unsorted or, when the cursor was there before, sorted).
    static void sort(Bucket& b) {
        if (b.size > 24) {
            std::sort(b.begin(), b.end(), Before{});
            return;
        }
        OpenNode* const v = b.begin();
        for (std::size_t i = 1; i < b.size; ++i) {
            const OpenNode x = v[i];
            std::size_t j = i;
            for (; j > 0 && x.key > v[j - 1].key; --j) v[j] = v[j - 1];
            v[j] = x;
        }
    }
    /// A key below the ring's reach: the ring restarts at its bucket, every node placed again in
    /// push order (buckets then hold their nodes in push order, as if pushed into this ring).
    void rebuild(const OpenNode& n, std::uint64_t a) {
        ++rebuilds_;
        std::vector<OpenNode> all;
        all.swap(overflow_);
        empty_buckets([&](Bucket& b) { all.insert(all.end(), b.begin(), b.end()); });
        all.push_back(n);
        std::sort(all.begin(), all.end(), [](const OpenNode& x, const OpenNode& y) { return x.seq < y.seq; });
        lo_ = a;
        limit_ = a + kSlots;
        for (const OpenNode& m : all) place(m);
    }
    /// Bucket a holds nodes.
    void mark(std::uint64_t a) noexcept { bits_[(a & kMask) / 64] |= std::uint64_t{1} << (a & 63); }
    /// Every nonempty bucket, in slot order, to `f` and then emptied; no bucket is marked after.
    template <class F>
    void empty_buckets(F&& f) {
        for (std::size_t w = 0; w < kWords; ++w)
            for (std::uint64_t m = bits_[w]; m != 0; m &= m - 1) {
                Bucket& b = slots_[w * 64 + static_cast<std::size_t>(std::countr_zero(m))];
                f(b);
                b.clear();
            }
        std::fill(std::begin(bits_), std::end(bits_), 0);
    }
    /// The distance from slot s to the next slot (cyclically, s itself last) whose bucket is
    /// nonempty, or kSlots when there is none.
    std::size_t next_distance(std::size_t s) const noexcept {
        const std::size_t w0 = s / 64, bit = s % 64;
        const std::uint64_t above = bit == 63 ? 0 : bits_[w0] & (~std::uint64_t{0} << (bit + 1));
        if (above != 0) return static_cast<std::size_t>(std::countr_zero(above)) - bit;
        for (std::size_t k = 1; k <= kWords; ++k) {
            const std::size_t w = (w0 + k) % kWords;
            if (bits_[w] != 0) {
                const std::size_t slot = w * 64 + static_cast<std::size_t>(std::countr_zero(bits_[w]));
                const std::size_t d = (slot + kSlots - s) % kSlots;
                return d == 0 ? kSlots : d;
            }
        }
        return kSlots;
    }

    Bucket slots_[kSlots];
    std::uint64_t bits_[kWords] = {};  // bit a % kSlots: bucket a holds nodes
    std::vector<OpenNode> overflow_;   // keys at or beyond limit_, in push order
    std::uint64_t lo_ = 0;             // the cursor: the bucket of the last pop (or the least)
    std::uint64_t limit_ = 0;          // buckets below it are in the ring; lo_ < limit_ <= lo_ + kSlots
    std::size_t size_ = 0;
    std::uint32_t seq_ = 0;
    std::size_t overflowed_ = 0, rebuilds_ = 0;
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
        // Two copies of the loop, so that the search of a whole map tests no window per neighbour.
        return window ? expand<true>(map, start, goal, g, w, out, corner_cutting)
                      : expand<false>(map, start, goal, g, w, out, corner_cutting);
    }

    /// Nodes expanded (taken off the open list) since construction.
    std::int64_t expansions() const noexcept { return expansions_; }

  private:
    /// The search from the opened start to the goal; with Windowed, only in w.
    template <bool Windowed>
    double expand(const GridMap& map, std::uint32_t start, std::uint32_t goal, Cell g, const Window& w, Path* out,
                  bool corner_cutting) {
        // Loop invariants in locals (the compiler cannot keep them in registers across the
        // vector stores otherwise): index offsets of the 8 steps, the goal, the stamps.
        const auto width = static_cast<std::uint32_t>(map.width());
        std::ptrdiff_t offsets[8];
        double cost[8];  // the step lengths, so that a step's g is one load and add
        for (int d = 0; d < 8; ++d) {
            offsets[d] = map.offset(d);
            cost[d] = is_diagonal(d) ? kSqrt2 : 1.0;
        }
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
                if (Windowed && !w.contains(Cell{c.x + kDx[d], c.y + kDy[d]})) continue;
                const auto ni = static_cast<std::uint32_t>(static_cast<std::ptrdiff_t>(index) + offsets[d]);
                Record& r = rec[ni];
                if (r.stamp == closed) continue;
                const double ng = gi + cost[d];
                if (r.stamp == seen && r.g <= ng) continue;
                const Cell n{c.x + kDx[d], c.y + kDy[d]};  // only here: most neighbours stop above
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

    /// The priority as one integer: f in units of 2^-20 above kTieBits bits that put the larger g
    /// first among equal f (deeper nodes first expand fewer nodes on open ground). Distinct octile
    /// lengths a + b sqrt(2) on maps below a few thousand cells a side differ by far more than
    /// 2^-20, so the order by f is exact; f must stay below 2^25.
    static std::uint64_t key(double f, double g) noexcept {
        const auto fq = round_half_up(f * 1048576.0);
        const auto gq = std::min<std::uint64_t>(round_half_up(g), (1u << kTieBits) - 1);
        return (fq << kTieBits) | ((1u << kTieBits) - 1 - gq);
    }
    using Node = OpenNode;

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
    OpenList heap_;
    std::vector<Node> level_;  // nodes with the f of the node being expanded, taken before the heap
    std::int64_t expansions_ = 0;
};

}  // namespace pride::grid

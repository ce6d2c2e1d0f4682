#pragma once
// Connector policies (docs/grid.md): how the `line` and `free` encodings join two
// consecutive waypoints. Each gives the cells after `a` up to and including `b` as map indices
// (a segment for LoopFreeChain): a straight line or a shortest path.
#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "framework/error.hpp"
#include "problems/grid/map.hpp"
#include "problems/grid/path.hpp"
#include "problems/grid/planners/astar.hpp"

namespace pride::grid {

/// The straight cell line, whatever it crosses; each blocked cell and each corner-cutting step
/// on it is a violation, which the problem scores at M apiece.
class PenaltyConnector {
  public:
    static constexpr const char* name = "penalty";
    /// The join's cells as map indices (valid until the next call). A step is a violation exactly
    /// when it is not one of its cell's legal moves (a step onto a blocked cell or one cutting a
    /// corner: what count_violations counts).
    std::span<const std::uint32_t> segment(const GridMap& map, Cell a, Cell b, int& violations, bool corner_cutting) {
        cells_.clear();
        for (LineSteps line(a, b); !line.done();) {
            const Cell c = line.current(), n = line.next();
            violations += !map.legal_move(c, n, corner_cutting);
            cells_.push_back(static_cast<std::uint32_t>(map.index(n)));
        }
        return cells_;
    }

  private:
    std::vector<std::uint32_t> cells_;  // scratch
};

/// The straight line when it is a legal join; otherwise the shortest legal detour between the two
/// ends, found by A* inside a window around the join that doubles its margin until a detour is
/// found (the whole map at last). Both ends must be reachable from each other, which the
/// encodings guarantee by snapping waypoints to cells connected to the start. A join (line or
/// detour) depends only on its two ends, so each is walked or searched once per run and then
/// remembered: a swarm that converges asks for the same joins again and again.
class RepairConnector {
  public:
    static constexpr const char* name = "repair";
    int initial_margin = 2;

    /// The join's cells as map indices (valid until the next call): a remembered join, or one
    /// worked out now and remembered (not when its ends are not connected: then the penalty line,
    /// with its violations, every time).
    std::span<const std::uint32_t> segment(const GridMap& map, Cell a, Cell b, int& violations, bool corner_cutting) {
        const std::uint64_t key = (static_cast<std::uint64_t>(map.index(a)) << 32) | map.index(b);
        if (const Slice* hit = store_.find(key)) return {store_.cells.data() + hit->first, hit->length};
        return first_time(map, a, b, key, violations, corner_cutting);
    }

    /// Cells of the joins remembered now (bounded by DetourStore::kMaxCells plus one join).
    std::size_t remembered_cells() const noexcept { return store_.cells.size(); }

  private:
    /// A join not met before: its line when free, else a search; out of line, so that the lookup
    /// above stays small enough to inline.
    [[gnu::noinline]] std::span<const std::uint32_t> first_time(const GridMap& map, Cell a, Cell b, std::uint64_t key,
                                                                int& violations, bool corner_cutting) {
        if (free_line(map, a, b, corner_cutting)) {
            store_.insert(key, cells_);  // remembered too: the next time costs a lookup, not a walk
            return cells_;
        }
        cells_.clear();
        for (int margin = initial_margin;; margin *= 2) {
            const Window w{std::max(0, std::min(a.x, b.x) - margin), std::max(0, std::min(a.y, b.y) - margin),
                           std::min(map.width() - 1, std::max(a.x, b.x) + margin),
                           std::min(map.height() - 1, std::max(a.y, b.y) + margin)};
            if (astar_.search(map, a, b, &detour_, &w, corner_cutting) >= 0.0) {
                for (std::size_t i = 1; i < detour_.size(); ++i)
                    cells_.push_back(static_cast<std::uint32_t>(map.index(detour_[i])));
                store_.insert(key, cells_);
                return cells_;
            }
            if (w.x0 == 0 && w.y0 == 0 && w.x1 == map.width() - 1 && w.y1 == map.height() - 1) break;
        }
        return penalty_.segment(map, a, b, violations, corner_cutting);  // unreachable ends: not remembered
    }

    /// True when the straight line from a to b is a legal join (line_is_free), writing its cells
    /// after a to cells_ as it goes.
    bool free_line(const GridMap& map, Cell a, Cell b, bool corner_cutting) {
        cells_.clear();
        if (!map.free(a)) return false;
        for (LineSteps line(a, b); !line.done();) {
            const Cell c = line.current(), n = line.next();
            if (!map.legal_move(c, n, corner_cutting)) return false;
            cells_.push_back(static_cast<std::uint32_t>(map.index(n)));
        }
        return true;
    }

    /// Where a remembered detour lies in DetourStore::cells: 16 bytes, so that a slot is found
    /// with a shift and the table takes two thirds of the cache lines a 24-byte slot would.
    struct Slice {
        std::uint64_t key;
        std::uint32_t first;
        std::uint32_t length;
    };
    /// The remembered detours by their two ends: open addressing with linear probing on a
    /// power-of-two table, one multiply and a probe or two per lookup (std::unordered_map's prime
    /// modulo and node walk cost more than the rest of a short join).
    struct DetourStore {
        static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
        static constexpr std::size_t kMaxCells = std::size_t{1} << 24;  // 64 MiB of remembered cells
        std::vector<Slice> table;
        std::size_t used = 0;
        std::vector<std::uint32_t> cells;  // every detour, one after the other

        std::size_t slot(std::uint64_t key) const noexcept {
            const std::size_t mask = table.size() - 1;
            std::size_t i = static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> 32) & mask;
            while (table[i].key != kEmpty && table[i].key != key) i = (i + 1) & mask;
            return i;
        }
        const Slice* find(std::uint64_t key) const noexcept {
            if (table.empty()) return nullptr;
            const Slice& s = table[slot(key)];
            return s.key == key ? &s : nullptr;
        }
        void insert(std::uint64_t key, const std::vector<std::uint32_t>& detour) {
            // Bounded: forgetting every join costs only their walks again (a join depends on its
            // ends alone, so results are unchanged), where an unbounded store grew by the whole
            // decoded chain per evaluation on a large open map (560 MB in 100 evaluations at
            // 2000 x 2000).
            if (cells.size() + detour.size() > kMaxCells) {
                std::fill(table.begin(), table.end(), Slice{kEmpty, 0, 0});
                used = 0;
                cells.clear();
            }
            if (2 * (used + 1) > table.size()) {  // keep the load at most 1/2
                std::vector<Slice> old(std::max<std::size_t>(64, 2 * table.size()), Slice{kEmpty, 0, 0});
                old.swap(table);
                for (const Slice& s : old)
                    if (s.key != kEmpty) table[slot(s.key)] = s;
            }
            table[slot(key)] =
                Slice{key, static_cast<std::uint32_t>(cells.size()), static_cast<std::uint32_t>(detour.size())};
            ++used;
            cells.insert(cells.end(), detour.begin(), detour.end());
        }
    };

    AStar astar_;  // scratch, reused across joins
    Path detour_;
    std::vector<std::uint32_t> cells_;  // scratch: the line, or a new detour
    DetourStore store_;
    PenaltyConnector penalty_;
};

/// The repair or the penalty connector, chosen at run time: a join costs a line walk or a search,
/// so the one branch per join is not measurable, and one instantiation of each encoding carries
/// both connectors.
class SelectableConnector {
  public:
    enum class Kind { repair, penalty };
    SelectableConnector() = default;
    explicit SelectableConnector(Kind kind) : kind_(kind) {}

    Kind kind() const noexcept { return kind_; }
    const char* name() const noexcept { return kind_ == Kind::repair ? RepairConnector::name : PenaltyConnector::name; }

    std::span<const std::uint32_t> segment(const GridMap& map, Cell a, Cell b, int& violations, bool corner_cutting) {
        return kind_ == Kind::repair ? repair_.segment(map, a, b, violations, corner_cutting)
                                     : penalty_.segment(map, a, b, violations, corner_cutting);
    }

  private:
    Kind kind_ = Kind::repair;
    RepairConnector repair_;
    PenaltyConnector penalty_;
};

}  // namespace pride::grid

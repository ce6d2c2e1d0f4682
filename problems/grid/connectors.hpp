#pragma once
// Connector policies (shared/spec/grid.md): how the `line` and `free` encodings join two
// consecutive waypoints. Both append the cells after `a` up to and including `b`.
#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include "problems/grid/astar.hpp"
#include "problems/grid/map.hpp"
#include "problems/grid/path.hpp"

namespace pride::grid {

/// The straight cell line, whatever it crosses; each blocked cell and each corner-cutting step
/// on it is a violation, which the problem scores at M apiece.
struct PenaltyConnector {
    static constexpr const char* name = "penalty";
    void join(const GridMap& map, Cell a, Cell b, Path& path, int& violations, bool corner_cutting) {
        const std::size_t first = path.size();  // path.back() is a
        append_line(a, b, path);
        violations += count_violations(map, path, first, corner_cutting);
    }
};

/// The straight line when it is a legal join; otherwise the shortest legal detour between the two
/// ends, found by A* inside a window around the join that doubles its margin until a detour is
/// found (the whole map at last). Both ends must be reachable from each other, which the
/// encodings guarantee by snapping waypoints to cells connected to the start. A detour depends
/// only on its two ends, so each is searched once per run and then remembered: a swarm that
/// converges asks for the same joins again and again.
class RepairConnector {
  public:
    static constexpr const char* name = "repair";
    int initial_margin = 2;

    void join(const GridMap& map, Cell a, Cell b, Path& path, int& violations, bool corner_cutting) {
        if (line_is_free(map, a, b, corner_cutting)) {
            append_line(a, b, path);
            return;
        }
        const std::uint64_t key = (static_cast<std::uint64_t>(map.index(a)) << 32) | map.index(b);
        if (const auto hit = known_.find(key); hit != known_.end()) {
            path.insert(path.end(), detours_.begin() + hit->second.first,
                        detours_.begin() + hit->second.first + hit->second.second);
            return;
        }
        const std::size_t first = path.size();
        const int before = violations;
        search(map, a, b, path, violations, corner_cutting);
        if (violations != before) return;  // no detour exists (ends not connected): not remembered
        known_.emplace(key, std::make_pair(detours_.size(), path.size() - first));
        detours_.insert(detours_.end(), path.begin() + static_cast<std::ptrdiff_t>(first), path.end());
    }

  private:
    void search(const GridMap& map, Cell a, Cell b, Path& path, int& violations, bool corner_cutting) {
        for (int margin = initial_margin;; margin *= 2) {
            const Window w{std::max(0, std::min(a.x, b.x) - margin), std::max(0, std::min(a.y, b.y) - margin),
                           std::min(map.width() - 1, std::max(a.x, b.x) + margin),
                           std::min(map.height() - 1, std::max(a.y, b.y) + margin)};
            if (astar_.search(map, a, b, &detour_, &w, corner_cutting) >= 0.0) {
                path.insert(path.end(), detour_.begin() + 1, detour_.end());
                return;
            }
            if (w.x0 == 0 && w.y0 == 0 && w.x1 == map.width() - 1 && w.y1 == map.height() - 1) break;
        }
        PenaltyConnector{}.join(map, a, b, path, violations, corner_cutting);  // unreachable ends
    }

    AStar astar_;  // scratch, reused across joins
    Path detour_;
    std::unordered_map<std::uint64_t, std::pair<std::size_t, std::size_t>> known_;  // (a, b) -> detours_ slice
    Path detours_;
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

    void join(const GridMap& map, Cell a, Cell b, Path& path, int& violations, bool corner_cutting) {
        if (kind_ == Kind::repair)
            repair_.join(map, a, b, path, violations, corner_cutting);
        else
            PenaltyConnector{}.join(map, a, b, path, violations, corner_cutting);
    }

  private:
    Kind kind_ = Kind::repair;
    RepairConnector repair_;
};

}  // namespace pride::grid

#pragma once
// The grid path-planning problem: a map, a start, a goal and an objective. It scores paths; it
// knows nothing of any algorithm. Encodings (encodings.hpp) turn it into a BoxProblem for them.
#include <algorithm>
#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "framework/error.hpp"
#include "problems/grid/map.hpp"
#include "problems/grid/path.hpp"

namespace pride::grid {

/// A chain decoded from a genotype, with the number of violations the penalty connector let
/// through (blocked cells, corner-cutting steps); 0 for every other connector.
struct DecodedPath {
    Path path;
    int violations = 0;
};

inline std::string to_string(Cell c) {
    return "(" + std::to_string(c.x) + "," + std::to_string(c.y) + ")";
}

/// The cells reachable from `start` by legal steps (1) and the rest (0), by breadth-first search.
inline std::vector<std::uint8_t> reachable_from(const GridMap& map, Cell start, bool corner_cutting = false) {
    std::vector<std::uint8_t> seen(map.size(), 0);
    if (!map.free(start)) return seen;
    std::vector<std::size_t> queue{map.index(start)};
    seen[queue.front()] = 1;
    for (std::size_t head = 0; head < queue.size(); ++head) {
        const Cell c = map.cell(queue[head]);
        for (int d = 0; d < 8; ++d) {
            if (!map.legal_step(c, d, corner_cutting)) continue;
            const std::size_t n = map.index({c.x + kDx[d], c.y + kDy[d]});
            if (!seen[n]) {
                seen[n] = 1;
                queue.push_back(n);
            }
        }
    }
    return seen;
}

/// Which walks the problem's suggested starting points are read off: Wan and Gao's (2022) rough-set rule
/// walks (the default: what ILSO's initialiser asks the problem for) or the goal-biased random
/// walk with taboo list (Zhang et al. (2025) and Cai and Du (2021)), or Zhang et al.'s (2025) SITP walks through a
/// transition point (sitp.hpp).
enum class Walks { rules, random, sitp };

template <class Objective>
class GridProblem {
  public:
    /// Checks start and goal: inside, free, and the goal reachable (a clear error, never a hang).
    GridProblem(std::shared_ptr<const GridMap> map, Cell start, Cell goal, Objective objective = {},
                bool corner_cutting = false)
        : map_(std::move(map)), start_(start), goal_(goal), objective_(objective), corner_cutting_(corner_cutting) {
        const GridMap& m = *map_;
        const std::string size = std::to_string(m.width()) + "x" + std::to_string(m.height());
        require(m.inside(start), "start", to_string(start) + " is outside the " + size + " map " + m.name());
        require(m.inside(goal), "goal", to_string(goal) + " is outside the " + size + " map " + m.name());
        require(m.free(start), "start", to_string(start) + " is a blocked cell of " + m.name());
        require(m.free(goal), "goal", to_string(goal) + " is a blocked cell of " + m.name());
        auto reach = std::make_shared<std::vector<std::uint8_t>>(reachable_from(m, start, corner_cutting));
        require((*reach)[m.index(goal)] != 0, "goal",
                to_string(goal) + " cannot be reached from the start " + to_string(start) + " on " + m.name());
        reachable_ = std::move(reach);
    }

    const GridMap& map() const noexcept { return *map_; }
    const std::shared_ptr<const GridMap>& shared_map() const noexcept { return map_; }
    Cell start() const noexcept { return start_; }
    Cell goal() const noexcept { return goal_; }
    const Objective& objective() const noexcept { return objective_; }
    bool corner_cutting() const noexcept { return corner_cutting_; }
    /// Free and connected to the start by legal steps.
    bool reachable(Cell c) const noexcept { return map_->inside(c) && (*reachable_)[map_->index(c)] != 0; }

    Walks walks() const noexcept { return walks_; }
    void set_walks(Walks w) noexcept { walks_ = w; }

    /// M of grid.md: W * H * 10, or more when the objective's weights allow larger feasible values.
    double penalty() const noexcept {
        const double cells = static_cast<double>(map_->width()) * map_->height();
        if constexpr (requires(const Objective& o) { o.bound(cells); })
            return std::max(10.0 * cells, objective_.bound(cells) + 1.0);
        else
            return 10.0 * cells;
    }

    /// The objective of a legal path: one evaluation. Algorithms reach it only through their run's
    /// evaluation guard (framework/run_state.hpp), which counts it against the budget.
    double evaluate(const Path& path) const {
        if (calls_) calls_->fetch_add(1, std::memory_order_relaxed);
        return value(path);
    }
    /// The value a finished result is reported with (A*'s path, a decoded best point): the
    /// objective, but no evaluation, since no search decision depends on it.
    double result_value(const Path& path) const { return value(path); }
    /// Counts every evaluation from here on in `calls` (shared by the problem's copies), so that a
    /// test or a user can check a run's `evaluations` against the objective's own count.
    void count_calls(std::shared_ptr<std::atomic<std::int64_t>> calls) noexcept { calls_ = std::move(calls); }
    /// A decoded chain: its objective plus M per violation (so any violation marks it infeasible).
    double evaluate(const DecodedPath& d) const { return evaluate(d.path) + penalty() * d.violations; }

  private:
    double value(const Path& path) const {
        if constexpr (requires { objective_.of_path(path); })
            return objective_.of_path(path);
        else
            return objective_(metrics(path));
    }

    std::shared_ptr<const GridMap> map_;                // shared: problems are copied per run
    std::shared_ptr<std::atomic<std::int64_t>> calls_;  // empty unless counted (count_calls)
    Cell start_, goal_;
    Objective objective_;
    bool corner_cutting_;
    Walks walks_ = Walks::rules;
    std::shared_ptr<const std::vector<std::uint8_t>> reachable_;
};

}  // namespace pride::grid

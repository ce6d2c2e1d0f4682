#pragma once
// The `line` and `free` encodings of docs/grid.md: a point in a box becomes a chain of
// cells through waypoints joined by a Connector policy. Both fit the framework's EncodingFor
// concept unchanged, so Encoded<GridProblem<O>, LineEncoding<C>> is a BoxProblem and every box
// algorithm (PSO, GA, NLopt) plans on grids without a line of grid code of its own.
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <vector>

#include "framework/error.hpp"
#include "framework/problem.hpp"
#include "framework/random.hpp"
#include "problems/grid/connectors.hpp"
#include "problems/grid/grid_problem.hpp"
#include "problems/grid/rule_walk.hpp"
#include "problems/grid/sitp.hpp"
#include "problems/grid/walk.hpp"

namespace pride::grid {

namespace detail {
/// Joins start, the waypoints waypoint(0..count-1) and goal with the connector into `out`,
/// cutting loops (LoopFreeChain: the same cells as cut_loops on the whole raw chain, without a
/// lookup per raw cell), and recounts violations that a cut loop may have held (cutting only
/// removes steps). The waypoints are all made first, into `ends`: the joins' loop then keeps its
/// registers for the joins (1 k instructions less per decode of 99 joins). No allocation once the
/// scratch has grown to the map and the raw chain.
template <class Objective, class Connector, class Waypoint>
void join_waypoints(const GridProblem<Objective>& p, int count, Waypoint&& waypoint, Connector& connector,
                    DecodedPath& out, LoopFreeChain& chain, std::vector<Cell>& ends) {
    const GridMap& map = p.map();
    out.violations = 0;
    ends.resize(static_cast<std::size_t>(count) + 2);
    ends[0] = p.start();
    for (int k = 0; k < count; ++k) ends[static_cast<std::size_t>(k) + 1] = waypoint(k);
    ends[static_cast<std::size_t>(count) + 1] = p.goal();
    chain.begin(map, static_cast<std::uint32_t>(map.index(p.start())));
    for (std::size_t k = 0; k + 1 < ends.size(); ++k)
        chain.append(connector.segment(map, ends[k], ends[k + 1], out.violations, p.corner_cutting()));
    chain.to_path(out.path);
    if (out.violations > 0) out.violations = count_violations(map, out.path, 1, p.corner_cutting());
}

/// Builds what the problem's walks need before any run starts: Wan and Gao's (2022) rule book is built once
/// per process at its first use, and building it here keeps that out of every run's clock.
template <class Objective>
void prepare_walks(const GridProblem<Objective>& p) {
    if (p.walks() == Walks::rules) (void)grid_rule_book();
}

/// One feasible walk from start to goal per column of `out` (rule walks, random walks or SITP
/// walks, as the problem says; SITP's band cycles 0, 1, 2 over the columns), handed to
/// read(walk, column).
template <class Objective, class Read>
void read_walks(const GridProblem<Objective>& p, Rng& rng, Matrix& out, Read&& read) {
    Path walk;
    auto fill = [&](auto walker) {
        for (Eigen::Index j = 0; j < out.cols(); ++j) {
            walker.walk(p.map(), p.start(), p.goal(), rng, walk, p.corner_cutting());
            read(walk, j);
        }
    };
    if (p.walks() == Walks::sitp) {
        SitpWalker sitp;
        for (Eigen::Index j = 0; j < out.cols(); ++j) {
            sitp.walk(
                p.map(), p.start(), p.goal(), rng, walk, p.corner_cutting(), static_cast<int>(j % 3),
                // Ranked by length, not by the objective: seeding a box population has no route to
                // the run's evaluation guard, and an uncounted objective call would be a free
                // evaluation (the chain space ranks by the counted objective).
                [&](Cell c) { return p.reachable(c); }, [](const Path& s) { return metrics(s, false).length; });
            read(walk, j);
        }
    } else if (p.walks() == Walks::rules)
        fill(RuleWalker{});
    else
        fill(RandomWalker{});
}

/// Rounds a gene to a coordinate in [0, extent - 1] (NaN to 0).
inline int to_coordinate(double v, int extent) {
    if (!(v >= 0.0)) return 0;
    if (v >= extent - 1) return extent - 1;
    return static_cast<int>(v + 0.5);  // round half up (v >= 0)
}
}  // namespace detail

/// `line`: one gene per row (or column) strictly between start and goal along the axis on which
/// they are farther apart (ties: rows); the gene is the cross coordinate of that line's waypoint.
/// Decoding rounds it, snaps a blocked (or unreachable) waypoint to the nearest reachable cell of
/// the same line (ties: nearer the straight start-goal line, then the lower coordinate), joins
/// start, waypoints and goal with the Connector, and cuts loops. The "serial-number" encoding of
/// Wan and Gao (2022).
template <class Connector = RepairConnector>
class LineEncoding {
  public:
    template <class Objective>
    explicit LineEncoding(const GridProblem<Objective>& p, Connector connector = {})
        : connector_(std::move(connector)) {
        detail::prepare_walks(p);
        const Cell s = p.start(), g = p.goal();
        rows_ = std::abs(g.y - s.y) >= std::abs(g.x - s.x);
        const int from = rows_ ? s.y : s.x, to = rows_ ? g.y : g.x;
        step_ = to >= from ? 1 : -1;
        first_ = from + step_;
        count_ = std::abs(to - from) - 1;
        require(count_ >= 1, "encoding line",
                "start and goal must be at least two rows or columns apart; use the free encoding");
        extent_ = rows_ ? p.map().width() : p.map().height();
        auto snap = std::make_shared<std::vector<int>>(static_cast<std::size_t>(count_) * extent_);
        for (int k = 0; k < count_; ++k) {
            const int line = first_ + k * step_;
            // Where the straight start-goal segment crosses this line (for tie-breaking).
            const double t = static_cast<double>(line - from) / (to - from);
            const double ideal = rows_ ? s.x + t * (g.x - s.x) : s.y + t * (g.y - s.y);
            // The nearest reachable coordinate o to each c: the last one at or before c (one scan
            // up) against the first one at or after c (one scan down); ties in |o - c| go to the
            // one nearer `ideal`, then to the lower. Linear in the line's length (a search from
            // every c was quadratic: 18 s for a 2000 x 2000 map); tests/test_grid_encodings.cpp
            // checks it against that definition.
            int* row = snap->data() + static_cast<std::size_t>(k) * extent_;
            for (int c = 0, below = -1; c < extent_; ++c) {
                if (p.reachable(at(line, c))) below = c;
                row[c] = below;
            }
            for (int c = extent_ - 1, above = -1; c >= 0; --c) {
                if (p.reachable(at(line, c))) above = c;
                const int below = row[c];
                if (above < 0) continue;
                if (below < 0 || above - c < c - below ||
                    (above - c == c - below && std::abs(above - ideal) < std::abs(below - ideal)))
                    row[c] = above;
            }
            // Every line between start and goal holds a reachable cell: a path must cross it.
        }
        snap_ = std::move(snap);
        lower_.assign(static_cast<std::size_t>(count_), 0.0);
        upper_.assign(static_cast<std::size_t>(count_), static_cast<double>(extent_ - 1));
    }

    template <class P>
    std::size_t dimension(const P&) const {
        return static_cast<std::size_t>(count_);
    }
    template <class P>
    std::span<const double> lower(const P&) const {
        return lower_;
    }
    template <class P>
    std::span<const double> upper(const P&) const {
        return upper_;
    }

    /// The waypoint a genotype puts on line k.
    Cell waypoint(std::span<const double> genotype, int k) const {
        const int c = detail::to_coordinate(genotype[static_cast<std::size_t>(k)], extent_);
        return at(first_ + k * step_, (*snap_)[static_cast<std::size_t>(k) * extent_ + c]);
    }

    template <class Objective>
    const DecodedPath& decode(const GridProblem<Objective>& p, std::span<const double> genotype) {
        detail::join_waypoints(
            p, count_, [&](int k) { return waypoint(genotype, k); }, connector_, out_, chain_, ends_);
        return out_;
    }

    /// Genotypes read off feasible walks (the problem's rule or random walks): each line's gene is
    /// where the walk first meets that line (the problem's suggestions for initialisers that
    /// accept them).
    template <class Objective>
    void starting_points(const GridProblem<Objective>& p, Rng& rng, Matrix& out) const {
        detail::read_walks(p, rng, out, [&](const Path& walk, Eigen::Index j) {
            for (int k = 0; k < count_; ++k) {
                const int line = first_ + k * step_;
                for (const Cell c : walk)
                    if ((rows_ ? c.y : c.x) == line) {
                        out(k, j) = rows_ ? c.x : c.y;
                        break;
                    }
            }
        });
    }

  private:
    Cell at(int line, int cross) const { return rows_ ? Cell{cross, line} : Cell{line, cross}; }

    bool rows_ = true;
    int first_ = 0, step_ = 1, count_ = 0, extent_ = 0;
    std::shared_ptr<const std::vector<int>> snap_;  // [line k][coordinate] -> snapped coordinate
    std::vector<double> lower_, upper_;
    Connector connector_{};
    DecodedPath out_;         // scratch: the decoded chain, valid until the next decode
    LoopFreeChain chain_;     // scratch: the raw chain and its loop cut
    std::vector<Cell> ends_;  // scratch: start, waypoints, goal
};

/// `free`: 2K genes, K waypoints (x, y) anywhere on the map. Decoding rounds each, snaps it to the
/// nearest cell reachable from the start (breadth-first over the 8 neighbours, ties to the cell
/// found first in row-major order), joins start, waypoints and goal with the Connector, and cuts
/// loops. Works where paths must go backwards (mazes).
template <class Connector = RepairConnector>
class FreeEncoding {
  public:
    template <class Objective>
    FreeEncoding(const GridProblem<Objective>& p, int waypoints, Connector connector = {})
        : k_(waypoints), connector_(std::move(connector)) {
        detail::prepare_walks(p);
        require(waypoints >= 1 && waypoints <= 1000, "waypoints",
                "must be in [1, 1000], got " + std::to_string(waypoints));
        const GridMap& m = p.map();
        auto nearest =
            std::make_shared<std::vector<std::uint32_t>>(m.size(), std::numeric_limits<std::uint32_t>::max());
        std::vector<std::size_t> queue;
        for (std::size_t i = 0; i < m.size(); ++i)
            if (p.reachable(m.cell(i))) {
                (*nearest)[i] = static_cast<std::uint32_t>(i);
                queue.push_back(i);
            }
        for (std::size_t head = 0; head < queue.size(); ++head) {
            const Cell c = m.cell(queue[head]);
            for (int d = 0; d < 8; ++d) {
                const Cell n{c.x + kDx[d], c.y + kDy[d]};
                if (!m.inside(n) || (*nearest)[m.index(n)] != std::numeric_limits<std::uint32_t>::max()) continue;
                (*nearest)[m.index(n)] = (*nearest)[queue[head]];
                queue.push_back(m.index(n));
            }
        }
        nearest_ = std::move(nearest);
        for (int k = 0; k < k_; ++k) {
            lower_.insert(lower_.end(), {0.0, 0.0});
            upper_.insert(upper_.end(), {m.width() - 1.0, m.height() - 1.0});
        }
    }

    template <class P>
    std::size_t dimension(const P&) const {
        return static_cast<std::size_t>(2 * k_);
    }
    template <class P>
    std::span<const double> lower(const P&) const {
        return lower_;
    }
    template <class P>
    std::span<const double> upper(const P&) const {
        return upper_;
    }

    template <class Objective>
    Cell waypoint(const GridProblem<Objective>& p, std::span<const double> genotype, int k) const {
        const GridMap& m = p.map();
        const Cell raw{detail::to_coordinate(genotype[2 * static_cast<std::size_t>(k)], m.width()),
                       detail::to_coordinate(genotype[2 * static_cast<std::size_t>(k) + 1], m.height())};
        return m.cell((*nearest_)[m.index(raw)]);
    }

    template <class Objective>
    const DecodedPath& decode(const GridProblem<Objective>& p, std::span<const double> genotype) {
        detail::join_waypoints(
            p, k_, [&](int k) { return waypoint(p, genotype, k); }, connector_, out_, chain_, ends_);
        return out_;
    }

    /// Genotypes read off feasible walks (the problem's rule or random walks): K cells sampled
    /// evenly along each walk.
    template <class Objective>
    void starting_points(const GridProblem<Objective>& p, Rng& rng, Matrix& out) const {
        detail::read_walks(p, rng, out, [&](const Path& walk, Eigen::Index j) {
            for (int k = 0; k < k_; ++k) {
                const std::size_t at =
                    (static_cast<std::size_t>(k) + 1) * (walk.size() - 1) / (static_cast<std::size_t>(k_) + 1);
                out(2 * k, j) = walk[at].x;
                out(2 * k + 1, j) = walk[at].y;
            }
        });
    }

  private:
    int k_;
    std::shared_ptr<const std::vector<std::uint32_t>> nearest_;  // cell -> nearest reachable cell
    std::vector<double> lower_, upper_;
    Connector connector_{};
    DecodedPath out_;
    LoopFreeChain chain_;
    std::vector<Cell> ends_;
};

}  // namespace pride::grid

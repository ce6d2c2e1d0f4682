#include "problems/grid/polyline.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "problems/grid/clearance.hpp"

namespace pride::grid {

Polyline polyline_of(const Path& chain) {
    Polyline out;
    out.reserve(chain.size());
    for (const Cell c : chain) out.push_back({static_cast<double>(c.x), static_cast<double>(c.y)});
    return out;
}

Polyline polyline_of(const std::vector<Point>& square) {
    Polyline out;
    out.reserve(square.size());
    for (const Point p : square) out.push_back({p.x - 0.5, p.y - 0.5});
    return out;
}

namespace {

double cross(double ax, double ay, double bx, double by) noexcept {
    return ax * by - ay * bx;
}

/// The point at arc length `arm` from vertex i along the path, backwards (step -1) or forwards
/// (+1), or the path's end when it is nearer than that.
PathPoint along(const Polyline& p, std::size_t i, int step, double arm) noexcept {
    double remaining = arm;
    std::size_t j = i;
    while (step < 0 ? j > 0 : j + 1 < p.size()) {
        const std::size_t k = step < 0 ? j - 1 : j + 1;
        const double dx = p[k].x - p[j].x, dy = p[k].y - p[j].y, len = std::hypot(dx, dy);
        if (len >= remaining) {  // remaining > 0 here, so len > 0
            const double t = remaining / len;
            return {p[j].x + t * dx, p[j].y + t * dy};
        }
        remaining -= len;
        j = k;
    }
    return p[j];
}

/// The Menger curvature of p0, v, p2 (the inverse radius of the circle through them), with the
/// limit circle of diameter min(|p0 v|, |v p2|) when p2 folds back onto the ray v -> p0.
double menger(PathPoint p0, PathPoint v, PathPoint p2) noexcept {
    const double ux = v.x - p0.x, uy = v.y - p0.y, wx = p2.x - v.x, wy = p2.y - v.y;
    const double a = std::hypot(ux, uy), b = std::hypot(wx, wy);
    // An arm that comes back to v exactly (a loop shorter than the arm): no circle. The vertex
    // where that loop reverses is a turn of its own and is measured there.
    if (a == 0.0 || b == 0.0) return 0.0;
    const double cr = cross(ux, uy, wx, wy);
    if (std::abs(cr) <= kCollinearRadians * a * b) {
        if (ux * wx + uy * wy < 0.0) return 2.0 / std::min(a, b);  // folded back: a reversal
        return 0.0;                                                // straight through
    }
    const double c = std::hypot(p2.x - p0.x, p2.y - p0.y);
    return 2.0 * std::abs(cr) / (a * b * c);
}

/// The clearance integral over the straight runs between the path's corners (ends and turn
/// vertices), fed one corner at a time.
class ClearanceSampler {
  public:
    ClearanceSampler(const PolylineScorer& scorer, PathPoint start) : scorer_(scorer), corner_(start) {
        last_ = min_ = *scorer.clearance(start);
    }
    void run_to(PathPoint b) {
        const double dx = b.x - corner_.x, dy = b.y - corner_.y, len = std::hypot(dx, dy);
        if (len > 0.0) {
            const double n = std::max(1.0, std::ceil(len / kClearanceSpacing));
            const double step = len / n;
            for (double k = 1.0; k <= n; k += 1.0) {
                // The last sample is b itself (no rounding drift into the next run).
                const PathPoint q = k == n ? b : PathPoint{corner_.x + (k / n) * dx, corner_.y + (k / n) * dy};
                const double c = *scorer_.clearance(q);
                integral_ += 0.5 * (last_ + c) * step;
                min_ = std::min(min_, c);
                last_ = c;
            }
            total_ += len;
        }
        corner_ = b;
    }
    double min() const noexcept { return min_; }
    double mean() const noexcept { return total_ > 0.0 ? integral_ / total_ : last_; }

  private:
    const PolylineScorer& scorer_;
    PathPoint corner_;
    double last_ = 0, min_ = 0, integral_ = 0, total_ = 0;
};

PolylineMetrics score_path(const Polyline& p, const PolylineScorer* scorer) {
    PolylineMetrics m;
    if (p.empty()) return m;
    std::optional<ClearanceSampler> sampler;
    if (scorer && scorer->has_obstacles()) sampler.emplace(*scorer, p.front());
    double total_rad = 0, max_rad = 0, total_deg = 0;
    // Each turn in degrees rounded to 1e-9: a chain's turns are then exact multiples of 45 and
    // their sum equals metrics().turn_angle_deg exactly (a sum of radians converted once gave
    // 720.0000000000002 for 16 turns).
    constexpr double kDeg = 180.0 / std::numbers::pi;
    const auto degrees = [](double rad) { return std::round(rad * kDeg * 1e9) / 1e9; };
    double px = 0, py = 0;  // the last non-zero segment
    bool has_previous = false;
    for (std::size_t i = 1; i < p.size(); ++i) {
        const double dx = p[i].x - p[i - 1].x, dy = p[i].y - p[i - 1].y, len = std::hypot(dx, dy);
        if (len == 0.0) continue;
        m.length += len;
        if (has_previous) {
            const double turn = std::atan2(std::abs(cross(px, py, dx, dy)), px * dx + py * dy);
            if (turn > kCollinearRadians) {
                ++m.turns;
                total_rad += turn;
                total_deg += degrees(turn);
                max_rad = std::max(max_rad, turn);
                const PathPoint v = p[i - 1];
                m.max_curvature = std::max(
                    m.max_curvature, menger(along(p, i - 1, -1, kCurvatureArm), v, along(p, i - 1, +1, kCurvatureArm)));
                if (sampler) sampler->run_to(v);
            }
        }
        px = dx;
        py = dy;
        has_previous = true;
    }
    m.total_turn_deg = total_deg;
    m.max_turn_deg = degrees(max_rad);
    m.angle_over_length = m.length > 0.0 ? total_rad / m.length : 0.0;
    if (sampler) {
        sampler->run_to(p.back());
        m.min_clearance = sampler->min();
        m.mean_clearance = sampler->mean();
    }
    return m;
}

}  // namespace

PolylineScorer::PolylineScorer(const GridMap& map)
    : width_(map.width()), height_(map.height()), d2_(squared_distance_transform(map)) {
    has_obstacles_ = !d2_.empty() && d2_.front() != kNoObstacle;
}

PolylineMetrics PolylineScorer::score(const Polyline& path) const {
    return score_path(path, this);
}

PolylineMetrics polyline_metrics(const Polyline& path) {
    return score_path(path, nullptr);
}

std::optional<double> PolylineScorer::clearance(PathPoint p) const {
    if (!has_obstacles_) return std::nullopt;
    return clearance_unchecked(p);
}

double PolylineScorer::clearance_unchecked(PathPoint p) const noexcept {
    // c: the map cell nearest p (p's own cell when p is inside), e = |p - c|. With D the distance
    // from c to the nearest blocked centre b*, the answer T is at most |p - b*| <= D + e; and a
    // blocked square at centre b is at least |c - b| - e - r from p (r = sqrt(1/2), half its
    // diagonal). So the nearest lies within |c - b| <= min(D + e, best so far) + e + r, and no
    // blocked centre is nearer c than D: only that annulus is scanned, rows nearest c first so that
    // the best so far tightens the rest.
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return std::numeric_limits<double>::quiet_NaN();
    const int cx = static_cast<int>(std::clamp(std::floor(p.x + 0.5), 0.0, width_ - 1.0));
    const int cy = static_cast<int>(std::clamp(std::floor(p.y + 0.5), 0.0, height_ - 1.0));
    const double e = std::hypot(p.x - cx, p.y - cy);
    const std::int64_t inner2 = d2_[static_cast<std::size_t>(cy) * static_cast<std::size_t>(width_) + cx];
    const double bound = std::sqrt(static_cast<double>(inner2)) + e;
    constexpr double kHalfDiagonal = 0.70710678118654757;
    constexpr double kSlack = 1e-7;  // scanning a cell too many costs nothing; one too few would
    double best = std::numeric_limits<double>::infinity();
    for (int t = 0;; ++t) {
        const int dy = (t & 1) ? (t + 1) / 2 : -(t / 2);  // 0, 1, -1, 2, -2, ...
        const double reach = std::min(bound, best) + e + kHalfDiagonal + kSlack;
        // Done beyond the reach, or once both rows are off the map (p may be far outside it).
        if (std::abs(dy) > reach || (cy + std::abs(dy) >= height_ && cy - std::abs(dy) < 0)) break;
        const int y = cy + dy;
        if (y < 0 || y >= height_) continue;
        const std::int64_t dy2 = std::int64_t{dy} * dy;
        const auto outer = static_cast<std::int64_t>(
            std::min(std::floor(std::sqrt(std::max(0.0, reach * reach - dy2))), static_cast<double>(width_)));
        std::int64_t in = 0;  // the least |dx| with dx^2 + dy^2 >= inner2
        if (inner2 > dy2) {
            in = static_cast<std::int64_t>(std::sqrt(static_cast<double>(inner2 - dy2)));
            while (in * in < inner2 - dy2) ++in;
            while (in > 0 && (in - 1) * (in - 1) >= inner2 - dy2) --in;
        }
        if (in > outer) continue;
        const std::int64_t* row = d2_.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(width_);
        const double ey = std::max(std::abs(p.y - y) - 0.5, 0.0);
        const auto scan = [&](std::int64_t from, std::int64_t to) {
            from = std::max<std::int64_t>(from, 0);
            to = std::min<std::int64_t>(to, width_ - 1);
            for (std::int64_t x = from; x <= to; ++x)
                if (row[x] == 0) best = std::min(best, std::hypot(std::max(std::abs(p.x - x) - 0.5, 0.0), ey));
        };
        if (in == 0) {
            scan(cx - outer, cx + outer);
        } else {
            scan(cx - outer, cx - in);
            scan(cx + in, cx + outer);
        }
    }
    return best;
}

}  // namespace pride::grid

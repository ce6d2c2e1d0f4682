#pragma once
// Empirical attainment surfaces of two objectives (Fonseca and Fleming 1996, "On the performance
// assessment and comparison of stochastic multiobjective optimizers", PPSN IV; Grunert da Fonseca,
// Fonseca and Hall 2001, "Inferential performance assessment of stochastic optimisers and the
// attainment function", EMO 2001), every objective minimised.
//
// n runs give n sets A_1..A_n. A point z is attained by a run when one of its points weakly
// dominates z. The k-th attainment surface (1 <= k <= n) bounds the points attained by at least k
// runs: at f1 = x, run i reaches down to b_i(x) = min { a_2 : a in A_i, a_1 <= x }, and the
// surface is at y_k(x), the k-th smallest of the b_i(x). It is a staircase; this returns its
// corners, the points (x, y_k(x)) where y_k drops, in increasing x (decreasing y). Each corner is
// attained by at least k runs, and every point attained by at least k runs is weakly dominated by a
// corner. k = 1 is the best surface (the runs' union, non-dominated), k = n the worst (what every
// run attained), k = ceil(n / 2) the median surface, ceil(n / 4) and ceil(3 n / 4) the quartiles.
//
// A sweep over the points in increasing f1 (ties: increasing f2): O(N log N + N n) for N points
// in all, the k-th smallest found by selection among the n current values.
#include <algorithm>
#include <cstddef>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "framework/error.hpp"
#include "framework/problem.hpp"

namespace pride::pareto {

/// The corners of the k-th attainment surface of `runs` (each a 2 x n_i matrix, one point per
/// column; a run may be empty, then it attains nothing), as a 2 x m matrix in increasing f1.
/// InputError unless every set has two objectives and no NaN and 1 <= k <= runs.size().
inline Matrix attainment_surface(const std::vector<Matrix>& runs, std::size_t k) {
    const std::size_t n = runs.size();
    require(n >= 1, "attainment_surface", "needs at least one run");
    require(k >= 1 && k <= n, "attainment_surface",
            "k must be in [1, " + std::to_string(n) + "], got " + std::to_string(k));
    struct Point {
        double x, y;
        std::size_t run;
    };
    std::vector<Point> points;
    for (std::size_t i = 0; i < n; ++i) {
        const Matrix& a = runs[i];
        require(a.cols() == 0 || a.rows() == 2, "attainment_surface",
                "run " + std::to_string(i) + " has " + std::to_string(a.rows()) +
                    " objectives; attainment surfaces here are of two");
        require(!a.hasNaN(), "attainment_surface", "run " + std::to_string(i) + " has a NaN objective value");
        for (Eigen::Index j = 0; j < a.cols(); ++j) points.push_back({a(0, j), a(1, j), i});
    }
    std::sort(points.begin(), points.end(),
              [](const Point& p, const Point& q) { return p.x < q.x || (p.x == q.x && p.y < q.y); });
    constexpr double none = std::numeric_limits<double>::infinity();
    std::vector<double> best(n, none), scratch(n);
    std::vector<std::pair<double, double>> corners;
    double last = none;
    for (std::size_t s = 0; s < points.size();) {
        // Every point of this f1 first: the surface is read once per distinct x.
        const double x = points[s].x;
        for (; s < points.size() && points[s].x == x; ++s)
            best[points[s].run] = std::min(best[points[s].run], points[s].y);
        scratch = best;
        std::nth_element(scratch.begin(), scratch.begin() + static_cast<std::ptrdiff_t>(k - 1), scratch.end());
        const double y = scratch[k - 1];
        if (y < last) {
            corners.emplace_back(x, y);
            last = y;
        }
    }
    Matrix out(2, static_cast<Eigen::Index>(corners.size()));
    for (std::size_t c = 0; c < corners.size(); ++c) {
        out(0, static_cast<Eigen::Index>(c)) = corners[c].first;
        out(1, static_cast<Eigen::Index>(c)) = corners[c].second;
    }
    return out;
}

}  // namespace pride::pareto

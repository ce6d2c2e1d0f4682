// framework/pareto/: dominance, non-dominated sorting and crowding, the hypervolume
// (2-D and 3-D sweeps, WFG) and its contributions, IGD, IGD+, GD, GD+ and the additive epsilon
// indicator. Hand-computed sets (the arithmetic in comments), an independent oracle
// (inclusion-exclusion over all subsets), the algorithms against each other, and properties.
#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <numeric>
#include <span>
#include <vector>

#include "framework/error.hpp"
#include "framework/pareto/dominance.hpp"
#include "framework/pareto/hypervolume.hpp"
#include "framework/pareto/indicators.hpp"
#include "framework/pareto/sorting.hpp"
#include "framework/problem.hpp"
#include "framework/random.hpp"

namespace {

using pride::Matrix;
namespace pp = pride::pareto;

/// A set given point by point: one column per point.
Matrix points(std::initializer_list<std::initializer_list<double>> list) {
    const auto m = static_cast<Eigen::Index>(list.begin()->size());
    Matrix f(m, static_cast<Eigen::Index>(list.size()));
    Eigen::Index j = 0;
    for (const auto& p : list) {
        Eigen::Index i = 0;
        for (const double v : p) f(i++, j) = v;
        ++j;
    }
    return f;
}

/// Uniform in [0, 1)^M.
Matrix cloud(pride::Rng& rng, Eigen::Index m, Eigen::Index n) {
    Matrix f(m, n);
    for (Eigen::Index j = 0; j < n; ++j)
        for (Eigen::Index i = 0; i < m; ++i) f(i, j) = rng.uniform();
    return f;
}

/// Values k / levels, k in [0, levels]: many ties and equal points.
Matrix grid_cloud(pride::Rng& rng, Eigen::Index m, Eigen::Index n, std::uint64_t levels) {
    Matrix f(m, n);
    for (Eigen::Index j = 0; j < n; ++j)
        for (Eigen::Index i = 0; i < m; ++i)
            f(i, j) = static_cast<double>(rng.below(levels + 1)) / static_cast<double>(levels);
    return f;
}

/// Points on the positive part of the unit sphere: mutually non-dominated.
Matrix sphere_front(pride::Rng& rng, Eigen::Index m, Eigen::Index n) {
    Matrix f(m, n);
    for (Eigen::Index j = 0; j < n; ++j) {
        for (Eigen::Index i = 0; i < m; ++i) f(i, j) = std::abs(rng.normal()) + 1e-3;
        f.col(j) /= f.col(j).norm();
    }
    return f;
}

/// The oracle: HV = sum over non-empty subsets T of the points strictly dominating r of
/// (-1)^(|T|+1) prod_i (r_i - max_{p in T} p_i): exact inclusion-exclusion over the boxes.
double hv_inclusion_exclusion(const Matrix& f, const std::vector<double>& r) {
    std::vector<Eigen::Index> in;
    for (Eigen::Index j = 0; j < f.cols(); ++j) {
        bool inside = true;
        for (Eigen::Index i = 0; i < f.rows(); ++i) inside = inside && f(i, j) < r[static_cast<std::size_t>(i)];
        if (inside) in.push_back(j);
    }
    const std::size_t n = in.size();
    REQUIRE(n <= 16);
    double total = 0.0;
    std::vector<double> join(static_cast<std::size_t>(f.rows()));
    for (std::uint32_t mask = 1; mask < (std::uint32_t{1} << n); ++mask) {
        std::fill(join.begin(), join.end(), -std::numeric_limits<double>::infinity());
        for (std::size_t k = 0; k < n; ++k)
            if (mask >> k & 1u)
                for (Eigen::Index i = 0; i < f.rows(); ++i)
                    join[static_cast<std::size_t>(i)] = std::max(join[static_cast<std::size_t>(i)], f(i, in[k]));
        double volume = 1.0;
        for (std::size_t i = 0; i < join.size(); ++i) volume *= r[i] - join[i];
        total += (std::popcount(mask) % 2 == 1 ? 1.0 : -1.0) * volume;
    }
    return total;
}

/// f without column j.
Matrix without(const Matrix& f, Eigen::Index j) {
    Matrix g(f.rows(), f.cols() - 1);
    for (Eigen::Index k = 0, c = 0; k < f.cols(); ++k)
        if (k != j) g.col(c++) = f.col(k);
    return g;
}

std::vector<std::size_t> ranks(const Matrix& f, bool fast) {
    std::vector<std::size_t> rank(static_cast<std::size_t>(f.cols()));
    pp::SortScratch scratch;
    if (fast)
        pp::detail::nondominated_sort_2d(f, rank, scratch);
    else
        pp::detail::nondominated_sort_deb(f, rank, scratch);
    return rank;
}

}  // namespace

TEST_CASE("pareto: dominance and the non-dominated columns of hand-made sets", "[pareto]") {
    const std::vector<double> a{1, 2}, b{1, 3}, c{2, 1}, d{1, 2};
    CHECK(pp::dominates(a, b));
    CHECK_FALSE(pp::dominates(b, a));
    CHECK_FALSE(pp::dominates(a, c));  // incomparable
    CHECK_FALSE(pp::dominates(c, a));
    CHECK_FALSE(pp::dominates(a, d));  // equal: weakly only
    CHECK(pp::weakly_dominates(a, d));
    CHECK(pp::weakly_dominates(a, b));
    CHECK_FALSE(pp::weakly_dominates(b, a));
    CHECK_FALSE(pp::weakly_dominates(a, c));

    // Columns 0 and 3 are equal (keep 0); 1 is dominated by 0; 4 by 2; 5 is incomparable with all.
    const Matrix f = points({{1, 2}, {1, 3}, {2, 1}, {1, 2}, {3, 1}, {0, 9}});
    CHECK(pp::nondominated(f) == std::vector<std::size_t>{0, 2, 5});
    // Equal points, the later one first: still the first index kept.
    CHECK(pp::nondominated(points({{2, 2, 2}, {1, 1, 1}, {1, 1, 1}, {3, 0, 3}})) == std::vector<std::size_t>{1, 3});
    CHECK(pp::nondominated(Matrix(3, 0)).empty());

    // Against the definition on random sets with ties, M = 2, 3, 5.
    pride::Rng rng(11);
    for (const Eigen::Index m : {2, 3, 5})
        for (int trial = 0; trial < 20; ++trial) {
            const Matrix g = grid_cloud(rng, m, 40, 3);
            std::vector<std::size_t> expected;
            for (Eigen::Index j = 0; j < g.cols(); ++j) {
                bool kept = true;
                for (Eigen::Index k = 0; k < g.cols() && kept; ++k)
                    kept = !(pp::dominates(pp::point(g, k), pp::point(g, j)) ||
                             (k < j && pp::weakly_dominates(pp::point(g, k), pp::point(g, j))));
                if (kept) expected.push_back(static_cast<std::size_t>(j));
            }
            CHECK(pp::nondominated(g) == expected);
        }
}

TEST_CASE("pareto: hypervolume and contributions of hand-computed sets in 2, 3 and 5 objectives", "[pareto]") {
    SECTION("2-D") {
        // Staircase (1,3), (2,2), (3,1) under r = (4,4), strips in increasing f1:
        // (4-1)(4-3) + (4-2)(3-2) + (4-3)(2-1) = 3 + 2 + 1 = 6. (3,3) is dominated, (5,0) and
        // (0,4) do not strictly dominate r (4 is not < 4): 6 still.
        const std::vector<double> r{4, 4};
        CHECK(pp::hypervolume(points({{1, 3}, {2, 2}, {3, 1}}), r) == 6.0);
        const Matrix f = points({{3, 3}, {1, 3}, {5, 0}, {2, 2}, {0, 4}, {3, 1}});
        CHECK(pp::hypervolume(f, r) == 6.0);
        // Each step alone: (2-1)(4-3) = 1, (3-2)(3-2) = 1, (4-3)(2-1) = 1; (3,3) is dominated:
        // removing it changes nothing.
        CHECK(pp::contributions(f, r) == std::vector<double>{0, 1, 0, 1, 0, 1});
        // A dominated point shows once its dominator is gone: (1,1) alone covers (3-1)(3-1) = 4,
        // of which (2,2) covers (3-2)(3-2) = 1 too, so (1,1) contributes 3.
        CHECK(pp::contributions(points({{1, 1}, {2, 2}}), std::vector<double>{3, 3}) == std::vector<double>{3, 0});
        // Equal points: removing either leaves the other, so both contribute 0; (2,1) alone covers
        // [2,3) x [1,2): 1.
        CHECK(pp::contributions(points({{1, 2}, {1, 2}, {2, 1}}), std::vector<double>{3, 3}) ==
              std::vector<double>{0, 0, 1});
    }
    SECTION("3-D") {
        // a = (1,2,3), b = (2,3,1), c = (3,1,2), r = (4,4,4). Boxes: 3*2*1 = 6 each. Pairwise joins:
        // a v b = (2,3,3): 2*1*1 = 2; a v c = (3,2,3): 1*2*1 = 2; b v c = (3,3,2): 1*1*2 = 2.
        // a v b v c = (3,3,3): 1. HV = 18 - 6 + 1 = 13. Without a: 6 + 6 - 2 = 10, so each point
        // contributes 13 - 10 = 3.
        const Matrix f = points({{1, 2, 3}, {2, 3, 1}, {3, 1, 2}});
        const std::vector<double> r{4, 4, 4};
        CHECK(pp::hypervolume(f, r) == 13.0);
        CHECK(pp::detail::hypervolume_with_base(f, r, 2) == 13.0);
        CHECK(pp::contributions(f, r) == std::vector<double>{3, 3, 3});
        // (2,3,3) is dominated by a, (4,1,1) is on r's face: 13 still; (1,1,1) dominates all:
        // its box (4-1)^3 = 27.
        CHECK(pp::hypervolume(points({{1, 2, 3}, {2, 3, 1}, {2, 3, 3}, {3, 1, 2}, {4, 1, 1}}), r) == 13.0);
        CHECK(pp::hypervolume(points({{1, 2, 3}, {1, 1, 1}, {3, 1, 2}}), r) == 27.0);
    }
    SECTION("5-D") {
        // r = (6,6,6,6,6); p1 = (1,2,3,4,5): box 5*4*3*2*1 = 120; p2 = (5,4,3,2,1): 120;
        // p3 = (3,3,3,3,3): 3^5 = 243. Joins: p1 v p2 = (5,4,3,4,5): 1*2*3*2*1 = 12;
        // p1 v p3 = (3,3,3,4,5): 3*3*3*2*1 = 54; p2 v p3 = (5,4,3,3,3): 1*2*3*3*3 = 54;
        // p1 v p2 v p3 = (5,4,3,4,5): 12. HV = 483 - 120 + 12 = 375.
        // Without p1: 120 + 243 - 54 = 309 (contribution 66); without p2: 309 (66); without p3:
        // 120 + 120 - 12 = 228 (147).
        const Matrix f = points({{1, 2, 3, 4, 5}, {5, 4, 3, 2, 1}, {3, 3, 3, 3, 3}});
        const std::vector<double> r(5, 6.0);
        CHECK(pp::hypervolume(f, r) == 375.0);
        CHECK(pp::detail::hypervolume_with_base(f, r, 2) == 375.0);
        CHECK(pp::contributions(f, r) == std::vector<double>{66, 66, 147});
        // p1 and p2 alone: 240 - 12 = 228.
        CHECK(pp::hypervolume(points({{1, 2, 3, 4, 5}, {5, 4, 3, 2, 1}}), r) == 228.0);
    }
    SECTION("1-D and empty sets") {
        // M = 1: r - min = 5 - 1 = 4; the minimum contributes 2 - 1 = 1 (the next point up).
        CHECK(pp::hypervolume(points({{3}, {1}, {2}}), std::vector<double>{5}) == 4.0);
        CHECK(pp::contributions(points({{3}, {1}, {2}}), std::vector<double>{5}) == std::vector<double>{0, 1, 0});
        CHECK(pp::hypervolume(Matrix(3, 0), std::vector<double>{1, 1, 1}) == 0.0);
        CHECK(pp::hypervolume(points({{2, 2, 2, 2}}), std::vector<double>{1, 1, 1, 1}) == 0.0);
    }
}

TEST_CASE("pareto: hypervolume equals inclusion-exclusion over all subsets", "[pareto]") {
    pride::Rng rng(2024);
    for (const Eigen::Index m : {2, 3, 5})
        for (int trial = 0; trial < 30; ++trial) {
            const Eigen::Index n = 1 + static_cast<Eigen::Index>(rng.below(12));
            // Half the trials on a grid (ties, equal points), half continuous; r cuts some points off.
            const Matrix f = trial % 2 == 0 ? cloud(rng, m, n) : grid_cloud(rng, m, n, 4);
            const std::vector<double> r(static_cast<std::size_t>(m), 0.9);
            const double expected = hv_inclusion_exclusion(f, r);
            INFO("M = " << m << ", N = " << n << ", trial " << trial);
            CHECK(pp::hypervolume(f, r) == Approx(expected).epsilon(1e-10).margin(1e-14));
            CHECK(pp::detail::hypervolume_with_base(f, r, 2) == Approx(expected).epsilon(1e-10).margin(1e-14));
        }
}

TEST_CASE("pareto: the 3-D sweep equals WFG on random fronts of up to 300 points", "[pareto]") {
    pride::Rng rng(7);
    for (const Eigen::Index n : {1, 2, 10, 50, 150, 300}) {
        const Matrix front = sphere_front(rng, 3, n);
        const Matrix mixed = cloud(rng, 3, n);
        const std::vector<double> r{1.1, 1.1, 1.1};
        INFO("N = " << n);
        const double sweep = pp::hypervolume(front, r);
        CHECK(sweep > 0.0);
        CHECK(sweep == Approx(pp::detail::hypervolume_with_base(front, r, 2)).epsilon(1e-12));
        CHECK(pp::hypervolume(mixed, r) == Approx(pp::detail::hypervolume_with_base(mixed, r, 2)).epsilon(1e-12));
    }
    // WFG over 4 and 5 objectives: its 3-D base case against recursing down to 2-D.
    for (const Eigen::Index m : {4, 5}) {
        const Matrix front = sphere_front(rng, m, 60);
        const std::vector<double> r(static_cast<std::size_t>(m), 1.0);
        CHECK(pp::hypervolume(front, r) == Approx(pp::detail::hypervolume_with_base(front, r, 2)).epsilon(1e-12));
    }
}

TEST_CASE("pareto: contributions equal hypervolume differences", "[pareto]") {
    pride::Rng rng(99);
    for (const Eigen::Index m : {1, 2, 3, 4, 5})
        for (int trial = 0; trial < 12; ++trial) {
            const Eigen::Index n = 1 + static_cast<Eigen::Index>(rng.below(25));
            // Fronts, clouds (dominated points) and grids (equal points).
            const Matrix f = trial % 3 == 0   ? sphere_front(rng, m, n)
                             : trial % 3 == 1 ? cloud(rng, m, n)
                                              : grid_cloud(rng, m, n, 3);
            const std::vector<double> r(static_cast<std::size_t>(m), 1.0);
            const double total = pp::hypervolume(f, r);
            const std::vector<double> c = pp::contributions(f, r);
            REQUIRE(c.size() == static_cast<std::size_t>(n));
            for (Eigen::Index j = 0; j < n; ++j) {
                INFO("M = " << m << ", N = " << n << ", trial " << trial << ", point " << j);
                CHECK(c[static_cast<std::size_t>(j)] >= 0.0);
                CHECK(c[static_cast<std::size_t>(j)] ==
                      Approx(total - pp::hypervolume(without(f, j), r)).margin(1e-12 * std::max(1.0, total)));
            }
        }
}

TEST_CASE("pareto: hypervolume is invariant to order, dominated and equal points, and scales", "[pareto]") {
    pride::Rng rng(5);
    for (const Eigen::Index m : {2, 3, 4, 5}) {
        const Matrix f = sphere_front(rng, m, 40);
        const std::vector<double> r(static_cast<std::size_t>(m), 1.2);
        const double hv = pp::hypervolume(f, r);
        INFO("M = " << m);
        // A permutation of the columns.
        std::vector<Eigen::Index> perm(static_cast<std::size_t>(f.cols()));
        std::iota(perm.begin(), perm.end(), Eigen::Index{0});
        for (std::size_t k = perm.size() - 1; k > 0; --k) std::swap(perm[k], perm[rng.below(k + 1)]);
        Matrix shuffled(f.rows(), f.cols());
        for (Eigen::Index j = 0; j < f.cols(); ++j) shuffled.col(j) = f.col(perm[static_cast<std::size_t>(j)]);
        CHECK(pp::hypervolume(shuffled, r) == Approx(hv).epsilon(1e-13));
        if (m <= 3) CHECK(pp::hypervolume(shuffled, r) == hv);  // the sweeps sort fully: same bits
        // Dominated points (each column pushed up) and copies of some columns.
        Matrix more(f.rows(), f.cols() + 30);
        more.leftCols(f.cols()) = f;
        for (Eigen::Index j = 0; j < 20; ++j)
            more.col(f.cols() + j) = f.col(j) + Eigen::VectorXd::Constant(m, 0.05 * rng.uniform());
        for (Eigen::Index j = 20; j < 30; ++j) more.col(f.cols() + j) = f.col(j);
        CHECK(pp::hypervolume(more, r) == Approx(hv).epsilon(1e-13));
        // Objective 0 (and r_0) scaled by 3: the volume too.
        Matrix scaled = f;
        scaled.row(0) *= 3.0;
        std::vector<double> scaled_r = r;
        scaled_r[0] *= 3.0;
        CHECK(pp::hypervolume(scaled, scaled_r) == Approx(3.0 * hv).epsilon(1e-13));
        // A larger reference point gives a larger volume.
        CHECK(pp::hypervolume(f, std::vector<double>(static_cast<std::size_t>(m), 1.3)) > hv);
    }
}

TEST_CASE("pareto: IGD, IGD+, GD, GD+ and epsilon of hand-computed sets", "[pareto]") {
    SECTION("2-D") {
        // Z = {(0,1), (1,0)}, A = {(0.5,0.5)}. d(z, a) = sqrt(0.25 + 0.25) = sqrt(0.5) for both z:
        // IGD = GD = sqrt(0.5). d+((0,1), a) = sqrt(0.5^2 + 0) = 0.5, and the same for (1,0):
        // IGD+ = GD+ = 0.5. eps: max_i(a_i - z_i) = max(0.5, -0.5) = 0.5 for both z: 0.5.
        const Matrix z = points({{0, 1}, {1, 0}});
        const Matrix a = points({{0.5, 0.5}});
        CHECK(pp::igd(a, z) == Approx(std::sqrt(0.5)));
        CHECK(pp::gd(a, z) == Approx(std::sqrt(0.5)));
        CHECK(pp::igd_plus(a, z) == 0.5);
        CHECK(pp::gd_plus(a, z) == 0.5);
        CHECK(pp::epsilon_additive(a, z) == 0.5);
        // A = {(0,2), (3,0)}: from (0,1) the nearest is (0,2), at 1; from (1,0) it is (3,0), at 2:
        // IGD = 1.5. d+ from (0,1): (0,2) -> 1, (3,0) -> 3; from (1,0): (0,2) -> 2, (3,0) -> 2:
        // IGD+ = (1 + 2) / 2 = 1.5. GD: (0,2) is 1 from (0,1), (3,0) is 2 from (1,0): 1.5.
        // eps: (0,1) needs min(max(0,1), max(3,-1)) = 1, (1,0) needs min(max(-1,2), max(2,0)) = 2: 2.
        const Matrix b = points({{0, 2}, {3, 0}});
        CHECK(pp::igd(b, z) == 1.5);
        CHECK(pp::igd_plus(b, z) == 1.5);
        CHECK(pp::gd(b, z) == 1.5);
        CHECK(pp::epsilon_additive(b, z) == 2.0);
        // A point better than Z: eps < 0 and IGD+ = 0 (nothing worse), IGD > 0.
        const Matrix c = points({{-1, -1}});
        CHECK(pp::epsilon_additive(c, z) == -1.0);  // max over z of max(-1 - 0, -1 - 1) = -1
        CHECK(pp::igd_plus(c, z) == 0.0);
        CHECK(pp::igd(c, z) == Approx(std::sqrt(5.0)));  // |(-1,-1) - (0,1)| = sqrt(1 + 4)
    }
    SECTION("3-D") {
        // Z = the unit vectors; A = {(1,1,1)}: d = sqrt(0 + 1 + 1) = sqrt(2) from each, and d+ the
        // same (a is worse in the two objectives where z is 0): IGD = IGD+ = GD = sqrt(2);
        // eps = max_i(a_i - z_i) = 1 - 0 = 1.
        const Matrix z = points({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
        const Matrix a = points({{1, 1, 1}});
        CHECK(pp::igd(a, z) == Approx(std::sqrt(2.0)));
        CHECK(pp::igd_plus(a, z) == Approx(std::sqrt(2.0)));
        CHECK(pp::gd(a, z) == Approx(std::sqrt(2.0)));
        CHECK(pp::epsilon_additive(a, z) == 1.0);
        // A = {(0,0,0)}, which dominates Z: IGD = 1 (distance 1 to each), IGD+ = GD+ = 0, eps =
        // max_z max_i(0 - z_i) = 0 (each z has a 0).
        const Matrix o = points({{0, 0, 0}});
        CHECK(pp::igd(o, z) == 1.0);
        CHECK(pp::igd_plus(o, z) == 0.0);
        CHECK(pp::gd_plus(o, z) == 0.0);
        CHECK(pp::epsilon_additive(o, z) == 0.0);
    }
    SECTION("5-D") {
        // Z = {(1,1,1,1,1)}; A = {(2,1,1,1,0), (1,1,1,1,3)}. d: sqrt(1 + 1) = sqrt(2) and 2: IGD =
        // sqrt(2). d+: sqrt(1) = 1 (the 0 is better) and 2: IGD+ = 1. GD = (sqrt(2) + 2) / 2;
        // GD+ = (1 + 2) / 2 = 1.5. eps: min(max(1, 0, 0, 0, -1), max(0, 0, 0, 0, 2)) = 1.
        const Matrix z = points({{1, 1, 1, 1, 1}});
        const Matrix a = points({{2, 1, 1, 1, 0}, {1, 1, 1, 1, 3}});
        CHECK(pp::igd(a, z) == Approx(std::sqrt(2.0)));
        CHECK(pp::igd_plus(a, z) == 1.0);
        CHECK(pp::gd(a, z) == Approx((std::sqrt(2.0) + 2.0) / 2.0));
        CHECK(pp::gd_plus(a, z) == 1.5);
        CHECK(pp::epsilon_additive(a, z) == 1.0);
    }
}

TEST_CASE("pareto: IGD+ <= IGD, a set against itself scores 0, and eps shifts exactly", "[pareto]") {
    pride::Rng rng(31);
    for (const Eigen::Index m : {2, 3, 5})
        for (int trial = 0; trial < 10; ++trial) {
            const Matrix z = sphere_front(rng, m, 50);
            const Matrix a = trial % 2 == 0 ? cloud(rng, m, 30) : grid_cloud(rng, m, 30, 3);
            INFO("M = " << m << ", trial " << trial);
            CHECK(pp::igd_plus(a, z) <= pp::igd(a, z));
            CHECK(pp::gd_plus(a, z) <= pp::gd(a, z));
            CHECK(pp::igd(a, z) > 0.0);
            // Against itself, dominated points included: 0 exactly.
            CHECK(pp::igd(a, a) == 0.0);
            CHECK(pp::igd_plus(a, a) == 0.0);
            CHECK(pp::gd(a, a) == 0.0);
            CHECK(pp::epsilon_additive(a, a) == 0.0);
            // Z moved up by 0.25 in every objective: eps(Z + 0.25, Z) = 0.25, the shift that brings
            // each moved point back onto its original (no point of a front is strictly better than
            // another, so no smaller shift will do); the other way round, -0.25.
            const Matrix up = (z.array() + 0.25).matrix();
            CHECK(pp::epsilon_additive(up, z) == Approx(0.25));
            CHECK(pp::epsilon_additive(z, up) == Approx(-0.25));
        }
}

TEST_CASE("pareto: non-dominated sort of a hand-made set", "[pareto]") {
    // (1,4), (2,2), (4,1) and the copy of (2,2) are non-dominated: front 0. (3,3) is dominated by
    // (2,2) only: front 1. (4,4) is dominated by (3,3): front 2. (5,5): front 3.
    const Matrix f = points({{1, 4}, {2, 2}, {4, 1}, {3, 3}, {4, 4}, {2, 2}, {5, 5}});
    const std::vector<std::size_t> expected{0, 0, 0, 1, 2, 0, 3};
    for (const bool fast : {false, true}) CHECK(ranks(f, fast) == expected);
    std::vector<std::size_t> rank(7);
    pp::SortScratch scratch;
    CHECK(pp::nondominated_sort(f, rank, scratch) == 4);
    CHECK(rank == expected);
    // The same in 3-D, a constant third objective: the general algorithm.
    Matrix g(3, f.cols());
    g.topRows(2) = f;
    g.row(2).setConstant(1.0);
    CHECK(pp::nondominated_sort(g, rank, scratch) == 4);
    CHECK(rank == expected);
    CHECK(pp::nondominated_sort(Matrix(2, 0), std::span<std::size_t>(), scratch) == 0);
    CHECK(pp::nondominated_sort(Matrix(3, 0), std::span<std::size_t>(), scratch) == 0);
}

TEST_CASE("pareto: the two-objective sort gives Deb's ranks on sets with ties and equal points", "[pareto]") {
    pride::Rng rng(17);
    for (int trial = 0; trial < 200; ++trial) {
        const Eigen::Index n = static_cast<Eigen::Index>(rng.below(120));
        const std::uint64_t levels = 1 + rng.below(8);  // 2 to 9 distinct values per objective
        const Matrix f = trial % 4 == 3 ? cloud(rng, 2, n) : grid_cloud(rng, 2, n, levels);
        INFO("trial " << trial << ", N = " << n);
        CHECK(ranks(f, true) == ranks(f, false));
    }
}

TEST_CASE("pareto: each front is dominated by the one before and by no later one", "[pareto]") {
    pride::Rng rng(23);
    pp::SortScratch scratch;
    for (const Eigen::Index m : {1, 2, 3, 5})
        for (int trial = 0; trial < 10; ++trial) {
            const Matrix f = trial % 2 == 0 ? cloud(rng, m, 80) : grid_cloud(rng, m, 80, 4);
            std::vector<std::size_t> rank(80);
            const std::size_t fronts = pp::nondominated_sort(f, rank, scratch);
            INFO("M = " << m << ", trial " << trial);
            CHECK(fronts == 1 + *std::max_element(rank.begin(), rank.end()));
            for (Eigen::Index j = 0; j < f.cols(); ++j) {
                const std::size_t k = rank[static_cast<std::size_t>(j)];
                bool below = k == 0;
                for (Eigen::Index i = 0; i < f.cols(); ++i) {
                    const bool dominates = pp::dominates(pp::point(f, i), pp::point(f, j));
                    if (dominates) CHECK(rank[static_cast<std::size_t>(i)] < k);
                    if (dominates && rank[static_cast<std::size_t>(i)] + 1 == k) below = true;
                }
                CHECK(below);
            }
        }
}

TEST_CASE("pareto: crowding distance of hand-made fronts", "[pareto]") {
    pp::SortScratch scratch;
    const double inf = std::numeric_limits<double>::infinity();
    // Columns 1, 2, 4, 5 form the front (1,5), (2,3), (4,2), (6,1); the others are not members.
    // f1: range 6 - 1 = 5, sorted (1,5), (2,3), (4,2), (6,1): ends infinite, (2,3) gets
    // (4 - 1) / 5 = 0.6, (4,2) gets (6 - 2) / 5 = 0.8. f2: range 5 - 1 = 4, sorted (6,1), (4,2),
    // (2,3), (1,5): (4,2) gets (3 - 1) / 4 = 0.5, (2,3) gets (5 - 2) / 4 = 0.75.
    // Totals: (2,3) 0.6 + 0.75 = 1.35, (4,2) 0.8 + 0.5 = 1.3.
    const Matrix f = points({{9, 9}, {1, 5}, {2, 3}, {7, 7}, {4, 2}, {6, 1}});
    const std::vector<std::size_t> members{5, 2, 1, 4};
    std::vector<double> distance(4);
    pp::crowding_distance(f, members, distance, scratch);
    CHECK(distance[0] == inf);
    CHECK(distance[1] == Approx(1.35));
    CHECK(distance[2] == inf);
    CHECK(distance[3] == Approx(1.3));
    // Another order of the members: the same bits for each member.
    const std::vector<std::size_t> reordered{4, 1, 5, 2};
    std::vector<double> again(4);
    pp::crowding_distance(f, reordered, again, scratch);
    CHECK(again == std::vector<double>{distance[3], distance[2], distance[0], distance[1]});

    // f2 constant: it adds nothing, not even infinities at its ends. f1: (2 - 0) / 3 and (3 - 1) / 3.
    const Matrix flat = points({{0, 7}, {1, 7}, {2, 7}, {3, 7}});
    const std::vector<std::size_t> all{0, 1, 2, 3};
    std::vector<double> d4(4);
    pp::crowding_distance(flat, all, d4, scratch);
    CHECK(d4[0] == inf);
    CHECK(d4[1] == Approx(2.0 / 3.0));
    CHECK(d4[2] == Approx(2.0 / 3.0));
    CHECK(d4[3] == inf);
    // Every objective constant (equal points): all 0.
    const Matrix same = points({{1, 1}, {1, 1}, {1, 1}});
    std::vector<double> d3(3, -1.0);
    pp::crowding_distance(same, std::vector<std::size_t>{0, 1, 2}, d3, scratch);
    CHECK(d3 == std::vector<double>{0, 0, 0});
    // Equal values at an end: the lowest column index is the boundary. f1 = 0, 0, 1, 2 over
    // columns 0..3 (f2 constant): column 0 infinite, column 1 gets (1 - 0) / 2.
    const Matrix tied = points({{0, 1}, {0, 1}, {1, 1}, {2, 1}});
    pp::crowding_distance(tied, std::vector<std::size_t>{3, 2, 1, 0}, d4, scratch);
    CHECK(d4 == std::vector<double>{inf, (2.0 - 0.0) / 2.0, 0.5, inf});
    // Two points or fewer: all infinite.
    std::vector<double> d2(2);
    pp::crowding_distance(f, std::vector<std::size_t>{1, 2}, d2, scratch);
    CHECK(d2 == std::vector<double>{inf, inf});
    pp::crowding_distance(f, std::span<const std::size_t>(), std::span<double>(), scratch);
}

TEST_CASE("pareto: a scratch used once is reused without reallocation", "[pareto]") {
    pride::Rng rng(3);
    for (const Eigen::Index m : {2, 3}) {
        pp::SortScratch scratch;
        std::vector<std::size_t> rank(200);
        std::vector<double> distance(200);
        std::vector<std::size_t> members(200);
        std::iota(members.begin(), members.end(), std::size_t{0});
        pp::nondominated_sort(cloud(rng, m, 200), rank, scratch);
        pp::crowding_distance(cloud(rng, m, 200), members, distance, scratch);
        const auto* order = scratch.order.data();
        const auto* last = scratch.last.data();
        const auto* count = scratch.count.data();
        const auto* dominated = scratch.dominated.data();
        for (int generation = 0; generation < 5; ++generation) {
            const Matrix f = grid_cloud(rng, m, 200, 5);
            pp::nondominated_sort(f, rank, scratch);
            pp::crowding_distance(f, members, distance, scratch);
        }
        CHECK(scratch.order.data() == order);
        CHECK(scratch.last.data() == last);
        CHECK(scratch.count.data() == count);
        CHECK(scratch.dominated.data() == dominated);
    }
}

TEST_CASE("pareto: bad input is refused with one line naming what", "[pareto]") {
    using Catch::Contains;
    const Matrix f = points({{1, 2}, {2, 1}});
    const std::vector<double> r2{3, 3}, r3{3, 3, 3};
    CHECK_THROWS_AS(pp::hypervolume(f, r3), pride::InputError);
    CHECK_THROWS_WITH(pp::hypervolume(f, r3),
                      Contains("hypervolume: the reference point has 3 coordinates for 2 objectives"));
    CHECK_THROWS_WITH(pp::contributions(f, r3), Contains("contributions: the reference point has 3 coordinates"));
    CHECK_THROWS_WITH(pp::hypervolume(Matrix(0, 2), std::vector<double>{}), Contains("no objectives (M == 0)"));
    Matrix nan = f;
    nan(1, 1) = std::nan("");
    CHECK_THROWS_WITH(pp::hypervolume(nan, r2), Contains("point 1 has a NaN objective value"));
    CHECK_THROWS_WITH(pp::hypervolume(f, std::vector<double>{3, std::nan("")}),
                      Contains("reference point coordinate 1 is not finite"));
    Matrix minus = f;
    minus(0, 0) = -std::numeric_limits<double>::infinity();
    CHECK_THROWS_WITH(pp::hypervolume(minus, r2), Contains("point 0 has an objective at -infinity"));

    CHECK_THROWS_WITH(pp::igd(f, points({{1, 2, 3}})),
                      Contains("igd: the reference set has 3 objectives, the points 2"));
    CHECK_THROWS_WITH(pp::igd_plus(f, Matrix(2, 0)), Contains("igd+: the reference set is empty"));
    CHECK_THROWS_WITH(pp::gd(Matrix(2, 0), f), Contains("gd: the set of points is empty"));
    CHECK_THROWS_WITH(pp::epsilon_additive(nan, f), Contains("epsilon: a point has a NaN objective value"));
    CHECK_THROWS_WITH(pp::gd_plus(f, nan), Contains("gd+: a reference point has a NaN objective value"));

    pp::SortScratch scratch;
    std::vector<std::size_t> rank(3);
    CHECK_THROWS_WITH(pp::nondominated_sort(f, rank, scratch),
                      Contains("nondominated_sort: rank has 3 entries for 2 points"));
    rank.resize(2);
    CHECK_THROWS_WITH(pp::nondominated_sort(nan, rank, scratch), Contains("point 1 has a NaN objective value"));
    CHECK_THROWS_WITH(pp::nondominated(nan), Contains("nondominated: point 1 has a NaN objective value"));
    std::vector<double> distance(1);
    const std::vector<std::size_t> members{0, 1};
    CHECK_THROWS_WITH(pp::crowding_distance(f, members, distance, scratch),
                      Contains("crowding_distance: distance has 1 entries for 2 members"));
    distance.resize(2);
    CHECK_THROWS_WITH(pp::crowding_distance(f, std::vector<std::size_t>{0, 2}, distance, scratch),
                      Contains("member 2 is not a column of f (2 points)"));
    CHECK_THROWS_WITH(pp::crowding_distance(nan, members, distance, scratch),
                      Contains("point 1 has a non-finite objective value"));
}

TEST_CASE("pareto: exact hypervolumes beyond their measured bound are refused, not run for minutes",
          "[pareto][hypervolume]") {
    // Before: 60 objectives and 30 points held pride.hypervolume (and Ctrl-C) for 30 s; 1000
    // objectives took 3.9 GB of WFG scratch and ended as bad_alloc.
    using Catch::Contains;
    pride::Rng rng(11);
    for (const std::size_t m : {4u, 8u, 12u, 16u, 40u}) {
        INFO(m);
        const auto most = static_cast<Eigen::Index>(pp::exact_hypervolume_points(m));
        const std::vector<double> r(m, 1.1);
        const Matrix at = sphere_front(rng, static_cast<Eigen::Index>(m), std::min<Eigen::Index>(most, 64));
        CHECK(pp::hypervolume(at, r) > 0.0);
        const Matrix beyond = sphere_front(rng, static_cast<Eigen::Index>(m), most + 1);
        CHECK_THROWS_WITH(pp::hypervolume(beyond, r), Contains("hypervolume: an exact hypervolume of " +
                                                               std::to_string(most + 1) + " non-dominated points"));
        CHECK_THROWS_WITH(pp::contributions(beyond, r), Contains("contributions: an exact hypervolume contribution"));
    }
    // Dominated points do not count: a large set with a small non-dominated part is computed.
    Matrix many(8, 2000);
    for (Eigen::Index j = 0; j < many.cols(); ++j) many.col(j).setConstant(0.5 + 0.0001 * static_cast<double>(j));
    CHECK(pp::hypervolume(many, std::vector<double>(8, 1.0)) == Approx(std::pow(0.5, 8)));
    // A thousand objectives: two points at most, and the scratch is checked before it is made.
    CHECK(pp::exact_hypervolume_points(1000) == 2);
    CHECK_THROWS_WITH(pp::hypervolume(sphere_front(rng, 1000, 3), std::vector<double>(1000, 1.1)),
                      Contains("at most 2 points in 1000 objectives"));
    CHECK(pp::hypervolume(sphere_front(rng, 1000, 2), std::vector<double>(1000, 1.1)) > 0.0);
}

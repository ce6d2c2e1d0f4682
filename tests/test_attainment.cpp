// Empirical attainment surfaces (framework/pareto/attainment.hpp): a hand-computed case, and on
// random runs (integer values, so ties abound) the definition checked point by point against a
// brute-force count of the runs that attain each point.
#include <catch2/catch.hpp>

#include <vector>

#include "framework/pareto/attainment.hpp"
#include "framework/pareto/dominance.hpp"
#include "framework/random.hpp"
#include "tests/test_support.hpp"

using pride::Matrix;
using pride::pareto::attainment_surface;

namespace {

Matrix points(std::initializer_list<std::pair<double, double>> list) {
    Matrix m(2, static_cast<Eigen::Index>(list.size()));
    Eigen::Index j = 0;
    for (const auto& [a, b] : list) {
        m(0, j) = a;
        m(1, j) = b;
        ++j;
    }
    return m;
}

/// How many runs have a point that weakly dominates (x, y).
std::size_t attaining(const std::vector<Matrix>& runs, double x, double y) {
    std::size_t count = 0;
    for (const Matrix& a : runs) {
        bool hit = false;
        for (Eigen::Index j = 0; j < a.cols() && !hit; ++j) hit = a(0, j) <= x && a(1, j) <= y;
        count += hit ? 1 : 0;
    }
    return count;
}

}  // namespace

TEST_CASE("attainment surfaces of three runs, by hand") {
    // Run 1: (1, 5), (3, 2); run 2: (2, 4); run 3: (4, 1).
    const std::vector<Matrix> runs{points({{1, 5}, {3, 2}}), points({{2, 4}}), points({{4, 1}})};
    // Best (k = 1): the union's non-dominated points.
    CHECK(attainment_surface(runs, 1) == points({{1, 5}, {2, 4}, {3, 2}, {4, 1}}));
    // k = 2: at x = 2 runs 1 and 2 reach 5 and 4 (the second smallest is 5); at x = 3, 2 and 4
    // (4); at x = 4, 2, 4 and 1 (2).
    CHECK(attainment_surface(runs, 2) == points({{2, 5}, {3, 4}, {4, 2}}));
    // k = 3: only from x = 4, where the worst of 2, 4, 1 is 4.
    CHECK(attainment_surface(runs, 3) == points({{4, 4}}));
}

TEST_CASE("attainment surfaces hold exactly the points attained by k runs (random runs, brute force)") {
    pride::Rng rng(11);
    for (int trial = 0; trial < 200; ++trial) {
        const std::size_t n = 1 + rng.below(6);
        std::vector<Matrix> runs(n);
        for (auto& a : runs) {
            const auto size = static_cast<Eigen::Index>(rng.below(6));  // empty runs too
            a.resize(2, size);
            for (Eigen::Index j = 0; j < size; ++j) {
                a(0, j) = static_cast<double>(rng.below(8));
                a(1, j) = static_cast<double>(rng.below(8));
            }
        }
        for (std::size_t k = 1; k <= n; ++k) {
            const Matrix s = attainment_surface(runs, k);
            INFO("trial " << trial << ", n " << n << ", k " << k);
            for (Eigen::Index c = 0; c < s.cols(); ++c) {
                CHECK(attaining(runs, s(0, c), s(1, c)) >= k);
                if (c > 0) {
                    CHECK(s(0, c - 1) < s(0, c));
                    CHECK(s(1, c - 1) > s(1, c));
                }
            }
            // Every point of the value grid (and half-steps between) is attained by k runs exactly
            // when a corner weakly dominates it.
            for (int xi = -1; xi <= 16; ++xi)
                for (int yi = -1; yi <= 16; ++yi) {
                    const double x = 0.5 * xi, y = 0.5 * yi;
                    bool covered = false;
                    for (Eigen::Index c = 0; c < s.cols() && !covered; ++c) covered = s(0, c) <= x && s(1, c) <= y;
                    CHECK(covered == (attaining(runs, x, y) >= k));
                }
        }
    }
}

TEST_CASE("attainment surfaces refuse what they cannot take") {
    const std::vector<Matrix> runs{points({{1, 2}})};
    using pride::test::input_error_message;
    CHECK(input_error_message([&] { (void)attainment_surface({}, 1); }) ==
          "attainment_surface: needs at least one run");
    CHECK(input_error_message([&] { (void)attainment_surface(runs, 0); }) ==
          "attainment_surface: k must be in [1, 1], got 0");
    CHECK(input_error_message([&] { (void)attainment_surface(runs, 2); }) ==
          "attainment_surface: k must be in [1, 1], got 2");
    Matrix three(3, 1);
    three << 1, 2, 3;
    CHECK(input_error_message([&] { (void)attainment_surface({three}, 1); }) ==
          "attainment_surface: run 0 has 3 objectives; attainment surfaces here are of two");
    Matrix nan = points({{1, 2}});
    nan(1, 0) = std::nan("");
    CHECK(input_error_message([&] { (void)attainment_surface({nan}, 1); }) ==
          "attainment_surface: run 0 has a NaN objective value");
}

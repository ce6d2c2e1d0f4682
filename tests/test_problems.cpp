// Tests of the continuous test functions (problems/continuous/): values at concrete points from
// external references, known optima, the shift transform, the catalog and the boxes.
//
// Every reference value in the first test cases is copied from
//   $PRIDE_DATA/continuous/reference_values.md
// (section 1: pagmo2 unit tests, esa/pagmo2 commit bd9c91e7; section 2: estripling/fbench
// tests/test_function.py commit 0a2ffb01 and pyBlindOpt; section 3: the [computed] table), with the
// tolerances that file states. pagmo's BOOST_CHECK_CLOSE(..., 1e-13) is a relative tolerance of
// 1e-13 percent, i.e. 1e-15. pagmo's fitness evaluates the whole point it is given whatever
// dimension the object was built with, so here each problem is built with the point's dimension.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <set>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "framework/error.hpp"
#include "framework/problem.hpp"
#include "framework/random.hpp"
#include "problems/continuous/catalog.hpp"
#include "problems/continuous/functions.hpp"
#include "problems/continuous/transformed.hpp"
#include "tests/test_support.hpp"

using namespace pride::continuous;
using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using pride::test::input_error_message;

namespace {

/// F built in the dimension of x, evaluated at x.
template <class F>
double eval(const std::vector<double>& x) {
    F f(x.size());
    return f.evaluate(x);
}

/// True when `value` rounded to `digits` decimals (as Python's round() in the fbench tests) is
/// `expected`: |value - expected| <= half a unit in the last kept decimal.
bool rounds_to(double value, double expected, int digits) {
    return std::abs(value - expected) <= 0.5 * std::pow(10.0, -digits) * (1.0 + 1e-12);
}

std::vector<double> random_point_in(std::span<const double> lo, std::span<const double> hi, pride::Rng& rng) {
    std::vector<double> x(lo.size());
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = rng.uniform(lo[i], hi[i]);
    return x;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// 1. pagmo2 unit-test values (reference_values.md, section 1), [source].

TEST_CASE("problems: pagmo2 reference values (reference_values.md section 1)", "[problems][reference]") {
    constexpr double rel = 1e-15;  // BOOST_CHECK_CLOSE(..., 1e-13) = 1e-13 percent
    const std::vector<double> p1{1.12};
    const std::vector<double> p3{-23.45, 12.34, 111.12};

    CHECK_THAT(eval<Ackley>(p1), WithinRel(4.659037611351948, rel));
    CHECK_THAT(eval<Ackley>(p3), WithinRel(21.941495638130885, rel));
    CHECK_THAT(eval<Griewank>(p1), WithinRel(0.5646311537232878, rel));
    CHECK_THAT(eval<Griewank>(p3), WithinRel(4.241511427781268, rel));
    CHECK_THAT(eval<Schwefel>(p1), WithinRel(418.0067810680098, rel));
    CHECK_THAT(eval<Schwefel>(p3), WithinRel(1338.0260195323838, rel));
    // Exact equalities in pagmo's tests.
    CHECK(eval<Rastrigin>({1.0}) == 1.0);
    CHECK(eval<Rastrigin>({1.0, 1.0, 1.0, 1.0, 1.0}) == 5.0);
    CHECK(eval<Rosenbrock>({1.0, 1.0}) == 0.0);
    CHECK(eval<Rosenbrock>({1.0, 1.0, 1.0, 1.0, 1.0}) == 0.0);
}

TEST_CASE("problems: pagmo2 best_known points (reference_values.md section 1)", "[problems][reference]") {
    // Ackley, Griewank, Rastrigin: 0 vector; Rosenbrock: all ones; Schwefel: 420.9687 per coordinate.
    CHECK(Ackley(3).optimum_point() == std::vector<double>(3, 0.0));
    CHECK(Griewank(3).optimum_point() == std::vector<double>(3, 0.0));
    CHECK(Rastrigin(3).optimum_point() == std::vector<double>(3, 0.0));
    CHECK(Sphere(3).optimum_point() == std::vector<double>(3, 0.0));
    CHECK(Rosenbrock(3).optimum_point() == std::vector<double>(3, 1.0));
    for (double c : Schwefel(3).optimum_point()) CHECK(rounds_to(c, 420.9687, 4));
    // Schwefel at pagmo's rounded best_known point, [420.9687]*3 = 8.14e-10 [computed] (3 digits).
    CHECK_THAT(eval<Schwefel>({420.9687, 420.9687, 420.9687}), WithinAbs(8.14e-10, 0.006e-10));
}

// ---------------------------------------------------------------------------------------------
// 2. fbench and pyBlindOpt values (reference_values.md, section 2), [source], rounded as stated.

TEST_CASE("problems: fbench reference values (reference_values.md section 2)", "[problems][reference]") {
    SECTION("Ackley, round 4") {
        CHECK(rounds_to(eval<Ackley>({0.0}), 0.0, 4));
        CHECK(rounds_to(eval<Ackley>({0.0, 0.0}), 0.0, 4));
        CHECK(rounds_to(eval<Ackley>({1.0, 1.0}), 3.6254, 4));
        CHECK(rounds_to(eval<Ackley>({2.0, 2.0}), 6.5936, 4));
        // The full value of the [1,1] point, [computed] in the same file.
        CHECK_THAT(eval<Ackley>({1.0, 1.0}), WithinRel(3.6253849384403627, 1e-13));
    }
    SECTION("Rastrigin") {
        CHECK(eval<Rastrigin>({0.0}) == 0.0);
        CHECK(eval<Rastrigin>({0.0, 0.0}) == 0.0);
        CHECK(rounds_to(eval<Rastrigin>({1.0, 1.0}), 2.0, 2));
        CHECK(rounds_to(eval<Rastrigin>({1.0, 2.0}), 5.0, 2));
        CHECK(rounds_to(eval<Rastrigin>({2.0, 1.0}), 5.0, 2));
        CHECK(rounds_to(eval<Rastrigin>({2.0, 2.0}), 8.0, 2));
        CHECK(rounds_to(eval<Rastrigin>({4.0, 4.5}), 56.25, 2));
        CHECK(rounds_to(eval<Rastrigin>({4.5, 4.0}), 56.25, 2));
        CHECK(rounds_to(eval<Rastrigin>({5.12, 5.12}), 57.85, 2));
    }
    SECTION("Rosenbrock") {
        CHECK(eval<Rosenbrock>({0.0, 0.0}) == 1.0);
        CHECK(eval<Rosenbrock>({1.0, 1.0}) == 0.0);
        CHECK(eval<Rosenbrock>({1.0, 1.0, 1.0}) == 0.0);
        CHECK(eval<Rosenbrock>({1.0, 1.0, 1.0, 1.0}) == 0.0);
        CHECK(eval<Rosenbrock>({1.0, 2.0}) == 100.0);
        CHECK(eval<Rosenbrock>({2.0, 1.0}) == 901.0);
        CHECK(eval<Rosenbrock>({2.0, 2.0}) == 401.0);
        CHECK(eval<Rosenbrock>({4.0, 4.5}) == 13234.0);
        CHECK(eval<Rosenbrock>({4.5, 4.0}) == 26418.5);
        CHECK(rounds_to(eval<Rosenbrock>({5.12, 5.12}), 44514.35, 2));
    }
    SECTION("Sphere, exact") {
        CHECK(eval<Sphere>({0.0}) == 0.0);
        CHECK(eval<Sphere>({0.0, 0.0}) == 0.0);
        CHECK(eval<Sphere>({1.0, 1.0}) == 2.0);
        CHECK(eval<Sphere>({2.0, 2.0}) == 8.0);
    }
    SECTION("pyBlindOpt") {
        CHECK(eval<Sphere>({1.0, 1.0}) == 2.0);
        CHECK(eval<Rastrigin>({1.0, 0.0}) == 1.0);
        CHECK(eval<Rosenbrock>({0.0, 0.0}) == 1.0);
        CHECK(eval<Rosenbrock>({2.0, 2.0}) == 401.0);
        CHECK(eval<Griewank>({0.0, 0.0, 0.0}) == 0.0);
    }
}

// ---------------------------------------------------------------------------------------------
// 3. The [computed] table (reference_values.md, section 3): Python float64 values of the formulas.

TEST_CASE("problems: computed reference table (reference_values.md section 3)", "[problems][reference]") {
    constexpr double rel = 1e-13;
    struct Row {
        std::vector<double> x;
        double sphere, rastrigin, rosenbrock, ackley, griewank, schwefel;
    };
    const std::vector<Row> rows{
        {{-23.45, 12.34, 111.12},
         13049.8325,
         13087.411646838527,
         29067448.879860986,
         21.941495638130885,
         4.241511427781268,
         1338.0260195323838},
        {{0.1, 0.2, 0.3, 0.4, 0.5}, 0.55, 60.55, 33.84, 3.1831579464839312, 0.07282383074072141, 2094.0793544288076},
        {{1.0, 1.0, 1.0, 1.0, 1.0}, 5.0, 5.0, 0.0, 3.6253849384403627, 0.728906414277732, 2090.7070814381295},
    };
    for (const auto& r : rows) {
        INFO("x[0] = " << r.x[0] << ", n = " << r.x.size());
        CHECK_THAT(eval<Sphere>(r.x), WithinRel(r.sphere, rel));
        CHECK_THAT(eval<Rastrigin>(r.x), WithinRel(r.rastrigin, rel));
        CHECK_THAT(eval<Rosenbrock>(r.x), WithinRel(r.rosenbrock, rel));
        CHECK_THAT(eval<Ackley>(r.x), WithinRel(r.ackley, rel));
        CHECK_THAT(eval<Griewank>(r.x), WithinRel(r.griewank, rel));
        CHECK_THAT(eval<Schwefel>(r.x), WithinRel(r.schwefel, rel));
    }
    // Exact where the arithmetic is exact.
    CHECK(eval<Sphere>({1.0, 1.0, 1.0, 1.0, 1.0}) == 5.0);
    CHECK(eval<Rastrigin>({1.0, 1.0, 1.0, 1.0, 1.0}) == 5.0);
    CHECK(eval<Rosenbrock>({1.0, 1.0, 1.0, 1.0, 1.0}) == 0.0);
    // The zero row.
    const std::vector<double> zero(5, 0.0);
    CHECK(eval<Sphere>(zero) == 0.0);
    CHECK(eval<Rastrigin>(zero) == 0.0);
    CHECK(eval<Rosenbrock>(zero) == 4.0);
    CHECK_THAT(eval<Ackley>(zero), WithinAbs(4.44e-16, 1e-15));
    CHECK(eval<Griewank>(zero) == 0.0);
    CHECK_THAT(eval<Schwefel>(zero), WithinRel(2094.914436362169, rel));
}

// ---------------------------------------------------------------------------------------------
// Known optima.

TEMPLATE_TEST_CASE("problems: value at the known optimum", "[problems][optimum]", Sphere, Rastrigin, Rosenbrock, Ackley,
                   Griewank, Schwefel) {
    for (std::size_t dim : {2, 3, 5, 10, 30, 100}) {
        TestType f(dim);
        INFO(f.name() << " in dimension " << dim);
        const auto xs = f.optimum_point();
        REQUIRE(xs.size() == dim);
        const double fs = f.evaluate(xs);
        // Exact for the separable sums; Ackley's 20 + e - 20 - e leaves float rounding (4.44e-16);
        // Schwefel's rounded constant leaves about 6e-14 per coordinate.
        const double tol = std::is_same_v<TestType, Schwefel> ? 1e-9 : std::is_same_v<TestType, Ackley> ? 1e-15 : 0.0;
        CHECK_THAT(fs, WithinAbs(f.optimum_value(), tol));
        CHECK(f.optimum_value() == 0.0);

        // The optimum is inside the box.
        for (std::size_t i = 0; i < dim; ++i) {
            CHECK(xs[i] >= f.lower()[i]);
            CHECK(xs[i] <= f.upper()[i]);
        }
        // A local minimum: moving any one coordinate a little either way makes things worse.
        for (std::size_t i = 0; i < std::min<std::size_t>(dim, 5); ++i)
            for (double step : {-1e-3, 1e-3}) {
                auto y = xs;
                y[i] += step;
                CHECK(f.evaluate(y) > fs);
            }
    }
}

TEMPLATE_TEST_CASE("problems: random points in the box are no better than the optimum", "[problems][optimum]", Sphere,
                   Rastrigin, Rosenbrock, Ackley, Griewank, Schwefel) {
    pride::Rng rng(2024, 7);
    for (std::size_t dim : {2, 5, 20}) {
        TestType f(dim);
        const double fs = f.evaluate(f.optimum_point());
        for (int k = 0; k < 2000; ++k) {
            const auto x = random_point_in(f.lower(), f.upper(), rng);
            const double v = f.evaluate(x);
            INFO(f.name() << " dim " << dim << " f = " << v);
            CHECK(std::isfinite(v));
            CHECK(v >= f.optimum_value());
            CHECK(v > fs);
        }
    }
}

// ---------------------------------------------------------------------------------------------
// The shift transform.

TEMPLATE_TEST_CASE("problems: Shifted<F> moves the optimum and keeps its value", "[problems][shifted]", Sphere,
                   Rastrigin, Rosenbrock, Ackley, Griewank) {
    using F = TestType;
    pride::Rng rng(99);
    for (std::size_t dim : {1, 2, 3, 10, 50}) {
        if (dim < F::info.min_dim) continue;
        Shifted<F> s(dim);
        F plain(dim);
        INFO(std::string(s.name()) << " dim " << dim);
        CHECK(s.name() == "shifted-" + std::string(F::info.name));
        CHECK(s.dimension() == dim);

        // Same box as F.
        REQUIRE(s.lower().size() == dim);
        REQUIRE(s.upper().size() == dim);
        for (std::size_t i = 0; i < dim; ++i) {
            CHECK(s.lower()[i] == F::info.lower);
            CHECK(s.upper()[i] == F::info.upper);
        }

        const auto o = s.optimum_point();
        REQUIRE(o.size() == dim);
        // The value at the shifted optimum is F's value at its own optimum.
        const double at_o = s.evaluate(o);
        CHECK(at_o == plain.evaluate(plain.optimum_point()));
        CHECK_THAT(at_o, WithinAbs(F::info.optimum_value, 1e-15));
        CHECK(s.optimum_value() == F::info.optimum_value);

        // The documented formula, recomputed independently.
        const double lo = F::info.lower, hi = F::info.upper, w = hi - lo;
        constexpr double phi = 0.6180339887498949;
        CHECK_THAT(phi, WithinRel((std::sqrt(5.0) - 1.0) / 2.0, 1e-15));
        double dist2_centre = 0.0, dist2_plain = 0.0;
        for (std::size_t i = 0; i < dim; ++i) {
            const double frac = std::fmod(static_cast<double>(i + 1) * phi, 1.0);
            CHECK_THAT(o[i], WithinRel(lo + w * (0.1 + 0.8 * frac), 1e-14));
            // Inside the middle 80 % of the box, never on the centre line.
            CHECK(o[i] >= lo + 0.1 * w - 1e-12);
            CHECK(o[i] <= lo + 0.9 * w + 1e-12);
            CHECK(o[i] != 0.5 * (lo + hi));
            dist2_centre += (o[i] - 0.5 * (lo + hi)) * (o[i] - 0.5 * (lo + hi));
            dist2_plain += (o[i] - F::info.optimum_coordinate) * (o[i] - F::info.optimum_coordinate);
        }
        // Away from the centre and from F's own optimum: at least 5 % of the box's diagonal.
        const double diagonal = w * std::sqrt(static_cast<double>(dim));
        CHECK(std::sqrt(dist2_centre) > 0.05 * diagonal);
        CHECK(std::sqrt(dist2_plain) > 0.05 * diagonal);

        // f(x) = F(x - o + x*) at random points (the same arithmetic, so exactly).
        for (int k = 0; k < 200; ++k) {
            const auto x = random_point_in(s.lower(), s.upper(), rng);
            std::vector<double> y(dim);
            for (std::size_t i = 0; i < dim; ++i) y[i] = x[i] - o[i] + F::info.optimum_coordinate;
            CHECK(s.evaluate(x) == plain.evaluate(y));
            CHECK(s.evaluate(x) >= at_o);
        }
    }
}

TEST_CASE("problems: shift vector, hand-worked values", "[problems][shifted]") {
    // o_0 = -5.12 + 10.24 * (0.1 + 0.8 * 0.6180339887498949)
    //     = -5.12 + 10.24 * 0.5944271909999159 = 0.9669344358391392
    // o_1: 2 phi = 1.2360679774997898, frac 0.2360679774997898, 0.1 + 0.8 * frac = 0.2888543819998318
    //     -> -5.12 + 10.24 * 0.2888543819998318 = -2.162131128321722
    const auto o = shift_optimum(2, -5.12, 5.12);
    REQUIRE(o.size() == 2);
    CHECK_THAT(o[0], WithinAbs(0.9669344358391392, 1e-12));
    CHECK_THAT(o[1], WithinAbs(-2.162131128321722, 1e-12));
    CHECK(Shifted<Sphere>(2).optimum_point() == o);
    // The shifted optimum does not depend on the dimension: a prefix stays a prefix.
    const auto o5 = shift_optimum(5, -5.12, 5.12);
    CHECK(o5[0] == o[0]);
    CHECK(o5[1] == o[1]);
}

// ---------------------------------------------------------------------------------------------
// Boxes (reference_values.md, formula table: pagmo bounds; sphere in [-5.12, 5.12]).

TEST_CASE("problems: boxes match the reference table", "[problems][bounds]") {
    auto check_box = [](const auto& f, double lo, double hi, std::size_t dim) {
        INFO(f.name() << " dim " << dim);
        REQUIRE(f.dimension() == dim);
        REQUIRE(f.lower().size() == dim);
        REQUIRE(f.upper().size() == dim);
        for (std::size_t i = 0; i < dim; ++i) {
            CHECK(f.lower()[i] == lo);
            CHECK(f.upper()[i] == hi);
        }
    };
    for (std::size_t dim : {2, 7}) {
        check_box(Sphere(dim), -5.12, 5.12, dim);
        check_box(Rastrigin(dim), -5.12, 5.12, dim);
        check_box(Rosenbrock(dim), -5.0, 10.0, dim);
        check_box(Ackley(dim), -15.0, 30.0, dim);
        check_box(Griewank(dim), -600.0, 600.0, dim);
        check_box(Schwefel(dim), -500.0, 500.0, dim);
        check_box(Shifted<Rosenbrock>(dim), -5.0, 10.0, dim);
        check_box(Shifted<Griewank>(dim), -600.0, 600.0, dim);
    }
}

// ---------------------------------------------------------------------------------------------
// The catalog.

TEST_CASE("problems: catalog names, construction and dimension", "[problems][catalog]") {
    const std::set<std::string> today{"sphere",     "shifted-sphere",     "rastrigin", "shifted-rastrigin",
                                      "rosenbrock", "shifted-rosenbrock", "ackley",    "shifted-ackley",
                                      "griewank",   "shifted-griewank",   "schwefel"};
    std::set<std::string> names;
    for (const auto& item : catalog().items()) {
        CHECK(names.insert(item.name).second);  // no duplicates
        CHECK_FALSE(item.summary.empty());
    }
    for (const auto& name : today) CHECK(names.count(name) == 1);
    CHECK(catalog().find("shifted-schwefel") == nullptr);

    for (const auto& item : catalog().items()) {
        const auto& e = item.entry;
        if (e.suite.starts_with("cec")) continue;  // the official data: tests/test_cec.cpp
        std::vector<std::int64_t> dims{2, 3, 10};
        if (e.fixed_dim != 0) dims = {static_cast<std::int64_t>(e.fixed_dim)};
        for (const std::int64_t dim : dims) {
            if (static_cast<std::size_t>(dim) < e.min_dim) continue;
            INFO(item.name << " dim " << dim);
            auto f = make_function(item.name, dim);
            CHECK(std::string(f.name()) == item.name);
            CHECK(f.instance() == default_instance(e));
            CHECK(f.dimension() == static_cast<std::size_t>(dim));
            CHECK(f.lower().size() == static_cast<std::size_t>(dim));
            CHECK(f.upper().size() == static_cast<std::size_t>(dim));
            // A working problem: its optimum has its optimum value (noise adds [0, 1)).
            const double at_optimum = f.evaluate(f.optimum_point());
            if (f.noisy()) {
                CHECK(at_optimum >= f.optimum_value());
                CHECK(at_optimum < f.optimum_value() + 1.0);
            } else {
                CHECK_THAT(at_optimum, WithinAbs(f.optimum_value(), 1e-9 * (1.0 + std::abs(f.optimum_value()))));
            }
        }
    }
    // Dimension 1 where the formula allows it.
    for (const auto& item : catalog().items()) {
        if (item.entry.min_dim > 1 || item.entry.fixed_dim > 1) continue;
        CHECK(make_function(item.name, 1).dimension() == 1u);
    }
}

TEST_CASE("problems: a catalog Function evaluates exactly as its typed class, scalar and batch",
          "[problems][catalog]") {
    pride::Rng rng(5);
    auto check = [&](auto typed, const std::string& name) {
        auto f = make_function(name, static_cast<std::int64_t>(typed.dimension()));
        pride::Matrix points(static_cast<Eigen::Index>(typed.dimension()), 7);
        for (Eigen::Index j = 0; j < points.cols(); ++j) {
            const auto x = random_point_in(typed.lower(), typed.upper(), rng);
            for (std::size_t d = 0; d < x.size(); ++d) points(static_cast<Eigen::Index>(d), j) = x[d];
        }
        std::vector<double> batch(7);
        f.evaluate_batch(points, batch);
        for (Eigen::Index j = 0; j < points.cols(); ++j) {
            INFO(name << " point " << j);
            const auto x = pride::column(points, j);
            CHECK(f.evaluate(x) == typed.evaluate(x));  // bit for bit
            CHECK(batch[static_cast<std::size_t>(j)] == typed.evaluate(x));
        }
        CHECK(f.optimum_point() == typed.optimum_point());
    };
    check(Sphere(5), "sphere");
    check(Rastrigin(6), "rastrigin");
    check(Rosenbrock(4), "rosenbrock");
    check(Ackley(3), "ackley");
    check(Griewank(8), "griewank");
    check(Schwefel(5), "schwefel");
    check(Shifted<Sphere>(5), "shifted-sphere");
    check(Shifted<Griewank>(9), "shifted-griewank");
    check(Shifted<Rosenbrock>(3), "shifted-rosenbrock");
}

TEST_CASE("problems: catalog rejects bad names and dimensions", "[problems][catalog]") {
    const auto unknown = input_error_message([] { (void)make_function("spheer", 3); });
    CHECK_THAT(unknown, Contains("problem:") && Contains("spheer"));

    const auto empty = input_error_message([] { (void)make_function("", 3); });
    CHECK_THAT(empty, Contains("problem:"));

    const auto zero = input_error_message([] { (void)make_function("sphere", 0); });
    CHECK_THAT(zero, Contains("dim:") && Contains("0"));

    const auto negative = input_error_message([] { (void)make_function("ackley", -3); });
    CHECK_THAT(negative, Contains("dim:") && Contains("-3"));

    const auto rosen1 = input_error_message([] { (void)make_function("rosenbrock", 1); });
    CHECK_THAT(rosen1, Contains("dim:") && Contains("rosenbrock") && Contains("2"));

    const auto srosen1 = input_error_message([] { (void)make_function("shifted-rosenbrock", 1); });
    CHECK_THAT(srosen1, Contains("dim:") && Contains("shifted-rosenbrock"));

    // Direct construction guards too, naming the function.
    const auto direct = input_error_message([] { Rosenbrock r(1); });
    CHECK_THAT(direct, Contains("rosenbrock"));
    const auto direct0 = input_error_message([] { Sphere s(0); });
    CHECK_THAT(direct0, Contains("sphere"));
    // And a good dimension does not throw.
    CHECK_NOTHROW(make_function("rosenbrock", 2));
}

// The concept holds for every catalog type.
static_assert(pride::BoxProblem<Sphere> && pride::BoxProblem<Schwefel> && pride::BoxProblem<Shifted<Ackley>>);
static_assert(pride::Named<Rosenbrock> && pride::Named<Shifted<Griewank>>);

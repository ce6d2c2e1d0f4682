// Tests of the classic functions: Yao, Liu and Lin (1999) Table I (yao.hpp, yao_fixed.hpp) and the
// four extras (extras.hpp): values at hand-computed points, the optima, the boxes, the fixed
// dimensions, the noise of F7 and the batch forms.
#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "framework/error.hpp"
#include "framework/problem.hpp"
#include "framework/random.hpp"
#include "problems/continuous/extras.hpp"
#include "problems/continuous/functions.hpp"
#include "problems/continuous/yao.hpp"
#include "problems/continuous/yao_fixed.hpp"

using namespace pride::continuous;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

static_assert(pride::BoxProblem<QuarticNoise> && pride::BoxProblem<Branin> && pride::BoxProblem<Schwefel226>);
// Batch forms only where they measured faster (bench/batch_bench.cpp): not for Sphere, Rastrigin,
// Schwefel 2.22 or Step, whose scalar loops the batch kernel did not beat.
static_assert(pride::BatchBoxProblem<Schwefel221> && pride::BatchBoxProblem<Ellipsoid>);
static_assert(!pride::BatchBoxProblem<Sphere> && !pride::BatchBoxProblem<Rastrigin>);

/// F built in the dimension of x, evaluated at x.
template <class F>
double eval(const std::vector<double>& x) {
    F f(x.size());
    return f.evaluate(x);
}

/// Value at the optimum, scaled tolerance: 1e-12 relative, or absolute when the value is 0.
double tolerance(double optimum) {
    return 1e-12 * std::max(1.0, std::abs(optimum));
}

/// Uniform points in F's box.
template <class F>
std::vector<double> random_point(const F& f, pride::Rng& rng) {
    std::vector<double> x(f.dimension());
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = rng.uniform(f.lower()[i], f.upper()[i]);
    return x;
}

template <class F>
std::vector<std::size_t> test_dims() {
    if constexpr (F::info.fixed_dim != 0)
        return {F::info.fixed_dim};
    else
        return {std::max<std::size_t>(F::info.min_dim, 1), 2, 10, 30};
}

}  // namespace

// Each value below was computed from the formula written out again in Python (mpmath, 40 digits;
// the script evaluates the textbook formula, not a port of this code: sums in their own order,
// x^6 as a power), and pasted to 17 significant digits. The same script gives the optima.
TEST_CASE("classic: values at hand-computed points", "[classic]") {
    struct Row {
        std::string function;
        std::vector<double> x;
        double value;
    };
    const std::vector<Row> rows{
        {"Sphere", {0.5, -1.25, 2.0}, 5.8125},
        {"Rosenbrock", {0.5, -1.25, 2.0}, 249.453125},
        {"Ackley", {0.5, -1.25, 2.0}, 6.5782241842650541},
        {"Rastrigin", {0.5, -1.25, 2.0}, 35.8125},
        {"Griewank", {0.5, -1.25, 2.0}, 0.7765112122955336},
        {"Schwefel222", {0.5, -1.25, 2.0}, 5.0},
        {"Schwefel222", {3.0, -0.5, 1.5, -2.0}, 11.5},
        {"Schwefel12", {0.5, -1.25, 2.0}, 2.375},
        {"Schwefel12", {3.0, -0.5, 1.5, -2.0}, 35.25},
        {"Schwefel221", {0.5, -1.25, 2.0}, 2.0},
        {"Schwefel221", {3.0, -7.5, 1.5, -2.0}, 7.5},
        {"Step", {0.49, -0.51, 2.5, -3.7}, 26.0},
        {"Step", {0.5, -1.25, 2.0}, 6.0},
        {"Quartic", {0.5, -1.0, 1.2}, 8.2833},
        {"Schwefel226", {100.0, -200.0, 300.0}, 554.13823993478285},
        {"Schwefel226", {0.5, -1.25, 2.0}, -1.1762976782707709},
        {"Penalized1", {0.5, -1.25, 2.0}, 9.7552929958920006},
        {"Penalized1", {12.0, -0.5, -13.0, 3.0}, 9732.237883506142},
        {"Penalized2", {0.5, -1.25, 2.0}, 0.74375},
        {"Penalized2", {6.0, 0.5, -7.5, 1.25}, 4022.15},
        {"ShekelFoxholes", {0.0, 0.0}, 12.670505812885985},
        {"ShekelFoxholes", {-32.0, 16.0}, 15.503817278588175},
        {"Kowalik", {0.25, 0.39, 0.415, 0.39}, 0.0053159058464491001},
        {"Kowalik", {1.0, 1.0, 1.0, 1.0}, 1.3768626462061769},
        {"SixHumpCamel", {1.0, 1.0}, 3.2333333333333333},
        {"SixHumpCamel", {-0.5, 0.25}, 0.51458333333333333},
        {"Branin", {0.0, 0.0}, 55.602112642270262},
        {"Branin", {1.0, 2.0}, 21.627635392062379},
        {"GoldsteinPrice", {1.0, 1.0}, 1876.0},
        {"GoldsteinPrice", {-0.5, 0.25}, 2738.7433013916016},
        {"Hartman3", {0.5, 0.5, 0.5}, -0.62802209617506145},
        {"Hartman3", {0.1, 0.5, 0.9}, -3.5190768146925762},
        {"Hartman6", {0.5, 0.5, 0.5, 0.5, 0.5, 0.5}, -0.50531499170223314},
        {"Hartman6", {0.2, 0.15, 0.5, 0.25, 0.3, 0.65}, -3.290905380046905},
        {"Shekel5", {1.0, 2.0, 3.0, 4.0}, -0.19369247090412721},
        {"Shekel7", {1.0, 2.0, 3.0, 4.0}, -0.2447701148795464},
        {"Shekel10", {1.0, 2.0, 3.0, 4.0}, -0.30065989695549291},
        {"Shekel10", {5.0, 5.0, 3.0, 3.0}, -3.8336350390608481},
        {"Ellipsoid", {0.5, -1.25, 2.0}, 15.375},
        {"Levy", {0.5, -1.25, 2.0}, 2.1786525518297428},
        {"Levy", {-3.0, 4.5, 0.0, 9.0}, 15.430422783721976},
        {"Zakharov", {0.5, -1.25, 2.0}, 25.8125},
        {"StyblinskiTang", {0.5, -1.25, 2.0}, -34.123046875},
        {"StyblinskiTang", {-2.9, 2.75, 0.0}, -64.195246875},
    };
    using Eval = std::function<double(const std::vector<double>&)>;
    const std::map<std::string, Eval> by_name{
        {"Sphere", eval<Sphere>},
        {"Rosenbrock", eval<Rosenbrock>},
        {"Ackley", eval<Ackley>},
        {"Rastrigin", eval<Rastrigin>},
        {"Griewank", eval<Griewank>},
        {"Schwefel222", eval<Schwefel222>},
        {"Schwefel12", eval<Schwefel12>},
        {"Schwefel221", eval<Schwefel221>},
        {"Step", eval<Step>},
        {"Quartic", [](const std::vector<double>& x) { return QuarticNoise::quartic(x); }},
        {"Schwefel226", eval<Schwefel226>},
        {"Penalized1", eval<Penalized1>},
        {"Penalized2", eval<Penalized2>},
        {"ShekelFoxholes", eval<ShekelFoxholes>},
        {"Kowalik", eval<Kowalik>},
        {"SixHumpCamel", eval<SixHumpCamel>},
        {"Branin", eval<Branin>},
        {"GoldsteinPrice", eval<GoldsteinPrice>},
        {"Hartman3", eval<Hartman3>},
        {"Hartman6", eval<Hartman6>},
        {"Shekel5", eval<Shekel5>},
        {"Shekel7", eval<Shekel7>},
        {"Shekel10", eval<Shekel10>},
        {"Ellipsoid", eval<Ellipsoid>},
        {"Levy", eval<Levy>},
        {"Zakharov", eval<Zakharov>},
        {"StyblinskiTang", eval<StyblinskiTang>},
    };
    for (const auto& row : rows) {
        INFO(row.function << " at x[0] = " << row.x[0]);
        const double f = by_name.at(row.function)(row.x);
        CHECK_THAT(f, WithinRel(row.value, 1e-13) || WithinAbs(row.value, 1e-15));
    }
}

TEMPLATE_TEST_CASE("classic: value at the known optimum", "[classic][optimum]", Schwefel222, Schwefel12, Schwefel221,
                   Step, Schwefel226, Penalized1, Penalized2, ShekelFoxholes, Kowalik, SixHumpCamel, Branin,
                   GoldsteinPrice, Hartman3, Hartman6, Shekel5, Shekel7, Shekel10, Ellipsoid, Levy, Zakharov,
                   StyblinskiTang) {
    for (std::size_t dim : test_dims<TestType>()) {
        INFO(TestType::info.name << " in dimension " << dim);
        const TestType f(dim);
        const std::vector<double> x = f.optimum_point();
        REQUIRE(x.size() == dim);
        const double opt = f.optimum_value();
        CHECK_THAT(f.evaluate(x), WithinAbs(opt, tolerance(opt)));
        // The point is a minimum: no better value one step away in any coordinate (the points were
        // polished in 50 digits, so this also guards against a mistyped digit).
        for (std::size_t i = 0; i < dim; ++i)
            for (double h : {-1e-6, 1e-6}) {
                auto y = x;
                y[i] = std::clamp(y[i] + h, f.lower()[i], f.upper()[i]);
                CHECK(f.evaluate(y) >= opt - tolerance(opt));
            }
    }
}

TEST_CASE("classic: optima that depend on n, several minimisers, F1/F5/F10 under Yao's boxes", "[classic][optimum]") {
    // F8 and Styblinski-Tang: the minimum is n times the per-coordinate value in info.
    CHECK(Schwefel226(30).optimum_value() == 30 * -418.9828872724337);
    CHECK_THAT(Schwefel226(30).optimum_value(), WithinAbs(-12569.486618173, 1e-9));  // Yao's -12569.5
    CHECK(StyblinskiTang(7).optimum_value() == 7 * -39.16616570377141);
    CHECK(Schwefel226::info.bounded_domain);
    // Branin's three minima and the camel's mirror image.
    const Branin branin(2);
    for (const std::vector<double>& x : std::vector<std::vector<double>>{
             {-std::numbers::pi, 12.275}, {std::numbers::pi, 2.275}, {3 * std::numbers::pi, 2.475}})
        CHECK_THAT(branin.evaluate(x), WithinAbs(Branin::info.optimum_value, 1e-12));
    CHECK_THAT(Branin::info.optimum_value, WithinAbs(5.0 / (4.0 * std::numbers::pi), 1e-15));
    CHECK_THAT(SixHumpCamel(2).evaluate(std::vector<double>{-0.08984201310031806, 0.7126564030207396}),
               WithinAbs(SixHumpCamel::info.optimum_value, 1e-12));
    // The formulas of functions.hpp at their optima under Yao's tables.
    for (std::size_t dim : {2, 30}) {
        const Sphere f1(dim, yao_f1_info);
        const Rosenbrock f5(dim, yao_f5_info);
        const Ackley f10(dim, yao_f10_info);
        CHECK(f1.evaluate(f1.optimum_point()) == 0.0);
        CHECK(f5.evaluate(f5.optimum_point()) == 0.0);
        CHECK_THAT(f10.evaluate(f10.optimum_point()), WithinAbs(0.0, 1e-14));
    }
    // F12 and F13 at their minimisers -1 and 1 (sin(pi) is not 0 in double: ~1e-31).
    CHECK(Penalized1::info.optimum_coordinate == -1.0);
    CHECK(Penalized2::info.optimum_coordinate == 1.0);
    // F7 at 0: the noise only.
    QuarticNoise f7(30);
    const double v = f7.evaluate(f7.optimum_point());
    CHECK((v >= 0.0 && v < 1.0));
}

TEST_CASE("classic: the boxes of Yao's Table I and of the extras", "[classic][bounds]") {
    struct Box {
        const FunctionInfo* info;
        double lower, upper;
        std::size_t fixed_dim;
    };
    const std::vector<Box> boxes{
        {&yao_f1_info, -100, 100, 0},
        {&Schwefel222::info, -10, 10, 0},
        {&Schwefel12::info, -100, 100, 0},
        {&Schwefel221::info, -100, 100, 0},
        {&yao_f5_info, -30, 30, 0},
        {&Step::info, -100, 100, 0},
        {&QuarticNoise::info, -1.28, 1.28, 0},
        {&Schwefel226::info, -500, 500, 0},
        {&Rastrigin::info, -5.12, 5.12, 0},
        {&yao_f10_info, -32, 32, 0},
        {&Griewank::info, -600, 600, 0},
        {&Penalized1::info, -50, 50, 0},
        {&Penalized2::info, -50, 50, 0},
        {&ShekelFoxholes::info, -65.536, 65.536, 2},
        {&Kowalik::info, -5, 5, 4},
        {&SixHumpCamel::info, -5, 5, 2},
        {&Branin::info, -5, 15, 2},
        {&GoldsteinPrice::info, -2, 2, 2},
        {&Hartman3::info, 0, 1, 3},
        {&Hartman6::info, 0, 1, 6},
        {&Shekel5::info, 0, 10, 4},
        {&Shekel7::info, 0, 10, 4},
        {&Shekel10::info, 0, 10, 4},
    };
    REQUIRE(boxes.size() == yao_table.size());
    std::set<std::string_view> names;
    for (std::size_t k = 0; k < boxes.size(); ++k) {
        const YaoEntry& e = yao_table[k];
        INFO("F" << k + 1 << " " << e.function);
        CHECK(e.alias == "yao-f" + std::to_string(k + 1));
        CHECK(e.info == boxes[k].info);
        CHECK(e.info->lower == boxes[k].lower);
        CHECK(e.info->upper == boxes[k].upper);
        CHECK(e.info->fixed_dim == boxes[k].fixed_dim);
        CHECK(e.default_dim == (boxes[k].fixed_dim ? boxes[k].fixed_dim : 30));
        CHECK(yao_names[k] == e.function);
        names.insert(e.info->name);
    }
    CHECK(names.size() == 23);  // every F number has its own table
    CHECK(yao_names[0] == "sphere");
    CHECK(yao_names[8] == "rastrigin");
    CHECK(yao_names[22] == "shekel-10");
    // Branin's box differs per coordinate.
    const Branin branin(2);
    CHECK(std::vector<double>(branin.lower().begin(), branin.lower().end()) == std::vector<double>{-5.0, 0.0});
    CHECK(std::vector<double>(branin.upper().begin(), branin.upper().end()) == std::vector<double>{10.0, 15.0});
    // A Yao table given to a functions.hpp class: its box and name, the same formula.
    const Sphere f1(30, yao_f1_info);
    CHECK(f1.name() == "yao-f1");
    CHECK((f1.lower()[29] == -100.0 && f1.upper()[0] == 100.0));
    const std::vector<double> x(30, 1.5);
    CHECK(f1.evaluate(x) == Sphere(30).evaluate(x));
    // The extras.
    CHECK((Ellipsoid::info.lower == -5.12 && Ellipsoid::info.upper == 5.12));
    CHECK((Levy::info.lower == -10.0 && Levy::info.upper == 10.0));
    CHECK((Zakharov::info.lower == -5.0 && Zakharov::info.upper == 10.0));
    CHECK((StyblinskiTang::info.lower == -5.0 && StyblinskiTang::info.upper == 5.0));
}

TEMPLATE_TEST_CASE("classic: fixed dimensions are enforced", "[classic][dimension]", ShekelFoxholes, Kowalik,
                   SixHumpCamel, Branin, GoldsteinPrice, Hartman3, Hartman6, Shekel5, Shekel7, Shekel10) {
    constexpr std::size_t d = TestType::info.fixed_dim;
    CHECK_NOTHROW(TestType(d));
    CHECK_THROWS_AS(TestType(d - 1), pride::InputError);
    CHECK_THROWS_AS(TestType(d + 1), pride::InputError);
    CHECK_THROWS_AS(TestType(30), pride::InputError);
    CHECK(TestType(d).dimension() == d);
}

TEMPLATE_TEST_CASE("classic: random points in the box are no better than the optimum", "[classic][optimum]",
                   Schwefel222, Schwefel12, Schwefel221, Step, QuarticNoise, Schwefel226, Penalized1, Penalized2,
                   ShekelFoxholes, Kowalik, SixHumpCamel, Branin, GoldsteinPrice, Hartman3, Hartman6, Shekel5, Shekel7,
                   Shekel10, Ellipsoid, Levy, Zakharov, StyblinskiTang) {
    pride::Rng rng(2024);
    for (std::size_t dim : test_dims<TestType>()) {
        TestType f(dim);
        const double opt = f.optimum_value();
        for (int k = 0; k < 2000; ++k) {
            const auto x = random_point(f, rng);
            const double v = f.evaluate(x);
            INFO(TestType::info.name << " dim " << dim);
            REQUIRE(v >= opt - tolerance(opt));
        }
    }
}

TEST_CASE("classic: F7's noise is a reproducible counter-based stream", "[classic][noise]") {
    const std::vector<double> x{0.3, -1.1, 0.9, 1.27, -0.05};
    const double base = QuarticNoise::quartic(x);
    auto draws = [&](std::uint64_t seed, int n) {
        QuarticNoise f(x.size());
        f.reseed(seed);
        std::vector<double> v;
        for (int k = 0; k < n; ++k) v.push_back(f.evaluate(x));
        return v;
    };
    const auto a = draws(7, 200), b = draws(7, 200), c = draws(8, 200);
    CHECK(a == b);  // same seed, same values
    int same = 0;
    for (std::size_t k = 0; k < a.size(); ++k) same += a[k] == c[k];
    CHECK(same == 0);  // another seed, other values
    // Values in [f, f + 1), spread over that interval, and the k-th is f + noise(s, k).
    double lo = 1.0, hi = 0.0;
    for (std::size_t k = 0; k < a.size(); ++k) {
        CHECK((a[k] >= base && a[k] < base + 1.0));
        CHECK(a[k] == base + QuarticNoise::noise(7, k));
        lo = std::min(lo, a[k] - base);
        hi = std::max(hi, a[k] - base);
    }
    CHECK(lo < 0.05);
    CHECK(hi > 0.95);
    // The documented derivation: the (k+1)-th output of splitmix64 started at seed ^ salt.
    std::uint64_t state = 7 ^ QuarticNoise::kNoiseSalt;
    for (std::uint64_t k = 0; k < 5; ++k)
        CHECK(QuarticNoise::noise(7, k) == static_cast<double>(pride::splitmix64(state) >> 11) * 0x1.0p-53);
    // Seed 0 by default; reseed restarts the count; a copy continues it.
    QuarticNoise f(x.size()), g(x.size());
    g.reseed(0);
    CHECK(f.evaluate(x) == g.evaluate(x));
    CHECK(f.counter() == 1);
    QuarticNoise h = f;
    CHECK(h.evaluate(x) == f.evaluate(x));
    f.reseed(0);
    CHECK(f.counter() == 0);
    CHECK(f.evaluate(x) == base + QuarticNoise::noise(0, 0));
}

namespace {

template <class F>
void check_batch_bits(std::size_t dim, Eigen::Index cols, std::uint64_t seed) {
    const F f(dim);
    pride::Rng rng(seed);
    pride::Matrix points(static_cast<Eigen::Index>(dim), cols);
    for (Eigen::Index j = 0; j < cols; ++j)
        for (Eigen::Index i = 0; i < points.rows(); ++i) {
            const auto u = static_cast<std::size_t>(i);
            double v = rng.uniform(f.lower()[u], f.upper()[u]);
            // Some exact ties and half-integers: the floors of Step, the maxima of Schwefel 2.21.
            if (rng.below(8) == 0) v = std::round(v) + 0.5 * static_cast<double>(rng.below(2));
            points(i, j) = std::clamp(v, f.lower()[u], f.upper()[u]);
        }
    std::vector<double> batch(static_cast<std::size_t>(cols), -1.0);
    f.evaluate_batch(points, batch);
    for (Eigen::Index j = 0; j < cols; ++j) {
        const double scalar = f.evaluate(pride::column(points, j));
        INFO(F::info.name << " dim " << dim << " column " << j << ": " << scalar << " vs " << batch[j]);
        REQUIRE(std::bit_cast<std::uint64_t>(batch[static_cast<std::size_t>(j)]) ==
                std::bit_cast<std::uint64_t>(scalar));
    }
    // A view of some columns, as the evaluation guard passes it.
    const Eigen::Index k = cols / 2;
    std::vector<double> part(static_cast<std::size_t>(k));
    f.evaluate_batch(points.leftCols(k), part);
    for (Eigen::Index j = 0; j < k; ++j)
        REQUIRE(part[static_cast<std::size_t>(j)] == batch[static_cast<std::size_t>(j)]);
}

}  // namespace

TEMPLATE_TEST_CASE("classic: batch evaluation equals evaluate() bit for bit", "[classic][batch]", Schwefel221,
                   Ellipsoid) {
    std::uint64_t seed = 1;
    for (std::size_t dim : {1, 2, 10, 40})
        for (Eigen::Index cols : {1, 7, 50, 300}) check_batch_bits<TestType>(dim, cols, seed++);
}

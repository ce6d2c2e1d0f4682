// Operators of typed spaces beyond rounding (framework/variables.hpp,
// algorithms/parts/variation/categorical.hpp): categorical coordinates keep their values through
// the real-coded operators and get uniform crossover and random resetting; starts draw every
// choice alike; a user's function of declared types with constraints or several objectives
// receives its types, and the GA family and NSGA-II search such spaces.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "algorithms/ga.hpp"
#include "algorithms/parts/variation/categorical.hpp"
#include "engine/problem.hpp"
#include "engine/run.hpp"
#include "framework/random.hpp"
#include "framework/variables.hpp"
#include "tests/test_support.hpp"

using namespace pride;

namespace typed_test {

/// Four coordinates: real in [-1, 1], categorical with 4 choices, integer in [0, 5], categorical
/// with 2 choices.
struct Mixed {
    std::vector<double> lo{-1.0, 0.0, 0.0, 0.0}, hi{1.0, 3.0, 5.0, 1.0};
    std::size_t dimension() const { return 4; }
    std::span<const double> lower() const { return lo; }
    std::span<const double> upper() const { return hi; }
    VariableType variable_type(std::size_t i) const {
        return i == 0 ? VariableType::real : i == 2 ? VariableType::integer : VariableType::categorical;
    }
    double evaluate(std::span<const double> x) const { return x[0] * x[0]; }
};

/// Whether every categorical and integer coordinate of x is one of its values.
template <class P>
bool on_values(const P& p, std::span<const double> x) {
    for (std::size_t i = 0; i < p.dimension(); ++i)
        if (variable_type(p, i) != VariableType::real &&
            (x[i] != std::floor(x[i]) || x[i] < p.lower()[i] || x[i] > p.upper()[i]))
            return false;
    return true;
}

}  // namespace typed_test

using typed_test::Mixed;

TEST_CASE("categorical operators: the real-coded operator leaves categorical coordinates alone",
          "[typed][categorical]") {
    const Mixed p;
    Rng rng(5);
    // An operator that moves every coordinate: only the real and integer ones keep its moves.
    std::vector<double> a{0.5, 1.0, 2.0, 0.0}, b{-0.5, 3.0, 4.0, 1.0};
    const auto scramble = [&] {
        for (std::size_t i = 0; i < 4; ++i) {
            a[i] += 0.25;
            b[i] -= 0.25;
        }
    };
    CategoricalVariation never(p, {0.0, 0.0});
    never.cross(a, b, rng, scramble);
    CHECK(a == std::vector<double>{0.75, 1.0, 2.25, 0.0});
    CHECK(b == std::vector<double>{-0.75, 3.0, 3.75, 1.0});
    CategoricalVariation always(p, {1.0, 0.0});
    always.cross(a, b, rng, [] {});
    CHECK(a == std::vector<double>{0.75, 3.0, 2.25, 1.0});  // both categorical coordinates exchanged
    CHECK(b == std::vector<double>{-0.75, 1.0, 3.75, 0.0});
    never.mutate(a, rng, [&] { a.assign(4, 0.5); });
    CHECK(a == std::vector<double>{0.5, 3.0, 0.5, 1.0});
}

TEST_CASE("categorical operators: resetting draws every choice alike, starts too", "[typed][categorical]") {
    const Mixed p;
    Rng rng(11);
    CategoricalVariation reset(p, {0.0, 1.0});
    std::array<int, 4> seen{};
    std::array<int, 2> seen2{};
    std::vector<double> x{0.0, 0.0, 0.0, 0.0};
    const int n = 40'000;
    for (int k = 0; k < n; ++k) {
        reset.mutate(x, rng, [] {});
        REQUIRE(typed_test::on_values(p, x));
        ++seen[static_cast<std::size_t>(x[1])];
        ++seen2[static_cast<std::size_t>(x[3])];
    }
    // Binomial(40000, 1/4): sd 87, so 1,000 is over 11 sd; 1/2: sd 100.
    for (const int c : seen) CHECK(std::abs(c - n / 4) < 1'000);
    for (const int c : seen2) CHECK(std::abs(c - n / 2) < 1'200);

    // Starting values: [0, 3] cut in four equal parts, so uniform starts give each choice 1/4
    // (rounding would give the ends 1/6 and the middle choices 1/3).
    std::array<int, 4> start{};
    for (int k = 0; k < n; ++k) ++start[static_cast<std::size_t>(choice_of_start(rng.uniform(0.0, 3.0), 0.0, 3.0))];
    for (const int c : start) CHECK(std::abs(c - n / 4) < 1'000);
    CHECK(choice_of_start(0.0, 0.0, 3.0) == 0.0);
    CHECK(choice_of_start(3.0, 0.0, 3.0) == 3.0);
    CHECK(choice_of_start(0.749, 0.0, 3.0) == 0.0);
    CHECK(choice_of_start(0.751, 0.0, 3.0) == 1.0);
    CHECK(choice_of_start(std::nan(""), 0.0, 3.0) == 0.0);
    CHECK(choice_of_start(-2.0, 0.0, 3.0) == 0.0);
    CHECK(choice_of_start(7.0, 0.0, 3.0) == 3.0);
}

TEST_CASE("categorical operators: nothing drawn on a problem without categorical coordinates",
          "[typed][categorical]") {
    struct Plain {
        std::vector<double> lo{0.0, 0.0}, hi{1.0, 1.0};
        std::size_t dimension() const { return 2; }
        std::span<const double> lower() const { return lo; }
        std::span<const double> upper() const { return hi; }
        double evaluate(std::span<const double>) const { return 0.0; }
    };
    CategoricalVariation none(Plain{}, {1.0, 1.0});
    CHECK(none.empty());
    Rng used(3), fresh(3);
    std::vector<double> a{0.1, 0.2}, b{0.3, 0.4};
    int calls = 0;
    none.cross(a, b, used, [&] { ++calls; });
    none.mutate(a, used, [&] { ++calls; });
    CHECK(calls == 2);
    CHECK(used() == fresh());
}

TEST_CASE("categorical operators: the GA family and NSGA-II search a user's mixed function", "[typed][categorical]") {
    // f = cost[c] + (n - 2)^2 + (x - 0.3)^2 with c categorical among 5 unordered choices (the best,
    // 3, lies between two bad ones), n integer in [0, 6], x real in [-2, 2].
    static constexpr std::array<double, 5> cost{3.0, 1.0, 4.0, 0.0, 5.0};
    auto off = std::make_shared<std::int64_t>(0);
    engine::CallbackSpec spec;
    spec.name = "mixed";
    spec.lower = {0.0, 0.0, -2.0};
    spec.upper = {4.0, 6.0, 2.0};
    spec.types = {VariableType::categorical, VariableType::integer, VariableType::real};
    spec.scalar = [off](std::span<const double> x) {
        if (x[0] != std::floor(x[0]) || x[1] != std::floor(x[1])) ++*off;
        return cost[static_cast<std::size_t>(x[0])] + (x[1] - 2.0) * (x[1] - 2.0) + (x[2] - 0.3) * (x[2] - 0.3);
    };
    const engine::Problem problem(spec);
    engine::Budget budget;
    budget.evaluations = 4000;
    for (const char* algo : {"ga", "ga-plus", "iaga", "icga", "ga-q", "ga-sga"}) {
        INFO(algo);
        const auto r = engine::run(engine::AlgorithmSpec{algo, {}}, problem, budget, 4);
        CHECK(*off == 0);
        CHECK(r.best_x[0] == 3.0);
        CHECK(r.best_x[1] == 2.0);
        CHECK(r.best_f < 1e-3);
    }
    // Categorical rates out of their range are refused by name.
    engine::AlgorithmSpec bad{"ga", {}};
    bad.params.set("cat_swap", 1.5);
    CHECK_THAT(test::input_error_message([&] { (void)engine::run(bad, problem, budget, 1); }),
               Catch::Contains("cat_swap"));

    // Two objectives: the same cost against its reverse; NSGA-II's front holds values only.
    engine::CallbackSpec two = spec;
    two.scalar = nullptr;
    two.objectives = 2;
    two.values = [off](std::span<const double> x, std::span<double> f) {
        if (x[0] != std::floor(x[0]) || x[1] != std::floor(x[1])) ++*off;
        const auto c = static_cast<std::size_t>(x[0]);
        f[0] = cost[c] + (x[1] - 2.0) * (x[1] - 2.0) + x[2] * x[2];
        f[1] = cost[4 - c] + (x[1] - 4.0) * (x[1] - 4.0) + (x[2] - 1.0) * (x[2] - 1.0);
    };
    const engine::Problem mo(two);
    for (const char* algo : {"nsga2", "nsga3"}) {
        INFO(algo);
        const auto r = engine::run(engine::AlgorithmSpec{algo, {}}, mo, budget, 2);
        CHECK(*off == 0);
        REQUIRE(r.front);
        REQUIRE(r.front->x.cols() > 1);
        for (Eigen::Index j = 0; j < r.front->x.cols(); ++j) {
            const std::span<const double> x(r.front->x.col(j).data(), 3);
            CHECK(x[0] == std::floor(x[0]));
            CHECK(x[1] == std::floor(x[1]));
            std::array<double, 2> f{};
            two.values(x, f);
            CHECK(f[0] == r.front->f(0, j));  // the reported point has the reported values
            CHECK(f[1] == r.front->f(1, j));
        }
    }
}

TEST_CASE("typed variables with constraints: the function receives its types, the result reports them",
          "[typed][constraints]") {
    // min (n - 2.6)^2 + x^2 subject to 3 - n <= 0, n integer in [0, 9]: n = 3, f = 0.16.
    auto off = std::make_shared<std::int64_t>(0);
    engine::CallbackSpec spec;
    spec.name = "constrained-mixed";
    spec.lower = {0.0, -1.0};
    spec.upper = {9.0, 1.0};
    spec.types = {VariableType::integer, VariableType::real};
    spec.inequalities = 1;
    spec.constrained = [off](std::span<const double> x, std::span<double> g) {
        if (x[0] != std::floor(x[0])) ++*off;
        g[0] = 3.0 - x[0];
        return (x[0] - 2.6) * (x[0] - 2.6) + x[1] * x[1];
    };
    const engine::Problem problem(spec);
    engine::Budget budget;
    budget.evaluations = 3000;
    for (const char* algo : {"de", "pso", "ga"}) {
        INFO(algo);
        const auto r = engine::run(engine::AlgorithmSpec{algo, {}}, problem, budget, 3);
        CHECK(*off == 0);
        CHECK(r.best_x[0] == 3.0);
        REQUIRE(r.best_violation);
        CHECK(*r.best_violation == 0.0);
        CHECK(r.best_f == Approx(0.16).margin(1e-6));
    }
    engine::CallbackSpec bad = spec;
    bad.lower[0] = 0.5;
    CHECK_THAT(test::input_error_message([&] { (void)engine::Problem(bad); }),
               Catch::Contains("variable 0 (integer) needs integer bounds"));
}

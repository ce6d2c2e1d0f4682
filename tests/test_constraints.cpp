// Constraints (framework/constraints.hpp) and their handlers (framework/constraint_handlers.hpp,
// constraint_order.hpp): the violation as CEC 2006 and 2020 define it, each handler on hand-worked
// cases from its paper's definition, the run guard's count and its best point by Deb's rules, and
// PSO on a constrained problem under each handler.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <string>
#include <tuple>
#include <vector>

#include "algorithms/de.hpp"
#include "algorithms/pso.hpp"
#include "engine/problem.hpp"
#include "engine/run.hpp"
#include "framework/constraint_handlers.hpp"
#include "framework/constraint_order.hpp"
#include "framework/constraints.hpp"
#include "framework/run_state.hpp"
#include "tests/cli_runner.hpp"
#include "tests/disc_problem.hpp"
#include "tests/json_reader.hpp"
#include "tests/test_support.hpp"

using namespace pride;

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

using test::Disc;

Matrix points_of(std::initializer_list<std::pair<double, double>> xs) {
    Matrix m(2, static_cast<Eigen::Index>(xs.size()));
    Eigen::Index j = 0;
    for (const auto& [a, b] : xs) {
        m(0, j) = a;
        m(1, j++) = b;
    }
    return m;
}

}  // namespace

TEST_CASE("violation: the mean of the inequalities' and equalities' excess, as CEC 2006 and 2020", "[constraints]") {
    const ConstraintCounts counts{2, 2};
    // G = max(0, g): 1, 0; H = |h| beyond the tolerance 1e-4: 0.5, 0 (5e-5 is within it).
    const std::vector<double> c{1.0, -2.0, -0.5, 5e-5};
    CHECK(mean_violation(c, counts) == (1.0 + 0.5) / 4.0);
    CHECK(mean_violation(c, counts, 0.0) == Approx((1.0 + 0.5 + 5e-5) / 4.0).epsilon(1e-15));
    CHECK(mean_violation(std::vector<double>{-1.0, 0.0, 0.0, 0.0}, counts) == 0.0);
    CHECK(mean_violation(std::vector<double>{std::nan(""), 0.0, 0.0, 0.0}, counts) == inf);
    CHECK(mean_violation({}, ConstraintCounts{}) == 0.0);
}

TEST_CASE("Deb's feasibility rules, the epsilon level and a static penalty compare (f, v) pairs", "[constraints]") {
    using constraints::deb_better;
    CHECK(deb_better(5.0, 0.0, 1.0, 0.1));  // feasible beats infeasible, whatever f
    CHECK_FALSE(deb_better(1.0, 0.1, 5.0, 0.0));
    CHECK(deb_better(1.0, 0.0, 2.0, 0.0));  // both feasible: by f
    CHECK(deb_better(9.0, 0.2, 1.0, 0.3));  // both infeasible: by v
    CHECK_FALSE(deb_better(1.0, 0.0, 1.0, 0.0));

    using constraints::epsilon_better;
    CHECK(epsilon_better(2.0, 0.3, 3.0, 0.4, 0.5));  // both within epsilon: by f
    CHECK(epsilon_better(2.0, 0.3, 1.0, 0.6, 0.5));  // one beyond: by v
    CHECK(epsilon_better(1.0, 0.7, 2.0, 0.7, 0.5));  // equal violations: by f
    CHECK(epsilon_better(5.0, 0.0, 1.0, 0.1, 0.0));  // epsilon 0: Deb's rules
    CHECK_FALSE(epsilon_better(1.0, 0.1, 5.0, 0.0, 0.0));

    CHECK(constraints::static_penalty(2.0, 0.5, 10.0) == 7.0);
    CHECK(constraints::static_penalty(2.0, 0.0, 10.0) == 2.0);
}

TEST_CASE("the epsilon level starts at the theta-th violation and falls as (1 - t/Tc)^cp", "[constraints]") {
    constraints::EpsilonSchedule s;
    s.cp = 2.0;
    s.tc = 10;
    s.theta = 0.2;
    s.start(std::vector<double>{9, 8, 7, 6, 5, 4, 3, 2, 1, 0});  // theta N = 2: the 2nd smallest, 1
    CHECK(s.initial == 1.0);
    CHECK(s.level(0) == 1.0);
    CHECK(s.level(5) == 0.25);
    CHECK(s.level(9) == Approx(0.01).epsilon(1e-12));
    CHECK(s.level(10) == 0.0);
    CHECK(s.level(11) == 0.0);
    s.start(std::vector<double>{3.0});  // fewer points than 1 / theta: the first
    CHECK(s.initial == 3.0);
}

TEST_CASE("stochastic ranking: by v with P_f = 0 (f among feasible points), by f with P_f = 1", "[constraints]") {
    const std::vector<double> f{3, 1, 2, 0}, v{0, 0, 1, 0.5};
    Rng rng(1);
    std::vector<std::size_t> order{0, 1, 2, 3};
    constraints::stochastic_rank(order, f, v, 0.0, 4, rng);
    CHECK(order == std::vector<std::size_t>{1, 0, 3, 2});
    order = {0, 1, 2, 3};
    constraints::stochastic_rank(order, f, v, 1.0, 4, rng);
    CHECK(order == std::vector<std::size_t>{3, 1, 2, 0});
    // One draw per comparison: a sweep of 4 points is 3 draws; a second sweep stops (no swap).
    Rng a(7), b(7);
    order = {1, 0, 3, 2};
    constraints::stochastic_rank(order, f, v, 0.0, 4, a);
    for (int k = 0; k < 3; ++k) (void)b.uniform();
    CHECK(a() == b());
    // The same seed gives the same ranking at P_f = 0.45.
    std::vector<std::size_t> o1(4), o2(4);
    std::iota(o1.begin(), o1.end(), 0);
    std::iota(o2.begin(), o2.end(), 0);
    Rng r1(3), r2(3);
    constraints::stochastic_rank(o1, f, v, 0.45, 4, r1);
    constraints::stochastic_rank(o2, f, v, 0.45, 4, r2);
    CHECK(o1 == o2);
}

TEST_CASE("the adaptive penalty (APM) on a hand-worked population", "[constraints]") {
    // <f> = 20; <v> = (1, 2/3); sum <v>^2 = 13/9; k = 20 / (13/9) <v> = (180/13, 120/13).
    const std::vector<double> f{10, 20, 30};
    Matrix v(2, 3);
    v << 0, 1, 2, 0, 0, 2;
    std::vector<double> out(3);
    constraints::adaptive_penalty(f, v, out);
    CHECK(out[0] == 10.0);                                                        // feasible: f
    CHECK(out[1] == Approx(20.0 + 180.0 / 13.0).epsilon(1e-14));                  // max(20, <f>) + k1
    CHECK(out[2] == Approx(30.0 + 2.0 * (180.0 + 120.0) / 13.0).epsilon(1e-14));  // 30 + 2 k1 + 2 k2
    Matrix none = Matrix::Zero(2, 3);
    constraints::adaptive_penalty(f, none, out);
    CHECK(out == f);
}

TEST_CASE("the run guard counts each constrained evaluation once and keeps Deb's best point", "[constraints]") {
    Disc disc;
    Termination t;
    t.max_evaluations = 6;
    RunState state(t, 2);
    // (0, 0): v = 1; (2, 2): feasible, f 8; (1.5, 0): feasible, f 2.25; (0.2, 0.2): v = 0.6.
    const Matrix x = points_of({{0, 0}, {2, 2}, {1.5, 0}, {0.2, 0.2}});
    std::vector<double> f(4), v(4);
    CHECK(state.evaluate_columns(disc, x, f, v) == 4);
    CHECK(*disc.constrained_calls == 4);
    CHECK(*disc.plain_calls == 0);
    CHECK(v == std::vector<double>{1.0, 0.0, 0.0, 1.0 - 0.2 - 0.2});
    CHECK(state.best() == 2.25);
    CHECK(state.best_x() == std::vector<double>{1.5, 0.0});
    // Past the budget: two more, the rest +inf and not evaluated.
    const Matrix y = points_of({{0.5, 0.5}, {3, 3}, {1, 1}});
    std::vector<double> g(3), w(3);
    CHECK(state.evaluate_columns(disc, y, g, w) == 2);
    CHECK(*disc.constrained_calls == 6);
    CHECK(g[2] == inf);
    CHECK(w[2] == inf);
    const Result r = state.finish();
    CHECK(r.best_f == 0.5);
    CHECK(r.best_violation == 0.0);
    CHECK(r.first_feasible == 2);
    CHECK(r.evaluations == 6);

    // No feasible point: the least violating one is the best, its value the run's best_f.
    RunState none(Termination{}, 2);
    const Matrix z = points_of({{0, 0}, {0.25, 0.25}, {-1, -1}});
    none.evaluate_columns(disc, z, g, w);
    CHECK(none.best() == inf);  // stopping rules and targets see feasible values only
    const Result rn = none.finish();
    CHECK(rn.best_violation == 0.5);
    CHECK(rn.best_f == 0.125);
    CHECK(rn.best_x == std::vector<double>{0.25, 0.25});
    CHECK_FALSE(rn.first_feasible.has_value());
}

TEST_CASE("PSO on a constrained problem: each handler reaches the optimum, every evaluation counted", "[constraints]") {
    for (const auto handler : {ConstraintHandling::Handler::deb, ConstraintHandling::Handler::epsilon,
                               ConstraintHandling::Handler::penalty}) {
        INFO(static_cast<int>(handler));
        Pso<> pso;
        pso.population = 20;
        pso.constraints.handler = handler;
        pso.constraints.epsilon.tc = 100;
        Disc disc;
        Termination t;
        t.max_evaluations = 4000;
        const Result r = pso.run(disc, t, 11);
        CHECK(r.evaluations == 4000);
        CHECK(*disc.constrained_calls == 4000);
        CHECK(*disc.plain_calls == 0);
        CHECK(r.best_violation == 0.0);
        CHECK(r.best_f == Approx(0.5).epsilon(1e-3));
        CHECK(r.best_x[0] + r.best_x[1] >= 1.0);
        CHECK(r.first_feasible.has_value());
        const Result again = pso.run(Disc{}, t, 11);
        CHECK(again.best_x == r.best_x);
        CHECK(again.history == r.history);
    }
    Pso<> bad;
    bad.constraints.penalty = -1.0;
    CHECK_THROWS_WITH(bad.run(Disc{}, Termination{}, 1), Catch::Contains("penalty"));
}

TEST_CASE("DE under constraints: rank, worst and gains follow the handler's order", "[constraints]") {
    const ConstraintOrder deb(ConstraintHandling{});
    // Points: 0 infeasible (v 2), 1 feasible f 3, 2 infeasible (v 1), 3 feasible f 1.
    const std::vector<double> f{0.0, 3.0, -5.0, 1.0}, v{2.0, 0.0, 1.0, 0.0};
    std::vector<std::size_t> order(4);
    de::rank(deb, f, v, order, 4);
    CHECK(order == std::vector<std::size_t>{3, 1, 2, 0});
    de::rank(deb, f, v, order, 1);
    CHECK(order[0] == 3);
    CHECK(de::worst_index(deb, f, v) == 0);
    // Without constraints: by value, the first of the largest.
    CHECK(de::worst_index(PlainOrder{}, std::vector<double>{1.0, 4.0, 4.0}, std::vector<double>(3, 0.0)) == 1);
    // Gains: falls of f 2, 0, 4 and of v 0, 3, 1 -> 2/4 + 0, 0 + 3/3, 4/4 + 1/3.
    std::vector<double> df{2.0, 0.0, 4.0};
    de::combine_gains(df, std::vector<double>{0.0, 3.0, 1.0});
    CHECK(df == std::vector<double>{0.5, 1.0, 1.0 + 1.0 / 3.0});
    // An infinite fall (an infinite violation made finite) takes the whole share of its kind.
    std::vector<double> dg{1.0, 1.0};
    de::combine_gains(dg, std::vector<double>{inf, 5.0});
    CHECK(dg == std::vector<double>{2.0, 1.0});
}

TEST_CASE("DE, L-SHADE and jSO on a constrained problem: each handler reaches the optimum, every evaluation counted",
          "[constraints]") {
    using Family = De<de::SelectableMutation, de::SelectableControl, de::SelectableRepair, de::SelectableSize,
                      de::SelectableReduction>;
    for (const auto handler : {ConstraintHandling::Handler::deb, ConstraintHandling::Handler::epsilon,
                               ConstraintHandling::Handler::penalty}) {
        for (const bool lshade : {false, true}) {
            INFO(static_cast<int>(handler) << (lshade ? " lshade" : " de"));
            Family de;
            de.population = 30;
            if (lshade) {
                de.mutation = de::CurrentToPBest<de::FixedRate>{{0.11}};
                de.control = de::LshadeControl{};
                de.archive.rate = 2.6;
                de.reduction = de::LinearReduction{4};
            }
            de.constraints.handler = handler;
            de.constraints.epsilon.tc = 100;
            Disc disc;
            Termination t;
            t.max_evaluations = 6000;
            const Result r = de.run(disc, t, 5);
            CHECK(r.evaluations == 6000);
            CHECK(*disc.constrained_calls == 6000);
            CHECK(*disc.plain_calls == 0);
            CHECK(r.best_violation == 0.0);
            CHECK(r.best_f == Approx(0.5).epsilon(1e-4));
            CHECK(r.best_x[0] + r.best_x[1] >= 1.0);
            REQUIRE(r.first_feasible.has_value());
            CHECK(*r.first_feasible <= 30);  // half the plane is feasible: the first population has a point
            const Result again = de.run(Disc{}, t, 5);
            CHECK(again.best_x == r.best_x);
            CHECK(again.history == r.history);
        }
    }
    Family bad;
    bad.constraints.epsilon.tc = 0;
    CHECK_THROWS_WITH(bad.run(Disc{}, Termination{}, 1), Catch::Contains("epsilon_tc"));
}

namespace {

/// The same disc as a user's function through the engine.
engine::CallbackSpec disc_spec(std::shared_ptr<std::int64_t> calls) {
    engine::CallbackSpec s;
    s.name = "disc";
    s.lower = {-2.0, -2.0};
    s.upper = {2.0, 2.0};
    s.inequalities = 1;
    s.constrained = [calls](std::span<const double> x, std::span<double> c) {
        ++*calls;
        c[0] = 1.0 - x[0] - x[1];
        return x[0] * x[0] + x[1] * x[1];
    };
    return s;
}

engine::Budget evaluations(std::int64_t n) {
    engine::Budget b;
    b.evaluations = n;
    return b;
}

}  // namespace

TEST_CASE("engine: a user's function with constraints runs with the algorithms that handle them", "[constraints]") {
    auto calls = std::make_shared<std::int64_t>(0);
    const engine::Problem disc(disc_spec(calls));
    const auto r = engine::run({"pso", {}}, disc, evaluations(3000), 4);
    CHECK(r.evaluations == 3000);
    CHECK(*calls == 3000);
    REQUIRE(r.best_violation.has_value());
    CHECK(*r.best_violation == 0.0);
    CHECK(r.best_f == Approx(0.5).epsilon(1e-3));
    CHECK(r.first_feasible.has_value());
    const auto again = engine::run({"pso", {}}, disc, evaluations(3000), 4);
    CHECK(again.best_x == r.best_x);

    engine::ParamValues epsilon;
    epsilon.set_from_string("constraints=epsilon");
    epsilon.set_from_string("epsilon_tc=50");
    const auto e = engine::run({"pso-constriction", epsilon}, disc, evaluations(3000), 4);
    CHECK(*e.best_violation == 0.0);
    CHECK(e.best_f == Approx(0.5).epsilon(1e-3));

    // A problem without constraints has no violation, and refuses the handlers' parameters.
    const engine::Problem sphere(engine::ContinuousSpec{"sphere", 2});
    CHECK_FALSE(engine::run({"pso", {}}, sphere, evaluations(100), 1).best_violation.has_value());
    const std::string refused = test::input_error_message([&] {
        engine::check({"pso", epsilon}, sphere, evaluations(100));
    });
    CHECK(refused.find("constraints says how constraints are handled; sphere has none") != std::string::npos);
    // An algorithm without constraint handling is refused, naming those with it.
    const std::string hs = test::input_error_message([&] { engine::check({"hs", {}}, disc, evaluations(100)); });
    CHECK(hs.find("algo: hs does not handle constraints") == 0);
    CHECK(hs.find("pso") != std::string::npos);
    CHECK(hs.find("cmaes") != std::string::npos);
    engine::Budget threads = evaluations(100);
    threads.threads = 2;
    CHECK(test::input_error_message([&] { engine::check({"pso", {}}, disc, threads); }).find("threads:") == 0);
}

TEST_CASE("engine: constraint declarations are checked, and a NaN constraint is an infinite violation",
          "[constraints]") {
    auto calls = std::make_shared<std::int64_t>(0);
    auto bad = disc_spec(calls);
    bad.inequalities = -1;
    CHECK(test::input_error_message([&] {
              engine::Problem{bad};
          }).find("inequalities: must be an integer in [0, 1000000]") == 0);
    bad = disc_spec(calls);
    bad.inequalities = 0;
    CHECK(test::input_error_message([&] { engine::Problem{bad}; }).find("constraints:") == 0);
    bad = disc_spec(calls);
    bad.constrained = nullptr;
    CHECK(test::input_error_message([&] { engine::Problem{bad}; }).find("constraints:") == 0);
    bad = disc_spec(calls);
    bad.tolerance = -1.0;
    CHECK(test::input_error_message([&] { engine::Problem{bad}; }).find("tolerance:") == 0);
    bad = disc_spec(calls);
    bad.objectives = 2;
    bad.values = [](std::span<const double>, std::span<double>) {};
    CHECK(test::input_error_message([&] { engine::Problem{bad}; }).find("constraints:") == 0);

    auto nan = disc_spec(calls);
    nan.constrained = [](std::span<const double> x, std::span<double> c) {
        c[0] = std::nan("");
        return x[0];
    };
    const auto r = engine::run({"pso", {}}, engine::Problem(nan), evaluations(200), 1);
    CHECK(r.evaluations == 200);
    CHECK(*r.best_violation == inf);
    CHECK_FALSE(r.first_feasible.has_value());
}

TEST_CASE("engine and pride run: the CEC 2006 problems by name, with their violation reported", "[constraints]") {
    const engine::Problem g06(engine::ContinuousSpec{"cec2006-g06", 2});
    CHECK(g06.dimension() == 2);
    // PSO with the inertia weight settles on the bound x1 = 13 (a plateau of the violation) from
    // some seeds; the constriction form reaches the feasible crescent from this one.
    const auto r = engine::run({"pso-constriction", {}}, g06, evaluations(20000), 1);
    REQUIRE(r.best_violation.has_value());
    CHECK(*r.best_violation == 0.0);
    CHECK(r.best_f < -6900.0);  // f* = -6961.81387558015 (Liang et al. 2006)
    CHECK(r.best_f >= -6961.81387558015 - 1e-6);
    CHECK(test::input_error_message([] {
              engine::Problem{engine::ContinuousSpec{"cec2006-g06", 3}};
          }).find("dim: cec2006-g06 has dimension 2, got 3") == 0);
    CHECK(test::input_error_message([] {
              engine::Problem{engine::ContinuousSpec{"cec2006-g25", 2}};
          }).find("problem:") == 0);

    const auto text =
        test::run_pride("run --algo pso-constriction --problem cec2006-g06 --dim 2 --evals 20000 --seed 1 --json");
    REQUIRE(text.status == 0);
    const auto doc = test::parse_json(text.out);
    CHECK(doc.at("best_violation").number == 0.0);
    CHECK(doc.at("first_feasible").kind == test::JsonValue::Kind::number);
    const auto plain =
        test::run_pride("run --algo pso-constriction --problem cec2006-g06 --dim 2 --evals 20000 --seed 1");
    CHECK(plain.out.find("violation    0\n") != std::string::npos);
    // The DE family on the same problem and budget. DE's default NP = 10 D = 20 collapses on the
    // crescent before reaching its tip (f = -5283 from this seed, feasible from evaluation 190);
    // with NP = 50 it reaches f*.
    for (const auto& [algo, pop, within] : std::vector<std::tuple<std::string, double, double>>{{"de", 50.0, 1e-9},
                                                                                                {"jde", 0.0, 1e-9},
                                                                                                {"jade", 0.0, 1e-5},
                                                                                                {"shade", 0.0, 1e-5},
                                                                                                {"lshade", 0.0, 1e-9},
                                                                                                {"jso", 0.0, 1e-9}}) {
        INFO(algo);
        engine::ParamValues params;
        if (pop > 0.0) params.set("pop", pop);
        const auto d = engine::run({algo, params}, g06, evaluations(20000), 1);
        CHECK(*d.best_violation == 0.0);
        CHECK(d.best_f == Approx(-6961.81387558015).epsilon(within));
        CHECK(d.best_f >= -6961.81387558015 - 1e-6);
    }
    test::expect_input_error("run --algo hs --problem cec2006-g06 --dim 2 --evals 200",
                             {"does not handle constraints"});
    test::expect_input_error("run --algo pso --problem sphere --dim 2 --evals 200 --param constraints=epsilon",
                             {"sphere has none"});
}

TEST_CASE("pride list: every constrained problem it names is built and run by that name", "[constraints]") {
    const auto& items = engine::constrained_problems();
    CHECK(items.size() == 24 + 57 + 54);
    for (const auto& item : items) {
        INFO(item.name);
        std::int64_t dim = 2;  // bbob-constrained: any from 2 to 40
        if (const auto at = item.summary.find("(dim = "); at != std::string::npos)
            dim = std::stoll(item.summary.substr(at + 7));
        const engine::Problem problem(engine::ContinuousSpec{item.name, dim});
        CHECK(problem.dimension() == static_cast<std::size_t>(dim));
        const auto r = engine::run({"de", {}}, problem, evaluations(50), 1);
        CHECK(r.evaluations == 50);
        CHECK(r.best_violation.has_value());
    }
    CHECK(test::input_error_message([] {
              engine::Problem{engine::ContinuousSpec{"cec2020rw-rc58", 9}};
          }).find("problem:") == 0);
    const auto listed = test::run_pride("list");
    REQUIRE(listed.status == 0);
    CHECK(listed.out.find("constrained_problems:\n  cec2006-g01 ") != std::string::npos);
    CHECK(listed.out.find("  bbob-constrained-f54 ") != std::string::npos);
    CHECK(listed.out.find("  cec2020rw-rc24 ") != std::string::npos);
}

// CMA-ES on problems with constraints (algorithms/cmaes.hpp): the lambda points ranked by Deb's
// rules, the epsilon level or a static penalty, and the augmented Lagrangian of Atamna, Auger and
// Hansen (2016, 2017) as pycma adapts it (algorithms/parts/cma/augmented_lagrangian.hpp).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "algorithms/cmaes.hpp"
#include "algorithms/parts/cma/augmented_lagrangian.hpp"
#include "engine/problem.hpp"
#include "engine/run.hpp"
#include "framework/constraints.hpp"
#include "tests/cli_runner.hpp"
#include "tests/disc_problem.hpp"
#include "tests/test_support.hpp"

using namespace pride;

namespace {

engine::Budget budget(std::int64_t n) {
    engine::Budget b;
    b.evaluations = n;
    return b;
}

engine::ParamValues params(std::initializer_list<std::string> settings) {
    engine::ParamValues p;
    for (const auto& s : settings) p.set_from_string(s);
    return p;
}

/// The test of pycma's ConstrainedFitnessAL: the sphere sum x_i^2 under the linear constraint
/// g(x) = x_1 + 1 <= 0 on [-5, 5]^n. The optimum is x* = (-1, 0, ..., 0), f* = 1, on the
/// constraint; from grad f(x*) + lam* grad g(x*) = (-2, 0, ...) + lam* (1, 0, ...) = 0 its Lagrange
/// multiplier is lam* = 2.
struct LinearSphere {
    std::size_t n = 3;
    std::vector<double> lo = std::vector<double>(n, -5.0), hi = std::vector<double>(n, 5.0);
    std::shared_ptr<std::int64_t> calls = std::make_shared<std::int64_t>(0);
    std::size_t dimension() const { return n; }
    std::span<const double> lower() const { return lo; }
    std::span<const double> upper() const { return hi; }
    double evaluate(std::span<const double> x) const {
        double s = 0.0;
        for (const double v : x) s += v * v;
        return s;
    }
    bool equality = false;  // h(x) = x_1 + 1 = 0 instead: the same x* and lam*
    ConstraintCounts constraint_counts() const { return equality ? ConstraintCounts{0, 1} : ConstraintCounts{1, 0}; }
    double evaluate_constrained(std::span<const double> x, std::span<double> c) {
        ++*calls;
        c[0] = x[0] + 1.0;
        return evaluate(x);
    }
    double violation(std::span<const double> c) const { return mean_violation(c, constraint_counts()); }
};
static_assert(ConstrainedProblem<LinearSphere>);

double distance_to_optimum(std::span<const double> x) {
    double s = (x[0] + 1.0) * (x[0] + 1.0);
    for (std::size_t i = 1; i < x.size(); ++i) s += x[i] * x[i];
    return std::sqrt(s);
}

}  // namespace

TEST_CASE("CMA-ES with Deb's rules reaches the optimum of CEC 2006 g06 and g08", "[cmaes][constraints]") {
    // f* of Liang et al. (2006): g06 -6961.81387558015, g08 -0.0958250414180359.
    const engine::Problem g06(engine::ContinuousSpec{"cec2006-g06", 2});
    const auto r6 = engine::run({"cmaes", {}}, g06, budget(20000), 1);
    REQUIRE(r6.best_violation.has_value());
    CHECK(*r6.best_violation == 0.0);
    CHECK(r6.first_feasible.has_value());
    CHECK(r6.evaluations == 20000);
    CHECK(r6.best_f == Approx(-6961.81387558015).epsilon(1e-9));
    CHECK(r6.best_f >= -6961.81387558015 - 1e-6);

    const engine::Problem g08(engine::ContinuousSpec{"cec2006-g08", 2});
    for (const std::string algo : {"cmaes", "ipop-cmaes", "bipop-cmaes", "sep-cmaes"}) {
        for (const std::string handler : {"deb", "epsilon", "penalty"}) {
            INFO(algo << " " << handler);
            const auto r8 = engine::run({algo, params({"constraints=" + handler})}, g08, budget(5000), 2);
            CHECK(*r8.best_violation == 0.0);
            CHECK(r8.evaluations == 5000);
            CHECK(r8.best_f == Approx(-0.0958250414180359).epsilon(1e-9));
        }
    }
}

TEST_CASE("CMA-ES under constraints: every evaluation counted once, the same run from the same seed",
          "[cmaes][constraints]") {
    for (const auto lagrangian : {false, true}) {
        for (const auto handler : {ConstraintHandling::Handler::deb, ConstraintHandling::Handler::epsilon,
                                   ConstraintHandling::Handler::penalty}) {
            INFO(lagrangian << " " << static_cast<int>(handler));
            Cmaes<> cma;
            cma.constraints.handler = handler;
            cma.constraints.epsilon.tc = 100;
            cma.augmented_lagrangian = lagrangian;
            cma.restarts = cma::Ipop{};
            test::Disc disc;
            Termination t;
            t.max_evaluations = 3001;  // restarts, and a last generation cut by the budget
            std::vector<cma::RunLog> log;
            const Result r = cma.run_logged(disc, t, 5, NoObserver{}, &log);
            CHECK(r.evaluations == 3001);
            CHECK(*disc.constrained_calls == 3001);
            CHECK(*disc.plain_calls == 0);
            CHECK(r.best_violation == 0.0);
            CHECK(r.best_f == Approx(0.5).epsilon(1e-5));
            CHECK(log.size() >= 2);  // IPOP restarted
            const Result again = cma.run(test::Disc{}, t, 5);
            CHECK(again.best_x == r.best_x);
            CHECK(again.history == r.history);
        }
    }
}

TEST_CASE("the augmented Lagrangian's coefficients follow pycma's set_coefficients and update by hand",
          "[cmaes][constraints]") {
    cma::AugmentedLagrangian al;
    al.reset(2, {1, 0}, cma::AlSettings{});
    CHECK(al.chi() == std::pow(2.0, 1.0 / 10.0));  // 2^(1 / (5 n)), n = 2
    // One generation: f = 1..5, g = -2, -1, 0.5, 1, 3, ranked before any coefficient (penalty 0).
    const std::vector<double> f{1, 2, 3, 4, 5}, g{-2, -1, 0.5, 1, 3};
    for (const double gi : g) CHECK(al.penalty(std::span<const double>(&gi, 1)) == 0.0);
    al.end_generation(f, g, f);
    // numpy's linear percentiles: iqr(f) = 4 - 2 = 2, iqr(g) = 1 - (-1) = 2, iqr(g^2) of
    // 0.25, 1, 1, 4, 9 = 4 - 1 = 3; the sign average -1 + 2 (3 / 5) = 0.2 (> -0.8: set; |.| < 0.8:
    // initialised):
    //   mu = 2/5 iqr(f) / n / (iqr(g) + 1e-6 iqr(g^2) + 1e-11 (iqr(f) + 1)) = 0.4 / 2.00000300000003
    //      = 0.19999970000...
    //   lam = iqr(f) / (n iqr(g) + 1e-11 (iqr(f) + 1)) = 2 / 4.00000000003 = 0.49999999999625
    const double mu0 = 0.4 * 2.0 / 2.0 / (2.0 + 1e-6 * 3.0 + 1e-11 * 3.0);
    const double lam0 = 2.0 / (2.0 * 2.0 + 1e-11 * 3.0);
    CHECK(al.coefficients()[0] == Approx(mu0).epsilon(1e-15));
    CHECK(al.multipliers()[0] == Approx(lam0).epsilon(1e-15));
    CHECK(al.initialized(0));
    // The update stored the best by the ranked values, (f, g) = (1, -2), and changed nothing.
    CHECK(al.multipliers()[0] == Approx(lam0).epsilon(1e-15));

    // Step 1: (f, g) = (0.5, 0.2). P(g) = lam g + mu g^2 / 2 (g > -lam / mu = -2.5: not raised):
    // P(0.2) = 0.1039999940, P(-2) = -0.6000006000; dh = 0.5 + P(0.2) - 1 - P(-2) = 0.2040005940.
    // lam += mu 0.2 / dgamma = lam + 0.04 mu = 0.5079999880. mu g^2 = 0.0080 < k1 |dh| / n = 0.3060:
    // mu *= chi^(1/4) = 2^(1/40): 0.2034956332.
    const double g1 = 0.2;
    al.update(0.5, std::span<const double>(&g1, 1));
    const double lam1 = lam0 + mu0 * 0.2 / 5.0;
    const double mu1 = mu0 * std::pow(2.0, 1.0 / 40.0);
    CHECK(al.multipliers()[0] == Approx(lam1).epsilon(1e-14));
    CHECK(al.multipliers()[0] == Approx(0.507999987996148).epsilon(1e-12));
    CHECK(al.coefficients()[0] == Approx(mu1).epsilon(1e-14));
    CHECK(al.coefficients()[0] == Approx(0.20349563317403507).epsilon(1e-12));

    // Step 2: g = 1.2 with f such that dh = 0 (f = 0.5 + P(0.2) - P(1.2) with the present lam1, mu1);
    // dg = 1: k2 |dg| = 5 >= |g_prev| = 0.2 and mu g^2 > 0 = k1 |dh| / n: mu /= chi; lam += 1.2 mu / 5.
    auto P = [&](double x) { return lam1 * x + 0.5 * mu1 * x * x; };
    const double g2 = 1.2;
    al.update(0.5 + P(0.2) - P(1.2), std::span<const double>(&g2, 1));
    CHECK(al.multipliers()[0] == Approx(lam1 + mu1 * 1.2 / 5.0).epsilon(1e-14));
    CHECK(al.coefficients()[0] == Approx(mu1 / std::pow(2.0, 0.1)).epsilon(1e-14));

    // An inactive constraint: the multiplier falls to 0 and stays there, mu unchanged.
    const double lam2 = al.multipliers()[0], mu2 = al.coefficients()[0];
    const double g3 = -1000.0;  // mu g < -lam: the penalty is its minimum -lam^2 / (2 mu)
    CHECK(al.penalty(std::span<const double>(&g3, 1)) == Approx(-lam2 * lam2 / (2.0 * mu2)));
    al.update(0.0, std::span<const double>(&g3, 1));
    CHECK(al.multipliers()[0] == 0.0);
    CHECK(al.coefficients()[0] == mu2);

    // Bad parameters are refused in one line.
    cma::AlSettings bad;
    bad.chi = 0.5;
    CHECK(test::input_error_message([&] { bad.validate("cmaes"); }).find("al_chi must be") != std::string::npos);
}

TEST_CASE("CMA-ES with the augmented Lagrangian converges linearly on the linearly constrained sphere",
          "[cmaes][constraints]") {
    Cmaes<> cma;
    cma.augmented_lagrangian = true;
    cma.restarts = cma::NoRestarts{};
    // The distance of the best feasible point so far at each generation.
    std::vector<std::pair<std::int64_t, double>> distance;
    auto observe = [&](const IterationView& v) {
        if (!std::isnan(v.best_x[0])) distance.emplace_back(v.evaluations, distance_to_optimum(v.best_x));
    };
    LinearSphere sphere;
    Termination t;
    t.max_evaluations = 4000;
    std::vector<cma::RunLog> log;
    const Result r = cma.run_logged(sphere, t, 3, observe, &log);
    REQUIRE(log.size() == 1);
    INFO("evaluations " << r.evaluations << " stop " << static_cast<int>(log[0].stop));
    CHECK(*sphere.calls == r.evaluations);
    CHECK(r.best_violation == 0.0);
    // The run ends by TolFun (its penalised values within 1e-12) near 1300 evaluations, the
    // best feasible point 1.6e-7 from x* (measured with this seed).
    CHECK(log[0].stop == cma::Stop::tol_fun);
    CHECK(distance_to_optimum(r.best_x) < 1e-6);
    CHECK(r.best_f == Approx(1.0).epsilon(1e-6));
    // The multiplier approaches lam* = 2 (2.0000005 here).
    REQUIRE(log[0].multipliers.size() == 1);
    CHECK(log[0].multipliers[0] == Approx(2.0).epsilon(1e-5));
    // Linear convergence: log distance falls as much in the run's second half as in its first
    // (3.3 and 3.9 decades here); a sublinear approach would slow down.
    auto at = [&](std::int64_t evaluations) {
        double d = distance.front().second;
        for (const auto& [e, x] : distance)
            if (e <= evaluations) d = x;
        return d;
    };
    const std::int64_t end = distance.back().first;
    const double first_half = std::log10(at(0) / at(end / 2)), second_half = std::log10(at(end / 2) / at(end));
    INFO(first_half << " " << second_half);
    CHECK(first_half > 2.5);
    CHECK(second_half > 2.5);

    // The same constraint as an equality (pycma's equality handling: no floor on h, lam of any
    // sign): the multiplier reaches lam* = 2 as well (1.9999994 here); feasible means |h| <= 1e-4.
    LinearSphere plane;
    plane.equality = true;
    std::vector<cma::RunLog> plane_log;
    const Result e = cma.run_logged(plane, t, 3, NoObserver{}, &plane_log);
    REQUIRE(plane_log.size() == 1);
    CHECK(e.best_violation == 0.0);
    CHECK(std::abs(e.best_x[0] + 1.0) <= 1e-4);
    CHECK(plane_log[0].multipliers[0] == Approx(2.0).epsilon(1e-5));
}

TEST_CASE("engine: CMA-ES's constraint parameters, refused without constraints, al for CMA-ES only",
          "[cmaes][constraints]") {
    const engine::Problem g08(engine::ContinuousSpec{"cec2006-g08", 2});
    // g08's constraints are inactive at x* (g = -1.74, -0.17); Algorithm 1 moves the first
    // multiplier only where the penalty is quadratic, so it stays at 0.003 and the run ends at the
    // budget 9e-7 short of f* from this seed (measured).
    const auto r = engine::run({"cmaes", params({"constraints=al"})}, g08, budget(5000), 2);
    CHECK(*r.best_violation == 0.0);
    CHECK(r.evaluations == 5000);
    CHECK(r.best_f == Approx(-0.0958250414180359).epsilon(1e-4));

    const engine::Problem sphere(engine::ContinuousSpec{"sphere", 2});
    CHECK(test::input_error_message([&] {
              engine::check({"cmaes", params({"constraints=al"})}, sphere, budget(100));
          }).find("sphere has none") != std::string::npos);
    CHECK(test::input_error_message([&] {
              engine::check({"cmaes", params({"al_k1=2"})}, sphere, budget(100));
          }).find("sphere has none") != std::string::npos);
    // The augmented Lagrangian is not offered to the DE family.
    CHECK(test::input_error_message([&] {
              engine::check({"de", params({"constraints=al"})}, g08, budget(100));
          }).find("constraints") != std::string::npos);
    // Bad AL parameters: one line each.
    const std::string chi = test::input_error_message([&] {
        engine::run({"cmaes", params({"constraints=al", "al_chi=0.5"})}, g08, budget(100), 1);
    });
    CHECK(chi.find("al_chi must be 0") != std::string::npos);
    CHECK(chi.find('\n') == std::string::npos);
    const std::string k1 = test::input_error_message([&] {
        engine::check({"cmaes", params({"al_k1=0"})}, g08, budget(100));
    });
    CHECK(k1.find("al_k1") != std::string::npos);
    CHECK(k1.find('\n') == std::string::npos);

    const auto text = test::run_pride(
        "run --algo cmaes --problem cec2006-g08 --dim 2 --evals 5000 --seed 2 --param constraints=al --json");
    REQUIRE(text.status == 0);
    test::expect_input_error("run --algo de --problem cec2006-g08 --dim 2 --evals 200 --param constraints=al",
                             {"constraints"});
    test::expect_input_error("run --algo cmaes --problem sphere --dim 2 --evals 200 --param constraints=al",
                             {"sphere has none"});
}

TEST_CASE("engine: bipop-cmaes's bookkeeping and boundary, and the stopping flags of every CMA-ES",
          "[cmaes][bipop][errors]") {
    const engine::Problem f5(engine::ContinuousSpec{"bbob-f5", 5, 1});
    // The default boundary is the penalty: BBOB's linear slope (f* = -9.21 in instance 1) solved
    // within 1,000 D evaluations, where resampling stays 0.22 short from this seed (measured).
    const auto penalty = engine::run({"bipop-cmaes", {}}, f5, budget(5000), 1);
    const auto resample = engine::run({"bipop-cmaes", params({"boundary=resample"})}, f5, budget(5000), 1);
    CHECK(penalty.best_f + 9.21 <= 1e-8);
    CHECK(resample.best_f + 9.21 > 0.1);
    CHECK(engine::run({"bipop-cmaes", params({"budgets=pycma"})}, f5, budget(2000), 1).evaluations == 2000);
    for (const std::string algo : {"cmaes", "ipop-cmaes", "bipop-cmaes", "sep-cmaes"})
        CHECK(engine::run({algo, params({"max_iter=0", "equal_fun_values=0"})}, f5, budget(1000), 1).evaluations ==
              1000);
    const auto message = test::input_error_message([&] {
        engine::check({"bipop-cmaes", params({"budgets=deap"})}, f5, budget(100));
    });
    CHECK(message.find("budgets") != std::string::npos);
    CHECK(test::input_error_message([&] {
              engine::check({"cmaes", params({"budgets=paper"})}, f5, budget(100));
          }).find("budgets") != std::string::npos);
}

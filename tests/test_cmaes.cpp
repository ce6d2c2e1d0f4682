// CMA-ES (algorithms/cmaes.hpp): table 1's strategy parameters against python3-cmaes 0.9.1's (an
// independent implementation of the same tutorial), convergence on the sphere and an ill-
// conditioned ellipsoid, the stopping criteria one by one, IPOP's doubling and BIPOP's two
// regimes (the bookkeeping step by step), MaxIter and EqualFunVals, the boundary policies, exact budgets,
// reproducibility and the parameter checks.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "algorithms/cmaes.hpp"
#include "engine/ask_tell.hpp"
#include "engine/run.hpp"
#include "framework/error.hpp"
#include "framework/termination.hpp"
#include "problems/continuous/functions.hpp"
#include "tests/test_support.hpp"

namespace {

namespace cma = pride::cma;
using Catch::Matchers::Contains;

/// f = sum 10^(6 (i - 1) / (n - 1)) (x_i - 1)^2 on [-5, 5]^n: condition 1e6, optimum 0 at (1, ..., 1).
struct Ellipsoid {
    std::vector<double> lo, hi;
    explicit Ellipsoid(std::size_t n) : lo(n, -5.0), hi(n, 5.0) {}
    std::size_t dimension() const { return lo.size(); }
    std::span<const double> lower() const { return lo; }
    std::span<const double> upper() const { return hi; }
    double evaluate(std::span<const double> x) const {
        double f = 0.0;
        const double n = static_cast<double>(x.size());
        for (std::size_t i = 0; i < x.size(); ++i)
            f += std::pow(10.0, 6.0 * static_cast<double>(i) / (n - 1.0)) * (x[i] - 1.0) * (x[i] - 1.0);
        return f;
    }
};

/// f = sum x_i on [0, 1]^n: the optimum is the corner 0, on the boundary.
struct Linear {
    std::vector<double> lo, hi;
    explicit Linear(std::size_t n) : lo(n, 0.0), hi(n, 1.0) {}
    std::size_t dimension() const { return lo.size(); }
    std::span<const double> lower() const { return lo; }
    std::span<const double> upper() const { return hi; }
    double evaluate(std::span<const double> x) const {
        double f = 0.0;
        for (double v : x) f += v;
        return f;
    }
};

/// A constant: every criterion on function values holds at once.
struct Flat {
    std::vector<double> lo, hi;
    explicit Flat(std::size_t n) : lo(n, -1.0), hi(n, 1.0) {}
    std::size_t dimension() const { return lo.size(); }
    std::span<const double> lower() const { return lo; }
    std::span<const double> upper() const { return hi; }
    double evaluate(std::span<const double>) const { return 3.0; }
};

/// Counts the points outside the box and the population size of every iteration.
struct Watch {
    std::vector<double> lo, hi;
    std::int64_t outside = 0;
    std::vector<Eigen::Index> sizes;
    Watch(std::size_t n, double low, double high) : lo(n, low), hi(n, high) {}
    void operator()(const pride::IterationView& v) {
        sizes.push_back(v.population.cols());
        for (Eigen::Index j = 0; j < v.population.cols(); ++j)
            for (Eigen::Index i = 0; i < v.population.rows(); ++i) {
                const double x = v.population(i, j);
                if (x < lo[static_cast<std::size_t>(i)] || x > hi[static_cast<std::size_t>(i)]) ++outside;
            }
    }
};

template <class Covariance = cma::FullCovariance>
pride::Cmaes<Covariance> plain() {
    pride::Cmaes<Covariance> a;
    a.restarts = cma::NoRestarts{};
    return a;
}

}  // namespace

TEST_CASE("CMA-ES table 1: the strategy parameters are python3-cmaes 0.9.1's", "[cmaes][equations]") {
    // Printed by python3-cmaes 0.9.1 (CMA(mean=zeros(n), sigma=1)._popsize, ._mu_eff, ...).
    struct Row {
        std::size_t n;
        std::int64_t lambda, mu;
        double mueff, c1, cmu, cs, ds, cc, chi_n, w1, wlast;
    };
    for (const Row& r :
         {Row{10, 10, 5, 3.1672992814107026, 0.015283824524751714, 0.02015428276120838, 0.2844285879463675,
              1.2844285879463675, 0.29499038303562225, 3.0847265651690123, 0.45627264690340597, -0.5862218287788353},
          Row{40, 15, 7, 4.540915209075957, 0.0011694327252618397, 0.0031225007109974066, 0.1320305687020827,
              1.1320305687020826, 0.09300921663424917, 6.28521508039776, 0.34479619859202054, -0.3155046217960348}}) {
        INFO("n = " << r.n);
        const auto s = cma::make_strategy(r.n, cma::default_lambda(r.n), true, false);
        CHECK(s.lambda == r.lambda);
        CHECK(s.mu == r.mu);
        CHECK(s.mueff == Approx(r.mueff).epsilon(1e-14));
        CHECK(s.c1 == Approx(r.c1).epsilon(1e-14));
        CHECK(s.cmu == Approx(r.cmu).epsilon(1e-14));
        CHECK(s.cs == Approx(r.cs).epsilon(1e-14));
        CHECK(s.ds == Approx(r.ds).epsilon(1e-14));
        CHECK(s.cc == Approx(r.cc).epsilon(1e-14));
        CHECK(s.chi_n == Approx(r.chi_n).epsilon(1e-14));
        CHECK(s.weights.front() == Approx(r.w1).epsilon(1e-14));
        CHECK(s.weights.back() == Approx(r.wlast).epsilon(1e-14));
        double positive = 0.0;
        for (std::int64_t i = 0; i < s.mu; ++i) positive += s.weights[static_cast<std::size_t>(i)];
        CHECK(positive == Approx(1.0).epsilon(1e-15));
    }
}

TEST_CASE("CMA-ES eq. 53: without the active update the negative weights are 0", "[cmaes][equations]") {
    const auto s = cma::make_strategy(10, 10, false, false);
    for (std::size_t i = 5; i < 10; ++i) CHECK(s.weights[i] == 0.0);
    CHECK(s.sum_weights == Approx(1.0).epsilon(1e-15));
    // Separable (Ros and Hansen 2008): c1 and c_mu times (n + 2) / 3.
    const auto full = cma::make_strategy(40, 15, true, false), sep = cma::make_strategy(40, 15, true, true);
    CHECK(sep.c1 == Approx(full.c1 * 42.0 / 3.0).epsilon(1e-14));
    CHECK(sep.cmu == Approx(full.cmu * 42.0 / 3.0).epsilon(1e-14));
    CHECK(sep.cs == full.cs);
}

TEST_CASE("CMA-ES solves the sphere and a 1e6-conditioned ellipsoid to 1e-10", "[cmaes]") {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        INFO("seed " << seed);
        auto a = plain();
        a.tolerances.fun = 0.0;  // let the run go to the target
        auto t = pride::max_evaluations(20000);
        t.target = 1e-10;
        const auto sphere = a.run(pride::continuous::Sphere(10), t, seed);
        CHECK(sphere.best_f <= 1e-10);
        // About 4,000 evaluations on the 10-D sphere from sigma0 = 0.3 of the box (1e-10 from ~10).
        CHECK(sphere.evaluations < 6000);
        const auto ellipsoid = a.run(Ellipsoid(10), pride::max_evaluations(40000), seed);
        CHECK(ellipsoid.best_f <= 1e-10);
    }
}

TEST_CASE("sep-CMA-ES: the diagonal form solves a separable ellipsoid", "[cmaes]") {
    auto a = plain<cma::DiagonalCovariance>();
    const auto r = a.run(Ellipsoid(20), pride::max_evaluations(60000), 4);
    CHECK(r.best_f <= 1e-8);
}

TEST_CASE("CMA-ES: the same seed gives the same bits, another seed another run", "[cmaes]") {
    pride::Cmaes<> a;
    a.restarts = cma::Ipop{};
    const pride::continuous::Rastrigin f(5);
    const auto r1 = a.run(f, pride::max_evaluations(5000), 11);
    const auto r2 = a.run(f, pride::max_evaluations(5000), 11);
    const auto r3 = a.run(f, pride::max_evaluations(5000), 12);
    CHECK(r1.best_x == r2.best_x);
    CHECK(r1.history == r2.history);
    CHECK(r1.best_x != r3.best_x);
}

TEST_CASE("CMA-ES: restarts spend the budget exactly, a single run stops at its criterion", "[cmaes]") {
    const pride::continuous::Rastrigin f(5);
    for (std::int64_t budget : {1, 7, 999, 20000}) {
        INFO("budget " << budget);
        for (auto r : {cma::SelectableRestarts(cma::Ipop{}), cma::SelectableRestarts(cma::Bipop{})}) {
            pride::Cmaes<> a;
            a.restarts = r;
            CHECK(a.run(f, pride::max_evaluations(budget), 3).evaluations == budget);
        }
    }
    std::vector<cma::RunLog> log;
    const auto single = plain().run_logged(f, pride::max_evaluations(1'000'000), 3, pride::NoObserver{}, &log);
    REQUIRE(log.size() == 1);
    CHECK(log[0].stop != cma::Stop::none);
    CHECK(single.evaluations < 1'000'000);
    CHECK(single.evaluations == log[0].evaluations);
}

TEST_CASE("IPOP-CMA-ES: each restart doubles lambda and starts when a criterion holds", "[cmaes]") {
    pride::Cmaes<> a;
    a.restarts = cma::Ipop{};
    std::vector<cma::RunLog> log;
    Watch watch(10, -5.12, 5.12);
    const auto r = a.run_logged(pride::continuous::Rastrigin(10), pride::max_evaluations(200000), 5, watch, &log);
    REQUIRE(log.size() >= 4);
    for (std::size_t k = 0; k < log.size(); ++k) {
        INFO("run " << k << " ended by " << cma::stop_name(log[k].stop));
        CHECK(log[k].lambda == (10 << k));
        if (k + 1 < log.size()) CHECK(log[k].stop != cma::Stop::none);
    }
    CHECK(watch.outside == 0);  // resampling keeps every evaluated point in the box
    // Auger and Hansen (2005): large populations solve Rastrigin, which a default run does not.
    CHECK(r.best_f < 1e-8);
    const auto single = plain().run(pride::continuous::Rastrigin(10), pride::max_evaluations(200000), 5);
    CHECK(single.best_f > 1.0);
}

TEST_CASE("BIPOP-CMA-ES restart bookkeeping, step by step, as Hansen (2009) sets it", "[cmaes][bipop]") {
    // lambda_def = 10; the evaluations each run used are fed by hand. The small runs' U are the
    // sequence's first two draws of the Rng, drawn again here from the same seed.
    const std::uint64_t seed = 42;
    pride::Rng rng(seed), twin(seed);
    auto s = cma::Bipop{}.sequence(10);
    cma::RunPlan plan;
    const auto unlimited = std::numeric_limits<std::int64_t>::max();

    REQUIRE(s.next(rng, plan));  // the first run: default lambda, booked to neither regime
    CHECK(plan.regime == cma::Regime::first);
    CHECK(plan.lambda == 10);
    CHECK(plan.sigma_factor == 1.0);
    CHECK(plan.max_evaluations == unlimited);
    s.used(1000);
    REQUIRE(s.next(rng, plan));  // 0 >= 0: the large regime, 2^1 lambda_def
    CHECK(plan.regime == cma::Regime::large);
    CHECK(plan.lambda == 20);
    CHECK(plan.max_evaluations == unlimited);
    s.used(4000);
    REQUIRE(s.next(rng, plan));  // small 0 < large 4000: a small run
    CHECK(plan.regime == cma::Regime::small);
    {
        const double u1 = twin.uniform(), u2 = twin.uniform();
        // lambda_l = 40 (the large regime's next), lambda_s = floor(10 (40 / 20)^(U1^2)) in [10, 20].
        const auto lambda = static_cast<std::int64_t>(std::floor(10.0 * std::pow(2.0, u1 * u1)));
        CHECK(plan.lambda == lambda);
        CHECK(plan.lambda >= 10);
        CHECK(plan.lambda <= 20);
        CHECK(plan.sigma_factor == std::pow(10.0, -2.0 * u2));
        // Half the last large run's 4000 evaluations, whole generations only.
        CHECK(plan.max_evaluations == 2000 - 2000 % lambda);
    }
    s.used(1500);
    REQUIRE(s.next(rng, plan));  // 1500 < 4000: small again
    CHECK(plan.regime == cma::Regime::small);
    twin.uniform(), twin.uniform();
    s.used(1999);
    REQUIRE(s.next(rng, plan));  // 3499 < 4000: small again
    CHECK(plan.regime == cma::Regime::small);
    twin.uniform(), twin.uniform();
    s.used(600);
    REQUIRE(s.next(rng, plan));  // 4099 >= 4000: large, 2^2 lambda_def
    CHECK(plan.regime == cma::Regime::large);
    CHECK(plan.lambda == 40);
    s.used(8000);
    REQUIRE(s.next(rng, plan));  // 4099 < 12000: small, lambda_s in [10, 40] (lambda_l = 80)
    CHECK(plan.regime == cma::Regime::small);
    {
        const double u1 = twin.uniform();
        twin.uniform();
        const auto lambda = static_cast<std::int64_t>(std::floor(10.0 * std::pow(4.0, u1 * u1)));
        CHECK(plan.lambda == lambda);
        CHECK(plan.max_evaluations == 4000 - 4000 % lambda);  // half the last large run's 8000
    }

    // pycma's bookkeeping: the first run goes to the small regime, and a small run is bounded by
    // half of all the large runs' evaluations.
    pride::Rng r2(seed);
    cma::Bipop pycma;
    pycma.pycma_budget = true;
    auto q = pycma.sequence(10);
    REQUIRE(q.next(r2, plan));
    CHECK(plan.regime == cma::Regime::first);
    q.used(1000);
    REQUIRE(q.next(r2, plan));  // small 1000 >= large 0: large
    CHECK(plan.regime == cma::Regime::large);
    CHECK(plan.lambda == 20);
    q.used(4000);
    REQUIRE(q.next(r2, plan));  // 1000 < 4000: small
    CHECK(plan.regime == cma::Regime::small);
    q.used(3000);
    REQUIRE(q.next(r2, plan));  // 4000 >= 4000: large
    CHECK(plan.regime == cma::Regime::large);
    CHECK(plan.lambda == 40);
    q.used(8000);
    REQUIRE(q.next(r2, plan));  // 4000 < 12000: small, within half of 12000 (the paper: of 8000)
    CHECK(plan.regime == cma::Regime::small);
    CHECK(plan.max_evaluations == 6000 - 6000 % plan.lambda);
}

TEST_CASE("BIPOP-CMA-ES: a first run, then doubling large runs and small runs by budget", "[cmaes][bipop]") {
    pride::Cmaes<> a;
    a.restarts = cma::Bipop{};
    std::vector<cma::RunLog> log;
    a.run_logged(pride::continuous::Rastrigin(10), pride::max_evaluations(300000), 8, pride::NoObserver{}, &log);
    REQUIRE(log.size() >= 6);
    REQUIRE(log[0].regime == cma::Regime::first);
    CHECK(log[0].lambda == 10);
    CHECK(log[1].regime == cma::Regime::large);  // the first run is booked to neither regime
    CHECK(log[1].lambda == 20);
    std::int64_t large_lambda = 10, last_large = 0, large = 0, small = 0;
    int smalls = 0, larges = 0;
    for (std::size_t k = 0; k < log.size(); ++k) {
        INFO("run " << k << " (" << cma::regime_name(log[k].regime) << "): lambda " << log[k].lambda << ", sigma0 "
                    << log[k].sigma0 << ", " << log[k].evaluations << " evaluations, " << cma::stop_name(log[k].stop));
        const bool last = k + 1 == log.size();
        if (log[k].regime == cma::Regime::first) {
            CHECK(k == 0);
        } else if (log[k].regime == cma::Regime::large) {
            ++larges;
            CHECK(small >= large);  // the regime that has used fewer evaluations (ties: large)
            CHECK(log[k].sigma0 == 0.3);
            CHECK(log[k].lambda == 2 * large_lambda);
            large_lambda = log[k].lambda;
            large += log[k].evaluations;
            last_large = log[k].evaluations;
        } else {
            ++smalls;
            REQUIRE(log[k].regime == cma::Regime::small);
            CHECK(small < large);
            CHECK(log[k].sigma0 <= 0.3);
            CHECK(log[k].sigma0 >= 0.003 * (1 - 1e-12));
            CHECK(log[k].lambda >= 10);            // lambda_def
            CHECK(log[k].lambda <= large_lambda);  // lambda_l / 2, lambda_l the large regime's next
            CHECK(log[k].evaluations % log[k].lambda == 0);
            // At most half the last large run's evaluations (at least one generation).
            CHECK(log[k].evaluations <= std::max(log[k].lambda, last_large / 2));
            if (!last) CHECK(log[k].stop != cma::Stop::none);
            small += log[k].evaluations;
        }
    }
    CHECK(smalls >= 2);
    CHECK(larges >= 2);
}

TEST_CASE("CMA-ES stopping criteria: TolFun on a flat function, TolX on the sphere, NoEffectCoord", "[cmaes]") {
    std::vector<cma::RunLog> log;
    // Every value equal: EqualFunVals holds once n = 4 generations are there (lambda 8).
    plain().run_logged(Flat(4), pride::max_evaluations(100000), 1, pride::NoObserver{}, &log);
    REQUIRE(log.size() == 1);
    CHECK(log[0].stop == cma::Stop::equal_fun_values);
    CHECK(log[0].evaluations == 8 * 4);
    auto flat = plain();
    flat.tolerances.equal_fun_values = false;
    log.clear();
    flat.run_logged(Flat(4), pride::max_evaluations(100000), 1, pride::NoObserver{}, &log);
    REQUIRE(log.size() == 1);
    CHECK(log[0].stop == cma::Stop::tol_fun);
    CHECK(log[0].evaluations == 8 * (10 + 30 * 4 / 8));  // lambda 8, after the window 10 + ceil(30 n / lambda)

    auto a = plain();
    a.tolerances.fun = 0.0;  // only the step can stop it
    log.clear();
    a.run_logged(pride::continuous::Sphere(4), pride::max_evaluations(1'000'000), 1, pride::NoObserver{}, &log);
    REQUIRE(log.size() == 1);
    INFO(cma::stop_name(log[0].stop));
    CHECK((log[0].stop == cma::Stop::tol_x || log[0].stop == cma::Stop::no_effect_coord ||
           log[0].stop == cma::Stop::no_effect_axis));

    a.tolerances.x = 0.0;  // and now only the numbers' resolution
    a.tolerances.max_iter = false;
    log.clear();
    a.run_logged(Ellipsoid(4), pride::max_evaluations(1'000'000), 1, pride::NoObserver{}, &log);
    REQUIRE(log.size() == 1);
    INFO(cma::stop_name(log[0].stop));
    CHECK((log[0].stop == cma::Stop::no_effect_coord || log[0].stop == cma::Stop::no_effect_axis ||
           log[0].stop == cma::Stop::condition_cov));
}

TEST_CASE("CMA-ES stopping criteria: the value histories", "[cmaes]") {
    cma::ValueHistory h;
    h.reset(3, 9);  // TolFun window 10 + ceil(30 * 3 / 9) = 20; stagnation after 120 + 10 = 130
    std::vector<double> values{1.0, 1.0, 1.0};
    for (int g = 0; g < 19; ++g) h.record(values, 3);
    CHECK_FALSE(h.tol_fun(1e-12));
    h.record(values, 3);
    CHECK(h.tol_fun(1e-12));
    values = {1.0, 1.0, 2.0};  // the last generation's own range counts too
    h.record(values, 3);
    CHECK_FALSE(h.tol_fun(1e-12));

    std::vector<double> scratch;
    cma::ValueHistory improving, stuck;
    improving.reset(3, 9);
    stuck.reset(3, 9);
    for (int g = 0; g < 200; ++g) {
        std::vector<double> v{1.0 / (g + 1.0), 2.0 / (g + 1.0), 3.0};
        improving.record(v, 3);
        std::vector<double> w{1.0, 2.0, 3.0};
        stuck.record(w, 3);
        if (g < 129) CHECK_FALSE(stuck.stagnation(scratch));
    }
    CHECK_FALSE(improving.stagnation(scratch));
    CHECK(stuck.stagnation(scratch));
}

TEST_CASE("CMA-ES stopping criteria: MaxIter and EqualFunVals", "[cmaes]") {
    // EqualFunVals, n = 3, lambda = 9: k = 1 + ceil(0.1 + 9 / 4) = 4; more than a third of the
    // last 3 generations, i.e. 2 of them, with the best value equal to the 4th best.
    cma::ValueHistory h;
    h.reset(3, 9);
    const std::vector<double> equal{1.0, 1.0, 1.0, 1.0, 2.0, 2.0, 2.0, 2.0, 2.0};
    const std::vector<double> third{1.0, 1.0, 1.0, 1.5, 2.0, 2.0, 2.0, 2.0, 2.0};  // equal only to the 3rd
    h.record(equal, 9);
    h.record(equal, 9);
    CHECK_FALSE(h.equal_fun_values());  // n generations not yet there
    h.record(third, 9);
    CHECK(h.equal_fun_values());  // 2 of 3
    h.record(third, 9);
    CHECK_FALSE(h.equal_fun_values());  // 1 of 3
    h.record(equal, 9);
    CHECK_FALSE(h.equal_fun_values());  // third, third, equal: 1 of 3
    h.record(equal, 9);
    CHECK(h.equal_fun_values());  // third, equal, equal: 2 of 3 again

    // MaxIter, n = 2, lambda = 6: 100 + 50 * 25 / sqrt(6) = 610.3, so it holds after 611 generations.
    cma::ValueHistory m;
    m.reset(2, 6);
    const std::vector<double> v{1.0, 2.0, 3.0, 4.0, 5.0, 6.0};
    for (int g = 0; g < 610; ++g) m.record(v, 6);
    CHECK_FALSE(m.max_iter());
    m.record(v, 6);
    CHECK(m.max_iter());

    // On the sphere with TolFun and TolX off, no other criterion comes first: 611 generations of 6.
    auto a = plain();
    a.tolerances.fun = 0.0;
    a.tolerances.x = 0.0;
    std::vector<cma::RunLog> log;
    a.run_logged(pride::continuous::Sphere(2), pride::max_evaluations(1'000'000), 1, pride::NoObserver{}, &log);
    REQUIRE(log.size() == 1);
    CHECK(log[0].stop == cma::Stop::max_iter);
    CHECK(log[0].evaluations == 6 * 611);
    a.tolerances.max_iter = false;  // and without it the run goes on
    log.clear();
    a.run_logged(pride::continuous::Sphere(2), pride::max_evaluations(1'000'000), 1, pride::NoObserver{}, &log);
    REQUIRE(log.size() == 1);
    CHECK(log[0].evaluations > 6 * 611);
}

TEST_CASE("CMA-ES boundary policies: every evaluated point lies in the box", "[cmaes]") {
    // On a linear function whose optimum is a corner of the box. Measured (seed 2, one run each):
    // the penalty reaches the corner exactly; resampling stagnates near it (0.025); the
    // Lamarckian clamp makes sigma grow until TolXUp (the clamped steps mislead step-size control).
    std::vector<double> best;
    for (auto b : {cma::SelectableBoundary(cma::Resample{}), cma::SelectableBoundary(cma::ClampRepair{}),
                   cma::SelectableBoundary(cma::Penalty{})}) {
        auto a = plain();
        a.boundary = b;
        Watch watch(5, 0.0, 1.0);
        std::vector<cma::RunLog> log;
        best.push_back(a.run_logged(Linear(5), pride::max_evaluations(5000), 2, watch, &log).best_f);
        CHECK(watch.outside == 0);
        REQUIRE(log.size() == 1);
        if (b.holds<cma::ClampRepair>()) CHECK(log[0].stop == cma::Stop::tol_x_up);
    }
    CHECK(best[0] < 0.05);
    CHECK(best[2] == 0.0);
}

TEST_CASE("CMA-ES ask and tell: ask returns the whole population", "[cmaes][ask_tell]") {
    namespace engine = pride::engine;
    engine::Budget budget;
    budget.evaluations = 100;
    engine::AskTell run({"cmaes", {}}, std::vector<double>(10, -1.0), std::vector<double>(10, 1.0), budget, 1);
    const pride::Matrix& x = run.ask();
    CHECK(x.cols() == 10);  // 4 + floor(3 ln 10)
    engine::ParamValues pop20;
    pop20.set("pop", 20);
    engine::AskTell ipop({"ipop-cmaes", pop20}, std::vector<double>(3, -1.0), std::vector<double>(3, 1.0), budget, 1);
    CHECK(ipop.ask().cols() == 20);
}

TEST_CASE("CMA-ES parameter checks name the parameter", "[cmaes][errors]") {
    const pride::continuous::Sphere f(3);
    auto refused = [&](auto a, const std::string& what) {
        INFO(what);
        CHECK_THROWS_WITH(a.run(f, pride::max_evaluations(100), 1), Contains(what));
    };
    auto a = plain();
    a.population = 1;
    refused(a, "population must be 0");
    a = plain();
    a.sigma0 = 0.0;
    refused(a, "sigma0 must be in (0, 10]");
    a = plain();
    a.tolerances.x_up = 1.0;
    refused(a, "tol_x_up must be > 1");
    a = plain();
    a.tolerances.fun = -1.0;
    refused(a, "tol_fun must be finite and >= 0");
    a = plain();
    a.boundary = cma::Penalty{-1.0};
    refused(a, "penalty weight must be finite and >= 0");
    a = plain();
    a.restarts = cma::Ipop{5.0};
    refused(a, "factor must be in [1, 4]");
    namespace engine = pride::engine;
    engine::ParamValues wrap;
    wrap.set_name("boundary", "wrap");
    CHECK_THROWS_WITH(
        engine::run({"cmaes", wrap}, engine::Problem(engine::ContinuousSpec{"sphere", 3}), engine::Budget{}, 1),
        Contains("boundary"));
}

// Tests of the algorithms used directly as templates and of their parts: convergence,
// termination, parameter validation and the operators on hand-worked values (budgets, bounds,
// reproducibility and NaN handling are in test_algorithms.cpp).
#include <catch2/catch.hpp>

#include "tests/algorithms_common.hpp"

// ---------------------------------------------------------------------------------------------
// 5. Convergence of PSO and GA

TEST_CASE("PSO reaches 1e-6 on the 10-D sphere within 20000 evaluations", "[algorithms][convergence]") {
    for (const std::int64_t population : {20, 50}) {
        for (std::uint64_t seed = 1; seed <= 5; ++seed) {
            INFO("population " << population << " seed " << seed);
            const auto r = pso(population).run(pride::continuous::Sphere(10), pride::max_evaluations(20000), seed);
            CHECK(r.evaluations == 20000);
            CHECK(r.best_f < 1e-6);
            for (double v : r.best_x) CHECK(std::abs(v) < 1e-3);
        }
    }
}

TEST_CASE("GA reaches 1e-6 on the 10-D sphere within 20000 evaluations", "[algorithms][convergence]") {
    // Tuned, not the defaults: population 20 and 4 elites (defaults 50 and 1) make the GA greedy
    // enough to reach 1e-6 in this budget; with the defaults it gets less far (next test).
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
        INFO("seed " << seed);
        const auto r = ga(20, 4).run(pride::continuous::Sphere(10), pride::max_evaluations(20000), seed);
        CHECK(r.evaluations == 20000);
        CHECK(r.best_f < 1e-6);
        // The GA must be doing real work: far better than the best of its initial population.
        CHECK(r.best_f < 1e-6 * r.history.front());
    }
}

TEST_CASE("GA with its default settings on the 10-D sphere within 20000 evaluations", "[algorithms][convergence]") {
    // Population 50 and one elite (the registry's defaults). Measured over seeds 1-5: best_f
    // 3.1e-4, 3.2e-4, 3.1e-5, 2.0e-4, 5.9e-4 from initial bests of 30-46; the bound leaves a
    // factor of ten over the worst seed.
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
        INFO("seed " << seed);
        const auto r = ga().run(pride::continuous::Sphere(10), pride::max_evaluations(20000), seed);
        CHECK(r.evaluations == 20000);
        CHECK(r.best_f < 6e-3);
        CHECK(r.best_f < 1e-3 * r.history.front());
    }
}

namespace {
/// The best of `n` uniform points of the box: what any search must beat.
template <class P>
double random_search(const P& problem, std::int64_t n, std::uint64_t seed) {
    P p = problem;
    std::mt19937_64 rng(seed);
    std::vector<double> x(p.dimension());
    double best = std::numeric_limits<double>::infinity();
    for (std::int64_t k = 0; k < n; ++k) {
        for (std::size_t i = 0; i < x.size(); ++i)
            x[i] = std::uniform_real_distribution<double>(p.lower()[i], p.upper()[i])(rng);
        best = std::min(best, p.evaluate(x));
    }
    return best;
}
}  // namespace

TEST_CASE("PSO and GA improve on a shifted multimodal problem", "[algorithms][convergence]") {
    // 20,000 evaluations on the 5-D shifted Rastrigin. Random search with the same budget reaches
    // 12.1-16.7 (seeds 1-5, computed below every time). Measured, seeds 1-5: PSO (population 20)
    // 0, 3.98, 0, 0, 0 (seed 2 ends in a local minimum); the GA (population 20, 2 elites)
    // 4e-8 to 3e-7. The bounds sit far below random search: a search that only samples fails them.
    const auto problem = pride::continuous::Shifted<pride::continuous::Rastrigin>(5);
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
        INFO("seed " << seed);
        const auto rp = pso(20).run(problem, pride::max_evaluations(20000), seed);
        const auto rg = ga(20, 2).run(problem, pride::max_evaluations(20000), seed);
        const double random = random_search(problem, 20000, seed);
        CHECK(random > 5.0);
        CHECK(rp.best_f < 0.2 * rp.history.front());
        CHECK(rg.best_f < 0.2 * rg.history.front());
        CHECK(rp.best_f < 0.5 * random);
        CHECK(rg.best_f < 0.5 * random);
        CHECK(rp.best_f < 5.0);
        CHECK(rg.best_f < 1e-5);
    }
}

// ---------------------------------------------------------------------------------------------
// 6. NLopt subplex on Rosenbrock

TEST_CASE("NLopt LN_SBPLX on 5-D Rosenbrock ends at the global or the known local minimum",
          "[algorithms][nlopt][convergence]") {
    // Measured with this adapter (and identically with NLopt called directly from the same start):
    // seeds 1, 2, 6, 8 reach < 1e-12 .. 2e-8; seeds 3, 4 stop in the second local minimum of 5-D
    // Rosenbrock, f = 3.93084 near (-0.962, 0.936, 0.881, 0.778, 0.606); seeds 5 and 7 are still
    // creeping along the valley at 500,000 evaluations (1.7e-6 and 1.3e-5).
    const double local_minimum = 3.93084;
    int global = 0;
    for (std::uint64_t seed = 1; seed <= 8; ++seed) {
        INFO("seed " << seed);
        auto p = probe(pride::continuous::Rosenbrock(5));
        const auto r = pride::Nlopt("LN_SBPLX").run(p, pride::max_evaluations(500000), seed);
        CHECK(p.log->calls == 500000);
        CHECK(r.evaluations == 500000);
        const bool near_global = r.best_f < 1e-4;
        const bool at_local = std::abs(r.best_f - local_minimum) < 1e-3;
        CHECK((near_global || at_local));
        if (near_global)
            for (double v : r.best_x) CHECK(v == Approx(1.0).margin(0.02));
        if (at_local) CHECK(r.best_x[0] == Approx(-0.9621).margin(0.01));
        if (r.best_f < 1e-6) ++global;
    }
    CHECK(global >= 4);
}

// ---------------------------------------------------------------------------------------------
// 7. Termination

TEST_CASE("max_iterations(k) runs exactly k iterations after the initial population", "[algorithms][termination]") {
    const auto problem = pride::continuous::Griewank(4);
    for (const std::int64_t k : {0, 1, 2, 7, 30}) {
        INFO("k = " << k);
        const auto rp = pso(20).run(problem, pride::max_iterations(k), 3);
        CHECK(rp.iterations == k);
        CHECK(rp.history.size() == static_cast<std::size_t>(k) + 1);
        CHECK(rp.evaluations == 20 * (k + 1));
        check_history(rp);

        const auto rg = ga(20, 3).run(problem, pride::max_iterations(k), 3);
        CHECK(rg.iterations == k);
        CHECK(rg.history.size() == static_cast<std::size_t>(k) + 1);
        CHECK(rg.evaluations == 20 + 17 * k);  // the 3 elites are not re-evaluated
        check_history(rg);

        // With an evaluation limit too, whichever comes first.
        const auto both = pso(20).run(problem, pride::max_iterations(k) | pride::max_evaluations(50), 3);
        CHECK(both.evaluations == std::min<std::int64_t>(50, 20 * (k + 1)));
    }
}

TEST_CASE("every derivative-free NLopt algorithm runs within its budget", "[algorithms][budget][nlopt]") {
    for (const auto& name : pride::nlopt_derivative_free_names()) {
        INFO(name);
        auto p = probe(pride::continuous::Rastrigin(3));
        pride::Result r;
        REQUIRE_NOTHROW(r = pride::Nlopt(name, 10).run(p, pride::max_evaluations(300), 4));
        CHECK(p.log->calls == r.evaluations);
        CHECK(r.evaluations == 300);
        CHECK(p.log->outside == 0);
        CHECK(std::isfinite(r.best_f));
        check_history(r);
    }
}

TEST_CASE("NLopt: one iteration is a block of record_every evaluations", "[algorithms][termination][nlopt]") {
    for (const std::int64_t k : {1, 2, 5}) {
        INFO("k = " << k);
        const auto r = pride::Nlopt("GN_CRS2_LM", 30).run(pride::continuous::Sphere(3), pride::max_iterations(k), 1);
        CHECK(r.iterations == k);
        CHECK(r.history.size() == static_cast<std::size_t>(k) + 1);
        CHECK(r.evaluations == 30 * (k + 1));
        check_history(r);
    }
}

TEST_CASE("NLopt: max_iterations(0) is the first block as for a population", "[algorithms][termination][nlopt]") {
    // Population algorithms evaluate their initial population under max_iterations(0); for the
    // NLopt adapter iteration 0 is the first block of record_every evaluations (its own
    // limit computation says (0 + 1) * record_every).
    const auto r = pride::Nlopt("GN_CRS2_LM", 30).run(pride::continuous::Sphere(3), pride::max_iterations(0), 1);
    CHECK(r.iterations == 0);
    CHECK(r.history.size() == 1);
    CHECK(r.evaluations == 30);
}

TEST_CASE("a target value stops the run at the end of the iteration that reaches it", "[algorithms][termination]") {
    const double target = 1e-3;
    const std::int64_t budget = 200000;
    const auto problem = pride::continuous::Sphere(5);
    auto check_target = [&](const std::string& label, const pride::Result& r, std::int64_t per_iteration) {
        INFO(label);
        CHECK(r.best_f <= target);
        CHECK(r.evaluations < budget);
        check_history(r);
        REQUIRE(r.history.size() >= 2);
        CHECK(r.history[r.history.size() - 2] > target);  // not one iteration later than needed
        if (per_iteration > 0) CHECK((r.evaluations - 20) % per_iteration == 0);
    };
    const auto stop = pride::max_evaluations(budget) | pride::target_value(target);
    check_target("pso", pso(20).run(problem, stop, 1), 20);
    check_target("pso-constriction", pso_constriction(20).run(problem, stop, 1), 20);
    check_target("ga", ga(20, 4).run(problem, stop, 1), 16);

    for (const char* name : {"LN_SBPLX", "GN_CRS2_LM"}) {
        INFO(name);
        const auto r = pride::Nlopt(name).run(problem, stop, 1);
        CHECK(r.best_f <= target);
        CHECK(r.evaluations < budget);
        check_history(r);
    }
    // A target already met by the initial population: no iteration at all.
    const auto easy = pso(20).run(problem, pride::max_evaluations(budget) | pride::target_value(1e9), 1);
    CHECK(easy.evaluations == 20);
    CHECK(easy.iterations == 0);
}

TEST_CASE("histories are monotone and consistent for every algorithm", "[algorithms][termination]") {
    for_each_algorithm(20, [&](const std::string& label, const auto& algo) {
        for (const std::int64_t n : {1, 19, 20, 21, 2017}) {
            INFO(label << " budget " << n);
            const auto r = algo.run(pride::continuous::Schwefel(3), pride::max_evaluations(n), 8);
            check_history(r);
            CHECK(r.history_evaluations.back() == r.evaluations);  // the last iteration is recorded
            CHECK(r.wall_ms >= 0.0);
        }
    });
}

TEST_CASE("Termination: combination and validation", "[algorithms][termination]") {
    const auto t = pride::max_evaluations(100) | pride::max_evaluations(70) | pride::max_iterations(9) |
                   pride::target_value(1.0) | pride::target_value(2.0);
    CHECK(*t.max_evaluations == 70);
    CHECK(*t.max_iterations == 9);
    CHECK(*t.target == 2.0);  // the larger target is reached first
    CHECK(pride::max_evaluations(120).horizon(20, 20) == 5);
    CHECK(pride::max_evaluations(121).horizon(20, 20) == 6);  // a partial last iteration counts
    CHECK(pride::max_evaluations(10).horizon(20, 20) == 0);
    CHECK((pride::max_iterations(3) | pride::max_evaluations(1000)).horizon(20, 20) == 3);

    const auto problem = pride::continuous::Sphere(2);
    CHECK_THROWS_AS(pso().run(problem, pride::target_value(1e-3), 1), pride::InputError);
    CHECK_THROWS_WITH(pso().run(problem, pride::target_value(1e-3), 1), Catch::Contains("limit"));
    CHECK_THROWS_AS(ga().run(problem, pride::target_value(1e-3), 1), pride::InputError);
    CHECK_THROWS_AS(pride::Nlopt("LN_SBPLX").run(problem, pride::target_value(1e-3), 1), pride::InputError);
    CHECK_THROWS_AS(pso().run(problem, pride::Termination{}, 1), pride::InputError);
    CHECK_THROWS_AS(pso().run(problem, pride::max_evaluations(0), 1), pride::InputError);
    CHECK_THROWS_AS(ga().run(problem, pride::max_iterations(-1), 1), pride::InputError);
    // A target together with a limit is fine.
    CHECK_NOTHROW(pso().run(problem, pride::target_value(1e-3) | pride::max_iterations(2), 1));
}

// ---------------------------------------------------------------------------------------------
// 8. Parameter validation

namespace {

/// Runs `algo` on a counting problem and checks it throws InputError naming `word` before any
/// evaluation.
template <class A>
void check_refused(const A& algo, const std::string& word) {
    INFO("expecting an InputError naming '" << word << "'");
    auto p = probe(pride::continuous::Sphere(3));
    CHECK_THROWS_AS(algo.validate(), pride::InputError);
    CHECK_THROWS_WITH(algo.validate(), Catch::Contains(word));
    CHECK_THROWS_AS(algo.run(p, pride::max_evaluations(100), 1), pride::InputError);
    CHECK_THROWS_WITH(algo.run(p, pride::max_evaluations(100), 1), Catch::Contains(word));
    CHECK(p.log->calls == 0);
}

}  // namespace

TEST_CASE("invalid parameters are refused with a message naming them", "[algorithms][params]") {
    SECTION("pso") {
        check_refused(pso(1), "population");
        check_refused(pso(0), "population");
        auto a = pso();
        a.velocity.inertia.start = -1.0;
        check_refused(a, "w_start");
        a = pso();
        a.velocity.inertia.end = 2.0;
        check_refused(a, "w_end");
        a = pso();
        a.velocity.c1 = -0.5;
        check_refused(a, "c1");
        a = pso();
        a.velocity.c2 = 11.0;
        check_refused(a, "c2");
        a = pso();
        a.velocity_clamp.fraction = 0.0;
        check_refused(a, "vmax");
        auto c = pso_constriction();
        c.velocity.chi = 1.0;
        check_refused(c, "chi");
        c = pso_constriction();
        c.velocity.c = 0.0;
        check_refused(c, "c must");
        CHECK_THROWS_WITH(pso_constriction(1).validate(), Catch::Contains("pso-constriction"));
    }
    SECTION("ga") {
        check_refused(ga(1, 0), "population");
        check_refused(ga(10, 10), "elitism");
        check_refused(ga(10, 11), "elitism");
        check_refused(ga(10, -1), "elitism");
        auto a = ga();
        a.selection.size = -2;
        check_refused(a, "tournament");
        a = ga();
        a.selection.size = 0;
        check_refused(a, "tournament");
        a = ga();
        a.crossover.probability = 1.5;
        check_refused(a, "pc");
        a = ga();
        a.crossover.probability = -0.1;
        check_refused(a, "pc");
        a = ga();
        a.crossover.eta = -1.0;
        check_refused(a, "eta_c");
        a = ga();
        a.mutation.eta = -1.0;
        check_refused(a, "eta_m");
        a = ga();
        a.mutation.probability = 1.5;
        check_refused(a, "pm");
        // Limits themselves are accepted.
        auto ok = ga(2, 1);
        ok.crossover.probability = 1.0;
        ok.mutation.probability = 1.0;
        ok.selection.size = 1;
        CHECK_NOTHROW(ok.validate());
        CHECK_NOTHROW(ok.run(pride::continuous::Sphere(2), pride::max_evaluations(30), 1));
    }
    SECTION("nlopt") {
        CHECK_THROWS_AS(pride::Nlopt("LN_NOSUCH"), pride::InputError);
        CHECK_THROWS_WITH(pride::Nlopt("LN_NOSUCH"), Catch::Contains("LN_NOSUCH"));
        CHECK_THROWS_AS(pride::Nlopt("nlopt:bogus"), pride::InputError);
        CHECK_THROWS_AS(pride::Nlopt(""), pride::InputError);
        CHECK_THROWS_AS(pride::Nlopt("LD_MMA"), pride::InputError);
        CHECK_THROWS_WITH(pride::Nlopt("LD_MMA"), Catch::Contains("LD_MMA") && Catch::Contains("gradient"));
        CHECK_THROWS_AS(pride::Nlopt("nlopt:LD_LBFGS"), pride::InputError);
        CHECK_THROWS_AS(pride::Nlopt("GD_STOGO"), pride::InputError);
        CHECK_THROWS_AS(pride::Nlopt("LN_SBPLX", 0), pride::InputError);
        CHECK_NOTHROW(pride::Nlopt("nlopt:LN_SBPLX"));
        CHECK(pride::Nlopt("nlopt:LN_SBPLX").name() == "nlopt:LN_SBPLX");
        CHECK(pride::Nlopt("GN_CRS2_LM").name() == "nlopt:GN_CRS2_LM");
        pride::Nlopt a("LN_SBPLX");
        a.record_every = 0;
        check_refused(a, "pop");
        // The derivative-free list holds no gradient algorithm and holds the two baselines.
        const auto names = pride::nlopt_derivative_free_names();
        CHECK(std::find(names.begin(), names.end(), "LN_SBPLX") != names.end());
        CHECK(std::find(names.begin(), names.end(), "GN_CRS2_LM") != names.end());
        // (NLopt's gradient algorithms are LD_* and GD_*; GN_DIRECT_L_RAND has "D_" in it but
        // needs no gradient.)
        CHECK(std::find(names.begin(), names.end(), "GN_DIRECT_L_RAND") != names.end());
        for (const auto& n : names) {
            INFO(n);
            CHECK_FALSE((n.size() > 2 && n[1] == 'D' && n[2] == '_'));
            CHECK_NOTHROW(pride::Nlopt(n));
        }
    }
}

// ---------------------------------------------------------------------------------------------
// 9. Operators

TEST_CASE("LinearInertia runs from w_start to w_end", "[operators]") {
    const pride::LinearInertia w;
    CHECK(w(0, 100) == 0.9);
    CHECK(w(99, 100) == Approx(0.4).margin(1e-15));
    CHECK(w(0, 11) == 0.9);
    CHECK(w(5, 11) == Approx(0.65).margin(1e-15));
    CHECK(w(10, 11) == Approx(0.4).margin(1e-15));
    CHECK(w(0, 1) == 0.9);  // a one-iteration horizon stays at the start
    for (std::int64_t t = 1; t < 100; ++t) CHECK(w(t, 100) < w(t - 1, 100));
    const pride::LinearInertia custom{1.2, 0.1};
    CHECK(custom(0, 5) == 1.2);
    CHECK(custom(4, 5) == Approx(0.1).margin(1e-15));
    CHECK(pride::ConstantInertia{0.5}(3, 10) == 0.5);

    const pride::InertiaVelocity<> v;
    const auto coeff = v(0, 10);
    CHECK(coeff.a == 0.9);
    CHECK(coeff.b1 == 2.0);
    CHECK(coeff.b2 == 2.0);
    const pride::ConstrictionVelocity cv;
    const auto cc = cv(7, 10);
    CHECK(cc.a == 0.7298);
    CHECK(cc.b1 == Approx(0.7298 * 2.05).epsilon(1e-15));
    CHECK(cc.b2 == Approx(0.7298 * 2.05).epsilon(1e-15));
    CHECK(pride::RangeVelocityClamp{}.limit(-5.0, 10.0) == Approx(3.0).epsilon(1e-15));
}

TEST_CASE("FixedPower agrees with std::pow", "[operators]") {
    // Integer exponents are computed by repeated squaring: each of the fewer than |e|
    // multiplications rounds once, so the relative error is below (|e| + 1) * 2^-53; powers of
    // two under a root are repeated square roots (each correctly rounded): below 2 * 2^-53. The
    // reference std::pow is itself within 1 ulp (2 * 2^-53), hence the extra 2u. Other exponents
    // fall back to std::pow itself: identical.
    const double u = 0x1.0p-53;
    struct Case {
        double e;
        double tolerance;
    };
    const Case cases[] = {{16.0, 19 * u},
                          {-16.0, 19 * u},
                          {1.0 / 16, 4 * u},
                          {21.0, 24 * u},
                          {1.0 / 21, 0.0},
                          {2.5, 0.0},
                          {1.0, 0.0},
                          {0.0, 0.0},
                          {-1.0, 3 * u},
                          {1.0 / 2, 4 * u},
                          {1.0 / 64, 4 * u},
                          {64.0, 67 * u},
                          {-(15.0 + 1.0), 19 * u},
                          {1.0 / (20.0 + 1.0), 0.0},
                          {65.0, 0.0},
                          {0.3, 0.0}};
    pride::Rng rng(7);
    for (const auto& c : cases) {
        const pride::FixedPower power(c.e);
        double worst = 0.0;
        for (int k = 0; k < 20000; ++k) {
            const double x = k % 2 ? rng.uniform(0.0, 2.0) : rng.uniform(0.0, 1e-2);
            const double expected = std::pow(x, c.e);
            const double got = power(x);
            if (expected == 0.0 || !std::isfinite(expected)) {
                CHECK(got == expected);
                continue;
            }
            worst = std::max(worst, std::abs(got - expected) / std::abs(expected));
        }
        INFO("exponent " << c.e << " worst relative error " << worst);
        CHECK(worst <= c.tolerance);

        // The array form gives the same bits as the scalar form, whatever the length (vector
        // lanes and the scalar tail alike).
        for (const std::size_t n : {0u, 1u, 3u, 8u, 37u}) {
            std::vector<double> values(n), expected(n);
            for (std::size_t k = 0; k < n; ++k) {
                values[k] = rng.uniform(0.0, 3.0);
                expected[k] = power(values[k]);
            }
            power.apply(values);
            INFO("apply on " << n << " values");
            CHECK(bits_equal(values, expected));
        }
    }
    // Exact points.
    CHECK(pride::FixedPower(16.0)(2.0) == 65536.0);
    CHECK(pride::FixedPower(-16.0)(2.0) == 1.0 / 65536.0);
    CHECK(pride::FixedPower(1.0 / 16)(65536.0) == 2.0);
    CHECK(pride::FixedPower(21.0)(1.0) == 1.0);
    CHECK(pride::FixedPower(21.0)(-1.0) == -1.0);
    CHECK(pride::FixedPower(3.0)(-2.0) == -8.0);
    CHECK(pride::FixedPower(1.0 / 16)(0.0) == 0.0);
}

namespace {

/// Checks that the empirical distribution of `samples` has CDF `cdf` at each point of `at`, within
/// 5 standard deviations of a binomial count.
template <class Cdf>
void check_distribution(const std::vector<double>& samples, const std::vector<double>& at, Cdf cdf) {
    const auto n = static_cast<double>(samples.size());
    for (const double b : at) {
        const double expected = cdf(b);
        const auto below = std::count_if(samples.begin(), samples.end(), [&](double v) { return v <= b; });
        INFO("P(X <= " << b << "): expected " << expected << ", got " << static_cast<double>(below) / n);
        CHECK(static_cast<double>(below) ==
              Approx(expected * n).margin(5.0 * std::sqrt(expected * (1 - expected) * n) + 1));
    }
}

}  // namespace

TEST_CASE("SBX crossover on hand-worked cases", "[operators][sbx]") {
    const pride::SbxCrossover sbx;  // eta 15, probability 0.9
    SECTION("children stay in the box") {
        const std::vector<double> lo = {0.0, -1.0, 10.0, -1e-3}, hi = {1.0, 1.0, 10.5, 1e-3};
        pride::Rng rng(1);
        pride::SbxCrossover wide = sbx;
        wide.eta = 0.0;  // the widest spread
        wide.probability = 1.0;
        for (int k = 0; k < 20000; ++k) {
            std::vector<double> a(4), b(4);
            for (std::size_t i = 0; i < 4; ++i) {
                a[i] = k % 3 == 0 ? lo[i] : rng.uniform(lo[i], hi[i]);  // some parents on a face
                b[i] = k % 5 == 0 ? hi[i] : rng.uniform(lo[i], hi[i]);
            }
            (k % 2 ? wide : sbx)(a, b, lo, hi, rng);
            REQUIRE(inside(a, lo, hi));
            REQUIRE(inside(b, lo, hi));
        }
    }
    SECTION("far from the bounds the children's mean is the parents' mean") {
        // With the box huge compared with the parents' distance, beta^-(eta+1) underflows to 0 for
        // both children, the bounded form equals the unbounded one and (c1 + c2)/2 = (y1 + y2)/2.
        const std::vector<double> lo(5, -1e6), hi(5, 1e6);
        pride::SbxCrossover always = sbx;
        always.probability = 1.0;
        pride::Rng rng(2);
        int changed = 0;
        for (int k = 0; k < 2000; ++k) {
            std::vector<double> a(5), b(5);
            for (std::size_t i = 0; i < 5; ++i) {
                a[i] = rng.uniform(-3.0, 3.0);
                b[i] = rng.uniform(-3.0, 3.0);
            }
            const auto a0 = a, b0 = b;
            always(a, b, lo, hi, rng);
            for (std::size_t i = 0; i < 5; ++i) {
                CHECK((a[i] + b[i]) == Approx(a0[i] + b0[i]).margin(1e-12));
                if (a[i] != a0[i] && a[i] != b0[i]) ++changed;
            }
        }
        CHECK(changed > 2000);  // about half of the 10,000 coordinates are crossed
    }
    SECTION("probability 0 leaves the parents alone; equal parents stay equal") {
        pride::SbxCrossover never = sbx;
        never.probability = 0.0;
        const std::vector<double> lo(3, 0.0), hi(3, 1.0);
        pride::Rng rng(3);
        for (int k = 0; k < 100; ++k) {
            std::vector<double> a = {0.1, 0.5, 0.9}, b = {0.7, 0.2, 0.3};
            never(a, b, lo, hi, rng);
            CHECK(a == std::vector<double>{0.1, 0.5, 0.9});
            CHECK(b == std::vector<double>{0.7, 0.2, 0.3});
            std::vector<double> c = {0.3, 0.3, 0.3}, d = c;
            sbx(c, d, lo, hi, rng);
            CHECK(c == std::vector<double>{0.3, 0.3, 0.3});
            CHECK(d == c);
        }
    }
    SECTION("the spread factor has the SBX distribution, bounded near a face") {
        // Parents -1 and 1 in a huge box: the children are -betaq and +betaq, whose law is
        //   P(betaq <= b) = b^(eta+1) / 2 (b <= 1),  1 - b^-(eta+1) / 2 (b > 1)   (Deb and Agrawal).
        // With probability 0.9 per pair and 1/2 per coordinate, 45 % of the coordinates cross.
        const double eta = 15.0;
        std::vector<double> betaq;
        int pairs_changed = 0, first_child_above = 0;
        {
            pride::Rng rng(6);
            const std::vector<double> lo(2, -1e6), hi(2, 1e6);
            const int pairs = 40000;
            for (int k = 0; k < pairs; ++k) {
                std::vector<double> a = {-1.0, -1.0}, b = {1.0, 1.0};
                sbx(a, b, lo, hi, rng);
                bool changed = false;
                for (std::size_t i = 0; i < 2; ++i) {
                    CHECK((a[i] + b[i]) == Approx(0.0).margin(1e-12));
                    if (std::abs(a[i]) != 1.0) {
                        betaq.push_back(std::abs(a[i]));
                        first_child_above += a[i] > 0.0;
                        changed = true;
                    }
                }
                pairs_changed += changed;
            }
            // P(pair changed) = 0.9 * (1 - 1/4) = 0.675; P(coordinate crossed) = 0.45.
            CHECK(pairs_changed == Approx(0.675 * pairs).margin(5 * std::sqrt(0.675 * 0.325 * pairs)));
            CHECK(static_cast<double>(betaq.size()) ==
                  Approx(0.45 * 2 * pairs).margin(5 * std::sqrt(0.45 * 0.55 * 2 * pairs)));
            // Which child gets the upper value is a fair coin.
            const double crossed = static_cast<double>(betaq.size());
            CHECK(first_child_above == Approx(0.5 * crossed).margin(5 * std::sqrt(0.25 * crossed)));
        }
        check_distribution(betaq, {0.8, 0.9, 0.95, 0.99, 1.0, 1.01, 1.05, 1.1, 1.2}, [&](double b) {
            return b <= 1.0 ? 0.5 * std::pow(b, eta + 1) : 1.0 - 0.5 * std::pow(b, -(eta + 1));
        });

        // The first parent on the lower face (0) and the other at 1, the upper face far away: the
        // bounded form gives beta = 1, alpha = 1 for the lower child, so betaq = u^(1/(eta+1)) and
        // the lower child 0.5 (1 - betaq) never leaves [0, 1/2]: P(betaq <= b) = b^(eta+1). (Plain
        // SBX and a clamp would instead put half the lower children exactly on the face.)
        std::vector<double> lower_betaq;
        int on_face = 0;
        {
            pride::Rng rng(7);
            pride::SbxCrossover always = sbx;
            always.probability = 1.0;
            const std::vector<double> lo = {0.0}, hi = {1e6};
            for (int k = 0; k < 40000; ++k) {
                std::vector<double> a = {0.0}, b = {1.0};
                always(a, b, lo, hi, rng);
                if (a[0] == 0.0 && b[0] == 1.0) continue;  // not crossed
                const double low_child = std::min(a[0], b[0]);
                REQUIRE(low_child >= 0.0);
                REQUIRE(low_child <= 0.5);
                on_face += low_child == 0.0;
                lower_betaq.push_back(1.0 - 2.0 * low_child);
            }
        }
        CHECK(lower_betaq.size() > 15000u);
        CHECK(on_face < 10);
        check_distribution(lower_betaq, {0.7, 0.8, 0.9, 0.95, 0.98, 0.99},
                           [&](double b) { return std::pow(b, eta + 1); });
    }
    SECTION("a larger eta keeps children closer to their parents") {
        // Parents -1 and 1 in a huge box: the children are -betaq and betaq, so |c - parent| is
        // |betaq - 1| (0 for coordinates not crossed); its mean falls as eta grows.
        auto spread = [](double eta) {
            pride::SbxCrossover op;
            op.eta = eta;
            op.probability = 1.0;
            const std::vector<double> lo = {-1e6}, hi = {1e6};
            pride::Rng rng(5);
            double total = 0.0;
            for (int k = 0; k < 20000; ++k) {
                std::vector<double> a = {-1.0}, b = {1.0};
                op(a, b, lo, hi, rng);
                CHECK((a[0] + b[0]) == Approx(0.0).margin(1e-12));
                total += std::abs(std::abs(a[0]) - 1.0);
            }
            return total / 20000.0;
        };
        const double s0 = spread(0.0), s2 = spread(2.0), s15 = spread(15.0), s100 = spread(100.0);
        CHECK(s0 > s2);
        CHECK(s2 > s15);
        CHECK(s15 > s100);
        CHECK(s100 < 0.01);
        CHECK(s15 > 0.01);
    }
}

TEST_CASE("polynomial mutation on hand-worked cases", "[operators][mutation]") {
    const std::vector<double> lo = {-1.0, 0.0, 10.0, -5.0, 0.25, -1e-6}, hi = {1.0, 2.0, 11.0, 5.0, 0.5, 1e-6};
    pride::Rng rng(9);
    SECTION("probability 1 changes every coordinate and stays in the box") {
        pride::PolynomialMutation all;
        all.probability = 1.0;
        for (int k = 0; k < 5000; ++k) {
            std::vector<double> x(6);
            for (std::size_t i = 0; i < 6; ++i) x[i] = lo[i] + (hi[i] - lo[i]) * (0.05 + 0.9 * rng.uniform());
            const auto x0 = x;
            all(x, lo, hi, rng);
            REQUIRE(inside(x, lo, hi));
            for (std::size_t i = 0; i < 6; ++i) {
                INFO("call " << k << " coordinate " << i);
                CHECK(x[i] != x0[i]);
            }
        }
    }
    SECTION("probability 0 changes nothing") {
        pride::PolynomialMutation none;
        none.probability = 0.0;
        for (int k = 0; k < 1000; ++k) {
            std::vector<double> x = {0.5, 1.0, 10.5, 0.0, 0.3, 0.0};
            const auto x0 = x;
            none(x, lo, hi, rng);
            CHECK(x == x0);
        }
    }
    SECTION("the default mutates 1/D of the coordinates on average") {
        pride::PolynomialMutation def;  // probability < 0: 1/D
        const std::vector<double> l(10, 0.0), h(10, 1.0);
        std::int64_t changed = 0;
        std::vector<std::int64_t> per_coordinate(10, 0);
        const int calls = 20000;
        for (int k = 0; k < calls; ++k) {
            std::vector<double> x(10, 0.5);
            def(x, l, h, rng);
            REQUIRE(inside(x, l, h));
            for (std::size_t i = 0; i < 10; ++i)
                if (x[i] != 0.5) {
                    ++changed;
                    ++per_coordinate[i];
                }
        }
        // Binomial(200000, 0.1): mean 20000, sd about 134.
        CHECK(changed == Approx(20000).margin(700));
        for (auto c : per_coordinate) CHECK(c == Approx(2000).margin(250));  // sd about 42
    }
    SECTION("stays in the box from the faces and moves by a small step for eta 20") {
        pride::PolynomialMutation all;
        all.probability = 1.0;
        double total = 0.0;
        for (int k = 0; k < 5000; ++k) {
            std::vector<double> x = {k % 2 ? -1.0 : 1.0};
            const std::vector<double> l = {-1.0}, h = {1.0};
            all(x, l, h, rng);
            REQUIRE(inside(x, l, h));
            total += std::abs(std::abs(x[0]) - 1.0);
        }
        // From a face the step is small on average (eta 20): well below a tenth of the width.
        CHECK(total / 5000 < 0.2);
        CHECK(total > 0.0);
    }
    SECTION("the step has the documented distribution") {
        // From y = 0 in [-1, 1] (width 2): for u <= 1/2, dq = (2u + (1 - 2u) c)^(1/(eta+1)) - 1
        // with c = (1/2)^(eta+1), so P(dq <= -t) = ((1 - t)^(eta+1) - c) / (2 (1 - c)) for t in
        // (0, 1), and symmetrically upwards.
        pride::PolynomialMutation all;
        all.probability = 1.0;
        const double eta = 20.0, c = std::pow(0.5, eta + 1);
        std::vector<double> dq;
        const std::vector<double> l = {-1.0}, h = {1.0};
        for (int k = 0; k < 40000; ++k) {
            std::vector<double> x = {0.0};
            all(x, l, h, rng);
            dq.push_back(x[0] / 2.0);
        }
        auto cdf = [&](double t) {  // P(dq <= t)
            const double down = (std::pow(1.0 - std::abs(t), eta + 1) - c) / (2.0 * (1.0 - c));
            return t < 0 ? down : 1.0 - down;
        };
        check_distribution(dq, {-0.3, -0.1, -0.05, -0.02, -0.005, 0.005, 0.02, 0.05, 0.1, 0.3}, cdf);
        // From the lower face the step is never downwards, and is 0 for u <= 1/2 (d1 = 0).
        int unchanged = 0;
        for (int k = 0; k < 4000; ++k) {
            std::vector<double> x = {-1.0};
            all(x, l, h, rng);
            REQUIRE(x[0] >= -1.0);
            unchanged += x[0] == -1.0;
        }
        CHECK(unchanged == Approx(2000).margin(200));
    }
}

TEST_CASE("tournament selection", "[operators][selection]") {
    const std::vector<double> fitness = {5.0, 3.0, 9.0, 0.5, 7.0, 2.0, 8.0, 4.0, 6.0, 1.0};
    pride::Rng rng(13);
    SECTION("a huge tournament picks the best") {
        const pride::TournamentSelection big{500};
        for (int k = 0; k < 200; ++k) CHECK(big(fitness, rng) == 3u);
    }
    SECTION("size 1 is uniform") {
        const pride::TournamentSelection one{1};
        std::vector<int> counts(fitness.size(), 0);
        for (int k = 0; k < 50000; ++k) ++counts[one(fitness, rng)];
        for (int c : counts) CHECK(c == Approx(5000).margin(400));  // sd about 67
    }
    SECTION("size 2 favours better members: P(rank r wins) = (2(n - r) - 1) / n^2") {
        const pride::TournamentSelection two{2};
        std::vector<int> counts(fitness.size(), 0);
        const int draws = 100000;
        for (int k = 0; k < draws; ++k) ++counts[two(fitness, rng)];
        // ranks (0 = best): index 3 (0.5) rank 0, index 9 (1.0) rank 1, ..., index 2 (9.0) rank 9
        const int rank_of[] = {5, 3, 9, 0, 7, 2, 8, 4, 6, 1};
        for (std::size_t i = 0; i < fitness.size(); ++i) {
            const double p = (2.0 * (10 - rank_of[i]) - 1.0) / 100.0;
            INFO("index " << i);
            CHECK(counts[i] == Approx(p * draws).margin(5 * std::sqrt(p * (1 - p) * draws) + 1));
        }
    }
    SECTION("+inf members lose to finite ones") {
        const std::vector<double> f = {inf, inf, 1.0, inf};
        const pride::TournamentSelection big{100};
        for (int k = 0; k < 50; ++k) CHECK(big(f, rng) == 2u);
    }
}

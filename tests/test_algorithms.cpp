// Tests of the algorithms used directly as templates (PSO, GA, the NLopt adapter, the DE family):
// exact budgets, bounds, reproducibility and NaN handling, for every algorithm. Convergence,
// termination, parameter validation and the operators are in test_algorithm_settings.cpp.
#include <catch2/catch.hpp>

#include "tests/algorithms_common.hpp"

// ---------------------------------------------------------------------------------------------
// 1. Budgets

TEST_CASE("every algorithm spends exactly the evaluation budget", "[algorithms][budget]") {
    const std::int64_t budgets[] = {1, 2, 7, 19, 20, 21, 49, 50, 51, 99, 1001};
    for (const std::int64_t population : {50, 20}) {
        for_each_algorithm(population, [&](const std::string& label, const auto& algo) {
            for (const std::int64_t n : budgets) {
                for (const std::size_t dim : {2u, 7u}) {
                    INFO(label << " population " << population << " budget " << n << " D " << dim);
                    auto p = probe(pride::continuous::Rastrigin(dim));
                    const auto r = algo.run(p, pride::max_evaluations(n), 11);
                    CHECK(p.log->calls == r.evaluations);
                    CHECK(r.evaluations == n);
                    CHECK(p.log->wrong_size == 0);
                    CHECK(std::isfinite(r.best_f));
                    check_history(r);
                }
            }
        });
    }
}

TEST_CASE("the evaluation budget is exact through the batch evaluation path", "[algorithms][budget]") {
    for (const std::int64_t n : {1, 7, 19, 20, 21, 39, 40, 41, 1001}) {
        INFO("budget " << n);
        BatchProbe<pride::continuous::Sphere> p{{pride::continuous::Sphere(3)}};
        const auto rp = pso(20).run(p, pride::max_evaluations(n), 5);
        CHECK(p.log->calls == rp.evaluations);
        CHECK(rp.evaluations == n);

        BatchProbe<pride::continuous::Sphere> q{{pride::continuous::Sphere(3)}};
        const auto rg = ga(20, 3).run(q, pride::max_evaluations(n), 5);
        CHECK(q.log->calls == rg.evaluations);
        CHECK(rg.evaluations == n);
    }
}

TEST_CASE("NLopt without restart may stop before the budget and never after it", "[algorithms][budget][nlopt]") {
    for (const char* name : {"LN_SBPLX", "GN_CRS2_LM"}) {
        for (const std::int64_t n : {1, 7, 49, 50, 51, 1001}) {
            INFO(name << " budget " << n);
            pride::Nlopt a(name);
            a.restart = false;
            auto p = probe(pride::continuous::Sphere(4));
            const auto r = a.run(p, pride::max_evaluations(n), 2);
            CHECK(p.log->calls == r.evaluations);
            CHECK(r.evaluations <= n);
            CHECK(r.evaluations >= 1);
        }
    }
    // A small smooth problem: subplex converges (to the exact minimum) long before 200,000
    // evaluations and, without restart, stops there.
    pride::Nlopt once("LN_SBPLX");
    once.restart = false;
    auto p = probe(pride::continuous::Sphere(2));
    const auto r = once.run(p, pride::max_evaluations(200000), 1);
    CHECK(p.log->calls == r.evaluations);
    CHECK(r.evaluations < 200000);
    CHECK(r.best_f < 1e-12);
    check_history(r);
    // With restart (the default) the same run spends the whole budget.
    pride::Nlopt again("LN_SBPLX");
    auto q = probe(pride::continuous::Sphere(2));
    const auto r2 = again.run(q, pride::max_evaluations(20000), 1);
    CHECK(q.log->calls == 20000);
    CHECK(r2.evaluations == 20000);
}

// ---------------------------------------------------------------------------------------------
// 2. Bounds

namespace {

/// Asymmetric per-coordinate box; the unconstrained optimum (target) lies outside the box in
/// several coordinates, so the search keeps pressing against the faces; a small Rastrigin term
/// makes it rugged (too small to make local minima where the target is 2 or more away, so even a
/// local method must end on the faces of coordinates 0 and 2). The one degenerate coordinate
/// (lo == hi) must stay fixed.
BoxOf pressing_box() {
    BoxOf b;
    b.lo = {-1.0, 2.0, -10.0, 0.5, -3.0, 1e-3, 7.25};
    b.hi = {3.0, 2.5, -9.0, 100.0, 7.0, 2e-3, 7.25};
    const std::vector<double> target = {5.0, 2.2, -50.0, 0.1, 1.3, 1.0, 7.25};
    b.f = [target](std::span<const double> x) {
        double f = 0.0;
        for (std::size_t i = 0; i < x.size(); ++i) {
            const double d = x[i] - target[i];
            f += d * d + 0.5 * (1.0 - std::cos(2.0 * 3.141592653589793 * d));
        }
        return f;
    };
    return b;
}

/// `reaches_faces`: the algorithm is expected to end on the faces where the constrained optimum
/// lies (true for clamping; reflection keeps a swarm off the faces, so PSO with reflection may not).
template <class A>
void check_bounds_kept(const std::string& label, const A& algo, bool reaches_faces = true) {
    for (const std::uint64_t seed : {1u, 2u, 3u}) {
        for (const std::int64_t budget : {3000, 3001}) {
            INFO(label << " seed " << seed << " budget " << budget);
            auto box = pressing_box();
            ObserverLog log;
            log.lo = box.lo;
            log.hi = box.hi;
            auto p = probe(box);
            const auto r = algo.run(p, pride::max_evaluations(budget), seed, log);
            CHECK(p.log->calls == budget);
            CHECK(p.log->outside == 0);
            CHECK(log.population_outside == 0);
            CHECK(inside(r.best_x, box.lo, box.hi));
            CHECK(r.best_x[6] == 7.25);
            CHECK(r.best_f < r.history.front());
            if (reaches_faces) {
                CHECK(r.best_f < 1620.0);  // the constrained minimum is about 1605
                // The constrained optimum has x0 on its upper face and x2 on its lower face; the
                // search must have got there (or very near) rather than been thrown back.
                CHECK(r.best_x[0] == Approx(3.0).margin(0.05));
                CHECK(r.best_x[2] == Approx(-10.0).margin(0.05));
            }
        }
    }
    for (const std::uint64_t seed : {1u, 2u}) {  // shifted Rosenbrock: box [-5, 10], optimum inside
        INFO(label << " shifted-rosenbrock seed " << seed);
        auto p = probe(pride::continuous::Shifted<pride::continuous::Rosenbrock>(6));
        const auto r = algo.run(p, pride::max_evaluations(2000), seed);
        CHECK(p.log->outside == 0);
        CHECK(inside(r.best_x, p.lower(), p.upper()));
    }
}

}  // namespace

TEST_CASE("PSO keeps every evaluated point in the box under clamping and reflection", "[algorithms][bounds]") {
    check_bounds_kept("pso clamp", pso(20));
    check_bounds_kept("pso-constriction clamp", pso_constriction(20));
    PsoReflect reflect;
    reflect.population = 20;
    check_bounds_kept("pso reflect", reflect, false);
    PsoReflectFree reflect_free;  // no velocity clamp: the largest excursions
    reflect_free.population = 20;
    reflect_free.velocity.c1 = reflect_free.velocity.c2 = 4.0;
    check_bounds_kept("pso reflect, no velocity clamp", reflect_free, false);
}

TEST_CASE("GA keeps every evaluated point in the box under clamping and reflection", "[algorithms][bounds]") {
    check_bounds_kept("ga clamp", ga(20, 2));
    GaReflect reflect;
    reflect.population = 20;
    reflect.replacement.elitism = 2;
    check_bounds_kept("ga reflect", reflect);
}

TEST_CASE("NLopt keeps every evaluated point in the box", "[algorithms][bounds][nlopt]") {
    check_bounds_kept("nlopt:LN_SBPLX", pride::Nlopt("LN_SBPLX"));
    check_bounds_kept("nlopt:GN_CRS2_LM", pride::Nlopt("GN_CRS2_LM"));
}

TEST_CASE("bound policies on hand-worked values", "[algorithms][bounds][operators]") {
    const std::vector<double> lo = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -2.0, 5.0};
    const std::vector<double> hi = {1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 2.0, 5.0};
    SECTION("clamp") {
        std::vector<double> x = {1.25, -0.25, 0.5, 7.0, -7.0, nan_value, inf, -inf, 2.0, 6.0};
        pride::Clamp{}(x, lo, hi);
        const std::vector<double> expected = {1.0, 0.0, 0.5, 1.0, 0.0, 0.0, 1.0, 0.0, 2.0, 5.0};
        CHECK(x == expected);
    }
    SECTION("reflect") {
        // Mirrored at each face crossed: 1.25 -> 0.75; -0.25 -> 0.25; 2.25 -> (1 - 1.25 = -0.25)
        // -> 0.25; -1.75 -> 1.75 -> 0.25; 3.5 in [-2, 2] -> 0.5; NaN -> lower face; +-inf -> faces.
        std::vector<double> x = {1.25, -0.25, 0.5, 2.25, -1.75, nan_value, inf, -inf, 3.5, 6.0};
        pride::Reflect{}(x, lo, hi);
        const std::vector<double> expected = {0.75, 0.25, 0.5, 0.25, 0.25, 0.0, 1.0, 0.0, 0.5, 5.0};
        for (std::size_t i = 0; i < x.size(); ++i) {
            INFO("coordinate " << i);
            CHECK(x[i] == Approx(expected[i]).margin(1e-15));
        }
        // Very far excursions land inside too.
        pride::Rng rng(4);
        for (int k = 0; k < 10000; ++k) {
            std::vector<double> y = {rng.uniform(-1e6, 1e6), rng.uniform(-50, 50), rng.uniform(-1e300, 1e300)};
            const std::vector<double> l = {-1.0, 0.1, -3.0}, h = {2.0, 0.2, 1e-9};
            pride::Reflect{}(y, l, h);
            REQUIRE(inside(y, l, h));
        }
    }
}

// ---------------------------------------------------------------------------------------------
// 3. Reproducibility

TEST_CASE("equal seeds give bit-identical runs, different seeds differ", "[algorithms][reproducible]") {
    for_each_algorithm(20, [&](const std::string& label, const auto& algo) {
        INFO(label);
        const auto problem = pride::continuous::Shifted<pride::continuous::Rastrigin>(6);
        const auto budget = pride::max_evaluations(3007);
        ObserverLog log1, log2, log3;
        const auto r1 = algo.run(problem, budget, 42, log1);
        const auto r2 = algo.run(problem, budget, 42, log2);
        const auto r3 = algo.run(problem, budget, 43, log3);

        CHECK(bits_equal(r1.best_x, r2.best_x));
        CHECK(bits_equal(r1.best_f, r2.best_f));
        CHECK(bits_equal(r1.history, r2.history));
        CHECK(r1.history_evaluations == r2.history_evaluations);
        CHECK(r1.evaluations == r2.evaluations);
        CHECK(r1.iterations == r2.iterations);
        CHECK(log1.lines.size() == r1.history.size());
        CHECK(log1.lines == log2.lines);

        CHECK_FALSE(bits_equal(r1.history, r3.history));
        CHECK_FALSE(bits_equal(r1.best_x, r3.best_x));
        CHECK(log1.lines != log3.lines);

        // A run with no observer is the same run as one with an observer.
        const auto r4 = algo.run(problem, budget, 42);
        CHECK(bits_equal(r1.history, r4.history));
        CHECK(bits_equal(r1.best_x, r4.best_x));

        // The observer sees what the history records.
        for (std::size_t k = 0; k < log1.lines.size() && k < r1.history.size(); ++k) {
            INFO("iteration " << k);
            CHECK(std::get<0>(log1.lines[k]) == static_cast<std::int64_t>(k));
            CHECK(std::get<1>(log1.lines[k]) == r1.history_evaluations[k]);
            CHECK(std::get<2>(log1.lines[k]) == std::bit_cast<std::uint64_t>(r1.history[k]));
        }
    });
}

TEST_CASE("a run does not depend on what ran before it", "[algorithms][reproducible]") {
    // NLopt's generator is global; the adapter reseeds it, so interleaving runs changes nothing.
    const auto problem = pride::continuous::Ackley(5);
    const pride::Nlopt crs("GN_CRS2_LM");
    const auto first = crs.run(problem, pride::max_evaluations(2000), 9);
    (void)crs.run(problem, pride::max_evaluations(1234), 10);
    (void)pso(20).run(problem, pride::max_evaluations(500), 9);
    const auto again = crs.run(problem, pride::max_evaluations(2000), 9);
    CHECK(bits_equal(first.history, again.history));
    CHECK(bits_equal(first.best_x, again.best_x));
}

// ---------------------------------------------------------------------------------------------
// 4. NaN and infinite values

TEST_CASE("NaN and infinite objective values never become the best", "[algorithms][nan]") {
    // A shifted sphere whose unconstrained minimum (2, 1, -1, 0.5) lies where x0 > 0, a region in
    // which the objective returns a non-finite value; the best finite value is 4 (at x0 = 0).
    const std::vector<double> centre = {2.0, 1.0, -1.0, 0.5};
    for (const double bad : {nan_value, inf, -inf}) {
        BoxOf box;
        box.lo.assign(4, -5.0);
        box.hi.assign(4, 5.0);
        box.f = [centre, bad](std::span<const double> x) {
            if (x[0] > 0.0) return bad;
            double f = 0.0;
            for (std::size_t i = 0; i < x.size(); ++i) f += (x[i] - centre[i]) * (x[i] - centre[i]);
            return f;
        };
        for_each_algorithm(20, [&](const std::string& label, const auto& algo) {
            for (const std::uint64_t seed : {1u, 2u, 3u}) {
                INFO(label << " bad value " << bad << " seed " << seed);
                auto p = probe(box);
                const auto r = algo.run(p, pride::max_evaluations(4000), seed);
                CHECK(r.evaluations == 4000);
                CHECK(std::isfinite(r.best_f));
                CHECK(r.best_f >= 4.0);
                REQUIRE(r.best_x.size() == 4);
                CHECK(r.best_x[0] <= 0.0);
                // best_f is the value at best_x
                CHECK(bits_equal(r.best_f, box.f(r.best_x)));
                check_history(r);
                for (double h : r.history) CHECK(!std::isnan(h));
                for (double h : r.history) CHECK(h != -inf);
            }
        });
    }
}

TEST_CASE("an objective that is never finite gives best_f = +inf and spends the budget", "[algorithms][nan]") {
    BoxOf box;
    box.lo.assign(3, -1.0);
    box.hi.assign(3, 1.0);
    box.f = [](std::span<const double> x) { return x[1] > 0.0 ? nan_value : -inf; };
    for_each_algorithm(20, [&](const std::string& label, const auto& algo) {
        INFO(label);
        auto p = probe(box);
        const auto r = algo.run(p, pride::max_evaluations(503), 1);
        CHECK(p.log->calls == 503);
        CHECK(r.evaluations == 503);
        CHECK(r.best_f == inf);
        for (double h : r.history) CHECK(h == inf);
    });
}

// Instances of the scalable functions (problems/continuous/instance.hpp): the rotation is
// orthogonal, the moved optimum is the optimum and lies where the definition says, instance k is
// the same on every run and thread, instance 0 is the function as defined; the catalog's instance
// rules and messages; a noisy function's noise follows the run's seed.
#include <catch2/catch.hpp>

#include <Eigen/Dense>
#include <cmath>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "engine/run.hpp"
#include "framework/random.hpp"
#include "problems/continuous/catalog.hpp"
#include "problems/continuous/functions.hpp"
#include "problems/continuous/instance.hpp"
#include "tests/test_support.hpp"

using namespace pride::continuous;
using Catch::Matchers::Contains;
using pride::test::input_error_message;

namespace {

std::vector<double> random_point(const Function& f, pride::Rng& rng) {
    std::vector<double> x(f.dimension());
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = rng.uniform(f.lower()[i], f.upper()[i]);
    return x;
}

/// The catalog's functions whose instances are the transform (scalable, not the shifted-* aliases).
std::vector<std::string> transformable() {
    std::vector<std::string> names;
    for (const auto& item : catalog().items())
        if (item.entry.instances == Instances::transform) names.push_back(item.name);
    return names;
}

}  // namespace

TEST_CASE("instances: the rotation is orthogonal to 1e-12 and differs between instances", "[instances]") {
    for (const std::size_t n : {1u, 2u, 3u, 10u, 40u}) {
        for (const std::uint64_t k : {1u, 2u, 17u}) {
            INFO("n " << n << " instance " << k);
            const Eigen::MatrixXd r = random_rotation(n, k);
            const Eigen::MatrixXd identity =
                Eigen::MatrixXd::Identity(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
            CHECK((r.transpose() * r - identity).cwiseAbs().maxCoeff() <= 1e-12);
            CHECK((r * r.transpose() - identity).cwiseAbs().maxCoeff() <= 1e-12);
            CHECK(r == random_rotation(n, k));  // the same every time, bit for bit
        }
        if (n > 1) CHECK(random_rotation(n, 1) != random_rotation(n, 2));
    }
}

TEST_CASE("instances: the sign fix makes the rotation uniform (Haar): E[trace] = 0, E[trace^2] = 1", "[instances]") {
    // For a Haar-distributed orthogonal matrix the trace has mean 0 and second moment 1 (Diaconis and
    // Shahshahani 1994); QR without the sign fix biases the diagonal towards positive values
    // (mean trace near n/2 for Householder QR's convention).
    const std::size_t n = 6;
    const int draws = 4000;
    double sum = 0.0, sum2 = 0.0;
    for (int k = 1; k <= draws; ++k) {
        const double t = random_rotation(n, static_cast<std::uint64_t>(k)).trace();
        sum += t;
        sum2 += t * t;
    }
    const double mean = sum / draws, second = sum2 / draws;
    // Var(trace) = 1 and Var(trace^2) is about 2, so 5 standard errors are 0.08 and 0.11.
    CHECK(std::abs(mean) < 0.08);
    CHECK(std::abs(second - 1.0) < 0.12);
}

TEST_CASE("instances: the moved optimum is inside the box, 20-80 % of the half-width from the centre", "[instances]") {
    const std::vector<double> lo{-5.0, -100.0, 0.0}, hi{10.0, 100.0, 1.0};
    for (const std::uint64_t k : {1u, 2u, 3u, 99u}) {
        const auto o = random_shift(lo, hi, k);
        for (std::size_t i = 0; i < o.size(); ++i) {
            const double centre = 0.5 * (lo[i] + hi[i]), half = 0.5 * (hi[i] - lo[i]);
            const double d = std::abs(o[i] - centre) / half;
            CHECK(d >= 0.2);
            CHECK(d <= 0.8);
        }
        CHECK(o == random_shift(lo, hi, k));
    }
    CHECK(random_shift(lo, hi, 1) != random_shift(lo, hi, 2));
}

TEST_CASE("instances: every scalable function's instance k has its optimum at o_k with F's value", "[instances]") {
    pride::Rng rng(11);
    for (const auto& name : transformable()) {
        for (const std::int64_t dim : {2, 5, 10}) {
            for (const std::int64_t k : {1, 2, 3}) {
                INFO(name << " dim " << dim << " instance " << k);
                auto f = make_function(name, dim, k);
                auto plain = make_function(name, dim, 0);
                CHECK(f.instance() == k);
                CHECK(f.optimum_value() == plain.optimum_value());
                const auto o = f.optimum_point();
                REQUIRE(o.size() == static_cast<std::size_t>(dim));
                CHECK(o != plain.optimum_point());
                for (std::size_t i = 0; i < o.size(); ++i) {
                    CHECK(o[i] > f.lower()[i]);
                    CHECK(o[i] < f.upper()[i]);
                }
                // z = x* + R (o - o) = x* exactly, so the value is F's at x*, to the bit.
                const double at_o = f.evaluate(o);
                const double plain_at_optimum = plain.evaluate(plain.optimum_point());
                if (f.noisy()) {
                    CHECK(at_o >= f.optimum_value());
                } else {
                    CHECK(at_o == plain_at_optimum);
                    // No point of the box is better (the bounded-domain clamp keeps Schwefel's).
                    for (int j = 0; j < 200; ++j) {
                        const double v = f.evaluate(random_point(f, rng));
                        CHECK(v >= at_o - 1e-9 * (1.0 + std::abs(at_o)));
                    }
                }
            }
        }
    }
}

TEST_CASE("instances: instance 0 is the function as defined, bit for bit", "[instances]") {
    pride::Rng rng(3);
    auto f = make_function("rastrigin", 7, 0);
    const Rastrigin typed(7);
    for (int j = 0; j < 20; ++j) {
        const auto x = random_point(f, rng);
        CHECK(f.evaluate(x) == typed.evaluate(x));
    }
    CHECK(make_function("rastrigin", 7).instance() == 0);  // the default
    CHECK(make_function("bbob-f3", 7).instance() == 1);    // BBOB's default: COCO counts from 1
}

TEST_CASE("instances: the transform costs one matrix-vector product: a rotated sphere is |x - o|^2", "[instances]") {
    // Hand-checkable: sphere under z = R (x - o) is |R (x - o)|^2 = |x - o|^2 for orthogonal R.
    auto f = make_function("sphere", 4, 5);
    const auto o = f.optimum_point();
    const std::vector<double> x{1.0, -2.0, 0.5, 3.0};
    double expected = 0.0;
    for (std::size_t i = 0; i < 4; ++i) expected += (x[i] - o[i]) * (x[i] - o[i]);
    CHECK(std::abs(f.evaluate(x) - expected) <= 1e-12 * expected);
    // And the rotation is not the identity: the ellipsoid (not rotation-invariant) changes.
    auto e = make_function("ellipsoid", 4, 5);
    auto e_shift_only = e.optimum_point();
    std::vector<double> y = e_shift_only;
    y[0] += 1.0;  // one unit along the first axis from the optimum
    const double along_axis = e.evaluate(y) - e.optimum_value();
    CHECK(std::abs(along_axis - 1.0) > 1e-3);  // unrotated it would be exactly 1 * 1^2
}

TEST_CASE("instances: the same instance on several threads gives the same bits", "[instances]") {
    std::vector<double> values(4);
    std::vector<std::thread> threads;
    const std::vector<double> x{0.3, -1.2, 2.2, 0.1, -0.7, 1.9, 0.0, 0.4};
    for (std::size_t t = 0; t < values.size(); ++t)
        threads.emplace_back([&, t] { values[t] = make_function("rosenbrock", 8, 4).evaluate(x); });
    for (auto& th : threads) th.join();
    for (double v : values) CHECK(v == values[0]);
}

TEST_CASE("instances: batch and scalar evaluation of an instance agree bit for bit", "[instances]") {
    pride::Rng rng(9);
    for (const std::string name : {"ellipsoid", "schwefel-2.21", "schwefel", "sphere", "bbob-f10"}) {
        auto f = make_function(name, 6, 2);
        pride::Matrix points(6, 9);
        for (Eigen::Index j = 0; j < points.cols(); ++j) {
            const auto x = random_point(f, rng);
            for (Eigen::Index i = 0; i < 6; ++i) points(i, j) = x[static_cast<std::size_t>(i)];
        }
        std::vector<double> batch(9);
        f.evaluate_batch(points, batch);
        for (Eigen::Index j = 0; j < points.cols(); ++j)
            CHECK(batch[static_cast<std::size_t>(j)] == f.evaluate(pride::column(points, j)));
    }
}

TEST_CASE("instances: what each function accepts, with messages naming the instance", "[instances]") {
    CHECK_THAT(input_error_message([] { (void)make_function("sphere", 3, -1); }),
               Contains("instance:") && Contains("-1"));
    CHECK_THAT(input_error_message([] { (void)make_function("branin", 2, 1); }),
               Contains("instance:") && Contains("branin") && Contains("one instance"));
    CHECK_THAT(input_error_message([] { (void)make_function("shifted-sphere", 3, 2); }),
               Contains("instance:") && Contains("sphere --instance K"));
    CHECK_THAT(input_error_message([] { (void)make_function("bbob-f7", 3, 0); }),
               Contains("instance:") && Contains("from 1"));
    CHECK_THAT(input_error_message([] { (void)make_function("branin", 3); }), Contains("dim:") && Contains("2 only"));
    CHECK_NOTHROW(make_function("shifted-sphere", 3, 0));
    CHECK_NOTHROW(make_function("bbob-f7", 3, 40));
}

TEST_CASE("instances: shifted-* keep their values: the golden-ratio shift, no rotation", "[instances]") {
    auto f = make_function("shifted-rastrigin", 3);
    const auto o = shift_optimum(3, -5.12, 5.12);
    CHECK(f.optimum_point() == o);
    // Hand-worked: o_0 = -5.12 + 10.24 (0.1 + 0.8 frac(phi)) with phi = 0.6180339887498949.
    CHECK(std::abs(o[0] - (-5.12 + 10.24 * (0.1 + 0.8 * 0.6180339887498949))) < 1e-15);
    const Rastrigin plain(3);
    const std::vector<double> x{1.0, 2.0, -3.0};
    const std::vector<double> moved{x[0] - o[0], x[1] - o[1], x[2] - o[2]};
    CHECK(f.evaluate(x) == plain.evaluate(moved));
}

TEST_CASE("instances: a noisy function's noise follows the run's seed", "[instances]") {
    using namespace pride::engine;
    const Problem problem(ContinuousSpec{"quartic-noise", 5});
    const AlgorithmSpec pso{"pso", {}};
    Budget budget;
    budget.evaluations = 2000;
    const auto a = run(pso, problem, budget, 4), b = run(pso, problem, budget, 4), c = run(pso, problem, budget, 5);
    CHECK(a.best_f == b.best_f);
    CHECK(a.history == b.history);
    CHECK(a.best_f != c.best_f);
    // The noise is in [0, 1): the best value is no lower than the noiseless quartic's 0.
    CHECK(a.best_f >= 0.0);
    // eval's noise: the same seed twice gives the same value; another seed another one.
    auto f = make_function("quartic-noise", 2);
    f.reseed(7);
    const double first = f.evaluate(std::vector<double>{0.0, 0.0});
    f.reseed(7);
    CHECK(f.evaluate(std::vector<double>{0.0, 0.0}) == first);
    f.reseed(8);
    CHECK(f.evaluate(std::vector<double>{0.0, 0.0}) != first);
}

TEST_CASE("instances: the evaluation guard records when each target is first reached, exactly",
          "[instances][targets]") {
    using namespace pride::engine;
    const Problem problem(ContinuousSpec{"sphere", 3, 2});
    Budget budget;
    budget.evaluations = 1500;
    budget.recorded_targets = {10.0, 1.0, 0.1, 0.01, 1e-30};
    const auto r = run(AlgorithmSpec{"pso", {}}, problem, budget, 1);
    REQUIRE(r.target_hits.size() >= 3);
    REQUIRE(r.target_hits.size() < 5);  // 1e-30 is out of reach in 1500 evaluations
    // Non-decreasing, within the budget, and consistent with the history: by the end of the
    // iteration whose history value first reaches a target, the hit has happened, and not before
    // the iteration before it ended.
    for (std::size_t k = 0; k < r.target_hits.size(); ++k) {
        if (k) CHECK(r.target_hits[k] >= r.target_hits[k - 1]);
        CHECK(r.target_hits[k] >= 1);
        CHECK(r.target_hits[k] <= r.evaluations);
        std::size_t it = 0;
        while (r.history[it] > budget.recorded_targets[k]) ++it;
        CHECK(r.target_hits[k] <= r.history_evaluations[it]);
        if (it > 0) CHECK(r.target_hits[k] > r.history_evaluations[it - 1]);
    }
}

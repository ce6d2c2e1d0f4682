// Tests of ask and tell (engine/ask_tell.hpp) and of observed runs (engine::run with an
// observer): every box algorithm driven batch by batch gives engine::run's result bit for bit,
// tells of the wrong size or after the end are refused, an AskTell destroyed mid-run ends its
// thread, and an observer that returns false stops the run where a stopping rule would.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <vector>

#include "engine/ask_tell.hpp"
#include "engine/registry.hpp"
#include "engine/run.hpp"
#include "tests/test_support.hpp"

using Catch::Matchers::Contains;
using pride::test::input_error_message;
namespace engine = pride::engine;

namespace {

double f(const double* x) {
    return (x[0] - 1.0) * (x[0] - 1.0) + x[1] * x[1] + std::abs(x[2]);
}

const std::vector<double> lower{-5, -4, -3}, upper{5, 4, 3};

engine::Budget evals(std::int64_t n) {
    engine::Budget b;
    b.evaluations = n;
    return b;
}

engine::RunResult direct(const std::string& algo, std::int64_t n, std::uint64_t seed) {
    engine::CallbackSpec spec;
    spec.lower = lower;
    spec.upper = upper;
    spec.scalar = [](std::span<const double> x) { return f(x.data()); };
    return engine::run({algo, {}}, engine::Problem(spec), evals(n), seed);
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), sizeof(double) * a.size()) == 0;
}

}  // namespace

TEST_CASE("ask and tell: every box algorithm gives engine::run's result bit for bit", "[engine][ask_tell]") {
    for (const auto& entry : engine::algorithms().entries()) {
        if (!entry.runs(engine::Kind::box)) continue;
        INFO(entry.name);
        engine::AskTell run({entry.name, {}}, lower, upper, evals(200), 6);
        std::int64_t told = 0;
        while (!run.done()) {
            const pride::Matrix& x = run.ask();
            std::vector<double> values(static_cast<std::size_t>(x.cols()));
            for (Eigen::Index j = 0; j < x.cols(); ++j) values[static_cast<std::size_t>(j)] = f(x.col(j).data());
            told += x.cols();
            run.tell(values);
        }
        const auto want = direct(entry.name, 200, 6);
        const auto& got = run.result();
        CHECK(told == got.evaluations);
        CHECK(got.evaluations == want.evaluations);
        CHECK(same_bits({got.best_f}, {want.best_f}));
        CHECK(same_bits(got.best_x, want.best_x));
        CHECK(same_bits(got.history, want.history));
        CHECK(run.ask().cols() == 0);
    }
}

TEST_CASE("ask and tell: wrong tells are refused, and a run dropped mid-way ends", "[engine][ask_tell]") {
    engine::AlgorithmSpec pso{"pso", {}};
    pso.params.set("pop", 10);
    {
        engine::AskTell run(pso, {0, 0}, {1, 1}, evals(25), 1);
        CHECK_THAT(input_error_message([&] { run.tell(std::vector<double>(10)); }), Contains("call ask() first"));
        CHECK(run.ask().cols() == 10);
        CHECK(run.ask().rows() == 2);
        CHECK_THAT(input_error_message([&] { run.tell(std::vector<double>(9)); }),
                   Contains("expected 10 values, one per point asked for, got 9"));
        CHECK_THAT(input_error_message([&] { run.result(); }), Contains("has not ended"));
        run.tell(std::vector<double>(10, 1.0));
        run.ask();
        run.tell(std::vector<double>(10, std::nan("")));  // NaN: worse than every value
        CHECK(run.ask().cols() == 5);                     // what is left of the budget
        run.tell(std::vector<double>(5, 2.0));
        CHECK(run.done());
        CHECK(run.result().evaluations == 25);
        CHECK(run.result().best_f == 1.0);
        CHECK_THAT(input_error_message([&] { run.tell(std::vector<double>(5)); }), Contains("the run has ended"));
    }
    for (int i = 0; i < 20; ++i) {  // destroyed while its run waits for a tell: no hang, no leak
        engine::AskTell run(pso, {0, 0}, {1, 1}, evals(1000), 1);
        run.ask();
    }
    {
        engine::AskTell run({"nlopt:LN_SBPLX", {}}, {0, 0}, {1, 1}, evals(1000), 1);
        run.tell(std::vector<double>(static_cast<std::size_t>(run.ask().cols()), 1.0));
        run.ask();
    }
    CHECK_THAT(input_error_message([&] {
                   engine::AskTell({"pso", {}}, {1}, {0}, evals(10), 1);
               }),
               Contains("lower <= upper"));
    CHECK_THAT(input_error_message([&] {
                   engine::AskTell({"astar", {}}, {0}, {1}, evals(10), 1);
               }),
               Contains("grid problems only"));
}

TEST_CASE("observed runs: the observer sees every iteration and false stops the run there", "[engine][observer]") {
    const engine::Problem sphere(engine::ContinuousSpec{"sphere", 4});
    engine::AlgorithmSpec pso{"pso", {}};
    pso.params.set("pop", 10);
    std::vector<std::int64_t> seen;
    const auto r = engine::run(pso, sphere, evals(10'000), 3, [&](const pride::IterationView& v) {
        seen.push_back(v.evaluations);
        CHECK(v.population.cols() == 10);
        return v.iteration < 3;
    });
    CHECK(seen == std::vector<std::int64_t>{10, 20, 30, 40});
    CHECK(r.iterations == 3);
    CHECK(r.evaluations == 40);
    // The unobserved run up to there (its schedule is the 10,000 evaluations').
    auto plain = engine::run(pso, sphere, evals(10'000), 3);
    plain.history.resize(4);
    CHECK(same_bits(r.history, plain.history));
    // Never stopping changes nothing.
    const auto watched = engine::run(pso, sphere, evals(500), 3, [](const pride::IterationView&) { return true; });
    CHECK(same_bits(watched.best_x, engine::run(pso, sphere, evals(500), 3).best_x));
    CHECK_THAT(
        input_error_message([&] {
            engine::GridSpec g;
            g.map = engine::load_map(std::string(PRIDE_SOURCE_DIR) + "/examples/maps/wan2022-10x10.map");
            g.start = {0, 9};
            g.goal = {9, 0};
            engine::run({"astar", {}}, engine::Problem(g), {}, 1, [](const pride::IterationView&) { return true; });
        }),
        Contains("observer: only box runs are observed"));
}

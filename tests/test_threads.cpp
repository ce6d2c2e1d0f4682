// Parallel evaluation inside one run (framework/parallel.hpp, Budget::threads): the same
// result, bit for bit, on 1, 2 and 4 threads for callbacks and grid encodings under several
// algorithms; errors of user code come back from worker threads; bad thread counts and callbacks
// not marked thread-safe are refused, by the engine, the command line and campaign files.
#include <catch2/catch.hpp>

#include <atomic>
#include <bit>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>

#include "engine/run.hpp"
#include "experiment/campaign/campaign.hpp"
#include "experiment/campaign/toml.hpp"
#include "framework/parallel.hpp"
#include "tests/cli_runner.hpp"
#include "tests/test_support.hpp"

using Catch::Matchers::Contains;
using pride::test::input_error_message;
namespace campaign = pride::campaign;
namespace engine = pride::engine;

namespace {

engine::Budget budget(std::int64_t evaluations, std::int64_t threads) {
    engine::Budget b;
    b.evaluations = evaluations;
    b.threads = threads;
    return b;
}

engine::AlgorithmSpec algo(const std::string& name) {
    return {name, {}};
}

std::string example_map(const char* name) {
    return (std::filesystem::path(PRIDE_SOURCE_DIR) / "examples" / "maps" / name).string();
}

void check_same(const engine::RunResult& a, const engine::RunResult& b) {
    CHECK(a.evaluations == b.evaluations);
    CHECK(a.iterations == b.iterations);
    CHECK(a.best_x == b.best_x);
    CHECK(std::bit_cast<std::uint64_t>(a.best_f) == std::bit_cast<std::uint64_t>(b.best_f));
    CHECK(a.history == b.history);
    CHECK(a.history_evaluations == b.history_evaluations);
    REQUIRE(a.grid.has_value() == b.grid.has_value());
    if (a.grid) {
        CHECK(a.grid->path == b.grid->path);
        CHECK(a.grid->feasible == b.grid->feasible);
    }
}

// A function whose value depends on the point alone, with some work (Rastrigin-like), marked
// thread-safe; it records the threads that called it.
engine::CallbackSpec rastrigin_callback(std::set<std::thread::id>* callers, std::mutex* m) {
    engine::CallbackSpec cb;
    cb.name = "mine";
    cb.lower.assign(8, -5.12);
    cb.upper.assign(8, 5.12);
    cb.thread_safe = true;
    cb.scalar = [callers, m](std::span<const double> x) {
        double f = 10.0 * static_cast<double>(x.size());
        for (double v : x) f += v * v - 10.0 * std::cos(6.283185307179586 * v);
        if (callers) {
            std::lock_guard lock(*m);
            callers->insert(std::this_thread::get_id());
        }
        return f;
    };
    return cb;
}

}  // namespace

TEST_CASE("threads: a callback gives the same run on 1, 2 and 4 threads under every box algorithm kind",
          "[threads][engine]") {
    std::set<std::thread::id> callers;
    std::mutex m;
    const engine::Problem problem(rastrigin_callback(&callers, &m));
    for (const char* name : {"pso", "pso-constriction", "ga", "ga-plus", "iaga", "icga", "woa", "hs", "hswoa", "lso",
                             "ilso", "nlopt:LN_SBPLX"}) {
        INFO(name);
        const auto one = engine::run(algo(name), problem, budget(1234, 1), 7);
        CHECK(one.evaluations == 1234);
        for (const std::int64_t threads : {2, 4}) {
            INFO("threads " << threads);
            check_same(one, engine::run(algo(name), problem, budget(1234, threads), 7));
        }
    }
    CHECK(callers.size() >= 2);  // the population algorithms did evaluate on workers
}

TEST_CASE("threads: a batch callback is handed slices of the population, with the same run", "[threads][engine]") {
    std::atomic<long> calls{0}, points{0};
    auto cb = rastrigin_callback(nullptr, nullptr);
    const auto scalar = cb.scalar;
    cb.scalar = {};
    cb.batch = [&, scalar](pride::MatrixView x, std::span<double> values) {
        REQUIRE(static_cast<std::size_t>(x.cols()) == values.size());
        ++calls;
        points += x.cols();
        for (Eigen::Index j = 0; j < x.cols(); ++j)
            values[static_cast<std::size_t>(j)] =
                scalar(std::span<const double>(x.col(j).data(), static_cast<std::size_t>(x.rows())));
    };
    const engine::Problem problem(cb);
    for (const char* name : {"pso", "ga", "ga-plus"}) {
        INFO(name);
        calls = 0;
        points = 0;
        const auto one = engine::run(algo(name), problem, budget(1000, 1), 3);
        const long one_calls = calls;
        CHECK(points == 1000);
        calls = 0;
        points = 0;
        check_same(one, engine::run(algo(name), problem, budget(1000, 3), 3));
        CHECK(points == 1000);         // every point once
        CHECK(calls > 2 * one_calls);  // each batch in three slices (one slice only when one point is left)
    }
}

TEST_CASE("threads: grid runs (line and free encodings, walk starts) give the same paths on 1, 2 and 4 threads",
          "[threads][grid]") {
    engine::GridSpec g;
    g.map = engine::load_map(example_map("zhang2025-20x20.map"));
    g.start = {0, 19};
    g.goal = {19, 0};
    for (const char* encoding : {"line", "free"}) {
        for (const char* init : {"uniform", "walk"}) {
            engine::GridSpec s = g;
            s.encoding = encoding;
            s.init = init;
            const engine::Problem problem(s);
            for (const char* name : {"pso", "ga", "ga-plus", "woa", "hswoa", "ilso"}) {
                INFO(encoding << " " << init << " " << name);
                engine::Budget b;
                b.iterations = 15;
                const auto one = engine::run(algo(name), problem, b, 11);
                for (const std::int64_t threads : {2, 4}) {
                    b.threads = threads;
                    check_same(one, engine::run(algo(name), problem, b, 11));
                }
            }
        }
    }
    // Whole-map algorithms and chains take the setting and run as they do on one thread.
    engine::GridSpec chain = g;
    chain.encoding = "chain";
    engine::Budget b;
    b.iterations = 5;
    const auto one = engine::run(algo("ga"), engine::Problem(chain), b, 2);
    b.threads = 2;
    check_same(one, engine::run(algo("ga"), engine::Problem(chain), b, 2));
    check_same(engine::run(algo("astar"), engine::Problem(g), budget(1, 1), 1),
               engine::run(algo("astar"), engine::Problem(g), budget(1, 4), 1));
}

TEST_CASE("threads: an exception in user code on a worker thread reaches the caller", "[threads][errors]") {
    auto cb = rastrigin_callback(nullptr, nullptr);
    std::atomic<int> count{0};
    cb.scalar = [&](std::span<const double> x) {
        if (++count == 70) throw std::runtime_error("user function failed");
        return x[0];
    };
    const engine::Problem problem(cb);
    CHECK_THROWS_WITH(engine::run(algo("pso"), problem, budget(1000, 4), 1), "user function failed");
    // The run after it is whole (no worker left waiting).
    count = 1000;
    CHECK(engine::run(algo("pso"), problem, budget(500, 4), 1).evaluations == 500);
}

TEST_CASE("threads: a pool evaluates batches smaller than its thread count", "[threads][framework]") {
    struct Square {
        std::vector<double> lo{-1.0, -1.0}, hi{1.0, 1.0};
        std::size_t dimension() const { return 2; }
        std::span<const double> lower() const { return lo; }
        std::span<const double> upper() const { return hi; }
        double evaluate(std::span<const double> x) { return x[0] * x[0] + x[1]; }
    };
    pride::ParallelBatch<Square> parallel(Square{}, 4);
    CHECK(parallel.threads() == 4);
    for (const Eigen::Index n : {1, 2, 3, 4, 5, 9}) {
        pride::Matrix x(2, n);
        for (Eigen::Index j = 0; j < n; ++j) x.col(j) << 0.1 * static_cast<double>(j), static_cast<double>(j);
        std::vector<double> values(static_cast<std::size_t>(n), -1.0);
        parallel.evaluate_batch(x, values);
        for (Eigen::Index j = 0; j < n; ++j)
            CHECK(values[static_cast<std::size_t>(j)] == Square{}.evaluate(pride::column(x, j)));
    }
}

TEST_CASE("threads: bad thread counts and callbacks not marked thread-safe are refused", "[threads][errors]") {
    const engine::Problem sphere(engine::ContinuousSpec{"sphere", 4});
    for (const std::int64_t bad : {0, -1, 257}) {
        INFO(bad);
        try {
            engine::check(algo("pso"), sphere, budget(100, bad));
            FAIL("accepted");
        } catch (const pride::InputError& e) {
            CHECK(e.where() == "threads");
            CHECK_THAT(e.detail(), Contains("[1, 256]"));
        }
    }
    CHECK(engine::run(algo("pso"), sphere, budget(100, 256), 1).evaluations == 100);
    auto cb = rastrigin_callback(nullptr, nullptr);
    cb.thread_safe = false;
    const engine::Problem unsafe(cb);
    CHECK(engine::run(algo("pso"), unsafe, budget(100, 1), 1).evaluations == 100);
    CHECK_THAT(input_error_message([&] { engine::run(algo("pso"), unsafe, budget(100, 2), 1); }),
               Contains("threads") && Contains("mine") && Contains("thread-safe"));

    for (const char* args : {"run --problem sphere --dim 3 --algo pso --evals 100 --threads 0",
                             "run --problem sphere --dim 3 --algo pso --evals 100 --threads 300",
                             "path --map MAP --start 0,0 --goal 9,9 --algo pso --iters 2 --threads -2"}) {
        std::string line = args;
        if (const auto at = line.find("MAP"); at != std::string::npos)
            line.replace(at, 3, "'" + example_map("wan2022-10x10.map") + "'");
        INFO(line);
        const auto r = pride::test::run_pride(line);
        CHECK(r.status == 2);
        CHECK_THAT(r.err, Contains("--threads") && Contains("[1, 256]"));
        CHECK(r.out.empty());
    }
    const auto ok = pride::test::run_pride("path --map '" + example_map("wan2022-10x10.map") +
                                           "' --start 0,0 --goal 9,9 --algo pso --iters 3 --threads 2");
    CHECK(ok.status == 0);

    const auto dir = std::filesystem::temp_directory_path() / "pride-test-threads";
    std::filesystem::create_directories(dir);
    const auto file = (dir / "threads.toml").string();
    auto campaign = [&](const std::string& threads) {
        std::ofstream(file) << "name = \"t\"\nseeds = 1\nthreads = " << threads
                            << "\n[budget]\nevaluations = 100\n[[problem]]\nid = \"s\"\ntype = \"sphere\"\ndim = 2\n"
                               "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\n";
    };
    campaign("3");
    CHECK(campaign::read_campaign(file).budget.threads == 3);
    for (const char* bad : {"0", "1000", "\"two\""}) {
        INFO(bad);
        campaign(bad);
        CHECK_THAT(input_error_message([&] { campaign::read_campaign(file); }), Contains("threads"));
    }
    std::filesystem::remove_all(dir);
}

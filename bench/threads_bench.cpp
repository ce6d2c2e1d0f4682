// Parallel evaluation inside one run: a user function that costs about 1 ms per
// evaluation (a fixed amount of arithmetic, calibrated once at start-up, so every evaluation does
// the same work on any thread; not a sleep, which would model waiting rather than computing),
// population 40, run through the engine at 1, 2, ... threads. Prints CSV
// `algo,threads,evaluations,wall_ms,speedup,same_result` (speed-up against 1 thread; same_result:
// best point, value and history bit-identical to 1 thread).
#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "engine/run.hpp"

namespace {

using namespace pride;

/// `steps` iterations of a dependent floating-point recurrence: a fixed amount of work the
/// compiler cannot remove or shorten.
double busy(std::int64_t steps, double seed) {
    double a = 1.0 + 1e-9 * seed;
    for (std::int64_t k = 0; k < steps; ++k) {
        a = a * 1.0000001 + 1e-7;
        asm volatile("" : "+x"(a));
    }
    return a;
}

/// Steps that take about `ms` milliseconds here (the median of 5 timings of 10^6 steps).
std::int64_t calibrate(double ms) {
    std::vector<double> per_step;
    for (int r = 0; r < 5; ++r) {
        const auto start = std::chrono::steady_clock::now();
        const double v = busy(1'000'000, 1.0);
        const double t = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        if (v == 42.0) fmt::print(stderr, " ");
        per_step.push_back(t / 1e6);
    }
    std::sort(per_step.begin(), per_step.end());
    return static_cast<std::int64_t>(ms / per_step[2]);
}

}  // namespace

int main(int argc, char** argv) {
    double ms = 1.0;
    std::int64_t evals = 800, max_threads = 2, dim = 10;
    std::vector<std::string> algos{"pso", "ga-plus"};
    CLI::App app{"parallel evaluation inside a run: a ~1 ms function, population 40, 1..N threads"};
    app.add_option("--ms", ms, "cost of one evaluation in ms (default 1)")->check(CLI::Range(0.001, 1000.0));
    app.add_option("--evals", evals, "evaluations per run (default 800)")->check(CLI::Range(40, 100000000));
    app.add_option("--threads", max_threads, "largest thread count (default 2)")->check(CLI::Range(1, 256));
    app.add_option("--algos", algos, "algorithms (default pso,ga-plus)")->delimiter(',');
    CLI11_PARSE(app, argc, argv);
    try {
        const std::int64_t steps = calibrate(ms);
        fmt::print(stderr, "{} steps per evaluation (about {} ms here)\n", steps, ms);
        engine::CallbackSpec cb;
        cb.name = "busy-sphere";
        cb.lower.assign(static_cast<std::size_t>(dim), -5.0);
        cb.upper.assign(static_cast<std::size_t>(dim), 5.0);
        cb.thread_safe = true;  // no shared state: each call works on its own locals
        cb.scalar = [steps](std::span<const double> x) {
            double f = 0.0;
            for (double v : x) f += v * v;
            const double w = busy(steps, x[0]);
            return f + (w > 0.0 ? 0.0 : 1.0);  // the work decides nothing, but is needed
        };
        const engine::Problem problem(cb);
        fmt::print("algo,threads,evaluations,wall_ms,speedup,same_result\n");
        for (const auto& name : algos) {
            engine::AlgorithmSpec a{name, {}};
            a.params.set("pop", 40.0);
            engine::RunResult one;
            for (std::int64_t t = 1; t <= max_threads; ++t) {
                engine::Budget b;
                b.evaluations = evals;
                b.threads = t;
                const auto r = engine::run(a, problem, b, 1);
                if (t == 1) one = r;
                const bool same = r.best_x == one.best_x && r.best_f == one.best_f && r.history == one.history;
                fmt::print("{},{},{},{:.1f},{:.3f},{}\n", name, t, r.evaluations, r.wall_ms, one.wall_ms / r.wall_ms,
                           same ? "yes" : "NO");
            }
        }
    } catch (const std::exception& e) {
        fmt::print(stderr, "threads_bench: {}\n", e.what());
        return 2;
    }
    return 0;
}

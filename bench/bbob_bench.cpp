// BBOB f1-f24 evaluation cost, pride's two routes.
//
// The same points (uniform in [-5, 5]^D, seed 7) go to pride's catalog Function point by point
// (scalar: one dispatch per call) and as one matrix (batch). Each is timed as the least of 7
// timings of about 20 ms, in ns per evaluation; the points stay in cache.
//
// Output: CSV on stdout, one row per (function, D).
#include <cstdio>
#include <vector>

#include <fmt/core.h>
#include <CLI/CLI.hpp>

#include "framework/problem.hpp"
#include "framework/random.hpp"
#include "problems/continuous/catalog.hpp"

#include "bench/best_time.hpp"

namespace {

using pride::Matrix;
using pride::bench::best_ns;

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"BBOB f1-f24: ns per evaluation of pride's scalar and batch routes"};
    std::vector<int> dims{2, 10, 40};
    std::vector<int> functions;
    long points = 1000;
    int instance = 1;
    app.add_option("--dims", dims, "dimensions")->capture_default_str();
    app.add_option("--functions", functions, "BBOB function numbers (default 1-24)");
    app.add_option("--points", points, "points per dimension")->check(CLI::Range(1L, 100000L))->capture_default_str();
    app.add_option("--instance", instance, "the BBOB instance number")
        ->check(CLI::Range(1, 100))
        ->capture_default_str();
    CLI11_PARSE(app, argc, argv);
    if (functions.empty())
        for (int f = 1; f <= 24; ++f) functions.push_back(f);
    for (const int d : dims)
        if (d < 2 || d > 640) {
            fmt::print(stderr, "bbob_bench: --dims {} is not in [2, 640]\n", d);
            return 2;
        }
    for (const int f : functions)
        if (f < 1 || f > 24) {
            fmt::print(stderr, "bbob_bench: --functions {} is not in [1, 24]\n", f);
            return 2;
        }

    fmt::print("function,dim,scalar_ns,batch_ns\n");
    double sink = 0.0;
    for (const int dim : dims) {
        pride::Rng rng(7);
        Matrix x(dim, points);
        for (Eigen::Index j = 0; j < x.cols(); ++j)
            for (Eigen::Index i = 0; i < x.rows(); ++i) x(i, j) = rng.uniform(-5.0, 5.0);
        std::vector<double> values(static_cast<std::size_t>(points));

        for (const int id : functions) {
            auto f = pride::continuous::make_function(fmt::format("bbob-f{}", id), dim, instance);
            const double scalar = best_ns(
                [&] {
                    for (Eigen::Index j = 0; j < x.cols(); ++j) {
                        double v = f.evaluate(pride::column(x, j));
                        asm volatile("" : "+x"(v) : : "memory");
                        sink += v;
                    }
                },
                points);
            const double batch = best_ns(
                [&] {
                    f.evaluate_batch(x, values);
                    asm volatile("" : : "r"(values.data()) : "memory");
                    sink += values[0];
                },
                points);
            fmt::print("f{},{},{:.2f},{:.2f}\n", id, dim, scalar, batch);
            std::fflush(stdout);
        }
    }
    if (sink == 42.0) std::fputs("", stderr);
    return 0;
}

// BBOB f1-f24 evaluation cost, pride's two routes beside the references in one process.
//
// The same points (uniform in [-5, 5]^D, seed 7) go to pride's catalog Function point by point
// (scalar: one dispatch per call) and as one matrix (batch), and, when the build was given their
// sources, to COCO's C code (coco_evaluate_function; its amalgamated coco.c, -DPRIDE_COCO_DIR=) and
// to IOHexperimenter's C++ classes (operator(); its include/ folder, -DPRIDE_IOH_INCLUDE=). Each is
// timed as the least of 7 timings of about 20 ms, in ns per evaluation; the points stay in cache.
// `same_as_coco` counts the points where pride's value has COCO's bits; `ioh_max_rel` is the
// largest relative difference from IOHexperimenter's (which does not promise COCO's bits).
//
// Output: CSV on stdout, one row per (function, D).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <fmt/core.h>
#include <CLI/CLI.hpp>

#include "framework/problem.hpp"
#include "framework/random.hpp"
#include "problems/continuous/catalog.hpp"

#include "bench/bbob_bench_references.hpp"
#include "bench/best_time.hpp"

namespace {

using pride::Matrix;
using pride::bench::best_ns;

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"BBOB f1-f24: ns per evaluation of pride's scalar and batch routes beside COCO and IOHexperimenter"};
    std::vector<int> dims{2, 10, 40};
    std::vector<int> functions;
    long points = 1000;
    int instance = 1;
    app.add_option("--dims", dims, "dimensions")->capture_default_str();
    app.add_option("--functions", functions, "BBOB function numbers (default 1-24)");
    app.add_option("--points", points, "points per dimension")->check(CLI::Range(1L, 100000L))->capture_default_str();
    app.add_option("--instance", instance, "COCO's instance number")->check(CLI::Range(1, 100))->capture_default_str();
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

    fmt::print("function,dim,scalar_ns,batch_ns,coco_ns,ioh_ns,same_as_coco,ioh_max_rel\n");
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
            f.evaluate_batch(x, values);

            std::string coco_ns = "", same = "", ioh_ns = "", ioh_rel = "";
            std::vector<double> reference(values.size());
            if (const double ns = pride::bench::coco_ns(id, instance, dim, x.data(), points, reference.data());
                ns > 0) {
                coco_ns = fmt::format("{:.2f}", ns);
                long equal = 0;
                for (std::size_t j = 0; j < values.size(); ++j) equal += reference[j] == values[j] ? 1 : 0;
                same = fmt::format("{}/{}", equal, points);
            }
            if (const double ns = pride::bench::ioh_ns(id, instance, dim, x.data(), points, reference.data()); ns > 0) {
                ioh_ns = fmt::format("{:.2f}", ns);
                double rel = 0.0;
                for (std::size_t j = 0; j < values.size(); ++j)
                    rel = std::max(rel, std::fabs(reference[j] - values[j]) / std::max(1.0, std::fabs(values[j])));
                ioh_rel = fmt::format("{:.3g}", rel);
            }
            fmt::print("f{},{},{:.2f},{:.2f},{},{},{},{}\n", id, dim, scalar, batch, coco_ns, ioh_ns, same, ioh_rel);
            std::fflush(stdout);
        }
    }
    if (sink == 42.0) std::fputs("", stderr);
    return 0;
}

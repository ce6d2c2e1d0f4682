// Scalar evaluate() against evaluate_batch() for the functions that have a batch form: one
// population of 50 uniform points in the box (D = 10 and 40), evaluated over and over.
//
// stdout: CSV `function,dim,scalar_ns,batch_ns,speedup`, ns per evaluation, the best of 7 timings
// of about 2 million evaluations each (the population stays in cache, as in a run). The batch
// values are checked to equal the scalar ones bit for bit.
#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <span>
#include <string_view>
#include <vector>

#include "framework/problem.hpp"
#include "framework/random.hpp"
#include "problems/continuous/extras.hpp"
#include "problems/continuous/functions.hpp"
#include "problems/continuous/yao.hpp"

namespace {

constexpr Eigen::Index kPopulation = 50;
constexpr int kRepeats = 7;
constexpr long kEvaluations = 2'000'000;

template <class Fn>
double best_ns_per_eval(Fn&& pass, double& sink) {
    const long passes = kEvaluations / kPopulation;
    double best = 1e300;
    for (int r = 0; r < kRepeats; ++r) {
        const auto t0 = std::chrono::steady_clock::now();
        for (long p = 0; p < passes; ++p) sink += pass();
        const auto t1 = std::chrono::steady_clock::now();
        best = std::min(best, std::chrono::duration<double, std::nano>(t1 - t0).count() /
                                  static_cast<double>(passes * kPopulation));
    }
    return best;
}

template <class F>
void bench(std::size_t dim, double& sink) {
    const F f(dim);
    pride::Rng rng(42);
    pride::Matrix points(static_cast<Eigen::Index>(dim), kPopulation);
    for (Eigen::Index j = 0; j < kPopulation; ++j)
        for (Eigen::Index i = 0; i < points.rows(); ++i)
            points(i, j) = rng.uniform(f.lower()[static_cast<std::size_t>(i)], f.upper()[static_cast<std::size_t>(i)]);
    std::vector<double> scalar(kPopulation), batch(kPopulation);

    const double scalar_ns = best_ns_per_eval(
        [&] {
            for (Eigen::Index j = 0; j < kPopulation; ++j)
                scalar[static_cast<std::size_t>(j)] = f.evaluate(pride::column(points, j));
            return scalar[0];
        },
        sink);
    const double batch_ns = best_ns_per_eval(
        [&] {
            f.evaluate_batch(points, batch);
            return batch[0];
        },
        sink);
    for (std::size_t j = 0; j < scalar.size(); ++j)
        if (std::bit_cast<std::uint64_t>(scalar[j]) != std::bit_cast<std::uint64_t>(batch[j])) {
            std::fprintf(stderr, "%s: batch differs from scalar in column %zu\n", F::info.name.data(), j);
            std::exit(1);
        }
    fmt::print("{},{},{:.2f},{:.2f},{:.2f}\n", F::info.name, dim, scalar_ns, batch_ns, scalar_ns / batch_ns);
}

}  // namespace

int main() {
    double sink = 0.0;
    fmt::print("function,dim,scalar_ns,batch_ns,speedup\n");
    for (std::size_t dim : {10, 40}) {
        bench<pride::continuous::Sphere>(dim, sink);
        bench<pride::continuous::Rastrigin>(dim, sink);
        bench<pride::continuous::Schwefel222>(dim, sink);
        bench<pride::continuous::Schwefel221>(dim, sink);
        bench<pride::continuous::Step>(dim, sink);
        bench<pride::continuous::Ellipsoid>(dim, sink);
    }
    std::fprintf(stderr, "(checksum %g)\n", sink);
}

// Scalar evaluate() against the row-by-row batch kernel (problems/continuous/batch.hpp) for the
// sum-like functions: one population of 50 uniform points in the box (D = 10 and 40), evaluated
// over and over. A function's own evaluate_batch() is timed when it has one (Schwefel 2.21, the
// ellipsoid); for the others the same kernel is written out here, which is how they were measured
// and found not to pay (so they have no batch form).
//
// stdout: CSV `function,dim,scalar_ns,batch_ns,speedup`, ns per evaluation, the best of 7 timings
// of about 2 million evaluations each (the population stays in cache, as in a run). The batch
// values are checked to equal the scalar ones bit for bit.
#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <numbers>
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

template <class F, class Batch>
void bench(std::size_t dim, Batch batch_form, double& sink) {
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
            batch_form(f, points, batch);
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

namespace pc = pride::continuous;
using Eigen::Index;

// The class's own batch form.
constexpr auto own = [](const auto& f, pride::MatrixView points, std::span<double> values) {
    f.evaluate_batch(points, values);
};
// The kernel for the functions without one, in the scalar loops' order (checked bit for bit).
constexpr auto sphere_rows = [](const auto&, pride::MatrixView points, std::span<double> values) {
    pc::accumulate_rows(points, values, 0.0, [](auto& f, const auto& v, Index) { f += v * v; });
};
constexpr auto rastrigin_rows = [](const auto&, pride::MatrixView points, std::span<double> values) {
    constexpr double omega = 2.0 * std::numbers::pi;
    pc::accumulate_rows(points, values, 10.0 * static_cast<double>(points.rows()), [](auto& f, const auto& v, Index) {
        f += v * v - 10.0 * v.unaryExpr([](double t) { return std::cos(omega * t); });
    });
};
constexpr auto schwefel222_rows = [](const auto&, pride::MatrixView points, std::span<double> values) {
    Eigen::ArrayXd p = Eigen::ArrayXd::Ones(points.cols());
    Eigen::Map<Eigen::ArrayXd> s(values.data(), points.cols());
    s.setZero();
    for (Index i = 0; i < points.rows(); ++i) {
        const auto a = points.row(i).transpose().array().abs();
        s += a;
        p *= a;
    }
    s += p;
};
constexpr auto step_rows = [](const auto&, pride::MatrixView points, std::span<double> values) {
    pc::accumulate_rows(points, values, 0.0, [](auto& f, const auto& v, Index) { f += (v + 0.5).floor().square(); });
};

}  // namespace

int main() {
    double sink = 0.0;
    fmt::print("function,dim,scalar_ns,batch_ns,speedup\n");
    for (std::size_t dim : {10, 40}) {
        bench<pc::Sphere>(dim, sphere_rows, sink);
        bench<pc::Rastrigin>(dim, rastrigin_rows, sink);
        bench<pc::Schwefel222>(dim, schwefel222_rows, sink);
        bench<pc::Schwefel221>(dim, own, sink);
        bench<pc::Step>(dim, step_rows, sink);
        bench<pc::Ellipsoid>(dim, own, sink);
    }
    std::fprintf(stderr, "(checksum %g)\n", sink);
}

#pragma once
// What the three parts of bench/mo_bench share: the settings, the rows of results, the reference
// fronts and the measurements (bare time of recorded points, quality against a front).
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "framework/pareto/hypervolume.hpp"
#include "framework/pareto/indicators.hpp"
#include "framework/problem.hpp"

namespace pride::mo_bench {

using Clock = std::chrono::steady_clock;
inline constexpr std::int64_t kPopulation = 100;

struct Settings {
    std::int64_t evals = 25000;
    std::int64_t seeds = 10;
    bool pagmo = true;
    std::vector<std::string> algos{"nsga2", "moead", "smsemoa", "nsga3"};
    bool wanted(const std::string& a) const { return std::find(algos.begin(), algos.end(), a) != algos.end(); }
};

struct Row {
    std::string algo, problem;
    std::int64_t seed = 0, fevals = 0;
    double wall_ms = 0.0, bare_ms = 0.0;
    Eigen::Index points = 0;
    double hv_ratio = 0.0, igd_plus = 0.0;
};

/// Every run's row, in the order the runs were made.
inline std::vector<Row> rows;

struct Reference {
    Matrix front;
    std::vector<double> point;
    double hv = 0.0;
};

inline Reference reference_of(const Matrix& front) {
    Reference r{front, std::vector<double>(static_cast<std::size_t>(front.rows())), 0.0};
    for (Eigen::Index i = 0; i < front.rows(); ++i)
        r.point[static_cast<std::size_t>(i)] = 1.1 * front.row(i).maxCoeff();
    r.hv = pareto::hypervolume(front, r.point);
    return r;
}

/// The reference fronts of the seven problems, by name.
struct References {
    Reference zdt1, zdt2, zdt3, zdt4, zdt6, dtlz1, dtlz2;
};

/// The time, in ms, of evaluating `points` (`dim` each) with `evaluate`, in chunks of a population
/// read once untimed first (in cache, as the run's own evaluations were).
template <class Evaluate>
double bare_ms(Evaluate evaluate, const std::vector<double>& points, std::size_t dim) {
    double total = 0.0, sink = 0.0;
    const std::size_t n = points.size() / dim, chunk = static_cast<std::size_t>(kPopulation);
    for (std::size_t first = 0; first < n; first += chunk) {
        const std::size_t last = std::min(n, first + chunk);
        for (std::size_t k = first * dim; k < last * dim; ++k) sink += points[k];
        const auto start = Clock::now();
        for (std::size_t j = first; j < last; ++j) {
            double v = evaluate(points.data() + j * dim);
            asm volatile("" : "+x"(v) : : "memory");
            sink += v;
        }
        total += std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    }
    if (sink == 42.0) std::fputs("", stderr);
    return total;
}

/// Quality of a set of objective vectors (columns) against the reference front.
inline std::pair<double, double> quality(const Matrix& f, const Reference& ref) {
    return {pareto::hypervolume(f, ref.point) / ref.hv, pareto::igd_plus(f, ref.front)};
}

/// pride's algorithms on the ZDT problems and on the DTLZ ones (mo_bench_pride.cpp).
void bench_pride_zdt(const Settings& s, const References& r);
void bench_pride_dtlz(const Settings& s, const References& r);
/// pagmo2's nsga2 and moead on the same problems (mo_bench_pagmo.cpp; built with pagmo only).
void bench_pagmo_all_problems(const Settings& s, const References& r);

}  // namespace pride::mo_bench

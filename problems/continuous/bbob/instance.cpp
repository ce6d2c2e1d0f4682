// COCO's legacy instance generators (suite_bbob_legacy_code.c, f_gallagher.c), rewritten; the
// arithmetic follows COCO's order so that every x_opt, f_opt and matrix entry is bit-identical.
#include "problems/continuous/bbob/instance.hpp"

#include "problems/continuous/instance.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <string>

#include "framework/error.hpp"

namespace pride::continuous::bbob {

void check_arguments(std::string_view name, std::size_t dim, std::int64_t instance) {
    const std::string where(name);
    require(dim >= 2, where, "dimension must be >= 2, got " + std::to_string(dim));
    require(instance >= 1, where,
            "instance must be >= 1 (COCO numbers instances from 1), got " + std::to_string(instance));
    require(instance <= kMaxInstance, where, instance_range_message(name, instance));
}

std::string instance_range_message(std::string_view name, std::int64_t instance) {
    return std::string(name) + ": COCO's instances are 1 to " + std::to_string(kMaxInstance) +
           " (its generator works modulo 2^31 - 1: a larger one would repeat a smaller one), got " +
           std::to_string(instance);
}

std::int64_t instance_seed(int function, std::int64_t instance) {
    const int base = function == 4 ? 3 : function == 18 ? 17 : function;
    return base + 10000 * instance;
}

namespace {

// One step of Park-Miller's minimal standard generator by Schrage's method, as COCO writes it
// (the quotient through floor of a double division).
std::int64_t park_miller(std::int64_t s) {
    const auto q = static_cast<std::int64_t>(std::floor(static_cast<double>(s) / 127773.0));
    s = 16807 * (s - q * 127773) - 2836 * q;
    return s < 0 ? s + 2147483647 : s;
}

}  // namespace

std::vector<double> uniform(std::size_t n, std::int64_t seed) {
    if (seed < 0) seed = -seed;
    if (seed < 1) seed = 1;
    std::int64_t state = seed;
    std::int64_t table[32];
    // 40 warm-up steps; the last 32 fill the shuffle table from the top down.
    for (int i = 39; i >= 0; --i) {
        state = park_miller(state);
        if (i < 32) table[i] = state;
    }
    std::int64_t current = table[0];
    std::vector<double> r(n);
    for (std::size_t i = 0; i < n; ++i) {
        state = park_miller(state);
        const auto slot = static_cast<std::size_t>(std::floor(static_cast<double>(current) / 67108865.0));
        current = table[slot];
        table[slot] = state;
        r[i] = static_cast<double>(current) / 2.147483647e9;
        if (r[i] == 0.0) r[i] = 1e-99;  // log(u) in gauss() must stay finite
    }
    return r;
}

std::vector<double> gauss(std::size_t n, std::int64_t seed) {
    const std::vector<double> u = uniform(2 * n, seed);
    std::vector<double> g(n);
    for (std::size_t i = 0; i < n; ++i) {
        g[i] = std::sqrt(-2.0 * std::log(u[i])) * std::cos(2.0 * std::numbers::pi * u[n + i]);
        if (g[i] == 0.0) g[i] = 1e-99;
    }
    return g;
}

std::vector<double> compute_xopt(std::size_t dim, std::int64_t seed) {
    std::vector<double> x = uniform(dim, seed);
    for (double& v : x) {
        v = 8.0 * std::floor(1e4 * v) / 1e4 - 4.0;
        if (v == 0.0) v = -1e-5;  // keeps the sign-dependent functions (f5, f6) well defined
    }
    return x;
}

double compute_fopt(int function, std::int64_t instance) {
    const int base = function == 4 ? 3 : function == 18 ? 17 : function;
    const std::int64_t seed = base + 10000 * instance;
    const double g1 = gauss(1, seed)[0];
    const double g2 = gauss(1, seed + 1)[0];
    const double rounded = std::floor(100.0 * 100.0 * g1 / g2 + 0.5) / 100.0;
    return std::min(1000.0, std::max(-1000.0, rounded));
}

RowMatrix compute_rotation(std::size_t dim, std::int64_t seed) {
    require_rotation_size(dim);
    const std::vector<double> g = gauss(dim * dim, seed);
    const auto n = static_cast<Eigen::Index>(dim);
    // Classical Gram-Schmidt on the columns, column by column, as COCO does it, the same operations
    // in the same order; the columns are held as rows of `c` so that each loop over k reads
    // consecutive memory (on a row-major b they were strided: 12.7 s at dimension 2000 against
    // 3 s now).
    RowMatrix c(n, n);
    for (Eigen::Index i = 0; i < n; ++i)
        for (Eigen::Index j = 0; j < n; ++j) c(j, i) = g[static_cast<std::size_t>(j * n + i)];
    for (Eigen::Index i = 0; i < n; ++i) {
        double* const ci = c.row(i).data();
        for (Eigen::Index j = 0; j < i; ++j) {
            const double* const cj = c.row(j).data();
            double prod = 0.0;
            for (Eigen::Index k = 0; k < n; ++k) prod += ci[k] * cj[k];
            for (Eigen::Index k = 0; k < n; ++k) ci[k] -= prod * cj[k];
        }
        double prod = 0.0;
        for (Eigen::Index k = 0; k < n; ++k) prod += ci[k] * ci[k];
        for (Eigen::Index k = 0; k < n; ++k) ci[k] /= std::sqrt(prod);
    }
    return c.transpose();
}

RowMatrix scaled_product(const RowMatrix& r, const std::vector<double>& scale, const RowMatrix& q) {
    const Eigen::Index n = r.rows();
    RowMatrix m(n, n);
    for (Eigen::Index i = 0; i < n; ++i)
        for (Eigen::Index j = 0; j < n; ++j) {
            double sum = 0.0;
            for (Eigen::Index k = 0; k < n; ++k) sum += r(i, k) * scale[static_cast<std::size_t>(k)] * q(k, j);
            m(i, j) = sum;
        }
    return m;
}

std::vector<double> power_ramp(double base, std::size_t dim) {
    std::vector<double> v(dim);
    for (std::size_t i = 0; i < dim; ++i)
        v[i] = std::pow(base, static_cast<double>(i) / (static_cast<double>(dim) - 1.0));
    return v;
}

namespace {

// Indices 0..n-1 ordered by their random number (COCO's qsort of (value, index) pairs; ties have
// probability zero).
std::vector<std::size_t> ranked_indices(const std::vector<double>& values, std::size_t n) {
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
    return order;
}

}  // namespace

GallagherPeaks make_gallagher_peaks(std::size_t dim, std::size_t peaks, std::int64_t seed) {
    // f21: y in [-5, 5]^D, condition numbers up to 1000 with sqrt(1000) for the global peak;
    // f22: y in [-4.9, 4.9]^D, condition up to 1000 for all peaks.
    const bool many = peaks == 101;
    const double max_condition = 1000.0;
    const double first_condition = many ? std::sqrt(max_condition) : max_condition;
    const double b = many ? 10.0 : 9.8;
    const double c = many ? 5.0 : 4.9;
    const double lowest_height = 1.1, highest_height = 9.1;
    const double best_scale = 0.8;  // the global peak's y_1 lies in [-4, 4]^D

    GallagherPeaks g;
    g.rotation = compute_rotation(dim, seed);

    const std::vector<std::size_t> peak_order = ranked_indices(uniform(peaks - 1, seed), peaks - 1);
    std::vector<double> condition(peaks);
    g.heights.assign(peaks, 0.0);
    condition[0] = first_condition;
    g.heights[0] = 10.0;
    for (std::size_t i = 1; i < peaks; ++i) {
        condition[i] = std::pow(max_condition, static_cast<double>(peak_order[i - 1]) / static_cast<double>(peaks - 2));
        g.heights[i] = static_cast<double>(i - 1) / static_cast<double>(peaks - 2) * (highest_height - lowest_height) +
                       lowest_height;
    }

    const auto n = static_cast<Eigen::Index>(dim);
    const auto np = static_cast<Eigen::Index>(peaks);
    g.scales.resize(np, n);
    for (std::size_t i = 0; i < peaks; ++i) {
        const std::vector<std::size_t> order =
            ranked_indices(uniform(dim, seed + static_cast<std::int64_t>(1000 * i)), dim);
        for (std::size_t j = 0; j < dim; ++j)
            g.scales(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) =
                std::pow(condition[i], static_cast<double>(order[j]) / static_cast<double>(dim - 1) - 0.5);
    }

    const std::vector<double> u = uniform(dim * peaks, seed);
    g.best.resize(dim);
    g.local.resize(np, n);
    for (std::size_t i = 0; i < dim; ++i) {
        g.best[i] = best_scale * (b * u[i] - c);
        for (std::size_t j = 0; j < peaks; ++j) {
            double sum = 0.0;
            for (std::size_t k = 0; k < dim; ++k)
                sum +=
                    g.rotation(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)) * (b * u[j * dim + k] - c);
            if (j == 0) sum *= best_scale;
            g.local(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(i)) = sum;
        }
    }
    return g;
}

}  // namespace pride::continuous::bbob

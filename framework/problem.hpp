#pragma once
// The problem concept: what every algorithm searching a box of reals needs to know of a problem.
// Evaluation is a non-const member so that a problem may keep scratch buffers (a decoder's path,
// say); an algorithm therefore owns its own copy of the problem for the length of one run.
#include <Eigen/Core>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "framework/random.hpp"

namespace pride {

/// A population or any set of points: one column per point (contiguous), one row per coordinate.
using Matrix = Eigen::MatrixXd;
/// A read-only view of some columns of a Matrix (a whole population or its first k members).
using MatrixView = Eigen::Ref<const Matrix>;

/// Column i of a population as a span (columns are contiguous).
inline std::span<double> column(Matrix& m, Eigen::Index i) {
    return {m.col(i).data(), static_cast<std::size_t>(m.rows())};
}
inline std::span<const double> column(const Matrix& m, Eigen::Index i) {
    return {m.col(i).data(), static_cast<std::size_t>(m.rows())};
}

template <class P>
concept BoxProblem = std::copy_constructible<P> && requires(P& p, const P& cp, std::span<const double> x) {
    { cp.dimension() } -> std::convertible_to<std::size_t>;
    { cp.lower() } -> std::convertible_to<std::span<const double>>;
    { cp.upper() } -> std::convertible_to<std::span<const double>>;
    { p.evaluate(x) } -> std::convertible_to<double>;
};

/// Optional: evaluates the columns of `points` into `values` in one call (vectorised or parallel
/// problems). The evaluation guard uses it when present and counts every column.
template <class P>
concept BatchBoxProblem = BoxProblem<P> && requires(P& p, MatrixView points, std::span<double> values) {
    p.evaluate_batch(points, values);
};

/// Optional: the problem proposes starting points (the grid problem proposes genotypes read off
/// feasible walks). Initialisers that accept suggestions use it; algorithms never ask directly.
template <class P>
concept SuggestsStartingPoints = BoxProblem<P> && requires(const P& p, Rng& rng, Matrix& out) {
    p.starting_points(rng, out);  // fills every column of `out` (rows = dimension)
};

/// Optional: a problem with noise (a noisy test function) restarts its noise from the run's seed,
/// so that a run is reproducible from its seed alone. Every algorithm calls seed_noise() once
/// on its own copy of the problem before the first evaluation.
template <class P>
concept Reseedable = requires(P& p, std::uint64_t seed) { p.reseed(seed); };

template <class P>
void seed_noise(P& problem, std::uint64_t seed) noexcept {
    if constexpr (Reseedable<P>) problem.reseed(seed);
}

/// Optional: a name for logs and the command line.
template <class P>
concept Named = requires(const P& p) {
    { p.name() } -> std::convertible_to<std::string_view>;
};

}  // namespace pride

#pragma once
// Instances of a scalable function, as in COCO and IOHprofiler: a problem is (function, instance,
// dimension). Instance 0 is the function as defined. Instance k >= 1 is
//
//     f_k(x) = F(x* + R_k (x - o_k)),
//
// whose optimum is at o_k with F's optimum value: o_k is drawn from seed k inside the box, away
// from its centre and from its bounds (each coordinate at 20 % to 80 % of the half-width from the
// centre, either side), and R_k is a uniformly distributed orthogonal matrix drawn from seed k (QR
// of a Gaussian matrix, each column of Q multiplied by the sign of R's diagonal entry: Mezzadri
// 2007, "How to generate random matrices from the classical compact groups", section 5). Both come
// from pride's own generator (framework/random.hpp), so instance k is the same on every machine,
// run and thread.
//
// The `shifted-*` problems are the same transform with R = I and the golden-ratio shift of
// shift_optimum() below, kept so that their values do not change.
//
// Functions whose formula falls below its optimum outside the box (bounded_domain: Schwefel's sine
// functions) would gain spurious optima once a rotation carries the argument out of it; for them
// the argument is clamped to the box and the squared distance it was moved is added, so the only
// optimum stays at o_k.
#include <Eigen/Core>
#include <Eigen/QR>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "framework/error.hpp"
#include "framework/random.hpp"

namespace pride::continuous {

/// The fixed shift of the `shifted-*` problems: with phi = (sqrt(5) - 1) / 2 and frac() the
/// fractional part, o_i = low + (high - low) * (0.1 + 0.8 * frac((i + 1) * phi)), i = 0..n-1 (a
/// golden-ratio sequence over the middle 80 % of each interval, never on the centre line).
inline std::vector<double> shift_optimum(std::size_t dim, double lower, double upper) {
    constexpr double phi = 0.6180339887498949;
    std::vector<double> o(dim);
    for (std::size_t i = 0; i < dim; ++i) {
        const double t = static_cast<double>(i + 1) * phi;
        o[i] = lower + (upper - lower) * (0.1 + 0.8 * (t - std::floor(t)));
    }
    return o;
}

/// z = x* + R (x - o), with R = I when `rotation` is empty.
struct Transform {
    std::vector<double> shift;   // o: where the optimum moves
    std::vector<double> anchor;  // x*: the function's own optimum
    Eigen::MatrixXd rotation;    // R (orthogonal), or 0 x 0 for none
    // bounded_domain: F's box, to clamp the argument into
    std::vector<double> clamp_lower, clamp_upper;

    bool rotates() const noexcept { return rotation.size() > 0; }

    /// z from x; `diff` is scratch of the dimension (no allocation). Returns the penalty to add
    /// (0 unless the argument was clamped).
    double apply(std::span<const double> x, std::span<double> z, Eigen::VectorXd& diff) const {
        const std::size_t n = x.size();
        if (!rotates()) {
            for (std::size_t i = 0; i < n; ++i) z[i] = anchor[i] + (x[i] - shift[i]);
        } else {
            for (std::size_t i = 0; i < n; ++i) diff[static_cast<Eigen::Index>(i)] = x[i] - shift[i];
            Eigen::Map<Eigen::VectorXd> out(z.data(), static_cast<Eigen::Index>(n));
            out.noalias() = rotation * diff;
            for (std::size_t i = 0; i < n; ++i) z[i] += anchor[i];
        }
        if (clamp_lower.empty()) return 0.0;
        double penalty = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            const double c = std::min(std::max(z[i], clamp_lower[i]), clamp_upper[i]);
            penalty += (z[i] - c) * (z[i] - c);
            z[i] = c;
        }
        return penalty;
    }
};

/// The largest dimension of a rotated instance. A rotation is built in O(n^3) time (COCO's
/// Gram-Schmidt, or a QR), which no memory check bounds: about 4 s at n = 2000, a minute at 5000
/// and 5 minutes at 8000 on the 2-core test machine, so that a small number on the command line
/// could start hours of work. Instances without a rotation take any dimension.
inline constexpr std::size_t kMaxRotatedDimension = 5000;

/// InputError("dim", ...) when a rotation of size n is beyond kMaxRotatedDimension.
inline void require_rotation_size(std::size_t n) {
    require(n <= kMaxRotatedDimension, "dim",
            "a rotated instance is built up to dimension " + std::to_string(kMaxRotatedDimension) +
                " (its rotation costs dimension^3 time and dimension^2 memory), got " + std::to_string(n) +
                "; instances without one (instance 0 of the classic functions, bbob-f1 to f5) take any dimension");
}

/// R_k: a uniformly distributed orthogonal n x n matrix drawn from seed k.
inline Eigen::MatrixXd random_rotation(std::size_t n, std::uint64_t instance) {
    require_rotation_size(n);
    Rng rng(instance, 0x726f74 /* "rot" */);
    const auto m = static_cast<Eigen::Index>(n);
    Eigen::MatrixXd g(m, m);
    for (Eigen::Index j = 0; j < m; ++j)
        for (Eigen::Index i = 0; i < m; ++i) g(i, j) = rng.normal();
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(g);
    Eigen::MatrixXd q = qr.householderQ();
    const Eigen::MatrixXd& r = qr.matrixQR();  // R is its upper triangle
    for (Eigen::Index j = 0; j < m; ++j)
        if (r(j, j) < 0.0) q.col(j) = -q.col(j);
    return q;
}

/// o_k: each coordinate at 20 % to 80 % of the half-width from the box's centre, either side.
inline std::vector<double> random_shift(std::span<const double> lower, std::span<const double> upper,
                                        std::uint64_t instance) {
    Rng rng(instance, 0x7368696674 /* "shift" */);
    std::vector<double> o(lower.size());
    for (std::size_t i = 0; i < o.size(); ++i) {
        const double centre = 0.5 * (lower[i] + upper[i]), half = 0.5 * (upper[i] - lower[i]);
        const double side = rng.bernoulli(0.5) ? 1.0 : -1.0;
        o[i] = centre + side * half * rng.uniform(0.2, 0.8);
    }
    return o;
}

/// Instance k >= 1 of a function with box [lower, upper] and optimum `anchor`.
inline Transform instance_transform(std::span<const double> lower, std::span<const double> upper,
                                    std::vector<double> anchor, std::uint64_t instance, bool bounded_domain) {
    Transform t;
    t.shift = random_shift(lower, upper, instance);
    t.anchor = std::move(anchor);
    t.rotation = random_rotation(lower.size(), instance);
    if (bounded_domain) {
        t.clamp_lower.assign(lower.begin(), lower.end());
        t.clamp_upper.assign(upper.begin(), upper.end());
    }
    return t;
}

}  // namespace pride::continuous

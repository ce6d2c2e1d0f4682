#pragma once
// The transformations shared by the BBOB functions (Hansen, Finck, Ros, Auger 2009, INRIA RR-6829,
// section 0.2), each in the floating-point form of the COCO file named beside it so that values
// match COCO's to the last bit or nearly. They write into caller-provided buffers: evaluate()
// must not allocate.
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

#include "problems/continuous/bbob/instance.hpp"

namespace pride::continuous::bbob {

/// T_osz of one coordinate (transform_vars_oscillate.c; transform_obj_oscillate.c is the same map).
inline double tosz(double x) noexcept {
    if (x > 0.0) {
        const double t = std::log(x) / 0.1;
        return std::pow(std::exp(t + 0.49 * (std::sin(t) + std::sin(0.79 * t))), 0.1);
    }
    if (x < 0.0) {
        const double t = std::log(-x) / 0.1;
        return -std::pow(std::exp(t + 0.49 * (std::sin(0.55 * t) + std::sin(0.31 * t))), 0.1);
    }
    return 0.0;
}

/// T_osz on every coordinate, in place.
inline void tosz(std::span<double> x) noexcept {
    for (double& v : x) v = tosz(v);
}

/// T_asy^beta in place (transform_vars_asymmetric.c): x_i^(1 + beta i/(D-1) sqrt(x_i)) where x_i > 0.
inline void tasy(std::span<double> x, double beta) noexcept {
    const double last = static_cast<double>(x.size()) - 1.0;
    for (std::size_t i = 0; i < x.size(); ++i)
        if (x[i] > 0.0) x[i] = std::pow(x[i], 1.0 + ((beta * static_cast<double>(i)) / last) * std::sqrt(x[i]));
}

/// f_pen = sum max(0, |x_i| - 5)^2 (transform_obj_penalize.c and the functions that inline it).
inline double boundary_penalty(std::span<const double> x) noexcept {
    double penalty = 0.0;
    for (double v : x) {
        const double excess = std::fabs(v) - 5.0;
        if (excess > 0.0) penalty += excess * excess;
    }
    return penalty;
}

/// out = x - offset (transform_vars_shift.c).
inline void shift(std::span<const double> x, std::span<const double> offset, std::span<double> out) noexcept {
    for (std::size_t i = 0; i < x.size(); ++i) out[i] = x[i] - offset[i];
}

/// out = M x + b, each out[i] summed from b over j = 0, 1, ... in order: transform_vars_affine.c
/// sums row i in the same order, so the bits are COCO's (no fused multiply-add: the build targets
/// baseline x86-64, and Eigen uses FMA only where the compiler may). The sweep adds x[j] times
/// column j (M is stored by columns) to every out[i] at once: D independent sums that vectorise,
/// where the row-by-row loop was one chain of D dependent additions per row, whose speed depended on
/// where the compiler placed it (the batch route was 1.3x slower than the scalar one at D = 40 on
/// f6, f12 and f13). Out of line, so the scalar and batch routes run this one copy.
[[gnu::noinline]] inline void affine(const AffineMatrix& m, std::span<const double> x, std::span<double> out,
                                     double b = 0.0) noexcept {
    const auto n = static_cast<Eigen::Index>(x.size());
    Eigen::Map<Eigen::VectorXd> sum(out.data(), n);
    sum.setConstant(b);
    for (Eigen::Index j = 0; j < n; ++j) sum += x[static_cast<std::size_t>(j)] * m.col(j);
}

/// Lambda^alpha as transform_vars_conditioning.c writes it: alpha^(0.5 i/(D-1)). COCO writes the
/// same diagonal two other ways, pow(sqrt(alpha), i/(D-1)) (power_ramp) and sqrt(pow(alpha,
/// i/(D-1))) (f7), which differ in the last bits; each function uses the form its COCO file uses.
inline std::vector<double> conditioning_diagonal(double alpha, std::size_t dim) {
    std::vector<double> d(dim);
    for (std::size_t i = 0; i < dim; ++i)
        d[i] = std::pow(alpha, 0.5 * static_cast<double>(i) / (static_cast<double>(dim) - 1.0));
    return d;
}

}  // namespace pride::continuous::bbob

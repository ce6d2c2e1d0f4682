#pragma once
// COCO's instance data for the bbob suite: its legacy random generators and what it builds from
// them (x_opt, f_opt, rotations, Gallagher's peaks). Every number here must equal COCO's bit for
// bit, so each function follows the order of operations of COCO's suite_bbob_legacy_code.c (and
// f_gallagher.c for the peaks); see $PRIDE_DATA/bbob/README.md for the conventions.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

namespace pride::continuous::bbob {

/// Dense matrix, row-major so that a row (one output coordinate) is contiguous in evaluate().
using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
/// The matrix of an affine map (transforms.hpp's affine), stored by columns, which it sweeps.
using AffineMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor>;

/// The largest instance: COCO's generator (uniform) works modulo the prime 2^31 - 1, and an
/// instance's seeds are function + 10000 instance (+ 1, + 1000000), so instances k and
/// k + 2^31 - 1 would be one instance under two numbers (2^31 was instance 1). Instances 1 to
/// 2^31 - 2 are all distinct.
inline constexpr std::int64_t kMaxInstance = 2'147'483'646;

/// The words every front end refuses an instance beyond kMaxInstance with.
std::string instance_range_message(std::string_view name, std::int64_t instance);

/// Throws InputError("bbob-fN", ...) unless dim >= 2 and 1 <= instance <= kMaxInstance.
void check_arguments(std::string_view name, std::size_t dim, std::int64_t instance);

/// COCO's seed of function `function`, instance `instance`: function + 10000 instance, except that
/// f4 uses f3's seed and f18 uses f17's (suite_bbob.c), so those pairs share x_opt, R and f_opt.
std::int64_t instance_seed(int function, std::int64_t instance);

/// bbob2009_unif: n uniform numbers in (0, 1] from Park-Miller 16807 with a 32-entry shuffle table.
std::vector<double> uniform(std::size_t n, std::int64_t seed);

/// bbob2009_gauss: n normals by Box-Muller from uniform(2n, seed) (u_i with u_{n+i}).
std::vector<double> gauss(std::size_t n, std::int64_t seed);

/// bbob2009_compute_xopt: 8 floor(1e4 u) / 1e4 - 4 per coordinate, 0 replaced by -1e-5.
std::vector<double> compute_xopt(std::size_t dim, std::int64_t seed);

/// bbob2009_compute_fopt: round(1e4 g1 / g2) / 100 clamped to [-1000, 1000], g1 and g2 normals
/// from the function's seed and seed + 1 (f4 and f18 borrow f3's and f17's).
double compute_fopt(int function, std::int64_t instance);

/// bbob2009_compute_rotation: dim^2 normals filled column by column, then Gram-Schmidt on the
/// columns; an orthogonal matrix.
RowMatrix compute_rotation(std::size_t dim, std::int64_t seed);

/// M = R diag(scale) Q, summed over k in COCO's order ((R_ik s_k) Q_kj, from 0).
RowMatrix scaled_product(const RowMatrix& r, const std::vector<double>& scale, const RowMatrix& q);

/// base^(i / (dim - 1)) for i = 0..dim-1, as COCO writes it inside its loops (pow per entry).
std::vector<double> power_ramp(double base, std::size_t dim);

/// Gallagher's peaks (f21: 101 peaks, f22: 21), as f_gallagher.c builds them.
struct GallagherPeaks {
    AffineMatrix rotation;        // R
    RowMatrix local;              // row p: R y_p (the peak's location, rotated)
    RowMatrix scales;             // row p: diagonal of C_p
    std::vector<double> heights;  // w_p
    std::vector<double> best;     // y_1, COCO's x_opt
};
GallagherPeaks make_gallagher_peaks(std::size_t dim, std::size_t peaks, std::int64_t seed);

}  // namespace pride::continuous::bbob

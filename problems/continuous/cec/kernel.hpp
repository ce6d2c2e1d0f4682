#pragma once
// The basic functions of the CEC 2017 and 2022 codes (cec17_test_func.cpp, Awad et al. 2016;
// cec22_test_func.cpp, Kumar et al. 2021), written to compute what those codes compute, quirks
// included, since published CEC results were made with them:
//
// - The official code keeps two work vectors y and z for the whole suite; a basic function writes
//   the shifted (and scaled) point into y and the rotated one into z. Schaffer's F7
//   (schaffer_f7) reads y, not z: standalone (2017 F6, 2022 F3) it is evaluated on the shifted,
//   unrotated point; inside a hybrid it reads y from index 0, that is the first coordinates of the
//   permuted vector, not its own group (2017 F14, F20; 2022 F7).
// - The Lunacek bi-Rastrigin (2017 F7, and in F13) takes the sign of o_i from the first entries
//   of the function's shift vector, also inside a hybrid, and writes y.
// - The non-continuous Rastrigin (2017 F8, 2022 F4) rounds y, then sr_func overwrites y: the
//   rounding never reaches the value, which is the plain shifted rotated Rastrigin's.
// - Hybrid functions apply each basic function's own scaling (sh_rate: 2.048/100 for Rosenbrock,
//   5.12/100 for Rastrigin, ...) to its group, unrotated and unshifted.
// - Levy's w is 1 + (z - 1)/4 in 2017 and 1 + z/4 in 2022.
//
// Everything else follows the report. Rotations sum in the official loop's order (kernel.cpp), so values are the
// official code's bit for bit where the compiler does not contract a * b + c into one instruction (x86-64 without
// -mfma: the default build and the official code's). Nothing allocates per evaluation: the work vectors are the
// Kernel's, sized once.
#include <cstddef>
#include <vector>

#include <Eigen/Core>

namespace pride::continuous::cec {

class Kernel {
  public:
    explicit Kernel(std::size_t dim) : y_(dim), z_(dim), tmp_(dim) {}

    // The official basic functions: x has nx coordinates, Os the shift, Mr the nx x nx rotation
    // (in Data::rotation's layout); s and r say whether to shift and rotate (sr_func's s_flag and r_flag).
    double ellips(const double* x, int nx, const double* os, const double* mr, bool s, bool r);
    double bent_cigar(const double* x, int nx, const double* os, const double* mr, bool s, bool r);
    double discus(const double* x, int nx, const double* os, const double* mr, bool s, bool r);
    double sum_diff_pow(const double* x, int nx, const double* os, const double* mr, bool s, bool r);
    double zakharov(const double* x, int nx, const double* os, const double* mr, bool s, bool r);
    double levy(const double* x, int nx, const double* os, const double* mr, bool s, bool r, bool y2022);
    double rosenbrock(const double* x, int nx, const double* os, const double* mr, bool s, bool r);
    double schaffer_f7(const double* x, int nx, const double* os, const double* mr, bool s, bool r);
    double ackley(const double* x, int nx, const double* os, const double* mr, bool s, bool r);
    double weierstrass(const double* x, int nx, const double* os, const double* mr, bool s, bool r);
    double griewank(const double* x, int nx, const double* os, const double* mr, bool s, bool r);
    double rastrigin(const double* x, int nx, const double* os, const double* mr, bool s, bool r);
    double step_rastrigin(const double* x, int nx, const double* os, const double* mr, bool s, bool r);
    double schwefel(const double* x, int nx, const double* os, const double* mr, bool s, bool r);
    double katsuura(const double* x, int nx, const double* os, const double* mr, bool s, bool r);
    double bi_rastrigin(const double* x, int nx, const double* os, const double* mr, bool s, bool r);
    double grie_rosen(const double* x, int nx, const double* os, const double* mr, bool s, bool r);
    double escaffer6(const double* x, int nx, const double* os, const double* mr, bool s, bool r);
    double happycat(const double* x, int nx, const double* os, const double* mr, bool s, bool r);
    double hgbat(const double* x, int nx, const double* os, const double* mr, bool s, bool r);

    /// sr_func: shift (x - Os), scale by rate, rotate by Mr, into out; writes y_ as the official does.
    void shift_rotate(const double* x, double* out, int nx, const double* os, const double* mr, double rate, bool s,
                      bool r);

    /// The hybrid frame (hf01-hf10): shift and rotate x into z, permute into y by `shuffle`.
    /// Then the caller evaluates group g on y() + start[g].
    void permute(const double* x, int nx, const double* os, const double* mr, const int* shuffle);
    double* y() noexcept { return y_.data(); }

    /// cf_cal: the weighted composition of fit (bias added here), weights from x's distance to each
    /// component's optimum (row i of os).
    static double compose(const double* x, int nx, const double* os, const double* delta, const double* bias,
                          double* fit, int components);

  private:
    std::vector<double> y_, z_, tmp_;
};

}  // namespace pride::continuous::cec

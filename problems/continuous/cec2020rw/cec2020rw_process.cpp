// The CEC 2020 real-world suite's process synthesis and design problems, RC08-RC14, as
// cec20_func.m computes them (cec2020rw_detail.hpp).
#include "problems/continuous/cec2020rw/cec2020rw_detail.hpp"

#include <cmath>

namespace pride::continuous::cec2020rw::detail {

// ---- RC08: process synthesis problem
double rc08(const double* x, double* c) noexcept {
    const double x1 = x[0], x2 = std::round(x[1]);
    c[0] = 1.25 - pw(x1, 2) - x2;
    c[1] = x1 + x2 - 1.6;
    return 2.0 * x1 + x2;
}

// ---- RC09: process synthesis and design problem
double rc09(const double* x, double* c) noexcept {
    const double x1 = x[0], x2 = x[1], x3 = std::round(x[2]);
    c[0] = -x1 + x2 + x3;
    c[1] = x1 - 2.0 * std::exp(-x2);
    return -x3 + 2.0 * x1 + x2;
}

// ---- RC10: process flow sheeting problem
double rc10(const double* x, double* c) noexcept {
    const double x1 = x[0], x2 = x[1], x3 = std::round(x[2]);
    c[0] = -std::exp(x1 - 0.2) - x2;
    c[1] = x2 + 1.1 * x3 + 1.0;
    c[2] = x1 - x3 - 0.2;
    return -0.7 * x3 + 5.0 * pw(x1 - 0.5, 2) + 0.8;
}

// ---- RC11: two-reactor problem
double rc11(const double* x, double* c) noexcept {
    const double x1 = x[0], x2 = x[1], v1 = x[2], v2 = x[3];
    const double y1 = std::round(x[4]), y2 = std::round(x[5]), x_ = x[6];
    const double z1 = 0.9 * (1.0 - std::exp(-0.5 * v1)) * x1;
    const double z2 = 0.8 * (1.0 - std::exp(-0.4 * v2)) * x2;
    c[0] = v1 - 10.0 * y1;
    c[1] = v2 - 10.0 * y2;
    c[2] = x1 - 20.0 * y1;
    c[3] = x2 - 20.0 * y2;
    c[4] = y1 + y2 - 1.0;
    c[5] = z1 + z2 - 10.0;
    c[6] = x1 + x2 - x_;
    c[7] = z1 * y1 + z2 * y2 - 10.0;
    return 7.5 * y1 + 5.5 * y2 + 7.0 * v1 + 6.0 * v2 + 5.0 * x_;
}

// ---- RC12: process synthesis problem ((x1 - 1)^22 as coded)
double rc12(const double* x, double* c) noexcept {
    const double x1 = x[0], x2 = x[1], x3 = x[2];
    const double y1 = std::round(x[3]), y2 = std::round(x[4]), y3 = std::round(x[5]), y4 = std::round(x[6]);
    const double f = pw(y1 - 1.0, 2) + pw(y2 - 1.0, 2) + pw(y3 - 1.0, 2) - std::log(y4 + 1.0) + pw(x1 - 1.0, 22) +
                     pw(x2 - 2.0, 2) + pw(x3 - 3.0, 2);
    c[0] = x1 + x2 + x3 + y1 + y2 + y3 - 5.0;
    c[1] = pw(y3, 2) + pw(x1, 2) + pw(x2, 2) + pw(x3, 2) - 5.5;
    c[2] = x1 + y1 - 1.2;
    c[3] = x2 + y2 - 1.8;
    c[4] = x3 + y3 - 2.5;
    c[5] = x1 + y4 - 1.2;
    c[6] = pw(y2, 2) + pw(x2, 2) - 1.64;
    c[7] = pw(y3, 2) + pw(x3, 2) - 4.25;
    c[8] = pw(y2, 2) + pw(x3, 2) - 4.64;
    return f;
}

// ---- RC13: process design problem
double rc13(const double* x, double* c) noexcept {
    const double x1 = x[0], x2 = x[1], x3 = x[2], y1 = std::round(x[3]), y2 = std::round(x[4]);
    constexpr double a[12] = {85.334407, 0.0056858, 0.0006262, 0.0022053, 80.51249,  0.0071317,
                              0.0029955, 0.0021813, 9.300961,  0.0047026, 0.0012547, 0.0019085};
    const double f = -5.357854 * pw(x1, 2) - 0.835689 * y1 * x3 - 37.29329 * y1 + 40792.141;
    c[0] = a[0] + a[1] * y2 * x3 + a[2] * y1 * x2 - a[3] * y1 * y1 * x3 - 92.0;
    c[1] = a[4] + a[5] * y2 * x3 + a[6] * y1 * x2 + a[7] * pw(x1, 2) - 90.0 - 20.0;
    c[2] = a[8] + a[9] * y1 * x2 + a[10] * y1 * x1 + a[11] * x1 * x2 - 20.0 - 5.0;
    return f;
}

// ---- RC14: multi-product batch plant
double rc14(const double* x, double* c) noexcept {
    constexpr double S[2][3] = {{2, 3, 4}, {4, 6, 3}};
    constexpr double t[2][3] = {{8, 20, 8}, {16, 4, 4}};
    const double H = 6000, alp = 250, beta = 0.6, Q1 = 40000, Q2 = 20000;
    const double N1 = std::round(x[0]), N2 = std::round(x[1]), N3 = std::round(x[2]);
    const double V1 = x[3], V2 = x[4], V3 = x[5], TL1 = x[6], TL2 = x[7], B1 = x[8], B2 = x[9];
    const double f = alp * (N1 * pw(V1, beta) + N2 * pw(V2, beta) + N3 * pw(V3, beta));
    c[0] = Q1 * TL1 / B1 + Q2 * TL2 / B2 - H;
    c[1] = S[0][0] * B1 + S[1][0] * B2 - V1;
    c[2] = S[0][1] * B1 + S[1][1] * B2 - V2;
    c[3] = S[0][2] * B1 + S[1][2] * B2 - V3;
    c[4] = t[0][0] - N1 * TL1;
    c[5] = t[0][1] - N2 * TL1;
    c[6] = t[0][2] - N3 * TL1;
    c[7] = t[1][0] - N1 * TL2;
    c[8] = t[1][1] - N2 * TL2;
    c[9] = t[1][2] - N3 * TL2;
    return f;
}

}  // namespace pride::continuous::cec2020rw::detail

// The problems of Kumar et al. (2020) as the organisers' cec20_func.m computes them, one function
// each: f(x), and the inequality values then the equality values into c. Variables are named as in
// the code; X(i) is the code's x(:,i). The operations keep the code's order (MATLAB evaluates left
// to right), so that the values agree with it to the last bits but for the library's rounding.
#include "problems/continuous/cec2020rw/cec2020rw.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <string>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include "framework/error.hpp"
#include "problems/continuous/cec2020rw/cec2020rw_detail.hpp"

namespace pride::continuous::cec2020rw {

namespace {

constexpr double kPi = std::numbers::pi;

// x.^e as MATLAB computes it for a real result (std::pow: NaN where MATLAB's would be complex).
double pw(double v, double e) noexcept {
    return std::pow(v, e);
}

// The code's x(:,i): 1-based.
struct OneBased {
    const double* x;
    double operator()(int i) const noexcept { return x[i - 1]; }
};

// Rounds a variable to the index of a table of n entries, as MATLAB's t(round(x)) does inside the
// box; outside it (where MATLAB stops with an error) the index is clamped to the table.
int table_index(double v, int n) noexcept {
    const double r = std::round(v);
    if (!(r >= 1.0)) return 0;
    if (r >= n) return n - 1;
    return static_cast<int>(r) - 1;
}

// ================= Industrial chemical processes

// ---- RC01: heat exchanger network design (case 1)
double rc01(const double* x, double* c) noexcept {
    const OneBased X{x};
    const double f = 35.0 * pw(X(1), 0.6) + 35.0 * pw(X(2), 0.6);
    c[0] = 200.0 * X(1) * X(4) - X(3);
    c[1] = 200.0 * X(2) * X(6) - X(5);
    c[2] = X(3) - 10000.0 * (X(7) - 100.0);
    c[3] = X(5) - 10000.0 * (300.0 - X(7));
    c[4] = X(3) - 10000.0 * (600.0 - X(8));
    c[5] = X(5) - 10000.0 * (900.0 - X(9));
    c[6] =
        X(4) * std::log(std::abs(X(8) - 100.0) + 1e-8) - X(4) * std::log((600.0 - X(7)) + 1e-8) - X(8) + X(7) + 500.0;
    c[7] = X(6) * std::log(std::abs(X(9) - X(7)) + 1e-8) - X(6) * std::log(600.0) - X(9) + X(7) + 600.0;
    return f;
}

// ---- RC02: heat exchanger network design (case 2)
double rc02(const double* x, double* c) noexcept {
    const OneBased X{x};
    const double f = pw(X(1) / (120.0 * X(4)), 0.6) + pw(X(2) / (80.0 * X(5)), 0.6) + pw(X(3) / (40.0 * X(6)), 0.6);
    c[0] = X(1) - 1e4 * (X(7) - 100.0);
    c[1] = X(2) - 1e4 * (X(8) - X(7));
    c[2] = X(3) - 1e4 * (500.0 - X(8));
    c[3] = X(1) - 1e4 * (300.0 - X(9));
    c[4] = X(2) - 1e4 * (400.0 - X(10));
    c[5] = X(3) - 1e4 * (600.0 - X(11));
    c[6] = X(4) * std::log(std::abs(X(9) - 100.0) + 1e-8) - X(4) * std::log(300.0 - X(7) + 1e-8) - X(9) - X(7) + 400.0;
    c[7] = X(5) * std::log(std::abs(X(10) - X(7)) + 1e-8) - X(5) * std::log(std::abs(400.0 - X(8)) + 1e-8) - X(10) +
           X(7) - X(8) + 400.0;
    c[8] = X(6) * std::log(std::abs(X(11) - X(8)) + 1e-8) - X(6) * std::log(100.0) - X(11) + X(8) + 100.0;
    return f;
}

// ---- RC03: optimal operation of alkylation unit
double rc03(const double* x, double* c) noexcept {
    const OneBased X{x};
    const double f = -1.715 * X(1) - 0.035 * X(1) * X(6) - 4.0565 * X(3) - 10.0 * X(2) + 0.063 * X(3) * X(5);
    c[0] = 0.0059553571 * pw(X(6), 2) * X(1) + 0.88392857 * X(3) - 0.1175625 * X(6) * X(1) - X(1);
    c[1] = 1.1088 * X(1) + 0.1303533 * X(1) * X(6) - 0.0066033 * X(1) * pw(X(6), 2) - X(3);
    c[2] = 6.66173269 * pw(X(6), 2) + 172.39878 * X(5) - 56.596669 * X(4) - 191.20592 * X(6) - 10000.0;
    c[3] = 1.08702 * X(6) + 0.32175 * X(4) - 0.03762 * pw(X(6), 2) - X(5) + 56.85075;
    c[4] = 0.006198 * X(7) * X(4) * X(3) + 2462.3121 * X(2) - 25.125634 * X(2) * X(4) - X(3) * X(4);
    c[5] = 161.18996 * X(3) * X(4) + 5000.0 * X(2) * X(4) - 489510.0 * X(2) - X(3) * X(4) * X(7);
    c[6] = 0.33 * X(7) - X(5) + 44.333333;
    c[7] = 0.022556 * X(5) - 0.007595 * X(7) - 1.0;
    c[8] = 0.00061 * X(3) - 0.0005 * X(1) - 1.0;
    c[9] = 0.819672 * X(1) - X(3) + 0.819672;
    c[10] = 24500.0 * X(2) - 250.0 * X(2) * X(4) - X(3) * X(4);
    c[11] = 1020.4082 * X(4) * X(2) + 1.2244898 * X(3) * X(4) - 100000.0 * X(2);
    c[12] = 6.25 * X(1) * X(6) + 6.25 * X(1) - 7.625 * X(3) - 100000.0;
    c[13] = 1.22 * X(3) - X(6) * X(1) - X(1) + 1.0;
    return f;
}

// ---- RC04: reactor network design
double rc04(const double* x, double* c) noexcept {
    const OneBased X{x};
    const double k1 = 0.09755988;
    const double k2 = 0.99 * k1;
    const double k3 = 0.0391908;
    const double k4 = 0.9 * k3;
    c[0] = pw(X(5), 0.5) + pw(X(6), 0.5) - 4.0;
    c[1] = X(1) + k1 * X(2) * X(5) - 1.0;
    c[2] = X(2) - X(1) + k2 * X(2) * X(6);
    c[3] = X(3) + X(1) + k3 * X(3) * X(5) - 1.0;
    c[4] = X(4) - X(3) + X(2) - X(1) + k4 * X(4) * X(6);
    return -X(4);
}

// ---- RC05: Haverly's pooling problem
double rc05(const double* x, double* c) noexcept {
    const OneBased X{x};
    const double f = -(9.0 * X(1) + 15.0 * X(2) - 6.0 * X(3) - 16.0 * X(4) - 10.0 * (X(5) + X(6)));
    c[0] = X(9) * X(7) + 2.0 * X(5) - 2.5 * X(1);
    c[1] = X(9) * X(8) + 2.0 * X(6) - 1.5 * X(2);
    c[2] = X(7) + X(8) - X(3) - X(4);
    c[3] = X(1) - X(7) - X(5);
    c[4] = X(2) - X(8) - X(6);
    c[5] = X(9) * X(7) + X(9) * X(8) - 3.0 * X(3) - X(4);
    return f;
}

// ---- RC06: blending-pooling-separation problem
double rc06(const double* x, double* c) noexcept {
    const OneBased X{x};
    const double third = 1.0 / 3.0;
    const double f = 0.9979 + 0.00432 * X(5) + 0.01517 * X(13);
    double* h = c;
    h[0] = X(1) + X(2) + X(3) + X(4) - 300.0;
    h[1] = X(6) - X(7) - X(8);
    h[2] = X(9) - X(10) - X(11) - X(12);
    h[3] = X(14) - X(15) - X(16) - X(17);
    h[4] = X(18) - X(19) - X(20);
    h[5] = X(5) * X(21) - X(6) * X(22) - X(9) * X(23);
    h[6] = X(5) * X(24) - X(6) * X(25) - X(9) * X(26);
    h[7] = X(5) * X(27) - X(6) * X(28) - X(9) * X(29);
    h[8] = X(13) * X(30) - X(14) * X(31) - X(18) * X(32);
    h[9] = X(13) * X(33) - X(14) * X(34) - X(18) * X(35);
    h[10] = X(13) * X(36) - X(14) * X(37) - X(18) * X(38);
    h[11] = third * X(1) + X(15) * X(31) - X(5) * X(21);
    h[12] = third * X(1) + X(15) * X(34) - X(5) * X(24);
    h[13] = third * X(1) + X(15) * X(37) - X(5) * X(27);
    h[14] = third * X(2) + X(10) * X(23) - X(13) * X(30);
    h[15] = third * X(2) + X(10) * X(26) - X(13) * X(33);
    h[16] = third * X(2) + X(10) * X(29) - X(13) * X(36);
    h[17] = third * X(3) + X(7) * X(22) + X(11) * X(23) + X(16) * X(31) + X(19) * X(32) - 30.0;
    h[18] = third * X(3) + X(7) * X(25) + X(11) * X(26) + X(16) * X(34) + X(19) * X(35) - 50.0;
    h[19] = third * X(3) + X(7) * X(28) + X(11) * X(29) + X(16) * X(37) + X(19) * X(38) - 30.0;
    h[20] = X(21) + X(24) + X(27) - 1.0;
    h[21] = X(22) + X(25) + X(28) - 1.0;
    h[22] = X(23) + X(26) + X(29) - 1.0;
    h[23] = X(30) + X(33) + X(36) - 1.0;
    h[24] = X(31) + X(34) + X(37) - 1.0;
    h[25] = X(32) + X(35) + X(38) - 1.0;
    h[26] = X(25);
    h[27] = X(28);
    h[28] = X(23);
    h[29] = X(37);
    h[30] = X(32);
    h[31] = X(35);
    return f;
}

// ---- RC07: propane, isobutane, n-butane nonsharp separation
double rc07(const double* x, double* c) noexcept {
    const OneBased X{x};
    const double third = 1.0 / 3.0;
    constexpr double k[6][2] = {{0.23947, 0.75835},     {-0.0139904, -0.0661588}, {0.0093514, 0.0338147},
                                {0.0077308, 0.0373349}, {-0.0005719, 0.0016371},  {0.0042656, 0.0288996}};
    const double f =
        k[0][0] + (k[1][0] + k[2][0] * X(24) + k[3][0] * X(28) + k[4][0] * X(33) + k[5][0] * X(34)) * X(5) + k[0][1] +
        (k[1][1] + k[2][1] * X(26) + k[3][1] * X(31) + k[4][1] * X(38) + k[5][1] * X(39)) * X(13);
    double* h = c;
    h[0] = X(1) + X(2) + X(3) + X(4) - 300.0;
    h[1] = X(6) - X(7) - X(8);
    h[2] = X(9) - X(10) - X(11) - X(12);
    h[3] = X(14) - X(15) - X(16) - X(17);
    h[4] = X(18) - X(19) - X(20);
    h[5] = X(6) * X(21) - X(24) * X(25);
    h[6] = X(14) * X(22) - X(26) * X(27);
    h[7] = X(9) * X(23) - X(28) * X(29);
    h[8] = X(18) * X(30) - X(31) * X(32);
    h[9] = X(25) - X(5) * X(33);
    h[10] = X(29) - X(5) * X(34);
    h[11] = X(35) - X(5) * X(36);
    h[12] = X(37) - X(13) * X(38);
    h[13] = X(27) - X(13) * X(39);
    h[14] = X(32) - X(13) * X(40);
    h[15] = X(25) - X(6) * X(21) - X(9) * X(41);
    h[16] = X(29) - X(6) * X(42) - X(9) * X(23);
    h[17] = X(35) - X(6) * X(43) - X(9) * X(44);
    h[18] = X(37) - X(14) * X(45) - X(18) * X(46);
    h[19] = X(27) - X(14) * X(22) - X(18) * X(47);
    h[20] = X(32) - X(14) * X(48) - X(18) * X(30);
    h[21] = third * X(1) + X(15) * X(45) - X(25);
    h[22] = third * X(1) + X(15) * X(22) - X(29);
    h[23] = third * X(1) + X(15) * X(48) - X(35);
    h[24] = third * X(2) + X(10) * X(41) - X(37);
    h[25] = third * X(2) + X(10) * X(23) - X(27);
    h[26] = third * X(2) + X(10) * X(44) - X(32);
    h[27] = X(33) + X(34) + X(36) - 1.0;
    h[28] = X(21) + X(42) + X(43) - 1.0;
    h[29] = X(41) + X(23) + X(44) - 1.0;
    h[30] = X(38) + X(39) + X(40) - 1.0;
    h[31] = X(45) + X(22) + X(48) - 1.0;
    h[32] = X(46) + X(47) + X(30) - 1.0;
    h[33] = X(43);
    h[34] = X(46);
    h[35] = third * X(3) + X(7) * X(21) + X(11) * X(41) + X(16) * X(45) + X(19) * X(46) - 30.0;
    h[36] = third * X(3) + X(7) * X(42) + X(11) * X(23) + X(16) * X(22) + X(19) * X(47) - 50.0;
    h[37] = third * X(3) + X(7) * X(43) + X(11) * X(44) + X(16) * X(48) + X(19) * X(30) - 30.0;
    return f;
}

// ================= Process synthesis and design

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

// ================= Mechanical engineering

// ---- RC15: weight minimisation of a speed reducer
double rc15(const double* x, double* c) noexcept {
    const OneBased X{x};
    const double f = 0.7854 * X(1) * pw(X(2), 2) * (3.3333 * pw(X(3), 2) + 14.9334 * X(3) - 43.0934) -
                     1.508 * X(1) * (pw(X(6), 2) + pw(X(7), 2)) + 7.477 * (pw(X(6), 3) + pw(X(7), 3)) +
                     0.7854 * (X(4) * pw(X(6), 2) + X(5) * pw(X(7), 2));
    c[0] = -X(1) * pw(X(2), 2) * X(3) + 27.0;
    c[1] = -X(1) * pw(X(2), 2) * pw(X(3), 2) + 397.5;
    c[2] = -X(2) * pw(X(6), 4) * X(3) * pw(X(4), -3) + 1.93;
    c[3] = -X(2) * pw(X(7), 4) * X(3) / pw(X(5), 3) + 1.93;
    c[4] = 10.0 * pw(X(6), -3) * std::sqrt(16.91 * 1e6 + pw(745.0 * X(4) / (X(2) * X(3)), 2)) - 1100.0;
    c[5] = 10.0 * pw(X(7), -3) * std::sqrt(157.5 * 1e6 + pw(745.0 * X(5) / (X(2) * X(3)), 2)) - 850.0;
    c[6] = X(2) * X(3) - 40.0;
    c[7] = -X(1) / X(2) + 5.0;
    c[8] = X(1) / X(2) - 12.0;
    c[9] = 1.5 * X(6) - X(4) + 1.9;
    c[10] = 1.1 * X(7) - X(5) + 1.9;
    return f;
}

// ---- RC16: optimal design of industrial refrigeration system
double rc16(const double* x, double* c) noexcept {
    const OneBased X{x};
    const double f =
        63098.88 * X(2) * X(4) * X(12) + 5441.5 * pw(X(2), 2) * X(12) + 115055.5 * pw(X(2), 1.664) * X(6) +
        6172.27 * pw(X(2), 2) * X(6) + 63098.88 * X(1) * X(3) * X(11) + 5441.5 * pw(X(1), 2) * X(11) +
        115055.5 * pw(X(1), 1.664) * X(5) + 6172.27 * pw(X(1), 2) * X(5) + 140.53 * X(1) * X(11) +
        281.29 * X(3) * X(11) + 70.26 * pw(X(1), 2) + 281.29 * X(1) * X(3) + 281.29 * pw(X(3), 2) +
        14437.0 * pw(X(8), 1.8812) * pw(X(12), 0.3424) * X(10) * pw(X(14), -1) * pw(X(1), 2) * X(7) * pw(X(9), -1) +
        20470.2 * pw(X(7), 2.893) * pw(X(11), 0.316) * pw(X(1), 2);
    c[0] = 1.524 * pw(X(7), -1) - 1.0;
    c[1] = 1.524 * pw(X(8), -1) - 1.0;
    c[2] = 0.07789 * X(1) - 2.0 * pw(X(7), -1) * X(9) - 1.0;
    c[3] = 7.05305 * pw(X(9), -1) * pw(X(1), 2) * X(10) * pw(X(8), -1) * pw(X(2), -1) * pw(X(14), -1) - 1.0;
    c[4] = 0.0833 / X(13) * X(14) - 1.0;
    c[5] = 0.04771 * X(10) * pw(X(8), 1.8812) * pw(X(12), 0.3424) - 1.0;
    c[6] = 0.0488 * X(9) * pw(X(7), 1.893) * pw(X(11), 0.316) - 1.0;
    c[7] = 0.0099 * X(1) / X(3) - 1.0;
    c[8] = 0.0193 * X(2) / X(4) - 1.0;
    c[9] = 0.0298 * X(1) / X(5) - 1.0;
    c[10] = 47.136 * pw(X(2), 0.333) / X(10) * X(12) - 1.333 * X(8) * pw(X(13), 2.1195) +
            62.08 * pw(X(13), 2.1195) * pw(X(8), 0.2) / (X(12) * X(10)) - 1.0;
    c[11] = 0.056 * X(2) / X(6) - 1.0;
    c[12] = 2.0 / X(9) - 1.0;
    c[13] = 2.0 / X(10) - 1.0;
    c[14] = X(12) / X(11) - 1.0;
    return f;
}

// ---- RC17: tension/compression spring design (case 1); four inequalities as coded
double rc17(const double* x, double* c) noexcept {
    const OneBased X{x};
    c[0] = 1.0 - (pw(X(2), 3) * X(3)) / (71785.0 * pw(X(1), 4));
    c[1] = (4.0 * pw(X(2), 2) - X(1) * X(2)) / (12566.0 * (X(2) * pw(X(1), 3) - pw(X(1), 4))) +
           1.0 / (5108.0 * pw(X(1), 2)) - 1.0;
    c[2] = 1.0 - 140.45 * X(1) / (pw(X(2), 2) * X(3));
    c[3] = (X(1) + X(2)) / 1.5 - 1.0;
    return pw(X(1), 2) * X(2) * (X(3) + 2.0);
}

// ---- RC18: pressure vessel design (x1, x2 multiples of 0.0625)
double rc18(const double* x, double* c) noexcept {
    const double x1 = 0.0625 * std::round(x[0]), x2 = 0.0625 * std::round(x[1]), x3 = x[2], x4 = x[3];
    const double f = 0.6224 * x1 * x3 * x4 + 1.7781 * x2 * pw(x3, 2) + 3.1661 * pw(x1, 2) * x4 + 19.84 * pw(x1, 2) * x3;
    c[0] = -x1 + 0.0193 * x3;
    c[1] = -x2 + 0.00954 * x3;
    c[2] = -kPi * pw(x3, 2) * x4 - 4.0 / 3.0 * kPi * pw(x3, 3) + 1296000.0;
    c[3] = x4 - 240.0;
    return f;
}

// ---- RC19: welded beam design
double rc19(const double* x, double* c) noexcept {
    const OneBased X{x};
    const double f = 1.10471 * pw(X(1), 2) * X(2) + 0.04811 * X(3) * X(4) * (14.0 + X(2));
    const double P = 6000, L = 14, delta_max = 0.25, E = 30 * 1e6, G = 12 * 1e6;
    const double T_max = 13600, sigma_max = 30000;
    const double s2 = std::sqrt(2.0);
    const double Pc = 4.013 * E * std::sqrt(pw(X(3), 2) * pw(X(4), 6) / 30.0) / pw(L, 2) *
                      (1.0 - X(3) / (2.0 * L) * std::sqrt(E / (4.0 * G)));
    const double sigma = 6.0 * P * L / (X(4) * pw(X(3), 2));
    const double delta = 6.0 * P * pw(L, 3) / (E * pw(X(3), 2) * X(4));
    const double J = 2.0 * (s2 * X(1) * X(2) * (pw(X(2), 2) / 4.0 + pw(X(1) + X(3), 2) / 4.0));
    const double R = std::sqrt(pw(X(2), 2) / 4.0 + pw(X(1) + X(3), 2) / 4.0);
    const double M = P * (L + X(2) / 2.0);
    const double ttt = M * R / J;
    const double tt = P / (s2 * X(1) * X(2));
    const double t = std::sqrt(pw(tt, 2) + 2.0 * tt * ttt * X(2) / (2.0 * R) + pw(ttt, 2));
    c[0] = t - T_max;
    c[1] = sigma - sigma_max;
    c[2] = X(1) - X(4);
    c[3] = delta - delta_max;
    c[4] = P - Pc;
    return f;
}

// ---- RC20: three-bar truss design
double rc20(const double* x, double* c) noexcept {
    const double x1 = x[0], x2 = x[1], s2 = std::sqrt(2.0);
    c[0] = (s2 * x1 + x2) / (s2 * pw(x1, 2) + 2.0 * x1 * x2) * 2.0 - 2.0;
    c[1] = x2 / (s2 * pw(x1, 2) + 2.0 * x1 * x2) * 2.0 - 2.0;
    c[2] = 1.0 / (s2 * x2 + x1) * 2.0 - 2.0;
    return (2.0 * s2 * x1 + x2) * 100.0;
}

// ---- RC21: multiple disk clutch brake design; eight inequalities as coded
double rc21(const double* x, double* c) noexcept {
    const OneBased X{x};
    const double Mf = 3, Ms = 40, Iz = 55, n = 250, Tmax = 15, s = 1.5, delta = 0.5;
    const double Vsrmax = 10, rho = 0.0000078, pmax = 1, mu = 0.6, Lmax = 30, delR = 20;
    const double Rsr = 2.0 / 3.0 * (pw(X(2), 3) - pw(X(1), 3)) / (pw(X(2), 2) * pw(X(1), 2));
    const double Vsr = kPi * Rsr * n / 30.0;
    const double A = kPi * (pw(X(2), 2) - pw(X(1), 2));
    const double Prz = X(4) / A;
    const double w = kPi * n / 30.0;
    const double Mh = 2.0 / 3.0 * mu * X(4) * X(5) * (pw(X(2), 3) - pw(X(1), 3)) / (pw(X(2), 2) - pw(X(1), 2));
    const double T = Iz * w / (Mh + Mf);
    c[0] = -X(2) + X(1) + delR;
    c[1] = (X(5) + 1.0) * (X(3) + delta) - Lmax;
    c[2] = Prz - pmax;
    c[3] = Prz * Vsr - pmax * Vsrmax;
    c[4] = Vsr - Vsrmax;
    c[5] = T - Tmax;
    c[6] = s * Ms - Mh;
    c[7] = -T;
    return kPi * (pw(X(2), 2) - pw(X(1), 2)) * X(3) * (X(5) + 1.0) * rho;
}

// MATLAB's max(..., [], 2): NaN entries are ignored (NaN only when all are).
double max_ignoring_nan(std::initializer_list<double> values) noexcept {
    double best = std::numeric_limits<double>::quiet_NaN();
    for (const double v : values)
        if (!std::isnan(v) && (std::isnan(best) || v > best)) best = v;
    return best;
}

// ---- RC22: planetary gear train design (all variables round(|x|); x7-x9 index tables)
double rc22(const double* x, double* c) noexcept {
    double r[9];
    for (int i = 0; i < 9; ++i) r[i] = std::round(std::abs(x[i]));
    constexpr double Pind[3] = {3, 4, 5};
    constexpr double mind[6] = {1.75, 2, 2.25, 2.5, 2.75, 3.0};
    const double N1 = r[0], N2 = r[1], N3 = r[2], N4 = r[3], N5 = r[4], N6 = r[5];
    const double p = Pind[table_index(r[6], 3)], m1 = mind[table_index(r[7], 6)], m2 = mind[table_index(r[8], 6)];
    const double i1 = N6 / N4, i01 = 3.11;
    const double i2 = N6 * (N1 * N3 + N2 * N4) / (N1 * N3 * (N6 - N4)), i02 = 1.84;
    const double iR = -(N2 * N6 / (N1 * N3)), i0R = -3.11;
    const double f = max_ignoring_nan({i1 - i01, i2 - i02, iR - i0R});
    const double Dmax = 220, dlt22 = 0.5, dlt33 = 0.5, dlt55 = 0.5, dlt35 = 0.5, dlt34 = 0.5, dlt56 = 0.5;
    const double arg = (pw(N6 - N3, 2) + pw(N4 + N5, 2) - pw(N3 + N5, 2)) / (2.0 * (N6 - N3) * (N4 + N5));
    c[0] = m2 * (N6 + 2.5) - Dmax;
    c[1] = m1 * (N1 + N2) + m1 * (N2 + 2.0) - Dmax;
    c[2] = m2 * (N4 + N5) + m2 * (N5 + 2.0) - Dmax;
    c[3] = std::abs(m1 * (N1 + N2) - m2 * (N6 - N3)) - m1 - m2;
    c[4] = -((N1 + N2) * std::sin(kPi / p) - N2 - 2.0 - dlt22);
    c[5] = -((N6 - N3) * std::sin(kPi / p) - N3 - 2.0 - dlt33);
    c[6] = -((N4 + N5) * std::sin(kPi / p) - N5 - 2.0 - dlt55);
    if (arg >= -1.0 && arg <= 1.0) {  // beta real (the code's beta == real(beta))
        const double beta = std::acos(arg);
        c[7] = pw(N3 + N5 + 2.0 + dlt35, 2) -
               (pw(N6 - N3, 2) + pw(N4 + N5, 2) - 2.0 * (N6 - N3) * (N4 + N5) * std::cos(2.0 * kPi / p - beta));
    } else {
        c[7] = 1e6;
    }
    c[8] = -(N6 - 2.0 * N3 - N4 - 4.0 - 2.0 * dlt34);
    c[9] = -(N6 - N4 - 2.0 * N5 - 4.0 - 2.0 * dlt56);
    c[10] = std::fmod(N6 - N4, p);  // rem: the sign of the dividend
    return f;
}

// ---- RC23: step-cone pulley problem
double rc23(const double* x, double* c) noexcept {
    const double d[4] = {x[0] * 1e-3, x[1] * 1e-3, x[2] * 1e-3, x[3] * 1e-3};
    const double w = x[4] * 1e-3;
    const double N = 350, Ns[4] = {750, 450, 250, 150};
    const double rho = 7200, a = 3, mu = 0.35, s = 1.75 * 1e6, t = 8 * 1e-3;
    double sum = 0.0;
    for (int i = 0; i < 4; ++i) sum += pw(d[i], 2) * (1.0 + pw(Ns[i] / N, 2));
    const double f = rho * w * kPi / 4.0 * sum;
    double C[4];
    for (int i = 0; i < 4; ++i) {
        C[i] = kPi * d[i] / 2.0 * (1.0 + Ns[i] / N) + pw(Ns[i] / N - 1.0, 2) * pw(d[i], 2) / (4.0 * a) + 2.0 * a;
        const double angle = kPi - 2.0 * std::asin((Ns[i] / N - 1.0) * d[i] / (2.0 * a));
        const double R = std::exp(mu * angle);
        const double P = s * t * w * (1.0 - std::exp(-mu * angle)) * kPi * d[i] * Ns[i] / 60.0;
        c[i] = -R + 2.0;
        c[4 + i] = -P + (0.75 * 745.6998);
    }
    c[8] = C[0] - C[1];
    c[9] = C[0] - C[2];
    c[10] = C[0] - C[3];
    return f;
}

// ---- RC25: hydrostatic thrust bearing design
double rc25(const double* x, double* c) noexcept {
    const double R = x[0], Ro = x[1], mu = x[2], Q = x[3];
    const double gamma = 0.0307, C = 0.5, n = -3.55, C1 = 10.04;
    const double Ws = 101000, Pmax = 1000, delTmax = 50, hmin = 0.001, gg = 386.4, N = 750;
    const double P = (std::log10(std::log10(8.122 * 1e6 * mu + 0.8)) - C1) / n;
    const double delT = 2.0 * (pw(10.0, P) - 560.0);
    const double Ef = 9336.0 * Q * gamma * C * delT;
    const double h = pw(2.0 * kPi * N / 60.0, 2) * 2.0 * kPi * mu / Ef * (pw(R, 4) / 4.0 - pw(Ro, 4) / 4.0) - 1e-5;
    const double Po = (6.0 * mu * Q / (kPi * pw(h, 3))) * std::log(R / Ro);
    const double W = kPi * Po / 2.0 * (pw(R, 2) - pw(Ro, 2)) / (std::log(R / Ro) - 1e-5);
    c[0] = Ws - W;
    c[1] = Po - Pmax;
    c[2] = delT - delTmax;
    c[3] = hmin - h;
    c[4] = Ro - R;
    c[5] = gamma / (gg * Po) * (Q / (2.0 * kPi * R * h)) - 0.001;
    c[6] = W / (kPi * (pw(R, 2) - pw(Ro, 2)) + 1e-5) - 5000.0;
    return (Q * Po / 0.7 + Ef) / 12.0;
}

// ---- RC26: four-stage gear box (all variables rounded; x9-x22 index tables)
double rc26(const double* x, double* c) noexcept {
    double r[22];
    for (int i = 0; i < 22; ++i) r[i] = std::round(x[i]);
    const double Np[4] = {r[0], r[2], r[4], r[6]}, Ng[4] = {r[1], r[3], r[5], r[7]};
    constexpr double Pvalue[4] = {3.175, 5.715, 8.255, 12.7};
    constexpr double XY[9] = {12.7, 25.4, 38.1, 50.8, 63.5, 76.2, 88.9, 101.6, 114.3};
    double b[4];
    for (int i = 0; i < 4; ++i) b[i] = Pvalue[table_index(r[8 + i], 4)];
    auto xy = [&](int i) { return XY[table_index(r[i], 9)]; };
    const double xp1 = xy(12), xg[4] = {xy(13), xy(14), xy(15), xy(16)};
    const double yp1 = xy(17), yg[4] = {xy(18), xy(19), xy(20), xy(21)};
    double cc[4];
    for (int i = 0; i < 4; ++i) cc[i] = std::sqrt(pw(xg[i] - xp1, 2) + pw(yg[i] - yp1, 2));
    const double CRmin = 1.4, dmin = 25.4, phi = 20.0 * kPi / 180.0, W = 55.9, JR = 0.2, Km = 1.6, Ko = 1.5;
    const double Lmax = 127, sigma_H = 3290, sigma_N = 2090, w1 = 5000, wmin = 245, wmax = 255, Cp = 464;
    double f = 0.0;
    for (int i = 0; i < 4; ++i) f += b[i] * pw(cc[i], 2) * (pw(Np[i], 2) + pw(Ng[i], 2)) / pw(Np[i] + Ng[i], 2);
    f = kPi / 1000.0 * f;
    // The speed factor of stage i: 366000 Ng1...Ng(i-1) / (pi w1 Np1...Np(i-1)).
    double pref[4];
    pref[0] = 366000.0 / (kPi * w1);
    pref[1] = 366000.0 * Ng[0] / (kPi * w1 * Np[0]);
    pref[2] = 366000.0 * Ng[0] * Ng[1] / (kPi * w1 * Np[0] * Np[1]);
    pref[3] = 366000.0 * Ng[0] * Ng[1] * Ng[2] / (kPi * w1 * Np[0] * Np[1] * Np[2]);
    const double bending = sigma_N * JR / (0.0167 * W * Ko * Km);
    const double contact = pw(sigma_H / Cp, 2) * (std::sin(phi) * std::cos(phi)) / (0.0334 * W * Ko * Km);
    const double sp2 = pw(std::sin(phi), 2);
    const double xs[4] = {xp1, xg[1], xg[2], xg[3]}, ys[4] = {yp1, yg[1], yg[2], yg[3]};
    for (int i = 0; i < 4; ++i) {
        const double np = Np[i], ng = Ng[i], bi = b[i], ci = cc[i], sum = np + ng;
        c[i] = (pref[i] + 2.0 * ci * np / sum) * (pw(sum, 2) / (4.0 * bi * pw(ci, 2) * np)) - bending;
        c[4 + i] = (pref[i] + 2.0 * ci * np / sum) * (pw(sum, 3) / (4.0 * bi * pw(ci, 2) * ng * pw(np, 2))) - contact;
        c[8 + i] = CRmin * kPi * std::cos(phi) - np * std::sqrt(sp2 / 4.0 + 1.0 / np + pw(1.0 / np, 2)) -
                   ng * std::sqrt(sp2 / 4.0 + 1.0 / ng + pw(1.0 / ng, 2)) + std::sin(phi) * sum / 2.0;
        c[12 + i] = dmin - 2.0 * ci * np / sum;
        c[16 + i] = dmin - 2.0 * ci * ng / sum;
        const double pinion = (np + 2.0) * ci / sum, gear = (ng + 2.0) * ci / sum;
        c[20 + i] = xs[i] + pinion - Lmax;
        c[24 + i] = -xs[i] + pinion;
        c[28 + i] = ys[i] + pinion - Lmax;
        c[32 + i] = -ys[i] + pinion;
        c[36 + i] = xg[i] + gear - Lmax;
        c[40 + i] = -xg[i] + gear;
        c[44 + i] = yg[i] + gear - Lmax;
        c[48 + i] = -yg[i] + gear;
        c[52 + i] = (0.945 * ci - np - ng) * (bi - 5.715) * (bi - 8.255) * (bi - 12.70) * (-1.0);
        c[56 + i] = (0.646 * ci - np - ng) * (bi - 3.175) * (bi - 8.255) * (bi - 12.70) * (+1.0);
        c[60 + i] = (0.504 * ci - np - ng) * (bi - 3.175) * (bi - 5.715) * (bi - 12.70) * (-1.0);
        c[64 + i] = (0.0 * ci - np - ng) * (bi - 3.175) * (bi - 5.715) * (bi - 8.255) * (+1.0);
        c[68 + i] = (-1.812 * ci + np + ng) * (bi - 5.715) * (bi - 8.255) * (bi - 12.70) * (-1.0);
        c[72 + i] = (-0.945 * ci + np + ng) * (bi - 3.175) * (bi - 8.255) * (bi - 12.70) * (+1.0);
        // As coded: constraints 79 and 80 take the pinion of the stage before (Np2, Np3).
        const double np77 = i >= 2 ? Np[i - 1] : np;
        c[76 + i] = (-0.646 * ci + np77 + ng) * (bi - 3.175) * (bi - 5.715) * (bi - 12.70) * (-1.0);
        c[80 + i] = (-0.504 * ci + np + ng) * (bi - 3.175) * (bi - 5.715) * (bi - 8.255) * (+1.0);
    }
    const double ratio = w1 * (Np[0] * Np[1] * Np[2] * Np[3]) / (Ng[0] * Ng[1] * Ng[2] * Ng[3]);
    c[84] = wmin - ratio;
    c[85] = -wmax + ratio;
    for (int i = 0; i < 86; ++i)
        if (std::isinf(c[i])) c[i] = 1e6;
    return f;
}

// ---- RC27: 10-bar truss (the first three natural frequencies of a planar truss). The code solves
// the generalised eigenproblem K v = w^2 M v with MATLAB's eig; here Eigen's solver for symmetric
// K and positive definite M (a Cholesky factor of M, then the symmetric eigenproblem), which agrees
// with LAPACK's to rounding only.
double rc27(const double* x, double* c) noexcept {
    const double E = 6.98 * 1e10, rho = 2770;
    constexpr double gx[6] = {18.288, 18.288, 9.144, 9.144, 0, 0}, gy[6] = {9.144, 0, 9.144, 0, 9.144, 0};
    constexpr int element[10][2] = {{3, 5}, {1, 3}, {4, 6}, {2, 4}, {3, 4}, {1, 2}, {4, 5}, {3, 6}, {2, 3}, {1, 4}};
    Eigen::Matrix<double, 12, 12> K = Eigen::Matrix<double, 12, 12>::Zero(), M = K;
    double weight = 0.0;
    for (int e = 0; e < 10; ++e) {
        const int n1 = element[e][0], n2 = element[e][1];
        const double dx = gx[n2 - 1] - gx[n1 - 1], dy = gy[n2 - 1] - gy[n1 - 1];
        const double le = std::sqrt(pw(dx, 2) + pw(dy, 2));
        weight = weight + rho * le * x[e];
        const double l = dx / le, m = dy / le;
        Eigen::Matrix<double, 2, 4> Te;
        Te << l, m, 0, 0, 0, 0, l, m;
        Eigen::Matrix2d k2;
        k2 << 1, -1, -1, 1;
        const Eigen::Matrix4d ke = Te.transpose() * (x[e] * E / le * k2) * Te;
        Eigen::Matrix4d me;
        me << 2, 0, 1, 0, 0, 2, 0, 1, 1, 0, 2, 0, 0, 1, 0, 2;
        me = rho * le * x[e] * me / 6.0;
        const int index[4] = {2 * n1 - 2, 2 * n1 - 1, 2 * n2 - 2, 2 * n2 - 1};
        for (int a = 0; a < 4; ++a)
            for (int b = 0; b < 4; ++b) {
                K(index[a], index[b]) += ke(a, b);
                M(index[a], index[b]) += me(a, b);
            }
    }
    for (int i = 0; i < 12; ++i) M(i, i) += 454.0;  // non-structural mass
    // Nodes 5 and 6 are fixed: their degrees of freedom 9-12 are the last four.
    const Eigen::Matrix<double, 8, 8> Kf = K.topLeftCorner<8, 8>(), Mf = M.topLeftCorner<8, 8>();
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix<double, 8, 8>> solver(Kf, Mf, Eigen::EigenvaluesOnly);
    const auto& w2 = solver.eigenvalues();  // ascending
    const double f1 = std::sqrt(w2(0)) / 2.0 / kPi, f2 = std::sqrt(w2(1)) / 2.0 / kPi,
                 f3 = std::sqrt(w2(2)) / 2.0 / kPi;
    c[0] = 7.0 / f1 - 1.0;
    c[1] = 15.0 / f2 - 1.0;
    c[2] = 20.0 / f3 - 1.0;
    return weight;
}

// ---- RC28: rolling element bearing
double rc28(const double* x, double* c) noexcept {
    const double Dm = x[0], Db = x[1], Z = std::round(x[2]), fi = x[3], fo = x[4];
    const double KDmin = x[5], KDmax = x[6], eps = x[7], e = x[8], chi = x[9];
    const double D = 160, d = 90, Bw = 30, T = D - d - 2.0 * Db;
    const double phi_o =
        2.0 * kPi -
        2.0 * std::acos((pw((D - d) * 0.5 - 0.75 * T, 2) + pw(0.5 * D - 0.25 * T - Db, 2) - pw(0.5 * d + 0.25 * T, 2)) /
                        (2.0 * (0.5 * (D - d) - 0.75 * T) * (0.5 * D - 0.25 * T - Db)));
    const double gamma = Db / Dm;
    const double fc = 37.91 *
                      pw(1.0 + pw(1.04 * pw((1.0 - gamma) / (1.0 + gamma), 1.72) *
                                      pw(fi * (2.0 * fo - 1.0) / (fo * (2.0 * fi - 1.0)), 0.41),
                                  10.0 / 3.0),
                         -0.3) *
                      (pw(gamma, 0.3) * pw(1.0 - gamma, 1.39) / pw(1.0 + gamma, 1.0 / 3.0)) *
                      pw(2.0 * fi / (2.0 * fi - 1.0), 0.41);
    const double f = Db > 25.4 ? 3.647 * fc * pw(Z, 2.0 / 3.0) * pw(Db, 1.4) : fc * pw(Z, 2.0 / 3.0) * pw(Db, 1.8);
    c[0] = Z - 1.0 - phi_o / (2.0 * std::asin(Db / Dm));
    c[1] = KDmin * (D - d) - 2.0 * Db;
    c[2] = 2.0 * Db - KDmax * (D - d);
    c[3] = chi * Bw - Db;
    c[4] = 0.5 * (D + d) - Dm;
    c[5] = Dm - (0.5 + e) * (D + d);
    c[6] = eps * Db - 0.5 * (D - Dm - Db);
    c[7] = 0.515 - fi;
    c[8] = 0.515 - fo;
    return f;
}

// ---- RC29: gas transmission compressor design
double rc29(const double* x, double* c) noexcept {
    const OneBased X{x};
    c[0] = X(4) * pw(X(2), -2) + pw(X(2), -2) - 1.0;
    return 8.61 * 1e5 * pw(X(1), 0.5) * X(2) * pw(X(3), -2.0 / 3.0) * pw(X(4), -1.0 / 2.0) + 3.69 * 1e4 * X(3) +
           7.72 * 1e8 * pw(X(1), -1) * pw(X(2), 0.219) - 765.43 * 1e6 * pw(X(1), -1);
}

// ---- RC30: tension/compression spring design (case 2); the wire table as coded
double rc30(const double* x, double* c) noexcept {
    constexpr double d[42] = {0.009, 0.0095, 0.0104, 0.0118, 0.0128, 0.0132, 0.014, 0.015,  0.0162, 0.0173, 0.018,
                              0.020, 0.023,  0.025,  0.028,  0.032,  0.035,  0.041, 0.047,  0.054,  0.063,  0.072,
                              0.080, 0.092,  0.0105, 0.120,  0.135,  0.148,  0.162, 0.177,  0.192,  0.207,  0.225,
                              0.244, 0.263,  0.283,  0.307,  0.331,  0.362,  0.394, 0.4375, 0.500};
    const double x1 = std::round(x[0]), x2 = x[1], x3 = d[table_index(x[2], 42)];
    const double f = (pw(kPi, 2) * x2 * pw(x3, 2) * (x1 + 2.0)) / 4.0;
    const double cf = (4.0 * x2 / x3 - 1.0) / (4.0 * x2 / x3 - 4.0) + 0.615 * x3 / x2;
    const double K = (11.5 * 1e6 * pw(x3, 4)) / (8.0 * x1 * pw(x2, 3));
    const double lf = 1000.0 / K + 1.05 * (x1 + 2.0) * x3;
    const double sigp = 300.0 / K;
    c[0] = (8000.0 * cf * x2) / (kPi * pw(x3, 3)) - 189000.0;
    c[1] = lf - 14.0;
    c[2] = 0.2 - x3;
    c[3] = x2 - 3.0;
    c[4] = 3.0 - x2 / x3;
    c[5] = sigp - 6.0;
    c[6] = sigp + 700.0 / K + 1.05 * (x1 + 2.0) * x3 - lf;
    c[7] = 1.25 - 700.0 / K;
    return f;
}

// ---- RC31: gear train design (unconstrained as coded: its g and h are 0)
double rc31(const double* x, double* c) noexcept {
    c[0] = 0.0;
    c[1] = 0.0;
    return pw(1.0 / 6.931 - (x[0] * x[1]) / (x[2] * x[3]), 2);
}

// ---- RC32: Himmelblau's function
double rc32(const double* x, double* c) noexcept {
    const double x1 = x[0], x2 = x[1], x3 = x[2], x4 = x[3], x5 = x[4];
    const double G1 = 85.334407 + 0.0056858 * x2 * x5 + 0.0006262 * x1 * x4 - 0.0022053 * x3 * x5;
    const double G2 = 80.51249 + 0.0071317 * x2 * x5 + 0.0029955 * x1 * x2 + 0.0021813 * pw(x3, 2);
    const double G3 = 9.300961 + 0.0047026 * x3 * x5 + 0.0012547 * x1 * x3 + 0.0019085 * x3 * x4;
    c[0] = G1 - 92.0;
    c[1] = -G1;
    c[2] = G2 - 110.0;
    c[3] = -G2 + 90.0;
    c[4] = G3 - 25.0;
    c[5] = -G3 + 20.0;
    return 5.3578547 * pw(x3, 2) + 0.8356891 * x1 * x5 + 37.293239 * x1 - 40792.141;
}

// ---- RC33: topology optimisation, a cantilever of 3 x 10 elements (Sigmund's 99-line code's
// compliance and its filtered sensitivities). The code solves K U = F with MATLAB's sparse
// backslash; here a dense Cholesky factorisation, which agrees with it to rounding only.
double rc33(const double* x, double* c) noexcept {
    constexpr int nelx = 3, nely = 10, ndof = 2 * (nelx + 1) * (nely + 1), nfixed = 2 * (nely + 1);
    constexpr int nfree = ndof - nfixed;
    const double penal = 3, rmin = 1.5;
    auto X = [x](int ely, int elx) { return x[(elx - 1) * nely + ely - 1]; };  // the code's X(ely, elx)
    const double E = 206000000.0, nu = 0.3;
    const double k[8] = {1.0 / 2.0 - nu / 6.0,
                         1.0 / 8.0 + nu / 8.0,
                         -1.0 / 4.0 - nu / 12.0,
                         -1.0 / 8.0 + 3.0 * nu / 8.0,
                         -1.0 / 4.0 + nu / 12.0,
                         -1.0 / 8.0 - nu / 8.0,
                         nu / 6.0,
                         1.0 / 8.0 - 3.0 * nu / 8.0};
    constexpr int pattern[8][8] = {{1, 2, 3, 4, 5, 6, 7, 8}, {2, 1, 8, 7, 6, 5, 4, 3}, {3, 8, 1, 6, 7, 4, 5, 2},
                                   {4, 7, 6, 1, 8, 3, 2, 5}, {5, 6, 7, 8, 1, 2, 3, 4}, {6, 5, 4, 3, 2, 1, 8, 7},
                                   {7, 4, 5, 2, 3, 8, 1, 6}, {8, 3, 2, 5, 4, 7, 6, 1}};
    Eigen::Matrix<double, 8, 8> KE;
    for (int a = 0; a < 8; ++a)
        for (int b = 0; b < 8; ++b) KE(a, b) = E / (1.0 - pw(nu, 2)) * k[pattern[a][b] - 1];
    auto edof = [](int elx, int ely, int* out) {
        const int n1 = (nely + 1) * (elx - 1) + ely, n2 = (nely + 1) * elx + ely;
        const int d[8] = {2 * n1 - 1, 2 * n1, 2 * n2 - 1, 2 * n2, 2 * n2 + 1, 2 * n2 + 2, 2 * n1 + 1, 2 * n1 + 2};
        for (int i = 0; i < 8; ++i) out[i] = d[i] - 1;
    };
    // The free degrees of freedom are those after the first 2 (nely + 1), fixed at the left edge.
    Eigen::Matrix<double, nfree, nfree> K = Eigen::Matrix<double, nfree, nfree>::Zero();
    int dofs[8];
    for (int elx = 1; elx <= nelx; ++elx)
        for (int ely = 1; ely <= nely; ++ely) {
            edof(elx, ely, dofs);
            const double scale = pw(X(ely, elx), penal);
            for (int a = 0; a < 8; ++a)
                for (int b = 0; b < 8; ++b)
                    if (dofs[a] >= nfixed && dofs[b] >= nfixed)
                        K(dofs[a] - nfixed, dofs[b] - nfixed) += scale * KE(a, b);
        }
    Eigen::Matrix<double, nfree, 1> F = Eigen::Matrix<double, nfree, 1>::Zero();
    F(nfree - 1) = -10000.0;  // the last degree of freedom
    const Eigen::Matrix<double, nfree, 1> Ufree = K.llt().solve(F);
    double U[ndof] = {};
    for (int i = 0; i < nfree; ++i) U[nfixed + i] = Ufree(i);
    double compliance = 0.0, dc[nely][nelx];
    for (int ely = 1; ely <= nely; ++ely)
        for (int elx = 1; elx <= nelx; ++elx) {
            edof(elx, ely, dofs);
            Eigen::Matrix<double, 8, 1> Ue;
            for (int i = 0; i < 8; ++i) Ue(i) = U[dofs[i]];
            const double energy = Ue.dot(KE * Ue);
            compliance = compliance + pw(X(ely, elx), penal) * energy;
            dc[ely - 1][elx - 1] = -penal * pw(X(ely, elx), penal - 1.0) * energy;
        }
    // The mesh-independency filter (the code's check), column by column into c.
    for (int i = 1; i <= nelx; ++i)
        for (int j = 1; j <= nely; ++j) {
            double sum = 0.0, dcn = 0.0;
            for (int kk = std::max(i - 1, 1); kk <= std::min(i + 1, nelx); ++kk)
                for (int l = std::max(j - 1, 1); l <= std::min(j + 1, nely); ++l) {
                    const double fac = rmin - std::sqrt(static_cast<double>((i - kk) * (i - kk) + (j - l) * (j - l)));
                    sum = sum + std::max(0.0, fac);
                    dcn = dcn + std::max(0.0, fac) * X(l, kk) * dc[l - 1][kk - 1];
                }
            c[(i - 1) * nely + (j - 1)] = dcn / (X(j, i) * sum);
        }
    return compliance;
}

// ================= Power systems

using cplx = std::complex<double>;

// I = Y V for a bus admittance matrix given by its entries (row by row, columns ascending): each
// I_r summed over the columns in order, as BLAS's zgemv does (the entries left out add 0).
template <int n>
void injected_currents(const detail::AdmittanceEntry* y, std::size_t count, const cplx* V, cplx* I) noexcept {
    for (int r = 0; r < n; ++r) I[r] = 0.0;
    for (std::size_t e = 0; e < count; ++e) I[y[e].row] += cplx(y[e].g, y[e].b) * V[y[e].column];
}

// The current mismatch at a bus, I - conj(S / V) with S = P + jQ its specified power: the real
// and imaginary parts, each an equality constraint of the power-flow problems.
void current_mismatch(cplx I, cplx V, double P, double Q, double& re, double& im) noexcept {
    const cplx spI = std::conj(cplx(P, Q) / V);
    re = I.real() - spI.real();
    im = I.imag() - spI.imag();
}

// The load's voltage dependence of RC35, RC36, RC40-RC43: P(:,1) .* (abs(V) ./ P(:,5)) .^ P(:,6).
double load(const double (*table)[6], int bus, cplx V) noexcept {
    return table[bus][0] * pw(std::abs(V) / table[bus][4], table[bus][5]);
}

// ---- RC34: single-phase distributed generation for phase balancing (30 buses, three phases)
double rc34(const double* x, double* c) noexcept {
    constexpr int n = 30;
    const cplx a1 = std::exp(cplx(0.0, 1.0) * 4.0 * kPi / 3.0), a2 = std::exp(cplx(0.0, 1.0) * 2.0 * kPi / 3.0);
    cplx V[n], I[n];
    double Psp[n] = {}, Qsp[n] = {}, Pdg[n] = {}, Qdg[n] = {};
    V[0] = 1.0;
    V[1] = a1;
    V[2] = a2;
    for (int i = 3; i < n; ++i) {
        V[i] = cplx(x[i - 3], x[27 + i - 3]);
        Psp[i] = x[54 + i - 3];
        Qsp[i] = x[81 + i - 3];
    }
    constexpr int dg[5] = {9, 16, 21, 24, 30};
    for (int i = 0; i < 5; ++i) {
        Pdg[dg[i] - 1] = x[108 + i];
        Qdg[dg[i] - 1] = x[113 + i];
    }
    injected_currents<n>(detail::kPs1Y, detail::kPs1YCount, V, I);
    for (int i = 3; i < n; ++i) {
        current_mismatch(I[i], V[i], Psp[i], Qsp[i], c[i - 3], c[27 + i - 3]);
        c[54 + i - 3] = Psp[i] - Pdg[i] - detail::kPs1P[i];
        c[81 + i - 3] = Qsp[i] - Qdg[i] - detail::kPs1Q[i];
    }
    return std::abs(I[0] + I[1] + I[2]) + std::abs(I[0] + a1 * I[1] + a2 * I[2]);
}

// ---- RC35, RC36: distributed generation (RC36: and capacitors) sized for the least active
// (RC36: active and reactive) power loss (38 buses)
double rc35_36(const double* x, double* c, bool reactive) noexcept {
    constexpr int n = 38;
    cplx V[n], I[n];
    double Psp[n] = {}, Qsp[n] = {}, Pdg[n] = {}, Qdg[n] = {};
    V[0] = 1.0;
    for (int i = 1; i < n; ++i) {
        V[i] = cplx(x[i - 1], x[37 + i - 1]);
        Psp[i] = x[74 + i - 1];
        Qsp[i] = x[111 + i - 1];
    }
    for (int i = 0; i < 5; ++i) {
        Pdg[33 + i] = x[148 + i];
        if (reactive) Qdg[33 + i] = x[153 + i];
    }
    injected_currents<n>(detail::kPs2Y, detail::kPs2YCount, V, I);
    for (int i = 1; i < n; ++i) {
        current_mismatch(I[i], V[i], Psp[i], Qsp[i], c[i - 1], c[37 + i - 1]);
        c[74 + i - 1] = Psp[i] - Pdg[i] + load(detail::kPs2P, i, V[i]);
        c[111 + i - 1] = Qsp[i] - Qdg[i] + load(detail::kPs2Q, i, V[i]);
    }
    const cplx S1 = V[0] * std::conj(I[0]);
    double sumP = 0.0, sumQ = 0.0;
    for (int i = 1; i < n; ++i) {
        sumP += Psp[i];
        sumQ += Qsp[i];
    }
    if (!reactive) return S1.real() + sumP;
    return 0.5 * (S1.real() + sumP) + 0.5 * (S1.imag() + sumQ);
}
double rc35(const double* x, double* c) noexcept {
    return rc35_36(x, c, false);
}
double rc36(const double* x, double* c) noexcept {
    return rc35_36(x, c, true);
}

// ---- RC37-RC39: optimal power flow, IEEE 30 buses: least active power loss (RC37), fuel cost
// (RC38), both (RC39)
double rc37_39(const double* x, double* c, int number) noexcept {
    constexpr int n = 30;
    cplx V[n], I[n];
    double Psp[n] = {}, Qsp[n] = {}, Pg[n] = {}, Qg[n] = {};
    V[0] = 1.0;
    for (int i = 1; i < n; ++i) {
        V[i] = cplx(x[i - 1], x[29 + i - 1]);
        Psp[i] = x[58 + i - 1];
        Qsp[i] = x[87 + i - 1];
    }
    constexpr int gen[5] = {2, 13, 22, 23, 27};
    for (int i = 0; i < 5; ++i) {
        Pg[gen[i] - 1] = x[116 + i];
        Qg[gen[i] - 1] = x[121 + i];
    }
    injected_currents<n>(detail::kPs11Y, detail::kPs11YCount, V, I);
    for (int i = 1; i < n; ++i) {
        current_mismatch(I[i], V[i], Psp[i], Qsp[i], c[i - 1], c[29 + i - 1]);
        c[58 + i - 1] = Psp[i] - Pg[i] + detail::kPs11P[i];
        c[87 + i - 1] = Qsp[i] - Qg[i] + detail::kPs11Q[i];
    }
    const double P1 = (V[0] * std::conj(I[0])).real();
    if (number == 37) {
        double sum = 0.0;
        for (int i = 1; i < n; ++i) sum += Psp[i];
        return P1 + sum;
    }
    Pg[0] = P1;
    constexpr int ng[6] = {1, 2, 13, 22, 23, 27};
    constexpr double b1[6] = {2, 1.75, 1, 3.25, 3, 3}, c1[6] = {0.02, 0.0175, 0.0625, 0.00834, 0.025, 0.0025};
    double cost = 0.0;
    for (int i = 0; i < 6; ++i) cost += 0.0 + b1[i] * Pg[ng[i] - 1] + c1[i] * pw(Pg[ng[i] - 1], 2);
    if (number == 38) return cost;
    double net = 0.0;
    for (int i = 0; i < n; ++i) net += Pg[i] - detail::kPs11P[i];
    return cost + 0.75 * net;
}
double rc37(const double* x, double* c) noexcept {
    return rc37_39(x, c, 37);
}
double rc38(const double* x, double* c) noexcept {
    return rc37_39(x, c, 38);
}
double rc39(const double* x, double* c) noexcept {
    return rc37_39(x, c, 39);
}

// The code's ybus: the admittance matrix of the 37 lines of FunctionPS14_linedata.txt at the
// frequency w (their reactances times w), dense.
void ybus(double w, cplx (*Y)[38]) noexcept {
    using detail::kPs14Lines;
    for (int r = 0; r < 38; ++r)
        for (int k = 0; k < 38; ++k) Y[r][k] = 0.0;
    cplx y[37], b[37];
    for (int k = 0; k < 37; ++k) {
        y[k] = 1.0 / cplx(kPs14Lines[k][2], kPs14Lines[k][3] * w);
        b[k] = cplx(0.0, 1.0) * kPs14Lines[k][4];
    }
    for (int k = 0; k < 37; ++k) {
        const int fb = static_cast<int>(kPs14Lines[k][0]) - 1, tb = static_cast<int>(kPs14Lines[k][1]) - 1;
        Y[fb][tb] = Y[fb][tb] - y[k] / kPs14Lines[k][5];
        Y[tb][fb] = Y[fb][tb];
    }
    for (int m = 0; m < 38; ++m)
        for (int k = 0; k < 37; ++k) {
            if (static_cast<int>(kPs14Lines[k][0]) - 1 == m)
                Y[m][m] = Y[m][m] + y[k] / pw(kPs14Lines[k][5], 2) + b[k];
            else if (static_cast<int>(kPs14Lines[k][1]) - 1 == m)
                Y[m][m] = Y[m][m] + y[k] + b[k];
        }
}

// ---- RC40, RC42, RC43: islanded microgrid (38 buses, droop-controlled generators at 34-38):
// power flow (RC40), droop settings for the least active (RC42) or active and reactive (RC43) loss
double islanded(const double* x, double* c, int number) noexcept {
    constexpr int n = 38;
    cplx V[n], I[n], Y[n][n];
    double Pc[n] = {}, Qc[n] = {}, Psp[n], Qsp[n];
    for (int i = 1; i < n; ++i) V[i] = cplx(x[i - 1], x[37 + i - 1]);
    if (number == 40) {
        constexpr double p[5] = {5.102e-03, 1.502e-03, 4.506e-03, 2.253e-03, 2.253e-03},
                         q[5] = {0.05, 0.03, 0.05, 0.01, 0.1};
        for (int i = 0; i < 5; ++i) {
            Pc[33 + i] = 1.0 / p[i];
            Qc[33 + i] = 1.0 / q[i];
        }
    } else {
        for (int i = 0; i < 5; ++i) {
            Pc[33 + i] = x[76 + i];
            Qc[33 + i] = x[81 + i];
        }
    }
    const double w = x[74];
    V[0] = x[75] + 1e-5;
    ybus(w, Y);
    for (int r = 0; r < n; ++r) {
        I[r] = 0.0;
        for (int k = 0; k < n; ++k) I[r] += Y[r][k] * V[k];
    }
    double f = 0.0, sumP = 0.0, sumQ = 0.0;
    for (int i = 0; i < n; ++i) {
        const double Vr = V[i].real(), Vm = V[i].imag();
        Psp[i] = Pc[i] * (1.0 - w) - load(detail::kPs2P, i, V[i]);
        Qsp[i] = Qc[i] * (1.0 - std::sqrt(pw(Vr, 2) + pw(Vm, 2))) - load(detail::kPs2Q, i, V[i]);
        current_mismatch(I[i], V[i], Psp[i], Qsp[i], c[i], c[n + i]);
        sumP += Psp[i];
        sumQ += Qsp[i];
    }
    if (number == 42) return sumP;
    if (number == 43) return 0.5 * (sumQ + sumP);
    double sumP2 = 0.0, sumQ2 = 0.0;
    for (int i = 0; i < n; ++i) {
        const double Vr = V[i].real(), Vm = V[i].imag(), Ir = I[i].real(), Im = I[i].imag();
        sumP2 += pw(Psp[i] - (Vr * Ir + Vm * Im), 2);
        sumQ2 += pw(Qsp[i] - (Vm * Ir - Vr * Im), 2);
    }
    f = sumP2 + sumQ2;
    return f;
}
double rc40(const double* x, double* c) noexcept {
    return islanded(x, c, 40);
}
double rc42(const double* x, double* c) noexcept {
    return islanded(x, c, 42);
}
double rc43(const double* x, double* c) noexcept {
    return islanded(x, c, 43);
}

// ---- RC41: grid-connected microgrid power flow (38 buses, generators at 34-38)
double rc41(const double* x, double* c) noexcept {
    constexpr int n = 38;
    cplx V[n], I[n];
    double Pdg[n] = {}, Qdg[n] = {};
    for (int i = 33; i < n; ++i) {
        Pdg[i] = 0.2;
        Qdg[i] = 0.18;
    }
    V[0] = 1.0;
    for (int i = 1; i < n; ++i) V[i] = cplx(x[i - 1], x[37 + i - 1]);
    injected_currents<n>(detail::kPs2Y, detail::kPs2YCount, V, I);
    double sumP = 0.0, sumQ = 0.0;
    for (int i = 1; i < n; ++i) {
        const double Vr = V[i].real(), Vm = V[i].imag(), Ir = I[i].real(), Im = I[i].imag();
        const double Psp = Pdg[i] - load(detail::kPs2P, i, V[i]);
        const double Qsp = Qdg[i] - load(detail::kPs2Q, i, V[i]);
        current_mismatch(I[i], V[i], Psp, Qsp, c[i - 1], c[37 + i - 1]);
        sumP += pw(Psp - (Vr * Ir + Vm * Im), 2);
        sumQ += pw(Qsp - (Vm * Ir - Vr * Im), 2);
    }
    return sumP + sumQ;
}

// ---- RC44: wind farm layout, 15 turbines at (x_{2i-1}, x_{2i}); Jensen's wake model over 24
// wind directions. cosd and sind as Octave computes them off the multiples of 90 degrees:
// cos(theta / 180 * pi), sin(theta / 180 * pi).
double rc44(const double* x, double* c) noexcept {
    constexpr int N = 15, interval_num = 24;
    const double interval = 15, cut_in_speed = 3.5, rated_speed = 14, cut_out_speed = 25, R = 40, CT = 0.8;
    const double a = 1.0 - std::sqrt(1.0 - CT), kappa = 0.01, k = 2;
    constexpr double cs[24] = {7,  5,   5,   5,   5,   4,   5, 6, 7,   7,   8,   9.5,
                               10, 8.5, 8.5, 6.5, 4.6, 2.6, 8, 5, 6.4, 5.2, 4.5, 3.9};
    constexpr double fre[24] = {0.0003, 0.0072, 0.0237, 0.0242, 0.0222, 0.0301, 0.0397, 0.0268,
                                0.0626, 0.0801, 0.1025, 0.1445, 0.1909, 0.1162, 0.0793, 0.0082,
                                0.0041, 0.0008, 0.0010, 0.0005, 0.0013, 0.0031, 0.0085, 0.0222};
    const double n_ws = (rated_speed - cut_in_speed) / 0.3;  // 35: the loop j = 1:n_ws
    double all_power = 0.0;
    for (int d = 1; d <= interval_num; ++d) {
        const double theta = (d - 0.5) * interval;
        const double cosd = std::cos(theta / 180.0 * kPi), sind = std::sin(theta / 180.0 * kPi);
        double sum_power = 0.0;
        for (int i = 1; i <= N; ++i) {  // downstream turbine i
            double vel_def_i = 0.0;
            for (int j = 1; j <= N; ++j) {  // upstream turbine j
                const double Tijx = x[2 * i - 2] - x[2 * j - 2];
                const double Tijy = x[2 * i - 1] - x[2 * j - 1];
                const double dij = cosd * Tijx + sind * Tijy;
                const double square = (pw(Tijx, 2) + pw(Tijy, 2)) - pw(dij, 2);
                // MATLAB's sqrt of a negative rounding residue is imaginary; > compares real parts.
                const double lij = square < 0.0 ? 0.0 : std::sqrt(square);
                const double l = dij * kappa + R;
                if (j != i && l > lij - R && dij > 0.0) {
                    const double def = a / pw(1.0 + kappa * dij / R, 2);
                    vel_def_i = vel_def_i + pw(def, 2);
                }
            }
            const double interval_c = cs[d - 1] * (1.0 - std::sqrt(vel_def_i));
            double power = 0.0;
            for (int j = 1; j <= n_ws; ++j) {
                const double v_j_1 = cut_in_speed + (j - 1) * 0.3, v_j = cut_in_speed + j * 0.3;
                const double e = std::exp((v_j_1 + v_j) / 2.0 - 7.5);
                power = power + 1500.0 * e / (5.0 + e) *
                                    (std::exp(-pw(v_j_1 / interval_c, k)) - std::exp(-pw(v_j / interval_c, k)));
            }
            power = power + 1500.0 * (std::exp(-pw(rated_speed / interval_c, k)) -
                                      std::exp(-pw(cut_out_speed / interval_c, k)));
            sum_power += power;
        }
        all_power = all_power + fre[d - 1] * sum_power;
    }
    // As coded, j runs from i + 1 to 14: the pairs with turbine 15 are left out (91 constraints).
    int m = 0;
    for (int i = 1; i <= N; ++i)
        for (int j = i + 1; j <= N - 1; ++j)
            c[m++] = 5.0 * R - std::sqrt(pw(x[2 * i - 2] - x[2 * j - 2], 2) + pw(x[2 * i - 1] - x[2 * j - 1], 2));
    return -all_power;
}

// ================= Power electronics: SOPWM for multilevel inverters (angles in degrees)

constexpr double kHarmonics[31] = {5,  7,  11, 13, 17, 19, 23, 25, 29, 31, 35, 37, 41, 43, 47, 49,
                                   53, 55, 59, 61, 65, 67, 71, 73, 77, 79, 83, 85, 91, 95, 97};
constexpr double kSigns46[25] = {1, -1, 1, 1, -1, 1, -1, 1, -1, -1, 1, -1, 1, 1, -1, 1, -1, 1, -1, -1, 1, -1, 1, 1, -1};
constexpr double kSigns47[25] = {1, -1, 1, 1, 1, -1, -1, -1, 1, 1, -1, -1, 1, 1, 1, -1, -1, -1, 1, 1, -1, -1, 1, 1, 1};
constexpr double kSigns48[30] = {1, 1,  1, 1,  -1, 1,  -1, -1, -1, 1, -1, -1, 1, 1,  1,
                                 1, -1, 1, -1, -1, -1, 1,  -1, -1, 1, 1,  1,  1, -1, 1};
constexpr double kSigns49[30] = {1,  -1, 1,  1, 1, -1, -1, -1, 1, 1, 1,  1,  -1, -1, 1,
                                 -1, -1, -1, 1, 1, 1,  1,  -1, 1, 1, -1, -1, 1,  -1, -1};
constexpr double kSigns50[30] = {1,  1, 1,  -1, 1,  -1, 1, -1, 1, 1,  1,  1,  -1, -1, -1,
                                 -1, 1, -1, 1,  -1, 1,  1, 1,  1, -1, -1, -1, 1,  -1, 1};

// f = scale sqrt(sum_j (sum_l s_l cos(k_j x_l))^2 / k_j^4) / sqrt(sum_j 1 / k_j^4), g_l = x_l -
// x_{l+1} + 1e-6, h = sum_l s_l cos(x_l) - target. `scale`: the code's 1/levels factor, written
// before the root when `scaled` (RC45's f has none).
double sopwm(const double* x, double* c, int D, const double* s, double scale, bool scaled, double target) noexcept {
    double su = 0.0;
    for (int j = 0; j < 31; ++j) {
        double su2 = 0.0;
        for (int l = 0; l < D; ++l) su2 = su2 + s[l] * std::cos(kHarmonics[j] * x[l] * kPi / 180.0);
        su = su + pw(su2, 2) / pw(kHarmonics[j], 4);
    }
    double norm = 0.0;
    for (int j = 0; j < 31; ++j) norm += 1.0 / pw(kHarmonics[j], 4);
    const double f = scaled ? scale * pw(su, 0.5) / pw(norm, 0.5) : pw(su, 0.5) / pw(norm, 0.5);
    for (int i = 0; i < D - 1; ++i) c[i] = x[i] - x[i + 1] + 1e-6;
    double h = 0.0;
    for (int l = 0; l < D; ++l) h += s[l] * std::cos(x[l] * kPi / 180.0);
    c[D - 1] = h - target;
    return f;
}

double rc45(const double* x, double* c) noexcept {
    double s[25];
    for (int i = 0; i < 25; ++i) s[i] = i % 2 == 0 ? 1.0 : -1.0;  // (-1)^(2:26)
    return sopwm(x, c, 25, s, 1.0, false, 0.32);
}
double rc46(const double* x, double* c) noexcept {
    return sopwm(x, c, 25, kSigns46, 0.5, true, 2.0 * 0.32);
}
double rc47(const double* x, double* c) noexcept {
    return sopwm(x, c, 25, kSigns47, 1.0 / 3.0, true, 3.0 * 0.36);
}
double rc48(const double* x, double* c) noexcept {
    return sopwm(x, c, 30, kSigns48, 1.0 / 4.0, true, 4.0 * 0.32);
}
double rc49(const double* x, double* c) noexcept {
    return sopwm(x, c, 30, kSigns49, 1.0 / 5.0, true, 5.0 * 0.3333);
}
double rc50(const double* x, double* c) noexcept {
    return sopwm(x, c, 30, kSigns50, 1.0 / 6.0, true, 6.0 * 0.32);
}

// ================= Livestock feed ration

// sum(x .* row): left to right, as MATLAB's sum of a row.
double dot(const double* x, const double* row, int n) noexcept {
    double s = x[0] * row[0];
    for (int i = 1; i < n; ++i) s = s + x[i] * row[i];
    return s;
}
double total(const double* x, int from, int to) noexcept {  // sum(x(from:to)), 1-based inclusive
    double s = x[from - 1];
    for (int i = from; i < to; ++i) s = s + x[i];
    return s;
}

// RC51-RC54: the four beef cattle cases differ in their bounds only: lower and upper bounds on
// rows 5, 4, 6, 7 of the feed table, on the share of x1..x17, on the share of row 3, on the sum of
// x34..x59, and the target of row 2.
struct BeefCase {
    double b[14];
    double target;
};
constexpr BeefCase kBeef[4] = {
    {{1.090, 2.170, 4.870, 5.200, 0.043, 0.086, 0.023, 0.046, 0.295, 0.36, 0.3, 0.4712, 9.2, 11.5}, 6.9},
    {{1.280, 2.560, 7.300, 7.810, 0.005, 0.094, 0.031, 0.062, 0.2, 0.24, 0.3, 0.4, 9.8, 16.4}, 9.8},
    {{1.170, 2.340, 6.940, 7.430, 0.038, 0.076, 0.034, 0.068, 0.085, 0.111, 0.25, 0.4, 11.6, 14.5}, 8.7},
    {{0.56, 1.12, 3.23, 3.46, 0.018, 0.036, 0.0116, 0.040, 0.25, 0.9, 0.3, 0.4384, 7.470, 9.340}, 5.6},
};

double beef(const double* x, double* c, const BeefCase& k) noexcept {
    using detail::kFeed;
    constexpr int n = 59;
    const double p5 = dot(x, kFeed[4], n), p4 = dot(x, kFeed[3], n), p6 = dot(x, kFeed[5], n);
    const double p7 = dot(x, kFeed[6], n), p3 = dot(x, kFeed[2], n), all = total(x, 1, n);
    const double first = total(x, 1, 17), last = total(x, 34, 59);
    c[0] = -p5 + k.b[0];
    c[1] = p5 - k.b[1];
    c[2] = -p4 + k.b[2];
    c[3] = p4 - k.b[3];
    c[4] = -p6 + k.b[4];
    c[5] = p6 - k.b[5];
    c[6] = -p7 + k.b[6];
    c[7] = p7 - k.b[7];
    c[8] = -first / all + k.b[8];
    c[9] = first / all - k.b[9];
    c[10] = -p3 / all + k.b[10];
    c[11] = p3 / all - k.b[11];
    c[12] = -last + k.b[12];
    c[13] = last - k.b[13];
    c[14] = dot(x, kFeed[1], n) - k.target;
    return dot(x, kFeed[0], n);
}

// RC55-RC57: the three dairy cattle cases: targets of rows 12, 2, 3, 13, 14 and of the column sums
// of rows 2..11 of the dairy table.
constexpr double kDairyTargets[3][6] = {
    {25.67, 0.0218, 0.062, 0.034, 0.021, 0.999},
    {65.24, 0.066, 0.159, 0.103, 0.052, 2.644},
    {30.05, 0.0259, 0.077, 0.096, 0.025, 1.214},
};

double dairy(const double* x, double* c, const double* targets) noexcept {
    using detail::kDairy;
    constexpr int n = 64;
    double sums[n];
    for (int j = 0; j < n; ++j) {
        double v = kDairy[1][j];
        for (int i = 2; i <= 10; ++i) v = v + kDairy[i][j];
        sums[j] = v;
    }
    c[0] = dot(x, kDairy[11], n) - targets[0];
    c[1] = dot(x, kDairy[1], n) - targets[1];
    c[2] = dot(x, kDairy[2], n) - targets[2];
    c[3] = dot(x, kDairy[12], n) - targets[3];
    c[4] = dot(x, kDairy[13], n) - targets[4];
    c[5] = dot(sums, x, n) - targets[5];
    return dot(x, kDairy[0], n);
}

// ================= The table of problems

using Function = double (*)(const double*, double*) noexcept;

double rc51(const double* x, double* c) noexcept {
    return beef(x, c, kBeef[0]);
}
double rc52(const double* x, double* c) noexcept {
    return beef(x, c, kBeef[1]);
}
double rc53(const double* x, double* c) noexcept {
    return beef(x, c, kBeef[2]);
}
double rc54(const double* x, double* c) noexcept {
    return beef(x, c, kBeef[3]);
}
double rc55(const double* x, double* c) noexcept {
    return dairy(x, c, kDairyTargets[0]);
}
double rc56(const double* x, double* c) noexcept {
    return dairy(x, c, kDairyTargets[1]);
}
double rc57(const double* x, double* c) noexcept {
    return dairy(x, c, kDairyTargets[2]);
}

// ================= Bounds (Cal_par.m)

template <std::size_t N>
constexpr std::array<double, N> filled(double v) {
    std::array<double, N> a{};
    for (auto& e : a) e = v;
    return a;
}
// `base` with the 1-based positions `at` set to v.
template <std::size_t N, std::size_t K>
constexpr std::array<double, N> with(std::array<double, N> base, const int (&at)[K], double v) {
    for (const int i : at) base[i - 1] = v;
    return base;
}
template <std::size_t N>
constexpr std::array<double, N> with_range(std::array<double, N> base, int from, int to, double v) {
    for (int i = from; i <= to; ++i) base[i - 1] = v;
    return base;
}

constexpr std::array<double, 9> kLo01 = {0, 0, 0, 0, 1000, 0, 100, 100, 100};
constexpr std::array<double, 9> kHi01 = {10, 200, 100, 200, 2000000, 600, 600, 600, 900};
constexpr std::array<double, 11> kLo02 = {1e4, 1e4, 1e4, 0, 0, 0, 100, 100, 100, 100, 100};
constexpr std::array<double, 11> kHi02 = {0.819 * 1e6, 1.131 * 1e6, 2.05 * 1e6, 0.05074, 0.05074, 0.05074,
                                          200,         300,         300,        300,     400};
constexpr std::array<double, 7> kLo03 = {1000, 0, 2000, 0, 0, 0, 0};
constexpr std::array<double, 7> kHi03 = {2000, 100, 4000, 100, 100, 20, 200};
constexpr std::array<double, 6> kLo04 = {0, 0, 0, 0, 1e-5, 1e-5};
constexpr std::array<double, 6> kHi04 = {1, 1, 1, 1, 16, 16};
constexpr auto kLo05 = filled<9>(0);
constexpr std::array<double, 9> kHi05 = {100, 200, 100, 100, 100, 100, 200, 100, 200};
constexpr auto kLo06 = filled<38>(0);
constexpr std::array<double, 38> kHi06 = {90, 150, 90,  150, 90,  90,  150, 90,  90,  90,  150, 150, 90,
                                          90, 150, 90,  150, 90,  150, 90,  1,   1.2, 1,   1,   1,   0.5,
                                          1,  1,   0.5, 0.5, 0.5, 1.2, 0.5, 1.2, 1.2, 0.5, 1.2, 1.2};
constexpr auto kLo07 = with(filled<48>(0), {24, 26, 28, 31}, 0.849999);
constexpr auto kHi07 =
    with(with(with(with(filled<48>(1), {4}, 140), {25, 27, 32, 35, 37, 29}, 30), {2, 3, 5, 13, 14, 15}, 90),
         {1, 6, 7, 8, 9, 10, 11, 12, 16, 17, 18, 19, 20}, 35);
constexpr std::array<double, 2> kLo08 = {0, -0.51};
constexpr std::array<double, 2> kHi08 = {1.6, 1.49};
constexpr std::array<double, 3> kLo09 = {0.5, 0.5, -0.51};
constexpr std::array<double, 3> kHi09 = {1.4, 1.4, 1.49};
constexpr std::array<double, 3> kLo10 = {0.2, -2.22554, -0.51};
constexpr std::array<double, 3> kHi10 = {1, -1, 1.49};
constexpr std::array<double, 7> kLo11 = {0, 0, 0, 0, -0.51, -0.51, 0};
constexpr std::array<double, 7> kHi11 = {20, 20, 10, 10, 1.49, 1.49, 40};
constexpr std::array<double, 7> kLo12 = {0, 0, 0, -0.51, -0.51, -0.51, -0.51};
constexpr std::array<double, 7> kHi12 = {100, 100, 100, 1.49, 1.49, 1.49, 1.49};
constexpr std::array<double, 5> kLo13 = {27, 27, 27, 77.51, 32.51};
constexpr std::array<double, 5> kHi13 = {45, 45, 45, 102.49, 45.49};
constexpr std::array<double, 10> kLo14 = {0.51, 0.51, 0.51, 250, 250, 250, 6, 4, 40, 10};
constexpr std::array<double, 10> kHi14 = {3.49, 3.49, 3.49, 2500, 2500, 2500, 20, 16, 700, 450};
constexpr std::array<double, 7> kLo15 = {2.6, 0.7, 17, 7.3, 7.3, 2.9, 5};
constexpr std::array<double, 7> kHi15 = {3.6, 0.8, 28, 8.3, 8.3, 3.9, 5.5};
constexpr auto kLo16 = filled<14>(0.001);
constexpr auto kHi16 = filled<14>(5);
constexpr std::array<double, 3> kLo17 = {0.05, 0.25, 2.00};
constexpr std::array<double, 3> kHi17 = {2, 1.3, 15.0};
constexpr std::array<double, 4> kLo18 = {0.51, 0.51, 10, 10};
constexpr std::array<double, 4> kHi18 = {99.49, 99.49, 200, 200};
constexpr std::array<double, 4> kLo19 = {0.125, 0.1, 0.1, 0.1};
constexpr std::array<double, 4> kHi19 = {2, 10, 10, 2};
constexpr auto kLo20 = filled<2>(0);
constexpr auto kHi20 = filled<2>(1);
constexpr std::array<double, 5> kLo21 = {60, 90, 1, 0, 2};
constexpr std::array<double, 5> kHi21 = {80, 110, 3, 1000, 9};
constexpr std::array<double, 9> kLo22 = {16.51, 13.51, 13.51, 16.51, 13.51, 47.51, 0.51, 0.51, 0.51};
constexpr std::array<double, 9> kHi22 = {96.49, 54.49, 51.49, 46.49, 51.49, 124.49, 3.49, 6.49, 6.49};
constexpr auto kLo23 = filled<5>(0);
constexpr std::array<double, 5> kHi23 = {60, 60, 90, 90, 90};
constexpr std::array<double, 7> kLo24 = {10, 10, 100, 0, 10, 100, 1};
constexpr std::array<double, 7> kHi24 = {150, 150, 200, 50, 150, 300, 3.14};
constexpr std::array<double, 4> kLo25 = {1, 1, 1e-6, 1};
constexpr std::array<double, 4> kHi25 = {16, 16, 16 * 1e-6, 16};
constexpr auto kLo26 = with_range(filled<22>(6.51), 9, 22, 0.51);
constexpr auto kHi26 = with_range(with_range(filled<22>(76.49), 9, 12, 4.49), 13, 22, 9.49);
constexpr auto kLo27 = filled<10>(0.645e-4);
constexpr auto kHi27 = filled<10>(50e-4);
constexpr std::array<double, 10> kLo28 = {125, 10.5, 4.51, 0.515, 0.515, 0.4, 0.6, 0.3, 0.02, 0.6};
constexpr std::array<double, 10> kHi28 = {150, 31.5, 50.49, 0.6, 0.6, 0.5, 0.7, 0.4, 0.1, 0.85};
constexpr std::array<double, 4> kLo29 = {20, 1, 20, 0.1};
constexpr std::array<double, 4> kHi29 = {50, 10, 50, 60};
constexpr std::array<double, 3> kLo30 = {0.51, 0.6, 0.51};
constexpr std::array<double, 3> kHi30 = {70.49, 3, 42.49};
constexpr auto kLo31 = filled<4>(12);
constexpr auto kHi31 = filled<4>(60);
constexpr std::array<double, 5> kLo32 = {78, 33, 27, 27, 27};
constexpr std::array<double, 5> kHi32 = {102, 45, 45, 45, 45};
constexpr auto kLo33 = filled<30>(0.001);
constexpr auto kHi33 = filled<30>(1);
constexpr auto kLo34 = filled<118>(-1);
constexpr auto kHi34 = filled<118>(1);
constexpr auto kLo35 = filled<153>(-1);
constexpr auto kHi35 = filled<153>(1);
constexpr auto kLo36 = filled<158>(-1);
constexpr auto kHi36 = filled<158>(1);
constexpr auto kLo37 = with_range(filled<126>(-1), 117, 126, 0);
constexpr auto kHi37 = filled<126>(1);
constexpr auto kLo40 = with_range(filled<76>(-1), 75, 76, 0);
constexpr auto kHi40 = with_range(filled<76>(1), 75, 76, 2);
constexpr auto kLo41 = filled<74>(-1);
constexpr auto kHi41 = filled<74>(1);
constexpr auto kLo42 = with_range(filled<86>(-1), 75, 86, 0);
constexpr auto kHi42 = with_range(with_range(filled<86>(1), 75, 76, 2), 77, 86, 500);
constexpr auto kLo44 = filled<30>(40);
constexpr auto kHi44 = filled<30>(1960);
constexpr auto kLo45 = filled<25>(0);
constexpr auto kHi45 = filled<25>(90);
constexpr auto kLo48 = filled<30>(0);
constexpr auto kHi48 = filled<30>(90);
constexpr auto kLo51 = filled<59>(0);
constexpr auto kHi51 = filled<59>(10);
constexpr auto kLo55 = filled<64>(0);
constexpr auto kHi55 = filled<64>(10);

struct Spec {
    std::string_view name;
    Function function;  // nullptr: not implemented
    std::size_t inequalities, equalities;
    double best_value;  // Table 3
    std::span<const double> lower, upper;
};

// Counts as the code returns them (RC17, RC21, RC44 differ from Cal_par.m: see the header).
const Spec kSpecs[kProblems] = {
    {"RC01", rc01, 0, 8, 1.8931162966E+02, kLo01, kHi01},   {"RC02", rc02, 0, 9, 7.0490369540E+03, kLo02, kHi02},
    {"RC03", rc03, 14, 0, -4.5291197395E+03, kLo03, kHi03}, {"RC04", rc04, 1, 4, -3.8826043623E-01, kLo04, kHi04},
    {"RC05", rc05, 2, 4, -4.0000560000E+02, kLo05, kHi05},  {"RC06", rc06, 0, 32, 1.8638304088E+00, kLo06, kHi06},
    {"RC07", rc07, 0, 38, 2.1158627569E+00, kLo07, kHi07},  {"RC08", rc08, 2, 0, 2.0000000000E+00, kLo08, kHi08},
    {"RC09", rc09, 1, 1, 2.5576545740E+00, kLo09, kHi09},   {"RC10", rc10, 3, 0, 1.0765430833E+00, kLo10, kHi10},
    {"RC11", rc11, 4, 4, 9.9238463653E+01, kLo11, kHi11},   {"RC12", rc12, 9, 0, 2.9248305537E+00, kLo12, kHi12},
    {"RC13", rc13, 3, 0, 2.6887000000E+04, kLo13, kHi13},   {"RC14", rc14, 10, 0, 5.3638942722E+04, kLo14, kHi14},
    {"RC15", rc15, 11, 0, 2.9944244658E+03, kLo15, kHi15},  {"RC16", rc16, 15, 0, 3.2213000814E-02, kLo16, kHi16},
    {"RC17", rc17, 4, 0, 1.2665232788E-02, kLo17, kHi17},   {"RC18", rc18, 4, 0, 5.8853327736E+03, kLo18, kHi18},
    {"RC19", rc19, 5, 0, 1.6702177263E+00, kLo19, kHi19},   {"RC20", rc20, 3, 0, 2.6389584338E+02, kLo20, kHi20},
    {"RC21", rc21, 8, 0, 2.3524245790E-01, kLo21, kHi21},   {"RC22", rc22, 10, 1, 5.2576870748E-01, kLo22, kHi22},
    {"RC23", rc23, 8, 3, 1.6069868725E+01, kLo23, kHi23},   {"RC24", nullptr, 7, 0, 2.5287918415E+00, kLo24, kHi24},
    {"RC25", rc25, 7, 0, 1.6254428092E+03, kLo25, kHi25},   {"RC26", rc26, 86, 0, 3.5359231973E+01, kLo26, kHi26},
    {"RC27", rc27, 3, 0, 5.2445076066E+02, kLo27, kHi27},   {"RC28", rc28, 9, 0, 1.4614135715E+04, kLo28, kHi28},
    {"RC29", rc29, 1, 0, 2.9648954173E+06, kLo29, kHi29},   {"RC30", rc30, 8, 0, 2.6138840583E+00, kLo30, kHi30},
    {"RC31", rc31, 1, 1, 0.0000000000E+00, kLo31, kHi31},   {"RC32", rc32, 6, 0, -3.0665538672E+04, kLo32, kHi32},
    {"RC33", rc33, 30, 0, 2.6393464970E+00, kLo33, kHi33},  {"RC34", rc34, 0, 108, 0.0000000000E+00, kLo34, kHi34},
    {"RC35", rc35, 0, 148, 8.9093896456E-02, kLo35, kHi35}, {"RC36", rc36, 0, 148, 7.2066551720E-02, kLo36, kHi36},
    {"RC37", rc37, 0, 116, 2.1962851478E-02, kLo37, kHi37}, {"RC38", rc38, 0, 116, 2.7766131989E+00, kLo37, kHi37},
    {"RC39", rc39, 0, 116, 2.8677165770E+00, kLo37, kHi37}, {"RC40", rc40, 0, 76, 0.0000000000E+00, kLo40, kHi40},
    {"RC41", rc41, 0, 74, 0.0000000000E+00, kLo41, kHi41},  {"RC42", rc42, 0, 76, 8.6241006360E-02, kLo42, kHi42},
    {"RC43", rc43, 0, 76, 8.0420545897E-02, kLo42, kHi42},  {"RC44", rc44, 91, 0, -6.2607000000E+03, kLo44, kHi44},
    {"RC45", rc45, 24, 1, 3.8029250566E-02, kLo45, kHi45},  {"RC46", rc46, 24, 1, 2.1215000000E-02, kLo45, kHi45},
    {"RC47", rc47, 24, 1, 1.5164538375E-02, kLo45, kHi45},  {"RC48", rc48, 29, 1, 1.6787535766E-02, kLo48, kHi48},
    {"RC49", rc49, 29, 1, 9.3118741800E-03, kLo48, kHi48},  {"RC50", rc50, 29, 1, 1.5096451396E-02, kLo48, kHi48},
    {"RC51", rc51, 14, 1, 4.5508511497E+03, kLo51, kHi51},  {"RC52", rc52, 14, 1, 3.3489821493E+03, kLo51, kHi51},
    {"RC53", rc53, 14, 1, 4.9976069290E+03, kLo51, kHi51},  {"RC54", rc54, 14, 1, 4.2405482538E+03, kLo51, kHi51},
    {"RC55", rc55, 0, 6, 6.6964145128E+03, kLo55, kHi55},   {"RC56", rc56, 0, 6, 1.4748932529E+04, kLo55, kHi55},
    {"RC57", rc57, 0, 6, 3.2132917019E+03, kLo55, kHi55},
};

// The most constraint values a problem writes (RC35, RC36: 148 equalities).
constexpr std::size_t kMaxConstraints = 148;

const Spec& spec(int number) {
    require(number >= 1 && number <= kProblems, "problem",
            "CEC 2020 real-world has problems 1 to " + std::to_string(kProblems) + " (RC01 ... RC57), got " +
                std::to_string(number));
    const Spec& s = kSpecs[number - 1];
    require(s.function != nullptr, "problem",
            "CEC 2020 real-world " + std::string(s.name) + " is not implemented in pride yet");
    return s;
}

}  // namespace

bool implemented(int number) noexcept {
    return number >= 1 && number <= kProblems && kSpecs[number - 1].function != nullptr;
}

Problem::Problem(int number) : number_(number) {
    const Spec& s = spec(number);
    name_ = s.name;
    counts_ = {s.inequalities, s.equalities};
    lower_ = s.lower;
    upper_ = s.upper;
    best_value_ = s.best_value;
}

double Problem::evaluate(std::span<const double> x) const noexcept {
    assert(x.size() == dimension());
    std::array<double, kMaxConstraints> scratch;
    return kSpecs[number_ - 1].function(x.data(), scratch.data());
}

double Problem::evaluate_constrained(std::span<const double> x, std::span<double> c) const noexcept {
    assert(x.size() == dimension() && c.size() >= counts_.total());
    return kSpecs[number_ - 1].function(x.data(), c.data());
}

}  // namespace pride::continuous::cec2020rw

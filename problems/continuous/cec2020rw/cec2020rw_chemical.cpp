// The CEC 2020 real-world suite's industrial chemical processes, RC01-RC07, as cec20_func.m
// computes them (cec2020rw_detail.hpp).
#include "problems/continuous/cec2020rw/cec2020rw_detail.hpp"

#include <cmath>

namespace pride::continuous::cec2020rw::detail {

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

}  // namespace pride::continuous::cec2020rw::detail

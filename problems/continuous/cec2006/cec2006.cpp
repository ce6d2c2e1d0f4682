// The 24 problems of Liang et al. (2006), each one function from the report's equations: f(x), and
// when c is given the inequality values then the equality values into c. Indices below are the
// report's minus one (x[0] is x1). Their boxes, x* and f* are the suite's table (cec2006_table.cpp).
#include "problems/continuous/cec2006/cec2006.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

#include "problems/continuous/cec2006/cec2006_detail.hpp"

namespace pride::continuous::cec2006 {

namespace {

double sq(double v) noexcept {
    return v * v;
}
double cube(double v) noexcept {
    return v * v * v;
}

// ---- g01 (eqs. 4-5)
double g01(const double* x, double* c) noexcept {
    double f = 0.0;
    for (int i = 0; i < 4; ++i) f += 5.0 * x[i] - 5.0 * x[i] * x[i];
    for (int i = 4; i < 13; ++i) f -= x[i];
    if (c) {
        c[0] = 2.0 * x[0] + 2.0 * x[1] + x[9] + x[10] - 10.0;
        c[1] = 2.0 * x[0] + 2.0 * x[2] + x[9] + x[11] - 10.0;
        c[2] = 2.0 * x[1] + 2.0 * x[2] + x[10] + x[11] - 10.0;
        c[3] = -8.0 * x[0] + x[9];
        c[4] = -8.0 * x[1] + x[10];
        c[5] = -8.0 * x[2] + x[11];
        c[6] = -2.0 * x[3] - x[4] + x[9];
        c[7] = -2.0 * x[5] - x[6] + x[10];
        c[8] = -2.0 * x[7] - x[8] + x[11];
    }
    return f;
}

// ---- g02 (eqs. 6-7), n = 20
double g02(const double* x, double* c) noexcept {
    constexpr int n = 20;
    double sum_cos4 = 0.0, prod_cos2 = 1.0, weighted = 0.0;
    for (int i = 0; i < n; ++i) {
        const double cs = sq(std::cos(x[i]));
        sum_cos4 += cs * cs;
        prod_cos2 *= cs;
        weighted += (i + 1) * x[i] * x[i];
    }
    if (c) {
        double prod = 1.0, sum = 0.0;
        for (int i = 0; i < n; ++i) {
            prod *= x[i];
            sum += x[i];
        }
        c[0] = 0.75 - prod;
        c[1] = sum - 7.5 * n;
    }
    return -std::abs((sum_cos4 - 2.0 * prod_cos2) / std::sqrt(weighted));
}

// ---- g03 (eqs. 8-9), n = 10: (sqrt n)^n = 1e5 exactly
double g03(const double* x, double* c) noexcept {
    double prod = 1.0, sum_sq = 0.0;
    for (int i = 0; i < 10; ++i) {
        prod *= x[i];
        sum_sq += x[i] * x[i];
    }
    if (c) c[0] = sum_sq - 1.0;
    return -1e5 * prod;
}

// ---- g04 (eqs. 10-11)
double g04(const double* x, double* c) noexcept {
    if (c) {
        const double u = 85.334407 + 0.0056858 * x[1] * x[4] + 0.0006262 * x[0] * x[3] - 0.0022053 * x[2] * x[4];
        const double v = 80.51249 + 0.0071317 * x[1] * x[4] + 0.0029955 * x[0] * x[1] + 0.0021813 * x[2] * x[2];
        const double w = 9.300961 + 0.0047026 * x[2] * x[4] + 0.0012547 * x[0] * x[2] + 0.0019085 * x[2] * x[3];
        c[0] = u - 92.0;
        c[1] = -u;
        c[2] = v - 110.0;
        c[3] = -v + 90.0;
        c[4] = w - 25.0;
        c[5] = -w + 20.0;
    }
    return 5.3578547 * x[2] * x[2] + 0.8356891 * x[0] * x[4] + 37.293239 * x[0] - 40792.141;
}

// ---- g05 (eqs. 12-13)
double g05(const double* x, double* c) noexcept {
    if (c) {
        c[0] = -x[3] + x[2] - 0.55;
        c[1] = -x[2] + x[3] - 0.55;
        c[2] = 1000.0 * std::sin(-x[2] - 0.25) + 1000.0 * std::sin(-x[3] - 0.25) + 894.8 - x[0];
        c[3] = 1000.0 * std::sin(x[2] - 0.25) + 1000.0 * std::sin(x[2] - x[3] - 0.25) + 894.8 - x[1];
        c[4] = 1000.0 * std::sin(x[3] - 0.25) + 1000.0 * std::sin(x[3] - x[2] - 0.25) + 1294.8;
    }
    return 3.0 * x[0] + 0.000001 * cube(x[0]) + 2.0 * x[1] + (0.000002 / 3.0) * cube(x[1]);
}

// ---- g06 (eqs. 14-15)
double g06(const double* x, double* c) noexcept {
    if (c) {
        c[0] = -sq(x[0] - 5.0) - sq(x[1] - 5.0) + 100.0;
        c[1] = sq(x[0] - 6.0) + sq(x[1] - 5.0) - 82.81;
    }
    return cube(x[0] - 10.0) + cube(x[1] - 20.0);
}

// ---- g07 (eqs. 16-17)
double g07(const double* x, double* c) noexcept {
    if (c) {
        c[0] = -105.0 + 4.0 * x[0] + 5.0 * x[1] - 3.0 * x[6] + 9.0 * x[7];
        c[1] = 10.0 * x[0] - 8.0 * x[1] - 17.0 * x[6] + 2.0 * x[7];
        c[2] = -8.0 * x[0] + 2.0 * x[1] + 5.0 * x[8] - 2.0 * x[9] - 12.0;
        c[3] = 3.0 * sq(x[0] - 2.0) + 4.0 * sq(x[1] - 3.0) + 2.0 * x[2] * x[2] - 7.0 * x[3] - 120.0;
        c[4] = 5.0 * x[0] * x[0] + 8.0 * x[1] + sq(x[2] - 6.0) - 2.0 * x[3] - 40.0;
        c[5] = x[0] * x[0] + 2.0 * sq(x[1] - 2.0) - 2.0 * x[0] * x[1] + 14.0 * x[4] - 6.0 * x[5];
        c[6] = 0.5 * sq(x[0] - 8.0) + 2.0 * sq(x[1] - 4.0) + 3.0 * x[4] * x[4] - x[5] - 30.0;
        c[7] = -3.0 * x[0] + 6.0 * x[1] + 12.0 * sq(x[8] - 8.0) - 7.0 * x[9];
    }
    return x[0] * x[0] + x[1] * x[1] + x[0] * x[1] - 14.0 * x[0] - 16.0 * x[1] + sq(x[2] - 10.0) +
           4.0 * sq(x[3] - 5.0) + sq(x[4] - 3.0) + 2.0 * sq(x[5] - 1.0) + 5.0 * x[6] * x[6] + 7.0 * sq(x[7] - 11.0) +
           2.0 * sq(x[8] - 10.0) + sq(x[9] - 7.0) + 45.0;
}

// ---- g08 (eqs. 18-19); NaN at x1 = 0, a bound, where the formula is 0/0
double g08(const double* x, double* c) noexcept {
    if (c) {
        c[0] = x[0] * x[0] - x[1] + 1.0;
        c[1] = 1.0 - x[0] + sq(x[1] - 4.0);
    }
    constexpr double two_pi = 2.0 * std::numbers::pi;
    return -cube(std::sin(two_pi * x[0])) * std::sin(two_pi * x[1]) / (cube(x[0]) * (x[0] + x[1]));
}

// ---- g09 (eqs. 20-21)
double g09(const double* x, double* c) noexcept {
    if (c) {
        c[0] = -127.0 + 2.0 * x[0] * x[0] + 3.0 * sq(sq(x[1])) + x[2] + 4.0 * x[3] * x[3] + 5.0 * x[4];
        c[1] = -282.0 + 7.0 * x[0] + 3.0 * x[1] + 10.0 * x[2] * x[2] + x[3] - x[4];
        c[2] = -196.0 + 23.0 * x[0] + x[1] * x[1] + 6.0 * x[5] * x[5] - 8.0 * x[6];
        c[3] = 4.0 * x[0] * x[0] + x[1] * x[1] - 3.0 * x[0] * x[1] + 2.0 * x[2] * x[2] + 5.0 * x[5] - 11.0 * x[6];
    }
    return sq(x[0] - 10.0) + 5.0 * sq(x[1] - 12.0) + sq(sq(x[2])) + 3.0 * sq(x[3] - 11.0) + 10.0 * cube(sq(x[4])) +
           7.0 * x[5] * x[5] + sq(sq(x[6])) - 4.0 * x[5] * x[6] - 10.0 * x[5] - 8.0 * x[6];
}

// ---- g10 (eq. 22 and its constraints)
double g10(const double* x, double* c) noexcept {
    if (c) {
        c[0] = -1.0 + 0.0025 * (x[3] + x[5]);
        c[1] = -1.0 + 0.0025 * (x[4] + x[6] - x[3]);
        c[2] = -1.0 + 0.01 * (x[7] - x[4]);
        c[3] = -x[0] * x[5] + 833.33252 * x[3] + 100.0 * x[0] - 83333.333;
        c[4] = -x[1] * x[6] + 1250.0 * x[4] + x[1] * x[3] - 1250.0 * x[3];
        c[5] = -x[2] * x[7] + 1250000.0 + x[2] * x[4] - 2500.0 * x[4];
    }
    return x[0] + x[1] + x[2];
}

// ---- g11 (eqs. 23-24)
double g11(const double* x, double* c) noexcept {
    if (c) c[0] = x[1] - x[0] * x[0];
    return x[0] * x[0] + sq(x[1] - 1.0);
}

// ---- g12 (eq. 25): feasible inside any of the 9^3 spheres of radius 0.25 centred at (p, q, r),
// p, q, r in 1..9; one constraint, the least of the 729 values. The terms are separable, so the
// nearest centre is the nearest integer per coordinate, clamped to 1..9 (rounding is monotone, so
// this is also the least of the 729 computed values, bit for bit).
double g12(const double* x, double* c) noexcept {
    if (c) {
        double sum = 0.0;
        for (int i = 0; i < 3; ++i) sum += sq(x[i] - std::clamp(std::round(x[i]), 1.0, 9.0));
        c[0] = sum - 0.0625;
    }
    return -(100.0 - sq(x[0] - 5.0) - sq(x[1] - 5.0) - sq(x[2] - 5.0)) / 100.0;
}

// ---- g13 (eqs. 26-27)
double g13(const double* x, double* c) noexcept {
    if (c) {
        c[0] = x[0] * x[0] + x[1] * x[1] + x[2] * x[2] + x[3] * x[3] + x[4] * x[4] - 10.0;
        c[1] = x[1] * x[2] - 5.0 * x[3] * x[4];
        c[2] = cube(x[0]) + cube(x[1]) + 1.0;
    }
    return std::exp(x[0] * x[1] * x[2] * x[3] * x[4]);
}

// ---- g14 (eqs. 28-29)
constexpr double kC14[10] = {-6.089, -17.164, -34.054, -5.914, -24.721, -14.986, -24.1, -10.708, -26.662, -22.179};
double g14(const double* x, double* c) noexcept {
    double sum = 0.0;
    for (int i = 0; i < 10; ++i) sum += x[i];
    double f = 0.0;
    // x ln(x / sum) -> 0 as x -> 0: the bound 0 (open in the report) gets the limit, not NaN.
    for (int i = 0; i < 10; ++i)
        if (x[i] != 0.0) f += x[i] * (kC14[i] + std::log(x[i] / sum));
    if (c) {
        c[0] = x[0] + 2.0 * x[1] + 2.0 * x[2] + x[5] + x[9] - 2.0;
        c[1] = x[3] + 2.0 * x[4] + x[5] + x[6] - 1.0;
        c[2] = x[2] + x[6] + x[7] + 2.0 * x[8] + x[9] - 1.0;
    }
    return f;
}

// ---- g15 (eqs. 30-31)
double g15(const double* x, double* c) noexcept {
    if (c) {
        c[0] = x[0] * x[0] + x[1] * x[1] + x[2] * x[2] - 25.0;
        c[1] = 8.0 * x[0] + 14.0 * x[1] + 7.0 * x[2] - 56.0;
    }
    return 1000.0 - x[0] * x[0] - 2.0 * x[1] * x[1] - x[2] * x[2] - x[0] * x[1] - x[0] * x[2];
}

// ---- g16 (eqs. 32-34): the y and c chain of eq. 34, 1-based as the report numbers it.
double g16(const double* x, double* c) noexcept {
    const double x1 = x[0], x2 = x[1], x3 = x[2], x4 = x[3], x5 = x[4];
    double y[18], k[18];
    y[1] = x2 + x3 + 41.6;
    k[1] = 0.024 * x4 - 4.62;
    y[2] = 12.5 / k[1] + 12.0;
    k[2] = 0.0003535 * x1 * x1 + 0.5311 * x1 + 0.08705 * y[2] * x1;
    k[3] = 0.052 * x1 + 78.0 + 0.002377 * y[2] * x1;
    y[3] = k[2] / k[3];
    y[4] = 19.0 * y[3];
    k[4] = 0.04782 * (x1 - y[3]) + 0.1956 * sq(x1 - y[3]) / x2 + 0.6376 * y[4] + 1.594 * y[3];
    k[5] = 100.0 * x2;
    k[6] = x1 - y[3] - y[4];
    k[7] = 0.950 - k[4] / k[5];
    y[5] = k[6] * k[7];
    y[6] = x1 - y[5] - y[4] - y[3];
    k[8] = (y[5] + y[4]) * 0.995;
    y[7] = k[8] / y[1];
    y[8] = k[8] / 3798.0;
    k[9] = y[7] - 0.0663 * y[7] / y[8] - 0.3153;
    y[9] = 96.82 / k[9] + 0.321 * y[1];
    y[10] = 1.29 * y[5] + 1.258 * y[4] + 2.29 * y[3] + 1.71 * y[6];
    y[11] = 1.71 * x1 - 0.452 * y[4] + 0.580 * y[3];
    k[10] = 12.3 / 752.3;
    k[11] = (1.75 * y[2]) * (0.995 * x1);
    k[12] = 0.995 * y[10] + 1998.0;
    y[12] = k[10] * x1 + k[11] / k[12];
    y[13] = k[12] - 1.75 * y[2];
    y[14] = 3623.0 + 64.4 * x2 + 58.4 * x3 + 146312.0 / (y[9] + x5);
    k[13] = 0.995 * y[10] + 60.8 * x2 + 48.0 * x4 - 0.1121 * y[14] - 5095.0;
    y[15] = y[13] / k[13];
    y[16] = 148000.0 - 331000.0 * y[15] + 40.0 * y[13] - 61.0 * y[15] * y[13];
    k[14] = 2324.0 * y[10] - 28740000.0 * y[2];
    y[17] = 14130000.0 - 1328.0 * y[10] - 531.0 * y[11] + k[14] / k[12];
    k[15] = y[13] / y[15] - y[13] / 0.52;
    k[16] = 1.104 - 0.72 * y[15];
    k[17] = y[9] + x5;
    if (c) {
        c[0] = 0.28 / 0.72 * y[5] - y[4];
        c[1] = x3 - 1.5 * x2;
        c[2] = 3496.0 * y[2] / k[12] - 21.0;
        c[3] = 110.6 + y[1] - 62212.0 / k[17];
        // g5 ... g38: lower_i <= y_i <= upper_i for y1 ... y17, each as two constraints.
        constexpr double range[17][2] = {{213.1, 405.23},      {17.505, 1053.6667},    {11.275, 35.03},
                                         {214.228, 665.585},   {7.458, 584.463},       {0.961, 265.916},
                                         {1.612, 7.046},       {0.146, 0.222},         {107.99, 273.366},
                                         {922.693, 1286.105},  {926.832, 1444.046},    {18.766, 537.141},
                                         {1072.163, 3247.039}, {8961.448, 26844.086},  {0.063, 0.386},
                                         {71084.33, 140000.0}, {2802713.0, 12146108.0}};
        for (int i = 0; i < 17; ++i) {
            c[4 + 2 * i] = range[i][0] - y[i + 1];
            c[5 + 2 * i] = y[i + 1] - range[i][1];
        }
    }
    return 0.000117 * y[14] + 0.1365 + 0.00002358 * y[13] + 0.000001502 * y[16] + 0.0321 * y[12] + 0.004324 * y[5] +
           0.0001 * k[15] / k[16] + 37.48 * y[2] / k[12] - 0.0000005843 * y[17];
}

// ---- g17 (eqs. 35-36): f of x1 and x2 themselves, as the report writes it (see the header).
double g17(const double* x, double* c) noexcept {
    const double x1 = x[0], x2 = x[1], x3 = x[2], x4 = x[3], x5 = x[4], x6 = x[5];
    const double f1 = (x1 < 300.0 ? 30.0 : 31.0) * x1;
    const double f2 = (x2 < 100.0 ? 28.0 : x2 < 200.0 ? 29.0 : 30.0) * x2;
    if (c) {
        const double a = x3 * x4 / 131.078, b3 = 0.90798 * x3 * x3 / 131.078, b4 = 0.90798 * x4 * x4 / 131.078;
        c[0] = -x1 + 300.0 - a * std::cos(1.48477 - x6) + b3 * std::cos(1.47588);
        c[1] = -x2 - a * std::cos(1.48477 + x6) + b4 * std::cos(1.47588);
        c[2] = -x5 - a * std::sin(1.48477 + x6) + b4 * std::sin(1.47588);
        c[3] = 200.0 - a * std::sin(1.48477 - x6) + b3 * std::sin(1.47588);
    }
    return f1 + f2;
}

// ---- g18 (eqs. 37-38)
double g18(const double* x, double* c) noexcept {
    if (c) {
        c[0] = x[2] * x[2] + x[3] * x[3] - 1.0;
        c[1] = x[8] * x[8] - 1.0;
        c[2] = x[4] * x[4] + x[5] * x[5] - 1.0;
        c[3] = x[0] * x[0] + sq(x[1] - x[8]) - 1.0;
        c[4] = sq(x[0] - x[4]) + sq(x[1] - x[5]) - 1.0;
        c[5] = sq(x[0] - x[6]) + sq(x[1] - x[7]) - 1.0;
        c[6] = sq(x[2] - x[4]) + sq(x[3] - x[5]) - 1.0;
        c[7] = sq(x[2] - x[6]) + sq(x[3] - x[7]) - 1.0;
        c[8] = x[6] * x[6] + sq(x[7] - x[8]) - 1.0;
        c[9] = x[1] * x[2] - x[0] * x[3];
        c[10] = -x[2] * x[8];
        c[11] = x[4] * x[8];
        c[12] = x[5] * x[6] - x[4] * x[7];
    }
    return -0.5 * (x[0] * x[3] - x[1] * x[2] + x[2] * x[8] - x[4] * x[8] + x[4] * x[7] - x[5] * x[6]);
}

// ---- g19 (eqs. 39-40, Table 1). C is symmetric; A[i][j] is a_ij (i over x1..x10, j over g1..g5).
constexpr double kB19[10] = {-40.0, -2.0, -0.25, -4.0, -4.0, -1.0, -40.0, -60.0, 5.0, 1.0};
constexpr double kC19[5][5] = {{30.0, -20.0, -10.0, 32.0, -10.0},
                               {-20.0, 39.0, -6.0, -31.0, 32.0},
                               {-10.0, -6.0, 10.0, -6.0, -10.0},
                               {32.0, -31.0, -6.0, 39.0, -20.0},
                               {-10.0, 32.0, -10.0, -20.0, 30.0}};
constexpr double kD19[5] = {4.0, 8.0, 10.0, 6.0, 2.0};
constexpr double kE19[5] = {-15.0, -27.0, -36.0, -18.0, -12.0};
constexpr double kA19[10][5] = {{-16.0, 2.0, 0.0, 1.0, 0.0},    {0.0, -2.0, 0.0, 0.4, 2.0},
                                {-3.5, 0.0, 2.0, 0.0, 0.0},     {0.0, -2.0, 0.0, -4.0, -1.0},
                                {0.0, -9.0, -2.0, 1.0, -2.8},   {2.0, 0.0, -4.0, 0.0, 0.0},
                                {-1.0, -1.0, -1.0, -1.0, -1.0}, {-1.0, -2.0, -3.0, -2.0, -1.0},
                                {1.0, 2.0, 3.0, 4.0, 5.0},      {1.0, 1.0, 1.0, 1.0, 1.0}};
double g19(const double* x, double* c) noexcept {
    const double* z = x + 10;  // x11 ... x15
    double quadratic = 0.0, cubic = 0.0, linear = 0.0;
    for (int j = 0; j < 5; ++j) {
        for (int i = 0; i < 5; ++i) quadratic += kC19[i][j] * z[i] * z[j];
        cubic += kD19[j] * cube(z[j]);
    }
    for (int i = 0; i < 10; ++i) linear += kB19[i] * x[i];
    if (c) {
        for (int j = 0; j < 5; ++j) {
            double cz = 0.0, ax = 0.0;
            for (int i = 0; i < 5; ++i) cz += kC19[i][j] * z[i];
            for (int i = 0; i < 10; ++i) ax += kA19[i][j] * x[i];
            c[j] = -2.0 * cz - 3.0 * kD19[j] * z[j] * z[j] - kE19[j] + ax;
        }
    }
    return quadratic + 2.0 * cubic - linear;
}

// ---- g20 (eqs. 41-42, Table 2): a_i and b_i repeat with period 12.
constexpr double kA20[12] = {0.0693, 0.0577, 0.05, 0.2, 0.26, 0.55, 0.06, 0.1, 0.12, 0.18, 0.1, 0.09};
constexpr double kB20[12] = {44.094, 58.12, 58.12, 137.4, 120.9, 170.9, 62.501, 84.94, 133.425, 82.507, 46.07, 60.097};
constexpr double kC20[12] = {123.7, 31.7, 45.7, 14.7, 84.7, 27.7, 49.7, 7.1, 2.1, 17.7, 0.85, 0.64};
constexpr double kD20[12] = {31.244, 36.12, 34.784, 92.7, 82.7, 91.6, 56.708, 82.7, 80.8, 64.517, 49.4, 49.1};
constexpr double kE20[6] = {0.1, 0.3, 0.4, 0.3, 0.6, 0.3};
constexpr double kK20 = 0.7302 * 530.0 * (14.7 / 40.0);
double g20(const double* x, double* c) noexcept {
    double f = 0.0;
    for (int i = 0; i < 24; ++i) f += kA20[i % 12] * x[i];
    if (c) {
        double total = 0.0, first_b = 0.0, second_b = 0.0, first_d = 0.0;
        for (int i = 0; i < 24; ++i) total += x[i];
        for (int i = 0; i < 12; ++i) {
            first_b += x[i] / kB20[i];
            second_b += x[i + 12] / kB20[i];
            first_d += x[i] / kD20[i];
        }
        for (int i = 0; i < 3; ++i) c[i] = (x[i] + x[i + 12]) / (total + kE20[i]);
        for (int i = 3; i < 6; ++i) c[i] = (x[i + 3] + x[i + 15]) / (total + kE20[i]);
        for (int i = 0; i < 12; ++i)
            c[6 + i] = x[i + 12] / (kB20[i] * second_b) - kC20[i] * x[i] / (40.0 * kB20[i] * first_b);
        c[18] = total - 1.0;
        c[19] = first_d + kK20 * second_b - 1.671;
    }
    return f;
}

// ---- g21 (eqs. 43-44)
double g21(const double* x, double* c) noexcept {
    if (c) {
        c[0] = -x[0] + 35.0 * std::pow(x[1], 0.6) + 35.0 * std::pow(x[2], 0.6);
        c[1] = -300.0 * x[2] + 7500.0 * x[4] - 7500.0 * x[5] - 25.0 * x[3] * x[4] + 25.0 * x[3] * x[5] + x[2] * x[3];
        c[2] = 100.0 * x[1] + 155.365 * x[3] + 2500.0 * x[6] - x[1] * x[3] - 25.0 * x[3] * x[6] - 15536.5;
        c[3] = -x[4] + std::log(-x[3] + 900.0);
        c[4] = -x[5] + std::log(x[3] + 300.0);
        c[5] = -x[6] + std::log(-2.0 * x[3] + 700.0);
    }
    return x[0];
}

// ---- g22 (eqs. 45-46)
double g22(const double* x, double* c) noexcept {
    if (c) {
        c[0] = -x[0] + std::pow(x[1], 0.6) + std::pow(x[2], 0.6) + std::pow(x[3], 0.6);
        c[1] = x[4] - 100000.0 * x[7] + 1e7;
        c[2] = x[5] + 100000.0 * x[7] - 100000.0 * x[8];
        c[3] = x[6] + 100000.0 * x[8] - 5e7;
        c[4] = x[4] + 100000.0 * x[9] - 3.3e7;
        c[5] = x[5] + 100000.0 * x[10] - 4.4e7;
        c[6] = x[6] + 100000.0 * x[11] - 6.6e7;
        c[7] = x[4] - 120.0 * x[1] * x[12];
        c[8] = x[5] - 80.0 * x[2] * x[13];
        c[9] = x[6] - 40.0 * x[3] * x[14];
        c[10] = x[7] - x[10] + x[15];
        c[11] = x[8] - x[11] + x[16];
        c[12] = -x[17] + std::log(x[9] - 100.0);
        c[13] = -x[18] + std::log(-x[7] + 300.0);
        c[14] = -x[19] + std::log(x[15]);
        c[15] = -x[20] + std::log(-x[8] + 400.0);
        c[16] = -x[21] + std::log(x[16]);
        c[17] = -x[7] - x[9] + x[12] * x[17] - x[12] * x[18] + 400.0;
        c[18] = x[7] - x[8] - x[10] + x[13] * x[19] - x[13] * x[20] + 400.0;
        c[19] = x[8] - x[11] - 4.60517 * x[14] + x[14] * x[21] + 100.0;
    }
    return x[0];
}

// ---- g23 (eqs. 47-48)
double g23(const double* x, double* c) noexcept {
    if (c) {
        c[0] = x[8] * x[2] + 0.02 * x[5] - 0.025 * x[4];
        c[1] = x[8] * x[3] + 0.02 * x[6] - 0.015 * x[7];
        c[2] = x[0] + x[1] - x[2] - x[3];
        c[3] = 0.03 * x[0] + 0.01 * x[1] - x[8] * (x[2] + x[3]);
        c[4] = x[2] + x[5] - x[4];
        c[5] = x[3] + x[6] - x[7];
    }
    return -9.0 * x[4] - 15.0 * x[7] + 6.0 * x[0] + 16.0 * x[1] + 10.0 * (x[5] + x[6]);
}

// ---- g24 (eqs. 49-50)
double g24(const double* x, double* c) noexcept {
    if (c) {
        const double x2 = x[0] * x[0], x3 = x2 * x[0], x4 = x2 * x2;
        c[0] = -2.0 * x4 + 8.0 * x3 - 8.0 * x2 + x[1] - 2.0;
        c[1] = -4.0 * x4 + 32.0 * x3 - 88.0 * x2 + 96.0 * x[0] + x[1] - 36.0;
    }
    return -x[0] - x[1];
}

}  // namespace

Problem::Problem(int number) : number_(number) {
    const detail::Spec& s = detail::spec(number);
    name_ = s.name;
    counts_ = {s.inequalities, s.equalities};
    lower_ = s.lower;
    upper_ = s.upper;
    best_point_ = s.best_point;
    best_value_ = s.best_value;
}

double Problem::evaluate(std::span<const double> x) const noexcept {
    assert(x.size() == dimension());
    return compute(x.data(), nullptr);
}

double Problem::evaluate_constrained(std::span<const double> x, std::span<double> c) const noexcept {
    assert(x.size() == dimension() && c.size() >= counts_.total());
    return compute(x.data(), c.data());
}

double Problem::compute(const double* x, double* c) const noexcept {
    switch (number_) {
        case 1:
            return g01(x, c);
        case 2:
            return g02(x, c);
        case 3:
            return g03(x, c);
        case 4:
            return g04(x, c);
        case 5:
            return g05(x, c);
        case 6:
            return g06(x, c);
        case 7:
            return g07(x, c);
        case 8:
            return g08(x, c);
        case 9:
            return g09(x, c);
        case 10:
            return g10(x, c);
        case 11:
            return g11(x, c);
        case 12:
            return g12(x, c);
        case 13:
            return g13(x, c);
        case 14:
            return g14(x, c);
        case 15:
            return g15(x, c);
        case 16:
            return g16(x, c);
        case 17:
            return g17(x, c);
        case 18:
            return g18(x, c);
        case 19:
            return g19(x, c);
        case 20:
            return g20(x, c);
        case 21:
            return g21(x, c);
        case 22:
            return g22(x, c);
        case 23:
            return g23(x, c);
        default:
            return g24(x, c);
    }
}

}  // namespace pride::continuous::cec2006

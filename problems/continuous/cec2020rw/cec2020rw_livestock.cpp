// The CEC 2020 real-world suite's livestock feed rations, RC51-RC57 (beef cattle RC51-RC54, dairy
// cattle RC55-RC57), as cec20_func.m computes them (cec2020rw_detail.hpp).
#include "problems/continuous/cec2020rw/cec2020rw_detail.hpp"

namespace pride::continuous::cec2020rw::detail {

namespace {

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

}  // namespace

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

}  // namespace pride::continuous::cec2020rw::detail

// The CEC 2020 real-world suite's power electronics problems, RC45-RC50 (synchronous optimal
// pulse-width modulation of multilevel inverters), as cec20_func.m computes them
// (cec2020rw_detail.hpp).
#include "problems/continuous/cec2020rw/cec2020rw_detail.hpp"

#include <cmath>

namespace pride::continuous::cec2020rw::detail {

namespace {

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

}  // namespace

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

}  // namespace pride::continuous::cec2020rw::detail

// The CEC 2020 real-world suite's mechanical engineering problems, RC15-RC33 (RC24 is not
// implemented: cec2020rw.hpp), as cec20_func.m computes them (cec2020rw_detail.hpp).
#include "problems/continuous/cec2020rw/cec2020rw_detail.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Eigenvalues>

namespace pride::continuous::cec2020rw::detail {

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

namespace {

// MATLAB's max(..., [], 2): NaN entries are ignored (NaN only when all are).
double max_ignoring_nan(std::initializer_list<double> values) noexcept {
    double best = std::numeric_limits<double>::quiet_NaN();
    for (const double v : values)
        if (!std::isnan(v) && (std::isnan(best) || v > best)) best = v;
    return best;
}

}  // namespace

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

}  // namespace pride::continuous::cec2020rw::detail

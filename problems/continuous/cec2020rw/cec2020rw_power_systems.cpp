// The CEC 2020 real-world suite's power system problems, RC34-RC44, as cec20_func.m computes them
// (cec2020rw_detail.hpp); the bus admittances, loads and lines are the organisers' data files'
// (cec2020rw_tables.cpp).
#include "problems/continuous/cec2020rw/cec2020rw_detail.hpp"

#include <cmath>
#include <complex>
#include <cstddef>

namespace pride::continuous::cec2020rw::detail {

namespace {

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

}  // namespace

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

namespace {

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

}  // namespace
double rc35(const double* x, double* c) noexcept {
    return rc35_36(x, c, false);
}
double rc36(const double* x, double* c) noexcept {
    return rc35_36(x, c, true);
}

namespace {

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

}  // namespace
double rc37(const double* x, double* c) noexcept {
    return rc37_39(x, c, 37);
}
double rc38(const double* x, double* c) noexcept {
    return rc37_39(x, c, 38);
}
double rc39(const double* x, double* c) noexcept {
    return rc37_39(x, c, 39);
}

namespace {

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

}  // namespace
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

}  // namespace pride::continuous::cec2020rw::detail

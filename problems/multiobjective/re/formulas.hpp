#pragma once
// The formulas of Tanabe and Ishibuchi's (2020) RE and CRE problems, one function per problem, as
// their official code computes them (GitHub ryojitanabe/reproblems, its C version; re.hpp says
// which version and lists the code's quirks kept here). Each expression keeps the code's order of
// operations and its constants as written (9.82 * 1e6 is not 9.82e6 in every bit), so that the
// values are the code's to the last bit on the same libm.
//
// re*(x, f): the M objectives of an RE problem; where the problem's constraints are folded into its
// last objective, that objective is the sum, in order, of fold(g_i) over the code's constraint
// values g_i (>= 0 feasible).
// cre*(x, f, c): the M objectives and the m constraint values of a CRE problem in pride's sign,
// c_i = -g_i (<= 0 feasible; framework/constraints.hpp).
#include <cmath>
#include <cstddef>
#include <iterator>
#include <numbers>

namespace pride::multiobjective::re::formulas {

/// The code's fold of a constraint value g (>= 0 feasible) into its violation: -g when g < 0, else
/// 0, so that a NaN g counts as satisfied (the comparison is false), as in the code.
inline double fold(double g) noexcept {
    return g < 0.0 ? -g : 0.0;
}

/// The value of `table` nearest to v; the first such on a tie (the code's strict < scan).
template <std::size_t N>
double nearest(const double (&table)[N], double v) noexcept {
    double best = table[0];
    double best_gap = std::fabs(table[0] - v);
    for (std::size_t i = 1; i < N; ++i) {
        const double gap = std::fabs(table[i] - v);
        if (gap < best_gap) {
            best_gap = gap;
            best = table[i];
        }
    }
    return best;
}

/// RE22's x1: the reinforcement areas the code allows. The code's list reads "3.08, 3,10, 3.16": 3
/// and 10 rather than 3.10, kept as such (77 entries, 3 twice; 10 is reachable, 3.10 is not).
inline constexpr double kRe22Areas[] = {0.20, 0.31, 0.40, 0.44, 0.60,  0.62, 0.79,  0.80,  0.88, 0.93, 1.0,  1.20, 1.24,
                                        1.32, 1.40, 1.55, 1.58, 1.60,  1.76, 1.80,  1.86,  2.0,  2.17, 2.20, 2.37, 2.40,
                                        2.48, 2.60, 2.64, 2.79, 2.80,  3.0,  3.08,  3,     10,   3.16, 3.41, 3.52, 3.60,
                                        3.72, 3.95, 3.96, 4.0,  4.03,  4.20, 4.34,  4.40,  4.65, 4.74, 4.80, 4.84, 5.0,
                                        5.28, 5.40, 5.53, 5.72, 6.0,   6.16, 6.32,  6.60,  7.11, 7.20, 7.80, 7.90, 8.0,
                                        8.40, 8.69, 9.0,  9.48, 10.27, 11.0, 11.06, 11.85, 12.0, 13.0, 14.0, 15.0};
static_assert(std::size(kRe22Areas) == 77);

/// RE25's x3: the wire diameters the code allows (42).
inline constexpr double kRe25Diameters[] = {
    0.009, 0.0095, 0.0104, 0.0118, 0.0128, 0.0132, 0.014, 0.015, 0.0162, 0.0173, 0.018, 0.02,  0.023,  0.025,
    0.028, 0.032,  0.035,  0.041,  0.047,  0.054,  0.063, 0.072, 0.08,   0.092,  0.105, 0.12,  0.135,  0.148,
    0.162, 0.177,  0.192,  0.207,  0.225,  0.244,  0.263, 0.283, 0.307,  0.331,  0.362, 0.394, 0.4375, 0.5};
static_assert(std::size(kRe25Diameters) == 42);

inline constexpr double kPi = std::numbers::pi;  // the code's M_PI

// ---------------------------------------------------------------------------------------------
// Two objectives.

/// RE21, four-bar truss: volume and displacement (no constraint).
inline void re21(const double* x, double* f) noexcept {
    const double force = 10, length = 200, modulus = 2 * 1e5;
    const double r2 = std::sqrt(2.0);
    f[0] = length * ((2 * x[0]) + r2 * x[1] + std::sqrt(x[2]) + x[3]);
    f[1] = ((force * length) / modulus) * ((2.0 / x[0]) + (2.0 * r2 / x[1]) - (2.0 * r2 / x[2]) + (2.0 / x[3]));
}

/// RE22, reinforced concrete beam: cost; x1 snapped to kRe22Areas; two constraints folded into f2.
inline void re22(const double* x, double* f) noexcept {
    const double a = nearest(kRe22Areas, x[0]), b = x[1], h = x[2];
    f[0] = (29.4 * a) + (0.6 * b * h);
    const double g1 = (a * h) - 7.735 * ((a * a) / b) - 180.0;
    const double g2 = 4.0 - (h / b);
    f[1] = fold(g1) + fold(g2);
}

/// RE23, pressure vessel: cost; x1, x2 are multiples of 1/16 (0.0625 round(x)); three constraints
/// folded into f2.
inline void re23(const double* x, double* f) noexcept {
    const double ts = 0.0625 * std::round(x[0]), th = 0.0625 * std::round(x[1]), r = x[2], len = x[3];
    f[0] = (0.6224 * ts * r * len) + (1.7781 * th * r * r) + (3.1661 * ts * ts * len) + (19.84 * ts * ts * r);
    const double g1 = ts - (0.0193 * r);
    const double g2 = th - (0.00954 * r);
    const double g3 = (kPi * r * r * len) + ((4.0 / 3.0) * (kPi * r * r * r)) - 1296000;
    f[1] = fold(g1) + fold(g2) + fold(g3);
}

/// RE24, hatch cover: weight; four constraints folded into f2.
inline void re24(const double* x, double* f) noexcept {
    const double a = x[0], b = x[1];
    f[0] = a + (120 * b);
    const double modulus = 700000, sigma_b_max = 700, tau_max = 450, delta_max = 1.5;
    const double sigma_k = (modulus * a * a) / 100;
    const double sigma_b = 4500 / (a * b);
    const double tau = 1800 / b;
    const double delta = (56.2 * 10000) / (modulus * a * b * b);
    const double g1 = 1 - (sigma_b / sigma_b_max);
    const double g2 = 1 - (tau / tau_max);
    const double g3 = 1 - (delta / delta_max);
    const double g4 = 1 - (sigma_b / sigma_k);
    f[1] = fold(g1) + fold(g2) + fold(g3) + fold(g4);
}

/// RE25, coil compression spring: volume; x1 (coils) rounded, x3 snapped to kRe25Diameters; six
/// constraints folded into f2.
inline void re25(const double* x, double* f) noexcept {
    const double coils = std::round(x[0]), dc = x[1], dw = nearest(kRe25Diameters, x[2]);
    f[0] = (kPi * kPi * dc * dw * dw * (coils + 2)) / 4.0;
    const double cf = ((4.0 * (dc / dw) - 1) / (4.0 * (dc / dw) - 4)) + (0.615 * dw / dc);
    const double f_max = 1000.0, s = 189000.0, shear = 11.5 * 1e+6;
    const double k = (shear * dw * dw * dw * dw) / (8 * coils * dc * dc * dc);
    const double l_max = 14.0;
    const double lf = (f_max / k) + 1.05 * (coils + 2) * dw;
    const double fp = 300.0, sigma_pm = 6, sigma_w = 1.25;
    const double sigma_p = fp / k;
    const double g1 = -((8 * cf * f_max * dc) / (kPi * dw * dw * dw)) + s;
    const double g2 = -lf + l_max;
    const double g3 = -3 + (dc / dw);
    const double g4 = -sigma_p + sigma_pm;
    const double g5 = -sigma_p - ((f_max - fp) / k) - 1.05 * (coils + 2) * dw + lf;
    const double g6 = sigma_w - ((f_max - fp) / k);
    f[1] = fold(g1) + fold(g2) + fold(g3) + fold(g4) + fold(g5) + fold(g6);
}

// ---------------------------------------------------------------------------------------------
// The shared bodies of the RE problems whose constraints CRE keeps as constraints: each writes the
// objectives and the code's constraint values g (>= 0 feasible).

/// Two-bar truss (RE31, CRE21): 2 objectives, 3 constraints.
inline void two_bar_truss(const double* x, double* f, double* g) noexcept {
    const double a1 = x[0], a2 = x[1], y = x[2];
    f[0] = a1 * std::sqrt(16.0 + (y * y)) + a2 * std::sqrt(1.0 + y * y);
    f[1] = (20.0 * std::sqrt(16.0 + (y * y))) / (a1 * y);
    g[0] = 0.1 - f[0];
    g[1] = 100000.0 - f[1];
    g[2] = 100000 - ((80.0 * std::sqrt(1.0 + y * y)) / (y * a2));
}

/// Welded beam (RE32, CRE22): 2 objectives, 4 constraints.
inline void welded_beam(const double* x, double* f, double* g) noexcept {
    const double h = x[0], l = x[1], t = x[2], b = x[3];
    const double load = 6000, length = 14, modulus = 30 * 1e6, shear = 12 * 1e6;
    const double tau_max = 13600, sigma_max = 30000;
    f[0] = (1.10471 * h * h * l) + (0.04811 * t * b) * (14.0 + l);
    f[1] = (4 * load * length * length * length) / (modulus * b * t * t * t);
    const double moment = load * (length + (l / 2));
    const double r = std::sqrt(((l * l) / 4.0) + std::pow((h + t) / 2.0, 2));
    const double j = 2 * std::sqrt(2) * h * l * (((l * l) / 12.0) + std::pow((h + t) / 2.0, 2));
    const double tau2 = (moment * r) / j;
    const double tau1 = load / (std::sqrt(2) * h * l);
    const double tau = std::sqrt(tau1 * tau1 + ((2 * tau1 * tau2 * l) / (2 * r)) + (tau2 * tau2));
    const double sigma = (6 * load * length) / (b * t * t);
    const double pc_base = 4.013 * modulus * std::sqrt((t * t * b * b * b * b * b * b) / 36.0) / (length * length);
    const double pc_factor = (t / (2 * length)) * std::sqrt(modulus / (4 * shear));
    const double pc = pc_base * (1 - pc_factor);
    g[0] = tau_max - tau;
    g[1] = sigma_max - sigma;
    g[2] = b - h;
    g[3] = pc - load;
}

/// Disc brake (RE33, CRE23): 2 objectives, 4 constraints.
inline void disc_brake(const double* x, double* f, double* g) noexcept {
    const double ri = x[0], ro = x[1], force = x[2], faces = x[3];
    const double area2 = ro * ro - ri * ri;
    const double area3 = ro * ro * ro - ri * ri * ri;
    f[0] = 4.9 * 1e-5 * area2 * (faces - 1.0);
    f[1] = ((9.82 * 1e6) * area2) / (force * faces * area3);
    g[0] = (ro - ri) - 20.0;
    g[1] = 0.4 - (force / (3.14 * area2));
    g[2] = 1.0 - (2.22 * 1e-3 * force * area3) / std::pow(area2, 2);
    g[3] = (2.66 * 1e-2 * force * faces * area3) / area2 - 900.0;
}

/// Speed reducer (RE35, CRE24): 2 objectives, 11 constraints; x3 (teeth) rounded.
inline void speed_reducer(const double* x, double* f, double* g) noexcept {
    const double b = x[0], m = x[1], z = std::round(x[2]), l1 = x[3], l2 = x[4], d1 = x[5], d2 = x[6];
    f[0] = 0.7854 * b * (m * m) * (((10.0 * z * z) / 3.0) + (14.933 * z) - 43.0934) - 1.508 * b * (d1 * d1 + d2 * d2) +
           7.477 * (d1 * d1 * d1 + d2 * d2 * d2) + 0.7854 * (l1 * d1 * d1 + l2 * d2 * d2);
    f[1] = std::sqrt(std::pow((745.0 * l1) / (m * z), 2.0) + 1.69 * 1e7) / (0.1 * d1 * d1 * d1);
    g[0] = -(1.0 / (b * m * m * z)) + 1.0 / 27.0;
    g[1] = -(1.0 / (b * m * m * z * z)) + 1.0 / 397.5;
    g[2] = -(l1 * l1 * l1) / (m * z * d1 * d1 * d1 * d1) + 1.0 / 1.93;
    g[3] = -(l2 * l2 * l2) / (m * z * d2 * d2 * d2 * d2) + 1.0 / 1.93;
    g[4] = -(m * z) + 40.0;
    g[5] = -(b / m) + 12.0;
    g[6] = -5.0 + (b / m);
    g[7] = -1.9 + l1 - 1.5 * d1;
    g[8] = -1.9 + l2 - 1.1 * d2;
    g[9] = -f[1] + 1300.0;
    g[10] = -std::sqrt(std::pow((745.0 * l2) / (m * z), 2.0) + 1.575 * 1e8) / (0.1 * d2 * d2 * d2) + 1100.0;
}

/// Gear train (RE36, CRE25): 2 objectives, 1 constraint; the four numbers of teeth rounded.
inline void gear_train(const double* x, double* f, double* g) noexcept {
    const double a = std::round(x[0]), b = std::round(x[1]), d = std::round(x[2]), e = std::round(x[3]);
    f[0] = std::fabs(6.931 - ((d / a) * (e / b)));
    double largest = a;  // the code's scan: a NaN-free max, first of equals
    if (b > largest) largest = b;
    if (d > largest) largest = d;
    if (e > largest) largest = e;
    f[1] = largest;
    g[0] = 0.5 - (f[0] / 6.931);
}

/// Car side impact (RE41, CRE31): 3 objectives, 10 constraints.
inline void car_side_impact(const double* x, double* f, double* g) noexcept {
    const double x1 = x[0], x2 = x[1], x3 = x[2], x4 = x[3], x5 = x[4], x6 = x[5], x7 = x[6];
    f[0] = 1.98 + 4.9 * x1 + 6.67 * x2 + 6.98 * x3 + 4.01 * x4 + 1.78 * x5 + 0.00001 * x6 + 2.73 * x7;
    f[1] = 4.72 - 0.5 * x4 - 0.19 * x2 * x3;
    const double v_mbp = 10.58 - 0.674 * x1 * x2 - 0.67275 * x2;
    const double v_fd = 16.45 - 0.489 * x3 * x7 - 0.843 * x5 * x6;
    f[2] = 0.5 * (v_mbp + v_fd);
    g[0] = 1 - (1.16 - 0.3717 * x2 * x4 - 0.0092928 * x3);
    g[1] = 0.32 - (0.261 - 0.0159 * x1 * x2 - 0.06486 * x1 - 0.019 * x2 * x7 + 0.0144 * x3 * x5 + 0.0154464 * x6);
    g[2] = 0.32 - (0.214 + 0.00817 * x5 - 0.045195 * x1 - 0.0135168 * x1 + 0.03099 * x2 * x6 - 0.018 * x2 * x7 +
                   0.007176 * x3 + 0.023232 * x3 - 0.00364 * x5 * x6 - 0.018 * x2 * x2);
    g[3] = 0.32 - (0.74 - 0.61 * x2 - 0.031296 * x3 - 0.031872 * x7 + 0.227 * x2 * x2);
    g[4] = 32 - (28.98 + 3.818 * x3 - 4.2 * x1 * x2 + 1.27296 * x6 - 2.68065 * x7);
    g[5] = 32 - (33.86 + 2.95 * x3 - 5.057 * x1 * x2 - 3.795 * x2 - 3.4431 * x7 + 1.45728);
    g[6] = 32 - (46.36 - 9.9 * x2 - 4.4505 * x1);
    g[7] = 4 - f[1];
    g[8] = 9.9 - v_mbp;
    g[9] = 15.7 - v_fd;
}

/// Conceptual marine design (RE42, CRE32): 3 objectives (the annual cargo, maximised, as its
/// negation), 9 constraints; the sixth is 500000 - DWT, after the code's fix (it read 50000).
inline void marine_design(const double* x, double* f, double* g) noexcept {
    const double len = x[0], beam = x[1], depth = x[2], draft = x[3], speed = x[4], block = x[5];
    const double displacement = 1.025 * len * beam * draft * block;
    const double v = 0.5144 * speed;
    const double gravity = 9.8065;
    const double froude = v / std::pow(gravity * len, 0.5);
    const double a = (4977.06 * block * block) - (8105.61 * block) + 4456.51;
    const double b = (-10847.2 * block * block) + (12817.0 * block) - 6960.32;
    const double power = (std::pow(displacement, 2.0 / 3.0) * std::pow(speed, 3.0)) / (a + (b * froude));
    const double outfit_weight =
        1.0 * std::pow(len, 0.8) * std::pow(beam, 0.6) * std::pow(depth, 0.3) * std::pow(block, 0.1);
    const double steel_weight =
        0.034 * std::pow(len, 1.7) * std::pow(beam, 0.7) * std::pow(depth, 0.4) * std::pow(block, 0.5);
    const double machinery_weight = 0.17 * std::pow(power, 0.9);
    const double light_ship_weight = steel_weight + outfit_weight + machinery_weight;
    const double ship_cost =
        1.3 * ((2000.0 * std::pow(steel_weight, 0.85)) + (3500.0 * outfit_weight) + (2400.0 * std::pow(power, 0.8)));
    const double capital_costs = 0.2 * ship_cost;
    const double dwt = displacement - light_ship_weight;
    const double running_costs = 40000.0 * std::pow(dwt, 0.3);
    const double round_trip_miles = 5000.0;
    const double sea_days = (round_trip_miles / 24.0) * speed;
    const double handling_rate = 8000.0;
    const double daily_consumption = ((0.19 * power * 24.0) / 1000.0) + 0.2;
    const double fuel_price = 100.0;
    const double fuel_cost = 1.05 * daily_consumption * sea_days * fuel_price;
    const double port_cost = 6.3 * std::pow(dwt, 0.8);
    const double fuel_carried = daily_consumption * (sea_days + 5.0);
    const double miscellaneous_dwt = 2.0 * std::pow(dwt, 0.5);
    const double cargo_dwt = dwt - fuel_carried - miscellaneous_dwt;
    const double port_days = 2.0 * ((cargo_dwt / handling_rate) + 0.5);
    const double round_trips = 350.0 / (sea_days + port_days);
    const double voyage_costs = (fuel_cost + port_cost) * round_trips;
    const double annual_costs = capital_costs + running_costs + voyage_costs;
    const double annual_cargo = cargo_dwt * round_trips;
    f[0] = annual_costs / annual_cargo;
    f[1] = light_ship_weight;
    f[2] = -annual_cargo;
    g[0] = (len / beam) - 6.0;
    g[1] = -(len / depth) + 15.0;
    g[2] = -(len / draft) + 19.0;
    g[3] = 0.45 * std::pow(dwt, 0.31) - draft;
    g[4] = 0.7 * depth + 0.7 - draft;
    g[5] = 500000.0 - dwt;
    g[6] = dwt - 3000.0;
    g[7] = 0.32 - froude;
    const double kb = 0.53 * draft;
    const double bmt = ((0.085 * block - 0.002) * beam * beam) / (draft * block);
    const double kg = 1.0 + 0.52 * depth;
    g[8] = (kb + bmt - kg) - (0.07 * beam);
}

/// Water resource planning (RE61, CRE51): 5 objectives, 7 constraints.
inline void water_resources(const double* x, double* f, double* g) noexcept {
    const double x1 = x[0], x2 = x[1], x3 = x[2];
    f[0] = 106780.37 * (x2 + x3) + 61704.67;
    f[1] = 3000 * x1;
    f[2] = 305700 * 2289 * x2 / std::pow(0.06 * 2289, 0.65);
    f[3] = 250 * 2289 * std::exp(-39.75 * x2 + 9.9 * x3 + 2.74);
    f[4] = 25 * (1.39 / (x1 * x2) + 4940 * x3 - 80);
    g[0] = 1 - (0.00139 / (x1 * x2) + 4.94 * x3 - 0.08);
    g[1] = 1 - (0.000306 / (x1 * x2) + 1.082 * x3 - 0.0986);
    g[2] = 50000 - (12.307 / (x1 * x2) + 49408.24 * x3 + 4051.02);
    g[3] = 16000 - (2.098 / (x1 * x2) + 8046.33 * x3 - 696.71);
    g[4] = 10000 - (2.138 / (x1 * x2) + 7883.39 * x3 - 705.04);
    g[5] = 2000 - (0.417 * x1 * x2 + 1721.26 * x3 - 136.54);
    g[6] = 550 - (0.164 / (x1 * x2) + 631.13 * x3 - 54.48);
}

/// The sum, in order, of fold(g_i), i < m: the code's last objective of an RE problem built on a
/// constrained body (it adds g[0] + g[1] + ..., the same bits as from 0.0: every term is >= +0).
inline double folded_sum(const double* g, std::size_t m) noexcept {
    double sum = fold(g[0]);
    for (std::size_t i = 1; i < m; ++i) sum += fold(g[i]);
    return sum;
}

// ---------------------------------------------------------------------------------------------
// Three and more objectives.

inline void re31(const double* x, double* f) noexcept {
    double g[3];
    two_bar_truss(x, f, g);
    f[2] = folded_sum(g, 3);
}

inline void re32(const double* x, double* f) noexcept {
    double g[4];
    welded_beam(x, f, g);
    f[2] = folded_sum(g, 4);
}

inline void re33(const double* x, double* f) noexcept {
    double g[4];
    disc_brake(x, f, g);
    f[2] = folded_sum(g, 4);
}

/// RE34, vehicle crashworthiness: three response surfaces (no constraint).
inline void re34(const double* x, double* f) noexcept {
    const double x1 = x[0], x2 = x[1], x3 = x[2], x4 = x[3], x5 = x[4];
    f[0] = 1640.2823 + (2.3573285 * x1) + (2.3220035 * x2) + (4.5688768 * x3) + (7.7213633 * x4) + (4.4559504 * x5);
    f[1] = 6.5856 + (1.15 * x1) - (1.0427 * x2) + (0.9738 * x3) + (0.8364 * x4) - (0.3695 * x1 * x4) +
           (0.0861 * x1 * x5) + (0.3628 * x2 * x4) - (0.1106 * x1 * x1) - (0.3437 * x3 * x3) + (0.1764 * x4 * x4);
    f[2] = -0.0551 + (0.0181 * x1) + (0.1024 * x2) + (0.0421 * x3) - (0.0073 * x1 * x2) + (0.024 * x2 * x3) -
           (0.0118 * x2 * x4) - (0.0204 * x3 * x4) - (0.008 * x3 * x5) - (0.0241 * x2 * x2) + (0.0109 * x4 * x4);
}

inline void re35(const double* x, double* f) noexcept {
    double g[11];
    speed_reducer(x, f, g);
    f[2] = folded_sum(g, 11);
}

inline void re36(const double* x, double* f) noexcept {
    double g[1];
    gear_train(x, f, g);
    f[2] = fold(g[0]);
}

/// RE37, rocket injector: three response surfaces (no constraint).
inline void re37(const double* x, double* f) noexcept {
    const double a = x[0], ha = x[1], oa = x[2], optt = x[3];
    f[0] = 0.692 + (0.477 * a) - (0.687 * ha) - (0.080 * oa) - (0.0650 * optt) - (0.167 * a * a) - (0.0129 * ha * a) +
           (0.0796 * ha * ha) - (0.0634 * oa * a) - (0.0257 * oa * ha) + (0.0877 * oa * oa) - (0.0521 * optt * a) +
           (0.00156 * optt * ha) + (0.00198 * optt * oa) + (0.0184 * optt * optt);
    f[1] = 0.153 - (0.322 * a) + (0.396 * ha) + (0.424 * oa) + (0.0226 * optt) + (0.175 * a * a) + (0.0185 * ha * a) -
           (0.0701 * ha * ha) - (0.251 * oa * a) + (0.179 * oa * ha) + (0.0150 * oa * oa) + (0.0134 * optt * a) +
           (0.0296 * optt * ha) + (0.0752 * optt * oa) + (0.0192 * optt * optt);
    f[2] = 0.370 - (0.205 * a) + (0.0307 * ha) + (0.108 * oa) + (1.019 * optt) - (0.135 * a * a) + (0.0141 * ha * a) +
           (0.0998 * ha * ha) + (0.208 * oa * a) - (0.0301 * oa * ha) - (0.226 * oa * oa) + (0.353 * optt * a) -
           (0.0497 * optt * oa) - (0.423 * optt * optt) + (0.202 * ha * a * a) - (0.281 * oa * a * a) -
           (0.342 * ha * ha * a) - (0.245 * ha * ha * oa) + (0.281 * oa * oa * ha) - (0.184 * optt * optt * a) -
           (0.281 * ha * a * oa);
}

inline void re41(const double* x, double* f) noexcept {
    double g[10];
    car_side_impact(x, f, g);
    f[3] = folded_sum(g, 10);
}

inline void re42(const double* x, double* f) noexcept {
    double g[9];
    marine_design(x, f, g);
    f[3] = folded_sum(g, 9);
}

inline void re61(const double* x, double* f) noexcept {
    double g[7];
    water_resources(x, f, g);
    f[5] = folded_sum(g, 7);
}

/// RE91, car cab design: 9 objectives of the 7 variables and 4 random values `xi` (the code draws
/// x8 ~ N(0.345, 0.006^2), x9 ~ N(0.192, 0.006^2), x10, x11 ~ N(0, 10^2) at each evaluation).
/// Note f1's 1.75 x5, where RE41's has 1.78: the code's.
inline void re91(const double* x, const double* xi, double* f) noexcept {
    const double x1 = x[0], x2 = x[1], x3 = x[2], x4 = x[3], x5 = x[4], x6 = x[5], x7 = x[6];
    const double x8 = xi[0], x9 = xi[1], x10 = xi[2], x11 = xi[3];
    f[0] = 1.98 + 4.9 * x1 + 6.67 * x2 + 6.98 * x3 + 4.01 * x4 + 1.75 * x5 + 0.00001 * x6 + 2.73 * x7;
    f[1] = std::fmax(0.0, (1.16 - 0.3717 * x2 * x4 - 0.00931 * x2 * x10 - 0.484 * x3 * x9 + 0.01343 * x6 * x10) / 1.0);
    f[2] = std::fmax(0.0, (0.261 - 0.0159 * x1 * x2 - 0.188 * x1 * x8 - 0.019 * x2 * x7 + 0.0144 * x3 * x5 +
                           0.87570001 * x5 * x10 + 0.08045 * x6 * x9 + 0.00139 * x8 * x11 + 0.00001575 * x10 * x11) /
                              0.32);
    f[3] = std::fmax(
        0.0, (0.214 + 0.00817 * x5 - 0.131 * x1 * x8 - 0.0704 * x1 * x9 + 0.03099 * x2 * x6 - 0.018 * x2 * x7 +
              0.0208 * x3 * x8 + 0.121 * x3 * x9 - 0.00364 * x5 * x6 + 0.0007715 * x5 * x10 - 0.0005354 * x6 * x10 +
              0.00121 * x8 * x11 + 0.00184 * x9 * x10 - 0.018 * x2 * x2) /
                 0.32);
    f[4] = std::fmax(
        0.0, (0.74 - 0.61 * x2 - 0.163 * x3 * x8 + 0.001232 * x3 * x10 - 0.166 * x7 * x9 + 0.227 * x2 * x2) / 0.32);
    const double mean =
        ((28.98 + 3.818 * x3 - 4.2 * x1 * x2 + 0.0207 * x5 * x10 + 6.63 * x6 * x9 - 7.77 * x7 * x8 + 0.32 * x9 * x10) +
         (33.86 + 2.95 * x3 + 0.1792 * x10 - 5.057 * x1 * x2 - 11 * x2 * x8 - 0.0215 * x5 * x10 - 9.98 * x7 * x8 +
          22 * x8 * x9) +
         (46.36 - 9.9 * x2 - 12.9 * x1 * x8 + 0.1107 * x3 * x10)) /
        3;
    f[5] = std::fmax(0.0, mean / 32);
    f[6] = std::fmax(
        0.0, (4.72 - 0.5 * x4 - 0.19 * x2 * x3 - 0.0122 * x4 * x10 + 0.009325 * x6 * x10 + 0.000191 * x11 * x11) / 4.0);
    f[7] = std::fmax(
        0.0,
        (10.58 - 0.674 * x1 * x2 - 1.95 * x2 * x8 + 0.02054 * x3 * x10 - 0.0198 * x4 * x10 + 0.028 * x6 * x10) / 9.9);
    f[8] = std::fmax(0.0, (16.45 - 0.489 * x3 * x7 - 0.843 * x5 * x6 + 0.0432 * x9 * x10 - 0.0556 * x9 * x11 -
                           0.000786 * x11 * x11) /
                              15.7);
}

}  // namespace pride::multiobjective::re::formulas

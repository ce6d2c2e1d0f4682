#pragma once
// Inside the CEC 2020 real-world suite: the problems' functions, the helpers they share, and the
// tables restated from the organisers' data files (cec2020rw_tables.cpp).
//
// The problems are Kumar et al. (2020)'s as the organisers' cec20_func.m computes them, one function
// each: f(x), and the inequality values then the equality values into c. Variables are named as in
// the code; X(i) is the code's x(:,i). The operations keep the code's order (MATLAB evaluates left
// to right), so that the values agree with it to the last bits but for the library's rounding.
#include <cmath>
#include <cstddef>
#include <numbers>

namespace pride::continuous::cec2020rw::detail {

inline constexpr double kPi = std::numbers::pi;

// x.^e as MATLAB computes it for a real result (std::pow: NaN where MATLAB's would be complex).
inline double pw(double v, double e) noexcept {
    return std::pow(v, e);
}

// The code's x(:,i): 1-based.
struct OneBased {
    const double* x;
    double operator()(int i) const noexcept { return x[i - 1]; }
};

// Rounds a variable to the index of a table of n entries, as MATLAB's t(round(x)) does inside the
// box; outside it (where MATLAB stops with an error) the index is clamped to the table.
inline int table_index(double v, int n) noexcept {
    const double r = std::round(v);
    if (!(r >= 1.0)) return 0;
    if (r >= n) return n - 1;
    return static_cast<int>(r) - 1;
}

// RC01-RC07: industrial chemical processes (cec2020rw_chemical.cpp).
double rc01(const double* x, double* c) noexcept;
double rc02(const double* x, double* c) noexcept;
double rc03(const double* x, double* c) noexcept;
double rc04(const double* x, double* c) noexcept;
double rc05(const double* x, double* c) noexcept;
double rc06(const double* x, double* c) noexcept;
double rc07(const double* x, double* c) noexcept;

// RC08-RC14: process synthesis and design (cec2020rw_process.cpp).
double rc08(const double* x, double* c) noexcept;
double rc09(const double* x, double* c) noexcept;
double rc10(const double* x, double* c) noexcept;
double rc11(const double* x, double* c) noexcept;
double rc12(const double* x, double* c) noexcept;
double rc13(const double* x, double* c) noexcept;
double rc14(const double* x, double* c) noexcept;

// RC15-RC33: mechanical engineering (cec2020rw_mechanical.cpp; RC24 in cec2020rw_gripper.cpp).
double rc15(const double* x, double* c) noexcept;
double rc16(const double* x, double* c) noexcept;
double rc17(const double* x, double* c) noexcept;
double rc18(const double* x, double* c) noexcept;
double rc19(const double* x, double* c) noexcept;
double rc20(const double* x, double* c) noexcept;
double rc21(const double* x, double* c) noexcept;
double rc22(const double* x, double* c) noexcept;
double rc23(const double* x, double* c) noexcept;
double rc24(const double* x, double* c) noexcept;  // cec2020rw_gripper.cpp
double rc25(const double* x, double* c) noexcept;
double rc26(const double* x, double* c) noexcept;
double rc27(const double* x, double* c) noexcept;
double rc28(const double* x, double* c) noexcept;
double rc29(const double* x, double* c) noexcept;
double rc30(const double* x, double* c) noexcept;
double rc31(const double* x, double* c) noexcept;
double rc32(const double* x, double* c) noexcept;
double rc33(const double* x, double* c) noexcept;

// RC34-RC44: power systems (cec2020rw_power_systems.cpp).
double rc34(const double* x, double* c) noexcept;
double rc35(const double* x, double* c) noexcept;
double rc36(const double* x, double* c) noexcept;
double rc37(const double* x, double* c) noexcept;
double rc38(const double* x, double* c) noexcept;
double rc39(const double* x, double* c) noexcept;
double rc40(const double* x, double* c) noexcept;
double rc41(const double* x, double* c) noexcept;
double rc42(const double* x, double* c) noexcept;
double rc43(const double* x, double* c) noexcept;
double rc44(const double* x, double* c) noexcept;

// RC45-RC50: power electronics (cec2020rw_power_electronics.cpp).
double rc45(const double* x, double* c) noexcept;
double rc46(const double* x, double* c) noexcept;
double rc47(const double* x, double* c) noexcept;
double rc48(const double* x, double* c) noexcept;
double rc49(const double* x, double* c) noexcept;
double rc50(const double* x, double* c) noexcept;

// RC51-RC57: livestock feed ration (cec2020rw_livestock.cpp).
double rc51(const double* x, double* c) noexcept;
double rc52(const double* x, double* c) noexcept;
double rc53(const double* x, double* c) noexcept;
double rc54(const double* x, double* c) noexcept;
double rc55(const double* x, double* c) noexcept;
double rc56(const double* x, double* c) noexcept;
double rc57(const double* x, double* c) noexcept;
struct AdmittanceEntry {
    int row, column;
    double g, b;  // Y = G + jB
};

extern const double kFeed[7][59];      // RC51-RC54: FunctionRM_feed.txt
extern const double kDairy[14][64];    // RC55-RC57: FunctionRM_dairy.txt
extern const AdmittanceEntry kPs1Y[];  // RC34: FunctionPS1_G.txt, FunctionPS1_B.txt
extern const std::size_t kPs1YCount;
extern const AdmittanceEntry kPs2Y[];  // RC35, RC36, RC41: FunctionPS2_G.txt, FunctionPS2_B.txt
extern const std::size_t kPs2YCount;
extern const AdmittanceEntry kPs11Y[];  // RC37-RC39: FunctionPS11_G.txt, FunctionPS11_B.txt
extern const std::size_t kPs11YCount;
extern const double kPs1P[30], kPs1Q[30], kPs11P[30], kPs11Q[30];
extern const double kPs2P[38][6], kPs2Q[38][6];  // RC35, RC36, RC40-RC43: loads and their exponents
extern const double kPs14Lines[37][6];           // RC40, RC42, RC43: from, to, R, X, B/2, tap

}  // namespace pride::continuous::cec2020rw::detail

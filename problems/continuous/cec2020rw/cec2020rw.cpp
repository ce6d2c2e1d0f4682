// The CEC 2020 real-world suite: the table of its problems (bounds of Cal_par.m, constraint counts
// as the code returns them, f* of Table 3) and the Problem that evaluates one. The problems' functions
// are in one file per family of the suite (cec2020rw_detail.hpp lists them).
#include "problems/continuous/cec2020rw/cec2020rw.hpp"

#include <array>
#include <cassert>
#include <string>

#include "framework/error.hpp"
#include "problems/continuous/cec2020rw/cec2020rw_detail.hpp"

namespace pride::continuous::cec2020rw {

namespace {

using namespace detail;  // the problems' functions rc01 ... rc57

using Function = double (*)(const double*, double*) noexcept;

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
    Function function;
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
    {"RC23", rc23, 8, 3, 1.6069868725E+01, kLo23, kHi23},   {"RC24", rc24, 7, 0, 2.5287918415E+00, kLo24, kHi24},
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
    return kSpecs[number - 1];
}

}  // namespace

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

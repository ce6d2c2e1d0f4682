#pragma once
// Tanabe and Ishibuchi's (2020) real-world multi-objective problems ("An easy-to-use real-world
// multi-objective optimization problem suite", Applied Soft Computing 89, 106078): the 16 RE
// problems RE21-RE91, unconstrained, and the 8 CRE problems CRE21-CRE51, constrained. Names lower
// case: "re21" ... "re91", "cre21" ... "cre51" (kCatalog).
//
// The definitions are the official code's (GitHub ryojitanabe/reproblems, commit 2884574 of
// 2021-05-29, its C version reproblem.c; the suite has no C++ version; its Python version gives the
// same values but for the last bits where numpy's pow and exp differ from libm's, at most 3e-14
// relative at tests/data/re/'s points). That code includes the suite's fixes, followed here: RE21's
// E = 2e5 (was 2 * 10e5) and f2's first term 2 / x1 (was 2 / x2); RE25's G = 11.5e6 (was
// 11.5 * 10e6); RE42's and CRE32's sixth constraint 500000 - DWT (was 50000 - DWT). The fronts of
// $PRIDE_DATA/re-fronts are those of the fixed problems (fronts.hpp).
//
// An RE problem with constraints has them folded into its last objective, as the code does: that
// objective is sum_i fold(g_i), fold(g) = -g where g < 0, else 0, over the code's constraint values
// g_i (>= 0 feasible), in order. A CRE problem keeps them as constraints: pride's inequality values
// are c_i = -g_i (<= 0 feasible, framework/constraints.hpp; the negation is exact), and violation(c)
// is the suite's measure, the sum in order of max(0, c_i) (the code's folded values, which its
// objectives of the RE versions add up; its jMetal version's overall violation sums only negative
// folded values, always 0). None has an equality constraint. A NaN c_i counts as an infinite
// violation (framework/constraints.hpp); the code's fold counts it as satisfied (NaN < 0 is
// false), and so does the RE objective here, which is the code's value. No value is NaN at 200000
// uniform points of each box; some are NaN on thin sets: RE22's corner x2 = x3 = 0, and RE33's
// and CRE23's x1 = x2 (a 0 / 0).
//
// The code's quirks, kept:
// - Discrete variables are made so inside the function, the point itself unchanged: RE22's x1
//   snapped to the nearest of its 77 areas (the code's list has "3,10" for 3.10: 3 and 10; the first
//   of equally near values), RE23's x1 and x2 are 0.0625 round(x), RE25's x1 round(x1) and x3 the
//   nearest of its 42 diameters, RE35's and CRE24's x3 round(x3), RE36's and CRE25's four variables
//   round(x). round() is C's, halves away from 0 (the Python version's np.round halves to even).
// - RE21's f1 has sqrt(x3), not sqrt(2) x3 (the code's).
// - RE31's and CRE21's first two constraints are of f1 and f2 (0.1 - f1, 100000 - f2).
// - RE42's and CRE32's third objective is minus the annual cargo (maximised).
// - RE91 is stochastic: each evaluation draws x8 ~ N(0.345, 0.006^2), x9 ~ N(0.192, 0.006^2),
//   x10, x11 ~ N(0, 10^2). Here they come from the problem's own Rng (framework/random.hpp), seed 0
//   until reseed(seed) (an algorithm calls it once, framework/problem.hpp's Reseedable): a copy
//   continues the same stream, so a run is reproducible from its seed. The code draws them from C's
//   rand() (Box-Muller) or numpy's global generator; formulas::re91 is the formula given the draws.
//   RE91's f1 has 1.75 x5 where RE41's has 1.78 (the code's).
// - RE36 and CRE25 (gear train): f2 is the largest number of teeth.
// Values equal the code's to the last bit on x86-64 with GCC and glibc (tests/test_re_problems.cpp).
#include <array>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <span>
#include <string>
#include <string_view>

#include "framework/constraints.hpp"
#include "framework/error.hpp"
#include "framework/problem.hpp"
#include "framework/random.hpp"
#include "problems/multiobjective/re/formulas.hpp"

namespace pride::multiobjective::re {

struct CatalogEntry {
    std::string_view name;
    std::string_view summary;
    std::size_t variables;    // n
    std::size_t objectives;   // M
    std::size_t constraints;  // m inequalities (CRE); 0 for RE
};

/// The suite, in the paper's order. The summaries name the engineering problem and, for RE, how
/// many of its constraints are folded into the last objective.
inline constexpr std::array<CatalogEntry, 24> kCatalog{{
    {"re21", "RE2-4-1 four-bar truss design: volume, displacement", 4, 2, 0},
    {"re22", "RE2-3-2 reinforced concrete beam design: cost; 2 constraints folded into f2", 3, 2, 0},
    {"re23", "RE2-4-3 pressure vessel design: cost; 3 constraints folded into f2", 4, 2, 0},
    {"re24", "RE2-2-4 hatch cover design: weight; 4 constraints folded into f2", 2, 2, 0},
    {"re25", "RE2-3-5 coil compression spring design: volume; 6 constraints folded into f2", 3, 2, 0},
    {"re31", "RE3-3-1 two-bar truss design: volume, stress; 3 constraints folded into f3", 3, 3, 0},
    {"re32", "RE3-4-2 welded beam design: cost, deflection; 4 constraints folded into f3", 4, 3, 0},
    {"re33", "RE3-4-3 disc brake design: mass, stopping time; 4 constraints folded into f3", 4, 3, 0},
    {"re34", "RE3-5-4 vehicle crashworthiness design: mass, acceleration, toe-board intrusion", 5, 3, 0},
    {"re35", "RE3-7-5 speed reducer design: weight, stress; 11 constraints folded into f3", 7, 3, 0},
    {"re36", "RE3-4-6 gear train design: ratio error, largest gear; 1 constraint folded into f3", 4, 3, 0},
    {"re37", "RE3-4-7 rocket injector design: three response surfaces", 4, 3, 0},
    {"re41", "RE4-7-1 car side impact design: 3 objectives; 10 constraints folded into f4", 7, 4, 0},
    {"re42", "RE4-6-2 conceptual marine design: 3 objectives; 9 constraints folded into f4", 6, 4, 0},
    {"re61", "RE6-3-1 water resource planning: 5 objectives; 7 constraints folded into f6", 3, 6, 0},
    {"re91", "RE9-7-1 car cab design: 9 objectives, 4 random parameters drawn at each evaluation", 7, 9, 0},
    {"cre21", "CRE2-3-1 two-bar truss design: volume, stress; 3 constraints", 3, 2, 3},
    {"cre22", "CRE2-4-2 welded beam design: cost, deflection; 4 constraints", 4, 2, 4},
    {"cre23", "CRE2-4-3 disc brake design: mass, stopping time; 4 constraints", 4, 2, 4},
    {"cre24", "CRE2-7-4 speed reducer design: weight, stress; 11 constraints", 7, 2, 11},
    {"cre25", "CRE2-4-5 gear train design: ratio error, largest gear; 1 constraint", 4, 2, 1},
    {"cre31", "CRE3-7-1 car side impact design: 3 objectives; 10 constraints", 7, 3, 10},
    {"cre32", "CRE3-6-2 conceptual marine design: 3 objectives; 9 constraints", 6, 3, 9},
    {"cre51", "CRE5-3-1 water resource planning: 5 objectives; 7 constraints", 3, 5, 7},
}};

// Problem::compute's cases are kCatalog's indices.
static_assert(kCatalog[0].name == "re21" && kCatalog[14].name == "re61" && kCatalog[15].name == "re91" &&
              kCatalog[16].name == "cre21" && kCatalog[23].name == "cre51");

/// The most variables, objectives and constraints of a problem of the suite (RE91's 9 objectives;
/// CRE24's 11 constraints).
inline constexpr std::size_t kMostVariables = 7;
inline constexpr std::size_t kMostObjectives = 9;
inline constexpr std::size_t kMostConstraints = 11;

/// The entry of `name`, or nullptr.
inline const CatalogEntry* find_problem(std::string_view name) noexcept {
    for (const auto& e : kCatalog)
        if (e.name == name) return &e;
    return nullptr;
}

/// The suite's names, comma-separated (for messages).
inline std::string problem_names() {
    std::string names;
    for (const auto& e : kCatalog) names += (names.empty() ? "" : ", ") + std::string(e.name);
    return names;
}

namespace detail {

/// The code's boxes, in kCatalog's order (a CRE problem has its RE version's box). RE21's lower
/// bounds are the code's (F / sigma) times 1, sqrt(2), sqrt(2), 1 with F = sigma = 10.
struct Box {
    double lower[kMostVariables];
    double upper[kMostVariables];
};
inline constexpr double kSqrt2 = std::numbers::sqrt2;  // sqrt(2.0), correctly rounded both ways
inline constexpr Box kTwoBarTruss{{0.00001, 0.00001, 1.0}, {100.0, 100.0, 3.0}};
inline constexpr Box kWeldedBeam{{0.125, 0.1, 0.1, 0.125}, {5.0, 10.0, 10.0, 5.0}};
inline constexpr Box kDiscBrake{{55, 75, 1000, 11}, {80, 110, 3000, 20}};
inline constexpr Box kSpeedReducer{{2.6, 0.7, 17, 7.3, 7.3, 2.9, 5.0}, {3.6, 0.8, 28, 8.3, 8.3, 3.9, 5.5}};
inline constexpr Box kGearTrain{{12, 12, 12, 12}, {60, 60, 60, 60}};
inline constexpr Box kCarSideImpact{{0.5, 0.45, 0.5, 0.5, 0.875, 0.4, 0.4}, {1.5, 1.35, 1.5, 1.5, 2.625, 1.2, 1.2}};
inline constexpr Box kMarineDesign{{150.0, 20.0, 13.0, 10.0, 14.0, 0.63}, {274.32, 32.31, 25.0, 11.71, 18.0, 0.75}};
inline constexpr Box kWaterResources{{0.01, 0.01, 0.01}, {0.45, 0.10, 0.10}};
inline constexpr std::array<Box, 24> kBoxes{{
    {{1.0, kSqrt2, kSqrt2, 1.0}, {3.0, 3.0, 3.0, 3.0}},      // re21
    {{0.2, 0, 0}, {15, 20, 40}},                             // re22
    {{1, 1, 10, 10}, {100, 100, 200, 240}},                  // re23
    {{0.5, 0.5}, {4, 50}},                                   // re24
    {{1, 0.6, 0.09}, {70, 3, 0.5}},                          // re25
    kTwoBarTruss,                                            // re31
    kWeldedBeam,                                             // re32
    kDiscBrake,                                              // re33
    {{1.0, 1.0, 1.0, 1.0, 1.0}, {3.0, 3.0, 3.0, 3.0, 3.0}},  // re34
    kSpeedReducer,                                           // re35
    kGearTrain,                                              // re36
    {{0.0, 0.0, 0.0, 0.0}, {1.0, 1.0, 1.0, 1.0}},            // re37
    kCarSideImpact,                                          // re41
    kMarineDesign,                                           // re42
    kWaterResources,                                         // re61
    kCarSideImpact,                                          // re91
    kTwoBarTruss,                                            // cre21
    kWeldedBeam,                                             // cre22
    kDiscBrake,                                              // cre23
    kSpeedReducer,                                           // cre24
    kGearTrain,                                              // cre25
    kCarSideImpact,                                          // cre31
    kMarineDesign,                                           // cre32
    kWaterResources,                                         // cre51
}};

}  // namespace detail

/// One problem of the suite, chosen by name when it is built. A copy is an index into constant
/// tables and RE91's generator state: copying is cheap, and an evaluation is one switch over the 24
/// problems, with neither a virtual call nor an allocation.
class Problem {
  public:
    /// `name`: one of kCatalog's names. InputError(where, "unknown RE problem 'NAME' (known: ...)")
    /// otherwise.
    explicit Problem(std::string_view name, std::string_view where = "problem") : index_(index_of(name, where)) {}

    std::string_view name() const noexcept { return entry().name; }
    const CatalogEntry& entry() const noexcept { return kCatalog[index_]; }
    std::size_t dimension() const noexcept { return entry().variables; }
    std::span<const double> lower() const noexcept { return {detail::kBoxes[index_].lower, dimension()}; }
    std::span<const double> upper() const noexcept { return {detail::kBoxes[index_].upper, dimension()}; }
    std::size_t objectives() const noexcept { return entry().objectives; }
    /// {m, 0}: m inequalities for a CRE problem, none for an RE one.
    ConstraintCounts constraint_counts() const noexcept { return {entry().constraints, 0}; }

    /// The objectives at x (dimension() values) into f (objectives() values). Not const: RE91 draws
    /// its random parameters from the problem's generator.
    void evaluate(std::span<const double> x, std::span<double> f) {
        double c[kMostConstraints];
        compute(x.data(), f.data(), c);
    }
    /// The objectives into f and the constraint values c_i (<= 0 feasible) into c (at least
    /// constraint_counts().total() values; none written for an RE problem): one evaluation.
    void evaluate_constrained(std::span<const double> x, std::span<double> f, std::span<double> c) {
        if (entry().constraints == 0) {
            evaluate(x, f);
            return;
        }
        compute(x.data(), f.data(), c.data());
    }
    /// Every column of `points` into the same column of `values` (objectives() rows), in column order
    /// (RE91's draws as many evaluate() calls would make them).
    void evaluate_batch(MatrixView points, Matrix& values) {
        double c[kMostConstraints];
        for (Eigen::Index j = 0; j < points.cols(); ++j) compute(points.col(j).data(), values.col(j).data(), c);
    }
    /// The suite's violation of the values evaluate_constrained() wrote: sum_i max(0, c_i), in order
    /// (a NaN c_i: +inf). 0 for an RE problem.
    double violation(std::span<const double> c) const noexcept {
        double sum = 0.0;
        for (std::size_t i = 0; i < entry().constraints; ++i) sum += inequality_violation(c[i]);
        return sum;
    }

    /// Restarts RE91's random parameters from `seed` (a no-op for the others).
    void reseed(std::uint64_t seed) noexcept { rng_ = Rng(seed); }
    /// True for RE91 only.
    bool noisy() const noexcept { return entry().name == "re91"; }

  private:
    static std::size_t index_of(std::string_view name, std::string_view where) {
        const CatalogEntry* e = find_problem(name);
        if (e == nullptr)
            throw InputError(std::string(where),
                             "unknown RE problem '" + std::string(name) + "' (known: " + problem_names() + ")");
        return static_cast<std::size_t>(e - kCatalog.data());
    }

    /// The CRE problems' constraint values in pride's sign.
    static void negate(double* c, std::size_t m) noexcept {
        for (std::size_t i = 0; i < m; ++i) c[i] = -c[i];
    }

    void compute(const double* x, double* f, double* c) {
        namespace fm = formulas;
        switch (index_) {
            case 0:
                return fm::re21(x, f);
            case 1:
                return fm::re22(x, f);
            case 2:
                return fm::re23(x, f);
            case 3:
                return fm::re24(x, f);
            case 4:
                return fm::re25(x, f);
            case 5:
                return fm::re31(x, f);
            case 6:
                return fm::re32(x, f);
            case 7:
                return fm::re33(x, f);
            case 8:
                return fm::re34(x, f);
            case 9:
                return fm::re35(x, f);
            case 10:
                return fm::re36(x, f);
            case 11:
                return fm::re37(x, f);
            case 12:
                return fm::re41(x, f);
            case 13:
                return fm::re42(x, f);
            case 14:
                return fm::re61(x, f);
            case 15: {
                // In the code's order: x8, x9, x10, x11.
                const double xi[4] = {0.006 * rng_.normal() + 0.345, 0.006 * rng_.normal() + 0.192,
                                      10 * rng_.normal() + 0.0, 10 * rng_.normal() + 0.0};
                return fm::re91(x, xi, f);
            }
            case 16:
                fm::two_bar_truss(x, f, c);
                return negate(c, 3);
            case 17:
                fm::welded_beam(x, f, c);
                return negate(c, 4);
            case 18:
                fm::disc_brake(x, f, c);
                return negate(c, 4);
            case 19:
                fm::speed_reducer(x, f, c);
                return negate(c, 11);
            case 20:
                fm::gear_train(x, f, c);
                return negate(c, 1);
            case 21:
                fm::car_side_impact(x, f, c);
                return negate(c, 10);
            case 22:
                fm::marine_design(x, f, c);
                return negate(c, 9);
            default:
                fm::water_resources(x, f, c);
                return negate(c, 7);
        }
    }

    std::size_t index_;
    Rng rng_{0};
};

}  // namespace pride::multiobjective::re

// The suites' functions as cec17_test_func.cpp and cec22_test_func.cpp assemble them from the basic
// functions (kernel.cpp): which basic function, which scaling of its value, which group shares
// (hybrids) and which deltas and biases (compositions). Equation numbers are the reports'.
#include "problems/continuous/cec/functions.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "framework/error.hpp"

namespace pride::continuous::cec {

namespace {

enum class Basic {
    ellips,
    bent_cigar,
    discus,
    sum_diff_pow,
    zakharov,
    rosenbrock,
    schaffer_f7,
    ackley,
    weierstrass,
    griewank,
    rastrigin,
    step_rastrigin,
    schwefel,
    katsuura,
    bi_rastrigin,
    grie_rosen,
    escaffer6,
    happycat,
    hgbat,
    levy_2017,
    levy_2022,
};

double call(Kernel& k, Basic b, const double* x, int nx, const double* os, const double* mr, bool s, bool r) {
    switch (b) {
        case Basic::ellips:
            return k.ellips(x, nx, os, mr, s, r);
        case Basic::bent_cigar:
            return k.bent_cigar(x, nx, os, mr, s, r);
        case Basic::discus:
            return k.discus(x, nx, os, mr, s, r);
        case Basic::sum_diff_pow:
            return k.sum_diff_pow(x, nx, os, mr, s, r);
        case Basic::zakharov:
            return k.zakharov(x, nx, os, mr, s, r);
        case Basic::rosenbrock:
            return k.rosenbrock(x, nx, os, mr, s, r);
        case Basic::schaffer_f7:
            return k.schaffer_f7(x, nx, os, mr, s, r);
        case Basic::ackley:
            return k.ackley(x, nx, os, mr, s, r);
        case Basic::weierstrass:
            return k.weierstrass(x, nx, os, mr, s, r);
        case Basic::griewank:
            return k.griewank(x, nx, os, mr, s, r);
        case Basic::rastrigin:
            return k.rastrigin(x, nx, os, mr, s, r);
        case Basic::step_rastrigin:
            return k.step_rastrigin(x, nx, os, mr, s, r);
        case Basic::schwefel:
            return k.schwefel(x, nx, os, mr, s, r);
        case Basic::katsuura:
            return k.katsuura(x, nx, os, mr, s, r);
        case Basic::bi_rastrigin:
            return k.bi_rastrigin(x, nx, os, mr, s, r);
        case Basic::grie_rosen:
            return k.grie_rosen(x, nx, os, mr, s, r);
        case Basic::escaffer6:
            return k.escaffer6(x, nx, os, mr, s, r);
        case Basic::happycat:
            return k.happycat(x, nx, os, mr, s, r);
        case Basic::hgbat:
            return k.hgbat(x, nx, os, mr, s, r);
        case Basic::levy_2017:
            return k.levy(x, nx, os, mr, s, r, false);
        case Basic::levy_2022:
            return k.levy(x, nx, os, mr, s, r, true);
    }
    return 0.0;
}

/// A hybrid function (2017 eq. of section 2.3, hf01-hf10): shift, rotate, permute, then basic
/// function i on group i (its share of the coordinates), unshifted and unrotated; the sum.
struct Hybrid {
    int groups;
    std::array<double, 6> share;
    std::array<Basic, 6> basic;
};

double hybrid(Kernel& k, const Hybrid& h, const double* x, int nx, const double* os, const double* mr,
              const int* shuffle) {
    std::array<int, 6> size{}, start{};
    int used = 0;
    for (int i = 0; i + 1 < h.groups; ++i) {
        size[i] = static_cast<int>(std::ceil(h.share[i] * nx));
        used += size[i];
    }
    size[h.groups - 1] = nx - used;
    for (int i = 1; i < h.groups; ++i) start[i] = start[i - 1] + size[i - 1];
    k.permute(x, nx, os, mr, shuffle);
    std::array<double, 6> fit{};
    for (int i = 0; i < h.groups; ++i) fit[i] = call(k, h.basic[i], k.y() + start[i], size[i], os, mr, false, false);
    double f = 0.0;
    for (int i = 0; i < h.groups; ++i) f += fit[i];
    return f;
}

using B = Basic;
// 2017 hf01-hf10 (F11-F20).
constexpr std::array<Hybrid, 10> kHybrid2017{{
    {3, {0.2, 0.4, 0.4}, {B::zakharov, B::rosenbrock, B::rastrigin}},
    {3, {0.3, 0.3, 0.4}, {B::ellips, B::schwefel, B::bent_cigar}},
    {3, {0.3, 0.3, 0.4}, {B::bent_cigar, B::rosenbrock, B::bi_rastrigin}},
    {4, {0.2, 0.2, 0.2, 0.4}, {B::ellips, B::ackley, B::schaffer_f7, B::rastrigin}},
    {4, {0.2, 0.2, 0.3, 0.3}, {B::bent_cigar, B::hgbat, B::rastrigin, B::rosenbrock}},
    {4, {0.2, 0.2, 0.3, 0.3}, {B::escaffer6, B::hgbat, B::rosenbrock, B::schwefel}},
    {5, {0.1, 0.2, 0.2, 0.2, 0.3}, {B::katsuura, B::ackley, B::grie_rosen, B::schwefel, B::rastrigin}},
    {5, {0.2, 0.2, 0.2, 0.2, 0.2}, {B::ellips, B::ackley, B::rastrigin, B::hgbat, B::discus}},
    {5, {0.2, 0.2, 0.2, 0.2, 0.2}, {B::bent_cigar, B::rastrigin, B::grie_rosen, B::weierstrass, B::escaffer6}},
    {6, {0.1, 0.1, 0.2, 0.2, 0.2, 0.2}, {B::hgbat, B::katsuura, B::ackley, B::rastrigin, B::schwefel, B::schaffer_f7}},
}};
// 2022 F6-F8 (the code's hf02, hf10, hf06, with their 2022 shares and functions).
constexpr std::array<Hybrid, 3> kHybrid2022{{
    {3, {0.4, 0.4, 0.2}, {B::bent_cigar, B::hgbat, B::rastrigin}},
    {6, {0.1, 0.2, 0.2, 0.2, 0.1, 0.2}, {B::hgbat, B::katsuura, B::ackley, B::rastrigin, B::schwefel, B::schaffer_f7}},
    {5, {0.3, 0.2, 0.2, 0.1, 0.2}, {B::katsuura, B::happycat, B::grie_rosen, B::schwefel, B::ackley}},
}};

/// One component of a composition: a basic function (or a hybrid: index into the hybrids), its
/// value scaled as num * f / den (1, 1: as is), rotated or not.
struct Component {
    Basic basic;
    double num = 1, den = 1;
    bool rotated = true;
    int hybrid = -1;  // 2017 F29, F30: index into kHybrid2017
};

/// A composition function (cf01-cf10): components evaluated at x, each with its own o_i and M_i,
/// combined by cf_cal with weights from delta and biases.
struct Composition {
    int components;
    std::array<Component, 6> c;
    std::array<double, 6> delta;
    std::array<double, 6> bias;
};

double composition(Kernel& k, const Composition& cf, const double* x, int nx, const Data& d) {
    std::array<double, 6> fit{};
    const auto n = static_cast<std::size_t>(nx);
    for (int i = 0; i < cf.components; ++i) {
        const Component& c = cf.c[i];
        const auto row = static_cast<std::size_t>(i);
        const double* os = d.shift.data() + row * n;
        const double* mr = d.rotation.data() + row * n * n;
        if (c.hybrid >= 0) {
            fit[i] =
                hybrid(k, kHybrid2017[static_cast<std::size_t>(c.hybrid)], x, nx, os, mr, d.shuffle.data() + row * n);
        } else {
            fit[i] = call(k, c.basic, x, nx, os, mr, true, c.rotated);
            if (c.num != 1 || c.den != 1) fit[i] = c.num * fit[i] / c.den;
        }
    }
    return Kernel::compose(x, nx, d.shift.data(), cf.delta.data(), cf.bias.data(), fit.data(), cf.components);
}

constexpr Component hyb(int index) {
    return Component{B::ellips, 1, 1, true, index};
}

// The components of the code's cf06 and cf07, which both years use (2017 F26, F27; 2022 F11, F12)
// with their own deltas and biases.
constexpr std::array<Component, 6> kCf06{
    {{B::escaffer6, 10000, 2e7}, {B::schwefel}, {B::griewank, 1000, 100}, {B::rosenbrock}, {B::rastrigin, 10000, 1e3}}};
constexpr std::array<Component, 6> kCf07{{{B::hgbat, 10000, 1000},
                                          {B::rastrigin, 10000, 1e3},
                                          {B::schwefel, 10000, 4e3},
                                          {B::bent_cigar, 10000, 1e30},
                                          {B::ellips, 10000, 1e10},
                                          {B::escaffer6, 10000, 2e7}}};

// 2017 cf01-cf10 (F21-F30).
const std::array<Composition, 10> kComposition2017{{
    {3, {{{B::rosenbrock}, {B::ellips, 10000, 1e10}, {B::rastrigin}}}, {10, 20, 30}, {0, 100, 200}},
    {3, {{{B::rastrigin}, {B::griewank, 1000, 100}, {B::schwefel}}}, {10, 20, 30}, {0, 100, 200}},
    {4,
     {{{B::rosenbrock}, {B::ackley, 1000, 100}, {B::schwefel}, {B::rastrigin}}},
     {10, 20, 30, 40},
     {0, 100, 200, 300}},
    {4,
     {{{B::ackley, 1000, 100}, {B::ellips, 10000, 1e10}, {B::griewank, 1000, 100}, {B::rastrigin}}},
     {10, 20, 30, 40},
     {0, 100, 200, 300}},
    {5,
     {{{B::rastrigin, 10000, 1e3},
       {B::happycat, 1000, 1e3},
       {B::ackley, 1000, 100},
       {B::discus, 10000, 1e10},
       {B::rosenbrock}}},
     {10, 20, 30, 40, 50},
     {0, 100, 200, 300, 400}},
    {5, kCf06, {10, 20, 20, 30, 40}, {0, 100, 200, 300, 400}},
    {6, kCf07, {10, 20, 30, 40, 50, 60}, {0, 100, 200, 300, 400, 500}},
    {6,
     {{{B::ackley, 1000, 100},
       {B::griewank, 1000, 100},
       {B::discus, 10000, 1e10},
       {B::rosenbrock},
       {B::happycat, 1000, 1e3},
       {B::escaffer6, 10000, 2e7}}},
     {10, 20, 30, 40, 50, 60},
     {0, 100, 200, 300, 400, 500}},
    {3, {{hyb(4), hyb(5), hyb(6)}}, {10, 30, 50}, {0, 100, 200}},  // hf05, hf06, hf07
    {3, {{hyb(4), hyb(7), hyb(8)}}, {10, 30, 50}, {0, 100, 200}},  // hf05, hf08, hf09
}};

// 2022 F9-F12 (the code's cf01, cf02, cf06, cf07 with their 2022 tables; F9's fifth and F10's first
// component are not rotated in the code).
const std::array<Composition, 4> kComposition2022{{
    {5,
     {{{B::rosenbrock, 10000, 1e4},
       {B::ellips, 10000, 1e10},
       {B::bent_cigar, 10000, 1e30},
       {B::discus, 10000, 1e10},
       {B::ellips, 10000, 1e10, false}}},
     {10, 20, 30, 40, 50},
     {0, 200, 300, 100, 400}},
    {3, {{{B::schwefel, 1, 1, false}, {B::rastrigin}, {B::hgbat}}}, {20, 10, 10}, {0, 200, 100}},
    {5, kCf06, {20, 20, 30, 30, 20}, {0, 200, 300, 400, 200}},
    {6, kCf07, {10, 20, 30, 40, 50, 60}, {0, 300, 500, 100, 400, 200}},
}};

// 2017 F1-F10 and 2022 F1-F5: one basic function, shifted and rotated.
constexpr std::array<Basic, 10> kSimple2017{B::bent_cigar, B::sum_diff_pow, B::zakharov,     B::rosenbrock,
                                            B::rastrigin,  B::schaffer_f7,  B::bi_rastrigin, B::step_rastrigin,
                                            B::levy_2017,  B::schwefel};
constexpr std::array<Basic, 5> kSimple2022{B::zakharov, B::rosenbrock, B::schaffer_f7, B::step_rastrigin, B::levy_2022};

constexpr std::array<double, 12> kBias2022{300, 400, 600, 800, 900, 1800, 2000, 2200, 2300, 2400, 2600, 2700};

Needs needs(Suite suite, int function) {
    if (suite == Suite::y2017) {
        if (function >= 11 && function <= 20) return {1, 1};
        if (function >= 21 && function <= 28)
            return {static_cast<std::size_t>(kComposition2017[static_cast<std::size_t>(function - 21)].components), 0};
        if (function >= 29) return {3, 3};
        return {1, 0};
    }
    if (function >= 6 && function <= 8) return {1, 1};
    if (function >= 9)
        return {static_cast<std::size_t>(kComposition2022[static_cast<std::size_t>(function - 9)].components), 0};
    return {1, 0};
}

#define PRIDE_CEC_INFO(suite, k, what)                                                             \
    FunctionInfo {                                                                                 \
        "cec" #suite "-f" #k, "CEC " #suite " F" #k ": " what, -100, 100, 2, unknown_coordinate, 0 \
    }

constexpr double unknown_coordinate = std::numeric_limits<double>::quiet_NaN();

// optimum_value is unused (CecFunction::optimum_value gives the bias); names and summaries.
constexpr std::array<FunctionInfo, 30> kInfo2017{
    PRIDE_CEC_INFO(2017, 1, "shifted and rotated bent cigar"),
    PRIDE_CEC_INFO(2017, 2, "shifted and rotated sum of different powers (excluded from the 2017 competition)"),
    PRIDE_CEC_INFO(2017, 3, "shifted and rotated Zakharov"),
    PRIDE_CEC_INFO(2017, 4, "shifted and rotated Rosenbrock"),
    PRIDE_CEC_INFO(2017, 5, "shifted and rotated Rastrigin"),
    PRIDE_CEC_INFO(2017, 6, "shifted and rotated expanded Schaffer F6 (the code: Schaffer F7, unrotated)"),
    PRIDE_CEC_INFO(2017, 7, "shifted and rotated Lunacek bi-Rastrigin"),
    PRIDE_CEC_INFO(2017, 8, "shifted and rotated non-continuous Rastrigin (the code: Rastrigin)"),
    PRIDE_CEC_INFO(2017, 9, "shifted and rotated Levy (the code: f(o) > f*)"),
    PRIDE_CEC_INFO(2017, 10, "shifted and rotated Schwefel"),
    PRIDE_CEC_INFO(2017, 11, "hybrid function 1 (N = 3)"),
    PRIDE_CEC_INFO(2017, 12, "hybrid function 2 (N = 3)"),
    PRIDE_CEC_INFO(2017, 13, "hybrid function 3 (N = 3)"),
    PRIDE_CEC_INFO(2017, 14, "hybrid function 4 (N = 4)"),
    PRIDE_CEC_INFO(2017, 15, "hybrid function 5 (N = 4)"),
    PRIDE_CEC_INFO(2017, 16, "hybrid function 6 (N = 4)"),
    PRIDE_CEC_INFO(2017, 17, "hybrid function 6 (N = 5)"),
    PRIDE_CEC_INFO(2017, 18, "hybrid function 6 (N = 5)"),
    PRIDE_CEC_INFO(2017, 19, "hybrid function 6 (N = 5)"),
    PRIDE_CEC_INFO(2017, 20, "hybrid function 6 (N = 6)"),
    PRIDE_CEC_INFO(2017, 21, "composition function 1 (N = 3)"),
    PRIDE_CEC_INFO(2017, 22, "composition function 2 (N = 3)"),
    PRIDE_CEC_INFO(2017, 23, "composition function 3 (N = 4)"),
    PRIDE_CEC_INFO(2017, 24, "composition function 4 (N = 4)"),
    PRIDE_CEC_INFO(2017, 25, "composition function 5 (N = 5)"),
    PRIDE_CEC_INFO(2017, 26, "composition function 6 (N = 5)"),
    PRIDE_CEC_INFO(2017, 27, "composition function 7 (N = 6)"),
    PRIDE_CEC_INFO(2017, 28, "composition function 8 (N = 6)"),
    PRIDE_CEC_INFO(2017, 29, "composition function 9 (N = 3, of hybrids)"),
    PRIDE_CEC_INFO(2017, 30, "composition function 10 (N = 3, of hybrids)"),
};
constexpr std::array<FunctionInfo, 12> kInfo2022{
    PRIDE_CEC_INFO(2022, 1, "shifted and full rotated Zakharov"),
    PRIDE_CEC_INFO(2022, 2, "shifted and full rotated Rosenbrock"),
    PRIDE_CEC_INFO(2022, 3, "shifted and full rotated expanded Schaffer f6 (the code: Schaffer F7, unrotated)"),
    PRIDE_CEC_INFO(2022, 4, "shifted and full rotated non-continuous Rastrigin (the code: Rastrigin)"),
    PRIDE_CEC_INFO(2022, 5, "shifted and full rotated Levy"),
    PRIDE_CEC_INFO(2022, 6, "hybrid function 1 (N = 3)"),
    PRIDE_CEC_INFO(2022, 7, "hybrid function 2 (N = 6)"),
    PRIDE_CEC_INFO(2022, 8, "hybrid function 3 (N = 5)"),
    PRIDE_CEC_INFO(2022, 9, "composition function 1 (N = 5)"),
    PRIDE_CEC_INFO(2022, 10, "composition function 2 (N = 3)"),
    PRIDE_CEC_INFO(2022, 11, "composition function 3 (N = 5)"),
    PRIDE_CEC_INFO(2022, 12, "composition function 4 (N = 6)"),
};
#undef PRIDE_CEC_INFO

void check_number(Suite suite, int function) {
    require(function >= 1 && function <= size(suite), std::string(suite_name(suite)),
            "has functions 1-" + std::to_string(size(suite)) + ", got " + std::to_string(function));
}

std::size_t checked_dim(Suite suite, int function, std::size_t dim) {
    check_number(suite, function);
    const auto dims = dimensions(suite, function);
    if (std::find(dims.begin(), dims.end(), dim) == dims.end()) {
        std::string list;
        for (const std::size_t d : dims) list += (list.empty() ? "" : ", ") + std::to_string(d);
        throw InputError(
            std::string(info(suite, function).name),
            "is defined in dimensions " + list + " (the official code and data), got " + std::to_string(dim));
    }
    return dim;
}

}  // namespace

int size(Suite suite) noexcept {
    return suite == Suite::y2017 ? 30 : 12;
}

double bias(Suite suite, int function) noexcept {
    if (suite == Suite::y2017) return 100.0 * function;
    return kBias2022[static_cast<std::size_t>(std::clamp(function, 1, 12) - 1)];
}

const FunctionInfo& info(Suite suite, int function) {
    check_number(suite, function);
    const auto i = static_cast<std::size_t>(function - 1);
    return suite == Suite::y2017 ? kInfo2017[i] : kInfo2022[i];
}

std::vector<std::size_t> dimensions(Suite suite, int function) {
    check_number(suite, function);
    if (suite == Suite::y2017) {
        const bool hybrid = function >= 11 && function <= 20;
        const bool at_2 = !hybrid && function != 21 && function != 22 && function != 29 && function != 30;
        const bool at_20 = function <= 10 || (function >= 20 && function <= 28);
        std::vector<std::size_t> d;
        if (at_2) d.push_back(2);
        d.push_back(10);
        if (at_20) d.push_back(20);
        for (const std::size_t n : {30, 50, 100}) d.push_back(n);
        return d;
    }
    if (function >= 6 && function <= 8) return {10, 20};
    return {2, 10, 20};
}

std::uint64_t data_fingerprint(Suite suite, int function, std::size_t dim) {
    const auto data = load(suite, function, checked_dim(suite, function, dim), needs(suite, function));
    std::uint64_t h = 14695981039346656037ULL;
    const auto add = [&](const void* bytes, std::size_t n) {
        const auto* p = static_cast<const unsigned char*>(bytes);
        for (std::size_t i = 0; i < n; ++i) h = (h ^ p[i]) * 1099511628211ULL;
    };
    add(data->shift.data(), data->shift.size() * sizeof(double));
    add(data->rotation.data(), data->rotation.size() * sizeof(double));
    add(data->shuffle.data(), data->shuffle.size() * sizeof(int));
    return h;
}

CecFunction::CecFunction(Suite suite, int function, std::size_t dim)
    : BoxFunction(checked_dim(suite, function, dim), cec::info(suite, function)),
      suite_(suite),
      number_(function),
      data_(load(suite, function, dim, needs(suite, function))),
      kernel_(dim) {}

std::vector<double> CecFunction::optimum_point() const {
    // 2017 F9: the code's Levy has sin(pi w + 1) and w = 1 + (z - 1)/4, so f(o) - f* = 0.72 (D = 2)
    // to 9.6 (D = 100) and the minimiser is not known.
    if (suite_ == Suite::y2017 && number_ == 9) return {};
    return std::vector<double>(data_->shift.begin(), data_->shift.begin() + static_cast<std::ptrdiff_t>(dimension()));
}

double CecFunction::evaluate(std::span<const double> x) {
    const int nx = static_cast<int>(dimension());
    const double f = suite_ == Suite::y2017 ? evaluate_2017(x.data(), nx) : evaluate_2022(x.data(), nx);
    return f + bias(suite_, number_);
}

double CecFunction::evaluate_2017(const double* x, int nx) {
    const Data& d = *data_;
    const double* os = d.shift.data();
    const double* mr = d.rotation.data();
    if (number_ <= 10)
        return call(kernel_, kSimple2017[static_cast<std::size_t>(number_ - 1)], x, nx, os, mr, true, true);
    if (number_ <= 20)
        return hybrid(kernel_, kHybrid2017[static_cast<std::size_t>(number_ - 11)], x, nx, os, mr, d.shuffle.data());
    return composition(kernel_, kComposition2017[static_cast<std::size_t>(number_ - 21)], x, nx, d);
}

double CecFunction::evaluate_2022(const double* x, int nx) {
    const Data& d = *data_;
    const double* os = d.shift.data();
    const double* mr = d.rotation.data();
    if (number_ <= 5)
        return call(kernel_, kSimple2022[static_cast<std::size_t>(number_ - 1)], x, nx, os, mr, true, true);
    if (number_ <= 8)
        return hybrid(kernel_, kHybrid2022[static_cast<std::size_t>(number_ - 6)], x, nx, os, mr, d.shuffle.data());
    return composition(kernel_, kComposition2022[static_cast<std::size_t>(number_ - 9)], x, nx, d);
}

}  // namespace pride::continuous::cec

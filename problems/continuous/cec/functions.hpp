#pragma once
// The CEC 2017 bound-constrained suite (Awad, Ali, Liang, Qu, Suganthan 2016, "Problem definitions
// and evaluation criteria for the CEC 2017 special session and competition on single objective
// real-parameter numerical optimization", F1-F30) and the CEC 2022 suite (Kumar, Price, Mohamed,
// Hadi, Suganthan 2021, F1-F12), as their official C codes compute them (kernel.hpp lists where
// the codes and the reports disagree; the codes are followed). Box [-100, 100]^D; f* = 100 k in
// 2017, the table of cec22_test_func.cpp in 2022; the official data is read at construction
// (data.hpp). 2017 keeps F2 (sum of different powers), as the final official code does, though
// the report's final version excludes it from the competition for its unstable behaviour.
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "problems/continuous/box_function.hpp"
#include "problems/continuous/cec/data.hpp"
#include "problems/continuous/cec/kernel.hpp"

namespace pride::continuous::cec {

/// The dimensions in which the official code defines `suite`'s function `function` and ships its
/// data: 2017: D = 2, 10, 20, 30, 50, 100 (at D = 2 neither the hybrids F11-F20 nor F21, F22, F29,
/// F30, which the code declares undefined there; at D = 20 no data for F11-F19, F29, F30);
/// 2022: D = 2, 10, 20 (F6-F8 not at D = 2).
std::vector<std::size_t> dimensions(Suite suite, int function);

/// How many functions the suite has (30, 12).
int size(Suite suite) noexcept;

/// f*: the bias the official code adds to function `function`.
double bias(Suite suite, int function) noexcept;

/// The catalog's facts for the function (name "cec2017-f5", the box, f*), a static table.
const FunctionInfo& info(Suite suite, int function);

/// A 64-bit fingerprint (FNV-1a) of the data the function reads, for stores to tell a resume on
/// other data (another folder, an edited file) from one on the same; loads the data (once).
std::uint64_t data_fingerprint(Suite suite, int function, std::size_t dim);

/// One function of one suite in one dimension, with its data. Copies share the (immutable) data and
/// have their own work vectors, so copies can run on different threads.
class CecFunction : public BoxFunction {
  public:
    CecFunction(Suite suite, int function, std::size_t dim);

    double evaluate(std::span<const double> x);

    Suite suite() const noexcept { return suite_; }
    int number() const noexcept { return number_; }
    /// o: the shift vector (of the first component for compositions), where the code gives f = f*;
    /// empty for 2017 F9, whose code does not (functions.cpp).
    std::vector<double> optimum_point() const;
    double optimum_value() const noexcept { return bias(suite_, number_); }

  private:
    double evaluate_2017(const double* x, int nx);
    double evaluate_2022(const double* x, int nx);

    Suite suite_;
    int number_;
    std::shared_ptr<const Data> data_;
    Kernel kernel_;
};

}  // namespace pride::continuous::cec

#pragma once
// Any function of the catalog (catalog.hpp), as one type: what the engine, the command line and
// Python run. The concrete function (a class of functions.hpp, yao.hpp, extras.hpp, bbob/...) and
// its instance transform (instance.hpp) live behind one pointer, so algorithms are compiled once
// for all functions instead of once per function; the price is one dispatch per call, which the
// batch form (evaluate_batch) pays once per population: inside it the loop over the points is
// fully typed. Scalar evaluate() pays it per evaluation (a switch over the function types, no
// virtual call); algorithms evaluate populations through the batch form.
//
// Batch and scalar evaluation give the same bits for the same point.
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "framework/problem.hpp"
#include "framework/variables.hpp"

namespace pride::continuous {

class Function {
  public:
    struct Impl;  // catalog.cpp
    explicit Function(std::unique_ptr<Impl> impl);
    Function(const Function& other);
    Function& operator=(const Function& other);
    Function(Function&&) noexcept;
    Function& operator=(Function&&) noexcept;
    ~Function();

    std::size_t dimension() const noexcept { return lower_.size(); }
    std::span<const double> lower() const noexcept { return lower_; }
    std::span<const double> upper() const noexcept { return upper_; }
    /// The type of variable i (framework/variables.hpp): integer on bbob-mixint's integer
    /// coordinates, real everywhere else.
    VariableType variable_type(std::size_t i) const noexcept {
        return i < integers_ ? VariableType::integer : VariableType::real;
    }
    /// The catalog name it was made from (an alias such as yao-f9 keeps its own name).
    std::string_view name() const noexcept;
    /// 0: the function as defined; k >= 1: instance k (instance.hpp; BBOB: COCO's instance k).
    std::int64_t instance() const noexcept;

    double evaluate(std::span<const double> x);
    void evaluate_batch(MatrixView points, std::span<double> values);

    /// The minimiser and the minimum of this instance, when known (empty / NaN otherwise).
    std::vector<double> optimum_point() const;
    double optimum_value() const;

    /// Restarts the noise of a noisy function (quartic-noise) from `seed`; a no-op otherwise.
    void reseed(std::uint64_t seed) noexcept;
    bool noisy() const noexcept;

  private:
    std::unique_ptr<Impl> impl_;
    std::vector<double> lower_, upper_;  // copies, so that the box is read without indirection
    std::size_t integers_ = 0;           // variables 0 .. integers_ - 1 are integer (bbob-mixint)
};

}  // namespace pride::continuous

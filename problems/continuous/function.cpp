// continuous::Function's members: each visits the variant of function_variant.hpp once; the
// batch form runs the typed loop over the points inside one visit.
#include <cmath>
#include <limits>
#include <type_traits>

#include "problems/continuous/function_variant.hpp"

namespace pride::continuous {

Function::Function(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {
    std::visit(
        [&](const auto& f) {
            lower_.assign(f.lower().begin(), f.lower().end());
            upper_.assign(f.upper().begin(), f.upper().end());
            if constexpr (requires { f.integer_variables(); }) integers_ = f.integer_variables();
        },
        impl_->function);
}
Function::Function(const Function& other)
    : impl_(std::make_unique<Impl>(*other.impl_)),
      lower_(other.lower_),
      upper_(other.upper_),
      integers_(other.integers_) {}
Function& Function::operator=(const Function& other) {
    if (this != &other) *this = Function(other);
    return *this;
}
Function::Function(Function&&) noexcept = default;
Function& Function::operator=(Function&&) noexcept = default;
Function::~Function() = default;

std::string_view Function::name() const noexcept {
    return impl_->name;
}
std::int64_t Function::instance() const noexcept {
    return impl_->instance;
}

namespace {
/// A formula that overflows far from the box (inf - inf, 0 * inf, sin(inf)) gives NaN at a finite
/// point; the function's value there is beyond the largest double, so it is +inf, like any other
/// overflow. (Ackley and Rastrigin, bounded or not there, are computed so that they do not
/// overflow into NaN: functions.hpp.) A NaN coordinate keeps its NaN.
double overflowed(double value, std::span<const double> x) noexcept {
    for (const double v : x)
        if (!std::isfinite(v)) return value;
    return std::numeric_limits<double>::infinity();
}
}  // namespace

double Function::evaluate(std::span<const double> x) {
    const double value = std::visit([&](auto& f) -> double { return f.evaluate(x); }, impl_->function);
    return std::isnan(value) ? overflowed(value, x) : value;
}

void Function::evaluate_batch(MatrixView points, std::span<double> values) {
    std::visit(
        [&](auto& f) {
            using F = std::decay_t<decltype(f)>;
            if constexpr (BatchBoxProblem<F>) {
                f.evaluate_batch(points, values);
            } else {
                const auto rows = static_cast<std::size_t>(points.rows());
                for (Eigen::Index j = 0; j < points.cols(); ++j)
                    values[static_cast<std::size_t>(j)] =
                        f.evaluate(std::span<const double>(points.col(j).data(), rows));
            }
        },
        impl_->function);
    const auto rows = static_cast<std::size_t>(points.rows());
    for (std::size_t j = 0; j < values.size(); ++j)
        if (std::isnan(values[j]))
            values[j] =
                overflowed(values[j], std::span<const double>(points.col(static_cast<Eigen::Index>(j)).data(), rows));
}

std::vector<double> Function::optimum_point() const {
    return std::visit([](const auto& f) { return f.optimum_point(); }, impl_->function);
}
double Function::optimum_value() const {
    return std::visit([](const auto& f) -> double { return f.optimum_value(); }, impl_->function);
}
void Function::reseed(std::uint64_t seed) noexcept {
    std::visit([&](auto& f) { seed_noise(f, seed); }, impl_->function);
}
bool Function::noisy() const noexcept {
    return std::visit([](const auto& f) { return Reseedable<std::decay_t<decltype(f)>>; }, impl_->function);
}

}  // namespace pride::continuous

// The catalog: every function class and its instances behind continuous::Function. This is the
// one file that compiles them all; the variant below is visited once per call, and once per batch
// in evaluate_batch, whose loop over the points is then typed.
#include "problems/continuous/catalog.hpp"

#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>
#include <variant>

#include "framework/error.hpp"
#include "problems/continuous/functions.hpp"
#include "problems/continuous/transformed.hpp"

namespace pride::continuous {

namespace {

template <class... F>
using WithInstances = std::variant<F..., Transformed<F>...>;

// Scalable functions appear plain and transformed (instances k >= 1, shifted-*).
using Scalable = WithInstances<Sphere, Rastrigin, Rosenbrock, Ackley, Griewank, Schwefel>;

template <class V, class... More>
struct Append;
template <class... A, class... More>
struct Append<std::variant<A...>, More...> {
    using type = std::variant<A..., More...>;
};

using Any = Scalable;

template <class F>
constexpr bool has_batch = requires(F& f, MatrixView points, std::span<double> values) {
    f.evaluate_batch(points, values);
};

}  // namespace

struct Function::Impl {
    Any function;
    std::string name;
    std::int64_t instance = 0;
    Matrix scratch;  // transformed points for a batch-capable function (grown, never shrunk)
};

Function::Function(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {
    std::visit(
        [&](const auto& f) {
            lower_.assign(f.lower().begin(), f.lower().end());
            upper_.assign(f.upper().begin(), f.upper().end());
        },
        impl_->function);
}
Function::Function(const Function& other)
    : impl_(std::make_unique<Impl>(*other.impl_)), lower_(other.lower_), upper_(other.upper_) {}
Function& Function::operator=(const Function& other) {
    if (this != &other) *this = Function(other);
    return *this;
}
Function::Function(Function&&) noexcept = default;
Function& Function::operator=(Function&&) noexcept = default;
Function::~Function() = default;

std::string_view Function::name() const noexcept { return impl_->name; }
std::int64_t Function::instance() const noexcept { return impl_->instance; }

double Function::evaluate(std::span<const double> x) {
    return std::visit([&](auto& f) -> double { return f.evaluate(x); }, impl_->function);
}

void Function::evaluate_batch(MatrixView points, std::span<double> values) {
    std::visit(
        [&](auto& f) {
            using F = std::decay_t<decltype(f)>;
            if constexpr (has_batch<F>) {
                f.evaluate_batch(points, values);
            } else {
                const auto rows = static_cast<std::size_t>(points.rows());
                for (Eigen::Index j = 0; j < points.cols(); ++j)
                    values[static_cast<std::size_t>(j)] = f.evaluate(std::span<const double>(points.col(j).data(), rows));
            }
        },
        impl_->function);
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

namespace {

template <class Held>
Function wrap(Held held, std::string name, std::int64_t instance) {
    auto impl = std::make_unique<Function::Impl>(Function::Impl{Any(std::move(held)), std::move(name), instance, {}});
    return Function(std::move(impl));
}

template <class F>
F build(std::size_t dim, const FunctionInfo* info) {
    if constexpr (std::is_constructible_v<F, std::size_t, const FunctionInfo&>)
        return info ? F(dim, *info) : F(dim);
    else
        return F(dim);
}

/// A scalable function: instance 0 as defined, k >= 1 through instance_transform(). `info`: a
/// static table other than F's own (Yao's box for the same formula), never a copy, since the
/// function keeps a pointer to it.
template <class F>
CatalogEntry scalable(std::string name, const FunctionInfo* info = nullptr) {
    CatalogEntry e;
    e.min_dim = F::info.min_dim;
    e.make = [name, info](std::size_t dim, std::int64_t instance) {
        F f = build<F>(dim, info);
        if (instance == 0) return wrap(std::move(f), name, 0);
        auto anchor = f.optimum_point();
        const bool bounded = F::info.bounded_domain;  // a property of the formula, whatever the box
        const auto lo = f.lower(), hi = f.upper();
        Transform t = instance_transform(lo, hi, std::move(anchor), static_cast<std::uint64_t>(instance), bounded);
        return wrap(Transformed<F>(std::move(f), std::move(t), name), name, instance);
    };
    return e;
}

/// shifted-NAME: F under the fixed golden-ratio shift (instance.hpp), instance 0 only.
template <class F>
CatalogEntry shifted() {
    CatalogEntry e;
    e.min_dim = F::info.min_dim;
    e.instances = Instances::none;
    e.make = [](std::size_t dim, std::int64_t) {
        Shifted<F> s(dim);
        return wrap(static_cast<Transformed<F>>(std::move(s)), "shifted-" + std::string(F::info.name), 0);
    };
    return e;
}

template <class F>
void add_scalable(Registry<CatalogEntry>& r, bool with_shift) {
    r.add(std::string(F::info.name), std::string(F::info.summary), scalable<F>(std::string(F::info.name)));
    if (with_shift)
        r.add("shifted-" + std::string(F::info.name),
              std::string(F::info.name) + " with its optimum moved off the centre (instance.hpp: shift_optimum)",
              shifted<F>());
}

}  // namespace

const Registry<CatalogEntry>& catalog() {
    static const Registry<CatalogEntry> r = [] {
        Registry<CatalogEntry> reg;
        add_scalable<Sphere>(reg, true);
        add_scalable<Rastrigin>(reg, true);
        add_scalable<Rosenbrock>(reg, true);
        add_scalable<Ackley>(reg, true);
        add_scalable<Griewank>(reg, true);
        // Schwefel is not shifted: its optimum is already off the centre, and a shifted argument
        // would leave [-500, 500], where the formula has lower values than its "optimum" (its
        // instances k >= 1 clamp the argument instead: instance.hpp).
        add_scalable<Schwefel>(reg, false);
        return reg;
    }();
    return r;
}

std::int64_t default_instance(const CatalogEntry& entry) {
    return entry.instances == Instances::coco ? 1 : 0;
}

Function make_function(std::string_view name, std::int64_t dim, std::optional<std::int64_t> instance,
                       const std::string& dim_source) {
    const auto* item = catalog().find(name);
    require(item != nullptr, "problem", "unknown problem '" + std::string(name) + "'");
    const auto& e = item->entry;
    require(dim >= 1, dim_source, "dimension must be >= 1, got " + std::to_string(dim));
    require(static_cast<std::size_t>(dim) >= e.min_dim, dim_source,
            std::string(name) + " needs dimension >= " + std::to_string(e.min_dim) + ", got " + std::to_string(dim));
    require(e.fixed_dim == 0 || static_cast<std::size_t>(dim) == e.fixed_dim, dim_source,
            std::string(name) + " is defined in dimension " + std::to_string(e.fixed_dim) + " only, got " +
                std::to_string(dim));
    const std::int64_t k = instance.value_or(default_instance(e));
    switch (e.instances) {
    case Instances::transform:
        require(k >= 0, "instance", "must be >= 0, got " + std::to_string(k));
        break;
    case Instances::none:
        require(k == 0, "instance",
                std::string(name) + " has one instance only (0)" +
                    (name.starts_with("shifted-") ? "; use " + std::string(name.substr(8)) + " --instance K" : ""));
        break;
    case Instances::coco:
        require(k >= 1, "instance", std::string(name) + ": COCO numbers instances from 1, got " + std::to_string(k));
        break;
    }
    return e.make(static_cast<std::size_t>(dim), k);
}

}  // namespace pride::continuous

#include "engine/callback.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <utility>

#include <fmt/format.h>

#include "framework/error.hpp"
#include "framework/initializer.hpp"

namespace pride::engine {

namespace {

/// The box of a user's function: coordinates, as many of each bound, finite, lower <= upper.
void check_box(const std::string& name, const std::vector<double>& lower, const std::vector<double>& upper) {
    require(!lower.empty(), name, "the box has no coordinates (lower and upper are empty)");
    require(lower.size() == upper.size(), name,
            "lower has " + std::to_string(lower.size()) + " coordinates and upper " + std::to_string(upper.size()));
    for (std::size_t i = 0; i < lower.size(); ++i)
        require(std::isfinite(lower[i]) && std::isfinite(upper[i]) && lower[i] <= upper[i], name,
                "bounds " + std::to_string(i) + " must be finite with lower <= upper");
}

/// The declared types, checked (one per coordinate, with the bounds each type needs); empty when
/// every variable is real, so that such a problem runs as one that declares nothing.
std::vector<VariableType> checked_types(const std::string& name, const std::vector<double>& lower,
                                        const std::vector<double>& upper, std::vector<VariableType> types) {
    if (types.empty()) return types;
    require(
        types.size() == lower.size(), name,
        "types has " + std::to_string(types.size()) + " entries for " + std::to_string(lower.size()) + " coordinates");
    for (std::size_t i = 0; i < types.size(); ++i) {
        if (types[i] == VariableType::real) continue;
        const std::string which = "variable " + std::to_string(i) + " (" + std::string(type_name(types[i])) + ")";
        require(std::floor(lower[i]) == lower[i] && std::floor(upper[i]) == upper[i], name,
                which + fmt::format(" needs integer bounds, got [{}, {}]", lower[i], upper[i]));
        if (types[i] == VariableType::categorical)
            require(
                lower[i] == 0.0 && upper[i] >= 1.0, name,
                which + fmt::format(" needs bounds 0 and k - 1 with k >= 2 choices, got [{}, {}]", lower[i], upper[i]));
    }
    if (std::all_of(types.begin(), types.end(), [](VariableType t) { return t == VariableType::real; })) types.clear();
    return types;
}

/// One buffer per thread and nesting depth for the typed copies of the points: no allocation per
/// call once it has grown, and a function that runs another typed problem inside keeps its point.
template <class Buffer>
struct TypedBuffers {
    std::deque<Buffer> depth;  // a deque: taking one more keeps the others in place
    std::size_t used = 0;
    Buffer& take() {
        if (used == depth.size()) depth.emplace_back();
        return depth[used++];
    }
};
/// One buffer taken for a call, given back when the call returns (or throws).
template <class Buffer>
class Taken {
  public:
    explicit Taken(TypedBuffers<Buffer>& b) : buffers_(&b), buffer_(&b.take()) {}
    ~Taken() { --buffers_->used; }
    Taken(const Taken&) = delete;
    Taken& operator=(const Taken&) = delete;
    Buffer& get() const noexcept { return *buffer_; }

  private:
    TypedBuffers<Buffer>* buffers_;
    Buffer* buffer_;
};

/// `f(point)` on a copy of x with the integer and categorical coordinates of `p` rounded: what
/// a user's function of declared types receives.
template <class P, class F>
decltype(auto) on_typed_point(const P& p, std::span<const double> x, F&& f) {
    thread_local TypedBuffers<std::vector<double>> buffers;
    const Taken<std::vector<double>> typed(buffers);
    std::vector<double>& point = typed.get();
    point.assign(x.begin(), x.end());
    round_to_types(p, point);
    return std::forward<F>(f)(std::span<const double>(point));
}

/// `f(batch)` on a copy of the points with their integer and categorical coordinates rounded.
template <class P, class F>
void on_typed_batch(const P& p, MatrixView points, F&& f) {
    thread_local TypedBuffers<Matrix> buffers;
    const Taken<Matrix> typed(buffers);
    Matrix& batch = typed.get();
    batch = points;
    for (Eigen::Index j = 0; j < batch.cols(); ++j)
        round_to_types(p, std::span<double>(batch.col(j).data(), static_cast<std::size_t>(batch.rows())));
    std::forward<F>(f)(MatrixView(batch));
}

}  // namespace

CallbackProblem::CallbackProblem(std::string name, std::vector<double> lower, std::vector<double> upper, Scalar scalar,
                                 Batch batch, bool thread_safe, Starts starts, std::vector<VariableType> types) {
    check_box(name, lower, upper);
    require(static_cast<bool>(scalar) || static_cast<bool>(batch), name, "no function to evaluate");
    types = checked_types(name, lower, upper, std::move(types));
    shared_ =
        std::make_shared<const Shared>(Shared{std::move(name), std::move(lower), std::move(upper), std::move(scalar),
                                              std::move(batch), thread_safe, std::move(starts), std::move(types)});
}

double CallbackProblem::evaluate(std::span<const double> x) {
    if (!shared_->types.empty())
        return on_typed_point(*this, x, [&](std::span<const double> point) { return evaluate_point(point); });
    return evaluate_point(x);
}

double CallbackProblem::evaluate_point(std::span<const double> x) {
    if (shared_->scalar) return shared_->scalar(x);
    double f = 0.0;
    const Eigen::Map<const Matrix> point(x.data(), static_cast<Eigen::Index>(x.size()), 1);
    shared_->batch(point, std::span<double>(&f, 1));
    return f;
}

void CallbackProblem::evaluate_batch(MatrixView points, std::span<double> values) {
    if (!shared_->types.empty())
        return on_typed_batch(*this, points, [&](MatrixView batch) { evaluate_typed(batch, values); });
    evaluate_typed(points, values);
}

void CallbackProblem::evaluate_typed(MatrixView points, std::span<double> values) {
    if (shared_->batch) {
        shared_->batch(points, values);
        return;
    }
    for (Eigen::Index j = 0; j < points.cols(); ++j)
        values[static_cast<std::size_t>(j)] =
            shared_->scalar(std::span<const double>(points.col(j).data(), static_cast<std::size_t>(points.rows())));
}

}  // namespace pride::engine

namespace pride::engine {

void CallbackProblem::starting_points(Rng& rng, Matrix& out) const {
    if (shared_->starts)
        shared_->starts(rng, out);
    else
        UniformInit{}(*this, rng, out);
}

MoCallbackProblem::MoCallbackProblem(std::string name, std::vector<double> lower, std::vector<double> upper,
                                     std::size_t objectives, Scalar scalar, Batch batch,
                                     std::vector<VariableType> types) {
    types = checked_types(name, lower, upper, std::move(types));
    shared_ = std::make_shared<const Shared>(Shared{std::move(name), std::move(lower), std::move(upper), objectives,
                                                    std::move(scalar), std::move(batch), std::move(types)});
}

void MoCallbackProblem::evaluate(std::span<const double> x, std::span<double> f) {
    if (!shared_->types.empty())
        return on_typed_point(*this, x, [&](std::span<const double> point) { evaluate_typed(point, f); });
    evaluate_typed(x, f);
}

void MoCallbackProblem::evaluate_batch(MatrixView points, Matrix& values) {
    if (!shared_->types.empty())
        return on_typed_batch(*this, points, [&](MatrixView batch) { evaluate_batch_typed(batch, values); });
    evaluate_batch_typed(points, values);
}

void MoCallbackProblem::evaluate_typed(std::span<const double> x, std::span<double> f) {
    if (shared_->scalar) {
        shared_->scalar(x, f);
        return;
    }
    // Only a batch function: a one-column batch.
    const Eigen::Map<const Matrix> point(x.data(), static_cast<Eigen::Index>(x.size()), 1);
    one_.resize(static_cast<Eigen::Index>(f.size()), 1);
    shared_->batch(point, one_);
    std::copy(one_.data(), one_.data() + f.size(), f.begin());
}

void MoCallbackProblem::evaluate_batch_typed(MatrixView points, Matrix& values) {
    if (shared_->batch) {
        shared_->batch(points, values);
        return;
    }
    const auto n = static_cast<std::size_t>(points.rows()), m = objectives();
    for (Eigen::Index j = 0; j < points.cols(); ++j)
        shared_->scalar(std::span<const double>(points.col(j).data(), n), std::span<double>(values.col(j).data(), m));
}

ConstrainedCallbackProblem::ConstrainedCallbackProblem(std::string name, std::vector<double> lower,
                                                       std::vector<double> upper, ConstraintCounts counts,
                                                       double tolerance, Function function,
                                                       std::vector<VariableType> types) {
    check_box(name, lower, upper);
    types = checked_types(name, lower, upper, std::move(types));
    require(counts.total() > 0, name, "no constraint declared");
    require(std::isfinite(tolerance) && tolerance >= 0.0, "tolerance",
            "must be a finite number >= 0, got " + std::to_string(tolerance));
    require(static_cast<bool>(function), name, "no function to evaluate");
    shared_ = std::make_shared<const Shared>(Shared{std::move(name), std::move(lower), std::move(upper), counts,
                                                    tolerance, std::move(function), std::move(types)});
    scratch_.assign(counts.total(), 0.0);
}

double ConstrainedCallbackProblem::evaluate(std::span<const double> x) {
    return evaluate_constrained(x, scratch_);
}

double ConstrainedCallbackProblem::evaluate_constrained(std::span<const double> x, std::span<double> constraints) {
    if (!shared_->types.empty())
        return on_typed_point(*this, x,
                              [&](std::span<const double> point) { return shared_->function(point, constraints); });
    return shared_->function(x, constraints);
}

}  // namespace pride::engine

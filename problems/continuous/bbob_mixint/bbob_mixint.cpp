// COCO's bbob-mixint problems (bbob_mixint.hpp): every step in the order of operations of COCO's
// transform_vars_discretize.c, so that the values are COCO's bit for bit.
#include "problems/continuous/bbob_mixint/bbob_mixint.hpp"

#include <cmath>
#include <utility>

#include "framework/error.hpp"
#include "problems/continuous/bbob/instance.hpp"

namespace pride::continuous::bbob_mixint {

namespace {

// COCO's suite_bbob_mixint_scaling_factors, f1 to f24: similar difficulty across the functions.
constexpr double kFactors[kFunctions] = {1,    1e-3, 1e-1, 1e-1, 1,  1e-2, 1,  1e-2, 1e-2, 1e-3, 1e-2, 1e-4,
                                         1e-1, 1,    1e-1, 1,    10, 1,    10, 1e-1, 1,    1,    10,   1e-1};
// The number of values of the integer variables in each of the first four blocks of D/5.
constexpr double kCardinalities[4] = {2, 4, 8, 16};

// COCO's coco_double_round: half-way cases go up.
double round_half_up(double v) noexcept {
    return std::floor(v + 0.5);
}

template <std::size_t K>
Inner make_one(std::size_t dim, std::int64_t instance) {
    return Inner(std::in_place_index<K>, dim, instance);
}

template <std::size_t... K>
Inner make_inner(int function, std::size_t dim, std::int64_t instance, std::index_sequence<K...>) {
    static constexpr Inner (*makers[])(std::size_t, std::int64_t) = {make_one<K>...};
    return makers[function - 1](dim, instance);
}

/// Checks the arguments (one-line InputError), then builds the bbob function.
Inner checked_inner(int function, std::size_t dim, std::int64_t instance) {
    require(function >= 1 && function <= kFunctions, "problem",
            name_of(function) + ": the suite's functions are " + kPrefix + "1 to " + name_of(kFunctions));
    const std::string name = name_of(function);
    require(dim >= kMinDimension && dim <= kMaxDimension && dim % 5 == 0, "dim",
            dimension_message(function, static_cast<std::int64_t>(dim)));
    require(instance >= 1, "instance",
            name + ": instance must be >= 1 (COCO numbers instances from 1), got " + std::to_string(instance));
    require(instance <= bbob::kMaxInstance, "instance", bbob::instance_range_message(name, instance));
    return make_inner(function, dim, instance, std::make_index_sequence<kFunctions>{});
}

/// The best value COCO's bbob problem carries: f_opt, except for f20, whose raw Schwefel function
/// is evaluated at its best parameter (420.96874633 in every coordinate, near but not at its
/// minimiser) and f_opt added to that (f_schwefel.c, transform_obj_shift.c).
double coco_best_value(int function, std::size_t dim, double f_opt) {
    if (function != 20) return f_opt;
    const double x = 420.96874633;
    double sum = 0.0;
    for (std::size_t i = 0; i < dim; ++i) sum += x * std::sin(std::sqrt(std::fabs(x)));
    const double raw = 0.01 * (0.0 + 418.9828872724339 - sum / static_cast<double>(dim));
    return raw + f_opt;
}

}  // namespace

std::string name_of(int function) {
    return kPrefix + std::to_string(function);
}

std::string dimension_message(int function, std::int64_t dim) {
    return name_of(function) +
           " takes a dimension that is a multiple of 5 from 5 to 40 (the suite's: 5, 10, 20, 40; COCO's 80 and 160 "
           "use its bbob-largescale functions, which pride does not have), got " +
           std::to_string(dim);
}

Problem::Problem(int function, std::size_t dim, std::int64_t instance)
    : function_(function),
      instance_(instance),
      name_(name_of(function)),
      integers_(dim / 5 * 4),
      inner_(checked_inner(function, dim, instance)) {
    const std::vector<double> inner_star = std::visit([](const auto& f) { return f.optimum_point(); }, inner_);
    factor_ = kFactors[function - 1];
    f_star_ = coco_best_value(function, dim, std::visit([](const auto& f) { return f.optimum_value(); }, inner_)) *
              factor_;  // transform_obj_scale scales the best value
    lower_.assign(dim, -5.0);
    upper_.assign(dim, 5.0);
    x_star_ = inner_star;
    z_.resize(dim);
    inner_low_.resize(integers_);
    inner_width_.resize(integers_);
    offset_.resize(integers_);
    // The bbob function's region for the integer coordinates, which COCO sets to [-4, 4].
    const double l = -4.0, u = 4.0;
    const double precision_offset = 1e-7;  // COCO's guard against rounding x* down
    for (std::size_t i = 0; i < integers_; ++i) {
        const double n = kCardinalities[i / (dim / 5)];
        lower_[i] = 0.0;
        upper_[i] = n - 1.0;
        const double outer_l = lower_[i], outer_u = upper_[i];
        const double inner_l = l + (u - l) / (n + 1.0);
        const double inner_u = u - (u - l) / (n + 1.0);
        double outer_xopt = outer_l + (outer_u - outer_l) * (inner_star[i] - inner_l) / (inner_u - inner_l);
        outer_xopt = round_half_up(outer_xopt + precision_offset);
        if (outer_xopt < outer_l) outer_xopt = outer_l;
        if (outer_xopt > outer_u) outer_xopt = outer_u;
        x_star_[i] = outer_xopt;
        const double inner_approx_xopt = inner_l + (inner_u - inner_l) * (outer_xopt - outer_l) / (outer_u - outer_l);
        inner_low_[i] = inner_l;
        inner_width_[i] = inner_u - inner_l;
        offset_[i] = inner_approx_xopt - inner_star[i];
    }
}

double Problem::evaluate(std::span<const double> x) noexcept {
    for (const double v : x)
        if (std::isnan(v)) return std::nan("");
    for (std::size_t i = 0; i < x.size(); ++i) z_[i] = x[i];
    for (std::size_t i = 0; i < integers_; ++i) {
        double d = round_half_up(x[i]);
        if (d < lower_[i]) d = lower_[i];
        if (d > upper_[i]) d = upper_[i];
        z_[i] = inner_low_[i] + inner_width_[i] * (d - lower_[i]) / (upper_[i] - lower_[i]) - offset_[i];
    }
    const double f = std::visit([&](auto& inner) { return inner.evaluate(z_); }, inner_);
    return f * factor_;
}

}  // namespace pride::continuous::bbob_mixint

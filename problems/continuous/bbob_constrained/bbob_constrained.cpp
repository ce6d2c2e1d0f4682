// COCO's bbob-constrained problems (bbob_constrained.hpp), built in the order COCO builds them:
// each step below names the COCO function it follows; the arithmetic is written in COCO's order
// (the order of each sum, the grouping of each product), which is what makes the values equal.
#include "problems/continuous/bbob_constrained/bbob_constrained.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "framework/error.hpp"
#include "problems/continuous/bbob/separable.hpp"
#include "problems/continuous/bbob/transforms.hpp"

namespace pride::continuous::bbob_constrained {

namespace {

namespace bbob = continuous::bbob;

/// coco_random.c: a lagged Fibonacci generator (lags 607 and 273) on doubles in [0, 1), its
/// state filled from the seed by Knuth's 1812433253 recurrence; normals by Box-Muller.
class CocoRandom {
  public:
    explicit CocoRandom(std::uint32_t seed) {
        for (std::size_t i = 0; i < kLong; ++i) {
            x_[i] = static_cast<double>(seed) / 4294967295.0;
            seed = 1812433253u * (seed ^ (seed >> 30)) + (static_cast<std::uint32_t>(i) + 1u);
        }
    }
    double uniform() noexcept {
        if (index_ >= kLong) generate();
        return x_[index_++];
    }
    double normal() noexcept {
        const double u1 = uniform();
        const double u2 = uniform();
        return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
    }

  private:
    static constexpr std::size_t kShort = 273, kLong = 607;
    void generate() noexcept {
        for (std::size_t i = 0; i < kShort; ++i) {
            double t = x_[i] + x_[i + (kLong - kShort)];
            if (t >= 1.0) t -= 1.0;
            x_[i] = t;
        }
        for (std::size_t i = kShort; i < kLong; ++i) {
            double t = x_[i] + x_[i - kShort];
            if (t >= 1.0) t -= 1.0;
            x_[i] = t;
        }
        index_ = 0;
    }
    std::array<double, kLong> x_{};
    std::size_t index_ = 12;
};

/// COCO seeds its generator with a long cast to uint32_t: modulo 2^32.
std::uint32_t coco_seed(std::int64_t seed) noexcept {
    return static_cast<std::uint32_t>(static_cast<std::uint64_t>(seed));
}

double norm(std::span<const double> x) noexcept {  // coco_vector_norm
    double s = 0.0;
    for (double v : x) s += v * v;
    return std::sqrt(s);
}

void scale(std::span<double> x, double nom, double denom) noexcept {  // coco_vector_scale
    if (denom != 0) nom /= denom;
    for (double& v : x) v *= nom;
}

/// c_linear_single_evaluate and c_sum_variables_evaluate: sum_i a_i (z_i - factor a_i), a term
/// counted where it is < 0 or > 1e-11.
double linear(const double* a, double factor, const double* z, std::size_t n) noexcept {
    double y = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const double t = a[i] * (z[i] - factor * a[i]);
        if (t > 1e-11 || t < 0) y += t;
    }
    return y;
}

/// nb_of_linear_constraints: the active constraints of function `function` in dimension `dim`.
std::size_t active_count(int function, std::size_t dim) noexcept {
    switch ((function - 1) % 6 + 1) {
        case 1:
            return 1;
        case 2:
            return 2;
        case 3:
            return 6;
        case 4:
            return 6 + dim / 2;
        case 5:
            return 6 + dim;
        default:
            return 6 + 3 * dim;
    }
}

/// f_rastrigin_cons_compute_xopt: integers trunc(10 u - 5), (i mod 9) - 4 if all are 0.
std::vector<double> rastrigin_xopt(std::size_t dim, std::int64_t seed) {
    std::vector<double> x = bbob::uniform(dim, seed);
    bool zero = true;
    for (double& v : x) {
        v = 10 * v - 5;
        v = static_cast<double>(static_cast<int>(v));
        zero = zero && v == 0.0;
    }
    if (zero)
        for (std::size_t i = 0; i < dim; ++i) x[i] = static_cast<double>(static_cast<int>(i % 9) - 4);
    return x;
}

/// out = M^T y, each out_j summed over i from 0 (transform_vars_affine_evaluate_gradient).
std::vector<double> transposed(const bbob::AffineMatrix& m, std::span<const double> y) {
    const auto n = static_cast<Eigen::Index>(y.size());
    std::vector<double> out(y.size(), 0.0);
    for (Eigen::Index j = 0; j < n; ++j)
        for (Eigen::Index i = 0; i < n; ++i)
            out[static_cast<std::size_t>(j)] += y[static_cast<std::size_t>(i)] * m(i, j);
    return out;
}

double sign(double x) noexcept {
    return x > 0 ? 1.0 : x < 0 ? -1.0 : 0.0;
}

}  // namespace

Problem::Problem(int function, std::size_t dim, std::int64_t instance)
    : function_(function), type_(0), instance_(instance) {
    require(function >= 1 && function <= kFunctions, "problem",
            std::string(kPrefix) + std::to_string(function) + ": the suite's functions are " + kPrefix + "1 to " +
                kPrefix + std::to_string(kFunctions));
    name_ = kPrefix + std::to_string(function);
    require(dim >= 2 && dim <= kMaxDimension, "dim",
            name_ + " takes a dimension from 2 to " + std::to_string(kMaxDimension) +
                " (the suite's: 2, 3, 5, 10, 20, 40), got " + std::to_string(dim));
    require(instance >= 1, "instance",
            name_ + ": instance must be >= 1 (COCO numbers instances from 1), got " + std::to_string(instance));
    require(instance <= bbob::kMaxInstance, "instance", bbob::instance_range_message(name_, instance));

    type_ = (function + 5) / 6;
    active_ = active_count(function, dim);
    lower_.assign(dim, -5.0);
    upper_.assign(dim, 5.0);
    shifted_.resize(dim);
    z_.resize(dim);
    u_.resize(dim);
    const std::size_t n = dim;
    const double nd = static_cast<double>(n);

    // coco_get_cons_bbob_problem: x* from N + 10000 i, the objective from N + 20000 i.
    x_star_ = bbob::compute_xopt(n, function + 10000 * instance);
    const std::int64_t rseed = function + 20000 * instance;
    f_opt_ = bbob::compute_fopt(function, instance);
    scale_ = type_ == 2 || type_ == 4 || type_ == 5 || type_ == 6 ? 1e-4 : type_ == 7 ? 1e2 : 10.0;
    if (type_ == 4 || type_ == 5 || type_ == 6 || type_ == 7 || type_ == 9)
        rotation_ = bbob::compute_rotation(n, rseed + 1000000);
    if (type_ == 8 || type_ == 9)
        x_o_ = rastrigin_xopt(n, rseed);
    else
        x_o_ = bbob::compute_xopt(n, type_ == 6 ? rseed + 1000000 : rseed);
    if (type_ == 7) {  // f_different_powers_bbob_constrained_problem_allocate: ||x_o|| = 1e-2
        double r = 0.0;
        for (double v : x_o_) r += v * v;
        r = std::sqrt(r);
        for (double& v : x_o_) v *= 1e-2 / r;
    }
    if (type_ == 2 || type_ == 4) {
        weight_ = bbob::power_ramp(1.0e6, n);
    } else if (type_ == 3) {  // f_linear_slope_allocate: the corner, and s_i's sign from it
        const std::vector<double> ramp = bbob::power_ramp(std::sqrt(100.0), n);
        weight_.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            x_o_[i] = x_o_[i] < 0.0 ? -5.0 : 5.0;
            weight_[i] = x_o_[i] > 0.0 ? ramp[i] : -ramp[i];
        }
    } else if (type_ == 7) {
        weight_.resize(n);
        for (std::size_t i = 0; i < n; ++i) weight_[i] = 2.0 + (4.0 * static_cast<double>(i)) / (nd - 1.0);
    }

    // The feasible direction p: the objective's gradient at the origin (each f_*_evaluate_gradient
    // under the transformations' gradients), then feasible_direction_set_length.
    std::vector<double> p(n);
    {
        std::vector<double> z(n), u(n);
        for (std::size_t i = 0; i < n; ++i) z[i] = 0.0 - x_o_[i];
        const bool rotated = type_ == 4 || type_ == 5 || type_ == 6 || type_ == 7;
        if (rotated) bbob::affine(rotation_, z, u);
        switch (type_) {
            case 1:
                for (std::size_t i = 0; i < n; ++i) p[i] = 2.0 * z[i];
                break;
            case 2:
                for (std::size_t i = 0; i < n; ++i) p[i] = 2.0 * weight_[i] * z[i];
                break;
            case 3:
                for (std::size_t i = 0; i < n; ++i) p[i] = -weight_[i];
                break;
            case 4:
                for (std::size_t i = 0; i < n; ++i) p[i] = 2.0 * weight_[i] * u[i];
                break;
            case 5:
                p[0] = 1.0e6 * 2.0 * u[0];
                for (std::size_t i = 1; i < n; ++i) p[i] = 2.0 * u[i];
                break;
            case 6:
                p[0] = 2.0 * u[0];
                for (std::size_t i = 1; i < n; ++i) p[i] = 2.0 * 1.0e6 * u[i];
                break;
            case 7: {
                double sum = 0.0;
                for (std::size_t i = 0; i < n; ++i) sum += std::pow(std::fabs(u[i]), weight_[i]);
                for (std::size_t i = 0; i < n; ++i) {
                    double aux = weight_[i];
                    p[i] = 0.5 * aux / sum;
                    aux -= 1.0;
                    p[i] *= std::pow(std::fabs(u[i]), aux) * sign(u[i]);
                }
                break;
            }
            default: {  // 8, 9: Rastrigin; for 9 the inner point is R 0 - x_o = -x_o too
                constexpr double pi = std::numbers::pi;
                for (std::size_t i = 0; i < n; ++i) p[i] = 2.0 * (10. * pi * std::sin(2.0 * pi * z[i]) + z[i]);
                break;
            }
        }
        if (rotated || type_ == 9) p = transposed(rotation_, p);

        double maxrel = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            const double a = p[i] / (5.0 - x_star_[i]), b = p[i] / (-5.0 - x_star_[i]);
            maxrel = maxrel >= a ? maxrel : a;  // coco_double_max
            maxrel = maxrel >= b ? maxrel : b;
        }
        const double r = bbob::uniform(1, rseed + 412)[0];
        scale(p, 0.75 + r * (1 - 0.75), maxrel);
    }

    // c_linear_cons_bbob_problem_allocate: m active and floor(m/2) inactive constraints.
    std::size_t inactive_left = active_ / 2;
    constraint_count_ = active_ + inactive_left;
    gradients_.assign(constraint_count_ * n, 0.0);
    shift_factor_.assign(constraint_count_, 0.0);
    std::vector<double> gradient_c1(n), combination(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) gradient_c1[i] = -p[i];
    const std::int64_t seed_cons = function + 10000 * instance;
    CocoRandom random1(coco_seed(seed_cons)), random2(coco_seed(seed_cons));
    const double factor1 = 100. * std::pow(10.0, random1.uniform());
    std::optional<std::size_t> first;  // the constraint whose gradient is -p

    // c_linear_single_cons_bbob_problem_allocate for constraint row k, COCO's number `number`.
    auto single = [&](std::size_t k, std::size_t number, bool from_p, double shift) {
        double* a = &gradients_[k * n];
        CocoRandom random(coco_seed(seed_cons + 50000 * static_cast<std::int64_t>(number)));
        const double factor2 = std::pow(100.0, random.uniform());
        if (from_p) {
            scale(gradient_c1, factor1 * factor2, norm(gradient_c1));
            std::copy(gradient_c1.begin(), gradient_c1.end(), a);
        } else {
            for (std::size_t i = 0; i < n; ++i) a[i] = factor1 * random.normal() * factor2 / std::sqrt(nd);
        }
        shift_factor_[k] = shift / norm({a, n});
        // c_guarantee_feasible_point: flip the constraint if p violates it.
        if (linear(a, shift_factor_[k], p.data(), n) > 0)
            for (std::size_t i = 0; i < n; ++i) a[i] *= -1.0;
    };
    // con_update_linear_combination, for an active constraint built from random normals.
    auto combine = [&](std::size_t k) {
        const double weight = random2.uniform();
        if (weight == 0) return;
        for (std::size_t i = 0; i < n; ++i) combination[i] += weight * gradients_[k * n + i];
    };

    bool from_p = instance % static_cast<std::int64_t>(active_) == 0;
    single(0, 1, from_p, 0.0);
    if (from_p)
        first = 0;
    else
        combine(0);
    const double total = static_cast<double>(constraint_count_);
    for (std::size_t j = 2, i = 1; j <= constraint_count_; ++j) {
        double shift = 0.0;
        if (i < active_ && random1.uniform() + 1e-23 > static_cast<double>(inactive_left) / total) {
            ++i;
            from_p = (static_cast<std::int64_t>(i) - 1 + instance) % static_cast<std::int64_t>(active_) == 0;
        } else {
            --inactive_left;  // never below 0: the active ones run out first
            from_p = false;
            shift = 0.01 + 2.0 * random1.uniform();
        }
        single(j - 1, i, from_p, shift);
        if (shift == 0) {
            if (from_p)
                first = j - 1;
            else
                combine(j - 1);
        }
    }
    // Disguise -p: subtract a share of the other active gradients, then restore its norm.
    if (active_ > 1 && first) {
        double* a = &gradients_[*first * n];
        const double a_norm = norm({a, n});  // as built: the flip kept it
        double fac = 0.0;
        for (std::size_t i = 0; i < n; ++i) fac += combination[i] * a[i];
        if (fac <= 0) {
            fac = nd;
        } else {
            const double ratio = a_norm * a_norm / fac;
            fac = nd <= ratio ? nd : ratio;  // coco_double_min
        }
        fac *= (1 + random2.uniform()) / (2 + 1. / nd);
        for (std::size_t i = 0; i < n; ++i) a[i] -= fac * combination[i];
        scale({a, n}, a_norm, norm({a, n}));
    }

    f_star_ = evaluate(x_star_);
}

const double* Problem::transformed(std::span<const double> x) noexcept {
    bbob::shift(x, x_star_, z_);
    if (type_ == 2 || type_ == 4 || type_ == 5 || type_ == 8 || type_ == 9) bbob::tosz(z_);
    if (type_ == 6 || type_ == 8 || type_ == 9) bbob::tasy(z_, 0.2);
    return z_.data();
}

double Problem::objective(const double* z) noexcept {
    const std::size_t n = z_.size();
    double* const s = shifted_.data();
    double f = 0.0;
    switch (type_) {
        case 1:
            for (std::size_t i = 0; i < n; ++i) {
                const double v = z[i] - x_o_[i];
                f += v * v;
            }
            break;
        case 2:
            for (std::size_t i = 0; i < n; ++i) s[i] = z[i] - x_o_[i];
            f = s[0] * s[0];
            for (std::size_t i = 1; i < n; ++i) f += weight_[i] * s[i] * s[i];
            break;
        case 3:  // f_linear_slope_raw at x itself (z is x here)
            for (std::size_t i = 0; i < n; ++i) {
                const double si = weight_[i];
                if (z[i] * x_o_[i] < 25.0)
                    f += 5.0 * std::fabs(si) - si * z[i];
                else
                    f += 5.0 * std::fabs(si) - si * x_o_[i];
            }
            break;
        case 9:
            bbob::affine(rotation_, {z, n}, u_);
            for (std::size_t i = 0; i < n; ++i) s[i] = u_[i] - x_o_[i];
            f = bbob::rastrigin_sum(shifted_);
            break;
        case 8:
            for (std::size_t i = 0; i < n; ++i) s[i] = z[i] - x_o_[i];
            f = bbob::rastrigin_sum(shifted_);
            break;
        default: {  // 4, 5, 6, 7: R (z - x_o)
            for (std::size_t i = 0; i < n; ++i) s[i] = z[i] - x_o_[i];
            bbob::affine(rotation_, shifted_, u_);
            const double* u = u_.data();
            if (type_ == 4) {
                f = u[0] * u[0];
                for (std::size_t i = 1; i < n; ++i) f += weight_[i] * u[i] * u[i];
            } else if (type_ == 5) {
                f = 1.0e6 * u[0] * u[0];
                for (std::size_t i = 1; i < n; ++i) f += u[i] * u[i];
            } else if (type_ == 6) {
                f = u[0] * u[0];
                for (std::size_t i = 1; i < n; ++i) f += 1.0e6 * u[i] * u[i];
            } else {
                for (std::size_t i = 0; i < n; ++i) f += std::pow(std::fabs(u[i]), weight_[i]);
                f = std::sqrt(f);
            }
            break;
        }
    }
    return (f + f_opt_) * scale_;
}

void Problem::constraints(const double* z, double* c) const noexcept {
    const std::size_t n = z_.size();
    for (std::size_t k = 0; k < constraint_count_; ++k) c[k] = linear(&gradients_[k * n], shift_factor_[k], z, n);
}

double Problem::evaluate(std::span<const double> x) noexcept {
    if (type_ == 3) return objective(x.data());
    return objective(transformed(x));
}

double Problem::evaluate_constrained(std::span<const double> x, std::span<double> c) noexcept {
    const double* z = transformed(x);
    constraints(z, c.data());
    return type_ == 3 ? objective(x.data()) : objective(z);
}

double Problem::violation(std::span<const double> c) const noexcept {
    double sum = 0.0;
    for (std::size_t k = 0; k < constraint_count_; ++k) sum += inequality_violation(c[k]);
    return sum;
}

}  // namespace pride::continuous::bbob_constrained

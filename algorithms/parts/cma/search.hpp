#pragma once
// One CMA-ES run's state and its equations (algorithms/cmaes.hpp cites them): sampling with a
// boundary policy, then ranking, the updates of m, sigma, the paths and C, the decomposition and
// the stopping criteria. It knows no problem: the skeleton evaluates the points in between, so
// this code is compiled once per covariance form, not once per problem type.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include <Eigen/Eigenvalues>

#include "algorithms/parts/cma/margin.hpp"
#include "algorithms/parts/cma/stopping.hpp"
#include "algorithms/parts/cma/strategy.hpp"
#include "framework/constraint_order.hpp"
#include "framework/error.hpp"
#include "framework/one_of.hpp"
#include "framework/problem.hpp"
#include "framework/random.hpp"
#include "framework/visit_policy.hpp"

namespace pride::cma {

/// Boundary: draw an infeasible point again, up to `tries` times, then clamp it.
struct Resample {
    static constexpr const char* name = "resample";
    std::int64_t tries = 100;
    void validate(const std::string& who) const {
        require(tries >= 0 && tries <= 1'000'000, who, "tries must be in [0, 1000000], got " + std::to_string(tries));
    }
};
/// Boundary: evaluate the clamped point and use it in the update (Lamarckian repair).
struct ClampRepair {
    static constexpr const char* name = "clamp";
    void validate(const std::string&) const {}
};
/// Boundary: evaluate the clamped point; rank by f plus `weight` times the squared distance to
/// it in units of the box; the unrepaired point enters the update.
struct Penalty {
    static constexpr const char* name = "penalty";
    double weight = 1.0;
    void validate(const std::string& who) const {
        require(weight >= 0.0 && std::isfinite(weight), who, "penalty weight must be finite and >= 0");
    }
};
using SelectableBoundary = OneOf<Resample, ClampRepair, Penalty>;

template <bool Separable>
class Search {
  public:
    Search(std::span<const double> lo, std::span<const double> hi)
        : n_(lo.size()), lo_(lo), hi_(hi), eigen_(static_cast<Eigen::Index>(lo.size())) {
        const auto N = static_cast<Eigen::Index>(n_);
        range_.resize(N);
        for (Eigen::Index i = 0; i < N; ++i)
            range_[i] = hi_[static_cast<std::size_t>(i)] - lo_[static_cast<std::size_t>(i)];
        for (auto* v : {&m_, &ps_, &pc_, &yw_, &tmp_, &inner_, &d_, &diag_c_}) v->resize(N);
    }

    /// A new run from mean `m0` with step sigma0 (a share of each range), population lambda; the
    /// buffers hold `columns` <= lambda points (what the budget allows). `unit`: C starts as
    /// (min range)^2 I instead of diag(range^2), the same step on every coordinate.
    void begin(std::span<const double> m0, double sigma0, std::int64_t lambda, Eigen::Index columns, bool active,
               bool unit = false) {
        const auto N = static_cast<Eigen::Index>(n_);
        s_ = make_strategy(n_, lambda, active, Separable);
        if (X_.cols() != columns) {
            X_.resize(N, columns), Xeval_.resize(N, columns), Y_.resize(N, columns);
            const auto c = static_cast<std::size_t>(columns);
            fx_.resize(c), rank_.resize(c), sorted_.resize(c), order_.resize(c);
            wcirc_.resize(columns);
        }
        for (Eigen::Index i = 0; i < N; ++i) m_[i] = m0[static_cast<std::size_t>(i)];
        sigma_ = sigma_start_ = sigma0;
        ps_.setZero();
        pc_.setZero();
        if (unit)
            d_.setConstant(range_.minCoeff());
        else
            d_ = range_;  // C = diag(range^2): B = I, D = range
        if constexpr (Separable) {
            diag_c_ = d_.array().square().matrix();
        } else {
            C_ = d_.array().square().matrix().asDiagonal();
            B_.setIdentity(N, N);
        }
        max_d0_ = d_.maxCoeff();
        eigen_interval_ = std::max(1.0, std::floor(1.0 / (10.0 * static_cast<double>(n_) * (s_.c1 + s_.cmu))));
        last_eigen_ = 0;
        generation_ = 0;
        hs_threshold_ = (1.4 + 2.0 / (static_cast<double>(n_) + 1.0)) * s_.chi_n;
        history_.reset(n_, lambda);
        discrete_.assign(n_, 0);
        margin_ = Margin{};
    }

    /// CMA-ES with margin for this run (margin.hpp): `integers` are the integer coordinates, their
    /// values the box's integers; alpha <= 0: 1 / (n lambda). Call after begin().
    void use_margin(std::span<const std::size_t> integers, double alpha) {
        margin_.reset(integers, lo_, hi_, alpha, n_, s_.lambda);
        for (const std::size_t j : integers) discrete_[j] = 1;
    }

    /// (38)-(40) for every column, with the boundary policy; Xeval() is then what to evaluate.
    template <class Boundary>
    void sample(Rng& rng, const Boundary& boundary) {
        const auto N = static_cast<Eigen::Index>(n_);
        visit_policy(boundary, [&](const auto& b) {
            using B = std::decay_t<decltype(b)>;
            for (Eigen::Index k = 0; k < X_.cols(); ++k) {
                auto y = Y_.col(k);
                auto x = X_.col(k);
                draw(rng, y, x);
                if constexpr (std::is_same_v<B, Resample>)
                    for (std::int64_t t = 0; t < b.tries && !inside(x); ++t) draw(rng, y, x);
                bool clamped = false;
                for (Eigen::Index i = 0; i < N; ++i) {
                    const auto u = static_cast<std::size_t>(i);
                    const double c = discrete_[u] ? x[i] : std::max(lo_[u], std::min(x[i], hi_[u]));
                    clamped = clamped || c != x[i];
                    Xeval_(i, k) = c;
                }
                // Resample's last resort and ClampRepair put the clamped point into the update.
                if constexpr (!std::is_same_v<B, Penalty>) {
                    if (clamped) {
                        x = Xeval_.col(k);
                        y = (x - m_) / sigma_;
                    }
                }
                if (margin_.active()) margin_.encode(x, m_, Xeval_.col(k));
            }
        });
    }

    const Matrix& Xeval() const { return Xeval_; }
    std::span<double> values() { return fx_; }
    std::int64_t lambda() const { return s_.lambda; }

    /// After the values of all lambda points: ranking, (41)-(47), the decomposition when due, and
    /// the stopping criteria (Stop::none: go on). Under constraints the points rank by `order`
    /// (framework/constraint_order.hpp) on (value, violation), and `added` (when given) is added
    /// to each value first (the augmented Lagrangian's penalty); without them, by value alone.
    /// Under stochastic ranking the points are ranked by constraints::stochastic_rank with `rng`
    /// (lambda sweeps at most, one draw per comparison).
    template <class Boundary, class Order = PlainOrder>
    Stop update(const Boundary& boundary, const Tolerances& tolerances, const Order& order = {},
                std::span<const double> violations = {}, std::span<const double> added = {}, Rng* rng = nullptr) {
        const auto L = static_cast<Eigen::Index>(s_.lambda);
        for (std::size_t k = 0; k < fx_.size(); ++k) rank_[k] = fx_[k];
        for (std::size_t k = 0; k < added.size(); ++k) rank_[k] += added[k];
        visit_policy(boundary, [&](const auto& b) {
            if constexpr (std::is_same_v<std::decay_t<decltype(b)>, Penalty>)
                for (Eigen::Index k = 0; k < L; ++k) {
                    double distance = 0.0;
                    if (!margin_.active()) {
                        distance = (X_.col(k) - Xeval_.col(k)).cwiseQuotient(range_).squaredNorm();
                    } else {  // over the continuous coordinates: the integer ones are encoded, not clamped
                        for (Eigen::Index i = 0; i < X_.rows(); ++i)
                            if (!discrete_[static_cast<std::size_t>(i)]) {
                                const double d = (X_(i, k) - Xeval_(i, k)) / range_[i];
                                distance += d * d;
                            }
                    }
                    rank_[static_cast<std::size_t>(k)] += b.weight * distance;
                }
        });
        std::iota(order_.begin(), order_.end(), Eigen::Index{0});
        if constexpr (std::is_same_v<Order, PlainOrder>) {
            std::sort(order_.begin(), order_.end(), [&](Eigen::Index a, Eigen::Index b) {
                const double fa = rank_[static_cast<std::size_t>(a)], fb = rank_[static_cast<std::size_t>(b)];
                return fa < fb || (!(fb < fa) && a < b);
            });
        } else if (order.handler() == ConstraintHandling::Handler::stochastic_ranking) {
            // Runarsson and Yao (2000), fig. 1, from the points in index order (ties keep it).
            constraints::stochastic_rank(order_, rank_, violations, order.pf(), order_.size(), *rng);
        } else {
            // Deb's rules, the epsilon level and the static penalty are strict weak orders (the
            // epsilon level's is that of (v or 0 when v <= epsilon, f)): ties go to the lower index.
            std::sort(order_.begin(), order_.end(), [&](Eigen::Index a, Eigen::Index b) {
                const auto ua = static_cast<std::size_t>(a), ub = static_cast<std::size_t>(b);
                const double fa = rank_[ua], fb = rank_[ub], va = violations[ua], vb = violations[ub];
                return order.better(fa, va, fb, vb) || (!order.better(fb, vb, fa, va) && a < b);
            });
        }
        for (std::size_t k = 0; k < order_.size(); ++k) sorted_[k] = rank_[static_cast<std::size_t>(order_[k])];
        auto ranked = [&](std::int64_t i) { return Y_.col(order_[static_cast<std::size_t>(i)]); };

        yw_.setZero();  // (41)
        for (std::int64_t i = 0; i < s_.mu; ++i) yw_ += s_.weights[static_cast<std::size_t>(i)] * ranked(i);
        m_ += s_.cm * sigma_ * yw_;  // (42)
        inverse_sqrt(yw_, tmp_);     // (43)
        ps_ = (1.0 - s_.cs) * ps_ + std::sqrt(s_.cs * (2.0 - s_.cs) * s_.mueff) * tmp_;
        const double ps_norm = ps_.norm();
        sigma_ *= std::exp(s_.cs / s_.ds * (ps_norm / s_.chi_n - 1.0));  // (44)
        const double hs_left =
            ps_norm / std::sqrt(1.0 - std::pow(1.0 - s_.cs, 2.0 * static_cast<double>(generation_ + 1)));
        const double hs = hs_left < hs_threshold_ ? 1.0 : 0.0;
        pc_ = (1.0 - s_.cc) * pc_ + hs * std::sqrt(s_.cc * (2.0 - s_.cc) * s_.mueff) * yw_;  // (45)
        for (Eigen::Index i = 0; i < L; ++i) {                                               // (46)
            const double w = s_.weights[static_cast<std::size_t>(i)];
            if (w >= 0.0) {
                wcirc_[i] = w;
            } else {
                inverse_sqrt(ranked(i), tmp_);
                const double sq = tmp_.squaredNorm();
                wcirc_[i] = sq > 0.0 ? w * static_cast<double>(n_) / sq : 0.0;
            }
        }
        const double delta = (1.0 - hs) * s_.cc * (2.0 - s_.cc);  // (47)
        const double decay = 1.0 + s_.c1 * delta - s_.c1 - s_.cmu * s_.sum_weights;
        if constexpr (Separable) {
            tmp_.setZero();
            for (Eigen::Index i = 0; i < L; ++i)
                if (wcirc_[i] != 0.0) tmp_ += wcirc_[i] * ranked(i).array().square().matrix();
            diag_c_ = decay * diag_c_ + s_.c1 * pc_.array().square().matrix() + s_.cmu * tmp_;
        } else {
            C_ *= decay;
            C_.noalias() += s_.c1 * pc_ * pc_.transpose();
            for (Eigen::Index i = 0; i < L; ++i)
                if (wcirc_[i] != 0.0) C_.noalias() += (s_.cmu * wcirc_[i]) * ranked(i) * ranked(i).transpose();
        }
        ++generation_;
        const bool definite = decompose();
        if (margin_.active()) {
            if constexpr (Separable)
                margin_.correct(m_, sigma_, diag_c_);
            else
                margin_.correct(m_, sigma_, C_.diagonal());
        }
        history_.record(sorted_, sorted_.size());
        return stopping(tolerances, definite);
    }

    double sigma() const { return sigma_; }
    const Eigen::VectorXd& mean() const { return m_; }
    /// The diagonal of C (the separable form's whole C).
    double c(Eigen::Index i) const {
        if constexpr (Separable)
            return diag_c_[i];
        else
            return C_(i, i);
    }
    const Eigen::VectorXd& axis_lengths() const { return d_; }
    const Strategy& strategy() const { return s_; }

  private:
    template <class Y, class X>
    void draw(Rng& rng, Y& y, X& x) {
        for (Eigen::Index i = 0; i < y.size(); ++i) tmp_[i] = rng.normal() * d_[i];  // D z
        if constexpr (Separable)
            y = tmp_;
        else
            y.noalias() = B_ * tmp_;
        x = m_ + sigma_ * y;
    }

    template <class X>
    bool inside(const X& x) const {
        for (Eigen::Index i = 0; i < x.size(); ++i) {
            const auto u = static_cast<std::size_t>(i);
            if (!discrete_[u] && !(x[i] >= lo_[u] && x[i] <= hi_[u])) return false;
        }
        return true;
    }

    /// out = C^(-1/2) v = B D^-1 B^T v, with the B and D the points were drawn with.
    template <class V>
    void inverse_sqrt(const V& v, Eigen::VectorXd& out) {
        if constexpr (Separable) {
            out = v.cwiseQuotient(d_);
        } else {
            inner_.noalias() = B_.transpose() * v;
            inner_ = inner_.cwiseQuotient(d_);
            out.noalias() = B_ * inner_;
        }
    }

    /// B and D from C when due (every generation for the diagonal form); false when C is not
    /// positive definite (counted as ConditionCov).
    bool decompose() {
        if constexpr (Separable) {
            bool ok = true;
            for (Eigen::Index i = 0; i < d_.size(); ++i) {
                ok = ok && diag_c_[i] > 0.0 && std::isfinite(diag_c_[i]);
                d_[i] = std::sqrt(std::max(diag_c_[i], 0.0));
            }
            return ok;
        } else {
            if (static_cast<double>(generation_ - last_eigen_) < eigen_interval_) return true;
            last_eigen_ = generation_;
            eigen_.compute(C_);  // reads the lower triangle
            if (eigen_.info() != Eigen::Success || !eigen_.eigenvalues().allFinite() ||
                !(eigen_.eigenvalues().minCoeff() > 0.0))
                return false;
            B_ = eigen_.eigenvectors();
            d_ = eigen_.eigenvalues().cwiseSqrt();
            return true;
        }
    }

    Stop stopping(const Tolerances& t, bool definite) {
        const auto N = static_cast<Eigen::Index>(n_);
        if (!definite || !std::isfinite(sigma_) || !m_.allFinite()) return Stop::condition_cov;
        const double dmax = d_.maxCoeff(), dmin = d_.minCoeff();
        if (!(dmin > 0.0) || (dmax / dmin) * (dmax / dmin) > t.condition) return Stop::condition_cov;
        if (sigma_ * dmax > t.x_up * sigma_start_ * max_d0_) return Stop::tol_x_up;
        bool small = true;
        for (Eigen::Index i = 0; i < N && small; ++i)
            small = sigma_ * std::max(std::abs(pc_[i]), std::sqrt(c(i))) < t.x * sigma_start_ * range_[i];
        if (small) return Stop::tol_x;
        for (Eigen::Index i = 0; i < N; ++i)
            if (m_[i] == m_[i] + 0.2 * sigma_ * std::sqrt(c(i))) return Stop::no_effect_coord;
        const auto axis = static_cast<Eigen::Index>((generation_ - 1) % static_cast<std::int64_t>(n_));
        bool no_effect = true;
        for (Eigen::Index j = 0; j < N && no_effect; ++j) {
            double bja = 0.0;
            if constexpr (Separable)
                bja = j == axis ? 1.0 : 0.0;
            else
                bja = B_(j, axis);
            no_effect = m_[j] == m_[j] + 0.1 * sigma_ * d_[axis] * bja;
        }
        if (no_effect) return Stop::no_effect_axis;
        if (history_.tol_fun(t.fun)) return Stop::tol_fun;
        if (t.stagnation && history_.stagnation(scratch_)) return Stop::stagnation;
        if (t.equal_fun_values && history_.equal_fun_values()) return Stop::equal_fun_values;
        if (t.max_iter && history_.max_iter()) return Stop::max_iter;
        return Stop::none;
    }

    std::size_t n_;
    std::span<const double> lo_, hi_;
    Strategy s_;
    Eigen::VectorXd range_, m_, ps_, pc_, yw_, tmp_, inner_, d_, diag_c_, wcirc_;
    Matrix C_, B_, X_, Xeval_, Y_;
    std::vector<double> fx_, rank_, sorted_, scratch_;
    std::vector<Eigen::Index> order_;
    Eigen::SelfAdjointEigenSolver<Matrix> eigen_;
    ValueHistory history_;
    std::vector<char> discrete_;  // the margin's integer coordinates: not clamped, encoded
    Margin margin_;
    double sigma_ = 0.0, sigma_start_ = 0.0, max_d0_ = 0.0, eigen_interval_ = 1.0, hs_threshold_ = 0.0;
    std::int64_t last_eigen_ = 0, generation_ = 0;
};

}  // namespace pride::cma

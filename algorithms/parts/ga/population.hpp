#pragma once
// The GA's population adapters: what differs between points in a box and chains, behind one
// interface, so that Ga (ga.hpp) has a single generation loop. An adapter owns the run (Rng and
// state, from run_setup.hpp), the individuals (parents, the next population, the children) and
// their fitness, and knows how to make and evaluate the initial population, copy an individual,
// apply the GA's crossover, mutation and bounds policies to one, evaluate the children, and carry
// the chosen members over to the next population.
//
// Points are the columns of Eigen matrices, evaluated through RunState::evaluate_columns (batch
// problems in one call); chains live in vectors of the problem's chain type and are evaluated one
// by one. For hooks (generation_hook.hpp) both offer size(), fitness(), individual(i) and renew().
// On a problem with constraints the box adapter also keeps each member's violation and constraint
// values (`constrained`), and gives the population's penalised values under APM
// (adaptive_penalty.hpp); without constraints none of it exists.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "algorithms/parts/common/adaptive_penalty.hpp"
#include "algorithms/parts/common/run_setup.hpp"
#include "algorithms/parts/ga/generation_context.hpp"
#include "algorithms/parts/variation/categorical.hpp"
#include "framework/chain.hpp"
#include "framework/constraints.hpp"
#include "framework/counted_chain.hpp"
#include "framework/problem.hpp"
#include "framework/random.hpp"
#include "framework/result.hpp"
#include "framework/run_state.hpp"
#include "framework/termination.hpp"

namespace pride {

namespace detail {
template <class Op>
void begin_generation(Op& op, const GenerationContext& context, Rng& rng) {
    if constexpr (requires { op.begin_generation(context, rng); }) op.begin_generation(context, rng);
}
}  // namespace detail

/// Points in the box of a BoxProblem. `Algorithm`: the GA, for its policies.
template <class Algorithm, BoxProblem P>
class BoxPopulation {
  public:
    static constexpr bool constrained = ConstrainedProblem<P>;

    template <class O>
    BoxPopulation(const Algorithm& ga, P& problem, const Termination& termination, std::uint64_t seed, O& observer)
        : ga_(ga),
          problem_(problem),
          run_(start_box_run(ga, problem, termination, seed, observer,
                             {ga.replacement.offspring(ga.population), nullptr}, constrained)),
          kids_(static_cast<std::size_t>(ga.replacement.offspring(ga.population))),
          next_(run_.x.rows(), run_.x.cols()),
          y_(run_.x.rows(), static_cast<Eigen::Index>(kids_)),
          spare_(run_.x.rows(), 1),
          fnext_(run_.fx.size()),
          fy_(kids_),
          cross_(detail::prepared(ga.crossover, run_.dim)),
          mutate_(detail::prepared(ga.mutation, run_.dim)) {
        if (ga.round_integers) categories_ = CategoricalVariation(problem, ga.categorical);
        if constexpr (constrained) {
            k_ = problem.constraint_counts().total();
            vnext_.assign(run_.fx.size(), 0.0);
            vy_.assign(kids_, 0.0);
            cnext_.assign(run_.cx.size(), 0.0);
            cy_.assign(k_ * kids_, 0.0);
        }
    }

    Rng& rng() noexcept { return run_.rng; }
    RunState& state() noexcept { return run_.state; }
    std::optional<std::int64_t> horizon() const noexcept { return run_.horizon; }
    std::size_t offspring() const noexcept { return kids_; }

    // The current population, for the loop and for hooks.
    std::size_t size() const noexcept { return run_.fx.size(); }
    std::span<const double> fitness() const noexcept { return run_.fx; }
    std::span<const double> individual(std::size_t i) const { return column(run_.x, index(i)); }

    // Variation: child k of this generation (the second child of an odd last pair goes to spare()).
    std::span<const std::size_t> regions() const noexcept { return {}; }  // points have no regions
    std::optional<double> best_length() const noexcept { return std::nullopt; }

    std::span<double> child(std::size_t k) { return column(y_, index(k)); }
    std::span<double> spare() { return column(spare_, 0); }
    void copy(std::size_t parent, std::span<double> to) const {
        std::copy_n(run_.x.col(index(parent)).data(), run_.dim, to.data());
    }
    /// At the start of each generation: the prepared operators that learn between generations.
    void begin_generation(const GenerationContext& context) {
        detail::begin_generation(cross_, context, run_.rng);
        detail::begin_generation(mutate_, context, run_.rng);
    }
    // The real-coded operators; categorical coordinates by their own (nothing without them).
    void cross(std::span<double> a, std::span<double> b, const GenerationContext& context) {
        categories_.cross(a, b, run_.rng, [&] { with_context(cross_, context, a, b, run_.lo, run_.hi, run_.rng); });
    }
    void mutate(std::span<double> c, const GenerationContext& context) {
        categories_.mutate(c, run_.rng, [&] { with_context(mutate_, context, c, run_.lo, run_.hi, run_.rng); });
    }
    void repair(std::span<double> c) const {
        ga_.bounds(c, run_.lo, run_.hi);
        run_.round(c);  // rounded children on integer coordinates (empty: none)
    }

    /// The children in order; +inf past the budget.
    void evaluate_children() {
        if constexpr (constrained)
            run_.state.evaluate_columns(problem_, y_, fy_, vy_, cy_);
        else
            run_.state.evaluate_columns(problem_, y_, fy_);
    }
    std::span<const double> children_fitness() const noexcept { return fy_; }

    // Constrained problems only: the violations of the current members and of the children, and
    // APM's penalised values of the current members (`parents`) or of the pool "parents, then
    // children", into `out`.
    std::span<const double> violations() const noexcept { return run_.vx; }
    std::span<const double> children_violations() const noexcept { return vy_; }
    void penalise(bool with_children, std::vector<double>& out) {
        if (!with_children) {
            out.resize(size());
            apm_(problem_, run_.fx, run_.vx, run_.cx, out);
            return;
        }
        pool_f_.assign(run_.fx.begin(), run_.fx.end());
        pool_f_.insert(pool_f_.end(), fy_.begin(), fy_.end());
        pool_v_.assign(run_.vx.begin(), run_.vx.end());
        pool_v_.insert(pool_v_.end(), vy_.begin(), vy_.end());
        pool_c_.assign(run_.cx.begin(), run_.cx.end());
        pool_c_.insert(pool_c_.end(), cy_.begin(), cy_.end());
        out.resize(pool_f_.size());
        apm_(problem_, pool_f_, pool_v_, pool_c_, out);
    }

    /// Member k of the next population is member `from` of the pool "parents, then children".
    void take(std::size_t k, std::size_t from) {
        const std::size_t n = size();
        next_.col(index(k)) = from < n ? run_.x.col(index(from)) : y_.col(index(from - n));
        fnext_[k] = from < n ? run_.fx[from] : fy_[from - n];
        if constexpr (constrained) {
            vnext_[k] = from < n ? run_.vx[from] : vy_[from - n];
            const double* c = from < n ? run_.cx.data() + from * k_ : cy_.data() + (from - n) * k_;
            std::copy_n(c, k_, cnext_.begin() + static_cast<std::ptrdiff_t>(k * k_));
        }
    }
    /// The next population becomes the current one.
    void advance() noexcept {
        std::swap(run_.x, next_);
        std::swap(run_.fx, fnext_);
        if constexpr (constrained) {
            std::swap(run_.vx, vnext_);
            std::swap(run_.cx, cnext_);
        }
    }
    template <class O>
    void end_iteration(O& observer) {
        run_.state.end_iteration(observer, run_.x, run_.fx);
    }
    Result finish() { return run_.state.finish(); }

    /// Replaces the members `which` by new points (the Init policy, then Bounds), evaluated in order
    /// (problems without constraints: no hook takes part in a constrained run).
    void renew(std::span<const std::size_t> which, Rng& rng) requires(!constrained) {
        Matrix fresh(run_.x.rows(), static_cast<Eigen::Index>(which.size()));
        std::vector<double> f(which.size());
        ga_.init(problem_, rng, fresh);
        for (Eigen::Index j = 0; j < fresh.cols(); ++j) ga_.bounds(column(fresh, j), run_.lo, run_.hi);
        run_.state.evaluate_columns(problem_, fresh, f);
        for (std::size_t j = 0; j < which.size(); ++j) {
            run_.x.col(index(which[j])) = fresh.col(index(j));
            run_.fx[which[j]] = f[j];
        }
    }

  private:
    static Eigen::Index index(std::size_t i) noexcept { return static_cast<Eigen::Index>(i); }

    const Algorithm& ga_;
    P& problem_;
    BoxRun run_;  // x, fx: the current population
    std::size_t kids_;
    Matrix next_, y_, spare_;
    std::vector<double> fnext_, fy_;
    detail::Prepared<decltype(Algorithm::crossover)> cross_;
    detail::Prepared<decltype(Algorithm::mutation)> mutate_;
    CategoricalVariation categories_;  // empty unless the problem has categorical coordinates
    // Constrained problems only: k_ = m + p; the next population's and the children's violations
    // and constraint values (the current ones are run_.vx, run_.cx); APM's pool and scratch.
    std::size_t k_ = 0;
    std::vector<double> vnext_, vy_, cnext_, cy_, pool_f_, pool_v_, pool_c_;
    AdaptivePenalty apm_;
};

/// Chains of a ChainProblem; the operators are the problem's (framework/chain.hpp), called through
/// the GA's chain operator policies (chain_operators.hpp). Bounds and Init do not apply.
template <class Algorithm, ChainProblem P>
class ChainPopulation {
  public:
    using Chain = typename P::chain_type;
    static constexpr bool constrained = false;

    /// The initial population: N random chains from the problem, made first, then evaluated in order.
    template <class O>
    ChainPopulation(const Algorithm& ga, P& problem, const Termination& termination, std::uint64_t seed, O& observer)
        : ga_(ga),
          problem_(problem),
          run_(start_run<Chain>(ga, termination, seed, {ga.replacement.offspring(ga.population), nullptr})),
          kids_(static_cast<std::size_t>(ga.replacement.offspring(ga.population))),
          x_(static_cast<std::size_t>(ga.population)),
          next_(x_.size()),
          y_(kids_),
          fx_(x_.size(), kInf),
          fnext_(x_.size()),
          fy_(kids_),
          cross_(detail::prepared(ga.crossover, 0)),
          mutate_(detail::prepared(ga.mutation, 0)) {
        for (auto& c : x_) counted().random_chain(run_.rng, c);
        for (std::size_t i = 0; i < x_.size() && !run_.state.exhausted(); ++i)
            fx_[i] = run_.state.evaluate(problem_, x_[i]);
        run_.state.end_iteration(observer, x_, fx_);
    }

    Rng& rng() noexcept { return run_.rng; }
    BasicRunState<Chain>& state() noexcept { return run_.state; }
    std::optional<std::int64_t> horizon() const noexcept { return run_.horizon; }
    std::size_t offspring() const noexcept { return kids_; }

    std::size_t size() const noexcept { return x_.size(); }
    std::span<const double> fitness() const noexcept { return fx_; }
    const Chain& individual(std::size_t i) const { return x_[i]; }

    /// The region of every current member when the space is RegionOf (worked out on each call),
    /// else empty.
    std::span<const std::size_t> regions() {
        if constexpr (RegionOf<P>) {
            regions_.resize(x_.size());
            for (std::size_t i = 0; i < x_.size(); ++i) regions_[i] = problem_.region(x_[i]);
        }
        return regions_;
    }

    /// The length of the best current member (the first of the smallest values) when the space is
    /// ChainLength, else empty.
    std::optional<double> best_length() const {
        if constexpr (ChainLength<P>) {
            if (x_.empty()) return std::nullopt;
            const auto best = static_cast<std::size_t>(std::min_element(fx_.begin(), fx_.end()) - fx_.begin());
            return static_cast<double>(problem_.length(x_[best]));
        } else {
            return std::nullopt;
        }
    }

    Chain& child(std::size_t k) { return y_[k]; }
    Chain& spare() { return spare_; }
    void copy(std::size_t parent, Chain& to) const { to = x_[parent]; }
    void begin_generation(const GenerationContext& context) {
        detail::begin_generation(cross_, context, run_.rng);
        detail::begin_generation(mutate_, context, run_.rng);
    }
    void cross(Chain& a, Chain& b, const GenerationContext& context) {
        auto problem = counted();
        with_context(cross_, context, problem, a, b, run_.rng);
    }
    void mutate(Chain& c, const GenerationContext& context) {
        auto problem = counted();
        with_context(mutate_, context, problem, c, run_.rng);
    }
    void repair(Chain&) const noexcept {}  // the chain operators keep every chain feasible

    void evaluate_children() {
        for (std::size_t k = 0; k < kids_; ++k)
            fy_[k] = run_.state.exhausted() ? kInf : run_.state.evaluate(problem_, y_[k]);
    }
    std::span<const double> children_fitness() const noexcept { return fy_; }

    void take(std::size_t k, std::size_t from) {
        const std::size_t n = size();
        next_[k] = from < n ? x_[from] : y_[from - n];
        fnext_[k] = from < n ? fx_[from] : fy_[from - n];
    }
    void advance() noexcept {
        std::swap(x_, next_);
        std::swap(fx_, fnext_);
    }
    template <class O>
    void end_iteration(O& observer) {
        run_.state.end_iteration(observer, x_, fx_);
    }
    BasicResult<Chain> finish() { return run_.state.finish(); }

    /// Replaces the members `which` by new random chains, made first, then evaluated in order.
    void renew(std::span<const std::size_t> which, Rng& rng) {
        for (const std::size_t i : which) counted().random_chain(rng, x_[i]);
        for (const std::size_t i : which) fx_[i] = run_.state.exhausted() ? kInf : run_.state.evaluate(problem_, x_[i]);
    }

  private:
    /// The space's operators through the run's evaluation guard (framework/counted_chain.hpp).
    CountedChains<P, BasicRunState<Chain>> counted() noexcept { return {problem_, run_.state}; }

    const Algorithm& ga_;
    P& problem_;
    RunStart<Chain> run_;
    std::size_t kids_;
    std::vector<Chain> x_, next_, y_;  // x_: the current population
    Chain spare_;
    std::vector<double> fx_, fnext_, fy_;
    std::vector<std::size_t> regions_;  // of x_, when asked for (regions())
    detail::Prepared<decltype(Algorithm::crossover)> cross_;
    detail::Prepared<decltype(Algorithm::mutation)> mutate_;
};

}  // namespace pride

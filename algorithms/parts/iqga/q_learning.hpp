#pragma once
// Adaptive operator selection by Q-learning, as Zhang et al. (2025) (IQGA, section 2.4, eq. 19) uses it to
// choose the probabilities of its mutation operators, written for any set of operators on boxes or
// chains (docs/algorithms.md, IQGA: Q-learning).
//
//   Watkins, C. J. C. H. and Dayan, P. (1992). Q-learning. Machine Learning 8, 279-292.
//   Zhang et al. 2025, eq. 19:
//     Q(s_t, a_t) <- Q(s_t, a_t) + alpha (r_{t+1} + gamma max_a' Q(s_{t+1}, a') - Q(s_t, a_t)).
//
// States: how this generation's best value (the population's smallest, GenerationContext::best)
// compares with the previous generation's: 1 = smaller (better), 2 = equal, 3 = larger (worse);
// with `by_length` (IQGA), how the best member's length (GenerationContext::best_length) does, as
// Zhang et al. (2025) and the project's decision word it, when the population gives one (else the best value).
// Actions: assignments of probabilities to the operators; by default the distinct orderings of a
// weight vector, for three operators of (0.6, 0.2, 0.2) (the paper's values): a1 = (0.6, 0.2, 0.2),
// a2 = (0.2, 0.6, 0.2), a3 = (0.2, 0.2, 0.6). Reward: r_t = u - w for a move from state s_t = u to
// s_{t+1} = w (the paper's definition, which rewards a move to a better state only with the states
// numbered from best to worst, as the project's decision numbers them). Choice: epsilon-greedy (epsilon = 0.1),
// alpha = 0.1, gamma = 0.9 (the paper's values).
//
// Once per generation (OperatorQLearning::begin_generation, at the start of the generation, before
// its first selection): the new state is observed, Q of the previous (state, action) is updated by
// eq. 19 with the reward of the move, and this generation's action is chosen from the new state's
// row. Each operator call then picks one operator by the action's probabilities.
// Rng draws, all from the run's Rng in this order: per generation one U(0,1) for the epsilon test
// and, when it explores, one Rng::below(actions) for the action; per call, one U(0,1) for whether
// to mutate at all (only when `probability` < 1), one U(0,1) for the operator (roulette on the
// probabilities), then the chosen operator's own draws.
// Decided by this project where the paper is silent: Q starts at 0; the first generation has no
// previous best, so it starts in state 2 without an update; a greedy choice among equal Q values
// takes the lowest action index; exploring draws uniformly among all actions (the greedy one
// included); the orderings are listed in decreasing lexicographic order from the weights sorted
// from largest to smallest (so a_i gives the largest weight to operator i when the others are
// equal); for other than three operators the default weights are 0.6 for the first operator and
// 0.4 shared equally by the others (1 for a single operator).
//
// API.
//   OperatorQLearning: the learner alone (a value per run) over the three states and a table of
//     actions; state(previous_best, best), reward(u, w), update(s, a, r, s'), choose(s, rng),
//     begin_generation(best, rng), probabilities(), action(), current_state(), pick(rng), q(s, a).
//     States are numbered 1, 2, 3 in every call.
//   QLearningMutation<Op...>: a GA mutation policy over the operators Op... (box mutations such as
//     PolynomialMutation, UniformMutation, GaussianMutation, or chain mutations such as
//     ChainMutation): its prepared form (one per run) holds the learner and the operators' own
//     prepared forms; the GA calls begin_generation once per generation and the mutation per child,
//     with the arguments of the operators and a trailing GenerationContext, which the chosen
//     operator also gets if it takes one (with_context).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "algorithms/parts/ga/generation_context.hpp"
#include "framework/error.hpp"
#include "framework/random.hpp"

namespace pride {

struct QLearningSettings {
    double epsilon = 0.1;  // probability of a random action
    double alpha = 0.1;    // learning rate
    double gamma = 0.9;    // discount factor

    void validate(const std::string& where) const {
        require(epsilon >= 0.0 && epsilon <= 1.0, where, "epsilon must be in [0, 1], got " + std::to_string(epsilon));
        require(alpha >= 0.0 && alpha <= 1.0, where, "alpha must be in [0, 1], got " + std::to_string(alpha));
        require(gamma >= 0.0 && gamma <= 1.0, where, "gamma must be in [0, 1], got " + std::to_string(gamma));
    }
};

/// The distinct orderings of `weights`, in decreasing lexicographic order starting from the weights
/// sorted from largest to smallest: (0.6, 0.2, 0.2) gives (0.6, 0.2, 0.2), (0.2, 0.6, 0.2), (0.2, 0.2, 0.6).
inline std::vector<std::vector<double>> orderings(std::vector<double> weights) {
    std::vector<std::vector<double>> out;
    std::sort(weights.begin(), weights.end(), std::greater<>());
    do out.push_back(weights);
    while (std::prev_permutation(weights.begin(), weights.end()));
    return out;
}

/// The default weights for m operators: (0.6, 0.2, 0.2) for three, as Zhang et al. (2025); otherwise 0.6 for
/// the first and 0.4 shared by the others, (1) for one.
inline std::vector<double> default_operator_weights(std::size_t m) {
    if (m <= 1) return std::vector<double>(m, 1.0);
    std::vector<double> w(m, 0.4 / static_cast<double>(m - 1));
    w[0] = 0.6;
    return w;
}

/// Checks a table of actions over m operators: at least one, each m probabilities summing to 1.
inline void validate_actions(const std::vector<std::vector<double>>& actions, std::size_t m, const std::string& where) {
    require(!actions.empty(), where, "Q-learning needs at least one action");
    for (const auto& a : actions) {
        require(a.size() == m, where,
                "each action must give " + std::to_string(m) + " probabilities, got " + std::to_string(a.size()));
        double sum = 0.0;
        for (const double p : a) {
            require(p >= 0.0 && p <= 1.0, where, "operator probabilities must be in [0, 1], got " + std::to_string(p));
            sum += p;
        }
        require(std::abs(sum - 1.0) <= 1e-9, where,
                "an action's probabilities must sum to 1, got " + std::to_string(sum));
    }
}

class OperatorQLearning {
  public:
    static constexpr int kStates = 3;

    OperatorQLearning(QLearningSettings settings, const std::vector<std::vector<double>>& actions)
        : settings_(settings),
          operators_(actions.empty() ? 0 : actions.front().size()),
          actions_(actions.size()),
          table_(actions_ * operators_),
          q_(kStates * actions_, 0.0) {
        validate_actions(actions, operators_, "Q-learning");
        for (std::size_t a = 0; a < actions.size(); ++a)
            std::copy(actions[a].begin(), actions[a].end(),
                      table_.begin() + static_cast<std::ptrdiff_t>(a * operators_));
    }

    /// 1 when best < previous (better), 2 when equal, 3 when larger (worse).
    static int state(double previous_best, double best) noexcept {
        return best < previous_best ? 1 : best == previous_best ? 2 : 3;
    }
    /// r = u - w for a move from state u to state w.
    static double reward(int u, int w) noexcept { return static_cast<double>(u - w); }

    std::size_t actions() const noexcept { return actions_; }
    std::size_t operators() const noexcept { return operators_; }
    const QLearningSettings& settings() const noexcept { return settings_; }

    double q(int state, std::size_t action) const { return q_[row(state) + action]; }
    double& q(int state, std::size_t action) { return q_[row(state) + action]; }

    /// Eq. 19: Q(s, a) += alpha (r + gamma max_a' Q(s', a') - Q(s, a)).
    void update(int s, std::size_t a, double r, int next) {
        const auto begin = q_.begin() + static_cast<std::ptrdiff_t>(row(next));
        const double best_next = *std::max_element(begin, begin + static_cast<std::ptrdiff_t>(actions()));
        double& value = q(s, a);
        value += settings_.alpha * (r + settings_.gamma * best_next - value);
    }

    /// Epsilon-greedy: with probability epsilon a uniformly drawn action, else the first of the
    /// row's largest Q values.
    std::size_t choose(int s, Rng& rng) const {
        if (rng.uniform() < settings_.epsilon) return static_cast<std::size_t>(rng.below(actions()));
        const auto begin = q_.begin() + static_cast<std::ptrdiff_t>(row(s));
        return static_cast<std::size_t>(std::max_element(begin, begin + static_cast<std::ptrdiff_t>(actions())) -
                                        begin);
    }

    /// Once per generation, with the generation's best value: observe, learn, choose.
    void begin_generation(double best, Rng& rng) {
        if (started_) {
            const int next = state(previous_best_, best);
            update(state_, action_, reward(state_, next), next);
            state_ = next;
        } else {
            started_ = true;
            state_ = 2;
        }
        previous_best_ = best;
        action_ = choose(state_, rng);
    }

    int current_state() const noexcept { return state_; }
    std::size_t action() const noexcept { return action_; }
    /// The current action's probability for each operator.
    std::span<const double> probabilities() const noexcept {
        return std::span<const double>(table_).subspan(action_ * operators_, operators_);
    }
    /// One operator drawn by probabilities() (one U(0,1) draw; rounding goes to the last with weight).
    std::size_t pick(Rng& rng) const {
        const auto p = probabilities();
        const double u = rng.uniform();
        double cumulative = 0.0;
        std::size_t last = 0;
        for (std::size_t i = 0; i < p.size(); ++i) {
            if (p[i] <= 0.0) continue;
            cumulative += p[i];
            last = i;
            if (u < cumulative) return i;
        }
        return last;
    }

  private:
    std::size_t row(int state) const noexcept { return static_cast<std::size_t>(state - 1) * actions(); }

    QLearningSettings settings_;
    std::size_t operators_;
    std::size_t actions_;
    std::vector<double> table_;  // actions x operators, row by row
    std::vector<double> q_;      // states x actions, row by row
    bool started_ = false;
    double previous_best_ = 0.0;
    int state_ = 2;
    std::size_t action_ = 0;
};

/// A mutation that applies one of the operators Op..., chosen per child by the probabilities of
/// the action a Q-learner (OperatorQLearning) picks once per generation.
template <class... Operators>
class QLearningMutation {
  public:
    static constexpr std::size_t size = sizeof...(Operators);
    static_assert(size >= 1, "QLearningMutation needs at least one operator");

    std::tuple<Operators...> operators{};
    std::vector<double> weights = default_operator_weights(size);  // actions: its orderings ...
    std::vector<std::vector<double>> actions;                      // ... unless given here
    QLearningSettings learning{};
    double probability = 1.0;  // of mutating a child at all (then one operator is chosen)
    // States from the best member's length (GenerationContext::best_length, when the population
    // gives one) instead of the best value: IQGA's states (Zhang et al. 2025: "the best path length").
    bool by_length = false;

    /// The table of actions the learner chooses among.
    std::vector<std::vector<double>> action_table() const { return actions.empty() ? orderings(weights) : actions; }

    void validate(const std::string& where) const {
        learning.validate(where);
        require(probability >= 0.0 && probability <= 1.0, where,
                "Q-learning mutation probability must be in [0, 1], got " + std::to_string(probability));
        validate_actions(action_table(), size, where);
        std::apply([&](const auto&... op) { (validate_one(op, where), ...); }, operators);
    }

    class Prepared {
      public:
        template <std::size_t... I>
        Prepared(const QLearningMutation& m, std::size_t dim, std::index_sequence<I...>)
            : ops_(detail::prepared(std::get<I>(m.operators), dim)...),
              learner_(m.learning, m.action_table()),
              probability_(m.probability),
              by_length_(m.by_length) {}

        void begin_generation(const GenerationContext& c, Rng& rng) {
            learner_.begin_generation(by_length_ && c.best_length ? *c.best_length : c.best, rng);
        }
        const OperatorQLearning& learner() const noexcept { return learner_; }

        /// (operator arguments..., Rng&, const GenerationContext&).
        template <class... Args>
        requires(sizeof...(Args) >= 2 &&
                 std::is_same_v<std::remove_cvref_t<std::tuple_element_t<sizeof...(Args) - 1, std::tuple<Args...>>>,
                                GenerationContext>) void
        operator()(Args&&... args) const {
            constexpr std::size_t n = sizeof...(Args);
            auto all = std::forward_as_tuple(std::forward<Args>(args)...);
            const GenerationContext& context = std::get<n - 1>(all);
            Rng& rng = std::get<n - 2>(all);
            if (probability_ < 1.0 && !rng.bernoulli(probability_)) return;
            apply(learner_.pick(rng), all, context, std::make_index_sequence<n - 1>{});
        }

      private:
        template <class Tuple, std::size_t... I>
        void apply(std::size_t chosen, Tuple& all, const GenerationContext& context, std::index_sequence<I...>) const {
            std::apply(
                [&](const auto&... op) {
                    std::size_t k = 0;
                    ((k++ == chosen ? (with_context(op, context, std::get<I>(all)...), 0) : 0), ...);
                },
                ops_);
        }

        std::tuple<detail::Prepared<Operators>...> ops_;
        OperatorQLearning learner_;
        double probability_;
        bool by_length_;
    };

    /// One per run: the learner starts afresh.
    Prepared prepare(std::size_t dim) const { return Prepared(*this, dim, std::index_sequence_for<Operators...>{}); }

  private:
    template <class Op>
    static void validate_one(const Op& op, const std::string& where) {
        if constexpr (requires { op.validate(where); }) op.validate(where);
    }
};

}  // namespace pride

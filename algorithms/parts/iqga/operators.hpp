#pragma once
// Zhang et al.'s (2025) IQGA (docs/algorithms.md, IQGA) as GA policies (ga.hpp), over any chain space
// with the capabilities of framework/chain.hpp (RegionOf, TwoPointCrossover, NumberedMutations):
//   RegionTournamentSelection  eqs. 14-18: a mating pool built once per generation from tournaments
//                              of three inside each region, then the parents drawn from it in
//                              pairs that respect the elite pairing rule of section 2.4.2;
//   EliteCrossover             section 2.4.2, fig. 7: with probability Pc the two-point crossover at
//                              two common cells, for pairs holding at least one elite member;
//   NumberedChainMutation<K>   section 2.4.3: the space's mutation K (0 deletion, 1 mid-point,
//                              2 turning point) with eq. 20's badness; IqgaMutation is the
//                              Q-learning choice among the three (q_learning.hpp, eq. 19), its
//                              states from the length of the generation's best path (ChainLength).
//
// What the paper says (Zhang et al. 2025, eqs. 16-18) and what is done here. Eq. 16: s_1 = n_1 if n_1 <= N/3,
// else N/3; s_2 likewise; s_3 = N - s_1 - s_2 (n_i the members in region i; N/3 is read as
// floor(N/3), the same test for whole n_i). Eq. 17: B = F_best - (21/20) F_worst, F the maximised
// fitness of the current population. Eq. 18: P_j = (F_i - F_worst) / (F_best - F_worst), F_i the
// fitness of the tournament's second member; it is kept when a U(0,1) draw P_r < P_j. The paper
// gives no temperature and no cooling schedule: its "simulated annealing" is only this acceptance of
// a worse member with probability P_j, which changes as the population does; none is added here.
// Text after eq. 18: if B > 0, the second is kept on P_r < P_j and the worst with probability 1/2;
// if B <= 0 the worst with probability 1/2 (the project's decision: the worst with 1/2 in either case).
// Decided by this project (the paper silent):
//   - F = -f, f the value the GA minimises (objective iqga is -(1/f1 + 1/f2 + 1/f3), so F is the
//     paper's positive eq. 12 fitness); members not evaluated (+inf) get P_j = 0;
//     F_best = F_worst gives P_j = 1;
//   - the three members are drawn uniformly with replacement from the region; a region with no
//     member (s_3 may be positive while n_3 = 0) draws its s_i tournaments from the whole
//     population; without regions (a space that is not RegionOf) the whole population is region 0;
//   - the tournament's members are ordered by f, ties by the order drawn;
//   - "the best path so far is always kept": the population's best member (the first of the
//     smallest f) joins the pool once more; with elitist replacement (elitism 1, as IQGA is
//     registered) it is the run's best so far, which the replacement also carries over unchanged;
//   - the pool holds between N + 1 and 3N + 1 entries (members may repeat); the GA asks for parents
//     in pairs (ga.hpp, step 1): the first parent of a pair is drawn uniformly from the pool, the
//     second uniformly from the pool when the first is elite, else uniformly from the pool's elite
//     entries (never empty: the population's best is elite and in the pool). That is where the
//     pairing rule lives; EliteCrossover does not cross a pair without an elite member, so the rule
//     also holds behind another selection (with this one no pair is refused);
//   - the elite: the E = min(elite, floor(N/2)) best members of the current population by f (ties
//     by index), so E = 20 for N >= 40 and N/2 below, as the project's decision says for elite = 20;
//   - eq. 20's badness B = (f_max - f_i)/(f_max - f_min) in the paper's maximised fitness, here
//     (f_i - f_min)/(f_max - f_min) on the minimised values, with f_i the value of the parent the
//     child was copied from (the child itself is not evaluated yet); 0.5 when f_max = f_min or a
//     value is not finite.
// Rng draws, in order: per generation (begin_generation), per tournament three Rng::below for the
// members (of the region, or of the population), then one U(0,1) for P_j when B > 0, then one
// U(0,1) for the worst (kept when < 1/2); per parent one Rng::below on the pool (or its elite
// entries); per pair one U(0,1) for Pc (only for a pair with an elite member), then the crossover's;
// the mutation's as q_learning.hpp says, then the chosen operator's.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "algorithms/parts/ga/generation_context.hpp"
#include "algorithms/parts/iqga/q_learning.hpp"
#include "framework/chain.hpp"
#include "framework/error.hpp"
#include "framework/random.hpp"

namespace pride {

namespace iqga {

/// E = min(elite, floor(N/2)): the elite's size in a population of n.
inline std::size_t elite_size(std::int64_t elite, std::size_t n) noexcept {
    return std::min(static_cast<std::size_t>(std::max<std::int64_t>(elite, 0)), n / 2);
}

/// Flags of the E best members of `f` (smallest values; ties by index), into `out`.
inline void elite_flags(std::span<const double> f, std::size_t e, std::vector<char>& out,
                        std::vector<std::size_t>& order) {
    order.resize(f.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return f[a] < f[b]; });
    out.assign(f.size(), 0);
    for (std::size_t k = 0; k < e && k < order.size(); ++k) out[order[k]] = 1;
}

/// Eq. 16: the selections per region for n_1, n_2 members in regions 1 and 2 of a population of N.
inline std::array<std::size_t, 3> selections(std::size_t n1, std::size_t n2, std::size_t n) noexcept {
    const std::size_t third = n / 3;
    const std::size_t s1 = std::min(n1, third), s2 = std::min(n2, third);
    return {s1, s2, n - s1 - s2};
}

/// Eq. 17 on maximised fitness values.
inline double uniformity(double f_best, double f_worst) noexcept {
    return f_best - 21.0 / 20.0 * f_worst;
}

/// Eq. 18 on maximised fitness values: the probability that a member of fitness F_i is kept.
inline double acceptance(double f_i, double f_best, double f_worst) noexcept {
    if (!std::isfinite(f_i) || !std::isfinite(f_best) || !std::isfinite(f_worst)) return 0.0;
    if (f_best == f_worst) return 1.0;
    return (f_i - f_worst) / (f_best - f_worst);
}

/// Eq. 20's badness of a member of value v (minimised) in a population of values [best, worst].
inline double badness(double v, double best, double worst) noexcept {
    if (!std::isfinite(v) || !std::isfinite(best) || !std::isfinite(worst) || worst <= best) return 0.5;
    return std::clamp((v - best) / (worst - best), 0.0, 1.0);
}

}  // namespace iqga

/// Eqs. 14-18: region-partitioned tournaments of three with the SA acceptance of the second; parents
/// drawn in pairs from the pool by the elite pairing rule (see the header comment).
struct RegionTournamentSelection {
    static constexpr bool uses_regions = true;  // the GA fills GenerationContext::regions for it
    std::int64_t elite = 20;                    // the pairing rule's elite: min(elite, N/2) best
    // Ablations (Zhang et al.'s (2025) changes removed one at a time): without `regions` the whole population
    // is one region and all N tournaments draw from it; without `pairing` the second parent is
    // drawn from the whole pool like the first (no elite pairing rule).
    bool regions = true;
    bool pairing = true;

    void validate(const std::string& where) const {
        require(elite >= 1, where, "elite must be >= 1, got " + std::to_string(elite));
    }

    class Prepared {
      public:
        explicit Prepared(std::int64_t elite, bool regions = true, bool pairing = true)
            : elite_(elite), regions_(regions), pairing_(pairing) {}

        /// Builds the generation's pool from the context's fitness and regions.
        void begin_generation(const GenerationContext& c, Rng& rng) {
            const std::span<const double> f = c.fitness;
            const std::size_t n = f.size();
            pool_.clear();
            pool_elite_.clear();
            pending_.reset();
            if (n == 0) return;
            for (auto& m : members_) m.clear();
            for (std::size_t i = 0; i < n; ++i) {
                const std::size_t r = regions_ && c.regions.size() == n ? std::min<std::size_t>(c.regions[i], 2) : 0;
                members_[r].push_back(i);
            }
            const auto s = regions_ ? iqga::selections(members_[0].size(), members_[1].size(), n)
                                    : std::array<std::size_t, 3>{n, 0, 0};
            // Maximised fitness F = -f of the population's best and worst.
            std::size_t best = 0;
            double worst = f[0];
            for (std::size_t i = 1; i < n; ++i) {
                if (f[i] < f[best]) best = i;
                worst = std::max(worst, f[i]);
            }
            const double F_best = -f[best], F_worst = -worst;
            const bool uniform = iqga::uniformity(F_best, F_worst) > 0.0;
            for (std::size_t r = 0; r < 3; ++r)
                for (std::size_t k = 0; k < s[r]; ++k) {
                    std::array<std::size_t, 3> t{};
                    for (auto& m : t)
                        m = members_[r].empty() ? static_cast<std::size_t>(rng.below(n))
                                                : members_[r][static_cast<std::size_t>(rng.below(members_[r].size()))];
                    std::stable_sort(t.begin(), t.end(), [&](std::size_t a, std::size_t b) { return f[a] < f[b]; });
                    pool_.push_back(t[0]);
                    if (uniform && rng.uniform() < iqga::acceptance(-f[t[1]], F_best, F_worst)) pool_.push_back(t[1]);
                    if (rng.uniform() < 0.5) pool_.push_back(t[2]);
                }
            pool_.push_back(best);
            iqga::elite_flags(f, iqga::elite_size(elite_, n), elite_flags_, order_);
            for (const std::size_t i : pool_)
                if (elite_flags_[i]) pool_elite_.push_back(i);
        }

        /// The next parent: the first of a pair from the pool, its partner by the pairing rule.
        std::size_t operator()(std::span<const double> fitness, Rng& rng) const {
            if (pool_.empty()) return static_cast<std::size_t>(rng.below(fitness.size()));  // not begun
            if (!pending_) {
                pending_ = pool_[static_cast<std::size_t>(rng.below(pool_.size()))];
                return *pending_;
            }
            const std::size_t first = *pending_;
            pending_.reset();
            const auto& from = !pairing_ || elite_flags_[first] ? pool_ : pool_elite_;
            return from[static_cast<std::size_t>(rng.below(from.size()))];
        }

        // For tests: this generation's pool and elite.
        std::span<const std::size_t> pool() const noexcept { return pool_; }
        bool is_elite(std::size_t i) const { return elite_flags_.at(i) != 0; }

      private:
        std::int64_t elite_;
        bool regions_, pairing_;
        std::array<std::vector<std::size_t>, 3> members_;
        std::vector<std::size_t> pool_, pool_elite_, order_;
        std::vector<char> elite_flags_;
        mutable std::optional<std::size_t> pending_;  // the first parent of the pair being drawn
    };

    Prepared prepare(std::size_t) const { return Prepared(elite, regions, pairing); }
};

/// Section 2.4.2, fig. 7: a pair with at least one elite member (min(elite, N/2) best of the
/// current population) is crossed with probability Pc at two common cells (TwoPointCrossover);
/// parents that cannot be crossed stay as they are.
struct EliteCrossover {
    double probability = 0.9;
    std::int64_t elite = 20;
    bool elite_only = true;  // ablation: false crosses every pair with probability Pc

    void validate(const std::string& where) const {
        require(probability >= 0.0 && probability <= 1.0, where,
                "pc must be in [0, 1], got " + std::to_string(probability));
        require(elite >= 1, where, "elite must be >= 1, got " + std::to_string(elite));
    }

    class Prepared {
      public:
        Prepared(double probability, std::int64_t elite, bool elite_only = true)
            : probability_(probability), elite_(elite), elite_only_(elite_only) {}
        void begin_generation(const GenerationContext& c, Rng&) {
            iqga::elite_flags(c.fitness, iqga::elite_size(elite_, c.fitness.size()), flags_, order_);
        }
        bool is_elite(std::size_t i) const { return i < flags_.size() && flags_[i] != 0; }

        template <TwoPointCrossover P>
        void operator()(P& problem, typename P::chain_type& a, typename P::chain_type& b, Rng& rng,
                        const GenerationContext& c) const {
            if (elite_only_ && !is_elite(c.parents[0]) && !is_elite(c.parents[1])) return;
            if (rng.bernoulli(probability_)) problem.crossover_two_point(a, b, rng);
        }

      private:
        double probability_;
        std::int64_t elite_;
        bool elite_only_;
        std::vector<char> flags_;
        std::vector<std::size_t> order_;
    };

    Prepared prepare(std::size_t) const { return Prepared(probability, elite, elite_only); }
};

/// The chain space's numbered mutation K (NumberedMutations), always applied (the Q-learning
/// mutation decides whether), with eq. 20's badness of the parent the child was copied from.
template <std::size_t K>
struct NumberedChainMutation {
    template <NumberedMutations P>
    void operator()(P& problem, typename P::chain_type& c, Rng& rng, const GenerationContext& context) const {
        const std::size_t parent = context.parents[context.child == 0 ? 0 : 1];
        const double v =
            parent < context.fitness.size() ? context.fitness[parent] : std::numeric_limits<double>::quiet_NaN();
        problem.mutate(K, c, rng, iqga::badness(v, context.best, context.worst));
    }
};

/// IQGA's mutation: with probability Pm (0.1) one of the three numbered mutations, by the
/// probabilities of the action Q-learning chooses once per generation (a1..a3: 0.6 / 0.2 / 0.2 on
/// deletion, mid-point, turning point in turn).
/// The states follow the length of the best member (the first of the smallest values) when the
/// space has lengths (ChainLength; the grid's ChainSpace has), as the project's decision says; else its value.
struct IqgaMutation : QLearningMutation<NumberedChainMutation<0>, NumberedChainMutation<1>, NumberedChainMutation<2>> {
    static constexpr bool uses_best_length = true;  // the GA fills GenerationContext::best_length
    IqgaMutation() {
        probability = 0.1;
        by_length = true;
    }
};

}  // namespace pride

#pragma once
// IAGA's adaptive crossover and mutation probabilities (the "improved adaptive GA" [30] that file
// 002 compares with; docs/algorithms.md, GA), as GA operator policies on boxes and chains.
//
//   Srinivas, M. and Patnaik, L. M. (1994). Adaptive probabilities of crossover and mutation in
//     genetic algorithms. IEEE Transactions on Systems, Man, and Cybernetics 24(4), 656-667.
//
// The paper maximises a fitness f; with fmax and favg the population's largest and mean fitness,
// f' the larger fitness of the two parents to be crossed and f the fitness of the solution to be
// mutated:
//   pc = k1 (fmax - f') / (fmax - favg)  if f' >= favg,   pc = k3  if f' < favg
//   pm = k2 (fmax - f)  / (fmax - favg)  if f  >= favg,   pm = k4  if f  < favg
// with k1 = k3 = 1.0 and k2 = k4 = 0.5 (the authors' values). Restated here for minimisation of
// the objective g (g = -f, so fmax becomes the population's smallest value `best`, favg its mean,
// and "at least average" becomes g <= mean):
//   pc = k1 (g' - best) / (mean - best)  if g' <= mean,   pc = k3  otherwise   (g' the smaller of the pair)
//   pm = k2 (g  - best) / (mean - best)  if g  <= mean,   pm = k4  otherwise
// best and mean are the GenerationContext's (the parents' population, generation_context.hpp).
// Decided by this project where the paper is silent or our setting differs:
//   - g for pm is the value of the parent the child started as a copy of (context.parents
//     [context.child]): the child itself is not evaluated before it is mutated;
//   - on boxes pm is the per-gene probability of polynomial mutation (the paper's pm is per bit),
//     on chains the probability that the child is mutated by the problem's operator;
//   - when mean = best (all members equal to the best) the scaled branch gives 0, the formula's
//     value at g = best; a member at +inf (not evaluated, or infeasible) is below average (k3, k4),
//     and a mean of +inf scales every finite member to 0 (the limit of the formula);
//   - pm is never below pm_min = 0.005, the default mutation rate the authors add so that the best
//     members (whose scaled pm is 0) do not stagnate. Without it (pm_min = 0, as first landed) the
//     best and the near-best are copied unchanged, the population fills with their copies and the
//     run stalls: rastrigin 10-D, 50,000 evaluations, seeds 1-5, best 27.6-67.5 (ga: 0.002-0.025);
//     with 0.005: 0.04-0.71; rosenbrock 10-D 85-76,879 against 0.3-300 (docs/algorithms.md).
//     The project's decision says only "adaptive probabilities (Srinivas and Patnaik)"; k1..k4 stay the authors'.
#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <string>

#include "algorithms/parts/ga/generation_context.hpp"
#include "algorithms/parts/variation/crossover.hpp"
#include "algorithms/parts/variation/mutation.hpp"
#include "framework/chain.hpp"
#include "framework/error.hpp"
#include "framework/random.hpp"

namespace pride {

/// One of Srinivas and Patnaik's adaptive probabilities (minimisation): `scaled` (k1 or k2) times
/// (g - best)/(mean - best) for a member at least as good as the mean, `flat` (k3 or k4) otherwise.
struct AdaptiveProbability {
    double scaled = 1.0;
    double flat = 1.0;
    double floor = 0.0;  // the least probability any member gets (pm_min; 0 for pc)

    /// (g - best)/(mean - best) in [0, 1] for g <= mean; empty for a member worse than the mean.
    static std::optional<double> scale(double g, double best, double mean) noexcept {
        if (!(g <= mean) || std::isinf(g)) return std::nullopt;
        const double spread = mean - best;
        if (!(spread > 0.0)) return 0.0;  // everyone is the best
        return std::clamp((g - best) / spread, 0.0, 1.0);
    }

    double operator()(double g, double best, double mean) const noexcept {
        const auto s = scale(g, best, mean);
        return std::max(floor, s ? scaled * *s : flat);
    }

    void validate(const std::string& where, const std::string& scaled_name, const std::string& flat_name) const {
        require(scaled >= 0.0 && scaled <= 1.0, where,
                scaled_name + " must be in [0, 1], got " + std::to_string(scaled));
        require(flat >= 0.0 && flat <= 1.0, where, flat_name + " must be in [0, 1], got " + std::to_string(flat));
        require(floor >= 0.0 && floor <= 1.0, where, "pm_min must be in [0, 1], got " + std::to_string(floor));
    }

    /// pc for the pair being crossed (g' the better parent's value).
    double for_pair(const GenerationContext& c) const noexcept {
        const double g = std::min(c.fitness[c.parents[0]], c.fitness[c.parents[1]]);
        return (*this)(g, c.best, c.mean);
    }
    /// pm for the child being mutated (the value of the parent it started from).
    double for_child(const GenerationContext& c) const noexcept {
        return (*this)(c.fitness[c.parents[c.child]], c.best, c.mean);
    }
};

/// The authors' constants: pc with k1 = k3 = 1.0, pm with k2 = k4 = 0.5 and their default mutation
/// rate 0.005 as the least pm of any member.
inline constexpr AdaptiveProbability kSrinivasPatnaikCrossover{1.0, 1.0};
inline constexpr AdaptiveProbability kSrinivasPatnaikMutation{0.5, 0.5, 0.005};

/// SBX (crossover.hpp) applied to a pair with IAGA's adaptive pc.
class AdaptiveSbxCrossover {
  public:
    double eta = 15.0;
    AdaptiveProbability probability = kSrinivasPatnaikCrossover;  // {k1, k3}

    void validate(const std::string& where) const {
        require(eta >= 0.0 && eta <= 1000.0, where, "eta_c must be in [0, 1000], got " + std::to_string(eta));
        probability.validate(where, "k1", "k3");
    }

    struct Prepared {
        SbxCrossover::Prepared sbx;
        AdaptiveProbability probability;
        void operator()(std::span<double> a, std::span<double> b, std::span<const double> lo,
                        std::span<const double> hi, Rng& rng, const GenerationContext& c) const {
            if (rng.bernoulli(probability.for_pair(c))) sbx.cross(a, b, lo, hi, rng);
        }
    };
    Prepared prepare(std::size_t) const { return {SbxCrossover::Prepared(eta, 1.0), probability}; }

    void operator()(std::span<double> a, std::span<double> b, std::span<const double> lo, std::span<const double> hi,
                    Rng& rng, const GenerationContext& c) const {
        prepare(a.size())(a, b, lo, hi, rng, c);
    }
};

/// Polynomial mutation (mutation.hpp) with IAGA's adaptive pm as its per-gene probability.
class AdaptivePolynomialMutation {
  public:
    double eta = 20.0;
    AdaptiveProbability probability = kSrinivasPatnaikMutation;  // {k2, k4}

    void validate(const std::string& where) const {
        require(eta >= 0.0 && eta <= 1000.0, where, "eta_m must be in [0, 1000], got " + std::to_string(eta));
        probability.validate(where, "k2", "k4");
    }

    struct Prepared {
        PolynomialMutation::Prepared polynomial;
        AdaptiveProbability probability;
        void operator()(std::span<double> x, std::span<const double> lo, std::span<const double> hi, Rng& rng,
                        const GenerationContext& c) const {
            polynomial.with_probability(probability.for_child(c), x, lo, hi, rng);
        }
    };
    Prepared prepare(std::size_t) const { return {PolynomialMutation::Prepared(eta, 0.0), probability}; }

    void operator()(std::span<double> x, std::span<const double> lo, std::span<const double> hi, Rng& rng,
                    const GenerationContext& c) const {
        prepare(x.size())(x, lo, hi, rng, c);
    }
};

/// The problem's chain crossover (chain_operators.hpp) applied to a pair with IAGA's adaptive pc.
struct AdaptiveChainCrossover {
    AdaptiveProbability probability = kSrinivasPatnaikCrossover;  // {k1, k3}
    void validate(const std::string& where) const { probability.validate(where, "k1", "k3"); }
    template <ChainProblem P>
    void operator()(P& problem, typename P::chain_type& a, typename P::chain_type& b, Rng& rng,
                    const GenerationContext& c) const {
        if (rng.bernoulli(probability.for_pair(c))) problem.crossover(a, b, rng);
    }
};

/// The problem's chain mutation applied to a child with IAGA's adaptive pm.
struct AdaptiveChainMutation {
    AdaptiveProbability probability = kSrinivasPatnaikMutation;  // {k2, k4}
    void validate(const std::string& where) const { probability.validate(where, "k2", "k4"); }
    template <ChainProblem P>
    void operator()(P& problem, typename P::chain_type& c, Rng& rng, const GenerationContext& context) const {
        if (rng.bernoulli(probability.for_child(context))) problem.mutate(c, rng);
    }
};

}  // namespace pride

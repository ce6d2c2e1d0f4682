#pragma once
// Variation of a typed space's categorical coordinates (framework/variables.hpp), whose choices
// have no order: a real-coded operator (SBX, polynomial mutation) would move them towards
// "neighbouring" choices that are not neighbours. So around the real-coded operators of a GA the
// categorical coordinates keep their values, and are then varied as pymoo's mixed-variable GA
// (pymoo 0.6, core/mixed.py) varies its Choice variables:
//   crossover: uniform crossover, each categorical coordinate exchanged between the two children
//     with probability `swap` (pymoo crosses each Choice variable on its own: UX with probability
//     0.9 per pair, then a fair coin per variable, so 0.45 per variable);
//   mutation: random resetting, each categorical coordinate of a child drawn anew, uniformly among
//     all its choices (the one it has included), with probability `reset` (pymoo's
//     ChoiceRandomMutation on a group of one variable: min(0.5, 1 / 1) = 0.5).
// Integer coordinates stay with the real-coded operators and the rounding operator (pymoo's SBX
// and PM with its RoundingRepair). On a problem without categorical coordinates nothing is drawn,
// so runs on real and integer variables are what they were, bit for bit.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "framework/error.hpp"
#include "framework/random.hpp"
#include "framework/variables.hpp"

namespace pride {

/// The probabilities of the categorical operators (defaults: pymoo's mixed-variable GA).
struct CategoricalRates {
    double swap = 0.45;  // per categorical coordinate and pair of children (uniform crossover)
    double reset = 0.5;  // per categorical coordinate and child (random resetting)

    void validate(const std::string& who) const {
        require(swap >= 0.0 && swap <= 1.0, who, "categorical swap probability must be in [0, 1]");
        require(reset >= 0.0 && reset <= 1.0, who, "categorical reset probability must be in [0, 1]");
    }
};

/// The categorical coordinates of one problem with their choices, and scratch for the values kept
/// around the real-coded operators (allocated once per run).
class CategoricalVariation {
  public:
    CategoricalVariation() = default;
    template <class P>
    requires(!std::same_as<P, CategoricalVariation> && Boxed<P>)  // not a copy constructor candidate
        CategoricalVariation(const P& p, CategoricalRates rates)
        : rates_(rates) {
        if constexpr (TypedVariables<P>) {
            for (std::size_t i = 0; i < p.dimension(); ++i)
                if (p.variable_type(i) == VariableType::categorical) {
                    index_.push_back(i);
                    first_.push_back(p.lower()[i]);
                    // The problem checked the bounds: integral, lower 0, at least two choices.
                    choices_.push_back(static_cast<std::uint64_t>(p.upper()[i] - p.lower()[i]) + 1);
                }
        }
        kept_.resize(2 * index_.size());
    }

    bool empty() const noexcept { return index_.empty(); }

    /// `real(a, b)` (the real-coded crossover) on every coordinate but the categorical ones, which
    /// then undergo the uniform crossover.
    template <class Real>
    void cross(std::span<double> a, std::span<double> b, Rng& rng, Real&& real) {
        if (index_.empty()) return std::forward<Real>(real)();
        const std::size_t m = index_.size();
        for (std::size_t k = 0; k < m; ++k) {
            kept_[k] = a[index_[k]];
            kept_[m + k] = b[index_[k]];
        }
        std::forward<Real>(real)();
        for (std::size_t k = 0; k < m; ++k) {
            const bool swap = rng.uniform() < rates_.swap;
            a[index_[k]] = swap ? kept_[m + k] : kept_[k];
            b[index_[k]] = swap ? kept_[k] : kept_[m + k];
        }
    }

    /// `real()` (the real-coded mutation of x) on every coordinate but the categorical ones, which
    /// then undergo random resetting.
    template <class Real>
    void mutate(std::span<double> x, Rng& rng, Real&& real) {
        if (index_.empty()) return std::forward<Real>(real)();
        const std::size_t m = index_.size();
        for (std::size_t k = 0; k < m; ++k) kept_[k] = x[index_[k]];
        std::forward<Real>(real)();
        for (std::size_t k = 0; k < m; ++k) {
            x[index_[k]] = kept_[k];
            if (rng.uniform() < rates_.reset) x[index_[k]] = first_[k] + static_cast<double>(rng.below(choices_[k]));
        }
    }

  private:
    CategoricalRates rates_{};
    std::vector<std::size_t> index_;      // the categorical coordinates, in order
    std::vector<double> first_;           // each one's first choice (its lower bound)
    std::vector<std::uint64_t> choices_;  // each one's number of choices
    std::vector<double> kept_;            // their values around the real-coded operator
};

}  // namespace pride

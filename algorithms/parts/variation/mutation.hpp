#pragma once
// Mutation for real-coded GAs.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>

#include "algorithms/parts/common/power.hpp"
#include "framework/error.hpp"
#include "framework/random.hpp"

namespace pride {

/// The two forms of polynomial mutation differ only in the step of one mutated coordinate; the
/// shell around it (which coordinates mutate, the bounds, the generator) is one,
/// PolynomialMutationOf<Form>.
namespace polynomial {

/// Bounded form (Deb and Goyal 1996; the form of Deb's NSGA-II code and pagmo2):
///   d1 = (y - low)/(high - low), d2 = (high - y)/(high - low), u ~ U(0,1)
///   u <= 1/2: dq = (2u + (1 - 2u)(1 - d1)^(eta+1))^(1/(eta+1)) - 1
///   u >  1/2: dq = 1 - (2(1 - u) + 2(u - 1/2)(1 - d2)^(eta+1))^(1/(eta+1))
///   y <- y + dq (high - low).  The project's default: eta = 20.
class Bounded {
  public:
    explicit Bounded(double eta) : power_(eta + 1.0), root_(1.0 / (eta + 1.0)) {}

    double operator()(double y, double low, double high, double u) const {
        const double width = high - low;
        double dq;
        if (u <= 0.5) {
            const double val = 2.0 * u + (1.0 - 2.0 * u) * power_(1.0 - (y - low) / width);
            dq = root_(val) - 1.0;
        } else {
            const double val = 2.0 * (1.0 - u) + 2.0 * (u - 0.5) * power_(1.0 - (high - y) / width);
            dq = 1.0 - root_(val);
        }
        return y + dq * width;
    }

  private:
    FixedPower power_;
    FixedPower root_;
};

/// Simple form of Deb and Deb (2014, "Analysing mutation schemes for real-parameter genetic
/// algorithms", IJAISC 4(1): the paper pagmo2's sga cites), which pagmo2's sga uses: the step is a
/// fraction of the distance to the face the coordinate moves towards, not of the box's width, and
/// the bound terms (1 - d)^(eta+1) of the bounded form are absent:
///   u <= 1/2: delta = (2u)^(1/(eta+1)) - 1,        y <- y + delta (y - low)
///   u >  1/2: delta = 1 - (2(1 - u))^(1/(eta+1)),  y <- y + delta (high - y)
/// For a coordinate in the middle of its box the step is half the bounded form's, and it shrinks
/// towards a face: this is what makes pagmo2's sga reach better medians than ga-plus
/// (docs/benchmarks.md).
class Simple {
  public:
    explicit Simple(double eta) : root_(1.0 / (eta + 1.0)) {}

    double operator()(double y, double low, double high, double u) const {
        return u <= 0.5 ? y + (root_(2.0 * u) - 1.0) * (y - low) : y + (1.0 - root_(2.0 * (1.0 - u))) * (high - y);
    }

  private:
    FixedPower root_;
};

}  // namespace polynomial

/// Polynomial mutation of either form: each coordinate mutates with probability pm (pm < 0 means
/// 1/D, the project's default) by the form's step, then is clamped to its bounds. Whether a
/// coordinate mutates is decided by 32 bits of a generator step (two coordinates per step): it
/// mutates when those bits, read as an integer, are below pm 2^32, so both forms draw alike.
template <class Form>
class PolynomialMutationOf {
  public:
    double eta = 20.0;
    double probability = -1.0;

    void validate(const std::string& where) const {
        require(eta >= 0.0 && eta <= 1000.0, where, "eta_m must be in [0, 1000], got " + std::to_string(eta));
        require(probability <= 1.0, where,
                "pm must be in [0, 1] (or negative for 1/D), got " + std::to_string(probability));
    }

    /// The operator with its constants (the threshold for pm, the powers) worked out once per run.
    class Prepared {
      public:
        Prepared(double eta, double pm) : threshold_(static_cast<std::uint64_t>(std::ldexp(pm, 32))), form_(eta) {}

        void operator()(std::span<double> x, std::span<const double> lo, std::span<const double> hi, Rng& rng) const {
            mutate(x, lo, hi, rng, threshold_);
        }

        /// With a per-gene probability pm given per call (IAGA's adaptive pm: adaptive_rates.hpp).
        void with_probability(double pm, std::span<double> x, std::span<const double> lo, std::span<const double> hi,
                              Rng& rng) const {
            mutate(x, lo, hi, rng, threshold(pm));
        }

        static std::uint64_t threshold(double pm) noexcept {
            return static_cast<std::uint64_t>(std::ldexp(std::clamp(pm, 0.0, 1.0), 32));
        }

      private:
        void mutate(std::span<double> x, std::span<const double> lo, std::span<const double> hi, Rng& run_rng,
                    std::uint64_t threshold) const {
            if (threshold == 0) return;
            // Drawn from a local copy, put back at the end: its state stays in registers (the same
            // draws in the same order), where the run's would be loaded and stored at every step.
            Rng rng = run_rng;
            std::uint64_t bits = 0;
            for (std::size_t i = 0; i < x.size(); ++i) {
                bits = i % 2 == 0 ? rng() : bits >> 32;
                if ((bits & 0xFFFFFFFFu) >= threshold) continue;
                if (!(hi[i] - lo[i] > 0.0)) continue;
                const double u = rng.uniform();
                x[i] = std::clamp(form_(x[i], lo[i], hi[i], u), lo[i], hi[i]);
            }
            run_rng = rng;
        }

        std::uint64_t threshold_;  // pm 2^32; 2^32 when pm = 1
        Form form_;
    };

    Prepared prepare(std::size_t dim) const {
        return Prepared(eta, probability < 0.0 ? 1.0 / static_cast<double>(dim) : probability);
    }

    void operator()(std::span<double> x, std::span<const double> lo, std::span<const double> hi, Rng& rng) const {
        prepare(x.size())(x, lo, hi, rng);
    }
};

/// The bounded form, the default of the GA, NSGA-II, MOEA/D and SMS-EMOA.
using PolynomialMutation = PolynomialMutationOf<polynomial::Bounded>;
/// The simple form, as pagmo2's sga (the registry's ga-sga).
using SimplePolynomialMutation = PolynomialMutationOf<polynomial::Simple>;

/// Uniform (random-reset) mutation: each coordinate mutates with probability pm (pm < 0 means
/// 1/D) and is then drawn anew, uniformly in [low, high] (Michalewicz 1996, Genetic Algorithms +
/// Data Structures = Evolution Programs, 3rd ed., Springer: "uniform mutation"). One U(0,1) draw
/// per coordinate decides, one more gives a mutated coordinate its value.
class UniformMutation {
  public:
    double probability = -1.0;

    void validate(const std::string& where) const {
        require(probability <= 1.0, where,
                "pm must be in [0, 1] (or negative for 1/D), got " + std::to_string(probability));
    }

    struct Prepared {
        double pm;
        void operator()(std::span<double> x, std::span<const double> lo, std::span<const double> hi, Rng& rng) const {
            for (std::size_t i = 0; i < x.size(); ++i)
                if (rng.bernoulli(pm)) x[i] = std::clamp(rng.uniform(lo[i], hi[i]), lo[i], hi[i]);
        }
    };

    Prepared prepare(std::size_t dim) const {
        return {probability < 0.0 ? 1.0 / static_cast<double>(dim) : probability};
    }

    void operator()(std::span<double> x, std::span<const double> lo, std::span<const double> hi, Rng& rng) const {
        prepare(x.size())(x, lo, hi, rng);
    }
};

/// Gaussian mutation: each coordinate mutates with probability pm (pm < 0 means 1/D) by
///   y <- clamp(y + sigma (high - low) N(0, 1)),
/// sigma relative to the coordinate's range (this project's choice: 0.1 by default, as the
/// step of the (1+1)-ES example). One U(0,1) draw per coordinate decides, one N(0,1) draw
/// (Rng::normal) moves a mutated coordinate.
class GaussianMutation {
  public:
    double sigma = 0.1;
    double probability = -1.0;

    void validate(const std::string& where) const {
        require(sigma > 0.0 && sigma <= 1.0, where, "sigma must be in (0, 1], got " + std::to_string(sigma));
        require(probability <= 1.0, where,
                "pm must be in [0, 1] (or negative for 1/D), got " + std::to_string(probability));
    }

    struct Prepared {
        double sigma, pm;
        void operator()(std::span<double> x, std::span<const double> lo, std::span<const double> hi, Rng& rng) const {
            for (std::size_t i = 0; i < x.size(); ++i)
                if (rng.bernoulli(pm)) x[i] = std::clamp(x[i] + sigma * (hi[i] - lo[i]) * rng.normal(), lo[i], hi[i]);
        }
    };

    Prepared prepare(std::size_t dim) const {
        return {sigma, probability < 0.0 ? 1.0 / static_cast<double>(dim) : probability};
    }

    void operator()(std::span<double> x, std::span<const double> lo, std::span<const double> hi, Rng& rng) const {
        prepare(x.size())(x, lo, hi, rng);
    }
};

}  // namespace pride

#pragma once
// What tests/test_algorithms.cpp and tests/test_algorithm_settings.cpp share: probes that record
// every evaluated point, the algorithms in their test settings, and for_each_algorithm (every
// registered box algorithm, for the suites that every algorithm must pass). Once one file;
// split so that neither translation unit takes over 30 s to compile.
#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <random>
#include <span>
#include <string>
#include <tuple>
#include <vector>

#include "algorithms/de.hpp"
#include "algorithms/ga.hpp"
#include "algorithms/lso.hpp"
#include "algorithms/nlopt.hpp"
#include "algorithms/parts/common/power.hpp"
#include "algorithms/parts/ga/selection.hpp"
#include "algorithms/parts/swarm/inertia.hpp"
#include "algorithms/parts/swarm/velocity.hpp"
#include "algorithms/parts/variation/crossover.hpp"
#include "algorithms/parts/variation/mutation.hpp"
#include "algorithms/pso.hpp"
#include "framework/bounds.hpp"
#include "framework/error.hpp"
#include "framework/termination.hpp"
#include "problems/continuous/functions.hpp"
#include "problems/continuous/transformed.hpp"

namespace algorithms_test {

using pride::Matrix;
constexpr double inf = std::numeric_limits<double>::infinity();
constexpr double nan_value = std::numeric_limits<double>::quiet_NaN();

// ---------------------------------------------------------------------------------------------
// Test problems and wrappers

/// A box problem with its own (per-coordinate) bounds and objective.
struct BoxOf {
    std::vector<double> lo, hi;
    std::function<double(std::span<const double>)> f;
    std::size_t dimension() const { return lo.size(); }
    std::span<const double> lower() const { return lo; }
    std::span<const double> upper() const { return hi; }
    double evaluate(std::span<const double> x) { return f(x); }
};

/// What a Probe saw, shared between the copies an algorithm makes of the problem.
struct ProbeLog {
    std::int64_t calls = 0;
    std::int64_t outside = 0;  // evaluated points with a coordinate outside the box (or NaN)
    std::int64_t wrong_size = 0;
};

/// Counts its own evaluations and checks every evaluated point against the box, independently of
/// the evaluation guard (so the guard cannot lie about its count).
template <class P>
struct Probe {
    P inner;
    std::shared_ptr<ProbeLog> log = std::make_shared<ProbeLog>();

    std::size_t dimension() const { return inner.dimension(); }
    std::span<const double> lower() const { return inner.lower(); }
    std::span<const double> upper() const { return inner.upper(); }
    double evaluate(std::span<const double> x) {
        ++log->calls;
        if (x.size() != dimension()) ++log->wrong_size;
        const auto lo = lower();
        const auto hi = upper();
        for (std::size_t i = 0; i < x.size() && i < lo.size(); ++i)
            if (!(x[i] >= lo[i] && x[i] <= hi[i])) {
                ++log->outside;
                break;
            }
        return inner.evaluate(x);
    }
};

template <class P>
Probe<P> probe(P p) {
    return Probe<P>{std::move(p)};
}

/// Like Probe, but offers batch evaluation, so the guard's batch path is exercised.
template <class P>
struct BatchProbe : Probe<P> {
    void evaluate_batch(pride::MatrixView points, std::span<double> values) {
        REQUIRE(static_cast<std::size_t>(points.cols()) == values.size());
        for (Eigen::Index j = 0; j < points.cols(); ++j) {
            const std::span<const double> x(points.col(j).data(), static_cast<std::size_t>(points.rows()));
            values[static_cast<std::size_t>(j)] = this->evaluate(x);
        }
    }
};
static_assert(pride::BatchBoxProblem<BatchProbe<pride::continuous::Sphere>>);
static_assert(!pride::BatchBoxProblem<Probe<pride::continuous::Sphere>>);

inline bool inside(std::span<const double> x, std::span<const double> lo, std::span<const double> hi) {
    if (x.size() != lo.size()) return false;
    for (std::size_t i = 0; i < x.size(); ++i)
        if (!(x[i] >= lo[i] && x[i] <= hi[i])) return false;
    return true;
}

inline bool bits_equal(const std::vector<double>& a, const std::vector<double>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (std::bit_cast<std::uint64_t>(a[i]) != std::bit_cast<std::uint64_t>(b[i])) return false;
    return true;
}

inline bool bits_equal(double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

inline std::uint64_t fnv1a(std::uint64_t h, const double* data, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) {
        auto bits = std::bit_cast<std::uint64_t>(data[i]);
        for (int b = 0; b < 8; ++b) {
            h ^= bits & 0xFF;
            h *= 0x100000001B3ULL;
            bits >>= 8;
        }
    }
    return h;
}

/// One line per observer call: iteration, evaluations, best_f bits, hash of population + fitness
/// + best_x.
struct ObserverLog {
    std::vector<std::tuple<std::int64_t, std::int64_t, std::uint64_t, std::uint64_t>> lines;
    std::int64_t population_outside = 0;  // columns seen outside the box (set by bounds tests)
    std::vector<double> lo, hi;

    void operator()(const pride::IterationView& v) {
        std::uint64_t h = 0xCBF29CE484222325ULL;
        h = fnv1a(h, v.population.data(), static_cast<std::size_t>(v.population.size()));
        h = fnv1a(h, v.fitness.data(), v.fitness.size());
        h = fnv1a(h, v.best_x.data(), v.best_x.size());
        lines.emplace_back(v.iteration, v.evaluations, std::bit_cast<std::uint64_t>(v.best_f), h);
        if (!lo.empty())
            for (Eigen::Index j = 0; j < v.population.cols(); ++j)
                if (!inside(pride::column(v.population, j), lo, hi)) ++population_outside;
    }
};

/// The history invariants every run must satisfy.
inline void check_history(const pride::Result& r) {
    REQUIRE(!r.history.empty());
    REQUIRE(r.history.size() == r.history_evaluations.size());
    CHECK(r.history.size() == static_cast<std::size_t>(r.iterations) + 1);
    for (std::size_t k = 0; k < r.history.size(); ++k) {
        INFO("history entry " << k);
        CHECK(!std::isnan(r.history[k]));
        if (k > 0) {
            CHECK(r.history[k] <= r.history[k - 1]);
            CHECK(r.history_evaluations[k] > r.history_evaluations[k - 1]);
        }
    }
    CHECK(r.history_evaluations.front() >= 1);
    CHECK(r.history_evaluations.back() <= r.evaluations);
    CHECK(bits_equal(r.history.back(), r.best_f));
}

// The algorithms under test, each built as a user would.
inline pride::Pso<> pso(std::int64_t population = 50) {
    pride::Pso<> a;
    a.population = population;
    return a;
}
inline pride::Pso<pride::ConstrictionVelocity> pso_constriction(std::int64_t population = 50) {
    pride::Pso<pride::ConstrictionVelocity> a;
    a.id = "pso-constriction";
    a.population = population;
    return a;
}
inline pride::Ga<> ga(std::int64_t population = 50, std::int64_t elitism = 1) {
    pride::Ga<> a;
    a.population = population;
    a.replacement.elitism = elitism;
    return a;
}
using PsoReflect = pride::Pso<pride::InertiaVelocity<pride::LinearInertia>, pride::RangeVelocityClamp, pride::Reflect>;
using PsoReflectFree = pride::Pso<pride::InertiaVelocity<pride::LinearInertia>, pride::NoVelocityClamp, pride::Reflect>;
using GaReflect = pride::Ga<pride::TournamentSelection, pride::SbxCrossover, pride::PolynomialMutation, pride::Reflect>;

using GaPlus = pride::Ga<pride::TournamentSelection, pride::SbxCrossover, pride::PolynomialMutation, pride::Clamp,
                         pride::UniformInit, pride::PlusReplacement>;
inline GaPlus ga_plus(std::int64_t population = 50) {
    GaPlus a;
    a.id = "ga-plus";
    a.population = population;
    return a;
}

// The differential evolution family as the registry configures it (engine/entries/de_entries.cpp): one
// type, so its four configurations share one instantiation per problem type.
using DeFamily = pride::De<pride::de::SelectableMutation, pride::de::SelectableControl, pride::de::SelectableRepair,
                           pride::de::SelectableSize, pride::de::SelectableReduction>;
inline DeFamily de_family(const std::string& id, std::int64_t population) {
    DeFamily a;
    a.id = id;
    a.population = population;
    if (id == "jade") {
        a.mutation = pride::de::CurrentToPBest<pride::de::FixedRate>{{0.05}};
        a.control = pride::de::JadeControl{};
        a.archive.rate = 1.0;
        a.archive.trim_after_generation = true;
        a.ties_replace = false;
    } else if (id == "lshade") {
        a.mutation = pride::de::CurrentToPBest<pride::de::FixedRate>{{0.11}};
        a.control = pride::de::LshadeControl{};
        a.archive = {2.6, true, false, true};
        a.reduction = pride::de::LinearReduction{};
    } else if (id == "jso") {
        a.mutation = pride::de::CurrentToPBest<pride::de::LinearRate>{{}, 0.5};
        a.control = pride::de::JsoControl{};
        a.archive.rate = 1.0;
        a.reduction = pride::de::LinearReduction{};
    }
    return a;
}

/// Calls `f(label, algorithm)` for every algorithm of the suite, with the given population.
template <class F>
void for_each_algorithm(std::int64_t population, F&& f) {
    f("pso", pso(population));
    f("pso-constriction", pso_constriction(population));
    f("ga", ga(population));
    f("ga-plus", ga_plus(population));
    // The GA variants of Zhang et al. (2025) (algorithms/parts/ga/adaptive_rates.hpp, catastrophe.hpp,
    // q_learning.hpp; tests/test_ga_variants.cpp): the catastrophe every 2 generations here.
    pride::Ga<pride::TournamentSelection, pride::AdaptiveSbxCrossover, pride::AdaptivePolynomialMutation> iaga;
    iaga.id = "iaga";
    iaga.population = population;
    f("iaga", iaga);
    pride::Ga<pride::TournamentSelection, pride::SbxCrossover, pride::PolynomialMutation, pride::Clamp,
              pride::UniformInit, pride::ElitistReplacement, pride::CatastropheHook>
        icga;
    icga.id = "icga";
    icga.population = population;
    icga.hook.k = 2;
    f("icga", icga);
    pride::Ga<pride::TournamentSelection, pride::SbxCrossover,
              pride::QLearningMutation<pride::PolynomialMutation, pride::UniformMutation, pride::GaussianMutation>>
        ga_q;
    ga_q.id = "ga-q";
    ga_q.population = population;
    f("ga-q", ga_q);
    pride::LsoAlgorithm lso;
    lso.population = population;
    f("lso", lso);
    auto ilso = pride::make_ilso();
    ilso.population = population;
    f("ilso", ilso);
    f("nlopt:LN_SBPLX", pride::Nlopt("LN_SBPLX", population));
    f("nlopt:GN_CRS2_LM", pride::Nlopt("GN_CRS2_LM", population));
    for (const char* id : {"de", "jade", "lshade", "jso"}) f(id, de_family(id, population));
}

}  // namespace algorithms_test

using namespace algorithms_test;

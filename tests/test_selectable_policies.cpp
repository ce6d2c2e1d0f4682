// Tests of the "one instantiation per family" types: a skeleton whose varying policy is a OneOf
// (framework/one_of.hpp) chosen at run time must give, bit for bit, the result of the skeleton
// instantiated with the policy it holds (best_f, best_x, history, evaluations):
//   - Pso<SelectableVelocity, ...> holding the inertia-weight or the constriction rule;
//   - Ga<..., SelectableInit, SelectableReplacement> holding the elitist or the plus replacement,
//     on a continuous function and on chains (a bundled map), and validated as the fixed types
//     are (elitism against the population);
//   - Lso<SelectableWeight, ...> holding UnitWeight (LSO) or QuadraticInertia with cub threshold
//     0.3 (ILSO), on continuous functions and, with the problem's rule walks, on a grid.
#include <catch2/catch.hpp>

#include <bit>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "algorithms/ga.hpp"
#include "algorithms/lso.hpp"
#include "algorithms/pso.hpp"
#include "framework/encoding.hpp"
#include "framework/error.hpp"
#include "framework/termination.hpp"
#include "problems/continuous/functions.hpp"
#include "problems/grid/chain.hpp"
#include "problems/grid/encodings.hpp"
#include "problems/grid/map_io.hpp"
#include "problems/grid/objectives.hpp"
#include "tests/test_support.hpp"

namespace {

using namespace pride;

bool same_bits(double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

template <class R>
void require_same_result(const R& a, const R& b) {
    REQUIRE(same_bits(a.best_f, b.best_f));
    REQUIRE(a.best_x.size() == b.best_x.size());
    if constexpr (std::is_same_v<R, Result>) {
        for (std::size_t i = 0; i < a.best_x.size(); ++i) REQUIRE(same_bits(a.best_x[i], b.best_x[i]));
    } else {
        REQUIRE(a.best_x == b.best_x);
    }
    REQUIRE(a.evaluations == b.evaluations);
    REQUIRE(a.iterations == b.iterations);
    REQUIRE(a.history.size() == b.history.size());
    for (std::size_t k = 0; k < a.history.size(); ++k) REQUIRE(same_bits(a.history[k], b.history[k]));
    REQUIRE(a.history_evaluations == b.history_evaluations);
}

/// Runs both on every problem, limit and seed and requires the same result.
template <class A, class B, class... Problems>
void require_same_runs(const A& selectable, const B& fixed, const Problems&... problems) {
    const std::vector<Termination> limits{max_evaluations(3001), max_iterations(30),
                                          max_evaluations(777) | max_iterations(12)};
    auto one = [&](const auto& problem) {
        for (const auto& limit : limits)
            for (const std::uint64_t seed : {1u, 7u}) {
                INFO("seed " << seed);
                require_same_result(selectable.run(problem, limit, seed), fixed.run(problem, limit, seed));
            }
    };
    (one(problems), ...);
}

const continuous::Rastrigin rastrigin(10);
const continuous::Rosenbrock rosenbrock(6);

std::filesystem::path bundled_map(const std::string& name) {
    return std::filesystem::path(PRIDE_SOURCE_DIR) / "examples" / "maps" / name;
}

grid::GridProblem<grid::CellsObjective> bundled_grid(const std::string& name) {
    auto map = std::make_shared<const grid::GridMap>(grid::read_map(bundled_map(name + ".map").string()));
    const auto scen = grid::read_scenario(bundled_map(name + ".map.scen").string());
    REQUIRE(scen.size() == 1);
    return grid::GridProblem<grid::CellsObjective>(map, scen[0].start, scen[0].goal);
}

using OnePso = Pso<SelectableVelocity, RangeVelocityClamp, Clamp, SelectableInit>;
using OneGa = Ga<TournamentSelection, SbxCrossover, PolynomialMutation, Clamp, SelectableInit, SelectableReplacement>;
using OneChainGa = Ga<TournamentSelection, ChainCrossover, ChainMutation, Clamp, UniformInit, SelectableReplacement>;
using OneLso = Lso<SelectableWeight, LsoCubs, Clamp, SelectableInit>;

}  // namespace

TEST_CASE("selectable policies: one PSO instantiation is pso and pso-constriction", "[selectable][pso]") {
    SECTION("inertia weight") {
        InertiaVelocity<LinearInertia> rule;
        rule.inertia.start = 0.85;
        rule.c2 = 1.9;
        OnePso one;
        one.population = 20;
        one.velocity = rule;
        Pso<InertiaVelocity<LinearInertia>, RangeVelocityClamp, Clamp, SelectableInit> fixed;
        fixed.population = 20;
        fixed.velocity = rule;
        REQUIRE(one.velocity.holds<InertiaVelocity<LinearInertia>>());
        require_same_runs(one, fixed, rastrigin, rosenbrock);
    }
    SECTION("constriction") {
        ConstrictionVelocity rule;
        rule.c = 2.0;
        OnePso one;
        one.id = "pso-constriction";
        one.population = 20;
        one.velocity = rule;
        one.velocity_clamp.fraction = 0.3;
        Pso<ConstrictionVelocity, RangeVelocityClamp, Clamp, SelectableInit> fixed;
        fixed.population = 20;
        fixed.velocity = rule;
        fixed.velocity_clamp.fraction = 0.3;
        require_same_runs(one, fixed, rastrigin, rosenbrock);
    }
    SECTION("validation goes to the policy held") {
        OnePso one;
        ConstrictionVelocity bad;
        bad.chi = 1.5;
        one.velocity = bad;
        Pso<ConstrictionVelocity> fixed;
        fixed.velocity = bad;
        REQUIRE(test::input_error_message([&] { one.validate(); }) ==
                test::input_error_message([&] { fixed.validate(); }));
    }
}

TEST_CASE("selectable policies: one GA instantiation is ga and ga-plus", "[selectable][ga]") {
    SECTION("elitist") {
        OneGa one;
        one.population = 16;
        one.replacement = ElitistReplacement{3};
        Ga<TournamentSelection, SbxCrossover, PolynomialMutation, Clamp, SelectableInit> fixed;
        fixed.population = 16;
        fixed.replacement.elitism = 3;
        REQUIRE(one.replacement.offspring(16) == 13);
        require_same_runs(one, fixed, rastrigin, rosenbrock);
    }
    SECTION("plus") {
        OneGa one;
        one.id = "ga-plus";
        one.population = 16;
        one.replacement = PlusReplacement{};
        one.mutation.eta = 12.0;
        Ga<TournamentSelection, SbxCrossover, PolynomialMutation, Clamp, SelectableInit, PlusReplacement> fixed;
        fixed.population = 16;
        fixed.mutation.eta = 12.0;
        REQUIRE(one.replacement.offspring(16) == 16);
        require_same_runs(one, fixed, rastrigin, rosenbrock);
    }
    SECTION("elitism is validated against the population through the selectable replacement") {
        OneGa one;
        one.population = 5;
        one.replacement = ElitistReplacement{5};
        Ga<> fixed;
        fixed.population = 5;
        fixed.replacement.elitism = 5;
        const auto message = test::input_error_message([&] { one.validate(); });
        REQUIRE(message == test::input_error_message([&] { fixed.validate(); }));
        REQUIRE(message.find("elitism must be in [0, population)") != std::string::npos);
        REQUIRE_THROWS_AS(one.run(rastrigin, max_evaluations(100), 1), InputError);
        one.replacement = ElitistReplacement{4};
        REQUIRE_NOTHROW(one.validate());
        one.replacement = PlusReplacement{};  // no elitism to check
        REQUIRE_NOTHROW(one.validate());
    }
}

TEST_CASE("selectable policies: one chain GA instantiation is ga and ga-plus on chains", "[selectable][ga][chain]") {
    const grid::ChainSpace<grid::CellsObjective> space(bundled_grid("zhang2025-20x20"));
    SECTION("elitist") {
        OneChainGa one;
        one.population = 12;
        one.replacement = ElitistReplacement{2};
        ChainGa fixed;
        fixed.population = 12;
        fixed.replacement.elitism = 2;
        require_same_runs(one, fixed, space);
    }
    SECTION("plus") {
        OneChainGa one;
        one.population = 12;
        one.replacement = PlusReplacement{};
        one.mutation.probability = 0.3;
        Ga<TournamentSelection, ChainCrossover, ChainMutation, Clamp, UniformInit, PlusReplacement> fixed;
        fixed.population = 12;
        fixed.mutation.probability = 0.3;
        require_same_runs(one, fixed, space);
    }
}

TEST_CASE("selectable policies: one LSO instantiation is lso and ilso", "[selectable][lso]") {
    SECTION("lso") {
        OneLso one;
        one.weight = UnitWeight{};
        Lso<UnitWeight, LsoCubs, Clamp, SelectableInit> fixed;
        require_same_runs(one, fixed, rastrigin, rosenbrock);
        one.gamma_per_coordinate = fixed.gamma_per_coordinate = true;
        one.step_factor = fixed.step_factor = 0.1;
        require_same_runs(one, fixed, rastrigin);
    }
    SECTION("ilso") {
        OneLso one;
        one.id = "ilso";
        one.weight = QuadraticInertia{};
        one.cubs.first = 0.3;
        auto fixed = make_ilso<Clamp, SelectableInit>();
        require_same_runs(one, fixed, rastrigin, rosenbrock);
        // On a grid, with the problem's starting points (rough-set rule walks).
        const auto problem = bundled_grid("wan2022-13x13");
        const Encoded<grid::GridProblem<grid::CellsObjective>, grid::LineEncoding<>> line(
            problem, grid::LineEncoding<>(problem));
        one.init.suggestions = fixed.init.suggestions = true;
        require_same_runs(one, fixed, line);
    }
}

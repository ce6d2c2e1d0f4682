// Tests of the GA's generation context and per-generation hook (algorithms/parts/
// generation_context.hpp, generation_hook.hpp):
//   - operator policies that take the context get it, and what they see agrees with the population
//     (best <= mean <= worst, the population's own minimum, mean and maximum, the pair being varied,
//     which child is mutated), while their draws and so the run stay bit for bit the plain run's;
//   - the hook is called once per generation after replacement: iterations 1, 2, ..., best so far
//     equal to the run's history, stagnation counted as the history says, the horizon as
//     Termination::horizon says, unevaluated children as +inf;
//   - a catastrophe hook (ICGA's kind) that renews all but the best through renew() keeps the
//     budget exact and the fitness true, on points and on chains, and the next generation's
//     context describes the renewed population (stagnation restarting on the hook's improvements);
//   - OneOf alternatives are asked one by one; a hook's validate() is part of the GA's.
#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <memory>
#include <numeric>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "algorithms/ga.hpp"
#include "algorithms/parts/ga/generation_context.hpp"
#include "algorithms/parts/ga/generation_hook.hpp"
#include "framework/error.hpp"
#include "framework/one_of.hpp"
#include "framework/termination.hpp"
#include "problems/continuous/functions.hpp"
#include "problems/grid/chain.hpp"
#include "problems/grid/map_io.hpp"
#include "problems/grid/objectives.hpp"

namespace {

using pride::GenerationContext;
constexpr double inf = std::numeric_limits<double>::infinity();

bool same_bits(double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

template <class R>
void require_same_run(const R& a, const R& b) {
    REQUIRE(same_bits(a.best_f, b.best_f));
    REQUIRE(a.best_x == b.best_x);
    REQUIRE(a.evaluations == b.evaluations);
    REQUIRE(a.iterations == b.iterations);
    REQUIRE(a.history.size() == b.history.size());
    for (std::size_t k = 0; k < a.history.size(); ++k) REQUIRE(same_bits(a.history[k], b.history[k]));
    REQUIRE(a.history_evaluations == b.history_evaluations);
}

/// The checks every context must pass against the population it describes.
void check_describes(const GenerationContext& c, std::span<const double> fitness) {
    REQUIRE(c.fitness.data() == fitness.data());
    REQUIRE(c.fitness.size() == fitness.size());
    REQUIRE(c.best <= c.mean);
    REQUIRE(c.mean <= c.worst);
    REQUIRE(c.best == *std::min_element(fitness.begin(), fitness.end()));
    REQUIRE(c.worst == *std::max_element(fitness.begin(), fitness.end()));
    if (std::isfinite(c.worst)) {
        const double mean = std::accumulate(fitness.begin(), fitness.end(), 0.0) / static_cast<double>(fitness.size());
        REQUIRE(c.mean == Approx(mean).epsilon(1e-12));
    } else {
        REQUIRE(c.mean == inf);  // a member not evaluated counts as +inf
    }
    REQUIRE(same_bits(c.best_so_far, c.best));  // elitist replacements keep the best ever
}

/// What the context-reading policies saw, shared between the copies the GA holds.
struct Seen {
    std::vector<GenerationContext> in_selection;  // one per generation: the first call's
    std::vector<GenerationContext> in_hook;
    std::vector<std::vector<double>> hook_fitness;
    std::vector<std::size_t> selected;  // every selection's result, in order
    std::int64_t crossings = 0, mutations = 0, replacements = 0;
};

/// Tournament selection that reads the context and checks it against the fitness it is given.
struct CheckingSelection {
    pride::TournamentSelection inner{};
    std::shared_ptr<Seen> seen = std::make_shared<Seen>();
    std::size_t operator()(std::span<const double> fitness, pride::Rng& rng, const GenerationContext& c) const {
        check_describes(c, fitness);
        if (seen->in_selection.empty() || seen->in_selection.back().iteration != c.iteration)
            seen->in_selection.push_back(c);
        const std::size_t chosen = inner(fitness, rng);
        seen->selected.push_back(chosen);
        return chosen;
    }
    void validate(const std::string& where) const { inner.validate(where); }
};

/// SBX and polynomial mutation that check the pair and the child the context names.
struct CheckingSbx {
    pride::SbxCrossover inner{};
    std::shared_ptr<Seen> seen;
    void operator()(std::span<double> a, std::span<double> b, std::span<const double> lo, std::span<const double> hi,
                    pride::Rng& rng, const GenerationContext& c) const {
        const auto& s = seen->selected;
        REQUIRE(s.size() >= 2);
        REQUIRE(c.parents[0] == s[s.size() - 2]);  // the pair just selected, in order
        REQUIRE(c.parents[1] == s[s.size() - 1]);
        REQUIRE(c.parents[0] < c.fitness.size());
        ++seen->crossings;
        inner(a, b, lo, hi, rng);  // prepares per call: the same constants, the same draws
    }
    void validate(const std::string& where) const { inner.validate(where); }
};
struct CheckingMutation {
    pride::PolynomialMutation inner{};
    std::shared_ptr<Seen> seen;
    void operator()(std::span<double> x, std::span<const double> lo, std::span<const double> hi, pride::Rng& rng,
                    const GenerationContext& c) const {
        REQUIRE(c.child == static_cast<std::size_t>(seen->mutations % 2));  // child 0, then child 1
        ++seen->mutations;
        inner(x, lo, hi, rng);  // pm = 1/D from x.size(), as prepare(D) gives
    }
    void validate(const std::string& where) const { inner.validate(where); }
};
/// The elitist replacement, told the context of the parents it chooses among.
struct CheckingReplacement : pride::ElitistReplacement {
    std::shared_ptr<Seen> seen;
    void operator()(std::span<const double> fp, std::span<const double> fc, std::span<std::size_t> chosen,
                    pride::ReplacementScratch& scratch, const GenerationContext& c) const {
        check_describes(c, fp);
        ++seen->replacements;
        ElitistReplacement::operator()(fp, fc, chosen, scratch);
    }
};

/// Records the context and the population's fitness at every call.
struct RecordingHook {
    std::shared_ptr<Seen> seen = std::make_shared<Seen>();
    template <class Population>
    void operator()(const GenerationContext& c, Population& population, pride::Rng&) const {
        check_describes(c, population.fitness());
        seen->in_hook.push_back(c);
        seen->hook_fitness.emplace_back(population.fitness().begin(), population.fitness().end());
    }
};

/// The history says when the best improved: the stagnation count must agree, generation by generation.
template <class R>
void check_hook_against_history(const Seen& seen, const R& r) {
    REQUIRE(seen.in_hook.size() == static_cast<std::size_t>(r.iterations));
    std::int64_t expected_stagnation = 0;
    for (std::size_t k = 0; k < seen.in_hook.size(); ++k) {
        const auto& c = seen.in_hook[k];
        const std::size_t t = k + 1;  // the hook after generation t - 1 reports t completed
        REQUIRE(c.iteration == static_cast<std::int64_t>(t));
        REQUIRE(same_bits(c.best_so_far, r.history[t]));
        expected_stagnation = r.history[t] < r.history[t - 1] ? 0 : expected_stagnation + 1;
        REQUIRE(c.stagnation == expected_stagnation);
    }
}

using Rastrigin = pride::continuous::Rastrigin;

}  // namespace

TEST_CASE("GA context: operators that take it see the population it describes, and change no bit", "[ga][context]") {
    auto seen = std::make_shared<Seen>();
    pride::Ga<CheckingSelection, CheckingSbx, CheckingMutation, pride::Clamp, pride::UniformInit, CheckingReplacement>
        checked;
    checked.population = 12;
    checked.selection.seen = seen;
    checked.crossover.seen = seen;
    checked.mutation.seen = seen;
    checked.replacement.seen = seen;
    checked.replacement.elitism = 2;
    pride::Ga<> plain;
    plain.population = 12;
    plain.replacement.elitism = 2;

    const Rastrigin problem(6);
    const auto termination = pride::max_iterations(40);
    const auto a = checked.run(problem, termination, 11);
    const auto b = plain.run(problem, termination, 11);
    require_same_run(a, b);

    // One context per generation, iterations 0..T-1, the horizon the iteration limit.
    REQUIRE(seen->in_selection.size() == 40);
    for (std::size_t t = 0; t < seen->in_selection.size(); ++t) {
        const auto& c = seen->in_selection[t];
        REQUIRE(c.iteration == static_cast<std::int64_t>(t));
        REQUIRE(c.horizon == std::optional<std::int64_t>(40));
        REQUIRE(same_bits(c.best_so_far, a.history[t]));  // the best after the generations completed
    }
    REQUIRE(seen->in_selection.front().stagnation == 0);
    // 10 children a generation: 5 pairs, 10 mutations, one replacement.
    REQUIRE(seen->crossings == 40 * 5);
    REQUIRE(seen->mutations == 40 * 10);
    REQUIRE(seen->replacements == 40);
}

TEST_CASE("GA hook: once per generation after replacement, with best so far and stagnation as the history says",
          "[ga][context][hook]") {
    for (const std::uint64_t seed : {1u, 2u, 3u}) {
        INFO("seed " << seed);
        pride::Ga<pride::TournamentSelection, pride::SbxCrossover, pride::PolynomialMutation, pride::Clamp,
                  pride::UniformInit, pride::ElitistReplacement, RecordingHook>
            hooked;
        hooked.population = 10;
        pride::Ga<> plain;
        plain.population = 10;
        const Rastrigin problem(4);
        // 10 + 9 per generation: the budget ends inside generation 23.
        const auto termination = pride::max_evaluations(10 + 9 * 22 + 4);
        std::vector<std::vector<double>> observed;
        const auto a = hooked.run(problem, termination, seed, [&](const pride::IterationView& v) {
            observed.emplace_back(v.fitness.begin(), v.fitness.end());
        });
        require_same_run(a, plain.run(problem, termination, seed));

        const Seen& seen = *hooked.hook.seen;
        check_hook_against_history(seen, a);
        // The hook sees the population the generation then records.
        REQUIRE(observed.size() == seen.hook_fitness.size() + 1);
        for (std::size_t k = 0; k < seen.hook_fitness.size(); ++k) REQUIRE(seen.hook_fitness[k] == observed[k + 1]);
        for (const auto& c : seen.in_hook) REQUIRE(c.horizon == termination.horizon(10, 9));
        REQUIRE(*seen.in_hook.front().horizon == 23);
        // A long enough run both improves and stalls.
        const auto stalled = std::count_if(seen.in_hook.begin(), seen.in_hook.end(),
                                           [](const GenerationContext& c) { return c.stagnation > 0; });
        REQUIRE(stalled > 0);
        REQUIRE(stalled < static_cast<std::ptrdiff_t>(seen.in_hook.size()));
        // The last generation ran out of budget: 5 of its 9 children were not evaluated.
        const auto& last = seen.in_hook.back();
        REQUIRE(std::isfinite(last.best));
        REQUIRE(last.worst == inf);
        REQUIRE(last.mean == inf);
    }
}

TEST_CASE("GA context: mean stays within [best, worst] when rounding would push it out", "[ga][context]") {
    GenerationContext c;
    const std::vector<double> same(3, 0.1);  // 0.1 + 0.1 + 0.1 = 0.30000000000000004, / 3 > 0.1
    c.describe(0, same, 0.1);
    REQUIRE(c.best == 0.1);
    REQUIRE(c.mean == 0.1);
    REQUIRE(c.worst == 0.1);
    // Stagnation: restarts on improvement, grows otherwise, 0 for the initial population.
    c.describe(1, same, 0.1);
    REQUIRE(c.stagnation == 1);
    c.describe(2, same, 0.1);
    REQUIRE(c.stagnation == 2);
    c.describe(2, same, 0.1);  // the same generation again (after a hook): no new generation
    REQUIRE(c.stagnation == 2);
    c.describe(2, same, 0.08);  // ... but one whose hook improved the best
    REQUIRE(c.stagnation == 0);
    c.describe(3, same, 0.08);
    REQUIRE(c.stagnation == 1);
    c.describe(4, same, 0.05);
    REQUIRE(c.stagnation == 0);
    c.describe(0, same, 0.05);
    REQUIRE(c.stagnation == 0);
}

namespace {

/// ICGA's kind of catastrophe: after every `k` generations without improvement, every member but
/// the best is renewed. Checks what renew() leaves behind: the values are the members' own.
struct Catastrophe {
    std::int64_t k = 3;
    std::shared_ptr<std::int64_t> catastrophes = std::make_shared<std::int64_t>(0);
    template <class Population>
    void operator()(const GenerationContext& c, Population& population, pride::Rng& rng) const {
        if (c.stagnation == 0 || c.stagnation % k != 0) return;
        const auto f = population.fitness();
        const auto best = static_cast<std::size_t>(std::min_element(f.begin(), f.end()) - f.begin());
        std::vector<std::size_t> others;
        for (std::size_t i = 0; i < population.size(); ++i)
            if (i != best) others.push_back(i);
        population.renew(others, rng);
        ++*catastrophes;
    }
    void validate(const std::string& where) const {
        pride::require(k >= 1, where, "catastrophe period must be >= 1, got " + std::to_string(k));
    }
};

/// A box problem that counts its evaluations and lets the test evaluate a member again.
struct CountedRastrigin {
    Rastrigin f{5};
    std::shared_ptr<std::int64_t> count = std::make_shared<std::int64_t>(0);
    std::size_t dimension() const { return f.dimension(); }
    std::span<const double> lower() const { return f.lower(); }
    std::span<const double> upper() const { return f.upper(); }
    double evaluate(std::span<const double> x) {
        ++*count;
        return f.evaluate(x);
    }
};

/// Checks, after the hook, that each member's fitness is its own value.
template <class Problem>
struct TruthfulFitness {
    Problem problem;  // a copy: evaluations here are not the run's
    template <class Population>
    void check(Population& population) {
        for (std::size_t i = 0; i < population.size(); ++i) {
            const double f = population.fitness()[i];
            if (std::isfinite(f)) REQUIRE(same_bits(f, problem.evaluate(population.individual(i))));
        }
    }
};

template <class Hook, class Check>
struct Then {
    Hook hook;
    std::shared_ptr<Check> check;
    template <class Population>
    void operator()(const GenerationContext& c, Population& population, pride::Rng& rng) const {
        hook(c, population, rng);
        check->check(population);
    }
    void validate(const std::string& where) const { hook.validate(where); }
};

std::filesystem::path bundled_map(const std::string& name) {
    return std::filesystem::path(PRIDE_SOURCE_DIR) / "examples" / "maps" / name;
}

}  // namespace

TEST_CASE("GA hook: a catastrophe through renew() keeps the budget exact and the fitness true (points)",
          "[ga][context][hook]") {
    using Hook = Then<Catastrophe, TruthfulFitness<Rastrigin>>;
    // The selection checks that each generation's context describes the population as the
    // catastrophe left it.
    pride::Ga<CheckingSelection, pride::SbxCrossover, pride::PolynomialMutation, pride::Clamp, pride::UniformInit,
              pride::ElitistReplacement, Hook>
        ga;
    ga.population = 8;
    ga.hook.check = std::make_shared<TruthfulFitness<Rastrigin>>(TruthfulFitness<Rastrigin>{Rastrigin(5)});
    for (const std::int64_t budget : {std::int64_t{50}, std::int64_t{997}, std::int64_t{3000}}) {
        INFO("budget " << budget);
        *ga.hook.hook.catastrophes = 0;
        CountedRastrigin problem;
        const auto r = ga.run(problem, pride::max_evaluations(budget), 5);
        CHECK(*problem.count == budget);
        CHECK(r.evaluations == budget);
        CHECK(r.history_evaluations.back() == budget);
        for (std::size_t k = 1; k < r.history.size(); ++k) CHECK(r.history[k] <= r.history[k - 1]);
        if (budget == 3000) CHECK(*ga.hook.hook.catastrophes > 0);
        // Stagnation as the history says, catastrophes' improvements included.
        const auto& contexts = ga.selection.seen->in_selection;
        REQUIRE(contexts.size() == static_cast<std::size_t>(r.iterations));  // one per generation
        std::int64_t expected = 0;
        for (std::size_t t = 1; t < contexts.size(); ++t) {
            expected = r.history[t] < r.history[t - 1] ? 0 : expected + 1;
            REQUIRE(contexts[t].stagnation == expected);
            REQUIRE(same_bits(contexts[t].best_so_far, r.history[t]));
        }
        ga.selection.seen->in_selection.clear();
        // Reproducible, catastrophes included.
        const auto again = ga.run(CountedRastrigin{}, pride::max_evaluations(budget), 5);
        require_same_run(r, again);
        ga.selection.seen->in_selection.clear();
    }
    ga.hook.hook.k = 0;
    REQUIRE_THROWS_AS(ga.validate(), pride::InputError);
}

TEST_CASE("GA hook: the same hooks run on chains", "[ga][context][hook][chain]") {
    using namespace pride::grid;
    auto map = std::make_shared<const GridMap>(read_map(bundled_map("zhang2025-20x20.map").string()));
    const auto scen = read_scenario(bundled_map("zhang2025-20x20.map.scen").string());
    REQUIRE(scen.size() == 1);
    const ChainSpace<CellsObjective> space(GridProblem<CellsObjective>(map, scen[0].start, scen[0].goal));

    pride::Ga<pride::TournamentSelection, pride::ChainCrossover, pride::ChainMutation, pride::Clamp, pride::UniformInit,
              pride::ElitistReplacement, RecordingHook>
        recorded;
    recorded.population = 10;
    const auto a = recorded.run(space, pride::max_iterations(30), 4);
    pride::ChainGa plain;
    plain.population = 10;
    require_same_run(a, plain.run(space, pride::max_iterations(30), 4));
    check_hook_against_history(*recorded.hook.seen, a);

    using Hook = Then<Catastrophe, TruthfulFitness<ChainSpace<CellsObjective>>>;
    pride::Ga<pride::TournamentSelection, pride::ChainCrossover, pride::ChainMutation, pride::Clamp, pride::UniformInit,
              pride::ElitistReplacement, Hook>
        catastrophic;
    catastrophic.population = 10;
    catastrophic.hook.hook.k = 2;
    catastrophic.hook.check = std::make_shared<TruthfulFitness<ChainSpace<CellsObjective>>>(
        TruthfulFitness<ChainSpace<CellsObjective>>{space});
    const auto r = catastrophic.run(space, pride::max_evaluations(600), 4);
    CHECK(r.evaluations == 600);
    CHECK(*catastrophic.hook.hook.catastrophes > 0);
    CHECK(std::isfinite(r.best_f));
    CHECK(same_bits(r.best_f, space.evaluate(r.best_x)));
}

TEST_CASE("GA context: a OneOf policy asks its alternative whether it takes the context", "[ga][context]") {
    using Selection = pride::OneOf<pride::TournamentSelection, CheckingSelection>;
    pride::Ga<Selection> ga;
    ga.population = 10;
    pride::Ga<> plain;
    plain.population = 10;
    const Rastrigin problem(3);
    const auto termination = pride::max_iterations(25);
    const auto expected = plain.run(problem, termination, 8);

    require_same_run(ga.run(problem, termination, 8), expected);  // the tournament, no context
    CheckingSelection checking;
    ga.selection = checking;
    require_same_run(ga.run(problem, termination, 8), expected);  // the checking one, with it
    REQUIRE(checking.seen->in_selection.size() == 25);
}

// Tests of the GA variants as policies (algorithms/parts/ga/adaptive_rates.hpp, catastrophe.hpp,
// q_learning.hpp) and their registry entries iaga, icga, ga-q (engine/entries/ga_entries.cpp):
//   - IAGA: Srinivas and Patnaik's probabilities at their end points (the best, the mean, below the
//     mean), worked by hand, from the GenerationContext of a pair and of a child; with every k = 0
//     nothing varies;
//   - ICGA: the catastrophe keeps the elite and re-seeds exactly the others, after exactly k
//     generations without improvement, on points and on chains;
//   - Q-learning: eq. 19 worked by hand, a generation-by-generation sequence, epsilon-greedy and
//     roulette frequencies, the orderings of (0.6, 0.2, 0.2); the mutation policy over box and
//     chain operators;
//   - every variant: the same seed gives the same bits; exact budgets counted on the problem's
//     side; box bounds kept and chains legal in every population.
#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <set>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/ga.hpp"
#include "engine/registry.hpp"
#include "engine/run.hpp"
#include "engine/specs.hpp"
#include "framework/error.hpp"
#include "framework/termination.hpp"
#include "problems/continuous/functions.hpp"
#include "problems/grid/chain.hpp"
#include "problems/grid/map_io.hpp"
#include "problems/grid/objectives.hpp"
#include "problems/grid/path.hpp"
#include "tests/counting_space.hpp"

namespace {

using namespace pride;
constexpr double inf = std::numeric_limits<double>::infinity();

bool same_bits(double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

template <class R>
void require_same_run(const R& a, const R& b) {
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

using IagaBox = Ga<TournamentSelection, AdaptiveSbxCrossover, AdaptivePolynomialMutation>;
using IagaChain = Ga<TournamentSelection, AdaptiveChainCrossover, AdaptiveChainMutation>;
using IcgaBox =
    Ga<TournamentSelection, SbxCrossover, PolynomialMutation, Clamp, UniformInit, ElitistReplacement, CatastropheHook>;
using IcgaChain =
    Ga<TournamentSelection, ChainCrossover, ChainMutation, Clamp, UniformInit, ElitistReplacement, CatastropheHook>;
using BoxQMutation = QLearningMutation<PolynomialMutation, UniformMutation, GaussianMutation>;
using GaQBox = Ga<TournamentSelection, SbxCrossover, BoxQMutation>;
using GaQChain = Ga<TournamentSelection, ChainCrossover, QLearningMutation<ChainMutation, ChainMutation>>;

using Chains = grid::ChainSpace<grid::CellsObjective>;

std::filesystem::path bundled_map(const std::string& name) {
    return std::filesystem::path(PRIDE_SOURCE_DIR) / "examples" / "maps" / name;
}

grid::GridProblem<grid::CellsObjective> bundled_grid() {
    auto map = std::make_shared<const grid::GridMap>(grid::read_map(bundled_map("zhang2025-20x20.map").string()));
    const auto scen = grid::read_scenario(bundled_map("zhang2025-20x20.map.scen").string());
    REQUIRE(scen.size() == 1);
    return grid::GridProblem<grid::CellsObjective>(map, scen[0].start, scen[0].goal);
}

/// A box problem that counts its evaluations outside itself (runs copy the problem).
struct CountedRastrigin {
    continuous::Rastrigin f{5};
    std::shared_ptr<std::int64_t> count = std::make_shared<std::int64_t>(0);
    std::size_t dimension() const { return f.dimension(); }
    std::span<const double> lower() const { return f.lower(); }
    std::span<const double> upper() const { return f.upper(); }
    double evaluate(std::span<const double> x) {
        ++*count;
        return f.evaluate(x);
    }
};

/// The chain space, counting every call of its objective (tests/counting_space.hpp).
using CountingChains = test::CountingSpace<Chains>;

bool is_simple(const grid::Path& p) {
    std::set<std::pair<int, int>> seen;
    for (const grid::Cell& c : p)
        if (!seen.insert({c.x, c.y}).second) return false;
    return true;
}

/// Counts the members of every population a box run shows that leave the box.
struct BoxChecker {
    std::vector<double> lo, hi;
    std::shared_ptr<std::int64_t> bad = std::make_shared<std::int64_t>(0);
    void operator()(const IterationView& v) const {
        for (Eigen::Index j = 0; j < v.population.cols(); ++j)
            for (Eigen::Index i = 0; i < v.population.rows(); ++i) {
                const double x = v.population(i, j);
                const auto d = static_cast<std::size_t>(i);
                if (!(x >= lo[d] && x <= hi[d])) ++*bad;
            }
    }
};

/// Counts the members of every population a chain run shows that are not legal simple paths, or
/// whose fitness is not their value.
struct ChainChecker {
    grid::GridProblem<grid::CellsObjective> problem;
    std::shared_ptr<std::int64_t> bad = std::make_shared<std::int64_t>(0);
    std::shared_ptr<std::int64_t> seen = std::make_shared<std::int64_t>(0);
    template <class View>
    void operator()(const View& view) const {
        const std::vector<grid::Path>& pop = view.population;
        for (std::size_t i = 0; i < pop.size(); ++i) {
            ++*seen;
            if (!grid::path_violation(problem.map(), pop[i], problem.start(), problem.goal()).empty() ||
                !is_simple(pop[i]))
                ++*bad;
            if (std::isfinite(view.fitness[i]) && view.fitness[i] != problem.evaluate(pop[i])) ++*bad;
        }
    }
};

}  // namespace

// ---------------------------------------------------------------------------------------------
// IAGA

TEST_CASE("IAGA: Srinivas-Patnaik probabilities at their end points, by hand", "[ga-variants][iaga]") {
    // Minimisation: best = 2, mean = 6. k1 = 0.8, k3 = 0.6 to tell the branches apart.
    const AdaptiveProbability pc{0.8, 0.6};
    CHECK(pc(2.0, 2.0, 6.0) == 0.0);                         // g = best: k1 * 0 (the best is kept as it is)
    CHECK(pc(6.0, 2.0, 6.0) == 0.8);                         // g = mean: k1 * 1
    CHECK(pc(4.0, 2.0, 6.0) == Approx(0.4).epsilon(1e-15));  // halfway: k1 / 2
    CHECK(pc(6.5, 2.0, 6.0) == 0.6);                         // worse than the mean: k3
    // The authors' constants: k2 = k4 = 0.5 for pm, k1 = k3 = 1 for pc, pm never below 0.005.
    const auto pm = kSrinivasPatnaikMutation;
    CHECK(pm(2.0, 2.0, 6.0) == 0.005);                          // the best: the floor, not 0
    CHECK(pm(2.02, 2.0, 6.0) == Approx(0.005).epsilon(1e-12));  // 0.5 * 0.005 = 0.0025 < 0.005
    CHECK(pm(2.4, 2.0, 6.0) == Approx(0.05).epsilon(1e-12));    // 0.5 * 0.1, above the floor
    CHECK(pm(6.0, 2.0, 6.0) == 0.5);
    CHECK(pm(5.0, 2.0, 6.0) == 0.375);  // 0.5 * 3/4
    CHECK(pm(100.0, 2.0, 6.0) == 0.5);
    CHECK(kSrinivasPatnaikCrossover(4.0, 2.0, 6.0) == 0.5);
    CHECK(kSrinivasPatnaikCrossover(7.0, 2.0, 6.0) == 1.0);
    // Degenerate populations.
    CHECK(pc(3.0, 3.0, 3.0) == 0.0);  // all equal to the best
    CHECK(pc(inf, 2.0, inf) == 0.6);  // a member at +inf is below average
    CHECK(pc(5.0, 2.0, inf) == 0.0);  // a mean of +inf scales finite members to 0
    CHECK_FALSE(AdaptiveProbability::scale(6.5, 2.0, 6.0).has_value());
    CHECK(*AdaptiveProbability::scale(6.0, 2.0, 6.0) == 1.0);

    // From a generation's context: fitness 2, 4, 6, 8 (best 2, mean 5).
    const std::vector<double> f{2.0, 4.0, 6.0, 8.0};
    GenerationContext c;
    c.describe(0, f, 2.0);
    REQUIRE(c.best == 2.0);
    REQUIRE(c.mean == 5.0);
    c.parents = {2, 1};  // g' = min(6, 4) = 4: k1 (4 - 2)/(5 - 2)
    CHECK(pc.for_pair(c) == Approx(0.8 * 2.0 / 3.0).epsilon(1e-15));
    c.parents = {3, 2};  // g' = 6 > 5: k3
    CHECK(pc.for_pair(c) == 0.6);
    c.parents = {0, 3};
    c.child = 0;  // the copy of member 0, the best: pm = the floor 0.005
    CHECK(pm.for_child(c) == 0.005);
    CHECK(AdaptiveProbability{0.5, 0.5}.for_child(c) == 0.0);  // no floor: 0
    c.child = 1;                                               // the copy of member 3, below the mean: k4
    CHECK(pm.for_child(c) == 0.5);
}

TEST_CASE("IAGA: with every k = 0 nothing is crossed or mutated", "[ga-variants][iaga]") {
    IagaBox box;
    box.population = 10;
    box.crossover.probability = {0.0, 0.0};
    box.mutation.probability = {0.0, 0.0};
    const auto r = box.run(continuous::Rastrigin(4), max_iterations(20), 3);
    for (const double h : r.history) CHECK(same_bits(h, r.history.front()));  // copies of the parents only

    IagaChain chain;
    chain.population = 10;
    chain.crossover.probability = {0.0, 0.0};
    chain.mutation.probability = {0.0, 0.0};
    const auto rc = chain.run(Chains(bundled_grid()), max_iterations(20), 3);
    for (const double h : rc.history) CHECK(same_bits(h, rc.history.front()));

    box.mutation.probability = {1.5, 0.5};
    REQUIRE_THROWS_AS(box.validate(), InputError);
    box.mutation.probability = {0.5, 0.5, -0.1};  // pm_min outside [0, 1]
    REQUIRE_THROWS_AS(box.validate(), InputError);
}

// ---------------------------------------------------------------------------------------------
// ICGA

namespace {

/// What a catastrophe hook did, generation by generation.
struct Event {
    std::int64_t iteration = 0, stagnation = 0;
    double best_so_far = inf;
    std::vector<double> before, after;  // the population's fitness around the hook
    std::vector<std::size_t> renewed;   // the members renew() was asked for (empty: none)
    std::vector<bool> member_changed;   // whether each member's individual changed
};

/// Stands for the population in front of the hook: forwards everything, records renew()'s members.
template <class Population>
struct Recording {
    Population& population;
    std::vector<std::size_t>* renewed;
    std::size_t size() const { return population.size(); }
    std::span<const double> fitness() const { return population.fitness(); }
    decltype(auto) individual(std::size_t i) const { return population.individual(i); }
    void renew(std::span<const std::size_t> which, Rng& rng) {
        renewed->assign(which.begin(), which.end());
        population.renew(which, rng);
    }
};

template <class Individual>
std::vector<Individual> copy_all(const auto& population) {
    std::vector<Individual> out;
    for (std::size_t i = 0; i < population.size(); ++i) {
        const auto& x = population.individual(i);
        out.emplace_back(x.begin(), x.end());
    }
    return out;
}

/// The catastrophe hook, observed.
template <class Individual>
struct ObservedCatastrophe {
    CatastropheHook hook;
    std::shared_ptr<std::vector<Event>> events = std::make_shared<std::vector<Event>>();
    void validate(const std::string& where, std::int64_t population) const { hook.validate(where, population); }
    template <class Population>
    void operator()(const GenerationContext& c, Population& population, Rng& rng) const {
        Event e;
        e.iteration = c.iteration;
        e.stagnation = c.stagnation;
        e.best_so_far = c.best_so_far;
        e.before.assign(population.fitness().begin(), population.fitness().end());
        const auto old = copy_all<Individual>(population);
        Recording<Population> recording{population, &e.renewed};
        hook(c, recording, rng);
        e.after.assign(population.fitness().begin(), population.fitness().end());
        const auto now = copy_all<Individual>(population);
        for (std::size_t i = 0; i < old.size(); ++i) e.member_changed.push_back(!(old[i] == now[i]));
        events->push_back(std::move(e));
    }
};

/// Checks the events against the rule: a catastrophe exactly when stagnation is a positive
/// multiple of k; it keeps the `elite` best (smallest values, ties to the lower index) as they
/// were and re-seeds exactly the others. `changes_for_sure`: a re-seeded member differs (points).
template <class R>
void check_catastrophes(const std::vector<Event>& events, const CatastropheHook& hook, const R& r,
                        bool changes_for_sure) {
    REQUIRE(events.size() == static_cast<std::size_t>(r.iterations));
    std::int64_t catastrophes = 0;
    bool first = true;
    for (const Event& e : events) {
        const bool due = e.stagnation > 0 && e.stagnation % hook.k == 0;
        INFO("iteration " << e.iteration << " stagnation " << e.stagnation);
        if (!due) {
            REQUIRE(e.renewed.empty());
            REQUIRE(e.before == e.after);
            continue;
        }
        ++catastrophes;
        // The elite: the `elite` best before the hook.
        std::vector<std::size_t> order(e.before.size());
        for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
        std::stable_sort(order.begin(), order.end(), [&](auto a, auto b) { return e.before[a] < e.before[b]; });
        std::set<std::size_t> elite(order.begin(), order.begin() + hook.elite);
        std::vector<std::size_t> others;
        for (std::size_t i = 0; i < e.before.size(); ++i)
            if (!elite.count(i)) others.push_back(i);
        REQUIRE(e.renewed == others);  // exactly the others, in order
        for (const std::size_t i : elite) {
            REQUIRE(same_bits(e.after[i], e.before[i]));
            REQUIRE_FALSE(e.member_changed[i]);
        }
        if (changes_for_sure)
            for (const std::size_t i : others) REQUIRE(e.member_changed[i]);
        // The first catastrophe comes after exactly k generations that did not improve the best:
        // the history (not yet touched by any catastrophe) says so.
        if (first) {
            first = false;
            const auto t = static_cast<std::size_t>(e.iteration);
            REQUIRE(t >= static_cast<std::size_t>(hook.k));
            for (std::size_t s = t - static_cast<std::size_t>(hook.k); s < t; ++s)
                REQUIRE(same_bits(r.history[s], e.best_so_far));
            const std::size_t start = t - static_cast<std::size_t>(hook.k);
            if (start > 0) REQUIRE(r.history[start] < r.history[start - 1]);
        }
    }
    REQUIRE(catastrophes > 0);
}

}  // namespace

TEST_CASE("ICGA: the catastrophe keeps the elite and re-seeds exactly the others after k stagnant generations",
          "[ga-variants][icga]") {
    SECTION("points") {
        for (const auto& [k, elite] : {std::pair<std::int64_t, std::int64_t>{3, 2}, {5, 1}, {2, 0}}) {
            INFO("k " << k << " elite " << elite);
            Ga<TournamentSelection, SbxCrossover, PolynomialMutation, Clamp, UniformInit, ElitistReplacement,
               ObservedCatastrophe<std::vector<double>>>
                ga;
            ga.population = 8;
            ga.hook.hook.k = k;
            ga.hook.hook.elite = elite;
            const continuous::Rastrigin problem(3);
            const auto r = ga.run(problem, max_iterations(150), 2);
            check_catastrophes(*ga.hook.events, ga.hook.hook, r, true);
            // The plain hook gives the same bits.
            IcgaBox plain;
            plain.population = 8;
            plain.hook.k = k;
            plain.hook.elite = elite;
            require_same_run(r, plain.run(problem, max_iterations(150), 2));
        }
    }
    SECTION("chains") {
        Ga<TournamentSelection, ChainCrossover, ChainMutation, Clamp, UniformInit, ElitistReplacement,
           ObservedCatastrophe<grid::Path>>
            ga;
        ga.population = 10;
        ga.hook.hook.k = 2;
        ga.hook.hook.elite = 3;
        const Chains space(bundled_grid());
        const auto r = ga.run(space, max_iterations(80), 4);
        check_catastrophes(*ga.hook.events, ga.hook.hook, r, false);
        IcgaChain plain;
        plain.population = 10;
        plain.hook.k = 2;
        plain.hook.elite = 3;
        require_same_run(r, plain.run(space, max_iterations(80), 4));
    }
    SECTION("k and elite are checked") {
        IcgaBox ga;
        ga.population = 5;
        ga.hook.k = 0;
        REQUIRE_THROWS_AS(ga.validate(), InputError);
        ga.hook.k = 1;
        ga.hook.elite = 5;
        REQUIRE_THROWS_AS(ga.validate(), InputError);
        ga.hook.elite = 4;
        REQUIRE_NOTHROW(ga.validate());
    }
}

// ---------------------------------------------------------------------------------------------
// Q-learning

TEST_CASE("Q-learning: eq. 19 and the reward r = u - w, by hand", "[ga-variants][q-learning]") {
    OperatorQLearning q({0.1, 0.1, 0.9}, orderings({0.6, 0.2, 0.2}));
    REQUIRE(q.actions() == 3);
    REQUIRE(q.operators() == 3);
    CHECK(OperatorQLearning::state(10.0, 8.0) == 1);  // shorter
    CHECK(OperatorQLearning::state(8.0, 8.0) == 2);   // equal
    CHECK(OperatorQLearning::state(8.0, 9.0) == 3);   // longer
    CHECK(OperatorQLearning::reward(3, 1) == 2.0);    // to a better state: rewarded
    CHECK(OperatorQLearning::reward(1, 2) == -1.0);   // to a worse one: punished

    // Q(1, a0) = 0.5; row 2 = (0.2, 1.0, -0.3); from state 1 to state 2: r = 1 - 2 = -1;
    // Q(1, a0) <- 0.5 + 0.1 (-1 + 0.9 * 1.0 - 0.5) = 0.5 - 0.06 = 0.44.
    q.q(1, 0) = 0.5;
    q.q(2, 0) = 0.2;
    q.q(2, 1) = 1.0;
    q.q(2, 2) = -0.3;
    q.update(1, 0, OperatorQLearning::reward(1, 2), 2);
    CHECK(q.q(1, 0) == Approx(0.44).epsilon(1e-15));
    // Q(3, a2) = 0; to state 1 (r = 2), row 1 now (0.44, 0, 0): 0 + 0.1 (2 + 0.9 * 0.44 - 0) = 0.2396.
    q.update(3, 2, OperatorQLearning::reward(3, 1), 1);
    CHECK(q.q(3, 2) == Approx(0.2396).epsilon(1e-15));
    CHECK(q.q(2, 1) == 1.0);  // nothing else moved
    // A table of actions must be one: each a probability vector over the same operators.
    REQUIRE_THROWS_AS(OperatorQLearning({}, {{0.5, 0.5}, {1.0}}), InputError);
    REQUIRE_THROWS_AS(OperatorQLearning({}, {}), InputError);
    REQUIRE_THROWS_AS(OperatorQLearning({}, {{0.7, 0.7}}), InputError);
}

TEST_CASE("Q-learning: one generation at a time, greedy, by hand", "[ga-variants][q-learning]") {
    OperatorQLearning q({0.0, 0.1, 0.9}, orderings({0.6, 0.2, 0.2}));  // epsilon 0: no draw decides
    Rng rng(1);
    q.begin_generation(10.0, rng);  // no previous best: state 2, no update; row 2 all 0: a1
    CHECK(q.current_state() == 2);
    CHECK(q.action() == 0);
    CHECK(std::vector<double>(q.probabilities().begin(), q.probabilities().end()) ==
          std::vector<double>{0.6, 0.2, 0.2});
    q.begin_generation(8.0, rng);  // shorter: 2 -> 1, r = 1: Q(2, a1) = 0.1 (1 + 0.9 * 0) = 0.1
    CHECK(q.current_state() == 1);
    CHECK(q.q(2, 0) == Approx(0.1).epsilon(1e-15));
    CHECK(q.action() == 0);
    q.begin_generation(8.0, rng);  // equal: 1 -> 2, r = -1: Q(1, a1) = 0.1 (-1 + 0.9 * 0.1) = -0.091
    CHECK(q.current_state() == 2);
    CHECK(q.q(1, 0) == Approx(-0.091).epsilon(1e-15));
    CHECK(q.action() == 0);        // row 2 = (0.1, 0, 0)
    q.begin_generation(9.0, rng);  // longer: 2 -> 3, r = -1: Q(2, a1) = 0.1 + 0.1 (-1 + 0 - 0.1) = -0.01
    CHECK(q.current_state() == 3);
    CHECK(q.q(2, 0) == Approx(-0.01).epsilon(1e-12));
    CHECK(q.action() == 0);        // row 3 all 0: the first
    q.begin_generation(9.0, rng);  // equal: 3 -> 2, r = 1: Q(3, a1) = 0.1 (1 + 0.9 * max(-0.01, 0, 0)) = 0.1
    CHECK(q.current_state() == 2);
    CHECK(q.q(3, 0) == Approx(0.1).epsilon(1e-15));
    CHECK(q.action() == 1);  // row 2 = (-0.01, 0, 0): a2 gives 0.6 to the second operator
    CHECK(std::vector<double>(q.probabilities().begin(), q.probabilities().end()) ==
          std::vector<double>{0.2, 0.6, 0.2});
}

TEST_CASE("Q-learning: epsilon-greedy and roulette frequencies, the orderings", "[ga-variants][q-learning]") {
    CHECK(orderings({0.6, 0.2, 0.2}) ==
          std::vector<std::vector<double>>{{0.6, 0.2, 0.2}, {0.2, 0.6, 0.2}, {0.2, 0.2, 0.6}});
    CHECK(orderings({0.2, 0.5, 0.3}).size() == 6);
    CHECK(orderings({0.5, 0.5}).size() == 1);
    CHECK(default_operator_weights(3) == std::vector<double>{0.6, 0.2, 0.2});
    CHECK(default_operator_weights(1) == std::vector<double>{1.0});

    const int n = 100000;
    for (const double epsilon : {0.0, 0.1, 0.5, 1.0}) {
        INFO("epsilon " << epsilon);
        OperatorQLearning q({epsilon, 0.1, 0.9}, orderings({0.6, 0.2, 0.2}));
        q.q(1, 2) = 1.0;  // the greedy action in state 1: a3
        Rng rng(5);
        std::vector<int> count(3, 0);
        for (int i = 0; i < n; ++i) ++count[q.choose(1, rng)];
        const double greedy = 1.0 - epsilon + epsilon / 3.0, other = epsilon / 3.0;
        CHECK(count[2] / double(n) == Approx(greedy).margin(0.006));
        CHECK(count[0] / double(n) == Approx(other).margin(0.006));
        CHECK(count[1] / double(n) == Approx(other).margin(0.006));
        if (epsilon == 0.0) CHECK(count[2] == n);
    }
    // The operators by the current action's probabilities.
    OperatorQLearning q({0.0, 0.1, 0.9}, orderings({0.6, 0.2, 0.2}));
    Rng rng(6);
    q.begin_generation(1.0, rng);
    std::vector<int> count(3, 0);
    for (int i = 0; i < n; ++i) ++count[q.pick(rng)];
    CHECK(count[0] / double(n) == Approx(0.6).margin(0.006));
    CHECK(count[1] / double(n) == Approx(0.2).margin(0.006));
    CHECK(count[2] / double(n) == Approx(0.2).margin(0.006));
    // Same seed, same choices.
    Rng a(9), b(9);
    OperatorQLearning qa({0.3, 0.1, 0.9}, orderings({0.6, 0.2, 0.2})), qb = qa;
    for (int i = 0; i < 100; ++i) REQUIRE(qa.choose(2, a) == qb.choose(2, b));
}

namespace {

/// A box mutation that only counts its calls (by which of the policy's operators it is).
struct CountingMutation {
    std::shared_ptr<std::vector<std::int64_t>> calls;
    std::size_t which = 0;
    void operator()(std::span<double>, std::span<const double>, std::span<const double>, Rng&) const {
        ++(*calls)[which];
    }
};

}  // namespace

TEST_CASE("Q-learning mutation: operators chosen by the action's probabilities, in a GA", "[ga-variants][q-learning]") {
    auto calls = std::make_shared<std::vector<std::int64_t>>(2, 0);
    Ga<TournamentSelection, SbxCrossover, QLearningMutation<CountingMutation, CountingMutation>> ga;
    ga.population = 21;  // 20 children a generation
    ga.mutation.operators = {CountingMutation{calls, 0}, CountingMutation{calls, 1}};
    ga.mutation.actions = {{0.25, 0.75}};  // one action: the learner has nothing to choose
    const auto r = ga.run(continuous::Sphere(3), max_iterations(500), 1);
    REQUIRE(r.iterations == 500);
    const auto total = (*calls)[0] + (*calls)[1];
    CHECK(total == 500 * 20);
    CHECK((*calls)[0] / double(total) == Approx(0.25).margin(0.015));

    ga.mutation.actions = {{0.5, 0.6}};
    REQUIRE_THROWS_AS(ga.validate(), InputError);
    ga.mutation.actions = {{0.5, 0.5, 0.0}};
    REQUIRE_THROWS_AS(ga.validate(), InputError);
    ga.mutation.actions.clear();
    ga.mutation.learning.epsilon = 1.5;
    REQUIRE_THROWS_AS(ga.validate(), InputError);
}

namespace {

/// A box mutation that records, per call, the generation and which operator it is.
struct RecordingMutation {
    std::shared_ptr<std::vector<std::pair<std::int64_t, std::size_t>>> calls;
    std::size_t which = 0;
    void operator()(std::span<double>, std::span<const double>, std::span<const double>, Rng&,
                    const GenerationContext& c) const {
        calls->emplace_back(c.iteration, which);
    }
};

}  // namespace

TEST_CASE("Q-learning mutation: learns once per generation from the population's best, as a replay says",
          "[ga-variants][q-learning]") {
    auto calls = std::make_shared<std::vector<std::pair<std::int64_t, std::size_t>>>();
    Ga<TournamentSelection, SbxCrossover, QLearningMutation<RecordingMutation, RecordingMutation>> ga;
    ga.population = 9;  // 8 children a generation
    ga.mutation.operators = {RecordingMutation{calls, 0}, RecordingMutation{calls, 1}};
    ga.mutation.weights = {1.0, 0.0};  // actions (1, 0) and (0, 1): the action is the operator
    ga.mutation.learning.epsilon = 0.0;
    const auto r = ga.run(continuous::Sphere(4), max_iterations(200), 3);
    REQUIRE(calls->size() == 200 * 8);

    // Replay: the learner told the best of each generation's parents (with elitism 1 the run's
    // best so far, history[t]) chooses the operator every child of generation t got.
    OperatorQLearning replay(ga.mutation.learning, ga.mutation.action_table());
    Rng unused(0);
    std::set<std::size_t> used;
    for (std::int64_t t = 0; t < 200; ++t) {
        replay.begin_generation(r.history[static_cast<std::size_t>(t)], unused);
        for (std::size_t k = 0; k < 8; ++k) {
            const auto& [iteration, which] = (*calls)[static_cast<std::size_t>(t) * 8 + k];
            REQUIRE(iteration == t);
            REQUIRE(which == replay.action());
        }
        used.insert(replay.action());
    }
    CHECK(used.size() == 2);  // the learner changed its mind at least once
}

// ---------------------------------------------------------------------------------------------
// Every variant: reproducible, exact budgets, valid results

TEST_CASE("GA variants: the same seed gives the same bits, on boxes and on chains", "[ga-variants]") {
    const continuous::Rastrigin problem(6);
    const Chains space(bundled_grid());
    auto twice = [&](const auto& ga, const auto& p, const Termination& t) {
        const auto a = ga.run(p, t, 7);
        require_same_run(a, ga.run(p, t, 7));
        const auto other = ga.run(p, t, 8);
        return !same_bits(a.best_f, other.best_f) || a.history != other.history;
    };
    IagaBox iaga;
    iaga.population = 20;
    CHECK(twice(iaga, problem, max_evaluations(3001)));
    IcgaBox icga;
    icga.population = 20;
    icga.hook.k = 3;
    CHECK(twice(icga, problem, max_evaluations(3001)));
    GaQBox q;
    q.population = 20;
    CHECK(twice(q, problem, max_evaluations(3001)));
    IagaChain iaga_chain;
    iaga_chain.population = 12;
    twice(iaga_chain, space, max_iterations(40));
    IcgaChain icga_chain;
    icga_chain.population = 12;
    icga_chain.hook.k = 2;
    twice(icga_chain, space, max_iterations(40));
    GaQChain q_chain;
    q_chain.population = 12;
    std::get<0>(q_chain.mutation.operators).probability = 0.1;
    std::get<1>(q_chain.mutation.operators).probability = 0.9;
    twice(q_chain, space, max_iterations(40));

    // Through the registry, on a box.
    const engine::Problem sphere(engine::ContinuousSpec{"rastrigin", 5});
    engine::Budget budget;
    budget.evaluations = 1234;
    for (const char* name : {"iaga", "icga", "ga-q"}) {
        INFO(name);
        const auto a = engine::run({name, {}}, sphere, budget, 3);
        const auto b = engine::run({name, {}}, sphere, budget, 3);
        REQUIRE(same_bits(a.best_f, b.best_f));
        REQUIRE(a.history == b.history);
        REQUIRE(a.best_x == b.best_x);
        REQUIRE(a.evaluations == 1234);
    }
}

TEST_CASE("GA variants: budgets are exact and results valid, on boxes and on chains", "[ga-variants]") {
    const continuous::Rastrigin reference(5);
    BoxChecker box_checker{std::vector<double>(reference.lower().begin(), reference.lower().end()),
                           std::vector<double>(reference.upper().begin(), reference.upper().end())};
    auto on_box = [&](const auto& ga, const std::string& label) {
        for (const std::int64_t budget : {1, 2, 7, 19, 20, 21, 997, 3000}) {
            INFO(label << " budget " << budget);
            CountedRastrigin problem;
            const auto r = ga.run(problem, max_evaluations(budget), 5, box_checker);
            CHECK(*problem.count == budget);
            CHECK(r.evaluations == budget);
            CHECK(r.history_evaluations.back() == budget);
            for (std::size_t k = 1; k < r.history.size(); ++k) CHECK(r.history[k] <= r.history[k - 1]);
            for (std::size_t d = 0; d < r.best_x.size(); ++d) {
                CHECK(r.best_x[d] >= reference.lower()[d]);
                CHECK(r.best_x[d] <= reference.upper()[d]);
            }
            CHECK(same_bits(r.best_f, continuous::Rastrigin(5).evaluate(r.best_x)));
        }
    };
    IagaBox iaga;
    iaga.population = 20;
    on_box(iaga, "iaga");
    IcgaBox icga;
    icga.population = 20;
    icga.hook.k = 2;  // many catastrophes, each spending 19 evaluations
    on_box(icga, "icga");
    GaQBox q;
    q.population = 20;
    on_box(q, "ga-q");
    CHECK(*box_checker.bad == 0);

    const auto grid_problem = bundled_grid();
    ChainChecker chain_checker{grid_problem};
    auto on_chain = [&](const auto& ga, const std::string& label) {
        for (const std::int64_t budget : {1, 7, 12, 13, 250, 601}) {
            INFO(label << " budget " << budget);
            CountingChains problem{Chains(grid_problem)};
            const auto r = ga.run(problem, max_evaluations(budget), 5, chain_checker);
            CHECK(*problem.count == budget);
            CHECK(r.evaluations == budget);
            CHECK(std::isfinite(r.best_f));
            CHECK(grid::path_violation(grid_problem.map(), r.best_x, grid_problem.start(), grid_problem.goal()) == "");
            CHECK(r.best_f == grid_problem.evaluate(r.best_x));
        }
    };
    IagaChain iaga_chain;
    iaga_chain.population = 12;
    on_chain(iaga_chain, "iaga");
    IcgaChain icga_chain;
    icga_chain.population = 12;
    icga_chain.hook.k = 2;
    on_chain(icga_chain, "icga");
    GaQChain q_chain;
    q_chain.population = 12;
    on_chain(q_chain, "ga-q chain");
    CHECK(*chain_checker.seen > 0);
    CHECK(*chain_checker.bad == 0);
}

TEST_CASE("GA variants: registry entries, their parameters and ranges", "[ga-variants][engine]") {
    auto& registry = engine::algorithms();
    const auto* iaga = registry.find("iaga");
    const auto* icga = registry.find("icga");
    const auto* gaq = registry.find("ga-q");
    REQUIRE(iaga);
    REQUIRE(icga);
    REQUIRE(gaq);
    CHECK(iaga->family == "ga");
    CHECK(icga->family == "ga");
    CHECK(gaq->family == "ga");
    CHECK(iaga->runs(engine::Kind::chain));
    CHECK(icga->runs(engine::Kind::chain));
    CHECK_FALSE(gaq->runs(engine::Kind::chain));
    auto param = [](const engine::AlgorithmEntry* e, const std::string& name) -> const engine::ParamSpec& {
        const auto it = std::find_if(e->params.begin(), e->params.end(), [&](const auto& p) { return p.name == name; });
        REQUIRE(it != e->params.end());
        return *it;
    };
    for (const auto& [name, value] :
         {std::pair<const char*, double>{"k1", 1.0}, {"k2", 0.5}, {"k3", 1.0}, {"k4", 0.5}, {"pm_min", 0.005}}) {
        const auto& p = param(iaga, name);
        CHECK(p.default_value == value);
        CHECK(p.min == 0.0);
        CHECK(p.max == 1.0);
    }
    CHECK(param(icga, "k").default_value == 10.0);
    CHECK(param(icga, "elite").default_value == 1.0);
    CHECK(param(gaq, "epsilon").default_value == 0.1);
    CHECK(param(gaq, "alpha").default_value == 0.1);
    CHECK(param(gaq, "gamma").default_value == 0.9);

    // Out of range and unknown parameters are refused before running.
    const engine::Problem sphere(engine::ContinuousSpec{"sphere", 3});
    engine::Budget budget;
    budget.evaluations = 100;
    engine::AlgorithmSpec bad{"iaga", {}};
    bad.params.set("k2", 1.5);
    CHECK_THROWS_AS(engine::run(bad, sphere, budget, 1), InputError);
    engine::AlgorithmSpec elite{"icga", {}};
    elite.params.set("pop", 5);
    elite.params.set("elite", 5);
    CHECK_THROWS_AS(engine::run(elite, sphere, budget, 1), InputError);

    // On a grid's chains, through the registry.
    engine::GridSpec g;
    g.map = engine::load_map(bundled_map("wan2022-10x10.map").string());
    g.start = {0, 0};
    g.goal = {9, 9};
    g.encoding = "chain";
    const engine::Problem chains(g);
    engine::Budget iterations;
    iterations.iterations = 15;
    for (const char* name : {"iaga", "icga"}) {
        INFO(name);
        const auto a = engine::run({name, {}}, chains, iterations, 2);
        const auto b = engine::run({name, {}}, chains, iterations, 2);
        REQUIRE(a.grid.has_value());
        CHECK(a.grid->encoding == "chain");
        CHECK(a.grid->feasible);
        CHECK(a.history == b.history);
        CHECK(a.grid->path == b.grid->path);
    }
    engine::AlgorithmSpec eta{"iaga", {}};
    eta.params.set("eta_c", 3);
    CHECK_THROWS_AS(engine::run(eta, chains, iterations, 1), InputError);
}

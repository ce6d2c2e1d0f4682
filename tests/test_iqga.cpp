// Tests of Zhang et al.'s (2025) IQGA as GA policies (algorithms/parts/iqga/operators.hpp, IqgaGa in
// algorithms/ga.hpp) and its registry entry iqga (engine/entries/ga_entries.cpp):
//   - eqs. 16-18 (selections per region, B, the SA acceptance P_j) and eq. 20's badness on worked
//     numbers;
//   - the mating pool: a replay of the documented draws gives it exactly; the population's best is
//     always in it; each region's entries come from its s_i tournaments (between s_i and 3 s_i,
//     about 1.5 s_i when B <= 0); an empty region draws from the whole population;
//   - the elite pairing rule in every pair of a run, and EliteCrossover refusing non-elite pairs;
//   - Q-learning learns once per generation (a replay of the learner chooses every child's operator);
//   - reproducible bit for bit; every member of every population a legal simple path from start to
//     goal on every bundled map and on 200 random maps; budgets exact;
//   - the registry entry: parameters, N = 40 on grids, SITP by default, chains only;
//   - the ablation flags (regions, elite_crossover, qlearning, with sitp): each removes its change
//     only, every variant legal and reproducible.
#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <map>
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
#include "framework/chain.hpp"
#include "framework/error.hpp"
#include "framework/termination.hpp"
#include "problems/grid/chain.hpp"
#include "problems/grid/grid_problem.hpp"
#include "problems/grid/map.hpp"
#include "problems/grid/map_io.hpp"
#include "problems/grid/objectives.hpp"
#include "problems/grid/path.hpp"
#include "problems/grid/walk.hpp"
#include "tests/counting_space.hpp"
#include "tests/grid_support.hpp"

namespace {

using namespace pride;
namespace fs = std::filesystem;
using Space = grid::ChainSpace<grid::IqgaObjective>;

static_assert(RegionOf<Space> && TwoPointCrossover<Space> && NumberedMutations<Space>);

bool same_bits(double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

fs::path bundled_maps() {
    return fs::path(PRIDE_SOURCE_DIR) / "examples" / "maps";
}

using Instance = test::GridInstance;

std::vector<Instance> bundled_instances() {
    return test::bundled_instances(bundled_maps());
}
using test::random_instances;

Space space_of(const Instance& in) {
    Space s(grid::GridProblem<grid::IqgaObjective>(in.map, in.start, in.goal, {}, in.corner_cutting));
    s.set_init(grid::Walks::sitp);
    return s;
}

bool is_simple(const grid::Path& p) {
    std::set<std::pair<int, int>> seen;
    for (const grid::Cell& c : p)
        if (!seen.insert({c.x, c.y}).second) return false;
    return true;
}

/// Counts members of every population that are not legal simple paths or whose fitness is not their value.
struct LegalityChecker {
    Instance in;
    std::shared_ptr<std::int64_t> bad = std::make_shared<std::int64_t>(0);
    std::shared_ptr<std::int64_t> seen = std::make_shared<std::int64_t>(0);
    std::shared_ptr<std::string> first = std::make_shared<std::string>();
    template <class View>
    void operator()(const View& view) const {
        const grid::GridProblem<grid::IqgaObjective> problem(in.map, in.start, in.goal, {}, in.corner_cutting);
        const std::vector<grid::Path>& pop = view.population;
        for (std::size_t i = 0; i < pop.size(); ++i) {
            ++*seen;
            std::string why = grid::path_violation(*in.map, pop[i], in.start, in.goal, in.corner_cutting);
            if (why.empty() && !is_simple(pop[i])) why = "a cell twice";
            if (why.empty() && std::isfinite(view.fitness[i]) && view.fitness[i] != problem.evaluate(pop[i]))
                why = "fitness is not the path's value";
            if (!why.empty()) {
                if (first->empty()) *first = why;
                ++*bad;
            }
        }
    }
};

/// The chain space, counting every call of its objective (tests/counting_space.hpp).
using CountedSpace = test::CountingSpace<Space>;

Instance zhang2025_40() {
    auto map = std::make_shared<const grid::GridMap>(grid::read_map((bundled_maps() / "zhang2025-40x40.map").string()));
    const auto scen = grid::read_scenario((bundled_maps() / "zhang2025-40x40.map.scen").string());
    return {map, scen.at(0).start, scen.at(0).goal, false};
}

Instance zhang2025_20() {
    auto map = std::make_shared<const grid::GridMap>(grid::read_map((bundled_maps() / "zhang2025-20x20.map").string()));
    const auto scen = grid::read_scenario((bundled_maps() / "zhang2025-20x20.map.scen").string());
    return {map, scen.at(0).start, scen.at(0).goal, false};
}

/// The pool of docs/algorithms.md, written out directly from the documented draws (iqga_operators.hpp).
std::vector<std::size_t> expected_pool(std::span<const double> f, std::span<const std::size_t> regions, Rng& rng) {
    const std::size_t n = f.size();
    std::vector<std::vector<std::size_t>> in(3);
    for (std::size_t i = 0; i < n; ++i) in[regions[i]].push_back(i);
    const std::size_t third = n / 3;
    const std::size_t s1 = in[0].size() <= third ? in[0].size() : third;
    const std::size_t s2 = in[1].size() <= third ? in[1].size() : third;
    const std::size_t s[3] = {s1, s2, n - s1 - s2};
    const double fb = -*std::min_element(f.begin(), f.end()), fw = -*std::max_element(f.begin(), f.end());
    const double B = fb - 1.05 * fw;
    std::vector<std::size_t> pool;
    for (int r = 0; r < 3; ++r)
        for (std::size_t k = 0; k < s[r]; ++k) {
            std::size_t t[3];
            for (auto& m : t) m = in[r].empty() ? rng.below(n) : in[r][rng.below(in[r].size())];
            std::stable_sort(t, t + 3, [&](std::size_t a, std::size_t b) { return f[a] < f[b]; });
            pool.push_back(t[0]);
            if (B > 0) {
                const double pj = fb == fw ? 1.0 : (-f[t[1]] - fw) / (fb - fw);
                if (rng.uniform() < pj) pool.push_back(t[1]);
            }
            if (rng.uniform() < 0.5) pool.push_back(t[2]);
        }
    pool.push_back(static_cast<std::size_t>(std::min_element(f.begin(), f.end()) - f.begin()));
    return pool;
}

GenerationContext context_of(std::span<const double> f, std::span<const std::size_t> regions) {
    GenerationContext c;
    c.describe(0, f, *std::min_element(f.begin(), f.end()));
    c.regions = regions;
    return c;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Equations

TEST_CASE("iqga: eqs. 16-18 and eq. 20's badness on worked numbers", "[iqga]") {
    // Eq. 16, N = 40 (N/3 = 13): s_1 = n_1 when n_1 <= 13, else 13; s_3 = N - s_1 - s_2.
    CHECK(iqga::selections(5, 30, 40) == std::array<std::size_t, 3>{5, 13, 22});
    CHECK(iqga::selections(20, 3, 40) == std::array<std::size_t, 3>{13, 3, 24});
    CHECK(iqga::selections(13, 13, 40) == std::array<std::size_t, 3>{13, 13, 14});
    CHECK(iqga::selections(0, 0, 20) == std::array<std::size_t, 3>{0, 0, 20});
    // Eq. 17: B = F_best - 21/20 F_worst.
    CHECK(iqga::uniformity(10.0, 2.0) == Approx(7.9));
    CHECK(iqga::uniformity(2.05, 2.0) == Approx(-0.05));
    CHECK(iqga::uniformity(2.1, 2.0) == Approx(0.0).margin(1e-12));
    // Eq. 18: P_j = (F_i - F_worst)/(F_best - F_worst).
    CHECK(iqga::acceptance(6.0, 10.0, 2.0) == Approx(0.5));
    CHECK(iqga::acceptance(4.0, 10.0, 2.0) == Approx(0.25));
    CHECK(iqga::acceptance(10.0, 10.0, 2.0) == 1.0);
    CHECK(iqga::acceptance(2.0, 10.0, 2.0) == 0.0);
    CHECK(iqga::acceptance(3.0, 3.0, 3.0) == 1.0);
    CHECK(iqga::acceptance(-std::numeric_limits<double>::infinity(), 10.0, 2.0) == 0.0);
    // On objective iqga's values: f = -(1/f1 + 1/f2 + 1/f3), F = -f. A best path F = 2.3, a worst
    // F = 1.6: B = 2.3 - 1.68 = 0.62 > 0; a second member of F = 1.95 is kept with P_j = 0.5.
    CHECK(iqga::uniformity(2.3, 1.6) == Approx(0.62));
    CHECK(iqga::acceptance(1.95, 2.3, 1.6) == Approx(0.5));
    // Eq. 20's badness on minimised values: 0 for the best, 1 for the worst; 0.5 when all are equal.
    CHECK(iqga::badness(-2.3, -2.3, -1.6) == 0.0);
    CHECK(iqga::badness(-1.6, -2.3, -1.6) == 1.0);
    CHECK(iqga::badness(-1.95, -2.3, -1.6) == Approx(0.5));
    CHECK(iqga::badness(-2.0, -2.0, -2.0) == 0.5);
    // The elite: min(elite, N/2).
    CHECK(iqga::elite_size(20, 40) == 20);
    CHECK(iqga::elite_size(20, 100) == 20);
    CHECK(iqga::elite_size(20, 30) == 15);
    CHECK(iqga::elite_size(20, 2) == 1);
}

// ---------------------------------------------------------------------------------------------
// The pool

TEST_CASE("iqga: the region pool, replayed, best always kept, regions in proportion to eq. 16", "[iqga]") {
    Rng make(11);
    for (int trial = 0; trial < 200; ++trial) {
        INFO("trial " << trial);
        const std::size_t n = 2 + make.below(60);
        std::vector<double> f(n);
        std::vector<std::size_t> regions(n);
        const bool spread = trial % 2 == 0;  // B > 0 (spread) or B <= 0 (all within 5 %)
        for (std::size_t i = 0; i < n; ++i) {
            f[i] = spread ? -(1.0 + 2.0 * make.uniform()) : -(2.0 + 0.04 * make.uniform());
            // Every third trial leaves region 2 (or 0) empty.
            regions[i] = trial % 3 == 0 ? make.below(2) : trial % 3 == 1 ? 1 + make.below(2) : make.below(3);
        }
        const auto c = context_of(f, regions);
        RegionTournamentSelection selection;
        auto prepared = selection.prepare(0);
        Rng a(100 + static_cast<std::uint64_t>(trial)), b(100 + static_cast<std::uint64_t>(trial));
        prepared.begin_generation(c, a);
        const std::vector<std::size_t> want = expected_pool(f, regions, b);
        const auto pool = prepared.pool();
        REQUIRE(std::vector<std::size_t>(pool.begin(), pool.end()) == want);
        REQUIRE(a.below(1u << 30) == b.below(1u << 30));  // the same number of draws

        // The best member is always there (the last entry).
        const auto best = static_cast<std::size_t>(std::min_element(f.begin(), f.end()) - f.begin());
        CHECK(pool.back() == best);
        // Entries from region r (the final best left out) lie in [s_r, 3 s_r] for regions that
        // have members; with B <= 0 in [s_r, 2 s_r].
        std::size_t n_r[3] = {0, 0, 0};
        for (const auto r : regions) ++n_r[r];
        const auto s = iqga::selections(n_r[0], n_r[1], n);
        std::size_t from[3] = {0, 0, 0};
        for (std::size_t k = 0; k + 1 < pool.size(); ++k) ++from[regions[pool[k]]];
        std::size_t borrowed = 0;  // tournaments of empty regions draw from all
        for (int r = 0; r < 3; ++r)
            if (n_r[r] == 0) borrowed += s[static_cast<std::size_t>(r)];
        for (int r = 0; r < 3; ++r) {
            if (n_r[r] == 0) {
                CHECK(from[r] == 0);
                continue;
            }
            CHECK(from[r] >= s[static_cast<std::size_t>(r)]);
            CHECK(from[r] <= (spread ? 3 : 2) * (s[static_cast<std::size_t>(r)] + borrowed));
        }
        CHECK(pool.size() >= n + 1);
        CHECK(pool.size() <= (spread ? 3 : 2) * n + 1);
    }
}

TEST_CASE("iqga: the pool's mean composition: 1 + 1/2 entries per tournament when B <= 0", "[iqga]") {
    // 30 members, 10 per region, all within 5 % (B <= 0): s = (10, 10, 10); each tournament keeps its
    // best and its worst with probability 1/2.
    std::vector<double> f(30);
    std::vector<std::size_t> regions(30);
    for (std::size_t i = 0; i < 30; ++i) {
        f[i] = -2.0 - 0.001 * static_cast<double>(i);
        regions[i] = i % 3;
    }
    const auto c = context_of(f, regions);
    auto prepared = RegionTournamentSelection{}.prepare(0);
    Rng rng(5);
    double total[3] = {0, 0, 0};
    const int runs = 4000;
    for (int t = 0; t < runs; ++t) {
        prepared.begin_generation(c, rng);
        const auto pool = prepared.pool();
        for (std::size_t k = 0; k + 1 < pool.size(); ++k) total[regions[pool[k]]] += 1.0;
    }
    for (int r = 0; r < 3; ++r) CHECK(total[r] / runs == Approx(15.0).margin(0.15));

    // With B > 0 (F_best = 2, F_worst = 1: B = 0.95) the second is also kept, with P_j: members
    // F = 1 + i/29 (i = 0..29), P_j = i/29 for the tournament's median, whose mean is 1/2, so a
    // tournament keeps 1 + 1/2 + 1/2 = 2 entries on average.
    for (std::size_t i = 0; i < 30; ++i) f[i] = -(1.0 + static_cast<double>(i) / 29.0);
    const auto spread = context_of(f, regions);
    double entries = 0;
    for (int t = 0; t < runs; ++t) {
        prepared.begin_generation(spread, rng);
        entries += static_cast<double>(prepared.pool().size() - 1);
    }
    CHECK(entries / runs / 30.0 == Approx(2.0).margin(0.02));
}

// ---------------------------------------------------------------------------------------------
// Elite pairing

TEST_CASE("iqga: every pair holds an elite member, EliteCrossover refuses a pair without one", "[iqga]") {
    Rng make(3);
    for (const std::size_t n : {4u, 11u, 30u, 40u, 41u, 80u}) {
        INFO("N " << n);
        std::vector<double> f(n);
        std::vector<std::size_t> regions(n);
        for (std::size_t i = 0; i < n; ++i) {
            f[i] = -(1.0 + make.uniform());
            regions[i] = make.below(3);
        }
        const auto c = context_of(f, regions);
        auto prepared = RegionTournamentSelection{}.prepare(0);
        Rng rng(n);
        prepared.begin_generation(c, rng);
        std::vector<char> elite;
        std::vector<std::size_t> order;
        iqga::elite_flags(f, iqga::elite_size(20, n), elite, order);
        std::size_t elite_count = 0;
        for (std::size_t i = 0; i < n; ++i) {
            elite_count += elite[i] != 0;
            CHECK(prepared.is_elite(i) == (elite[i] != 0));
        }
        CHECK(elite_count == (n >= 40 ? 20 : n / 2));
        const std::set<std::size_t> in_pool(prepared.pool().begin(), prepared.pool().end());
        bool non_elite_first = false;
        for (int k = 0; k < 2000; ++k) {
            const std::size_t a = prepared(f, rng), b = prepared(f, rng);
            REQUIRE(in_pool.count(a) == 1);
            REQUIRE(in_pool.count(b) == 1);
            REQUIRE((elite[a] || elite[b]));
            non_elite_first |= !elite[a];
        }
        CHECK(non_elite_first);
    }

    // EliteCrossover: two non-elite parents are not crossed (and draw nothing).
    const Instance in = zhang2025_20();
    Space space = space_of(in);
    Rng rng(9);
    grid::Path p, q;
    space.random_chain(rng, p, test::uncounted_score(space));
    space.random_chain(rng, q, test::uncounted_score(space));
    std::vector<double> f{-3.0, -2.0, -1.0, -0.5};  // elite: member 0 and 1
    GenerationContext c;
    c.describe(0, f, -3.0);
    EliteCrossover crossover;
    crossover.probability = 1.0;
    auto x = crossover.prepare(0);
    x.begin_generation(c, rng);
    CHECK(x.is_elite(0));
    CHECK(x.is_elite(1));
    CHECK(!x.is_elite(2));
    c.parents = {2, 3};
    grid::Path a = p, b = q;
    Rng before = rng;
    x(space, a, b, rng, c);
    CHECK(a == p);
    CHECK(b == q);
    CHECK(rng.below(1u << 30) == before.below(1u << 30));
    // An elite member in the pair: crossed (fig. 7) whenever the two share two cells.
    int crossed = 0;
    for (int k = 0; k < 50; ++k) {
        space.random_chain(rng, p, test::uncounted_score(space));
        space.random_chain(rng, q, test::uncounted_score(space));
        a = p;
        b = q;
        c.parents = {3, 0};
        x(space, a, b, rng, c);
        crossed += a != p || b != q;
    }
    CHECK(crossed > 0);
}

namespace {

/// A crossover policy that records whether each pair of a run held an elite member.
struct PairChecker {
    std::shared_ptr<std::int64_t> pairs = std::make_shared<std::int64_t>(0);
    std::shared_ptr<std::int64_t> bad = std::make_shared<std::int64_t>(0);
    void validate(const std::string&) const {}
    template <class P>
    void operator()(P&, typename P::chain_type&, typename P::chain_type&, Rng&, const GenerationContext& c) const {
        std::vector<char> elite;
        std::vector<std::size_t> order;
        iqga::elite_flags(c.fitness, iqga::elite_size(20, c.fitness.size()), elite, order);
        ++*pairs;
        if (!elite[c.parents[0]] && !elite[c.parents[1]]) ++*bad;
    }
};

}  // namespace

TEST_CASE("iqga: the pairing rule holds in every pair of a run", "[iqga]") {
    Ga<RegionTournamentSelection, PairChecker, IqgaMutation> ga;
    ga.population = 40;
    const Instance in = zhang2025_40();
    const auto r = ga.run(space_of(in), max_iterations(30), 4);
    CHECK(r.iterations == 30);
    CHECK(*ga.crossover.pairs == 30 * 20);
    CHECK(*ga.crossover.bad == 0);
}

// ---------------------------------------------------------------------------------------------
// Q-learning

namespace {

/// A chain mutation recording, per call, the generation and which operator it is.
struct RecordingChainMutation {
    std::shared_ptr<std::vector<std::pair<std::int64_t, std::size_t>>> calls;
    std::size_t which = 0;
    template <class P>
    void operator()(P&, typename P::chain_type&, Rng&, const GenerationContext& c) const {
        calls->emplace_back(c.iteration, which);
    }
};

}  // namespace

TEST_CASE("iqga: the Q-table learns once per generation, from the generation's best", "[iqga]") {
    auto calls = std::make_shared<std::vector<std::pair<std::int64_t, std::size_t>>>();
    Ga<RegionTournamentSelection, EliteCrossover,
       QLearningMutation<RecordingChainMutation, RecordingChainMutation, RecordingChainMutation>>
        ga;
    ga.population = 21;  // 20 children a generation
    ga.mutation.operators = {RecordingChainMutation{calls, 0}, RecordingChainMutation{calls, 1},
                             RecordingChainMutation{calls, 2}};
    ga.mutation.weights = {1.0, 0.0, 0.0};  // action a_i is operator i
    ga.mutation.learning.epsilon = 0.0;
    ga.mutation.probability = 1.0;
    const Instance in = zhang2025_20();
    const auto r = ga.run(space_of(in), max_iterations(60), 3);
    REQUIRE(calls->size() == 60 * 20);
    OperatorQLearning replay(ga.mutation.learning, ga.mutation.action_table());
    Rng unused(0);
    for (std::int64_t t = 0; t < 60; ++t) {
        replay.begin_generation(r.history[static_cast<std::size_t>(t)], unused);  // elitism 1: the best
        for (std::size_t k = 0; k < 20; ++k) {
            const auto& [iteration, which] = (*calls)[static_cast<std::size_t>(t) * 20 + k];
            REQUIRE(iteration == t);
            REQUIRE(which == replay.action());
        }
    }
    // One update per generation: after the first generation's state 2 every begin_generation
    // changes exactly one Q value (or none, when the update adds 0).
    OperatorQLearning q(QLearningSettings{}, orderings({0.6, 0.2, 0.2}));
    q.begin_generation(-1.0, unused);
    for (int s = 1; s <= 3; ++s)
        for (std::size_t a = 0; a < 3; ++a) CHECK(q.q(s, a) == 0.0);
    const std::size_t a0 = q.action();
    q.begin_generation(-1.5, unused);  // 2 -> 1: reward 1
    CHECK(q.q(2, a0) == Approx(0.1));
    int changed = 0;
    for (int s = 1; s <= 3; ++s)
        for (std::size_t a = 0; a < 3; ++a) changed += q.q(s, a) != 0.0;
    CHECK(changed == 1);
}

// ---------------------------------------------------------------------------------------------
// Whole runs

TEST_CASE("iqga: reproducible bit for bit", "[iqga]") {
    IqgaGa ga;
    ga.population = 40;
    const Instance in = zhang2025_40();
    const auto a = ga.run(space_of(in), max_iterations(40), 7);
    const auto b = ga.run(space_of(in), max_iterations(40), 7);
    REQUIRE(same_bits(a.best_f, b.best_f));
    REQUIRE(a.best_x == b.best_x);
    REQUIRE(a.evaluations == b.evaluations);
    REQUIRE(a.history.size() == b.history.size());
    for (std::size_t k = 0; k < a.history.size(); ++k) REQUIRE(same_bits(a.history[k], b.history[k]));
    const auto other = ga.run(space_of(in), max_iterations(40), 8);
    CHECK((other.history != a.history || other.best_x != a.best_x));
    for (std::size_t k = 1; k < a.history.size(); ++k) CHECK(a.history[k] <= a.history[k - 1]);
}

TEST_CASE("iqga: every member of every population is legal, on every bundled map and 200 random maps", "[iqga]") {
    std::vector<Instance> instances = bundled_instances();
    REQUIRE(instances.size() >= 5);
    const std::size_t bundled = instances.size();
    for (const auto& r : random_instances(2024, 200)) instances.push_back(r);
    REQUIRE(instances.size() == bundled + 200);
    for (std::size_t k = 0; k < instances.size(); ++k) {
        const Instance& in = instances[k];
        INFO("instance " << k << " " << in.map->width() << "x" << in.map->height() << " " << grid::to_string(in.start)
                         << " -> " << grid::to_string(in.goal));
        IqgaGa ga;
        ga.population = k < bundled ? 40 : 12;
        ga.mutation.probability = 0.5;  // more mutations than the default, to exercise them
        LegalityChecker checker{in};
        const auto r = ga.run(space_of(in), max_iterations(k < bundled ? 15 : 6), k, checker);
        CHECK(*checker.bad == 0);
        if (*checker.bad) FAIL_CHECK(*checker.first);
        CHECK(*checker.seen > 0);
        CHECK(grid::path_violation(*in.map, r.best_x, in.start, in.goal, in.corner_cutting).empty());
        CHECK(is_simple(r.best_x));
    }
}

TEST_CASE("iqga: budgets are exact", "[iqga]") {
    const Instance in = zhang2025_20();
    for (const std::int64_t budget : {1, 7, 39, 40, 41, 79, 250, 601}) {
        INFO("budget " << budget);
        IqgaGa ga;
        ga.population = 40;
        CountedSpace problem{space_of(in)};
        LegalityChecker checker{in};
        const auto r = ga.run(problem, max_evaluations(budget), 5, checker);
        CHECK(*problem.count == budget);
        CHECK(r.evaluations == budget);
        CHECK(r.history_evaluations.back() == budget);
        CHECK(std::isfinite(r.best_f));
        CHECK(*checker.bad == 0);
    }
    // Iterations: N + G (N - 1) whole chains, plus the SITP segments ranked by the objective (ten
    // walks per SITP path: two segments of N/8 = 5), every one counted.
    IqgaGa ga;
    ga.population = 40;
    CountedSpace problem{space_of(in)};
    const auto r = ga.run(problem, max_iterations(12), 5);
    CHECK(r.iterations == 12);
    CHECK(*problem.count == r.evaluations);
    CHECK(r.evaluations >= 40 + 12 * 39 + 40 * 10);  // the initial SITP paths' segments at least
    // Ranked by length, SITP evaluates nothing: N + G (N - 1) evaluations.
    CountedSpace by_length{space_of(in)};
    by_length.space.set_sitp(false, grid::SitpScore::length);
    const auto l = ga.run(by_length, max_iterations(12), 5);
    CHECK(*by_length.count == 40 + 12 * 39);
    CHECK(l.evaluations == 40 + 12 * 39);
}

// ---------------------------------------------------------------------------------------------
// The registry entry

TEST_CASE("iqga: registry entry, defaults, N = 40 on grids, SITP by default, chains only", "[iqga][engine]") {
    const auto* e = engine::algorithms().find("iqga");
    REQUIRE(e != nullptr);
    CHECK(e->family == "ga");
    CHECK(e->spaces() == std::vector<std::string>{"chain"});
    CHECK(e->grid_population == 40);
    const std::map<std::string, double> defaults{{"pop", 40},      {"elite", 20},  {"pc", 0.9},    {"pm", 0.1},
                                                 {"epsilon", 0.1}, {"alpha", 0.1}, {"gamma", 0.9}, {"sitp", 1}};
    for (const auto& [name, value] : defaults) {
        INFO(name);
        const auto* p = e->param(name);
        REQUIRE(p != nullptr);
        REQUIRE(p->default_value.has_value());
        CHECK(*p->default_value == Approx(value));
    }

    engine::GridSpec g;
    g.map = engine::load_map((bundled_maps() / "zhang2025-20x20.map").string());
    const auto scen = grid::read_scenario((bundled_maps() / "zhang2025-20x20.map.scen").string());
    g.start = scen.at(0).start;
    g.goal = scen.at(0).goal;
    g.encoding = "chain";
    g.objective = "iqga";
    engine::Budget budget;
    budget.iterations = 10;
    const auto plain = engine::run({"iqga", {}}, engine::Problem(g), budget, 2);
    REQUIRE(plain.grid.has_value());
    CHECK(plain.grid->feasible);
    // N = 40 on grids, each SITP path's two segments the best of 5 walks by the objective: 10
    // counted evaluations per path before the path's own.
    CHECK(plain.history_evaluations.front() == 40 + 40 * 10);
    CHECK(plain.evaluations > 40 + 10 * 39);
    engine::AlgorithmSpec by_length{"iqga", {}};
    by_length.params.set_name("sitp_score", "length");
    const auto ranked_by_length = engine::run(by_length, engine::Problem(g), budget, 2);
    CHECK(ranked_by_length.history_evaluations.front() == 40);
    CHECK(ranked_by_length.evaluations == 40 + 10 * 39);
    CHECK(plain.history == engine::run({"iqga", {}}, engine::Problem(g), budget, 2).history);
    // SITP by default: the same run as init = "sitp", not the same as random-walk chains.
    g.init = "sitp";
    const auto sitp = engine::run({"iqga", {}}, engine::Problem(g), budget, 2);
    CHECK(sitp.history == plain.history);
    CHECK(sitp.grid->path == plain.grid->path);
    g.init = "walk";
    const auto walks = engine::run({"iqga", {}}, engine::Problem(g), budget, 2);
    CHECK(walks.history.front() != plain.history.front());
    engine::AlgorithmSpec off{"iqga", {}};
    off.params.set("sitp", 0);
    g.init = "";
    const auto off_run = engine::run(off, engine::Problem(g), budget, 2);
    CHECK(off_run.history == walks.history);
    // A population given is kept.
    engine::AlgorithmSpec small{"iqga", {}};
    small.params.set("pop", 12);
    small.params.set_name("sitp_score", "length");
    CHECK(engine::run(small, engine::Problem(g), budget, 2).history_evaluations.front() == 12);
    // Ranges; boxes are refused.
    engine::AlgorithmSpec bad{"iqga", {}};
    bad.params.set("pc", 1.5);
    CHECK_THROWS_AS(engine::run(bad, engine::Problem(g), budget, 1), InputError);
    const engine::Problem sphere(engine::ContinuousSpec{"sphere", 3});
    CHECK_THROWS_AS(engine::run({"iqga", {}}, sphere, budget, 1), InputError);
    g.encoding = "line";
    CHECK_THROWS_AS(engine::run({"iqga", {}}, engine::Problem(g), budget, 1), InputError);
}

namespace {

/// Records, per generation, the length of the best member (the first of the smallest values).
struct BestLengthRecorder {
    std::shared_ptr<std::vector<double>> lengths = std::make_shared<std::vector<double>>();
    template <class View>
    void operator()(const View& view) const {
        const std::vector<grid::Path>& pop = view.population;
        const auto best =
            static_cast<std::size_t>(std::min_element(view.fitness.begin(), view.fitness.end()) - view.fitness.begin());
        lengths->push_back(grid::metrics(pop[best], false).length);
    }
};

/// RecordingChainMutation's operators inside a by-length Q-learning mutation that asks for lengths.
struct ByLengthMutation : QLearningMutation<RecordingChainMutation, RecordingChainMutation, RecordingChainMutation> {
    static constexpr bool uses_best_length = true;
};

}  // namespace

TEST_CASE("iqga: the Q-learning states follow the best path's length", "[iqga]") {
    static_assert(ChainLength<Space>);
    auto calls = std::make_shared<std::vector<std::pair<std::int64_t, std::size_t>>>();
    Ga<RegionTournamentSelection, EliteCrossover, ByLengthMutation> ga;
    ga.population = 21;
    ga.mutation.operators = {RecordingChainMutation{calls, 0}, RecordingChainMutation{calls, 1},
                             RecordingChainMutation{calls, 2}};
    ga.mutation.weights = {1.0, 0.0, 0.0};
    ga.mutation.learning.epsilon = 0.0;
    ga.mutation.probability = 1.0;
    ga.mutation.by_length = true;
    CHECK(IqgaMutation{}.by_length);
    CHECK(IqgaMutation{}.probability == 0.1);
    const Instance in = zhang2025_40();
    // Real crossovers move the best path: the IQGA operators do the variation, the recording
    // mutation only watches (so the lengths come from crossover and selection).
    BestLengthRecorder lengths;
    const auto r = ga.run(space_of(in), max_iterations(80), 6, lengths);
    REQUIRE(r.iterations == 80);
    REQUIRE(lengths.lengths->size() == 81);
    REQUIRE(calls->size() == 80 * 20);
    OperatorQLearning replay(ga.mutation.learning, ga.mutation.action_table());
    Rng unused(0);
    for (std::int64_t t = 0; t < 80; ++t) {
        replay.begin_generation((*lengths.lengths)[static_cast<std::size_t>(t)], unused);
        for (std::size_t k = 0; k < 20; ++k) {
            const auto& [iteration, which] = (*calls)[static_cast<std::size_t>(t) * 20 + k];
            REQUIRE(iteration == t);
            REQUIRE(which == replay.action());
        }
    }
}

TEST_CASE("iqga: the ablation flags each remove one change, and only that one", "[iqga][ablation]") {
    // regions = false: the whole population is one region; the pool no longer depends on the regions.
    Rng make(5);
    const std::size_t n = 40;
    std::vector<double> f(n);
    std::vector<std::size_t> regions_a(n), regions_b(n, 1);
    for (std::size_t i = 0; i < n; ++i) {
        f[i] = -(1.0 + make.uniform());
        regions_a[i] = make.below(3);
    }
    auto pool_of = [&](bool regions, const std::vector<std::size_t>& r) {
        RegionTournamentSelection s;
        s.regions = regions;
        auto prepared = s.prepare(0);
        Rng rng(11);
        prepared.begin_generation(context_of(f, r), rng);
        return std::vector<std::size_t>(prepared.pool().begin(), prepared.pool().end());
    };
    CHECK(pool_of(false, regions_a) == pool_of(false, regions_b));
    CHECK(pool_of(true, regions_a) != pool_of(true, regions_b));
    const auto flat = pool_of(false, regions_a);
    CHECK(flat.size() >= n + 1);  // N tournaments, each keeps its best, plus the population's best
    CHECK(flat.size() <= 3 * n + 1);

    // pairing = false: pairs without an elite member occur; with it they never do.
    std::vector<char> elite;
    std::vector<std::size_t> order;
    iqga::elite_flags(f, iqga::elite_size(20, n), elite, order);
    for (const bool pairing : {true, false}) {
        RegionTournamentSelection s;
        s.pairing = pairing;
        auto prepared = s.prepare(0);
        Rng rng(2);
        prepared.begin_generation(context_of(f, regions_a), rng);
        int without = 0;
        for (int k = 0; k < 2000; ++k) {
            const std::size_t a = prepared(f, rng), b = prepared(f, rng);
            without += !elite[a] && !elite[b];
        }
        if (pairing)
            CHECK(without == 0);
        else
            CHECK(without > 0);
    }

    // elite_only = false: a pair of two non-elite members is crossed too.
    const Instance in = zhang2025_20();
    Space space = space_of(in);
    Rng rng(9);
    std::vector<double> g{-3.0, -2.0, -1.0, -0.5};  // elite: members 0 and 1
    GenerationContext c;
    c.describe(0, g, -3.0);
    c.parents = {2, 3};
    for (const bool elite_only : {true, false}) {
        EliteCrossover crossover;
        crossover.probability = 1.0;
        crossover.elite_only = elite_only;
        auto x = crossover.prepare(0);
        x.begin_generation(c, rng);
        int crossed = 0;
        for (int k = 0; k < 30; ++k) {
            grid::Path p, q;
            space.random_chain(rng, p, test::uncounted_score(space));
            space.random_chain(rng, q, test::uncounted_score(space));
            grid::Path a = p, b = q;
            x(space, a, b, rng, c);
            crossed += a != p || b != q;
            CHECK(grid::path_violation(space.problem().map(), a, in.start, in.goal).empty());
            CHECK(grid::path_violation(space.problem().map(), b, in.start, in.goal).empty());
        }
        if (elite_only)
            CHECK(crossed == 0);
        else
            CHECK(crossed > 0);
    }
}

TEST_CASE("iqga: the ablation flags through the engine: defaults, legal results, each its own run",
          "[iqga][ablation][engine]") {
    const auto* e = engine::algorithms().find("iqga");
    REQUIRE(e != nullptr);
    for (const char* name : {"regions", "elite_crossover", "qlearning"}) {
        INFO(name);
        const auto* p = e->param(name);
        REQUIRE(p != nullptr);
        REQUIRE(p->default_value.has_value());
        CHECK(*p->default_value == 1.0);
    }
    engine::GridSpec g;
    g.map = engine::load_map((bundled_maps() / "zhang2025-20x20.map").string());
    const auto scen = grid::read_scenario((bundled_maps() / "zhang2025-20x20.map.scen").string());
    g.start = scen.at(0).start;
    g.goal = scen.at(0).goal;
    g.encoding = "chain";
    g.objective = "iqga";
    engine::Budget budget;
    budget.iterations = 30;
    const auto full = engine::run({"iqga", {}}, engine::Problem(g), budget, 4);
    engine::AlgorithmSpec all_on{"iqga", {}};
    for (const char* name : {"regions", "elite_crossover", "qlearning"}) all_on.params.set(name, 1);
    CHECK(engine::run(all_on, engine::Problem(g), budget, 4).history == full.history);  // 1 = the default
    for (const char* name : {"sitp", "regions", "elite_crossover", "qlearning"}) {
        INFO(name);
        engine::AlgorithmSpec off{"iqga", {}};
        off.params.set(name, 0);
        const auto r = engine::run(off, engine::Problem(g), budget, 4);
        REQUIRE(r.grid.has_value());
        CHECK(r.grid->feasible);
        CHECK(grid::path_violation(*g.map, r.grid->path, g.start, g.goal).empty());
        // SITP's segment scores are evaluations: the count follows how many mutations regenerate.
        if (std::string(name) == "sitp") CHECK(r.evaluations < full.evaluations);
        // On this map every path of these runs lies in the middle region, so eq. 16 sends all N
        // tournaments there and regions = 0 draws the same: the policy test above tells them apart.
        if (std::string(name) != "regions") CHECK(r.history != full.history);
        CHECK(engine::run(off, engine::Problem(g), budget, 4).history == r.history);  // reproducible
    }
}

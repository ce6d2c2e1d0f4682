// Every call of an objective is an evaluation (docs/architecture.md): counted from outside,
// by the objective itself, for every registered algorithm on every space and encoding it runs on
// and every grid objective, the calls must equal the result's `evaluations` and stay within the
// budget. Iterated over the registry, so that an algorithm registered tomorrow is covered.
#include <catch2/catch.hpp>

#include <atomic>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "engine/registry.hpp"
#include "engine/run.hpp"
#include "problems/grid/path.hpp"
#include "tests/test_support.hpp"

namespace {

using namespace pride;

struct Space {
    std::string encoding, connector;
};

/// The spaces of a grid `entry` plans on: the box encodings with each connector, and chains.
std::vector<Space> grid_spaces(const engine::AlgorithmEntry& entry) {
    std::vector<Space> out;
    if (entry.runs(engine::Kind::box))
        for (const char* encoding : {"line", "free"})
            for (const char* connector : {"repair", "penalty"}) out.push_back({encoding, connector});
    if (entry.runs(engine::Kind::chain)) out.push_back({"chain", "repair"});
    return out;
}

/// One run on Zhang et al.'s (2025) 20 x 20 map (obstacles on the way, where SITP, shortcuts and repairs all
/// have work), the objective counting its calls.
engine::RunResult counted_run(const std::string& algo, const Space& s, const std::string& objective,
                              engine::Budget budget, std::int64_t& calls) {
    engine::GridSpec g;
    g.map = engine::load_map((std::filesystem::path(PRIDE_SOURCE_DIR) / "examples/maps/zhang2025-20x20.map").string());
    g.start = {0, 19};
    g.goal = {19, 0};
    g.objective = objective;
    g.encoding = s.encoding;
    g.connector = s.connector;
    g.objective_calls = std::make_shared<std::atomic<std::int64_t>>(0);
    engine::AlgorithmSpec a{algo, {}};
    if (const auto* e = engine::algorithms().find(algo); e && e->param("pop")) a.params.set("pop", 8);
    const auto r = engine::run(a, engine::Problem(g), budget, 7);
    calls = g.objective_calls->load();
    return r;
}

}  // namespace

TEST_CASE("counting: every grid algorithm's objective calls are its evaluations, within the budget",
          "[counting][grid]") {
    int covered = 0;
    for (const auto& entry : engine::algorithms().entries()) {
        if (entry.runs(engine::Kind::grid)) continue;  // A*, the exact optimum: no objective evaluations
        if (entry.name.rfind("nlopt:", 0) == 0 && entry.name != "nlopt:LN_SBPLX" && entry.name != "nlopt:GN_CRS2_LM")
            continue;  // one adapter for every NLopt algorithm: two of them stand for the rest
        for (const Space& s : grid_spaces(entry))
            for (const std::string objective : {"cells", "length", "weighted", "hswoa", "iqga"}) {
                INFO(entry.name << " on " << s.encoding << " (" << s.connector << "), objective " << objective);
                ++covered;
                for (const std::int64_t n : {1, 97, 400}) {
                    INFO("--evals " << n);
                    engine::Budget b;
                    b.evaluations = n;
                    std::int64_t calls = 0;
                    const auto r = counted_run(entry.name, s, objective, b, calls);
                    CHECK(calls == r.evaluations);
                    CHECK(r.evaluations == n);
                }
                engine::Budget b;
                b.iterations = 2;
                // L-SHADE and jSO need an evaluation limit (their schedules run over it).
                if (entry.name == "lshade" || entry.name == "jso" || entry.name == "colshade")
                    b.evaluations = 1'000'000;
                std::int64_t calls = 0;
                const auto r = counted_run(entry.name, s, objective, b, calls);
                INFO("--iters 2");
                CHECK(calls == r.evaluations);
                CHECK(r.evaluations > 0);
            }
    }
    CHECK(covered >= 100);
}

TEST_CASE("counting: the chain space's scoring settings spend counted evaluations only", "[counting][grid]") {
    // SITP ranked by the objective, and shortcuts kept only when not worse, cost evaluations; each
    // is counted, and ranked by length / kept unconditionally they cost none beyond the chains'.
    for (const std::string algo : {"iqga", "ga", "hswoa"}) {
        for (const std::string setting :
             {"sitp_score=objective", "sitp_score=length", "shortcut_keep=1", "shortcut=elbow", "walks=eq10"}) {
            INFO(algo << " " << setting);
            engine::GridSpec g;
            g.map = engine::load_map(
                (std::filesystem::path(PRIDE_SOURCE_DIR) / "examples/maps/zhang2025-20x20.map").string());
            g.start = {0, 19};
            g.goal = {19, 0};
            g.objective = algo == "iqga" ? "iqga" : "hswoa";
            g.encoding = "chain";
            g.init = algo == "ga" ? "sitp" : "";
            g.objective_calls = std::make_shared<std::atomic<std::int64_t>>(0);
            engine::AlgorithmSpec a{algo, {}};
            a.params.set_from_string(setting);
            if (setting == "shortcut_keep=1") a.params.set_name("shortcut", "line");
            engine::Budget b;
            b.evaluations = 333;
            const auto r = engine::run(a, engine::Problem(g), b, 3);
            CHECK(g.objective_calls->load() == 333);
            CHECK(r.evaluations == 333);
            REQUIRE(r.grid.has_value());
            CHECK(r.grid->feasible);
        }
    }
}

TEST_CASE("counting: every box algorithm's calls of a user function are its evaluations", "[counting][box]") {
    int covered = 0;
    for (const auto& entry : engine::algorithms().entries()) {
        if (!entry.runs(engine::Kind::box)) continue;
        INFO(entry.name);
        ++covered;
        for (const std::int64_t n : {1, 61, 300}) {
            auto calls = std::make_shared<std::int64_t>(0);
            engine::CallbackSpec cb;
            cb.lower = {-2.0, -2.0, -2.0};
            cb.upper = {2.0, 2.0, 2.0};
            cb.scalar = [calls](std::span<const double> x) {
                ++*calls;
                return x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
            };
            engine::Budget b;
            b.evaluations = n;
            const auto r = engine::run({entry.name, {}}, engine::Problem(cb), b, 5);
            CHECK(*calls == r.evaluations);
            CHECK(r.evaluations <= n);
        }
    }
    CHECK(covered >= 14);
}

TEST_CASE("counting: every algorithm that handles constraints counts each constrained evaluation once",
          "[counting][box][constraints]") {
    int covered = 0;
    for (const auto& entry : engine::algorithms().entries()) {
        if (!entry.runs(engine::Kind::constrained_box)) continue;
        ++covered;
        // Each of its handlers (COLSHADE has its own rules and no `constraints`): the GA's apm and
        // CMA-ES's stochastic-ranking among them.
        std::vector<std::string> handlers{""};
        if (const auto* spec = entry.param("constraints")) handlers = spec->choices;
        for (const auto& handler : handlers) {
            for (const std::int64_t n : {1, 61, 300}) {
                INFO(entry.name << " " << handler << " " << n);
                auto calls = std::make_shared<std::int64_t>(0);
                engine::CallbackSpec cb;
                cb.lower = {-2.0, -2.0, -2.0};
                cb.upper = {2.0, 2.0, 2.0};
                cb.inequalities = 1;
                cb.equalities = 1;
                cb.constrained = [calls](std::span<const double> x, std::span<double> c) {
                    ++*calls;
                    c[0] = 1.0 - x[0] - x[1];
                    c[1] = x[2] - 0.5;
                    return x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
                };
                engine::Budget b;
                b.evaluations = n;
                engine::AlgorithmSpec a{entry.name, {}};
                if (!handler.empty()) a.params.set_from_string("constraints=" + handler);
                const auto r = engine::run(a, engine::Problem(cb), b, 5);
                CHECK(*calls == r.evaluations);
                CHECK(r.evaluations <= n);
            }
        }
    }
    CHECK(covered >= 15);  // pso (2), the DE family and COLSHADE (7), CMA-ES (4), ga and ga-plus (2)
}

TEST_CASE("counting: a user's objective on paths runs with every grid algorithm, each call an evaluation",
          "[counting][grid][user]") {
    // The length of a path, by the user's own function, counting its calls; its per-step form:
    // 1 orthogonal, sqrt(2) diagonal, whatever the previous step.
    auto calls = std::make_shared<std::int64_t>(0);
    auto user = std::make_shared<engine::UserPathObjective>();
    user->value = [calls](const grid::Path& p) {
        ++*calls;
        return grid::metrics(p, false).length;
    };
    user->step_cost = [](int, int d) { return d % 2 == 0 ? 1.0 : std::sqrt(2.0); };
    engine::GridSpec g;
    g.map = engine::load_map((std::filesystem::path(PRIDE_SOURCE_DIR) / "examples/maps/zhang2025-20x20.map").string());
    g.start = {0, 19};
    g.goal = {19, 0};
    g.objective = "user";
    g.path_objective = user;
    const engine::Problem problem(g);
    int covered = 0;
    for (const auto& entry : engine::algorithms().entries()) {
        if (entry.runs(engine::Kind::grid) || (entry.name.rfind("nlopt:", 0) == 0 && entry.name != "nlopt:LN_SBPLX"))
            continue;
        for (const std::string& encoding : entry.encodings()) {
            INFO(entry.name << " on " << encoding);
            ++covered;
            engine::AlgorithmSpec a{entry.name, {}};
            a.params.set_name("encoding", encoding);
            engine::Budget b;
            b.evaluations = 150;
            *calls = 0;
            const auto r = engine::run(a, problem, b, 2);
            CHECK(*calls == r.evaluations);  // the reported value is the run's own, not a new call
            CHECK(r.evaluations == 150);
            REQUIRE(r.grid.has_value());
            if (r.grid->feasible) CHECK(r.grid->value == grid::metrics(r.grid->path, false).length);
        }
    }
    CHECK(covered >= 30);
    // exact: the oracle on the per-step costs, the same optimum as the length objective's.
    engine::GridSpec length = g;
    length.objective = "length";
    length.path_objective = nullptr;
    // Whole-map planners value their path by the step costs: no call of the objective.
    *calls = 0;
    const auto by_user = engine::run({"exact", {}}, problem, {}, 1);
    const auto astar = engine::run({"astar", {}}, problem, {}, 1);
    CHECK(*calls == 0);
    const auto by_length = engine::run({"exact", {}}, engine::Problem(length), {}, 1);
    REQUIRE(by_user.grid->optimum.has_value());
    CHECK(*by_user.grid->optimum == Approx(*by_length.grid->optimum).epsilon(1e-12));
    CHECK(by_user.grid->value == Approx(*by_length.grid->optimum).epsilon(1e-12));
    CHECK(astar.grid->value == Approx(*by_length.grid->optimum).epsilon(1e-12));
    // Per-step costs that do not sum to the objective show when a run beats their optimum: refused.
    // So are negative ones.
    auto wrong = std::make_shared<engine::UserPathObjective>(*user);
    wrong->step_cost = [](int, int) { return 10.0; };
    engine::GridSpec w = g;
    w.path_objective = wrong;
    w.oracle = true;
    engine::AlgorithmSpec ga{"ga", {}};
    ga.params.set_name("encoding", "chain");
    CHECK_THAT(test::input_error_message([&] {
                   engine::Budget b;
                   b.evaluations = 60;
                   engine::run(ga, engine::Problem(w), b, 1);
               }),
               Catch::Contains("step_cost: the per-step costs give an optimum of"));
    w.oracle = false;
    auto negative = std::make_shared<engine::UserPathObjective>(*user);
    negative->step_cost = [](int, int) { return -1.0; };
    w.path_objective = negative;
    CHECK_THAT(test::input_error_message([&] {
                   engine::run({"exact", {}}, engine::Problem(w), {}, 1);
               }),
               Catch::Contains("step_cost: must be a finite number >= 0"));
    // Without per-step costs there is no exact optimum, said so.
    auto plain = std::make_shared<engine::UserPathObjective>();
    plain->value = user->value;
    w.path_objective = plain;
    CHECK_THAT(test::input_error_message([&] {
                   engine::run({"exact", {}}, engine::Problem(w), {}, 1);
               }),
               Catch::Contains("the user objective has no per-step costs (step_cost), so exact has no optimum"));
    // The objective user comes with a function, and a function with the objective user.
    engine::GridSpec missing = g;
    missing.path_objective = nullptr;
    CHECK_THAT(test::input_error_message([&] { engine::Problem{missing}; }), Catch::Contains("user needs"));
}

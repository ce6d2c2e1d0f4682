// Tests of the runtime library (engine/): parameters declared once and checked, the registry, the
// run function against the typed algorithms, callback problems, sizes checked before allocation,
// campaigns built from structs, and errors that name spec fields rather than command-line flags.
#include <catch2/catch.hpp>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "algorithms/ga.hpp"
#include "algorithms/pso.hpp"
#include "engine/params.hpp"
#include "engine/registry.hpp"
#include "engine/run.hpp"
#include "experiment/campaign/prepare.hpp"
#include "experiment/campaign/run.hpp"
#include "experiment/campaign/run_one.hpp"
#include "framework/error.hpp"
#include "problems/continuous/functions.hpp"
#include "tests/test_support.hpp"

using Catch::Matchers::Contains;
using pride::test::input_error_message;
namespace campaign = pride::campaign;
namespace engine = pride::engine;

namespace {

engine::Budget evals(std::int64_t n) {
    engine::Budget b;
    b.evaluations = n;
    return b;
}

engine::AlgorithmSpec algo(const std::string& name, std::initializer_list<std::pair<const char*, double>> params = {}) {
    engine::AlgorithmSpec a{name, {}};
    for (const auto& [k, v] : params) a.params.set(k, v);
    return a;
}

std::string map_file() {
    return (std::filesystem::path(PRIDE_SOURCE_DIR) / "examples" / "maps" / "wan2022-10x10.map").string();
}

}  // namespace

TEST_CASE("engine: choice parameters take one of their names, nothing else", "[engine][params]") {
    const std::vector<engine::ParamSpec> specs{
        engine::choice("shortcut", {"none", "line", "elbow"}, "line", "a shortcut"),
        engine::real("pc", 0.9, 0.0, 1.0, "crossover")};
    CHECK(specs[0].type == engine::ParamType::choice);
    CHECK(specs[0].range() == "none, line or elbow");
    CHECK(specs[0].default_text() == "line");
    CHECK(engine::Params("algo", specs, {}).choice("shortcut") == "line");  // the default
    engine::ParamValues v;
    v.set_from_string("shortcut=elbow");
    CHECK(engine::Params("algo", specs, v).choice("shortcut") == "elbow");
    v.set("shortcut", 1.0);  // a later set wins, and a number is no name
    CHECK_THAT(input_error_message([&] { engine::Params("algo", specs, v); }),
               Contains("shortcut takes a name: none, line or elbow"));
    v.set_name("shortcut", "zigzag");
    CHECK_THAT(input_error_message([&] { engine::Params("algo", specs, v); }),
               Contains("algo: shortcut must be none, line or elbow (a shortcut), got 'zigzag'"));
    engine::ParamValues w;
    w.set_name("pc", "high");
    CHECK_THAT(input_error_message([&] { engine::Params("algo", specs, w); }),
               Contains("pc must be a finite number in [0, 1], got 'high'"));
    CHECK_THROWS_AS(engine::choice("x", {"a", "b"}, "c", "a default not among the choices"), pride::InputError);
    // Every registered choice parameter's default is one of its names, and every chain-space
    // setting is declared alike by every algorithm that plans on chains.
    for (const auto& e : engine::algorithms().entries()) {
        for (const auto& p : e.params)
            if (p.type == engine::ParamType::choice) {
                INFO(e.name << " " << p.name);
                // The grid settings have none: the problem's, else the native encoding, applies.
                if (p.grid_only) {
                    CHECK_FALSE(p.default_value.has_value());
                    continue;
                }
                REQUIRE(p.default_value.has_value());
                CHECK(*p.default_value < static_cast<double>(p.choices.size()));
            }
        if (!e.runs(engine::Kind::chain)) continue;
        for (const char* name : {"shortcut", "shortcut_keep", "walks", "sitp_column", "sitp_score"}) {
            INFO(e.name << " " << name);
            REQUIRE(e.param(name) != nullptr);
            CHECK(e.param(name)->chain_only);
        }
    }
}

TEST_CASE("engine: parameter values parse NAME=VALUE strictly", "[engine][params]") {
    engine::ParamValues v;
    v.set_from_string("a=1.5");
    v.set_from_string("b=-2e-3");
    v.set_from_string("a=7");  // a later set wins
    CHECK(v.find("a") == 7.0);
    CHECK(v.find("b") == -2e-3);
    CHECK_FALSE(v.contains("c"));
    // A value that is not a number is a name (for a choice parameter, checked against its choices
    // by Params): it starts with a letter and holds letters, digits, '_' and '-' only.
    v.set_from_string("shortcut=line");
    CHECK(v.names().at("shortcut") == "line");
    CHECK_FALSE(v.find("shortcut"));
    for (const char* bad : {"a", "=1", "a=inf", "a=-inf", "a=nan", "a=", "a=1.5x", "a=1e999", "a=-x", "a=x y", ""}) {
        INFO("'" << bad << "'");
        engine::ParamValues q;
        const auto msg = input_error_message([&] { q.set_from_string(bad); });
        CHECK_THAT(msg, Contains("parameter"));
        CHECK_FALSE(q.contains("a"));
    }
}

TEST_CASE("engine: parameters are checked against their declared type and range", "[engine][params]") {
    const std::vector<engine::ParamSpec> specs{engine::integer("pop", 20, 2, 1000, "population size"),
                                               engine::real("w", 0.5, 0.0, 1.0, "a weight").open_below(),
                                               engine::flag("walk", false, "a switch"),
                                               engine::real("step", 0.0, 0.0, 1.0, "a step").no_default()};
    engine::ParamValues given;
    const engine::Params defaults("toy", specs, given);
    CHECK(defaults.integer("pop") == 20);
    CHECK(defaults.real("w") == 0.5);
    CHECK_FALSE(defaults.flag("walk"));
    CHECK_FALSE(defaults.optional("step").has_value());
    CHECK_THROWS_AS(defaults.real("undeclared"), std::logic_error);

    auto refused = [&](const char* name, double value) {
        engine::ParamValues v;
        v.set(name, value);
        return input_error_message([&] { engine::Params("toy", specs, v); });
    };
    CHECK_THAT(refused("pop", 1),
               Contains("toy") && Contains("pop") && Contains("[2, 1000]") && Contains("population size"));
    CHECK_THAT(refused("pop", 2.5), Contains("pop") && Contains("integer"));
    CHECK_THAT(refused("w", 0.0), Contains("(0, 1]"));  // open below
    CHECK_THAT(refused("walk", 2), Contains("0 or 1"));
    CHECK_THAT(refused("nosuch", 1), Contains("unknown parameter 'nosuch'") && Contains("pop, w, walk, step"));
    engine::ParamValues ok;
    ok.set("w", 1.0);
    ok.set("step", 0.25);
    const engine::Params p("toy", specs, ok);
    CHECK(p.real("w") == 1.0);
    CHECK(p.optional("step") == 0.25);
    CHECK(p.given("w"));
    CHECK_FALSE(p.given("pop"));
}

TEST_CASE("engine: the registry lists every family with its spaces and parameters", "[engine][registry]") {
    const auto& r = engine::algorithms();
    for (const char* name : {"pso", "pso-constriction", "ga", "ga-plus", "lso", "ilso", "astar", "exact",
                             "nlopt:LN_SBPLX", "nlopt:GN_CRS2_LM"}) {
        INFO(name);
        REQUIRE(r.find(name) != nullptr);
        CHECK_FALSE(r.at(name).summary.empty());
    }
    CHECK(r.at("ga").spaces() == std::vector<std::string>{"box", "chain", "constrained box"});
    CHECK(r.at("ga-plus").spaces() == std::vector<std::string>{"box", "chain", "constrained box"});
    CHECK(r.at("pso").spaces() == std::vector<std::string>{"box", "constrained box"});
    CHECK(r.at("astar").spaces() == std::vector<std::string>{"grid"});
    CHECK(r.at("exact").needs_optimum);
    CHECK(r.at("astar").params.empty());
    // Variants are configurations of a family, with their own defaults.
    CHECK(r.at("ilso").family == "lso");
    CHECK(r.at("ilso").param("walk_init")->default_value == 1.0);
    CHECK(r.at("lso").param("walk_init")->default_value == 0.0);
    CHECK(r.at("ilso").param("cub_first")->default_value == 0.3);
    CHECK(r.at("pso-constriction").param("chi")->default_value == 0.7298);
    CHECK(r.at("ga-plus").param("elitism") == nullptr);
    CHECK_FALSE(r.at("ga").param("pm")->default_value.has_value());              // 1/D on boxes, 0.1 on chains
    for (const auto& e : r.entries()) CHECK(e.name.rfind("nlopt:LD_", 0) != 0);  // gradients: not here

    CHECK_THAT(input_error_message([&] { r.at("nosuch"); }), Contains("algo") && Contains("'nosuch'"));
    CHECK_THAT(input_error_message([&] { r.at("nlopt:LD_MMA"); }), Contains("LD_MMA"));
    engine::AlgorithmRegistry local;
    engine::AlgorithmEntry e = r.at("astar");
    local.add(e);
    CHECK_THROWS_AS(local.add(e), std::logic_error);  // a duplicate name
    engine::AlgorithmEntry empty;
    empty.name = "nothing";
    CHECK_THROWS_AS(local.add(empty), std::logic_error);  // no runner
}

TEST_CASE("engine: a run through the registry equals the typed run, bit for bit", "[engine][run]") {
    const engine::Problem sphere(engine::ContinuousSpec{"sphere", 5});
    pride::Pso<pride::InertiaVelocity<pride::LinearInertia>, pride::RangeVelocityClamp, pride::Clamp,
               pride::SelectableInit>
        typed;
    const auto direct = typed.run(pride::continuous::Sphere(5), pride::max_evaluations(1000), 3);
    const auto r = engine::run(algo("pso"), sphere, evals(1000), 3);
    CHECK(r.best_f == direct.best_f);
    CHECK(r.best_x == direct.best_x);
    CHECK(r.history == direct.history);
    CHECK(r.evaluations == 1000);

    pride::Ga<pride::TournamentSelection, pride::SbxCrossover, pride::PolynomialMutation, pride::Clamp,
              pride::UniformInit, pride::PlusReplacement>
        plus;
    plus.id = "ga-plus";
    plus.population = 30;
    const auto gd = plus.run(pride::continuous::Sphere(5), pride::max_evaluations(999), 4);
    const auto gr = engine::run(algo("ga-plus", {{"pop", 30}}), sphere, evals(999), 4);
    CHECK(gr.best_x == gd.best_x);
    CHECK(gr.history == gd.history);
    CHECK(gr.evaluations == 999);
}

TEST_CASE("engine: callback problems run every box algorithm, scalar or batch, with the same bits",
          "[engine][callback]") {
    auto sphere = [](std::span<const double> x) {
        double f = 0.0;
        for (double v : x) f += v * v;
        return f;
    };
    std::atomic<int> batches{0};
    std::atomic<long> batch_points{0};
    engine::CallbackSpec scalar{"mine", std::vector<double>(4, -5.12), std::vector<double>(4, 5.12), sphere, {}};
    engine::CallbackSpec batch = scalar;
    batch.scalar = {};
    batch.batch = [&](pride::MatrixView points, std::span<double> values) {
        ++batches;
        batch_points += points.cols();
        REQUIRE(static_cast<std::size_t>(points.cols()) == values.size());
        for (Eigen::Index j = 0; j < points.cols(); ++j)
            values[static_cast<std::size_t>(j)] = points.col(j).squaredNorm();
    };
    const engine::Problem registered(engine::ContinuousSpec{"sphere", 4});
    const engine::Problem by_scalar(scalar), by_batch(batch);
    CHECK(by_scalar.dimension() == 4);
    for (const char* name : {"pso", "pso-constriction", "ga", "lso", "ilso", "nlopt:LN_SBPLX"}) {
        INFO(name);
        const auto reference = engine::run(algo(name), registered, evals(777), 5);
        const auto s = engine::run(algo(name), by_scalar, evals(777), 5);
        CHECK(s.evaluations == 777);
        CHECK(s.history == reference.history);
        CHECK(s.best_x == reference.best_x);
        const auto b = engine::run(algo(name), by_batch, evals(777), 5);
        CHECK(b.evaluations == 777);
        CHECK(b.best_x == s.best_x);  // squaredNorm sums in the same order
    }
    CHECK(batches > 0);
    CHECK(batch_points > 0);
    // A NaN from user code is never the best.
    engine::CallbackSpec nan = scalar;
    nan.scalar = [](std::span<const double> x) { return x[0] > 0 ? std::nan("") : x[0] * x[0]; };
    const auto r = engine::run(algo("pso"), engine::Problem(nan), evals(500), 1);
    CHECK(std::isfinite(r.best_f));
    CHECK(r.best_x[0] <= 0.0);
    // A box that is not one is refused.
    engine::CallbackSpec bad = scalar;
    bad.upper = std::vector<double>(3, 1.0);
    CHECK_THAT(input_error_message([&] { engine::Problem{bad}; }), Contains("mine") && Contains("coordinates"));
    bad = scalar;
    bad.scalar = {};
    CHECK_THAT(input_error_message([&] { engine::Problem{bad}; }), Contains("no function"));
}

TEST_CASE("engine: sizes are checked before anything is allocated", "[engine][memory]") {
    const engine::Problem sphere(engine::ContinuousSpec{"sphere", 10});
    const auto huge_pop = input_error_message([&] { engine::check(algo("pso", {{"pop", 2e9}}), sphere, evals(100)); });
    CHECK_THAT(huge_pop, Contains("pso") && Contains("2000000000") && Contains("memory") && Contains("GB"));
    CHECK_THAT(input_error_message([&] {
                   engine::run(algo("ga", {{"pop", 3e9}}), sphere, evals(100), 1);
               }),
               Contains("memory"));
    CHECK_THAT(input_error_message([&] {
                   engine::Problem(engine::ContinuousSpec{"sphere", 4'000'000'000'000});
               }),
               Contains("dim") && Contains("memory"));
    // An iteration limit whose history could not be kept.
    engine::Budget forever;
    forever.iterations = 100'000'000'000'000;
    CHECK_THAT(input_error_message([&] { engine::check(algo("pso"), sphere, forever); }), Contains("memory"));
    CHECK(engine::available_memory() > 1e8);
    CHECK(engine::format_bytes(2.5e9) == "2.5 GB");
}

TEST_CASE("engine: errors name the spec's fields, never a front end's flags", "[engine][errors]") {
    engine::GridSpec g;
    g.map = engine::load_map(map_file());
    g.start = {0, 0};
    g.goal = {9, 9};
    auto where = [](const engine::ProblemSpec& spec) {
        try {
            engine::Problem p(spec);
        } catch (const pride::InputError& e) {
            CHECK(std::string(e.what()).find("--") == std::string::npos);
            return e.where();
        }
        return std::string("<nothing thrown>");
    };
    auto with = [&](auto change) {
        engine::GridSpec s = g;
        change(s);
        return where(s);
    };
    CHECK(with([](auto& s) { s.encoding = "nosuch"; }) == "encoding");
    CHECK(with([](auto& s) { s.objective = "nosuch"; }) == "objective");
    CHECK(with([](auto& s) { s.connector = "nosuch"; }) == "connector");
    CHECK(with([](auto& s) { s.start = {5, 1}; }) == "start");  // an obstacle
    CHECK(with([](auto& s) { s.goal = {10, 9}; }) == "goal");
    CHECK(with([](auto& s) { s.waypoints = 0; }) == "waypoints");
    CHECK(with([](auto& s) { s.weights = {1, 1}; }) == "weights");
    CHECK(where(engine::ContinuousSpec{"nosuch", 3}) == "problem");
    CHECK(where(engine::ContinuousSpec{"rosenbrock", 1}) == "dim");
    const engine::Problem grid(g);
    auto refused = [&](const engine::AlgorithmSpec& a, const engine::Problem& p) {
        try {
            engine::check(a, p, evals(100));
        } catch (const pride::InputError& e) {
            CHECK(std::string(e.what()).find("--") == std::string::npos);
            return std::string(e.what());
        }
        return std::string("<nothing thrown>");
    };
    CHECK_THAT(refused(algo("astar"), engine::Problem(engine::ContinuousSpec{"sphere", 2})),
               Contains("astar") && Contains("grid"));
    CHECK_THAT(refused(algo("astar", {{"pop", 3}}), grid), Contains("unknown parameter 'pop'"));
    engine::GridSpec chain = g;
    chain.encoding = "chain";
    CHECK_THAT(refused(algo("pso"), engine::Problem(chain)), Contains("pso") && Contains("chain"));
    CHECK_THAT(refused(algo("ga", {{"eta_c", 3}}), engine::Problem(chain)), Contains("eta_c"));
    engine::GridSpec iqga = g;
    iqga.objective = "iqga";
    // iqga has an exact optimum too (the best point of the 3-D Pareto front).
    CHECK(refused(algo("exact"), engine::Problem(iqga)) == "<nothing thrown>");
    CHECK(engine::Problem(iqga).has_optimum());
    CHECK(engine::run(algo("astar"), engine::Problem(iqga).with_oracle(), evals(1), 1).grid->optimum.has_value());
    CHECK_THAT(input_error_message([&] {
                   engine::Problem(engine::ContinuousSpec{"sphere", 2}).with_oracle();
               }),
               Contains("oracle"));
    const auto with_optimum = engine::Problem(g).with_oracle();
    CHECK(std::get<engine::GridSpec>(with_optimum.spec()).oracle);
    CHECK(engine::run(algo("astar"), with_optimum, evals(1), 1).grid->optimum.has_value());
    CHECK_FALSE(engine::run(algo("astar"), grid, evals(1), 1).grid->optimum.has_value());
}

TEST_CASE("engine: a grid run returns a legal path, the optimum, and the papers' N = 20", "[engine][run][grid]") {
    engine::GridSpec g;
    g.map = engine::load_map(map_file());
    g.start = {0, 0};
    g.goal = {9, 9};
    g.oracle = true;
    const engine::Problem problem(g);
    CHECK(problem.is_grid());
    CHECK(problem.additive());
    engine::Budget b;
    b.iterations = 10;
    const auto r = engine::run(algo("pso"), problem, b, 2);
    REQUIRE(r.grid.has_value());
    CHECK(r.grid->encoding == "line");
    CHECK(r.evaluations == 20 * 11);  // N = 20 on grids unless a population is given
    REQUIRE(r.grid->optimum.has_value());
    CHECK(*r.grid->optimum == 12.0);
    if (r.grid->feasible) CHECK(r.grid->value >= *r.grid->optimum);
    const auto exact = engine::run(algo("exact"), problem, b, 1);
    CHECK(exact.grid->feasible);
    CHECK(exact.grid->value == 12.0);
    CHECK(exact.grid->path.front() == pride::grid::Cell{0, 0});
    CHECK(exact.grid->path.back() == pride::grid::Cell{9, 9});
}

TEST_CASE("engine: a campaign built from structs reads each map once and stores every run", "[engine][campaign]") {
    pride::test::TempDir dir;
    campaign::Campaign c;
    c.name = "from structs";
    c.seeds = 2;
    c.budget.iterations = 5;
    for (const char* id : {"a", "b"}) {
        campaign::CampaignProblem p;
        p.id = id;
        engine::GridSpec g;
        g.start = {0, 0};
        g.goal = {9, 9};
        g.encoding = std::string(id) == "a" ? "line" : "chain";
        p.spec = g;
        p.map_file = map_file();
        c.problems.push_back(p);
    }
    campaign::CampaignProblem s;
    s.id = "s";
    s.spec = engine::ContinuousSpec{"sphere", 3};
    c.algorithms.push_back({"ga", algo("ga"), 0});
    c.algorithms.push_back({"exact", algo("exact"), 0});
    campaign::prepare(c);
    const auto& ga = std::get<engine::GridSpec>(c.problems[0].spec);
    const auto& gb = std::get<engine::GridSpec>(c.problems[1].spec);
    CHECK(ga.map == gb.map);  // one map, read once
    CHECK(ga.oracle);         // the exact optimum beside every run of an additive objective
    CHECK_FALSE(c.text.empty());
    const auto summary = campaign::run_campaign(c, dir.file("s.sqlite"), 2);
    CHECK(summary.stored == 2 * 2 * 2);
    CHECK(summary.total == 8);
    const auto again = campaign::run_campaign(c, dir.file("s.sqlite"), 1);
    CHECK(again.stored == 0);
    CHECK(again.already == 8);
    const auto one = campaign::run_one(c.problems[1], c.algorithms[0], c.budget, 2);
    CHECK(one.feasible);
    CHECK(one.optimum == 12.0);

    // Bad input names the item.
    campaign::Campaign bad = c;
    bad.algorithms.push_back({"p", algo("pso"), 0});  // pso on the chain problem
    CHECK_THAT(input_error_message([&] { campaign::prepare(bad); }),
               Contains("'p'") && Contains("'b'") && Contains("chain"));
    bad = c;
    bad.problems.push_back(s);
    bad.problems.push_back(s);
    CHECK_THAT(input_error_message([&] { campaign::prepare(bad); }), Contains("duplicate problem id 's'"));
}

// Where each algorithm plans on a grid (docs/architecture.md: every algorithm declares its
// native space; front ends use it when the user names none, and refuse a space the algorithm
// cannot use with the ones it can): the encoding a run names, else the problem's, else the
// algorithm's native one; one grid problem then holds planners on every space side by side, in one
// campaign.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "engine/registry.hpp"
#include "engine/run.hpp"
#include "experiment/campaign/run_one.hpp"
#include "experiment/campaign/toml.hpp"
#include "framework/error.hpp"
#include "tests/cli_runner.hpp"
#include "tests/test_support.hpp"

namespace {

using namespace pride;

const std::string kMap = std::string(PRIDE_SOURCE_DIR) + "/examples/maps/zhang2025-20x20.map";

engine::GridSpec zhang2025_20(const std::string& encoding = "") {
    engine::GridSpec g;
    g.map = engine::load_map(kMap);
    g.start = {0, 19};
    g.goal = {19, 0};
    g.objective = "length";
    g.encoding = encoding;
    return g;
}

engine::RunResult run(const std::string& algo, const engine::Problem& p, const std::vector<std::string>& params = {}) {
    engine::AlgorithmSpec a{algo, {}};
    for (const auto& s : params) a.params.set_from_string(s);
    engine::Budget b;
    b.evaluations = 300;
    return engine::run(a, p, b, 1);
}

/// A campaign file on Zhang et al.'s (2025) 20 x 20 map with `objective`, A* first among its algorithms, then
/// `algorithms` (TOML [[algorithm]] tables), under `budget` (the [budget] table's lines).
std::string campaign_toml(const std::string& name, const std::string& budget, const std::string& objective,
                          const std::string& algorithms) {
    return "name = \"" + name + "\"\nseeds = 2\n[budget]\n" + budget + R"(
[[problem]]
id = "f002"
type = "grid"
map = ")" + kMap +
           R"("
start = [0, 19]
goal = [19, 0]
objective = ")" +
           objective + R"("
[[algorithm]]
id = "astar"
type = "astar"
)" + algorithms;
}

}  // namespace

TEST_CASE("planning spaces: every algorithm declares its native encoding, its papers' one", "[grid][spaces]") {
    for (const std::string name : {"iqga", "iaga", "icga", "woa", "woa-hs", "woa-balance", "hswoa"}) {
        INFO(name);
        CHECK(engine::algorithms().at(name).native_encoding == "chain");
    }
    for (const std::string name : {"pso", "pso-constriction", "lso", "ilso", "ga", "ga-plus", "nlopt:LN_SBPLX"}) {
        INFO(name);
        CHECK(engine::algorithms().at(name).native_encoding == "line");
    }
    for (const std::string name : {"astar", "exact"}) {
        INFO(name);
        CHECK(engine::algorithms().at(name).native_encoding.empty());
        CHECK_FALSE(engine::algorithms().at(name).evaluates());
    }
}

TEST_CASE("planning spaces: the run's encoding, else the problem's, else the native one", "[grid][spaces]") {
    const engine::Problem unnamed(zhang2025_20());
    CHECK(run("pso", unnamed).grid->encoding == "line");
    CHECK(run("ga", unnamed).grid->encoding == "line");
    CHECK(run("iqga", unnamed).grid->encoding == "chain");
    CHECK(run("hswoa", unnamed).grid->encoding == "chain");
    CHECK(run("astar", unnamed).grid->encoding == "none");
    // The run names its own: it wins over the problem's and the native one.
    CHECK(run("ga", unnamed, {"encoding=chain"}).grid->encoding == "chain");
    CHECK(run("hswoa", unnamed, {"encoding=line"}).grid->encoding == "line");
    const engine::Problem named(zhang2025_20("free"));
    CHECK(run("pso", named).grid->encoding == "free");
    CHECK(run("ga", named, {"encoding=chain"}).grid->encoding == "chain");
    // The same plan gives the same run whether the problem or the run names it.
    const auto by_problem = run("ga", engine::Problem(zhang2025_20("chain")));
    const auto by_run = run("ga", unnamed, {"encoding=chain"});
    CHECK(by_problem.history == by_run.history);
    CHECK(by_problem.grid->path == by_run.grid->path);
    // Every result is a legal path.
    for (const auto& r : {by_problem, run("iqga", unnamed), run("pso", unnamed, {"connector=penalty", "init=walk"})})
        CHECK(r.grid->feasible);
}

TEST_CASE("planning spaces: a space the algorithm cannot use is refused with the ones it can", "[grid][spaces]") {
    const engine::Problem unnamed(zhang2025_20());
    const std::string iqga_line = test::input_error_message([&] { run("iqga", unnamed, {"encoding=line"}); });
    CHECK(iqga_line ==
          "encoding line: iqga runs on chain, not on line: name no encoding (iqga's own is chain) or "
          "choose another algorithm");
    const std::string pso_chain =
        test::input_error_message([&] { run("pso", engine::Problem(zhang2025_20("chain"))); });
    CHECK(pso_chain ==
          "encoding chain: pso runs on line or free, not on chain: name no encoding (pso's own is line) "
          "or choose another algorithm");
    CHECK_THAT(test::input_error_message([&] { run("ga", unnamed, {"encoding=zigzag"}); }),
               Catch::Contains("encoding must be line, free or chain"));
    // Settings of grids have no meaning elsewhere.
    CHECK_THAT(test::input_error_message([&] {
                   run("pso", engine::Problem(engine::ContinuousSpec{"sphere", 2}), {"encoding=line"});
               }),
               Catch::Contains("encoding says how a grid is planned on"));
}

TEST_CASE("planning spaces: pride path plans on the native space and refuses others", "[grid][spaces][cli]") {
    const std::string where = "path --map " + kMap + " --start 0,19 --goal 19,0 --iters 3 --json";
    const auto iqga = test::run_pride(where + " --algo iqga --objective iqga");
    REQUIRE(iqga.status == 0);
    CHECK(iqga.out.find("\"encoding\": \"chain\"") != std::string::npos);
    const auto hswoa = test::run_pride(where + " --algo hswoa --objective hswoa");
    REQUIRE(hswoa.status == 0);
    CHECK(hswoa.out.find("\"encoding\": \"chain\"") != std::string::npos);
    const auto pso = test::run_pride(where + " --algo pso");
    REQUIRE(pso.status == 0);
    CHECK(pso.out.find("\"encoding\": \"line\"") != std::string::npos);
    const auto refused = test::run_pride(where + " --algo iqga --encoding line");
    CHECK(refused.status == 2);
    CHECK(refused.err ==
          "pride: --encoding line: iqga runs on chain, not on line: name no encoding (iqga's own is chain) or choose "
          "another algorithm\n");
}

TEST_CASE("planning spaces: one campaign holds A*, PSO on line and the GA family on chains", "[grid][spaces][bench]") {
    const test::TempDir dir("pride-spaces");
    const std::string toml =
        dir.write("mixed.toml", campaign_toml("mixed", "evaluations = 400", "length", R"([[algorithm]]
id = "pso-line"
type = "pso"
[[algorithm]]
id = "ga-chain"
type = "ga"
encoding = "chain"
shortcut = "line"
[[algorithm]]
id = "iqga"
type = "iqga"
[[algorithm]]
id = "hswoa"
type = "hswoa"
init = "walk"
)"));
    const campaign::Campaign c = campaign::read_campaign(toml);
    REQUIRE(c.algorithms.size() == 5);
    for (const auto& a : c.algorithms)
        for (std::int64_t seed = 1; seed <= 2; ++seed) {
            INFO(a.id << " seed " << seed);
            const campaign::RunRecord r = campaign::run_one(c.problems.front(), a, c.budget, seed);
            CHECK(r.feasible);
            if (a.id != "astar") CHECK(r.evaluations == 400);
        }
    const auto bench = test::run_pride("bench " + toml + " --out " + dir.file("mixed.sqlite"));
    INFO(bench.err);
    REQUIRE(bench.status == 0);
    CHECK(bench.out.find("10 runs stored") != std::string::npos);
}

TEST_CASE("planning spaces: pride report warns when compared runs used evaluation counts 5 % apart",
          "[grid][spaces][report]") {
    const test::TempDir dir("pride-equal");
    auto campaign = [&](const std::string& name, const std::string& budget) {
        return dir.write(name + ".toml", campaign_toml(name, budget, "iqga", R"([[algorithm]]
id = "ga"
type = "ga"
encoding = "chain"
pop = 10
[[algorithm]]
id = "iqga"
type = "iqga"
pop = 10
)"));
    };
    // Equal iterations: IQGA's SITP scores are evaluations too, so it spends far more than the GA.
    const std::string iterations = campaign("iterations", "iterations = 5");
    REQUIRE(test::run_pride("bench " + iterations + " --out " + dir.file("i.sqlite")).status == 0);
    const auto unequal = test::run_pride("report " + dir.file("i.sqlite"));
    REQUIRE(unequal.status == 0);
    CHECK(unequal.out.find("Warning: on f002 the algorithms compared used different numbers of evaluations (mean: ga "
                           "55, iqga 205; more than 5 % apart)") != std::string::npos);
    CHECK(unequal.out.find("On f002, astar plans on the whole map and evaluates no objective") != std::string::npos);
    CHECK(unequal.out.find("mean: astar") == std::string::npos);  // A* is not among the compared
    // Equal evaluations: no warning; A* is still labelled.
    const std::string evaluations = campaign("evaluations", "evaluations = 300");
    REQUIRE(test::run_pride("bench " + evaluations + " --out " + dir.file("e.sqlite")).status == 0);
    const auto equal = test::run_pride("report " + dir.file("e.sqlite"));
    REQUIRE(equal.status == 0);
    CHECK(equal.out.find("Warning") == std::string::npos);
    CHECK(equal.out.find("On f002, astar plans on the whole map") != std::string::npos);
    const auto latex = test::run_pride("report " + dir.file("i.sqlite") + " --format latex");
    CHECK(latex.out.find("% Warning: on f002") != std::string::npos);
}

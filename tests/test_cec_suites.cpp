// The CEC suites in campaigns and reports: [[suite]] name = "cec2017" / "cec2022" and
// what they expand to, their refusals (instances, a dimension without official data, an unknown
// function) through `pride bench`, the suites' default budgets and runs; the best value so far that
// every run records at exact evaluation counts, and `pride report --format cec` on a store of
// hand-chosen values, its checkpoints and statistics against numbers worked out by hand. Nothing
// here reads the official data: the report's store holds runs of another function, with f* set.
#include <fmt/format.h>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "engine/run.hpp"
#include "experiment/campaign/identity.hpp"
#include "experiment/campaign/prepare.hpp"
#include "experiment/campaign/run.hpp"
#include "experiment/campaign/toml.hpp"
#include "experiment/report/cec.hpp"
#include "experiment/report/report.hpp"
#include "experiment/storage/reader.hpp"
#include "problems/continuous/cec/suites.hpp"
#include "tests/cec_synthetic.hpp"
#include "tests/cli_runner.hpp"
#include "tests/sqlite_support.hpp"
#include "tests/test_support.hpp"

using Catch::Matchers::Contains;
using pride::test::check_input_error;
using pride::test::exec_sql;
using pride::test::input_error_message;
using pride::test::run_pride;
using pride::test::TempDir;
namespace cec = pride::report::cec;
namespace cec_suites = pride::continuous::cec;  // the checkpoints themselves, which runs record

namespace {

std::vector<std::int64_t> evaluations_of(const std::vector<cec_suites::Checkpoint>& checkpoints) {
    std::vector<std::int64_t> out;
    for (const auto& c : checkpoints) out.push_back(c.evaluations);
    return out;
}

std::string quoted(const std::string& s) {
    return "'" + s + "'";
}

/// A campaign file's text: a header (name, seeds, budget: any of them may be left out by the
/// caller's `head`) and the tables in `body`, with one algorithm.
std::string campaign(const std::string& head, const std::string& body) {
    return "name = \"cec\"\n" + head + body + "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\n";
}

std::vector<std::string> ids_of(const pride::campaign::Campaign& c) {
    std::vector<std::string> ids;
    for (const auto& p : c.problems) ids.push_back(p.id);
    return ids;
}

}  // namespace

TEST_CASE("cec suites: the checkpoints are those of the CEC 2017 and CEC 2022 reports", "[cec-suites]") {
    // CEC 2017, section 2.2: (0.01, 0.02, 0.03, 0.05, 0.1, 0.2, ..., 1.0) x MaxFES.
    const auto y2017 = cec_suites::checkpoints_2017(100000);
    CHECK(evaluations_of(y2017) == std::vector<std::int64_t>{1000, 2000, 3000, 5000, 10000, 20000, 30000, 40000, 50000,
                                                             60000, 70000, 80000, 90000, 100000});
    CHECK(y2017.front().label == "0.01");
    CHECK(y2017[3].label == "0.05");
    CHECK(y2017.back().label == "1.0");
    // CEC 2022, section 2.2: floor(D^(k/5-3) x MaxFES), k = 0..15, at its two settings (the floors
    // worked out with 50-digit decimals).
    const auto d10 = cec_suites::checkpoints_2022(200000, 10);
    CHECK(evaluations_of(d10) == std::vector<std::int64_t>{200, 316, 502, 796, 1261, 2000, 3169, 5023, 7962, 12619,
                                                           20000, 31697, 50237, 79621, 126191, 200000});
    CHECK(d10.front().label == "k=0");
    CHECK(d10.back().label == "k=15");
    CHECK(evaluations_of(cec_suites::checkpoints_2022(1000000, 20)) ==
          std::vector<std::int64_t>{125, 227, 414, 754, 1373, 2500, 4551, 8286, 15085, 27464, 50000, 91028, 165722,
                                    301708, 549280, 1000000});
    CHECK(evaluations_of(cec_suites::checkpoints("cec2022", 200000, 10)) == evaluations_of(d10));
    CHECK(evaluations_of(cec_suites::checkpoints("bbob", 100000, 10)) == evaluations_of(y2017));
    // Floors of a budget that 100 does not divide, and never below 1 evaluation.
    CHECK(evaluations_of(cec_suites::checkpoints_2017(250)) ==
          std::vector<std::int64_t>{2, 5, 7, 12, 25, 50, 75, 100, 125, 150, 175, 200, 225, 250});
    CHECK(evaluations_of(cec_suites::checkpoints_2017(50)).front() == 1);
    CHECK(evaluations_of(cec_suites::checkpoints_2022(100, 10)).front() == 1);
    // What a campaign records: both lists, each count once, increasing.
    const auto both = cec_suites::recorded_evaluations(2000, 10);
    CHECK(both == std::vector<std::int64_t>{2,   3,   5,   7,   12,  20,  31,   40,   50,   60,   79,   100,  126, 200,
                                            316, 400, 502, 600, 796, 800, 1000, 1200, 1261, 1400, 1600, 1800, 2000});
}

TEST_CASE("cec suites: errors below 1e-8 count as 0", "[cec-suites]") {
    CHECK(cec::error_of(100.0 + 5e-9, 100.0) == 0.0);                         // 5.0000004e-9 after the subtraction
    CHECK(cec::error_of(100.0 - 1e-6, 100.0) == 0.0);                         // below f* by rounding: no negative error
    CHECK(cec::error_of(std::ldexp(1.0, -26), 0.0) == std::ldexp(1.0, -26));  // 1.49e-8 is kept
    CHECK(cec::error_of(1e-8, 0.0) == 1e-8);  // "smaller than 10^-8": 1e-8 itself is not
    CHECK(cec::error_of(103.0, 100.0) == 3.0);
    CHECK(std::isinf(cec::error_of(std::numeric_limits<double>::infinity(), 100.0)));
}

TEST_CASE("cec suites: a run records the best value so far at exact evaluation counts", "[cec-suites]") {
    // Every value the function returns, in the order evaluated (one thread): the best so far after
    // e evaluations is the least of the first e.
    for (const char* algorithm : {"pso", "nlopt:LN_SBPLX", "ga"}) {
        INFO(algorithm);
        auto values = std::make_shared<std::vector<double>>();
        pride::engine::CallbackSpec spec;
        spec.name = "logged";
        spec.lower = {-3, -3, -3};
        spec.upper = {3, 3, 3};
        spec.scalar = [values](std::span<const double> x) {
            const double f = x[0] * x[0] + 2 * x[1] * x[1] + std::abs(x[2]);
            values->push_back(f);
            return f;
        };
        pride::engine::Budget budget;
        budget.evaluations = 95;
        budget.recorded_evaluations = {1, 5, 10, 11, 37, 94, 95, 200};
        const auto r = pride::engine::run({algorithm, {}}, pride::engine::Problem(spec), budget, 7);
        REQUIRE(values->size() == static_cast<std::size_t>(r.evaluations));
        // Those the run reached (200 is past its end; subplex may stop before 95).
        const auto reached = static_cast<std::size_t>(
            std::count_if(budget.recorded_evaluations.begin(), budget.recorded_evaluations.end(),
                          [&](std::int64_t e) { return e <= r.evaluations; }));
        CHECK(reached >= 5);
        REQUIRE(r.checkpoints.size() == reached);
        for (std::size_t i = 0; i < r.checkpoints.size(); ++i) {
            const std::int64_t e = budget.recorded_evaluations[i];
            CHECK(r.checkpoints[i].evaluations == e);
            CHECK(r.checkpoints[i].best == *std::min_element(values->begin(), values->begin() + e));
        }
        if (r.evaluations == 95) CHECK(r.checkpoints.back().best == r.best_f);
    }
    pride::engine::Budget bad;
    bad.evaluations = 10;
    bad.recorded_evaluations = {5, 5};
    CHECK_THAT(input_error_message([&] {
                   (void)pride::engine::run({"pso", {}},
                                            pride::engine::Problem(pride::engine::ContinuousSpec{"sphere", 2}), bad, 1);
               }),
               Contains("recorded_evaluations") && Contains("increasing"));
}

TEST_CASE("cec suites: [[suite]] cec2017 and cec2022 expand to one problem per function and dimension",
          "[cec-suites]") {
    const TempDir dir;
    const std::string file = dir.write("c.toml", campaign("seeds = 2\n[budget]\nevaluations = 1000\n",
                                                          "[[suite]]\nname = \"cec2017\"\nfunctions = [1, 11, 22]\n"
                                                          "dimensions = [10, 30, 10]\n"
                                                          "[[suite]]\nname = \"cec2022\"\nid = \"c22\"\n"
                                                          "dimensions = [20]\n"));
    // Without building a problem: no data is read.
    const auto c = pride::campaign::parse_campaign(file);
    std::vector<std::string> expected{"cec2017-f1-d10",  "cec2017-f1-d30",  "cec2017-f11-d10",
                                      "cec2017-f11-d30", "cec2017-f22-d10", "cec2017-f22-d30"};
    for (int f = 1; f <= 12; ++f) expected.push_back("c22-f" + std::to_string(f) + "-d20");  // all 12 by default
    CHECK(ids_of(c) == expected);
    const auto& f11 = std::get<pride::engine::ContinuousSpec>(c.problems[3].spec);
    CHECK(f11.function == "cec2017-f11");
    CHECK(f11.dim == 30);
    CHECK(!f11.instance);  // CEC functions have one, as defined
    CHECK(c.problems[3].suite == "cec2017");
    const auto& last = std::get<pride::engine::ContinuousSpec>(c.problems.back().spec);
    CHECK(last.function == "cec2022-f12");
    CHECK(last.dim == 20);
    CHECK(c.problems.back().suite == "cec2022");
    CHECK(c.seeds == 2);

    // The campaign shipped as an example (docs/campaigns.md): cec2017 F1 and F22 at D = 10, with
    // the suite's budget and runs.
    auto example =
        pride::campaign::parse_campaign(std::string(PRIDE_SOURCE_DIR) + "/examples/campaigns/cec2017-small.toml");
    pride::campaign::apply_suite_rules(example);
    CHECK(ids_of(example) == std::vector<std::string>{"cec2017-f1-d10", "cec2017-f22-d10"});
    CHECK(example.seeds == 51);
    for (const auto& p : example.problems) CHECK(p.evaluations == 100000);
}

TEST_CASE("cec suites: a campaign without a budget or seeds takes the suites' rules", "[cec-suites]") {
    const TempDir dir;
    const auto applied = [&](const std::string& head, const std::string& body) {
        auto c = pride::campaign::parse_campaign(dir.write("c.toml", campaign(head, body)));
        pride::campaign::apply_suite_rules(c);
        return c;
    };
    const std::string y2017 = "[[suite]]\nname = \"cec2017\"\nfunctions = [3]\ndimensions = [10, 50]\n";
    const std::string y2022 = "[[suite]]\nname = \"cec2022\"\nfunctions = [2]\ndimensions = [10, 20]\n";
    // CEC 2017: 10000 D evaluations, 51 runs.
    const auto a = applied("", y2017);
    CHECK(a.seeds == 51);
    CHECK(a.problems[0].evaluations == 100000);
    CHECK(a.problems[1].evaluations == 500000);
    CHECK(pride::campaign::budget_definition(a) == "evaluations by the CEC suites' rules");
    // CEC 2022: 200,000 at D = 10, 1,000,000 at D = 20, 30 runs; a [[problem]] on a CEC function too.
    const auto b = applied("", y2022 + "[[problem]]\nid = \"one\"\ntype = \"cec2022-f4\"\ndim = 10\n");
    CHECK(b.seeds == 30);
    CHECK(b.problems[0].evaluations == 200000);
    CHECK(b.problems[1].evaluations == 1000000);
    CHECK(b.problems[2].evaluations == 200000);
    // Seeds and an evaluation budget given are the campaign's.
    const auto c = applied("seeds = 7\n[budget]\nevaluations = 5000\n", y2017);
    CHECK(c.seeds == 7);
    CHECK(!c.problems[0].evaluations);
    CHECK(pride::campaign::budget_definition(c) == "evaluations = 5000");
    // An iteration budget alone leaves the suites' MaxFES (runs end at whichever comes first).
    const auto d = applied("[budget]\niterations = 10\n", y2017);
    CHECK(d.problems[1].evaluations == 500000);
    CHECK(pride::campaign::budget_definition(d) == "iterations = 10; evaluations by the CEC suites' rules");
    // Refused: seeds for two suites at once, a budget for a problem of no CEC suite or at a
    // dimension whose MaxFES no rule gives.
    const auto refused = [&](const std::string& head, const std::string& body) {
        return input_error_message([&] { (void)applied(head, body); });
    };
    CHECK_THAT(refused("", y2017 + y2022),
               Contains("c.toml: missing key 'seeds': only a campaign of one CEC suite's problems has a default (51 "
                        "runs for cec2017, 30 for cec2022, 25 for cec2020rw)"));
    CHECK_THAT(refused("seeds = 3\n", y2017 + "[[problem]]\nid = \"sph\"\ntype = \"sphere\"\ndim = 2\n"),
               Contains("missing [budget]") && Contains("problem 'sph' has none"));
    CHECK_THAT(refused("", "[[suite]]\nname = \"cec2022\"\nfunctions = [1]\ndimensions = [2]\n"),
               Contains("problem 'cec2022-f1-d2' has none"));
    CHECK_THAT(refused("", "[[problem]]\nid = \"sph\"\ntype = \"sphere\"\ndim = 2\n"),
               Catch::Matchers::EndsWith("c.toml: missing key 'seeds'"));
}

TEST_CASE("cec suites: instances, dimensions without data and unknown functions are refused by pride bench",
          "[cec-suites]") {
    const TempDir dir;
    const auto refused = [&](const std::string& body, const std::vector<std::string>& words) {
        const std::string file = dir.write("c.toml", campaign("seeds = 1\n[budget]\nevaluations = 100\n", body));
        INFO(body);
        check_input_error(run_pride("bench " + quoted(file) + " --out " + quoted(dir.file("c.sqlite"))), words);
        CHECK(!std::filesystem::exists(dir.file("c.sqlite")));  // refused before anything ran
    };
    refused("[[suite]]\nname = \"cec2017\"\ninstances = [1, 2]\ndimensions = [10]\n",
            {"c.toml:7:13: 'instances': cec2017 has no instances (each function is defined once per dimension, by "
             "the official data); leave the key out"});
    refused("[[suite]]\nname = \"cec2022\"\ndimensions = [10]\ninstances = [0]\n",
            {"c.toml:8:13: 'instances': cec2022 has no instances"});
    refused("[[suite]]\nname = \"cec2017\"\nfunctions = [1, 11]\ndimensions = [10, 20]\n",
            {"c.toml:8:14: cec2017-f11 has no official data in dimension 20 (the official code and data define it "
             "in 10, 30, 50, 100 only); leave 20 out of 'dimensions', or F11 out of 'functions'"});
    refused("[[suite]]\nname = \"cec2022\"\nfunctions = [6]\ndimensions = [2]\n",
            {"c.toml:8:14: cec2022-f6 has no official data in dimension 2", "in 10, 20 only"});
    refused("[[suite]]\nname = \"cec2017\"\nfunctions = [2, 31]\ndimensions = [10]\n",
            {"c.toml:7:13: function 31 is not in the cec2017 suite (1-30)"});
    refused("[[suite]]\nname = \"cec2022\"\nfunctions = [0]\ndimensions = [10]\n",
            {"c.toml:7:13: function 0 is not in the cec2022 suite (1-12)"});
    refused("[[suite]]\nname = \"cec2021\"\ndimensions = [10]\n",
            {"c.toml:5: unknown suite 'cec2021' (bbob, bbob-constrained, bbob-mixint, classic, cec2017, cec2022, "
             "cec2020rw)"});
    // A [[problem]] on a CEC function: the catalog's own refusals, naming the problem.
    refused("[[problem]]\nid = \"p\"\ntype = \"cec2017-f3\"\ndim = 10\ninstance = 2\n",
            {"c.toml:5", "problem 'p'", "CEC functions have no instances"});
    refused("[[problem]]\nid = \"p\"\ntype = \"cec2017-f3\"\ndim = 7\n",
            {"c.toml:5", "problem 'p'", "cec2017-f3 is defined in dimensions 2, 10, 20, 30, 50, 100 only, got 7"});
}

namespace {

/// The hand-made store of the report test: `pride bench` writes a true store (runs of the sphere
/// in D = 10, 2000 evaluations), whose runs the test then replaces with chosen values.
struct HandStore {
    TempDir dir;
    std::string store = dir.file("s.sqlite");

    HandStore() {
        const std::string file = dir.write("c.toml",
                                           "name = \"by hand\"\nseeds = 3\n[budget]\nevaluations = 2000\n"
                                           "[[problem]]\nid = \"s10\"\ntype = \"sphere\"\ndim = 10\n"
                                           "[[problem]]\nid = \"t10\"\ntype = \"sphere\"\ndim = 10\n"
                                           "[[algorithm]]\nid = \"a\"\ntype = \"pso\"\n");
        auto c = pride::campaign::read_campaign(file);
        (void)pride::campaign::run_campaign(c, store, 1);
        // f* = 100 for both; t10 reported as a CEC 2022 problem (its checkpoints).
        exec_sql(store,
                 "UPDATE problems SET f_opt = 100; UPDATE problems SET suite = 'cec2022', fid = 1 WHERE id = "
                 "'t10'; DELETE FROM runs WHERE problem = 't10' AND seed = 3");
    }

    /// Run (problem, seed) ends after `evaluations` with the values 100 + error at the counts given.
    void set(const std::string& problem, int seed, std::int64_t evaluations, const std::vector<std::int64_t>& counts,
             const std::vector<double>& errors) const {
        REQUIRE(counts.size() >= errors.size());
        std::string trace;
        for (std::size_t i = 0; i < errors.size(); ++i)
            trace += fmt::format("{}{}, {:.17g}", i ? ", " : "", counts[i], 100.0 + errors[i]);
        const double best = 100.0 + errors.back();
        exec_sql(store, fmt::format("UPDATE runs SET evaluations = {1}, best = {2:.17g}, history = '[{2:.17g}]', "
                                    "history_evaluations = '[{1}]', target_hits = '[]', trace_targets = '[]', "
                                    "trace_evaluations = '[]', max_evaluations = 2000, checkpoints = '[{3}]' WHERE "
                                    "problem = '{0}' AND seed = {4}",
                                    problem, evaluations, best, trace, seed));
    }
};

const double e26 = std::ldexp(1.0, -26);  // 1.49e-8: kept
const double e27 = std::ldexp(1.0, -27);  // 7.45e-9: taken as 0

void fill(const HandStore& s) {
    // s10, CEC 2017's checkpoints of 2000 evaluations: 20, 40, 60, 100, 200, 400, ..., 2000.
    const auto y2017 = evaluations_of(cec_suites::checkpoints_2017(2000));
    s.set("s10", 1, 2000, y2017, {64, 32, 16, 8, 4, 2, 1, 0.5, 0.25, 0.125, std::ldexp(1.0, -20), e26, e27, e27});
    s.set("s10", 2, 2000, y2017, {128, 64, 64, 32, 32, 16, 8, 8, 4, 4, 2, 2, 1, 0.5});
    // Seed 3 ended after 1000 evaluations with 103: its best so far at 1200 ... 2000 is 103.
    s.set("s10", 3, 1000, y2017, {96, 48, 24, 12, 6, 3, 3, 3, 3});
    // t10, CEC 2022's checkpoints of 2000 evaluations in D = 10: 2, 3, 5, 7, 12, 20, ..., 2000.
    const auto y2022 = evaluations_of(cec_suites::checkpoints_2022(2000, 10));
    std::vector<double> halving, ones(16, 1.0);
    for (int k = 0; k < 15; ++k) halving.push_back(std::ldexp(1.0, 15 - k));
    halving.push_back(e27);
    ones.back() = e26;
    s.set("t10", 1, 2000, y2022, halving);
    s.set("t10", 2, 2000, y2022, ones);
}

}  // namespace

TEST_CASE("cec suites: the CEC table of a store of hand-chosen runs", "[cec-suites]") {
    const HandStore s;
    fill(s);
    const auto table = cec::make_table(pride::storage::read_store(s.store), s.store);
    REQUIRE(table.rows.size() == 2);
    const cec::Row& r = table.rows[0];
    CHECK(r.problem == "s10");
    CHECK(r.algorithm == "a");
    CHECK(r.dim == 10);
    CHECK(r.f_opt == 100);
    CHECK(r.max_evaluations == 2000);
    CHECK(r.runs == 3);
    REQUIRE(r.checkpoints.size() == 14);
    const auto at = [&](std::size_t k) { return r.checkpoints[k].errors; };
    // 0.01 MaxFES (20): errors 64, 128, 96.
    CHECK(r.checkpoints[0].checkpoint.evaluations == 20);
    CHECK(at(0).best == 64);
    CHECK(at(0).worst == 128);
    CHECK(at(0).median == 96);
    CHECK(at(0).mean == 96);
    CHECK(at(0).std == Approx(32.0).epsilon(1e-15));
    // 0.5 MaxFES (1000): 0.125, 4, 3.
    CHECK(r.checkpoints[8].checkpoint.evaluations == 1000);
    CHECK(at(8).median == 3);
    // 0.6 MaxFES (1200): seed 3 had ended, with 103: 0.125, 4, 3.
    CHECK(r.checkpoints[9].checkpoint.evaluations == 1200);
    CHECK(at(9).best == 0.125);
    CHECK(at(9).worst == 4);
    CHECK(at(9).median == 3);
    // 0.7 MaxFES (1400): 2^-20, 2, 3.
    CHECK(at(10).best == std::ldexp(1.0, -20));
    // 0.8 MaxFES (1600): 2^-26 = 1.49e-8 stays, 2, 3.
    CHECK(at(11).best == e26);
    CHECK(at(11).median == 2);
    // 0.9 MaxFES (1800): 2^-27 = 7.45e-9 is 0; 1, 3: mean 4/3, std sqrt(7/3).
    CHECK(at(12).best == 0);
    CHECK(at(12).median == 1);
    CHECK(at(12).mean == Approx(4.0 / 3).epsilon(1e-15));
    CHECK(at(12).std == Approx(std::sqrt(7.0 / 3)).epsilon(1e-15));
    // MaxFES (2000): 0, 0.5, 3: mean 7/6, std sqrt(31/12).
    CHECK(r.checkpoints[13].checkpoint.label == "1.0");
    CHECK(at(13).best == 0);
    CHECK(at(13).worst == 3);
    CHECK(at(13).median == 0.5);
    CHECK(at(13).mean == Approx(7.0 / 6).epsilon(1e-15));
    CHECK(at(13).std == Approx(std::sqrt(31.0 / 12)).epsilon(1e-15));

    const cec::Row& t = table.rows[1];
    CHECK(t.problem == "t10");
    CHECK(t.suite == "cec2022");
    CHECK(t.runs == 2);
    REQUIRE(t.checkpoints.size() == 16);
    // k = 0 (2 evaluations): 32768 and 1.
    CHECK(t.checkpoints[0].checkpoint.evaluations == 2);
    CHECK(t.checkpoints[0].errors.median == 16384.5);
    CHECK(t.checkpoints[0].errors.std == Approx(32767 / std::sqrt(2.0)).epsilon(1e-15));
    // k = 15 (MaxFES): 0 (7.45e-9) and 1.49e-8; the median, a statistic, is 7.45e-9 as it is.
    CHECK(t.checkpoints[15].checkpoint.evaluations == 2000);
    CHECK(t.checkpoints[15].errors.best == 0);
    CHECK(t.checkpoints[15].errors.worst == e26);
    CHECK(t.checkpoints[15].errors.median == e26 / 2);

    // As pride report prints it: markdown, 6 significant digits ...
    const auto md = run_pride("report " + quoted(s.store) + " --format cec");
    INFO(md.err);
    REQUIRE(md.status == 0);
    CHECK_THAT(md.out, Contains("# CEC errors: by hand\n"));
    CHECK_THAT(md.out, Contains("| s10 | a | 10 | 2000 | 3 | 0 | 3 | 0.5 | 1.16667 | 1.60728 |\n"));
    CHECK_THAT(md.out, Contains("| t10 | a | 10 | 2000 | 2 | 0 | 1.49012e-08 | 7.45058e-09 | 7.45058e-09 | "
                                "1.05367e-08 |\n"));
    CHECK_THAT(md.out, Contains("### s10, a\n\nsphere, D = 10, f* = 100, MaxFES = 2000, 3 runs.\n"));
    CHECK_THAT(md.out, Contains("| 0.01 | 20 | 64 | 128 | 96 | 96 | 32 |\n"));
    CHECK_THAT(md.out, Contains("| 0.9 | 1800 | 0 | 3 | 1 | 1.33333 | 1.52753 |\n"));
    CHECK_THAT(md.out, Contains("### t10, a\n\nsphere (cec2022), D = 10, f* = 100, MaxFES = 2000, 2 runs.\n"));
    CHECK_THAT(md.out, Contains("| k | FES | best | worst | median | mean | std |\n"));
    CHECK_THAT(md.out, Contains("| 0 | 2 | 1 | 32768 | 16384.5 | 16384.5 | 23169.8 |\n"));
    // ... and CSV, every number as the double it is.
    const auto csv = run_pride("report " + quoted(s.store) + " --format cec-csv");
    REQUIRE(csv.status == 0);
    const auto lines = pride::test::lines_of(csv.out);
    REQUIRE(lines.size() == 1 + 14 + 16);
    CHECK(lines[0] ==
          "problem,function,suite,dim,f_opt,algorithm,max_evaluations,runs,checkpoint,evaluations,best,worst,median,"
          "mean,std");
    CHECK(lines[12] ==
          "s10,sphere,,10,100,a,2000,3,0.8,1600,1.4901161193847656e-08,3,2,1.6666666716337204,"
          "1.5275252235226966");
    CHECK(lines[14] == "s10,sphere,,10,100,a,2000,3,1.0,2000,0,3,0.5,1.1666666666666667,1.607275126832159");
    CHECK(lines[30] ==
          "t10,sphere,cec2022,10,100,a,2000,2,k=15,2000,0,1.4901161193847656e-08,7.450580596923828e-09,"
          "7.450580596923828e-09,1.0536712127723509e-08");
}

TEST_CASE("cec suites: --format cec refuses runs without a budget or checkpoints, and its own misuses",
          "[cec-suites]") {
    const HandStore s;
    fill(s);
    // A store from before schema 4: its runs have no max_evaluations and no checkpoints. The
    // comparison report reads it; the CEC table says why it cannot.
    exec_sql(s.store,
             "ALTER TABLE runs DROP COLUMN checkpoints; ALTER TABLE runs DROP COLUMN max_evaluations; PRAGMA "
             "user_version = 3");
    CHECK(run_pride("report " + quoted(s.store)).status == 0);
    check_input_error(run_pride("report " + quoted(s.store) + " --format cec"),
                      {s.store + ": run (problem 's10', algorithm 'a', seed 1) records no evaluation budget (MaxFES)",
                       "store schema 4"});
    // A resume migrates it: the columns come back, empty for the runs already there.
    const std::string file = s.dir.file("c.toml");
    const auto bench = run_pride("bench " + quoted(file) + " --out " + quoted(s.store));
    INFO(bench.err);
    CHECK(bench.status == 0);
    CHECK_THAT(bench.out, Contains("1 runs stored"));  // (t10, seed 3), deleted above
    const auto store = pride::storage::read_store(s.store);
    for (const auto& run : store.runs) {
        INFO(run.problem << " " << run.seed);
        const bool new_run = run.problem == "t10" && run.seed == 3;
        CHECK(run.max_evaluations.has_value() == new_run);
        CHECK(run.checkpoints.empty() == !new_run);
    }
    const auto misuse = [&](const std::string& options, const std::vector<std::string>& words) {
        check_input_error(run_pride("report " + quoted(s.store) + " " + options), words);
    };
    misuse("--format cec --raw", {"--raw", "errors f - f*"});
    misuse("--format cec --plots " + quoted(s.dir.file("figures")), {"--plots"});
    misuse("--format cecc",
           {"expected md, csv, latex, ert-csv, functions-csv, cec, cec-csv, cec2020rw or cec2020rw-csv, got 'cecc'"});
}

TEST_CASE("cec suites: a campaign stores each run's budget and its best values at the checkpoints", "[cec-suites]") {
    const TempDir dir;
    const std::string file = dir.write("c.toml",
                                       "name = \"k\"\nseeds = 2\n[budget]\nevaluations = 500\n"
                                       "[[suite]]\nname = \"bbob\"\nfunctions = [1, 15]\ninstances = [1]\n"
                                       "dimensions = [2]\n"
                                       "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\n"
                                       "[[algorithm]]\nid = \"sbplx\"\ntype = \"nlopt:LN_SBPLX\"\n");
    auto c = pride::campaign::read_campaign(file);
    const std::string path = dir.file("k.sqlite");
    (void)pride::campaign::run_campaign(c, path, 2);
    const auto store = pride::storage::read_store(path);
    REQUIRE(store.runs.size() == 8);
    for (const auto& run : store.runs) {
        INFO(run.problem << " " << run.algorithm << " " << run.seed);
        CHECK(run.max_evaluations == 500);
        std::vector<std::int64_t> counts;
        for (const auto& t : run.checkpoints) counts.push_back(t.evaluations);
        const auto wanted = cec_suites::recorded_evaluations(500, 2);
        // A run that stopped early (subplex converged) records the counts it reached.
        const auto reached =
            static_cast<std::size_t>(std::upper_bound(wanted.begin(), wanted.end(), run.evaluations) - wanted.begin());
        CHECK(counts ==
              std::vector<std::int64_t>(wanted.begin(), wanted.begin() + static_cast<std::ptrdiff_t>(reached)));
        if (run.evaluations == 500) CHECK(run.checkpoints.back().best == run.best);
    }
    // Under an iteration budget alone there is no MaxFES, and nothing to record against it.
    const std::string iterations = dir.write("i.toml",
                                             "name = \"i\"\nseeds = 1\n[budget]\niterations = 3\n"
                                             "[[problem]]\nid = \"s\"\ntype = \"sphere\"\ndim = 2\n"
                                             "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\n");
    auto ci = pride::campaign::read_campaign(iterations);
    (void)pride::campaign::run_campaign(ci, dir.file("i.sqlite"), 1);
    const auto si = pride::storage::read_store(dir.file("i.sqlite"));
    REQUIRE(si.runs.size() == 1);
    CHECK(!si.runs[0].max_evaluations);
    CHECK(si.runs[0].checkpoints.empty());
    check_input_error(run_pride("report " + quoted(dir.file("i.sqlite")) + " --format cec"),
                      {"records no evaluation budget (MaxFES)"});
}

TEST_CASE("cec suites: problems without a known f* are left out of the CEC table, and alone refused", "[cec-suites]") {
    const TempDir dir;
    const std::string file =
        dir.write("g.toml", fmt::format("name = \"g\"\nseeds = 2\n[budget]\nevaluations = 300\n"
                                        "[[problem]]\nid = \"grid10\"\ntype = \"grid\"\nmap = \"{}\"\n"
                                        "start = [0, 0]\ngoal = [9, 9]\n"
                                        "[[problem]]\nid = \"sph\"\ntype = \"sphere\"\ndim = 2\n"
                                        "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\n",
                                        std::string(PRIDE_SOURCE_DIR) + "/examples/maps/wan2022-10x10.map"));
    const std::string store = dir.file("g.sqlite");
    auto c = pride::campaign::read_campaign(file);
    (void)pride::campaign::run_campaign(c, store, 1);
    const auto r = run_pride("report " + quoted(store) + " --format cec");
    REQUIRE(r.status == 0);
    CHECK_THAT(r.out, Contains("| sph | pso | 2 | 300 | 2 | "));
    CHECK_THAT(r.out, Contains("\nLeft out: grid10 (no known optimum f*, so no error f - f*).\n"));
    CHECK(r.out.find("| grid10 |") == std::string::npos);
    exec_sql(store, "DELETE FROM runs WHERE problem = 'sph'");
    check_input_error(run_pride("report " + quoted(store) + " --format cec"),
                      {store + ": holds no run on a problem with a known optimum f*, so it has no CEC errors"});
}

TEST_CASE("cec suites: the example campaign runs as the docs say and its CEC table reads", "[cec-suites]") {
    // The commands of docs/campaigns.md's sh block on examples/campaigns/cec2017-small.toml, run as
    // written (`pride` the one just built, first on PATH) in a folder laid out as the top of a
    // clone, with a synthetic input_data folder in the official format (tests/cec_synthetic.hpp)
    // in place of the official one, which CI does not have.
    namespace fs = std::filesystem;
    std::vector<std::string> commands;
    {
        bool in_block = false;
        std::vector<std::string> block;
        for (const auto& line :
             pride::test::lines_of(pride::test::slurp(std::string(PRIDE_SOURCE_DIR) + "/docs/campaigns.md"))) {
            if (!in_block && line == "```sh") {
                in_block = true;
                block.clear();
            } else if (in_block && line == "```") {
                in_block = false;
                if (!block.empty() && block.front().find("cec2017-small.toml") != std::string::npos) commands = block;
            } else if (in_block) {
                block.push_back(line);
            }
        }
    }
    REQUIRE(commands.size() == 2);
    const TempDir top("pride-cec-example");
    fs::create_directory_symlink(fs::path(PRIDE_SOURCE_DIR) / "examples", top.path() / "examples");
    fs::create_directory(top.path() / ".bin");
    fs::create_symlink(PRIDE_EXE, top.path() / ".bin" / "pride");
    const std::string data = top.file("input_data");
    pride::test::cec_synthetic::write_input_data(data, 2017);
    const auto shell = [&](std::string command) {
        const std::string placeholder = "/path/to/input_data";
        if (const auto at = command.find(placeholder); at != std::string::npos)
            command.replace(at, placeholder.size(), data);
        const std::string line = "cd '" + top.path().string() + "' && PATH='" + top.file(".bin") + ":" +
                                 std::getenv("PATH") + "' " + command + " >'" + top.file("out") + "' 2>&1 </dev/null";
        const int status = std::system(line.c_str());
        return std::make_pair(status, pride::test::slurp(top.file("out")));
    };
    const auto [bench_status, bench] = shell(commands[0]);
    INFO(commands[0] << "\n" << bench);
    REQUIRE(bench_status == 0);
    // 2 problems x 2 algorithms x 51 runs (the suite's), of 100,000 evaluations (10000 D) each.
    CHECK(bench == "cec2017-small: 204 runs stored in cec2017-small.sqlite (0 were there already, 204 in all)\n");
    const auto [report_status, report] = shell(commands[1]);
    INFO(commands[1] << "\n" << report);
    REQUIRE(report_status == 0);
    for (const char* problem : {"cec2017-f1-d10", "cec2017-f22-d10"})
        for (const char* algorithm : {"ga", "pso"}) {
            CHECK_THAT(report, Contains(fmt::format("| {} | {} | 10 | 100000 | 51 | ", problem, algorithm)));
            CHECK_THAT(report, Contains(fmt::format("### {}, {}\n", problem, algorithm)));
        }
    CHECK_THAT(report, Contains("cec2017-f22 (cec2017), D = 10, f* = 2200, MaxFES = 100000, 51 runs.\n"));
    CHECK_THAT(report, Contains("| 0.01 | 1000 | "));
    CHECK_THAT(report, Contains("| 1.0 | 100000 | "));
}

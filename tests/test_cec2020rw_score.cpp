// The CEC 2020 real-world competition's statistics and ranking (experiment/report/cec2020rw_score.hpp)
// on an example worked by hand from the guidelines' eq. 4-9 and their edge cases; the campaigns'
// [[suite]] name = "cec2020rw" (its problems, default runs and budgets, refusals) and
// `pride report --format cec2020rw` on a store those campaigns wrote.
#include <fmt/format.h>
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "engine/run.hpp"
#include "experiment/campaign/prepare.hpp"
#include "experiment/campaign/run.hpp"
#include "experiment/campaign/toml.hpp"
#include "experiment/report/cec2017_score.hpp"
#include "experiment/report/cec2020rw_score.hpp"
#include "experiment/report/cec2020rw_table.hpp"
#include "experiment/storage/reader.hpp"
#include "framework/error.hpp"
#include "tests/cli_runner.hpp"
#include "tests/test_support.hpp"

using namespace pride::report::cec2020rw;
using Catch::Matchers::Contains;

TEST_CASE("cec2020rw score: the footnote's order and section 3.1's statistics", "[cec2020rw-score]") {
    // Feasible by f, then infeasible by violation, whatever their f.
    CHECK(precedes({5, 0}, {-100, 0.1}));
    CHECK(precedes({1, 0}, {2, 0}));
    CHECK(precedes({9, 0.1}, {-9, 0.2}));
    CHECK_FALSE(precedes({-9, 0.2}, {9, 0.1}));
    const std::vector<Outcome> runs{{0.5, 0.2}, {4, 0}, {5, 0}};
    const Summary s = summarise(runs, "B on P1");
    CHECK(s.best.f == 4);
    CHECK(s.median.f == 5);
    CHECK(s.worst.violation == 0.2);
    CHECK(s.mean.f == Approx(9.5 / 3));
    CHECK(s.mean.violation == Approx(0.2 / 3));
    CHECK(s.feasible_rate == Approx(2.0 / 3));
    CHECK(s.runs == 3);
    // Sample standard deviation of 0.5, 4, 5.
    CHECK(s.std_f == Approx(2.3629078131));
    // Of 25 runs the median is the 13th in the order (the runs given in reverse).
    std::vector<Outcome> many;
    for (int k = 25; k >= 1; --k) many.push_back({static_cast<double>(k), 0});
    CHECK(summarise(many, "x").median.f == 13);
    const std::vector<Outcome> one{{3, 0}};
    CHECK(summarise(one, "x").std_f == 0);
}

TEST_CASE("cec2020rw score: eq. 5's weights", "[cec2020rw-score]") {
    CHECK(weight(2) == 0.008);
    CHECK(weight(10) == 0.008);
    CHECK(weight(11) == 0.016);
    CHECK(weight(30) == 0.016);
    CHECK(weight(50) == 0.024);
    CHECK(weight(150) == 0.032);
    CHECK(weight(158) == 0.040);
}

TEST_CASE("cec2020rw score: eq. 4-9 on an example worked by hand", "[cec2020rw-score]") {
    // Three algorithms, P1 (D = 5, w = 0.008) and P2 (D = 20, w = 0.016), three runs each.
    const std::vector<std::vector<std::vector<Outcome>>> runs{
        {{{1, 0}, {3, 0}, {2, 0}}, {{10, 1}, {10, 3}, {10, 2}}},     // A
        {{{0.5, 0.2}, {4, 0}, {5, 0}}, {{7, 0}, {9, 0}, {8, 0.5}}},  // B
        {{{2, 0}, {2, 0}, {2, 0}}, {{6, 0}, {6, 0}, {6, 0}}},        // C
    };
    std::vector<std::vector<Summary>> s;
    for (const auto& algorithm : runs) {
        s.emplace_back();
        for (const auto& problem : algorithm) s.back().push_back(summarise(problem, "x"));
    }
    const std::vector<std::int64_t> dims{5, 20};
    const auto scores = score(s, dims);
    // By hand. Best: P1 A 1, B 4, C 2 -> 0, 1, 1/3; P2 A infeasible (nu 1) with the worst feasible
    // best 7 -> 8, B 7, C 6 -> 1, 1/2, 0. Mean: P1 A 2, B infeasible (nu 0.2/3) over the worst
    // feasible mean 2, C 2 -> 0, 1, 0; P2 A (nu 2) and B (nu 1/6) over C's 6 -> 1, 1/12, 0. Median:
    // P1 A 2, B 5, C 2 -> 0, 1, 0; P2 A (nu 2) over the worst feasible median 9 -> 11, B 9, C 6 ->
    // 1, 3/5, 0.
    CHECK(scores[0].best == Approx(0.016));
    CHECK(scores[0].mean == Approx(0.016));
    CHECK(scores[0].median == Approx(0.016));
    CHECK(scores[0].total == Approx(0.016));
    CHECK(scores[1].best == Approx(0.008 + 0.016 * 0.5));
    CHECK(scores[1].mean == Approx(0.008 + 0.016 / 12));
    CHECK(scores[1].median == Approx(0.008 + 0.016 * 0.6));
    CHECK(scores[1].total == Approx(0.5 * 0.016 + 0.3 * (0.008 + 0.016 / 12) + 0.2 * 0.0176));
    CHECK(scores[2].best == Approx(0.008 / 3));
    CHECK(scores[2].mean == 0);
    CHECK(scores[2].median == 0);
    CHECK(ranks(scores) == std::vector<int>{3, 2, 1});
}

TEST_CASE("cec2020rw score: no feasible solution, equal values, bad input", "[cec2020rw-score]") {
    // No feasible best on the problem: f_worst is 0 and the violations alone decide.
    const std::vector<Outcome> a{{100, 1}}, b{{-100, 3}};
    std::vector<std::vector<Summary>> s{{summarise(a, "a")}, {summarise(b, "b")}};
    const std::vector<std::int64_t> dims{40};
    auto scores = score(s, dims);
    CHECK(scores[0].best == 0);
    CHECK(scores[1].best == Approx(0.024));
    // Equal adjusted values everywhere add nothing (eq. 7 would divide by 0).
    s = {{summarise(a, "a")}, {summarise(a, "a")}};
    scores = score(s, dims);
    CHECK(scores[0].total == 0);
    CHECK(scores[1].total == 0);
    CHECK(ranks(scores) == std::vector<int>{1, 1});
    // Errors name what.
    CHECK_THROWS_WITH(summarise(std::vector<Outcome>{}, "colshade on RC01"),
                      Contains("colshade on RC01") && Contains("no runs"));
    CHECK_THROWS_WITH(summarise(std::vector<Outcome>{{std::numeric_limits<double>::infinity(), 0}}, "RC02"),
                      Contains("RC02") && Contains("finite"));
    CHECK_THROWS_WITH(summarise(std::vector<Outcome>{{1, -1}}, "RC03"), Contains("RC03"));
    CHECK_THROWS_AS(score(s, std::vector<std::int64_t>{1, 2}), pride::InputError);
}

TEST_CASE("cec2020rw score: no result (NaN) counts as MATLAB counts it in the organisers' script",
          "[cec2020rw-score]") {
    // Two problems (D = 5 and D = 60, weights 0.008 and 0.032). C has no result on the first (NaN f
    // and violation, as the text "nan" of an entrant's workbook reads): it is left out of that
    // problem's worst feasible f and range, and scores 1 there in every kind.
    const double nan = std::nan("");
    const std::vector<Outcome> a1{{1, 0}}, b1{{3, 0}}, c1{{nan, nan}}, a2{{5, 0}}, b2{{5, 0}}, c2{{1, 2}};
    const Summary none = summarise(c1, "c");
    CHECK(std::isnan(none.best.f));
    CHECK(std::isnan(none.mean.violation));
    std::vector<std::vector<Summary>> s{
        {summarise(a1, "a"), summarise(a2, "a")}, {summarise(b1, "b"), summarise(b2, "b")}, {none, summarise(c2, "c")}};
    const std::vector<std::int64_t> dims{5, 60};
    auto scores = score(s, dims);
    // Problem 1: A 0, B 1 (range 1..3), C 1. Problem 2: worst feasible f 5, so C's 5 + 2 = 7:
    // A and B 0, C 1.
    CHECK(scores[0].best == 0);
    CHECK(scores[1].best == Approx(0.008));
    CHECK(scores[2].best == Approx(0.008 + 0.032));
    CHECK(scores[2].total == Approx(0.040));
    CHECK(ranks(scores) == std::vector<int>{1, 2, 3});
    // A NaN f with a violation (the workbook's 12345 beside "nan") is infeasible, so it counts as
    // the worst feasible f plus the violation, a number: on problem 1, 3 + 12345 widens the range.
    s[2][0] = summarise(std::vector<Outcome>{{nan, 12345}}, "c");
    scores = score(s, dims);
    CHECK(scores[1].best == Approx(0.008 * 2.0 / 12347.0));
    CHECK(scores[2].best == Approx(0.040));
    // A feasible NaN f is left out of the worst feasible f and scores 1.
    s[2][0] = summarise(std::vector<Outcome>{{nan, 0}}, "c");
    scores = score(s, dims);
    CHECK(scores[1].best == Approx(0.008));
    CHECK(scores[2].best == Approx(0.040));
    // Everyone else equal on a problem: they add 0 there, the one without a result still 1.
    s = {{summarise(a1, "a")}, {summarise(a1, "a")}, {none}};
    const auto equal = score(s, std::vector<std::int64_t>{5});
    CHECK(equal[0].total == 0);
    CHECK(equal[2].total == Approx(0.008));
    // In the footnote's order a run with a NaN comes last; in the order given it stays where it is.
    const std::vector<Outcome> runs{{nan, 0}, {4, 0}, {2, 1}};
    CHECK(summarise(runs, "r").best.f == 4);
    CHECK(summarise(runs, "r").median.violation == 1);
    CHECK(std::isnan(summarise(runs, "r", pride::report::cec2020rw::Order::given).best.f));
    CHECK(std::isnan(summarise(runs, "r").mean.f));
}

namespace {

std::string quoted(const std::string& s) {
    return "'" + s + "'";
}

}  // namespace

TEST_CASE("cec2020rw suite: [[suite]] expands to pride's problems with the competition's runs and budgets",
          "[cec2020rw-score]") {
    const pride::test::TempDir dir;
    auto c = pride::campaign::parse_campaign(
        dir.write("c.toml",
                  "name = \"rw\"\n[[suite]]\nname = \"cec2020rw\"\nfunctions = [17, 8, 36]\n"
                  "[[algorithm]]\nid = \"de\"\ntype = \"de\"\n"));
    pride::campaign::apply_suite_rules(c);
    std::vector<std::string> ids;
    std::vector<std::int64_t> dims, evaluations;
    for (const auto& p : c.problems) {
        ids.push_back(p.id);
        dims.push_back(std::get<pride::engine::ContinuousSpec>(p.spec).dim);
        evaluations.push_back(p.evaluations.value_or(-1));
        CHECK(p.suite == "cec2020rw");
    }
    CHECK(ids == std::vector<std::string>{"cec2020rw-rc17", "cec2020rw-rc08", "cec2020rw-rc36"});
    CHECK(dims == std::vector<std::int64_t>{3, 2, 158});
    // The guidelines' eq. 1 and 25 runs.
    CHECK(evaluations == std::vector<std::int64_t>{100000, 100000, 1000000});
    CHECK(c.seeds == 25);
    // Without `functions`: all 57.
    auto all = pride::campaign::parse_campaign(
        dir.write("a.toml",
                  "name = \"rw\"\nseeds = 2\n[budget]\nevaluations = 10\n[[suite]]\nname = "
                  "\"cec2020rw\"\nid = \"rw\"\n[[algorithm]]\nid = \"de\"\ntype = \"de\"\n"));
    REQUIRE(all.problems.size() == 57);
    CHECK(all.problems[23].id == "rw-rc24");
    CHECK(all.problems[56].id == "rw-rc57");
}

TEST_CASE("cec2020rw suite: dimensions, instances and problems outside the suite are refused by pride bench",
          "[cec2020rw-score]") {
    const pride::test::TempDir dir;
    const auto refused = [&](const std::string& body, const std::vector<std::string>& words) {
        const std::string file = dir.write("c.toml", "name = \"rw\"\nseeds = 1\n[budget]\nevaluations = 100\n" + body +
                                                         "[[algorithm]]\nid = \"de\"\ntype = \"de\"\n");
        INFO(body);
        pride::test::check_input_error(
            pride::test::run_pride("bench " + quoted(file) + " --out " + quoted(dir.file("c.sqlite"))), words);
        CHECK(!std::filesystem::exists(dir.file("c.sqlite")));
    };
    refused("[[suite]]\nname = \"cec2020rw\"\ndimensions = [10]\n",
            {"c.toml:7:14: 'dimensions': each cec2020rw problem has one dimension of its own and no instances"});
    refused("[[suite]]\nname = \"cec2020rw\"\ninstances = [1]\n", {"c.toml:7:13: 'instances'"});
    refused("[[suite]]\nname = \"cec2020rw\"\nfunctions = [58]\n",
            {"c.toml:7:13: problem 58 is not in the cec2020rw suite (1-57)"});
    refused("[[suite]]\nname = \"cec2020rw\"\nfunctions = []\n", {"c.toml:5", "must not be empty"});
}

TEST_CASE("cec2020rw report: the tables and the score of a campaign's store", "[cec2020rw-score]") {
    const pride::test::TempDir dir;
    const std::string file =
        dir.write("c.toml",
                  "name = \"rw\"\nseeds = 3\n[budget]\nevaluations = 400\n[[suite]]\nname = \"cec2020rw\"\n"
                  "functions = [8, 17]\n[[algorithm]]\nid = \"colshade\"\ntype = \"colshade\"\n"
                  "[[algorithm]]\nid = \"de\"\ntype = \"de\"\npop = 10\n");
    const std::string store = dir.file("rw.sqlite");
    auto c = pride::campaign::read_campaign(file);
    (void)pride::campaign::run_campaign(c, store, 1);
    const auto stored = pride::storage::read_store(store);
    const auto table = pride::report::cec2020rw::make_table(stored, store);
    REQUIRE(table.rows.size() == 4);
    CHECK(table.algorithms == std::vector<std::string>{"colshade", "de"});
    CHECK(table.scored == std::vector<std::string>{"cec2020rw-rc08", "cec2020rw-rc17"});
    // Each row is section 3.1 of the store's runs; the scores are eq. 4 of those rows.
    std::map<std::pair<std::string, std::string>, std::vector<Outcome>> runs;
    for (const auto& r : stored.runs)
        runs[{r.problem, r.algorithm}].push_back(
            {r.best ? *r.best : *r.infeasible_f, r.best ? r.best_violation.value_or(0.0) : *r.best_violation});
    std::vector<std::vector<Summary>> by_algorithm(2);
    for (const auto& row : table.rows) {
        const Summary want = summarise(runs.at({row.problem, row.algorithm}), "x");
        CHECK(row.summary.best.f == want.best.f);
        CHECK(row.summary.median.violation == want.median.violation);
        CHECK(row.summary.mean.f == want.mean.f);
        CHECK(row.summary.runs == 3);
        by_algorithm[row.algorithm == "de"].push_back(want);
    }
    const std::vector<std::int64_t> dims{2, 3};
    const auto want = score(by_algorithm, dims);
    for (std::size_t a = 0; a < 2; ++a) CHECK(table.scores[a].total == want[a].total);
    // The command prints it; its CSV holds the same numbers; misuses are one line.
    const auto md = pride::test::run_pride("report " + quoted(store) + " --format cec2020rw");
    REQUIRE(md.status == 0);
    CHECK_THAT(md.out, Contains("| cec2020rw-rc08 | 2 | colshade | 3 |") && Contains("## The competition's score"));
    const auto csv = pride::test::run_pride("report " + quoted(store) + " --format cec2020rw-csv");
    REQUIRE(csv.status == 0);
    CHECK_THAT(csv.out, Contains(fmt::format("colshade,{},{},{},{},{},2", want[0].best, want[0].mean, want[0].median,
                                             want[0].total, table.ranks[0])));
    pride::test::check_input_error(pride::test::run_pride("report " + quoted(store) + " --format cec2020rw --raw"),
                                   {"--raw", "values f already"});
    // A store without such problems.
    const std::string other = dir.write("o.toml",
                                        "name = \"o\"\nseeds = 1\n[budget]\nevaluations = 50\n[[problem]]\n"
                                        "id = \"s\"\ntype = \"sphere\"\ndim = 2\n[[algorithm]]\nid = \"de\"\n"
                                        "type = \"de\"\n");
    auto o = pride::campaign::read_campaign(other);
    (void)pride::campaign::run_campaign(o, dir.file("o.sqlite"), 1);
    pride::test::check_input_error(
        pride::test::run_pride("report " + quoted(dir.file("o.sqlite")) + " --format cec2020rw"),
        {"o.sqlite", "has no run on a CEC 2020 real-world problem"});
}

TEST_CASE("cec2017 score: Score1, Score2 and ranks of an example worked by hand", "[cec2020rw-score]") {
    namespace c17 = pride::report::cec2017;
    // F1 at D = 10 and 30: A 1 and 4, B 3 and 2. SE: A 0.9, B 0.7; SR: A 0.1 + 0.4, B 0.2 + 0.2.
    const std::vector<c17::Cell> cells{{1, 10}, {1, 30}};
    const auto s = c17::score({{1.0, 4.0}, {3.0, 2.0}}, cells);
    CHECK(s[0].se == Approx(0.9));
    CHECK(s[1].sr == Approx(0.4));
    CHECK(s[0].score1 == Approx(50.0 * 0.7 / 0.9));
    CHECK(s[0].score2 == Approx(40.0));
    CHECK(s[1].total == 100.0);
    CHECK(s[1].rank == 1);
    CHECK(s[0].rank == 2);
    // Ties share their mean rank: both 1.5, both Score2 50.
    const auto tied = c17::score({{1.0, 4.0}, {1.0, 4.0}}, cells);
    CHECK(tied[0].sr == Approx(0.1 * 1.5 + 0.2 * 1.5));
    CHECK(tied[0].rank == 1);
    CHECK(tied[1].rank == 1);
    CHECK_THROWS_WITH(c17::weight(20), Contains("D = 10, 30, 50 and 100, got 20"));
    CHECK_THROWS_WITH(c17::score({{1.0}}, cells), Contains("1 mean errors for 2 cells"));
    CHECK_THROWS_WITH(c17::score({{1.0, -2.0}}, cells), Contains("F1 at D = 30"));
    CHECK_THROWS_AS(c17::score({}, cells), pride::InputError);
}

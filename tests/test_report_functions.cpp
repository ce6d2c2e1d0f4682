// Reports on suites with instances (experiment/report/report.hpp): the runs of all the instances and
// seeds of a function are one sample per algorithm, as COCO pools instances, for the tests against
// the best, the table of functions and Friedman's blocks; problems without instances keep their own
// tests. Also the natural order of every listing (natural_order.hpp) and the layout of Demsar's
// critical-difference diagram (experiment/html/cd_diagram.hpp), checked in ranks and rows.
#include <fmt/format.h>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "experiment/html/cd_diagram.hpp"
#include "experiment/report/critical_difference.hpp"
#include "experiment/report/natural_order.hpp"
#include "experiment/report/report.hpp"
#include "tests/cli_runner.hpp"
#include "tests/test_support.hpp"

namespace {

using pride::report::natural_compare;
using pride::report::NaturalLess;

pride::storage::StoredRun run(const std::string& problem, const std::string& algorithm, std::int64_t seed,
                              double best) {
    pride::storage::StoredRun r;
    r.problem = problem;
    r.algorithm = algorithm;
    r.seed = seed;
    r.best = best;
    r.evaluations = 100;
    r.wall_ms = 1;
    return r;
}

pride::storage::StoredProblem problem(const std::string& id, const std::string& function, std::int64_t instance,
                                      double f_opt) {
    pride::storage::StoredProblem p;
    p.id = id;
    p.dim = 2;
    p.function = function;
    p.instance = instance;
    p.f_opt = f_opt;
    return p;
}

/// bbob-f1 in 2-D, instances 1 (f_opt 0) and 2 (f_opt -4), algorithms a and b, 3 seeds each, with
/// precisions chosen so that f - f_opt is exact; and sphere (instance 0, f_opt 0), a problem of its own.
pride::storage::CampaignStore hand_made() {
    pride::storage::CampaignStore s;
    s.name = "pooled";
    s.problems = std::vector{problem("bbob-f1-i2-d2", "bbob-f1", 2, -4), problem("bbob-f1-i1-d2", "bbob-f1", 1, 0),
                             problem("sphere", "sphere", 0, 0)};
    const std::vector<double> a1{1e-9, 0.25, 2}, a2{0, 0.5, 4}, b1{10, 30, 50}, b2{20, 40, 60};
    for (std::int64_t k = 0; k < 3; ++k) {
        s.runs.push_back(run("bbob-f1-i1-d2", "a", k + 1, a1[k]));
        s.runs.push_back(run("bbob-f1-i1-d2", "b", k + 1, b1[k]));
        s.runs.push_back(run("bbob-f1-i2-d2", "a", k + 1, -4 + a2[k]));
        s.runs.push_back(run("bbob-f1-i2-d2", "b", k + 1, -4 + b2[k]));
        s.runs.push_back(run("sphere", "a", k + 1, 1.0 + static_cast<double>(k)));
        s.runs.push_back(run("sphere", "b", k + 1, 0.5 + static_cast<double>(k)));
    }
    return s;
}

}  // namespace

TEST_CASE("natural order: digit runs compare by value", "[report][natural-order]") {
    std::vector<std::string> names{"f10",
                                   "f2",
                                   "f1",
                                   "g10",
                                   "g2",
                                   "RC10",
                                   "RC2",
                                   "RC01",
                                   "bbob-f15-i1-d5",
                                   "bbob-f8-i1-d5",
                                   "bbob-f8-i10-d5",
                                   "bbob-f8-i2-d5",
                                   "f",
                                   "f1a",
                                   "f01"};
    std::sort(names.begin(), names.end(), NaturalLess{});
    CHECK(names == std::vector<std::string>{"RC01", "RC2", "RC10", "bbob-f8-i1-d5", "bbob-f8-i2-d5", "bbob-f8-i10-d5",
                                            "bbob-f15-i1-d5", "f", "f1", "f01", "f1a", "f2", "f10", "g2", "g10"});
    CHECK(natural_compare("f2", "f10") < 0);
    CHECK(natural_compare("f10", "f2") > 0);
    CHECK(natural_compare("g2", "g2") == 0);
    // Only equal strings compare equal: a map keeps f1 and f01 apart (f1 first, fewer zeros).
    CHECK(natural_compare("f1", "f01") < 0);
    CHECK(natural_compare("f01", "f1") > 0);
    // Numbers beyond any integer type compare by their digits.
    CHECK(natural_compare("x123456789012345678901234567890", "x99999999999999999999999999999") > 0);
    CHECK(natural_compare("", "a") < 0);
    CHECK(natural_compare("a-2", "a_2") < 0);  // '-' before '_' as in ASCII
}

TEST_CASE("report: rows and functions in natural order", "[report][natural-order]") {
    pride::storage::CampaignStore s;
    s.name = "order";
    for (const std::string p : {"f10", "f2", "f1"})
        for (const std::string a : {"pso", "ga"}) s.runs.push_back(run(p, a, 1, 1.0));
    const auto report = pride::report::make_report(s);
    std::vector<std::string> problems;
    for (const auto& r : report.rows)
        if (problems.empty() || problems.back() != r.problem) problems.push_back(r.problem);
    CHECK(problems == std::vector<std::string>{"f1", "f2", "f10"});
    CHECK(report.rows.front().algorithm == "ga");
}

TEST_CASE("report: a function's instances are one sample, its table's numbers by hand", "[report][functions]") {
    const auto s = hand_made();
    for (const bool raw : {false, true}) {
        INFO("raw " << raw);
        const auto report = pride::report::make_report(s, pride::report::ReportOptions{raw});
        REQUIRE(report.functions.size() == 2);
        const auto& a = report.functions[0];
        const auto& b = report.functions[1];
        CHECK(a.function == "bbob-f1");
        CHECK(a.dim == 2);
        CHECK(a.algorithm == "a");
        CHECK(a.runs == 6);
        CHECK(a.instances == 2);
        CHECK(a.precision);
        // a: 0, 1e-9, 0.25, 0.5, 2, 4 (precisions, also under --raw).
        CHECK(a.median == 0.375);
        // Hazen's percentiles (cocopp's): position p/100 * 6 - 1/2, 0.1 and 4.9.
        CHECK(a.p10 == Approx(1e-10).epsilon(1e-12));
        CHECK(a.p90 == Approx(3.8).epsilon(1e-15));
        CHECK(a.mean == Approx(6.750000001 / 6).epsilon(1e-15));
        CHECK(a.solved == 2);  // 0 and 1e-9 are within 1e-8
        CHECK(a.best);
        CHECK_FALSE(a.p_holm);
        // b: 10, 20, ..., 60.
        CHECK(b.algorithm == "b");
        CHECK(b.median == 35);
        CHECK(b.p10 == Approx(11).epsilon(1e-15));
        CHECK(b.p90 == Approx(59).epsilon(1e-15));
        CHECK(b.mean == 35);
        CHECK(b.solved == 0);
        CHECK_FALSE(b.best);
        // Every run of a below every run of b: U = 0 of 36 pairs; z = (18 - 1/2) / sqrt(6 * 6 * 13 / 12);
        // one test, so Holm leaves it; per instance (3 against 3) it could not go below 0.1.
        REQUIRE(b.p_holm);
        CHECK(*b.p_holm == Approx(std::erfc(17.5 / std::sqrt(39.0) / std::sqrt(2.0))).epsilon(1e-12));
        CHECK(*b.p_holm < 0.05);
        REQUIRE(b.a12);
        CHECK(*b.a12 == 0);
        // The instances' own rows: described, best marked, but not tested one instance at a time.
        std::size_t instance_rows = 0;
        for (const auto& r : report.rows) {
            INFO(r.problem << " " << r.algorithm);
            if (r.problem == "sphere") {
                CHECK(r.function.empty());
                CHECK(r.p_holm.has_value() == !r.best);
                continue;
            }
            ++instance_rows;
            CHECK(r.function == "bbob-f1 2-D");
            CHECK_FALSE(r.p_holm);
            CHECK_FALSE(r.a12);
            CHECK(r.best == (r.algorithm == "a"));
        }
        CHECK(instance_rows == 4);
        // Friedman: the function is one block, sphere another.
        REQUIRE(report.friedman);
        CHECK(report.friedman->problems == 2);
        CHECK(report.friedman->functions == 1);
        // a wins bbob-f1 (median 0.375 against 35), b wins sphere (1.5 against 2): ranks 1.5 each.
        CHECK(report.friedman->test.average_ranks == std::vector<double>{1.5, 1.5});
        const std::string md = pride::report::render_markdown(report);
        INFO(md);
        CHECK(md.find("| bbob-f1 | 2 | a | 6 | 2 | 0.375 | 1e-10 | 3.8 | 1.125 | 2/6 | best | - |\n") !=
              std::string::npos);
        CHECK(md.find("| bbob-f1 | 2 | b | 6 | 2 | 35 | 11 | 59 | 35 | 0/6 | 0.00507* | 0.00 |\n") !=
              std::string::npos);
        CHECK(md.find("Friedman average ranks over 2 blocks, 1 function and dimension and 1 problem without "
                      "instances (1 = best; a function's value is the median precision f - f_opt of its runs over "
                      "all its instances and seeds, a problem's the median of its runs):") != std::string::npos);
        CHECK(md.find("Per function and dimension, over all its instances and seeds") != std::string::npos);
    }
}

TEST_CASE("report: a store without instances has no table of functions and ranks problems", "[report][functions]") {
    auto s = hand_made();
    for (auto& p : *s.problems) p.instance = 0;
    const auto report = pride::report::make_report(s);
    CHECK(report.functions.empty());
    REQUIRE(report.friedman);
    CHECK(report.friedman->problems == 3);
    CHECK(report.friedman->functions == 0);
    for (const auto& r : report.rows) CHECK(r.p_holm.has_value() == !r.best);
    const std::string md = pride::report::render_markdown(report);
    CHECK(md.find("Friedman average ranks over 3 problems (1 = best; median values):") != std::string::npos);
    CHECK(md.find("Per function and dimension") == std::string::npos);
}

TEST_CASE("report: pride bench on 15 BBOB instances, 1 seed: the function's test is significant",
          "[report][functions][bench]") {
    // One seed per instance: no (function, instance) comparison can be significant (1 run against
    // 1), while over 15 instances CMA-ES beats random sampling on the sphere and the ellipsoid.
    const pride::test::TempDir tmp("pride-functions");
    const std::string file =
        tmp.write("c.toml",
                  "name = \"instances\"\nseeds = 1\n[budget]\nevaluations = 400\n"
                  "[[suite]]\nname = \"bbob\"\nfunctions = [1, 2]\ninstances = [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, "
                  "13, 14, 15]\ndimensions = [2]\n"
                  "[[algorithm]]\nid = \"cmaes\"\ntype = \"cmaes\"\n"
                  "[[algorithm]]\nid = \"ga\"\ntype = \"ga\"\npop = 10\n");
    const auto bench = pride::test::run_pride("bench '" + file + "' --jobs 2 --out '" + tmp.file("c.sqlite") + "'");
    INFO(bench.err);
    REQUIRE(bench.status == 0);
    const auto report = pride::report::load_report(tmp.file("c.sqlite"));
    REQUIRE(report.functions.size() == 4);
    for (const auto& f : report.functions) {
        INFO(f.function << " " << f.algorithm);
        CHECK(f.runs == 15);
        CHECK(f.instances == 15);
        CHECK(f.best == (f.algorithm == "cmaes"));
        if (!f.best) {
            REQUIRE(f.p_holm);
            CHECK(*f.p_holm < 0.01);
        }
    }
    CHECK(report.rows.size() == 60);
    for (const auto& r : report.rows) {
        CHECK(r.runs == 1);
        CHECK_FALSE(r.p_holm);
    }
    REQUIRE(report.friedman);
    CHECK(report.friedman->problems == 2);
    CHECK(report.friedman->functions == 2);
    // The markdown lists the instances in natural order: i2 before i10.
    const std::string md = pride::report::render_markdown(report);
    CHECK(md.find("| bbob-f1-i2-d2 | cmaes") < md.find("| bbob-f1-i10-d2 | cmaes"));
    CHECK(md.find("Friedman average ranks over 2 functions and dimensions") != std::string::npos);
    // The same rows as CSV, every number the double it is.
    const auto csv = pride::test::run_pride("report '" + tmp.file("c.sqlite") + "' --format functions-csv");
    REQUIRE(csv.status == 0);
    const auto lines = pride::test::lines_of(csv.out);
    REQUIRE(lines.size() == 5);
    CHECK(lines[0] ==
          "function,dim,algorithm,runs,instances,median,p10,p90,mean,measure,solved,feasible_runs,best,p_holm_vs_best,"
          "a12_vs_best");
    for (std::size_t i = 0; i < report.functions.size(); ++i) {
        const auto& f = report.functions[i];
        CHECK(lines[i + 1] == fmt::format("{},2,{},15,15,{},{},{},{},precision,{},,{},{},{}", f.function, f.algorithm,
                                          f.median, f.p10, f.p90, f.mean, f.solved, f.best ? 1 : 0,
                                          f.p_holm ? fmt::format("{}", *f.p_holm) : "",
                                          f.a12 ? fmt::format("{}", *f.a12) : ""));
    }
}

TEST_CASE("critical-difference diagram: names, sides, rows and bars laid out in ranks",
          "[report][critical-difference]") {
    using pride::html::cd_layout;
    // Five algorithms; by rank 1 (1.0), 3 (1.5), 0 (2.5), 4 (3.0), 2 (3.75). With CD = 1 the groups
    // are {1, 3}, {0, 4} and {4, 2}: the first two side by side on one level, the third (which
    // shares algorithm 4 with the second) on the next.
    const std::vector<double> ranks{2.5, 1.0, 3.75, 1.5, 3.0};
    const pride::stats::CriticalDifference cd{0.05, 1.0, pride::stats::critical_difference_cliques(ranks, 1.0)};
    REQUIRE(cd.cliques == std::vector<std::vector<std::size_t>>{{1, 3}, {0, 4}, {4, 2}});
    const auto layout = cd_layout(ranks, cd);
    CHECK(layout.low == 1);
    CHECK(layout.high == 5);
    CHECK(layout.cd_from == 1);
    CHECK(layout.cd_to == 2);
    REQUIRE(layout.names.size() == 5);
    struct Want {
        std::size_t algorithm;
        double rank;
        bool left;
        std::size_t row;
    };
    // The better three at the left, best nearest the axis; the worse two at the right, worst nearest.
    const std::vector<Want> want{
        {1, 1.0, true, 0}, {3, 1.5, true, 1}, {0, 2.5, true, 2}, {4, 3.0, false, 1}, {2, 3.75, false, 0}};
    for (std::size_t i = 0; i < want.size(); ++i) {
        INFO("name " << i);
        CHECK(layout.names[i].algorithm == want[i].algorithm);
        CHECK(layout.names[i].rank == want[i].rank);
        CHECK(layout.names[i].left == want[i].left);
        CHECK(layout.names[i].row == want[i].row);
    }
    REQUIRE(layout.bars.size() == 3);
    CHECK(layout.bars[0].from == 1.0);
    CHECK(layout.bars[0].to == 1.5);
    CHECK(layout.bars[0].level == 0);
    CHECK(layout.bars[1].from == 2.5);
    CHECK(layout.bars[1].to == 3.0);
    CHECK(layout.bars[1].level == 0);
    CHECK(layout.bars[2].from == 3.0);
    CHECK(layout.bars[2].to == 3.75);
    CHECK(layout.bars[2].level == 1);
    CHECK(layout.levels == 2);

    // Two algorithms over two problems: CD = 1.96 sqrt(2 * 3 / 12) = 1.386 is longer than the axis
    // from 1 to 2, which then reaches rank 3; ranks 1 and 2 differ by less: one bar.
    const std::vector<double> two{2.0, 1.0};
    const auto d = pride::stats::critical_difference(two, 2);
    const auto l = cd_layout(two, d);
    CHECK(l.high == 3);
    CHECK(l.cd_to == Approx(1 + d.cd));
    REQUIRE(l.bars.size() == 1);
    CHECK(l.bars[0].from == 1.0);
    CHECK(l.bars[0].to == 2.0);
    CHECK(l.names[0].algorithm == 1);
    CHECK(l.names[0].left);
    CHECK_FALSE(l.names[1].left);
    CHECK(l.names[1].row == 0);
}

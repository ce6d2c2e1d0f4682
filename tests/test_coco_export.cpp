// `pride export STORE --coco DIR`: COCO's data files (.info, .dat, .tdat) from each run's COCO
// trace (framework/coco_trace.hpp), and cocopp reading them (scripts/cocopp_check.py) when a
// numbbo/coco-postprocess checkout is named by PRIDE_COCOPP_SRC.
#include <fmt/format.h>
#include <sqlite3.h>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "experiment/storage/reader.hpp"
#include "framework/coco_trace.hpp"
#include "framework/run_state.hpp"
#include "problems/continuous/bbob_constrained/bbob_constrained.hpp"
#include "tests/cli_runner.hpp"
#include "tests/sqlite_support.hpp"
#include "tests/test_support.hpp"

namespace fs = std::filesystem;
using pride::test::expect_input_error;
using pride::test::run_pride;
using pride::test::slurp;

using pride::test::exec_sql;

namespace {

constexpr const char* kCampaign =
    "name = \"coco-export\"\nseeds = 2\n[budget]\nevaluations_per_dim = 300\n"
    "[[suite]]\nname = \"bbob\"\nfunctions = [1, 15]\ninstances = [1, 2]\ndimensions = [2, 3]\n"
    "[[problem]]\nid = \"rastrigin3\"\ntype = \"rastrigin\"\ndim = 3\n"
    "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\npop = 10\n"
    "[[algorithm]]\nid = \"ga\"\ntype = \"ga\"\npop = 10\n";

struct Line {
    long long evaluations = 0;
    double precision = 0, best = 0;
};

/// The blocks of a .dat or .tdat file: one per run, each its data lines.
std::vector<std::vector<Line>> blocks(const std::string& text) {
    std::vector<std::vector<Line>> out;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("% f evaluations | g evaluations | best noise-free fitness - Fopt (", 0) == 0) {
            out.emplace_back();
            continue;
        }
        REQUIRE(!out.empty());
        std::istringstream fields(line);
        Line l;
        long long g = -1;
        double measured = 0;
        fields >> l.evaluations >> g >> l.precision >> measured >> l.best;
        REQUIRE(fields);
        CHECK(g == 0);
        CHECK(measured == l.best);
        out.back().push_back(l);
    }
    return out;
}

}  // namespace

TEST_CASE("coco trace: COCO's triggers, as its bbob logger fires them", "[coco][export]") {
    pride::CocoTrace t(10.0, 2);  // f_opt 10, dimension 2
    // Evaluation 1 is always logged; improvements are logged when the precision enters a new
    // 1/20 decade (COCO's 20 target triggers per decade).
    const std::vector<double> values{110.0, 109.0, 80.0, 79.99, 15.0, 10.5, 10.0 + 1e-9, 10.0};
    double best = INFINITY;
    for (std::size_t k = 0; k < values.size(); ++k) {
        const bool better = values[k] < best;
        if (better) best = values[k];
        t.record(static_cast<std::int64_t>(k + 1), best, better);
    }
    // precisions 100 (eval 1), 99 (ceil(20 log10 99) = 40: a new trigger from eval 1's, which
    // moved none), 70 (37), 69.99 (37: not new), 5 (14), 0.5 (-6), 1e-9 (clamped to 1e-8: -160),
    // 0 (1e-9: -180).
    const std::vector<pride::TracePoint> targets{{1, 110.0}, {2, 109.0},       {3, 80.0}, {5, 15.0},
                                                 {6, 10.5},  {7, 10.0 + 1e-9}, {8, 10.0}};
    CHECK(t.targets() == targets);
    // Evaluation triggers: floor(10^(k/20)) gives 1, 2, 3, 4, 5, 6, 7, 8, ...; dim * {1, 2, 5} gives
    // 2, 4, 10: every one of the first eight evaluations.
    CHECK(t.evaluations().size() == 8);

    pride::CocoTrace long_run(0.0, 10);
    for (std::int64_t e = 1; e <= 100000; ++e) long_run.record(e, 1.0, false);
    std::vector<std::int64_t> logged;
    for (const auto& p : long_run.evaluations()) logged.push_back(p.evaluations);
    // floor(10^(k/20)) up to 10^5 and 10 * {1, 2, 5} * 10^k: 1..8, then 10, 11, 12, 14, 15, 17, 20, ...
    CHECK(logged.front() == 1);
    CHECK(logged.back() == 100000);
    CHECK(std::count(logged.begin(), logged.end(), 50) == 1);  // 10 * 5
    CHECK(std::count(logged.begin(), logged.end(), 89) == 1);  // floor(10^(39/20)) = 89
    CHECK(std::count(logged.begin(), logged.end(), 9) == 0);   // neither trigger
    CHECK(logged.size() < 130);                                // 20 per decade + 3, not 10^5
}

TEST_CASE("export --coco: COCO's bbob files from a campaign, equal to the stored runs", "[coco][export]") {
    const pride::test::TempDir tmp("pride-coco-export");
    const fs::path& dir = tmp.path();
    std::ofstream(dir / "c.toml") << kCampaign;
    const std::string store = (dir / "c.sqlite").string();
    REQUIRE(run_pride("bench '" + (dir / "c.toml").string() + "' --jobs 2 --out '" + store + "'").status == 0);
    const auto r = run_pride("export '" + store + "' --coco '" + (dir / "coco").string() + "'");
    INFO(r.out << r.err);
    REQUIRE(r.status == 0);
    // 2 algorithms x 2 functions x 2 dimensions x 2 instances x 2 seeds; the rastrigin runs are not bbob.
    CHECK(r.out == "32 runs of 2 algorithms written as COCO data (20 files) under " + (dir / "coco").string() +
                       "\n4 runs on problems outside the bbob suite not written (not COCO's data)\n");

    const auto s = pride::storage::read_store(store);
    std::map<std::string, const pride::storage::StoredProblem*> problems;
    for (const auto& p : *s.problems) problems[p.id] = &p;
    for (const char* algorithm : {"pso", "ga"}) {
        for (const int fid : {1, 15}) {
            const fs::path a = dir / "coco" / algorithm;
            const std::string info = slurp(a / ("bbobexp_f" + std::to_string(fid) + ".info"));
            CHECK(info.rfind("suite = 'bbob', funcId = " + std::to_string(fid) +
                                 ", DIM = 2, Precision = 1.000e-08, algId = '" + algorithm +
                                 "', coco_version = 'pride ",
                             0) == 0);
            // As COCO's logger: the next dimension's header on the line after the last run's entry.
            CHECK(info.find("\nsuite = 'bbob', funcId = " + std::to_string(fid) + ", DIM = 3,") != std::string::npos);
            for (const int dim : {2, 3}) {
                const std::string stem =
                    "data_f" + std::to_string(fid) + "/bbobexp_f" + std::to_string(fid) + "_DIM" + std::to_string(dim);
                CHECK(info.find(stem + ".dat, 1:" + std::to_string(300 * dim) + "|") != std::string::npos);
                const auto dat = blocks(slurp(a / (stem + ".dat")));
                const auto tdat = blocks(slurp(a / (stem + ".tdat")));
                REQUIRE(dat.size() == 4);  // instances 1, 2 x seeds 1, 2, in that order
                REQUIRE(tdat.size() == 4);
                std::size_t k = 0;
                for (const int instance : {1, 2})
                    for (const int seed : {1, 2}) {
                        const std::string id = "bbob-f" + std::to_string(fid) + "-i" + std::to_string(instance) + "-d" +
                                               std::to_string(dim);
                        const pride::storage::StoredRun* run = nullptr;
                        for (const auto& x : s.runs)
                            if (x.problem == id && x.algorithm == algorithm && x.seed == seed) run = &x;
                        REQUIRE(run);
                        const double f_opt = *problems.at(id)->f_opt;
                        INFO(id << " " << algorithm << " seed " << seed);
                        for (const auto* b : {&dat[k], &tdat[k]}) {
                            REQUIRE(!b->empty());
                            CHECK(b->front().evaluations == 1);
                            CHECK(b->back().evaluations == run->evaluations);  // the last line: the run's end
                            CHECK(b->back().best == Approx(*run->best).epsilon(1e-9));
                            // Both printed to 10 digits (%+10.9e): the best value to 1e-9 of its size.
                            for (const auto& l : *b)
                                CHECK(l.precision == Approx(l.best - f_opt).margin(1e-8 * (std::abs(l.best) + 1)));
                        }
                        // The .dat gives every target hit the run recorded: the first line at or
                        // below f_opt + precision is the hit (20 triggers per decade hold COCO's 5).
                        for (std::size_t j = 0; j < s.precisions->size(); ++j) {
                            const double precision = (*s.precisions)[j];
                            std::optional<std::int64_t> first;
                            for (const auto& l : dat[k])
                                if (l.precision <= precision * (1 + 1e-9)) {
                                    first = l.evaluations;
                                    break;
                                }
                            CHECK(first == run->target_hits[j]);
                        }
                        ++k;
                    }
            }
        }
    }
    CHECK(!fs::exists(dir / "coco" / "pso" / "bbobexp_f1001.info"));  // rastrigin3 is not COCO's
}

TEST_CASE("export --coco: bad input is one line, exit 2", "[coco][export]") {
    const pride::test::TempDir tmp("pride-coco-export-bad");
    const fs::path& dir = tmp.path();
    std::ofstream(dir / "c.toml") << kCampaign;
    const std::string store = (dir / "c.sqlite").string();
    REQUIRE(run_pride("bench '" + (dir / "c.toml").string() + "' --out '" + store + "'").status == 0);
    expect_input_error("export '" + store + "' --coco a --ioh b", {"--coco", "--ioh"});
    expect_input_error("export '" + store + "'", {"--ioh DIR or --coco DIR"});
    expect_input_error("export '" + (dir / "none.sqlite").string() + "' --coco '" + (dir / "x").string() + "'",
                       {"none.sqlite"});
    // A file where the folder should be.
    std::ofstream(dir / "file") << "x";
    expect_input_error("export '" + store + "' --coco '" + (dir / "file").string() + "'",
                       {(dir / "file").string() + ": exists and is not a folder"});

    // Only problems outside bbob: nothing to write.
    std::ofstream(dir / "r.toml") << "name = \"r\"\nseeds = 1\n[budget]\nevaluations = 50\n"
                                     "[[problem]]\nid = \"sphere2\"\ntype = \"sphere\"\ndim = 2\n"
                                     "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\npop = 10\n";
    const std::string other = (dir / "r.sqlite").string();
    REQUIRE(run_pride("bench '" + (dir / "r.toml").string() + "' --out '" + other + "'").status == 0);
    expect_input_error("export '" + other + "' --coco '" + (dir / "r").string() + "'",
                       {"r.sqlite", "no run on the bbob, bbob-mixint or bbob-constrained suites"});

    // Runs stored before pride kept a trace cannot be written as COCO's data.
    exec_sql(store, "UPDATE runs SET trace_targets = '[]' WHERE seed = 2");
    expect_input_error("export '" + store + "' --coco '" + (dir / "old").string() + "'",
                       {"c.sqlite", "seed 2", "no COCO trace", "new store"});
    // A damaged trace is a damaged store.
    exec_sql(store, "UPDATE runs SET trace_targets = '[5, 1.0, 3, 0.5]' WHERE seed = 1");
    expect_input_error("export '" + store + "' --coco '" + (dir / "old").string() + "'",
                       {"damaged store", "trace_targets", "increasing evaluations"});
    exec_sql(store, "UPDATE runs SET trace_targets = '[1, 1.0, 3]' WHERE seed = 1");
    expect_input_error("export '" + store + "' --coco '" + (dir / "old").string() + "'",
                       {"damaged store", "trace_targets", "pairs"});
}

TEST_CASE("export --coco: cocopp reads the files and computes pride's ERTs exactly", "[coco][export][cocopp]") {
    const char* source = std::getenv("PRIDE_COCOPP_SRC");
    if (!source || !fs::is_directory(fs::path(source))) {
        WARN(
            "skipped: set PRIDE_COCOPP_SRC to the src/cocopp folder of a numbbo/coco-postprocess checkout to "
            "check the COCO export with cocopp (docs/analysis.md)");
        return;
    }
    const pride::test::TempDir tmp("pride-cocopp");
    const fs::path& dir = tmp.path();
    std::ofstream(dir / "c.toml") << kCampaign;
    const std::string store = (dir / "c.sqlite").string();
    REQUIRE(run_pride("bench '" + (dir / "c.toml").string() + "' --jobs 2 --out '" + store + "'").status == 0);
    REQUIRE(run_pride("export '" + store + "' --coco '" + (dir / "coco").string() + "'").status == 0);
    const auto ert = run_pride("report '" + store + "' --format ert-csv");
    REQUIRE(ert.status == 0);
    std::ofstream(dir / "ert.csv") << ert.out;
    const std::string command = "/usr/bin/python3 '" + std::string(PRIDE_SOURCE_DIR) + "/scripts/cocopp_check.py' '" +
                                source + "' '" + (dir / "coco").string() + "' '" + (dir / "ert.csv").string() +
                                "' > '" + (dir / "out.txt").string() + "' 2>&1";
    const int status = std::system(command.c_str());
    const std::string out = slurp(dir / "out.txt");
    INFO(out);
    CHECK(status == 0);
    // 2 algorithms x 2 functions x 2 dimensions, 51 precisions each.
    CHECK(out.find("cocopp read 8 data sets; 408 ERTs equal to pride's") != std::string::npos);
}

namespace {

constexpr const char* kConstrainedCampaign =
    "name = \"coco-constrained\"\nseeds = 2\n[budget]\nevaluations_per_dim = 100\n"
    "[[suite]]\nname = \"bbob-constrained\"\nfunctions = [1, 13]\ninstances = [1, 2]\ndimensions = [2, 3]\n"
    "[[problem]]\nid = \"sphere2\"\ntype = \"sphere\"\ndim = 2\n"
    "[[algorithm]]\nid = \"de\"\ntype = \"de\"\npop = 10\n";

/// A line of tests/data/bbob_constrained/logger.txt: what COCO's logger wrote.
struct CocoLoggerLine {
    int fid = 0;
    std::string file;
    long long evaluations = 0, g_evaluations = 0;
    std::string logged;
};

std::vector<CocoLoggerLine> coco_logger_lines() {
    std::ifstream in(std::string(PRIDE_SOURCE_DIR) + "/tests/data/bbob_constrained/logger.txt");
    REQUIRE(in);
    std::vector<CocoLoggerLine> out;
    std::string text;
    while (std::getline(in, text)) {
        if (text.empty() || text[0] == '#') continue;
        std::istringstream fields(text);
        CocoLoggerLine l;
        fields >> l.fid >> l.file >> l.evaluations >> l.g_evaluations >> l.logged;
        REQUIRE(fields);
        out.push_back(l);
    }
    return out;
}

}  // namespace

TEST_CASE("coco trace: on bbob-constrained, COCO's logger's lines on the same points", "[coco][export][constraints]") {
    // The points and what COCO's bbob logger wrote for them: tests/data/bbob_constrained/README.md.
    const auto lines = coco_logger_lines();
    REQUIRE(lines.size() == 190);
    for (const int fid : {1, 13, 43}) {
        INFO("bbob-constrained-f" << fid);
        pride::continuous::bbob_constrained::Problem problem(fid, 2, 1);
        const std::vector<double> x_star(problem.optimum_point().begin(), problem.optimum_point().end());
        pride::Termination termination;
        termination.max_evaluations = 200;
        termination.optimum = problem.optimum_value();
        pride::RunState state(termination, 2);
        Eigen::MatrixXd point(2, 1);
        double value = 0.0, violation = 0.0, scale = 5.0;
        for (int k = 0; k < 200; ++k) {
            for (int i = 0; i < 2; ++i) {
                double u =
                    static_cast<double>(k + 1) * 0.6180339887498949 + static_cast<double>(i) * 0.41421356237309515;
                u -= static_cast<double>(static_cast<long>(u));
                point(i, 0) = std::clamp(x_star[static_cast<std::size_t>(i)] + scale * (2.0 * u - 1.0), -5.0, 5.0);
            }
            state.evaluate_columns(problem, point, std::span<double>(&value, 1), std::span<double>(&violation, 1));
            scale *= 0.9;
        }
        const auto result = state.finish();
        // The trace: COCO's logged value max(f, f_opt) + sum g_i+ (infeasible points too) at its
        // target triggers (.dat) and at its evaluation triggers on f + g evaluations (.tdat), each
        // closed at the last evaluation; every line as COCO printed it.
        for (const std::string file : {"dat", "tdat"}) {
            const auto& trace = file == "dat" ? result.trace_targets : result.trace_evaluations;
            std::vector<std::string> ours, theirs;
            for (const auto& t : trace)
                ours.push_back(
                    fmt::format("{} {} {:+10.9e}", t.evaluations, t.evaluations, t.best - problem.optimum_value()));
            for (const auto& l : lines)
                if (l.fid == fid && l.file == file)
                    theirs.push_back(fmt::format("{} {} {}", l.evaluations, l.g_evaluations, l.logged));
            CHECK(ours == theirs);
        }
    }
}

TEST_CASE("export --coco: bbob-constrained runs as COCO's logger writes them", "[coco][export][constraints]") {
    const pride::test::TempDir tmp("pride-coco-constrained");
    const fs::path& dir = tmp.path();
    std::ofstream(dir / "c.toml") << kConstrainedCampaign;
    const std::string store = (dir / "c.sqlite").string();
    REQUIRE(run_pride("bench '" + (dir / "c.toml").string() + "' --jobs 2 --out '" + store + "'").status == 0);
    // A constructed run: bbob-constrained-f1, instance 1, D = 2 (f(x*) = 1030.3193472), seed 2.
    exec_sql(store,
             "UPDATE runs SET evaluations = 200, trace_targets = '[1, 1330.3193472, 2, 1055.8193472, 37, 1030.8193472, "
             "200, 1030.8193472]', trace_evaluations = '[1, 1330.3193472, 2, 1055.8193472, 200, 1030.8193472]' "
             "WHERE problem = 'bbob-constrained-f1-i1-d2' AND seed = 2");
    const auto r = run_pride("export '" + store + "' --coco '" + (dir / "coco").string() + "'");
    INFO(r.out << r.err);
    REQUIRE(r.status == 0);
    // 2 functions x 2 dimensions x 2 instances x 2 seeds; the sphere's runs are not COCO's.
    CHECK(r.out == "16 runs of 1 algorithm written as COCO data (10 files) under " + (dir / "coco").string() +
                       "\n2 runs on problems outside the bbob-constrained suite not written (not COCO's data)\n");
    const fs::path a = dir / "coco" / "de";
    const std::string header =
        "% f evaluations | g evaluations | best noise-free fitness - Fopt (1.030319347200e+03) + sum g_i+ | measured "
        "fitness | best measured fitness or single-digit g-values | x1 | x2...\n";
    const std::string constructed = header +
                                    "1 1 +3.000000000e+02 +1.330319347e+03 +1.330319347e+03\n"
                                    "2 2 +2.550000000e+01 +1.055819347e+03 +1.055819347e+03\n"
                                    "37 37 +5.000000000e-01 +1.030819347e+03 +1.030819347e+03\n"
                                    "200 200 +5.000000000e-01 +1.030819347e+03 +1.030819347e+03\n";
    const std::string dat = slurp(a / "data_f1/bbobexp_f1_DIM2.dat");
    const std::string tdat = slurp(a / "data_f1/bbobexp_f1_DIM2.tdat");
    // The second block (instance 1, seed 2), exactly; the .tdat's the same without evaluation 37.
    const auto second = [&](const std::string& text) {
        const std::size_t begin = text.find(header, 1);
        return text.substr(begin, text.find("\n%", begin) + 1 - begin);
    };
    CHECK(second(dat) == constructed);
    CHECK(second(tdat) == header +
                              "1 1 +3.000000000e+02 +1.330319347e+03 +1.330319347e+03\n"
                              "2 2 +2.550000000e+01 +1.055819347e+03 +1.055819347e+03\n"
                              "200 200 +5.000000000e-01 +1.030819347e+03 +1.030819347e+03\n");
    const std::string info = slurp(a / "bbobexp_f1.info");
    CHECK(info.rfind("suite = 'bbob-constrained', funcId = 1, DIM = 2, Precision = 1.000e-08, algId = 'de', "
                     "coco_version = 'pride ",
                     0) == 0);
    CHECK(info.find("\n% pride campaign coco-constrained, algorithm de\ndata_f1/bbobexp_f1_DIM2.dat, 1:200|") !=
          std::string::npos);
    CHECK(info.find(", 1:200|5.0e-01, 2:200|") != std::string::npos);  // the constructed run, second

    // Every other run: its trace as stored, both counters equal, the logged value less f(x*).
    const auto s = pride::storage::read_store(store);
    std::map<std::string, const pride::storage::StoredProblem*> problems;
    for (const auto& p : *s.problems) problems[p.id] = &p;
    for (const int fid : {1, 13})
        for (const int dim : {2, 3}) {
            const std::string stem =
                "data_f" + std::to_string(fid) + "/bbobexp_f" + std::to_string(fid) + "_DIM" + std::to_string(dim);
            const std::string text = slurp(a / (stem + ".dat"));
            std::string want, entries;
            for (const int instance : {1, 2})
                for (const int seed : {1, 2}) {
                    const std::string id = "bbob-constrained-f" + std::to_string(fid) + "-i" +
                                           std::to_string(instance) + "-d" + std::to_string(dim);
                    const pride::storage::StoredRun* run = nullptr;
                    for (const auto& x : s.runs)
                        if (x.problem == id && x.algorithm == "de" && x.seed == seed) run = &x;
                    REQUIRE(run);
                    const pride::storage::StoredProblem& p = *problems.at(id);
                    CHECK(p.suite == "bbob-constrained");
                    CHECK(p.fid == fid);
                    CHECK(p.instance == instance);
                    want += fmt::format(
                        "% f evaluations | g evaluations | best noise-free fitness - Fopt ({:13.12e}) "
                        "+ sum g_i+ | measured fitness | best measured fitness or single-digit "
                        "g-values | x1 | x2...\n",
                        *p.f_opt);
                    for (const auto& t : run->trace_targets)
                        want += fmt::format("{} {} {:+10.9e} {:+10.9e} {:+10.9e}\n", t.evaluations, t.evaluations,
                                            t.best - *p.f_opt, t.best, t.best);
                    REQUIRE(!run->trace_targets.empty());
                    CHECK(run->trace_targets.back().evaluations == run->evaluations);
                    CHECK(run->trace_targets.front().evaluations == 1);
                    entries += fmt::format(", {}:{}|{:.1e}", instance, run->evaluations,
                                           run->trace_targets.back().best - *p.f_opt);
                }
            CHECK(text == want);
            CHECK(slurp(a / ("bbobexp_f" + std::to_string(fid) + ".info")).find(stem + ".dat" + entries + "\n") !=
                  std::string::npos);
        }
}

TEST_CASE("export --coco: a store of two COCO suites, or of neither, is one line, exit 2",
          "[coco][export][constraints]") {
    const pride::test::TempDir tmp("pride-coco-suites");
    const fs::path& dir = tmp.path();
    std::ofstream(dir / "m.toml") << "name = \"mixed\"\nseeds = 1\n[budget]\nevaluations_per_dim = 20\n"
                                     "[[suite]]\nname = \"bbob\"\nfunctions = [1]\ninstances = [1]\ndimensions = [2]\n"
                                     "[[suite]]\nname = \"bbob-constrained\"\nfunctions = [2]\ninstances = [1]\n"
                                     "dimensions = [2]\n"
                                     "[[algorithm]]\nid = \"de\"\ntype = \"de\"\npop = 10\n";
    const std::string mixed = (dir / "m.sqlite").string();
    REQUIRE(run_pride("bench '" + (dir / "m.toml").string() + "' --out '" + mixed + "'").status == 0);
    expect_input_error(
        "export '" + mixed + "' --coco '" + (dir / "m").string() + "'",
        {"m.sqlite", "two COCO suites", "'bbob-f1-i1-d2'", "'bbob-constrained-f2-i1-d2'", "store of its own"});
    CHECK(!fs::exists(dir / "m"));  // nothing half-written

    // Another suite only: CEC 2006's problems are not COCO's.
    std::ofstream(dir / "g.toml") << "name = \"g\"\nseeds = 1\n[budget]\nevaluations = 50\n"
                                     "[[problem]]\nid = \"g06\"\ntype = \"cec2006-g06\"\ndim = 2\n"
                                     "[[algorithm]]\nid = \"de\"\ntype = \"de\"\npop = 10\n";
    const std::string other = (dir / "g.sqlite").string();
    REQUIRE(run_pride("bench '" + (dir / "g.toml").string() + "' --out '" + other + "'").status == 0);
    expect_input_error("export '" + other + "' --coco '" + (dir / "g").string() + "'",
                       {"g.sqlite", "no run on the bbob, bbob-mixint or bbob-constrained suites"});
    CHECK(!fs::exists(dir / "g"));

    // A constrained run whose trace does not end at its last evaluation was stored before pride
    // logged COCO's constrained values.
    std::ofstream(dir / "c.toml") << kConstrainedCampaign;
    const std::string store = (dir / "c.sqlite").string();
    REQUIRE(run_pride("bench '" + (dir / "c.toml").string() + "' --out '" + store + "'").status == 0);
    exec_sql(store,
             "UPDATE runs SET trace_targets = '[1, 2000.0, 5, 1500.0]' WHERE problem = "
             "'bbob-constrained-f13-i2-d3' AND seed = 1");
    expect_input_error("export '" + store + "' --coco '" + (dir / "c").string() + "'",
                       {"c.sqlite", "bbob-constrained-f13-i2-d3", "seed 1", "COCO's constrained values", "new store"});
    CHECK(!fs::exists(dir / "c"));
}

TEST_CASE("campaigns: [[suite]] name = \"bbob-constrained\", and its refusals at the key", "[campaign][constraints]") {
    const pride::test::TempDir tmp("pride-bbobc-suite");
    const fs::path& dir = tmp.path();
    const auto campaign = [](const std::string& suite) {
        return "name = \"s\"\nseeds = 1\n[budget]\nevaluations_per_dim = 10\n[[suite]]\nname = \"bbob-constrained\"\n" +
               suite + "[[algorithm]]\nid = \"de\"\ntype = \"de\"\npop = 10\n";
    };
    const auto refused = [&](const std::string& suite, const std::vector<std::string>& words) {
        std::ofstream(dir / "c.toml") << campaign(suite);
        INFO(suite);
        expect_input_error("bench '" + (dir / "c.toml").string() + "' --out '" + (dir / "c.sqlite").string() + "'",
                           words);
        CHECK(!fs::exists(dir / "c.sqlite"));  // refused before anything ran
    };
    refused("functions = [1, 55]\ndimensions = [2]\n",
            {"c.toml:7:", "function 55 is not in the bbob-constrained suite (1-54)"});
    refused("instances = [0]\ndimensions = [2]\n", {"c.toml:7:", "bbob-constrained: COCO's instances are 1 to"});
    refused("dimensions = [2, 41]\n",
            {"c.toml:7:", "dimension 41: the bbob-constrained functions take a dimension from 2 to 40"});
    refused("functions = [1]\n", {"c.toml:5", "a [[suite]] needs 'dimensions'"});
    refused("functions = []\ndimensions = [2]\n", {"c.toml:5", "must not be empty"});

    // The default functions (all 54) and instances (1-5), one problem per (function, dimension,
    // instance), in that order, with COCO's f(x*) and the suite's function number in the store.
    std::ofstream(dir / "c.toml") << campaign("id = \"bc\"\ndimensions = [2]\n");
    const std::string store = (dir / "c.sqlite").string();
    REQUIRE(run_pride("bench '" + (dir / "c.toml").string() + "' --jobs 2 --out '" + store + "'").status == 0);
    const auto s = pride::storage::read_store(store);
    REQUIRE(s.problems);
    REQUIRE(s.problems->size() == 54u * 5u);
    CHECK(s.runs.size() == 54u * 5u);
    std::size_t k = 0;
    for (int f = 1; f <= 54; ++f)
        for (int i = 1; i <= 5; ++i) {
            const auto& p = (*s.problems)[k++];
            CHECK(p.id == fmt::format("bc-f{}-i{}-d2", f, i));
            CHECK(p.suite == "bbob-constrained");
            CHECK(p.fid == f);
            CHECK(p.instance == i);
            CHECK(p.dim == 2);
            REQUIRE(p.f_opt);
            CHECK(*p.f_opt == pride::continuous::bbob_constrained::Problem(f, 2, i).optimum_value());
        }
    // COCO's f(x*) of f1, instance 1, D = 2, as its logger printed it (tests/data/bbob_constrained/logger.txt).
    CHECK(fmt::format("{:13.12e}", *(*s.problems)[0].f_opt) == "1.030319347200e+03");
}

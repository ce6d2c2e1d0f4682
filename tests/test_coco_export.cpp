// `pride export STORE --coco DIR`: COCO's bbob data files (.info, .dat, .tdat) from each run's COCO
// trace (framework/coco_trace.hpp), and cocopp reading them (scripts/cocopp_check.py) when a
// numbbo/coco-postprocess checkout is named by PRIDE_COCOPP_SRC.
#include <sqlite3.h>
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "experiment/storage/reader.hpp"
#include "framework/coco_trace.hpp"
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
                       {"r.sqlite", "no run on the bbob suite"});

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

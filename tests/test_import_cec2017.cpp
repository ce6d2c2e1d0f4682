// CEC 2017 entrants' result files as published runs (`pride import STORE --cec2017 FOLDER`,
// experiment/report/cec2017_import.hpp): small folders written here, in the layouts the entrants
// used (blanks, tabs, commas, MOS's labelled rows, IDEbestNsize's NAME_D_F), stored as pride's CEC
// 2017 campaigns store runs and reported by `pride report --format cec-csv`; bad input is one line
// naming file and line, exit 2, with nothing written. python/tests/test_import_cec2017.py holds
// the entrants' own files against statistics computed from them.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "experiment/storage/reader.hpp"
#include "tests/cli_runner.hpp"
#include "tests/test_support.hpp"

namespace fs = std::filesystem;
using pride::test::expect_input_error;
using pride::test::run_pride;

namespace {

constexpr const char* kCitation = "'pride (2026), test'";

/// 14 rows (checkpoints) of `runs` errors: run k's error at checkpoint c is (k + 1) * 10^(3 - c / 2),
/// falling; `sep` between the values.
std::string table(int runs, const std::string& sep) {
    std::ostringstream out;
    out << std::setprecision(17);
    for (int c = 0; c < 14; ++c) {
        for (int k = 0; k < runs; ++k) out << (k ? sep : "") << (k + 1) * std::pow(10.0, 3.0 - c / 2.0);
        out << "\n";
    }
    return out.str();
}

/// The lines of a table, one replaced.
std::string with_line(const std::string& text, std::size_t line, const std::string& replacement) {
    std::istringstream in(text);
    std::string out, l;
    for (std::size_t n = 1; std::getline(in, l); ++n) out += (n == line ? replacement : l) + "\n";
    return out;
}

struct Entrant {
    pride::test::TempDir tmp{"pride-cec2017"};
    fs::path folder = tmp.path() / "A01";
    std::string store = tmp.file("s.sqlite");
    Entrant() { fs::create_directories(folder); }
    void write(const std::string& name, const std::string& text) const { std::ofstream(folder / name) << text; }
    std::string import(const std::string& into, const fs::path& from, const std::string& name = "x") const {
        return "import '" + into + "' --cec2017 '" + from.string() + "' --name " + name + " --citation " + kCitation;
    }
};

/// `pride report --format cec-csv`: (problem, algorithm, checkpoint) -> (MaxFES, runs, evaluations,
/// median, mean, std), as written.
std::map<std::tuple<std::string, std::string, std::string>, std::vector<std::string>> cec_csv(
    const std::string& store) {
    const auto r = run_pride("report '" + store + "' --format cec-csv");
    INFO(r.err);
    REQUIRE(r.status == 0);
    std::map<std::tuple<std::string, std::string, std::string>, std::vector<std::string>> out;
    const auto lines = pride::test::lines_of(r.out);
    for (std::size_t i = 1; i < lines.size(); ++i) {
        std::vector<std::string> cells;
        std::istringstream in(lines[i]);
        for (std::string c; std::getline(in, c, ',');) cells.push_back(c);
        REQUIRE(cells.size() == 15);
        out[{cells[0], cells[5], cells[8]}] = {cells[6], cells[7], cells[9], cells[12], cells[13], cells[14]};
    }
    return out;
}

}  // namespace

TEST_CASE("import --cec2017: an entrant's files stored as pride's CEC 2017 runs, its checkpoints reported",
          "[import][cec]") {
    const Entrant e;
    e.write("algo_1_10.txt", table(3, "   "));
    e.write("algo_3_10.txt", table(3, "\t"));
    // MOS's layout: a header line, then labelled rows of comma-separated values.
    std::string mos = "algo_5_10.csv , Run 1, Run 2, Run 3\n";
    const std::vector<int> fes = {1000,  2000,  3000,  5000,  10000, 20000, 30000,
                                  40000, 50000, 60000, 70000, 80000, 90000, 100000};
    const auto rows = pride::test::lines_of(table(3, ","));
    for (std::size_t c = 0; c < 14; ++c)
        mos += "Function error values when FEs = " + std::to_string(fes[c]) + " , " + rows[c] + "\n";
    e.write("algo_5_10.csv", mos);
    e.write("README.txt", "not a result file\n");
    const auto r = run_pride(e.import(e.store, e.folder, "algo-2017"));
    INFO(r.out << r.err);
    REQUIRE(r.status == 0);
    CHECK(r.out == "9 runs of published:algo-2017 imported into " + e.store + " (0 problems of the store, 3 added)\n");

    const auto s = pride::storage::read_store(e.store);
    REQUIRE(s.published.count("published:algo-2017"));
    CHECK(s.published.at("published:algo-2017").format == "cec2017");
    CHECK(s.published.at("published:algo-2017").source == "A01");
    REQUIRE(s.problems);
    std::map<std::string, double> f_opt;
    for (const auto& p : *s.problems) {
        CHECK(p.suite == "cec2017");
        CHECK(p.dim == 10);
        f_opt[p.id] = *p.f_opt;
    }
    CHECK(f_opt == std::map<std::string, double>{{"published:cec2017-f1-d10", 100},
                                                 {"published:cec2017-f3-d10", 300},
                                                 {"published:cec2017-f5-d10", 500}});
    REQUIRE(s.runs.size() == 9);
    for (const auto& run : s.runs) {
        INFO(run.problem << " seed " << run.seed);
        CHECK(run.evaluations == 100000);
        CHECK(run.max_evaluations == 100000);
        CHECK(run.target_hits.empty());  // no runtimes: out of the ERT
        REQUIRE(run.checkpoints.size() == 14);
        CHECK(run.checkpoints.front().evaluations == 1000);
        CHECK(run.checkpoints[3].evaluations == 5000);
        CHECK(run.checkpoints.back().best == Approx(f_opt.at(run.problem) + run.seed * std::pow(10.0, -3.5)));
        CHECK(*run.best == run.checkpoints.back().best);
    }
    // The CEC table: errors of runs 1, 2, 3 x e at each checkpoint: mean = median = 2e, std = e.
    const auto cec = cec_csv(e.store);
    CHECK(cec.size() == 3 * 14);
    for (const auto& [key, cells] : cec) {
        INFO(std::get<0>(key) << " at " << std::get<2>(key));
        CHECK(cells[0] == "100000");  // MaxFES
        CHECK(cells[1] == "3");
        const double median = std::stod(cells[3]);
        CHECK(std::stod(cells[4]) == Approx(median).epsilon(1e-9));
        CHECK(std::stod(cells[5]) == Approx(median / 2).epsilon(1e-9));
    }
    CHECK(std::stod(cec.at({"published:cec2017-f3-d10", "published:algo-2017", "0.01"})[3]) ==
          Approx(2000).epsilon(1e-12));
    CHECK(cec.at({"published:cec2017-f5-d10", "published:algo-2017", "0.05"})[2] == "5000");
}

TEST_CASE("import --cec2017: NAME_D_F files, as IDEbestNsize's, read by what their numbers cover", "[import][cec]") {
    const Entrant e;
    e.write("ide_10_1.txt", table(2, " "));
    e.write("ide_30_12.txt", table(2, " "));  // function 12, not dimension 12
    const auto r = run_pride(e.import(e.store, e.folder));
    INFO(r.err);
    REQUIRE(r.status == 0);
    const auto s = pride::storage::read_store(e.store);
    std::vector<std::string> ids;
    for (const auto& p : *s.problems) ids.push_back(p.id);
    std::sort(ids.begin(), ids.end());
    CHECK(ids == std::vector<std::string>{"published:cec2017-f1-d10", "published:cec2017-f12-d30"});
}

TEST_CASE("import --cec2017: bad input is one line naming file and line, exit 2, nothing written", "[import][cec]") {
    const Entrant e;
    const std::string good = table(3, " ");
    const fs::path file = e.folder / "algo_1_10.txt";
    const auto refused = [&](const std::string& text, const std::vector<std::string>& words,
                             const std::string& name = "algo_1_10.txt") {
        fs::remove_all(e.folder);
        fs::create_directories(e.folder);
        e.write(name, text);
        expect_input_error(e.import(e.store, e.folder), words);
        CHECK(!fs::exists(e.store));  // no store left behind
    };
    expect_input_error(e.import(e.store, e.tmp.path() / "none"), {"none: no such folder"});
    e.write("algo_1_10.txt", good);
    expect_input_error(e.import(e.store, file), {"algo_1_10.txt: not a folder"});
    expect_input_error("import '" + e.store + "' --cec2017 '" + e.folder.string() + "' --name x", {"--citation"});
    expect_input_error("import '" + e.store + "' --name x --citation c", {"--coco FOLDER", "--cec2017 FOLDER"});
    expect_input_error("import '" + e.store + "' --cec2017 '" + e.folder.string() + "' --coco '" + e.folder.string() +
                           "' --name x --citation c",
                       {"--cec2017", "excludes", "--coco"});
    CHECK(!fs::exists(e.store));

    refused(with_line(good, 2, "1.0 nan 2.0"), {file.string() + ":2",
                                                "run 2: expected an error f - f* (a finite number "
                                                ">= 0), got 'nan'"});
    refused(with_line(good, 5, "1.0 -2.0 3.0"), {file.string() + ":5", "run 2", "got '-2.0'"});
    refused(with_line(good, 3, "1.0 2.0"), {file.string() + ":3", "holds 2 runs' errors, the first row 3"});
    refused(with_line(good, 4, "1e9 1 1"),
            {file.string() + ":4", "run 1: the error rises from 100 to ", "best error so far"});
    refused(good + "1 1 1\n", {file.string() + ":15", "expected 14 rows, one per CEC 2017 checkpoint", "got more"});
    refused(with_line(good, 14, ""), {file.string() + ":13", "expected 14 rows", "got 13"});
    refused("", {file.string() + ": expected 14 rows", "got 0"});
    refused(with_line(good, 1, "x 1 2"), {file.string() + ":1",
                                          "expected an error f - f* (a number) or a label "
                                          "'FEs = N' in column 1, got 'x'"});
    // MOS's labelled rows: the label must give the checkpoint's evaluations.
    refused("n.csv , Run 1\nFunction error values when FEs = 1000 , 5\nFunction error values when FEs = 2500 , 4\n",
            {file.string() + ":3", "labelled FEs = 2500, the CEC 2017 checkpoint 0.02 x MaxFES of 10-D", "2000"});
    refused("n.csv , Run 1\nFunction error values when FEs = 1000 , 5\n4\n",
            {file.string() + ":3", "expected a label 'FEs = N' in column 1"});
    refused(good, {"algo_31_10.txt", "names function 31 (algo_31_10: NAME_F_D), CEC 2017's are 1-30"},
            "algo_31_10.txt");
    refused(good, {"algo_11_20.txt", "names F11 in dimension 20", "defines in 10, 30, 50, 100 only"}, "algo_11_20.txt");
    refused(good, {"holds no CEC 2017 result file (NAME_F_D.txt"}, "results_stat_10.txt");

    // Files of two entrants, one function twice, an entrant whose results are in subfolders.
    fs::remove_all(e.folder);
    fs::create_directories(e.folder / "res_a");
    fs::create_directories(e.folder / "res_b");
    expect_input_error(e.import(e.store, e.folder),
                       {"holds no CEC 2017 result file", "import its folders one by one: res_a, res_b"});
    e.write("algo_1_10.txt", good);
    e.write("other_3_10.txt", good);
    expect_input_error(e.import(e.store, e.folder), {"other_3_10.txt: is a file of 'other'",
                                                     "algo_1_10.txt one of "
                                                     "'algo'"});
    fs::remove(e.folder / "other_3_10.txt");
    e.write("algo_1_10.dat", good);
    expect_input_error(e.import(e.store, e.folder), {"algo_1_10.txt: holds F1 in 10-D, as ", "algo_1_10.dat does"});
    CHECK(!fs::exists(e.store));

    // Into a store that holds the name already: nothing changes.
    fs::remove(e.folder / "algo_1_10.dat");
    REQUIRE(run_pride(e.import(e.store, e.folder)).status == 0);
    const std::string bytes = pride::test::slurp(e.store);
    expect_input_error(e.import(e.store, e.folder), {e.store + ": holds the algorithm 'published:x' already, imported "
                                                               "from A01"});
    CHECK(pride::test::slurp(e.store) == bytes);
}

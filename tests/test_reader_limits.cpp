// Readers of outside data under streams and sizes no real file has: every reader is
// capped, so an endless standard input (`yes`) is one line and exit 2 after a bounded read,
// never unbounded memory; a device or FIFO is refused at once, never waited on; a one-row CSV table of 100,000 columns
// is analysed in linear time; a CSV table that is not UTF-8 is refused, so `pride roughset --json` never prints invalid
// UTF-8.
#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <sys/wait.h>

#include <filesystem>

#include <cstdlib>
#include <random>
#include <string>

#include "framework/read_file.hpp"
#include "roughset/roughset.hpp"
#include "tests/cli_runner.hpp"
#include "tests/json_reader.hpp"
#include "tests/test_support.hpp"

namespace {

using pride::test::check_input_error;
using pride::test::CliOutput;
using pride::test::expect_input_error;
using pride::test::run_pride;
using pride::test::TempDir;

/// `pride ARGS` with stdin from the shell pipeline `feed` (e.g. "yes 1"), as a user would run it,
/// with the environment's assignments `env` (NAME='VALUE' ...) when given.
CliOutput run_fed(const std::string& feed, const std::string& args, const std::string& env = "") {
    const TempDir dir("pride-fed");
    const std::string cmd = feed + " | " + (env.empty() ? "" : "env " + env + " ") + "'" + PRIDE_EXE + "' " + args +
                            " >" + dir.file("out") + " 2>" + dir.file("err");
    const int raw = std::system(cmd.c_str());
    CliOutput r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.out = pride::test::slurp(dir.file("out"));
    r.err = pride::test::slurp(dir.file("err"));
    return r;
}

bool valid_utf8(const std::string& s) {
    for (std::size_t i = 0; i < s.size();) {
        const auto c = static_cast<unsigned char>(s[i]);
        const std::size_t len = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
        if (len == 0 || i + len > s.size()) return false;
        for (std::size_t k = 1; k < len; ++k)
            if ((static_cast<unsigned char>(s[i + k]) & 0xC0) != 0x80) return false;
        i += len;
    }
    return true;
}

}  // namespace

TEST_CASE("readers: devices and FIFOs are refused at once, endless standard input after a bounded read, exit 2",
          "[readers][cli]") {
    // Before: 10.5 GB (roughset) and 7.7 GB (bench) in 60 s, eval never returned; later refused
    // after reading the cap; now refused from what the file is.
    for (const char* command : {"roughset /dev/zero", "bench /dev/zero", "scen /dev/zero",
                                "path --map /dev/zero --start 0,0 --goal 1,1 --algo astar"})
        expect_input_error(command, {"/dev/zero: not a regular file (a character device)", "/dev/stdin"});
    // A FIFO without a writer blocked every reader until killed: now one line at once, wherever
    // it stands (a map named on the command line, a map named by a scenario, a CEC data file).
    const TempDir dir;
    const std::string fifo = dir.file("fifo.map");
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    expect_input_error("path --map " + fifo + " --start 0,0 --goal 1,1 --algo astar",
                       {fifo + ": not a regular file (a FIFO)"});
    dir.write("fifo.scen", "version 1\n0 fifo.map 2 2 0 0 1 1 1.41421356\n");
    expect_input_error("scen " + dir.file("fifo.scen"), {"fifo.map: not a regular file (a FIFO)"});
    std::filesystem::create_directories(dir.file("cec"));
    std::string identity;
    for (int i = 0; i < 10; ++i)
        for (int j = 0; j < 10; ++j) identity += (i == j ? "1" : "0") + std::string(j == 9 ? "\n" : " ");
    dir.write("cec/M_1_D10.txt", identity);
    const std::string shift = dir.file("cec/shift_data_1.txt");
    REQUIRE(::mkfifo(shift.c_str(), 0600) == 0);
    check_input_error(run_fed("true", "run --problem cec2017-f1 --dim 10 --algo de --evals 100",
                              "PRIDE_CEC2017_DATA='" + dir.file("cec") + "'"),
                      {"shift_data_1.txt: not a regular file (a FIFO)"});
    // A map that never ends: refused at 64 MiB read (it was 1 GiB, after 2 GB of memory).
    check_input_error(run_fed("yes .", "path --map /dev/stdin --start 0,0 --goal 1,1 --algo astar"),
                      {"too large", "64 MiB"});
    // eval --x -: a NUL byte at once, an endless text stream at 64 MiB.
    check_input_error(run_fed("cat /dev/zero", "eval --problem sphere --x -"), {"stdin line 1", "NUL byte"});
    expect_input_error("eval --problem sphere --x -", {"stdin line 2", "NUL byte"}, std::string("1,2\n3,\0", 7));
    check_input_error(run_fed("yes 1,2", "eval --problem sphere --x -"), {"stdin", "64 MiB"});
}

TEST_CASE("readers: CEC data that would make every value infinite or drop a dimension is refused", "[readers][cec]") {
    // Before: shifts of 1e308 ran with every value inf and best_f null, exit 0; an all-zero matrix ran.
    const TempDir dir;
    std::filesystem::create_directories(dir.file("cec"));
    const auto matrix = [](double diagonal, double corner) {
        std::string m;
        for (int i = 0; i < 10; ++i)
            for (int j = 0; j < 10; ++j)
                m += std::to_string(i == j ? diagonal : (i == 0 && j == 9 ? corner : 0.0)) + (j == 9 ? "\n" : " ");
        return m;
    };
    const auto run = [&] {
        return run_fed("true", "run --problem cec2017-f1 --dim 10 --algo de --evals 100",
                       "PRIDE_CEC2017_DATA='" + dir.file("cec") + "'");
    };
    dir.write("cec/shift_data_1.txt", "1 2 3 4 5 6 7 8 9 10\n");
    dir.write("cec/M_1_D10.txt", matrix(0.0, 0.0));
    check_input_error(run(), {"M_1_D10.txt: matrix 1 of 1 is singular (rank 0 of 10): a damaged file"});
    dir.write("cec/M_1_D10.txt", matrix(1.0, 1e6));
    check_input_error(run(), {"M_1_D10.txt: matrix 1 of 1 has an entry outside [-1000, 1000]"});
    dir.write("cec/M_1_D10.txt", matrix(1.0, 0.5));
    dir.write("cec/shift_data_1.txt", "1 2 3 4 5 6 7 8 9 1e308\n");
    check_input_error(run(), {"shift_data_1.txt: shift value 10 lies outside the search box [-100, 100]"});
    dir.write("cec/shift_data_1.txt", "1 2 3 4 5 6 7 8 9 SECRET\n");
    const auto r = run();
    check_input_error(r, {"shift_data_1.txt:1: expected a finite number"});
    CHECK(r.err.find("SECRET") == std::string::npos);
    dir.write("cec/shift_data_1.txt", "1 2 3 4 5 6 7 8 9 10\n");
    CHECK(run().status == 0);
}

TEST_CASE("readers: a regular file over the cap is refused from its size, a directory by name", "[readers]") {
    const TempDir dir;
    const std::string big = dir.file("big.csv");
    {
        std::ofstream f(big, std::ios::binary);
        f.seekp((std::streamoff{16} << 20) + 1);  // a sparse 16 MiB + 1 byte: nothing read
        f.put('\n');
    }
    CHECK_THAT(pride::test::input_error_message([&] { pride::roughset::read_csv(big); }),
               Catch::StartsWith(big + ": too large: more than 16 MiB"));
    CHECK_THAT(pride::test::input_error_message([&] { pride::read_capped_file(dir.path().string(), 100, "x"); }),
               Catch::EndsWith("is a folder, not a file"));
    expect_input_error("bench " + dir.path().string(), {dir.path().string(), "is a folder, not a campaign file"});
    // Exactly at the cap is accepted.
    const std::string at = dir.write("at", std::string(100, 'x'));
    CHECK(pride::read_capped_file(at, 100, "x").size() == 100);
    CHECK_THAT(pride::test::input_error_message([&] { pride::read_capped_file(at, 99, "x"); }),
               Catch::Contains("too large"));
}

TEST_CASE("readers: a one-row CSV table of 100,000 columns is analysed (it was quadratic)", "[readers][roughset]") {
    // Before: over 60 s (pairwise name checks, and the core refined |C| times over |C| - 1
    // attributes); now the core search refines O(|C| log |C|) times.
    const TempDir dir;
    std::string header, row;
    for (int i = 0; i < 100000; ++i) {
        header += (i ? ",c" : "c") + std::to_string(i);
        row += i ? ",v" : "v";
    }
    const std::string csv = dir.write("wide.csv", header + "\n" + row + "\n");
    const auto r = run_pride("roughset --json '" + csv + "'");
    REQUIRE(r.status == 0);
    const auto j = pride::test::parse_json(r.out);
    CHECK(j.at("rows").number == 1);
    CHECK(j.at("conditions").items.size() == 99999);
    CHECK(j.at("core").items.empty());  // one object: every attribute can go
    CHECK(j.at("consistent").boolean);
    // A row over 1,000,000 columns is refused while it is read.
    std::string wider = "a";
    for (int i = 0; i < 1000000; ++i) wider += ",a";
    const std::string too_wide = dir.write("too-wide.csv", wider + "\n");
    expect_input_error("roughset '" + too_wide + "'", {"too-wide.csv:1:", "more than 1000000 columns"});
}

TEST_CASE("readers: the core by halves equals its definition on random tables", "[readers][roughset]") {
    // core(C) = {a in C : POS_{C - a}(D) != POS_C(D)}, checked against positive_region directly.
    std::mt19937 rng(14);
    for (int trial = 0; trial < 200; ++trial) {
        const std::size_t cols = 2 + rng() % 9, rows = 1 + rng() % 12, values = 1 + rng() % 3;
        std::vector<std::string> names;
        for (std::size_t c = 0; c < cols; ++c) names.push_back("a" + std::to_string(c));
        pride::roughset::DecisionTable t(names);
        std::vector<int> codes(cols);
        for (std::size_t r = 0; r < rows; ++r) {
            for (auto& v : codes) v = static_cast<int>(rng() % values);
            t.add_row(codes);
        }
        const auto C = t.conditions(), D = t.decision();
        const auto pos = pride::roughset::positive_region(t, C, D);
        pride::roughset::Attributes expected;
        for (std::size_t k = 0; k < C.size(); ++k) {
            auto rest = C;
            rest.erase(rest.begin() + static_cast<std::ptrdiff_t>(k));
            if (pride::roughset::positive_region(t, rest, D) != pos) expected.push_back(C[k]);
        }
        INFO("trial " << trial);
        CHECK(pride::roughset::core(t, C, D) == expected);
    }
}

TEST_CASE("readers: a CSV table that is not UTF-8 is refused at its line and column", "[readers][roughset]") {
    const TempDir dir;
    const std::string latin1 = dir.write("latin1.csv", "name,d\ncaf\xE9,yes\nx,no\n");
    expect_input_error("roughset --json '" + latin1 + "'", {"latin1.csv:2:4:", "not UTF-8"});
    const std::string nul = dir.write("nul.csv", std::string("a,d\r\n1,\0\r\n", 10));
    expect_input_error("roughset '" + nul + "'", {"nul.csv:2:3:", "NUL byte"});
    const std::string surrogate = dir.write("surrogate.csv", "a,d\n\xED\xA0\x80,1\n");
    expect_input_error("roughset '" + surrogate + "'", {"surrogate.csv:2:1:", "not UTF-8"});
    const std::string truncated = dir.write("truncated.csv", "a,d\n1,\xC3");
    expect_input_error("roughset '" + truncated + "'", {"truncated.csv:2:3:", "not UTF-8"});
    // Valid UTF-8 (a BOM, accents, 4-byte characters) is read and printed as it is.
    const std::string utf8 =
        dir.write("utf8.csv", "\xEF\xBB\xBFnom,d\xC3\xA9\x63ision\ncaf\xC3\xA9,\xF0\x9F\x99\x82\nth\xC3\xA9,no\n");
    const auto r = run_pride("roughset --json '" + utf8 + "'");
    REQUIRE(r.status == 0);
    CHECK(valid_utf8(r.out));
    CHECK(r.out.find("d\xC3\xA9\x63ision") != std::string::npos);
}

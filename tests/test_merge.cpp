// pride merge (experiment/storage/merge.hpp): stores of one campaign run in parts (seeds split, an algorithm
// added elsewhere) join into the store one run of the whole would give (bar wall times); a run in
// two stores is kept once when equal and refused, naming it, when not; incompatible stores are
// refused naming what differs; the inputs stay as they were and a refused merge writes nothing.
#include <sqlite3.h>
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "tests/cli_runner.hpp"
#include "tests/test_support.hpp"

namespace fs = std::filesystem;

namespace {

const std::string kProblems =
    "[[problem]]\nid = \"s\"\ntype = \"sphere\"\ndim = 3\n"
    "[[problem]]\nid = \"f3\"\ntype = \"bbob-f3\"\ndim = 2\ninstance = 1\n";
const std::string kPso = "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\npop = 10\n";
const std::string kGa = "[[algorithm]]\nid = \"ga\"\ntype = \"ga\"\npop = 10\n";

std::string campaign(int seeds, const std::string& algorithms, int evaluations = 300) {
    return "name = \"m\"\nseeds = " + std::to_string(seeds) +
           "\n[budget]\nevaluations = " + std::to_string(evaluations) + "\n" + kProblems + algorithms;
}

/// Every run of a store but its wall time, in key order, as text.
std::vector<std::string> runs(const std::string& store) {
    sqlite3* db = nullptr;
    REQUIRE(sqlite3_open_v2(store.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK);
    sqlite3_stmt* s = nullptr;
    REQUIRE(sqlite3_prepare_v2(db,
                               "SELECT problem, algorithm, seed, feasible, quote(best), evaluations, iterations, "
                               "solution, history, history_evaluations, target_hits, encoding FROM runs ORDER BY "
                               "problem, algorithm, seed",
                               -1, &s, nullptr) == SQLITE_OK);
    std::vector<std::string> out;
    while (sqlite3_step(s) == SQLITE_ROW) {
        std::string row;
        for (int i = 0; i < sqlite3_column_count(s); ++i)
            row += std::string(reinterpret_cast<const char*>(sqlite3_column_text(s, i))) + "|";
        out.push_back(row);
    }
    sqlite3_finalize(s);
    sqlite3_close(db);
    return out;
}

/// The hidden files a merge writes before its output is whole, left in `dir`.
std::vector<std::string> temporaries(const pride::test::TempDir& dir) {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(dir.file("")))
        if (e.path().filename().string().find(".pride-merge-") != std::string::npos)
            out.push_back(e.path().filename().string());
    return out;
}

std::string bench(const pride::test::TempDir& dir, const std::string& name, const std::string& text,
                  const std::string& store) {
    const auto r = pride::test::run_pride("bench '" + dir.write(name, text) + "' --out '" + dir.file(store) + "'");
    INFO(r.err);
    REQUIRE(r.status == 0);
    return dir.file(store);
}

}  // namespace

TEST_CASE("merge: stores of one campaign run in parts equal the whole campaign's store", "[merge]") {
    const pride::test::TempDir dir("pride-merge");
    // Machine A ran seeds 1-2 with pso; machine B seeds 1-3 with pso and ga (seeds 1-2 of pso in both).
    const std::string a = bench(dir, "a.toml", campaign(2, kPso), "a.sqlite");
    const std::string b = bench(dir, "b.toml", campaign(3, kPso + kGa), "b.sqlite");
    const std::string whole = bench(dir, "w.toml", campaign(3, kPso + kGa), "w.sqlite");
    const auto a_runs = runs(a), b_runs = runs(b);
    const auto r = pride::test::run_pride("merge '" + a + "' '" + b + "' --out '" + dir.file("m.sqlite") + "'");
    INFO(r.err);
    REQUIRE(r.status == 0);
    CHECK(r.out == "merged 2 stores into " + dir.file("m.sqlite") +
                       ": 12 runs (4 found in more than one store, equal, kept once)\n");
    CHECK(runs(dir.file("m.sqlite")) == runs(whole));
    CHECK(runs(a) == a_runs);  // inputs untouched
    CHECK(runs(b) == b_runs);
    CHECK(temporaries(dir).empty());
    // The merged store reports as the parts read together do, and grows like any other store.
    const auto merged = pride::test::run_pride("report '" + dir.file("m.sqlite") + "' --format csv");
    const auto parts = pride::test::run_pride("report '" + a + "' '" + b + "' --format csv");
    REQUIRE(merged.status == 0);
    REQUIRE(parts.status == 0);
    CHECK(parts.out == merged.out);
    const auto plots = pride::test::run_pride("report '" + a + "' '" + b + "' --plots '" + dir.file("figs") + "'");
    CHECK(plots.status == 2);
    CHECK_THAT(plots.err, Catch::Contains("--plots: draws one store; join several into one with pride merge first"));
    const auto grown = pride::test::run_pride("bench '" + dir.write("g.toml", campaign(4, kPso + kGa)) + "' --out '" +
                                              dir.file("m.sqlite") + "'");
    INFO(grown.err);
    CHECK(grown.status == 0);
    CHECK(grown.out.find("4 runs stored") != std::string::npos);
}

TEST_CASE("merge: what cannot be merged is refused, naming it, and nothing is written", "[merge]") {
    const pride::test::TempDir dir("pride-merge-refused");
    const std::string a = bench(dir, "a.toml", campaign(2, kPso), "a.sqlite");
    auto refused = [&](const std::string& other, const std::string& words) {
        const std::string out = dir.file("m.sqlite");
        const auto r = pride::test::run_pride("merge '" + a + "' '" + other + "' --out '" + out + "'");
        CHECK(r.status == 2);
        CHECK_THAT(r.err, Catch::Contains(words));
        CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
        CHECK(!fs::exists(out));
        CHECK(temporaries(dir).empty());
    };
    refused(bench(dir, "b.toml", campaign(2, kPso, 301), "b.sqlite"),
            "its runs have the budget 'evaluations = 301', those of " + a + " 'evaluations = 300'");
    refused(bench(dir, "c.toml", campaign(2, "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\npop = 11\n"), "c.sqlite"),
            "algorithm 'pso' is defined as pso pop=11 there and as pso pop=10 in " + a);
    // The same run with another value: edited here, as a store from a changed build would hold it.
    const std::string d = bench(dir, "d.toml", campaign(2, kPso), "d.sqlite");
    {
        sqlite3* db = nullptr;
        REQUIRE(sqlite3_open(d.c_str(), &db) == SQLITE_OK);
        REQUIRE(sqlite3_exec(db, "UPDATE runs SET best = best + 1e-9 WHERE problem = 's' AND seed = 2", nullptr,
                             nullptr, nullptr) == SQLITE_OK);
        sqlite3_close(db);
    }
    refused(d, "run (problem 's', algorithm 'pso', seed 2) differs from the same run in " + a);
    const auto report = pride::test::run_pride("report '" + a + "' '" + d + "'");
    CHECK(report.status == 2);
    CHECK_THAT(report.err, Catch::Contains("run (problem 's', algorithm 'pso', seed 2) differs between the stores"));
    refused(dir.write("notes.sqlite", "not a database"), "notes.sqlite");
    refused(dir.file("missing.sqlite"), "missing.sqlite: no such store");
    const auto exists = pride::test::run_pride("merge '" + a + "' '" + a + "' --out '" + a + "'");
    CHECK(exists.status == 2);
    CHECK_THAT(exists.err, Catch::Contains("exists already"));
    // An output whose folder cannot be written (here: a file in the folder's place) is the user's
    // error, one line and exit 2 (it was "internal error: filesystem error ...", exit 1).
    const std::string file = dir.write("plain", "x");
    const auto unwritable =
        pride::test::run_pride("merge '" + a + "' '" + bench(dir, "e.toml", campaign(2, kPso), "e.sqlite") +
                               "' --out '" + file + "/m.sqlite'");
    CHECK(unwritable.status == 2);
    CHECK_THAT(unwritable.err, Catch::Contains(file + "/m.sqlite: cannot write the merged store: Not a directory"));
}

// Campaigns and stores: no silent mixing (docs/reliability.md). A store remembers what
// each problem was (SHA-256 digests of its map and settings, store schema 3) and refuses a resume
// or a merge on another problem under the same id; pride bench and pride merge check a store as
// pride report does before trusting it; a classic suite without instance 0 is refused; a campaign
// file's expansion is bounded before it is made; names with control characters are refused.
#include <sqlite3.h>
#include <catch2/catch.hpp>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "experiment/campaign/prepare.hpp"
#include "experiment/campaign/toml.hpp"
#include "experiment/storage/digest.hpp"
#include "experiment/storage/schema.hpp"
#include "tests/sqlite_support.hpp"
#include "tests/test_support.hpp"

using pride::test::exec_sql;

namespace {

using pride::test::check_input_error;
using pride::test::run_pride;
using pride::test::slurp;
using pride::test::TempDir;

std::string bundled_map_text() {
    return slurp(std::filesystem::path(PRIDE_SOURCE_DIR) / "examples" / "maps" / "wan2022-10x10.map");
}

/// A grid campaign on m.map (beside the file) and a continuous problem: 2 x 1 x `seeds` runs.
std::string grid_campaign(int seeds = 2) {
    return "name = \"ident\"\nseeds = " + std::to_string(seeds) +
           "\n[budget]\niterations = 4\n"
           "[[problem]]\nid = \"g\"\ntype = \"grid\"\nmap = \"m.map\"\nstart = [0, 0]\ngoal = [9, 9]\n"
           "[[problem]]\nid = \"s\"\ntype = \"sphere\"\ndim = 2\n"
           "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\npop = 8\n";
}

/// The bundled 10 x 10 map with one free cell of its last row blocked (start and goal stay free).
std::string edited_map() {
    std::string m = bundled_map_text();
    const auto last_row = m.rfind('\n', m.size() - 2) + 1;
    for (std::size_t i = last_row + 1; i < m.size(); ++i)
        if (m[i] == '.') {
            m[i] = '@';
            break;
        }
    return m;
}

pride::test::CliOutput bench(const TempDir& dir, const std::string& config, const std::string& store) {
    return run_pride("bench '" + dir.file(config) + "' --jobs 1 --out '" + store + "'");
}

std::string scalar(const std::string& store, const std::string& sql) {
    sqlite3* db = nullptr;
    REQUIRE(sqlite3_open_v2(store.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK);
    sqlite3_stmt* s = nullptr;
    REQUIRE(sqlite3_prepare_v2(db, sql.c_str(), -1, &s, nullptr) == SQLITE_OK);
    std::string out = "(none)";
    if (sqlite3_step(s) == SQLITE_ROW)
        out = sqlite3_column_type(s, 0) == SQLITE_NULL ? "NULL"
                                                       : reinterpret_cast<const char*>(sqlite3_column_text(s, 0));
    sqlite3_finalize(s);
    sqlite3_close(db);
    return out;
}

/// `pride ARGS` under an address-space limit of `kb` KiB (what available_memory() honours).
pride::test::CliOutput run_pride_limited(long kb, const std::string& args) {
    const TempDir io;
    const std::string cmd = "ulimit -v " + std::to_string(kb) + " && '" + PRIDE_EXE + "' " + args + " >'" +
                            io.file("out") + "' 2>'" + io.file("err") + "'";
    const int raw = std::system(cmd.c_str());
    pride::test::CliOutput r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.out = slurp(io.file("out"));
    r.err = slurp(io.file("err"));
    return r;
}

}  // namespace

TEST_CASE("store identity: SHA-256 as FIPS 180-4's examples give it", "[store-identity]") {
    using pride::storage::Sha256;
    CHECK(Sha256().hex() == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
    CHECK(Sha256().add("abc").hex() == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    CHECK(Sha256().add("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq").hex() ==
          "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
    Sha256 million;  // in uneven pieces, across block boundaries
    for (int done = 0; done < 1'000'000;) {
        const int n = std::min(1'000'000 - done, 1 + done % 97);
        million.add(std::string(static_cast<std::size_t>(n), 'a'));
        done += n;
    }
    CHECK(million.hex() == "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST_CASE("store identity: a map edited between a campaign and its resume is refused, the store untouched",
          "[store-identity][cli][bench][errors]") {
    const TempDir dir;
    dir.write("m.map", bundled_map_text());
    dir.write("c.toml", grid_campaign(2));
    const std::string store = dir.file("c.sqlite");
    REQUIRE(bench(dir, "c.toml", store).status == 0);
    CHECK(scalar(store, "PRAGMA user_version") == std::to_string(pride::storage::schema_version));
    CHECK(scalar(store, "SELECT digest FROM problems WHERE id = 'g'").rfind("map sha256:", 0) == 0);
    const std::string bytes = slurp(store);

    dir.write("m.map", edited_map());
    // The same campaign file (its text unchanged), and a grown one (one more seed): both refused.
    for (const int seeds : {2, 3}) {
        INFO("seeds " << seeds);
        dir.write("c.toml", grid_campaign(seeds));
        check_input_error(bench(dir, "c.toml", store),
                          {store, "problem 'g' has another map than the stored one", "give the problem another id"});
        CHECK(slurp(store) == bytes);
    }
    // The same cells in another file (moved, not edited) are the same map: the grown campaign runs.
    dir.write("c.toml", grid_campaign(3));
    dir.write("m.map", bundled_map_text());
    const auto r = bench(dir, "c.toml", store);
    CHECK(r.status == 0);
    CHECK(r.out.find("2 runs stored") != std::string::npos);
}

TEST_CASE("store identity: a store from schema 2 is migrated on resume, its digests taken from that campaign",
          "[store-identity][cli][bench]") {
    const TempDir dir;
    dir.write("m.map", bundled_map_text());
    dir.write("c.toml", grid_campaign(1));
    const std::string store = dir.file("c.sqlite");
    REQUIRE(bench(dir, "c.toml", store).status == 0);
    // As older versions of pride wrote it: no digest column, schema 2.
    exec_sql(store, "ALTER TABLE problems DROP COLUMN digest; PRAGMA user_version = 2");
    const auto old_report = run_pride("report '" + store + "' --format csv");
    CHECK(old_report.status == 0);  // report reads old stores as they are
    REQUIRE(bench(dir, "c.toml", store).status == 0);
    CHECK(scalar(store, "PRAGMA user_version") == std::to_string(pride::storage::schema_version));
    CHECK(scalar(store, "SELECT digest FROM problems WHERE id = 'g'").rfind("map sha256:", 0) == 0);
    CHECK(run_pride("report '" + store + "' --format csv").out == old_report.out);
    // From then on an edit is seen.
    dir.write("m.map", edited_map());
    check_input_error(bench(dir, "c.toml", store), {store, "problem 'g' has another map"});
}

TEST_CASE("store identity: bench and merge check a store as report does, and refuse a damaged one",
          "[store-identity][cli][bench][merge][damaged][errors]") {
    const TempDir dir;
    dir.write("m.map", bundled_map_text());
    dir.write("c.toml", grid_campaign(3));
    const std::string good = dir.file("good.sqlite");
    REQUIRE(bench(dir, "c.toml", good).status == 0);
    const std::string bytes = slurp(good);

    // Truncated: refused, naming the store and what is wrong, as report says it.
    const std::string cut = dir.write("cut.sqlite", bytes.substr(0, bytes.size() / 2));
    check_input_error(bench(dir, "c.toml", cut), {cut, "damaged store: the file is truncated", "nothing was run"});
    check_input_error(run_pride("report '" + cut + "'"), {cut, "damaged store: the file is truncated"});
    CHECK(slurp(cut) == bytes.substr(0, bytes.size() / 2));

    // A value of a run damaged in place (its history no longer a list of numbers).
    const std::string edited = dir.write("edited.sqlite", bytes);
    exec_sql(edited, "UPDATE runs SET history = '[1, x]' WHERE rowid = 1");
    check_input_error(bench(dir, "c.toml", edited), {edited, "damaged store:", "history"});
    check_input_error(run_pride("merge '" + good + "' '" + edited + "' --out '" + dir.file("m1.sqlite") + "'"),
                      {edited, "damaged store:", "history"});
    CHECK(!std::filesystem::exists(dir.file("m1.sqlite")));

    // Bit flips anywhere in the store's pages: bench says exactly what report says (both accept,
    // or both refuse), and never reports a success on a store report calls damaged.
    std::mt19937_64 rng(25);
    int refused = 0;
    for (int k = 0; k < 48; ++k) {
        std::string flipped = bytes;
        const std::size_t at = 100 + rng() % (flipped.size() - 100);
        flipped[at] = static_cast<char>(flipped[at] ^ (1 << (rng() % 8)));
        const std::string store = dir.write("f.sqlite", flipped);
        const auto rep = run_pride("report '" + store + "' --format csv");
        const auto b = bench(dir, "c.toml", store);
        INFO("byte " << at << ": report " << rep.status << " " << rep.err << "bench " << b.status << " " << b.err);
        if (rep.status != 0) {
            ++refused;
            check_input_error(b, {store, "nothing was run"});
        } else {
            CHECK((b.status == 0 || b.err.find("damaged store") != std::string::npos));
        }
        std::filesystem::remove(store);
        for (const char* suffix : {"-wal", "-shm"}) std::filesystem::remove(store + suffix);
    }
    INFO(refused << " of 48 flips refused");
    SUCCEED();
}

TEST_CASE("store identity: bench refuses a store whose damage only SQLite's quick_check finds",
          "[store-identity][cli][bench][damaged][errors]") {
    const TempDir dir;
    dir.write("m.map", bundled_map_text());
    dir.write("c.toml", grid_campaign(2));
    const std::string store = dir.file("c.sqlite");
    REQUIRE(bench(dir, "c.toml", store).status == 0);
    // A page of the claims' index, which no query of report reads (the claims are not results).
    const int root =
        std::stoi(scalar(store, "SELECT rootpage FROM sqlite_master WHERE name = 'sqlite_autoindex_claims_1'"));
    const auto page_size = static_cast<std::size_t>(std::stoul(scalar(store, "PRAGMA page_size")));
    exec_sql(store, "PRAGMA journal_mode = DELETE");  // every page in the file, none in a -wal
    REQUIRE(!std::filesystem::exists(store + "-wal"));
    std::string bytes = slurp(store);
    const std::size_t page = page_size * static_cast<std::size_t>(root - 1);
    REQUIRE(page + page_size <= bytes.size());
    for (std::size_t i = 0; i < 16; ++i) bytes[page + i] = static_cast<char>(0xa5);
    dir.write("c.sqlite", bytes);
    check_input_error(bench(dir, "c.toml", store), {store, "damaged store", "quick_check", "nothing was run"});
}

TEST_CASE("store identity: merge refuses two stores whose problem of one id differs in content",
          "[store-identity][cli][merge][errors]") {
    const TempDir dir;
    dir.write("m.map", bundled_map_text());
    dir.write("c.toml", grid_campaign(1));
    REQUIRE(bench(dir, "c.toml", dir.file("a.sqlite")).status == 0);
    dir.write("m.map", edited_map());
    REQUIRE(bench(dir, "c.toml", dir.file("b.sqlite")).status == 0);  // a new store: its own map
    const std::string out = dir.file("ab.sqlite");
    check_input_error(
        run_pride("merge '" + dir.file("a.sqlite") + "' '" + dir.file("b.sqlite") + "' --out '" + out + "'"),
        {dir.file("b.sqlite"), "problem 'g' has another map", "not merged"});
    CHECK(!std::filesystem::exists(out));
}

TEST_CASE("store identity: a classic suite without instance 0 is refused at its key",
          "[store-identity][suites][errors]") {
    const TempDir dir;
    const std::string head = "name = \"x\"\nseeds = 1\n[budget]\nevaluations = 10\n";
    const std::string tail = "[[algorithm]]\nid = \"a\"\ntype = \"pso\"\n";
    const std::string bad =
        dir.write("bad.toml", head + "[[suite]]\nname = \"classic\"\ninstances = [1]\ndimensions = [2]\n" + tail);
    check_input_error(run_pride("bench '" + bad + "' --out '" + dir.file("s.sqlite") + "'"),
                      {bad + ":7:13", "'instances' has no instance 0", "yao-f14"});
    CHECK(!std::filesystem::exists(dir.file("s.sqlite")));
    // Without the fixed-dimension functions, or with instance 0 listed, it runs.
    const auto ok = pride::campaign::read_campaign(dir.write(
        "ok.toml",
        head + "[[suite]]\nname = \"classic\"\nfunctions = [1, 2]\ninstances = [1]\ndimensions = [2]\n" + tail));
    CHECK(ok.problems.size() == 2);
    CHECK(ok.problems[0].problem->instance() == 1);
}

TEST_CASE("store identity: instance lists and suites are bounded before they expand",
          "[store-identity][memory][errors]") {
    const TempDir dir;
    const std::string head = "name = \"big\"\nseeds = 1\n[budget]\nevaluations = 100\n";
    const std::string tail = "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\n";
    std::string list;
    for (int k = 1; k <= 200'000; ++k) list += (k > 1 ? ", " : "") + std::to_string(k);
    const std::string big = dir.write(
        "big.toml", head + "[[problem]]\nid = \"s\"\ntype = \"sphere\"\ndim = 2\ninstance = [" + list + "]\n" + tail);
    check_input_error(run_pride("bench '" + big + "' --out '" + dir.file("s.sqlite") + "'"),
                      {big + ":9:12", "'instance' lists 200000 problems", "at most 100000"});
    std::string instances;
    for (int k = 1; k <= 3000; ++k) instances += (k > 1 ? ", " : "") + std::to_string(k);
    const std::string suite = dir.write("suite.toml", head + "[[suite]]\nname = \"bbob\"\ninstances = [" + instances +
                                                          "]\ndimensions = [2, 3, 5, 10, 20, 40]\n" + tail);
    check_input_error(run_pride("bench '" + suite + "' --out '" + dir.file("s.sqlite") + "'"),
                      {suite + ":7:13", "'instances'", "432000 problems", "at most 100000"});
    // Under the cap, the memory of the problems built is checked before any is: 60000 problems
    // of 16 kB each are more than a 700 MB address space.
    list.clear();
    for (int k = 1; k <= 60'000; ++k) list += (k > 1 ? ", " : "") + std::to_string(k);
    const std::string mid = dir.write(
        "mid.toml", head + "[[problem]]\nid = \"s\"\ntype = \"sphere\"\ndim = 2\ninstance = [" + list + "]\n" + tail);
    if (!PRIDE_UNDER_ASAN)
        check_input_error(run_pride_limited(700'000, "bench '" + mid + "' --out '" + dir.file("s.sqlite") + "'"),
                          {mid + ":9:12", "'instance' lists 60000 problems", "of memory once built"});
    CHECK(dir.entries() == std::vector<std::string>{"big.toml", "mid.toml", "suite.toml"});
}

TEST_CASE("store identity: empty names and names with NUL or control characters are refused at their key",
          "[store-identity][cli][bench][errors]") {
    const TempDir dir;
    const std::string base =
        "name = \"n\"\nseeds = 1\n[budget]\nevaluations = 20\n"
        "[[problem]]\nid = \"s\"\ntype = \"sphere\"\ndim = 2\n"
        "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\n";
    const auto replaced = [&](const std::string& from, const std::string& to) {
        std::string t = base;
        t.replace(t.find(from), from.size(), to);
        return t;
    };
    struct Case {
        std::string from, to, words;
    };
    const std::vector<Case> cases{
        {"id = \"s\"", "id = \"\"", ":6:6: 'id' must not be empty"},
        {"id = \"pso\"", "id = \"\"", ":10:6: 'id' must not be empty"},
        {"name = \"n\"", "name = \"\"", ":1:8: 'name' must not be empty"},
        {"id = \"s\"", "id = \"a\\u0000b\"", ":6:6: 'id' must not contain a NUL character (U+0000 at byte 2)"},
        {"name = \"n\"", "name = \"x\\u001b[31my\"", ":1:8: 'name' must not contain control characters (U+001B"},
        {"id = \"pso\"", "id = \"p\\u009bq\"", ":10:6: 'id' must not contain control characters (U+009B"},
        {"id = \"pso\"", "id = \"p\\tq\"", ":10:6: 'id' must not contain control characters (U+0009"},
        // Before: a 5,000-byte id was stored, and every later report --html and export failed.
        {"id = \"s\"", "id = \"" + std::string(5000, 's') + "\"",
         ":6:6: 'id' must be at most 100 bytes long (it has 5000): reports and exports name files after it"},
        {"id = \"pso\"", "id = \"" + std::string(101, 'p') + "\"",
         ":10:6: 'id' must be at most 100 bytes long (it has 101)"},
    };
    for (const auto& c : cases) {
        INFO(c.to);
        const std::string file = dir.write("c.toml", replaced(c.from, c.to));
        const auto r = run_pride("bench '" + file + "' --out '" + dir.file("s.sqlite") + "'");
        check_input_error(r, {file + c.words});
        CHECK(r.err.find('\x1b') == std::string::npos);  // never printed raw
        CHECK(!std::filesystem::exists(dir.file("s.sqlite")));
    }
    // A suite's prefix becomes part of every id: checked the same way.
    const std::string suite =
        dir.write("s.toml",
                  "name = \"n\"\nseeds = 1\n[budget]\nevaluations = 20\n[[suite]]\nname = \"bbob\"\nid = \"b\\u0007\"\n"
                  "functions = [1]\ndimensions = [2]\n[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\n");
    check_input_error(run_pride("bench '" + suite + "' --out '" + dir.file("s.sqlite") + "'"),
                      {suite + ":7:6: 'id' must not contain control characters (U+0007"});
    // A prefix within the bound whose ids are not: the ids the suite makes are checked too.
    const std::string long_suite =
        dir.write("l.toml", "name = \"n\"\nseeds = 1\n[budget]\nevaluations = 20\n[[suite]]\nname = \"bbob\"\nid = \"" +
                                std::string(95, 'b') +
                                "\"\nfunctions = [1]\ndimensions = [2]\n[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\n");
    check_input_error(run_pride("bench '" + long_suite + "' --out '" + dir.file("s.sqlite") + "'"),
                      {"problem id must be at most 100 bytes long"});
    CHECK(!std::filesystem::exists(dir.file("s.sqlite")));
}

TEST_CASE("store identity: campaigns built in code get the same name checks (prepare)", "[store-identity]") {
    pride::campaign::Campaign c;
    c.name = "code";
    c.seeds = 1;
    c.budget.evaluations = 10;
    pride::campaign::CampaignProblem p;
    p.id = std::string("a\0b", 3);
    p.spec = pride::engine::ContinuousSpec{"sphere", 2};
    c.problems.push_back(p);
    pride::campaign::CampaignAlgorithm a;
    a.id = "pso";
    a.spec.name = "pso";
    c.algorithms.push_back(a);
    CHECK_THROWS_WITH(pride::campaign::prepare(c), Catch::Contains("problem id must not contain a NUL character"));
    c.problems[0].id = "ok";
    c.name = "\x1b]0;title\x07";
    CHECK_THROWS_WITH(pride::campaign::prepare(c), Catch::Contains("name must not contain control characters (U+001B"));
}

// A campaign split across machines (docs/campaigns.md, "Splitting a campaign across machines"):
// `seeds` as a count, a list or a range names the same runs by their seeds' values, so that stores
// of its parts grow into and merge with one another; `pride bench --shard K/N` runs part K of N of
// the runs, and the parts' stores, made apart and merged, are the whole campaign's store (every
// run bit for bit, and its report); each bad `seeds` or `--shard` is one line, exit 2, no store.
#include <sqlite3.h>
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <numeric>
#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "experiment/campaign/ledger.hpp"
#include "experiment/campaign/prepare.hpp"
#include "experiment/campaign/run.hpp"
#include "framework/error.hpp"
#include "tests/cli_runner.hpp"
#include "tests/test_support.hpp"

namespace {

namespace fs = std::filesystem;
using pride::test::CliOutput;
using pride::test::run_pride;
using pride::test::TempDir;

/// 2 problems x 2 algorithms x SEEDS: 12 runs with `seeds = 3`, in the order s/pso, s/ga, f3/pso,
/// f3/ga, seeds innermost.
std::string campaign(const std::string& seeds) {
    return "name = \"sh\"\nseeds = " + seeds +
           "\n[budget]\nevaluations = 300\n"
           "[[problem]]\nid = \"s\"\ntype = \"sphere\"\ndim = 3\n"
           "[[problem]]\nid = \"f3\"\ntype = \"bbob-f3\"\ndim = 2\ninstance = 1\n"
           "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\npop = 10\n"
           "[[algorithm]]\nid = \"ga\"\ntype = \"ga\"\npop = 10\n";
}

std::string q(const std::string& s) {
    return "'" + s + "'";
}

CliOutput bench(const std::string& file, const std::string& store, const std::string& more = "") {
    return run_pride("bench " + q(file) + " --jobs 2 --out " + q(store) + (more.empty() ? "" : " " + more));
}

/// `pride bench` that must succeed: its summary line.
std::string bench_ok(const std::string& file, const std::string& store, const std::string& more = "") {
    const CliOutput r = bench(file, store, more);
    INFO(r.err);
    REQUIRE(r.status == 0);
    return r.out;
}

/// Every run of a store but its wall time, in key order: each value as SQLite holds it (a REAL by
/// its bits), so that equal rows are the same run bit for bit.
std::vector<std::string> runs(const std::string& store) {
    sqlite3* db = nullptr;
    REQUIRE(sqlite3_open_v2(store.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK);
    sqlite3_stmt* s = nullptr;
    REQUIRE(sqlite3_prepare_v2(db, "SELECT * FROM runs ORDER BY problem, algorithm, seed", -1, &s, nullptr) ==
            SQLITE_OK);
    std::vector<std::string> out;
    while (sqlite3_step(s) == SQLITE_ROW) {
        std::string row;
        for (int i = 0; i < sqlite3_column_count(s); ++i) {
            if (std::string(sqlite3_column_name(s, i)) == "wall_ms") continue;
            switch (sqlite3_column_type(s, i)) {
                case SQLITE_NULL:
                    row += "NULL";
                    break;
                case SQLITE_FLOAT: {
                    const double v = sqlite3_column_double(s, i);
                    std::uint64_t bits = 0;
                    std::memcpy(&bits, &v, sizeof bits);
                    row += fmt::format("{:016x}", bits);
                    break;
                }
                default:
                    row += reinterpret_cast<const char*>(sqlite3_column_text(s, i));
            }
            row += "|";
        }
        out.push_back(row);
    }
    sqlite3_finalize(s);
    sqlite3_close(db);
    return out;
}

/// The (problem, algorithm, seed) of every run of a store, as "problem/algorithm/seed".
std::set<std::string> keys(const std::string& store) {
    std::set<std::string> out;
    for (const auto& row : runs(store)) {
        const auto first = row.find('|'), second = row.find('|', first + 1), third = row.find('|', second + 1);
        out.insert(row.substr(0, first) + "/" + row.substr(first + 1, second - first - 1) + "/" +
                   row.substr(second + 1, third - second - 1));
    }
    return out;
}

/// `pride report STORES --format csv` without its column of wall times (the one thing that differs
/// between two runs of one campaign).
std::string report_csv(const std::string& stores) {
    const CliOutput r = run_pride("report " + stores + " --format csv");
    INFO(r.err);
    REQUIRE(r.status == 0);
    std::string out;
    int wall = -1;
    for (const auto& line : pride::test::lines_of(r.out)) {
        std::vector<std::string> fields;
        std::size_t from = 0;
        for (std::size_t comma; (comma = line.find(',', from)) != std::string::npos; from = comma + 1)
            fields.push_back(line.substr(from, comma - from));
        fields.push_back(line.substr(from));
        if (wall < 0)
            for (std::size_t i = 0; i < fields.size(); ++i)
                if (fields[i] == "mean_wall_ms") wall = static_cast<int>(i);
        for (std::size_t i = 0; i < fields.size(); ++i)
            if (static_cast<int>(i) != wall) out += fields[i] + ",";
        out += "\n";
    }
    REQUIRE(wall >= 0);
    return out;
}

/// The bad-input contract: exit 2, one line naming `words`, nothing on stdout.
void refused(const CliOutput& r, const std::vector<std::string>& words) {
    pride::test::check_input_error(r, words);
}

}  // namespace

TEST_CASE("campaign seeds: a list and a range run those seeds, the same runs as a count's", "[campaign][seeds]") {
    const TempDir dir("pride-seeds");
    const std::string whole = dir.file("w.sqlite"), listed = dir.file("l.sqlite"), ranged = dir.file("r.sqlite");
    bench_ok(dir.write("w.toml", campaign("4")), whole);
    CHECK(bench_ok(dir.write("l.toml", campaign("[3, 1]")), listed) ==
          "sh: 8 runs stored in " + listed + " (0 were there already, 8 in all)\n");
    CHECK(bench_ok(dir.write("r.toml", campaign("{ from = 2, to = 4 }")), ranged) ==
          "sh: 12 runs stored in " + ranged + " (0 were there already, 12 in all)\n");
    std::set<std::string> expected;
    for (const char* p : {"f3", "s"})
        for (const char* a : {"ga", "pso"})
            for (const int seed : {1, 3}) expected.insert(fmt::format("{}/{}/{}", p, a, seed));
    CHECK(keys(listed) == expected);
    // Each listed run is the count's run of that seed, bit for bit.
    const auto all = runs(whole);
    const std::set<std::string> all_rows(all.begin(), all.end());
    for (const auto& row : runs(listed)) CHECK(all_rows.count(row) == 1);
    for (const auto& row : runs(ranged)) CHECK(all_rows.count(row) == 1);
    // Merged, seeds {1, 3} and {2, 3, 4} are the store of seeds = 4 (seed 3 found in both, equal).
    const std::string merged = dir.file("m.sqlite");
    const CliOutput m = run_pride("merge " + q(listed) + " " + q(ranged) + " --out " + q(merged));
    INFO(m.err);
    REQUIRE(m.status == 0);
    CHECK(m.out == "merged 2 stores into " + merged + ": 16 runs (4 found in more than one store, equal, kept once)\n");
    CHECK(runs(merged) == all);
    CHECK(report_csv(q(merged)) == report_csv(q(whole)));
}

TEST_CASE("campaign seeds: a store grows from a list to a count, running only the seeds it lacks",
          "[campaign][seeds]") {
    const TempDir dir("pride-seeds-grow");
    const std::string store = dir.file("g.sqlite");
    CHECK(bench_ok(dir.write("a.toml", campaign("[5]")), store) ==
          "sh: 4 runs stored in " + store + " (0 were there already, 4 in all)\n");
    CHECK(bench_ok(dir.write("b.toml", campaign("5")), store) ==
          "sh: 16 runs stored in " + store + " (4 were there already, 20 in all)\n");
    CHECK(bench_ok(dir.write("c.toml", campaign("{ from = 4, to = 6 }")), store) ==
          "sh: 4 runs stored in " + store + " (8 were there already, 12 in all)\n");
    const std::string fresh = dir.file("f.sqlite");
    bench_ok(dir.write("f.toml", campaign("6")), fresh);
    CHECK(runs(store) == runs(fresh));
}

TEST_CASE("campaign seeds: a bad list or range is one line naming the file, line and key",
          "[campaign][seeds][errors]") {
    const TempDir dir("pride-seeds-errors");
    const std::string store = dir.file("c.sqlite");
    const auto refused_seeds = [&](const std::string& seeds, const std::string& message) {
        INFO("seeds = " << seeds);
        const std::string file = dir.write("c.toml", campaign(seeds));
        refused(bench(file, store), {file + ":2:", message, "'seeds'"});
        CHECK(!fs::exists(store));
    };
    refused_seeds("[]", "c.toml:2:9: 'seeds' must not be an empty list");
    refused_seeds("[4, 5, 4]", "c.toml:2:16: 'seeds' lists seed 4 twice");
    refused_seeds("[0]", "c.toml:2:10: 'seeds': a seed must be in [1, 1000000], got 0");
    refused_seeds("[3, -2]", "c.toml:2:13: 'seeds': a seed must be in [1, 1000000], got -2");
    refused_seeds("[1000001]", "'seeds': a seed must be in [1, 1000000], got 1000001");
    refused_seeds("[1, 2.5]", "c.toml:2:13: 'seeds' must list integers (the seeds)");
    refused_seeds("[1, \"2\"]", "c.toml:2:13: 'seeds' must list integers (the seeds)");
    refused_seeds("{ from = 5, to = 4 }",
                  "c.toml:2:9: 'seeds' from 5 to 4 is empty ('from' must be at most 'to': both are included)");
    refused_seeds("{ from = 1, to = 1000001 }", "'seeds': 'to' must be in [1, 1000000], got 1000001");
    refused_seeds("{ from = 0, to = 3 }", "'seeds': 'from' must be in [1, 1000000], got 0");
    refused_seeds("{ from = 1.0, to = 3 }", "'seeds': 'from' must be an integer");
    refused_seeds("{ from = 1 }", "'seeds' needs 'from' and 'to' (its first and last seeds)");
    refused_seeds("{ from = 1, to = 3, step = 2 }", "unknown key 'step' in the range 'seeds' (from, to)");
    refused_seeds("2.5", "c.toml:2: 'seeds' must be an integer N (seeds 1..N), a list of seeds");
    refused_seeds("\"1..3\"", "c.toml:2: 'seeds' must be an integer N (seeds 1..N), a list of seeds");
    refused_seeds("0", "c.toml:2: 'seeds' must be in [1, 1000000], got 0");  // a count, as before
}

TEST_CASE("bench --shard: shards 1/3, 2/3 and 3/3 merged are the whole campaign's store", "[campaign][shard]") {
    const TempDir dir("pride-shards");
    const std::string file = dir.write("c.toml", campaign("3"));
    const std::string whole = dir.file("w.sqlite");
    CHECK(bench_ok(file, whole) == "sh: 12 runs stored in " + whole + " (0 were there already, 12 in all)\n");
    std::vector<std::string> parts;
    std::set<std::string> seen;
    for (int k = 1; k <= 3; ++k) {
        const std::string part = dir.file(fmt::format("p{}.sqlite", k));
        CHECK(bench_ok(file, part, fmt::format("--shard {}/3", k)) ==
              fmt::format("sh: 4 runs stored in {} (0 were there already, 4 in all; shard {}/3 of the campaign's 12 "
                          "runs)\n",
                          part, k));
        // Every third run of the ordered list (problems, algorithms, seeds): here seed k of each pair.
        std::set<std::string> expected;
        for (const char* p : {"f3", "s"})
            for (const char* a : {"ga", "pso"}) expected.insert(fmt::format("{}/{}/{}", p, a, k));
        CHECK(keys(part) == expected);
        for (const auto& key : keys(part)) CHECK(seen.insert(key).second);  // no run in two shards
        parts.push_back(part);
    }
    const std::string merged = dir.file("m.sqlite");
    const CliOutput m =
        run_pride("merge " + q(parts[0]) + " " + q(parts[1]) + " " + q(parts[2]) + " --out " + q(merged));
    INFO(m.err);
    REQUIRE(m.status == 0);
    CHECK(m.out == "merged 3 stores into " + merged + ": 12 runs (0 found in more than one store, equal, kept once)\n");
    CHECK(runs(merged) == runs(whole));
    CHECK(report_csv(q(merged)) == report_csv(q(whole)));
    // The parts read as one by pride report, unmerged, report the same.
    CHECK(report_csv(q(parts[0]) + " " + q(parts[1]) + " " + q(parts[2])) == report_csv(q(whole)));
    // The merged store is the whole campaign's: a bench of the whole finds every run there.
    CHECK(bench_ok(file, merged) == "sh: 0 runs stored in " + merged + " (12 were there already, 12 in all)\n");
    // More shards than runs: the last ones are empty, and say so.
    const std::string empty = dir.file("e.sqlite");
    CHECK(bench_ok(file, empty, "--shard 13/20") ==
          "sh: 0 runs stored in " + empty +
              " (0 were there already, 0 in all; shard 13/20 of the campaign's 12 runs)\n");
    CHECK(runs(empty).empty());
}

TEST_CASE("bench --shard: a shard's store takes the other shards and the whole, no run twice", "[campaign][shard]") {
    const TempDir dir("pride-shards-resume");
    const std::string file = dir.write("c.toml", campaign("{ from = 1, to = 3 }"));
    const std::string whole = dir.file("w.sqlite"), store = dir.file("s.sqlite");
    bench_ok(file, whole);
    const std::string of = " of the campaign's 12 runs)\n";
    CHECK(bench_ok(file, store, "--shard 1/2") ==
          "sh: 6 runs stored in " + store + " (0 were there already, 6 in all; shard 1/2" + of);
    CHECK(bench_ok(file, store, "--shard 1/2") ==
          "sh: 0 runs stored in " + store + " (6 were there already, 6 in all; shard 1/2" + of);
    CHECK(bench_ok(file, store, "--shard 2/2") ==
          "sh: 6 runs stored in " + store + " (0 were there already, 6 in all; shard 2/2" + of);
    CHECK(bench_ok(file, store) == "sh: 0 runs stored in " + store + " (12 were there already, 12 in all)\n");
    CHECK(runs(store) == runs(whole));
    // A shard's store finished by the whole campaign: the rest run once.
    const std::string rest = dir.file("r.sqlite");
    bench_ok(file, rest, "--shard 3/4");
    CHECK(bench_ok(file, rest) == "sh: 9 runs stored in " + rest + " (3 were there already, 12 in all)\n");
    CHECK(runs(rest) == runs(whole));
}

TEST_CASE("bench --shard: a bad part is one line naming --shard, exit 2, nothing written",
          "[campaign][shard][errors]") {
    const TempDir dir("pride-shards-errors");
    const std::string file = dir.write("c.toml", campaign("3"));
    const std::string store = dir.file("s.sqlite");
    for (const std::string bad : {"0/3", "4/3", "3", "1/0", "0/0", "a/b", "1/3/4", "-1/3", "1/-3", "1.5/3", "1/3.0",
                                  "1e1/20", "/3", "1/", " 1/3", "99999999999999999999/3"}) {
        INFO("--shard '" << bad << "'");
        refused(bench(file, store, "--shard=" + q(bad)),
                {"pride: --shard: must be K/N, part K of N with integers 1 <= K <= N (e.g. 2/3), got '" + bad + "'"});
        CHECK(!fs::exists(store));
    }
    // No value at all: the argument parser's own line, naming the flag.
    refused(bench(file, store, "--shard=''"), {"pride: --shard: 1 required TEXT missing"});
    refused(bench(file, store, "--shard"), {"--shard"});
    CHECK(!fs::exists(store));
}

TEST_CASE("campaign seeds and shards in code: listed seeds checked, parts dealt round-robin", "[campaign][shard]") {
    using namespace pride::campaign;
    Campaign c;
    c.name = "code";
    c.budget.evaluations = 200;
    for (const char* id : {"a", "b", "c"}) {
        CampaignProblem p;
        p.id = id;
        p.spec = pride::engine::ContinuousSpec{"sphere", 2};
        c.problems.push_back(p);
    }
    c.algorithms.push_back({"pso", pride::engine::AlgorithmSpec{"pso", {}}, 0});
    c.seed_list = {7, 3};
    c.seeds = 2;
    Campaign twice = c, miscounted = c, zero = c;
    twice.seed_list = {7, 7};
    miscounted.seeds = 3;
    zero.seed_list = {0, 3};
    CHECK(pride::test::input_error_message([&] { prepare(twice); }) == "campaign: seeds: seed 7 is listed twice");
    CHECK(pride::test::input_error_message([&] { prepare(miscounted); }) ==
          "campaign: seeds: 3 runs per problem and algorithm, but 2 seeds listed");
    CHECK(pride::test::input_error_message([&] { prepare(zero); }) ==
          "campaign: seeds: a seed must be in [1, 1000000], got 0");
    Campaign apart = c;  // a seed twice, not side by side
    apart.seed_list = {9, 3, 5, 3};
    apart.seeds = 4;
    CHECK(pride::test::input_error_message([&] { prepare(apart); }) == "campaign: seeds: seed 3 is listed twice");
    Campaign million = c;  // the largest range, as the file's reader lists it
    million.seed_list.resize(1'000'000);
    std::iota(million.seed_list.begin(), million.seed_list.end(), std::int64_t{1});
    million.seeds = 1'000'000;
    prepare(million);
    CHECK(million.seed_list.back() == 1'000'000);
    CHECK(million.text.find("seeds = [1, 2, 3, ") != std::string::npos);
    prepare(c);
    CHECK(c.text.find("seeds = [7, 3]\n") != std::string::npos);  // the canonical text of a code-built campaign
    // Six runs, a7 a3 b7 b3 c7 c3; part 2 of 4 takes runs 1 and 5.
    const auto part = all_tasks(c, Shard{2, 4});
    REQUIRE(part.size() == 2);
    CHECK((part[0].problem->id == "a" && part[0].seed == 3));
    CHECK((part[1].problem->id == "c" && part[1].seed == 3));
    std::size_t dealt = 0;
    for (std::int64_t k = 1; k <= 4; ++k) dealt += all_tasks(c, Shard{k, 4}).size();
    CHECK(dealt == all_tasks(c).size());
    const TempDir dir("pride-shards-code");
    CHECK(pride::test::input_error_message([&] {
              run_campaign(c, dir.file("s.sqlite"), 1, {}, {}, Shard{3, 2});
          }) == "shard: must be part K of N with 1 <= K <= N, got 3/2");
    const BenchSummary s = run_campaign(c, dir.file("s.sqlite"), 1, {}, {}, Shard{2, 4});
    CHECK((s.stored == 2 && s.already == 0 && s.total == 2 && s.others == 0));
    const BenchSummary rest = run_campaign(c, dir.file("s.sqlite"), 2);
    CHECK((rest.stored == 4 && rest.already == 2 && rest.total == 6 && rest.others == 0));
    CHECK(keys(dir.file("s.sqlite")) ==
          std::set<std::string>{"a/pso/3", "a/pso/7", "b/pso/3", "b/pso/7", "c/pso/3", "c/pso/7"});
}

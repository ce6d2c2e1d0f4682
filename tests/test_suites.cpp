// Suites in campaign files ([[suite]] name = "bbob" | "classic", instance lists on problems) and
// what a suite campaign stores: the problems' function, instance, f_opt, suite and number, COCO's
// precisions, and each run's exact target hits; stores from before these columns still resume.
#include <sqlite3.h>
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <set>
#include <string>
#include <vector>

#include "experiment/campaign/run.hpp"
#include "experiment/campaign/toml.hpp"
#include "tests/sqlite_support.hpp"
#include "tests/test_support.hpp"

using Catch::Matchers::Contains;
using pride::test::input_error_message;
using pride::test::TempDir;

using pride::test::exec_sql;

namespace {

/// Every row of `sql` as text (NULL as "null", reals with 17 digits).
std::vector<std::vector<std::string>> rows(const std::string& store, const std::string& sql) {
    sqlite3* db = nullptr;
    REQUIRE(sqlite3_open_v2(store.c_str(), &db, SQLITE_OPEN_READWRITE, nullptr) == SQLITE_OK);
    sqlite3_stmt* s = nullptr;
    REQUIRE(sqlite3_prepare_v2(db, sql.c_str(), -1, &s, nullptr) == SQLITE_OK);
    std::vector<std::vector<std::string>> out;
    while (sqlite3_step(s) == SQLITE_ROW) {
        std::vector<std::string> row;
        for (int i = 0; i < sqlite3_column_count(s); ++i) {
            if (sqlite3_column_type(s, i) == SQLITE_FLOAT) {
                char buffer[64];
                std::snprintf(buffer, sizeof buffer, "%.17g", sqlite3_column_double(s, i));
                row.emplace_back(buffer);
                continue;
            }
            const auto* text = sqlite3_column_text(s, i);
            row.emplace_back(text ? reinterpret_cast<const char*>(text) : "null");
        }
        out.push_back(std::move(row));
    }
    sqlite3_finalize(s);
    sqlite3_close(db);
    return out;
}

const std::string kSuiteCampaign = R"(name = "suites"
seeds = 2
[budget]
evaluations = 600
[[suite]]
name = "bbob"
functions = [1, 8]
instances = [1, 2]
dimensions = [2, 3]
[[suite]]
name = "classic"
id = "yao"
functions = [1, 16]
instances = [0, 1]
dimensions = [4, 6]
[[problem]]
id = "sph"
type = "sphere"
dim = 3
instance = [0, 5]
[[algorithm]]
id = "pso"
type = "pso"
pop = 10
)";

}  // namespace

TEST_CASE("suites: [[suite]] and instance lists expand to one problem per (function, instance, dimension)",
          "[suites]") {
    const TempDir dir;
    const auto c = pride::campaign::read_campaign(dir.write("c.toml", kSuiteCampaign));
    std::vector<std::string> ids;
    for (const auto& p : c.problems) ids.push_back(p.id);
    // bbob: 2 functions x 2 dimensions x 2 instances; classic: F1 in 4 and 6 at instances 0 and 1,
    // F16 (2-D, one instance) once; then the instance list of "sph".
    const std::vector<std::string> expected{"bbob-f1-i1-d2", "bbob-f1-i2-d2", "bbob-f1-i1-d3", "bbob-f1-i2-d3",
                                            "bbob-f8-i1-d2", "bbob-f8-i2-d2", "bbob-f8-i1-d3", "bbob-f8-i2-d3",
                                            "yao-f1-i0-d4",  "yao-f1-i1-d4",  "yao-f1-i0-d6",  "yao-f1-i1-d6",
                                            "yao-f16-i0-d2", "sph-i0",        "sph-i5"};
    CHECK(ids == expected);
    const auto& f8 = std::get<pride::engine::ContinuousSpec>(c.problems[7].spec);
    CHECK(f8.function == "bbob-f8");
    CHECK(f8.dim == 3);
    CHECK(f8.instance == 2);
    CHECK(c.problems[7].problem->instance() == 2);
    CHECK(c.problems[0].suite == "bbob");
    CHECK(c.problems[13].suite.empty());
    CHECK(c.problems[14].problem->instance() == 5);
}

TEST_CASE("suites: bad suite tables are one line naming the file and line", "[suites]") {
    const TempDir dir;
    auto error = [&](const std::string& suite) {
        const std::string text = "name = \"x\"\nseeds = 1\n[budget]\nevaluations = 10\n" + suite +
                                 "[[algorithm]]\nid = \"a\"\ntype = \"pso\"\n";
        return input_error_message([&] { (void)pride::campaign::read_campaign(dir.write("bad.toml", text)); });
    };
    CHECK_THAT(error("[[suite]]\nname = \"cec\"\ndimensions = [2]\n"),
               Contains("bad.toml:5") && Contains("unknown suite 'cec'"));
    CHECK_THAT(error("[[suite]]\nname = \"bbob\"\n"), Contains("bad.toml:5") && Contains("needs 'dimensions'"));
    CHECK_THAT(error("[[suite]]\nname = \"bbob\"\nfunctions = [25]\ndimensions = [2]\n"),
               Contains("bad.toml:7") && Contains("function 25 is not in the bbob suite"));
    CHECK_THAT(error("[[suite]]\nname = \"bbob\"\ninstances = [0]\ndimensions = [2]\n"),
               Contains("instance") && Contains("from 1"));
    CHECK_THAT(error("[[suite]]\nname = \"bbob\"\ndimensions = [1]\n"), Contains("dim") && Contains(">= 2"));
    CHECK_THAT(error("[[suite]]\nname = \"bbob\"\ndimensions = []\n"), Contains("must not be empty"));
    CHECK_THAT(error("[[suite]]\nname = \"bbob\"\ndimensions = [2]\nseed = 3\n"), Contains("unknown key 'seed'"));
    CHECK_THAT(error("[[suite]]\nname = \"bbob\"\ndimensions = 2\n"), Contains("'dimensions' must be a list"));
    CHECK_THAT(error("[[problem]]\nid = \"p\"\ntype = \"sphere\"\ndim = 2\ninstance = []\n"),
               Contains("'instance' must not be an empty list"));
    CHECK_THAT(error("[[problem]]\nid = \"p\"\ntype = \"branin\"\ndim = 2\ninstance = 3\n"),
               Contains("one instance only"));
    // The same problem twice (a suite and a problem with the same id).
    CHECK_THAT(error("[[suite]]\nname = \"bbob\"\nfunctions = [1]\ninstances = [1]\ndimensions = [2]\n"
                     "[[problem]]\nid = \"bbob-f1-i1-d2\"\ntype = \"sphere\"\ndim = 2\n"),
               Contains("bbob-f1-i1-d2"));
}

TEST_CASE("suites: a suite campaign stores f_opt, instance, suite, COCO's precisions and exact target hits",
          "[suites]") {
    const TempDir dir;
    const std::string config = dir.write("c.toml", kSuiteCampaign);
    const std::string store = dir.file("c.sqlite");
    const auto c = pride::campaign::read_campaign(config);
    const auto summary = pride::campaign::run_campaign(c, store, 2);
    CHECK(summary.stored == 15 * 2);

    const auto precisions = rows(store, "SELECT precisions FROM campaign");
    // Shortest round-trip decimals: 10^1.8 = 63.09573444801933, ..., 1e-08 last.
    CHECK(precisions.at(0).at(0).rfind("[100, 63.09573444801933, 39.810717055349734, ", 0) == 0);
    CHECK(precisions.at(0).at(0).find(", 10, ") != std::string::npos);
    CHECK(precisions.at(0).at(0).size() > 300);
    CHECK(precisions.at(0).at(0).substr(precisions.at(0).at(0).size() - 6) == "1e-08]");

    const auto problems = rows(store, "SELECT id, function, instance, f_opt, suite, fid FROM problems ORDER BY rowid");
    REQUIRE(problems.size() == 15);
    // bbob_optima.tsv (COCO): f1 instance 1 has f_opt 79.480000000000004, instance 2 394.48000000000002.
    CHECK(problems[0] == std::vector<std::string>{"bbob-f1-i1-d2", "bbob-f1", "1", "79.480000000000004", "bbob", "1"});
    CHECK(problems[1] == std::vector<std::string>{"bbob-f1-i2-d2", "bbob-f1", "2", "394.48000000000002", "bbob", "1"});
    CHECK(problems[12] ==
          std::vector<std::string>{"yao-f16-i0-d2", "yao-f16", "0", "-1.0316284534898774", "classic", "16"});
    CHECK(problems[14] == std::vector<std::string>{"sph-i5", "sphere", "5", "0", "null", "null"});

    // Each run's hits: 51 entries (COCO's targets), an integer or null, non-decreasing, within the run's evaluations,
    // and agreeing with the best value stored (reached iff best <= f_opt + precision).
    const auto runs = rows(store,
                           "SELECT r.target_hits, r.best, r.evaluations, p.f_opt FROM runs r JOIN problems p ON "
                           "p.id = r.problem");
    REQUIRE(runs.size() == 30);
    const std::vector<double>& p = pride::campaign::coco_precisions();
    REQUIRE(p.size() == 51);
    for (const auto& r : runs) {
        INFO(r[0]);
        const auto parsed = pride::test::parse_json(r[0]);
        REQUIRE(parsed.items.size() == 51);
        const double best = std::stod(r[1]), f_opt = std::stod(r[3]);
        const long long evaluations = std::stoll(r[2]);
        long long last = 0;
        for (std::size_t k = 0; k < 51; ++k) {
            const auto& hit = parsed.items[k];
            CHECK((hit.kind == pride::test::JsonValue::Kind::null) == !(best <= f_opt + p[k]));
            if ((hit.kind == pride::test::JsonValue::Kind::null)) continue;
            const auto n = static_cast<long long>(hit.number);
            CHECK(n >= std::max(1LL, last));
            CHECK(n <= evaluations);
            last = n;
        }
    }
}

TEST_CASE("suites: a store written before the suite columns resumes and gains them", "[suites]") {
    const TempDir dir;
    const std::string config = dir.write("c.toml", kSuiteCampaign);
    const std::string store = dir.file("c.sqlite");
    const auto c = pride::campaign::read_campaign(config);
    (void)pride::campaign::run_campaign(c, store, 1);
    // Back to the schema of before: no new columns, half the runs.
    exec_sql(
        store,
        "DELETE FROM runs WHERE seed = 2; ALTER TABLE runs DROP COLUMN target_hits; ALTER TABLE campaign DROP COLUMN "
        "precisions; ALTER TABLE problems DROP COLUMN function; ALTER TABLE problems DROP COLUMN instance; ALTER TABLE "
        "problems DROP COLUMN f_opt; ALTER TABLE problems DROP COLUMN suite; ALTER TABLE problems DROP COLUMN fid");
    const auto summary = pride::campaign::run_campaign(c, store, 1);
    CHECK(summary.already == 15);
    CHECK(summary.stored == 15);
    const auto hits = rows(store, "SELECT seed, target_hits FROM runs ORDER BY seed");
    REQUIRE(hits.size() == 30);
    CHECK(hits.front()[1] == "[]");  // the old runs: no hits recorded
    CHECK(hits.back()[1].size() > 2);
}

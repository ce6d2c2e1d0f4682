// The store's schema version (experiment/storage/schema.hpp): written by pride bench, and a store from a
// newer pride refused by bench, report and export alike, one line naming the store and both versions.
#include <sqlite3.h>
#include <catch2/catch.hpp>

#include <string>

#include "experiment/storage/schema.hpp"
#include "tests/cli_runner.hpp"
#include "tests/test_support.hpp"

namespace {

int user_version(const std::string& store, int set = -1) {
    sqlite3* db = nullptr;
    REQUIRE(sqlite3_open(store.c_str(), &db) == SQLITE_OK);
    if (set >= 0)
        REQUIRE(sqlite3_exec(db, ("PRAGMA user_version = " + std::to_string(set)).c_str(), nullptr, nullptr, nullptr) ==
                SQLITE_OK);
    sqlite3_stmt* s = nullptr;
    REQUIRE(sqlite3_prepare_v2(db, "PRAGMA user_version", -1, &s, nullptr) == SQLITE_OK);
    REQUIRE(sqlite3_step(s) == SQLITE_ROW);
    const int v = sqlite3_column_int(s, 0);
    sqlite3_finalize(s);
    sqlite3_close(db);
    return v;
}

}  // namespace

TEST_CASE("store: its schema version is written, and a newer one refused", "[store][schema]") {
    const pride::test::TempDir tmp("pride-schema");
    const std::string file = tmp.write("c.toml",
                                       "name = \"v\"\nseeds = 1\n[budget]\nevaluations = 50\n"
                                       "[[problem]]\nid = \"s\"\ntype = \"sphere\"\ndim = 2\n"
                                       "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\npop = 10\n");
    const std::string store = tmp.file("c.sqlite");
    REQUIRE(pride::test::run_pride("bench '" + file + "' --out '" + store + "'").status == 0);
    CHECK(user_version(store) == pride::storage::schema_version);
    // A store of schema 0 (before the version was kept) is migrated by the next bench.
    user_version(store, 0);
    REQUIRE(pride::test::run_pride("bench '" + file + "' --out '" + store + "'").status == 0);
    CHECK(user_version(store) == pride::storage::schema_version);
    CHECK(pride::test::run_pride("report '" + store + "'").status == 0);

    user_version(store, pride::storage::schema_version + 1);
    const std::string newer = std::to_string(pride::storage::schema_version + 1);
    for (const std::string& command : {"bench '" + file + "' --out '" + store + "'", "report '" + store + "'",
                                       "export '" + store + "' --ioh '" + tmp.file("ioh") + "'"}) {
        INFO(command);
        const auto r = pride::test::run_pride(command);
        CHECK(r.status == 2);
        CHECK_THAT(r.err, Catch::StartsWith("pride: " + store + ": was written by a newer pride (store schema " +
                                            newer + "; this pride knows 0 to "));
        CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    }
    CHECK(user_version(store) == pride::storage::schema_version + 1);  // left as it was
}

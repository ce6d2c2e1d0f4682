#pragma once
// Statements run on a store by the tests that damage, edit or inspect one directly.
#include <sqlite3.h>

#include <catch2/catch.hpp>
#include <string>

namespace pride::test {

/// Runs `sql` (one or more statements) on the existing SQLite file `store` (never created here);
/// a failure fails the test with SQLite's message.
inline void exec_sql(const std::string& store, const std::string& sql) {
    sqlite3* db = nullptr;
    REQUIRE(sqlite3_open_v2(store.c_str(), &db, SQLITE_OPEN_READWRITE, nullptr) == SQLITE_OK);
    char* error = nullptr;
    const int rc = sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &error);
    INFO((error ? error : ""));
    sqlite3_free(error);
    sqlite3_close(db);
    REQUIRE(rc == SQLITE_OK);
}

}  // namespace pride::test

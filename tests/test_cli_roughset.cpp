// Tests of `pride roughset` as a user runs it: the published results of Pawlak's table in the
// human output and in the JSON, the grid table's sizes, and bad input (exit status 2, one line).
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include "tests/cli_runner.hpp"
#include "tests/json_reader.hpp"
#include "tests/test_support.hpp"

namespace {

using pride::test::JsonValue;
using pride::test::lines_of;
using pride::test::parse_json;
using pride::test::run_pride;

const std::string p72 = std::string("'") + PRIDE_SHARED_DATA + "/roughset/pawlak1991_p72.csv'";

std::vector<std::string> strings(const JsonValue& array) {
    REQUIRE(array.kind == JsonValue::Kind::array);
    std::vector<std::string> out;
    for (const auto& item : array.items) {
        REQUIRE(item.kind == JsonValue::Kind::string);
        out.push_back(item.text);
    }
    return out;
}

void expect_input_error(const std::string& args, const std::string& fragment) {
    INFO("pride " << args);
    const auto r = run_pride(args);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    const auto lines = lines_of(r.err);
    REQUIRE(lines.size() == 1);
    CHECK(lines[0].find(fragment) != std::string::npos);
}

}  // namespace

TEST_CASE("cli roughset: human output on pawlak1991_p72 gives the published results", "[cli][roughset]") {
    const auto r = run_pride("roughset " + p72);
    REQUIRE(r.status == 0);
    CHECK(r.err.empty());
    const auto lines = lines_of(r.out);
    auto has = [&](const std::string& line) { return std::find(lines.begin(), lines.end(), line) != lines.end(); };
    CHECK(has("consistent: yes"));
    CHECK(has("positive region: 7 of 7 objects (dependency 1)"));
    CHECK(has("core: {a, b, d}"));
    CHECK(has("reducts: 1 (exhaustive over 4 condition attributes)"));
    CHECK(has("  {a, b, d}"));
    CHECK(has("rules on {a, b, d} (the only reduct): 4 minimal certain rules"));
    CHECK(has("  a=1 and b=0 -> e=1  [objects 1, 2]"));
    CHECK(has("  a=0 -> e=0          [object 3]"));
    CHECK(has("  b=1 and d=1 -> e=0  [object 4]"));
    CHECK(has("  d=2 -> e=2          [objects 5, 6, 7]"));
}

TEST_CASE("cli roughset: --json on pawlak1991_p72 gives the published results", "[cli][roughset]") {
    const auto r = run_pride("roughset " + p72 + " --json");
    REQUIRE(r.status == 0);
    const JsonValue j = parse_json(r.out);
    CHECK(j.at("consistent").kind == JsonValue::Kind::boolean);
    CHECK(j.at("consistent").boolean);
    CHECK(j.at("positive_region").is_integer());
    CHECK(j.at("positive_region").number == 7);
    CHECK(strings(j.at("core")) == std::vector<std::string>{"a", "b", "d"});
    REQUIRE(j.at("reducts").items.size() == 1);
    CHECK(strings(j.at("reducts").items[0]) == std::vector<std::string>{"a", "b", "d"});
    CHECK(strings(j.at("reduct_used")) == std::vector<std::string>{"a", "b", "d"});
    const auto& rules = j.at("rules");
    REQUIRE(rules.items.size() == 4);
    std::vector<std::string> got;
    for (const auto& rule : rules.items) {
        std::string s;
        for (const auto& [name, value] : rule.at("if").members) s += name + "=" + value.text + " ";
        got.push_back(s + "-> " + rule.at("then").text);
    }
    CHECK(got == std::vector<std::string>{"a=1 b=0 -> 1", "a=0 -> 0", "b=1 d=1 -> 0", "d=2 -> 2"});
}

TEST_CASE("cli roughset: labels and names are JSON-escaped and printed as read", "[cli][roughset]") {
    pride::test::TempDir dir;
    const auto path = dir.write("t.csv", "\"say \"\"hi\"\"\",\"back\\slash\"\nx,\"a\tb\"\ny,c\n");
    const auto r = run_pride("roughset '" + path + "' --json");
    REQUIRE(r.status == 0);
    const JsonValue j = parse_json(r.out);
    CHECK(strings(j.at("core")) == std::vector<std::string>{"say \"hi\""});
    REQUIRE(j.at("rules").items.size() == 2);
    CHECK(j.at("rules").items[0].at("then").text == "a\tb");
    CHECK(j.at("rules").items[0].at("if").at("say \"hi\"").text == "x");
}

TEST_CASE("cli roughset: bad input exits with status 2 and one line", "[cli][roughset]") {
    pride::test::TempDir dir;
    expect_input_error("roughset", "give a decision table TABLE.csv, or --grid");
    expect_input_error("roughset " + p72 + " --grid", "not both");
    expect_input_error("roughset /nonexistent/t.csv", "/nonexistent/t.csv: cannot open");
    const auto bad = dir.write("bad.csv", "a,b,c\n1,2,3\n1,2\n");
    expect_input_error("roughset '" + bad + "'", "bad.csv:3:4: row has 2 fields, expected 3");
    const auto unterminated = dir.write("q.csv", "a,b\n\"1,2\n");
    expect_input_error("roughset '" + unterminated + "' --json", "q.csv:2:1: unterminated quote");
}

TEST_CASE("cli roughset: --grid --json gives the sizes beside file 000's", "[cli][roughset]") {
    const auto r = run_pride("roughset --grid --json");
    REQUIRE(r.status == 0);
    const JsonValue j = parse_json(r.out);
    const auto& sizes = j.at("sizes");
    CHECK(sizes.at("rows").number == 6561);
    CHECK(sizes.at("attributes").number == 5);
    CHECK(sizes.at("reduced_rows").number == 243);
    CHECK(sizes.at("rules").number == static_cast<double>(j.at("rules").items.size()));
    const auto& paper = j.at("paper");
    CHECK(paper.at("rows").number == 4374);
    CHECK(paper.at("attributes").number == 5);
    CHECK(paper.at("reduced_rows").number == 162);
    CHECK(paper.at("rules").number == 80);
    // The three backward-facing neighbours X4, X5, X6 are dispensable.
    CHECK(strings(j.at("reduct_used")) == std::vector<std::string>{"X1", "X2", "X3", "X7", "X8"});
    CHECK(j.at("consistent").boolean);
    const auto human = run_pride("roughset --grid");
    REQUIRE(human.status == 0);
    CHECK(human.out.find("rows of the full table          6561      4374") != std::string::npos);
}

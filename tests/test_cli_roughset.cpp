// Tests of `pride roughset` as a user runs it: the published results of Pawlak's table in the
// human output and in the JSON, the grid table's sizes, and bad input (exit status 2, one line).
#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <optional>
#include <string>
#include <vector>

#include "tests/cli_runner.hpp"
#include "tests/json_reader.hpp"
#include "tests/test_support.hpp"

namespace {

using pride::test::expect_input_error;
using pride::test::JsonValue;
using pride::test::lines_of;
using pride::test::parse_json;
using pride::test::run_pride;

/// Pawlak's table of p. 72, quoted for the shell ($PRIDE_DATA/roughset), or nothing (skipped).
std::optional<std::string> pawlak72() {
    const auto path = pride::test::shared_data("roughset/pawlak1991_p72.csv", "Pawlak's decision tables");
    if (!path) return std::nullopt;
    return "'" + path->string() + "'";
}

std::vector<std::string> strings(const JsonValue& array) {
    REQUIRE(array.kind == JsonValue::Kind::array);
    std::vector<std::string> out;
    for (const auto& item : array.items) {
        REQUIRE(item.kind == JsonValue::Kind::string);
        out.push_back(item.text);
    }
    return out;
}

}  // namespace

TEST_CASE("cli roughset: human output on pawlak1991_p72 gives the published results", "[cli][roughset]") {
    const auto p72 = pawlak72();
    if (!p72) return;
    const auto r = run_pride("roughset " + *p72);
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
    const auto p72 = pawlak72();
    if (!p72) return;
    const auto r = run_pride("roughset " + *p72 + " --json");
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
    expect_input_error("roughset", {"give a decision table TABLE.csv, or --grid"});
    expect_input_error("roughset '" + dir.write("table.csv", "a,d\n1,0\n") + "' --grid", {"not both"});
    expect_input_error("roughset /nonexistent/t.csv", {"/nonexistent/t.csv: cannot open"});
    const auto bad = dir.write("bad.csv", "a,b,c\n1,2,3\n1,2\n");
    expect_input_error("roughset '" + bad + "'", {"bad.csv:3:4: row has 2 fields, expected 3"});
    const auto unterminated = dir.write("q.csv", "a,b\n\"1,2\n");
    expect_input_error("roughset '" + unterminated + "' --json", {"q.csv:2:1: unterminated quote"});
}

TEST_CASE("cli roughset: --grid --json gives the sizes beside those of Wan and Gao (2022)", "[cli][roughset]") {
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
    CHECK(human.out.find("rows of the full table          6561                4374") != std::string::npos);
}

namespace {

// A CSV of the given header and rows, each a list of fields.
std::string csv_of(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows) {
    std::string s;
    for (std::size_t i = 0; i < header.size(); ++i) s += (i ? "," : "") + header[i];
    s += "\n";
    for (const auto& row : rows) {
        for (std::size_t i = 0; i < row.size(); ++i) s += (i ? "," : "") + row[i];
        s += "\n";
    }
    return s;
}

// The lines of `text` as a predicate: whether `line` is one of them.
auto line_finder(const std::string& text) {
    return [lines = lines_of(text)](const std::string& line) {
        return std::find(lines.begin(), lines.end(), line) != lines.end();
    };
}

// The rules of a --json document as "name=value name=value -> then (support)".
std::vector<std::string> rule_strings(const JsonValue& rules) {
    REQUIRE(rules.kind == JsonValue::Kind::array);
    std::vector<std::string> out;
    for (const auto& rule : rules.items) {
        REQUIRE(rule.at("if").kind == JsonValue::Kind::object);
        std::string s;
        for (const auto& [name, value] : rule.at("if").members) s += name + "=" + value.text + " ";
        out.push_back(s + "-> " + rule.at("then").text + " (" +
                      std::to_string(static_cast<int>(rule.at("support").number)) + ")");
    }
    return out;
}

}  // namespace

TEST_CASE("cli roughset: more than 16 condition attributes, the QuickReduct result only", "[cli][roughset]") {
    // 18 conditions: c1 and c2 decide (d = c1 + c2 mod 3), c3 copies c1, c4..c18 are constant. The
    // reducts are {c1, c2} and {c2, c3}; QuickReduct breaks the tie by the lowest column.
    std::vector<std::string> header;
    for (int i = 1; i <= 18; ++i) header.push_back("c" + std::to_string(i));
    header.push_back("d");
    std::vector<std::vector<std::string>> rows;
    for (int p = 0; p < 3; ++p)
        for (int q = 0; q < 3; ++q) {
            std::vector<std::string> row{std::to_string(p), std::to_string(q), std::to_string(p)};
            for (int i = 4; i <= 18; ++i) row.push_back("k");
            row.push_back(std::to_string((p + q) % 3));
            rows.push_back(row);
        }
    pride::test::TempDir dir;
    const auto path = dir.write("wide.csv", csv_of(header, rows));

    const auto r = run_pride("roughset '" + path + "' --json");
    REQUIRE(r.status == 0);
    CHECK(r.err.empty());
    const JsonValue j = parse_json(r.out);
    CHECK(j.at("conditions").items.size() == 18);
    CHECK(j.at("exhaustive").kind == JsonValue::Kind::boolean);
    CHECK_FALSE(j.at("exhaustive").boolean);
    REQUIRE(j.at("reducts").items.size() == 1);
    CHECK(strings(j.at("reducts").items[0]) == std::vector<std::string>{"c1", "c2"});
    CHECK(strings(j.at("quick_reduct")) == std::vector<std::string>{"c1", "c2"});
    CHECK(strings(j.at("reduct_used")) == std::vector<std::string>{"c1", "c2"});
    CHECK(strings(j.at("core")) == std::vector<std::string>{"c2"});
    CHECK(j.at("consistent").boolean);
    CHECK(rule_strings(j.at("rules")).size() == 9);  // d needs both values of every row

    const auto human = run_pride("roughset '" + path + "'");
    REQUIRE(human.status == 0);
    const auto has = line_finder(human.out);
    CHECK(has("reducts: not searched exhaustively (18 condition attributes, the limit is 16)"));
    CHECK(has("  {c1, c2} (QuickReduct, greedy: a reduct, not necessarily a smallest one)"));
    CHECK(has("rules on {c1, c2} (the QuickReduct result): 9 minimal certain rules"));
    CHECK(has("  c1=0 and c2=0 -> d=0  [object 1]"));
}

TEST_CASE("cli roughset: an inconsistent table has certain rules for its positive region only", "[cli][roughset]") {
    pride::test::TempDir dir;
    // Objects 1 and 2 agree on a and b and differ on d: outside the positive region.
    const auto path = dir.write("inc.csv", "a,b,d\n0,0,x\n0,0,y\n1,0,x\n1,1,y\n");
    const auto r = run_pride("roughset '" + path + "' --json");
    REQUIRE(r.status == 0);
    const JsonValue j = parse_json(r.out);
    CHECK_FALSE(j.at("consistent").boolean);
    CHECK(j.at("rows").number == 4);
    CHECK(j.at("positive_region").number == 2);
    CHECK(j.at("dependency").number == 0.5);
    CHECK(strings(j.at("core")) == std::vector<std::string>{"a", "b"});
    CHECK(rule_strings(j.at("rules")) == std::vector<std::string>{"a=1 b=0 -> x (1)", "b=1 -> y (1)"});

    const auto human = run_pride("roughset '" + path + "'");
    REQUIRE(human.status == 0);
    const auto has = line_finder(human.out);
    CHECK(has("consistent: no"));
    CHECK(has("positive region: 2 of 4 objects (dependency 0.5)"));
    CHECK(
        has("rules on {a, b} (the only reduct): 2 minimal certain rules (none for the 2 objects outside the "
            "positive region)"));
    CHECK(has("  a=1 and b=0 -> d=x  [object 3]"));
    CHECK(has("  b=1 -> d=y          [object 4]"));
    CHECK(human.out.find("object 1") == std::string::npos);
    CHECK(human.out.find("object 2") == std::string::npos);
}

TEST_CASE("cli roughset: a table with an empty positive region has no rules, and says so", "[cli][roughset]") {
    pride::test::TempDir dir;
    const auto path = dir.write("none.csv", "a,d\n1,x\n1,y\n2,x\n2,y\n");
    const auto r = run_pride("roughset '" + path + "' --json");
    REQUIRE(r.status == 0);
    const JsonValue j = parse_json(r.out);
    CHECK_FALSE(j.at("consistent").boolean);
    CHECK(j.at("positive_region").number == 0);
    CHECK(j.at("dependency").number == 0);
    CHECK(strings(j.at("core")).empty());
    // The empty set keeps the (empty) positive region: it is the only reduct.
    REQUIRE(j.at("reducts").items.size() == 1);
    CHECK(strings(j.at("reducts").items[0]).empty());
    REQUIRE(j.at("rules").kind == JsonValue::Kind::array);  // computed, and there are none
    CHECK(j.at("rules").items.empty());
    CHECK_FALSE(j.has("rules_note"));

    const auto human = run_pride("roughset '" + path + "'");
    REQUIRE(human.status == 0);
    const auto has = line_finder(human.out);
    CHECK(has("positive region: 0 of 4 objects (dependency 0)"));
    CHECK(has("reducts: 1 (exhaustive over 1 condition attribute)"));
    CHECK(has("rules on {} (the only reduct): none (the positive region is empty: no object has a certain rule)"));
    CHECK(lines_of(human.out).back().starts_with("rules on {}"));
}

TEST_CASE("cli roughset: rules are not computed on a reduct of more than 16 attributes", "[cli][roughset]") {
    // Object 1 is all zeros with d = no; object i + 1 differs from it in c_i only, with d = yes. Every
    // attribute is indispensable, so the only reduct has all 17, over the limit of the rule search.
    std::vector<std::string> header;
    for (int i = 1; i <= 17; ++i) header.push_back("c" + std::to_string(i));
    header.push_back("d");
    std::vector<std::vector<std::string>> rows;
    rows.push_back(std::vector<std::string>(17, "0"));
    rows.back().push_back("no");
    for (int i = 0; i < 17; ++i) {
        rows.push_back(std::vector<std::string>(17, "0"));
        rows.back()[static_cast<std::size_t>(i)] = "1";
        rows.back().push_back("yes");
    }
    pride::test::TempDir dir;
    const auto path = dir.write("all.csv", csv_of(header, rows));
    const std::string note = "not computed: the reduct has 17 attributes, the limit is 16";

    const auto r = run_pride("roughset '" + path + "' --json");
    REQUIRE(r.status == 0);
    const JsonValue j = parse_json(r.out);
    CHECK_FALSE(j.at("exhaustive").boolean);
    CHECK(strings(j.at("core")).size() == 17);
    CHECK(strings(j.at("reduct_used")).size() == 17);
    CHECK(j.at("rules").kind == JsonValue::Kind::null);
    CHECK(j.at("rules_note").text == note);

    const auto human = run_pride("roughset '" + path + "'");
    REQUIRE(human.status == 0);
    CHECK(lines_of(human.out).back().ends_with("(the QuickReduct result): " + note));
}

TEST_CASE("cli roughset: rules are not computed past 2^28 value-subset steps", "[cli][roughset]") {
    // 16 binary attributes, every vector with at most five ones (6885 rows), d their parity: every
    // attribute is in the core, and 2^16 subsets x 6885 distinct rows is over 2^28.
    std::vector<std::string> header;
    for (int i = 1; i <= 16; ++i) header.push_back("x" + std::to_string(i));
    header.push_back("y");
    std::vector<std::vector<std::string>> rows;
    for (unsigned v = 0; v < (1u << 16); ++v) {
        const int ones = std::popcount(v);
        if (ones > 5) continue;
        std::vector<std::string> row;
        for (int i = 0; i < 16; ++i) row.push_back(v >> i & 1 ? "1" : "0");
        row.push_back(std::to_string(ones % 2));
        rows.push_back(std::move(row));
    }
    REQUIRE(rows.size() == 6885);
    pride::test::TempDir dir;
    const auto path = dir.write("parity.csv", csv_of(header, rows));
    const std::string note = "not computed: 2^16 value subsets x 6885 distinct rows is over the limit of 2^28";

    const auto r = run_pride("roughset '" + path + "' --json");
    REQUIRE(r.status == 0);
    const JsonValue j = parse_json(r.out);
    CHECK(j.at("exhaustive").boolean);
    REQUIRE(j.at("reducts").items.size() == 1);
    CHECK(strings(j.at("reducts").items[0]).size() == 16);
    CHECK(j.at("rules").kind == JsonValue::Kind::null);
    CHECK(j.at("rules_note").text == note);

    const auto human = run_pride("roughset '" + path + "'");
    REQUIRE(human.status == 0);
    CHECK(lines_of(human.out).back().ends_with("(the only reduct): " + note));
}

TEST_CASE("cli roughset: a single-valued decision gives one rule without conditions", "[cli][roughset]") {
    pride::test::TempDir dir;
    const auto path = dir.write("same.csv", "a,b,d\n1,p,x\n2,q,x\n3,p,x\n");
    const auto r = run_pride("roughset '" + path + "' --json");
    REQUIRE(r.status == 0);
    const JsonValue j = parse_json(r.out);
    CHECK(j.at("consistent").boolean);
    CHECK(strings(j.at("core")).empty());
    REQUIRE(j.at("reducts").items.size() == 1);
    CHECK(strings(j.at("reducts").items[0]).empty());
    REQUIRE(j.at("rules").items.size() == 1);
    const auto& rule = j.at("rules").items[0];
    CHECK(rule.at("if").kind == JsonValue::Kind::object);
    CHECK(rule.at("if").members.empty());
    CHECK(rule.at("then").text == "x");
    CHECK(rule.at("support").number == 3);
    CHECK(r.out.find("{\"if\": {}, \"then\": \"x\", \"support\": 3}") != std::string::npos);

    const auto human = run_pride("roughset '" + path + "'");
    REQUIRE(human.status == 0);
    const auto has = line_finder(human.out);
    CHECK(has("rules on {} (the only reduct): 1 minimal certain rule"));
    CHECK(has("  always -> d=x  [objects 1, 2, 3]"));
}

TEST_CASE("cli roughset: a blank-only field is reported where it starts", "[cli][roughset]") {
    pride::test::TempDir dir;
    const auto path = dir.write("blank.csv", "a,b,d\n1,  ,3\n");
    const auto r = run_pride("roughset '" + path + "'");
    CHECK(r.status == 2);
    CHECK(r.err.find(path + ":2:3: empty value in column 2") != std::string::npos);
}

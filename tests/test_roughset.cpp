// Tests of the rough-set module (roughset/): every result published for the reference
// tables of $PRIDE_DATA/roughset (its README.md), properties on random tables checked against brute
// force, and the CSV reader's edge cases and error messages.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "framework/error.hpp"
#include "framework/random.hpp"
#include "roughset/roughset.hpp"
#include "tests/test_support.hpp"

using namespace pride::roughset;

namespace {

/// Pawlak's published tables ($PRIDE_DATA/roughset), or nothing (the test then says it is skipped).
std::optional<DecisionTable> pawlak(const std::string& name) {
    const auto path = pride::test::shared_data("roughset/" + name, "Pawlak's decision tables");
    if (!path) return std::nullopt;
    return read_csv(path->string());
}
std::optional<DecisionTable> pawlak72() {
    return pawlak("pawlak1991_p72.csv");
}
std::optional<DecisionTable> pawlak8() {
    return pawlak("pawlak_8obj.csv");
}

// Column indices of the named attributes, sorted.
Attributes attrs(const DecisionTable& t, std::initializer_list<const char*> names) {
    Attributes out;
    for (auto n : names) {
        const auto a = t.find(n);
        REQUIRE(a.has_value());
        out.push_back(*a);
    }
    std::sort(out.begin(), out.end());
    return out;
}

// 1-based object numbers as in the README, to 0-based Objects.
Objects objs(std::initializer_list<std::size_t> one_based) {
    Objects out;
    for (auto o : one_based) out.push_back(o - 1);
    std::sort(out.begin(), out.end());
    return out;
}

std::set<Objects> as_set(const Classes& c) {
    return {c.begin(), c.end()};
}

// A table of `rows` random rows: `conditions` attributes with `card` values each, and a decision
// with `decisions` values that is a function of the first `relevant` attributes plus noise.
DecisionTable random_table(std::uint64_t seed, std::size_t rows, std::size_t conditions, int card, int decisions,
                           std::size_t relevant, double noise) {
    pride::Rng rng(seed);
    std::vector<std::string> names;
    for (std::size_t a = 0; a < conditions; ++a) names.push_back("c" + std::to_string(a));
    names.push_back("d");
    DecisionTable t(names);
    std::vector<int> row(conditions + 1);
    for (std::size_t r = 0; r < rows; ++r) {
        int sum = 0;
        for (std::size_t a = 0; a < conditions; ++a) {
            row[a] = static_cast<int>(rng.below(static_cast<std::uint64_t>(card)));
            if (a < relevant) sum = sum * 7 + row[a];
        }
        row[conditions] =
            rng.bernoulli(noise) ? static_cast<int>(rng.below(static_cast<std::uint64_t>(decisions))) : sum % decisions;
        t.add_row(row);
    }
    return t;
}

// Every subset of C (as masks) whose dependency equals gamma_C, by brute force through dependency().
std::vector<Attributes> brute_force_reducts(const DecisionTable& t, const Attributes& C, const Attributes& D) {
    const double full = dependency(t, C, D);
    std::vector<Attributes> keeping;
    for (std::uint64_t s = 0; s < (std::uint64_t{1} << C.size()); ++s) {
        Attributes R;
        for (std::size_t k = 0; k < C.size(); ++k)
            if (s >> k & 1) R.push_back(C[k]);
        if (dependency(t, R, D) == full) keeping.push_back(R);
    }
    std::vector<Attributes> minimal;
    for (const auto& R : keeping) {
        const bool has_smaller = std::any_of(keeping.begin(), keeping.end(), [&](const Attributes& Q) {
            return Q.size() < R.size() && std::includes(R.begin(), R.end(), Q.begin(), Q.end());
        });
        if (!has_smaller) minimal.push_back(R);
    }
    std::sort(minimal.begin(), minimal.end(), [](const Attributes& a, const Attributes& b) {
        return a.size() != b.size() ? a.size() < b.size() : a < b;
    });
    return minimal;
}

Attributes without(Attributes R, std::size_t a) {
    R.erase(std::find(R.begin(), R.end(), a));
    return R;
}

std::string error_of(std::string_view csv) {
    try {
        parse_csv(csv, "t.csv");
    } catch (const pride::InputError& e) {
        return e.what();
    }
    return "(no error)";
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Pawlak 1991, p. 72

TEST_CASE("roughset: pawlak1991_p72, c is dispensable, the only reduct is {a,b,d}", "[roughset]") {
    const auto table = pawlak72();
    if (!table) return;
    const auto& t = *table;
    REQUIRE(t.rows() == 7);
    REQUIRE(t.columns() == 5);
    const auto C = t.conditions(), D = t.decision();
    CHECK(D == attrs(t, {"e"}));
    CHECK(consistent(t, C, D));
    CHECK(dependency(t, attrs(t, {"a", "b", "d"}), D) == dependency(t, C, D));
    CHECK(dependency(t, attrs(t, {"a", "b", "c"}), D) < 1.0);
    CHECK(reducts(t, C, D) == std::vector<Attributes>{attrs(t, {"a", "b", "d"})});
}

TEST_CASE("roughset: pawlak1991_p72, the relative core is {a,b,d}", "[roughset]") {
    const auto table = pawlak72();
    if (!table) return;
    const auto& t = *table;
    CHECK(core(t, t.conditions(), t.decision()) == attrs(t, {"a", "b", "d"}));
}

TEST_CASE("roughset: pawlak1991_p72, the value cores per object", "[roughset]") {
    const auto table = pawlak72();
    if (!table) return;
    const auto& t = *table;
    const std::vector<Attributes> expected = {
        attrs(t, {"b"}), attrs(t, {"a"}), attrs(t, {"a"}), attrs(t, {"b", "d"}), attrs(t, {"d"}), {}, {}};
    // The same on the reduct (where Pawlak computes them) and on all four conditions.
    CHECK(value_cores(t, attrs(t, {"a", "b", "d"}), t.decision()) == expected);
    CHECK(value_cores(t, t.conditions(), t.decision()) == expected);
}

TEST_CASE("roughset: pawlak1991_p72, value cores are the intersections of the value reducts", "[roughset]") {
    const auto table = pawlak72();
    if (!table) return;
    const auto& t = *table;
    const auto B = attrs(t, {"a", "b", "d"});
    const auto cores = value_cores(t, B, t.decision());
    const auto reds = value_reducts(t, B, t.decision());
    REQUIRE(reds.size() == t.rows());
    for (std::size_t x = 0; x < t.rows(); ++x) {
        REQUIRE(!reds[x].empty());
        Attributes common = reds[x][0];
        for (const auto& r : reds[x]) {
            Attributes next;
            std::set_intersection(common.begin(), common.end(), r.begin(), r.end(), std::back_inserter(next));
            common = next;
        }
        CHECK(common == cores[x]);
    }
    // Object 1 (a=1, b=0, d=1, e=1): {a,b} or {b,d}; object 7: any single one of its values.
    CHECK(reds[0] == std::vector<Attributes>{attrs(t, {"a", "b"}), attrs(t, {"b", "d"})});
    CHECK(reds[6] == std::vector<Attributes>{attrs(t, {"a"}), attrs(t, {"b"}), attrs(t, {"d"})});
}

TEST_CASE("roughset: pawlak1991_p72, the minimal rules are those of Table 11", "[roughset]") {
    const auto table = pawlak72();
    if (!table) return;
    const auto& t = *table;
    const auto a = *t.find("a"), b = *t.find("b"), d = *t.find("d"), e = *t.find("e");
    const auto rules = minimal_rules(t, attrs(t, {"a", "b", "d"}), t.decision());
    auto code = [&](std::size_t col, const char* label) { return *t.code(col, label); };
    // a=1 and b=0 -> e=1; a=0 -> e=0; b=1 and d=1 -> e=0; d=2 -> e=2.
    std::set<std::pair<std::vector<Condition>, std::vector<int>>> expected = {
        {{{a, code(a, "1")}, {b, code(b, "0")}}, {code(e, "1")}},
        {{{a, code(a, "0")}}, {code(e, "0")}},
        {{{b, code(b, "1")}, {d, code(d, "1")}}, {code(e, "0")}},
        {{{d, code(d, "2")}}, {code(e, "2")}},
    };
    std::set<std::pair<std::vector<Condition>, std::vector<int>>> got;
    for (const auto& r : rules) got.insert({r.conditions, r.decision});
    CHECK(rules.size() == 4);
    CHECK(got == expected);
    // Ordered by support: objects {1,2}, {3}, {4}, {5,6,7}.
    REQUIRE(rules.size() == 4);
    CHECK(rules[0].support == objs({1, 2}));
    CHECK(rules[1].support == objs({3}));
    CHECK(rules[2].support == objs({4}));
    CHECK(rules[3].support == objs({5, 6, 7}));
    // The same rules from all four conditions (c never helps).
    std::set<std::pair<std::vector<Condition>, std::vector<int>>> from_all;
    for (const auto& r : minimal_rules(t, t.conditions(), t.decision())) from_all.insert({r.conditions, r.decision});
    CHECK(from_all == expected);
}

// ---------------------------------------------------------------------------------------------
// Pawlak's 8-object system

TEST_CASE("roughset: pawlak_8obj, absolute reduct and core of {a,b,c}", "[roughset]") {
    const auto table = pawlak8();
    if (!table) return;
    const auto& t = *table;
    const auto B = attrs(t, {"a", "b", "c"});
    CHECK(reducts(t, B, B) == std::vector<Attributes>{attrs(t, {"a", "b"})});
    CHECK(core(t, B, B) == attrs(t, {"a", "b"}));
    CHECK(quick_reduct(t, B, B) == attrs(t, {"a", "b"}));
    // c is dispensable: IND({a,b}) = IND({a,b,c}).
    CHECK(indiscernibility(t, attrs(t, {"a", "b"})) == indiscernibility(t, B));
}

TEST_CASE("roughset: pawlak_8obj, indiscernibility classes", "[roughset]") {
    const auto table = pawlak8();
    if (!table) return;
    const auto& t = *table;
    const auto a = indiscernibility(t, attrs(t, {"a"}));
    CHECK(as_set(a) == std::set<Objects>{objs({2, 8}), objs({1, 4, 5}), objs({3, 6, 7})});
    // Classes in the order of their first object.
    CHECK(a == Classes{objs({1, 4, 5}), objs({2, 8}), objs({3, 6, 7})});
    const auto abc = indiscernibility(t, attrs(t, {"a", "b", "c"}));
    CHECK(as_set(abc) == std::set<Objects>{objs({2, 8}), objs({7}), objs({3}), objs({1, 5}), objs({6}), objs({4})});
    CHECK(indiscernibility(t, {}) == Classes{all_objects(t)});
}

TEST_CASE("roughset: pawlak_8obj, approximations of X = {1,2,3,4,5}", "[roughset]") {
    const auto table = pawlak8();
    if (!table) return;
    const auto& t = *table;
    const auto B = attrs(t, {"a", "b", "c"});
    const auto X = objs({1, 2, 3, 4, 5});
    CHECK(lower_approximation(t, B, X) == objs({1, 3, 4, 5}));
    CHECK(upper_approximation(t, B, X) == objs({1, 2, 3, 4, 5, 8}));
    CHECK(boundary(t, B, X) == objs({2, 8}));
}

TEST_CASE("roughset: pawlak_8obj, {a,b,c} => {d,e} is inconsistent, POS = {3,4,6,7}", "[roughset]") {
    const auto table = pawlak8();
    if (!table) return;
    const auto& t = *table;
    const auto C = attrs(t, {"a", "b", "c"}), D = attrs(t, {"d", "e"});
    CHECK_FALSE(consistent(t, C, D));
    CHECK(positive_region(t, C, D) == objs({3, 4, 6, 7}));
    CHECK(dependency(t, C, D) == Approx(0.5));
    // The rules cover exactly the positive region and decide both d and e.
    std::set<std::size_t> covered;
    for (const auto& r : minimal_rules(t, C, D)) {
        CHECK(r.decision.size() == 2);
        covered.insert(r.support.begin(), r.support.end());
    }
    CHECK(Objects(covered.begin(), covered.end()) == objs({3, 4, 6, 7}));
}

// ---------------------------------------------------------------------------------------------
// Properties on random tables

TEST_CASE("roughset: reducts equal brute force and the core is their intersection", "[roughset]") {
    for (std::uint64_t seed = 1; seed <= 30; ++seed) {
        const std::size_t conds = 3 + seed % 6;
        const auto t = random_table(seed, 10 + 7 * seed, conds, 2 + static_cast<int>(seed % 3), 3, 1 + seed % 4,
                                    seed % 3 == 0 ? 0.2 : 0.0);
        const auto C = t.conditions(), D = t.decision();
        INFO("seed " << seed);
        const auto all = reducts(t, C, D);
        CHECK(all == brute_force_reducts(t, C, D));
        REQUIRE(!all.empty());
        Attributes common = all[0];
        for (const auto& r : all) {
            Attributes next;
            std::set_intersection(common.begin(), common.end(), r.begin(), r.end(), std::back_inserter(next));
            common = next;
        }
        CHECK(core(t, C, D) == common);
    }
}

TEST_CASE("roughset: every reduct keeps gamma_C and is minimal", "[roughset]") {
    for (std::uint64_t seed = 100; seed < 120; ++seed) {
        const auto t = random_table(seed, 60, 7, 3, 2, 3, seed % 2 ? 0.1 : 0.0);
        const auto C = t.conditions(), D = t.decision();
        const double gamma = dependency(t, C, D);
        INFO("seed " << seed);
        for (const auto& R : reducts(t, C, D)) {
            CHECK(std::is_sorted(R.begin(), R.end()));
            CHECK(dependency(t, R, D) == gamma);
            for (auto a : R) CHECK(dependency(t, without(R, a), D) < gamma);
        }
    }
}

TEST_CASE("roughset: quick_reduct is a reduct with full dependency", "[roughset]") {
    for (std::uint64_t seed = 200; seed < 230; ++seed) {
        const auto t = random_table(seed, 80, 9, 3, 3, 2 + seed % 3, seed % 4 == 0 ? 0.15 : 0.0);
        const auto C = t.conditions(), D = t.decision();
        const double gamma = dependency(t, C, D);
        INFO("seed " << seed);
        const auto q = quick_reduct(t, C, D);
        CHECK(std::is_sorted(q.begin(), q.end()));
        CHECK(dependency(t, q, D) == gamma);
        for (auto a : q) CHECK(dependency(t, without(q, a), D) < gamma);  // no attribute to spare
        const auto all = reducts(t, C, D);
        CHECK(std::find(all.begin(), all.end(), q) != all.end());
    }
}

TEST_CASE("roughset: more than 16 conditions, reducts() refuses and quick_reduct works", "[roughset]") {
    const auto t = random_table(7, 300, 20, 3, 2, 3, 0.0);
    const auto C = t.conditions(), D = t.decision();
    CHECK_THROWS_AS(reducts(t, C, D), pride::InputError);
    CHECK_THROWS_WITH(reducts(t, C, D), Catch::Contains("20 attributes") && Catch::Contains("at most 16"));
    const auto q = quick_reduct(t, C, D);
    CHECK(dependency(t, q, D) == dependency(t, C, D));
    for (auto a : q) CHECK(dependency(t, without(q, a), D) < dependency(t, C, D));
    CHECK(core(t, C, D).size() <= q.size());
}

TEST_CASE("roughset: minimal rules are consistent, minimal and cover the positive region", "[roughset]") {
    for (std::uint64_t seed = 300; seed < 325; ++seed) {
        const auto t = random_table(seed, 50 + seed % 50, 5, 3, 3, 2 + seed % 2, seed % 3 == 0 ? 0.2 : 0.0);
        const auto C = t.conditions(), D = t.decision();
        INFO("seed " << seed);
        const auto pos = positive_region(t, C, D);
        std::set<std::size_t> covered;
        for (const auto& r : minimal_rules(t, C, D)) {
            Objects matched;
            for (std::size_t x = 0; x < t.rows(); ++x)
                if (matches(t, r, x)) matched.push_back(x);
            CHECK(matched == r.support);
            for (auto x : matched) {
                CHECK(t.value(x, D[0]) == r.decision[0]);  // consistent: a certain rule
                CHECK(std::binary_search(pos.begin(), pos.end(), x));
            }
            for (std::size_t i = 0; i < r.conditions.size(); ++i) {  // no condition to spare
                Rule shorter = r;
                shorter.conditions.erase(shorter.conditions.begin() + static_cast<std::ptrdiff_t>(i));
                bool inconsistent = false;
                for (std::size_t x = 0; x < t.rows(); ++x)
                    if (matches(t, shorter, x) && t.value(x, D[0]) != r.decision[0]) inconsistent = true;
                CHECK(inconsistent);
            }
            covered.insert(matched.begin(), matched.end());
        }
        CHECK(Objects(covered.begin(), covered.end()) == pos);
    }
}

TEST_CASE("roughset: everything is deterministic and duplicate rows change no rule", "[roughset]") {
    const auto t = random_table(42, 120, 6, 3, 3, 3, 0.05);
    const auto C = t.conditions(), D = t.decision();
    const auto r1 = minimal_rules(t, C, D), r2 = minimal_rules(t, C, D);
    REQUIRE(r1.size() == r2.size());
    for (std::size_t i = 0; i < r1.size(); ++i) {
        CHECK(r1[i].conditions == r2[i].conditions);
        CHECK(r1[i].support == r2[i].support);
    }
    // Doubling every row doubles the supports and keeps the conditions.
    DecisionTable twice(t.names());
    for (int k = 0; k < 2; ++k)
        for (std::size_t x = 0; x < t.rows(); ++x) twice.add_row(t.row(x));
    const auto r3 = minimal_rules(twice, C, D);
    REQUIRE(r3.size() == r1.size());
    for (std::size_t i = 0; i < r1.size(); ++i) {
        CHECK(r3[i].conditions == r1[i].conditions);
        CHECK(r3[i].support.size() == 2 * r1[i].support.size());
    }
}

TEST_CASE("roughset: 10^5 rows and 16 conditions, every state of 8 three-valued attributes", "[roughset]") {
    // Behaviour only: how long these take is for the benchmarks to report, not for a test to assert.
    {
        const auto t = random_table(5, 100000, 16, 3, 4, 3, 0.0);
        const auto all = reducts(t, t.conditions(), t.decision());
        const auto rules = minimal_rules(t, all.at(0), t.decision());
        CHECK(all == std::vector<Attributes>{{0, 1, 2}});
        CHECK(rules.size() <= 27);
    }
    {
        // Every state of 8 three-valued attributes, the decision a function of five of them.
        DecisionTable t({"X1", "X2", "X3", "X4", "X5", "X6", "X7", "X8", "Y"});
        std::vector<int> row(9);
        for (int s = 0; s < 6561; ++s) {
            int v = s;
            for (int a = 0; a < 8; ++a, v /= 3) row[static_cast<std::size_t>(a)] = 1 + v % 3;
            int y = 0;
            for (int a : {0, 1, 7, 2, 6}) {
                if (row[static_cast<std::size_t>(a)] == 3) {
                    y = a + 1;
                    break;
                }
            }
            row[8] = y;
            t.add_row(row);
        }
        const auto all = reducts(t, t.conditions(), t.decision());
        const auto rules = minimal_rules(t, all.at(0), t.decision());
        CHECK(all == std::vector<Attributes>{{0, 1, 2, 6, 7}});
        // Y = 1 needs X1=3 only; Y = 2 needs X1 in {1,2} (two rules) and X2=3; ...; Y = 0 all five in {1,2}.
        CHECK(rules.size() == 1 + 2 + 4 + 8 + 16 + 32);
    }
}

TEST_CASE("roughset: a constant attribute after 64 bits of packed codes changes nothing", "[roughset]") {
    // Eight attributes with 129..248 values each take 8 bits apiece in the packed row keys, 64 in all;
    // the constant column after them takes none (a shift by 64 would be undefined behaviour). The
    // constant is dispensable: every result equals the one on the table without it.
    constexpr std::size_t n = 8, rows = 300;
    std::vector<std::string> with_names, without_names;
    for (std::size_t a = 0; a < n; ++a) {
        with_names.push_back("c" + std::to_string(a));
        without_names.push_back("c" + std::to_string(a));
    }
    with_names.push_back("constant");
    with_names.push_back("d");
    without_names.push_back("d");
    DecisionTable with(with_names), without(without_names);
    std::vector<int> w(n + 2), wo(n + 1);
    std::vector<std::size_t> card(n);
    for (std::size_t a = 0; a < n; ++a) card[a] = 129 + 17 * a;             // 129..248 values: 8 bits each
    const std::size_t prime[n] = {257, 263, 269, 271, 277, 281, 283, 293};  // each prime to every card
    for (std::size_t r = 0; r < rows + 1; ++r) {
        const std::size_t x = r < rows ? r : 0;  // the last row repeats row 0 with another decision
        for (std::size_t a = 0; a < n; ++a) {
            w[a] = wo[a] = static_cast<int>((x * prime[a] + a) % card[a]);  // all card[a] values: x runs over 0..299
        }
        w[n] = 42;
        const int d = static_cast<int>((w[0] + 2 * w[1] + w[3] / 50) % 3);
        w[n + 1] = wo[n] = r < rows ? d : (d + 1) % 3;
        with.add_row(w);
        without.add_row(wo);
    }
    for (std::size_t a = 0; a < n; ++a) REQUIRE(indiscernibility(with, {a}).size() == card[a]);
    REQUIRE(indiscernibility(with, {n}).size() == 1);
    const Attributes C = with.conditions(), C0 = without.conditions();
    REQUIRE(C.size() == n + 1);
    const Attributes D = with.decision(), D0 = without.decision();

    const auto pos = positive_region(with, C, D);
    CHECK(pos == positive_region(without, C0, D0));
    CHECK(pos.size() == rows - 1);  // objects 0 and 300 conflict
    CHECK(core(with, C, D) == core(without, C0, D0));
    const auto all = reducts(with, C, D);
    CHECK(all == reducts(without, C0, D0));
    CHECK(all.size() > 1);
    for (const auto& R : all) CHECK(std::find(R.begin(), R.end(), n) == R.end());
    CHECK(quick_reduct(with, C, D) == quick_reduct(without, C0, D0));
    CHECK(value_reducts(with, C, D) == value_reducts(without, C0, D0));
    const auto r1 = minimal_rules(with, C, D), r0 = minimal_rules(without, C0, D0);
    REQUIRE(r1.size() == r0.size());
    for (std::size_t i = 0; i < r1.size(); ++i) {
        CHECK(r1[i].conditions == r0[i].conditions);
        CHECK(r1[i].decision == r0[i].decision);
        CHECK(r1[i].support == r0[i].support);
    }
}

// ---------------------------------------------------------------------------------------------
// Decision tables and CSV

TEST_CASE("roughset: decision table codes, labels and names", "[roughset]") {
    DecisionTable t({"colour", "size", "class"});
    const std::vector<std::string> r1{"red", "big", "yes"}, r2{"blue", "big", "no"}, r3{"red", "small", "no"};
    t.add_row_labels(r1);
    t.add_row_labels(r2);
    t.add_row_labels(r3);
    CHECK(t.rows() == 3);
    CHECK(t.columns() == 3);
    CHECK(t.value(0, 0) == 0);
    CHECK(t.value(1, 0) == 1);
    CHECK(t.value(2, 0) == 0);
    CHECK(t.label(0, 1) == "blue");
    CHECK(t.label(2, t.value(2, 2)) == "no");
    CHECK(t.conditions() == Attributes{0, 1});
    CHECK(t.decision() == Attributes{2});
    CHECK(t.find("size") == std::optional<std::size_t>{1});
    CHECK_FALSE(t.find("weight").has_value());
    DecisionTable n({"x", "y"});
    const std::vector<int> codes{7, -2};
    n.add_row(codes);
    CHECK(n.label(0, 7) == "7");
    CHECK(n.label(1, -2) == "-2");
    CHECK_THROWS_AS(DecisionTable({"only"}), pride::InputError);
    CHECK_THROWS_AS(DecisionTable({"x", "x"}), pride::InputError);
    const std::vector<int> short_row{1};
    CHECK_THROWS_AS(n.add_row(short_row), pride::InputError);
    CHECK_THROWS_AS(indiscernibility(n, {5}), pride::InputError);
}

TEST_CASE("roughset: CSV quoting, CRLF, BOM, blanks and blank lines", "[roughset]") {
    const std::string csv =
        "\xEF\xBB\xBF"
        "name , \"size, in cm\",\"class\"\r\n"
        "\r\n"
        "  \"say \"\"hi\"\"\" ,  12 , yes\r\n"
        "   \n"
        "\"two\nlines\",12,\"no\"\n"
        "x,\"\",maybe";
    const std::string bad_empty = error_of(csv);
    CHECK(bad_empty == "t.csv:7:3: empty value in column 2");
    const auto t = parse_csv(csv.substr(0, csv.rfind('x')), "t.csv");
    REQUIRE(t.columns() == 3);
    CHECK(t.name(0) == "name");
    CHECK(t.name(1) == "size, in cm");
    CHECK(t.name(2) == "class");
    REQUIRE(t.rows() == 2);
    CHECK(t.label(0, t.value(0, 0)) == "say \"hi\"");
    CHECK(t.label(0, t.value(1, 0)) == "two\nlines");
    CHECK(t.label(1, t.value(0, 1)) == "12");
    CHECK(t.value(0, 1) == t.value(1, 1));
    CHECK(t.label(2, t.value(1, 2)) == "no");
    // Values are coded per column in order of first appearance.
    const auto u = parse_csv("a,b\nz,1\ny,1\nz,0\n", "u.csv");
    CHECK(u.value(0, 0) == 0);
    CHECK(u.value(1, 0) == 1);
    CHECK(u.value(2, 0) == 0);
    CHECK(u.value(2, 1) == 1);
    // A last line without its line end, and a lone CR.
    CHECK(parse_csv("a,b\r1,2", "v.csv").rows() == 1);
}

TEST_CASE("roughset: CSV error messages name file, line and column", "[roughset]") {
    CHECK(error_of("") == "t.csv:1:1: empty file (expected a header line naming the columns)");
    CHECK(error_of("\n  \n\r\n") == "t.csv:1:1: empty file (expected a header line naming the columns)");
    CHECK(error_of("\n a\n1\n") ==
          "t.csv:2:2: the header has 1 column, need at least 2 (conditions, then the decision)");
    CHECK(error_of("a,,c\n1,2,3\n") == "t.csv:1:3: empty column name (column 2)");
    CHECK(error_of("a,b,a\n1,2,3\n") == "t.csv:1:5: duplicate column name (columns 1 and 3)");
    CHECK(error_of("a,b,c\n1,2,3\n1,2\n") == "t.csv:3:4: row has 2 fields, expected 3");
    CHECK(error_of("a,b,c\n1,2,3\n1,2,3,4\n") == "t.csv:3:7: row has 4 fields, expected 3");
    CHECK(error_of("a,b\n1,\n") == "t.csv:2:3: empty value in column 2");
    // A blank-only field is reported where it starts, not at the comma or line end after it.
    CHECK(error_of("a,b,d\n1,  ,3\n") == "t.csv:2:3: empty value in column 2");
    CHECK(error_of("a,b\n1, \t\n") == "t.csv:2:3: empty value in column 2");
    CHECK(error_of("a,b\n  ,1\n") == "t.csv:2:1: empty value in column 1");
    CHECK(error_of("a,  ,c\n1,2,3\n") == "t.csv:1:3: empty column name (column 2)");
    CHECK(error_of("a,b\n1,  \"\"\n") == "t.csv:2:5: empty value in column 2");  // quoted: at the quote
    CHECK(error_of("a,b\n1, \"x\n") == "t.csv:2:4: unterminated quote");
    CHECK(error_of("a,b\n") == "t.csv:2:1: no data rows after the header");
    CHECK(error_of("a,b\n\"x\"y,1\n") == "t.csv:2:4: unexpected character after a closing quote");
    CHECK(error_of("a,b\nx\"y,1\n") == "t.csv:2:2: quote inside an unquoted field (quote the whole field)");
    CHECK(error_of("a,b\n1,2\n\xC3\xA9,2,3\n") ==
          "t.csv:3:5: row has 3 fields, expected 2");  // columns count characters
    CHECK_THROWS_WITH(read_csv("/nonexistent/x.csv"), Catch::StartsWith("/nonexistent/x.csv: cannot open"));
}

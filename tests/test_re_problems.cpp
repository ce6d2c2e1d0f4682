// Tanabe and Ishibuchi's (2020) RE and CRE problems (problems/multiobjective/re/) against their
// official code: the objectives, the constraint values and the violation at 20 points per problem,
// as tests/data/re/re_official.tsv holds them (its header says how they were made), the boxes, the
// catalog, the errors; and the published fronts ($PRIDE_DATA/re-fronts).
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <span>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "framework/constraints.hpp"
#include "framework/error.hpp"
#include "framework/multi_objective.hpp"
#include "framework/problem.hpp"
#include "problems/multiobjective/re/fronts.hpp"
#include "problems/multiobjective/re/re.hpp"
#include "tests/test_support.hpp"

namespace re_problems_test {

namespace re = pride::multiobjective::re;
using pride::Matrix;
using pride::test::input_error_message;

static_assert(pride::ConstrainedMultiObjectiveProblem<re::Problem>);
static_assert(pride::Reseedable<re::Problem>);
static_assert(pride::BatchMultiObjectiveProblem<re::Problem>);
static_assert(std::is_nothrow_copy_constructible_v<re::Problem>);

struct Row {
    std::string name;  // lower case, as the catalog
    int k = 0;
    std::size_t n = 0, m_obj = 0, m_con = 0;
    std::vector<double> x, f, g, xi;  // g: the code's sign (>= 0 feasible); xi: RE91's draws
    double violation = 0.0;
};

struct Reference {
    std::vector<Row> rows;
    std::map<std::string, std::vector<double>> lower, upper;
};

std::string lower_case(std::string s) {
    for (char& ch : s)
        if (ch >= 'A' && ch <= 'Z') ch = static_cast<char>(ch - 'A' + 'a');
    return s;
}

const Reference& reference() {
    static const Reference ref = [] {
        Reference r;
        std::ifstream in(std::string(PRIDE_SOURCE_DIR) + "/tests/data/re/re_official.tsv");
        REQUIRE(in.good());
        std::string line;
        while (std::getline(in, line)) {
            if (line.empty() || line[0] == '#') continue;
            std::istringstream ls(line);
            std::string name, second;
            ls >> name >> second;
            name = lower_case(name);
            if (second == "lower" || second == "upper") {
                auto& v = (second == "lower" ? r.lower : r.upper)[name];
                for (double d; ls >> d;) v.push_back(d);
                continue;
            }
            Row row;
            row.name = name;
            row.k = std::stoi(second);
            ls >> row.n >> row.m_obj >> row.m_con;
            const auto read = [&](std::vector<double>& v, std::size_t count) {
                v.resize(count);
                for (auto& d : v) ls >> d;
            };
            read(row.x, row.n);
            read(row.f, row.m_obj);
            read(row.g, row.m_con);
            if (row.m_con > 0) ls >> row.violation;
            if (name == "re91") read(row.xi, 4);
            REQUIRE(!ls.fail());
            r.rows.push_back(std::move(row));
        }
        return r;
    }();
    return ref;
}

/// a and b hold the same doubles, bit for bit (+0 and -0 apart; NaN never appears here).
bool same_bits(double a, double b) {
    return a == b && std::signbit(a) == std::signbit(b);
}

TEST_CASE("re problems: every problem gives the official code's values, bit for bit", "[re]") {
    const auto& ref = reference();
    REQUIRE(ref.rows.size() == 24 * 20);
    std::set<std::string> seen;
    for (const auto& row : ref.rows) {
        INFO(row.name << " point " << row.k);
        seen.insert(row.name);
        re::Problem p(row.name);
        REQUIRE(p.dimension() == row.n);
        REQUIRE(p.objectives() == row.m_obj);
        REQUIRE(p.constraint_counts() == pride::ConstraintCounts{row.m_con, 0});
        std::vector<double> f(row.m_obj, -1.0), c(row.m_con, -1.0);
        if (row.name == "re91") {
            // The code's draws given: the formula is deterministic.
            re::formulas::re91(row.x.data(), row.xi.data(), f.data());
            for (std::size_t i = 0; i < f.size(); ++i) CHECK(same_bits(f[i], row.f[i]));
            continue;
        }
        p.evaluate_constrained(row.x, f, c);
        for (std::size_t i = 0; i < f.size(); ++i) CHECK(same_bits(f[i], row.f[i]));
        // pride's inequality values are the negated code's (>= 0 feasible there, <= 0 here).
        for (std::size_t i = 0; i < c.size(); ++i) CHECK(same_bits(c[i], -row.g[i]));
        CHECK(same_bits(p.violation(c), row.violation));
        // evaluate() alone gives the same objectives.
        std::vector<double> f2(row.m_obj, -1.0);
        p.evaluate(row.x, f2);
        for (std::size_t i = 0; i < f.size(); ++i) CHECK(same_bits(f2[i], row.f[i]));
    }
    CHECK(seen.size() == 24);
    // Both feasible and infeasible points are among the CRE rows, so both sides of the fold are checked.
    std::size_t feasible = 0, infeasible = 0;
    for (const auto& row : ref.rows)
        if (row.m_con > 0) (row.violation == 0.0 ? feasible : infeasible) += 1;
    CHECK(feasible > 0);
    CHECK(infeasible > 0);
}

TEST_CASE("re problems: a batch gives each point's values", "[re]") {
    const auto& ref = reference();
    for (const std::string name : {"re42", "cre24", "re91"}) {
        INFO(name);
        std::vector<const Row*> rows;
        for (const auto& row : ref.rows)
            if (row.name == name) rows.push_back(&row);
        REQUIRE(rows.size() == 20);
        re::Problem p(name), q(name);
        Matrix points(static_cast<Eigen::Index>(p.dimension()), 20),
            values(static_cast<Eigen::Index>(p.objectives()), 20);
        for (Eigen::Index j = 0; j < 20; ++j)
            for (std::size_t i = 0; i < p.dimension(); ++i) points(static_cast<Eigen::Index>(i), j) = rows[j]->x[i];
        p.evaluate_batch(points, values);
        std::vector<double> f(p.objectives());
        for (Eigen::Index j = 0; j < 20; ++j) {
            q.evaluate(rows[j]->x, f);  // RE91: q draws as p did, one point after the other
            for (std::size_t i = 0; i < f.size(); ++i) CHECK(same_bits(values(static_cast<Eigen::Index>(i), j), f[i]));
        }
    }
}

TEST_CASE("re problems: the boxes are the code's", "[re]") {
    const auto& ref = reference();
    REQUIRE(ref.lower.size() == 24);
    for (const auto& e : re::kCatalog) {
        INFO(e.name);
        const re::Problem p(e.name);
        const auto& lo = ref.lower.at(std::string(e.name));
        const auto& hi = ref.upper.at(std::string(e.name));
        REQUIRE(p.lower().size() == lo.size());
        REQUIRE(p.upper().size() == hi.size());
        for (std::size_t i = 0; i < lo.size(); ++i) {
            CHECK(same_bits(p.lower()[i], lo[i]));
            CHECK(same_bits(p.upper()[i], hi[i]));
            CHECK(p.lower()[i] < p.upper()[i]);
        }
    }
}

TEST_CASE("re problems: RE91 draws its random parameters from its own seeded generator", "[re]") {
    re::Problem a("re91");
    CHECK(a.noisy());
    CHECK_FALSE(re::Problem("re41").noisy());
    const std::vector<double> x{1.0, 0.9, 1.0, 1.0, 1.7, 0.8, 0.8};
    std::vector<double> fa(9), fb(9), fc(9);
    a.reseed(7);
    re::Problem b = a;  // a copy continues the same stream
    a.evaluate(x, fa);
    b.evaluate(x, fb);
    for (std::size_t i = 0; i < 9; ++i) CHECK(same_bits(fa[i], fb[i]));
    a.evaluate(x, fc);  // the next draws: another value
    bool differs = false;
    for (std::size_t i = 1; i < 9; ++i) differs = differs || fc[i] != fa[i];
    CHECK(differs);
    CHECK(same_bits(fc[0], fa[0]));  // f1 has no random parameter
    for (double v : fa) CHECK((std::isfinite(v) && v >= 0.0));
    // The same seed again: the same values.
    a.reseed(7);
    a.evaluate(x, fc);
    for (std::size_t i = 0; i < 9; ++i) CHECK(same_bits(fc[i], fa[i]));
    // f1 is the same whatever the draws, e.g. at their means.
    const double means[4] = {0.345, 0.192, 0.0, 0.0};
    std::vector<double> fm(9);
    re::formulas::re91(x.data(), means, fm.data());
    CHECK(same_bits(fm[0], fa[0]));
}

TEST_CASE("re problems: the catalog", "[re]") {
    REQUIRE(re::kCatalog.size() == 24);
    std::set<std::string_view> names;
    std::size_t constrained = 0;
    for (const auto& e : re::kCatalog) {
        INFO(e.name);
        names.insert(e.name);
        // The paper's names: RE<M>-<n>-<k>, CRE<M>-<n>-<k>.
        const bool cre = e.name.starts_with("cre");
        const std::string expected =
            (cre ? "CRE" : "RE") + std::to_string(e.objectives) + "-" + std::to_string(e.variables) + "-";
        CHECK(e.summary.substr(0, expected.size()) == expected);
        CHECK((cre ? e.constraints > 0 : e.constraints == 0));
        constrained += cre ? 1 : 0;
        CHECK(e.variables <= re::kMostVariables);
        CHECK(e.objectives <= re::kMostObjectives);
        CHECK(e.constraints <= re::kMostConstraints);
        const re::Problem p(e.name);
        CHECK(p.name() == e.name);
        CHECK(p.dimension() == e.variables);
        CHECK(p.objectives() == e.objectives);
        CHECK(p.constraint_counts().inequalities == e.constraints);
        CHECK(p.constraint_counts().equalities == 0);
        CHECK(re::find_problem(e.name) == &e);
    }
    CHECK(names.size() == 24);
    CHECK(constrained == 8);
    // The sizes of the paper's Table 1 (n, M) and of the code's constraints.
    const std::map<std::string_view, std::array<std::size_t, 3>> table{
        {"re21", {4, 2, 0}},  {"re22", {3, 2, 0}},   {"re23", {4, 2, 0}},  {"re24", {2, 2, 0}},  {"re25", {3, 2, 0}},
        {"re31", {3, 3, 0}},  {"re32", {4, 3, 0}},   {"re33", {4, 3, 0}},  {"re34", {5, 3, 0}},  {"re35", {7, 3, 0}},
        {"re36", {4, 3, 0}},  {"re37", {4, 3, 0}},   {"re41", {7, 4, 0}},  {"re42", {6, 4, 0}},  {"re61", {3, 6, 0}},
        {"re91", {7, 9, 0}},  {"cre21", {3, 2, 3}},  {"cre22", {4, 2, 4}}, {"cre23", {4, 2, 4}}, {"cre24", {7, 2, 11}},
        {"cre25", {4, 2, 1}}, {"cre31", {7, 3, 10}}, {"cre32", {6, 3, 9}}, {"cre51", {3, 5, 7}},
    };
    for (const auto& [name, sizes] : table) {
        INFO(name);
        const auto* e = re::find_problem(name);
        REQUIRE(e != nullptr);
        CHECK(e->variables == sizes[0]);
        CHECK(e->objectives == sizes[1]);
        CHECK(e->constraints == sizes[2]);
    }
    CHECK(re::find_problem("RE21") == nullptr);  // names are lower case
}

TEST_CASE("re problems: an unknown name is an InputError listing the names", "[re][errors]") {
    const std::string message = input_error_message([] { (void)re::Problem("re26"); });
    CHECK(message.rfind("problem: unknown RE problem 're26' (known: re21, re22, ", 0) == 0);
    CHECK(message.find("re91, cre21, ") != std::string::npos);
    CHECK(message.find("cre51)") != std::string::npos);
    CHECK(message.find('\n') == std::string::npos);
    CHECK_THAT(input_error_message([] { (void)re::Problem("RE21", "--problem"); }),
               Catch::Matchers::StartsWith("--problem: unknown RE problem 'RE21'"));
    CHECK_THAT(input_error_message([] { (void)re::Problem(""); }),
               Catch::Matchers::StartsWith("problem: unknown RE problem ''"));
}

TEST_CASE("re problems: the code's quirks", "[re]") {
    std::vector<double> f(3);
    SECTION("RE22's x1 is snapped to its list, whose '3,10' is 3 and 10") {
        re::Problem p("re22");
        std::vector<double> f2(2);
        p.evaluate(std::vector<double>{9.9, 10.0, 20.0}, f2);  // nearest: 10 (9.48 and 10.27 are farther)
        CHECK(same_bits(f2[0], (29.4 * 10.0) + (0.6 * 10.0 * 20.0)));
        p.evaluate(std::vector<double>{3.1, 10.0, 20.0}, f2);  // 3.08, not 3.10
        CHECK(same_bits(f2[0], (29.4 * 3.08) + (0.6 * 10.0 * 20.0)));
    }
    SECTION("rounding is C's: halves away from 0") {
        re::Problem p("re36");
        p.evaluate(std::vector<double>{12.5, 12.5, 12.5, 59.5}, f);
        CHECK(f[1] == 60.0);  // the largest, 59.5 rounded up
        CHECK(same_bits(f[0], std::fabs(6.931 - ((13.0 / 13.0) * (60.0 / 13.0)))));
    }
    SECTION("the folded objective counts a NaN constraint as satisfied, the violation as infinite") {
        // At x1 = x2 the disc brake divides 0 by 0: g3 and g4 are NaN, g2 is -inf.
        const std::vector<double> x{77.0, 77.0, 2000.0, 15.0};
        re::Problem folded("re33");
        folded.evaluate(x, f);
        CHECK(std::isnan(f[1]));
        CHECK(f[2] == std::numeric_limits<double>::infinity());  // fold(g1) = 20, fold(-inf) = inf, NaN: 0
        CHECK(re::formulas::fold(std::nan("")) == 0.0);
        re::Problem p("cre23");
        std::vector<double> f2(2), c(4);
        p.evaluate_constrained(x, f2, c);
        CHECK(c[0] == 20.0);
        CHECK(c[1] == std::numeric_limits<double>::infinity());
        CHECK(std::isnan(c[2]));
        CHECK(std::isnan(c[3]));
        CHECK(p.violation(c) == std::numeric_limits<double>::infinity());
        const std::vector<double> one_nan{std::nan("")};
        CHECK(re::Problem("cre25").violation(one_nan) == std::numeric_limits<double>::infinity());
    }
    SECTION("the violation is the sum of the positive values; an RE problem has none") {
        re::Problem p("cre25");
        CHECK(p.violation(std::vector<double>{-3.0}) == 0.0);
        CHECK(p.violation(std::vector<double>{0.25}) == 0.25);
        re::Problem q("cre21");
        CHECK(q.violation(std::vector<double>{0.5, -1.0, 0.25}) == 0.75);
        re::Problem r("re21");
        CHECK(r.violation(std::vector<double>{}) == 0.0);
        std::vector<double> c(1, 42.0), f2(2);
        r.evaluate_constrained(std::vector<double>{2.0, 2.0, 2.0, 2.0}, f2, std::span<double>(c.data(), 0));
        CHECK(c[0] == 42.0);  // nothing written
    }
}

// ---------------------------------------------------------------------------------------------
// The published fronts ($PRIDE_DATA/re-fronts, its README.md: source and commit).

/// How many columns of `front` another column dominates (all objectives minimised).
std::size_t dominated_count(const Matrix& front) {
    std::size_t count = 0;
    for (Eigen::Index j = 0; j < front.cols(); ++j) {
        for (Eigen::Index k = 0; k < front.cols(); ++k) {
            if (k == j) continue;
            const bool no_worse = (front.col(k).array() <= front.col(j).array()).all();
            const bool better = (front.col(k).array() < front.col(j).array()).any();
            if (no_worse && better) {
                ++count;
                break;
            }
        }
    }
    return count;
}

TEST_CASE("re problems: the published fronts read, are non-dominated and span their ideal points", "[re][fronts]") {
    const auto folder = pride::test::shared_data("re-fronts", "the RE suite's approximated Pareto fronts");
    if (!folder) return;
    // The number of points of each file.
    const std::map<std::string, Eigen::Index> sizes{{"re21", 1000}, {"re22", 1000}, {"re23", 1000}, {"re24", 1000},
                                                    {"re25", 1000}, {"re31", 1500}, {"re32", 1500}, {"re33", 1500},
                                                    {"re34", 1500}, {"re35", 1500}, {"re36", 28},   {"re37", 1500},
                                                    {"re41", 2000}, {"re42", 1999}, {"re61", 2999}, {"re91", 4500}};
    // The ideal files are the fronts' minima to the 9 digits the fronts are printed with (1e-7 of
    // each objective's range), but for RE34 (1.2e-7), RE41 (2.2e-6) and RE91 (5.9e-5), whose ideal
    // points lie below their fronts' minima (from other points). The nadir files are the fronts' maxima only
    // for these six problems; for the other ten they differ by up to the whole range, either way
    // (RE21's nadir file is not its front's maximum, which its bug_ file is).
    const std::set<std::string> nadir_is_max{"re22", "re23", "re24", "re25", "re31", "re34"};
    for (const auto& e : re::kCatalog) {
        if (e.constraints > 0) continue;
        const std::string name(e.name);
        INFO(name);
        const Matrix front = re::read_re_front(*folder, name);
        REQUIRE(front.rows() == static_cast<Eigen::Index>(e.objectives));
        CHECK(front.cols() == sizes.at(name));
        CHECK(dominated_count(front) == 0);
        const std::vector<double> ideal = re::read_re_ideal(*folder, name);
        const std::vector<double> nadir = re::read_re_nadir(*folder, name);
        REQUIRE(ideal.size() == e.objectives);
        REQUIRE(nadir.size() == e.objectives);
        const double ideal_tolerance = name == "re34" ? 3e-7 : name == "re41" ? 5e-6 : name == "re91" ? 1e-4 : 1e-7;
        bool nadir_matches = true;
        for (std::size_t i = 0; i < e.objectives; ++i) {
            const auto row = front.row(static_cast<Eigen::Index>(i));
            const double lo = row.minCoeff(), hi = row.maxCoeff(), range = hi - lo;
            REQUIRE(range > 0.0);
            CHECK(std::abs(lo - ideal[i]) <= ideal_tolerance * range);
            nadir_matches = nadir_matches && std::abs(hi - nadir[i]) <= 1e-6 * range;
        }
        CHECK(nadir_matches == (nadir_is_max.count(name) == 1));
    }
}

TEST_CASE("re problems: the front reader's errors name the file and line", "[re][fronts][errors]") {
    pride::test::TempDir dir("pride-re-fronts");
    std::filesystem::create_directory(dir.path() / "ideal_nadir");
    dir.write("reference_points_RE21.dat", "1.0 2.0\n\n3 4\n");
    const Matrix ok = re::read_re_front(dir.path(), "re21");
    REQUIRE(ok.rows() == 2);
    REQUIRE(ok.cols() == 2);
    CHECK(ok(0, 1) == 3.0);
    CHECK(ok(1, 0) == 2.0);

    const std::string file = (dir.path() / "reference_points_RE21.dat").string();
    dir.write("reference_points_RE21.dat", "1.0 2.0\n3.0\n");
    CHECK(input_error_message([&] { (void)re::read_re_front(dir.path(), "re21"); }) ==
          file + ":2: expected 2 values (the problem's M), got 1");
    dir.write("reference_points_RE21.dat", "1.0 2.0 3.0\n");
    CHECK(input_error_message([&] { (void)re::read_re_front(dir.path(), "re21"); }) ==
          file + ":1: expected 2 values (the problem's M), got more");
    dir.write("reference_points_RE21.dat", "1.0 2.0\n1.0 abc\n");
    CHECK(input_error_message([&] { (void)re::read_re_front(dir.path(), "re21"); }) ==
          file + ":2:5: expected a finite number (the file is not an RE front)");
    dir.write("reference_points_RE21.dat", "1.0 nan\n");
    CHECK(input_error_message([&] { (void)re::read_re_front(dir.path(), "re21"); }) ==
          file + ":1:5: expected a finite number (the file is not an RE front)");
    // Nothing of a file that is no front is shown (before: its first word, quoted).
    dir.write("reference_points_RE21.dat", "SECRET hunter2\n");
    CHECK(input_error_message([&] { (void)re::read_re_front(dir.path(), "re21"); }) ==
          file + ":1:1: expected a finite number (the file is not an RE front)");
    dir.write("reference_points_RE21.dat", "1 1e999\n");
    CHECK(input_error_message([&] { (void)re::read_re_front(dir.path(), "re21"); }) ==
          file + ":1:3: a number beyond the largest finite number (a damaged front file)");
    dir.write("reference_points_RE21.dat", " \n");
    CHECK(input_error_message([&] { (void)re::read_re_front(dir.path(), "re21"); }) == file + ": no points");
    CHECK_THAT(input_error_message([&] { (void)re::read_re_front(dir.path(), "re22"); }),
               Catch::Matchers::StartsWith((dir.path() / "reference_points_RE22.dat").string() + ": cannot open"));
    CHECK(input_error_message([&] { (void)re::read_re_front(dir.path(), "cre21"); }) ==
          "cre21: the suite publishes no Pareto front of a CRE problem");
    CHECK_THAT(input_error_message([&] { (void)re::read_re_front(dir.path(), "zdt1"); }),
               Catch::Matchers::StartsWith("problem: unknown RE problem 'zdt1'"));

    dir.write("ideal_nadir/ideal_point_RE21.dat", "1 2");  // no newline at the end, as the suite's
    CHECK(re::read_re_ideal(dir.path(), "re21") == std::vector<double>{1.0, 2.0});
    dir.write("ideal_nadir/nadir_point_RE21.dat", "1 2\n3 4\n");
    CHECK(input_error_message([&] { (void)re::read_re_nadir(dir.path(), "re21"); }) ==
          (dir.path() / "ideal_nadir/nadir_point_RE21.dat").string() +
              ": too many lines: 2 of M = 2 values, at most 1 read");
}

}  // namespace re_problems_test

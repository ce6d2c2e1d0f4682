// COCO's bbob-constrained suite (problems/continuous/bbob_constrained/) against COCO's C code:
// tests/data/bbob_constrained/ holds what COCO computed (its README.md says how), f and every
// constraint value at five points of each problem, as 64-bit hashes of their bits over every
// function, the suite's six dimensions and instances 1-15 (and a few others), and in full for
// instance 1 in D = 2 and 3. Every comparison is bit for bit.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <optional>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "engine/problem.hpp"
#include "engine/run.hpp"
#include "framework/constraints.hpp"
#include "framework/error.hpp"
#include "problems/continuous/bbob_constrained/bbob_constrained.hpp"
#include "tests/cli_runner.hpp"
#include "tests/test_support.hpp"

namespace bbob_constrained_test {

using pride::continuous::bbob_constrained::Problem;
namespace suite = pride::continuous::bbob_constrained;

namespace engine = pride::engine;
namespace test = pride::test;
using pride::ConstraintCounts;

static_assert(pride::ConstrainedProblem<Problem>);

/// The rows of tests/data/bbob_constrained/`file`, split at tabs, after the header `header`.
std::vector<std::vector<std::string>> read_rows(const std::string& file, const std::string& header) {
    const std::string path = std::string(PRIDE_SOURCE_DIR) + "/tests/data/bbob_constrained/" + file;
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot read " + path);
    std::string line;
    REQUIRE(std::getline(in, line));
    REQUIRE(line == header);
    std::vector<std::vector<std::string>> rows;
    while (std::getline(in, line)) {
        std::vector<std::string> fields;
        std::istringstream s(line);
        for (std::string f; std::getline(s, f, '\t');) fields.push_back(f);
        rows.push_back(fields);
    }
    return rows;
}

std::vector<std::int64_t> instances(const std::string& text) {
    if (text == "1-15") {
        std::vector<std::int64_t> all;
        for (std::int64_t i = 1; i <= 15; ++i) all.push_back(i);
        return all;
    }
    std::vector<std::int64_t> list;
    std::istringstream s(text);
    for (std::string f; std::getline(s, f, ',');) list.push_back(std::stoll(f));
    return list;
}

/// The reference program's points: 0 is x*, 1-3 uniform in [-5, 5]^D, 4 is x* + 1e-2 (2u - 1), u
/// from a 64-bit LCG seeded with 1000000 fid + 1000 iid + dim (as $PRIDE_DATA/bbob's points).
struct Points {
    std::uint64_t s;
    double next() {
        s = s * 6364136223846793005ULL + 1442695040888963407ULL;
        return static_cast<double>(s >> 11) * (1.0 / 9007199254740992.0);
    }
    std::vector<double> point(int k, std::span<const double> x_star) {
        std::vector<double> x(x_star.size());
        for (std::size_t i = 0; i < x.size(); ++i)
            x[i] = k == 0 ? x_star[i] : k < 4 ? -5.0 + 10.0 * next() : x_star[i] + 1e-2 * (2.0 * next() - 1.0);
        return x;
    }
};

std::uint64_t fnv(std::uint64_t h, double v) {
    unsigned char b[8];
    std::memcpy(b, &v, 8);
    for (unsigned char c : b) {
        h ^= c;
        h *= 1099511628211ULL;
    }
    return h;
}

std::vector<double> numbers(const std::string& text) {
    std::vector<double> v;
    std::istringstream s(text);
    for (std::string f; std::getline(s, f, ',');) v.push_back(std::strtod(f.c_str(), nullptr));
    return v;
}

engine::Budget budget(std::int64_t n) {
    engine::Budget b;
    b.evaluations = n;
    return b;
}

TEST_CASE(
    "bbob-constrained: f and every g_i equal COCO's bit for bit (hashes over 54 functions, 6 dimensions, "
    "instances 1-15)",
    "[bbob_constrained]") {
    const auto rows = read_rows("hashes.tsv", "fid\tdim\tinstances\tconstraints\thash");
    REQUIRE(rows.size() == 54 * 11);
    int equal = 0;
    for (const auto& r : rows) {
        const int fid = std::stoi(r[0]);
        const auto dim = static_cast<std::size_t>(std::stoul(r[1]));
        std::uint64_t h = 1469598103934665603ULL;
        std::size_t count = 0;
        for (const std::int64_t iid : instances(r[2])) {
            Problem p(fid, dim, iid);
            count = p.constraint_counts().total();
            std::vector<double> c(count);
            h = fnv(h, p.optimum_value());
            for (double v : p.optimum_point()) h = fnv(h, v);
            Points points{1000000ULL * static_cast<std::uint64_t>(fid) + 1000ULL * static_cast<std::uint64_t>(iid) +
                          dim};
            for (int k = 0; k < 5; ++k) {
                const auto x = points.point(k, p.optimum_point());
                h = fnv(h, p.evaluate_constrained(x, c));
                for (double v : c) h = fnv(h, v);
            }
        }
        char hex[17];
        std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
        INFO("bbob-constrained-f" << fid << " D = " << dim << " instances " << r[2]);
        CHECK(count == std::stoul(r[3]));
        CHECK(std::string(hex) == r[4]);
        equal += std::string(hex) == r[4];
    }
    CHECK(equal == 54 * 11);
}

TEST_CASE("bbob-constrained: the values COCO printed for instance 1 in D = 2 and 3, at x* and one uniform point",
          "[bbob_constrained]") {
    const auto rows = read_rows("values.tsv", "fid\tiid\tdim\tpoint\tf\tg");
    REQUIRE(rows.size() == 54 * 2 * 2);
    for (const auto& r : rows) {
        const int fid = std::stoi(r[0]);
        const std::int64_t iid = std::stoll(r[1]);
        const auto dim = static_cast<std::size_t>(std::stoul(r[2]));
        const int k = std::stoi(r[3]);
        Problem p(fid, dim, iid);
        Points points{1000000ULL * static_cast<std::uint64_t>(fid) + 1000ULL * static_cast<std::uint64_t>(iid) + dim};
        std::vector<double> x;
        for (int j = 0; j <= k; ++j) x = points.point(j, p.optimum_point());
        std::vector<double> c(p.constraint_counts().total());
        const double f = p.evaluate_constrained(x, c);
        INFO("bbob-constrained-f" << fid << " D = " << dim << " point " << k);
        CHECK(f == std::strtod(r[4].c_str(), nullptr));
        CHECK(c == numbers(r[5]));
        CHECK(p.evaluate(x) == f);
    }
}

TEST_CASE("bbob-constrained: counts, the optimum and COCO's violation (the sum of the positive g_i)",
          "[bbob_constrained]") {
    for (const std::size_t dim : {2, 3, 5, 10, 20, 40}) {
        const std::size_t d = dim;
        const std::size_t active[6] = {1, 2, 6, 6 + d / 2, 6 + d, 6 + 3 * d};
        for (int fid = 1; fid <= suite::kFunctions; ++fid) {
            Problem p(fid, dim, 3);
            INFO(p.name() << " D = " << dim);
            const std::size_t m = active[(fid - 1) % 6];
            CHECK(p.active_constraints() == m);
            CHECK(p.constraint_counts() == ConstraintCounts{m + m / 2, 0});
            CHECK(p.dimension() == dim);
            CHECK(p.lower()[0] == -5.0);
            CHECK(p.upper()[dim - 1] == 5.0);
            std::vector<double> c(m + m / 2);
            const std::vector<double> x_star(p.optimum_point().begin(), p.optimum_point().end());
            CHECK(p.evaluate_constrained(x_star, c) == p.optimum_value());
            CHECK(p.violation(c) == 0.0);
            for (double g : c) CHECK(g <= 0.0);
        }
    }
    Problem p(9, 5, 1);
    std::vector<double> c(p.constraint_counts().total());
    const std::vector<double> corner(5, 5.0);
    p.evaluate_constrained(corner, c);
    double positive = 0.0;
    for (double g : c) positive += g > 0.0 ? g : 0.0;
    CHECK(positive > 0.0);
    CHECK(p.violation(c) == positive);
    c[0] = std::nan("");
    CHECK(p.violation(c) == std::numeric_limits<double>::infinity());
    CHECK(p.name() == "bbob-constrained-f9");
}

TEST_CASE("bbob-constrained: bad function, dimension or instance in one line", "[bbob_constrained]") {
    auto message = [](int fid, std::size_t dim, std::int64_t iid) {
        return test::input_error_message([&] { Problem(fid, dim, iid); });
    };
    CHECK(message(0, 2, 1) ==
          "problem: bbob-constrained-f0: the suite's functions are bbob-constrained-f1 to bbob-constrained-f54");
    CHECK(message(55, 2, 1).starts_with("problem: bbob-constrained-f55:"));
    CHECK(message(1, 1, 1) ==
          "dim: bbob-constrained-f1 takes a dimension from 2 to 40 (the suite's: 2, 3, 5, 10, 20, 40), got 1");
    CHECK(message(1, 41, 1).starts_with("dim: "));
    CHECK(message(1, 2, 0).starts_with("instance: bbob-constrained-f1: instance must be >= 1"));
    CHECK(message(1, 2, 2147483647).starts_with("instance: bbob-constrained-f1: COCO's instances are 1 to"));

    auto engine_message = [](const std::string& name, std::int64_t dim, std::optional<std::int64_t> iid) {
        return test::input_error_message([&] { engine::Problem{engine::ContinuousSpec{name, dim, iid}}; });
    };
    CHECK(engine_message("bbob-constrained-f55", 2, 1).starts_with("problem: unknown problem 'bbob-constrained-f55'"));
    CHECK(engine_message("bbob-constrained-f01", 2, 1).starts_with("problem: unknown problem"));
    CHECK(engine_message("bbob-constrained-f", 2, 1).starts_with("problem: unknown problem"));
    CHECK(engine_message("bbob-constrained-f1", -3, 1).starts_with("dim: bbob-constrained-f1 takes a dimension"));
    CHECK(engine_message("bbob-constrained-f1", 2, 0).starts_with("instance: "));

    test::expect_input_error("run --algo jade --problem bbob-constrained-f55 --dim 2 --evals 100",
                             {"bbob-constrained-f54"});
    test::expect_input_error("run --algo jade --problem bbob-constrained-f1 --dim 41 --evals 100", {"dim"});
    test::expect_input_error("run --algo jade --problem bbob-constrained-f1 --dim 2 --instance 0 --evals 100",
                             {"instance"});
    test::expect_input_error("run --algo hs --problem bbob-constrained-f1 --dim 2 --evals 100",
                             {"does not handle constraints"});
}

TEST_CASE("bbob-constrained: by name in the engine and pride run, with the constrained runners", "[bbob_constrained]") {
    const engine::Problem f1(engine::ContinuousSpec{"bbob-constrained-f1", 2, 1});
    CHECK(f1.dimension() == 2);
    const Problem reference(1, 2, 1);
    const auto r = engine::run({"jade", {}}, f1, budget(10000), 1);
    CHECK(r.evaluations == 10000);
    REQUIRE(r.best_violation.has_value());
    CHECK(*r.best_violation == 0.0);
    CHECK(r.best_f >= reference.optimum_value() - 1e-9);  // nothing feasible lies below f(x*)
    CHECK(r.best_f == Approx(reference.optimum_value()).epsilon(1e-6));

    const auto text = test::run_pride(
        "run --algo jade --problem bbob-constrained-f1 --dim 2 --instance 1 "
        "--evals 2000 --seed 1 --json");
    REQUIRE(text.status == 0);
    CHECK(text.out.find("\"instance\": 1,") != std::string::npos);
    CHECK(text.out.find("\"best_violation\": 0,") != std::string::npos);
    CHECK(f1.instance() == 1);
    CHECK(f1.optimum_value() == reference.optimum_value());
    // No instance given: instance 1, as for bbob-fN.
    CHECK(engine::Problem(engine::ContinuousSpec{"bbob-constrained-f1", 2}).instance() == 1);
}

}  // namespace bbob_constrained_test

// COCO's bbob-mixint suite (problems/continuous/bbob_mixint/) against COCO's C code:
// tests/data/bbob_mixint/ holds what COCO computed (its README.md says how): the best value, x*,
// the box and f at six points of each problem, as 64-bit hashes of their bits over every function,
// the suite's dimensions below its largescale ones (5, 10, 20, 40) and instances 1-15 (and a few
// others), and in full for instance 1 in D = 5. Every comparison is bit for bit.
#include <fmt/format.h>
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "engine/problem.hpp"
#include "engine/run.hpp"
#include "experiment/storage/reader.hpp"
#include "framework/error.hpp"
#include "problems/continuous/bbob_mixint/bbob_mixint.hpp"
#include "problems/continuous/catalog.hpp"
#include "problems/continuous/integer_variables.hpp"
#include "tests/cli_runner.hpp"
#include "tests/test_support.hpp"

namespace bbob_mixint_test {

using pride::continuous::bbob_mixint::Problem;
namespace suite = pride::continuous::bbob_mixint;
namespace engine = pride::engine;
namespace test = pride::test;

/// The rows of tests/data/bbob_mixint/`file`, split at tabs, after the header `header`.
std::vector<std::vector<std::string>> read_rows(const std::string& file, const std::string& header) {
    const std::string path = std::string(PRIDE_SOURCE_DIR) + "/tests/data/bbob_mixint/" + file;
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
    std::vector<std::int64_t> list;
    if (text == "1-15") {
        for (std::int64_t i = 1; i <= 15; ++i) list.push_back(i);
        return list;
    }
    std::istringstream s(text);
    for (std::string f; std::getline(s, f, ',');) list.push_back(std::stoll(f));
    return list;
}

/// The reference program's points (README.md): 0 is x*; 1-3 uniform in [l - 1, u + 1]; 4 is
/// x* + 1e-2 (2u - 1); 5 the half-way cases on the integer coordinates, uniform in [-5, 5] on the
/// others. u from a 64-bit LCG seeded with 1000000 fid + 1000 iid + dim.
struct Points {
    std::uint64_t s;
    double next() {
        s = s * 6364136223846793005ULL + 1442695040888963407ULL;
        return static_cast<double>(s >> 11) * (1.0 / 9007199254740992.0);
    }
    std::vector<double> point(int k, const Problem& p, const std::vector<double>& x_star) {
        std::vector<double> x(p.dimension());
        for (std::size_t i = 0; i < x.size(); ++i) {
            const double l = p.lower()[i], u = p.upper()[i];
            if (k == 0)
                x[i] = x_star[i];
            else if (k < 4)
                x[i] = (l - 1.0) + (u - l + 2.0) * next();
            else if (k == 4)
                x[i] = x_star[i] + 1e-2 * (2.0 * next() - 1.0);
            else
                x[i] = p.is_integer(i) ? std::floor((u - l + 2.0) * next()) - 0.5 : -5.0 + 10.0 * next();
        }
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

TEST_CASE("bbob-mixint: f, x*, the best value and the box equal COCO's bit for bit (24 functions, D = 5 to 40)",
          "[bbob_mixint]") {
    const auto rows = read_rows("hashes.tsv", "fid\tdim\tinstances\tintegers\thash");
    REQUIRE(rows.size() == 24 * 9);
    int equal = 0;
    std::size_t values = 0;
    for (const auto& r : rows) {
        const int fid = std::stoi(r[0]);
        const auto dim = static_cast<std::size_t>(std::stoul(r[1]));
        std::uint64_t h = 1469598103934665603ULL;
        std::size_t integers = 0;
        for (const std::int64_t iid : instances(r[2])) {
            Problem p(fid, dim, iid);
            integers = p.integer_variables();
            const std::vector<double> x_star = p.optimum_point();
            h = fnv(h, p.optimum_value());
            for (double v : x_star) h = fnv(h, v);
            for (double v : p.lower()) h = fnv(h, v);
            for (double v : p.upper()) h = fnv(h, v);
            Points points{1000000ULL * static_cast<std::uint64_t>(fid) + 1000ULL * static_cast<std::uint64_t>(iid) +
                          dim};
            for (int k = 0; k < 6; ++k) h = fnv(h, p.evaluate(points.point(k, p, x_star)));
            values += 1 + 3 * dim + 6;
        }
        char hex[17];
        std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
        INFO("bbob-mixint-f" << fid << " D = " << dim << " instances " << r[2]);
        CHECK(integers == std::stoul(r[3]));
        CHECK(std::string(hex) == r[4]);
        equal += std::string(hex) == r[4];
    }
    CHECK(equal == 24 * 9);
    // 24 functions x (15 instances x (5 + 10 + 20 + 40) + 2 x (15 + 25 + 30 + 35) + 3 x 5) dimensions:
    // the best value, x*, the box's two sides and six values per problem.
    CHECK(values == 24 * (15 * (4 * 7 + 3 * 75) + 2 * (4 * 7 + 3 * 105) + 3 * (7 + 3 * 5)));
}

TEST_CASE("bbob-mixint: the values COCO printed for instance 1 in D = 5", "[bbob_mixint]") {
    const auto rows = read_rows("values.tsv", "fid\tiid\tdim\tpoint\tf\tx");
    REQUIRE(rows.size() == 24 * 6);
    for (const auto& r : rows) {
        Problem p(std::stoi(r[0]), static_cast<std::size_t>(std::stoul(r[2])), std::stoll(r[1]));
        const std::vector<double> x = numbers(r[5]);
        INFO(p.name() << " point " << r[3]);
        CHECK(p.evaluate(x) == std::strtod(r[4].c_str(), nullptr));
    }
}

TEST_CASE("bbob-mixint: integer variables, the box, rounding and clamping as COCO's", "[bbob_mixint]") {
    for (const std::size_t dim : {5, 10, 20, 40}) {
        for (int fid = 1; fid <= suite::kFunctions; ++fid) {
            Problem p(fid, dim, 2);
            INFO(p.name() << " D = " << dim);
            CHECK(p.integer_variables() == dim / 5 * 4);
            const std::vector<double> x_star = p.optimum_point();
            for (std::size_t i = 0; i < dim; ++i) {
                const double n = i < p.integer_variables() ? double(2 << (i / (dim / 5))) : 0.0;
                CHECK(p.is_integer(i) == (n > 0.0));
                CHECK(p.lower()[i] == (n > 0.0 ? 0.0 : -5.0));
                CHECK(p.upper()[i] == (n > 0.0 ? n - 1.0 : 5.0));
                if (p.is_integer(i)) {
                    CHECK(x_star[i] == std::floor(x_star[i]));
                    CHECK((x_star[i] >= p.lower()[i] && x_star[i] <= p.upper()[i]));
                }
            }
            // An integer coordinate is rounded (half-way up) and clamped before the function sees it.
            std::vector<double> x = x_star, y = x_star;
            x[0] = x_star[0] + 0.49;
            y[0] = x_star[0] == 0.0 ? -7.0 : 9.0;  // out of the box on x*'s side (0 or 1): clamped to x*[0]
            const double f = p.evaluate(x_star);
            CHECK(p.evaluate(x) == f);
            CHECK(p.evaluate(y) == f);
            x[0] = 0.5;
            y[0] = 1.0;
            CHECK(p.evaluate(x) == p.evaluate(y));
        }
    }
    Problem p(1, 5, 1);
    CHECK(p.name() == "bbob-mixint-f1");
    CHECK(p.function() == 1);
    CHECK(p.instance() == 1);
    std::vector<double> x(5, 0.0);
    x[4] = std::nan("");
    CHECK(std::isnan(p.evaluate(x)));
}

TEST_CASE("bbob-mixint: bad function, dimension or instance in one line", "[bbob_mixint]") {
    auto message = [](int fid, std::size_t dim, std::int64_t iid) {
        return test::input_error_message([&] { Problem(fid, dim, iid); });
    };
    CHECK(message(25, 5, 1) == "problem: bbob-mixint-f25: the suite's functions are bbob-mixint-f1 to bbob-mixint-f24");
    CHECK(message(0, 5, 1).starts_with("problem: bbob-mixint-f0:"));
    CHECK(message(1, 7, 1) ==
          "dim: bbob-mixint-f1 takes a dimension that is a multiple of 5 from 5 to 40 (the suite's: 5, 10, 20, 40; "
          "COCO's 80 and 160 use its bbob-largescale functions, which pride does not have), got 7");
    CHECK(message(1, 80, 1).starts_with("dim: "));
    CHECK(message(1, 5, 0) == "instance: bbob-mixint-f1: instance must be >= 1 (COCO numbers instances from 1), got 0");
    CHECK(message(1, 5, 2147483647).starts_with("instance: bbob-mixint-f1: COCO's instances are 1 to"));

    auto engine_message = [](const std::string& name, std::int64_t dim, std::optional<std::int64_t> iid) {
        return test::input_error_message([&] { engine::Problem{engine::ContinuousSpec{name, dim, iid}}; });
    };
    CHECK(engine_message("bbob-mixint-f25", 5, 1).starts_with("problem: unknown problem 'bbob-mixint-f25'"));
    CHECK(
        engine_message("bbob-mixint-f1", 7, 1).starts_with("dim: bbob-mixint-f1 takes a dimension that is a multiple"));
    CHECK(engine_message("bbob-mixint-f1", 160, 1).starts_with("dim: bbob-mixint-f1 takes a dimension"));
    CHECK(engine_message("bbob-mixint-f1", 5, 0).starts_with("instance: bbob-mixint-f1: COCO numbers instances"));

    test::expect_input_error("run --algo de --problem bbob-mixint-f25 --dim 5 --evals 100", {"bbob-mixint-f25"});
    test::expect_input_error("run --algo de --problem bbob-mixint-f1 --dim 7 --evals 100", {"dim", "multiple of 5"});
    test::expect_input_error("run --algo de --problem bbob-mixint-f1 --dim 5 --instance 0 --evals 100", {"instance"});
}

TEST_CASE("bbob-mixint: by name in the catalog, the engine and pride run", "[bbob_mixint]") {
    const auto* item = pride::continuous::catalog().find("bbob-mixint-f7");
    REQUIRE(item != nullptr);
    CHECK(item->entry.suite == "bbob-mixint");
    CHECK(item->entry.number == 7);
    // The function the engine holds says which variables are integer (bbob-mixint's only).
    auto function = pride::continuous::make_function("bbob-mixint-f7", 10, 3);
    CHECK(pride::continuous::integer_variables(function) == 8);
    CHECK(function.lower()[7] == 0.0);
    CHECK(function.upper()[7] == 15.0);
    CHECK(pride::continuous::integer_variables(pride::continuous::make_function("bbob-f7", 10, 3)) == 0);
    CHECK(pride::continuous::integer_variables(pride::continuous::make_function("sphere", 10)) == 0);
    Problem direct(7, 10, 3);
    const std::vector<double> x_star = direct.optimum_point();
    CHECK(function.evaluate(x_star) == direct.evaluate(x_star));
    CHECK(function.optimum_value() == direct.optimum_value());
    CHECK(function.optimum_point() == x_star);

    const engine::Problem f7(engine::ContinuousSpec{"bbob-mixint-f7", 10, 3});
    const Problem reference(7, 10, 3);
    CHECK(f7.dimension() == 10);
    CHECK(f7.instance() == 3);
    CHECK(f7.optimum_value() == reference.optimum_value());
    CHECK(engine::Problem(engine::ContinuousSpec{"bbob-mixint-f7", 10}).instance() == 1);

    engine::Budget budget;
    budget.evaluations = 2000;
    const auto r = engine::run({"de", {}}, f7, budget, 1);
    CHECK(r.evaluations == 2000);
    CHECK(r.best_f >= reference.optimum_value() - 1e-13);  // COCO's own check of its values
    Problem check(7, 10, 3);
    CHECK(check.evaluate(r.best_x) == r.best_f);  // the run's values are the problem's

    const auto text =
        test::run_pride("run --algo de --problem bbob-mixint-f7 --dim 10 --instance 3 --evals 500 --json");
    REQUIRE(text.status == 0);
    CHECK(text.out.find("\"instance\": 3,") != std::string::npos);
}

TEST_CASE("campaigns: [[suite]] name = \"bbob-mixint\", and its refusals at the key", "[campaign][bbob_mixint]") {
    const test::TempDir tmp("pride-mixint-suite");
    const std::filesystem::path& dir = tmp.path();
    const auto campaign = [](const std::string& suite) {
        return "name = \"s\"\nseeds = 1\n[budget]\nevaluations_per_dim = 10\n[[suite]]\nname = \"bbob-mixint\"\n" +
               suite + "[[algorithm]]\nid = \"de\"\ntype = \"de\"\npop = 10\n";
    };
    const auto refused = [&](const std::string& suite, const std::vector<std::string>& words) {
        std::ofstream(dir / "c.toml") << campaign(suite);
        INFO(suite);
        test::expect_input_error(
            "bench '" + (dir / "c.toml").string() + "' --out '" + (dir / "c.sqlite").string() + "'", words);
        CHECK(!std::filesystem::exists(dir / "c.sqlite"));  // refused before anything ran
    };
    refused("functions = [1, 25]\ndimensions = [5]\n",
            {"c.toml:7:", "function 25 is not in the bbob-mixint suite (1-24)"});
    refused("instances = [0]\ndimensions = [5]\n", {"c.toml:7:", "bbob-mixint: COCO's instances are 1 to"});
    refused("dimensions = [5, 7]\n", {"c.toml:7:", "dimension 7: the bbob-mixint functions take a multiple of 5"});
    refused("dimensions = [80]\n", {"c.toml:7:", "dimension 80:", "bbob-largescale"});
    refused("functions = [1]\n", {"c.toml:5", "a [[suite]] needs 'dimensions'"});

    // The default instances (1-5), one problem per (function, dimension, instance), in that order,
    // with COCO's best value and the suite's function number in the store.
    std::ofstream(dir / "c.toml") << campaign("id = \"mi\"\nfunctions = [1, 20]\ndimensions = [5, 10]\n");
    const std::string store = (dir / "c.sqlite").string();
    REQUIRE(test::run_pride("bench '" + (dir / "c.toml").string() + "' --jobs 2 --out '" + store + "'").status == 0);
    const auto s = pride::storage::read_store(store);
    REQUIRE(s.problems);
    REQUIRE(s.problems->size() == 2u * 2u * 5u);
    CHECK(s.runs.size() == 2u * 2u * 5u);
    std::size_t k = 0;
    for (const int f : {1, 20})
        for (const int d : {5, 10})
            for (int i = 1; i <= 5; ++i) {
                const auto& p = (*s.problems)[k++];
                CHECK(p.id == fmt::format("mi-f{}-i{}-d{}", f, i, d));
                CHECK(p.suite == "bbob-mixint");
                CHECK(p.fid == f);
                CHECK(p.instance == i);
                CHECK(p.dim == d);
                REQUIRE(p.f_opt);
                CHECK(*p.f_opt == Problem(f, static_cast<std::size_t>(d), i).optimum_value());
            }
}

}  // namespace bbob_mixint_test

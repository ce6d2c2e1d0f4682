// Tests of the `pride` command as a user runs it (docs/cli.md): exit statuses and error
// lines, the JSON of `run` and `list`, the values printed by `eval`.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "json_reader.hpp"
#include "problems/continuous/catalog.hpp"
#include "tests/test_support.hpp"

using pride::test::json_numbers;
using pride::test::lines_of;

namespace {

using pride::test::expect_input_error;
using pride::test::JsonValue;
using pride::test::parse_json;
using pride::test::run_pride;

std::string format17(double v) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.17g", v);
    return buffer;
}

/// Runs a command that must succeed, returning its stdout.
std::string expect_success(const std::string& args, const std::string& stdin_text = "") {
    INFO("pride " << args);
    const auto r = run_pride(args, stdin_text);
    INFO("stderr: " << r.err);
    REQUIRE(r.status == 0);
    CHECK(r.err.empty());
    return r.out;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// 1. Errors

TEST_CASE("cli: unknown names are input errors", "[cli][errors]") {
    expect_input_error("run --problem sphere --dim 3 --algo nosuchalgo --evals 100", {"nosuchalgo"});
    expect_input_error("run --problem nosuchproblem --dim 3 --algo pso --evals 100", {"nosuchproblem"});
    expect_input_error("eval --problem nosuchproblem --x 1,2", {"nosuchproblem"});
    expect_input_error("run --problem sphere --dim 3 --algo nlopt:LN_NOSUCH --evals 100", {"LN_NOSUCH"});
    expect_input_error("run --problem sphere --dim 3 --algo nlopt:LD_MMA --evals 100", {"LD_MMA"});
    expect_input_error("run --problem sphere --dim 3 --algo nlopt:LD_LBFGS --evals 100", {"LD_LBFGS"});
}

TEST_CASE("cli: bad dimensions are input errors", "[cli][errors]") {
    expect_input_error("run --problem sphere --dim -3 --algo pso --evals 100", {"--dim"});
    expect_input_error("run --problem sphere --dim 0 --algo pso --evals 100", {"--dim"});
    expect_input_error("run --problem sphere --dim abc --algo pso --evals 100", {"--dim"});
    expect_input_error("run --problem sphere --dim 2.5 --algo pso --evals 100", {"--dim"});
    expect_input_error("run --problem rosenbrock --dim 1 --algo pso --evals 100", {"--dim"});  // needs >= 2
    expect_input_error("eval --problem rosenbrock --x 1", {"rosenbrock"});
}

TEST_CASE("cli: malformed points are input errors", "[cli][errors]") {
    expect_input_error("eval --problem sphere --x 1,,2", {"--x"});
    expect_input_error("eval --problem sphere --x abc", {"--x", "abc"});
    expect_input_error("eval --problem sphere --x 1,2,", {"--x"});
    expect_input_error("eval --problem sphere --x ''", {"--x"});
    expect_input_error("eval --problem sphere --x ,1", {"--x"});
    expect_input_error("eval --problem sphere --x 1,nan", {"--x"});
    expect_input_error("eval --problem sphere --x 1,inf", {"--x"});
    expect_input_error("eval --problem sphere --x 1e999", {"--x"});
    expect_input_error("eval --problem sphere --x 1x", {"--x"});
    expect_input_error("eval --problem sphere --x '1 2'", {"--x"});
    expect_input_error("eval --problem sphere --dim 3 --x 1,2", {"3"});
}

TEST_CASE("cli: malformed stdin points name the line", "[cli][errors]") {
    expect_input_error("eval --problem sphere --x -", {"line 3"}, "1,2\n3,4\n1,x\n5,6\n");
    expect_input_error("eval --problem sphere --x -", {"line 2"}, "1,2\n3,,4\n");
    expect_input_error("eval --problem sphere --x -", {"line 3"}, "1,2\n3,4\n1,2,3\n");  // not like the first
    expect_input_error("eval --problem sphere --x -", {}, "");                           // no point at all
    expect_input_error("eval --problem sphere --dim 3 --x -", {"3"}, "1,2\n3,4\n");
}

TEST_CASE("cli: option errors are input errors", "[cli][errors]") {
    expect_input_error("run --bogus");
    expect_input_error("run --problem sphere --dim 3 --algo pso --evals 100 --bogus", {"--bogus"});
    expect_input_error("run --problem sphere --dim 3 --algo pso --evals 100 stray", {"stray"});
    expect_input_error("run --problem sphere --dim 3 --evals 100", {"--algo"});  // missing required option
    expect_input_error("run --dim 3 --algo pso --evals 100", {"--problem"});
    expect_input_error("eval --problem sphere", {"--x"});
    expect_input_error("");  // no subcommand
    expect_input_error("nosuchcommand", {"nosuchcommand"});
    expect_input_error("run --problem sphere --dim 3 --algo pso --evals 100 --iters 5", {"--evals", "--iters"});
    expect_input_error("run --problem sphere --dim 3 --algo pso --evals 0", {"--evals"});
    expect_input_error("run --problem sphere --dim 3 --algo pso --evals -5", {"--evals"});
    expect_input_error("run --problem sphere --dim 3 --algo pso --evals 1e3", {"--evals"});
    expect_input_error("run --problem sphere --dim 3 --algo pso --iters -1", {"--iters"});
    expect_input_error("run --problem sphere --dim 3 --algo pso --evals 100 --wall-ms 0", {"--wall-ms"});
    expect_input_error("run --problem sphere --dim 3 --algo pso --evals 100 --seed 1.5", {"--seed"});
    expect_input_error("run --problem sphere --dim 3 --algo pso --evals 100 --pop 1", {"population"});
}

TEST_CASE("cli: a negative seed is refused rather than wrapped around", "[cli][errors]") {
    // --seed is unsigned; "-1" must not silently become 18446744073709551615.
    expect_input_error("run --problem sphere --dim 3 --algo pso --evals 100 --seed -1", {"--seed"});
}

TEST_CASE("cli: bad algorithm parameters are input errors", "[cli][errors]") {
    expect_input_error("run --problem sphere --dim 3 --algo pso --evals 100 --param pop=abc", {"pop", "abc"});
    expect_input_error("run --problem sphere --dim 3 --algo pso --evals 100 --param nosuchparam=1", {"nosuchparam"});
    expect_input_error("run --problem sphere --dim 3 --algo pso --evals 100 --param pop", {"pop"});
    expect_input_error("run --problem sphere --dim 3 --algo pso --evals 100 --param pop=2.5", {"pop"});
    expect_input_error("run --problem sphere --dim 3 --algo pso --evals 100 --param w_start=-1", {"w_start"});
    expect_input_error("run --problem sphere --dim 3 --algo ga --evals 100 --param pc=1.5", {"pc"});
    expect_input_error("run --problem sphere --dim 3 --algo ga --evals 100 --param tournament=-2", {"tournament"});
    expect_input_error("run --problem sphere --dim 3 --algo ga --evals 100 --param elitism=50", {"elitism"});
    // a parameter of another algorithm
    expect_input_error("run --problem sphere --dim 3 --algo ga --evals 100 --param w_start=0.5", {"w_start"});
    expect_input_error("run --problem sphere --dim 3 --algo nlopt:LN_SBPLX --evals 100 --param elitism=1", {"elitism"});
}

// ---------------------------------------------------------------------------------------------
// 2. run --json

namespace {

/// The JSON of one run, with the wall time (the one field allowed to differ) blanked.
std::string without_wall_ms(const std::string& out) {
    const auto key = out.find("\"wall_ms\"");
    if (key == std::string::npos) return out;
    const auto colon = out.find(':', key);
    const auto end = out.find_first_of(",}", colon);
    return out.substr(0, colon + 1) + "#" + out.substr(end);
}

}  // namespace

TEST_CASE("cli: run --json prints one object with the documented keys", "[cli][run]") {
    const std::string args = "run --problem rastrigin --dim 5 --algo pso --evals 1000 --seed 3 --json";
    const std::string out = expect_success(args);
    REQUIRE(!out.empty());
    CHECK(out.back() == '\n');
    CHECK(std::count(out.begin(), out.end(), '\n') == 1);
    const JsonValue j = parse_json(out);
    REQUIRE(j.kind == JsonValue::Kind::object);

    auto keys = j.keys();
    const std::set<std::string> unique(keys.begin(), keys.end());
    CHECK(unique.size() == keys.size());  // no key twice
    const std::set<std::string> expected = {"algo",   "problem", "dim",         "instance", "seed",
                                            "best_f", "best_x",  "evaluations", "wall_ms",  "history"};
    CHECK(unique == expected);

    CHECK(j.at("algo").kind == JsonValue::Kind::string);
    CHECK(j.at("algo").text == "pso");
    CHECK(j.at("problem").text == "rastrigin");
    CHECK(j.at("dim").kind == JsonValue::Kind::number);
    CHECK(j.at("dim").text == "5");
    CHECK(j.at("seed").text == "3");
    CHECK(j.at("evaluations").text == "1000");
    REQUIRE(j.at("wall_ms").kind == JsonValue::Kind::number);
    CHECK(j.at("wall_ms").number >= 0.0);
    REQUIRE(j.at("best_f").kind == JsonValue::Kind::number);
    const double best_f = j.at("best_f").number;
    CHECK(std::isfinite(best_f));
    CHECK(best_f >= 0.0);

    const auto best_x = json_numbers(j.at("best_x"));
    REQUIRE(best_x.size() == 5);
    for (double v : best_x) {
        CHECK(v >= -5.12);
        CHECK(v <= 5.12);
    }
    const auto history = json_numbers(j.at("history"));
    REQUIRE(!history.empty());
    CHECK(history.size() == 20);  // default population 50: 1 + 19 iterations in 1000 evaluations
    for (std::size_t k = 1; k < history.size(); ++k) CHECK(history[k] <= history[k - 1]);
    CHECK(history.back() == best_f);

    // Numbers are printed so that they read back exactly: evaluating best_x gives best_f.
    std::string x_text;
    for (std::size_t i = 0; i < best_x.size(); ++i) x_text += (i ? "," : "") + j.at("best_x").items[i].text;
    const std::string value = expect_success("eval --problem rastrigin --x " + x_text);
    CHECK(std::strtod(value.c_str(), nullptr) == best_f);

    // Same command, same output except the wall time; another seed, another run.
    const std::string again = expect_success(args);
    CHECK(without_wall_ms(again) == without_wall_ms(out));
    CHECK(without_wall_ms(out) != out);  // the blanking did find the field
    const std::string other = expect_success("run --problem rastrigin --dim 5 --algo pso --evals 1000 --seed 4 --json");
    const JsonValue o = parse_json(other);
    CHECK(o.at("seed").text == "4");
    CHECK(json_numbers(o.at("history")) != history);
}

TEST_CASE("cli: run --json for every algorithm family and limit", "[cli][run]") {
    struct Case {
        std::string args;
        std::int64_t evaluations;  // -1: less than the budget
    };
    const Case cases[] = {
        {"--problem sphere --dim 4 --algo ga --evals 777 --pop 20", 777},
        {"--problem shifted-ackley --dim 3 --algo pso-constriction --evals 501 --pop 10", 501},
        {"--problem griewank --dim 2 --algo nlopt:GN_CRS2_LM --evals 333", 333},
        {"--problem sphere --dim 2 --algo pso --iters 5 --pop 10", 60},
        {"--problem sphere --dim 2 --algo ga --iters 4 --pop 10 --param elitism=2", 10 + 4 * 8},
        {"--problem sphere --dim 3 --algo pso --evals 100000 --target 1e-3 --pop 20", -1},
        {"--problem sphere --dim 3 --algo pso --param pop=30 --param w_start=0.8 --param c1=1.5 --evals 90", 90},
    };
    for (const auto& c : cases) {
        INFO(c.args);
        const JsonValue j = parse_json(expect_success("run " + c.args + " --json"));
        const auto evaluations = static_cast<std::int64_t>(j.at("evaluations").number);
        if (c.evaluations >= 0)
            CHECK(evaluations == c.evaluations);
        else {
            CHECK(evaluations < 100000);
            CHECK(j.at("best_f").number <= 1e-3);
        }
        const auto history = json_numbers(j.at("history"));
        REQUIRE(!history.empty());
        CHECK(history.back() == j.at("best_f").number);
    }
}

TEST_CASE("cli: a wall-time limit far in the future does not end the run", "[cli][run]") {
    // 1e13 ms (about 317 years) overflows a nanosecond duration; it must still mean "no limit yet".
    for (const char* wall : {"1e6", "1e13", "1e300"}) {
        INFO("--wall-ms " << wall);
        const JsonValue j = parse_json(expect_success(
            std::string("run --problem sphere --dim 3 --algo pso --evals 1000 --json --wall-ms ") + wall));
        CHECK(j.at("evaluations").number == 1000);
    }
}

TEST_CASE("cli: run without --json prints a readable report", "[cli][run]") {
    const std::string out = expect_success("run --problem sphere --dim 2 --algo ga --evals 200 --seed 2");
    CHECK(out.find("best_f") != std::string::npos);
    CHECK(out.find("200") != std::string::npos);
    CHECK(out.find("ga") != std::string::npos);
}

// ---------------------------------------------------------------------------------------------
// 3. eval

TEST_CASE("cli: eval prints 17 significant digits", "[cli][eval]") {
    CHECK(expect_success("eval --problem rastrigin --x 1,1,1,1,1") == "5\n");
    CHECK(expect_success("eval --problem rastrigin --x 1") == "1\n");
    CHECK(expect_success("eval --problem rosenbrock --x 1,1,1,1,1") == "0\n");
    CHECK(expect_success("eval --problem sphere --x ' 1 , +2 '") == "5\n");
    CHECK(expect_success("eval --problem sphere --x 0.1") == "0.010000000000000002\n");

    // Reference values from pagmo2's tests ($PRIDE_DATA/continuous/reference_values.md), rel 1e-15.
    struct Case {
        const char* problem;
        const char* x;
        double value;
    };
    const Case cases[] = {
        {"ackley", "-23.45,12.34,111.12", 21.941495638130885},
        {"ackley", "1.12", 4.659037611351948},
        {"griewank", "1.12", 0.5646311537232878},
        {"griewank", "-23.45,12.34,111.12", 4.241511427781268},
        {"schwefel", "1.12", 418.0067810680098},
        {"schwefel", "-23.45,12.34,111.12", 1338.0260195323838},
    };
    for (const auto& c : cases) {
        INFO(c.problem << " at " << c.x);
        const std::string out = expect_success(std::string("eval --problem ") + c.problem + " --x " + c.x);
        REQUIRE(!out.empty());
        CHECK(out.back() == '\n');
        CHECK(std::count(out.begin(), out.end(), '\n') == 1);
        const std::string line = out.substr(0, out.size() - 1);
        const double v = std::strtod(line.c_str(), nullptr);
        CHECK(v == Approx(c.value).epsilon(1e-15));
        CHECK(line == format17(v));  // printed as %.17g
    }
    const std::string ackley = expect_success("eval --problem ackley --x -23.45,12.34,111.12");
    CHECK(std::strtod(ackley.c_str(), nullptr) == Approx(21.941495638130885).epsilon(1e-15));
}

TEST_CASE("cli: eval --x - reads one point per line", "[cli][eval]") {
    const std::string out = expect_success("eval --problem sphere --x -", "1,2,3\n0,0,0\n-1.5,0.5,2\n");
    CHECK(out == "14\n0\n6.5\n");
    const auto lines = lines_of(expect_success("eval --problem ackley --x -", "-23.45,12.34,111.12\n1,2,3\n0,0,0\n"));
    REQUIRE(lines.size() == 3);
    CHECK(lines[0] == lines_of(expect_success("eval --problem ackley --x -23.45,12.34,111.12"))[0]);
    CHECK(lines[1] == lines_of(expect_success("eval --problem ackley --x 1,2,3"))[0]);
    CHECK(std::abs(std::strtod(lines[2].c_str(), nullptr)) < 1e-14);
    // A last line without a newline still counts.
    CHECK(expect_success("eval --problem sphere --x -", "1\n2") == "1\n4\n");
}

// ---------------------------------------------------------------------------------------------
// 4. list and help

TEST_CASE("cli: list names every algorithm and problem", "[cli][list]") {
    const std::string out = expect_success("list");
    std::set<std::string> first_words;
    for (const auto& line : lines_of(out)) {
        const auto start = line.find_first_not_of(' ');
        if (start == std::string::npos) continue;
        first_words.insert(line.substr(start, line.find(' ', start) - start));
    }
    std::vector<std::string> expected = {"pso", "ga", "pso-constriction", "nlopt:LN_SBPLX", "nlopt:GN_CRS2_LM"};
    for (const auto& item : pride::continuous::catalog().items()) expected.push_back(item.name);
    CHECK(pride::continuous::catalog().items().size() >= 6);
    for (const auto& name : expected) {
        INFO(name);
        CHECK(first_words.count(name) == 1);
    }
    CHECK(out.find("nlopt:LD_") == std::string::npos);  // gradient algorithms cannot run here

    const JsonValue j = parse_json(expect_success("list --json"));
    REQUIRE(j.kind == JsonValue::Kind::object);
    std::set<std::string> algorithms, problems;
    REQUIRE(j.has("algorithms"));
    REQUIRE(j.has("problems"));
    for (const auto& a : j.at("algorithms").items) algorithms.insert(a.at("name").text);
    std::map<std::string, std::size_t> dimension;  // one each problem is defined in
    for (const auto& p : j.at("problems").items) {
        problems.insert(p.at("name").text);
        const auto& fixed = p.at("fixed_dim");
        dimension[p.at("name").text] = fixed.kind == JsonValue::Kind::null
                                           ? std::max<std::size_t>(3, static_cast<std::size_t>(p.at("min_dim").number))
                                           : static_cast<std::size_t>(fixed.number);
        CHECK(p.has("instances"));
        CHECK(p.has("suite"));
    }
    for (const char* a : {"pso", "ga", "pso-constriction", "nlopt:LN_SBPLX", "nlopt:GN_CRS2_LM"})
        CHECK(algorithms.count(a) == 1);
    for (const auto& item : pride::continuous::catalog().items()) CHECK(problems.count(item.name) == 1);
    // Every listed problem can be evaluated, every listed algorithm run.
    for (const auto& name : problems) {
        INFO(name);
        if (name.starts_with("cec")) continue;  // the official data: tests/test_cec.cpp
        std::string x = "0.5";
        for (std::size_t d = 1; d < dimension[name]; ++d) x += ",0.25";
        const auto r = run_pride("eval --problem " + name + " --x " + x);
        CHECK(r.status == 0);
        CHECK(lines_of(r.out).size() == 1);
    }
    for (const char* a : {"pso", "ga", "pso-constriction", "nlopt:LN_SBPLX", "nlopt:GN_CRS2_LM", "nlopt:LN_COBYLA",
                          "nlopt:GN_DIRECT_L", "nlopt:GN_ISRES"}) {
        INFO(a);
        REQUIRE(algorithms.count(a) == 1);
        const JsonValue r =
            parse_json(expect_success(std::string("run --problem sphere --dim 2 --evals 120 --json --algo ") + a));
        CHECK(r.at("evaluations").number == 120);
    }
}

TEST_CASE("cli: help", "[cli][help]") {
    const auto top = run_pride("--help");
    CHECK(top.status == 0);
    CHECK(top.err.empty());
    for (const char* sub : {"run", "eval", "list"}) CHECK(top.out.find(sub) != std::string::npos);

    const auto run = run_pride("run --help");
    CHECK(run.status == 0);
    for (const char* opt : {"--problem", "--dim", "--algo", "--evals", "--iters", "--pop", "--seed", "--json"}) {
        INFO(opt);
        CHECK(run.out.find(opt) != std::string::npos);
    }
    for (const char* sub : {"eval --help", "list --help"}) {
        const auto r = run_pride(sub);
        INFO(sub);
        CHECK(r.status == 0);
        CHECK(!r.out.empty());
    }
}

// ---------------------------------------------------------------------------------------------
// 5. NLopt through the command line

TEST_CASE("cli: NLopt subplex on the sphere", "[cli][nlopt]") {
    const JsonValue j =
        parse_json(expect_success("run --problem sphere --dim 3 --algo nlopt:LN_SBPLX --evals 2000 --json"));
    CHECK(j.at("algo").text == "nlopt:LN_SBPLX");
    CHECK(j.at("evaluations").number == 2000);
    CHECK(j.at("best_f").number < 1e-10);
    CHECK(json_numbers(j.at("best_x")).size() == 3);

    // restart=0 runs NLopt once: it converges and stops before the budget.
    const JsonValue once = parse_json(
        expect_success("run --problem sphere --dim 2 --algo nlopt:LN_SBPLX --evals 100000 --param restart=0 --json"));
    CHECK(once.at("evaluations").number < 100000);
    CHECK(once.at("best_f").number < 1e-12);
    // pop sets the evaluations per recorded iteration: 2000 / 100 = 20 entries.
    const JsonValue blocks =
        parse_json(expect_success("run --problem sphere --dim 3 --algo nlopt:LN_SBPLX --evals 2000 --pop 100 --json"));
    CHECK(json_numbers(blocks.at("history")).size() == 20);
}

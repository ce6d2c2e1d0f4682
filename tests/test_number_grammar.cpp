// One grammar for numbers given as text (framework/number.hpp): the command line's reals and
// integers, `--param NAME=VALUE` and points on stdin accept and refuse the same spellings.
#include <catch2/catch.hpp>
#include <string>

#include "framework/number.hpp"
#include "tests/cli_runner.hpp"

using pride::NumberText;
using pride::parse_decimal;
using pride::test::run_pride;

TEST_CASE("numbers: one decimal grammar without hex, inner spaces, inf or nan, where an underflow rounds", "[cli]") {
    double v = -1.0;
    for (const char* good : {"2", "+2", "-2", "2.", ".5", "-.5", "1e3", "1E-3", "+1.5e+2", "0"}) {
        INFO(good);
        CHECK(parse_decimal(good, v) == NumberText::ok);
    }
    CHECK((parse_decimal("+1.5e+2", v) == NumberText::ok && v == 150.0));
    for (const char* bad : {"", "+", "-", ".", "e3", "1e", "1e+", "0x1", "0x1p3", " 2", "2 ", "inf", "nan", "1,2",
                            "--1", "1..2", "1e3.5", "INF", "Infinity"}) {
        INFO(bad);
        CHECK(parse_decimal(bad, v) == NumberText::not_a_number);
    }
    CHECK(parse_decimal("1e400", v) == NumberText::too_large);
    CHECK(parse_decimal("-1e400", v) == NumberText::too_large);
    CHECK((parse_decimal("1e-400", v) == NumberText::ok && v == 0.0));
    CHECK((parse_decimal("-1e-400", v) == NumberText::ok && v == 0.0 && std::signbit(v)));
    CHECK((parse_decimal("5e-324", v) == NumberText::ok && v > 0.0));
}

TEST_CASE("numbers: the command line takes the same spellings everywhere", "[cli]") {
    const std::string run = "run --problem sphere --algo pso --evals 40 ";
    // Refused alike as a flag's value, a parameter's value and a coordinate.
    for (const std::string bad : {"0x1", "' 1'", "inf"}) {
        INFO(bad);
        CHECK(run_pride(run + "--dim 2 --param c1=" + bad).status == 2);
        CHECK(run_pride(run + "--dim 2 --target " + bad).status == 2);
        if (bad != "' 1'")  // in a list, spaces around an item are fine (below)
            CHECK(run_pride("eval --problem sphere --x " + bad + ",1").status == 2);
    }
    CHECK(run_pride(run + "--dim ' 2'").status == 2);
    CHECK(run_pride(run + "--dim 0x2").status == 2);
    // Accepted alike: a leading '+'.
    CHECK(run_pride(run + "--dim +2 --param c1=+1.5").status == 0);
    const auto plus = run_pride("eval --problem sphere --x +1,2");
    CHECK(plus.out == "5\n");
    // An underflow is the nearest double, an overflow an error that says so.
    const auto tiny = run_pride("eval --problem sphere --x 1e-400,2");
    CHECK(tiny.status == 0);
    CHECK(tiny.out == "4\n");
    const auto huge = run_pride("eval --problem sphere --x 1e400,2");
    CHECK(huge.status == 2);
    CHECK(huge.err == "pride: --x coordinate 1: '1e400' is beyond the largest finite number\n");
    // Points on stdin: spaces around items of a list are fine, inside a number they are not.
    CHECK(run_pride("eval --problem sphere --x -", " 1 , 2 \n").out == "5\n");
    CHECK(run_pride("eval --problem sphere --x -", "1 0,2\n").status == 2);
}

TEST_CASE("cli: an option the run would ignore is refused: --waypoints off the free encoding, a one-objective front",
          "[cli]") {
    const std::string map = std::string(PRIDE_SOURCE_DIR) + "/examples/maps/wan2022-10x10.map";
    const std::string path = "path --map " + map + " --start 0,0 --goal 9,9 --evals 40 ";
    const auto native = run_pride(path + "--algo pso --waypoints 5");
    CHECK(native.status == 2);
    CHECK(native.err ==
          "pride: --waypoints: only the free encoding has waypoints; this run plans on line (pso's "
          "own; --encoding free to use them)\n");
    CHECK(run_pride(path + "--algo ga --encoding chain --waypoints 5").status == 2);
    CHECK(run_pride(path + "--algo astar --waypoints 5").err ==
          "pride: --waypoints: astar plans on the whole map, it has no waypoints\n");
    CHECK(run_pride(path + "--algo pso --encoding free --waypoints 5").status == 0);
    const auto one = run_pride("pareto --map " + map + " --start 0,0 --goal 9,9 --objectives length");
    CHECK(one.status == 2);
    CHECK(one.err.find("a Pareto front needs two to four objectives, got only 'length'") != std::string::npos);
}

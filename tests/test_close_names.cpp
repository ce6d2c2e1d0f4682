// Close names for an unknown algorithm or problem (framework/close_names.hpp): the distance, the
// choice of names and the message every front end shows.
#include <catch2/catch.hpp>

#include "cli_runner.hpp"
#include "engine/problem_names.hpp"
#include "engine/registry.hpp"
#include "framework/close_names.hpp"
#include "test_support.hpp"

using pride::close_names;
using pride::did_you_mean;
using pride::name_distance;

TEST_CASE("close names: the optimal string alignment distance", "[framework][close-names]") {
    CHECK(name_distance("kitten", "sitting") == 3);  // two substitutions and an insertion
    CHECK(name_distance("", "pso") == 3);
    CHECK(name_distance("pso", "pso") == 0);
    CHECK(name_distance("spo", "pso") == 1);  // a swap of neighbours is one edit
    CHECK(name_distance("ca", "abc") == 3);   // no edit of a swapped pair again (not Damerau's unrestricted 2)
    CHECK(name_distance("PSO", "pso") == 0);  // letters without case
}

TEST_CASE("close names: nearest first, within one edit per three characters", "[framework][close-names]") {
    const std::vector<std::string> known{"sphere", "rastrigin", "rosenbrock", "ga",       "pso",
                                         "de",     "bbob-f1",   "bbob-f2",    "bbob-f12", "bbob-f21"};
    CHECK(close_names("spher", known) == std::vector<std::string>{"sphere"});
    CHECK(close_names("rastrign", known) == std::vector<std::string>{"rastrigin"});
    // Two at one edit, then the first of two at two edits.
    CHECK(close_names("bbob-f3", known) == std::vector<std::string>{"bbob-f1", "bbob-f2", "bbob-f12"});
    CHECK(close_names("bbob-f11", known) == std::vector<std::string>{"bbob-f1", "bbob-f12", "bbob-f21"});
    CHECK(close_names("nosuch", known).empty());
    CHECK(close_names("", known).empty());
    CHECK(close_names("pso", known).empty());  // a known name is no typo of itself
    CHECK(close_names(std::string(101, 'a'), known).empty());
    CHECK(did_you_mean("spher", known) == "; did you mean 'sphere'?");
    CHECK(did_you_mean("bbob-f3", known) == "; did you mean 'bbob-f1', 'bbob-f2' or 'bbob-f12'?");
    CHECK(did_you_mean("spehre", known) == "; did you mean 'sphere'?");
    CHECK(did_you_mean("bbob-f11", known) == "; did you mean 'bbob-f1', 'bbob-f12' or 'bbob-f21'?");
    CHECK(did_you_mean("nosuch", known).empty());
}

TEST_CASE("close names: unknown algorithms and problems name them", "[engine][close-names][errors]") {
    const auto algorithm = pride::test::input_error_message([] { pride::engine::algorithms().at("psoo"); });
    CHECK(algorithm.rfind("algo: unknown algorithm 'psoo'; did you mean 'pso'", 0) == 0);
    CHECK(algorithm.find(" (known: ") != std::string::npos);
    CHECK(pride::engine::unknown_problem("rastrign") == "unknown problem 'rastrign'; did you mean 'rastrigin'?");
    CHECK(pride::engine::unknown_problem("zdt7").rfind("unknown problem 'zdt7'; did you mean 'zdt1'", 0) == 0);
    CHECK(pride::engine::unknown_problem("nosuch") == "unknown problem 'nosuch'");
    pride::test::expect_input_error("run --algo pso --problem rastrign --dim 2",
                                    {"--problem: unknown problem 'rastrign'; did you mean 'rastrigin'?"});
}

// Sizes checked before anything is allocated, through the command line: a population, a
// dimension or a campaign run that cannot fit in memory is refused up front with exit status 2
// and one line saying how much it would need (never bad_alloc, never the kernel's OOM killer).
#include <catch2/catch.hpp>

#include "tests/cli_runner.hpp"

using pride::test::check_input_error;
using pride::test::run_pride;

TEST_CASE("cli: a run that cannot fit in memory is refused before it starts", "[cli][memory][errors]") {
    check_input_error(run_pride("run --problem sphere --dim 10 --algo pso --pop 2000000000"),
                      {"pso", "2000000000", "memory", "GB"});
    check_input_error(run_pride("run --problem sphere --dim 100000000 --algo pso"), {"pso", "memory"});
    check_input_error(run_pride("run --problem rastrigin --dim 4000000000000 --algo ga"), {"--dim", "memory"});
    check_input_error(run_pride("run --problem sphere --dim 10 --algo ga-plus --param pop=3e9"), {"ga-plus", "memory"});
    const std::string map = std::string(PRIDE_SOURCE_DIR) + "/examples/maps/wan2022-10x10.map";
    check_input_error(run_pride("path --map '" + map + "' --start 0,0 --goal 9,9 --algo lso --pop 3000000000"),
                      {"lso", "memory"});
    check_input_error(
        run_pride("path --map '" + map + "' --start 0,0 --goal 9,9 --algo ga --encoding chain --pop 100000000"),
        {"ga", "chains", "memory"});
}

TEST_CASE("cli: a campaign with a run that cannot fit in memory is refused before anything is stored",
          "[cli][bench][memory][errors]") {
    pride::test::TempDir dir;
    const std::string config = dir.write("huge.toml",
                                         "name = \"huge\"\nseeds = 1\n[budget]\nevaluations = 100\n"
                                         "[[problem]]\nid = \"s\"\ntype = \"sphere\"\ndim = 100000000\n"
                                         "[[algorithm]]\nid = \"p\"\ntype = \"pso\"\npop = 1000\n");
    check_input_error(run_pride("bench '" + config + "' --out '" + dir.file("s.sqlite") + "'"),
                      {config + ":9", "'p'", "'s'", "memory"});
    CHECK(dir.entries() == std::vector<std::string>{"huge.toml"});  // no store written
    // The most seeds (1000000) on 1000 instances: 10^9 runs, whose list is checked before it is made.
    std::string instances;
    for (int k = 1; k <= 1000; ++k) instances += (k > 1 ? ", " : "") + std::to_string(k);
    const std::string many = dir.write("many.toml",
                                       "name = \"many\"\nseeds = 1000000\n[budget]\nevaluations = 100\n"
                                       "[[problem]]\nid = \"s\"\ntype = \"sphere\"\ndim = 2\ninstance = [" +
                                           instances +
                                           "]\n"
                                           "[[algorithm]]\nid = \"p\"\ntype = \"pso\"\n");
    check_input_error(run_pride("bench '" + many + "' --out '" + dir.file("m.sqlite") + "'"),
                      {many, "1000000000 runs", "memory"});
    CHECK(dir.entries() == std::vector<std::string>{"huge.toml", "many.toml"});
}

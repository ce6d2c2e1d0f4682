// `[budget] target`: pride report gives, per (problem, algorithm), how many runs reached the target
// and their mean evaluations to reach it, read off each run's history.
#include <catch2/catch.hpp>

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/cli_runner.hpp"

namespace fs = std::filesystem;

TEST_CASE("report: evaluations to reach the campaign's target", "[report][target]") {
    const fs::path dir = fs::temp_directory_path() / ("pride-target-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    {
        std::ofstream f(dir / "c.toml");
        f << "name = \"target\"\nseeds = 4\n[budget]\nevaluations = 3000\ntarget = 1e-3\n"
             "[[problem]]\nid = \"sphere\"\ntype = \"sphere\"\ndim = 4\n"
             "[[problem]]\nid = \"rastrigin\"\ntype = \"rastrigin\"\ndim = 8\n"
             "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\npop = 20\n"
             "[[algorithm]]\nid = \"sbplx\"\ntype = \"nlopt:LN_SBPLX\"\npop = 10\n";
    }
    REQUIRE(pride::test::run_pride("bench '" + (dir / "c.toml").string() + "' --jobs 2 --out '" +
                                   (dir / "c.sqlite").string() + "'")
                .status == 0);
    const auto r = pride::test::run_pride("report '" + (dir / "c.sqlite").string() + "' --format csv");
    REQUIRE(r.status == 0);
    std::istringstream in(r.out);
    std::string line;
    std::getline(in, line);
    const std::string tail = "best,target,reached_target,mean_evaluations_to_target";
    REQUIRE(line.size() > tail.size());
    CHECK(line.substr(line.size() - tail.size()) == tail);
    int rows = 0;
    while (std::getline(in, line)) {
        std::vector<std::string> f;
        std::stringstream cells(line);
        for (std::string c; std::getline(cells, c, ',');) f.push_back(c);
        if (line.back() == ',') f.push_back("");
        REQUIRE(f.size() == 18);
        ++rows;
        INFO(line);
        CHECK(f[15] == "0.001");
        const int reached = std::stoi(f[16]);
        CHECK(reached >= 0);
        CHECK(reached <= 4);
        if (f[0] == "sphere") {  // both reach 1e-3 on a 4-D sphere within 3000 evaluations
            CHECK(reached == 4);
            const double mean = std::stod(f[17]);
            CHECK(mean > 0);
            CHECK(mean <= 3000);
        }
        if (reached == 0) CHECK(f[17].empty());
    }
    CHECK(rows == 4);
    const auto md = pride::test::run_pride("report '" + (dir / "c.sqlite").string() + "'");
    CHECK(md.out.find("| evals to target |") != std::string::npos);
    CHECK(md.out.find("(4/4) |") != std::string::npos);
    fs::remove_all(dir);
}

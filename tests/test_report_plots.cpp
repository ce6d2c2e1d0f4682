// `pride report --plots`: figures from a real campaign store, through python3-matplotlib.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include "tests/cli_runner.hpp"

namespace fs = std::filesystem;

namespace {
bool is_png(const fs::path& p) {
    std::ifstream f(p, std::ios::binary);
    char head[8] = {};
    f.read(head, 8);
    return f.gcount() == 8 && std::string(head, 8) == std::string("\x89PNG\r\n\x1a\n", 8);
}
}  // namespace

TEST_CASE("report: --plots writes convergence, final-value and path figures", "[report][plots]") {
    const fs::path dir = fs::temp_directory_path() / ("pride-plots-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path maps = fs::path(PRIDE_SOURCE_DIR) / "examples" / "maps";
    {
        std::ofstream f(dir / "c.toml");
        f << "name = \"plots\"\nseeds = 3\n[budget]\niterations = 10\n"
             "[[problem]]\nid = \"sphere\"\ntype = \"sphere\"\ndim = 4\n"
             "[[problem]]\nid = \"map\"\ntype = \"grid\"\nmap = \""
          << (maps / "wan2022-10x10.map").string()
          << "\"\nstart = [0, 0]\ngoal = [9, 9]\n"
             "[[algorithm]]\nid = \"ga\"\ntype = \"ga\"\npop = 10\n";
    }
    const auto bench = pride::test::run_pride("bench '" + (dir / "c.toml").string() + "' --jobs 2 --out '" +
                                              (dir / "c.sqlite").string() + "'");
    REQUIRE(bench.status == 0);
    const auto report = pride::test::run_pride("report '" + (dir / "c.sqlite").string() + "' --plots '" +
                                               (dir / "figures").string() + "'");
    if (report.status == 2 && report.err.find("matplotlib") != std::string::npos)
        FAIL("python3-matplotlib is missing: scripts/deps.sh installs it");
    REQUIRE(report.status == 0);
    for (const char* stem : {"sphere-convergence", "sphere-final", "map-convergence", "map-final", "map-paths"}) {
        INFO(stem);
        CHECK(is_png(dir / "figures" / (std::string(stem) + ".png")));
        CHECK(fs::file_size(dir / "figures" / (std::string(stem) + ".svg")) > 1000);
    }
    CHECK(!fs::exists(dir / "figures" / "sphere-paths.png"));  // paths only for grid problems
    fs::remove_all(dir);
}

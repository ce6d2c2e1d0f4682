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

TEST_CASE("report: --plots draws paths on a map_server map, a polyline planner's polyline too", "[report][plots]") {
    const fs::path dir = fs::temp_directory_path() / ("pride-plots-ros-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    {
        // A 12 x 8 occupancy image (P2: 0 occupied, 255 free, 205 unknown) with a wall across the
        // middle columns, and its map_server YAML; unknown cells are free in the campaign.
        std::ofstream f(dir / "m.pgm");
        f << "P2\n12 8\n255\n";
        for (int y = 0; y < 8; ++y) {
            for (int x = 0; x < 12; ++x) f << (x == 6 && y < 6 ? 0 : (x == 2 && y == 7 ? 205 : 255)) << ' ';
            f << '\n';
        }
        std::ofstream(dir / "m.yaml") << "image: m.pgm\nresolution: 0.05\norigin: [-10.0, -10.0, 0.0]\n"
                                         "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";
        std::ofstream(dir / "c.toml") << "name = \"ros\"\nseeds = 2\n[budget]\nevaluations = 300\n"
                                         "[[problem]]\nid = \"ros\"\ntype = \"grid\"\nmap = \""
                                      << (dir / "m.yaml").string()
                                      << "\"\nunknown_free = true\nstart = [0, 0]\ngoal = [11, 0]\n"
                                         "objective = \"length\"\n"
                                         "[[algorithm]]\nid = \"ga\"\ntype = \"ga\"\npop = 10\n"
                                         "[[algorithm]]\nid = \"theta\"\ntype = \"theta-star\"\n";
    }
    const auto bench =
        pride::test::run_pride("bench '" + (dir / "c.toml").string() + "' --out '" + (dir / "c.sqlite").string() + "'");
    INFO(bench.err);
    REQUIRE(bench.status == 0);
    const auto report = pride::test::run_pride("report '" + (dir / "c.sqlite").string() + "' --plots '" +
                                               (dir / "figures").string() + "'");
    INFO(report.err);
    REQUIRE(report.status == 0);
    CHECK(is_png(dir / "figures" / "ros-paths.png"));
    std::ifstream svg(dir / "figures" / "ros-paths.svg");
    const std::string text((std::istreambuf_iterator<char>(svg)), std::istreambuf_iterator<char>());
    // matplotlib keeps each text of the figure as a comment beside its glyphs: both legends' entries.
    CHECK(text.find("<!-- theta (") != std::string::npos);
    CHECK(text.find("<!-- ga (") != std::string::npos);
    // No map file left behind in the figures' folder: the matrices pride wrote were scratch.
    for (const auto& e : fs::directory_iterator(dir / "figures"))
        CHECK((e.path().extension() == ".png" || e.path().extension() == ".svg"));
    fs::remove_all(dir);
}

TEST_CASE("report: --plots names a whole-map planner and a sampling planner as the notes do", "[report][plots]") {
    if (pride::test::run_pride("list").out.find("ompl:RRTstar") == std::string::npos) {
        WARN("skipped: this build has no OMPL planners");
        return;
    }
    const fs::path dir = fs::temp_directory_path() / ("pride-plots-ompl-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path map = fs::path(PRIDE_SOURCE_DIR) / "examples" / "maps" / "wan2022-10x10.map";
    std::ofstream(dir / "c.toml") << "name = \"ompl\"\nseeds = 2\n[budget]\nevaluations = 500\n"
                                     "[[problem]]\nid = \"map\"\ntype = \"grid\"\nmap = \""
                                  << map.string()
                                  << "\"\nstart = [0, 0]\ngoal = [9, 9]\nobjective = \"length\"\n"
                                     "[[algorithm]]\nid = \"astar\"\ntype = \"astar\"\n"
                                     "[[algorithm]]\nid = \"rrt\"\ntype = \"ompl:RRTstar\"\n"
                                     "[[algorithm]]\nid = \"ga\"\ntype = \"ga\"\npop = 10\n";
    REQUIRE(
        pride::test::run_pride("bench '" + (dir / "c.toml").string() + "' --out '" + (dir / "c.sqlite").string() + "'")
            .status == 0);
    const auto report = pride::test::run_pride("report '" + (dir / "c.sqlite").string() + "' --plots '" +
                                               (dir / "figures").string() + "'");
    INFO(report.err);
    REQUIRE(report.status == 0);
    std::ifstream svg(dir / "figures" / "map-convergence.svg");
    const std::string text((std::istreambuf_iterator<char>(svg)), std::istreambuf_iterator<char>());
    CHECK(text.find("<!-- astar (whole map) -->") != std::string::npos);
    CHECK(text.find("<!-- rrt (final value, no history) -->") != std::string::npos);
    // The report's note names the same planner alone as evaluating nothing.
    CHECK(report.out.find("astar plan") != std::string::npos);
    CHECK(report.out.find("rrt plan") == std::string::npos);
    fs::remove_all(dir);
}

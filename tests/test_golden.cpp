// The golden-results gate: the JSON results (every field but wall_ms) of a fixed set of `pride run`
// and `pride path` commands, recorded before the engine refactor (tests/data/golden/, written by
// scripts/golden_commands.py and the commands' own output), must come out bit for bit the same.
// Commands for the suites and the algorithms added later (instances, BBOB, WOA, HS, IAGA, ICGA,
// IQGA, SITP, the exact iqga optimum, the DE family) are appended after the first 447, recorded when
// they landed.
// Four commands read Moving AI maps, named `$PRIDE_DATA/movingai/...`: without PRIDE_DATA they are
// skipped, with the one line saying so.
// A change of results is a documented fix: the golden file is updated in the same commit, with the
// reason in its message.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include "tests/cli_runner.hpp"

namespace {

std::vector<std::string> read_lines(const std::string& path) {
    std::ifstream in(path);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

std::string without_wall_time(const std::string& json) {
    static const std::regex wall(R"("wall_ms": [^,}]*(, )?)");
    std::string s = std::regex_replace(json, wall, "");
    while (!s.empty() && (s.back() == '\n' || s.back() == '\r')) s.pop_back();
    return s;
}

/// Checks the commands i with i % parts == part: the gate is split in four test cases so that
/// ctest -j runs them side by side (one case took 65 s under the sanitizers, the suite's tail).
void check_golden_part(std::size_t part, std::size_t parts) {
    const std::string dir = std::string(PRIDE_SOURCE_DIR) + "/tests/data/golden/";
    const auto commands = read_lines(dir + "commands.txt");
    const auto expected = read_lines(dir + "expected.jsonl");
    REQUIRE(commands.size() >= 400);
    REQUIRE(commands.size() == expected.size());
    std::size_t differ = 0, checked = 0, skipped = 0;
    // The folder of the Moving AI maps some commands name, looked up (and its absence told) once.
    const std::string marker = "$PRIDE_DATA/";
    std::optional<std::optional<std::filesystem::path>> data;
    for (std::size_t i = part; i < commands.size(); i += parts) {
        // The commands name maps relative to the top of the checkout, or under $PRIDE_DATA.
        std::string command = commands[i];
        if (const auto at = command.find(marker); at != std::string::npos) {
            if (!data) data = pride::test::shared_data("movingai", "Moving AI maps, for the golden commands on them");
            if (!*data) {
                ++skipped;
                continue;
            }
            const std::string root = std::getenv("PRIDE_DATA");
            command.replace(at, marker.size() - 1, "'" + root + "'");
        }
        ++checked;
        const auto r = pride::test::run_pride_in(PRIDE_SOURCE_DIR, command);
        const std::string got = without_wall_time(r.out);
        if (r.status != 0 || got != expected[i]) {
            ++differ;
            INFO("line " << i + 1 << ": pride " << commands[i]);
            INFO("stderr: " << r.err);
            CHECK(r.status == 0);
            CHECK(got == expected[i]);
        }
    }
    CHECK(checked + skipped == (commands.size() - part + parts - 1) / parts);
    CHECK(differ == 0);
}

}  // namespace

TEST_CASE("golden results, part 1 of 4: every recorded run and path command gives the same bits", "[golden]") {
    check_golden_part(0, 4);
}
TEST_CASE("golden results, part 2 of 4: every recorded run and path command gives the same bits", "[golden]") {
    check_golden_part(1, 4);
}
TEST_CASE("golden results, part 3 of 4: every recorded run and path command gives the same bits", "[golden]") {
    check_golden_part(2, 4);
}
TEST_CASE("golden results, part 4 of 4: every recorded run and path command gives the same bits", "[golden]") {
    check_golden_part(3, 4);
}

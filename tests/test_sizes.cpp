// Work and memory that a small input could make unbounded are bounded or refused up front
// (docs/reliability.md, "Sizes before work"): rotated instances, the exact optimum on large maps,
// the history of a huge iteration limit, and the repair connector's remembered joins.
#include <sys/wait.h>

#include <catch2/catch.hpp>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "framework/random.hpp"
#include "problems/grid/connectors.hpp"
#include "tests/cli_runner.hpp"

using pride::test::run_pride;

namespace {

std::string coordinates(int n) {
    std::string x;
    for (int i = 0; i < n; ++i) x += i == 0 ? "0.5" : ",0.5";
    return x;
}

/// `pride ARGS` under an address-space limit of `kib` KiB (what `ulimit -v` sets): its status and
/// stderr.
pride::test::CliOutput run_limited(long kib, const std::string& args) {
    const std::string err = "/tmp/pride-sizes-" + std::to_string(getpid()) + ".err";
    const std::string cmd =
        "ulimit -v " + std::to_string(kib) + "; '" + std::string(PRIDE_EXE) + "' " + args + " >/dev/null 2>" + err;
    const int raw = std::system(("sh -c \"" + cmd + "\"").c_str());
    pride::test::CliOutput r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    std::ifstream f(err);
    r.err.assign(std::istreambuf_iterator<char>(f), {});
    std::remove(err.c_str());
    return r;
}

}  // namespace

TEST_CASE("sizes: a rotated instance beyond dimension 5000 is refused before its rotation is built", "[faults]") {
    for (const std::string problem : {"bbob-f10 --instance 1", "rastrigin --instance 1"}) {
        const auto r = run_pride("eval --problem " + problem + " --x " + coordinates(5001));
        INFO(r.err);
        CHECK(r.status == 2);
        CHECK(r.err.find("a rotated instance is built up to dimension 5000") != std::string::npos);
        CHECK(r.err.find("got 5001") != std::string::npos);
    }
    const auto run = run_pride("run --problem ellipsoid --instance 3 --dim 6000 --algo pso --evals 10");
    CHECK(run.status == 2);
    CHECK(run.err.find("rotated instance") != std::string::npos);
    // Without a rotation the same dimension is evaluated.
    const auto plain = run_pride("eval --problem bbob-f1 --instance 1 --x " + coordinates(5001));
    CHECK(plain.status == 0);
}

TEST_CASE("sizes: the exact optimum on a map too large for memory is refused up front, A* is not", "[faults]") {
    if (PRIDE_UNDER_ASAN) return;  // no address-space limit under ASan (tests/test_support.hpp)
    const std::string map = "/tmp/pride-sizes-" + std::to_string(getpid()) + ".map";
    {
        std::ofstream f(map);
        f << "type octile\nheight 1500\nwidth 1500\nmap\n";
        const std::string row(1500, '.');
        for (int i = 0; i < 1500; ++i) f << row << '\n';
    }
    const std::string path = "path --map " + map + " --start 0,0 --goal 1499,1499 ";
    // 1500 x 1500 cells: the oracle's states take about 405 MB, A*'s records 36 MB, the path
    // scorer's distance field 18 MB.
    const auto exact = run_limited(300 * 1024, path + "--algo exact");
    INFO(exact.err);
    CHECK(exact.status == 2);
    CHECK(exact.err ==
          "pride: exact: the exact optimum on a 1500 x 1500 map needs about 405 MB (423 MB with the rest of the run) "
          "of memory, more than the 315 MB this machine has\n");
    const auto oracle = run_limited(300 * 1024, path + "--algo astar --oracle");
    CHECK(oracle.status == 2);
    CHECK(oracle.err.find("pride: --oracle: the exact optimum on a 1500 x 1500 map") == 0);
    const auto astar = run_limited(300 * 1024, path + "--algo astar");
    INFO(astar.err);
    CHECK(astar.status == 0);
    std::remove(map.c_str());
}

TEST_CASE("sizes: a huge iteration limit is blamed for the history, not the population", "[faults]") {
    const auto r = run_pride("run --problem sphere --dim 2 --algo pso --iters 1000000000000000");
    CHECK(r.status == 2);
    CHECK(r.err.find("pride: --iters: the history of 1000000000000000 iterations needs about") == 0);
}

TEST_CASE("sizes: the repair connector forgets its joins past its bound and gives the same joins", "[grid]") {
    using namespace pride::grid;
    const GridMap map(2000, 2000, std::vector<std::uint8_t>(2000 * 2000, 0), "open");
    RepairConnector remembering, fresh;
    pride::Rng rng(99);
    std::size_t most = 0, longest = 0;
    bool forgot = false;
    for (int k = 0; k < 24000; ++k) {
        const Cell a{static_cast<int>(rng.below(2000)), static_cast<int>(rng.below(2000))};
        const Cell b{static_cast<int>(rng.below(2000)), static_cast<int>(rng.below(2000))};
        int v1 = 0, v2 = 0;
        const auto before = remembering.remembered_cells();
        const auto got = remembering.segment(map, a, b, v1, false);
        const std::vector<std::uint32_t> copy(got.begin(), got.end());
        longest = std::max(longest, copy.size());
        forgot = forgot || remembering.remembered_cells() < before;
        most = std::max(most, remembering.remembered_cells());
        if (k % 500 == 0) {  // the same join, worked out anew
            const auto want = fresh.segment(map, a, b, v2, false);
            CHECK(std::vector<std::uint32_t>(want.begin(), want.end()) == copy);
        }
        if (k % 997 == 0) {  // a join remembered earlier (or forgotten and walked again) is unchanged
            const auto again = remembering.segment(map, a, b, v1, false);
            CHECK(std::vector<std::uint32_t>(again.begin(), again.end()) == copy);
        }
    }
    CHECK(forgot);
    CHECK(most <= (std::size_t{1} << 24) + longest);
}

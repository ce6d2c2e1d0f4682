// Tests of the grid map and scenario readers (problems/grid/map_io.hpp) and of the map conventions
// of shared/spec/grid.md they rely on: both formats, lenient line ends, every error with its
// FILE:LINE:COL, the Moving AI files of shared/data/movingai (sizes, free endpoints and, on a sample,
// the recorded optimal lengths), the bundled maps of examples/maps, random-input robustness, the
// papers' cell numbering (file 002 eq. 2) and obstacle inflation (file 003 section 3.1).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <queue>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "framework/error.hpp"
#include "problems/grid/map.hpp"
#include "problems/grid/map_io.hpp"

using namespace pride::grid;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;
using Catch::Matchers::WithinAbs;

namespace {

namespace fs = std::filesystem;

/// The message of the InputError that f throws; fails the test when f throws nothing or
/// something else.
std::string error_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const pride::InputError& e) {
        return e.what();
    } catch (const std::exception& e) {
        FAIL("not an InputError: " << e.what());
    }
    FAIL("no InputError thrown");
    return {};
}

std::string map_error(const std::string& text) {
    return error_of([&] { (void)parse_map(text, "m.map"); });
}

std::string scen_error(const std::string& text) {
    return error_of([&] { (void)parse_scenario(text, "s.scen"); });
}

bool same_map(const GridMap& a, const GridMap& b) {
    if (a.width() != b.width() || a.height() != b.height()) return false;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            if (a.free({x, y}) != b.free({x, y})) return false;
    return true;
}

/// A file in the temporary directory, removed at the end of the scope.
struct TempFile {
    fs::path path;
    TempFile(const std::string& name, const std::string& content)
        : path(fs::temp_directory_path() / ("pride_test_grid_io_" + std::to_string(::getpid_like()) + "_" + name)) {
        std::ofstream out(path, std::ios::binary);
        out << content;
    }
    ~TempFile() {
        std::error_code ec;
        fs::remove(path, ec);
    }
    static long getpid_like_impl();
};

}  // namespace

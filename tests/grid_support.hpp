#pragma once
// Small helpers shared by the grid tests: hand-drawn maps, bounded random integers, and the
// bundled and random (map, start, goal) instances the property tests run over.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "framework/random.hpp"
#include "problems/grid/grid_problem.hpp"
#include "problems/grid/map.hpp"
#include "problems/grid/map_io.hpp"
#include "tests/test_support.hpp"

namespace pride::test {

/// A map from rows of '.' (free) and '@' (blocked), top row first.
inline grid::GridMap map_of(const std::vector<std::string>& rows) {
    std::vector<std::uint8_t> blocked;
    for (const auto& r : rows)
        for (const char ch : r) blocked.push_back(ch == '@' ? 1 : 0);
    return grid::GridMap(static_cast<int>(rows.front().size()), static_cast<int>(rows.size()), std::move(blocked),
                         "hand");
}

/// The Moving AI scenario files of `dir` ($PRIDE_DATA/movingai: test_support.hpp's shared_data), in name order.
inline std::vector<std::filesystem::path> movingai_scenarios(const std::filesystem::path& dir) {
    namespace fs = std::filesystem;
    std::vector<fs::path> scenarios;
    for (const auto& entry : fs::directory_iterator(dir))
        if (entry.path().extension() == ".scen") scenarios.push_back(entry.path());
    std::sort(scenarios.begin(), scenarios.end());
    return scenarios;
}

/// A uniform integer in [0, n), n > 0.
inline int below(Rng& rng, int n) {
    return static_cast<int>(rng.below(static_cast<std::uint64_t>(n)));
}

/// One planning task: a map, its end points and whether corners may be cut.
struct GridInstance {
    std::shared_ptr<const grid::GridMap> map;
    grid::Cell start, goal;
    bool corner_cutting = false;
};

/// The bundled maps (examples/maps) and every start/goal pair of their scenario files.
inline std::vector<GridInstance> bundled_instances(const std::filesystem::path& maps) {
    std::vector<GridInstance> out;
    for (const std::filesystem::directory_entry& f : std::filesystem::directory_iterator(maps)) {
        if (f.path().extension() != ".map") continue;
        auto map = std::make_shared<const grid::GridMap>(grid::read_map(f.path().string()));
        for (const auto& s : grid::read_scenario(f.path().string() + ".scen")) out.push_back({map, s.start, s.goal});
    }
    return out;
}

/// Random maps 8x8 .. 30x30 with 0-35 % obstacles and a reachable start/goal pair each; every fifth
/// map allows corner cutting, every fourth pair shares a column.
inline std::vector<GridInstance> random_instances(std::uint64_t seed, int maps) {
    Rng rng(seed);
    std::vector<GridInstance> out;
    for (int m = 0; m < maps; ++m) {
        const int w = 8 + below(rng, 23), h = 8 + below(rng, 23);
        std::vector<std::uint8_t> blocked(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
        const double density = 0.35 * rng.uniform();
        for (auto& b : blocked) b = rng.uniform() < density ? 1 : 0;
        auto map = std::make_shared<const grid::GridMap>(w, h, std::move(blocked), "random");
        const bool cc = m % 5 == 4;
        for (int tries = 0; tries < 5000; ++tries) {
            const grid::Cell s{below(rng, w), below(rng, h)};
            grid::Cell g{below(rng, w), below(rng, h)};
            if (m % 4 == 1) g.x = s.x;
            if (!map->free(s) || !map->free(g) || s == g || !grid::reachable_from(*map, s, cc)[map->index(g)]) continue;
            out.push_back({map, s, g, cc});
            break;
        }
    }
    return out;
}

/// The brute-force fronts' turn cost, worked out apart from problems/grid/path.hpp: the angle
/// between two step vectors in whole degrees (the arc cosine of 2 / (sqrt 2 sqrt 2) is not exactly
/// 0 in floating point), and the project's W for it (0, 10 below 90 degrees, 20 at 90, 50 above).
inline double angle_between(int ax, int ay, int bx, int by) {
    const double c = (ax * bx + ay * by) / (std::hypot(ax, ay) * std::hypot(bx, by));
    return std::round(std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / 3.14159265358979323846);
}

inline int w_of_degrees(double theta) {
    if (theta < 1e-9) return 0;
    if (theta < 90 - 1e-9) return 10;
    if (theta < 90 + 1e-9) return 20;
    return 50;
}

}  // namespace pride::test

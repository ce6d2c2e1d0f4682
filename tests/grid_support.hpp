#pragma once
// Small helpers shared by the grid tests: hand-drawn maps and bounded random integers.
#include <cstdint>
#include <string>
#include <vector>

#include "framework/random.hpp"
#include "problems/grid/map.hpp"

namespace pride::test {

/// A map from rows of '.' (free) and '@' (blocked), top row first.
inline grid::GridMap map_of(const std::vector<std::string>& rows) {
    std::vector<std::uint8_t> blocked;
    for (const auto& r : rows)
        for (const char ch : r) blocked.push_back(ch == '@' ? 1 : 0);
    return grid::GridMap(static_cast<int>(rows.front().size()), static_cast<int>(rows.size()), std::move(blocked),
                         "hand");
}

/// A uniform integer in [0, n), n > 0.
inline int below(Rng& rng, int n) {
    return static_cast<int>(rng.below(static_cast<std::uint64_t>(n)));
}

}  // namespace pride::test

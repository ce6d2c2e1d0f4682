// Moving AI scenario files (problems/grid/map_io.hpp: parse_scenario), as `pride scen` reads them:
// every entry accepted has start and goal inside its map and a finite optimum >= 0.
#include <cmath>

#include "fuzz/fuzz_support.hpp"
#include "problems/grid/map_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace pride;
    try {
        for (const auto& e : grid::parse_scenario(fuzz::text(data, size), "fuzz.scen")) {
            fuzz::expect(e.width >= 1 && e.height >= 1, "a scenario side below 1");
            fuzz::expect(e.start.x >= 0 && e.start.x < e.width && e.start.y >= 0 && e.start.y < e.height,
                         "a start outside its map");
            fuzz::expect(e.goal.x >= 0 && e.goal.x < e.width && e.goal.y >= 0 && e.goal.y < e.height,
                         "a goal outside its map");
            fuzz::expect(std::isfinite(e.optimal) && e.optimal >= 0, "an optimum that is not a number >= 0");
        }
    } catch (const InputError&) {
    }
    return 0;
}

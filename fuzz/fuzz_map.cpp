// Maps, Moving AI `.map` and 0/1 matrices (problems/grid/map_io.hpp: parse_map), as `--map` and
// campaign files read them. A map read back from its Moving AI form must be the same map.
#include "fuzz/fuzz_support.hpp"
#include "problems/grid/map_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace pride;
    try {
        const grid::GridMap m = grid::parse_map(fuzz::text(data, size), "fuzz.map");
        const grid::GridMap back = grid::parse_map(grid::to_movingai(m), "fuzz.map");
        fuzz::expect(back.width() == m.width() && back.height() == m.height(), "map sides change on a round trip");
        for (int y = 0; y < m.height(); ++y)
            for (int x = 0; x < m.width(); ++x)
                fuzz::expect(back.free(grid::Cell{x, y}) == m.free(grid::Cell{x, y}), "a cell changes on a round trip");
    } catch (const InputError&) {
    }
    return 0;
}

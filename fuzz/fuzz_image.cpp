// Map images, PNG (libpng) and Netpbm PGM/PPM/PBM/PAM (libnetpbm) (problems/grid/image_map.hpp),
// as `--map` reads a plain image: every map_server mode on the decoded pixels too. The decoders
// report errors by longjmp; a bad file must come out as an InputError, never an exit or a crash.
#include "fuzz/fuzz_support.hpp"
#include "problems/grid/image_map.hpp"
#include "problems/grid/map_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace pride;
    try {
        const grid::Image image = grid::decode_image(fuzz::text(data, size), "fuzz.png");
        fuzz::expect(image.samples.size() == static_cast<std::size_t>(image.width) *
                                                 static_cast<std::size_t>(image.height) *
                                                 static_cast<std::size_t>(image.channels),
                     "sample count does not match the image's size");
        for (const grid::MapMode mode : {grid::MapMode::trinary, grid::MapMode::scale, grid::MapMode::raw}) {
            grid::Occupancy o;
            o.mode = mode;
            o.negate = size % 2 == 1;
            const grid::GridMap m = grid::image_to_map(image, o, "fuzz.png");
            fuzz::expect(m.width() == image.width && m.height() == image.height, "map and image sizes differ");
        }
        // The map as read_map reads it: the same cells as the trinary default.
        const grid::GridMap m = grid::parse_map(fuzz::text(data, size), "fuzz.png");
        fuzz::expect(m.width() == image.width, "parse_map reads another image");
    } catch (const InputError&) {
    }
    return 0;
}

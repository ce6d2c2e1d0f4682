// The YAML of a ROS map_server map (problems/grid/ros_map.hpp: parse_ros_yaml, yaml-cpp), as
// `--map map.yaml` reads it before its image; what it accepts must be a usable world frame, from a
// text within the bound that keeps yaml-cpp's memory in proportion.
#include <cmath>

#include "fuzz/fuzz_support.hpp"
#include "problems/grid/ros_map.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace pride;
    try {
        const auto text = fuzz::text(data, size);
        (void)grid::looks_like_ros_yaml(text);
        const grid::RosMapInfo info = grid::parse_ros_yaml(text, "fuzz.yaml");
        fuzz::expect(text.size() <= 64 * 1024, "a YAML text over the 64 KiB bound accepted");
        fuzz::expect(!info.image.empty(), "an empty image name accepted");
        fuzz::expect(std::isfinite(info.frame.resolution) && info.frame.resolution > 0, "a bad resolution accepted");
        fuzz::expect(info.yaw == 0.0, "a yaw accepted");
        fuzz::expect(info.occupancy.free_thresh <= info.occupancy.occupied_thresh, "thresholds out of order accepted");
        grid::GridMap m(1, 1, std::vector<std::uint8_t>(1, 0), "fuzz");
        m.set_frame(info.frame);  // must not throw: the YAML reader checked it
    } catch (const InputError&) {
    }
    return 0;
}

// ROS map_server maps (see ros_map.hpp).
#include "problems/grid/ros_map.hpp"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "framework/error.hpp"
#include "framework/read_file.hpp"

namespace pride::grid {
namespace {

// An image map file: the cap of the text maps (map_io.cpp), far above any ROS map.
constexpr std::size_t kMaxImageBytes = std::size_t{64} << 20;

/// `text` with control characters as \xNN: yaml-cpp's messages may hold the character they
/// stumbled on (a line end), and a message is one line.
std::string printable(const std::string& text) {
    static constexpr char kHex[] = "0123456789ABCDEF";
    std::string out;
    for (const char c : text) {
        const auto u = static_cast<unsigned char>(c);
        if (u < 0x20 || u == 0x7F)
            out += std::string("\\x") + kHex[u >> 4] + kHex[u & 15];
        else
            out += c;
    }
    return out;
}

/// Throws InputError "name:LINE:COL: what" at the node's place, "name: what" when it has none.
[[noreturn]] void fail(const std::string& name, const YAML::Mark& mark, const std::string& what) {
    if (mark.is_null() || mark.line < 0) throw InputError(name + ": " + printable(what));
    throw InputError(name + ":" + std::to_string(mark.line + 1) + ":" + std::to_string(mark.column + 1) + ": " +
                     printable(what));
}

/// ", got a list" (a mapping, nothing) where a node is not a value; a value is never shown: nothing of a file that did
/// not parse as a map YAML is quoted (map_io.cpp says why).
std::string got(const YAML::Node& node) {
    if (node.IsScalar()) return "";
    return node.IsSequence() ? ", got a list" : node.IsMap() ? ", got a mapping" : ", got nothing";
}

// A map_server YAML names one image and a few numbers: a few hundred bytes. yaml-cpp holds some 140
// times its input's size, so the text is bounded before it builds anything, and so is the nesting
// of flow collections ([ and {), which it follows by recursion.
constexpr std::size_t kMaxYamlBytes = std::size_t{64} << 10;
constexpr int kMaxYamlNesting = 16;

void check_yaml_bounds(std::string_view text, const std::string& name) {
    if (text.size() > kMaxYamlBytes)
        throw InputError(name +
                         ": too large for a map_server YAML file: more than 64 KiB (it names an image and "
                         "a few numbers)");
    int depth = 0;
    std::size_t line = 1;
    for (const char c : text) {
        if (c == '\n') ++line;
        if (c == '[' || c == '{') {
            if (++depth > kMaxYamlNesting)
                throw InputError(name + ":" + std::to_string(line) + ": lists or mappings nested deeper than " +
                                 std::to_string(kMaxYamlNesting) + " levels: not a map_server YAML file");
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
}

std::string number_text(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

double number(const YAML::Node& node, const std::string& key, const std::string& name) {
    if (!node.IsScalar()) fail(name, node.Mark(), key + " must be a number" + got(node));
    double v = 0.0;
    if (!YAML::convert<double>::decode(node, v) || !std::isfinite(v))
        fail(name, node.Mark(), key + " must be a finite number" + got(node));
    return v;
}

double threshold(const YAML::Node& doc, const char* key, double fallback, const std::string& name) {
    const YAML::Node node = doc[key];
    if (!node) return fallback;
    const double v = number(node, key, name);
    if (v < 0.0 || v > 1.0) fail(name, node.Mark(), std::string(key) + " must be in [0, 1], got " + number_text(v));
    return v;
}

}  // namespace

bool looks_like_ros_yaml(std::string_view text) noexcept {
    bool image = false, resolution = false;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        const std::string_view line = text.substr(start, end - start);
        image = image || line.substr(0, 6) == "image:";
        resolution = resolution || line.substr(0, 11) == "resolution:";
        start = end + 1;
    }
    return image && resolution;
}

RosMapInfo parse_ros_yaml(std::string_view text, const std::string& name) {
    check_yaml_bounds(text, name);
    YAML::Node doc;
    try {
        doc = YAML::Load(std::string(text));
    } catch (const YAML::Exception& e) {
        fail(name, e.mark, "bad YAML: " + e.msg);
    }
    if (!doc.IsMap()) fail(name, doc.Mark(), "a map_server YAML file is a mapping (image:, resolution:, origin:, ...)");
    RosMapInfo info;
    try {
        const YAML::Node image = doc["image"];
        if (!image) fail(name, doc.Mark(), "missing `image:` (the map's image file)");
        if (!image.IsScalar() || image.Scalar().empty())
            fail(name, image.Mark(), "image must name the image file" + got(image));
        info.image = image.Scalar();
        if (info.image.find('\0') != std::string::npos) fail(name, image.Mark(), "image holds a NUL byte");

        const YAML::Node res = doc["resolution"];
        if (!res) fail(name, doc.Mark(), "missing `resolution:` (metres per pixel)");
        info.frame.resolution = number(res, "resolution", name);
        if (info.frame.resolution <= 0.0)
            fail(name, res.Mark(),
                 "resolution must be > 0 (metres per pixel), got " + number_text(info.frame.resolution));

        const YAML::Node origin = doc["origin"];
        if (!origin) fail(name, doc.Mark(), "missing `origin:` ([x, y, yaw] of the map's bottom-left corner)");
        if (!origin.IsSequence() || origin.size() != 3)
            fail(name, origin.Mark(),
                 "origin must be [x, y, yaw] (3 numbers)" +
                     (origin.IsSequence() ? ", got " + std::to_string(origin.size()) + " values" : got(origin)));
        info.frame.origin_x = number(origin[0], "origin x", name);
        info.frame.origin_y = number(origin[1], "origin y", name);
        info.yaw = number(origin[2], "origin yaw", name);
        try {
            GridMap::check_frame(info.frame, 1, 1, "");  // what no map can use; its size is checked with the image
        } catch (const InputError& e) {
            fail(name, origin.Mark(), e.detail());
        }
        if (info.yaw != 0.0)
            fail(name, origin[2].Mark(), "origin yaw " + number_text(info.yaw) + " is not supported: rotate the image");

        Occupancy& o = info.occupancy;
        o.occupied_thresh = threshold(doc, "occupied_thresh", o.occupied_thresh, name);
        o.free_thresh = threshold(doc, "free_thresh", o.free_thresh, name);
        if (o.free_thresh > o.occupied_thresh)
            fail(name, doc["free_thresh"].Mark(),
                 "free_thresh " + number_text(o.free_thresh) + " is above occupied_thresh " +
                     number_text(o.occupied_thresh));

        if (const YAML::Node negate = doc["negate"]) {
            const std::string s = negate.IsScalar() ? negate.Scalar() : "";
            if (s == "0" || s == "false" || s == "False")
                o.negate = false;
            else if (s == "1" || s == "true" || s == "True")
                o.negate = true;
            else
                fail(name, negate.Mark(), "negate must be 0 or 1" + got(negate));
        }
        if (const YAML::Node mode = doc["mode"]) {
            const std::string s = mode.IsScalar() ? mode.Scalar() : "";
            if (s == "trinary")
                o.mode = MapMode::trinary;
            else if (s == "scale")
                o.mode = MapMode::scale;
            else if (s == "raw")
                o.mode = MapMode::raw;
            else
                fail(name, mode.Mark(), "mode must be trinary, scale or raw" + got(mode));
        }
    } catch (const YAML::Exception& e) {  // a lookup into a node of the wrong kind
        fail(name, e.mark, "bad YAML: " + e.msg);
    }
    return info;
}

GridMap read_ros_map(const std::string& path, std::string_view text, bool unknown_free) {
    RosMapInfo info = parse_ros_yaml(text, path);
    namespace fs = std::filesystem;
    const fs::path image =
        fs::path(info.image).is_absolute() ? fs::path(info.image) : fs::path(path).parent_path() / info.image;
    std::string bytes;
    try {
        bytes = read_capped_file(image.string(), kMaxImageBytes, "map image", true);  // named in the YAML
    } catch (const InputError& e) {
        throw InputError(path + ": image: " + e.what());
    }
    info.occupancy.unknown_free = unknown_free;
    GridMap map = image_to_map(decode_image(bytes, image.string()), info.occupancy, path);
    map.set_frame(info.frame);
    return map;
}

}  // namespace pride::grid

// Tests of the map images and ROS map_server maps (problems/grid/image_map.hpp, ros_map.hpp), the
// world frame of map.hpp, CSV matrices, and `pride path --start-world/--goal-world`: images made
// here (PGM by hand, PNG with libpng), every map_server mode, negate and threshold boundaries,
// the row / y convention, every error as one line, and the public ROS maps of $PRIDE_DATA/ros.
#include <png.h>
#include <unistd.h>
#include <zlib.h>
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "framework/error.hpp"
#include "problems/grid/image_map.hpp"
#include "problems/grid/map.hpp"
#include "problems/grid/map_io.hpp"
#include "problems/grid/planners/astar.hpp"
#include "problems/grid/ros_map.hpp"
#include "tests/cli_runner.hpp"

using namespace pride::grid;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

namespace fs = std::filesystem;

std::string error_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const pride::InputError& e) {
        return e.what();
    }
    FAIL("no InputError");
    return "";
}

void one_line(const std::string& message) {
    INFO(message);
    CHECK(message.find('\n') == std::string::npos);
    CHECK(!message.empty());
}

/// A folder of its own in the temporary directory, removed at the end of the scope.
struct TempDir {
    fs::path path;
    explicit TempDir(const std::string& name)
        : path(fs::temp_directory_path() / ("pride_test_image_maps_" + std::to_string(::getpid()) + "_" + name)) {
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempDir() { fs::remove_all(path); }
    std::string write(const std::string& file, const std::string& content) const {
        std::ofstream(path / file, std::ios::binary) << content;
        return (path / file).string();
    }
    std::string file(const std::string& name) const { return (path / name).string(); }
};

/// A binary PGM (P5) of 8-bit values, rows top first.
std::string pgm(int w, int h, const std::vector<int>& values, int maxval = 255) {
    std::string s = "P5\n" + std::to_string(w) + " " + std::to_string(h) + "\n" + std::to_string(maxval) + "\n";
    for (int v : values) s += static_cast<char>(v);
    return s;
}

/// A PNG of `channels` 8-bit samples per pixel (1 grey, 2 grey+alpha, 3 RGB, 4 RGBA), by libpng.
std::string png(int w, int h, int channels, const std::vector<int>& samples) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    image.width = static_cast<png_uint_32>(w);
    image.height = static_cast<png_uint_32>(h);
    image.format = channels == 1   ? PNG_FORMAT_GRAY
                   : channels == 2 ? PNG_FORMAT_GA
                   : channels == 3 ? PNG_FORMAT_RGB
                                   : PNG_FORMAT_RGBA;
    std::vector<png_byte> pixels(samples.begin(), samples.end());
    png_alloc_size_t size = 0;
    REQUIRE(png_image_write_to_memory(&image, nullptr, &size, 0, pixels.data(), 0, nullptr));
    std::string out(size, '\0');
    REQUIRE(png_image_write_to_memory(&image, out.data(), &size, 0, pixels.data(), 0, nullptr));
    out.resize(size);
    return out;
}

/// The PNG with its IHDR width and height replaced (and its CRC made right again).
std::string png_with_size(std::string file, std::uint32_t w, std::uint32_t h) {
    const auto put = [&](std::size_t at, std::uint32_t v) {
        for (int k = 0; k < 4; ++k) file[at + k] = static_cast<char>(v >> (24 - 8 * k));
    };
    put(16, w);
    put(20, h);
    const auto crc = crc32(0, reinterpret_cast<const Bytef*>(file.data() + 12), 17);  // "IHDR" + 13 bytes
    put(29, static_cast<std::uint32_t>(crc));
    return file;
}

std::vector<int> blocked_cells(const GridMap& m) {
    std::vector<int> out;
    for (int y = 0; y < m.height(); ++y)
        for (int x = 0; x < m.width(); ++x) out.push_back(m.free({x, y}) ? 0 : 1);
    return out;
}

std::string yaml(const std::string& image, const std::string& extra = "",
                 const std::string& origin = "[1.0, 2.0, 0.0]") {
    return "image: " + image + "\nresolution: 0.5\norigin: " + origin + "\n" + extra;
}

/// nav2's two map_server maps ($PRIDE_DATA/ros), or nothing after the line saying the test is skipped.
std::optional<fs::path> ros_maps() {
    return pride::test::shared_data("ros", "nav2's ROS map_server maps");
}

}  // namespace

TEST_CASE("image maps: a map_saver PGM keeps occupied, free and unknown cells (unknown blocked or free)",
          "[grid][map][image]") {
    // map_saver writes 0 occupied, 254 free, 205 unknown; map_server's default thresholds.
    const std::string file = pgm(3, 1, {0, 254, 205});
    CHECK(blocked_cells(parse_map(file, "m.pgm")) == std::vector<int>{1, 0, 1});
    MapReadOptions free_unknown;
    free_unknown.unknown_free = true;
    CHECK(blocked_cells(parse_map(file, "m.pgm", free_unknown)) == std::vector<int>{1, 0, 0});
    CHECK_FALSE(parse_map(file, "m.pgm").frame().has_value());
    // Plain PGM (P2) and PBM (P1: 1 is black, so blocked) too.
    CHECK(blocked_cells(parse_map("P2\n2 2\n255\n0 255\n255 0\n", "m.pgm")) == std::vector<int>{1, 0, 0, 1});
    CHECK(blocked_cells(parse_map("P1\n3 1\n1 0 1\n", "m.pbm")) == std::vector<int>{1, 0, 1});
    // A colour PPM: the mean of R, G and B.
    CHECK(blocked_cells(parse_map("P3\n2 1\n255\n255 255 0  255 255 255\n", "m.ppm")) == std::vector<int>{1, 0});
}

TEST_CASE("image maps: the image's top row is y = 0, and its world point is at the top", "[grid][map][image]") {
    // 3 x 2 pixels, one black at column 2 of the image's first row.
    const std::string image = pgm(3, 2, {254, 254, 0, 254, 254, 254});
    const GridMap m = parse_map(image, "m.pgm");
    CHECK(blocked_cells(m) == std::vector<int>{0, 0, 1, 0, 0, 0});
    TempDir dir("rows");
    dir.write("m.pgm", image);
    const GridMap w = read_map(dir.write("m.yaml", yaml("m.pgm")));
    REQUIRE(w.frame().has_value());
    CHECK(w.frame()->resolution == 0.5);
    CHECK(w.frame()->origin_x == 1.0);
    CHECK(w.frame()->origin_y == 2.0);
    CHECK_FALSE(w.free({2, 0}));
    // Cell (2, 0): x from 1 + 2 * 0.5, centre 2.25; the top row spans y in 2 + [0.5, 1.0), centre 2.75.
    const WorldPoint p = w.world({2, 0});
    CHECK(p.x == Approx(2.25));
    CHECK(p.y == Approx(2.75));
    CHECK(w.world({0, 1}).y == Approx(2.25));
    CHECK(w.cell_at({2.25, 2.75}) == std::optional<Cell>(Cell{2, 0}));
    // The bottom-left corner is the origin; borders belong to the cell right of or above them.
    CHECK(w.cell_at({1.0, 2.0}) == std::optional<Cell>(Cell{0, 1}));
    CHECK(w.cell_at({1.5, 2.5}) == std::optional<Cell>(Cell{1, 0}));
    CHECK_FALSE(w.cell_at({0.999, 2.2}).has_value());
    CHECK_FALSE(w.cell_at({2.5, 2.2}).has_value());  // x = 1 + 3 * 0.5 is past the last column
    CHECK_FALSE(w.cell_at({1.2, 3.0}).has_value());
    CHECK_FALSE(w.cell_at({NAN, 2.2}).has_value());
    // Inflation keeps the frame.
    CHECK(w.inflated(1).frame() == w.frame());
}

TEST_CASE("image maps: world points and cells round trip", "[grid][map][image]") {
    GridMap m(37, 23, std::vector<std::uint8_t>(37 * 23, 0), "m");
    CHECK_THROWS_AS(m.world({0, 0}), pride::InputError);  // no frame yet
    m.set_frame({0.05, -10.0, -7.83});
    for (int y = 0; y < m.height(); ++y)
        for (int x = 0; x < m.width(); ++x) {
            const WorldPoint p = m.world({x, y});
            CHECK(m.cell_at(p) == std::optional<Cell>(Cell{x, y}));
            CHECK(m.cell_at({p.x - 0.024, p.y + 0.024}) == std::optional<Cell>(Cell{x, y}));
        }
    CHECK_THROWS_AS(m.set_frame({0.0, 0.0, 0.0}), pride::InputError);
    CHECK_THROWS_AS(m.set_frame({-1.0, 0.0, 0.0}), pride::InputError);
    CHECK_THROWS_AS(m.set_frame({1.0, INFINITY, 0.0}), pride::InputError);
    // Frames whose coordinates overflow or whose cells cannot be told apart: refused, the map's
    // size counted (a frame fine for one cell may not be for 37).
    CHECK_THROWS_WITH(m.set_frame({1e308, 0.0, 0.0}), Contains("beyond 1e15 metres"));
    CHECK_THROWS_WITH(m.set_frame({1e-300, 1e300, 0.0}), Contains("beyond 1e15 metres"));
    CHECK_THROWS_WITH(m.set_frame({1e-6, 1e5, 0.0}), Contains("cells could not be told apart"));
    CHECK_NOTHROW(GridMap::check_frame({1e14, 0.0, 0.0}, 1, 1, "m"));
    CHECK_THROWS_WITH(m.set_frame({1e14, 0.0, 0.0}), Contains("beyond 1e15 metres"));
    CHECK_NOTHROW(m.set_frame({0.01, 6.4e6, -3.0e6}));  // centimetres at Earth-centred coordinates
}

TEST_CASE("image maps: map_server modes, negate and thresholds at their boundaries", "[grid][map][image]") {
    TempDir dir("modes");
    // maxval 4: occupancies 1, 0.75, 0.5, 0.25, 0 exactly; a threshold equal to one is not passed.
    dir.write("q.pgm", pgm(5, 1, {0, 1, 2, 3, 4}, 4));
    const auto cells = [&](const std::string& extra, bool unknown_free = false) {
        MapReadOptions o;
        o.unknown_free = unknown_free;
        return blocked_cells(read_map(dir.write("q.yaml", yaml("q.pgm", extra)), o));
    };
    const std::string th = "occupied_thresh: 0.75\nfree_thresh: 0.25\n";
    CHECK(cells(th) == std::vector<int>{1, 1, 1, 1, 0});
    CHECK(cells(th, true) == std::vector<int>{1, 0, 0, 0, 0});
    CHECK(cells(th + "negate: 1\n", true) == std::vector<int>{0, 0, 0, 0, 1});
    CHECK(cells(th + "negate: true\n") == std::vector<int>{0, 1, 1, 1, 1});
    CHECK(cells(th + "mode: trinary\n", true) == std::vector<int>{1, 0, 0, 0, 0});
    // scale: the same on opaque pixels; the scaled costs between the thresholds are unknown here.
    CHECK(cells(th + "mode: scale\n", true) == std::vector<int>{1, 0, 0, 0, 0});
    CHECK(cells(th + "mode: scale\n", false) == std::vector<int>{1, 1, 1, 1, 0});

    // scale with alpha: a pixel that is not opaque is unknown whatever its shade.
    dir.write("a.png", png(3, 1, 2, {0, 255, 254, 255, 0, 128}));
    CHECK(blocked_cells(read_map(dir.write("a.yaml", yaml("a.png", "mode: scale\n")))) == std::vector<int>{1, 0, 1});
    MapReadOptions free_unknown;
    free_unknown.unknown_free = true;
    CHECK(blocked_cells(read_map(dir.write("a.yaml", yaml("a.png", "mode: scale\n")), free_unknown)) ==
          std::vector<int>{1, 0, 0});
    // trinary averages the opacity in: grey 0 fully transparent is (0 + 0 + 0 + 0) / 4, occupied;
    // grey 254 half transparent is (3 * 254 + 128) / 4 = 222.5, occ 0.127: free.
    dir.write("b.png", png(2, 1, 2, {0, 0, 254, 128}));
    CHECK(blocked_cells(read_map(dir.write("b.yaml", yaml("b.png")))) == std::vector<int>{1, 0});

    // raw: the value is an occupancy percentage (0 free, 100 occupied, above 100 unknown); negate ignored.
    dir.write("r.pgm", pgm(5, 1, {0, 19, 50, 100, 255}));
    const std::string raw = "mode: raw\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";
    CHECK(blocked_cells(read_map(dir.write("r.yaml", yaml("r.pgm", raw)), free_unknown)) ==
          std::vector<int>{0, 0, 0, 1, 0});
    CHECK(blocked_cells(read_map(dir.write("r.yaml", yaml("r.pgm", raw)))) == std::vector<int>{0, 0, 1, 1, 1});
    CHECK(blocked_cells(read_map(dir.write("r.yaml", yaml("r.pgm", raw + "negate: 1\n")))) ==
          std::vector<int>{0, 0, 1, 1, 1});
}

TEST_CASE("image maps: PNG colour, palette, 16-bit and interlaced images are read by libpng", "[grid][map][image]") {
    // RGB: the mean of the channels (255, 255, 0) is 170, occ 0.333: unknown, blocked by default.
    CHECK(blocked_cells(parse_map(png(3, 1, 3, {0, 0, 0, 255, 255, 255, 255, 255, 0}), "c.png")) ==
          std::vector<int>{1, 0, 1});
    CHECK(blocked_cells(parse_map(png(2, 2, 1, {0, 255, 255, 0}), "g.png")) == std::vector<int>{1, 0, 0, 1});
    // RGBA, opaque: as RGB in trinary mode, the opacity averaged in (255) keeps white free.
    CHECK(blocked_cells(parse_map(png(2, 1, 4, {0, 0, 0, 255, 255, 255, 255, 255}), "c.png")) ==
          std::vector<int>{1, 0});
    // 16-bit grey and a palette image, written with libpng's full API.
    for (const bool palette : {false, true}) {
        std::string out;
        png_structp p = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
        png_infop info = png_create_info_struct(p);
        png_set_write_fn(
            p, &out,
            [](png_structp q, png_bytep data, png_size_t n) {
                static_cast<std::string*>(png_get_io_ptr(q))->append(reinterpret_cast<char*>(data), n);
            },
            nullptr);
        png_set_IHDR(p, info, 2, 1, palette ? 8 : 16, palette ? PNG_COLOR_TYPE_PALETTE : PNG_COLOR_TYPE_GRAY,
                     PNG_INTERLACE_ADAM7, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
        png_color colours[2] = {{255, 255, 255}, {0, 0, 0}};
        if (palette) png_set_PLTE(p, info, colours, 2);
        png_write_info(p, info);
        png_byte row16[4] = {0xFF, 0xFF, 0x00, 0x00};  // white, black
        png_byte row8[2] = {0, 1};                     // white, black
        png_bytep rows[1] = {palette ? row8 : row16};
        png_write_image(p, rows);  // every pass of the interlacing
        png_write_end(p, nullptr);
        png_destroy_write_struct(&p, &info);
        CHECK(blocked_cells(parse_map(out, "p.png")) == std::vector<int>{0, 1});
    }
}

TEST_CASE("image maps: CSV 0/1 matrices", "[grid][map]") {
    CHECK(blocked_cells(parse_map("0,1,0\n1, 0 ,0\r\n", "m.csv")) == std::vector<int>{0, 1, 0, 1, 0, 0});
    std::string e = error_of([] { (void)parse_map("0,1,0\n1,,0\n", "m.csv"); });
    CHECK(e == "m.csv:2:3: empty matrix cell: expected 0 (free) or 1 (blocked)");
    e = error_of([] { (void)parse_map("0,1,0\n1,2,0\n", "m.csv"); });
    CHECK(e == "m.csv:2:3: matrix cell must be 0 (free) or 1 (blocked)");
    e = error_of([] { (void)parse_map("0,1,0\n1,0\n", "m.csv"); });
    CHECK_THAT(e, StartsWith("m.csv:2:"));
    CHECK_THAT(e, Contains("short matrix row"));
    e = error_of([] { (void)parse_map("0,1,\n", "m.csv"); });
    CHECK_THAT(e, StartsWith("m.csv:1:5: empty matrix cell"));
}

TEST_CASE("image maps: every bad image is one line naming the file, sizes refused before allocation",
          "[grid][map][image]") {
    const std::string good = png(4, 3, 1, std::vector<int>(12, 255));
    std::vector<std::pair<std::string, std::string>> cases = {
        {good.substr(0, good.size() / 2), "m.png: bad PNG: "},
        {good.substr(0, 20), "m.png: bad PNG: "},
        {png_with_size(good, 100000, 100000), "m.png: the image is 100000 x 100000 pixels, more than"},
        {png_with_size(good, 4000, 4000), "m.png: truncated or corrupt"},
        {png_with_size(good, 0, 3), "m.png: bad PNG: "},
        {"P5\n100000 100000\n255\n", "m.png: the image is 100000 x 100000 pixels, more than"},
        {"P5\n3000 3000\n255\nabc", "m.png: truncated or corrupt"},
        {"P5\n4 4\n255\nabc", "m.png: bad Netpbm image: "},
        {"P2\n2 2\n255\n0 1 x 3\n", "m.png: bad Netpbm image: "},
        {"P2\n2 2\n0\n0 0 0 0\n", "m.png: bad Netpbm image: "},
        {"P5 \n", "m.png: bad Netpbm image: "},
        {"P7\nWIDTH 1\nHEIGHT 1\nDEPTH 1\nMAXVAL 255\nENDHDR\na", "m.png: PAM (P7) images are not read"},
    };
    for (const auto& [case_bytes, start] : cases) {
        INFO(start);
        const std::string& bytes = case_bytes;  // clang 14 does not capture structured bindings
        const std::string e = error_of([&] { (void)parse_map(bytes, "m.png"); });
        one_line(e);
        CHECK_THAT(e, StartsWith(start));
    }
    // Fuzzed at random: never anything but an InputError.
    std::mt19937 rng(7);
    for (int k = 0; k < 300; ++k) {
        std::string bytes = k % 2 ? good : pgm(3, 3, std::vector<int>(9, 128));
        for (int j = 0; j < 3; ++j) bytes[rng() % bytes.size()] = static_cast<char>(rng());
        if (k % 3 == 0) bytes.resize(rng() % bytes.size());
        try {
            (void)parse_map(bytes, "m");
        } catch (const pride::InputError& e) {
            one_line(e.what());
        }
    }
}

TEST_CASE("ros maps: the YAML's errors are one line with the file, line and column", "[grid][map][ros]") {
    TempDir dir("yaml");
    dir.write("m.pgm", pgm(2, 2, {0, 254, 254, 254}));
    const auto read = [&](const std::string& text) {
        const std::string path = dir.write("m.yaml", text);
        return error_of([&] { (void)read_map(path); });
    };
    const std::string f = (dir.path / "m.yaml").string();
    CHECK(read(yaml("m.pgm", "", "[1.0, 2.0, 0.3]")) == f + ":3:20: origin yaw 0.3 is not supported: rotate the image");
    CHECK(read("image: m.pgm\nresolution: -0.05\norigin: [0, 0, 0]\n") ==
          f + ":2:13: resolution must be > 0 (metres per pixel), got -0.05");
    CHECK(read("image: m.pgm\nresolution: abc\norigin: [0, 0, 0]\n") ==
          f + ":2:13: resolution must be a finite number");
    CHECK(read("image: m.pgm\nresolution: .nan\norigin: [0, 0, 0]\n") ==
          f + ":2:13: resolution must be a finite number");
    CHECK(read("image: m.pgm\nresolution: 1\norigin: [0, 0]\n") ==
          f + ":3:9: origin must be [x, y, yaw] (3 numbers), got 2 values");
    CHECK(read("image: m.pgm\nresolution: 1\n") ==
          f + ":1:1: missing `origin:` ([x, y, yaw] of the map's bottom-left corner)");
    CHECK(read(yaml("m.pgm", "mode: fancy\n")) == f + ":4:7: mode must be trinary, scale or raw");
    CHECK(read(yaml("m.pgm", "negate: 2\n")) == f + ":4:9: negate must be 0 or 1");
    CHECK(read(yaml("m.pgm", "occupied_thresh: 1.5\n")) == f + ":4:18: occupied_thresh must be in [0, 1], got 1.5");
    CHECK(read(yaml("m.pgm", "occupied_thresh: 0.2\nfree_thresh: 0.3\n")) ==
          f + ":5:14: free_thresh 0.3 is above occupied_thresh 0.2");
    CHECK(read(yaml("m.pgm", "origin2: [1, 2\n")).rfind(f + ":", 0) == 0);  // unclosed flow sequence
    CHECK_THAT(read(yaml("m.pgm", "origin2: [1, 2\n")), Contains("bad YAML: "));
    CHECK(read(yaml("[a, b]")) == f + ":1:8: image must name the image file, got a list");
    CHECK(read("image: m.pgm\nresolution: 1e308\norigin: [0, 0, 0]\n") ==
          f + ":3:9: the world frame reaches beyond 1e15 metres (origin plus the map's size times the resolution)");
    CHECK_THAT(read("image: m.pgm\nresolution: 1e-300\norigin: [1e10, 0, 0]\n"),
               StartsWith(f + ":3:9: the resolution is too small beside the origin"));
    // A 6e14 m cell passes the YAML (one cell), not the 2 x 2 image: the map's name, no line.
    CHECK_THAT(read("image: m.pgm\nresolution: 6e14\norigin: [0, 0, 0]\n"), Contains("beyond 1e15 metres"));
    // Bounded before yaml-cpp builds anything: size and flow nesting.
    CHECK(read(yaml("m.pgm", "# " + std::string(70000, 'x') + "\n")) ==
          f + ": too large for a map_server YAML file: more than 64 KiB (it names an image and a few numbers)");
    CHECK(read(yaml("m.pgm", "deep: " + std::string(17, '[') + std::string(17, ']') + "\n")) ==
          f + ":4: lists or mappings nested deeper than 16 levels: not a map_server YAML file");
    CHECK_NOTHROW(
        read_map(dir.write("m.yaml", yaml("m.pgm", "deep: " + std::string(16, '[') + std::string(16, ']') + "\n"))));
    // The image: relative to the YAML's folder (whatever the working directory), or missing.
    CHECK(read(yaml("nothere.pgm")) ==
          f + ": image: " + (dir.path / "nothere.pgm").string() + ": cannot open: No such file or directory");
    dir.write("bad.pgm", "P5\n2 2\n255\nab");
    CHECK_THAT(read(yaml("bad.pgm")), StartsWith((dir.path / "bad.pgm").string() + ": bad Netpbm image: "));
    dir.write("text.pgm", "hello");
    CHECK(read(yaml("text.pgm")) ==
          (dir.path / "text.pgm").string() + ": not a PNG or Netpbm (PGM, PPM, PBM, PAM) image");
    fs::create_directories(dir.path / "sub");
    dir.write("sub/m.pgm", pgm(1, 1, {0}));
    const GridMap sub = read_map(dir.write("sub/m.yaml", yaml("m.pgm")));
    CHECK(blocked_cells(sub) == std::vector<int>{1});
    CHECK(sub.name() == (dir.path / "sub" / "m.yaml").string());
    const GridMap absolute = read_map(dir.write("abs.yaml", yaml((dir.path / "sub" / "m.pgm").string())));
    CHECK(blocked_cells(absolute) == std::vector<int>{1});
    // Defaults: thresholds, negate and mode may be left out; other keys are ignored.
    CHECK(blocked_cells(read_map(dir.write("d.yaml", yaml("m.pgm", "comment: hi\n")))) == std::vector<int>{1, 0, 0, 0});
    // parse_map reads no file: a YAML given as text is refused.
    const std::string e = error_of([] { (void)parse_map("image: m.pgm\nresolution: 1\n", "t.yaml"); });
    CHECK_THAT(e, StartsWith("t.yaml: a ROS map_server YAML file names its image file"));
    // Random damage to a YAML: an InputError, one line, or a map.
    std::mt19937 rng(3);
    const std::string text = yaml("m.pgm", "occupied_thresh: 0.65\nfree_thresh: 0.196\nnegate: 0\n");
    const std::string_view damage = "[]{}:,-#&*!|>'\"%@` \n0.9e";
    for (int k = 0; k < 300; ++k) {
        std::string t = text;
        for (int j = 0; j < 2; ++j) t[rng() % t.size()] = damage[rng() % damage.size()];
        try {
            (void)parse_ros_yaml(t, "m.yaml");
        } catch (const pride::InputError& err) {
            one_line(err.what());
        }
    }
}

TEST_CASE("ros maps: the public nav2 maps load with their frames, and A* crosses them", "[grid][map][ros]") {
    const auto ros = ros_maps();
    if (!ros) return;
    const GridMap sandbox = read_map((*ros / "tb3_sandbox.yaml").string());
    CHECK(sandbox.width() == 384);
    CHECK(sandbox.height() == 384);
    REQUIRE(sandbox.frame().has_value());
    CHECK(sandbox.frame()->resolution == 0.05);
    CHECK(sandbox.frame()->origin_x == -10.0);
    CHECK(sandbox.frame()->origin_y == -10.0);
    const GridMap depot = read_map((*ros / "depot.yaml").string());
    CHECK(depot.width() == 604);
    CHECK(depot.height() == 307);
    CHECK(depot.frame()->origin_x == -7.14);

    // The cells against a decoder of this test's own (the P5 bytes, map_server's formula).
    for (const auto& [name, free_thresh] : {std::pair{"tb3_sandbox", 0.196}, std::pair{"depot", 0.25}}) {
        std::ifstream in(*ros / (std::string(name) + ".pgm"), std::ios::binary);
        const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        const GridMap& m = std::string(name) == "depot" ? depot : sandbox;
        const std::size_t data = bytes.size() - m.size();  // 8-bit pixels after the header
        std::size_t blocked = 0, occupied = 0;
        for (std::size_t i = 0; i < m.size(); ++i) {
            const double occ = (255.0 - static_cast<unsigned char>(bytes[data + i])) / 255.0;
            const bool b = !(occ < free_thresh);  // occupied or unknown
            blocked += b;
            occupied += occ > 0.65;
            REQUIRE(m.free_index(i) == !b);
        }
        CHECK(occupied > 0);
        CHECK(blocked < m.size());
    }
    // (-2, -0.5) m is free in the sandbox (where the TurtleBot 3 starts), and so is a point 1.5 m away.
    const auto s = sandbox.cell_at({-2.0, -0.5}), g = sandbox.cell_at({-0.5, 0.5});
    REQUIRE(s.has_value());
    REQUIRE(g.has_value());
    CHECK(sandbox.free(*s));
    CHECK(sandbox.free(*g));
}

TEST_CASE("pride path: --start-world and --goal-world on a map_server map, path_world in the output",
          "[grid][map][ros][cli]") {
    using pride::test::expect_input_error;
    // A map without a frame has no path_world.
    const std::string movingai = std::string(PRIDE_SOURCE_DIR) + "/examples/maps/wan2022-10x10.map";
    const auto plain =
        pride::test::run_pride("path --map '" + movingai + "' --start 0,0 --goal 9,9 --algo astar --json");
    REQUIRE(plain.status == 0);
    CHECK_THAT(plain.out, !Contains("path_world"));
    expect_input_error("path --map '" + movingai + "' --start-world 0,0 --goal 9,9 --algo astar",
                       {"--start-world", "has no world frame", "--start"});

    // nav2's sandbox map, where it is at hand.
    if (const auto ros = ros_maps()) {
        const std::string map = (*ros / "tb3_sandbox.yaml").string();
        const auto r = pride::test::run_pride("path --map '" + map +
                                              "' --start-world -2,-0.5 --goal-world -0.5,0.5 --algo astar --json");
        INFO(r.err);
        REQUIRE(r.status == 0);
        CHECK_THAT(r.out, Contains("\"path_world\": [[-1.975, -0.475], "));
        CHECK_THAT(r.out, Contains("[-0.475, 0.525]]"));
        const auto text =
            pride::test::run_pride("path --map '" + map + "' --start 160,193 --goal 190,173 --algo astar");
        REQUIRE(text.status == 0);
        CHECK_THAT(text.out, Contains("path_world      [[-1.975, -0.475], "));
        expect_input_error("path --map '" + map + "' --start-world 30,0 --goal-world 0,0 --algo astar",
                           {"--start-world", "outside the map", "[-10, 9.2)"});
        // (0, 0) m is a blocked cell of the sandbox (named since blocked world points are refused
        // at their option): the start is a free point, so the goal's syntax is what fails.
        expect_input_error("path --map '" + map + "' --start-world -2,-0.5 --goal-world 0:0 --algo astar",
                           {"--goal-world"});
        expect_input_error("path --map '" + map + "' --start-world 0,0 --goal-world -0.5,0.5 --algo astar",
                           {"--start-world: the point (0, 0) is in cell (200,183), a blocked cell of"});
        expect_input_error("path --map '" + map + "' --goal-world 0,0 --algo astar", {"--start", "--start-world"});
        expect_input_error("path --map '" + map + "' --start 1,1 --start-world 0,0 --goal 2,2 --algo astar",
                           {"--start"});
    }
    // Bad image files are one line too, exit status 2.
    const TempDir dir("cli");
    const std::string bad = dir.write("bad.png", "\x89PNG\r\n\x1a\nxx");
    expect_input_error("path --map '" + bad + "' --start 0,0 --goal 1,1 --algo astar", {bad, "bad PNG"});
    dir.write("u.pgm", pgm(3, 1, {254, 205, 254}));
    const std::string u = dir.write("u.yaml", yaml("u.pgm"));
    expect_input_error("path --map '" + u + "' --start 0,0 --goal 2,0 --algo astar");
    const auto through =
        pride::test::run_pride("path --map '" + u + "' --start 0,0 --goal 2,0 --algo astar --unknown-free");
    CHECK(through.status == 0);
    // pride pareto and pride front read maps the same way: the unknown cell blocks the only way,
    // unless --unknown-free (then the front is the one straight path).
    expect_input_error("pareto --map '" + u + "' --start 0,0 --goal 2,0 --objectives length,turns",
                       {"--goal", "cannot be reached"});
    const auto exact = pride::test::run_pride("pareto --map '" + u +
                                              "' --start 0,0 --goal 2,0 --objectives length,turns --unknown-free");
    INFO(exact.err);
    CHECK(exact.status == 0);
    CHECK_THAT(exact.out, Contains("\n2 0"));
    const auto front = pride::test::run_pride("front --algo nsga2 --map '" + u +
                                              "' --start 0,0 --goal 2,0 --encoding chain --evals 400 --unknown-free");
    INFO(front.err);
    CHECK(front.status == 0);
    CHECK_THAT(front.out, Contains("exact front  1 of its 1 points found"));
    expect_input_error("front --algo nsga2 --problem zdt1 --unknown-free", {"--unknown-free", "--map"});
}

TEST_CASE("image maps: a campaign reads a map_server map with unknown_free, and its definition says so",
          "[maps][ros][bench]") {
    const TempDir dir("bench");
    dir.write("u.pgm", pgm(3, 1, {254, 205, 254}));
    const std::string u = dir.write("u.yaml", yaml("u.pgm"));
    const auto campaign = [&](const std::string& extra) {
        // A* alone: no budget (a campaign of planners refuses one it would not use).
        return "name = \"u\"\nseeds = 1\n[[problem]]\nid = \"u\"\ntype = \"grid\"\nmap = "
               "\"" +
               u + "\"\nstart = [0, 0]\ngoal = [2, 0]\n" + extra + "[[algorithm]]\nid = \"a\"\ntype = \"astar\"\n";
    };
    // Unknown cells blocked (the default): the goal cannot be reached, refused before any run.
    const std::string blocked = dir.write("blocked.toml", campaign(""));
    pride::test::expect_input_error("bench '" + blocked + "' --out '" + dir.file("b.sqlite") + "'",
                                    {"cannot be reached"});
    const std::string through = dir.write("free.toml", campaign("unknown_free = true\n"));
    const auto run = pride::test::run_pride("bench '" + through + "' --out '" + dir.file("f.sqlite") + "'");
    INFO(run.err);
    REQUIRE(run.status == 0);
    // The store's problem definition (what resumes and reports read) names the setting.
    std::string definition;
    {
        FILE* pipe = popen(("sqlite3 '" + dir.file("f.sqlite") + "' 'SELECT definition FROM problems'").c_str(), "r");
        REQUIRE(pipe);
        char buffer[512];
        while (fgets(buffer, sizeof buffer, pipe)) definition += buffer;
        CHECK(pclose(pipe) == 0);
    }
    CHECK_THAT(definition, Contains(" unknown_free true"));
    const std::string wrong = dir.write("wrong.toml", campaign("unknown_free = 1\n"));
    pride::test::expect_input_error("bench '" + wrong + "' --out '" + dir.file("w.sqlite") + "'",
                                    {"wrong.toml:9", "'unknown_free' must be true or false"});
}

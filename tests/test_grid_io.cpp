// Tests of the grid map and scenario readers (problems/grid/map_io.hpp) and of the map conventions
// of docs/grid.md they rely on: both formats, lenient line ends, every error with its
// FILE:LINE:COL, the Moving AI files of $PRIDE_DATA/movingai (sizes, free endpoints and, on a sample,
// the recorded optimal lengths), the bundled maps of examples/maps, random-input robustness, the
// papers' cell numbering (Zhang et al. 2025, eq. 2) and obstacle inflation (Cai and Du 2021, section 3.1).
#include <unistd.h>
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
#include "tests/test_support.hpp"

using namespace pride::grid;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

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
        : path(fs::temp_directory_path() / ("pride_test_grid_io_" + std::to_string(::getpid()) + "_" + name)) {
        std::ofstream out(path, std::ios::binary);
        out << content;
    }
    TempFile(const TempFile&) = delete;
    TempFile& operator=(const TempFile&) = delete;
    ~TempFile() {
        std::error_code ec;
        fs::remove(path, ec);
    }
    std::string str() const { return path.string(); }
};

/// Optimal octile length from a to b (no corner cutting, as GridMap::legal_step), by a plain
/// Dijkstra written here so that the readers' conventions are checked against recorded lengths
/// without depending on the library's own search; -1 when b cannot be reached.
double octile_distance(const GridMap& map, Cell a, Cell b) {
    std::vector<double> dist(map.size(), std::numeric_limits<double>::infinity());
    using Item = std::pair<double, std::size_t>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
    dist[map.index(a)] = 0.0;
    open.push({0.0, map.index(a)});
    while (!open.empty()) {
        const auto [d, i] = open.top();
        open.pop();
        if (d > dist[i]) continue;
        const Cell c = map.cell(i);
        if (c == b) return d;
        for (int dir = 0; dir < 8; ++dir) {
            if (!map.legal_step(c, dir)) continue;
            const Cell n{c.x + kDx[dir], c.y + kDy[dir]};
            const double nd = d + (is_diagonal(dir) ? std::sqrt(2.0) : 1.0);
            if (nd < dist[map.index(n)]) {
                dist[map.index(n)] = nd;
                open.push({nd, map.index(n)});
            }
        }
    }
    return -1.0;
}

const std::string kHeader = "type octile\nheight 2\nwidth 3\nmap\n";  // rows are lines 5 and 6

}  // namespace

// ---------------------------------------------------------------------------------------------
// Reading what is right

TEST_CASE("grid io: Moving AI map, characters and the (x, y) convention", "[grid][io]") {
    const GridMap m = parse_map("type octile\nheight 3\nwidth 4\nmap\n.GS@\nOTW.\n....\n", "m.map");
    REQUIRE(m.width() == 4);
    REQUIRE(m.height() == 3);
    CHECK(m.name() == "m.map");
    // x is the column from the left, y the row from the first map line downwards.
    CHECK(m.free({0, 0}));
    CHECK(m.free({1, 0}));        // G
    CHECK(m.free({2, 0}));        // S
    CHECK_FALSE(m.free({3, 0}));  // @
    CHECK_FALSE(m.free({0, 1}));  // O
    CHECK_FALSE(m.free({1, 1}));  // T
    CHECK_FALSE(m.free({2, 1}));  // W
    CHECK(m.free({3, 1}));
    for (int x = 0; x < 4; ++x) CHECK(m.free({x, 2}));
}

TEST_CASE("grid io: both formats give the same map", "[grid][io]") {
    const GridMap movingai = parse_map("type octile\nheight 3\nwidth 4\nmap\n..@.\n@...\n.@@.\n", "a.map");
    const GridMap spaced = parse_map("0 0 1 0\n1 0 0 0\n0 1 1 0\n", "b.txt");
    const GridMap packed = parse_map("0010\n1000\n0110", "c");
    const GridMap tabbed = parse_map("  0\t0 1  0\n1 0\t0 0\t\n0 1 1 0\r\n\r\n", "d");
    CHECK(same_map(movingai, spaced));
    CHECK(same_map(movingai, packed));
    CHECK(same_map(movingai, tabbed));
    CHECK(same_map(movingai, parse_map(to_movingai(packed), "e")));
    CHECK(to_movingai(movingai) == "type octile\nheight 3\nwidth 4\nmap\n..@.\n@...\n.@@.\n");
    // The format comes from the content, not the name: a matrix in a file called .map is a matrix.
    CHECK(same_map(movingai, parse_map("0010\n1000\n0110\n", "looks-like.map")));
    // A one-column matrix.
    const GridMap column = parse_map("0\n1\n0\n", "col");
    CHECK(column.width() == 1);
    CHECK(column.height() == 3);
    CHECK_FALSE(column.free({0, 1}));
}

TEST_CASE("grid io: CRLF, trailing blanks, final newline, blank lines and BOM are accepted", "[grid][io]") {
    const GridMap plain = parse_map(kHeader + "...\n.@.\n", "m.map");
    const std::vector<std::string> variants = {
        "type octile\r\nheight 2\r\nwidth 3\r\nmap\r\n...\r\n.@.\r\n",
        "type octile \nheight 2\t\nwidth 3  \t\nmap \n... \n.@.\t\t\n",
        "type octile \r\nheight 2\t\r\nwidth 3 \r\nmap\r\n...  \r\n.@. \r\n",
        kHeader + "...\n.@.",
        kHeader + "...\n.@.\n\n\n",
        kHeader + "...\n.@.\r\n\r\n \r\n\t\n",
        "\n\n" + kHeader + "...\n.@.\n",
        "type  octile\nheight\t2\n  width 3\nmap\n...\n.@.\n",
        "\xEF\xBB\xBF" + kHeader + "...\n.@.\n",
    };
    for (const auto& text : variants) {
        INFO(text);
        CHECK(same_map(plain, parse_map(text, "m.map")));
    }
    CHECK(same_map(plain, parse_map("000\r\n010  \r\n\r\n", "m.txt")));
    CHECK(same_map(plain, parse_map("0 0 0 \t\r\n0 1 0", "m.txt")));
}

// ---------------------------------------------------------------------------------------------
// Errors: every one names the file, the line and (where it makes sense) the column

TEST_CASE("grid io: unknown characters are placed and their kind named, never shown", "[grid][io][errors]") {
    // A map path may name any readable file: its errors give where and what was expected, nothing
    // of what it holds.
    auto e = map_error(kHeader + "...\n.x.\n");
    CHECK(e == "m.map:6:2: unknown map character (a character) in map row 2 (free: . G S, blocked: @ O T W)");
    e = map_error(kHeader + "..#\n...\n");
    CHECK_THAT(e, StartsWith("m.map:5:3: "));
    CHECK_THAT(e, !Contains("#"));
    e = map_error(kHeader + "...\n.\x01.\n");
    CHECK_THAT(e, StartsWith("m.map:6:2: "));
    CHECK_THAT(e, Contains("a control character"));
    e = map_error(kHeader + "...\n.\x7f.\n");
    CHECK_THAT(e, Contains("a control character"));
    e = map_error(kHeader + "...\n.\t.\n");
    CHECK_THAT(e, StartsWith("m.map:6:2: "));
    CHECK_THAT(e, Contains("tab"));
    e = map_error(kHeader + " ..\n...\n");
    CHECK_THAT(e, StartsWith("m.map:5:1: "));
    CHECK_THAT(e, Contains("space"));
    // Valid UTF-8 that is not a map character: the column counts characters, not bytes.
    e = map_error(kHeader + "...\n.\xC3\xA9.\n");
    CHECK_THAT(e, StartsWith("m.map:6:2: "));
    CHECK_THAT(e, !Contains("U+00E9"));
    e = map_error(kHeader + "...\n\xE2\x96\x88..\n");  // a block character
    CHECK_THAT(e, StartsWith("m.map:6:1: "));
    CHECK_THAT(e, !Contains("U+2588"));
}

TEST_CASE("grid io: short, long and empty rows say expected against got", "[grid][io][errors]") {
    auto e = map_error(kHeader + "...\n..\n");
    CHECK_THAT(e, StartsWith("m.map:6:3: "));
    CHECK_THAT(e, Contains("short row") && Contains("expected 3") && Contains("got 2"));
    e = map_error(kHeader + "....\n...\n");
    CHECK_THAT(e, StartsWith("m.map:5:4: "));
    CHECK_THAT(e, Contains("long row") && Contains("expected 3") && Contains("got 4"));
    e = map_error(kHeader + "\n...\n");
    CHECK_THAT(e, StartsWith("m.map:5:1: "));
    CHECK_THAT(e, Contains("empty row") && Contains("expected 3"));
    // Trailing blanks are not cells: "..  " is a short row, not a long one.
    e = map_error(kHeader + "..  \n...\n");
    CHECK_THAT(e, StartsWith("m.map:5:3: "));
    CHECK_THAT(e, Contains("got 2"));
}

TEST_CASE("grid io: missing, malformed and misordered header lines", "[grid][io][errors]") {
    auto e = map_error("height 2\nwidth 3\nmap\n...\n...\n");
    CHECK_THAT(e, StartsWith("m.map:1:1: "));
    CHECK_THAT(e, Contains("missing") && Contains("`type octile`"));
    e = map_error("type octile\nwidth 3\nheight 2\nmap\n...\n...\n");
    CHECK_THAT(e, StartsWith("m.map:2:1: "));
    CHECK_THAT(e, Contains("out of order") && Contains("`height H`"));
    e = map_error("type octile\nheight 2\nmap\n...\n...\n");
    CHECK_THAT(e, StartsWith("m.map:3:1: "));
    CHECK_THAT(e, Contains("missing") && Contains("`width W`"));
    e = map_error("type octile\nheight 2\nwidth 3\n...\n...\n");
    CHECK_THAT(e, StartsWith("m.map:4"));
    CHECK_THAT(e, Contains("missing") && Contains("`map`"));
    e = map_error("type octile\nheight x\nwidth 3\nmap\n...\n...\n");
    CHECK_THAT(e, StartsWith("m.map:2:8: "));
    CHECK_THAT(e, Contains("height") && !Contains("x"));
    e = map_error("type octile\nheight 2\nwidth 3.5\nmap\n...\n...\n");
    CHECK_THAT(e, StartsWith("m.map:3:7: "));
    CHECK_THAT(e, Contains("width") && !Contains("3.5"));
    e = map_error("type octile\nheight 0\nwidth 3\nmap\n");
    CHECK_THAT(e, StartsWith("m.map:2:8: "));
    CHECK_THAT(e, Contains("at least 1"));
    e = map_error("type octile\nheight -4\nwidth 3\nmap\n");
    CHECK_THAT(e, StartsWith("m.map:2:8: "));
    e = map_error("type octile\nheight 99999999999\nwidth 3\nmap\n");
    CHECK_THAT(e, StartsWith("m.map:2:8: "));
    CHECK_THAT(e, Contains("too large"));
    e = map_error("type octile\nheight\nwidth 3\nmap\n");
    CHECK_THAT(e, StartsWith("m.map:2:"));
    CHECK_THAT(e, Contains("needs a value"));
    e = map_error("type octile\nheight 2 3\nwidth 3\nmap\n");
    CHECK_THAT(e, StartsWith("m.map:2:10: "));
    CHECK_THAT(e, Contains("unexpected text after `height` and its value") && !Contains("3"));
    e = map_error("type grid\nheight 2\nwidth 3\nmap\n...\n...\n");
    CHECK_THAT(e, StartsWith("m.map:1:6: "));
    CHECK_THAT(e, Contains("unsupported map type: only `type octile` is read") && !Contains("grid"));
    e = map_error("type octile\ntype octile\nheight 2\nwidth 3\nmap\n");
    CHECK_THAT(e, StartsWith("m.map:2:1: "));
    CHECK_THAT(e, Contains("duplicate"));
    e = map_error("type octile\nheight 2\nwidth 3\nmap x\n...\n...\n");
    CHECK_THAT(e, StartsWith("m.map:4:5: "));
    e = map_error("type octile\nheight 2\n");
    CHECK_THAT(e, StartsWith("m.map:3: "));
    CHECK_THAT(e, Contains("missing") && Contains("`width W`"));
    e = map_error("type octile\n\nheight 2\nwidth 3\nmap\n");
    CHECK_THAT(e, StartsWith("m.map:2: "));
    CHECK_THAT(e, Contains("empty line"));
    e = map_error("...\n.@.\n");
    CHECK_THAT(e, StartsWith("m.map:1: "));
    CHECK_THAT(e, Contains("missing Moving AI header"));
    e = map_error("Type octile\nheight 2\nwidth 3\nmap\n...\n...\n");
    CHECK_THAT(e, StartsWith("m.map:1:1: "));
    CHECK_THAT(e, Contains("not a map"));
}

TEST_CASE("grid io: a size that disagrees with the rows", "[grid][io][errors]") {
    auto e = map_error(kHeader + "...\n");
    CHECK_THAT(e, StartsWith("m.map:6: "));
    CHECK_THAT(e, Contains("too few rows") && Contains("height 2"));
    e = map_error(kHeader + "...\n\n\n");  // trailing blank lines are not rows
    CHECK_THAT(e, StartsWith("m.map:6: "));
    CHECK_THAT(e, Contains("too few rows"));
    e = map_error(kHeader);
    CHECK_THAT(e, StartsWith("m.map:5: "));
    CHECK_THAT(e, Contains("too few rows"));
    e = map_error(kHeader + "...\n...\n...\n");
    CHECK_THAT(e, StartsWith("m.map:7: "));
    CHECK_THAT(e, Contains("too many rows"));
    e = map_error(kHeader + "...\n...\n\n\n...\n");
    CHECK_THAT(e, StartsWith("m.map:9: "));
    CHECK_THAT(e, Contains("too many rows"));
    // The width disagreeing with the rows is the short/long row error.
    e = map_error("type octile\nheight 2\nwidth 4\nmap\n...\n...\n");
    CHECK_THAT(e, StartsWith("m.map:5:4: "));
    CHECK_THAT(e, Contains("expected 4"));
}

TEST_CASE("grid io: empty and binary files", "[grid][io][errors]") {
    auto e = map_error("");
    CHECK_THAT(e, StartsWith("m.map:1: "));
    CHECK_THAT(e, Contains("empty"));
    e = map_error("\n \r\n\t\n");
    CHECK_THAT(e, StartsWith("m.map:1: "));
    CHECK_THAT(e, Contains("blank"));
    e = map_error(kHeader + std::string("..\0\n...\n", 8));
    CHECK_THAT(e, StartsWith("m.map:5:3: "));
    CHECK_THAT(e, Contains("NUL") && Contains("binary"));
    e = map_error(std::string("\0\0\0\0", 4));
    CHECK_THAT(e, StartsWith("m.map:1:1: "));
    CHECK_THAT(e, Contains("NUL"));
    e = map_error(kHeader + "...\n.\xff.\n");
    CHECK_THAT(e, StartsWith("m.map:6:2: "));
    CHECK_THAT(e, Contains("not UTF-8") && !Contains("\\xFF"));
    // A PNG signature makes it an image (image_map.hpp): a cut one is a bad PNG, not text.
    e = map_error("\x89PNG\r\n\x1a\n");
    CHECK_THAT(e, StartsWith("m.map: "));
    CHECK_THAT(e, Contains("PNG") && Contains("truncated"));
    e = map_error("\x89PNX\r\n\x1a\n");
    CHECK_THAT(e, StartsWith("m.map:1:1: "));
    CHECK_THAT(e, Contains("not UTF-8") && !Contains("\\x89"));
    e = map_error("type octile\nheight 2\nwidth 3\nmap\n..\xC3");  // cut inside a UTF-8 sequence
    CHECK_THAT(e, StartsWith("m.map:5:3: "));
    // Old Mac line ends leave carriage returns inside a line.
    e = map_error("type octile\rheight 2\rwidth 3\rmap\r...\r...\r");
    CHECK_THAT(e, StartsWith("m.map:1:12: "));
    CHECK_THAT(e, Contains("carriage return"));
    e = map_error("hello world\n");
    CHECK_THAT(e, StartsWith("m.map:1:1: "));
    CHECK_THAT(e, Contains("not a map"));
}

TEST_CASE("grid io: matrix errors", "[grid][io][errors]") {
    auto e = map_error("0 1 0\n0 2 0\n");
    CHECK_THAT(e, StartsWith("m.map:2:3: "));
    CHECK_THAT(e, Contains("0 (free) or 1 (blocked)") && !Contains("`2`"));
    e = map_error("010\n0x0\n");
    CHECK_THAT(e, StartsWith("m.map:2:2: "));
    CHECK_THAT(e, !Contains("'x'"));
    e = map_error("0 10\n0 0\n");  // a token of two characters is not two cells
    CHECK_THAT(e, StartsWith("m.map:1:3: "));
    CHECK_THAT(e, !Contains("10"));
    e = map_error("2 0\n0 0\n");
    CHECK_THAT(e, StartsWith("m.map:1:1: "));
    e = map_error("010\n00\n");
    CHECK_THAT(e, StartsWith("m.map:2:3: "));
    CHECK_THAT(e, Contains("short") && Contains("expected 3") && Contains("got 2") && Contains("line 1"));
    e = map_error("0 1 0\n0 0 0\n0 0 0 1\n");
    CHECK_THAT(e, StartsWith("m.map:3:7: "));
    CHECK_THAT(e, Contains("long") && Contains("expected 3") && Contains("got 4"));
    e = map_error("010\n\n000\n");
    CHECK_THAT(e, StartsWith("m.map:2: "));
    CHECK_THAT(e, Contains("empty row"));
    // Commas make a CSV matrix (0,1,0 is a map); an empty field or another separator is an error.
    e = map_error("0,,1\n");
    CHECK_THAT(e, StartsWith("m.map:1:3: "));
    CHECK_THAT(e, Contains("empty matrix cell"));
    e = map_error("0;1\n");
    CHECK_THAT(e, StartsWith("m.map:1:2: "));
    CHECK_THAT(e, !Contains(";"));
    e = map_error("01\xC3\xA9\n");
    CHECK_THAT(e, StartsWith("m.map:1:3: "));
    CHECK_THAT(e, !Contains("U+00E9"));
}

TEST_CASE("grid io: every message is one line", "[grid][io][errors]") {
    const std::vector<std::string> bad = {
        "",
        kHeader + "...\n.\n.\n",
        "type octile\nheight 2\r\rx\n",
        "\x01\x02\n\x03",
        "version 1\n",
        "type octile\nheight " + std::string(300, '9') + "\n",
        "type " + std::string(500, 'q') + "\n",
        kHeader + "...\n.\xE2\x80\xAE.\n",
    };
    for (const auto& text : bad) {
        const auto e = map_error(text);
        INFO(e);
        CHECK(e.find('\n') == std::string::npos);
        CHECK(e.find('\r') == std::string::npos);
        CHECK(e.size() < 400);
        CHECK_THAT(e, StartsWith("m.map:"));
    }
}

// ---------------------------------------------------------------------------------------------
// Files

TEST_CASE("grid io: read_map and read_scenario read files and name them in errors", "[grid][io][files]") {
    const TempFile good("good.map", "type octile\r\nheight 2\r\nwidth 3\r\nmap\r\n...\r\n.@.\r\n");
    const GridMap m = read_map(good.str());
    CHECK(m.width() == 3);
    CHECK(m.height() == 2);
    CHECK(m.name() == good.str());
    CHECK_FALSE(m.free({1, 1}));

    const TempFile bad("bad.map", "type octile\nheight 2\nwidth 3\nmap\n...\n.?.\n");
    CHECK_THAT(error_of([&] { (void)read_map(bad.str()); }), StartsWith(bad.str() + ":6:2: "));

    const TempFile matrix("matrix.txt", "0 0 0\n0 1 0\n");
    CHECK(same_map(m, read_map(matrix.str())));

    const std::string missing = (fs::temp_directory_path() / "pride_test_grid_io_no_such_file.map").string();
    auto e = error_of([&] { (void)read_map(missing); });
    CHECK_THAT(e, StartsWith(missing + ": "));
    CHECK_THAT(e, Contains("cannot open"));
    e = error_of([&] { (void)read_map(fs::temp_directory_path().string()); });
    CHECK_THAT(e, StartsWith(fs::temp_directory_path().string() + ": "));

    const TempFile scen("s.map.scen", "version 1\r\n3\tgood.map\t3\t2\t0\t0\t2\t1\t2.41421356\r\n");
    const auto entries = read_scenario(scen.str());
    REQUIRE(entries.size() == 1);
    CHECK(entries[0].map == "good.map");
    const TempFile badscen("bad.scen", "version 1\n3\tgood.map\t3\t2\t0\t0\t2\n");
    CHECK_THAT(error_of([&] { (void)read_scenario(badscen.str()); }), StartsWith(badscen.str() + ":2: "));
}

// ---------------------------------------------------------------------------------------------
// Scenarios

TEST_CASE("grid io: scenario lines", "[grid][io][scen]") {
    const auto v = parse_scenario(
        "version 1\n"
        "1\tempty-8-8.map\t8\t8\t1\t0\t6\t1\t5.41421356\n"
        "\n"
        "0 maps/x.map  8 8   5 3 3 3 2\r\n",
        "s.scen");
    REQUIRE(v.size() == 2);
    CHECK(v[0].bucket == 1);
    CHECK(v[0].map == "empty-8-8.map");
    CHECK(v[0].width == 8);
    CHECK(v[0].height == 8);
    CHECK(v[0].start == Cell{1, 0});
    CHECK(v[0].goal == Cell{6, 1});
    CHECK(v[0].optimal == Approx(5.41421356).margin(1e-12));
    CHECK(v[0].line == 2);
    CHECK(v[1].map == "maps/x.map");
    CHECK(v[1].start == Cell{5, 3});
    CHECK(v[1].optimal == 2.0);
    CHECK(v[1].line == 4);
    CHECK(parse_scenario("version 1.0\n0\ta.map\t2\t2\t0\t0\t1\t1\t1.41421356", "s").size() == 1);
    CHECK(parse_scenario("version 1\n", "s").empty());
}

TEST_CASE("grid io: scenario errors", "[grid][io][scen][errors]") {
    const std::string v1 = "version 1\n";
    auto e = scen_error("");
    CHECK_THAT(e, StartsWith("s.scen:1: "));
    CHECK_THAT(e, Contains("empty"));
    e = scen_error("0\ta.map\t8\t8\t1\t0\t6\t1\t5.4\n");
    CHECK_THAT(e, StartsWith("s.scen:1: "));
    CHECK_THAT(e, Contains("`version 1`"));
    e = scen_error("version 2\n");
    CHECK_THAT(e, StartsWith("s.scen:1: "));
    CHECK_THAT(e, Contains("unsupported scenario version"));
    e = scen_error(v1 + "0\ta.map\t8\t8\t1\t0\t6\t1\t5.4\n0\ta.map\t8\t8\t1\t0\t6\t1\n");
    CHECK_THAT(e, StartsWith("s.scen:3: "));
    CHECK_THAT(e, Contains("expected 9 fields") && Contains("got 8"));
    e = scen_error(v1 + "0\ta.map\t8\t8\t1\t0\t6\t1\t5.4\t7\n");
    CHECK_THAT(e, Contains("got 10"));
    e = scen_error(v1 + "x\ta.map\t8\t8\t1\t0\t6\t1\t5.4\n");
    CHECK_THAT(e, StartsWith("s.scen:2:"));
    CHECK_THAT(e, Contains("bucket") && !Contains("x"));
    e = scen_error(v1 + "0\ta.map\t0\t8\t0\t0\t0\t0\t0\n");
    CHECK_THAT(e, StartsWith("s.scen:2:"));
    CHECK_THAT(e, Contains("width"));
    e = scen_error(v1 + "0\ta.map\t8\tten\t1\t0\t6\t1\t5.4\n");
    CHECK_THAT(e, Contains("height") && !Contains("ten"));
    e = scen_error(v1 + "0\ta.map\t8\t8\t8\t0\t6\t1\t5.4\n");
    CHECK_THAT(e, StartsWith("s.scen:2:"));
    CHECK_THAT(e, Contains("start x 8") && Contains("outside"));
    e = scen_error(v1 + "0\ta.map\t8\t8\t1\t-1\t6\t1\t5.4\n");
    CHECK_THAT(e, Contains("start y -1") && Contains("outside"));
    e = scen_error(v1 + "0\ta.map\t8\t4\t1\t0\t6\t4\t5.4\n");
    CHECK_THAT(e, Contains("goal y 4") && Contains("height 4"));
    e = scen_error(v1 + "0\ta.map\t8\t8\t1\t0\t6.5\t1\t5.4\n");
    CHECK_THAT(e, Contains("goal x") && !Contains("6.5"));
    for (const char* opt : {"nan", "inf", "-1", "abc", "1.5.2"}) {
        e = scen_error(v1 + "0\ta.map\t8\t8\t1\t0\t6\t1\t" + opt + "\n");
        INFO(opt);
        CHECK_THAT(e, StartsWith("s.scen:2:"));
        CHECK_THAT(e, Contains("optimal length"));
    }
    e = scen_error(v1 + std::string("0\ta.map\t8\t8\t1\t0\t6\t1\t5\0\n", 23));
    CHECK_THAT(e, StartsWith("s.scen:2:22: "));
    CHECK_THAT(e, Contains("NUL"));
}

// ---------------------------------------------------------------------------------------------
// External data and the bundled maps

TEST_CASE("grid io: every Moving AI map and scenario of $PRIDE_DATA parses and agrees", "[grid][io][movingai]") {
    const auto data = pride::test::shared_data("movingai", "Moving AI maps and scenarios");
    if (!data) return;
    const fs::path dir = *data;
    REQUIRE(fs::is_directory(dir));
    int maps = 0, scens = 0;
    std::size_t lines = 0;
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(dir)) files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    for (const auto& path : files) {
        if (path.extension() == ".map") {
            INFO(path.string());
            const GridMap m = read_map(path.string());
            CHECK(m.width() >= 1);
            ++maps;
        }
    }
    for (const auto& path : files) {
        if (path.extension() != ".scen") continue;
        INFO(path.string());
        const auto entries = read_scenario(path.string());
        REQUIRE_FALSE(entries.empty());
        const GridMap m = read_map((dir / entries.front().map).string());
        std::size_t k = 0;
        for (const auto& e : entries) {
            INFO("line " << e.line);
            REQUIRE(e.map == entries.front().map);
            CHECK(e.width == m.width());
            CHECK(e.height == m.height());
            CHECK(m.free(e.start));
            CHECK(m.free(e.goal));
            // On a sample, the recorded optimal length: this fixes x as the column and y as the
            // row (a transposed reading gives other lengths or blocked endpoints).
            if (k++ % 11 == 0) CHECK(std::abs(octile_distance(m, e.start, e.goal) - e.optimal) <= 1e-6);
        }
        lines += entries.size();
        ++scens;
    }
    CHECK(maps == 16);
    CHECK(scens == 16);
    CHECK(lines > 8000);
}

TEST_CASE("grid io: the bundled maps of examples/maps", "[grid][io][bundled]") {
    const fs::path dir = fs::path(PRIDE_SOURCE_DIR) / "examples" / "maps";
    REQUIRE(fs::is_directory(dir));
    struct Expected {
        const char* name;
        int size;
        Cell start, goal;
        long paper_start, paper_goal;  // eq. 2 of Zhang et al. (2025) numbers
    };
    const Expected expected[] = {
        {"wan2022-10x10.map", 10, {0, 0}, {9, 9}, 90, 9},  // top-left to bottom-right
        {"wan2022-13x13.map", 13, {0, 0}, {12, 12}, 156, 12},
        {"zhang2025-20x20.map", 20, {0, 19}, {19, 0}, 0, 399},    // paper (1,1) to (20,20)
        {"zhang2025-40x40.map", 40, {1, 38}, {38, 1}, 41, 1558},  // paper (2,2) to (39,39)
        {"cai2021-50x50.map", 50, {0, 49}, {49, 0}, 0, 2499},
    };
    for (const auto& x : expected) {
        INFO(x.name);
        const GridMap m = read_map((dir / x.name).string());
        const auto entries = read_scenario((dir / (std::string(x.name) + ".scen")).string());
        REQUIRE(entries.size() == 1);
        const auto& e = entries[0];
        CHECK(e.map == x.name);
        CHECK(m.width() == x.size);
        CHECK(m.height() == x.size);
        CHECK(e.width == x.size);
        CHECK(e.height == x.size);
        CHECK(e.start == x.start);
        CHECK(e.goal == x.goal);
        CHECK(m.free(e.start));
        CHECK(m.free(e.goal));
        CHECK(m.paper_number(e.start) == x.paper_start);
        CHECK(m.paper_number(e.goal) == x.paper_goal);
        CHECK(std::abs(octile_distance(m, e.start, e.goal) - e.optimal) <= 1e-6);
    }
    // Section 4.1 of Cai and Du (2021): an obstacle coverage of 20 %.
    const GridMap m50 = read_map((dir / "cai2021-50x50.map").string());
    std::size_t blocked = 0;
    for (std::size_t i = 0; i < m50.size(); ++i) blocked += m50.free_index(i) ? 0 : 1;
    CHECK(blocked == 500);
}

// ---------------------------------------------------------------------------------------------
// Robustness

TEST_CASE("grid io: random input never crashes or hangs", "[grid][io][fuzz]") {
    std::mt19937 rng(20240611);
    const std::string alphabet = ".@GSOTW01 \t\r\n\n\n\n";
    const std::vector<std::string> seeds = {
        "type octile\nheight 3\nwidth 4\nmap\n..@.\n@...\n.@@.\n",
        "0 0 1 0\n1 0 0 0\n0 1 1 0\n",
        "0010\r\n1000\r\n0110\r\n",
        "version 1\n1\tempty-8-8.map\t8\t8\t1\t0\t6\t1\t5.41421356\n0\tm.map\t4\t3\t0\t0\t3\t2\t3.41421356\n",
    };
    int parsed = 0, rejected = 0;
    const auto attempt = [&](const std::string& text) {
        for (int kind = 0; kind < 2; ++kind) {
            try {
                if (kind == 0) {
                    const GridMap m = parse_map(text, "fuzz");
                    REQUIRE(m.width() >= 1);
                    REQUIRE(m.height() >= 1);
                    REQUIRE(m.size() == static_cast<std::size_t>(m.width()) * static_cast<std::size_t>(m.height()));
                } else {
                    for (const auto& e : parse_scenario(text, "fuzz")) {
                        REQUIRE(e.start.x >= 0);
                        REQUIRE(e.start.x < e.width);
                        REQUIRE(e.goal.y < e.height);
                    }
                }
                ++parsed;
            } catch (const pride::InputError& e) {
                const std::string what = e.what();
                if (what.rfind("fuzz:", 0) != 0 || what.find('\n') != std::string::npos) FAIL("bad message: " << what);
                ++rejected;
            }
        }
    };
    for (int i = 0; i < 1500; ++i) {  // uniform bytes
        std::string text(std::uniform_int_distribution<int>(0, 120)(rng), '\0');
        for (auto& c : text) c = static_cast<char>(std::uniform_int_distribution<int>(0, 255)(rng));
        attempt(text);
    }
    for (int i = 0; i < 1500; ++i) {  // map characters, blanks and line ends
        std::string text(std::uniform_int_distribution<int>(0, 80)(rng), '\0');
        for (auto& c : text) c = alphabet[std::uniform_int_distribution<std::size_t>(0, alphabet.size() - 1)(rng)];
        attempt(text);
    }
    for (int i = 0; i < 3000; ++i) {  // valid files with a few bytes changed, inserted or removed
        std::string text = seeds[static_cast<std::size_t>(i) % seeds.size()];
        const int edits = std::uniform_int_distribution<int>(1, 4)(rng);
        for (int k = 0; k < edits && !text.empty(); ++k) {
            const std::size_t at = std::uniform_int_distribution<std::size_t>(0, text.size() - 1)(rng);
            const auto byte = static_cast<char>(std::uniform_int_distribution<int>(0, 255)(rng));
            switch (std::uniform_int_distribution<int>(0, 3)(rng)) {
                case 0:
                    text[at] = byte;
                    break;
                case 1:
                    text.insert(text.begin() + static_cast<std::ptrdiff_t>(at), byte);
                    break;
                case 2:
                    text.erase(at, 1);
                    break;
                default:
                    text[at] = alphabet[static_cast<unsigned char>(byte) % alphabet.size()];
                    break;
            }
        }
        attempt(text);
    }
    CHECK(parsed > 0);
    CHECK(rejected > 0);
}

// ---------------------------------------------------------------------------------------------
// Conventions of map.hpp used with the files: paper numbering and inflation

TEST_CASE("grid io: paper numbering (Zhang et al. 2025, eq. 2)", "[grid][io][paper]") {
    // 3 columns, 2 rows. The papers number cells from 0, left to right and bottom to top:
    //   y = 0 (first line):  3 4 5
    //   y = 1 (bottom line): 0 1 2
    const GridMap m = parse_map("010\n000\n", "m");
    CHECK(m.paper_number({0, 1}) == 0);
    CHECK(m.paper_number({2, 1}) == 2);
    CHECK(m.paper_number({0, 0}) == 3);
    CHECK(m.paper_number({1, 0}) == 4);
    CHECK(m.paper_number({2, 0}) == 5);
    CHECK(m.from_paper_number(4) == Cell{1, 0});
    CHECK(m.from_paper_number(0) == Cell{0, 1});
    // Eq. 2: x = G % s + 1, y = floor(G / s) + 1 in the paper's 1-based bottom-left coordinates.
    const GridMap big = parse_map(to_movingai(GridMap(7, 5, std::vector<std::uint8_t>(35, 0))), "big");
    for (long g = 0; g < 35; ++g) {
        const Cell c = big.from_paper_number(g);
        CHECK(big.paper_number(c) == g);
        CHECK(c.x + 1 == g % 7 + 1);
        CHECK(big.height() - c.y == g / 7 + 1);
    }
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 7; ++x) CHECK(big.from_paper_number(big.paper_number({x, y})) == Cell{x, y});
    CHECK_THAT(error_of([&] { (void)m.from_paper_number(6); }), Contains("out of range"));
    CHECK_THAT(error_of([&] { (void)m.from_paper_number(-1); }), Contains("out of range"));
    // Zhang et al.'s (2025) 20 x 20 start (1, 1) and goal (20, 20) are the bottom-left and top-right cells.
    const GridMap m20(20, 20, std::vector<std::uint8_t>(400, 0));
    CHECK(m20.from_paper_number(0) == Cell{0, 19});
    CHECK(m20.from_paper_number(399) == Cell{19, 0});
}

TEST_CASE("grid io: obstacle inflation by r = 1 (Cai and Du 2021, section 3.1)", "[grid][io][inflate]") {
    const GridMap m = parse_map(
        "type octile\nheight 5\nwidth 6\nmap\n"
        "@.....\n"
        "......\n"
        "...@..\n"
        "......\n"
        "......\n",
        "m");
    const GridMap expected = parse_map(
        "110000\n"
        "111110\n"
        "001110\n"
        "001110\n"
        "000000\n",
        "e");
    const GridMap inflated = m.inflated(1);
    CHECK(same_map(inflated, expected));
    CHECK(same_map(m.inflated(0), m));
    CHECK(same_map(inflated.inflated(1), m.inflated(2)));
    CHECK_THAT(error_of([&] { (void)m.inflated(-1); }), Contains("radius"));
}

// Map and scenario readers (see map_io.hpp for the formats and the error contract).
#include "problems/grid/map_io.hpp"

#include <algorithm>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "framework/error.hpp"
#include "framework/read_file.hpp"
#include "framework/utf8.hpp"
#include "problems/grid/image_map.hpp"
#include "problems/grid/ros_map.hpp"

namespace pride::grid {
namespace {

// 64 MiB: an 8000 x 8000 Moving AI map; the largest maps of the benchmark sets are 1-2 MB, and the
// grid algorithms keep several arrays per cell. Read in chunks under the cap (framework/read_file.hpp).
constexpr std::size_t kMaxFileBytes = std::size_t{64} << 20;

// ---------------------------------------------------------------------------------------------
// Messages

/// Throws InputError "name:line:col: what"; col 0 leaves the column out.
[[noreturn]] void fail(const std::string& name, std::size_t line, std::size_t col, const std::string& what) {
    std::string msg = name + ":" + std::to_string(line);
    if (col > 0) msg += ":" + std::to_string(col);
    msg += ": " + what;
    throw InputError(msg);
}

// Nothing of a file that did not parse is quoted in its errors, only its name, line, column and
// what was expected there: a map or scenario path can name any readable file (a downloaded
// scenario or campaign file names its own), and an error must not show what such a file holds.

/// What kind of character stands at s[i], without showing it: "a space", "a tab", "a control
/// character", "a character".
std::string char_kind(std::string_view s, std::size_t i) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c == ' ') return "a space";
    if (c == '\t') return "a tab";
    if (c == '\r') return "a carriage return";
    if (c < 0x20 || c == 0x7F) return "a control character";
    return "a character";
}

/// 1-based column (in characters) of byte `pos` of a line that is valid UTF-8 up to pos.
std::size_t column(std::string_view line, std::size_t pos) {
    std::size_t col = 1;
    for (std::size_t i = 0; i < pos && i < line.size(); ++i)
        if ((static_cast<unsigned char>(line[i]) & 0xC0) != 0x80) ++col;
    return col;
}

// ---------------------------------------------------------------------------------------------
// Text and lines

bool is_blank(char c) {
    return c == ' ' || c == '\t';
}

/// Drops a UTF-8 byte-order mark, then rejects binary content: the first NUL byte or byte that is
/// not UTF-8 is an error at its line and column.
std::string_view check_text(std::string_view text, const std::string& name) {
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    std::size_t line = 1, line_start = 0;
    for (std::size_t i = 0; i < text.size();) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c == '\n') {
            ++line;
            line_start = ++i;
            continue;
        }
        if (c == 0)
            fail(name, line, column(text.substr(line_start), i - line_start),
                 "NUL byte (\\x00): this is a binary file, not a text map or scenario");
        const std::size_t len = utf8_length(text, i);
        if (len == 0)
            fail(name, line, column(text.substr(line_start), i - line_start),
                 "a byte that is not UTF-8 text: a map or scenario must be a text file");
        i += len;
    }
    return text;
}

struct Line {
    std::string_view text;  // without the line end and trailing blanks
    std::size_t number;     // 1-based
};

/// Splits at LF; drops a CR before the LF and trailing spaces and tabs; a final newline does not
/// start another line. A CR left inside a line (old Mac line ends, stray bytes) is an error.
std::vector<Line> split_lines(std::string_view text, const std::string& name) {
    std::vector<Line> lines;
    std::size_t start = 0, number = 1;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        const bool last = end == std::string_view::npos;
        if (last) end = text.size();
        std::string_view s = text.substr(start, end - start);
        while (!s.empty() && (s.back() == '\r' || is_blank(s.back()))) s.remove_suffix(1);
        if (const std::size_t cr = s.find('\r'); cr != std::string_view::npos)
            fail(name, number, column(s, cr), "carriage return (\\r) inside a line: line ends must be LF or CRLF");
        lines.push_back({s, number});
        ++number;
        if (last) break;
        start = end + 1;
    }
    return lines;
}

struct Token {
    std::string_view text;
    std::size_t pos;  // byte offset in its line
};

std::vector<Token> tokens(std::string_view line) {
    std::vector<Token> out;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && is_blank(line[i])) ++i;
        if (i >= line.size()) break;
        const std::size_t start = i;
        while (i < line.size() && !is_blank(line[i])) ++i;
        out.push_back({line.substr(start, i - start), start});
    }
    return out;
}

/// A whole number made of decimal digits only (an optional leading '-' when `allow_minus`), or
/// false when it is anything else or does not fit a long long.
bool parse_integer(std::string_view s, long long& out, bool allow_minus) {
    if (s.empty()) return false;
    if (s.front() == '-' && !allow_minus) return false;
    const char* first = s.data();
    const char* last = s.data() + s.size();
    const auto [ptr, ec] = std::from_chars(first, last, out);
    return ec == std::errc{} && ptr == last;
}

std::size_t first_nonblank(const std::vector<Line>& lines) {
    std::size_t i = 0;
    while (i < lines.size() && lines[i].text.empty()) ++i;
    return i;
}

bool rest_blank(const std::vector<Line>& lines, std::size_t from) {
    for (std::size_t i = from; i < lines.size(); ++i)
        if (!lines[i].text.empty()) return false;
    return true;
}

// ---------------------------------------------------------------------------------------------
// Moving AI maps

// 0 = free, 1 = blocked, -1 = not a map character.
int map_char(char c) {
    switch (c) {
        case '.':
        case 'G':
        case 'S':
            return 0;
        case '@':
        case 'O':
        case 'T':
        case 'W':
            return 1;
        default:
            return -1;
    }
}

bool looks_like_map_row(std::string_view s) {
    if (s.empty()) return false;
    for (char c : s)
        if (map_char(c) < 0) return false;
    return true;
}

constexpr std::string_view kKeywords[4] = {"type", "height", "width", "map"};
constexpr std::string_view kHeaderForms[4] = {"`type octile`", "`height H`", "`width W`", "`map`"};
constexpr std::string_view kHeaderAll = "`type octile`, `height H`, `width W`, `map`";

int keyword_index(std::string_view word) {
    for (int k = 0; k < 4; ++k)
        if (word == kKeywords[k]) return k;
    return -1;
}

GridMap parse_movingai(const std::vector<Line>& lines, std::size_t first, std::size_t text_size,
                       const std::string& name) {
    long long dims[2] = {0, 0};  // height, width
    std::size_t dim_line[2] = {0, 0};
    std::size_t i = first;
    for (int k = 0; k < 4; ++k, ++i) {
        const std::string expected(kHeaderForms[k]);
        if (i >= lines.size())
            fail(name, lines.back().number + 1, 0,
                 "missing header line " + expected + ": the file ends after " +
                     std::string(k == 0 ? "nothing" : kHeaderForms[k - 1]) + " (a Moving AI map starts with " +
                     std::string(kHeaderAll) + ")");
        const Line& ln = lines[i];
        const auto tok = tokens(ln.text);
        if (tok.empty())
            fail(name, ln.number, 0,
                 "missing header line " + expected + ": got an empty line (a Moving AI map starts with " +
                     std::string(kHeaderAll) + ")");
        const int got = keyword_index(tok[0].text);
        if (got != k) {
            const std::size_t col = column(ln.text, tok[0].pos);
            if (got > k) {
                // A later header line came early: swapped lines, or this one is missing.
                bool later = false;
                for (std::size_t j = i + 1; j < lines.size() && j <= first + 4; ++j) {
                    const auto t = tokens(lines[j].text);
                    if (!t.empty() && t[0].text == kKeywords[k]) later = true;
                }
                if (later)
                    fail(name, ln.number, col,
                         "header out of order: " + expected + " must come before `" + std::string(kKeywords[got]) +
                             "` (the order is " + std::string(kHeaderAll) + ")");
                fail(name, ln.number, col,
                     "missing header line " + expected + " before `" + std::string(kKeywords[got]) +
                         "` (a Moving AI map starts with " + std::string(kHeaderAll) + ")");
            }
            if (got >= 0)
                fail(name, ln.number, col,
                     "duplicate header line `" + std::string(kKeywords[got]) + "`: expected " + expected + " here");
            if (looks_like_map_row(ln.text))
                fail(name, ln.number, 0,
                     "missing header line " + expected + ": this looks like a map row, but the header (" +
                         std::string(kHeaderAll) + ") is not complete");
            fail(name, ln.number, col, "expected header line " + expected);
        }
        if (k == 3) {  // map
            if (tok.size() > 1)
                fail(name, ln.number, column(ln.text, tok[1].pos),
                     "unexpected text after `map`: the map rows start on the next line");
            continue;
        }
        const std::string key(kKeywords[k]);
        if (tok.size() < 2)
            fail(name, ln.number, column(ln.text, ln.text.size()), "`" + key + "` needs a value: " + expected);
        if (tok.size() > 2)
            fail(name, ln.number, column(ln.text, tok[2].pos),
                 "unexpected text after `" + key + "` and its value: expected " + expected);
        const Token& value = tok[1];
        const std::size_t vcol = column(ln.text, value.pos);
        if (k == 0) {
            if (value.text != "octile") fail(name, ln.number, vcol, "unsupported map type: only `type octile` is read");
            continue;
        }
        long long v = 0;
        if (!parse_integer(value.text, v, true)) fail(name, ln.number, vcol, key + " must be a whole number >= 1");
        if (v < 1) fail(name, ln.number, vcol, key + " must be at least 1, got " + std::to_string(v));
        if (v > INT_MAX) fail(name, ln.number, vcol, key + " too large: " + std::to_string(v));
        dims[k - 1] = v;
        dim_line[k - 1] = ln.number;
    }

    const auto height = static_cast<int>(dims[0]);
    const auto width = static_cast<int>(dims[1]);
    const std::size_t map_line = lines[i - 1].number;
    std::vector<std::uint8_t> blocked;
    // A valid file holds one byte per cell, so the text bounds what to reserve whatever the header says.
    blocked.reserve(std::min(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), text_size));
    for (int r = 0; r < height; ++r, ++i) {
        if (i >= lines.size() || (lines[i].text.empty() && rest_blank(lines, i)))
            fail(name, map_line + static_cast<std::size_t>(r) + 1, 0,
                 "too few rows: the header says height " + std::to_string(height) + " (line " +
                     std::to_string(dim_line[0]) + "), but the file ends after " + std::to_string(r) + " map row" +
                     (r == 1 ? "" : "s"));
        const Line& ln = lines[i];
        const std::string_view s = ln.text;
        for (std::size_t p = 0; p < s.size(); ++p)
            if (map_char(s[p]) < 0)
                fail(name, ln.number, column(s, p),
                     "unknown map character (" + char_kind(s, p) + ") in map row " + std::to_string(r + 1) +
                         " (free: . G S, blocked: @ O T W)");
        const auto w = static_cast<std::size_t>(width);
        if (s.size() < w)
            fail(name, ln.number, s.size() + 1,
                 std::string(s.empty() ? "empty" : "short") + " row: expected " + std::to_string(width) +
                     " characters (width, line " + std::to_string(dim_line[1]) + "), got " + std::to_string(s.size()));
        if (s.size() > w)
            fail(name, ln.number, w + 1,
                 "long row: expected " + std::to_string(width) + " characters (width, line " +
                     std::to_string(dim_line[1]) + "), got " + std::to_string(s.size()));
        for (char c : s) blocked.push_back(static_cast<std::uint8_t>(map_char(c)));
    }
    for (; i < lines.size(); ++i)
        if (!lines[i].text.empty())
            fail(name, lines[i].number, 0,
                 "too many rows: the header says height " + std::to_string(height) + " (line " +
                     std::to_string(dim_line[0]) + "), but more map data follows row " + std::to_string(height));
    return GridMap(width, height, std::move(blocked), name);
}

// ---------------------------------------------------------------------------------------------
// 0/1 matrices

GridMap parse_matrix(const std::vector<Line>& lines, std::size_t first, const std::string& name) {
    std::size_t last = lines.size();
    while (last > first && lines[last - 1].text.empty()) --last;
    std::vector<std::uint8_t> blocked;
    std::size_t width = 0;
    std::size_t width_line = 0;
    for (std::size_t i = first; i < last; ++i) {
        const Line& ln = lines[i];
        const std::string_view s = ln.text;
        if (s.empty())
            fail(name, ln.number, 0,
                 "empty row inside the matrix: expected " + std::to_string(width) + " cells of 0 or 1");
        std::size_t lead = 0;
        while (lead < s.size() && is_blank(s[lead])) ++lead;
        const bool csv = s.find(',') != std::string_view::npos;
        const bool spaced = !csv && s.find_first_of(" \t", lead) != std::string_view::npos;
        // Each cell: its byte offset; the token (spaced, CSV) or the single character.
        std::size_t count = 0;
        std::size_t extra_pos = 0;  // offset of cell width+1, for the "long row" column
        const auto add = [&](std::string_view cell, std::size_t pos) {
            if (csv && cell.empty())
                fail(name, ln.number, column(s, pos), "empty matrix cell: expected 0 (free) or 1 (blocked)");
            if (cell != "0" && cell != "1")
                fail(name, ln.number, column(s, pos), "matrix cell must be 0 (free) or 1 (blocked)");
            if (width_line != 0 && count == width) extra_pos = pos;
            ++count;
            blocked.push_back(cell == "1" ? 1 : 0);
        };
        if (csv) {
            for (std::size_t p = lead;;) {
                std::size_t end = s.find(',', p);
                const bool last = end == std::string_view::npos;
                if (last) end = s.size();
                std::size_t a = p, b = end;
                while (a < b && is_blank(s[a])) ++a;
                while (b > a && is_blank(s[b - 1])) --b;
                add(s.substr(a, b - a), a);
                if (last) break;
                p = end + 1;
            }
        } else if (spaced) {
            for (const Token& t : tokens(s)) add(t.text, t.pos);
        } else {
            for (std::size_t p = lead; p < s.size();) {
                const std::size_t len = std::max<std::size_t>(1, utf8_length(s, p));
                add(s.substr(p, len), p);
                p += len;
            }
        }
        if (width_line == 0) {
            width = count;
            width_line = ln.number;
        } else if (count != width) {
            const std::string what = std::string(count < width ? "short" : "long") + " matrix row: expected " +
                                     std::to_string(width) + " cells (as on line " + std::to_string(width_line) +
                                     "), got " + std::to_string(count);
            fail(name, ln.number, count < width ? column(s, s.size()) : column(s, extra_pos), what);
        }
    }
    const auto height = last - first;
    if (width > static_cast<std::size_t>(INT_MAX) || height > static_cast<std::size_t>(INT_MAX))
        fail(name, lines[first].number, 0, "matrix too large");
    return GridMap(static_cast<int>(width), static_cast<int>(height), std::move(blocked), name);
}

// ---------------------------------------------------------------------------------------------
// Files

std::string read_file(const std::string& path, bool named_in_file = false) {
    return read_capped_file(path, kMaxFileBytes, "map and scenario", named_in_file);
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Public

GridMap parse_map(std::string_view text, const std::string& name, const MapReadOptions& options) {
    if (text.empty()) fail(name, 1, 0, "empty file: no map");
    if (is_png(text) || is_netpbm(text)) return parse_image_map(text, name, options.unknown_free);
    text = check_text(text, name);
    if (looks_like_ros_yaml(text))
        throw InputError(name +
                         ": a ROS map_server YAML file names its image file: read it from its file "
                         "(read_map, --map), not from text");
    const auto lines = split_lines(text, name);
    const std::size_t first = first_nonblank(lines);
    if (first == lines.size()) fail(name, 1, 0, "the file holds only blank lines: no map");

    const Line& ln = lines[first];
    const auto tok = tokens(ln.text);
    if (keyword_index(tok[0].text) >= 0) return parse_movingai(lines, first, text.size(), name);
    const auto c = static_cast<unsigned char>(tok[0].text[0]);
    if (c >= '0' && c <= '9') return parse_matrix(lines, first, name);
    if (looks_like_map_row(ln.text))
        fail(name, ln.number, 0,
             "missing Moving AI header: a .map file starts with " + std::string(kHeaderAll) +
                 ", but this line is already a map row");
    fail(name, ln.number, column(ln.text, tok[0].pos),
         "not a map: expected a Moving AI header (`type octile`) or a row of 0/1 matrix cells");
}

GridMap read_map(const std::string& path, const MapReadOptions& options) {
    const std::string bytes = read_file(path, options.named_in_file);
    if (!is_png(bytes) && !is_netpbm(bytes) && looks_like_ros_yaml(bytes)) {
        check_text(bytes, path);
        return read_ros_map(path, bytes, options.unknown_free);
    }
    return parse_map(bytes, path, options);
}

std::vector<ScenarioEntry> parse_scenario(std::string_view text, const std::string& name) {
    if (text.empty()) fail(name, 1, 0, "empty file: no scenario (expected `version 1` and scenario lines)");
    text = check_text(text, name);
    const auto lines = split_lines(text, name);
    const std::size_t first = first_nonblank(lines);
    if (first == lines.size()) fail(name, 1, 0, "the file holds only blank lines: no scenario");

    {
        const Line& ln = lines[first];
        const auto tok = tokens(ln.text);
        if (tok[0].text != "version")
            fail(name, ln.number, 0, "missing `version 1` line: a scenario file starts with it");
        if (tok.size() < 2) fail(name, ln.number, 0, "`version` needs a value: `version 1`");
        if (tok.size() > 2 || (tok[1].text != "1" && tok[1].text != "1.0"))
            fail(name, ln.number, 0, "unsupported scenario version: expected `version 1` or `version 1.0`");
    }

    std::vector<ScenarioEntry> out;
    for (std::size_t i = first + 1; i < lines.size(); ++i) {
        const Line& ln = lines[i];
        if (ln.text.empty()) continue;
        const auto tok = tokens(ln.text);
        if (tok.size() != 9)
            fail(name, ln.number, 0,
                 "expected 9 fields (bucket map width height start_x start_y goal_x goal_y optimal_length), got " +
                     std::to_string(tok.size()));
        const auto where = [&](std::size_t k) { return column(ln.text, tok[k].pos); };
        const auto integer = [&](std::size_t k, const char* field, long long lo) {
            long long v = 0;
            if (!parse_integer(tok[k].text, v, true))
                fail(name, ln.number, where(k), std::string(field) + " must be a whole number");
            if (v < lo)
                fail(name, ln.number, where(k),
                     std::string(field) + " must be at least " + std::to_string(lo) + ", got " + std::to_string(v));
            if (v > INT_MAX) fail(name, ln.number, where(k), std::string(field) + " too large: " + std::to_string(v));
            return static_cast<int>(v);
        };
        ScenarioEntry e;
        e.line = static_cast<int>(std::min<std::size_t>(ln.number, INT_MAX));
        e.bucket = integer(0, "bucket", 0);
        e.map = std::string(tok[1].text);
        e.width = integer(2, "width", 1);
        e.height = integer(3, "height", 1);
        const char* names[4] = {"start x", "start y", "goal x", "goal y"};
        int xy[4] = {0, 0, 0, 0};
        for (std::size_t k = 0; k < 4; ++k) {
            long long v = 0;
            if (!parse_integer(tok[4 + k].text, v, true))
                fail(name, ln.number, where(4 + k), std::string(names[k]) + " must be a whole number");
            const int extent = (k % 2 == 0) ? e.width : e.height;
            if (v < 0 || v >= extent)
                fail(name, ln.number, where(4 + k),
                     std::string(names[k]) + " " + std::to_string(v) + " is outside the map (" +
                         ((k % 2 == 0) ? "width " : "height ") + std::to_string(extent) + ": 0.." +
                         std::to_string(extent - 1) + ")");
            xy[k] = static_cast<int>(v);
        }
        e.start = {xy[0], xy[1]};
        e.goal = {xy[2], xy[3]};
        {
            const std::string_view s = tok[8].text;
            double v = 0.0;
            const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
            if (ec != std::errc{} || ptr != s.data() + s.size() || !std::isfinite(v) || v < 0.0)
                fail(name, ln.number, where(8), "optimal length must be a number >= 0");
            e.optimal = v;
        }
        out.push_back(std::move(e));
    }
    return out;
}

std::vector<ScenarioEntry> read_scenario(const std::string& path) {
    return parse_scenario(read_file(path), path);
}

std::string to_movingai(const GridMap& map) {
    std::string out =
        "type octile\nheight " + std::to_string(map.height()) + "\nwidth " + std::to_string(map.width()) + "\nmap\n";
    out.reserve(out.size() + map.size() + static_cast<std::size_t>(map.height()));
    for (int y = 0; y < map.height(); ++y) {
        for (int x = 0; x < map.width(); ++x) out += map.free(Cell{x, y}) ? '.' : '@';
        out += '\n';
    }
    return out;
}

}  // namespace pride::grid

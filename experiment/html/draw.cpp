#include "experiment/html/draw.hpp"

#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <system_error>

#include <fmt/format.h>

#include "experiment/html/cairo_output.hpp"
#include "experiment/html/font_session.hpp"
#include "framework/error.hpp"

namespace pride::html {

std::string length_words(double cells, const grid::WorldFrame& frame) {
    return fmt::format("length {:.6g} cells = {:.6g} m", cells, cells * frame.resolution);
}
namespace {

/// A chain of cells or a polyline (cell (i, j)'s centre at (i, j) in both).
template <class Points>
void trace_path(cairo_t* cr, const Points& path, double cell) {
    for (std::size_t i = 0; i < path.size(); ++i) {
        const double x = (path[i].x + 0.5) * cell, y = (path[i].y + 0.5) * cell;
        if (i == 0)
            cairo_move_to(cr, x, y);
        else
            cairo_line_to(cr, x, y);
    }
}

/// The cells of `w` (drawn in the map's own coordinates: the caller translates and clips).
void paint_map(cairo_t* cr, const grid::GridMap& map, const MapWindow& w, double cell) {
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_set_source_rgb(cr, 0.2, 0.2, 0.22);
    for (int y = w.y0; y < w.y1; ++y)
        for (int x = w.x0; x < w.x1; ++x)
            if (!map.free({x, y})) cairo_rectangle(cr, x * cell, y * cell, cell, cell);
    cairo_fill(cr);
    if (cell >= 6) {  // grid lines only where cells are big enough to tell apart
        cairo_set_source_rgba(cr, 0, 0, 0, 0.15);
        cairo_set_line_width(cr, 1.0);
        for (int x = w.x0; x <= w.x1; ++x) {
            cairo_move_to(cr, x * cell, w.y0 * cell);
            cairo_line_to(cr, x * cell, w.y1 * cell);
        }
        for (int y = w.y0; y <= w.y1; ++y) {
            cairo_move_to(cr, w.x0 * cell, y * cell);
            cairo_line_to(cr, w.x1 * cell, y * cell);
        }
        cairo_stroke(cr);
    }
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
}

void paint_ends(cairo_t* cr, grid::Cell start, grid::Cell goal, double cell) {
    const double radius = std::max(2.5, cell * 0.35);
    cairo_set_source_rgb(cr, 0.05, 0.6, 0.15);
    cairo_arc(cr, (start.x + 0.5) * cell, (start.y + 0.5) * cell, radius, 0, 6.283185307179586);
    cairo_fill(cr);
    cairo_set_source_rgb(cr, 0.85, 0.1, 0.1);
    cairo_arc(cr, (goal.x + 0.5) * cell, (goal.y + 0.5) * cell, radius, 0, 6.283185307179586);
    cairo_fill(cr);
}

constexpr double kMapLegendLine = 18.0, kMapLegendPad = 6.0;

struct Rgba {
    double r, g, b, a;
};
const Rgba kStart{0.05, 0.6, 0.15, 1}, kGoal{0.85, 0.1, 0.1, 1}, kFound{0.1, 0.3, 0.9, 1},
    kOptimal{0.1, 0.65, 0.25, 0.45};

/// A legend entry: a dot (start, goal) or a line swatch, and its words.
struct Entry {
    Rgba colour;
    bool dot;
    std::string words;
};

/// The legend under the map (from y = top): one line per entry.
void paint_legend(cairo_t* cr, const std::vector<Entry>& entries, double top, double width) {
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_rectangle(cr, 0, top, width, legend_height(entries.size()));
    cairo_fill(cr);
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, 12.0);
    for (std::size_t i = 0; i < entries.size(); ++i) {
        const Entry& e = entries[i];
        const double y = top + kMapLegendPad + kMapLegendLine * (static_cast<double>(i) + 0.5);
        cairo_set_source_rgba(cr, e.colour.r, e.colour.g, e.colour.b, e.colour.a);
        if (e.dot) {
            cairo_arc(cr, 18, y, 5, 0, 6.283185307179586);
            cairo_fill(cr);
        } else {
            cairo_set_line_width(cr, 4);
            cairo_move_to(cr, 8, y);
            cairo_line_to(cr, 28, y);
            cairo_stroke(cr);
        }
        cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
        cairo_move_to(cr, 36, y + 4);
        cairo_show_text(cr, e.words.c_str());
    }
}

void paint(cairo_t* cr, const grid::GridMap& map, grid::Cell start, grid::Cell goal, const grid::Polyline* path,
           const grid::Path* optimal, double cell) {
    paint_map(cr, map, whole_map(map), cell);
    if (optimal && !optimal->empty()) {  // underneath, wide and pale, so the found path stays visible
        cairo_set_source_rgba(cr, kOptimal.r, kOptimal.g, kOptimal.b, kOptimal.a);
        cairo_set_line_width(cr, std::max(3.0, cell * 0.55));
        trace_path(cr, *optimal, cell);
        cairo_stroke(cr);
    }
    if (path && !path->empty()) {
        cairo_set_source_rgb(cr, kFound.r, kFound.g, kFound.b);
        cairo_set_line_width(cr, std::max(1.5, cell * 0.2));
        trace_path(cr, *path, cell);
        cairo_stroke(cr);
    }
    paint_ends(cr, start, goal, cell);
}

/// The colour of path i of n in a picture of several: from blue (the first) to red (the last).
Rgba hue(std::size_t i, std::size_t n) {
    const double t = static_cast<double>(i) / static_cast<double>(std::max<std::size_t>(n, 2) - 1);
    return {0.1 + 0.8 * t, 0.3 * (1.0 - std::abs(2.0 * t - 1.0)) + 0.1, 0.9 - 0.8 * t, 0.6};
}

/// The colour of path i of n: `colours[i]` when given, else its hue, half transparent.
Rgba colour_of(std::size_t i, std::size_t n, const std::vector<Rgb>& colours) {
    if (i < colours.size()) return {colours[i].r, colours[i].g, colours[i].b, 0.6};
    return hue(i, n);
}

/// Several paths, each in its own colour (by default from blue for the first to red for the last),
/// half transparent so that shared stretches show as darker.
void paint_many(cairo_t* cr, const grid::GridMap& map, const MapWindow& window, grid::Cell start, grid::Cell goal,
                const std::vector<grid::Polyline>& paths, const std::vector<Rgb>& colours, double cell) {
    paint_map(cr, map, window, cell);
    for (std::size_t i = 0; i < paths.size(); ++i) {
        const Rgba c = colour_of(i, paths.size(), colours);
        cairo_set_source_rgba(cr, c.r, c.g, c.b, c.a);
        cairo_set_line_width(cr, std::max(1.5, cell * 0.18));
        trace_path(cr, paths[i], cell);
        cairo_stroke(cr);
    }
    paint_ends(cr, start, goal, cell);
}

template <class Paint>
void draw(const MapWindow& window, const std::vector<Entry>& legend, OutputFiles::File& file, PictureFormat format,
          Paint paint_with) {
    // About 800 pixels on the longer side, cells between 2 and 40 pixels; the legend below, at
    // least 240 pixels wide so that its words fit beside a small map.
    const int columns = window.x1 - window.x0, rows = window.y1 - window.y0;
    const double cell = std::clamp(800.0 / std::max(columns, rows), 2.0, 40.0);
    const double map_w = columns * cell, map_h = rows * cell;
    const double w = std::max(map_w, 240.0), h = map_h + legend_height(legend.size());
    const FontSession fonts;  // the legend's text
    cairo_surface_t* surface = format == PictureFormat::svg
                                   ? cairo_svg_surface_create_for_stream(write_to_file, &file, w, h)
                                   : cairo_image_surface_create(CAIRO_FORMAT_RGB24, static_cast<int>(std::ceil(w)),
                                                                static_cast<int>(std::ceil(h)));
    cairo_t* cr = cairo_create(surface);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_save(cr);
    cairo_rectangle(cr, 0, 0, map_w, map_h);
    cairo_clip(cr);
    cairo_translate(cr, -window.x0 * cell, -window.y0 * cell);
    paint_with(cr, cell);
    cairo_restore(cr);
    // A frame, so that the map's edge (or a cropped region's) shows on a white page.
    cairo_set_source_rgba(cr, 0, 0, 0, 0.35);
    cairo_set_line_width(cr, 1.0);
    cairo_rectangle(cr, 0.5, 0.5, map_w - 1.0, map_h - 1.0);
    cairo_stroke(cr);
    paint_legend(cr, legend, map_h, w);
    cairo_destroy(cr);
    finish_into(surface, file, format == PictureFormat::png, "the picture");
}

}  // namespace

MapWindow whole_map(const grid::GridMap& map) {
    return {0, 0, map.width(), map.height()};
}

MapWindow paths_window(const grid::GridMap& map, grid::Cell start, grid::Cell goal,
                       const std::vector<grid::Polyline>& paths) {
    double lo_x = std::min(start.x, goal.x), hi_x = std::max(start.x, goal.x);
    double lo_y = std::min(start.y, goal.y), hi_y = std::max(start.y, goal.y);
    for (const grid::Polyline& p : paths)
        for (const auto& v : p) {
            lo_x = std::min(lo_x, v.x), hi_x = std::max(hi_x, v.x);
            lo_y = std::min(lo_y, v.y), hi_y = std::max(hi_y, v.y);
        }
    // Vertices are cell centres (cell i spans [i - 0.5, i + 0.5]); the margin is whole cells.
    const double margin = std::max(5.0, std::ceil(0.1 * std::max(hi_x - lo_x, hi_y - lo_y)));
    MapWindow w;
    w.x0 = static_cast<int>(std::max(0.0, std::floor(lo_x + 0.5) - margin));
    w.y0 = static_cast<int>(std::max(0.0, std::floor(lo_y + 0.5) - margin));
    w.x1 = static_cast<int>(std::min<double>(map.width(), std::floor(hi_x + 0.5) + 1 + margin));
    w.y1 = static_cast<int>(std::min<double>(map.height(), std::floor(hi_y + 0.5) + 1 + margin));
    if (w.x1 - w.x0 >= 0.7 * map.width() && w.y1 - w.y0 >= 0.7 * map.height()) return whole_map(map);
    return w;
}

std::string window_words(const grid::GridMap& map, const MapWindow& w) {
    if (w.whole(map)) return "";
    return fmt::format(" Cropped to the paths' region: columns {}-{} and rows {}-{} of the {} x {} map.", w.x0,
                       w.x1 - 1, w.y0, w.y1 - 1, map.width(), map.height());
}

double legend_height(std::size_t entries) {
    return entries == 0 ? 0.0 : 2 * kMapLegendPad + kMapLegendLine * static_cast<double>(entries);
}

void draw_grid(const grid::GridMap& map, grid::Cell start, grid::Cell goal, const grid::Polyline* path,
               const grid::Path* optimal, const PathLabels& labels, OutputFiles::File& file, PictureFormat format) {
    std::vector<Entry> legend{{kStart, true, "start"}, {kGoal, true, "goal"}};
    if (path && !path->empty()) legend.push_back({kFound, false, labels.path});
    if (optimal && !optimal->empty())
        legend.push_back({{kOptimal.r, kOptimal.g, kOptimal.b, 0.6}, false, labels.optimal});
    draw(whole_map(map), legend, file, format,
         [&](cairo_t* cr, double cell) { paint(cr, map, start, goal, path, optimal, cell); });
}

void draw_grid_paths(const grid::GridMap& map, grid::Cell start, grid::Cell goal, const std::vector<grid::Path>& paths,
                     const std::vector<std::string>& labels, OutputFiles::File& file, PictureFormat format,
                     const std::vector<Rgb>& colours) {
    std::vector<grid::Polyline> lines;
    lines.reserve(paths.size());
    for (const grid::Path& p : paths) lines.push_back(grid::polyline_of(p));
    draw_grid_paths(map, start, goal, lines, labels, file, format, colours);
}

void draw_grid_paths(const grid::GridMap& map, grid::Cell start, grid::Cell goal,
                     const std::vector<grid::Polyline>& paths, const std::vector<std::string>& labels,
                     OutputFiles::File& file, PictureFormat format, const std::vector<Rgb>& colours,
                     const std::optional<MapWindow>& window) {
    std::vector<Entry> legend{{kStart, true, "start"}, {kGoal, true, "goal"}};
    // A long front: its first and last paths named, the rest said in one line (colours run in order).
    const std::size_t n = paths.size(), shown = n > 10 ? 4 : n;
    for (std::size_t i = 0; i < n; ++i) {
        if (i == shown && n > 10) {
            legend.push_back({{0, 0, 0, 0}, false, fmt::format("... {} more, their colours in order", n - 2 * shown)});
            i = n - shown;
        }
        legend.push_back({colour_of(i, n, colours), false, i < labels.size() ? labels[i] : std::string()});
    }
    const MapWindow drawn = window.value_or(whole_map(map));
    draw(drawn, legend, file, format,
         [&](cairo_t* cr, double cell) { paint_many(cr, map, drawn, start, goal, paths, colours, cell); });
}

void write_pictures(const std::vector<std::pair<std::string, PictureFormat>>& pictures, OutputFiles& files,
                    const std::function<void(OutputFiles::File& file, PictureFormat)>& draw_one) {
    namespace fs = std::filesystem;
    std::error_code ec;
    // Everything checked before anything is written: one file named twice (OutputFiles would
    // refuse it too, but after the first was drawn, and in its own words).
    for (std::size_t i = 0; i < pictures.size(); ++i) {
        const std::string& file = pictures[i].first;
        for (std::size_t j = 0; j < i; ++j) {
            const fs::path a = fs::weakly_canonical(file, ec), b = fs::weakly_canonical(pictures[j].first, ec);
            if (a == b || file == pictures[j].first)
                throw InputError(file + ": named for two pictures (--svg and --png); give each its own file");
        }
    }
    // Pictures renamed into place first, devices last: a failure drawing one of the first writes
    // nothing to a device.
    for (const bool direct : {false, true})
        for (const auto& [file, format] : pictures) {
            if (OutputFiles::writes_directly(file) != direct) continue;
            draw_one(files.create(file), format);
        }
}

}  // namespace pride::html

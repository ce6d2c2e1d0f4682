#include "cli/draw.hpp"

#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <cstdio>

#include "framework/error.hpp"

namespace pride::cli {
namespace {

void trace_path(cairo_t* cr, const grid::Path& path, double cell) {
    for (std::size_t i = 0; i < path.size(); ++i) {
        const double x = (path[i].x + 0.5) * cell, y = (path[i].y + 0.5) * cell;
        if (i == 0)
            cairo_move_to(cr, x, y);
        else
            cairo_line_to(cr, x, y);
    }
}

void paint(cairo_t* cr, const grid::GridMap& map, grid::Cell start, grid::Cell goal, const grid::Path* path,
           const grid::Path* optimal, double cell) {
    const double w = map.width() * cell, h = map.height() * cell;
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_set_source_rgb(cr, 0.2, 0.2, 0.22);
    for (int y = 0; y < map.height(); ++y)
        for (int x = 0; x < map.width(); ++x)
            if (!map.free({x, y})) cairo_rectangle(cr, x * cell, y * cell, cell, cell);
    cairo_fill(cr);
    if (cell >= 6) {  // grid lines only where cells are big enough to tell apart
        cairo_set_source_rgba(cr, 0, 0, 0, 0.15);
        cairo_set_line_width(cr, 1.0);
        for (int x = 0; x <= map.width(); ++x) {
            cairo_move_to(cr, x * cell, 0);
            cairo_line_to(cr, x * cell, h);
        }
        for (int y = 0; y <= map.height(); ++y) {
            cairo_move_to(cr, 0, y * cell);
            cairo_line_to(cr, w, y * cell);
        }
        cairo_stroke(cr);
    }
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    if (optimal && !optimal->empty()) {  // underneath, wide and pale, so the found path stays visible
        cairo_set_source_rgba(cr, 0.1, 0.65, 0.25, 0.45);
        cairo_set_line_width(cr, std::max(3.0, cell * 0.55));
        trace_path(cr, *optimal, cell);
        cairo_stroke(cr);
    }
    if (path && !path->empty()) {
        cairo_set_source_rgb(cr, 0.1, 0.3, 0.9);
        cairo_set_line_width(cr, std::max(1.5, cell * 0.2));
        trace_path(cr, *path, cell);
        cairo_stroke(cr);
    }
    const double radius = std::max(2.5, cell * 0.35);
    cairo_set_source_rgb(cr, 0.05, 0.6, 0.15);
    cairo_arc(cr, (start.x + 0.5) * cell, (start.y + 0.5) * cell, radius, 0, 6.283185307179586);
    cairo_fill(cr);
    cairo_set_source_rgb(cr, 0.85, 0.1, 0.1);
    cairo_arc(cr, (goal.x + 0.5) * cell, (goal.y + 0.5) * cell, radius, 0, 6.283185307179586);
    cairo_fill(cr);
}

}  // namespace

void draw_grid(const grid::GridMap& map, grid::Cell start, grid::Cell goal, const grid::Path* path,
               const grid::Path* optimal, const std::string& file, const std::string& shown_as, PictureFormat format) {
    // About 800 pixels on the longer side, cells between 2 and 40 pixels.
    const double cell = std::clamp(800.0 / std::max(map.width(), map.height()), 2.0, 40.0);
    const double w = map.width() * cell, h = map.height() * cell;
    cairo_surface_t* surface =
        format == PictureFormat::svg
            ? cairo_svg_surface_create(file.c_str(), w, h)
            : cairo_image_surface_create(CAIRO_FORMAT_RGB24, static_cast<int>(w), static_cast<int>(h));
    cairo_t* cr = cairo_create(surface);
    paint(cr, map, start, goal, path, optimal, cell);
    cairo_destroy(cr);
    cairo_status_t status = cairo_surface_status(surface);
    if (format == PictureFormat::png && status == CAIRO_STATUS_SUCCESS)
        status = cairo_surface_write_to_png(surface, file.c_str());
    cairo_surface_finish(surface);  // flushes the SVG
    if (status == CAIRO_STATUS_SUCCESS) status = cairo_surface_status(surface);
    cairo_surface_destroy(surface);
    if (status != CAIRO_STATUS_SUCCESS)
        throw InputError(shown_as + ": cannot write the picture: " + cairo_status_to_string(status));
}

}  // namespace pride::cli

#pragma once
// Text on a cairo context, for the figures drawn with cairo (figure.cpp, cd_diagram.cpp): its
// width and a line aligned on a point.
#include <cairo.h>

#include <string>

namespace pride::html {

/// The advance of `s` at font size `size` (the context's face; sets that size).
inline double text_width(cairo_t* cr, const std::string& s, double size) {
    cairo_set_font_size(cr, size);
    cairo_text_extents_t e;
    cairo_text_extents(cr, s.c_str(), &e);
    return e.x_advance;
}

/// Text at (x, y) (its baseline), aligned left (0), centred (0.5) or right (1).
inline void show_text(cairo_t* cr, const std::string& s, double x, double y, double size, double align = 0) {
    const double w = text_width(cr, s, size);
    cairo_move_to(cr, x - align * w, y);
    cairo_show_text(cr, s.c_str());
}

}  // namespace pride::html

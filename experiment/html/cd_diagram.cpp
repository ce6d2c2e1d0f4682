#include "experiment/html/cd_diagram.hpp"

#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include <fmt/format.h>

#include "experiment/html/cairo_output.hpp"
#include "experiment/html/cairo_text.hpp"
#include "experiment/html/font_session.hpp"

namespace pride::html {

CdLayout cd_layout(std::span<const double> average_ranks, const stats::CriticalDifference& cd) {
    CdLayout out;
    const std::size_t k = average_ranks.size();
    std::vector<std::size_t> order(k);
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return average_ranks[a] < average_ranks[b]; });
    const std::size_t left = (k + 1) / 2;
    for (std::size_t i = 0; i < k; ++i)
        out.names.push_back({order[i], average_ranks[order[i]], i < left, i < left ? i : k - 1 - i});
    out.cd_from = 1;
    out.cd_to = 1 + cd.cd;
    // Average ranks lie in [1, k]; the axis ends at a whole rank that holds the CD segment too.
    out.high = std::max(static_cast<double>(std::max<std::size_t>(k, 2)), std::ceil(out.cd_to - 1e-9));
    std::vector<double> level_end;  // per level, the worst rank of its last bar
    for (const auto& clique : cd.cliques) {
        double from = average_ranks[clique.front()], to = from;
        for (const std::size_t j : clique) from = std::min(from, average_ranks[j]), to = std::max(to, average_ranks[j]);
        std::size_t level = 0;
        while (level < level_end.size() && !(level_end[level] < from)) ++level;
        if (level == level_end.size()) level_end.push_back(to);
        level_end[level] = to;
        out.bars.push_back({from, to, level});
    }
    out.levels = level_end.size();
    return out;
}

// Named apart from figure.cpp's helpers: the library is built in unity groups.
namespace cd_drawing {

constexpr double kScaleWidth = 440, kTitleFont = 14, kFont = 12, kSmallFont = 11;
constexpr double kAxisY = 104, kRowHeight = 21, kLevelHeight = 9, kMargin = 16;

std::string label(const CdLayout::Name& n, const std::vector<std::string>& names) {
    return fmt::format("{} ({:.3g})", names.at(n.algorithm), n.rank);
}

void draw(const CdLayout& layout, const std::vector<std::string>& names, const std::string& title,
          const std::string& subtitle, OutputFiles::File& file) {
    const FontSession fonts;
    // The widths of the labels at each side and of the titles, measured before the surface is made.
    double left_w = 0, right_w = 0, title_w = 0;
    std::size_t rows = 0;
    {
        cairo_surface_t* scratch = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 1, 1);
        cairo_t* cr = cairo_create(scratch);
        cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
        for (const auto& n : layout.names) {
            (n.left ? left_w : right_w) = std::max(n.left ? left_w : right_w, text_width(cr, label(n, names), kFont));
            rows = std::max(rows, n.row + 1);
        }
        title_w = text_width(cr, subtitle, kSmallFont);
        cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
        title_w = std::max(title_w, text_width(cr, title, kTitleFont));
        cairo_destroy(cr);
        cairo_surface_destroy(scratch);
    }
    const double x0 = kMargin + left_w + 24, x1 = x0 + kScaleWidth;
    const double width = std::ceil(std::max(x1 + 24 + right_w + kMargin, kMargin + title_w + kMargin));
    const double names_top = kAxisY + 14 + kLevelHeight * static_cast<double>(layout.levels) + 10;
    const double height = std::ceil(names_top + kRowHeight * static_cast<double>(rows) + 6);
    const auto x = [&](double rank) { return x0 + (rank - layout.low) / (layout.high - layout.low) * kScaleWidth; };

    cairo_surface_t* surface = cairo_svg_surface_create_for_stream(write_to_file, &file, width, height);
    cairo_svg_surface_set_document_unit(surface, CAIRO_SVG_UNIT_PX);
    cairo_t* cr = cairo_create(surface);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
    show_text(cr, title, kMargin, 20, kTitleFont);
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_source_rgb(cr, 0.35, 0.35, 0.35);
    show_text(cr, subtitle, kMargin, 38, kSmallFont);

    // The critical difference at the axis' scale, from rank 1, with its name above it.
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    cairo_set_line_width(cr, 1.5);
    const double cd_y = 62;
    cairo_move_to(cr, x(layout.cd_from), cd_y);
    cairo_line_to(cr, x(layout.cd_to), cd_y);
    for (const double r : {layout.cd_from, layout.cd_to}) {
        cairo_move_to(cr, x(r), cd_y - 4);
        cairo_line_to(cr, x(r), cd_y + 4);
    }
    cairo_stroke(cr);
    show_text(cr, "CD", 0.5 * (x(layout.cd_from) + x(layout.cd_to)), cd_y - 7, kSmallFont, 0.5);

    // The axis: whole ranks labelled above it, half ranks as shorter ticks.
    cairo_set_line_width(cr, 1.2);
    cairo_move_to(cr, x(layout.low), kAxisY);
    cairo_line_to(cr, x(layout.high), kAxisY);
    for (double r = layout.low; r <= layout.high + 1e-9; r += 0.5) {
        const bool whole = std::abs(r - std::round(r)) < 1e-9;
        cairo_move_to(cr, x(r), kAxisY);
        cairo_line_to(cr, x(r), kAxisY - (whole ? 7 : 4));
        if (whole) show_text(cr, fmt::format("{:g}", r), x(r), kAxisY - 11, kSmallFont, 0.5);
    }
    cairo_stroke(cr);

    // Each name's line: down from its rank to its row, then out to its side.
    cairo_set_line_width(cr, 1);
    for (const auto& n : layout.names) {
        const double y = names_top + kRowHeight * static_cast<double>(n.row);
        const double end = n.left ? x0 - 12 : x1 + 12;
        cairo_move_to(cr, x(n.rank), kAxisY);
        cairo_line_to(cr, x(n.rank), y);
        cairo_line_to(cr, end, y);
        cairo_stroke(cr);
        show_text(cr, label(n, names), n.left ? end - 4 : end + 4, y + 4, kFont, n.left ? 1 : 0);
    }

    // The groups not significantly different: thick bars under the axis, a little past their ends.
    cairo_set_line_width(cr, 4);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    for (const auto& b : layout.bars) {
        const double y = kAxisY + 14 + kLevelHeight * static_cast<double>(b.level);
        cairo_move_to(cr, x(b.from) - 4, y);
        cairo_line_to(cr, x(b.to) + 4, y);
    }
    cairo_stroke(cr);

    cairo_destroy(cr);
    finish_into(surface, file, false, "the critical-difference diagram");
}

}  // namespace cd_drawing

void write_cd_diagram(const CdLayout& layout, const std::vector<std::string>& names, const std::string& title,
                      const std::string& subtitle, OutputFiles::File& file) {
    cd_drawing::draw(layout, names, title, subtitle, file);
}

}  // namespace pride::html

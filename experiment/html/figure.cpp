#include "experiment/html/figure.hpp"

#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include <fmt/format.h>

#include "experiment/html/cairo_output.hpp"
#include "experiment/html/cairo_text.hpp"
#include "experiment/html/font_session.hpp"
#include "framework/error.hpp"

namespace pride::html {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPlotWidth = 520, kPlotHeight = 300;
constexpr double kTop = 52, kBottom = 48, kRight = 16, kLegendGap = 18;
constexpr double kTickFont = 11, kLabelFont = 12.5, kTitleFont = 14, kLegendLine = 18;

/// The ends of an axis as drawn and where its ticks go.
struct Ticks {
    double lo = 0, hi = 1;
    std::vector<double> major, minor;
    std::vector<std::string> labels;
};

bool usable(double v, Scale s) {
    return std::isfinite(v) && (s == Scale::linear || v > 0);
}

/// Ticks at 1, 2 or 5 times a power of ten, about five over the range.
Ticks linear_ticks(double lo, double hi) {
    Ticks t{lo, hi, {}, {}, {}};
    const double raw = (hi - lo) / 5;
    const double mag = std::pow(10.0, std::floor(std::log10(raw))), norm = raw / mag;
    const double step = (norm < 1.5 ? 1 : norm < 3 ? 2 : norm < 7 ? 5 : 10) * mag;
    for (double k = std::ceil(lo / step - 1e-9); k * step <= hi + 1e-9 * step; ++k) {
        const double v = k * step;
        t.major.push_back(v);
        t.labels.push_back(fmt::format("{:.6g}", v == 0 ? 0.0 : v));  // no "-0"
    }
    return t;
}

/// Ticks at powers of ten (every k-th when the range spans many decades), minor ticks at 2-9
/// times them when few; labels as plain numbers near 1, else 1eK.
Ticks log_ticks(double lo, double hi) {
    Ticks t{lo, hi, {}, {}, {}};
    const int first = static_cast<int>(std::ceil(std::log10(lo) - 1e-9)),
              last = static_cast<int>(std::floor(std::log10(hi) + 1e-9));
    const int decades = last - first, stride = std::max(1, (decades + 7) / 8);
    for (int d = first; d <= last; ++d) {
        if ((d - first) % stride) continue;
        t.major.push_back(std::pow(10.0, d));
        t.labels.push_back(d >= -3 && d <= 4 ? fmt::format("{:g}", std::pow(10.0, d)) : fmt::format("1e{}", d));
    }
    if (decades <= 6)
        for (int d = first - 1; d <= last; ++d)
            for (int m = 2; m <= 9; ++m)
                if (const double v = m * std::pow(10.0, d); v > lo && v < hi) t.minor.push_back(v);
    return t;
}

/// The axis over [lo, hi] of the data (or its fixed ends).
Ticks axis_ticks(const Axis& a, double lo, double hi) {
    if (a.min) lo = *a.min;
    if (a.max) hi = *a.max;
    if (a.scale == Scale::log) {
        if (!(lo > 0 && std::isfinite(hi))) lo = 1, hi = 10;
        if (!a.min) lo = std::pow(10.0, std::floor(std::log10(lo) + 1e-9));
        if (!a.max) hi = std::pow(10.0, std::ceil(std::log10(hi) - 1e-9));
        if (hi <= lo) hi = lo * 10;
        return log_ticks(lo, hi);
    }
    if (!std::isfinite(lo) || !std::isfinite(hi)) lo = 0, hi = 1;
    if (hi <= lo) {
        const double pad = lo == 0 ? 1 : 0.1 * std::abs(lo);
        lo -= pad, hi += pad;
    } else {
        const double pad = 0.04 * (hi - lo);
        if (!a.min) lo -= pad;
        if (!a.max) hi += pad;
    }
    return linear_ticks(lo, hi);
}

void set_dash(cairo_t* cr, int dash) {
    static const double patterns[3][4] = {{7, 3.5, 0, 0}, {2, 2.5, 0, 0}, {9, 3, 2, 3}};
    static const int counts[3] = {2, 2, 4};
    if (dash <= 0)
        cairo_set_dash(cr, nullptr, 0, 0);
    else
        cairo_set_dash(cr, patterns[(dash - 1) % 3], counts[(dash - 1) % 3], 0);
}

void set_colour(cairo_t* cr, Rgb c, double alpha = 1.0) {
    cairo_set_source_rgba(cr, c.r, c.g, c.b, alpha);
}

void draw_marker(cairo_t* cr, Marker m, double x, double y, double r) {
    switch (m) {
        case Marker::circle:
            cairo_new_sub_path(cr);
            cairo_arc(cr, x, y, r, 0, 2 * std::numbers::pi);
            cairo_fill(cr);
            break;
        case Marker::square:
            cairo_rectangle(cr, x - r, y - r, 2 * r, 2 * r);
            cairo_fill(cr);
            break;
        case Marker::diamond:
            cairo_move_to(cr, x, y - 1.3 * r);
            cairo_line_to(cr, x + 1.3 * r, y);
            cairo_line_to(cr, x, y + 1.3 * r);
            cairo_line_to(cr, x - 1.3 * r, y);
            cairo_close_path(cr);
            cairo_fill(cr);
            break;
        case Marker::cross:
            cairo_set_line_width(cr, 2);
            cairo_move_to(cr, x - r, y - r);
            cairo_line_to(cr, x + r, y + r);
            cairo_move_to(cr, x - r, y + r);
            cairo_line_to(cr, x + r, y - r);
            cairo_stroke(cr);
            break;
    }
}

}  // namespace

double quantile(const std::vector<double>& sorted, double p) {
    if (sorted.empty()) return std::numeric_limits<double>::quiet_NaN();
    const double h = p * static_cast<double>(sorted.size() - 1);
    const auto i = static_cast<std::size_t>(std::floor(h));
    if (i + 1 >= sorted.size()) return sorted.back();
    const double a = sorted[i], b = sorted[i + 1], f = h - static_cast<double>(i);
    // a + f (b - a) would be NaN for b = +inf (a run without a value yet) with f = 0 or a = b.
    return f == 0 || a == b ? a : a + f * (b - a);
}

BoxStats box_stats(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    BoxStats s;
    s.q1 = quantile(values, 0.25);
    s.median = quantile(values, 0.5);
    s.q3 = quantile(values, 0.75);
    const double reach = 1.5 * (s.q3 - s.q1);
    s.low = s.q1, s.high = s.q3;
    for (const double v : values) {
        if (v < s.q1 - reach || v > s.q3 + reach)
            s.outliers.push_back(v);
        else
            s.low = std::min(s.low, v), s.high = std::max(s.high, v);
    }
    return s;
}

Figure::Figure(std::string title, Axis x, Axis y) : title_(std::move(title)), x_(std::move(x)), y_(std::move(y)) {}

void Figure::line(std::vector<double> x, std::vector<double> y, Rgb colour, std::string label, int dash, bool steps) {
    series_.push_back(
        {steps ? Kind::steps : Kind::line, std::move(x), std::move(y), {}, colour, std::move(label), dash});
}

void Figure::band(std::vector<double> x, std::vector<double> low, std::vector<double> high, Rgb colour) {
    series_.push_back({Kind::band, std::move(x), std::move(low), std::move(high), colour, {}, 0});
}

void Figure::hline(double y, Rgb colour, std::string label, int dash) {
    series_.push_back({Kind::hline, {}, {y}, {}, colour, std::move(label), dash});
}

void Figure::markers(std::vector<double> x, std::vector<double> y, Rgb colour, std::string label, Marker shape) {
    series_.push_back({Kind::markers, std::move(x), std::move(y), {}, colour, std::move(label), 0, shape});
}

void Figure::box(std::string name, const std::vector<double>& values, Rgb colour) {
    std::vector<double> finite;
    for (const double v : values)
        if (usable(v, y_.scale)) finite.push_back(v);
    boxes_.push_back({std::move(name), finite.empty() ? std::nullopt : std::optional(box_stats(finite)), colour});
}

void Figure::write(OutputFiles::File& file) const {
    const FontSession fonts;
    // The data's ranges (finite values only; positive ones on a log axis).
    double x_lo = kInf, x_hi = -kInf, y_lo = kInf, y_hi = -kInf;
    const auto take_y = [&](double v) {
        if (usable(v, y_.scale)) y_lo = std::min(y_lo, v), y_hi = std::max(y_hi, v);
    };
    for (const Series& s : series_) {
        for (std::size_t i = 0; i < s.x.size(); ++i) {
            const bool shown = i < s.y.size() && usable(s.y[i], y_.scale);
            if (usable(s.x[i], x_.scale) && shown) x_lo = std::min(x_lo, s.x[i]), x_hi = std::max(x_hi, s.x[i]);
        }
        for (std::size_t i = 0; i < s.y.size(); ++i)
            if (s.kind == Kind::hline || (i < s.x.size() && usable(s.x[i], x_.scale))) take_y(s.y[i]);
        for (const double v : s.y2) take_y(v);
    }
    for (const Box& b : boxes_)
        if (b.stats) {
            take_y(b.stats->low), take_y(b.stats->high);
            for (const double v : b.stats->outliers) take_y(v);
        }
    const bool categorical = !boxes_.empty();
    Ticks xt =
        categorical ? Ticks{-0.6, static_cast<double>(boxes_.size()) - 0.4, {}, {}, {}} : axis_ticks(x_, x_lo, x_hi);
    if (categorical)
        for (std::size_t i = 0; i < boxes_.size(); ++i) {
            xt.major.push_back(static_cast<double>(i));
            xt.labels.push_back(boxes_[i].name);
        }
    const Ticks yt = axis_ticks(y_, y_lo, y_hi);

    // Sizes measured before the surface is made: the left margin fits the y tick labels, the
    // legend at the right its longest entry.
    struct Entry {
        const Series* series;
        std::string words;
    };
    std::vector<Entry> legend;
    for (const Series& s : series_)
        if (!s.label.empty()) legend.push_back({&s, s.label});
    for (const Box& b : boxes_)
        if (!b.stats) legend.push_back({nullptr, b.name + ": no finite value"});
    double y_labels = 0, legend_w = 0, title_w = 0, x_label_w = 0;
    {
        cairo_surface_t* scratch = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 1, 1);
        cairo_t* cr = cairo_create(scratch);
        cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
        for (const auto& l : yt.labels) y_labels = std::max(y_labels, text_width(cr, l, kTickFont));
        for (const auto& e : legend) legend_w = std::max(legend_w, 34 + text_width(cr, e.words, kTickFont));
        title_w = std::max(text_width(cr, subtitle_, kTickFont), 0.0);
        for (const auto& l : xt.labels) x_label_w = std::max(x_label_w, text_width(cr, l, kTickFont));
        cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
        title_w = std::max(title_w, text_width(cr, title_, kTitleFont));
        cairo_destroy(cr);
        cairo_surface_destroy(scratch);
    }
    // Categorical labels too wide for their place are turned by 30 degrees.
    const bool turned = categorical && x_label_w > kPlotWidth / static_cast<double>(boxes_.size()) - 6;
    const double left = 30 + y_labels + 10, bottom = kBottom + (turned ? 0.5 * x_label_w : 0);
    const double legend_x = left + kPlotWidth + kLegendGap;
    double width = legend_x + (legend.empty() ? 0 : legend_w) + kRight;
    width = std::ceil(std::max(width, left + title_w + kRight));
    const double height =
        std::ceil(kTop + std::max(kPlotHeight, kLegendLine * static_cast<double>(legend.size())) + bottom);

    const auto tx = [&](double v) {
        const bool lg = !categorical && x_.scale == Scale::log;
        const double a = lg ? std::log10(xt.lo) : xt.lo, b = lg ? std::log10(xt.hi) : xt.hi;
        return left + ((lg ? std::log10(v) : v) - a) / (b - a) * kPlotWidth;
    };
    const auto ty = [&](double v) {
        const bool lg = y_.scale == Scale::log;
        const double a = lg ? std::log10(yt.lo) : yt.lo, b = lg ? std::log10(yt.hi) : yt.hi;
        return kTop + kPlotHeight - ((lg ? std::log10(v) : v) - a) / (b - a) * kPlotHeight;
    };
    const auto x_ok = [&](double v) { return categorical || usable(v, x_.scale); };

    cairo_surface_t* surface = cairo_svg_surface_create_for_stream(write_to_file, &file, width, height);
    cairo_svg_surface_set_document_unit(surface, CAIRO_SVG_UNIT_PX);
    cairo_t* cr = cairo_create(surface);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    show_text(cr, title_, left, 20, kTitleFont);
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    if (!subtitle_.empty()) {
        cairo_set_source_rgb(cr, 0.35, 0.35, 0.35);
        show_text(cr, subtitle_, left, 38, kTickFont);
    }

    // Grid lines and ticks.
    cairo_set_line_width(cr, 1);
    cairo_set_source_rgb(cr, 0.9, 0.9, 0.92);
    for (const double v : yt.major) {
        cairo_move_to(cr, left, std::round(ty(v)) + 0.5);
        cairo_line_to(cr, left + kPlotWidth, std::round(ty(v)) + 0.5);
    }
    if (!categorical)
        for (const double v : xt.major) {
            cairo_move_to(cr, std::round(tx(v)) + 0.5, kTop);
            cairo_line_to(cr, std::round(tx(v)) + 0.5, kTop + kPlotHeight);
        }
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
    for (std::size_t i = 0; i < yt.major.size(); ++i) {
        const double y = ty(yt.major[i]);
        cairo_move_to(cr, left - 5, y);
        cairo_line_to(cr, left, y);
        show_text(cr, yt.labels[i], left - 8, y + 4, kTickFont, 1);
    }
    for (const double v : yt.minor) {
        cairo_move_to(cr, left - 3, ty(v));
        cairo_line_to(cr, left, ty(v));
    }
    for (std::size_t i = 0; i < xt.major.size(); ++i) {
        const double x = tx(xt.major[i]), y = kTop + kPlotHeight;
        cairo_move_to(cr, x, y);
        cairo_line_to(cr, x, y + 5);
        if (turned) {
            cairo_save(cr);
            cairo_move_to(cr, x, y + 16);
            cairo_rotate(cr, std::numbers::pi / 6);
            cairo_show_text(cr, xt.labels[i].c_str());
            cairo_restore(cr);
        } else {
            show_text(cr, xt.labels[i], x, y + 18, kTickFont, 0.5);
        }
    }
    for (const double v : xt.minor) {
        cairo_move_to(cr, tx(v), kTop + kPlotHeight);
        cairo_line_to(cr, tx(v), kTop + kPlotHeight + 3);
    }
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    show_text(cr, x_.label, left + kPlotWidth / 2, height - 12, kLabelFont, 0.5);
    cairo_save(cr);
    cairo_move_to(cr, 18, kTop + kPlotHeight / 2 + text_width(cr, y_.label, kLabelFont) / 2);
    cairo_rotate(cr, -std::numbers::pi / 2);
    cairo_show_text(cr, y_.label.c_str());
    cairo_restore(cr);

    // The data, clipped to the plot area: bands first, then lines and markers over them.
    cairo_save(cr);
    cairo_rectangle(cr, left, kTop, kPlotWidth, kPlotHeight);
    cairo_clip(cr);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    for (const Series& s : series_) {
        if (s.kind != Kind::band) continue;
        // One polygon per run of points where both ends are drawable.
        for (std::size_t i = 0; i < s.x.size();) {
            const auto ok = [&](std::size_t k) {
                return x_ok(s.x[k]) && usable(s.y[k], y_.scale) && usable(s.y2[k], y_.scale);
            };
            if (!ok(i)) {
                ++i;
                continue;
            }
            std::size_t j = i;
            while (j + 1 < s.x.size() && ok(j + 1)) ++j;
            cairo_move_to(cr, tx(s.x[i]), ty(s.y2[i]));
            for (std::size_t k = i + 1; k <= j; ++k) cairo_line_to(cr, tx(s.x[k]), ty(s.y2[k]));
            for (std::size_t k = j + 1; k-- > i;) cairo_line_to(cr, tx(s.x[k]), ty(s.y[k]));
            cairo_close_path(cr);
            set_colour(cr, s.colour, 0.2);
            cairo_fill(cr);
            i = j + 1;
        }
    }
    for (std::size_t b = 0; b < boxes_.size(); ++b) {
        if (!boxes_[b].stats) continue;
        const BoxStats& st = *boxes_[b].stats;
        const double x = tx(static_cast<double>(b)), half = std::min(40.0, kPlotWidth / boxes_.size() * 0.3);
        set_dash(cr, 0);
        cairo_set_line_width(cr, 1.2);
        cairo_rectangle(cr, x - half, ty(st.q3), 2 * half, ty(st.q1) - ty(st.q3));
        set_colour(cr, boxes_[b].colour, 0.3);
        cairo_fill_preserve(cr);
        set_colour(cr, boxes_[b].colour);
        cairo_stroke(cr);
        cairo_move_to(cr, x, ty(st.q3));
        cairo_line_to(cr, x, ty(st.high));
        cairo_move_to(cr, x - half / 2, ty(st.high));
        cairo_line_to(cr, x + half / 2, ty(st.high));
        cairo_move_to(cr, x, ty(st.q1));
        cairo_line_to(cr, x, ty(st.low));
        cairo_move_to(cr, x - half / 2, ty(st.low));
        cairo_line_to(cr, x + half / 2, ty(st.low));
        cairo_stroke(cr);
        cairo_set_line_width(cr, 2.4);
        cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
        cairo_move_to(cr, x - half, ty(st.median));
        cairo_line_to(cr, x + half, ty(st.median));
        cairo_stroke(cr);
        set_colour(cr, boxes_[b].colour);
        cairo_set_line_width(cr, 1.2);
        for (const double v : st.outliers) {
            cairo_new_sub_path(cr);
            cairo_arc(cr, x, ty(v), 3, 0, 2 * std::numbers::pi);
        }
        cairo_stroke(cr);
    }
    for (const Series& s : series_) {
        set_colour(cr, s.colour);
        set_dash(cr, s.dash);
        cairo_set_line_width(cr, 1.8);
        if (s.kind == Kind::hline) {
            if (usable(s.y[0], y_.scale)) {
                cairo_move_to(cr, left, ty(s.y[0]));
                cairo_line_to(cr, left + kPlotWidth, ty(s.y[0]));
                cairo_stroke(cr);
            }
        } else if (s.kind == Kind::line || s.kind == Kind::steps) {
            bool open = false;
            for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
                if (!x_ok(s.x[i]) || !usable(s.y[i], y_.scale)) {
                    open = false;
                    continue;
                }
                if (!open) {
                    cairo_move_to(cr, tx(s.x[i]), ty(s.y[i]));
                    open = true;
                    continue;
                }
                if (s.kind == Kind::steps) cairo_line_to(cr, tx(s.x[i]), ty(s.y[i - 1]));
                cairo_line_to(cr, tx(s.x[i]), ty(s.y[i]));
            }
            cairo_stroke(cr);
        } else if (s.kind == Kind::markers) {
            set_dash(cr, 0);
            for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i)
                if (x_ok(s.x[i]) && usable(s.y[i], y_.scale)) draw_marker(cr, s.marker, tx(s.x[i]), ty(s.y[i]), 4.5);
        }
    }
    cairo_restore(cr);
    set_dash(cr, 0);
    cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
    cairo_set_line_width(cr, 1);
    cairo_rectangle(cr, left + 0.5, kTop + 0.5, kPlotWidth - 1, kPlotHeight - 1);
    cairo_stroke(cr);

    // The legend: a swatch of each labelled series and its words.
    for (std::size_t i = 0; i < legend.size(); ++i) {
        const double y = kTop + 8 + kLegendLine * static_cast<double>(i);
        if (const Series* s = legend[i].series) {
            set_colour(cr, s->colour);
            if (s->kind == Kind::markers) {
                draw_marker(cr, s->marker, legend_x + 13, y, 4.5);
            } else {
                set_dash(cr, s->dash);
                cairo_set_line_width(cr, 2.2);
                cairo_move_to(cr, legend_x, y);
                cairo_line_to(cr, legend_x + 26, y);
                cairo_stroke(cr);
                set_dash(cr, 0);
            }
        }
        cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
        show_text(cr, legend[i].words, legend_x + 34, y + 4, kTickFont);
    }

    cairo_destroy(cr);
    finish_into(surface, file, false, "the figure");
}

}  // namespace pride::html

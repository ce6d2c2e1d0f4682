#pragma once
// The HTML report's charts, drawn with cairo as SVG: lines (plain or steps), translucent bands,
// horizontal lines, markers and boxplots on one plot area, with axes and ticks on linear or log
// scales, a title, a subtitle and a legend at the right. Every chart of the report is drawn here;
// maps and paths are draw.hpp's.
#include <optional>
#include <string>
#include <vector>

#include "experiment/html/colour.hpp"
#include "framework/output_files.hpp"

namespace pride::html {

enum class Scale { linear, log };

struct Axis {
    std::string label;
    Scale scale = Scale::linear;
    std::optional<double> min, max;  // fixed ends; else the data's (log: whole decades)
};

enum class Marker { circle, cross, square, diamond };

/// Quartiles and whiskers of a boxplot (Tukey's: whiskers at the furthest values within 1.5
/// interquartile ranges of the box, the rest outliers); quartiles interpolated linearly between
/// order statistics (numpy's default). `values` finite and not empty.
struct BoxStats {
    double q1 = 0, median = 0, q3 = 0, low = 0, high = 0;
    std::vector<double> outliers;
};
BoxStats box_stats(std::vector<double> values);

/// The p-quantile (0 <= p <= 1) of sorted values, interpolated linearly (numpy's default).
double quantile(const std::vector<double>& sorted, double p);

class Figure {
  public:
    Figure(std::string title, Axis x, Axis y);

    /// A line through the points, broken where a point is not finite (or not positive on a log
    /// axis). `dash` 0 is solid, 1, 2, 3 three dash patterns; `steps` holds each y until the next x.
    void line(std::vector<double> x, std::vector<double> y, Rgb colour, std::string label, int dash = 0,
              bool steps = false);
    /// A translucent band between `low` and `high` (no legend entry), broken as line() is.
    void band(std::vector<double> x, std::vector<double> low, std::vector<double> high, Rgb colour);
    /// A horizontal line across the plot area.
    void hline(double y, Rgb colour, std::string label, int dash = 0);
    /// Markers at the points (a legend entry when `label` is not empty).
    void markers(std::vector<double> x, std::vector<double> y, Rgb colour, std::string label, Marker shape);
    /// A boxplot of `values` (finite ones drawn) at the next place on a categorical x axis named
    /// `name`; a figure with boxes has that axis instead of a numeric one.
    void box(std::string name, const std::vector<double>& values, Rgb colour);
    /// A line of smaller text under the title.
    void subtitle(std::string text) { subtitle_ = std::move(text); }

    /// Writes the figure as SVG into `file` and closes it; InputError naming it when it cannot.
    void write(OutputFiles::File& file) const;

  private:
    enum class Kind { line, steps, band, hline, markers };
    struct Series {
        Kind kind;
        std::vector<double> x, y, y2;
        Rgb colour;
        std::string label;
        int dash = 0;
        Marker marker = Marker::circle;
    };
    struct Box {
        std::string name;
        std::optional<BoxStats> stats;  // empty: no finite value
        Rgb colour;
    };
    std::string title_, subtitle_;
    Axis x_, y_;
    std::vector<Series> series_;
    std::vector<Box> boxes_;
};

}  // namespace pride::html

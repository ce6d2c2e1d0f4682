#pragma once
// Colours of the report's pictures: one per series, the same for an algorithm in every figure of
// a page (its convergence line, its box, its path on the map, its marker beside a Pareto front).
#include <array>
#include <cstddef>

namespace pride::html {

/// A colour as red, green and blue in [0, 1].
struct Rgb {
    double r = 0, g = 0, b = 0;
};

/// The colour of series i: Tableau's ten (matplotlib's default cycle, so the page reads like the
/// `--plots` figures), then again.
inline Rgb series_colour(std::size_t i) {
    static constexpr std::array<std::array<int, 3>, 10> tableau{{{31, 119, 180},
                                                                 {255, 127, 14},
                                                                 {44, 160, 44},
                                                                 {214, 39, 40},
                                                                 {148, 103, 189},
                                                                 {140, 86, 75},
                                                                 {227, 119, 194},
                                                                 {127, 127, 127},
                                                                 {188, 189, 34},
                                                                 {23, 190, 207}}};
    const auto& c = tableau[i % tableau.size()];
    return {c[0] / 255.0, c[1] / 255.0, c[2] / 255.0};
}

}  // namespace pride::html

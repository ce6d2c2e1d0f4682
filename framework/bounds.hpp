#pragma once
// Bound handling as a policy: what to do with a coordinate an operator moved out of the box.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>

namespace pride {

/// Puts each coordinate on the nearest face of the box (the project's default); NaN goes to the
/// lower face.
struct Clamp {
    static constexpr const char* name = "clamp";
    void operator()(std::span<double> x, std::span<const double> lo, std::span<const double> hi) const {
        // max(lo, min(x, hi)) compiles to branch-free minsd/maxsd and sends NaN to lo.
        for (std::size_t i = 0; i < x.size(); ++i) x[i] = std::max(lo[i], std::min(x[i], hi[i]));
    }
};

/// Mirrors each coordinate at the faces it crossed, as often as needed (so far excursions land
/// inside too); a NaN coordinate goes to the lower face.
struct Reflect {
    static constexpr const char* name = "reflect";
    void operator()(std::span<double> x, std::span<const double> lo, std::span<const double> hi) const {
        for (std::size_t i = 0; i < x.size(); ++i) {
            double v = x[i];
            if (v >= lo[i] && v <= hi[i]) continue;
            const double width = hi[i] - lo[i];
            if (!(width > 0.0) || !std::isfinite(v)) {
                x[i] = std::isnan(v) ? lo[i] : (v < lo[i] ? lo[i] : hi[i]);
                continue;
            }
            const double outside = v < lo[i] ? lo[i] - v : v - hi[i];  // > 0
            if (outside <= width) {  // one mirror, the usual case; also safe near +-DBL_MAX
                x[i] = v < lo[i] ? std::min(hi[i], lo[i] + outside) : std::max(lo[i], hi[i] - outside);
                continue;
            }
            double r = std::fmod(v - lo[i], 2.0 * width);  // position in one mirror period
            if (r < 0) r += 2.0 * width;
            v = r <= width ? lo[i] + r : hi[i] - (r - width);
            x[i] = !(v >= lo[i]) ? lo[i] : (v > hi[i] ? hi[i] : v);  // rounding (and overflow) guard
        }
    }
};

}  // namespace pride

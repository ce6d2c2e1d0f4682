#include "problems/grid/clearance.hpp"

#include <algorithm>
#include <string>

#include "framework/error.hpp"

namespace pride::grid {

void ClearanceParams::validate() const {
    require(bands >= 1 && bands <= 63, "clearance",
            "bands must be a whole number in [1, 63], got " + std::to_string(bands));
    require(band_width >= 1 && band_width <= 1'000'000, "clearance",
            "band_width must be a whole number in [1, 1000000], got " + std::to_string(band_width));
}

namespace {

__extension__ typedef __int128 Wide;  // GCC/Clang built-in: products of two 64-bit values

/// Felzenszwalb and Huttenlocher's 1-D transform, d[q] = min over p of (q - p)^2 + f[p], by the
/// lower envelope of the parabolas. The intersections are kept as fractions and compared by cross
/// multiplication, so the envelope, and every distance, is exact (no floating-point tie to break).
/// Samples at kNoObstacle are left out: they lie on no envelope.
class Envelope {
  public:
    explicit Envelope(std::size_t n) : v_(n), num_(n), den_(n) {}

    void run(const std::int64_t* f, std::int64_t* d, int n) {
        int k = -1;  // the envelope's last parabola; z[0] = -infinity is implicit
        for (int q = 0; q < n; ++q) {
            if (f[q] == kNoObstacle) continue;
            std::int64_t sn = 0, sd = 1;
            while (k >= 0) {
                const std::int64_t p = v_[k];
                sn = (f[q] + std::int64_t{q} * q) - (f[p] + p * p);
                sd = 2 * (q - p);
                // Parabola k is hidden when q's takes over no later than k's own start: sn / sd <= z[k].
                if (k > 0 && Wide{sn} * den_[k] <= Wide{num_[k]} * sd) {
                    --k;
                    continue;
                }
                break;
            }
            ++k;
            v_[k] = q;
            num_[k] = sn;
            den_[k] = sd;
        }
        if (k < 0) {
            std::fill(d, d + n, kNoObstacle);
            return;
        }
        for (int q = 0, j = 0; q < n; ++q) {
            while (j < k && Wide{num_[j + 1]} < Wide{q} * den_[j + 1]) ++j;  // z[j + 1] < q
            const std::int64_t p = v_[j];
            d[q] = (q - p) * (q - p) + f[p];
        }
    }

  private:
    std::vector<std::int64_t> v_;          // the envelope's parabolas (their sample positions)
    std::vector<std::int64_t> num_, den_;  // where each begins: num / den, den > 0
};

/// The band thresholds (1 + k w)^2 for k = 0..B.
std::vector<std::int64_t> thresholds(const ClearanceParams& p) {
    std::vector<std::int64_t> t(static_cast<std::size_t>(p.bands) + 1);
    for (int k = 0; k <= p.bands; ++k) {
        const std::int64_t r = 1 + std::int64_t{k} * p.band_width;  // <= 1 + 63e6: squares fit easily
        t[static_cast<std::size_t>(k)] = r * r;
    }
    return t;
}

int band_cost(const std::vector<std::int64_t>& t, std::int64_t d2) noexcept {
    if (d2 == 0) return static_cast<int>(t.size());  // blocked: B + 1
    // The band: how many of (1 + w)^2, ..., (1 + B w)^2 are <= d2 (d2 >= 1 = t[0] on a free cell).
    const auto k = std::upper_bound(t.begin() + 1, t.end(), d2) - (t.begin() + 1);
    return static_cast<int>(t.size()) - 1 - static_cast<int>(k);
}

}  // namespace

std::vector<std::int64_t> squared_distance_transform(const GridMap& map) {
    const int w = map.width(), h = map.height();
    std::vector<std::int64_t> out(map.size());
    const auto n = static_cast<std::size_t>(std::max(w, h));
    Envelope envelope(n);
    std::vector<std::int64_t> f(n), d(n);
    for (int x = 0; x < w; ++x) {  // columns: the distance to the nearest blocked cell in the column
        for (int y = 0; y < h; ++y) f[static_cast<std::size_t>(y)] = map.free({x, y}) ? kNoObstacle : 0;
        envelope.run(f.data(), d.data(), h);
        for (int y = 0; y < h; ++y) out[map.index({x, y})] = d[static_cast<std::size_t>(y)];
    }
    for (int y = 0; y < h; ++y) {  // rows: the nearest of those, over the row
        std::int64_t* row = out.data() + map.index({0, y});
        std::copy(row, row + w, f.begin());
        envelope.run(f.data(), row, w);
    }
    return out;
}

int clearance_band_cost(std::int64_t squared_distance, const ClearanceParams& params) {
    params.validate();
    require(squared_distance >= 0, "clearance",
            "a squared distance must be >= 0, got " + std::to_string(squared_distance));
    return band_cost(thresholds(params), squared_distance);
}

MapClearance::MapClearance(const GridMap& map, const ClearanceParams& params)
    : width_(map.width()), height_(map.height()), params_(params) {
    params.validate();
    const std::vector<std::int64_t> t = thresholds(params);
    const std::vector<std::int64_t> d2 = squared_distance_transform(map);
    cost_.resize(d2.size());
    for (std::size_t i = 0; i < d2.size(); ++i) cost_[i] = static_cast<std::uint8_t>(band_cost(t, d2[i]));
}

}  // namespace pride::grid

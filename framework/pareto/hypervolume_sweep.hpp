#pragma once
// Exact hypervolume in two and three dimensions by sweeping, the base cases of hypervolume.hpp and
// of WFG (hypervolume_wfg.hpp). Internal: points are stored flat, `stride` doubles apart, and every
// point strictly dominates the reference point (the callers filter the others out).
//
// 3-D: the dimension-sweep algorithm of Beume, Fonseca, López-Ibáñez, Paquete and Vahrenhold 2009
// ("On the complexity of computing the hypervolume indicator", IEEE TEC 13(5), sec. III; first
// described by Fonseca, Paquete and López-Ibáñez 2006), O(N log N): the points in increasing f3;
// the non-dominated (f1, f2) staircase of those seen so far is kept in a balanced tree, with its
// area; each slab between two consecutive f3 values adds area * thickness.
// Decisions the paper leaves open: points are swept in (f3, f1, f2) order, so that the result is a
// function of the set alone, bit for bit, whatever the order of the input; a point whose (f1, f2)
// is weakly dominated by the staircase changes nothing (equal points included); the tree's nodes
// come from one buffer sized for N points, so no allocation per point.
#include <algorithm>
#include <cstddef>
#include <iterator>
#include <map>
#include <memory_resource>
#include <numeric>
#include <vector>

namespace pride::pareto::detail {

/// Buffers of the sweeps, reused across calls (WFG calls them many times).
struct SweepScratch {
    std::vector<std::size_t> order;
    std::vector<std::max_align_t> tree;  // the 3-D staircase's nodes
};

/// prod_i (ref_i - p_i) over the first d coordinates: the volume p dominates alone.
inline double box_volume(const double* p, std::size_t d, const double* ref) noexcept {
    double v = 1.0;
    for (std::size_t i = 0; i < d; ++i) v *= ref[i] - p[i];
    return v;
}

/// 2-D: in increasing f1 (then f2), each point that lowers the staircase adds the strip between
/// its f2 and the previous lowest f2, of width ref1 - f1. O(N log N).
inline double hypervolume_2d(const double* p, std::size_t n, std::size_t stride, const double* ref, SweepScratch& s) {
    s.order.resize(n);
    std::iota(s.order.begin(), s.order.end(), std::size_t{0});
    std::sort(s.order.begin(), s.order.end(), [p, stride](std::size_t a, std::size_t b) {
        const double* pa = p + a * stride;
        const double* pb = p + b * stride;
        return pa[0] != pb[0] ? pa[0] < pb[0] : pa[1] < pb[1];
    });
    double volume = 0.0, lowest = ref[1];
    for (const std::size_t k : s.order) {
        const double* q = p + k * stride;
        if (q[1] < lowest) {
            volume += (ref[0] - q[0]) * (lowest - q[1]);
            lowest = q[1];
        }
    }
    return volume;
}

/// 3-D: Beume et al. 2009's sweep (see the top of this file).
inline double hypervolume_3d(const double* p, std::size_t n, std::size_t stride, const double* ref, SweepScratch& s) {
    if (n == 0) return 0.0;
    s.order.resize(n);
    std::iota(s.order.begin(), s.order.end(), std::size_t{0});
    std::sort(s.order.begin(), s.order.end(), [p, stride](std::size_t a, std::size_t b) {
        const double* pa = p + a * stride;
        const double* pb = p + b * stride;
        if (pa[2] != pb[2]) return pa[2] < pb[2];
        return pa[0] != pb[0] ? pa[0] < pb[0] : pa[1] < pb[1];
    });
    // A map node holds two doubles and three pointers and a colour: 64 bytes is enough on the
    // usual ABIs; if not, the resource falls back on new (still correct).
    const std::size_t words = (n * 64 + 256) / sizeof(std::max_align_t);
    if (s.tree.size() < words) s.tree.resize(words);
    std::pmr::monotonic_buffer_resource pool(s.tree.data(), s.tree.size() * sizeof(std::max_align_t));
    std::pmr::map<double, double> front(&pool);  // f1 -> f2: increasing f1, decreasing f2
    double area = 0.0, volume = 0.0;
    double z = p[s.order.front() * stride + 2];
    for (const std::size_t k : s.order) {
        const double* q = p + k * stride;
        const double x = q[0], y = q[1];
        volume += area * (q[2] - z);
        z = q[2];
        auto it = front.lower_bound(x);  // the first step at f1 >= x
        if (it != front.end() && it->first == x && it->second <= y) continue;
        double height = ref[1];  // the staircase's level just left of x
        if (it != front.begin()) {
            const auto before = std::prev(it);
            if (before->second <= y) continue;
            height = before->second;
        }
        // Remove the steps q dominates, adding what q covers above each, then up to the next step.
        double from = x;
        while (it != front.end() && it->second >= y) {
            area += (it->first - from) * (height - y);
            from = it->first;
            height = it->second;
            it = front.erase(it);
        }
        area += ((it == front.end() ? ref[0] : it->first) - from) * (height - y);
        front.emplace_hint(it, x, y);
    }
    return volume + area * (ref[2] - z);
}

}  // namespace pride::pareto::detail

#pragma once
// Exact hypervolume in any dimension: the WFG algorithm of While, Bradstreet and Barone 2012
// ("A fast way of calculating exact hypervolumes", IEEE TEC 16(1)). Internal, as
// hypervolume_sweep.hpp: points flat, `stride` apart, every one strictly dominating the reference.
//
//   wfg(S) = sum_k exclhv(S, k),  exclhv(S, k) = inclhv(s_k) - wfg(nds(limitset(S, k))),
//   limitset(S, k) = { max(s_k, s_j) componentwise : j > k },
//
// inclhv(p) being the box p dominates alone and nds() the non-dominated points. As in the paper's
// implementation, S is first sorted by its last objective, decreasing: every point of the limit set
// of s_k then has s_k's last objective, so exclhv(S, k) = (r_d - s_kd) * exclhv in d - 1 objectives,
// and each level of the recursion drops one objective, down to the 2-D or 3-D sweep.
// Decisions the paper leaves open: ties in the last objective are taken in input order (the sum
// depends on it only through rounding); nds() keeps the first of equal limit points; the buffers
// of each level (one limit set is alive per number of objectives) are sized once per call.
#include <algorithm>
#include <cstddef>
#include <numeric>
#include <vector>

#include "framework/pareto/hypervolume_sweep.hpp"

namespace pride::pareto::detail {

struct WfgScratch {
    std::size_t stride = 0;
    std::size_t base = 3;                         // the dimension handed to a sweep (2 or 3)
    std::vector<std::vector<double>> limit;       // limit[d]: a limit set in d objectives
    std::vector<std::vector<std::size_t>> order;  // order[d]: a set in d objectives, sorted
    std::vector<std::vector<double>> candidate;   // candidate[d]: one limit point in d objectives
    SweepScratch sweep;

    /// Buffers for sets of up to n points of `objectives` coordinates.
    void prepare(std::size_t n, std::size_t objectives, std::size_t base_dimension) {
        stride = objectives;
        base = base_dimension;
        limit.resize(objectives + 1);
        order.resize(objectives + 1);
        candidate.resize(objectives + 1);
        for (auto& c : candidate) c.resize(stride);
        for (auto& l : limit)
            if (l.size() < n * stride) l.resize(n * stride);
        for (auto& o : order)
            if (o.size() < n) o.resize(n);
        sweep.order.reserve(n);
    }
};

/// a <= b in the first d coordinates.
inline bool weakly_dominates_flat(const double* a, const double* b, std::size_t d) noexcept {
    for (std::size_t i = 0; i < d; ++i)
        if (a[i] > b[i]) return false;
    return true;
}

/// Adds `w` to the non-dominated set set[0, count) (d coordinates, stride apart) unless a member
/// weakly dominates it, removing the members it dominates; returns the new count. If w dominates a
/// member, no member weakly dominates w (the members are mutually non-dominated), so one pass does.
inline std::size_t add_nondominated(double* set, std::size_t count, const double* w, std::size_t d,
                                    std::size_t stride) noexcept {
    for (std::size_t t = 0; t < count;) {
        double* u = set + t * stride;
        if (weakly_dominates_flat(u, w, d)) return count;
        if (weakly_dominates_flat(w, u, d)) {
            --count;
            if (t != count) std::copy_n(set + count * stride, d, u);  // the last member takes its place
        } else {
            ++t;
        }
    }
    if (w != set + count * stride) std::copy_n(w, d, set + count * stride);  // w may be in place already
    return count + 1;
}

/// The hypervolume of p[0, n) in the first d objectives (any set; non-dominated is faster).
inline double wfg(const double* p, std::size_t n, std::size_t d, const double* ref, WfgScratch& s) {
    if (n == 0) return 0.0;
    if (n == 1) return box_volume(p, d, ref);
    if (d == 2) return hypervolume_2d(p, n, s.stride, ref, s.sweep);
    if (d == 3 && s.base == 3) return hypervolume_3d(p, n, s.stride, ref, s.sweep);
    const std::size_t stride = s.stride, last = d - 1;
    std::size_t* order = s.order[d].data();
    std::iota(order, order + n, std::size_t{0});
    std::sort(order, order + n, [p, stride, last](std::size_t a, std::size_t b) {
        const double va = p[a * stride + last], vb = p[b * stride + last];
        return va != vb ? va > vb : a < b;
    });
    double* limit = s.limit[last].data();
    double* w = s.candidate[last].data();
    double volume = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        const double* a = p + order[k] * stride;
        std::size_t count = 0;
        for (std::size_t j = k + 1; j < n; ++j) {
            const double* b = p + order[j] * stride;
            for (std::size_t i = 0; i < last; ++i) w[i] = std::max(a[i], b[i]);
            count = add_nondominated(limit, count, w, last, stride);
        }
        volume += (ref[last] - a[last]) * (box_volume(a, last, ref) - wfg(limit, count, last, ref, s));
    }
    return volume;
}

}  // namespace pride::pareto::detail

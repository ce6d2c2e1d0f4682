// The core and the reducts: searches over attribute subsets of the collapsed table.
#include "roughset/reducts.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "roughset/partition.hpp"

namespace pride::roughset {

using namespace detail;

namespace {

// Whether each position k in [lo, hi) of B is in the core, given `outside`, the partition of the
// merged rows on every position of B outside [lo, hi): the partition on B - {k} is `outside`
// refined by the rest of [lo, hi), built by halves, so that the whole search refines
// O(|B| log |B|) times instead of |B|^2 (a table may have 100,000 columns).
void core_search(const Collapsed& rows, const Partition& outside, std::size_t lo, std::size_t hi,
                 std::vector<char>& in_core) {
    if (hi - lo == 1) {
        // Dropping k keeps POS_B(D) iff every (B - k)-class has a single generalised decision.
        std::vector<std::uint32_t> g(outside.count, none);
        for (std::size_t c = 0; c < rows.rows; ++c) {
            auto& v = g[outside.id[c]];
            if (v == none) {
                v = rows.gd[c];
            } else if (v != rows.gd[c]) {
                in_core[lo] = 1;
                return;
            }
        }
        return;
    }
    const std::size_t mid = lo + (hi - lo) / 2;
    Partition left = outside;
    for (std::size_t k = mid; k < hi; ++k) left = refine(left, rows.cols[k]);
    core_search(rows, left, lo, mid, in_core);
    left = {};
    Partition right = outside;
    for (std::size_t k = lo; k < mid; ++k) right = refine(right, rows.cols[k]);
    core_search(rows, right, mid, hi, in_core);
}

}  // namespace

Attributes core(const DecisionTable& t, const Attributes& C0, const Attributes& D) {
    const Attributes C = checked(t, C0, "C");
    const Collapsed rows(t, C, checked(t, D, "D"));
    Attributes out;
    if (C.empty()) return out;
    std::vector<char> in_core(C.size(), 0);
    core_search(rows, single_class(rows.rows), 0, C.size(), in_core);
    for (std::size_t k = 0; k < C.size(); ++k)
        if (in_core[k]) out.push_back(C[k]);
    return out;
}

std::vector<Attributes> reducts(const DecisionTable& t, const Attributes& C0, const Attributes& D) {
    const Attributes C = checked(t, C0, "C");
    require_small(C, "reducts");
    Collapsed rows(t, C, checked(t, D, "D"));
    const std::size_t m = C.size();
    const std::uint64_t full = (std::uint64_t{1} << m) - 1;
    // Whether each subset keeps POS_C(D) is monotone: supersets of a keeping set keep it, subsets of
    // a losing set lose it. Levels are settled from both ends, the one with fewer unknown subsets
    // first, and every answer is spread up or down, so only the subsets near the border are checked.
    enum : char { unknown = 0, keeps = 1, loses = 2 };
    std::vector<char> state(std::size_t{1} << m, unknown);
    auto spread_up = [&](auto&& self, std::uint64_t s) -> void {
        if (state[s] == keeps) return;
        state[s] = keeps;
        for (std::size_t k = 0; k < m; ++k)
            if (!(s >> k & 1)) self(self, s | std::uint64_t{1} << k);
    };
    auto spread_down = [&](auto&& self, std::uint64_t s) -> void {
        if (state[s] == loses) return;
        state[s] = loses;
        for (std::size_t k = 0; k < m; ++k)
            if (s >> k & 1) self(self, s & ~(std::uint64_t{1} << k));
    };
    std::vector<std::vector<std::uint64_t>> level(m + 1);
    for (std::uint64_t s = 0; s <= full; ++s) level[static_cast<std::size_t>(std::popcount(s))].push_back(s);
    spread_up(spread_up, full);
    auto unknown_in = [&](std::size_t k) {
        return std::count_if(level[k].begin(), level[k].end(), [&](std::uint64_t s) { return state[s] == unknown; });
    };
    std::size_t lo = 0, hi = m;
    while (lo <= hi && hi != static_cast<std::size_t>(-1)) {
        const bool low_first = unknown_in(lo) <= unknown_in(hi);
        const std::size_t k = low_first ? lo : hi;
        for (auto s : level[k]) {
            if (state[s] != unknown) continue;
            if (rows.keeps(s))
                spread_up(spread_up, s);
            else
                spread_down(spread_down, s);
        }
        if (low_first)
            ++lo;
        else if (hi-- == 0)
            break;
    }
    // A reduct keeps POS and none of its one-smaller subsets does.
    std::vector<Attributes> out;
    for (std::uint64_t s = 0; s <= full; ++s) {
        if (state[s] != keeps) continue;
        bool minimal = true;
        for (std::size_t k = 0; k < m && minimal; ++k)
            if (s >> k & 1) minimal = state[s & ~(std::uint64_t{1} << k)] == loses;
        if (minimal) out.push_back(attributes_of(C, s));
    }
    std::sort(out.begin(), out.end(), by_size_then_lex);
    return out;
}

Attributes quick_reduct(const DecisionTable& t, const Attributes& C0, const Attributes& D) {
    const Attributes C = checked(t, C0, "C");
    const Collapsed rows(t, C, checked(t, D, "D"));
    std::size_t target = 0;
    for (std::size_t c = 0; c < rows.rows; ++c)
        if (rows.gd[c] != rows.conflict) target += rows.weight[c];
    std::vector<std::size_t> chosen;  // positions, in the order added
    std::vector<char> used(C.size(), 0);
    Partition p = single_class(rows.rows);
    std::size_t have = rows.positive(p);
    while (have < target) {
        std::size_t best = C.size(), best_pos = 0;
        Partition best_p;
        for (std::size_t k = 0; k < C.size(); ++k) {
            if (used[k]) continue;
            Partition q = refine(p, rows.cols[k]);
            const std::size_t n = rows.positive(q);
            if (best == C.size() || n > best_pos) {
                best = k;
                best_pos = n;
                best_p = std::move(q);
            }
        }
        used[best] = 1;
        chosen.push_back(best);
        p = std::move(best_p);
        have = best_pos;
    }
    // Greedy additions can make earlier ones unnecessary: drop those, last added first.
    for (std::size_t i = chosen.size(); i-- > 0;) {
        std::vector<std::size_t> rest;
        for (std::size_t j = 0; j < chosen.size(); ++j)
            if (j != i) rest.push_back(chosen[j]);
        if (rows.positive(rows.partition(rest)) == target) chosen = std::move(rest);
    }
    Attributes out;
    for (auto k : chosen) out.push_back(C[k]);
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace pride::roughset

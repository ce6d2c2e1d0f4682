// Value reducts, value cores and minimal decision rules.
#include "roughset/rules.hpp"

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

bool matches(const DecisionTable& t, const Rule& rule, std::size_t row) {
    return std::all_of(rule.conditions.begin(), rule.conditions.end(),
                       [&](const Condition& c) { return t.value(row, c.attribute) == c.value; });
}

namespace {

// Per merged row, the masks (over positions of B) of its value reducts; with `want_groups`, also
// the candidate rules: one per (mask, class of merged rows that the rule matches), shared by the
// rows of that class. Subsets are visited by increasing size, so a subset that contains a reduct
// already found for a row is not minimal for it and is skipped.
struct ValueReducts {
    std::vector<std::vector<std::uint64_t>> masks;  // per merged row
    struct Group {
        std::uint64_t mask;
        std::vector<std::uint32_t> matched;  // merged rows, ascending
    };
    std::vector<Group> groups;
};

ValueReducts search_value_reducts(Collapsed& rows, std::size_t m, bool want_groups) {
    ValueReducts out;
    out.masks.resize(rows.rows);
    const std::uint64_t full = (std::uint64_t{1} << m) - 1;
    std::vector<std::uint64_t> order;
    for (std::uint64_t s = 0; s <= full; ++s) order.push_back(s);
    std::stable_sort(order.begin(), order.end(),
                     [](std::uint64_t a, std::uint64_t b) { return std::popcount(a) < std::popcount(b); });
    std::vector<std::uint32_t> open;  // merged rows in POS
    for (std::size_t c = 0; c < rows.rows; ++c)
        if (rows.gd[c] != rows.conflict) open.push_back(static_cast<std::uint32_t>(c));
    std::vector<std::uint32_t> need, group_of;
    for (auto s : order) {
        need.clear();
        for (auto c : open) {
            const auto& found = out.masks[c];
            if (std::none_of(found.begin(), found.end(), [&](std::uint64_t r) { return (s & r) == r; }))
                need.push_back(c);
        }
        if (need.empty()) continue;
        const Partition p = rows.partition_mask(s);
        std::vector<std::uint32_t> g(p.count, none);
        for (std::size_t c = 0; c < rows.rows; ++c) {
            auto& v = g[p.id[c]];
            if (v == none)
                v = rows.gd[c];
            else if (v != rows.gd[c])
                v = rows.conflict;
        }
        if (want_groups) group_of.assign(p.count, none);
        bool any = false;
        for (auto c : need) {
            if (g[p.id[c]] == rows.conflict) continue;
            out.masks[c].push_back(s);
            if (want_groups && group_of[p.id[c]] == none) {
                group_of[p.id[c]] = static_cast<std::uint32_t>(out.groups.size());
                out.groups.push_back({s, {}});
                any = true;
            }
        }
        if (any)
            for (std::size_t c = 0; c < rows.rows; ++c)
                if (group_of[p.id[c]] != none)
                    out.groups[group_of[p.id[c]]].matched.push_back(static_cast<std::uint32_t>(c));
    }
    return out;
}

}  // namespace

std::vector<std::vector<Attributes>> value_reducts(const DecisionTable& t, const Attributes& B0, const Attributes& D) {
    const Attributes B = checked(t, B0, "B");
    require_small(B, "value reducts");
    Collapsed rows(t, B, checked(t, D, "D"));
    const ValueReducts vr = search_value_reducts(rows, B.size(), false);
    std::vector<std::vector<Attributes>> per_row(rows.rows);
    for (std::size_t c = 0; c < rows.rows; ++c) {
        for (auto s : vr.masks[c]) per_row[c].push_back(attributes_of(B, s));
        std::sort(per_row[c].begin(), per_row[c].end(), by_size_then_lex);
    }
    std::vector<std::vector<Attributes>> out(t.rows());
    for (std::size_t r = 0; r < t.rows(); ++r) out[r] = per_row[rows.of_object[r]];
    return out;
}

std::vector<Attributes> value_cores(const DecisionTable& t, const Attributes& B0, const Attributes& D) {
    const Attributes B = checked(t, B0, "B");
    require_small(B, "value cores");
    const Collapsed rows(t, B, checked(t, D, "D"));
    // A value is in the core iff dropping it alone makes the object's rule inconsistent (then every
    // subset without it does too, so it lies in every value reduct).
    std::vector<Attributes> per_row(rows.rows);
    std::vector<std::size_t> others;
    for (std::size_t k = 0; k < B.size(); ++k) {
        others.clear();
        for (std::size_t j = 0; j < B.size(); ++j)
            if (j != k) others.push_back(j);
        const Partition p = rows.partition(others);
        std::vector<std::uint32_t> g(p.count, none);
        for (std::size_t c = 0; c < rows.rows; ++c) {
            auto& v = g[p.id[c]];
            if (v == none)
                v = rows.gd[c];
            else if (v != rows.gd[c])
                v = rows.conflict;
        }
        for (std::size_t c = 0; c < rows.rows; ++c)
            if (rows.gd[c] != rows.conflict && g[p.id[c]] == rows.conflict) per_row[c].push_back(B[k]);
    }
    std::vector<Attributes> out(t.rows());
    for (std::size_t r = 0; r < t.rows(); ++r) out[r] = per_row[rows.of_object[r]];
    return out;
}

std::vector<Rule> minimal_rules(const DecisionTable& t, const Attributes& B0, const Attributes& D0) {
    const Attributes B = checked(t, B0, "B");
    const Attributes D = checked(t, D0, "D");
    require_small(B, "minimal rules");
    Collapsed rows(t, B, D);
    const ValueReducts vr = search_value_reducts(rows, B.size(), true);

    // The candidates: one per (value reduct, class it matches); distinct groups have distinct
    // conditions, since equal values on the same attributes would be the same class.
    struct Candidate {
        Rule rule;
        std::vector<std::uint32_t> matched;
    };
    std::vector<Candidate> cand;
    cand.reserve(vr.groups.size());
    for (const auto& grp : vr.groups) {
        const std::size_t x = rows.first[grp.matched.front()];
        Rule r;
        for (auto k : positions_of(grp.mask)) r.conditions.push_back({B[k], t.value(x, B[k])});
        for (auto a : D) r.decision.push_back(t.value(x, a));
        cand.push_back({std::move(r), grp.matched});
    }

    // Greedy cover of the positive region, counted in objects (merged rows weigh their objects).
    std::vector<std::uint32_t> cover(rows.rows, 0);  // chosen rules matching each merged row
    std::size_t uncovered = 0;
    for (std::size_t c = 0; c < rows.rows; ++c)
        if (rows.gd[c] != rows.conflict) uncovered += rows.weight[c];
    auto gain = [&](const Candidate& k) {
        std::size_t g = 0;
        for (auto c : k.matched)
            if (cover[c] == 0) g += rows.weight[c];
        return g;
    };
    auto better = [&](std::size_t ga, const Candidate& a, std::size_t gb, const Candidate& b) {
        if (ga != gb) return ga > gb;
        if (a.rule.conditions.size() != b.rule.conditions.size())
            return a.rule.conditions.size() < b.rule.conditions.size();
        return a.rule.conditions < b.rule.conditions;
    };
    // Lazy greedy: gains only fall as objects get covered, so a candidate whose recomputed gain is
    // still its stored one is the best of the heap (ties are ordered the same way in the heap).
    using Entry = std::pair<std::size_t, std::size_t>;  // (stored gain, candidate)
    auto worse = [&](const Entry& a, const Entry& b) {
        return better(b.first, cand[b.second], a.first, cand[a.second]);
    };
    std::vector<Entry> heap;
    for (std::size_t i = 0; i < cand.size(); ++i) heap.push_back({gain(cand[i]), i});
    std::make_heap(heap.begin(), heap.end(), worse);
    std::vector<std::size_t> picked;
    while (uncovered > 0 && !heap.empty()) {
        std::pop_heap(heap.begin(), heap.end(), worse);
        Entry top = heap.back();
        heap.pop_back();
        const std::size_t g = gain(cand[top.second]);
        if (g == 0) continue;
        if (g < top.first) {
            heap.push_back({g, top.second});
            std::push_heap(heap.begin(), heap.end(), worse);
            continue;
        }
        picked.push_back(top.second);
        for (auto c : cand[top.second].matched) ++cover[c];
        uncovered -= g;
    }
    // A rule whose every object another chosen rule also covers is redundant: drop, last picked first.
    std::vector<char> keep(picked.size(), 1);
    for (std::size_t i = picked.size(); i-- > 0;) {
        const auto& m = cand[picked[i]].matched;
        if (std::all_of(m.begin(), m.end(), [&](std::uint32_t c) { return cover[c] >= 2; })) {
            keep[i] = 0;
            for (auto c : m) --cover[c];
        }
    }

    // Order of the matched merged rows -> objects: each merged row's objects.
    Classes objects_of(rows.rows);
    for (std::size_t r = 0; r < t.rows(); ++r) objects_of[rows.of_object[r]].push_back(r);
    std::vector<Rule> out;
    for (std::size_t i = 0; i < picked.size(); ++i) {
        if (!keep[i]) continue;
        Candidate& k = cand[picked[i]];
        for (auto c : k.matched)
            k.rule.support.insert(k.rule.support.end(), objects_of[c].begin(), objects_of[c].end());
        std::sort(k.rule.support.begin(), k.rule.support.end());
        out.push_back(std::move(k.rule));
    }
    std::sort(out.begin(), out.end(), [](const Rule& a, const Rule& b) {
        if (a.support != b.support) return a.support < b.support;
        return a.conditions < b.conditions;
    });
    return out;
}

}  // namespace pride::roughset

#pragma once
// The partitions behind every rough-set computation (approximations, reducts, rules): class ids
// refined one attribute at a time, and the table collapsed to one row per class for the searches
// over subsets; shared by those three files, not part of the module's interface.
#include <algorithm>
#include <bit>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "framework/error.hpp"
#include "roughset/decision_table.hpp"
#include "roughset/reducts.hpp"

namespace pride::roughset {

namespace detail {

inline constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();

// Class ids 0..count-1 per row, numbered in order of each class's first row.
struct Partition {
    std::vector<std::uint32_t> id;
    std::uint32_t count = 0;
};

inline Partition single_class(std::size_t rows) {
    return {std::vector<std::uint32_t>(rows, 0), rows ? 1u : 0u};
}

// Dense codes 0..card-1 of one column over some rows, in order of first appearance.
struct Column {
    std::vector<std::uint32_t> code;
    std::uint32_t card = 0;
};

// Splits every class of p by the column's codes: O(rows), through a direct table when it is small
// enough and a hash map otherwise.
inline Partition refine(const Partition& p, const Column& c) {
    const std::size_t rows = p.id.size();
    Partition out;
    out.id.resize(rows);
    const std::uint64_t cells = std::uint64_t{p.count} * c.card;
    if (cells <= std::max<std::uint64_t>(4 * rows, 1 << 16)) {
        std::vector<std::uint32_t> slot(static_cast<std::size_t>(cells), none);
        for (std::size_t r = 0; r < rows; ++r) {
            auto& s = slot[std::size_t{p.id[r]} * c.card + c.code[r]];
            if (s == none) s = out.count++;
            out.id[r] = s;
        }
    } else {
        std::unordered_map<std::uint64_t, std::uint32_t> slot;
        slot.reserve(rows);
        for (std::size_t r = 0; r < rows; ++r) {
            auto [it, added] = slot.try_emplace(std::uint64_t{p.id[r]} * c.card + c.code[r], out.count);
            if (added) ++out.count;
            out.id[r] = it->second;
        }
    }
    return out;
}

inline Column column_of(const DecisionTable& t, std::size_t a) {
    Column c;
    c.code.resize(t.rows());
    std::unordered_map<int, std::uint32_t> seen;
    for (std::size_t r = 0; r < t.rows(); ++r) {
        auto [it, added] = seen.try_emplace(t.value(r, a), c.card);
        if (added) ++c.card;
        c.code[r] = it->second;
    }
    return c;
}

// An attribute set checked against the table, sorted and without repeats.
inline Attributes checked(const DecisionTable& t, Attributes B, const char* what) {
    std::sort(B.begin(), B.end());
    B.erase(std::unique(B.begin(), B.end()), B.end());
    for (auto a : B)
        require(
            a < t.columns(), std::string("rough sets: ") + what,
            "attribute " + std::to_string(a) + " out of range (table has " + std::to_string(t.columns()) + " columns)");
    return B;
}

inline Partition partition_of(const DecisionTable& t, const Attributes& B) {
    Partition p = single_class(t.rows());
    for (auto a : B) p = refine(p, column_of(t, a));
    return p;
}

inline Classes classes_of(const Partition& p) {
    Classes out(p.count);
    for (std::size_t r = 0; r < p.id.size(); ++r) out[p.id[r]].push_back(r);
    return out;
}

inline std::vector<char> membership(const DecisionTable& t, const Objects& X) {
    std::vector<char> in(t.rows(), 0);
    for (auto x : X) {
        require(x < t.rows(), "rough sets: X",
                "object " + std::to_string(x) + " out of range (table has " + std::to_string(t.rows()) + " rows)");
        in[x] = 1;
    }
    return in;
}

// The table seen through B and D, with duplicate rows on B merged: one row per B-class, carrying
// its number of objects and its generalised decision (the D-class id when the B-class has a single
// value on D, `conflict` otherwise). A subset S of B keeps POS_B(D) iff every S-class of these
// rows has a single generalised decision; an object's S-values make a certain rule iff its S-class
// has the object's generalised decision only.
class Collapsed {
  public:
    Collapsed(const DecisionTable& t, const Attributes& B, const Attributes& D) {
        std::vector<Column> full;
        Partition pb = single_class(t.rows());
        for (auto a : B) {
            full.push_back(column_of(t, a));
            pb = refine(pb, full.back());
        }
        const Partition pd = partition_of(t, D);
        conflict = pd.count;
        rows = pb.count;
        of_object = pb.id;
        first.assign(rows, 0);
        weight.assign(rows, 0);
        gd.assign(rows, none);
        for (std::size_t r = t.rows(); r-- > 0;) first[pb.id[r]] = r;
        for (std::size_t r = 0; r < t.rows(); ++r) {
            const auto c = pb.id[r];
            ++weight[c];
            if (gd[c] == none)
                gd[c] = pd.id[r];
            else if (gd[c] != pd.id[r])
                gd[c] = conflict;
        }
        // Per attribute, the codes of the merged rows; then packed keys when they fit in 64 bits.
        cols.resize(B.size());
        unsigned bits = 0;
        for (std::size_t k = 0; k < B.size(); ++k) {
            cols[k].card = full[k].card;
            cols[k].code.resize(rows);
            for (std::size_t c = 0; c < rows; ++c) cols[k].code[c] = full[k].code[first[c]];
            bits += static_cast<unsigned>(std::bit_width(std::max<std::uint32_t>(cols[k].card, 1) - 1));
        }
        packed = bits <= 64;
        if (packed) {
            key.assign(rows, 0);
            unsigned offset = 0;
            for (std::size_t k = 0; k < B.size(); ++k) {
                // A constant attribute (one value, code 0) takes no bits and is never shifted: once
                // the fields before it fill all 64 bits, its offset is 64, a shift by the full width.
                // Otherwise w <= 32 and offset + w <= 64, so offset < 64.
                const auto w = static_cast<unsigned>(std::bit_width(std::max<std::uint32_t>(cols[k].card, 1) - 1));
                if (w == 0) {
                    field.push_back(0);
                    continue;
                }
                field.push_back(((std::uint64_t{1} << w) - 1) << offset);
                for (std::size_t c = 0; c < rows; ++c) key[c] |= std::uint64_t{cols[k].code[c]} << offset;
                offset += w;
            }
            std::size_t size = 16;
            while (size < 2 * rows) size *= 2;
            slot_key.resize(size);
            slot_val.resize(size);
            slot_stamp.assign(size, 0);
            shift = 64 - static_cast<unsigned>(std::countr_zero(size));
        }
    }

    // The partition of the merged rows on the attributes at positions `pos` of B.
    Partition partition(const std::vector<std::size_t>& pos) const {
        Partition p = single_class(rows);
        for (auto k : pos) p = refine(p, cols[k]);
        return p;
    }

    // The number of objects in POS_S(D), S given by its partition of the merged rows.
    std::size_t positive(const Partition& p) const {
        std::vector<std::uint32_t> g(p.count, none);
        for (std::size_t c = 0; c < rows; ++c) {
            auto& v = g[p.id[c]];
            if (v == none)
                v = gd[c];
            else if (v != gd[c])
                v = conflict;
        }
        std::size_t n = 0;
        for (std::size_t c = 0; c < rows; ++c)
            if (g[p.id[c]] != conflict) n += weight[c];
        return n;
    }

    // Whether the positions in `mask` (bit k = position k of B) keep POS_B(D): every class with a
    // single generalised decision. Stops at the first conflict.
    bool keeps(std::uint64_t mask) {
        if (!packed) {
            const Partition p = partition_mask(mask);
            std::vector<std::uint32_t> g(p.count, none);
            for (std::size_t c = 0; c < rows; ++c) {
                auto& v = g[p.id[c]];
                if (v == none)
                    v = gd[c];
                else if (v != gd[c])
                    return false;
            }
            return true;
        }
        const std::uint64_t m = bits_of(mask);
        const std::uint32_t stamp = next_stamp();
        const std::size_t wrap = slot_key.size() - 1;
        for (std::size_t c = 0; c < rows; ++c) {
            const std::uint64_t k = key[c] & m;
            for (std::size_t h = hash(k);; h = (h + 1) & wrap) {
                if (slot_stamp[h] != stamp) {
                    slot_stamp[h] = stamp;
                    slot_key[h] = k;
                    slot_val[h] = gd[c];
                    break;
                }
                if (slot_key[h] == k) {
                    if (slot_val[h] != gd[c]) return false;
                    break;
                }
            }
        }
        return true;
    }

    // The partition of the merged rows on the positions in `mask`.
    Partition partition_mask(std::uint64_t mask) {
        if (!packed) {
            std::vector<std::size_t> pos;
            for (std::size_t k = 0; k < cols.size(); ++k)
                if (mask >> k & 1) pos.push_back(k);
            return partition(pos);
        }
        const std::uint64_t m = bits_of(mask);
        const std::uint32_t stamp = next_stamp();
        const std::size_t wrap = slot_key.size() - 1;
        Partition p;
        p.id.resize(rows);
        for (std::size_t c = 0; c < rows; ++c) {
            const std::uint64_t k = key[c] & m;
            for (std::size_t h = hash(k);; h = (h + 1) & wrap) {
                if (slot_stamp[h] != stamp) {
                    slot_stamp[h] = stamp;
                    slot_key[h] = k;
                    slot_val[h] = p.count++;
                    p.id[c] = slot_val[h];
                    break;
                }
                if (slot_key[h] == k) {
                    p.id[c] = slot_val[h];
                    break;
                }
            }
        }
        return p;
    }

    std::size_t rows = 0;
    std::vector<std::uint32_t> of_object;  // per object: its merged row
    std::vector<std::size_t> first;        // per merged row: its first object
    std::vector<std::uint32_t> weight;     // per merged row: its number of objects
    std::vector<std::uint32_t> gd;         // per merged row: generalised decision
    std::uint32_t conflict = 0;
    std::vector<Column> cols;  // per position of B

  private:
    std::uint64_t bits_of(std::uint64_t mask) const {
        std::uint64_t m = 0;
        for (std::size_t k = 0; k < field.size(); ++k)
            if (mask >> k & 1) m |= field[k];
        return m;
    }
    std::size_t hash(std::uint64_t k) const { return static_cast<std::size_t>((k * 0x9E3779B97F4A7C15ull) >> shift); }
    std::uint32_t next_stamp() {
        if (++stamp_ == 0) {  // wrapped: forget every old stamp
            std::fill(slot_stamp.begin(), slot_stamp.end(), 0);
            stamp_ = 1;
        }
        return stamp_;
    }

    bool packed = false;
    std::vector<std::uint64_t> key;    // per merged row: codes packed in bit fields
    std::vector<std::uint64_t> field;  // per position: its bit field
    std::vector<std::uint64_t> slot_key;
    std::vector<std::uint32_t> slot_val, slot_stamp;
    std::uint32_t stamp_ = 0;
    unsigned shift = 64;
};

inline std::vector<std::size_t> positions_of(std::uint64_t mask) {
    std::vector<std::size_t> pos;
    for (std::size_t k = 0; k < 64; ++k)
        if (mask >> k & 1) pos.push_back(k);
    return pos;
}

inline Attributes attributes_of(const Attributes& B, std::uint64_t mask) {
    Attributes out;
    for (std::size_t k = 0; k < B.size(); ++k)
        if (mask >> k & 1) out.push_back(B[k]);
    return out;
}

inline bool by_size_then_lex(const Attributes& a, const Attributes& b) {
    if (a.size() != b.size()) return a.size() < b.size();
    return a < b;
}

inline void require_small(const Attributes& B, const char* what) {
    require(B.size() <= max_exhaustive_attributes, std::string("rough sets: ") + what,
            std::to_string(B.size()) + " attributes, the exhaustive search handles at most " +
                std::to_string(max_exhaustive_attributes));
}

}  // namespace detail

}  // namespace pride::roughset

// The rough-set module. Every partition is built by refining class ids one attribute at a time
// (or, in the searches over subsets, by hashing packed row codes), so that nothing is pairwise.
#include <algorithm>
#include <bit>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numeric>
#include <sstream>
#include <unordered_map>
#include <unordered_set>

#include "framework/error.hpp"
#include "framework/read_file.hpp"
#include "framework/utf8.hpp"
#include "roughset/roughset.hpp"

namespace pride::roughset {

// ---------------------------------------------------------------------------------------------
// DecisionTable

DecisionTable::DecisionTable(std::vector<std::string> names) : names_(std::move(names)) {
    require(names_.size() >= 2, "decision table", "needs at least 2 columns, got " + std::to_string(names_.size()));
    // A hash set, not pairwise comparisons: tables may have 100,000 columns.
    std::unordered_set<std::string_view> seen;
    seen.reserve(names_.size());
    for (std::size_t i = 0; i < names_.size(); ++i) {
        require(!names_[i].empty(), "decision table", "column " + std::to_string(i + 1) + " has an empty name");
        require(seen.insert(names_[i]).second, "decision table", "duplicate column name '" + names_[i] + "'");
    }
    labels_.resize(names_.size());
    lookup_.resize(names_.size());
}

void DecisionTable::add_row(std::span<const int> codes) {
    require(codes.size() == columns(), "decision table",
            "row " + std::to_string(rows_ + 1) + " has " + std::to_string(codes.size()) + " values, expected " +
                std::to_string(columns()));
    codes_.insert(codes_.end(), codes.begin(), codes.end());
    ++rows_;
}

void DecisionTable::add_row_labels(std::span<const std::string> labels) {
    require(labels.size() == columns(), "decision table",
            "row " + std::to_string(rows_ + 1) + " has " + std::to_string(labels.size()) + " values, expected " +
                std::to_string(columns()));
    for (std::size_t c = 0; c < columns(); ++c) {
        auto [it, added] = lookup_[c].try_emplace(labels[c], static_cast<int>(labels_[c].size()));
        if (added) labels_[c].push_back(labels[c]);
        codes_.push_back(it->second);
    }
    ++rows_;
}

std::string DecisionTable::label(std::size_t column, int code) const {
    const auto& l = labels_.at(column);
    if (code >= 0 && static_cast<std::size_t>(code) < l.size()) return l[static_cast<std::size_t>(code)];
    return std::to_string(code);
}

std::optional<int> DecisionTable::code(std::size_t column, std::string_view label) const {
    const auto& m = lookup_.at(column);
    if (auto it = m.find(std::string(label)); it != m.end()) return it->second;
    return std::nullopt;
}

Attributes DecisionTable::conditions() const {
    Attributes a(columns() - 1);
    std::iota(a.begin(), a.end(), std::size_t{0});
    return a;
}

Attributes DecisionTable::decision() const {
    return {columns() - 1};
}

Attributes DecisionTable::all() const {
    Attributes a(columns());
    std::iota(a.begin(), a.end(), std::size_t{0});
    return a;
}

std::optional<std::size_t> DecisionTable::find(std::string_view name) const {
    for (std::size_t i = 0; i < names_.size(); ++i)
        if (names_[i] == name) return i;
    return std::nullopt;
}

Objects all_objects(const DecisionTable& t) {
    Objects o(t.rows());
    std::iota(o.begin(), o.end(), std::size_t{0});
    return o;
}

// ---------------------------------------------------------------------------------------------
// CSV

namespace {

struct Field {
    std::string text;
    std::size_t line = 0, col = 0;
};
struct Record {
    std::vector<Field> fields;
    std::size_t line = 0;
    std::size_t end_col = 0;  // column just past the last character of the record's last line
};

// Limits on what a CSV table may hold, checked while reading so that memory stays bounded: the
// file (read in chunks under the cap, framework/read_file.hpp) and the fields of one row.
constexpr std::size_t kMaxCsvBytes = std::size_t{16} << 20;
constexpr std::size_t kMaxCsvColumns = 1000000;

/// The first place where `s` is not UTF-8 text (a NUL byte, a byte outside a valid UTF-8
/// sequence): InputError "SOURCE:LINE:COL: ..." with the line and column the reader would give,
/// so that labels and names, printed as read and in --json, are always valid UTF-8.
void check_utf8(std::string_view s, const std::string& source) {
    std::size_t line = 1, col = 1;
    std::size_t i = s.starts_with("\xEF\xBB\xBF") ? 3 : 0;
    static constexpr char hex[] = "0123456789ABCDEF";
    while (i < s.size()) {
        const auto c = static_cast<unsigned char>(s[i]);
        const auto fail = [&](const std::string& what) {
            throw InputError(source + ":" + std::to_string(line) + ":" + std::to_string(col) + ": " + what);
        };
        if (c == 0) fail("NUL byte (\\x00): this is a binary file, not a CSV table");
        const std::size_t len = utf8_length(s, i);
        if (len == 0)
            fail(std::string("byte \\x") + hex[c >> 4] + hex[c & 15] + " is not UTF-8: a CSV table must be UTF-8 text");
        if (c == '\n' || (c == '\r' && (i + 1 >= s.size() || s[i + 1] != '\n'))) {
            ++line;
            col = 1;
        } else if (c != '\r') {
            ++col;
        }
        i += len;
    }
}

// A small cursor that knows its line and column (in characters: UTF-8 continuation bytes do not
// advance the column).
class CsvReader {
  public:
    CsvReader(std::string_view text, const std::string& source) : s_(text), source_(source) {
        if (s_.starts_with("\xEF\xBB\xBF")) i_ = 3;
    }

    // The next record that is not a blank line; false at the end.
    bool next(Record& r) {
        while (i_ < s_.size()) {
            r = Record{};
            r.line = line_;
            read_record(r);
            const bool blank = r.fields.size() == 1 && r.fields[0].text.empty() && !quoted_;
            if (!blank) return true;
        }
        return false;
    }
    std::size_t line() const { return line_; }
    std::size_t col() const { return col_; }
    [[noreturn]] void fail(std::size_t line, std::size_t col, const std::string& what) const {
        throw InputError(source_ + ":" + std::to_string(line) + ":" + std::to_string(col) + ": " + what);
    }

  private:
    char peek() const { return i_ < s_.size() ? s_[i_] : '\0'; }
    bool at_end() const { return i_ >= s_.size(); }
    void advance() {
        const char c = s_[i_++];
        if (c == '\n') {
            ++line_;
            col_ = 1;
        } else if (c == '\r') {
            if (peek() != '\n') {  // a lone CR ends a line too
                ++line_;
                col_ = 1;
            }
        } else if ((static_cast<unsigned char>(c) & 0xC0) != 0x80) {
            ++col_;
        }
    }
    static bool blank(char c) { return c == ' ' || c == '\t'; }
    bool line_end() const { return peek() == '\n' || peek() == '\r'; }
    void skip_line_end() {
        if (peek() == '\r') advance();
        if (peek() == '\n') advance();
    }

    void read_record(Record& r) {
        quoted_ = false;
        for (;;) {
            Field f;
            // Where the field starts, blanks included: the place an empty (blank-only) field is
            // reported at. A field with text is reported at its first non-blank character.
            const std::size_t start_line = line_, start_col = col_;
            while (blank(peek())) advance();
            f.line = line_;
            f.col = col_;
            if (peek() == '"') {
                quoted_ = true;
                advance();
                for (;;) {
                    if (at_end()) fail(f.line, f.col, "unterminated quote");
                    if (peek() == '"') {
                        advance();
                        if (peek() != '"') break;
                    }
                    f.text += peek();
                    advance();
                }
                while (blank(peek())) advance();
                if (!at_end() && peek() != ',' && !line_end())
                    fail(line_, col_, "unexpected character after a closing quote");
            } else {
                while (!at_end() && peek() != ',' && !line_end()) {
                    if (peek() == '"') fail(line_, col_, "quote inside an unquoted field (quote the whole field)");
                    f.text += peek();
                    advance();
                }
                while (!f.text.empty() && blank(f.text.back())) f.text.pop_back();
                if (f.text.empty()) {
                    f.line = start_line;
                    f.col = start_col;
                }
            }
            r.fields.push_back(std::move(f));
            if (r.fields.size() > kMaxCsvColumns)
                fail(r.fields.back().line, r.fields.back().col,
                     "more than " + std::to_string(kMaxCsvColumns) + " columns in one row");
            if (peek() == ',') {
                advance();
                continue;
            }
            r.end_col = col_;
            skip_line_end();
            return;
        }
    }

    std::string_view s_;
    const std::string& source_;
    std::size_t i_ = 0, line_ = 1, col_ = 1;
    bool quoted_ = false;  // whether the record just read had a quoted field
};

}  // namespace

DecisionTable parse_csv(std::string_view text, const std::string& source_name) {
    check_utf8(text, source_name);
    CsvReader in(text, source_name);
    Record header;
    if (!in.next(header)) in.fail(1, 1, "empty file (expected a header line naming the columns)");
    const std::size_t n = header.fields.size();
    if (n < 2)
        in.fail(header.line, header.fields[0].col,
                "the header has 1 column, need at least 2 (conditions, then the decision)");
    std::vector<std::string> names;
    std::unordered_map<std::string_view, std::size_t> column_of_name;  // not pairwise: 100,000 columns
    column_of_name.reserve(n);
    for (std::size_t c = 0; c < n; ++c) {
        const Field& f = header.fields[c];
        if (f.text.empty()) in.fail(f.line, f.col, "empty column name (column " + std::to_string(c + 1) + ")");
        const auto [it, added] = column_of_name.try_emplace(f.text, c);
        if (!added)
            in.fail(f.line, f.col,
                    "duplicate column name '" + f.text + "' (columns " + std::to_string(it->second + 1) + " and " +
                        std::to_string(c + 1) + ")");
        names.push_back(f.text);
    }
    DecisionTable table(names);
    Record r;
    std::vector<std::string> values(n);
    while (in.next(r)) {
        if (r.fields.size() != n) {
            const std::string what = "row has " + std::to_string(r.fields.size()) + " field" +
                                     (r.fields.size() == 1 ? "" : "s") + ", expected " + std::to_string(n);
            if (r.fields.size() > n) in.fail(r.fields[n].line, r.fields[n].col, what);
            const Field& last = r.fields.back();
            in.fail(last.line, r.end_col, what);
        }
        for (std::size_t c = 0; c < n; ++c) {
            if (r.fields[c].text.empty())
                in.fail(r.fields[c].line, r.fields[c].col, "empty value in column '" + names[c] + "'");
            values[c] = std::move(r.fields[c].text);
        }
        table.add_row_labels(values);
    }
    if (table.rows() == 0) in.fail(header.line + 1, 1, "no data rows after the header");
    return table;
}

DecisionTable read_csv(const std::string& path) {
    return parse_csv(read_capped_file(path, kMaxCsvBytes, "decision table"), path);
}

// ---------------------------------------------------------------------------------------------
// Partitions

namespace {

constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();

// Class ids 0..count-1 per row, numbered in order of each class's first row.
struct Partition {
    std::vector<std::uint32_t> id;
    std::uint32_t count = 0;
};

Partition single_class(std::size_t rows) {
    return {std::vector<std::uint32_t>(rows, 0), rows ? 1u : 0u};
}

// Dense codes 0..card-1 of one column over some rows, in order of first appearance.
struct Column {
    std::vector<std::uint32_t> code;
    std::uint32_t card = 0;
};

// Splits every class of p by the column's codes: O(rows), through a direct table when it is small
// enough and a hash map otherwise.
Partition refine(const Partition& p, const Column& c) {
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

Column column_of(const DecisionTable& t, std::size_t a) {
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
Attributes checked(const DecisionTable& t, Attributes B, const char* what) {
    std::sort(B.begin(), B.end());
    B.erase(std::unique(B.begin(), B.end()), B.end());
    for (auto a : B)
        require(
            a < t.columns(), std::string("rough sets: ") + what,
            "attribute " + std::to_string(a) + " out of range (table has " + std::to_string(t.columns()) + " columns)");
    return B;
}

Partition partition_of(const DecisionTable& t, const Attributes& B) {
    Partition p = single_class(t.rows());
    for (auto a : B) p = refine(p, column_of(t, a));
    return p;
}

Classes classes_of(const Partition& p) {
    Classes out(p.count);
    for (std::size_t r = 0; r < p.id.size(); ++r) out[p.id[r]].push_back(r);
    return out;
}

std::vector<char> membership(const DecisionTable& t, const Objects& X) {
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

std::vector<std::size_t> positions_of(std::uint64_t mask) {
    std::vector<std::size_t> pos;
    for (std::size_t k = 0; k < 64; ++k)
        if (mask >> k & 1) pos.push_back(k);
    return pos;
}

Attributes attributes_of(const Attributes& B, std::uint64_t mask) {
    Attributes out;
    for (std::size_t k = 0; k < B.size(); ++k)
        if (mask >> k & 1) out.push_back(B[k]);
    return out;
}

bool by_size_then_lex(const Attributes& a, const Attributes& b) {
    if (a.size() != b.size()) return a.size() < b.size();
    return a < b;
}

void require_small(const Attributes& B, const char* what) {
    require(B.size() <= max_exhaustive_attributes, std::string("rough sets: ") + what,
            std::to_string(B.size()) + " attributes, the exhaustive search handles at most " +
                std::to_string(max_exhaustive_attributes));
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Approximations

Classes indiscernibility(const DecisionTable& t, const Attributes& B) {
    return classes_of(partition_of(t, checked(t, B, "B")));
}

namespace {
/// The union of the B-classes that lie inside X (`inside`: the lower approximation) or meet X
/// (the upper one).
Objects approximation(const DecisionTable& t, const Attributes& B, const Objects& X, bool inside) {
    const auto in = membership(t, X);
    const auto member = [&](std::size_t x) { return in[x] != 0; };
    Objects out;
    for (const auto& cls : indiscernibility(t, B))
        if (inside ? std::all_of(cls.begin(), cls.end(), member) : std::any_of(cls.begin(), cls.end(), member))
            out.insert(out.end(), cls.begin(), cls.end());
    std::sort(out.begin(), out.end());
    return out;
}
}  // namespace

Objects lower_approximation(const DecisionTable& t, const Attributes& B, const Objects& X) {
    return approximation(t, B, X, true);
}

Objects upper_approximation(const DecisionTable& t, const Attributes& B, const Objects& X) {
    return approximation(t, B, X, false);
}

Objects boundary(const DecisionTable& t, const Attributes& B, const Objects& X) {
    const Objects up = upper_approximation(t, B, X), low = lower_approximation(t, B, X);
    Objects out;
    std::set_difference(up.begin(), up.end(), low.begin(), low.end(), std::back_inserter(out));
    return out;
}

Objects positive_region(const DecisionTable& t, const Attributes& C, const Attributes& D) {
    const Collapsed rows(t, checked(t, C, "C"), checked(t, D, "D"));
    Objects out;
    for (std::size_t r = 0; r < t.rows(); ++r)
        if (rows.gd[rows.of_object[r]] != rows.conflict) out.push_back(r);
    return out;
}

double dependency(const DecisionTable& t, const Attributes& C, const Attributes& D) {
    if (t.rows() == 0) return 1.0;
    return static_cast<double>(positive_region(t, C, D).size()) / static_cast<double>(t.rows());
}

bool consistent(const DecisionTable& t, const Attributes& C, const Attributes& D) {
    return positive_region(t, C, D).size() == t.rows();
}

// ---------------------------------------------------------------------------------------------
// Core and reducts

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

// ---------------------------------------------------------------------------------------------
// Rules

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

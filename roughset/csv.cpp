// Decision tables from CSV text: UTF-8 checked, fields bounded, every error at its line and column.
#include "roughset/csv.hpp"

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <string>
#include <unordered_map>
#include <vector>

#include "framework/error.hpp"
#include "framework/read_file.hpp"
#include "framework/utf8.hpp"

namespace pride::roughset {

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
    while (i < s.size()) {
        const auto c = static_cast<unsigned char>(s[i]);
        const auto fail = [&](const std::string& what) {
            throw InputError(source + ":" + std::to_string(line) + ":" + std::to_string(col) + ": " + what);
        };
        if (c == 0) fail("NUL byte (\\x00): this is a binary file, not a CSV table");
        const std::size_t len = utf8_length(s, i);
        if (len == 0) fail("a byte that is not UTF-8: a CSV table must be UTF-8 text");
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
                    "duplicate column name (columns " + std::to_string(it->second + 1) + " and " +
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
                in.fail(r.fields[c].line, r.fields[c].col, "empty value in column " + std::to_string(c + 1));
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

}  // namespace pride::roughset

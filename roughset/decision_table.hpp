#pragma once
// A decision table of rough-set theory: objects (rows) by attributes (columns), each value a small
// integer code; the original text of each code is kept so that results can be printed as read.
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace pride::roughset {

using Attributes = std::vector<std::size_t>;  // column indices, sorted ascending
using Objects = std::vector<std::size_t>;     // 0-based row indices, sorted ascending
using Classes = std::vector<Objects>;         // each class sorted; classes ordered by first object

/// Every column is an attribute; by convention the last one is the decision (conditions(),
/// decision()), but every function of the module takes the attribute sets explicitly.
class DecisionTable {
  public:
    /// Column names, at least 2, non-empty and distinct (InputError otherwise).
    explicit DecisionTable(std::vector<std::string> names);

    /// A row of codes used as given; label(column, code) is then the number itself unless the code
    /// came from add_row_labels. InputError unless codes.size() == columns().
    void add_row(std::span<const int> codes);
    /// A row of text values, coded per column 0, 1, 2, ... in order of first appearance.
    /// Do not mix with add_row on the same column unless the codes are meant to coincide.
    void add_row_labels(std::span<const std::string> labels);

    std::size_t rows() const { return rows_; }
    std::size_t columns() const { return names_.size(); }
    const std::string& name(std::size_t column) const { return names_[column]; }
    const std::vector<std::string>& names() const { return names_; }
    int value(std::size_t row, std::size_t column) const { return codes_[row * names_.size() + column]; }
    /// The codes of one row, columns() of them.
    std::span<const int> row(std::size_t r) const { return {codes_.data() + r * names_.size(), names_.size()}; }
    /// The original text of a code (its decimal form when it was given as a number).
    std::string label(std::size_t column, int code) const;
    /// The code of a text value in a column, if that text has been seen there.
    std::optional<int> code(std::size_t column, std::string_view label) const;

    Attributes conditions() const;  // all columns but the last
    Attributes decision() const;    // {last column}
    Attributes all() const;         // every column
    std::optional<std::size_t> find(std::string_view name) const;

  private:
    std::vector<std::string> names_;
    std::vector<int> codes_;  // row-major, rows_ x columns()
    std::size_t rows_ = 0;
    std::vector<std::vector<std::string>> labels_;              // per column: code -> text
    std::vector<std::unordered_map<std::string, int>> lookup_;  // per column: text -> code
};

/// Every object, {0, ..., rows - 1}.
Objects all_objects(const DecisionTable& t);

}  // namespace pride::roughset

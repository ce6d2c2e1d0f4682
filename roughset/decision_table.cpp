// Decision tables: attribute names, rows of codes and their labels.
#include "roughset/decision_table.hpp"

#include <numeric>
#include <span>
#include <string>
#include <unordered_set>
#include <utility>

#include "framework/error.hpp"

namespace pride::roughset {

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

}  // namespace pride::roughset

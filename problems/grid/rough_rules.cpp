// The grid rule book of rough_rules.hpp: full table -> reduct -> minimal rules -> per-state lookup.
#include "problems/grid/rough_rules.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>

namespace pride::grid {
namespace {

roughset::DecisionTable full_table() {
    roughset::DecisionTable table({"X1", "X2", "X3", "X4", "X5", "X6", "X7", "X8", "Y"});
    std::array<int, 9> row{};
    for (std::size_t i = 0; i < kGridStates; ++i) {
        const std::array<int, 8> values = state_values(i);
        std::copy(values.begin(), values.end(), row.begin());
        row[8] = policy_move(values);
        table.add_row(row);
    }
    return table;
}

void check(bool ok, const std::string& what) {
    if (!ok) throw std::logic_error("grid rule book: " + what);
}

GridRuleBook build() {
    roughset::DecisionTable table = full_table();
    const roughset::Attributes c = table.conditions(), d = table.decision();
    check(table.rows() == kGridStates && c.size() == 8 && d.size() == 1, "the full table has the wrong shape");
    check(roughset::consistent(table, c, d), "the full table is inconsistent");

    const std::vector<roughset::Attributes> all = roughset::reducts(table, c, d);
    check(all.size() == 1, "the reduct is not unique (" + std::to_string(all.size()) + " reducts)");
    roughset::Attributes reduct = all.front();
    for (const std::size_t backward : {3u, 4u, 5u})  // X4, X5, X6 must come out dispensable
        check(std::find(reduct.begin(), reduct.end(), backward) == reduct.end(),
              "the reduct keeps " + table.name(backward));

    std::set<std::vector<int>> distinct;  // the table's rows on the reduct
    for (std::size_t r = 0; r < table.rows(); ++r) {
        std::vector<int> key;
        for (const std::size_t a : reduct) key.push_back(table.value(r, a));
        distinct.insert(std::move(key));
    }

    std::vector<roughset::Rule> rules = roughset::minimal_rules(table, reduct, d);

    // The lookup comes from the rules alone: every state must be matched, and every matching rule
    // must prescribe the same move, one the walk can take (a free unvisited neighbour, or back).
    std::array<std::uint8_t, kGridStates> moves{};
    for (std::size_t i = 0; i < kGridStates; ++i) {
        const std::array<int, 8> values = state_values(i);
        int move = 0;
        for (const roughset::Rule& rule : rules) {
            const bool matches = std::all_of(
                rule.conditions.begin(), rule.conditions.end(),
                [&](const roughset::Condition& k) { return k.attribute < 8 && values[k.attribute] == k.value; });
            if (!matches) continue;
            check(rule.decision.size() == 1, "a rule without exactly one decision value");
            check(move == 0 || move == rule.decision.front(), "rules disagree on state " + std::to_string(i));
            move = rule.decision.front();
        }
        check(move != 0, "no rule matches state " + std::to_string(i));
        check(move == kBack || (move >= 1 && move <= 8 && values[move - 1] == kOpen),
              "a rule moves to a neighbour that is not free and unvisited (state " + std::to_string(i) + ")");
        moves[i] = static_cast<std::uint8_t>(move);
    }
    return GridRuleBook{std::move(table), std::move(reduct), distinct.size(), std::move(rules), moves};
}

}  // namespace

const GridRuleBook& grid_rule_book() {
    static const GridRuleBook book = build();
    return book;
}

}  // namespace pride::grid

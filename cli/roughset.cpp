// pride roughset: the rough-set analysis of a decision table, for people (names and labels as in
// the file) and as one JSON object.
#include "cli/roughset.hpp"

#include <fmt/format.h>

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "cli/numbers.hpp"
#include "framework/error.hpp"
#include "problems/grid/rough_rules.hpp"
#include "roughset/roughset.hpp"

namespace pride::cli {
namespace {

using roughset::Attributes;
using roughset::DecisionTable;
using roughset::Rule;

using roughset::analyse;
using roughset::Analysis;

std::string names_of(const DecisionTable& t, const Attributes& A) {
    std::string s = "{";
    for (std::size_t i = 0; i < A.size(); ++i) s += (i ? ", " : "") + t.name(A[i]);
    return s + "}";
}

std::string json_names(const DecisionTable& t, const Attributes& A) {
    std::string s = "[";
    for (std::size_t i = 0; i < A.size(); ++i) s += (i ? ", " : "") + json_string(t.name(A[i]));
    return s + "]";
}

std::string rule_text(const DecisionTable& t, const Rule& r, const Attributes& D) {
    std::string s;
    for (std::size_t i = 0; i < r.conditions.size(); ++i) {
        const auto& c = r.conditions[i];
        s += fmt::format("{}{}={}", i ? " and " : "", t.name(c.attribute), t.label(c.attribute, c.value));
    }
    if (r.conditions.empty()) s = "always";
    s += " ->";
    for (std::size_t i = 0; i < D.size(); ++i) s += fmt::format(" {}={}", t.name(D[i]), t.label(D[i], r.decision[i]));
    return s;
}

std::string support_text(const Rule& r) {
    if (r.support.size() > 10) return fmt::format("[{} objects]", r.support.size());
    std::string s = r.support.size() == 1 ? "[object " : "[objects ";
    for (std::size_t i = 0; i < r.support.size(); ++i) s += fmt::format("{}{}", i ? ", " : "", r.support[i] + 1);
    return s + "]";
}

void print_human(const DecisionTable& t, const Analysis& a, std::string& s) {
    s += fmt::format("consistent: {}\n", a.consistent ? "yes" : "no");
    s += fmt::format("positive region: {} of {} objects (dependency {})\n", a.positive, a.rows, json_number(a.gamma));
    s += fmt::format("core: {}\n", names_of(t, a.core));
    if (a.exhaustive) {
        s += fmt::format("reducts: {} (exhaustive over {} condition attribute{})\n", a.reducts.size(), a.C.size(),
                         a.C.size() == 1 ? "" : "s");
        for (const auto& r : a.reducts) s += fmt::format("  {}\n", names_of(t, r));
    } else {
        s += fmt::format("reducts: not searched exhaustively ({} condition attributes, the limit is {})\n", a.C.size(),
                         roughset::max_exhaustive_attributes);
        s +=
            fmt::format("  {} (QuickReduct, greedy: a reduct, not necessarily a smallest one)\n", names_of(t, a.quick));
    }
    if (!a.rules) {
        s += fmt::format("rules on {} ({}): {}\n", names_of(t, a.used), a.why, a.no_rules);
        return;
    }
    // Certain rules only: objects outside the positive region have none.
    const std::size_t outside = a.rows - a.positive;
    if (a.positive == 0) {
        s += fmt::format("rules on {} ({}): none (the positive region is empty: no object has a certain rule)\n",
                         names_of(t, a.used), a.why);
        return;
    }
    s += fmt::format("rules on {} ({}): {} minimal certain rule{}", names_of(t, a.used), a.why, a.rules->size(),
                     a.rules->size() == 1 ? "" : "s");
    if (outside > 0)
        s += fmt::format(" (none for the {} object{} outside the positive region)", outside, outside == 1 ? "" : "s");
    s += "\n";
    std::vector<std::string> texts;
    std::size_t width = 0;
    for (const auto& r : *a.rules) {
        texts.push_back(rule_text(t, r, a.D));
        width = std::max(width, texts.back().size());
    }
    for (std::size_t i = 0; i < texts.size(); ++i)
        s += fmt::format("  {:<{}}  {}\n", texts[i], width, support_text((*a.rules)[i]));
}

std::string json_body(const DecisionTable& t, const Analysis& a) {
    std::string s;
    s += fmt::format("\"rows\": {}, \"conditions\": {}, \"decision\": {}, ", a.rows, json_names(t, a.C),
                     json_string(t.name(a.D.front())));
    s += fmt::format("\"consistent\": {}, \"positive_region\": {}, \"dependency\": {}, ",
                     a.consistent ? "true" : "false", a.positive, json_number(a.gamma));
    s += fmt::format("\"core\": {}, \"exhaustive\": {}, \"reducts\": [", json_names(t, a.core),
                     a.exhaustive ? "true" : "false");
    for (std::size_t i = 0; i < a.reducts.size(); ++i) s += (i ? ", " : "") + json_names(t, a.reducts[i]);
    s += fmt::format("], \"quick_reduct\": {}, \"reduct_used\": {}, ", json_names(t, a.quick), json_names(t, a.used));
    if (!a.rules) return s + fmt::format("\"rules\": null, \"rules_note\": {}", json_string(a.no_rules));
    s += "\"rules\": [";
    for (std::size_t i = 0; i < a.rules->size(); ++i) {
        const Rule& r = (*a.rules)[i];
        s += i ? ", {\"if\": {" : "{\"if\": {";
        for (std::size_t k = 0; k < r.conditions.size(); ++k) {
            const auto& c = r.conditions[k];
            s += fmt::format("{}{}: {}", k ? ", " : "", json_string(t.name(c.attribute)),
                             json_string(t.label(c.attribute, c.value)));
        }
        s += fmt::format("}}, \"then\": {}, \"support\": {}}}", json_string(t.label(a.D.front(), r.decision.front())),
                         r.support.size());
    }
    return s + "]";
}

}  // namespace

int roughset_command(const RoughsetOptions& o, std::ostream& out) {
    if (o.grid && !o.table.empty()) throw InputError("roughset: give either TABLE.csv or --grid, not both");
    if (!o.grid && o.table.empty()) throw InputError("roughset: give a decision table TABLE.csv, or --grid");
    std::string s;
    if (!o.grid) {
        const DecisionTable t = roughset::read_csv(o.table);
        const Analysis a = analyse(t);
        if (o.json) {
            s = fmt::format("{{\"table\": {}, {}}}\n", json_string(o.table), json_body(t, a));
        } else {
            std::vector<std::string> conds;
            for (auto c : a.C) conds.push_back(t.name(c));
            s = fmt::format("table: {} ({} objects; conditions {}; decision {})\n", o.table, a.rows,
                            fmt::join(conds, ", "), t.name(a.D.front()));
            print_human(t, a, s);
        }
        out << s;
        return 0;
    }
    const auto& book = grid::grid_rule_book();
    const DecisionTable& t = book.table;
    const Analysis a = analyse(t, roughset::GivenRules{book.reduct, book.rules, "the grid rule book's reduct"});
    // Wan and Gao (2022) report their own table's sizes (4374 rows -> 5 attributes, 162 rows -> 80 rules).
    if (o.json) {
        s = fmt::format(
            "{{\"table\": \"grid\", {}, \"sizes\": {{\"rows\": {}, \"attributes\": {}, \"reduced_rows\": {}, "
            "\"rules\": {}}}, \"paper\": {{\"rows\": 4374, \"attributes\": 5, \"reduced_rows\": 162, \"rules\": "
            "80}}}}\n",
            json_body(t, a), t.rows(), book.reduct.size(), book.reduced_rows, book.rules.size());
    } else {
        s = "table: the grid decision table of Wan and Gao (2022), section 2.2 (X1..X8: the neighbours clockwise\n"
            "from the goal direction, 1 = blocked, 2 = visited, 3 = free; Y: the neighbour to move to, 9 = back)\n";
        s += fmt::format("{:<30}{:>8}{:>20}\n", "sizes", "pride", "Wan and Gao (2022)");
        s += fmt::format("  {:<28}{:>8}{:>20}\n", "rows of the full table", t.rows(), 4374);
        s += fmt::format("  {:<28}{:>8}{:>20}   {}\n", "attributes kept", book.reduct.size(), 5,
                         names_of(t, book.reduct));
        s += fmt::format("  {:<28}{:>8}{:>20}\n", "rows on the reduct", book.reduced_rows, 162);
        s += fmt::format("  {:<28}{:>8}{:>20}\n", "minimal rules", book.rules.size(), 80);
        print_human(t, a, s);
    }
    out << s;
    return 0;
}

}  // namespace pride::cli

// Rough sets for Python: a decision table from codes or labels (pride/__init__.py turns arrays
// and DataFrames into those) or a CSV file, analysed as `pride roughset --json` analyses one:
// the same keys, the same limits, the same choice of the reduct the rules are computed on.
#include <fmt/format.h>

#include "common.hpp"
#include "roughset/roughset.hpp"

namespace pride::python {

namespace {

using roughset::Attributes;
using roughset::DecisionTable;

// cli/roughset.cpp's limit: minimal rules cost about 2^|B| partitions of the distinct rows.
constexpr double rule_budget = 1 << 28;

py::list names(const DecisionTable& t, const Attributes& A) {
    py::list l;
    for (auto a : A) l.append(t.name(a));
    return l;
}

py::dict analyse(const DecisionTable& t) {
    const Attributes C = t.conditions(), D = t.decision();
    py::dict d;
    const std::size_t positive = roughset::positive_region(t, C, D).size();
    d["rows"] = t.rows();
    d["conditions"] = names(t, C);
    d["decision"] = t.name(D.front());
    d["consistent"] = positive == t.rows();
    d["positive_region"] = positive;
    d["dependency"] = roughset::dependency(t, C, D);
    d["core"] = names(t, roughset::core(t, C, D));
    const Attributes quick = roughset::quick_reduct(t, C, D);
    const bool exhaustive = C.size() <= roughset::max_exhaustive_attributes;
    std::vector<Attributes> reducts;
    Attributes used;
    if (exhaustive) {
        reducts = roughset::reducts(t, C, D);
        used = reducts.front();
    } else {
        reducts = {quick};
        used = quick;
    }
    d["exhaustive"] = exhaustive;
    py::list rl;
    for (const auto& r : reducts) rl.append(names(t, r));
    d["reducts"] = rl;
    d["quick_reduct"] = names(t, quick);
    d["reduct_used"] = names(t, used);
    const std::size_t distinct = roughset::indiscernibility(t, used).size();
    if (used.size() > roughset::max_exhaustive_attributes) {
        d["rules"] = py::none();
        d["rules_note"] = fmt::format("not computed: the reduct has {} attributes, the limit is {}", used.size(),
                                      roughset::max_exhaustive_attributes);
    } else if (static_cast<double>(std::uint64_t{1} << used.size()) * static_cast<double>(distinct) > rule_budget) {
        d["rules"] = py::none();
        d["rules_note"] = fmt::format("not computed: 2^{} value subsets x {} distinct rows is over the limit of 2^28",
                                      used.size(), distinct);
    } else {
        std::vector<roughset::Rule> rules;
        {
            py::gil_scoped_release release;
            rules = roughset::minimal_rules(t, used, D);
        }
        py::list out;
        for (const auto& r : rules) {
            py::dict conditions;
            for (const auto& c : r.conditions) conditions[py::str(t.name(c.attribute))] = t.label(c.attribute, c.value);
            py::list support;
            for (auto o : r.support) support.append(o);
            out.append(py::dict(py::arg("if") = conditions, py::arg("then") = t.label(D.front(), r.decision.front()),
                                py::arg("support") = r.support.size(), py::arg("objects") = support));
        }
        d["rules"] = out;
    }
    return d;
}

/// A table of integer codes (labels their decimal text) or of text labels, row by row.
DecisionTable table(const std::vector<std::string>& columns, const py::object& rows, bool labels) {
    DecisionTable t(columns);
    for (const auto& row : rows) {
        if (labels) {
            const auto v = row.cast<std::vector<std::string>>();
            t.add_row_labels(v);
        } else {
            const auto v = row.cast<std::vector<int>>();
            t.add_row(v);
        }
    }
    require(t.rows() > 0, "table", "the decision table has no rows");
    return t;
}

}  // namespace

void bind_roughset(py::module_& m) {
    m.def(
        "roughset_table",
        [](const std::vector<std::string>& columns, const py::object& rows, bool labels) {
            return analyse(table(columns, rows, labels));
        },
        py::arg("columns"), py::arg("rows"), py::arg("labels"));
    m.def(
        "roughset_csv",
        [](const std::string& path) {
            const DecisionTable t = roughset::read_csv(path);
            return analyse(t);
        },
        py::arg("path"));
}

}  // namespace pride::python

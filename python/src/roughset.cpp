// Rough sets for Python: a decision table from codes or labels (pride/__init__.py turns arrays
// and DataFrames into those) or a CSV file, analysed by roughset::analyse as `pride roughset
// --json` analyses one: the same keys, limits and choice of the reduct the rules are computed on.
#include "roughset/roughset.hpp"
#include "common.hpp"

namespace pride::python {

namespace {

using roughset::Attributes;
using roughset::DecisionTable;

py::list names(const DecisionTable& t, const Attributes& A) {
    py::list l;
    for (auto a : A) l.append(t.name(a));
    return l;
}

/// roughset::analyse (with the GIL released) as the keys of `pride roughset --json`; rules also
/// list their objects (0-based).
py::dict analysis_dict(const DecisionTable& t) {
    roughset::Analysis a;
    {
        py::gil_scoped_release release;
        a = roughset::analyse(t);
    }
    py::dict d;
    d["rows"] = a.rows;
    d["conditions"] = names(t, a.C);
    d["decision"] = t.name(a.D.front());
    d["consistent"] = a.consistent;
    d["positive_region"] = a.positive;
    d["dependency"] = a.gamma;
    d["core"] = names(t, a.core);
    d["exhaustive"] = a.exhaustive;
    py::list reducts;
    for (const auto& r : a.reducts) reducts.append(names(t, r));
    d["reducts"] = reducts;
    d["quick_reduct"] = names(t, a.quick);
    d["reduct_used"] = names(t, a.used);
    if (!a.rules) {
        d["rules"] = py::none();
        d["rules_note"] = a.no_rules;
        return d;
    }
    py::list rules;
    for (const auto& r : *a.rules) {
        py::dict conditions;
        for (const auto& c : r.conditions) conditions[py::str(t.name(c.attribute))] = t.label(c.attribute, c.value);
        py::list support;
        for (auto o : r.support) support.append(o);
        rules.append(py::dict(py::arg("if") = conditions, py::arg("then") = t.label(a.D.front(), r.decision.front()),
                              py::arg("support") = r.support.size(), py::arg("objects") = support));
    }
    d["rules"] = rules;
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
            return analysis_dict(table(columns, rows, labels));
        },
        py::call_guard<Call>(), py::arg("columns"), py::arg("rows"), py::arg("labels"));
    m.def(
        "roughset_csv",
        [](const std::string& path) {
            const DecisionTable t = roughset::read_csv(path);
            return analysis_dict(t);
        },
        py::call_guard<Call>(), py::arg("path"));
}

}  // namespace pride::python

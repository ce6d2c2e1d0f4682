// pride.cec2020rw_score: the CEC 2020 real-world competition's ranking
// (experiment/report/cec2020rw_score.hpp) of runs given as arrays, pride's or published ones.
#include <fmt/format.h>

#include <algorithm>
#include <string>
#include <vector>

#include "common.hpp"
#include "experiment/report/cec2017_score.hpp"
#include "experiment/report/cec2020rw_score.hpp"

namespace pride::python {
namespace {

namespace rw = report::cec2020rw;

/// A sequence of integers (dims, exclude): TypeError naming `what` otherwise.
std::vector<std::int64_t> integers(const py::object& o, const char* what) {
    if (!py::isinstance<py::sequence>(o) || py::isinstance<py::str>(o))
        throw py::type_error(std::string(what) + ": expected a sequence of integers");
    std::vector<std::int64_t> out;
    for (const py::handle item : py::reinterpret_borrow<py::sequence>(o)) {
        if (!py::isinstance<py::int_>(item) || py::isinstance<py::bool_>(item))
            throw py::type_error(std::string(what) + ": expected integers, got " +
                                 std::string(py::str(py::type::of(item).attr("__name__"))));
        out.push_back(item.cast<std::int64_t>());
    }
    return out;
}

/// results: {name: (f, violation)}, each a (problems, runs) array; dims: one integer per problem.
py::dict cec2020rw_score(const py::object& results, const py::object& dims, const py::object& order) {
    if (!py::isinstance<py::str>(order)) throw py::type_error("order: expected 'guidelines' or 'given'");
    const std::string how = order.cast<std::string>();
    require(how == "guidelines" || how == "given", "order", "expected 'guidelines' or 'given', got '" + how + "'");
    const auto run_order = how == "given" ? rw::Order::given : rw::Order::guidelines;
    if (!py::isinstance<py::dict>(results))
        throw py::type_error("results: expected a dict {name: (f, violation)}, got " +
                             std::string(py::str(py::type::of(results).attr("__name__"))));
    const auto d = integers(dims, "dims");
    for (const std::int64_t dim : d) require(dim >= 1, "dims", fmt::format("a dimension must be >= 1, got {}", dim));
    require(!d.empty(), "dims", "no problems");
    const auto& table = results.cast<py::dict>();
    require(!table.empty(), "results", "no algorithms");
    std::vector<std::string> names;
    std::vector<std::vector<rw::Summary>> summaries;
    for (const auto& [key, value] : table) {
        if (!py::isinstance<py::str>(key)) throw py::type_error("results: expected names (str) as keys");
        const std::string name = key.cast<std::string>();
        const std::string where = "results['" + name + "']";
        if (!py::isinstance<py::tuple>(value) || py::len(value) != 2)
            throw py::type_error(where + ": expected a pair (f, violation)");
        const auto pair = value.cast<py::tuple>();
        const auto f = real_array(pair[0], where + "[0]");
        const auto v = real_array(pair[1], where + "[1]");
        for (const auto* a : {&f, &v})
            require(a->ndim() == 2 && a->shape(0) == static_cast<py::ssize_t>(d.size()) && a->shape(1) >= 1, where,
                    fmt::format("f and violation must be ({}, runs) arrays, one row per problem of dims", d.size()));
        require(f.shape(1) == v.shape(1), where, "f and violation must have the same shape");
        names.push_back(name);
        summaries.emplace_back();
        const py::ssize_t runs = f.shape(1);
        std::vector<rw::Outcome> outcomes(static_cast<std::size_t>(runs));
        for (py::ssize_t j = 0; j < f.shape(0); ++j) {
            for (py::ssize_t r = 0; r < runs; ++r) outcomes[static_cast<std::size_t>(r)] = {f.at(j, r), v.at(j, r)};
            summaries.back().push_back(rw::summarise(outcomes, fmt::format("{}, problem {}", where, j), run_order));
        }
    }
    const auto scores = rw::score(summaries, d);
    const auto ranks = rw::ranks(scores);
    py::dict out;
    for (std::size_t i = 0; i < names.size(); ++i) {
        py::dict s;
        s["best"] = scores[i].best;
        s["mean"] = scores[i].mean;
        s["median"] = scores[i].median;
        s["total"] = scores[i].total;
        s["rank"] = ranks[i];
        out[py::str(names[i])] = s;
    }
    return out;
}

/// results: {name: (functions, dims) array of mean errors, F1 in row 0}; the rows of `exclude` left out.
py::dict cec2017_score(const py::object& results, const py::object& dims, const py::object& exclude) {
    if (!py::isinstance<py::dict>(results))
        throw py::type_error("results: expected a dict {name: mean errors}, got " +
                             std::string(py::str(py::type::of(results).attr("__name__"))));
    const auto d = integers(dims, "dims");
    require(!d.empty(), "dims", "no dimensions");
    for (const std::int64_t dim : d) report::cec2017::weight(dim);  // refuses another dimension, naming it
    const auto left_out = integers(exclude, "exclude");
    const auto& table = results.cast<py::dict>();
    require(!table.empty(), "results", "no algorithms");
    std::vector<std::string> names;
    std::vector<std::vector<double>> means;
    std::vector<report::cec2017::Cell> cells;
    for (const auto& [key, value] : table) {
        if (!py::isinstance<py::str>(key)) throw py::type_error("results: expected names (str) as keys");
        const std::string where = "results['" + key.cast<std::string>() + "']";
        const auto a = real_array(py::reinterpret_borrow<py::object>(value), where);
        require(
            a.ndim() == 2 && a.shape(1) == static_cast<py::ssize_t>(d.size()) && a.shape(0) >= 1, where,
            fmt::format("expected a (functions, {}) array of mean errors, one column per dimension of dims", d.size()));
        std::vector<double> row;
        std::vector<report::cec2017::Cell> these;
        for (py::ssize_t f = 0; f < a.shape(0); ++f) {
            if (std::find(left_out.begin(), left_out.end(), f + 1) != left_out.end()) continue;
            for (std::size_t k = 0; k < d.size(); ++k) {
                row.push_back(a.at(f, static_cast<py::ssize_t>(k)));
                these.push_back({static_cast<int>(f + 1), d[k]});
            }
        }
        if (names.empty()) cells = these;
        require(these.size() == cells.size(), where, "every algorithm must have the same functions");
        names.push_back(key.cast<std::string>());
        means.push_back(std::move(row));
    }
    const auto scores = report::cec2017::score(means, cells);
    py::dict out;
    for (std::size_t i = 0; i < names.size(); ++i) {
        py::dict s;
        s["se"] = scores[i].se;
        s["sr"] = scores[i].sr;
        s["score1"] = scores[i].score1;
        s["score2"] = scores[i].score2;
        s["total"] = scores[i].total;
        s["rank"] = scores[i].rank;
        out[py::str(names[i])] = s;
    }
    return out;
}

}  // namespace

void bind_score(py::module_& m) {
    m.def("cec2017_score", &cec2017_score, py::arg("results"), py::arg("dims"), py::arg("exclude"));
    m.def("cec2020rw_score", &cec2020rw_score, py::arg("results"), py::arg("dims"), py::arg("order"));
}

}  // namespace pride::python

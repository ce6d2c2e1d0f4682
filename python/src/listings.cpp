// pride.algorithms(), pride.problems() and pride.grid_names(): the engine's registries as Python
// lists of dicts, every name, parameter and range as the command line lists them.
#include "common.hpp"
#include "engine/grid_names.hpp"
#include "engine/registry.hpp"
#include "problems/continuous/catalog.hpp"

namespace pride::python {

namespace {

py::dict param_dict(const engine::ParamSpec& p) {
    py::dict d;
    d["name"] = p.name;
    d["type"] = std::string(engine::to_string(p.type));
    if (p.default_value) {
        if (p.type == engine::ParamType::integer)
            d["default"] = static_cast<std::int64_t>(*p.default_value);
        else if (p.type == engine::ParamType::flag)
            d["default"] = *p.default_value != 0.0;
        else if (p.type == engine::ParamType::choice)
            d["default"] = p.default_text();
        else
            d["default"] = *p.default_value;
    } else {
        d["default"] = py::none();
    }
    d["min"] = p.min;
    d["max"] = p.max;
    d["min_open"] = p.min_open;
    d["max_open"] = p.max_open;
    d["range"] = p.range();
    d["doc"] = p.doc;
    if (p.type == engine::ParamType::choice) d["choices"] = p.choices;
    return d;
}

py::list algorithms() {
    py::list out;
    for (const auto& a : engine::algorithms().entries()) {
        py::dict d;
        d["name"] = a.name;
        d["family"] = a.family;
        d["summary"] = a.summary;
        d["spaces"] = a.spaces();
        py::list params;
        for (const auto& p : a.params) params.append(param_dict(p));
        d["params"] = params;
        out.append(d);
    }
    return out;
}

py::list problems() {
    static constexpr const char* instances[] = {"transform", "none", "coco"};
    py::list out;
    for (const auto& item : continuous::catalog().items()) {
        const auto& e = item.entry;
        py::dict d;
        d["name"] = item.name;
        d["summary"] = item.summary;
        d["min_dim"] = e.min_dim;
        d["fixed_dim"] = e.fixed_dim ? py::object(py::int_(e.fixed_dim)) : py::object(py::none());
        d["instances"] = instances[static_cast<int>(e.instances)];
        d["default_instance"] = continuous::default_instance(e);
        d["suite"] = e.suite.empty() ? py::object(py::none()) : py::object(py::str(e.suite));
        d["number"] = e.suite.empty() ? py::object(py::none()) : py::object(py::int_(e.number));
        // Not None: the only dimensions (a CEC function: where the official data is).
        d["dims"] = e.dims.empty() ? py::object(py::none()) : py::object(py::cast(e.dims));
        out.append(d);
    }
    return out;
}

py::dict grid_names() {
    auto items = [](const std::vector<engine::NamedItem>& v) {
        py::list l;
        for (const auto& i : v) l.append(py::dict(py::arg("name") = i.name, py::arg("summary") = i.summary));
        return l;
    };
    py::dict d;
    d["objectives"] = items(engine::grid_objectives());
    d["encodings"] = items(engine::grid_encodings());
    d["connectors"] = items(engine::grid_connectors());
    d["inits"] = items(engine::grid_inits());
    return d;
}

}  // namespace

void bind_listings(py::module_& m) {
    m.def("algorithms", &algorithms);
    m.def("problems", &problems);
    m.def("grid_names", &grid_names);
}

}  // namespace pride::python

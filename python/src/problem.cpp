// pride.Problem: a registered continuous function evaluated from Python.
#include <cmath>
#include <string>
#include <vector>

#include "common.hpp"
#include "engine/problem_names.hpp"
#include "problems/continuous/catalog.hpp"

namespace pride::python {

namespace {

/// Problem: a registered continuous function to evaluate from Python (another optimiser's
/// objective, say), the same values, bit for bit, as pride's own runs see.
class PyProblem {
  public:
    PyProblem(const std::string& name, std::optional<std::int64_t> dim, std::optional<std::int64_t> instance,
              std::uint64_t seed) {
        const auto* item = continuous::catalog().find(name);
        if (!item) throw InputError("problem", engine::unknown_problem(name) + " (see pride.problems())");
        if (!dim && item->entry.fixed_dim) dim = static_cast<std::int64_t>(item->entry.fixed_dim);
        require(dim.has_value(), "dim", "give the dimension of problem '" + name + "'");
        count_in("dim", *dim, 1);
        function_.emplace(continuous::make_function(name, *dim, instance));
        function_->reseed(seed);
    }

    /// f(x) for x of shape (dim,), or the n values of the rows of an (n, dim) array.
    py::object call(const py::object& x) {
        const auto a = real_array(x, "x");
        const auto dim = static_cast<py::ssize_t>(function_->dimension());
        if (a.ndim() == 1) {
            require(a.shape(0) == dim, "x",
                    "has " + std::to_string(a.shape(0)) + " coordinates, the problem " + std::to_string(dim));
            return py::float_(function_->evaluate(std::span<const double>(a.data(), static_cast<std::size_t>(dim))));
        }
        require(a.ndim() == 2, "x",
                "must be one point (dim,) or a batch (n, dim), got " + std::to_string(a.ndim()) + " dimensions");
        require(a.shape(1) == dim, "x",
                "rows have " + std::to_string(a.shape(1)) + " coordinates, the problem " + std::to_string(dim));
        const py::ssize_t n = a.shape(0);
        py::array_t<double> out(n);
        if (n == 0) return out;
        // Row-major (n, dim) is column-major (dim, n): one column per point, as evaluate_batch takes.
        const Eigen::Map<const Matrix> points(a.data(), dim, n);
        function_->evaluate_batch(points, std::span<double>(out.mutable_data(), static_cast<std::size_t>(n)));
        return out;
    }

    std::string name() const { return std::string(function_->name()); }
    std::int64_t dim() const { return static_cast<std::int64_t>(function_->dimension()); }
    std::int64_t instance() const { return function_->instance(); }
    py::array_t<double> lower() const { return vector_array(function_->lower()); }
    py::array_t<double> upper() const { return vector_array(function_->upper()); }
    /// Each variable's type: "real" or "integer" (bbob-mixint's first 4D/5).
    std::vector<std::string> types() const {
        std::vector<std::string> out;
        for (std::size_t i = 0; i < function_->dimension(); ++i)
            out.emplace_back(pride::type_name(function_->variable_type(i)));
        return out;
    }
    py::object optimum() const {
        const double v = function_->optimum_value();
        return std::isnan(v) ? py::object(py::none()) : py::object(py::float_(v));
    }

  private:
    static py::array_t<double> vector_array(std::span<const double> v) {
        py::array_t<double> a(static_cast<py::ssize_t>(v.size()));
        std::copy(v.begin(), v.end(), a.mutable_data());
        return a;
    }
    std::optional<continuous::Function> function_;
};

}  // namespace

void bind_problem(py::module_& m) {
    py::class_<PyProblem>(m, "Problem")
        .def(py::init<const std::string&, std::optional<std::int64_t>, std::optional<std::int64_t>, std::uint64_t>(),
             py::call_guard<Call>(), py::arg("name"), py::arg("dim"), py::arg("instance"), py::arg("seed"))
        .def("__call__", &PyProblem::call, py::call_guard<Call>(), py::arg("x"))
        .def_property_readonly("name", &PyProblem::name)
        .def_property_readonly("dim", &PyProblem::dim)
        .def_property_readonly("instance", &PyProblem::instance)
        .def_property_readonly("lower", &PyProblem::lower)
        .def_property_readonly("upper", &PyProblem::upper)
        .def_property_readonly("optimum", &PyProblem::optimum)
        .def_property_readonly("types", &PyProblem::types);
}

}  // namespace pride::python

// pride.minimize(): one run of a registered algorithm on a registered problem or a Python function
// (with its constraints), its result as a dict.
#include <fmt/format.h>

#include <cmath>

#include "common.hpp"
#include "engine/prepared.hpp"
#include "engine/problem_names.hpp"
#include "engine/registry.hpp"
#include "problems/continuous/catalog.hpp"
#include "problems/continuous/cec2006/cec2006.hpp"
#include "problems/continuous/cec2020rw/cec2020rw.hpp"

namespace pride::python {

namespace {

/// The constraints of minimize() on a Python function: `subject_to` g(x) (or, without it, the
/// function returning (f, g)), the counts and the tolerance, as the engine's CallbackSpec names them.
struct ConstraintArgs {
    py::object subject_to = py::none();
    std::optional<std::int64_t> inequalities, equalities;
    std::optional<double> tolerance;
    bool declared() const { return !subject_to.is_none() || inequalities || equalities; }
};

/// The f of a user's constrained function as a number; `refusal` starts the TypeError's message.
double objective_value(const py::object& value, const std::string& refusal) {
    const double f = PyFloat_AsDouble(value.ptr());
    if (f == -1.0 && PyErr_Occurred()) {
        PyErr_Clear();
        throw py::type_error(refusal + type_name(value));
    }
    return f;
}

/// A constrained user function: f(x) and subject_to(x) (or one function returning (f, g)), one
/// call of each per evaluation; g's m + p values checked for their number.
void set_constraints(engine::CallbackSpec& spec, const py::object& fn, const ConstraintArgs& c,
                     const std::shared_ptr<UserError>& errors) {
    spec.inequalities = c.inequalities.value_or(0);
    spec.equalities = c.equalities.value_or(0);
    spec.tolerance = c.tolerance.value_or(kEqualityTolerance);
    // The counts as the engine checks them (InputError naming each), then the tolerance, before any call.
    engine::CallbackSpec counted;
    counted.inequalities = spec.inequalities;
    counted.equalities = spec.equalities;
    if (spec.inequalities + spec.equalities > 0)
        counted.constrained = [](std::span<const double>, std::span<double>) { return 0.0; };
    const bool any = engine::has_constraints(counted);
    require(any, "inequalities",
            "give how many constraint values g(x) has: inequalities=m (g_i(x) <= 0, first) and/or "
            "equalities=p (h_j(x) = 0)");
    require(std::isfinite(spec.tolerance) && spec.tolerance >= 0.0, "tolerance",
            fmt::format("must be a finite number >= 0, got {}", spec.tolerance));
    const auto k = static_cast<std::size_t>(spec.inequalities + spec.equalities);
    const std::string counts =
        "inequalities=" + std::to_string(spec.inequalities) + ", then equalities=" + std::to_string(spec.equalities);
    auto function = std::make_shared<py::object>(fn);
    auto g = c.subject_to.is_none() ? nullptr : std::make_shared<py::object>(c.subject_to);
    const std::string where = g ? "subject_to" : "problem";
    spec.constrained = [function, g, errors, k, counts, where](std::span<const double> x,
                                                               std::span<double> values) -> double {
        return python_call(errors, [&] {
            double f = 0.0;
            py::object constraint_values;
            if (g) {
                f = objective_value((*function)(point_array(x)), "the function must return one number, got ");
                constraint_values = (*g)(point_array(x));
            } else {
                const py::object both = (*function)(point_array(x));
                if (!py::isinstance<py::tuple>(both) || py::len(both) != 2)
                    throw py::type_error(
                        "problem: with inequalities or equalities and no subject_to, the function returns (f, g), "
                        "f a number and g the constraint values; got " +
                        type_name(both));
                const auto pair = both.cast<py::tuple>();
                f = objective_value(pair[0], "problem: the function returns (f, g), f one number; got f of type ");
                constraint_values = pair[1];
            }
            const auto a = real_array(constraint_values, where + ": the constraint values");
            require(a.ndim() <= 1 && static_cast<std::size_t>(a.size()) == k, where,
                    "returned " + std::to_string(a.size()) + " constraint values" +
                        (a.ndim() > 1 ? " (" + std::to_string(a.ndim()) + "-D)" : std::string()) + ", expected " +
                        std::to_string(k) + " (" + counts + ")");
            std::copy(a.data(), a.data() + k, values.begin());
            return f;
        });
    };
}

/// The problem of minimize(): a registered name (dim, instance) or a Python callable on bounds,
/// its size checked with the run's (`algorithm` under `budget`) before anything is built.
engine::ProblemSpec problem_spec(const py::object& problem, std::optional<std::int64_t> dim, const py::object& bounds,
                                 std::optional<std::int64_t> instance, bool vectorized,
                                 const ConstraintArgs& constraints, const std::shared_ptr<UserError>& errors,
                                 const engine::AlgorithmSpec& algorithm, const engine::Budget& budget,
                                 const std::optional<std::vector<std::int64_t>>& integers,
                                 const std::optional<std::vector<std::int64_t>>& categorical) {
    if (py::isinstance<py::str>(problem)) {
        const auto name = utf8_arg(problem, "problem");
        require(bounds.is_none(), "bounds",
                "only for Python functions: problem '" + name + "' has its own box (see pride.problems())");
        require(!integers, "integers",
                "only for Python functions: problem '" + name + "' declares its own variables' types");
        require(!categorical, "categorical",
                "only for Python functions: problem '" + name + "' declares its own variables' types");
        require(!vectorized, "vectorized", "only for Python functions");
        for (const auto& [given, what] : {std::pair{!constraints.subject_to.is_none(), "subject_to"},
                                          std::pair{constraints.inequalities.has_value(), "inequalities"},
                                          std::pair{constraints.equalities.has_value(), "equalities"},
                                          std::pair{constraints.tolerance.has_value(), "tolerance"}})
            require(!given, what, "only for Python functions: problem '" + name + "' has its own constraints, or none");
        // The constrained suites: CEC 2006's and CEC 2020's each in its own dimension, COCO's
        // bbob-constrained in the one given; checked when the problem is built.
        if (const auto number = engine::cec2006_number(name)) {
            if (!dim) dim = static_cast<std::int64_t>(continuous::cec2006::Problem(*number).dimension());
            return engine::ContinuousSpec{name, *dim, instance};
        }
        if (const auto number = engine::cec2020rw_number(name)) {
            if (!dim) dim = static_cast<std::int64_t>(continuous::cec2020rw::Problem(*number).dimension());
            return engine::ContinuousSpec{name, *dim, instance};
        }
        if (engine::bbob_constrained_number(name)) {
            require(dim.has_value(), "dim", "give the dimension of problem '" + name + "'");
            return engine::ContinuousSpec{name, *dim, instance};
        }
        if (!dim)
            if (const auto* item = continuous::catalog().find(name); item && item->entry.fixed_dim)
                dim = static_cast<std::int64_t>(item->entry.fixed_dim);
        if (!dim && !continuous::catalog().find(name)) throw InputError("problem", engine::unknown_problem(name));
        require(dim.has_value(), "dim", "give the dimension of problem '" + name + "'");
        const engine::ContinuousSpec spec{name, *dim, instance};
        engine::check_before_building(algorithm, spec, *dim, budget);
        return spec;
    }
    if (!PyCallable_Check(problem.ptr()))
        throw py::type_error("problem: expected a registered problem's name (str) or a callable, got " +
                             py::str(py::type::of(problem).attr("__name__")).cast<std::string>());
    require(!instance, "instance", "only for registered problems");
    require(!bounds.is_none(), "bounds", "a Python function needs bounds=(lower, upper)");
    if (!constraints.declared()) {
        require(!constraints.tolerance, "tolerance",
                "only with constraints: give subject_to and inequalities or equalities");
        auto [lower, upper] = parse_bounds(bounds, dim, box_check(algorithm, "bounds", budget));
        auto types = variable_types(integers, categorical, lower.size());
        auto spec = callback_spec(problem, vectorized, std::move(lower), std::move(upper), errors);
        spec.types = std::move(types);
        return spec;
    }
    require(!vectorized, "vectorized",
            "not with constraints: the engine evaluates a constrained point at a time (give f(x) and "
            "subject_to(x) of one point)");
    const engine::AlgorithmSpec unconstrained = without_constraint_params(algorithm);
    auto [lower, upper] = parse_bounds(bounds, dim, box_check(unconstrained, "bounds", budget));
    engine::CallbackSpec spec;
    spec.name = "bounds";
    spec.types = variable_types(integers, categorical, lower.size());
    spec.lower = std::move(lower);
    spec.upper = std::move(upper);
    set_constraints(spec, problem, constraints, errors);
    return spec;
}

py::dict minimize(const std::string& algo, const py::object& problem, std::optional<std::int64_t> dim,
                  const py::object& bounds, std::optional<std::int64_t> evals, std::optional<std::int64_t> iters,
                  std::optional<double> target, std::optional<double> wall_ms, std::uint64_t seed,
                  std::optional<std::int64_t> instance, const py::object& callback, bool vectorized,
                  const py::object& subject_to, std::optional<std::int64_t> inequalities,
                  std::optional<std::int64_t> equalities, std::optional<double> tolerance,
                  const std::optional<std::vector<std::int64_t>>& integers,
                  const std::optional<std::vector<std::int64_t>>& categorical, const py::dict& params) {
    auto errors = std::make_shared<UserError>();
    const engine::AlgorithmSpec algorithm{algo, param_values(algo, params)};
    const engine::Budget b = budget(evals, iters, target, wall_ms);
    const ConstraintArgs constraints{subject_to, inequalities, equalities, tolerance};
    std::optional<engine::Problem> prepared;
    prepared.emplace(
        problem_spec(problem, dim, bounds, instance, vectorized, constraints, errors, algorithm, b, integers,
                     categorical));
    engine::check(algorithm, *prepared, b);
    const engine::RunResult r = run_released(algorithm, *prepared, b, seed, callback, errors);
    py::dict d = result_dict(r);
    d["problem"] = prepared->name();
    d["instance"] = prepared->instance();
    return d;
}

}  // namespace

void bind_minimize(py::module_& m) {
    m.def("minimize", &minimize, py::call_guard<Call>(), py::arg("algo"), py::arg("problem"), py::arg("dim"),
          py::arg("bounds"), py::arg("evals"), py::arg("iters"), py::arg("target"), py::arg("wall_ms"), py::arg("seed"),
          py::arg("instance"), py::arg("callback"), py::arg("vectorized"), py::arg("subject_to"),
          py::arg("inequalities"), py::arg("equalities"), py::arg("tolerance"), py::arg("integers"), py::arg("categorical"),
          py::arg("params"));
}

}  // namespace pride::python

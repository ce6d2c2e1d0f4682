// pride._pride: the engine for Python (docs/python.md). The package's pride/__init__.py wraps
// these functions in the Python-facing API; everything here takes plain values.
#include <fmt/format.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <map>

#include "common.hpp"
#include "engine/ask_tell.hpp"
#include "engine/prepared.hpp"
#include "engine/registry.hpp"
#include "framework/error_place.hpp"
#include "problems/continuous/catalog.hpp"
#include "problems/continuous/cec2006/cec2006.hpp"
#include "problems/continuous/cec2020rw/cec2020rw.hpp"

namespace pride::python {

namespace {

// The command line's integer ranges and wording (cli/flags.hpp: max_count, max_seed), so that an
// error reads the same from Python as from `pride`.
constexpr std::int64_t kMaxCount = 1'000'000'000'000'000;

void integer_in(const char* name, std::int64_t value, std::int64_t lo, const std::string& hi_text, bool in_range) {
    require(in_range, name,
            "must be an integer in [" + std::to_string(lo) + ", " + hi_text + "], got " + std::to_string(value));
}

void count_in(const char* name, std::int64_t value, std::int64_t lo) {
    integer_in(name, value, lo, std::to_string(kMaxCount), value >= lo && value <= kMaxCount);
}

/// The command line's one-line message (cli/flags.cpp) with the Python keyword where the command
/// line names its flag: "dim: ..." for "--dim: ...", "evals: ..." for "--evals: ...".
std::string python_message(const InputError& e) {
    static const std::map<std::string, std::string, std::less<>> keywords{{"evaluations", "evals"},
                                                                          {"iterations", "iters"}};
    return renamed_message(e, keywords).value_or(e.what());
}

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

/// The constraints of minimize() on a Python function: `subject_to` g(x) (or, without it, the
/// function returning (f, g)), the counts and the tolerance, as the engine's CallbackSpec names them.
struct ConstraintArgs {
    py::object subject_to = py::none();
    std::optional<std::int64_t> inequalities, equalities;
    std::optional<double> tolerance;
    bool declared() const { return !subject_to.is_none() || inequalities || equalities; }
};

/// The algorithm without the parameters that choose a constraint handler: what the size checks
/// before building see, since a box not built yet has no constraints to allow them (engine::check
/// sees them all once the problem is built).
engine::AlgorithmSpec without_constraint_params(const engine::AlgorithmSpec& algorithm) {
    const engine::AlgorithmEntry* entry = engine::algorithms().find(algorithm.name);
    if (!entry) return algorithm;
    engine::AlgorithmSpec out{algorithm.name, {}};
    const auto kept = [&](const std::string& name) {
        const engine::ParamSpec* spec = entry->param(name);
        return !spec || !spec->constrained_only;
    };
    for (const auto& [name, value] : algorithm.params.values())
        if (kept(name)) out.params.set(name, value);
    for (const auto& [name, value] : algorithm.params.names())
        if (kept(name)) out.params.set_name(name, value);
    return out;
}

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
                                 const engine::AlgorithmSpec& algorithm, const engine::Budget& budget) {
    if (py::isinstance<py::str>(problem)) {
        const auto name = utf8_arg(problem, "problem");
        require(bounds.is_none(), "bounds",
                "only for Python functions: problem '" + name + "' has its own box (see pride.problems())");
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
        if (!dim && !continuous::catalog().find(name)) throw InputError("problem", "unknown problem '" + name + "'");
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
        return callback_spec(problem, vectorized, std::move(lower), std::move(upper), errors);
    }
    require(!vectorized, "vectorized",
            "not with constraints: the engine evaluates a constrained point at a time (give f(x) and "
            "subject_to(x) of one point)");
    const engine::AlgorithmSpec unconstrained = without_constraint_params(algorithm);
    auto [lower, upper] = parse_bounds(bounds, dim, box_check(unconstrained, "bounds", budget));
    engine::CallbackSpec spec;
    spec.name = "bounds";
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
                  std::optional<std::int64_t> equalities, std::optional<double> tolerance, const py::dict& params) {
    auto errors = std::make_shared<UserError>();
    const engine::AlgorithmSpec algorithm{algo, param_values(algo, params)};
    const engine::Budget b = budget(evals, iters, target, wall_ms);
    const ConstraintArgs constraints{subject_to, inequalities, equalities, tolerance};
    std::optional<engine::Problem> prepared;
    prepared.emplace(problem_spec(problem, dim, bounds, instance, vectorized, constraints, errors, algorithm, b));
    engine::check(algorithm, *prepared, b);
    const engine::RunResult r = run_released(algorithm, *prepared, b, seed, callback, errors);
    py::dict d = result_dict(r);
    d["problem"] = prepared->name();
    d["instance"] = prepared->instance();
    return d;
}

/// Optimizer: an engine::AskTell, stopped and joined without the GIL.
class Optimizer {
  public:
    Optimizer(const std::string& algo, const py::object& bounds, std::optional<std::int64_t> dim,
              std::optional<std::int64_t> evals, std::optional<std::int64_t> iters, std::optional<double> target,
              std::optional<double> wall_ms, std::uint64_t seed, std::optional<std::int64_t> objectives,
              std::optional<std::int64_t> inequalities, std::optional<std::int64_t> equalities,
              std::optional<double> tolerance, const py::dict& params) {
        require(!bounds.is_none(), "bounds", "the Optimizer needs bounds=(lower, upper)");
        engine::AlgorithmSpec algorithm{algo, param_values(algo, params)};
        const auto b = budget(evals, iters, target, wall_ms);
        const engine::AlgorithmEntry& entry = engine::algorithms().at(algo);
        const std::int64_t m = objectives.value_or(1);
        if (objectives) require(m >= 1 && m <= 10'000, "objectives", "must be in [1, 10000], got " + std::to_string(m));
        // A multi-objective run's checks need its M, made by AskTell: here only the box's size.
        const engine::AskTellConstraints constraints{inequalities.value_or(0), equalities.value_or(0),
                                                     tolerance.value_or(kEqualityTolerance)};
        require(inequalities || equalities || !tolerance, "tolerance",
                "only with constraints: give inequalities or equalities");
        if (inequalities || equalities) {
            for (const auto& [count, where] :
                 {std::pair{constraints.inequalities, "inequalities"}, std::pair{constraints.equalities, "equalities"}})
                require(count >= 0 && count <= engine::kMaxConstraints, where,
                        fmt::format("must be an integer in [0, {}], got {}", engine::kMaxConstraints, count));
            require(constraints.total() > 0, "inequalities",
                    "give how many constraint values each point has: inequalities=m (g_i(x) <= 0, first) and/or "
                    "equalities=p (h_j(x) = 0)");
            require(std::isfinite(constraints.tolerance) && constraints.tolerance >= 0.0, "tolerance",
                    fmt::format("must be a finite number >= 0, got {}", constraints.tolerance));
        }
        // A box not built yet has no constraints: its size checks leave the handler's parameters
        // to AskTell, which checks everything on the built problem.
        const engine::AlgorithmSpec sized =
            inequalities || equalities ? without_constraint_params(algorithm) : algorithm;
        auto [lower, upper] = parse_bounds(
            bounds, dim, entry.multiobjective() ? multiobjective_box_check(m) : box_check(sized, "bounds", b));
        py::gil_scoped_release release;
        run_ = std::make_unique<engine::AskTell>(std::move(algorithm), std::move(lower), std::move(upper), b, seed, m,
                                                 constraints);
    }
    ~Optimizer() { close(); }

    void close() {
        if (!run_) return;
        // Joining its thread needs no Python, so the GIL is kept off a thread that could not take
        // it back once the interpreter's exit has begun (a daemon thread dropping an optimizer).
        if (!on_main_thread()) {
            run_.reset();
            return;
        }
        py::gil_scoped_release release;
        run_.reset();
    }

    py::array_t<double> ask() {
        const Matrix* points = nullptr;
        bool ended = false;
        {
            py::gil_scoped_release release;
            points = &live().ask();  // rethrows what ended a run that failed
            ended = points->cols() == 0 && live().done();
        }
        require(!ended, "ask", "the run has ended (done is true): nothing more to ask; its result is in result");
        const auto n = static_cast<py::ssize_t>(points->cols()), dim = static_cast<py::ssize_t>(points->rows());
        py::array_t<double> out({n, dim});
        // A column of the engine's matrix is a row of X: one copy of the whole block.
        if (n > 0) std::memcpy(out.mutable_data(), points->data(), sizeof(double) * static_cast<std::size_t>(n * dim));
        return out;
    }

    void tell(const py::object& values, const py::object& g) {
        const auto v = real_array(values, "tell: values");
        const auto m = static_cast<py::ssize_t>(live().objectives());
        if (m == 1)
            require(v.ndim() == 1 || (v.ndim() == 2 && v.shape(1) == 1), "tell",
                    "expected a 1-D array of values, one per point asked for, got an array with " +
                        std::to_string(v.ndim()) + " dimensions");
        else
            require(v.ndim() == 2 && v.shape(1) == m, "tell",
                    "expected an (n, " + std::to_string(m) + ") array, a row of M values per point asked for");
        const auto k = static_cast<py::ssize_t>(live().constraints());
        std::optional<py::array_t<double, py::array::c_style | py::array::forcecast>> c;
        if (!g.is_none()) {
            require(k > 0, "tell",
                    "g was given, but the optimizer has no constraints (declare inequalities or equalities when "
                    "it is made)");
            c = real_array(g, "tell: g");
            // One constraint: g may be the n values themselves.
            require((c->ndim() == 2 && c->shape(1) == k) || (k == 1 && c->ndim() == 1), "tell",
                    "g: expected an (n, " + std::to_string(k) + ") array, a row of the " + std::to_string(k) +
                        " constraint values (inequalities, then equalities) per point asked for");
        } else {
            require(k == 0, "tell",
                    "g: the optimizer has " + std::to_string(k) + " constraints: tell(values, g) with g of shape (n, " +
                        std::to_string(k) + ")");
        }
        const std::span<const double> values_span(v.data(), static_cast<std::size_t>(v.size()));
        const std::span<const double> g_span =
            c ? std::span<const double>(c->data(), static_cast<std::size_t>(c->size())) : std::span<const double>();
        py::gil_scoped_release release;
        live().tell(values_span, g_span);
    }

    bool done() {
        py::gil_scoped_release release;
        return live().done();
    }

    py::dict result() {
        const engine::RunResult* r = nullptr;
        {
            py::gil_scoped_release release;
            r = &live().result();
        }
        return live().objectives() > 1 ? front_result_dict(*r, live().objectives()) : result_dict(*r);
    }

    std::size_t dimension() { return live().dimension(); }

  private:
    engine::AskTell& live() {
        if (!run_) throw InputError("optimizer", "closed: its run was stopped");
        return *run_;
    }
    std::unique_ptr<engine::AskTell> run_;
};

}  // namespace

std::string type_name(const py::handle& o) {
    return py::str(py::type::of(o).attr("__name__")).cast<std::string>();
}

std::int64_t integer_arg(const py::handle& o, const std::string& name) {
    if (PyBool_Check(o.ptr()) || !py::isinstance(o, py::module_::import("numbers").attr("Integral")))
        throw py::type_error(name + ": expected an integer, got " + type_name(o));
    const py::int_ i = py::reinterpret_steal<py::int_>(PyNumber_Index(o.ptr()));
    if (!i) throw py::error_already_set();
    int overflow = 0;
    const long long v = PyLong_AsLongLongAndOverflow(i.ptr(), &overflow);
    if (overflow != 0)
        throw py::value_error(name + ": " + py::str(py::handle(i)).cast<std::string>() +
                              " is out of range (64-bit integers)");
    return v;
}

double number_arg(const py::handle& o, const std::string& name) {
    if (PyBool_Check(o.ptr()) || !py::isinstance(o, py::module_::import("numbers").attr("Real")))
        throw py::type_error(name + ": expected a number, got " + type_name(o));
    const double v = PyFloat_AsDouble(o.ptr());
    if (v == -1.0 && PyErr_Occurred()) throw py::error_already_set();
    return v;
}

std::string utf8_arg(const py::handle& o, const std::string& name) {
    Py_ssize_t size = 0;
    const char* bytes = PyUnicode_AsUTF8AndSize(o.ptr(), &size);
    if (!bytes) {
        PyErr_Clear();
        throw py::value_error(name +
                              ": not valid UTF-8 (a lone surrogate, as os.listdir gives for a name whose bytes are "
                              "not UTF-8): pride takes UTF-8 text");
    }
    return std::string(bytes, static_cast<std::size_t>(size));
}

std::string text_arg(const py::handle& o, const std::string& name) {
    if (!py::isinstance<py::str>(o)) throw py::type_error(name + ": expected a str, got " + type_name(o));
    return utf8_arg(o, name);
}

std::string path_arg(const py::handle& o, const std::string& name) {
    if (py::isinstance<py::str>(o)) return utf8_arg(o, name);
    if (py::isinstance(o, py::module_::import("os").attr("PathLike"))) {
        const py::object p = py::module_::import("os").attr("fspath")(o);
        if (py::isinstance<py::str>(p)) return utf8_arg(p, name);
    }
    throw py::type_error(name + ": expected a path (str or os.PathLike), got " + type_name(o));
}

bool flag_arg(const py::handle& o, const std::string& name) {
    if (PyBool_Check(o.ptr())) return o.ptr() == Py_True;
    if (py::isinstance(o, py::module_::import("numpy").attr("bool_"))) return o.cast<bool>();
    throw py::type_error(name + ": expected True or False, got " + type_name(o));
}

engine::ParamValues param_values(const std::string& algo, const py::dict& params) {
    engine::ParamValues v;
    const engine::AlgorithmEntry* entry = engine::algorithms().find(algo);
    for (const auto& [key, value] : params) {
        const auto name =
            py::isinstance<py::str>(key) ? utf8_arg(key, "parameter names") : py::str(key).cast<std::string>();
        // A choice parameter takes a name (a str), every other parameter a number.
        const engine::ParamSpec* spec = entry ? entry->param(name) : nullptr;
        const bool choice = spec && spec->type == engine::ParamType::choice;
        const std::string type = py::str(py::type::of(value).attr("__name__")).cast<std::string>();
        if (choice) {
            if (!py::isinstance<py::str>(value))
                throw py::type_error("parameter " + name + ": expected one of " + spec->range() + " (a str), got " +
                                     type);
            v.set_name(name, utf8_arg(value, "parameter " + name));
            continue;
        }
        if (PyBool_Check(value.ptr())) {
            v.set(name, value.cast<bool>() ? 1.0 : 0.0);
        } else if (PyLong_Check(value.ptr()) || PyFloat_Check(value.ptr()) ||
                   py::isinstance(value, py::module_::import("numbers").attr("Real"))) {
            const double d = value.cast<double>();
            require(std::isfinite(d), "parameter " + name, "must be a finite number");
            v.set(name, d);
        } else {
            throw py::type_error("parameter " + name + ": expected a number, got " +
                                 py::str(py::type::of(value).attr("__name__")).cast<std::string>());
        }
    }
    return v;
}

py::array numeric_array(const py::object& o, const std::string& what) {
    // numpy would turn None and objects into NaN and complex numbers into their real part.
    const auto type = [&] { return py::str(py::type::of(o).attr("__name__")).cast<std::string>(); };
    if (o.is_none()) throw py::type_error(what + ": expected real numbers, got NoneType");
    py::array a;
    try {
        a = py::module_::import("numpy").attr("asarray")(o);
    } catch (const py::error_already_set&) {
        throw py::type_error(what + ": expected real numbers, got " + type());
    }
    const char kind = a.dtype().kind();
    if (kind != 'f' && kind != 'i' && kind != 'u' && kind != 'b')
        throw py::type_error(what + ": expected real numbers, got " + type() + " of dtype " +
                             py::str(a.dtype()).cast<std::string>());
    return a;
}

py::array_t<double, py::array::c_style | py::array::forcecast> real_array(const py::object& o,
                                                                          const std::string& what) {
    const py::array a = numeric_array(o, what);
    auto f = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
    if (!f)
        throw py::value_error(what + ": " + std::to_string(a.size()) +
                              " numbers do not fit in memory as an array of doubles");
    return f;
}

std::function<void(std::int64_t)> box_check(const engine::AlgorithmSpec& algorithm, const std::string& name,
                                            const engine::Budget& budget) {
    return [&algorithm, name, &budget](std::int64_t dimension) {
        engine::CallbackSpec box;
        box.name = name;
        engine::check_before_building(algorithm, box, dimension, budget);
    };
}

std::pair<std::vector<double>, std::vector<double>> parse_bounds(const py::object& bounds,
                                                                 std::optional<std::int64_t> dim,
                                                                 const std::function<void(std::int64_t)>& check_size) {
    if (!py::isinstance<py::sequence>(bounds) || py::isinstance<py::str>(bounds) || py::len(bounds) != 2)
        throw py::type_error("bounds: expected (lower, upper), got " +
                             py::str(py::type::of(bounds).attr("__name__")).cast<std::string>());
    const py::sequence pair = bounds.cast<py::sequence>();
    // The user's numbers as arrays first (as large as what the user holds), the box's size
    // checked before a number broadcast to dim coordinates is.
    const auto lower = real_array(pair[0], "bounds: lower"), upper = real_array(pair[1], "bounds: upper");
    require(lower.ndim() <= 1, "bounds", "lower must be a number or a 1-D sequence");
    require(upper.ndim() <= 1, "bounds", "upper must be a number or a 1-D sequence");
    if (lower.ndim() == 0) require(dim.has_value(), "dim", "give dim when lower is one number");
    if (upper.ndim() == 0) require(dim.has_value(), "dim", "give dim when upper is one number");
    if (dim) {
        count_in("dim", *dim, 1);
        for (const auto& [side, a] : {std::pair{"lower", &lower}, std::pair{"upper", &upper}})
            require(
                a->ndim() == 0 || a->size() == *dim, "dim",
                "is " + std::to_string(*dim) + " but " + side + " has " + std::to_string(a->size()) + " coordinates");
    }
    const std::int64_t n = dim ? *dim : static_cast<std::int64_t>(lower.size());
    if (check_size && n >= 1) check_size(n);  // an empty box is the engine's to refuse
    const auto coordinates = [n](const py::array_t<double, py::array::c_style | py::array::forcecast>& a) {
        if (a.ndim() == 0) return std::vector<double>(static_cast<std::size_t>(n), *a.data());
        return std::vector<double>(a.data(), a.data() + a.size());
    };
    return {coordinates(lower), coordinates(upper)};
}

engine::CallbackSpec callback_spec(const py::object& fn, bool vectorized, std::vector<double> lower,
                                   std::vector<double> upper, const std::shared_ptr<UserError>& errors,
                                   std::string name) {
    // The function lives as long as the problem; it is released with the GIL held (the problem
    // is destroyed in the binding's own scope, after the run).
    auto function = std::make_shared<py::object>(fn);
    engine::CallbackSpec spec;
    spec.name = std::move(name);
    spec.lower = std::move(lower);
    spec.upper = std::move(upper);
    if (!vectorized) {
        spec.scalar = [function, errors](std::span<const double> x) -> double {
            return python_call(errors, [&] {
                const py::object value = (*function)(point_array(x));
                const double f = PyFloat_AsDouble(value.ptr());
                if (f == -1.0 && PyErr_Occurred()) {
                    PyErr_Clear();
                    throw py::type_error("the function must return one number, got " + type_name(value));
                }
                return f;
            });
        };
    } else {
        spec.batch = [function, errors](MatrixView points, std::span<double> values) {
            python_call(errors, [&] {
                const auto n = static_cast<py::ssize_t>(points.cols());
                const auto f = real_array((*function)(rows_array(points)),
                                          "vectorized: the function must return one value per row of X");
                require(f.size() == n, "vectorized",
                        "the function returned " + std::to_string(f.size()) + " values for " + std::to_string(n) +
                            " points (X has one point per row; expected shape (" + std::to_string(n) + ",))");
                std::memcpy(values.data(), f.data(), sizeof(double) * static_cast<std::size_t>(n));
            });
        };
    }
    return spec;
}

engine::IterationObserver observer(const py::object& fn, const std::shared_ptr<UserError>& errors) {
    auto function = std::make_shared<py::object>(fn);
    return [function, errors](const IterationView& v) -> bool {
        return python_call(errors, [&] {
            // Copies the observer may keep: the run's own memory is reused or freed after the
            // call, and numpy cannot revoke a view of it. Read-only: writing them would not change
            // the run.
            py::array_t<double> population = rows_array(v.population);
            py::array_t<double> fitness(static_cast<py::ssize_t>(v.fitness.size()));
            if (!v.fitness.empty())
                std::memcpy(fitness.mutable_data(), v.fitness.data(), sizeof(double) * v.fitness.size());
            population.attr("flags").attr("writeable") = false;
            fitness.attr("flags").attr("writeable") = false;
            const py::object r = (*function)(v.iteration, v.evaluations, v.best_f, population, fitness);
            return !(r.ptr() == Py_False);
        });
    };
}

engine::Budget budget(std::optional<std::int64_t> evals, std::optional<std::int64_t> iters,
                      std::optional<double> target, std::optional<double> wall_ms) {
    // The command line's rules: one limit of evaluations or of iterations, a target that is a number.
    require(!(evals && iters), "evals", "excludes iters (give one of them)");
    if (evals) count_in("evals", *evals, 1);
    if (iters) count_in("iters", *iters, 0);
    require(!target || !std::isnan(*target), "target", "must be a number, got nan");
    engine::Budget b;
    b.evaluations = evals;
    b.iterations = iters;
    b.target = target;
    b.wall_ms = wall_ms;
    return b;
}

engine::RunResult run_released(const engine::AlgorithmSpec& algorithm, const engine::Problem& problem,
                               const engine::Budget& budget, std::uint64_t seed, const py::object& callback,
                               const std::shared_ptr<UserError>& errors) {
    std::optional<engine::IterationObserver> watch;
    if (!callback.is_none()) {
        if (!PyCallable_Check(callback.ptr())) throw py::type_error("callback: expected a callable");
        watch = observer(callback, errors);
    }
    engine::Budget stoppable = budget;
    stoppable.stop = UserError::flag(errors);
    // Python's functions run on this thread (where Ctrl-C raises in them); a run that calls none
    // runs beside it, which then takes Ctrl-C (Call::run).
    const auto* grid = std::get_if<engine::GridSpec>(&problem.spec());
    const bool calls_python =
        watch || std::holds_alternative<engine::CallbackSpec>(problem.spec()) || (grid && grid->path_objective);
    try {
        return Call::current().run(
            [&] {
                return watch ? engine::run(algorithm, problem, stoppable, seed, *watch)
                             : engine::run(algorithm, problem, stoppable, seed);
            },
            [errors] { errors->stopped.store(true); }, !calls_python, &errors->stopped);
    } catch (...) {
        errors->rethrow_or(std::current_exception());
    }
}

py::array_t<double> point_array(std::span<const double> x) {
    py::array_t<double> a(static_cast<py::ssize_t>(x.size()));
    if (!x.empty()) std::memcpy(a.mutable_data(), x.data(), sizeof(double) * x.size());
    return a;
}

py::array_t<double> rows_array(MatrixView points) {
    // A column of the engine's matrix is a row here: one copy of a contiguous block when the
    // columns are (an Eigen::Ref of a whole matrix), else one per column.
    const auto n = static_cast<py::ssize_t>(points.cols()), dim = static_cast<py::ssize_t>(points.rows());
    py::array_t<double> a({n, dim});
    for (py::ssize_t j = 0; j < n; ++j)
        std::memcpy(a.mutable_data() + j * dim, points.col(j).data(), sizeof(double) * static_cast<std::size_t>(dim));
    return a;
}

py::array_t<double> vector_array(const std::vector<double>& v) {
    py::array_t<double> a(static_cast<py::ssize_t>(v.size()));
    if (!v.empty()) std::memcpy(a.mutable_data(), v.data(), sizeof(double) * v.size());
    return a;
}

py::array_t<int> path_array(const grid::Path& path) {
    py::array_t<int> a({static_cast<py::ssize_t>(path.size()), py::ssize_t{2}});
    auto m = a.mutable_unchecked<2>();
    for (std::size_t i = 0; i < path.size(); ++i) {
        m(static_cast<py::ssize_t>(i), 0) = path[i].x;
        m(static_cast<py::ssize_t>(i), 1) = path[i].y;
    }
    return a;
}

py::dict result_dict(const engine::RunResult& r) {
    py::dict d;
    d["algo"] = r.algorithm;
    d["best_f"] = r.best_f;
    // Nothing finite found: no best point (the command line writes null), best_f stays +inf.
    d["best_x"] = std::isfinite(r.best_f) ? py::object(vector_array(r.best_x)) : py::object(py::none());
    d["evaluations"] = r.evaluations;
    d["iterations"] = r.iterations;
    d["wall_ms"] = r.wall_ms;
    d["history"] = vector_array(r.history);
    py::array_t<std::int64_t> he(static_cast<py::ssize_t>(r.history_evaluations.size()));
    if (!r.history_evaluations.empty())
        std::memcpy(he.mutable_data(), r.history_evaluations.data(),
                    sizeof(std::int64_t) * r.history_evaluations.size());
    d["history_evaluations"] = he;
    if (r.best_violation) {
        // A problem with constraints: best_f is the best feasible value, else the least violating
        // point's (docs/constraints.md).
        d["violation"] = *r.best_violation;
        d["feasible"] = *r.best_violation == 0.0;
        d["first_feasible"] = r.first_feasible ? py::object(py::int_(*r.first_feasible)) : py::object(py::none());
    }
    if (r.grid) {
        const auto& g = *r.grid;
        const auto m = grid::metrics(g.path);
        d["encoding"] = g.encoding;
        d["feasible"] = g.feasible;
        d["path"] = path_array(g.path);
        d["objective_value"] = g.feasible ? py::object(py::float_(g.value)) : py::object(py::none());
        // A polyline planner's path has no cells, and no chain metrics (its path_metrics has them).
        if (g.feasible && g.path.empty() && !g.polyline.empty())
            d["metrics"] = py::none();
        else
            d["metrics"] =
                py::dict(py::arg("cells") = m.cells, py::arg("length") = m.length, py::arg("turns") = m.turns,
                         py::arg("turn_angle_deg") = m.turn_angle_deg, py::arg("angle_penalty") = m.angle_penalty);
        d["optimum"] = g.optimum ? py::object(py::float_(*g.optimum)) : py::object(py::none());
        d["optimal_path"] = g.optimum ? py::object(path_array(g.optimal_path)) : py::object(py::none());
    }
    return d;
}

/// Problem: a registered continuous function to evaluate from Python (another optimiser's
/// objective, say), the same values, bit for bit, as pride's own runs see.
class PyProblem {
  public:
    PyProblem(const std::string& name, std::optional<std::int64_t> dim, std::optional<std::int64_t> instance,
              std::uint64_t seed) {
        const auto* item = continuous::catalog().find(name);
        if (!item) throw InputError("problem", "unknown problem '" + name + "' (see pride.problems())");
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

}  // namespace pride::python

PYBIND11_MODULE(_pride, m) {
    using namespace pride::python;
    m.doc() = "pride's engine (use the pride package, not this module)";
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const pride::InputError& e) {
            PyErr_SetString(PyExc_ValueError, python_message(e).c_str());
        } catch (const Exiting&) {
            PyErr_SetString(PyExc_SystemExit, "pride: the interpreter is exiting; the call was stopped");
        } catch (const Stopped&) {  // a callback's, always replaced by why its run was stopped
            PyErr_SetString(PyExc_RuntimeError, "pride: the run was stopped");
        }
    });
    on_main_thread();  // learns which thread is the main one, while the import holds the GIL
    py::module_::import("atexit").attr("register")(py::cpp_function(&stop_calls_at_exit));
    m.def("algorithms", &algorithms);
    m.def("problems", &problems);
    m.def("grid_names", &grid_names);
    m.def("minimize", &minimize, py::call_guard<Call>(), py::arg("algo"), py::arg("problem"), py::arg("dim"),
          py::arg("bounds"), py::arg("evals"), py::arg("iters"), py::arg("target"), py::arg("wall_ms"), py::arg("seed"),
          py::arg("instance"), py::arg("callback"), py::arg("vectorized"), py::arg("subject_to"),
          py::arg("inequalities"), py::arg("equalities"), py::arg("tolerance"), py::arg("params"));
    py::class_<PyProblem>(m, "Problem")
        .def(py::init<const std::string&, std::optional<std::int64_t>, std::optional<std::int64_t>, std::uint64_t>(),
             py::call_guard<Call>(), py::arg("name"), py::arg("dim"), py::arg("instance"), py::arg("seed"))
        .def("__call__", &PyProblem::call, py::call_guard<Call>(), py::arg("x"))
        .def_property_readonly("name", &PyProblem::name)
        .def_property_readonly("dim", &PyProblem::dim)
        .def_property_readonly("instance", &PyProblem::instance)
        .def_property_readonly("lower", &PyProblem::lower)
        .def_property_readonly("upper", &PyProblem::upper)
        .def_property_readonly("optimum", &PyProblem::optimum);
    py::class_<Optimizer>(m, "Optimizer")
        .def(py::init<const std::string&, const py::object&, std::optional<std::int64_t>, std::optional<std::int64_t>,
                      std::optional<std::int64_t>, std::optional<double>, std::optional<double>, std::uint64_t,
                      std::optional<std::int64_t>, std::optional<std::int64_t>, std::optional<std::int64_t>,
                      std::optional<double>, const py::dict&>(),
             py::call_guard<Call>(), py::arg("algo"), py::arg("bounds"), py::arg("dim"), py::arg("evals"),
             py::arg("iters"), py::arg("target"), py::arg("wall_ms"), py::arg("seed"), py::arg("objectives"),
             py::arg("inequalities"), py::arg("equalities"), py::arg("tolerance"), py::arg("params"))
        .def("ask", &Optimizer::ask, py::call_guard<Call>())
        .def("tell", &Optimizer::tell, py::call_guard<Call>(), py::arg("values"), py::arg("g"))
        .def("done", &Optimizer::done, py::call_guard<Call>())
        .def("result", &Optimizer::result, py::call_guard<Call>())
        .def("dimension", &Optimizer::dimension)
        .def("close", &Optimizer::close, py::call_guard<Call>());
    bind_grid(m);
    bind_roughset(m);
    bind_campaign(m);
    bind_pareto(m);
    bind_score(m);
    bind_front(m);
}

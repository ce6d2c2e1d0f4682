// What common.hpp declares for the module's parts, but the calls in progress (calls.cpp) and a
// multi-objective result (front.cpp): Python arguments checked into engine specs, runs with the GIL
// released, and results as Python values.
#include <fmt/format.h>

#include <cmath>
#include <cstring>

#include "common.hpp"
#include "engine/prepared.hpp"
#include "engine/registry.hpp"

namespace pride::python {

namespace {

// The command line's integer ranges and wording (cli/flags.hpp: max_count, max_seed), so that an
// error reads the same from Python as from `pride`.
constexpr std::int64_t kMaxCount = 1'000'000'000'000'000;

void integer_in(const char* name, std::int64_t value, std::int64_t lo, const std::string& hi_text, bool in_range) {
    require(in_range, name,
            "must be an integer in [" + std::to_string(lo) + ", " + hi_text + "], got " + std::to_string(value));
}

}  // namespace

void count_in(const char* name, std::int64_t value, std::int64_t lo) {
    integer_in(name, value, lo, std::to_string(kMaxCount), value >= lo && value <= kMaxCount);
}

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

std::vector<VariableType> variable_types(const std::optional<std::vector<std::int64_t>>& integers,
                                         const std::optional<std::vector<std::int64_t>>& categorical, std::size_t dim) {
    if (!integers && !categorical) return {};
    std::vector<VariableType> types(dim, VariableType::real);
    const auto mark = [&](const std::optional<std::vector<std::int64_t>>& list, VariableType type, const char* name) {
        if (!list) return;
        for (const std::int64_t i : *list) {
            require(i >= 0 && static_cast<std::size_t>(i) < dim, name,
                    fmt::format("{} is not a coordinate of the box (0 to {})", i, dim - 1));
            const auto u = static_cast<std::size_t>(i);
            require(types[u] != type, name, fmt::format("{} is listed twice", i));
            require(types[u] == VariableType::real, name, fmt::format("{} is also listed in integers", i));
            types[u] = type;
        }
    };
    mark(integers, VariableType::integer, "integers");
    mark(categorical, VariableType::categorical, "categorical");
    return types;
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
    const bool calls_python = watch || std::holds_alternative<engine::CallbackSpec>(problem.spec()) ||
                              (grid && grid->path_objective) || is_python_algorithm(algorithm.name);
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

}  // namespace pride::python

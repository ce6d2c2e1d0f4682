// pride.front and pride.plan_front: multi-objective runs from Python, on a catalog
// problem, a Python function of M objectives, or a grid with several criteria; the result as
// numpy arrays (one row per point), with its quality against the problem's reference front.
#include <fmt/format.h>

#include <cstring>

#include "common.hpp"
#include "engine/multiobjective.hpp"
#include "framework/memory.hpp"
#include "problems/multiobjective/catalog.hpp"

namespace pride::python {
namespace {

py::object quality_dict(const engine::FrontQuality& q) {
    py::dict d;
    d["hypervolume"] = q.hypervolume;
    d["reference_hypervolume"] = q.reference_hypervolume;
    d["hypervolume_ratio"] = q.hypervolume_ratio;
    d["igd_plus"] = q.igd_plus;
    d["ideal"] = vector_array(q.ideal);
    d["nadir"] = vector_array(q.nadir);
    d["reference_point"] = 1.1;
    d["reference_size"] = q.reference_size;
    d["exact_found"] = q.exact_found ? py::object(py::int_(*q.exact_found)) : py::object(py::none());
    return d;
}

py::dict front_dict(const engine::RunResult& r, const std::vector<std::string>& names) {
    py::dict d;
    d["algo"] = r.algorithm;
    d["objectives"] = names;
    d["f"] = rows_array(r.front->f);
    d["x"] = rows_array(r.front->x);
    d["evaluations"] = r.evaluations;
    d["iterations"] = r.iterations;
    d["wall_ms"] = r.wall_ms;
    py::array_t<std::int64_t> he(static_cast<py::ssize_t>(r.history_evaluations.size()));
    if (!r.history_evaluations.empty())
        std::memcpy(he.mutable_data(), r.history_evaluations.data(),
                    sizeof(std::int64_t) * r.history_evaluations.size());
    d["history_evaluations"] = he;
    // Problems with constraints: each point's violation and the first feasible evaluation.
    if (!r.front->violation.empty()) {
        py::array_t<double> v(static_cast<py::ssize_t>(r.front->violation.size()));
        std::memcpy(v.mutable_data(), r.front->violation.data(), sizeof(double) * r.front->violation.size());
        d["violation"] = v;
        d["first_feasible"] = r.first_feasible ? py::object(py::int_(*r.first_feasible)) : py::object(py::none());
    }
    return d;
}

/// A Python function of M objectives: f(x) -> M values, or with `vectorized` f(X) (n, dim) -> (n, M).
engine::CallbackSpec mo_callback(const py::object& fn, bool vectorized, std::vector<double> lower,
                                 std::vector<double> upper, std::int64_t m, const std::shared_ptr<UserError>& errors) {
    auto function = std::make_shared<py::object>(fn);
    engine::CallbackSpec spec;
    spec.name = "function";
    spec.lower = std::move(lower);
    spec.upper = std::move(upper);
    spec.objectives = m;
    const auto count = static_cast<py::ssize_t>(m);
    if (!vectorized) {
        spec.values = [function, errors, count](std::span<const double> x, std::span<double> f) {
            python_call(errors, [&] {
                const auto v = real_array((*function)(point_array(x)), "function: its result (M numbers)");
                require(v.size() == count, "function",
                        "returned " + std::to_string(v.size()) + " values, expected M = " + std::to_string(count));
                std::memcpy(f.data(), v.data(), sizeof(double) * f.size());
            });
        };
    } else {
        spec.values_batch = [function, errors, count](MatrixView points, Matrix& values) {
            python_call(errors, [&] {
                const auto n = static_cast<py::ssize_t>(points.cols());
                const auto v =
                    real_array((*function)(rows_array(points)), "vectorized: the function must return an (n, M) array");
                require(v.ndim() == 2 && v.shape(0) == n && v.shape(1) == count, "vectorized",
                        "the function must return an array of shape (" + std::to_string(n) + ", " +
                            std::to_string(count) + "), one row of M values per row of X");
                // Row j of the (n, M) array is column j of the M x n matrix: the same memory order.
                std::memcpy(values.data(), v.data(), sizeof(double) * static_cast<std::size_t>(n * count));
            });
        };
    }
    return spec;
}

/// Runs with the GIL released, stopped by Ctrl-C and the interpreter's exit, as run_released.
engine::RunResult mo_run_released(const engine::AlgorithmSpec& algorithm, const engine::Problem& problem,
                                  const engine::Budget& budget, std::uint64_t seed, bool calls_python,
                                  const std::shared_ptr<UserError>& errors) {
    engine::Budget stoppable = budget;
    stoppable.stop = UserError::flag(errors);
    try {
        return Call::current().run([&] { return engine::run(algorithm, problem, stoppable, seed); },
                                   [errors] { errors->stopped.store(true); }, !calls_python, &errors->stopped);
    } catch (...) {
        errors->rethrow_or(std::current_exception());
    }
}

py::dict finish(const engine::RunResult& r, const engine::Problem& problem, bool reference, std::uint64_t seed) {
    py::dict d = front_dict(r, problem.objective_names());
    d["problem"] = problem.name();
    d["seed"] = seed;
    if (reference) {
        std::optional<engine::FrontQuality> q;
        {
            py::gil_scoped_release release;  // a grid's exact front can take a while
            q = engine::quality(problem, r.front->f, r.front->violation);
        }
        d["quality"] = quality_dict(*q);
    } else {
        d["quality"] = py::none();
    }
    return d;
}

py::dict front(const std::string& algo, const py::object& problem, std::optional<std::int64_t> dim,
               std::optional<std::int64_t> objectives, const py::object& bounds, std::optional<std::int64_t> evals,
               std::optional<std::int64_t> iters, std::optional<double> wall_ms, std::uint64_t seed, bool vectorized,
               bool reference, const std::optional<std::vector<std::int64_t>>& integers,
               const std::optional<std::vector<std::int64_t>>& categorical, const py::dict& params) {
    auto errors = std::make_shared<UserError>();
    // `pride front --dim`'s range: 0 is no default here (it ran the paper's n).
    require(!dim || (*dim >= 1 && *dim <= engine::max_budget), "dim",
            fmt::format("must be an integer in [1, {}], got {}", engine::max_budget, dim.value_or(0)));
    const engine::AlgorithmSpec algorithm{algo, param_values(algo, params)};
    const engine::Budget b = budget(evals, iters, std::nullopt, wall_ms);
    engine::ProblemSpec spec;
    const bool function = !py::isinstance<py::str>(problem);
    if (!function) {
        require(bounds.is_none(), "bounds",
                "only for Python functions: " + utf8_arg(problem, "problem") + " has its own box");
        require(!vectorized, "vectorized", "only for Python functions");
        require(!integers && !categorical, integers ? "integers" : "categorical",
                "only for Python functions: " + utf8_arg(problem, "problem") + " has real variables");
        const auto name = utf8_arg(problem, "problem");
        require(engine::is_multiobjective_problem(name), "problem",
                "unknown multi-objective problem '" + name + "' (known: " + multiobjective::problem_names() + ")");
        // `pride front --objectives`' words: 0 is no default here (it ran M = 3).
        require(!objectives || *objectives >= 1, "objectives",
                "expected the number of objectives M of " + name + ", got '" + std::to_string(objectives.value_or(0)) +
                    "'");
        spec = engine::ContinuousSpec{name, dim.value_or(0), std::nullopt, objectives.value_or(0)};
    } else {
        if (!PyCallable_Check(problem.ptr()))
            throw py::type_error("problem: expected a multi-objective problem's name (str) or a callable, got " +
                                 type_name(problem));
        require(!bounds.is_none(), "bounds", "a Python function needs bounds=(lower, upper)");
        require(objectives.has_value(), "objectives", "a Python function needs objectives=M, its number of values");
        require(*objectives >= 2 && *objectives <= 10'000, "objectives",
                "must be in [2, 10000], got " + std::to_string(*objectives));
        const auto m = *objectives;
        auto [lower, upper] = parse_bounds(bounds, dim, multiobjective_box_check(m));
        auto types = variable_types(integers, categorical, lower.size());
        auto cb = mo_callback(problem, vectorized, std::move(lower), std::move(upper), m, errors);
        cb.types = std::move(types);
        spec = std::move(cb);
        reference = false;  // a function has no reference front
    }
    std::optional<engine::Problem> prepared;
    prepared.emplace(spec);
    engine::check(algorithm, *prepared, b);
    if (reference) engine::check_quality(*prepared);
    const auto r = mo_run_released(algorithm, *prepared, b, seed, function, errors);
    return finish(r, *prepared, reference, seed);
}

py::dict plan_front(const Grid& g, const py::object& start, const py::object& goal, const std::string& algo,
                    const std::string& objectives, const std::string& encoding, const std::string& init,
                    const std::string& connector, std::int64_t waypoints, bool corner_cutting,
                    std::int64_t clearance_bands, std::int64_t clearance_width, std::optional<std::int64_t> evals,
                    std::optional<std::int64_t> iters, std::optional<double> wall_ms, std::uint64_t seed,
                    bool reference, const py::dict& params) {
    auto errors = std::make_shared<UserError>();
    engine::GridSpec spec;
    spec.map = g.map;
    spec.start = grid_cell(start, "start");
    spec.goal = grid_cell(goal, "goal");
    spec.encoding = encoding;
    spec.init = init;
    spec.connector = connector;
    spec.waypoints = waypoints;
    spec.corner_cutting = corner_cutting;
    spec.objectives = objectives;
    spec.clearance_bands = clearance_bands;
    spec.clearance_width = clearance_width;
    const engine::AlgorithmSpec algorithm{algo, param_values(algo, params)};
    const engine::Budget b = budget(evals, iters, std::nullopt, wall_ms);
    std::optional<engine::Problem> problem;
    {
        py::gil_scoped_release release;  // reachability, the encoding's tables, the clearance
        problem.emplace(spec);
    }
    engine::check(algorithm, *problem, b);
    const auto r = mo_run_released(algorithm, *problem, b, seed, false, errors);
    py::dict d = finish(r, *problem, reference, seed);
    py::list paths;
    for (const auto& p : r.front->paths) paths.append(path_array(p));
    d["paths"] = paths;
    const std::vector<char>& feasible = r.front->feasible;
    py::array_t<bool> legal(static_cast<py::ssize_t>(feasible.size()));
    for (std::size_t j = 0; j < feasible.size(); ++j) legal.mutable_data()[j] = feasible[j] != 0;
    d["legal"] = legal;
    return d;
}

}  // namespace

std::function<void(std::int64_t)> multiobjective_box_check(std::int64_t objectives) {
    return [objectives](std::int64_t d) {
        require(d >= 1 && d <= 100'000'000, "bounds", "the box must have 1 to 100000000 coordinates");
        // The box, and a run's populations of points and values (at least 100 of each).
        require_memory(8.0 * (2.0 * static_cast<double>(d) + 600.0 * static_cast<double>(d + objectives)), "bounds",
                       "a box of " + std::to_string(d) + " coordinates");
    };
}

py::dict front_result_dict(const engine::RunResult& r, std::size_t objectives) {
    std::vector<std::string> names;
    for (std::size_t i = 1; i <= objectives; ++i) names.push_back("f" + std::to_string(i));
    return front_dict(r, names);
}

void bind_front(py::module_& m) {
    m.def("front", &front, py::call_guard<Call>(), py::arg("algo"), py::arg("problem"), py::arg("dim"),
          py::arg("objectives"), py::arg("bounds"), py::arg("evals"), py::arg("iters"), py::arg("wall_ms"),
          py::arg("seed"), py::arg("vectorized"), py::arg("reference"), py::arg("integers"), py::arg("categorical"),
          py::arg("params"));
    m.def("plan_front", &plan_front, py::call_guard<Call>(), py::arg("grid"), py::arg("start"), py::arg("goal"),
          py::arg("algo"), py::arg("objectives"), py::arg("encoding"), py::arg("init"), py::arg("connector"),
          py::arg("waypoints"), py::arg("corner_cutting"), py::arg("clearance_bands"), py::arg("clearance_width"),
          py::arg("evals"), py::arg("iters"), py::arg("wall_ms"), py::arg("seed"), py::arg("reference"),
          py::arg("params"));
}

}  // namespace pride::python

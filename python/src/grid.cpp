// Grids for Python: maps from files or 0/1 arrays, planning with every grid algorithm of the
// registry (engine::run, as `pride path`), and the exact Pareto front (as `pride pareto`).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "common.hpp"
#include "engine/planner_settings.hpp"
#include "problems/grid/grid_problem.hpp"
#include "problems/grid/objectives.hpp"
#include "problems/grid/pareto.hpp"

namespace pride::python {

namespace {

Grid grid_from_array(const py::object& array) {
    const py::array raw = numeric_array(array, "array");  // sizes checked before any copy
    if (raw.ndim() != 2)
        throw InputError("array", "expected a 2-D array of 0 (free) and 1 (blocked), rows top first, got " +
                                      std::to_string(raw.ndim()) + " dimensions");
    const auto height = raw.shape(0), width = raw.shape(1);
    require(width >= 1 && height >= 1, "array", "a map needs at least one row and one column");
    require(width <= 1'000'000 && height <= 1'000'000 && width * height <= 100'000'000, "array",
            fmt::format("a {} x {} map is larger than 10^8 cells", width, height));
    std::vector<std::uint8_t> blocked(static_cast<std::size_t>(width * height));
    // As doubles a block of rows at a time (about 2^20 cells): a map of 10^8 cells is not
    // copied whole into 800 MB of doubles.
    const py::ssize_t rows = std::max<py::ssize_t>(1, (py::ssize_t{1} << 20) / width);
    for (py::ssize_t y0 = 0; y0 < height; y0 += rows) {
        const py::ssize_t y1 = std::min(height, y0 + rows);
        const auto a = real_array(raw[py::slice(y0, y1, 1)], "array");
        const double* v = a.data();
        for (py::ssize_t k = 0; k < (y1 - y0) * width; ++k) {
            const py::ssize_t i = y0 * width + k;
            require(v[k] == 0.0 || v[k] == 1.0, "array",
                    fmt::format("cell ({},{}) is {}; expected 0 (free) or 1 (blocked)", i % width, i / width, v[k]));
            blocked[static_cast<std::size_t>(i)] = v[k] == 1.0;
        }
    }
    return {std::make_shared<const grid::GridMap>(static_cast<int>(width), static_cast<int>(height), std::move(blocked),
                                                  "array")};
}

}  // namespace

grid::Cell grid_cell(const py::handle& o, const std::string& where) {
    if (!py::isinstance<py::sequence>(o) || py::isinstance<py::str>(o) || py::len(o) != 2)
        throw py::type_error(where + ": expected (x, y), got " + type_name(o));
    const py::sequence s = o.cast<py::sequence>();
    auto coordinate = [&](const py::object& c) {
        if (!py::isinstance(c, py::module_::import("numbers").attr("Integral")) || PyBool_Check(c.ptr()))
            throw py::type_error(where + ": expected integer coordinates (x, y), got " + type_name(c));
        const auto v = integer_arg(c, where);
        require(v > -1'000'000'000 && v < 1'000'000'000, where, "coordinate out of range");
        return static_cast<int>(v);
    };
    return {coordinate(s[0]), coordinate(s[1])};
}

namespace {

/// A start or goal given as a cell (`where`) or a world point in metres (`where`_world): exactly
/// one of them; TypeError or ValueError naming the keyword otherwise.
grid::Cell endpoint(const grid::GridMap& map, const py::object& cell, const py::object& world,
                    const std::string& where) {
    const std::string world_name = where + "_world";
    if (cell.is_none() && world.is_none())
        throw py::type_error(where + ": give " + where + "=(x, y) (a cell) or " + world_name + "=(x, y) (metres)");
    if (world.is_none()) return grid_cell(cell, where);
    if (!py::isinstance<py::sequence>(world) || py::isinstance<py::str>(world) || py::len(world) != 2)
        throw py::type_error(world_name + ": expected (x, y) in metres, got " + type_name(world));
    const py::sequence s = world.cast<py::sequence>();
    const double x = number_arg(s[0], world_name), y = number_arg(s[1], world_name);
    if (!cell.is_none()) throw py::type_error(world_name + ": give " + where + " or " + world_name + ", not both");
    require(std::isfinite(x) && std::isfinite(y), world_name, "the point must be finite");
    return engine::world_cell(map, x, y, world_name, where);
}

/// The path's cells as world points (cell centres, rounded to 1e-9 m as `pride path` prints them).
py::array_t<double> world_path_array(const grid::GridMap& map, const grid::Polyline& path) {
    py::array_t<double> a({static_cast<py::ssize_t>(path.size()), py::ssize_t{2}});
    auto v = a.mutable_unchecked<2>();
    for (std::size_t i = 0; i < path.size(); ++i) {
        const grid::WorldPoint p = map.world(path[i].x, path[i].y);
        v(static_cast<py::ssize_t>(i), 0) = grid::printed_world(p.x);
        v(static_cast<py::ssize_t>(i), 1) = grid::printed_world(p.y);
    }
    return a;
}

py::array_t<double> polyline_array(const grid::Polyline& line) {
    py::array_t<double> a({static_cast<py::ssize_t>(line.size()), py::ssize_t{2}});
    auto v = a.mutable_unchecked<2>();
    for (std::size_t i = 0; i < line.size(); ++i) {
        v(static_cast<py::ssize_t>(i), 0) = line[i].x;
        v(static_cast<py::ssize_t>(i), 1) = line[i].y;
    }
    return a;
}

py::object optional_number(const std::optional<double>& v) {
    return v ? py::object(py::float_(*v)) : py::object(py::none());
}

/// The metrics every path gets (problems/grid/polyline.hpp), as pride path --json gives them.
py::dict path_metrics_dict(const grid::PolylineMetrics& m) {
    py::dict d;
    d["length"] = m.length;
    d["turns"] = m.turns;
    d["total_turn_deg"] = m.total_turn_deg;
    d["max_turn_deg"] = m.max_turn_deg;
    d["angle_over_length"] = m.angle_over_length;
    d["max_curvature"] = m.max_curvature;
    d["min_clearance"] = optional_number(m.min_clearance);
    d["mean_clearance"] = optional_number(m.mean_clearance);
    return d;
}

}  // namespace

/// A Python objective on paths: fn(cells), cells an (n, 2) array of int (x, y) that the function
/// may keep (each call gets its own), returning one number; with step_cost(previous, direction)
/// (previous -1 for the first step) its per-step form for the exact optimum. Each call holds the
/// GIL; what it raises is remembered and raised again from plan() or Campaign.run().
std::shared_ptr<const engine::UserPathObjective> user_objective(const py::object& fn, const py::object& step_cost,
                                                                const std::shared_ptr<UserError>& errors,
                                                                const std::string& where) {
    auto value = std::make_shared<py::object>(fn);
    auto user = std::make_shared<engine::UserPathObjective>();
    auto number = [](const py::object& v, const char* what) {
        const double f = PyFloat_AsDouble(v.ptr());
        if (f == -1.0 && PyErr_Occurred()) {
            PyErr_Clear();
            throw py::type_error(std::string(what) + ": the function must return one number, got " +
                                 py::str(py::type::of(v).attr("__name__")).cast<std::string>());
        }
        return f;
    };
    user->value = [value, errors, number](const grid::Path& path) -> double {
        return python_call(errors, [&] { return number((*value)(path_array(path)), "objective"); });
    };
    if (!step_cost.is_none()) {
        if (!PyCallable_Check(step_cost.ptr())) throw py::type_error(where + "step_cost: expected a callable");
        auto step = std::make_shared<py::object>(step_cost);
        user->step_cost = [step, errors, number](int previous, int direction) -> double {
            return python_call(
                errors, [&] { return number((*step)(previous, direction), "step_cost"); }, false);
        };
    }
    return user;
}

void set_path_objective(engine::GridSpec& spec, const py::object& objective, const py::object& step_cost,
                        const std::shared_ptr<UserError>& errors, const std::string& where) {
    if (py::isinstance<py::str>(objective)) {
        spec.objective = utf8_arg(objective, where + "objective");
        if (!step_cost.is_none()) throw py::type_error(where + "step_cost: only with an objective that is a function");
    } else if (PyCallable_Check(objective.ptr())) {
        spec.objective = "user";
        spec.path_objective = user_objective(objective, step_cost, errors, where);
    } else {
        throw py::type_error(where + "objective: expected a name or a function of the path's cells, got " +
                             py::str(py::type::of(objective).attr("__name__")).cast<std::string>());
    }
}

namespace {

py::dict plan(const Grid& g, const py::object& start, const py::object& goal, const py::object& start_world,
              const py::object& goal_world, const std::string& algo, const py::object& objective,
              const py::object& step_cost, const std::string& encoding, const std::string& connector,
              const std::string& init, std::int64_t waypoints, const std::optional<std::vector<double>>& weights,
              std::optional<double> lambda, bool corner_cutting, bool oracle, bool gaps,
              std::optional<std::int64_t> evals, std::optional<std::int64_t> iters, std::uint64_t seed,
              const py::object& callback, const py::dict& params) {
    engine::GridSpec spec;
    auto errors = std::make_shared<UserError>();
    if (objective.is_none()) {
        if (!step_cost.is_none()) throw py::type_error("step_cost: only with an objective that is a function");
        spec.objective = engine::default_grid_objective(algo);
    } else {
        set_path_objective(spec, objective, step_cost, errors, "");
    }
    spec.encoding = encoding;
    spec.connector = connector;
    spec.init = init;
    spec.waypoints = waypoints;
    if (weights) spec.weights = *weights;
    spec.lambda = lambda;
    spec.corner_cutting = corner_cutting;
    spec.oracle = oracle;
    spec.path_gaps = gaps;
    engine::check_grid_names(spec);
    spec.map = g.map;
    spec.start = endpoint(*g.map, start, start_world, "start");
    spec.goal = endpoint(*g.map, goal, goal_world, "goal");
    const engine::AlgorithmSpec algorithm{algo, param_values(algo, params)};
    std::optional<engine::Problem> problem;
    try {
        py::gil_scoped_release release;  // reachability and the encodings' tables
        problem.emplace(spec);
    } catch (const InputError& e) {
        // The goal unreachable from a world point's cell: named by the keyword that gave it.
        throw engine::endpoint_error(e, start_world.is_none() ? "" : "start_world",
                                     goal_world.is_none() ? "" : "goal_world");
    }
    const engine::Budget b = budget(evals, iters, std::nullopt, std::nullopt);
    engine::PlannerSettingNames names;
    names.evaluations = "evals";
    names.iterations = "iters";
    engine::refuse_unused_planner_settings(algorithm, spec, b, names);
    engine::check(algorithm, *problem, b);
    const engine::RunResult r = run_released(algorithm, *problem, b, seed, callback, errors);
    py::dict d = result_dict(r);
    d["objective"] = spec.objective;
    d["seed"] = seed;
    const auto& run = *r.grid;
    d["polyline"] = polyline_array(run.polyline);
    if (run.feasible) {
        py::dict metrics = path_metrics_dict(run.metrics);
        // As pride path --json: the lengths in metres too, on a map with a world frame.
        if (const auto& frame = g.map->frame()) {
            const auto metres = [&](const std::optional<double>& v) {
                return optional_number(v ? std::optional(*v * frame->resolution) : std::nullopt);
            };
            metrics["length_m"] = run.metrics.length * frame->resolution;
            metrics["min_clearance_m"] = metres(run.metrics.min_clearance);
            metrics["mean_clearance_m"] = metres(run.metrics.mean_clearance);
        }
        d["path_metrics"] = metrics;
    } else {
        d["path_metrics"] = py::none();
    }
    if (gaps) {
        d["shortest_grid_length"] = optional_number(run.shortest_grid_length);
        d["shortest_any_angle_length"] = optional_number(run.shortest_any_angle_length);
        d["grid_gap"] = optional_number(run.grid_gap);
        d["any_angle_gap"] = optional_number(run.any_angle_gap);
    }
    if (g.map->frame())
        d["path_world"] = world_path_array(*g.map, run.polyline);
    else
        d["path_world"] = py::none();
    if (run.optimum && run.feasible) {
        // As `pride path`: values that agree to 1e-9 (relative) are the optimum, gap exactly 0.
        const double scale = std::max(1.0, std::abs(*run.optimum));
        d["gap"] = std::abs(run.value - *run.optimum) <= 1e-9 * scale
                       ? 0.0
                       : (run.value - *run.optimum) / std::abs(*run.optimum);
    } else {
        d["gap"] = py::none();
    }
    return d;
}

py::list pareto(const Grid& g, const py::object& start, const py::object& goal, const std::string& objectives,
                bool corner_cutting) {
    const grid::Criteria criteria = grid::parse_criteria(objectives);
    const grid::Cell s = grid_cell(start, "start"), e = grid_cell(goal, "goal");
    // The checks of `pride pareto`: inside, free, the goal reachable, and memory.
    const grid::GridProblem<grid::LengthObjective> checked(g.map, s, e, {}, corner_cutting);
    grid::ParetoOptions options;
    options.corner_cutting = corner_cutting;
    options.max_labels =
        std::min(options.max_labels, grid::label_limit(g.map->size(), engine::available_memory(), g.map->name()));
    std::vector<grid::FrontPoint> front;
    {
        py::gil_scoped_release release;
        front = grid::pareto_front(*g.map, s, e, criteria, options);
    }
    py::list out;
    for (const auto& p : front) {
        py::dict d(py::arg("length") = p.length, py::arg("turns") = p.turns, py::arg("angle_penalty") = p.angle_penalty,
                   py::arg("path") = path_array(p.path));
        if (criteria.clearance) d["clearance"] = p.clearance;  // as pride pareto shows it: when asked for
        out.append(d);
    }
    return out;
}

py::array_t<std::uint8_t> grid_array(const Grid& g) {
    const auto& m = *g.map;
    py::array_t<std::uint8_t> a({static_cast<py::ssize_t>(m.height()), static_cast<py::ssize_t>(m.width())});
    auto v = a.mutable_unchecked<2>();
    for (int y = 0; y < m.height(); ++y)
        for (int x = 0; x < m.width(); ++x) v(y, x) = m.free({x, y}) ? 0 : 1;
    return a;
}

}  // namespace

void bind_grid(py::module_& m) {
    py::class_<Grid>(m, "Grid")
        .def(py::init(&grid_from_array), py::arg("array"))
        .def_static(
            "load",
            [](const py::object& path, const py::object& inflate, const py::object& unknown_free) {
                const std::string file = path_arg(path, "path");
                const std::int64_t r = integer_arg(inflate, "inflate");
                grid::MapReadOptions options;
                options.unknown_free = flag_arg(unknown_free, "unknown_free");
                py::gil_scoped_release release;
                return Grid{engine::load_map(file, r, options)};
            },
            py::call_guard<Call>(), py::arg("path"), py::arg("inflate") = 0, py::arg("unknown_free") = false)
        .def(
            "inflated",
            [](const Grid& g, const py::object& radius) {
                const std::int64_t r = integer_arg(radius, "radius");
                require(r >= 0 && r <= 1000, "radius",
                        "must be in [0, 1000] (cells to inflate obstacles by), got " + std::to_string(r));
                return Grid{std::make_shared<const grid::GridMap>(g.map->inflated(static_cast<int>(r)))};
            },
            py::arg("radius"))
        .def_property_readonly("width", [](const Grid& g) { return g.map->width(); })
        .def_property_readonly("height", [](const Grid& g) { return g.map->height(); })
        .def_property_readonly("name", [](const Grid& g) { return g.map->name(); })
        // The world frame of a ROS map_server map: metres per cell, and the world point of the
        // map's bottom-left corner; None for maps without one.
        .def_property_readonly("resolution",
                               [](const Grid& g) -> py::object {
                                   if (!g.map->frame()) return py::none();
                                   return py::float_(g.map->frame()->resolution);
                               })
        .def_property_readonly("origin",
                               [](const Grid& g) -> py::object {
                                   if (!g.map->frame()) return py::none();
                                   return py::make_tuple(g.map->frame()->origin_x, g.map->frame()->origin_y);
                               })
        .def("to_array", &grid_array)
        .def(
            "free",
            [](const Grid& g, const py::object& x, const py::object& y) {
                const std::int64_t cx = integer_arg(x, "x"), cy = integer_arg(y, "y");
                // Outside the map is not free (and beyond int, outside).
                return cx >= 0 && cy >= 0 && cx < g.map->width() && cy < g.map->height() &&
                       g.map->free({static_cast<int>(cx), static_cast<int>(cy)});
            },
            py::arg("x"), py::arg("y"));
    m.def("plan", &plan, py::call_guard<Call>(), py::arg("grid"), py::arg("start"), py::arg("goal"),
          py::arg("start_world"), py::arg("goal_world"), py::arg("algo"), py::arg("objective"), py::arg("step_cost"),
          py::arg("encoding"), py::arg("connector"), py::arg("init"), py::arg("waypoints"), py::arg("weights"),
          py::arg("lambda_"), py::arg("corner_cutting"), py::arg("oracle"), py::arg("gaps"), py::arg("evals"),
          py::arg("iters"), py::arg("seed"), py::arg("callback"), py::arg("params"));
    m.def("pareto", &pareto, py::call_guard<Call>(), py::arg("grid"), py::arg("start"), py::arg("goal"),
          py::arg("objectives"), py::arg("corner_cutting"));
}

}  // namespace pride::python

#pragma once
// What the parts of the Python module share: Python values into engine specs (parameters, boxes,
// user functions) and engine results into Python values. The module is as thin as the command
// line: every name, parameter and check comes from the engine and its registry.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "engine/run.hpp"
#include "engine/specs.hpp"
#include "framework/error.hpp"
#include "problems/grid/map.hpp"

namespace pride::python {

namespace py = pybind11;

/// pride.Grid: a map, shared with every problem planned on it.
struct Grid {
    std::shared_ptr<const grid::GridMap> map;
};

/// The first exception a user function (or observer) raised in a run. NLopt turns an exception
/// thrown through it into its own error, so the run's caller rethrows this one instead: an
/// exception raised in user code propagates unchanged.
struct UserError {
    std::mutex mutex;
    std::exception_ptr first;
    void remember(std::exception_ptr e) {
        const std::lock_guard lock(mutex);
        if (!first) first = std::move(e);
    }
    [[noreturn]] void rethrow_or(std::exception_ptr e) {
        std::exception_ptr saved;
        {
            const std::lock_guard lock(mutex);
            saved = first;
        }
        std::rethrow_exception(saved ? saved : e);
    }
};

/// Keyword arguments `**params` as the engine's ParamValues: numbers and bools only.
/// The keyword parameters of algorithm `algo`: numbers, or names for its choice parameters.
engine::ParamValues param_values(const std::string& algo, const py::dict& params);

/// A user function as a CallbackSpec on [lower, upper]: called with the GIL held, a copy of each
/// point (scalar: x of shape (dim,); vectorized: X of shape (n, dim), one point per row).
engine::CallbackSpec callback_spec(const py::object& fn, bool vectorized, std::vector<double> lower,
                                   std::vector<double> upper, const std::shared_ptr<UserError>& errors,
                                   std::string name = "bounds");

/// o as a numpy array of real numbers (float, int, bool; any layout, not copied when it is one);
/// None, objects, text and complex numbers are a TypeError "WHAT: expected real numbers, got ...".
py::array numeric_array(const py::object& o, const std::string& what);

/// numeric_array(o) as a C-contiguous array of doubles.
py::array_t<double, py::array::c_style | py::array::forcecast> real_array(const py::object& o, const std::string& what);

/// (lower, upper) from Python: sequences or scalars (broadcast to `dim`).
std::pair<std::vector<double>, std::vector<double>> parse_bounds(const py::object& bounds,
                                                                 std::optional<std::int64_t> dim);

/// An observer from a Python callable fn(iteration, evaluations, best_f, population, fitness):
/// population an (n, dim) and fitness an (n,) read-only view, valid during the call; returning
/// False stops the run.
engine::IterationObserver observer(const py::object& fn, const std::shared_ptr<UserError>& errors);

/// The budget from the keywords evals, iters, target, wall_ms.
engine::Budget budget(std::optional<std::int64_t> evals, std::optional<std::int64_t> iters,
                      std::optional<double> target, std::optional<double> wall_ms);

/// A seed: an integer >= 0 (ValueError "seed: ..." as the command line says it).
std::uint64_t checked_seed(std::int64_t seed);

/// engine::run with the GIL released (taken again by user functions) and user errors rethrown.
engine::RunResult run_released(const engine::AlgorithmSpec& algorithm, const engine::Problem& problem,
                               const engine::Budget& budget, std::uint64_t seed, const py::object& callback,
                               const std::shared_ptr<UserError>& errors);

/// A RunResult as a dict (numpy arrays for points and histories; grid runs add their path).
py::dict result_dict(const engine::RunResult& r);

py::array_t<double> vector_array(const std::vector<double>& v);
py::array_t<int> path_array(const grid::Path& path);

/// A grid problem's objective from Python: a name, or a function of the path's cells (an (n, 2)
/// int array) with an optional step_cost(previous, direction) for the exact optimum. `where`
/// prefixes messages ("problems[2]: "). Errors the functions raise go to `errors`.
void set_path_objective(engine::GridSpec& spec, const py::object& objective, const py::object& step_cost,
                        const std::shared_ptr<UserError>& errors, const std::string& where);

void bind_grid(py::module_& m);
void bind_roughset(py::module_& m);
void bind_campaign(py::module_& m);

}  // namespace pride::python

#pragma once
// What the parts of the Python module share: Python values into engine specs (parameters, boxes,
// user functions) and engine results into Python values. The module is as thin as the command
// line: every name, parameter and check comes from the engine and its registry.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "engine/multiobjective.hpp"
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

/// Thrown by a Python callback of a run stopped from outside (Ctrl-C, the interpreter's exit)
/// instead of calling Python again; the call then raises why it was stopped.
struct Stopped {};

/// A Python algorithm's function failed (algorithm.cpp): pride.AlgorithmError, one line naming
/// the algorithm, the seed and what the function raised.
struct AlgorithmFailure : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// True for an algorithm registered from Python (pride.register_algorithm): its runs call Python.
bool is_python_algorithm(const std::string& name);
/// True while an Optimizer's run has not ended (optimizer.cpp): its thread reads the algorithm
/// registry.
bool optimizers_running();

/// Raised (as SystemExit, which ends a thread silently) by a call that the interpreter's exit
/// stopped, or that a thread other than the main one begins once the exit has begun.
struct Exiting {};

/// The first exception a user function (or observer) raised in a run. NLopt turns an exception
/// thrown through it into its own error, so the run's caller rethrows this one instead: an
/// exception raised in user code propagates unchanged. It also carries the flag that stops the
/// runs of a call from outside.
struct UserError {
    std::mutex mutex;
    std::exception_ptr first;
    // Set to stop the call's runs: they read it once per iteration (Budget::stop), its Python
    // callbacks before each call (they throw Stopped instead of calling).
    std::atomic<bool> stopped{false};

    /// The stop flag as Budget::stop takes it (it keeps this object alive).
    static std::shared_ptr<const std::atomic<bool>> flag(const std::shared_ptr<UserError>& e) {
        return {e, &e->stopped};
    }
    void check_stopped() const {
        if (stopped.load(std::memory_order_relaxed)) throw Stopped{};
    }
    /// Ready for another call (a campaign is run again after an interruption).
    void reset() {
        const std::lock_guard lock(mutex);
        first = nullptr;
        stopped.store(false);
    }
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

/// A call of the module from Python: the guard of every binding (py::call_guard<Call>), made and
/// destroyed with the GIL held. The calls in progress are listed, so that
///  - Ctrl-C on the main thread stops the C++ work of the call it interrupts (run()), and
///  - the interpreter's exit (an atexit hook) stops the calls in progress on other threads and
///    waits until they have returned: a thread that takes the GIL once finalisation has begun is
///    ended by a forced unwinding, which C++ frames (noexcept destructors, catch (...)) turn into
///    std::terminate. A call begun on another thread once the exit has begun raises SystemExit.
class Call {
  public:
    Call();
    ~Call();
    Call(const Call&) = delete;
    Call& operator=(const Call&) = delete;

    /// The innermost call on this thread.
    static Call& current();
    /// True when no other call is in progress, on any thread (nor an outer one on this thread).
    static bool alone();

    /// Runs `work` with the GIL released, stopped from outside by `stop` (called with the GIL
    /// held; it sets flags the work reads). On the main thread with `poll` (work that calls no
    /// Python on this thread; Python runs signal handlers on its main thread only, between
    /// bytecodes), Ctrl-C stops the work and its KeyboardInterrupt is raised once the work has
    /// ended, whatever it returned: with `flag` (what `stop` sets) and Python's default SIGINT
    /// handler, a signal handler in front of Python's sets `flag`; otherwise the work runs on a
    /// helper thread while this one runs Python's handlers every 20 ms, and an exception one
    /// raises calls `stop`. A call the exit stopped raises SystemExit.
    template <class F>
    auto run(F&& work, const std::function<void()>& stop, bool poll, std::atomic<bool>* flag = nullptr)
        -> decltype(work()) {
        std::optional<decltype(work())> out;
        run_work([&] { out.emplace(work()); }, stop, poll, flag);
        return std::move(*out);
    }

  private:
    friend void stop_calls_at_exit();
    void run_work(const std::function<void()>& work, const std::function<void()>& stop, bool poll,
                  std::atomic<bool>* flag);

    std::thread::id thread_;
    Call* outer_;                 // the call this one is made from, on the same thread
    std::function<void()> stop_;  // while run() works
    std::exception_ptr reason_;   // why it was stopped: KeyboardInterrupt, Exiting
};

/// The module's atexit hook (Call).
void stop_calls_at_exit();

/// True on the interpreter's main thread (where signal handlers run).
bool on_main_thread();

/// A call of Python from a run (a user function, an observer): with the GIL, refused once the
/// run is stopped; with `signals`, Ctrl-C reaches the run at this call even when the function runs
/// no bytecode. An exception `body` raises is remembered in `errors` (the run's caller rethrows
/// the first one unchanged) and rethrown, which ends the run.
template <class Body>
auto python_call(const std::shared_ptr<UserError>& errors, Body&& body, bool signals = true) -> decltype(body()) {
    py::gil_scoped_acquire gil;
    errors->check_stopped();
    try {
        if (signals && PyErr_CheckSignals() != 0) throw py::error_already_set();
        return body();
    } catch (...) {
        errors->remember(std::current_exception());
        throw;
    }
}

/// Arguments taken as Python objects and checked here, so that a wrong type is a one-line
/// TypeError naming the argument ("NAME: expected an integer, got str"), never pybind11's
/// multi-line list of signatures nor its "Unable to cast" RuntimeError.
std::string type_name(const py::handle& o);
/// An integer (Python or numpy; bool refused) in the int64 range (else ValueError).
std::int64_t integer_arg(const py::handle& o, const std::string& name);
/// A real number (Python or numpy; bool refused); not checked for being finite.
double number_arg(const py::handle& o, const std::string& name);
/// The UTF-8 bytes of the str `o`, or a one-line ValueError naming `name` when it has none (a lone
/// surrogate: what os.listdir and sys.argv give for a name whose bytes are not UTF-8), never
/// pybind11's "Unable to cast" RuntimeError. Every str of the user's that C++ takes goes through it.
std::string utf8_arg(const py::handle& o, const std::string& name);
/// A str.
std::string text_arg(const py::handle& o, const std::string& name);
/// A file's path: a str or an os.PathLike giving one.
std::string path_arg(const py::handle& o, const std::string& name);
/// True or False (Python or numpy bool).
bool flag_arg(const py::handle& o, const std::string& name);

/// A count the command line bounds as it does (cli/flags.hpp: max_count): an integer in
/// [lo, 10^18], else InputError naming `name` in the command line's wording.
void count_in(const char* name, std::int64_t value, std::int64_t lo);

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

/// (lower, upper) from Python: sequences or scalars (broadcast to `dim`); `check_size` gets the
/// box's dimension before its coordinates are allocated.
std::pair<std::vector<double>, std::vector<double>> parse_bounds(const py::object& bounds,
                                                                 std::optional<std::int64_t> dim,
                                                                 const std::function<void(std::int64_t)>& check_size);

/// The types of a box of `dim` coordinates whose `integers` (indices from 0) are integer, whose
/// `categorical` ones categorical (bounds 0 and k - 1: k choices), the others real; empty when
/// neither is given. ValueError naming the argument for an index outside the box or listed twice.
std::vector<VariableType> variable_types(const std::optional<std::vector<std::int64_t>>& integers,
                                         const std::optional<std::vector<std::int64_t>>& categorical, std::size_t dim);

/// The algorithm without the parameters that choose a constraint handler: what the size checks
/// before building see, since a box not built yet has no constraints to allow them (engine::check
/// sees them all once the problem is built).
engine::AlgorithmSpec without_constraint_params(const engine::AlgorithmSpec& algorithm);

/// A check_size for parse_bounds: engine::check_before_building for `algorithm` under `budget`
/// on a box named `name` (the references must outlive it).
std::function<void(std::int64_t)> box_check(const engine::AlgorithmSpec& algorithm, const std::string& name,
                                            const engine::Budget& budget);

/// A check_size for parse_bounds of a multi-objective box of `objectives` values per point (its
/// checks need M, which a box check of a single-objective algorithm does not know): 1 to 10^8
/// coordinates, and the box with a run's populations (at least 100 points and values) in memory.
std::function<void(std::int64_t)> multiobjective_box_check(std::int64_t objectives);

/// An observer from a Python callable fn(iteration, evaluations, best_f, population, fitness):
/// population an (n, dim) and fitness an (n,) read-only copy, the observer's to keep; returning
/// False stops the run.
engine::IterationObserver observer(const py::object& fn, const std::shared_ptr<UserError>& errors);

/// The budget from the keywords evals, iters, target, wall_ms.
engine::Budget budget(std::optional<std::int64_t> evals, std::optional<std::int64_t> iters,
                      std::optional<double> target, std::optional<double> wall_ms);

/// engine::run with the GIL released (taken again by user functions), stopped by Ctrl-C and the
/// interpreter's exit (Call::run), and user errors rethrown.
engine::RunResult run_released(const engine::AlgorithmSpec& algorithm, const engine::Problem& problem,
                               const engine::Budget& budget, std::uint64_t seed, const py::object& callback,
                               const std::shared_ptr<UserError>& errors);

/// A RunResult as a dict (numpy arrays for points and histories; grid runs add their path).
py::dict result_dict(const engine::RunResult& r);

py::array_t<double> vector_array(const std::vector<double>& v);
/// A copy of a point as an array of shape (dim,).
py::array_t<double> point_array(std::span<const double> x);
/// Copies of points, one per column, as an (n, dim) array, one per row.
py::array_t<double> rows_array(MatrixView points);
/// A multi-objective run's result as a dict (front.cpp): f (n, M), x (n, dim), the counts.
py::dict front_result_dict(const engine::RunResult& r, std::size_t objectives);
py::array_t<int> path_array(const grid::Path& path);

/// A cell (x, y) of integers; `where` names it in messages ("start", "problems[0]: goal").
grid::Cell grid_cell(const py::handle& o, const std::string& where);

/// A grid problem's objective from Python: a name, or a function of the path's cells (an (n, 2)
/// int array) with an optional step_cost(previous, direction) for the exact optimum. `where`
/// prefixes messages ("problems[2]: "). Errors the functions raise go to `errors`.
void set_path_objective(engine::GridSpec& spec, const py::object& objective, const py::object& step_cost,
                        const std::shared_ptr<UserError>& errors, const std::string& where);

// The module's bindings, one function per area (module.cpp calls them in this order).
/// pride.algorithms, pride.problems, pride.grid_names: the registries (listings.cpp).
void bind_listings(py::module_& m);
/// pride.minimize (minimize.cpp).
void bind_minimize(py::module_& m);
/// pride.Problem: a registered function evaluated from Python (problem.cpp).
void bind_problem(py::module_& m);
/// pride.Optimizer: ask and tell (optimizer.cpp).
void bind_optimizer(py::module_& m);
void bind_grid(py::module_& m);
void bind_roughset(py::module_& m);
void bind_campaign(py::module_& m);
/// pride.hypervolume and the other indicators of framework/pareto/ (pareto.cpp).
void bind_pareto(py::module_& m);
/// pride.front and pride.plan_front: multi-objective runs (front.cpp).
void bind_front(py::module_& m);
/// pride.cec2020rw_score: the CEC 2020 real-world competition's ranking (score.cpp).
void bind_score(py::module_& m);
/// pride.register_algorithm: algorithms written in Python (algorithm.cpp).
void bind_algorithm(py::module_& m);

}  // namespace pride::python

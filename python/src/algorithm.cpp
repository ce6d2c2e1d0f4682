// pride.register_algorithm: an algorithm written in Python, registered in the engine's registry
// beside the C++ ones, so that minimize, plan and campaigns run it by name. Its function is called
// once per run as fn(problem, seed): `problem` evaluates batches of points through the run's
// evaluation guard (framework/run_state.hpp), so every evaluation is counted, the budget and the
// stopping rules hold as for a C++ algorithm, and the run's history, targets and traces are the
// engine's. Each call of problem.evaluate is one iteration (the first: iteration 0).
#include <fmt/format.h>

#include <cctype>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "common.hpp"
#include "engine/family.hpp"
#include "engine/registry.hpp"
#include "framework/run_state.hpp"

namespace pride::python {

namespace {

/// Thrown by evaluate() once the run is over: pride.BudgetExhausted in Python, which ends the run
/// as its budget would when it leaves the algorithm's function.
struct RunOver {};

// pride.BudgetExhausted and pride.AlgorithmError, made once at import and kept for the process.
PyObject* run_over_type = nullptr;
PyObject* algorithm_error_type = nullptr;

/// A Python algorithm's function, replaced when its name is registered again. The registry lives
/// as long as the process, past the interpreter: the reference is never released.
struct PythonFunction {
    std::string name;
    PyObject* fn = nullptr;  // a strong reference; read and replaced with the GIL held
};

/// The Python algorithms by name (with the GIL held), never destroyed (PythonFunction).
std::map<std::string, std::shared_ptr<PythonFunction>>& python_algorithms() {
    static auto* registered = new std::map<std::string, std::shared_ptr<PythonFunction>>();
    return *registered;
}

/// A run's evaluation guard as the Python side uses it: one batch of points (columns) per call,
/// closed as an iteration. Virtual once per batch, never per evaluation.
class Evaluator {
  public:
    virtual ~Evaluator() = default;
    /// Evaluates the first min(n, remaining) columns into `values` (+inf for the others) and ends
    /// an iteration; returns how many were evaluated.
    virtual std::int64_t evaluate(const Matrix& points, std::span<double> values) = 0;
    virtual bool done() const = 0;
    virtual std::int64_t evaluations() const = 0;
    virtual std::int64_t iterations() const = 0;
    virtual double best() const = 0;
};

template <class P, class O>
class TypedEvaluator final : public Evaluator {
  public:
    TypedEvaluator(P& problem, BasicRunState<>& state, O& observer)
        : problem_(problem), state_(state), observer_(observer) {}
    std::int64_t evaluate(const Matrix& points, std::span<double> values) override {
        const auto n = state_.evaluate_columns(problem_, points, values);
        state_.end_iteration(observer_, points, values);
        return static_cast<std::int64_t>(n);
    }
    bool done() const override { return state_.done(); }
    std::int64_t evaluations() const override { return state_.progress().evaluations; }
    std::int64_t iterations() const override { return state_.iteration(); }
    double best() const override { return state_.best(); }

  private:
    P& problem_;
    BasicRunState<>& state_;
    O& observer_;
};

/// What the algorithm's function gets as `problem`: the box, the budget, evaluate(X). Usable
/// during the call only: kept past it, it refuses to evaluate.
struct RunProblem {
    std::string algorithm;
    Evaluator* run = nullptr;  // null once the function has returned
    std::vector<double> lower, upper;
    std::optional<std::int64_t> budget;

    Evaluator& open() const {
        if (!run)
            throw py::value_error("problem: the run of algorithm '" + algorithm +
                                  "' is over (its function has returned); evaluate during the call only");
        return *run;
    }

    py::object evaluate(const py::object& x) {
        Evaluator& r = open();
        if (r.done()) throw RunOver{};
        const auto dim = static_cast<py::ssize_t>(lower.size());
        const auto a = real_array(x, "X");
        require(a.ndim() == 1 || a.ndim() == 2, "X",
                fmt::format("expected a point (dim,) or points (n, dim), got {} dimensions", a.ndim()));
        const bool one = a.ndim() == 1;
        const py::ssize_t n = one ? 1 : a.shape(0), columns = one ? a.shape(0) : a.shape(1);
        require(columns == dim, "X", fmt::format("expected points of dimension {}, got {}", dim, columns));
        require(n >= 1, "X", "expected at least one point, got none");
        Matrix points(static_cast<Eigen::Index>(dim), static_cast<Eigen::Index>(n));
        const double* data = a.data();
        for (py::ssize_t j = 0; j < n; ++j)
            for (py::ssize_t i = 0; i < dim; ++i) {
                const double v = data[j * dim + i];
                const auto k = static_cast<std::size_t>(i);
                // The engine's problems are defined on their box (a grid's encodings decode
                // nothing else): a point outside is the algorithm's error, not the problem's.
                if (!(v >= lower[k] && v <= upper[k]))
                    throw InputError(
                        "X", fmt::format("{}coordinate {} is {}, outside the box [{}, {}]",
                                         one ? std::string() : fmt::format("point {}, ", j), i, v, lower[k], upper[k]));
                points(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = v;
            }
        std::vector<double> values(static_cast<std::size_t>(n));
        try {
            // A problem or observer written in Python takes the GIL back for its calls.
            py::gil_scoped_release release;
            r.evaluate(points, values);
        } catch (py::error_already_set& e) {
            // What a problem or observer written in Python raised, kept for the run's caller, which
            // raises it: raised here too (the same exception object), through a fresh capture, as
            // pybind11 restores each capture into Python once.
            PyErr_Restore(e.type().inc_ref().ptr(), e.value().inc_ref().ptr(), e.trace().inc_ref().ptr());
            throw py::error_already_set();
        }
        if (one) return py::float_(values.front());
        return vector_array(values);
    }
};

/// The one-line message of an exception the algorithm's function raised: its type, its text and
/// where it was raised (the innermost frame).
std::string one_line(const py::error_already_set& e) {
    std::string text = py::str(e.value()).cast<std::string>();
    for (char& c : text)
        if (c == '\n' || c == '\r') c = ' ';
    std::string out = py::str(e.type().attr("__name__")).cast<std::string>() + (text.empty() ? "" : ": " + text);
    if (e.trace()) {
        const py::list frames = py::module_::import("traceback").attr("extract_tb")(e.trace());
        if (!frames.empty()) {
            const py::object last = frames[frames.size() - 1];
            out += fmt::format(" ({}, line {})", py::str(last.attr("filename")).cast<std::string>(),
                               last.attr("lineno").cast<long>());
        }
    }
    return out;
}

/// An algorithm that calls a Python function once per run (the typed algorithm of its entry).
struct PythonAlgorithm {
    std::shared_ptr<PythonFunction> function;

    std::string name() const { return function->name; }

    template <BoxProblem P, class O>
    Result run(P problem, const Termination& termination, std::uint64_t seed, O&& observer) const {
        termination.validate(name());
        seed_noise(problem, seed);
        BasicRunState<> state(termination, problem.dimension());
        TypedEvaluator<P, std::remove_reference_t<O>> evaluator(problem, state, observer);
        const auto stopped = [&] { return termination.stop && termination.stop->load(); };
        {
            py::gil_scoped_acquire gil;
            const std::span<const double> lo = problem.lower(), hi = problem.upper();
            auto view = std::make_shared<RunProblem>(
                RunProblem{function->name, &evaluator, std::vector<double>(lo.begin(), lo.end()),
                           std::vector<double>(hi.begin(), hi.end()), termination.max_evaluations});
            // The function may keep `problem`: it is closed (refuses to evaluate) once the call
            // returns, whatever it returns or raises.
            struct Close {
                RunProblem& view;
                ~Close() { view.run = nullptr; }
            } close{*view};
            const py::object handle = py::cast(view);
            const py::object fn = py::reinterpret_borrow<py::object>(function->fn);
            try {
                fn(handle, seed);
            } catch (py::error_already_set& e) {
                // BudgetExhausted: the run is over, as the algorithm was told. KeyboardInterrupt,
                // SystemExit: the caller's, unchanged. A run stopped from outside ends whatever
                // the function raised (its caller says why it stopped).
                const bool over = e.matches(run_over_type) || (e.matches(PyExc_Exception) && stopped());
                if (!over && !e.matches(PyExc_Exception)) throw;
                if (!over)
                    throw AlgorithmFailure(fmt::format("algorithm '{}' (seed {}): {}", name(), seed, one_line(e)));
            }
        }
        if (state.progress().evaluations == 0 && !stopped())
            throw AlgorithmFailure(fmt::format(
                "algorithm '{}' (seed {}): its function returned without evaluating a point (problem.evaluate)", name(),
                seed));
        return state.finish();
    }
};

/// A name a campaign's files and stores take as they are: letters, digits, '-', '_', '.'.
void check_name(const std::string& name) {
    require(!name.empty() && name.size() <= 100, "name",
            "expected 1 to 100 characters, got " + std::to_string(name.size()));
    for (const char c : name)
        require(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.', "name",
                "'" + name + "': expected letters, digits, '-', '_' and '.' only");
}

void register_algorithm(const std::string& name, const py::object& fn, const std::string& summary) {
    check_name(name);
    // The registry grows here, and runs in progress read it: none may be.
    require(Call::alone(), "register_algorithm",
            "not while another call of pride is running (a run, a campaign): register algorithms first");
    require(!optimizers_running(), "register_algorithm",
            "not while an Optimizer's run is going: finish or close it first");
    auto& registered = python_algorithms();
    if (const auto it = registered.find(name); it != registered.end()) {
        // Registered again (a notebook's cell run twice): the new function from now on.
        PyObject* old = it->second->fn;
        it->second->fn = fn.inc_ref().ptr();
        Py_XDECREF(old);
        return;
    }
    require(engine::algorithms().find(name) == nullptr, "name",
            "'" + name + "' is an algorithm of pride's own; choose another name");
    auto function = std::make_shared<PythonFunction>();
    function->name = name;
    function->fn = fn.inc_ref().ptr();
    auto entry = engine::box_algorithm(name, "python", summary, {},
                                       [function](const engine::Params&) { return PythonAlgorithm{function}; });
    engine::algorithms().add(std::move(entry));
    registered.emplace(name, std::move(function));
}

}  // namespace

bool is_python_algorithm(const std::string& name) {
    return python_algorithms().count(name) != 0;
}

void bind_algorithm(py::module_& m) {
    // Kept for the process (never released past the interpreter's end).
    run_over_type = (new py::exception<RunOver>(m, "BudgetExhausted", PyExc_Exception))->ptr();
    algorithm_error_type = (new py::exception<AlgorithmFailure>(m, "AlgorithmError", PyExc_RuntimeError))->ptr();
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const RunOver&) {
            PyErr_SetString(run_over_type, "the run is over: its budget is spent or a stopping rule holds");
        } catch (const AlgorithmFailure& e) {
            PyErr_SetString(algorithm_error_type, e.what());
        }
    });
    py::class_<RunProblem, std::shared_ptr<RunProblem>>(m, "RunProblem")
        .def("evaluate", &RunProblem::evaluate, py::arg("X"))
        .def("__call__", &RunProblem::evaluate, py::arg("X"))
        .def_property_readonly("dim", [](const RunProblem& p) { return p.lower.size(); })
        .def_property_readonly("lower", [](const RunProblem& p) { return vector_array(p.lower); })
        .def_property_readonly("upper", [](const RunProblem& p) { return vector_array(p.upper); })
        .def_property_readonly("budget", [](const RunProblem& p) { return p.budget; })
        .def_property_readonly("evaluations", [](const RunProblem& p) { return p.open().evaluations(); })
        .def_property_readonly("iterations", [](const RunProblem& p) { return p.open().iterations(); })
        .def_property_readonly("best", [](const RunProblem& p) { return p.open().best(); })
        .def_property_readonly("remaining",
                               [](const RunProblem& p) -> std::optional<std::int64_t> {
                                   const std::int64_t used = p.open().evaluations();
                                   if (!p.budget) return std::nullopt;
                                   return *p.budget - used;
                               })
        .def_property_readonly("done", [](const RunProblem& p) { return p.open().done(); });
    m.def("register_algorithm", &register_algorithm, py::call_guard<Call>(), py::arg("name"), py::arg("fn"),
          py::arg("summary"));
}

}  // namespace pride::python

// pride._pride: the engine for Python (docs/python.md). The package's pride/__init__.py wraps
// these functions in the Python-facing API; everything here takes plain values.
//
// One registration function per area, each in its own file and declared in common.hpp: a new
// binding goes into the file of its area, or a new file with its bind_ function called below.
#include <functional>
#include <map>

#include "common.hpp"
#include "framework/error_place.hpp"

namespace pride::python {

namespace {

/// The command line's one-line message (cli/flags.cpp) with the Python keyword where the command
/// line names its flag: "dim: ..." for "--dim: ...", "evals: ..." for "--evals: ...".
std::string python_message(const InputError& e) {
    static const std::map<std::string, std::string, std::less<>> keywords{{"evaluations", "evals"},
                                                                          {"iterations", "iters"}};
    return renamed_message(e, keywords).value_or(e.what());
}

}  // namespace

}  // namespace pride::python

PYBIND11_MODULE(_pride, m) {
    using namespace pride::python;
    m.doc() = "pride's engine (use the pride package, not this module)";
    m.attr("__version__") = PRIDE_VERSION;
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
    bind_listings(m);
    bind_minimize(m);
    bind_problem(m);
    bind_optimizer(m);
    bind_grid(m);
    bind_roughset(m);
    bind_campaign(m);
    bind_pareto(m);
    bind_score(m);
    bind_front(m);
    bind_algorithm(m);
}

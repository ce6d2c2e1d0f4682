// pride.Optimizer: ask and tell, the run driven from Python (engine::AskTell).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>

#include "common.hpp"
#include "engine/ask_tell.hpp"
#include "engine/prepared.hpp"
#include "engine/registry.hpp"

namespace pride::python {

namespace {

class Optimizer;
// The optimizers not closed, with the GIL held: their runs' threads read the algorithm registry
// until the runs end.
std::set<const Optimizer*> open_optimizers;

/// Optimizer: an engine::AskTell, stopped and joined without the GIL.
class Optimizer {
  public:
    Optimizer(const std::string& algo, const py::object& bounds, std::optional<std::int64_t> dim,
              std::optional<std::int64_t> evals, std::optional<std::int64_t> iters, std::optional<double> target,
              std::optional<double> wall_ms, std::uint64_t seed, std::optional<std::int64_t> objectives,
              std::optional<std::int64_t> inequalities, std::optional<std::int64_t> equalities,
              std::optional<double> tolerance, const std::optional<std::vector<std::int64_t>>& integers,
              const std::optional<std::vector<std::int64_t>>& categorical, const py::dict& params) {
        require(!is_python_algorithm(algo), "algo",
                "'" + algo + "' is written in Python and drives its own loop: run it with minimize or a campaign");
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
        auto types = variable_types(integers, categorical, lower.size());
        py::gil_scoped_release release;
        run_ = std::make_unique<engine::AskTell>(std::move(algorithm), std::move(lower), std::move(upper), b, seed, m,
                                                 constraints, std::move(types));
        open_optimizers.insert(this);
    }
    ~Optimizer() { close(); }

    void close() {
        if (!run_) return;
        open_optimizers.erase(this);
        // Joining its thread needs no Python, so the GIL is kept off a thread that could not take
        // it back once the interpreter's exit has begun (a daemon thread dropping an optimizer).
        if (!on_main_thread()) {
            run_.reset();
            return;
        }
        py::gil_scoped_release release;
        run_.reset();
    }

    /// True while its run has not ended (its thread is in the engine).
    bool running() const { return run_ && !run_->done(); }

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

bool optimizers_running() {
    return std::any_of(open_optimizers.begin(), open_optimizers.end(), [](const Optimizer* o) { return o->running(); });
}

void bind_optimizer(py::module_& m) {
    py::class_<Optimizer>(m, "Optimizer")
        .def(py::init<const std::string&, const py::object&, std::optional<std::int64_t>, std::optional<std::int64_t>,
                      std::optional<std::int64_t>, std::optional<double>, std::optional<double>, std::uint64_t,
                      std::optional<std::int64_t>, std::optional<std::int64_t>, std::optional<std::int64_t>,
                      std::optional<double>, const std::optional<std::vector<std::int64_t>>&,
                      const std::optional<std::vector<std::int64_t>>&, const py::dict&>(),
             py::call_guard<Call>(), py::arg("algo"), py::arg("bounds"), py::arg("dim"), py::arg("evals"),
             py::arg("iters"), py::arg("target"), py::arg("wall_ms"), py::arg("seed"), py::arg("objectives"),
             py::arg("inequalities"), py::arg("equalities"), py::arg("tolerance"), py::arg("integers"),
             py::arg("categorical"), py::arg("params"))
        .def("ask", &Optimizer::ask, py::call_guard<Call>())
        .def("tell", &Optimizer::tell, py::call_guard<Call>(), py::arg("values"), py::arg("g"))
        .def("done", &Optimizer::done, py::call_guard<Call>())
        .def("result", &Optimizer::result, py::call_guard<Call>())
        .def("dimension", &Optimizer::dimension)
        .def("close", &Optimizer::close, py::call_guard<Call>());
}

}  // namespace pride::python

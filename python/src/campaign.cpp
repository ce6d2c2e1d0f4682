// Campaigns for Python: built from Python data (problems may be Python functions) or read from a
// TOML file (`pride bench`'s format), run on threads into an SQLite store, and the store and its
// report read back as Python data. MPI stays with the command line.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstring>
#include <set>
#include <type_traits>

#include "common.hpp"
#include "engine/json.hpp"
#include "engine/problem.hpp"
#include "experiment/campaign/prepare.hpp"
#include "experiment/campaign/run.hpp"
#include "experiment/campaign/toml.hpp"
#include "experiment/html/report_page.hpp"
#include "experiment/report/cec2017_import.hpp"
#include "experiment/report/coco_import.hpp"
#include "experiment/report/ioh_import.hpp"
#include "experiment/report/report.hpp"
#include "experiment/storage/reader.hpp"

namespace pride::python {

namespace {

/// A prepared campaign and the first exception its Python functions raised.
struct PyCampaign {
    campaign::Campaign campaign;
    std::shared_ptr<UserError> errors = std::make_shared<UserError>();
    bool python_functions = false;
};

const std::set<std::string> problem_keys{"id",        "problem",        "dim",        "instance",     "grid",
                                         "map",       "inflate",        "start",      "goal",         "objective",
                                         "encoding",  "connector",      "init",       "waypoints",    "weights",
                                         "lambda",    "corner_cutting", "function",   "bounds",       "vectorized",
                                         "step_cost", "f_opt",          "objectives", "unknown_free", "path_gaps"};

/// d[key] checked as a T (None or missing: empty); a wrong type is a TypeError "WHERE: KEY: ...".
template <class T>
std::optional<T> get(const py::dict& d, const char* key, const std::string& where) {
    if (!d.contains(key) || d[key].is_none()) return std::nullopt;
    const py::object v = d[key];
    const std::string name = where + ": " + key;
    if constexpr (std::is_same_v<T, std::string>)
        return text_arg(v, name);
    else if constexpr (std::is_same_v<T, std::int64_t>)
        return integer_arg(v, name);
    else if constexpr (std::is_same_v<T, double>)
        return number_arg(v, name);
    else if constexpr (std::is_same_v<T, bool>)
        return flag_arg(v, name);
    else {
        static_assert(std::is_same_v<T, std::vector<double>>);
        if (!py::isinstance<py::sequence>(v) || py::isinstance<py::str>(v))
            throw py::type_error(name + ": expected a sequence of numbers, got " + type_name(v));
        std::vector<double> out;
        for (const auto& x : v.cast<py::sequence>()) out.push_back(number_arg(x, name));
        return out;
    }
}

campaign::CampaignProblem problem(const py::dict& d, PyCampaign& c, std::size_t index,
                                  const std::vector<campaign::CampaignAlgorithm>& algorithms,
                                  const engine::Budget& budget, std::optional<std::int64_t> evals_per_dim) {
    const std::string where = "problems[" + std::to_string(index) + "]";
    for (const auto& [k, v] : d) {
        if (!py::isinstance<py::str>(k)) throw py::type_error(where + ": keys must be str, got " + type_name(k));
        const std::string key = utf8_arg(k, where + ": a key");
        require(problem_keys.count(key) != 0, where, "unknown key '" + key + "'");
    }
    campaign::CampaignProblem p;
    const auto id = get<std::string>(d, "id", where);
    require(id && !id->empty(), where, "needs an id (a non-empty str)");
    p.id = *id;
    const int kinds =
        int(d.contains("problem")) + int(d.contains("grid") || d.contains("map")) + int(d.contains("function"));
    require(kinds == 1, where, "give exactly one of problem (a registered name), grid (a map) or function");
    require(!d.contains("f_opt") || d.contains("function"), where,
            "f_opt is for a function (registered problems know their own)");
    // A size is checked with every algorithm's run before anything of that size is built.
    const auto check_size = [&](const engine::ProblemSpec& spec, std::int64_t dimension) {
        // A problem with constraints is none of the catalog's: small, its dimension checked as it
        // is built, and each algorithm checked on it by prepare().
        if (const auto* f = std::get_if<engine::ContinuousSpec>(&spec)) {
            const auto& named = engine::constrained_problems();
            if (std::any_of(named.begin(), named.end(), [&](const auto& item) { return item.name == f->function; }))
                return;
        }
        engine::Budget b = budget;
        if (evals_per_dim) {
            if (static_cast<double>(*evals_per_dim) * static_cast<double>(dimension) >
                static_cast<double>(engine::max_budget))
                return;  // prepare() says so
            b.evaluations = *evals_per_dim * dimension;
        }
        for (const auto& a : algorithms) {
            try {
                engine::check_before_building(a.spec, spec, dimension, b);
            } catch (const InputError& e) {
                throw InputError(where, "algorithm '" + a.id + "' on problem '" + p.id + "': " + e.what());
            }
        }
    };
    if (d.contains("problem") && !d["problem"].is_none() && py::isinstance<py::str>(d["problem"]) &&
        engine::is_multiobjective_problem(utf8_arg(d["problem"], where + ": problem"))) {
        // zdt1..dtlz7, wfg1..wfg9: several objectives, `objectives` M for DTLZ and WFG (default: the paper's n and M).
        require(!d.contains("instance"), where, "a multi-objective problem has no instances");
        const auto m = get<std::int64_t>(d, "objectives", where);
        p.objectives = m ? std::to_string(*m) : std::string();
        p.spec = engine::ContinuousSpec{utf8_arg(d["problem"], where + ": problem"),
                                        get<std::int64_t>(d, "dim", where).value_or(0)};
        return p;
    }
    require(!d.contains("objectives") || d.contains("grid") || d.contains("map"), where,
            "objectives: only for multi-objective problems (zdt1-zdt6, dtlz1-dtlz7, wfg1-wfg9) and grids");
    if (d.contains("problem")) {
        const auto dim = get<std::int64_t>(d, "dim", where);
        require(dim.has_value(), where, "problem '" + p.id + "' needs dim");
        const auto name = get<std::string>(d, "problem", where);
        require(name.has_value(), where, "problem: expected a registered problem's name, got None");
        const engine::ContinuousSpec spec{*name, *dim, get<std::int64_t>(d, "instance", where)};
        check_size(spec, *dim);
        p.spec = spec;
    } else if (d.contains("function")) {
        const py::object fn = d["function"];
        if (!PyCallable_Check(fn.ptr()))
            throw py::type_error(where + ": function: expected a callable, got " + type_name(fn));
        require(d.contains("bounds"), where, "a function needs bounds=(lower, upper)");
        engine::CallbackSpec box;
        box.name = p.id;
        auto [lower, upper] =
            parse_bounds(d["bounds"], get<std::int64_t>(d, "dim", where), [&](std::int64_t n) { check_size(box, n); });
        auto spec = callback_spec(fn, get<bool>(d, "vectorized", where).value_or(false), std::move(lower),
                                  std::move(upper), c.errors, p.id);
        if (d.contains("f_opt") && !d["f_opt"].is_none()) {
            const py::object v = d["f_opt"];
            if (PyBool_Check(v.ptr()) || (!py::isinstance<py::float_>(v) && !py::isinstance<py::int_>(v)))
                throw py::type_error(where + ": f_opt must be a number, got " +
                                     py::str(py::type::of(v).attr("__name__")).cast<std::string>());
            spec.f_opt = v.cast<double>();
            require(std::isfinite(*spec.f_opt), where, "f_opt must be a finite number");
        }
        p.spec = std::move(spec);
        c.python_functions = true;
    } else {
        engine::GridSpec g;
        const py::object map = d.contains("grid") ? d["grid"] : d["map"];
        if (py::isinstance<Grid>(map)) {
            // A pride.Grid (its map is shared as it is; inflate it with Grid.inflated).
            require(!d.contains("inflate"), where, "inflate a Grid with grid.inflated(r)");
            require(!d.contains("unknown_free"), where, "load the Grid with pride.Grid.load(path, unknown_free=True)");
            g.map = map.cast<const Grid&>().map;
        } else {
            if (!py::isinstance<py::str>(map) && !py::isinstance(map, py::module_::import("os").attr("PathLike")))
                throw py::type_error(where + ": grid: expected a map file's path or a pride.Grid, got " +
                                     type_name(map));
            p.map_file = path_arg(map, where + ": grid");
            p.inflate = get<std::int64_t>(d, "inflate", where).value_or(0);
            p.unknown_free = get<bool>(d, "unknown_free", where).value_or(false);
        }
        auto cell = [&](const char* key) {
            require(d.contains(key), where, std::string("a grid problem needs ") + key + "=(x, y)");
            return grid_cell(d[key], where + ": " + key);
        };
        g.start = cell("start");
        g.goal = cell("goal");
        if (d.contains("objective") && !d["objective"].is_none()) {
            const py::object step_cost = d.contains("step_cost") ? py::object(d["step_cost"]) : py::object(py::none());
            set_path_objective(g, d["objective"], step_cost, c.errors, where + ": ");
            c.python_functions = c.python_functions || g.objective == "user";
        } else {
            require(!d.contains("step_cost"), where, "step_cost: only with an objective that is a function");
        }
        g.encoding = get<std::string>(d, "encoding", where).value_or(g.encoding);
        g.connector = get<std::string>(d, "connector", where).value_or(g.connector);
        g.init = get<std::string>(d, "init", where).value_or(g.init);
        g.waypoints = get<std::int64_t>(d, "waypoints", where).value_or(g.waypoints);
        g.weights = get<std::vector<double>>(d, "weights", where).value_or(g.weights);
        g.lambda = get<double>(d, "lambda", where);
        g.corner_cutting = get<bool>(d, "corner_cutting", where).value_or(false);
        p.path_gaps = get<bool>(d, "path_gaps", where).value_or(false);
        if (d.contains("objectives") && !d["objectives"].is_none()) {
            // Several criteria: a comma-separated str or a list of names.
            const py::object o = d["objectives"];
            std::string list;
            if (py::isinstance<py::str>(o)) {
                list = utf8_arg(o, where + ": objectives");
            } else if (py::isinstance<py::list>(o) || py::isinstance<py::tuple>(o)) {
                for (const auto& item : o.cast<py::sequence>())
                    list += (list.empty() ? "" : ",") + text_arg(item, where + ": objectives");
            } else {
                throw py::type_error(where + ": objectives: expected names of criteria (a str or a list), got " +
                                     type_name(o));
            }
            require(!d.contains("objective") || d["objective"].is_none(), where,
                    "a grid with objectives (several) takes no objective (one)");
            p.objectives = list;
        }
        p.spec = std::move(g);
    }
    return p;
}

campaign::CampaignAlgorithm algorithm(const py::handle& item, std::size_t index) {
    const std::string where = "algorithms[" + std::to_string(index) + "]";
    campaign::CampaignAlgorithm a;
    if (py::isinstance<py::str>(item)) {
        a.id = a.spec.name = utf8_arg(item, where);
        return a;
    }
    if (!py::isinstance<py::dict>(item))
        throw py::type_error(where + ": expected an algorithm name or a dict, got " + type_name(item));
    py::dict d = item.cast<py::dict>();
    const auto algo = get<std::string>(d, "algo", where);
    require(algo.has_value(), where, "needs algo (a registered algorithm's name)");
    a.spec.name = *algo;
    a.id = get<std::string>(d, "id", where).value_or(*algo);
    require(!a.id.empty(), where, "id must not be empty");
    py::dict params;
    for (const auto& [k, v] : d) {
        if (!py::isinstance<py::str>(k)) throw py::type_error(where + ": keys must be str, got " + type_name(k));
        const auto key = utf8_arg(k, where + ": a key");
        if (key == "id" || key == "algo") continue;
        if (key == "params") {
            if (!py::isinstance<py::dict>(v))
                throw py::type_error(where + ": params: expected a dict, got " + type_name(v));
            for (const auto& [pk, pv] : v.cast<py::dict>()) {
                if (!py::isinstance<py::str>(pk))
                    throw py::type_error(where + ": params: keys must be str, got " + type_name(pk));
                params[pk] = pv;
            }
        } else {
            params[k] = v;
        }
    }
    a.spec.params = param_values(*algo, params);
    return a;
}

std::shared_ptr<PyCampaign> from_data(const std::string& name, std::int64_t seeds, std::optional<std::int64_t> evals,
                                      std::optional<std::int64_t> evals_per_dim, std::optional<std::int64_t> iters,
                                      std::optional<double> target, std::optional<double> precision,
                                      const py::list& problems, const py::list& algorithms) {
    auto c = std::make_shared<PyCampaign>();
    auto& k = c->campaign;
    require(!name.empty(), "name", "a campaign needs a name");
    require(seeds >= 1 && seeds <= campaign::max_campaign_seeds, "seeds", campaign::seeds_range_message(seeds));
    require(!(evals && evals_per_dim), "evals_per_dim", "give evals or evals_per_dim, not both");
    // The budget before the problems, whose sizes are checked with their runs under it.
    const auto count = [](const char* name, std::optional<std::int64_t> v, std::int64_t lo) {
        require(!v || (*v >= lo && *v <= engine::max_budget), name,
                fmt::format("must be an integer in [{}, {}], got {}", lo, engine::max_budget, v.value_or(0)));
    };
    count("evals", evals, 1);
    count("iters", iters, 0);
    require(!evals_per_dim || (*evals_per_dim >= 1 && *evals_per_dim <= engine::max_budget), "evals_per_dim",
            fmt::format("must be in [1, {}], got {}", engine::max_budget, evals_per_dim.value_or(0)));
    require(!(target && precision), "precision", "give target (an absolute value) or precision, not both");
    require(!precision || (std::isfinite(*precision) && *precision > 0), "precision",
            "must be a finite number > 0 (a target f_opt + precision)");
    // As the campaign file's 'target' (campaign_toml.cpp): a report threshold that is a number.
    require(!target || std::isfinite(*target), "target",
            "must be a finite number, got " + fmt::format("{}", target.value_or(0.0)));
    k.name = name;
    k.seeds = seeds;
    k.budget.evaluations = evals;
    k.evaluations_per_dim = evals_per_dim;
    k.budget.iterations = iters;
    k.target = target;
    k.target_precision = precision;
    require(py::len(problems) > 0, "problems", "a campaign needs at least one problem");
    require(py::len(algorithms) > 0, "algorithms", "a campaign needs at least one algorithm");
    // The algorithms first: each function's and problem's size is checked with their runs.
    std::size_t i = 0;
    for (const auto& a : algorithms) k.algorithms.push_back(algorithm(a, i++));
    // Planners alone need none (and refuse one: prepare()).
    require(evals || evals_per_dim || iters || campaign::planners_only(k), "campaign",
            "give evals, evals_per_dim or iters (the budget of every run)");
    i = 0;
    for (const auto& p : problems) {
        if (!py::isinstance<py::dict>(p))
            throw py::type_error("problems[" + std::to_string(i) + "]: expected a dict, got " + type_name(p));
        k.problems.push_back(problem(p.cast<py::dict>(), *c, i++, k.algorithms, k.budget, evals_per_dim));
    }
    k.budget.stop = UserError::flag(c->errors);
    campaign::prepare(k);
    return c;
}

std::shared_ptr<PyCampaign> from_file(const py::object& path) {
    const std::string file = path_arg(path, "path");
    auto c = std::make_shared<PyCampaign>();
    {
        py::gil_scoped_release release;
        c->campaign = campaign::read_campaign(file);
    }
    c->campaign.budget.stop = UserError::flag(c->errors);
    return c;
}

py::dict run(PyCampaign& c, const py::object& store_path, const py::object& jobs_arg, std::int64_t shard_index,
             std::int64_t shard_count) {
    const std::string store = path_arg(store_path, "store");
    const std::int64_t jobs = integer_arg(jobs_arg, "jobs");
    const campaign::Shard shard{shard_index, shard_count};  // checked by run_campaign, as the command line's
    c.errors->reset();
    // Stopping (Ctrl-C, the interpreter's exit) goes through the campaign's own path: the storing
    // thread commits the runs that finished and drops the claims of the running ones; only then
    // are these stopped (Budget::stop, and Python functions not called again), so that a run cut
    // short is never stored.
    std::atomic<int> signal{0};
    const auto errors = c.errors;
    const campaign::Stop stop{&signal, [errors](const campaign::Interrupted&) { errors->stopped.store(true); }};
    campaign::BenchSummary s;
    try {
        // Runs of Python functions take the GIL for each call: threads never run Python at once.
        s = Call::current().run([&] { return campaign::run_campaign(c.campaign, store, jobs, {}, stop, shard); },
                                [&signal] { signal.store(SIGINT); }, true);
    } catch (...) {
        c.errors->rethrow_or(std::current_exception());
    }
    return py::dict(py::arg("stored") = s.stored, py::arg("already") = s.already, py::arg("total") = s.total);
}

py::object optional_number(const std::optional<double>& v) {
    return v ? py::object(py::float_(*v)) : py::object(py::none());
}

py::dict read_store(const py::object& store) {
    const std::string path = path_arg(store, "path");
    storage::CampaignStore s;
    {
        py::gil_scoped_release release;
        s = storage::read_store(path);
    }
    // A COCO trace as an (n, 2) array of rows (evaluations, best so far).
    const auto trace_array = [](const std::vector<TracePoint>& t) {
        py::array_t<double> a({static_cast<py::ssize_t>(t.size()), py::ssize_t{2}});
        auto m = a.mutable_unchecked<2>();
        for (std::size_t i = 0; i < t.size(); ++i) {
            m(static_cast<py::ssize_t>(i), 0) = static_cast<double>(t[i].evaluations);
            m(static_cast<py::ssize_t>(i), 1) = t[i].best;
        }
        return a;
    };
    // A multi-objective run's front: its points' objective values as an (n, M) array (None for
    // other runs and for a front whose entries are not lists of numbers of one length).
    const py::object loads = py::module_::import("json").attr("loads");
    const auto front_array = [&loads](const std::string& text) -> py::object {
        if (text.empty()) return py::none();
        std::vector<std::vector<double>> rows;
        for (const auto& point : loads(text)) {
            if (!py::isinstance<py::dict>(point) || !point.cast<py::dict>().contains("f")) return py::none();
            std::vector<double> f;
            for (const auto& v : point.cast<py::dict>()["f"]) {
                if (PyBool_Check(v.ptr()) || (!py::isinstance<py::float_>(v) && !py::isinstance<py::int_>(v)))
                    return py::none();
                f.push_back(v.cast<double>());
            }
            if (!rows.empty() && f.size() != rows.front().size()) return py::none();
            rows.push_back(std::move(f));
        }
        const auto m = rows.empty() ? py::ssize_t{0} : static_cast<py::ssize_t>(rows.front().size());
        py::array_t<double> a({static_cast<py::ssize_t>(rows.size()), m});
        for (std::size_t i = 0; i < rows.size(); ++i)
            std::copy(rows[i].begin(), rows[i].end(), a.mutable_data() + static_cast<py::ssize_t>(i) * m);
        return a;
    };
    py::list runs;
    const std::vector<double> precisions = s.precisions.value_or(std::vector<double>{});
    for (const auto& r : s.runs) {
        // COCO's target hits: {precision: the evaluations after which best - f_opt <= it first
        // held, None where never}; empty where the run records none.
        py::dict hits;
        for (std::size_t k = 0; k < r.target_hits.size() && k < precisions.size(); ++k)
            hits[py::float_(precisions[k])] =
                r.target_hits[k] ? py::object(py::int_(*r.target_hits[k])) : py::object(py::none());
        py::object metrics = py::none();
        if (!r.path_metrics.empty()) {
            py::dict m;
            for (std::size_t k = 0; k < r.path_metrics.size(); ++k)
                m[storage::kPathMetricNames[k]] = optional_number(r.path_metrics[k]);
            metrics = m;
        }
        py::array_t<std::int64_t> he(static_cast<py::ssize_t>(r.history_evaluations.size()));
        if (!r.history_evaluations.empty())
            std::memcpy(he.mutable_data(), r.history_evaluations.data(),
                        sizeof(std::int64_t) * r.history_evaluations.size());
        runs.append(py::dict(
            py::arg("problem") = r.problem, py::arg("algorithm") = r.algorithm, py::arg("seed") = r.seed,
            py::arg("best") = optional_number(r.best),
            py::arg("best_x") = r.best_x.empty() ? py::object(py::none()) : py::object(vector_array(r.best_x)),
            py::arg("evaluations") = r.evaluations,
            py::arg("iterations") = r.iterations ? py::object(py::int_(*r.iterations)) : py::object(py::none()),
            py::arg("wall_ms") = r.wall_ms, py::arg("optimum") = optional_number(r.optimum),
            py::arg("history") = vector_array(r.history), py::arg("history_evaluations") = he,
            py::arg("encoding") = r.encoding, py::arg("trace_targets") = trace_array(r.trace_targets),
            py::arg("trace_evaluations") = trace_array(r.trace_evaluations),
            py::arg("front") = front_array(r.front_json), py::arg("path_metrics") = metrics,
            py::arg("target_hits") = hits, py::arg("violation") = optional_number(r.best_violation),
            py::arg("first_feasible") =
                r.first_feasible ? py::object(py::int_(*r.first_feasible)) : py::object(py::none())));
    }
    py::list problems;
    if (s.problems)
        for (const auto& p : *s.problems)
            problems.append(py::dict(py::arg("id") = p.id, py::arg("dim") = p.dim, py::arg("function") = p.function,
                                     py::arg("instance") = p.instance, py::arg("f_opt") = optional_number(p.f_opt),
                                     py::arg("suite") = p.suite, py::arg("fid") = p.fid));
    return py::dict(py::arg("name") = s.name, py::arg("target") = optional_number(s.target),
                    py::arg("precisions") = precisions, py::arg("problems") = problems, py::arg("runs") = runs);
}

/// What pride.import_coco, pride.import_cec2017 and pride.import_ioh return: `import`
/// (report::import_coco, import_cec2017 or import_ioh) run without the GIL, and the summary of what it added.
py::dict imported(storage::ImportSummary (*import)(const std::string&, const std::string&,
                                                   const report::PublishedImportOptions&, const std::vector<double>&,
                                                   const std::string&),
                  const std::string& store, const std::string& folder, const report::PublishedImportOptions& options) {
    storage::ImportSummary s;
    {
        py::gil_scoped_release release;
        s = import(store, folder, options, campaign::coco_precisions(),
                   engine::json_array(campaign::coco_precisions()));
    }
    return py::dict(py::arg("algorithm") = std::string(storage::kPublishedPrefix) + options.name,
                    py::arg("runs") = s.runs, py::arg("problems_matched") = s.problems_matched,
                    py::arg("problems_added") = s.problems_added);
}

/// pride.import_coco's work: a COCO data set's folder into a store (experiment/report/coco_import.hpp).
py::dict import_coco(const std::string& store, const std::string& folder, const std::string& name,
                     const std::string& citation, const std::optional<std::string>& source,
                     const std::optional<std::string>& sha256) {
    report::CocoImportOptions options;
    options.name = name;
    options.citation = citation;
    options.source = source;
    options.sha256 = sha256;
    return imported(&report::import_coco, store, folder, options);
}

/// pride.import_cec2017's work: a CEC 2017 entrant's folder into a store (experiment/report/cec2017_import.hpp).
py::dict import_cec2017(const std::string& store, const std::string& folder, const std::string& name,
                        const std::string& citation) {
    report::PublishedImportOptions options;
    options.name = name;
    options.citation = citation;
    return imported(&report::import_cec2017, store, folder, options);
}

/// pride.import_ioh's work: an algorithm's IOHprofiler folder onto a store's problems
/// (experiment/report/ioh_import.hpp).
py::dict import_ioh(const std::string& store, const std::string& folder, const std::string& name,
                    const std::string& citation) {
    report::PublishedImportOptions options;
    options.name = name;
    options.citation = citation;
    return imported(&report::import_ioh, store, folder, options);
}

py::dict report_data(const std::vector<std::string>& paths, bool raw) {
    report::ReportData r;
    {
        py::gil_scoped_release release;
        r = report::load_report(paths, report::ReportOptions{raw});
    }
    py::list rows;
    for (const auto& x : r.rows)
        rows.append(
            py::dict(py::arg("problem") = x.problem, py::arg("algorithm") = x.algorithm, py::arg("runs") = x.runs,
                     py::arg("min") = x.min, py::arg("mean") = x.mean, py::arg("std") = x.std,
                     py::arg("median") = x.median, py::arg("max") = x.max, py::arg("mean_wall_ms") = x.mean_wall_ms,
                     py::arg("mean_evaluations") = x.mean_evaluations, py::arg("optimum") = optional_number(x.optimum),
                     py::arg("mean_gap") = optional_number(x.mean_gap), py::arg("success") = optional_number(x.success),
                     py::arg("is_best") = x.best, py::arg("p_holm") = optional_number(x.p_holm),
                     py::arg("reached_target") = x.reached_target,
                     py::arg("mean_evaluations_to_target") = optional_number(x.mean_evaluations_to_target),
                     py::arg("f_opt") = optional_number(x.f_opt), py::arg("precision") = x.precision,
                     py::arg("a12") = optional_number(x.a12),
                     py::arg("feasible_runs") =
                         x.feasible_runs ? py::object(py::int_(*x.feasible_runs)) : py::object(py::none())));
    py::list feasibility;
    for (const auto& f : r.feasibility)
        feasibility.append(py::dict(py::arg("problem") = f.problem, py::arg("algorithm") = f.algorithm,
                                    py::arg("runs") = f.runs, py::arg("feasible") = f.feasible,
                                    py::arg("median_first_feasible") = optional_number(f.median_first_feasible),
                                    py::arg("median_violation") = optional_number(f.median_violation)));
    py::object friedman = py::none();
    if (r.friedman) {
        py::list pairs;
        for (const auto& q : r.friedman->pairs)
            pairs.append(py::dict(py::arg("a") = r.friedman->algorithms[q.a],
                                  py::arg("b") = r.friedman->algorithms[q.b], py::arg("z") = q.z, py::arg("p") = q.p,
                                  py::arg("p_holm") = q.p_holm));
        const auto& c = r.friedman->critical_difference;
        py::list cliques;
        for (const auto& clique : c.cliques) {
            py::list names;
            for (const std::size_t j : clique) names.append(r.friedman->algorithms[j]);
            cliques.append(names);
        }
        const py::dict cd(py::arg("alpha") = c.alpha, py::arg("cd") = c.cd, py::arg("cliques") = cliques);
        friedman =
            py::dict(py::arg("algorithms") = r.friedman->algorithms, py::arg("problems") = r.friedman->problems,
                     py::arg("average_ranks") = r.friedman->test.average_ranks,
                     py::arg("statistic") = r.friedman->test.statistic, py::arg("p_value") = r.friedman->test.p_value,
                     py::arg("pairs") = pairs, py::arg("critical_difference") = cd);
    }
    return py::dict(py::arg("campaign") = r.campaign, py::arg("target") = optional_number(r.target),
                    py::arg("rows") = rows, py::arg("friedman") = friedman, py::arg("feasibility") = feasibility,
                    py::arg("markdown") = report::render_markdown(r), py::arg("csv") = report::render_csv(r));
}

/// The HTML report of one store (experiment/html/report_page.hpp): DIR/index.html and its figures.
py::dict report_html(const std::string& path, const std::string& dir, bool raw) {
    html::PageSummary page;
    {
        py::gil_scoped_release release;
        page = html::write_report_page(path, dir, report::ReportOptions{raw});
    }
    return py::dict(py::arg("index") = page.index, py::arg("figures") = page.figures);
}

}  // namespace

void bind_campaign(py::module_& m) {
    py::class_<PyCampaign, std::shared_ptr<PyCampaign>>(m, "Campaign")
        .def_property_readonly("name", [](const PyCampaign& c) { return c.campaign.name; })
        .def_property_readonly("seeds", [](const PyCampaign& c) { return c.campaign.seeds; })
        .def_property_readonly(
            "runs",
            [](const PyCampaign& c) {
                return static_cast<std::int64_t>(c.campaign.problems.size() * c.campaign.algorithms.size()) *
                       c.campaign.seeds;
            })
        .def_property_readonly("problems",
                               [](const PyCampaign& c) {
                                   std::vector<std::string> ids;
                                   for (const auto& p : c.campaign.problems) ids.push_back(p.id);
                                   return ids;
                               })
        .def_property_readonly("algorithms", [](const PyCampaign& c) {
            std::vector<std::string> ids;
            for (const auto& a : c.campaign.algorithms) ids.push_back(a.id);
            return ids;
        });
    m.def("campaign_from_data", &from_data, py::call_guard<Call>(), py::arg("name"), py::arg("seeds"), py::arg("evals"),
          py::arg("evals_per_dim"), py::arg("iters"), py::arg("target"), py::arg("precision"), py::arg("problems"),
          py::arg("algorithms"));
    m.def("campaign_from_file", &from_file, py::call_guard<Call>(), py::arg("path"));
    m.def("campaign_run", &run, py::call_guard<Call>(), py::arg("campaign"), py::arg("store"), py::arg("jobs"),
          py::arg("shard_index") = 1, py::arg("shard_count") = 1);
    m.def("read_store", &read_store, py::call_guard<Call>(), py::arg("path"));
    m.def("import_coco", &import_coco, py::call_guard<Call>(), py::arg("store"), py::arg("folder"), py::arg("name"),
          py::arg("citation"), py::arg("source"), py::arg("sha256"));
    m.def("import_cec2017", &import_cec2017, py::call_guard<Call>(), py::arg("store"), py::arg("folder"),
          py::arg("name"), py::arg("citation"));
    m.def("import_ioh", &import_ioh, py::call_guard<Call>(), py::arg("store"), py::arg("folder"), py::arg("name"),
          py::arg("citation"));
    m.def("report", &report_data, py::call_guard<Call>(), py::arg("paths"), py::arg("raw") = false);
    m.def("report_html", &report_html, py::call_guard<Call>(), py::arg("path"), py::arg("dir"), py::arg("raw") = false);
}

}  // namespace pride::python

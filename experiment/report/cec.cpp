#include "experiment/report/cec.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include "experiment/report/cells.hpp"
#include "experiment/report/statistics.hpp"
#include "framework/error.hpp"

namespace pride::report::cec {
namespace {

using cells::csv;
using cells::exact;
using cells::markdown;
using cells::num;
using continuous::cec::checkpoints;

constexpr double inf = std::numeric_limits<double>::infinity();

std::string run_name(const storage::StoredRun& r) {
    return fmt::format("run (problem '{}', algorithm '{}', seed {})", r.problem, r.algorithm, r.seed);
}

/// The best value so far of `run` after `evaluations`: its checkpoint there, or its final best
/// value when it ended before.
double best_after(const storage::StoredRun& run, std::int64_t evaluations, const std::string& store) {
    if (evaluations > run.evaluations) return run.best.value_or(inf);
    const auto it = std::find_if(run.checkpoints.begin(), run.checkpoints.end(),
                                 [&](const TracePoint& t) { return t.evaluations == evaluations; });
    require(it != run.checkpoints.end(), store,
            fmt::format("{} records no best value after {} evaluations (its checkpoints are of another budget); "
                        "run the campaign into a new store",
                        run_name(run), evaluations));
    return it->best;
}

Errors statistics(const std::vector<double>& errors) {
    Errors e;
    e.best = *std::min_element(errors.begin(), errors.end());
    e.worst = *std::max_element(errors.begin(), errors.end());
    e.median = stats::median_of(errors);
    e.mean = stats::mean_of(errors);
    e.std = stats::sample_std(errors);
    return e;
}

}  // namespace

double error_of(double f, double f_opt) {
    const double e = f - f_opt;
    return e < zero_below ? 0.0 : e;
}

Table make_table(const storage::CampaignStore& store, const std::string& name) {
    Table table;
    table.campaign = store.name;
    require(store.problems.has_value(), name,
            "has no problems table (a store from before it): the CEC table needs each problem's f* and dimension");
    std::map<std::string, std::size_t> order;  // the campaign's order of problems
    std::map<std::string, const storage::StoredProblem*> problems;
    for (const storage::StoredProblem& p : *store.problems) {
        order.emplace(p.id, order.size());
        problems[p.id] = &p;
    }
    // Runs by (problem in the campaign's order, algorithm); read_store orders runs by seed within.
    std::map<std::pair<std::size_t, std::string>, std::vector<const storage::StoredRun*>> cells;
    std::set<std::string> left_out;
    for (const storage::StoredRun& r : store.runs) {
        const auto it = problems.find(r.problem);
        if (it == problems.end() || !it->second->f_opt) {
            left_out.insert(r.problem);
            continue;
        }
        cells[{order.at(r.problem), r.algorithm}].push_back(&r);
    }
    require(!cells.empty(), name,
            "holds no run on a problem with a known optimum f*, so it has no CEC errors (report it with --format "
            "md)");
    for (const auto& [key, runs] : cells) {
        const storage::StoredRun& first = *runs.front();
        const storage::StoredProblem& p = *problems.at(first.problem);
        Row row;
        row.problem = p.id;
        row.algorithm = first.algorithm;
        row.function = p.function.value_or(p.id);
        row.suite = p.suite.value_or("");
        row.dim = p.dim;
        row.f_opt = *p.f_opt;
        row.runs = runs.size();
        for (const storage::StoredRun* r : runs) {
            require(r->max_evaluations.has_value(), name,
                    fmt::format("{} records no evaluation budget (MaxFES): it ran under an iteration budget alone, "
                                "or was stored before pride recorded budgets and checkpoints (store schema 4); the "
                                "CEC table needs runs of a campaign with an evaluation budget, stored by this pride",
                                run_name(*r)));
            require(*r->max_evaluations == *first.max_evaluations, name,
                    fmt::format("the runs of problem '{}' and algorithm '{}' had different budgets ({} and {} "
                                "evaluations); the CEC table gives one MaxFES per row",
                                row.problem, row.algorithm, *first.max_evaluations, *r->max_evaluations));
        }
        row.max_evaluations = *first.max_evaluations;
        for (const Checkpoint& c : checkpoints(row.suite, row.max_evaluations, row.dim)) {
            std::vector<double> errors;
            for (const storage::StoredRun* r : runs)
                errors.push_back(error_of(best_after(*r, c.evaluations, name), row.f_opt));
            row.checkpoints.push_back({c, statistics(errors)});
        }
        table.rows.push_back(std::move(row));
    }
    if (!left_out.empty()) {
        std::string list;
        for (const auto& id : left_out) list += (list.empty() ? "" : ", ") + id;
        table.notes.push_back(fmt::format("Left out: {} (no known optimum f*, so no error f - f*).", list));
    }
    return table;
}

std::string render_markdown(const Table& table) {
    std::string text = fmt::format("# CEC errors: {}\n\n", markdown(table.campaign));
    text +=
        "Errors f - f* of the best value so far (below 1e-8 taken as 0) over each problem's runs, as the CEC "
        "reports give them: best, worst, median, mean, std (sample). MaxFES: the runs' evaluation budget.\n\n";
    text += "## At MaxFES\n\n";
    text += "| problem | algorithm | D | MaxFES | runs | best | worst | median | mean | std |\n";
    text += "|---|---|---|---|---|---|---|---|---|---|\n";
    for (const Row& r : table.rows) {
        const Errors& e = r.checkpoints.back().errors;
        text += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", markdown(r.problem),
                            markdown(r.algorithm), r.dim, r.max_evaluations, r.runs, num(e.best), num(e.worst),
                            num(e.median), num(e.mean), num(e.std));
    }
    text += "\n## At the checkpoints\n\n";
    text +=
        "CEC 2017 (Awad et al. 2016, section 2.2): after (0.01, 0.02, 0.03, 0.05, 0.1, 0.2, ..., 0.9, 1.0) x "
        "MaxFES evaluations; CEC 2022 (Kumar et al. 2021, section 2.2): after floor(D^(k/5-3) x MaxFES), "
        "k = 0, ..., 15; problems of other suites as CEC 2017.\n";
    for (const Row& r : table.rows) {
        text += fmt::format("\n### {}, {}\n\n", markdown(r.problem), markdown(r.algorithm));
        text += fmt::format("{}{}, D = {}, f* = {}, MaxFES = {}, {} runs.\n\n", markdown(r.function),
                            r.suite.empty() ? "" : " (" + markdown(r.suite) + ")", r.dim, num(r.f_opt),
                            r.max_evaluations, r.runs);
        text +=
            fmt::format("| {} | FES | best | worst | median | mean | std |\n", r.suite == "cec2022" ? "k" : "x MaxFES");
        text += "|---|---|---|---|---|---|---|\n";
        for (const CheckpointErrors& c : r.checkpoints) {
            const std::string label =
                r.suite == "cec2022" ? c.checkpoint.label.substr(c.checkpoint.label.find('=') + 1) : c.checkpoint.label;
            text += fmt::format("| {} | {} | {} | {} | {} | {} | {} |\n", label, c.checkpoint.evaluations,
                                num(c.errors.best), num(c.errors.worst), num(c.errors.median), num(c.errors.mean),
                                num(c.errors.std));
        }
    }
    for (const auto& note : table.notes) text += "\n" + note + "\n";
    return text;
}

std::string render_csv(const Table& table) {
    std::string text =
        "problem,function,suite,dim,f_opt,algorithm,max_evaluations,runs,checkpoint,evaluations,best,worst,median,"
        "mean,std\n";
    for (const Row& r : table.rows)
        for (const CheckpointErrors& c : r.checkpoints)
            text +=
                fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", csv(r.problem), csv(r.function),
                            csv(r.suite), r.dim, exact(r.f_opt), csv(r.algorithm), r.max_evaluations, r.runs,
                            c.checkpoint.label, c.checkpoint.evaluations, exact(c.errors.best), exact(c.errors.worst),
                            exact(c.errors.median), exact(c.errors.mean), exact(c.errors.std));
    return text;
}

}  // namespace pride::report::cec

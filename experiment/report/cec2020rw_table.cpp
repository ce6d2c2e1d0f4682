#include "experiment/report/cec2020rw_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "experiment/report/cells.hpp"
#include "framework/error.hpp"

namespace pride::report::cec2020rw {
namespace {

using cells::csv;
using cells::exact;
using cells::markdown;
using cells::num;

bool is_cec2020rw(const std::optional<std::string>& function) {
    return function && function->rfind("cec2020rw-rc", 0) == 0;
}

/// A run's final best as the guidelines record it: its best point's f and violation.
Outcome outcome(const storage::StoredRun& r, const std::string& store) {
    const double violation = r.best ? r.best_violation.value_or(0.0) : r.best_violation.value_or(INFINITY);
    const double f = r.best ? *r.best : r.infeasible_f.value_or(NAN);
    require(std::isfinite(violation) && std::isfinite(f), store,
            fmt::format("run (problem '{}', algorithm '{}', seed {}) found no point with a finite f and violation; "
                        "the competition's tables need one",
                        r.problem, r.algorithm, r.seed));
    return {f, violation};
}

}  // namespace

Table make_table(const storage::CampaignStore& store, const std::string& name) {
    Table t;
    t.campaign = store.name;
    std::vector<const storage::StoredProblem*> problems;
    std::size_t others = 0;
    if (store.problems)
        for (const auto& p : *store.problems) {
            if (is_cec2020rw(p.function))
                problems.push_back(&p);
            else
                ++others;
        }
    require(!problems.empty(), name, "has no run on a CEC 2020 real-world problem (cec2020rw-rcNN)");
    if (others) t.notes.push_back(fmt::format("{} problem(s) of other suites left out.", others));
    // Runs by (problem, algorithm), algorithms in the store's order.
    std::map<std::pair<std::string, std::string>, std::vector<Outcome>> runs;
    for (const auto& r : store.runs) {
        if (std::none_of(problems.begin(), problems.end(), [&](const auto* p) { return p->id == r.problem; })) continue;
        if (std::find(t.algorithms.begin(), t.algorithms.end(), r.algorithm) == t.algorithms.end())
            t.algorithms.push_back(r.algorithm);
        runs[{r.problem, r.algorithm}].push_back(outcome(r, name));
    }
    std::vector<std::vector<Summary>> per_algorithm(t.algorithms.size());
    std::vector<std::int64_t> dims;
    for (const auto* p : problems) {
        std::vector<std::size_t> rows;  // this problem's rows, one per algorithm that ran on it
        for (const auto& algorithm : t.algorithms) {
            const auto it = runs.find({p->id, algorithm});
            if (it == runs.end()) continue;
            rows.push_back(t.rows.size());
            t.rows.push_back({p->id, algorithm, *p->function, p->dim, summarise(it->second, p->id + ", " + algorithm)});
        }
        if (rows.size() < t.algorithms.size()) {
            t.notes.push_back(fmt::format("Problem '{}' is not scored: not every algorithm ran on it.", p->id));
            continue;
        }
        t.scored.push_back(p->id);
        dims.push_back(p->dim);
        for (std::size_t a = 0; a < rows.size(); ++a) per_algorithm[a].push_back(t.rows[rows[a]].summary);
    }
    if (!t.scored.empty()) {
        t.scores = score(per_algorithm, dims);
        t.ranks = ranks(t.scores);
    }
    return t;
}

std::string render_markdown(const Table& t) {
    std::string out = fmt::format("# {}: CEC 2020 real-world constrained tables\n\n", markdown(t.campaign));
    out +=
        "Each run's final best point, sorted as the competition's guidelines say (feasible points by f, then "
        "infeasible ones by their violation nu, the mean of the constraints' violations): best, median (the "
        "middle run of that order), mean, worst and standard deviation of f and of nu over the runs; FR, the "
        "share of runs that found a feasible point (Kumar et al. 2020, section 3).\n\n";
    out +=
        "| problem | D | algorithm | runs | best f | best nu | median f | median nu | mean f | mean nu | worst f | "
        "worst nu | std f | std nu | FR "
        "|\n|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const Row& r : t.rows) {
        const Summary& s = r.summary;
        out +=
            fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
                        markdown(r.problem), r.dim, markdown(r.algorithm), s.runs, num(s.best.f), num(s.best.violation),
                        num(s.median.f), num(s.median.violation), num(s.mean.f), num(s.mean.violation), num(s.worst.f),
                        num(s.worst.violation), num(s.std_f), num(s.std_violation), num(s.feasible_rate));
    }
    if (!t.scored.empty()) {
        out += fmt::format(
            "\n## The competition's score\n\nPM = 0.5 best + 0.3 mean + 0.2 median (eq. 4), each a sum over the {} "
            "problem(s) every algorithm ran of the problem's weight (eq. 5, by D) times the algorithm's adjusted value "
            "(f if feasible, else the worst feasible f of the algorithms plus nu) normalised over the algorithms of "
            "this table; lower is better. Scored against other algorithms, the same runs score differently.\n\n",
            t.scored.size());
        out += "| algorithm | best | mean | median | PM | rank |\n|---|---:|---:|---:|---:|---:|\n";
        std::vector<std::size_t> order(t.algorithms.size());
        for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
        std::stable_sort(order.begin(), order.end(), [&](auto a, auto b) { return t.ranks[a] < t.ranks[b]; });
        for (const std::size_t i : order)
            out += fmt::format("| {} | {} | {} | {} | {} | {} |\n", markdown(t.algorithms[i]), num(t.scores[i].best),
                               num(t.scores[i].mean), num(t.scores[i].median), num(t.scores[i].total), t.ranks[i]);
    }
    for (const auto& n : t.notes) out += "\n" + n + "\n";
    return out;
}

std::string render_csv(const Table& t) {
    std::string out =
        "problem,function,dim,algorithm,runs,best_f,best_violation,median_f,median_violation,mean_f,mean_violation,"
        "worst_f,worst_violation,std_f,std_violation,feasible_rate\n";
    for (const Row& r : t.rows) {
        const Summary& s = r.summary;
        out += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", csv(r.problem), csv(r.function), r.dim,
                           csv(r.algorithm), s.runs, exact(s.best.f), exact(s.best.violation), exact(s.median.f),
                           exact(s.median.violation), exact(s.mean.f), exact(s.mean.violation), exact(s.worst.f),
                           exact(s.worst.violation), exact(s.std_f), exact(s.std_violation), exact(s.feasible_rate));
    }
    if (!t.scored.empty()) {
        out += "\nalgorithm,score_best,score_mean,score_median,pm,rank,problems\n";
        for (std::size_t i = 0; i < t.algorithms.size(); ++i)
            out += fmt::format("{},{},{},{},{},{},{}\n", csv(t.algorithms[i]), exact(t.scores[i].best),
                               exact(t.scores[i].mean), exact(t.scores[i].median), exact(t.scores[i].total), t.ranks[i],
                               t.scored.size());
    }
    return out;
}

}  // namespace pride::report::cec2020rw

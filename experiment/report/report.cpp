#include "experiment/report/report.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <tuple>

#include "experiment/report/cells.hpp"
#include "framework/error.hpp"

namespace pride::report {
namespace {

using cells::csv;
using cells::exact;
using cells::markdown;
using cells::num;

constexpr double inf = std::numeric_limits<double>::infinity();

struct Cell {                  // one (problem, algorithm): its runs
    std::vector<double> best;  // +inf for a run without a feasible value
    std::vector<double> wall_ms, evaluations;
    std::optional<double> optimum;
    std::vector<std::optional<double>> to_target;  // evaluations when the best first reached the target
    std::optional<double> f_opt;                   // continuous problems with a known optimum
    // Problems with constraints: each run's best violation (0: feasible), its first feasible
    // evaluation, and its rank among all runs of the problem by Deb's order (1: the best).
    bool constrained = false;
    std::vector<double> violation;
    std::vector<std::optional<std::int64_t>> first_feasible;
    std::vector<double> deb_rank;
};

/// Every run of a constrained problem ranked by Deb's order (Deb 2000): feasible before infeasible,
/// feasible by f, infeasible by violation; ties get their mean rank. The rank tests, A12 and the
/// medians that choose the best then compare runs in that order (they see only ranks).
template <class Cells>
void rank_by_deb_order(Cells& by_algorithm) {
    struct Entry {
        bool infeasible;
        double key;
        double* rank;
    };
    std::vector<Entry> all;
    for (auto& [algorithm, c] : by_algorithm) {
        c.deb_rank.assign(c.best.size(), 0.0);
        for (std::size_t i = 0; i < c.best.size(); ++i) {
            const bool infeasible = c.violation[i] > 0;
            all.push_back({infeasible, infeasible ? c.violation[i] : c.best[i], &c.deb_rank[i]});
        }
    }
    const auto before = [](const Entry& a, const Entry& b) {
        return a.infeasible != b.infeasible ? !a.infeasible : a.key < b.key;
    };
    std::sort(all.begin(), all.end(), before);
    for (std::size_t i = 0; i < all.size();) {
        std::size_t j = i + 1;
        while (j < all.size() && !before(all[i], all[j])) ++j;
        const double rank = 0.5 * static_cast<double>(i + 1 + j);  // the mean of ranks i + 1 ... j
        for (std::size_t k = i; k < j; ++k) *all[k].rank = rank;
        i = j;
    }
}

/// The evaluations at which a run's best value first reached `target` (from its history).
std::optional<double> evaluations_to(double target, const storage::StoredRun& run) {
    for (std::size_t k = 0; k < run.history.size() && k < run.history_evaluations.size(); ++k)
        if (run.history[k] <= target) return static_cast<double>(run.history_evaluations[k]);
    return std::nullopt;
}

using stats::mean_of;
using stats::median_of;

/// For reading an ERT: 3 significant digits.
std::string num3(double v) {
    return std::isfinite(v) ? fmt::format("{:.3g}", v) : "inf";
}

/// Text for a LaTeX table cell: the characters LaTeX treats specially are escaped.
std::string latex(const std::string& s) {
    std::string out;
    for (const char c : s) {
        if (c == '%' || c == '&' || c == '_' || c == '#' || c == '$' || c == '{' || c == '}')
            out += std::string("\\") + c;
        else if (c == '~' || c == '^' || c == '\\')
            out += c == '~' ? "\\textasciitilde{}" : (c == '^' ? "\\textasciicircum{}" : "\\textbackslash{}");
        else
            out += c;
    }
    return out;
}

std::string render_ert(const coco::Analysis& a, bool md);

/// Markdown and LaTeX share their columns; only the cell syntax differs.
std::string render_table(const ReportData& report, bool md) {
    const std::string sep = md ? " | " : " & ", end = md ? " |\n" : " \\\\\n", begin = md ? "| " : "";
    auto line = [&](const std::vector<std::string>& cols) {
        std::string s = begin;
        for (std::size_t i = 0; i < cols.size(); ++i) s += (i ? sep : "") + (md ? markdown(cols[i]) : latex(cols[i]));
        return s + end;
    };
    const bool precisions =
        std::any_of(report.rows.begin(), report.rows.end(), [](const ReportRow& r) { return r.precision; });
    const bool f_opts =
        std::any_of(report.rows.begin(), report.rows.end(), [](const ReportRow& r) { return r.f_opt.has_value(); });
    std::vector<std::string> head{"problem", "algorithm", "runs"};
    if (f_opts) head.push_back("f_opt");
    for (const char* h : {"min", "mean", "std", "median", "max", "mean ms", "gap", "optimal", "p (Holm)", "A12"})
        head.push_back(h);
    const bool has_target = report.target || report.target_precision;
    if (has_target) head.push_back("evals to target");
    std::string text;
    if (md) {
        text += fmt::format(
            "Campaign `{}`. Per problem, `best` marks the algorithm with the lowest median; "
            "p (Holm) is the Wilcoxon rank-sum test of each other algorithm against it, Holm-corrected "
            "over the problem's algorithms, with `*` where p < 0.05, and A12 its effect size (Vargha-Delaney: the "
            "chance that a run of the algorithm ends better than one of the best, ties half; 0.5 is none).",
            report.campaign);
        if (precisions)
            text +=
                " Where f_opt is known, min to max are precisions f - f_opt (`--raw`: the values f), gap is "
                "their mean and optimal the share of runs within 1e-8 of f_opt.";
        else if (f_opts)
            text +=
                " Values are f as run (raw); gap is the mean of f - f_opt and optimal the share of runs within "
                "1e-8 of f_opt.";
        if (report.target_precision) text += fmt::format(" Target: f_opt + {}.", num(*report.target_precision));
        if (!report.feasibility.empty()) text += " " + deb_order_text();
        text += "\n\n";
        text += line(head) + "|";
        for (std::size_t i = 0; i < head.size(); ++i) text += i < 2 ? "---|" : "---:|";
        text += "\n";
    } else {
        text += "\\begin{tabular}{ll" + std::string(head.size() - 2, 'r') + "}\n\\hline\n" + line(head) + "\\hline\n";
    }
    for (const auto& r : report.rows) {
        const std::string p =
            r.best ? "best" : (r.p_holm ? fmt::format("{:.3g}{}", *r.p_holm, *r.p_holm < 0.05 ? "*" : "") : "");
        std::vector<std::string> cols{r.problem, r.algorithm, runs_cell(r)};
        if (f_opts) cols.push_back(r.f_opt ? num(*r.f_opt) : "-");
        const std::string gap = !r.mean_gap ? "-"
                                : r.f_opt   ? num(*r.mean_gap)  // a precision, not a share
                                            : fmt::format("{:.2f} %", 100 * *r.mean_gap);
        const auto value = [&](double v) { return r.feasible_runs == std::size_t{0} ? std::string("-") : num(v); };
        for (const std::string& s : {value(r.min), value(r.mean), value(r.std), value(r.median), value(r.max),
                                     fmt::format("{:.3f}", r.mean_wall_ms), gap,
                                     r.success ? fmt::format("{:.0f} %", 100 * *r.success) : std::string("-"), p,
                                     r.a12 ? fmt::format("{:.2f}", *r.a12) : std::string("-")})
            cols.push_back(s);
        if (has_target)  // mean over the runs that reached it, and how many did
            cols.push_back(r.mean_evaluations_to_target
                               ? fmt::format("{} ({}/{})", num(*r.mean_evaluations_to_target), r.reached_target, r.runs)
                               : fmt::format("- (0/{})", r.runs));
        text += line(cols);
    }
    if (!md) text += "\\hline\n\\end{tabular}\n";
    if (!report.feasibility.empty()) {
        if (md)
            text += "\n" + feasibility_heading() + "\n\n";
        else
            text +=
                "\n% " + deb_order_text() + "\n% " + feasibility_heading() + "\n\\begin{tabular}{llrrrr}\n\\hline\n";
        text += line({"problem", "algorithm", "runs", "feasible", "median first feasible", "median violation"});
        if (md) text += "|---|---|---:|---:|---:|---:|\n";
        if (!md) text += "\\hline\n";
        for (const auto& f : report.feasibility) text += line(feasibility_cells(f));
        if (!md) text += "\\hline\n\\end{tabular}\n";
    }
    for (const auto& note : report.notes) text += (md ? std::string("\n") : std::string("\n% ")) + note + "\n";
    if (md && !report.fronts.empty()) {
        text +=
            "\nProblems of several objectives, per algorithm: the median hypervolume ratio (1 - the gap above), the "
            "median IGD+ (normalised the same way; 0 is the reference front) and, on grids, the median number of the "
            "exact front's points found; p (Holm) is the rank-sum test of each algorithm's IGD+ against the lowest "
            "median's, Holm-corrected over the problem's algorithms.\n\n"
            "| problem | algorithm | runs | HV ratio | IGD+ | exact points | p (Holm) |\n"
            "|---|---|---:|---:|---:|---:|---:|\n";
        for (const auto& r : report.fronts)
            text += fmt::format("| {} | {} | {} | {:.4g} | {:.4g} | {} | {} |\n", markdown(r.problem),
                                markdown(r.algorithm), r.runs, r.hypervolume_ratio, r.igd_plus,
                                r.exact_found ? fmt::format("{:g}", *r.exact_found) : "-",
                                r.best     ? "best"
                                : r.p_holm ? fmt::format("{:.3g}{}", *r.p_holm, *r.p_holm < 0.05 ? "*" : "")
                                           : "");
    }
    if (md && !report.paths.empty()) {
        text +=
            "\nPaths on grids, per algorithm, scored alike whoever planned them (docs/grid.md, \"Polylines and their "
            "metrics\"): the runs that found a path, then medians over them of the length, turns, total turn "
            "(degrees), angle over length (rad per cell), maximum curvature (1/cell), minimum and mean clearance "
            "(cells) and, with the problem's `path_gaps`, the gaps to the shortest grid and any-angle lengths; the "
            "median planning time over all runs.\n\n"
            "| problem | algorithm | found | length | turns | turn deg | AOL | max curv. | min clear. | mean clear. | "
            "grid gap | any-angle gap | median ms |\n"
            "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
        for (const auto& r : report.paths) {
            text += fmt::format("| {} | {} | {}/{} |", markdown(r.problem), markdown(r.algorithm), r.found, r.runs);
            for (const auto& m : r.medians) text += m ? fmt::format(" {:.4g} |", *m) : std::string(" - |");
            text += fmt::format(" {:.3f} |\n", r.median_wall_ms);
        }
    }
    if (const auto& f = report.friedman) {
        text += md ? "\nFriedman average ranks over " : "\n% Friedman average ranks over ";
        text += fmt::format("{} problems (1 = best; median values):", f->problems);
        for (std::size_t j = 0; j < f->algorithms.size(); ++j)
            text += fmt::format(" {} {:.3g}{}", f->algorithms[j], f->test.average_ranks[j],
                                j + 1 < f->algorithms.size() ? "," : "");
        text += fmt::format("; chi-squared {:.4g}, p = {:.3g}\n", f->test.statistic, f->test.p_value);
        text += md ? "\nPairs (z-test on the average ranks, Holm over "
                   : "% Pairs (z-test on the average ranks, Holm over ";
        text += fmt::format("{} pairs; Demsar 2006):", f->pairs.size());
        for (std::size_t i = 0; i < f->pairs.size(); ++i) {
            const auto& q = f->pairs[i];
            text += fmt::format(" {} vs {} p = {:.3g}{}{}", f->algorithms[q.a], f->algorithms[q.b], q.p_holm,
                                q.p_holm < 0.05 ? "*" : "", i + 1 < f->pairs.size() ? ";" : "");
        }
        text += "\n";
        const auto& cd = f->critical_difference;
        text += md ? "\nNemenyi critical difference (alpha " : "% Nemenyi critical difference (alpha ";
        text += fmt::format("{:g}; Demsar 2006): CD = {:.3g}; not significantly different:", cd.alpha, cd.cd);
        for (std::size_t i = 0; i < cd.cliques.size(); ++i) {
            std::vector<std::string> names;
            for (const std::size_t j : cd.cliques[i]) names.push_back(f->algorithms[j]);
            text += fmt::format(" {{{}}}{}", fmt::join(names, ", "), i + 1 < cd.cliques.size() ? "," : "");
        }
        if (cd.cliques.empty()) text += " none";
        text += "\n";
    }
    if (report.coco) text += render_ert(*report.coco, md);
    return text;
}

}  // namespace

std::vector<std::size_t> shown_precisions(const std::vector<double>& precisions) {
    std::vector<std::size_t> shown;
    for (const double want : {1e1, 1e-1, 1e-3, 1e-5, 1e-7, 1e-8})
        for (std::size_t k = 0; k < precisions.size(); ++k)
            if (std::abs(precisions[k] - want) <= 1e-9 * want) {
                shown.push_back(k);
                break;
            }
    if (shown.empty())
        for (std::size_t k = 0; k < precisions.size(); ++k) shown.push_back(k);
    return shown;
}

std::string precision_label(double p) {
    if (p > 0) {
        const double k = std::round(std::log10(p));
        if (std::abs(p - std::pow(10.0, k)) <= 1e-9 * p) return fmt::format("1e{}", static_cast<int>(k));
    }
    return fmt::format("{:.6g}", p);
}

std::string feasibility_heading() {
    return "Feasibility, per problem with constraints and algorithm: the runs whose best point is feasible (and "
           "their share), the median evaluation at which the runs that found a feasible point first found one, and "
           "the median violation of the runs that found none (-: no such run).";
}

std::string deb_order_text() {
    return "On problems with constraints, runs are compared by Deb's order (Deb 2000), as the CEC 2020 real-world "
           "competition ranks them: feasible before infeasible, feasible runs by f, infeasible ones by their "
           "violation; best, p (Holm), A12 and Friedman's ranks use that order, while runs counts all runs with the "
           "feasible ones in brackets and min to max, mean, std and gap are over the feasible runs only (`-`: none).";
}

std::string runs_cell(const ReportRow& r) {
    return r.feasible_runs ? fmt::format("{} ({} feasible)", r.runs, *r.feasible_runs) : std::to_string(r.runs);
}

std::vector<std::string> feasibility_cells(const FeasibilityRow& f) {
    return {f.problem,
            f.algorithm,
            std::to_string(f.runs),
            fmt::format("{} ({:.0f} %)", f.feasible,
                        f.runs ? 100.0 * static_cast<double>(f.feasible) / static_cast<double>(f.runs) : 0.0),
            f.median_first_feasible ? num(*f.median_first_feasible) : std::string("-"),
            f.median_violation ? num(*f.median_violation) : std::string("-")};
}

namespace {

/// The ERT tables, one per function and dimension: rows the algorithms, columns the shown
/// precisions and #succ (the runs that reached the campaign's smallest precision, of all).
std::string render_ert(const coco::Analysis& a, bool md) {
    const auto shown = shown_precisions(a.precisions);
    const std::string sep = md ? " | " : " & ", end = md ? " |\n" : " \\\\\n", begin = md ? "| " : "";
    auto line = [&](const std::vector<std::string>& cols) {
        std::string s = begin;
        for (std::size_t i = 0; i < cols.size(); ++i) s += (i ? sep : "") + (md ? markdown(cols[i]) : latex(cols[i]));
        return s + end;
    };
    std::vector<std::string> head{"algorithm"};
    for (const std::size_t k : shown) head.push_back("ERT " + precision_label(a.precisions[k]));
    head.push_back("#succ");
    std::string text = md ? "\n## Expected running time (ERT)\n\n"
                            "ERT: the evaluations of all runs (up to the target where reached) over the runs that "
                            "reached f_opt + precision, over the instances of each function; inf where none did; "
                            "in brackets the 10th and 90th percentiles of the ERT over 1000 bootstrap resamples of "
                            "the runs (cocopp's bootstrap of the ERT; Hansen et al. 2022). "
                            "#succ: the runs that reached the smallest precision"
                          : "\n% Expected running time (ERT) per function and dimension, [10th, 90th percentiles "
                            "over 1000 bootstrap resamples]; #succ: the runs that reached the smallest precision";
    // The smallest precision, wherever the campaign lists it (analyse() returns none without any).
    const std::size_t smallest =
        static_cast<std::size_t>(std::min_element(a.precisions.begin(), a.precisions.end()) - a.precisions.begin());
    text += fmt::format(" ({}).\n", precision_label(a.precisions[smallest]));
    if (a.runs_without_hits)
        text += fmt::format("{}{} runs record no target hits and are left out.\n", md ? "" : "% ", a.runs_without_hits);
    for (std::size_t i = 0; i < a.erts.size();) {
        const std::string& function = a.erts[i].function;
        const std::int64_t dim = a.erts[i].dim;
        const std::string title = fmt::format("{}, {}-D ({} instance{})", function, dim, a.erts[i].instances,
                                              a.erts[i].instances == 1 ? "" : "s");
        if (md) {
            text += "\n### " + markdown(title) + "\n\n" + line(head) + "|---|";
            for (std::size_t c = 1; c < head.size(); ++c) text += "---:|";
            text += "\n";
        } else {
            text += "\n% " + title + "\n\\begin{tabular}{l" + std::string(head.size() - 1, 'r') + "}\n\\hline\n" +
                    line(head) + "\\hline\n";
        }
        for (; i < a.erts.size() && a.erts[i].function == function && a.erts[i].dim == dim; ++i) {
            const coco::ErtRow& r = a.erts[i];
            std::vector<std::string> cols{r.algorithm};
            for (const std::size_t k : shown) {
                const auto& b = r.ert_interval[k];
                cols.push_back(std::isfinite(r.ert[k].value)
                                   ? fmt::format("{} [{}, {}]", num3(r.ert[k].value), num3(b.p10), num3(b.p90))
                                   : num3(r.ert[k].value));
            }
            cols.push_back(fmt::format("{}/{}", r.ert[smallest].successes, r.runs));
            text += line(cols);
        }
        if (!md) text += "\\hline\n\\end{tabular}\n";
    }
    return text;
}

}  // namespace

/// Comparisons are made at equal evaluations: the notes of one problem when its compared
/// algorithms' mean evaluation counts lie more than 5 % apart, and the whole-map planners exempt.
template <class Cells>
void equal_evaluations_note(ReportData& report, const storage::CampaignStore& store, const std::string& problem,
                            const Cells& by_algorithm) {
    std::vector<std::string> exempt;
    std::vector<std::pair<std::string, double>> counted;
    for (const auto& [algorithm, c] : by_algorithm) {
        if (store.whole_map_algorithms.count(algorithm))
            exempt.push_back(algorithm);
        else
            counted.emplace_back(algorithm, mean_of(c.evaluations));
    }
    if (counted.size() >= 2) {
        double lo = inf, hi = 0;
        for (const auto& [a, e] : counted) lo = std::min(lo, e), hi = std::max(hi, e);
        if (hi > 1.05 * lo) {
            std::string list;
            for (const auto& [a, e] : counted) list += (list.empty() ? "" : ", ") + fmt::format("{} {:.0f}", a, e);
            report.notes.push_back(fmt::format(
                "Warning: on {} the algorithms compared used different numbers of evaluations (mean: {}; more than "
                "5 % apart), so their values are not compared at equal evaluations; give the campaign an evaluation "
                "budget ([budget] evaluations).",
                problem, list));
        }
    }
    if (!exempt.empty()) {
        std::string list;
        for (const auto& a : exempt) list += (list.empty() ? "" : ", ") + a;
        report.notes.push_back(fmt::format(
            "On {}, {} {} on the whole map and {} no objective (the evaluations of such a planner count "
            "its own work): exempt from the equal-evaluation comparison.",
            problem, list, exempt.size() == 1 ? "plans" : "plan", exempt.size() == 1 ? "evaluates" : "evaluate"));
    }
}

ReportData make_report(const storage::CampaignStore& store, const ReportOptions& options) {
    ReportData report;
    report.campaign = store.name;
    report.target = store.target;
    report.target_precision = store.target_precision;
    report.raw = options.raw;
    report.coco = coco::analyse(store);
    std::map<std::string, std::optional<double>> f_opt;  // continuous problems with a known optimum
    if (store.problems)
        for (const storage::StoredProblem& p : *store.problems)
            if (p.f_opt && std::isfinite(*p.f_opt)) f_opt[p.id] = p.f_opt;
    const bool has_target = store.target || store.target_precision;
    std::map<std::string, std::map<std::string, Cell>> cells;
    for (const storage::StoredRun& run : store.runs) {
        Cell& c = cells[run.problem][run.algorithm];
        const auto optimum = f_opt.count(run.problem) ? f_opt.at(run.problem) : std::nullopt;
        // f - f_opt: exact for the values near f_opt that precisions are about (Sterbenz).
        const double f = run.best.value_or(inf);
        c.best.push_back(optimum && !options.raw ? f - *optimum : f);
        c.wall_ms.push_back(run.wall_ms);
        c.evaluations.push_back(static_cast<double>(run.evaluations));
        if (run.optimum) c.optimum = run.optimum;
        if (optimum) c.f_opt = optimum;
        if (run.best_violation) c.constrained = true;
        c.violation.push_back(run.best_violation.value_or(0.0));
        c.first_feasible.push_back(run.first_feasible);
        // The threshold on the runs' own values (their histories are of f).
        if (store.target)
            c.to_target.push_back(evaluations_to(*store.target, run));
        else if (store.target_precision)
            c.to_target.push_back(optimum ? evaluations_to(*optimum + *store.target_precision, run) : std::nullopt);
    }

    auto& rows = report.rows;
    // What runs are compared by: their values, or with constraints their ranks by Deb's order.
    const auto compared = [](const Cell& c) -> const std::vector<double>& {
        return c.constrained ? c.deb_rank : c.best;
    };
    for (auto& [problem, by_algorithm] : cells) {
        const bool constrained =
            std::any_of(by_algorithm.begin(), by_algorithm.end(), [](const auto& a) { return a.second.constrained; });
        if (constrained) {
            for (auto& [algorithm, c] : by_algorithm) c.constrained = true;
            rank_by_deb_order(by_algorithm);
            for (const auto& [algorithm, c] : by_algorithm) {
                FeasibilityRow f;
                f.problem = problem;
                f.algorithm = algorithm;
                f.runs = c.best.size();
                std::vector<double> first, violation;
                for (std::size_t i = 0; i < c.best.size(); ++i) {
                    if (c.violation[i] == 0) ++f.feasible;
                    if (c.violation[i] > 0) violation.push_back(c.violation[i]);
                    if (c.first_feasible[i]) first.push_back(static_cast<double>(*c.first_feasible[i]));
                }
                if (!first.empty()) f.median_first_feasible = median_of(first);
                if (!violation.empty()) f.median_violation = median_of(violation);
                report.feasibility.push_back(f);
            }
        }
    }
    for (const auto& [problem, by_algorithm] : cells) {
        // The best algorithm of the problem: the lowest median best value (ties: lowest mean); with
        // constraints, the lowest median rank by Deb's order.
        std::string best;
        double best_median = 0, best_mean = 0;
        for (const auto& [algorithm, c] : by_algorithm) {
            const double md = median_of(compared(c)), mn = mean_of(compared(c));
            if (best.empty() || md < best_median || (md == best_median && mn < best_mean)) {
                best = algorithm;
                best_median = md;
                best_mean = mn;
            }
        }
        std::vector<double> p_values;
        std::vector<std::size_t> tested;
        for (const auto& [algorithm, c] : by_algorithm) {
            ReportRow r;
            r.problem = problem;
            r.algorithm = algorithm;
            r.runs = c.best.size();
            // With constraints, the values of the feasible runs alone (+inf when there is none).
            std::vector<double> feasible;
            if (c.constrained) {
                for (std::size_t i = 0; i < c.best.size(); ++i)
                    if (c.violation[i] == 0) feasible.push_back(c.best[i]);
                r.feasible_runs = feasible.size();
                if (feasible.empty()) feasible.push_back(inf);
            }
            const std::vector<double>& values = c.constrained ? feasible : c.best;
            r.min = *std::min_element(values.begin(), values.end());
            r.max = *std::max_element(values.begin(), values.end());
            r.mean = mean_of(values);
            r.std = stats::sample_std(values);
            r.median = median_of(values);
            r.mean_wall_ms = mean_of(c.wall_ms);
            r.mean_evaluations = mean_of(c.evaluations);
            r.best = algorithm == best;
            if (has_target) {
                double sum = 0.0;
                for (const auto& e : c.to_target)
                    if (e) {
                        ++r.reached_target;
                        sum += *e;
                    }
                if (r.reached_target) r.mean_evaluations_to_target = sum / static_cast<double>(r.reached_target);
            }
            if (c.f_opt) {
                r.f_opt = c.f_opt;
                r.precision = !options.raw;
                double sum = 0, solved = 0;
                for (const double v : c.best) {
                    const double precision = options.raw ? v - *c.f_opt : v;
                    solved += precision <= solved_precision ? 1.0 : 0.0;
                    if (!c.constrained) sum += precision;
                }
                // With constraints, the gap of the feasible runs (an infeasible run has no value);
                // optimal stays a share of all runs.
                if (c.constrained) {
                    for (const double v : feasible) sum += options.raw ? v - *c.f_opt : v;
                    if (*r.feasible_runs > 0) r.mean_gap = sum / static_cast<double>(*r.feasible_runs);
                } else {
                    r.mean_gap = sum / static_cast<double>(r.runs);
                }
                r.success = solved / static_cast<double>(r.runs);
            } else if (c.optimum) {
                r.optimum = c.optimum;
                double gap = 0, success = 0;
                for (double v : c.best) {
                    const bool at = std::abs(v - *c.optimum) <= 1e-9 * std::max(1.0, std::abs(*c.optimum));
                    // gap = (value - optimum) / optimum, as pride path reports it: infinite when the
                    // optimum is 0 and the value is not.
                    gap += at ? 0.0 : (*c.optimum != 0 ? (v - *c.optimum) / std::abs(*c.optimum) : inf);
                    success += at ? 1.0 : 0.0;
                }
                r.mean_gap = gap / static_cast<double>(r.runs);
                r.success = success / static_cast<double>(r.runs);
            }
            if (!r.best) {
                r.a12 = stats::vargha_delaney_a(compared(c), compared(by_algorithm.at(best)));
                p_values.push_back(stats::rank_sum_test(compared(c), compared(by_algorithm.at(best))).p_value);
                tested.push_back(rows.size());
            }
            rows.push_back(r);
        }
        const auto adjusted = stats::holm(p_values);
        for (std::size_t i = 0; i < tested.size(); ++i) rows[tested[i]].p_holm = adjusted[i];
        equal_evaluations_note(report, store, problem, by_algorithm);
    }

    // Friedman over the problems, on the median best value, for the algorithms run on all of them.
    std::map<std::string, std::size_t> count;
    for (const auto& [problem, by_algorithm] : cells)
        for (const auto& [algorithm, c] : by_algorithm) ++count[algorithm];
    std::vector<std::string> algorithms;
    for (const auto& [algorithm, n] : count)
        if (n == cells.size()) algorithms.push_back(algorithm);
    if (algorithms.size() >= 2 && cells.size() >= 2) {
        std::vector<std::vector<double>> blocks;
        for (const auto& [problem, by_algorithm] : cells) {
            std::vector<double> block;
            for (const auto& a : algorithms) block.push_back(median_of(compared(by_algorithm.at(a))));
            blocks.push_back(block);
        }
        report.friedman = FriedmanSummary{algorithms, cells.size(), stats::friedman(blocks), {}, {}};
        report.friedman->pairs = stats::friedman_pairs(report.friedman->test.average_ranks, cells.size());
        report.friedman->critical_difference =
            stats::critical_difference(report.friedman->test.average_ranks, cells.size(), 0.05);
    }
    std::set<std::string> fronts;
    std::map<std::string, std::map<std::string, std::vector<const storage::StoredRun*>>> by_front;
    for (const storage::StoredRun& run : store.runs)
        if (run.front && run.igd_plus) {
            fronts.insert(run.problem);
            by_front[run.problem][run.algorithm].push_back(&run);
        }
    for (const auto& [problem, by_algorithm] : by_front) {
        std::vector<FrontRow> rows;
        std::map<std::string, std::vector<double>> igd;
        for (const auto& [algorithm, runs] : by_algorithm) {
            FrontRow r;
            r.problem = problem;
            r.algorithm = algorithm;
            r.runs = runs.size();
            std::vector<double> ratio, found;
            for (const storage::StoredRun* run : runs) {
                ratio.push_back(1.0 - run->best.value_or(1.0));
                igd[algorithm].push_back(*run->igd_plus);
                if (run->exact_found) found.push_back(static_cast<double>(*run->exact_found));
            }
            r.hypervolume_ratio = median_of(ratio);
            r.igd_plus = median_of(igd[algorithm]);
            if (found.size() == runs.size()) r.exact_found = median_of(found);
            rows.push_back(r);
        }
        std::size_t best = 0;
        for (std::size_t i = 1; i < rows.size(); ++i)
            if (rows[i].igd_plus < rows[best].igd_plus) best = i;
        rows[best].best = true;
        std::vector<double> p;
        for (const auto& r : rows)
            if (!r.best) p.push_back(stats::rank_sum_test(igd[r.algorithm], igd[rows[best].algorithm]).p_value);
        const auto adjusted = stats::holm(p);
        for (std::size_t i = 0, k = 0; i < rows.size(); ++i)
            if (!rows[i].best) rows[i].p_holm = adjusted[k++];
        report.fronts.insert(report.fronts.end(), rows.begin(), rows.end());
    }
    // Every grid path scored alike (runs.path_metrics): the planners compared on what they found.
    std::map<std::string, std::map<std::string, std::vector<const storage::StoredRun*>>> by_path;
    for (const storage::StoredRun& run : store.runs)
        if (!run.front) by_path[run.problem][run.algorithm].push_back(&run);
    for (const auto& [problem, by_algorithm] : by_path) {
        const bool recorded = std::any_of(by_algorithm.begin(), by_algorithm.end(), [](const auto& a) {
            return std::any_of(a.second.begin(), a.second.end(),
                               [](const storage::StoredRun* r) { return !r->path_metrics.empty(); });
        });
        if (!recorded) continue;
        for (const auto& [algorithm, runs] : by_algorithm) {
            PathRow r;
            r.problem = problem;
            r.algorithm = algorithm;
            r.runs = runs.size();
            std::vector<std::vector<double>> values(std::size(storage::kPathMetricNames));
            std::vector<double> wall;
            for (const storage::StoredRun* run : runs) {
                wall.push_back(run->wall_ms);
                if (run->best) ++r.found;  // a path found (runs stored before path metrics too)
                if (run->path_metrics.empty()) continue;
                for (std::size_t k = 0; k < values.size(); ++k)
                    if (run->path_metrics[k]) values[k].push_back(*run->path_metrics[k]);
            }
            for (const auto& v : values) r.medians.push_back(v.empty() ? std::nullopt : std::optional(median_of(v)));
            r.median_wall_ms = median_of(wall);
            report.paths.push_back(std::move(r));
        }
    }
    if (!fronts.empty()) {
        std::string list;
        for (const auto& p : fronts) list += (list.empty() ? "" : ", ") + p;
        report.notes.push_back(fmt::format(
            "{} {} several objectives: {} values are hypervolume gaps, 1 - HV / HV_ref, the set's hypervolume "
            "against the reference front's (the analytic front sampled, or a grid's exact front) on objectives "
            "normalised by that front, reference point 1.1 (0: as good as the reference front; "
            "docs/multiobjective.md). Each run's front, its IGD+ and on grids the exact points it found are in the "
            "store (runs.solution).",
            list, fronts.size() == 1 ? "has" : "have", fronts.size() == 1 ? "its" : "their"));
    }
    return report;
}

ReportData load_report(const std::string& path, const ReportOptions& options) {
    const storage::CampaignStore store = storage::read_store(path);
    require(!store.runs.empty(), path, "holds no runs yet (run pride bench first)");
    return make_report(store, options);
}

storage::CampaignStore read_stores(const std::vector<std::string>& paths) {
    require(!paths.empty(), "report", "give a store");
    if (paths.size() == 1) {
        storage::CampaignStore store = storage::read_store(paths.front());
        require(!store.runs.empty(), paths.front(), "holds no runs yet (run pride bench first)");
        return store;
    }
    storage::CampaignStore all = storage::read_store(paths.front());
    std::map<std::string, storage::StoredProblem> problems;
    if (all.problems)
        for (const auto& p : *all.problems) problems.emplace(p.id, p);
    std::map<std::tuple<std::string, std::string, std::int64_t>, const storage::StoredRun*> seen;
    std::vector<storage::CampaignStore> others;
    for (std::size_t i = 1; i < paths.size(); ++i) others.push_back(storage::read_store(paths[i]));
    for (std::size_t i = 0; i < others.size(); ++i) {
        const storage::CampaignStore& s = others[i];
        const std::string& path = paths[i + 1];
        if (s.name != all.name && all.name.find(" + " + s.name) == std::string::npos) all.name += " + " + s.name;
        require(s.precisions == all.precisions, path,
                "records other target precisions than " + paths.front() + "; its runs cannot be reported with them");
        require(s.target == all.target && s.target_precision == all.target_precision, path,
                "has another report target than " + paths.front());
        if (s.problems)
            for (const auto& p : *s.problems) {
                const auto [it, fresh] = problems.emplace(p.id, p);
                const storage::StoredProblem& q = it->second;
                require(fresh || (q.dim == p.dim && q.function == p.function && q.instance == p.instance &&
                                  q.f_opt == p.f_opt),
                        path, "problem '" + p.id + "' is another problem in " + paths.front());
            }
        all.whole_map_algorithms.insert(s.whole_map_algorithms.begin(), s.whole_map_algorithms.end());
        all.unreproducible_algorithms.insert(s.unreproducible_algorithms.begin(), s.unreproducible_algorithms.end());
    }
    // Runs: each once; a run in two stores must be the same run (its values, not its wall time).
    std::vector<storage::StoredRun> runs = std::move(all.runs);
    for (auto& s : others)
        for (auto& r : s.runs) runs.push_back(std::move(r));
    std::vector<storage::StoredRun> kept;
    for (const storage::StoredRun& r : runs) {
        const auto [it, fresh] = seen.emplace(std::make_tuple(r.problem, r.algorithm, r.seed), &r);
        if (fresh) continue;
        const storage::StoredRun& o = *it->second;
        if (all.unreproducible_algorithms.count(r.algorithm)) continue;  // the first store's run is kept
        require(o.best == r.best && o.evaluations == r.evaluations && o.history == r.history &&
                    o.history_evaluations == r.history_evaluations && o.target_hits == r.target_hits &&
                    o.max_evaluations == r.max_evaluations && o.checkpoints == r.checkpoints &&
                    o.best_violation == r.best_violation && o.first_feasible == r.first_feasible &&
                    o.infeasible_f == r.infeasible_f,
                "report",
                fmt::format("run (problem '{}', algorithm '{}', seed {}) differs between the stores; they cannot be "
                            "reported as one",
                            r.problem, r.algorithm, r.seed));
    }
    for (const auto& [key, r] : seen) kept.push_back(*r);  // in key order
    all.runs = std::move(kept);
    if (all.problems) {
        all.problems->clear();
        for (auto& [id, p] : problems) all.problems->push_back(p);
    }
    require(!all.runs.empty(), "report", "the stores hold no runs yet (run pride bench first)");
    return all;
}

ReportData load_report(const std::vector<std::string>& paths, const ReportOptions& options) {
    return make_report(read_stores(paths), options);
}

std::string render_markdown(const ReportData& report) {
    return render_table(report, true);
}

std::string render_latex(const ReportData& report) {
    return render_table(report, false);
}

std::string render_csv(const ReportData& report) {
    std::string text =
        "problem,algorithm,runs,min,mean,std,median,max,mean_wall_ms,mean_evaluations,optimum,mean_gap,success,"
        "p_holm_vs_best,best,f_opt,measure,a12_vs_best";
    // Only campaigns with a target have its columns (target: the absolute threshold, or empty with
    // target_precision, the threshold then f_opt + it).
    const bool has_target = report.target || report.target_precision;
    text += report.target_precision ? ",target,target_precision,reached_target,mean_evaluations_to_target\n"
            : report.target         ? ",target,reached_target,mean_evaluations_to_target\n"
                                    : "\n";
    // With constraints, three columns more (empty for problems without): the feasible runs, the
    // median first feasible evaluation and the median violation of the infeasible runs.
    const bool feasibility = !report.feasibility.empty();
    if (feasibility) text.insert(text.size() - 1, ",feasible_runs,median_first_feasible,median_violation");
    const auto optional = [](const std::optional<double>& v) { return v ? exact(*v) : std::string(); };
    const auto feasibility_columns = [&](const ReportRow& r) {
        for (const auto& f : report.feasibility)
            if (f.problem == r.problem && f.algorithm == r.algorithm)
                return fmt::format(",{},{},{}\n", f.feasible, optional(f.median_first_feasible),
                                   optional(f.median_violation));
        return std::string(",,,\n");
    };
    for (const auto& r : report.rows) {
        text += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}", csv(r.problem), csv(r.algorithm),
                            r.runs, exact(r.min), exact(r.mean), exact(r.std), exact(r.median), exact(r.max),
                            exact(r.mean_wall_ms), exact(r.mean_evaluations), optional(r.optimum), optional(r.mean_gap),
                            optional(r.success), optional(r.p_holm), r.best ? 1 : 0, optional(r.f_opt),
                            r.precision ? "precision" : "value", optional(r.a12));
        if (report.target_precision)
            text +=
                fmt::format(",{},{},{},{}\n", r.f_opt ? exact(*r.f_opt + *report.target_precision) : "",
                            exact(*report.target_precision), r.reached_target, optional(r.mean_evaluations_to_target));
        else
            text += has_target ? fmt::format(",{},{},{}\n", exact(*report.target), r.reached_target,
                                             optional(r.mean_evaluations_to_target))
                               : "\n";
        if (feasibility) {
            text.pop_back();
            text += feasibility_columns(r);
        }
    }
    return text;
}

std::string render_ert_csv(const ReportData& report) {
    std::string text = "function,dim,algorithm,precision,ert,successes,runs,ert_p10,ert_p50,ert_p90\n";
    if (const auto& a = report.coco)
        for (const coco::ErtRow& r : a->erts)
            for (std::size_t k = 0; k < a->precisions.size(); ++k)
                text += fmt::format("{},{},{},{},{},{},{},{},{},{}\n", csv(r.function), r.dim, csv(r.algorithm),
                                    exact(a->precisions[k]), exact(r.ert[k].value), r.ert[k].successes, r.runs,
                                    exact(r.ert_interval[k].p10), exact(r.ert_interval[k].p50),
                                    exact(r.ert_interval[k].p90));
    return text;
}

}  // namespace pride::report

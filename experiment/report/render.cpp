// A report rendered as text: markdown and LaTeX share one table (render_table), then the notes,
// Friedman's ranks, the feasibility of the problems with constraints and COCO's ERT tables; CSV
// writes every number as the double it is.
#include "experiment/report/report.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>

#include "experiment/report/cells.hpp"
#include "framework/error.hpp"

namespace pride::report {
namespace {

using cells::csv;
using cells::exact;
using cells::markdown;
using cells::num;

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
        if (!report.functions.empty())
            text +=
                " Problems that are instances of a function are tested per function over all its instances (the "
                "table of functions below), not one instance at a time: their p (Holm) and A12 are left empty here.";
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
    if (!report.functions.empty()) {
        const std::vector<std::string> head{"function", "D",   "algorithm", "runs",        "instances", "median",
                                            "p10",      "p90", "mean",      "solved 1e-8", "p (Holm)",  "A12"};
        if (md)
            text += "\n" + functions_heading(report) + "\n\n" + line(head) +
                    "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
        else
            text += "\n% " + functions_heading(report) + "\n\\begin{tabular}{lrl" + std::string(head.size() - 3, 'r') +
                    "}\n\\hline\n" + line(head) + "\\hline\n";
        for (const auto& f : report.functions) text += line(function_cells(f));
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
        const bool metres = paths_in_metres(report.paths);
        text +=
            "\nPaths on grids, per algorithm, scored alike whoever planned them (docs/grid.md, \"Polylines and their "
            "metrics\"): the runs that found a path, then medians over them of the length" +
            std::string(metres ? " (in cells, then in metres on maps with a world frame)" : "") +
            ", turns, total turn "
            "(degrees), angle over length (rad per cell), maximum curvature (1/cell), minimum and mean clearance "
            "(cells) and, with the problem's `path_gaps`, the gaps to the shortest grid and any-angle lengths; the "
            "median planning time over all runs.\n\n"
            "| problem | algorithm | found | length | " +
            std::string(metres ? "length (m) | " : "") +
            "turns | turn deg | AOL | max curv. | min clear. | mean clear. | "
            "grid gap | any-angle gap | median ms |\n"
            "|---|---|---:|---:|" +
            std::string(metres ? "---:|" : "") + "---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
        for (const auto& r : report.paths) {
            text += fmt::format("| {} | {} | {}/{} |", markdown(r.problem), markdown(r.algorithm), r.found, r.runs);
            for (const auto& m : r.columns(metres)) text += m ? fmt::format(" {:.4g} |", *m) : std::string(" - |");
            text += fmt::format(" {:.3f} |\n", r.median_wall_ms);
        }
    }
    if (const auto& f = report.friedman) {
        text += md ? "\nFriedman average ranks over " : "\n% Friedman average ranks over ";
        text += friedman_blocks_text(*f) + ":";
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

std::string functions_heading(const ReportData& report) {
    const bool constrained = std::any_of(report.functions.begin(), report.functions.end(),
                                         [](const FunctionRow& f) { return f.feasible_runs.has_value(); });
    std::string text =
        "Per function and dimension, over all its instances and seeds (COCO treats the instances as repetitions: "
        "they form one sample per algorithm): the final precisions f - f_opt of the runs (f where f_opt is unknown), "
        "their median, 10th and 90th percentiles (cocopp's) and mean, and the runs that reached COCO's final target "
        "f - f_opt <= 1e-8. `best` marks the lowest median (ties: the lowest mean); p (Holm) is the Wilcoxon "
        "rank-sum test of each other algorithm's runs against the best's, Holm-corrected over the function's "
        "algorithms, with `*` where p < 0.05, and A12 its effect size.";
    if (constrained)
        text +=
            " With constraints a run without a feasible point counts as +inf, runs reads `N (F feasible)`, and best, "
            "p (Holm) and A12 compare the runs in Deb's order.";
    return text;
}

std::vector<std::string> function_cells(const FunctionRow& f) {
    return {f.function,
            std::to_string(f.dim),
            f.algorithm,
            f.feasible_runs ? fmt::format("{} ({} feasible)", f.runs, *f.feasible_runs) : std::to_string(f.runs),
            std::to_string(f.instances),
            num(f.median),
            num(f.p10),
            num(f.p90),
            num(f.mean),
            f.precision ? fmt::format("{}/{}", f.solved, f.runs) : std::string("-"),
            f.best ? std::string("best")
                   : (f.p_holm ? fmt::format("{:.3g}{}", *f.p_holm, *f.p_holm < 0.05 ? "*" : "") : std::string()),
            f.a12 ? fmt::format("{:.2f}", *f.a12) : std::string("-")};
}

std::string friedman_blocks_text(const FriedmanSummary& f) {
    if (f.functions == 0) return fmt::format("{} problems (1 = best; median values)", f.problems);
    const auto count = [](std::size_t n, const char* one, const char* many) {
        return fmt::format("{} {}", n, n == 1 ? one : many);
    };
    const std::string functions = count(f.functions, "function and dimension", "functions and dimensions");
    const std::string per_function =
        "a function's value is the median precision f - f_opt of its runs over all its instances and seeds";
    if (f.functions == f.problems) return fmt::format("{} (1 = best; {})", functions, per_function);
    return fmt::format("{} blocks, {} and {} (1 = best; {}, a problem's the median of its runs)", f.problems, functions,
                       count(f.problems - f.functions, "problem without instances", "problems without instances"),
                       per_function);
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

std::string render_markdown(const ReportData& report) {
    return render_table(report, true);
}

std::string render_latex(const ReportData& report) {
    return render_table(report, false);
}

std::string render_csv(const ReportData& report) {
    std::string text =
        "problem,algorithm,runs,min,mean,std,median,max,mean_wall_ms,mean_evaluations,optimum,mean_gap,success,"
        "p_holm_vs_best,is_best,f_opt,measure,a12_vs_best";
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

std::string render_functions_csv(const ReportData& report) {
    std::string text =
        "function,dim,algorithm,runs,instances,median,p10,p90,mean,measure,solved,feasible_runs,best,p_holm_vs_best,"
        "a12_vs_best\n";
    const auto optional = [](const auto& v) { return v ? exact(static_cast<double>(*v)) : std::string(); };
    for (const FunctionRow& f : report.functions)
        text += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", csv(f.function), f.dim, csv(f.algorithm),
                            f.runs, f.instances, exact(f.median), exact(f.p10), exact(f.p90), exact(f.mean),
                            f.precision ? "precision" : "value", f.precision ? std::to_string(f.solved) : "",
                            optional(f.feasible_runs), f.best ? 1 : 0, optional(f.p_holm), optional(f.a12));
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

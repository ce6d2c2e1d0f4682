#include "experiment/html/report_page.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <vector>

#include <fmt/format.h>

#include "experiment/html/cd_diagram.hpp"
#include "experiment/html/colour.hpp"
#include "experiment/html/figure.hpp"
#include "experiment/html/font_session.hpp"
#include "experiment/html/page.hpp"
#include "experiment/html/page_store.hpp"
#include "experiment/html/problem_figures.hpp"
#include "experiment/html/provenance.hpp"
#include "experiment/report/coco.hpp"
#include "experiment/report/natural_order.hpp"
#include "experiment/storage/file_name.hpp"
#include "experiment/storage/reader.hpp"
#include "framework/error.hpp"
#include "framework/output_files.hpp"

namespace pride::html {
namespace {

namespace fs = std::filesystem;
using report::deb_order_text;
using report::feasibility_cells;
using report::feasibility_heading;
using report::FeasibilityRow;
using report::FunctionRow;
using report::ReportData;
using report::ReportRow;
using report::runs_cell;
using storage::StoredRun;

const char* kStyle = R"css(
body { font-family: "DejaVu Sans", Helvetica, Arial, sans-serif; margin: 0 auto; max-width: 1360px;
       padding: 0 24px 48px; color: #1a1a1a; line-height: 1.45; font-size: 15px; }
h1 { font-size: 26px; margin: 24px 0 4px; }
h2 { font-size: 21px; margin-top: 36px; border-bottom: 2px solid #d8dde6; padding-bottom: 4px; }
h3 { font-size: 17px; margin-top: 28px; }
nav { background: #f3f5f9; padding: 8px 12px; border-radius: 4px; font-size: 14px; }
nav a { margin-right: 14px; }
table { border-collapse: collapse; margin: 10px 0 16px; font-size: 13px; display: block; overflow-x: auto;
        max-width: 100%; }
th, td { border: 1px solid #cdd3dd; padding: 3px 8px; }
th { background: #eef1f6; text-align: left; }
td.n, th.n { text-align: right; font-variant-numeric: tabular-nums; }
tr.best td { font-weight: bold; background: #f4faf1; }
table.kv th { width: 170px; }
pre { background: #f6f7f9; border: 1px solid #dde1e7; padding: 10px; overflow-x: auto; font-size: 13px; }
div.wide { overflow-x: auto; }
td { white-space: nowrap; }
div.figures { display: grid; grid-template-columns: repeat(auto-fill, minmax(560px, 1fr)); gap: 12px 20px; }
figure { margin: 0; }
figure img { width: 100%; height: auto; border: 1px solid #e4e7ec; }
figcaption { font-size: 13px; color: #444; }
.note { color: #6b4e00; background: #fff8e1; padding: 4px 8px; border-radius: 3px; }
)css";

// Opened as index.html?check, the page loads every figure at once (they are lazy otherwise) and
// writes into itself, so that a browser run without a display (chromium --headless --dump-dom)
// shows it, whether every figure loaded (body's data-figures: "loaded N" or "missing NAME ...")
// and which tables are wider than the page (data-overflow: "none" or their headers' first cells).
const char* kScript = R"js(
var checking = location.search.indexOf("check") >= 0;
document.addEventListener("DOMContentLoaded", function () {
  if (checking) for (var i = 0; i < document.images.length; ++i) document.images[i].loading = "eager";
});
window.addEventListener("load", function () {
  if (!checking) return;
  var images = document.images, missing = [], wide = [];
  for (var i = 0; i < images.length; ++i)
    if (!(images[i].complete && images[i].naturalWidth > 0)) missing.push(images[i].getAttribute("src"));
  document.body.setAttribute("data-figures", missing.length ? "missing " + missing.join(" ") : "loaded " + images.length);
  var tables = document.getElementsByTagName("table");
  for (var j = 0; j < tables.length; ++j)
    if (tables[j].scrollWidth > tables[j].clientWidth + 1 || tables[j].getBoundingClientRect().right > document.body.clientWidth + 1)
      wide.push(tables[j].rows[0].cells[0].textContent);
  document.body.setAttribute("data-overflow", wide.length ? wide.join(" | ") : "none");
});
)js";

std::string provenance_section(const std::string& store, const storage::CampaignStore& s, const ReportData& data) {
    const Provenance p = provenance();
    std::string h = "<section id=\"provenance\"><h2>Provenance</h2>\n<table class=\"kv\">\n";
    const auto row = [&](const std::string& k, const std::string& v) {
        h += "<tr><th>" + escape(k) + "</th><td>" + escape(v) + "</td></tr>\n";
    };
    row("campaign", s.name);
    row("store", store);
    row("runs", std::to_string(s.runs.size()));
    row("values", data.raw ? "f as run (--raw)" : "precisions f - f_opt where f_opt is known, else f");
    row("pride", p.version);
    row("git commit", p.commit + " (when the build was configured)");
    row("compiler", p.compiler);
    row("report made", p.date);
    row("machine", p.machine + " (" + p.host + ")");
    return h + "</table></section>\n";
}

/// Escaped text with the markdown's `code` spans as <code> (the report's sentences are shared).
std::string with_code(const std::string& text) {
    std::string out;
    bool open = false;
    for (const char c : escape(text)) {
        if (c != '`') {
            out += c;
            continue;
        }
        open = !open;
        out += open ? "<code>" : "</code>";
    }
    return out;
}

std::string results_section(const ReportData& r) {
    const bool f_opts =
        std::any_of(r.rows.begin(), r.rows.end(), [](const ReportRow& x) { return x.f_opt.has_value(); });
    const bool precisions = std::any_of(r.rows.begin(), r.rows.end(), [](const ReportRow& x) { return x.precision; });
    const bool has_target = r.target || r.target_precision;
    std::string h =
        "<section id=\"results\"><h2>Results</h2>\n<p>Per problem and algorithm, the final best values of "
        "the runs. <b>best</b> marks the algorithm with the lowest median (ties: the lowest mean).";
    if (precisions)
        h += " Where f_opt is known, min to max are precisions f - f_opt, gap is their mean and optimal the share of "
             "runs within 1e-8 of f_opt.";
    else if (f_opts)
        h += " Values are f as run (raw); gap is the mean of f - f_opt and optimal the share of runs within 1e-8 of "
             "f_opt.";
    h += " On grids, gap is the mean relative gap to the exact optimum and optimal the share of runs that reached it.";
    if (r.target) h += " Target: " + escape(num(*r.target)) + ".";
    if (r.target_precision) h += " Target: f_opt + " + escape(num(*r.target_precision)) + ".";
    if (!r.feasibility.empty()) h += " " + escape(deb_order_text());
    if (!r.functions.empty())
        h += " Problems that are instances of a function are tested per function over all its instances (the table "
             "of functions below), not one instance at a time: their p (Holm) and A12 are left empty here.";
    h += "</p>\n<div class=\"wide\"><table>\n<tr><th>problem</th><th>algorithm</th><th class=\"n\">runs</th>";
    if (f_opts) h += "<th class=\"n\">f_opt</th>";
    for (const char* c : {"min", "mean", "std", "median", "max", "mean ms", "gap", "optimal", "p (Holm)", "A12"})
        h += std::string("<th class=\"n\">") + c + "</th>";
    if (has_target) h += "<th class=\"n\">evals to target</th>";
    h += "</tr>\n";
    for (const ReportRow& x : r.rows) {
        h += x.best ? "<tr class=\"best\">" : "<tr>";
        const auto cell = [&](const std::string& v) { h += "<td class=\"n\">" + escape(v) + "</td>"; };
        h += "<td>" + escape(x.problem) + "</td><td>" + escape(x.algorithm) + "</td>";
        cell(runs_cell(x));
        if (f_opts) cell(x.f_opt ? num(*x.f_opt) : "-");
        for (const double v : {x.min, x.mean, x.std, x.median, x.max})
            cell(x.feasible_runs == std::size_t{0} ? std::string("-") : num(v));
        cell(fmt::format("{:.3f}", x.mean_wall_ms));
        cell(!x.mean_gap ? "-" : x.f_opt ? num(*x.mean_gap) : fmt::format("{:.2f} %", 100 * *x.mean_gap));
        cell(x.success ? fmt::format("{:.0f} %", 100 * *x.success) : "-");
        cell(x.best ? "best" : x.p_holm ? fmt::format("{:.3g}{}", *x.p_holm, *x.p_holm < 0.05 ? "*" : "") : "");
        cell(x.a12 ? fmt::format("{:.2f}", *x.a12) : "-");
        if (has_target)
            cell(x.mean_evaluations_to_target
                     ? fmt::format("{} ({}/{})", num(*x.mean_evaluations_to_target), x.reached_target, x.runs)
                     : fmt::format("- (0/{})", x.runs));
        h += "</tr>\n";
    }
    h += "</table></div>\n";
    if (!r.feasibility.empty()) {
        // The markdown report's feasibility table, the same rows.
        h += "<p>" + escape(feasibility_heading()) +
             "</p>\n<div class=\"wide\"><table>\n<tr><th>problem</th><th>algorithm</th><th class=\"n\">runs</th>"
             "<th class=\"n\">feasible</th><th class=\"n\">median first feasible</th><th class=\"n\">median "
             "violation</th></tr>\n";
        for (const FeasibilityRow& f : r.feasibility) {
            const auto cells = feasibility_cells(f);
            h += "<tr><td>" + escape(cells[0]) + "</td><td>" + escape(cells[1]) + "</td>";
            for (std::size_t k = 2; k < cells.size(); ++k) h += "<td class=\"n\">" + escape(cells[k]) + "</td>";
            h += "</tr>\n";
        }
        h += "</table></div>\n";
    }
    if (!r.functions.empty()) {
        // The markdown report's table of functions, the same rows.
        h += "<p id=\"functions\">" + with_code(report::functions_heading(r)) +
             "</p>\n<div class=\"wide\"><table>\n<tr><th>function</th><th class=\"n\">D</th><th>algorithm</th>";
        for (const char* c : {"runs", "instances", "median", "p10", "p90", "mean", "solved 1e-8", "p (Holm)", "A12"})
            h += std::string("<th class=\"n\">") + c + "</th>";
        h += "</tr>\n";
        for (const FunctionRow& f : r.functions) {
            const auto cells = report::function_cells(f);
            h += std::string(f.best ? "<tr class=\"best\">" : "<tr>") + "<td>" + escape(cells[0]) +
                 "</td><td class=\"n\">" + escape(cells[1]) + "</td><td>" + escape(cells[2]) + "</td>";
            for (std::size_t k = 3; k < cells.size(); ++k) h += "<td class=\"n\">" + escape(cells[k]) + "</td>";
            h += "</tr>\n";
        }
        h += "</table></div>\n";
    }
    for (const auto& note : r.notes) h += "<p class=\"note\">" + escape(note) + "</p>\n";
    if (!r.fronts.empty()) {
        // The markdown report's table of fronts, the same rows.
        h += "<p>Problems of several objectives, per algorithm: the median hypervolume ratio (1 - the gap above), the "
             "median IGD+ (normalised the same way; 0 is the reference front) and, on grids, the median number of the "
             "exact front's points found; <b>best</b> marks the lowest median IGD+; p (Holm) is the rank-sum test of "
             "each algorithm's IGD+ against the best's, Holm-corrected over the problem's algorithms.</p>\n"
             "<table>\n<tr><th>problem</th><th>algorithm</th><th class=\"n\">runs</th><th class=\"n\">HV "
             "ratio</th><th class=\"n\">IGD+</th><th class=\"n\">exact points</th><th class=\"n\">p "
             "(Holm)</th></tr>\n";
        for (const auto& x : r.fronts)
            h += fmt::format(
                "{}<td>{}</td><td>{}</td><td class=\"n\">{}</td><td class=\"n\">{:.4g}</td><td "
                "class=\"n\">{:.4g}</td><td class=\"n\">{}</td><td class=\"n\">{}</td></tr>\n",
                x.best ? "<tr class=\"best\">" : "<tr>", escape(x.problem), escape(x.algorithm), x.runs,
                x.hypervolume_ratio, x.igd_plus, x.exact_found ? fmt::format("{:g}", *x.exact_found) : "-",
                x.best     ? "best"
                : x.p_holm ? fmt::format("{:.3g}{}", *x.p_holm, *x.p_holm < 0.05 ? "*" : "")
                           : "");
        h += "</table>\n";
    }
    if (!r.paths.empty()) {
        // The markdown report's table of paths, the same rows.
        const bool metres = report::paths_in_metres(r.paths);
        h += "<p>Paths on grids, per algorithm, scored alike whoever planned them (docs/grid.md, \"Polylines and "
             "their metrics\"): the runs that found a path, then medians over them of the length" +
             std::string(metres ? " (in cells, then in metres on maps with a world frame)" : "") +
             ", turns, total turn "
             "(degrees), angle over length (rad per cell), maximum curvature (1/cell), minimum and mean clearance "
             "(cells) and, with the problem's <code>path_gaps</code>, the gaps to the shortest grid and any-angle "
             "lengths; the median planning time over all runs.</p>\n<div class=\"wide\"><table>\n<tr><th>problem</th>"
             "<th>algorithm</th><th class=\"n\">found</th><th class=\"n\">length</th>" +
             std::string(metres ? "<th class=\"n\">length (m)</th>" : "") +
             "<th class=\"n\">turns</th><th "
             "class=\"n\">turn deg</th><th class=\"n\">AOL</th><th class=\"n\">max curv.</th><th class=\"n\">min "
             "clear.</th><th class=\"n\">mean clear.</th><th class=\"n\">grid gap</th><th class=\"n\">any-angle "
             "gap</th><th class=\"n\">median ms</th></tr>\n";
        for (const auto& x : r.paths) {
            h += fmt::format("<tr><td>{}</td><td>{}</td><td class=\"n\">{}/{}</td>", escape(x.problem),
                             escape(x.algorithm), x.found, x.runs);
            for (const auto& m : x.columns(metres))
                h += m ? fmt::format("<td class=\"n\">{:.4g}</td>", *m) : std::string("<td class=\"n\">-</td>");
            h += fmt::format("<td class=\"n\">{:.3f}</td></tr>\n", x.median_wall_ms);
        }
        h += "</table></div>\n";
    }
    return h + "</section>\n";
}

std::string statistics_section(const ReportData& r) {
    std::string h =
        "<section id=\"statistics\"><h2>Statistics</h2>\n<p><b>Per problem</b> (the table above): each algorithm "
        "against the best one by the two-sided <b>Wilcoxon rank-sum test</b> (Mann-Whitney U, normal approximation "
        "with tie and continuity corrections), its p-values <b>Holm</b>-corrected over the problem's algorithms, "
        "<code>*</code> where p &lt; 0.05; beside it the <b>Vargha-Delaney A12</b> effect size: the chance that a run "
        "of the algorithm ends better than a run of the best, ties counting half (0.5: no effect).";
    if (!r.functions.empty())
        h += " <b>Per function</b> (the table of functions): where problems are instances of a function (BBOB, "
             "bbob-constrained), the same tests on the runs of all the function's instances and seeds, one sample per "
             "algorithm, as COCO pools instances.";
    h += "</p>\n";
    if (const auto& f = r.friedman) {
        h += fmt::format(
            "<p><b>Over the problems</b>: the <b>Friedman test</b> of the {} algorithms run on all of them, over {}: "
            "chi-squared {:.4g}, p = {:.3g}; then every pair by the post-hoc z-test on the average ranks, "
            "Holm-corrected over the {} pairs (Dem&scaron;ar 2006).</p>\n",
            f->algorithms.size(), escape(report::friedman_blocks_text(*f)), f->test.statistic, f->test.p_value,
            f->pairs.size());
        h += "<table><tr><th>algorithm</th><th class=\"n\">average rank</th></tr>\n";
        for (std::size_t j = 0; j < f->algorithms.size(); ++j)
            h += fmt::format("<tr><td>{}</td><td class=\"n\">{:.3g}</td></tr>\n", escape(f->algorithms[j]),
                             f->test.average_ranks[j]);
        h += "</table>\n<table><tr><th>pair</th><th class=\"n\">z</th><th class=\"n\">p</th><th class=\"n\">p "
             "(Holm)</th></tr>\n";
        for (const auto& q : f->pairs)
            h += fmt::format(
                "<tr><td>{} vs {}</td><td class=\"n\">{:.3g}</td><td class=\"n\">{:.3g}</td><td "
                "class=\"n\">{:.3g}{}</td></tr>\n",
                escape(f->algorithms[q.a]), escape(f->algorithms[q.b]), q.z, q.p, q.p_holm, q.p_holm < 0.05 ? "*" : "");
        h += "</table>\n";
        const auto& cd = f->critical_difference;
        std::string groups;
        for (const auto& clique : cd.cliques) {
            std::string names;
            for (const std::size_t j : clique) names += (names.empty() ? "" : ", ") + escape(f->algorithms[j]);
            groups += (groups.empty() ? "" : "; ") + ("{" + names + "}");
        }
        h += fmt::format(
            "<p><b>Nemenyi's critical difference</b> at alpha {:g} (Dem&scaron;ar 2006): CD = {:.3g}; algorithms whose "
            "average ranks differ by less are not significantly different: {}.</p>\n",
            cd.alpha, cd.cd, groups.empty() ? std::string("none") : groups);
    } else {
        h += "<p>No Friedman test: it needs two algorithms run on every one of two problems or more.</p>\n";
    }
    return h;
}

/// Demsar's critical-difference diagram (cd_diagram.hpp); then the statistics section ends.
void cd_diagram(Page& page, const ReportData& r) {
    if (const auto& f = r.friedman) {
        const auto& cd = f->critical_difference;
        const std::string blocks = f->functions == 0             ? fmt::format("{} problems", f->problems)
                                   : f->functions == f->problems ? fmt::format("{} functions", f->functions)
                                                                 : fmt::format("{} blocks", f->problems);
        const std::string name = "critical-difference.svg";
        write_cd_diagram(cd_layout(f->test.average_ranks, cd), f->algorithms, "critical-difference diagram",
                         fmt::format("Friedman over {}; Nemenyi CD = {:.3g} at alpha {:g}", blocks, cd.cd, cd.alpha),
                         page.create(name));
        page.put(name, "critical-difference diagram",
                 "Average ranks (1 = best, at the left); each algorithm's name joined to its rank. Thick bars join "
                 "algorithms whose ranks differ by less than Nemenyi's critical difference (CD, the segment at the "
                 "top): not significantly different (Dem&scaron;ar 2006).");
    }
    page.html += "</section>\n";
}

/// The ERT tables (as the markdown report's) and the runtime ECDFs.
void ert_section(Page& page, const ReportData& r) {
    if (!r.coco) return;
    const report::coco::Analysis& a = *r.coco;
    const auto shown = report::shown_precisions(a.precisions);
    const std::size_t smallest =
        static_cast<std::size_t>(std::min_element(a.precisions.begin(), a.precisions.end()) - a.precisions.begin());
    std::string& h = page.html;
    h += fmt::format(
        "<section id=\"ert\"><h2>Expected running time (ERT) and runtime ECDFs</h2>\n<p>ERT: the evaluations of all "
        "runs (up to the target where reached) over the runs that reached f_opt + precision, over the instances of "
        "each function; inf where none did; in brackets the 10th and 90th percentiles of the ERT over 1000 bootstrap "
        "resamples of the runs. #succ: the runs that reached the smallest precision ({}). ECDFs: solid, the runs as "
        "they are; dotted, with COCO's simulated restarts (100 per function, dimension and target). Definitions of "
        "COCO (Hansen et al., COCO: performance assessment).{}</p>\n",
        escape(report::precision_label(a.precisions[smallest])),
        a.runs_without_hits ? fmt::format(" {} runs record no target hits and are left out.", a.runs_without_hits)
                            : std::string());
    for (std::size_t i = 0; i < a.erts.size();) {
        const std::string& function = a.erts[i].function;
        const std::int64_t dim = a.erts[i].dim;
        h += fmt::format("<h3>{}, {}-D ({} instance{})</h3>\n<table><tr><th>algorithm</th>", escape(function), dim,
                         a.erts[i].instances, a.erts[i].instances == 1 ? "" : "s");
        for (const std::size_t k : shown)
            h += "<th class=\"n\">ERT " + escape(report::precision_label(a.precisions[k])) + "</th>";
        h += "<th class=\"n\">#succ</th></tr>\n";
        for (; i < a.erts.size() && a.erts[i].function == function && a.erts[i].dim == dim; ++i) {
            const auto& e = a.erts[i];
            h += "<tr><td>" + escape(e.algorithm) + "</td>";
            for (const std::size_t k : shown)
                h += "<td class=\"n\">" +
                     (std::isfinite(e.ert[k].value)
                          ? fmt::format("{:.3g} <small>[{:.3g}, {:.3g}]</small>", e.ert[k].value, e.ert_interval[k].p10,
                                        e.ert_interval[k].p90)
                          : std::string("inf")) +
                     "</td>";
            h += fmt::format("<td class=\"n\">{}/{}</td></tr>\n", e.ert[smallest].successes, e.runs);
        }
        h += "</table>\n";
    }
    double lo = 0, hi = 1;
    int span_hi = 0, span_lo = 0;
    for (const double p : a.precisions)
        if (p > 0)
            span_hi = std::max(span_hi, static_cast<int>(std::round(std::log10(p)))),
            span_lo = std::min(span_lo, static_cast<int>(std::round(std::log10(p))));
    h += "<div class=\"figures\">\n";
    for (std::size_t i = 0; i < a.curves.size();) {
        const std::string group = a.curves[i].group;
        std::size_t j = i;
        std::vector<std::int64_t> dims;
        for (; j < a.curves.size() && a.curves[j].group == group; ++j)
            for (const auto d : a.curves[j].dims)
                if (std::find(dims.begin(), dims.end(), d) == dims.end()) dims.push_back(d);
        std::sort(dims.begin(), dims.end());
        for (std::size_t k = i; k < j; ++k) {
            const auto& e = a.curves[k].ecdf;
            if (!e.x.empty()) lo = std::min(lo, e.x.front());
            if (std::isfinite(e.max_budget)) hi = std::max(hi, e.max_budget);
            const auto& rs = a.curves[k].restarts;
            if (!rs.x.empty() && std::isfinite(rs.x.back())) hi = std::max(hi, rs.x.back());
        }
        std::string dim_list;
        for (const auto d : dims) dim_list += (dim_list.empty() ? "" : ", ") + std::to_string(d);
        const std::string title =
            (group == "all" ? std::string("all functions") : report::coco::bbob_group_title(group)) +
            ", D = " + dim_list;
        Figure f(title, Axis{"log10(evaluations / dimension)", Scale::linear, lo, hi + 0.05 * (hi - lo)},
                 Axis{"fraction of (run, target) pairs", Scale::linear, -0.02, 1.02});
        f.subtitle(fmt::format("{} targets f_opt + 10^k, k from {} to {}; x: the run's largest budget",
                               a.precisions.size(), span_hi, span_lo));
        for (std::size_t k = i; k < j; ++k) {
            const auto& c = a.curves[k];
            const auto& e = c.ecdf;
            const double end = std::isfinite(e.max_budget) ? e.max_budget : hi;
            std::vector<double> xs{lo}, ys{0.0};
            xs.insert(xs.end(), e.x.begin(), e.x.end());
            ys.insert(ys.end(), e.y.begin(), e.y.end());
            xs.push_back(end);
            ys.push_back(e.y.empty() ? 0.0 : e.y.back());
            const std::string algorithm = c.algorithm;
            const bool known = page.algorithms.count(algorithm) > 0;
            const Rgb colour = known ? page.colour(algorithm) : series_colour(k - i);
            f.line(xs, ys, colour, fmt::format("{} ({} pairs)", algorithm, e.pairs), known ? page.dash(algorithm) : 0,
                   true);
            f.markers({end}, {ys.back()}, colour, "", Marker::cross);
            const auto& rs = c.restarts;
            if (!rs.x.empty()) {
                std::vector<double> rx{lo}, ry{0.0};
                rx.insert(rx.end(), rs.x.begin(), rs.x.end());
                ry.insert(ry.end(), rs.y.begin(), rs.y.end());
                rx.push_back(hi);
                ry.push_back(rs.y.back());
                f.line(rx, ry, colour, algorithm + ", simulated restarts", 3, true);
            }
        }
        page.add(f, page.file("ecdf", group), "runtime ECDF: " + title,
                 "Runtime ECDF, " + escape(title) +
                     ": the fraction of (run, target) pairs reached within 10^x &times; dimension evaluations.");
        i = j;
    }
    h += "</div>\n</section>\n";
}

/// The folder as named, without a trailing separator.
fs::path folder_of(const std::string& dir) {
    fs::path p(dir);
    while (p.has_relative_path() && p.filename().empty()) p = p.parent_path();
    return p;
}

}  // namespace

PageSummary write_report_page(const std::string& store, const std::string& dir, const report::ReportOptions& options) {
    OutputFiles files;
    PageSummary summary = write_report_page(store, dir, options, files);
    files.commit();  // index.html last: it was created last
    return summary;
}

PageSummary write_report_page(const std::string& store, const std::string& dir, const report::ReportOptions& options,
                              OutputFiles& files) {
    require(!dir.empty(), "html", "expected a folder, got ''");
    // Everything is read and checked before anything is written.
    const storage::CampaignStore s = storage::read_store(store);
    require(!s.runs.empty(), store, "holds no runs yet (run pride bench first)");
    const ReportData data = report::make_report(s, options);
    const PageStore extra = read_page_store(store);

    const fs::path target = folder_of(dir);
    PageSummary summary;
    summary.index = (target / "index.html").string();
    try {
        files.output_folder(target);
        files.scratch_folder(target);  // that the folder can be written, known before the figures are drawn
        const FontSession fonts;       // one for all the figures
        Page page;
        page.files = &files;
        page.folder = target;
        std::size_t next = 0;
        for (const ReportRow& row : data.rows)
            if (!page.algorithms.count(row.algorithm)) page.algorithms[row.algorithm] = next++;
        std::map<std::string, std::vector<const StoredRun*>, report::NaturalLess> by_problem;
        for (const StoredRun& run : s.runs) by_problem[run.problem].push_back(&run);
        std::vector<std::string> problems;
        for (const auto& entry : by_problem) problems.push_back(entry.first);
        page.names = storage::unique_file_names(problems);

        page.html = provenance_section(store, s, data);
        page.html +=
            "<section id=\"definition\"><h2>Campaign definition</h2>\n<p>As stored: the campaign file's text (the "
            "newest, for a campaign that grew), or pride's description of a campaign built in code.</p>\n<pre>" +
            escape(extra.text) + "</pre>\n";
        page.html += "</section>\n" + results_section(data) + statistics_section(data);
        cd_diagram(page, data);
        ert_section(page, data);
        page.html += "<section id=\"problems\"><h2>Figures per problem</h2>\n";
        for (const auto& [problem, runs] : by_problem) problem_section(page, problem, runs, data, s, extra);
        page.html += "</section>\n";

        std::string nav =
            "<nav><a href=\"#provenance\">provenance</a><a href=\"#definition\">definition</a><a "
            "href=\"#results\">results</a><a href=\"#statistics\">statistics</a>";
        if (data.coco) nav += "<a href=\"#ert\">ERT and ECDF</a>";
        nav += "<a href=\"#problems\">figures:</a>";
        for (const auto& [problem, runs] : by_problem)
            nav += fmt::format("<a href=\"#problem-{}\">{}</a>", escape(page.names.at(problem)), escape(problem));
        nav += "</nav>\n";
        const std::string html = fmt::format(
            "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<meta name=\"generator\" "
            "content=\"pride {}\">\n<title>pride report: {}</title>\n<style>{}</style>\n<script>{}</script>\n</head>\n"
            "<body>\n<h1>Campaign {}</h1>\n{}{}</body>\n</html>\n",
            escape(provenance().version), escape(s.name), kStyle, kScript, escape(s.name), nav, page.html);
        files.write(target / "index.html", html);
        summary.figures = page.figures;
    } catch (const InputError& e) {
        if (e.where() == "html") throw;
        throw InputError("html", e.what());
    }
    return summary;
}

}  // namespace pride::html

#include "experiment/html/report_page.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "engine/specs.hpp"
#include "experiment/html/colour.hpp"
#include "experiment/html/draw.hpp"
#include "experiment/html/figure.hpp"
#include "experiment/html/font_session.hpp"
#include "experiment/html/front_figures.hpp"
#include "experiment/html/page.hpp"
#include "experiment/html/page_store.hpp"
#include "experiment/html/provenance.hpp"
#include "experiment/report/coco.hpp"
#include "experiment/storage/file_name.hpp"
#include "experiment/storage/reader.hpp"
#include "framework/error.hpp"
#include "framework/output_files.hpp"
#include "problems/grid/pareto.hpp"
#include "problems/grid/path.hpp"

namespace pride::html {
namespace {

namespace fs = std::filesystem;
using report::deb_order_text;
using report::feasibility_cells;
using report::feasibility_heading;
using report::FeasibilityRow;
using report::ReportData;
using report::ReportRow;
using report::runs_cell;
using storage::StoredRun;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kFloor = 1e-12;                 // precisions at or below it are drawn at it on log axes
constexpr std::size_t kCurvePoints = 400;        // x positions per convergence curve at most
constexpr std::size_t kParetoCells = 4096;       // maps up to 64 x 64 get their Pareto front: it is cheap
constexpr std::size_t kParetoLabels = 1u << 22;  // and it stops here on a map where it is not

/// The seeds' values at each x: median and quartiles; x evaluations or iterations.
struct Curve {
    std::vector<double> x, median, q1, q3;
};

/// At most kCurvePoints of `xs` (sorted), evenly spread over its indices, first and last kept.
std::vector<double> thinned(const std::vector<double>& xs) {
    if (xs.size() <= kCurvePoints) return xs;
    std::vector<double> out;
    for (std::size_t i = 0; i < kCurvePoints; ++i) out.push_back(xs[i * (xs.size() - 1) / (kCurvePoints - 1)]);
    return out;
}

/// The best value of each run after x evaluations (+inf before its first record; its last value
/// after its end) or after iteration x (its last value after its last iteration), as shown.
template <class Shown>
Curve summarise(const std::vector<const StoredRun*>& runs, bool by_evaluations, Shown shown) {
    std::vector<double> xs;
    if (by_evaluations) {
        for (const StoredRun* r : runs)
            for (const auto e : r->history_evaluations) xs.push_back(static_cast<double>(e));
        std::sort(xs.begin(), xs.end());
        xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
    } else {
        std::size_t longest = 0;
        for (const StoredRun* r : runs) longest = std::max(longest, r->history.size());
        for (std::size_t k = 0; k < longest; ++k) xs.push_back(static_cast<double>(k));
    }
    Curve c;
    c.x = thinned(xs);
    std::vector<std::size_t> at(runs.size(), 0);  // per run: records up to the current x
    std::vector<double> values(runs.size());
    for (const double x : c.x) {
        for (std::size_t i = 0; i < runs.size(); ++i) {
            const StoredRun& r = *runs[i];
            if (by_evaluations) {
                while (at[i] < r.history_evaluations.size() && static_cast<double>(r.history_evaluations[at[i]]) <= x)
                    ++at[i];
                values[i] = at[i] == 0 ? kInf : shown(r.history[at[i] - 1]);
            } else {
                values[i] = shown(r.history[std::min(static_cast<std::size_t>(x), r.history.size() - 1)]);
            }
        }
        std::sort(values.begin(), values.end());
        c.median.push_back(quantile(values, 0.5));
        c.q1.push_back(quantile(values, 0.25));
        c.q3.push_back(quantile(values, 0.75));
    }
    return c;
}

/// The curve as the step function it is (a best value holds until the next record): each value
/// repeated at the next x.
Curve as_steps(const Curve& c) {
    Curve s;
    for (std::size_t i = 0; i < c.x.size(); ++i) {
        for (int twice = 0; twice < (i + 1 < c.x.size() ? 2 : 1); ++twice) {
            s.x.push_back(twice ? c.x[i + 1] : c.x[i]);
            s.median.push_back(c.median[i]);
            s.q1.push_back(c.q1[i]);
            s.q3.push_back(c.q3[i]);
        }
    }
    return s;
}

const char* kStyle = R"css(
body { font-family: "DejaVu Sans", Helvetica, Arial, sans-serif; margin: 0 auto; max-width: 1240px;
       padding: 0 24px 48px; color: #1a1a1a; line-height: 1.45; font-size: 15px; }
h1 { font-size: 26px; margin: 24px 0 4px; }
h2 { font-size: 21px; margin-top: 36px; border-bottom: 2px solid #d8dde6; padding-bottom: 4px; }
h3 { font-size: 17px; margin-top: 28px; }
nav { background: #f3f5f9; padding: 8px 12px; border-radius: 4px; font-size: 14px; }
nav a { margin-right: 14px; }
table { border-collapse: collapse; margin: 10px 0 16px; font-size: 13px; }
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

// Whether every figure loaded, written into the page itself (body's data-figures), so that a
// browser run without a display (chromium --headless --dump-dom) shows it: "loaded N" or
// "missing NAME ...".
const char* kScript = R"js(
window.addEventListener("load", function () {
  var images = document.images, missing = [];
  for (var i = 0; i < images.length; ++i)
    if (!(images[i].complete && images[i].naturalWidth > 0)) missing.push(images[i].getAttribute("src"));
  document.body.setAttribute("data-figures", missing.length ? "missing " + missing.join(" ") : "loaded " + images.length);
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
        h += "<p>Paths on grids, per algorithm, scored alike whoever planned them (docs/grid.md, \"Polylines and "
             "their metrics\"): the runs that found a path, then medians over them of the length, turns, total turn "
             "(degrees), angle over length (rad per cell), maximum curvature (1/cell), minimum and mean clearance "
             "(cells) and, with the problem's <code>path_gaps</code>, the gaps to the shortest grid and any-angle "
             "lengths; the median planning time over all runs.</p>\n<div class=\"wide\"><table>\n<tr><th>problem</th>"
             "<th>algorithm</th><th class=\"n\">found</th><th class=\"n\">length</th><th class=\"n\">turns</th><th "
             "class=\"n\">turn deg</th><th class=\"n\">AOL</th><th class=\"n\">max curv.</th><th class=\"n\">min "
             "clear.</th><th class=\"n\">mean clear.</th><th class=\"n\">grid gap</th><th class=\"n\">any-angle "
             "gap</th><th class=\"n\">median ms</th></tr>\n";
        for (const auto& x : r.paths) {
            h += fmt::format("<tr><td>{}</td><td>{}</td><td class=\"n\">{}/{}</td>", escape(x.problem),
                             escape(x.algorithm), x.found, x.runs);
            for (const auto& m : x.medians)
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
        "of the algorithm ends better than a run of the best, ties counting half (0.5: no effect).</p>\n";
    if (const auto& f = r.friedman) {
        h += fmt::format(
            "<p><b>Over the problems</b>: the <b>Friedman test</b> on the median values of the {} algorithms run on "
            "all {} problems (1 = best): chi-squared {:.4g}, p = {:.3g}; then every pair by the post-hoc z-test on "
            "the average ranks, Holm-corrected over the {} pairs (Dem&scaron;ar 2006).</p>\n",
            f->algorithms.size(), f->problems, f->test.statistic, f->test.p_value, f->pairs.size());
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

/// Demsar's critical-difference diagram: the average ranks, the CD, and a bar over each group of
/// algorithms not significantly different; then the statistics section ends.
void cd_diagram(Page& page, const ReportData& r) {
    if (const auto& f = r.friedman) {
        const auto& cd = f->critical_difference;
        const double k = static_cast<double>(f->algorithms.size());
        Figure fig("critical-difference diagram", Axis{"average rank (1 = best)", Scale::linear, 0.5, k + 0.5},
                   Axis{"", Scale::linear, -0.5, k + 1.5});
        fig.subtitle(
            fmt::format("Friedman over {} problems; Nemenyi CD = {:.3g} at alpha {:g}", f->problems, cd.cd, cd.alpha));
        std::vector<std::size_t> order(f->algorithms.size());
        for (std::size_t j = 0; j < order.size(); ++j) order[j] = j;
        std::sort(order.begin(), order.end(),
                  [&](std::size_t a, std::size_t b) { return f->test.average_ranks[a] < f->test.average_ranks[b]; });
        for (std::size_t i = 0; i < order.size(); ++i) {
            const std::size_t j = order[i];
            const std::string& name = f->algorithms[j];
            const bool known = page.algorithms.count(name) > 0;
            const double y = k - static_cast<double>(i);
            const Rgb colour = known ? page.colour(name) : series_colour(i);
            fig.line({f->test.average_ranks[j], f->test.average_ranks[j]}, {0.0, y}, colour, "", 0);
            fig.markers({f->test.average_ranks[j]}, {y}, colour,
                        fmt::format("{} ({:.3g})", name, f->test.average_ranks[j]), Marker::circle);
        }
        const Rgb black{0, 0, 0};
        fig.line({1.0, 1.0 + cd.cd}, {k + 1, k + 1}, black, fmt::format("CD = {:.3g}", cd.cd), 0);
        for (std::size_t c = 0; c < cd.cliques.size(); ++c) {
            double lo = k + 1, hi = 0;
            for (const std::size_t j : cd.cliques[c])
                lo = std::min(lo, f->test.average_ranks[j]), hi = std::max(hi, f->test.average_ranks[j]);
            const double y = 0.25 + 0.5 * static_cast<double>(c) / std::max<double>(1.0, k);
            fig.line({lo, hi}, {y, y}, black, c == 0 ? "not significantly different" : "", 0);
        }
        page.add(fig, "critical-difference.svg", "critical-difference diagram",
                 "Average ranks over the problems (1 = best); bars join algorithms whose ranks differ by less than "
                 "Nemenyi's critical difference (the segment at the top).");
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

/// Per problem: convergence, final values, and on grids the paths and the Pareto front (figures
/// in a grid of two columns where the window is wide enough; notes under them). A problem of
/// several objectives: the final hypervolume gaps, then its fronts (front_figures.hpp).
void problem_figures(Page& page, const std::string& problem, const std::vector<const StoredRun*>& runs,
                     const ReportData& r, const storage::CampaignStore& s, const PageStore& extra) {
    // Its runs store fronts, and as their value the hypervolume gap; they record no convergence.
    const bool fronts = std::all_of(runs.begin(), runs.end(), [](const StoredRun* x) { return x->front; });
    std::optional<double> f_opt;
    bool precision = false;
    for (const ReportRow& row : r.rows)
        if (row.problem == problem && row.f_opt) f_opt = row.f_opt, precision = row.precision;
    bool floored = false;
    const auto shown = [&](double v) {
        if (!precision || !std::isfinite(v)) return v;
        const double p = v - *f_opt;
        if (p <= kFloor) floored = true;
        return std::max(p, kFloor);
    };
    std::map<std::string, std::vector<const StoredRun*>> by_algorithm;
    for (const StoredRun* run : runs) by_algorithm[run->algorithm].push_back(run);

    // Convergence: algorithms whose runs record a history; the others (whole-map planners) as a
    // line at their median value.
    std::vector<std::string> curves, flat;
    for (const auto& [a, rs] : by_algorithm)
        (std::all_of(rs.begin(), rs.end(), [](const StoredRun* x) { return !x->history.empty(); }) ? curves : flat)
            .push_back(a);
    bool by_evaluations = !curves.empty();
    for (const auto& a : curves)
        for (const StoredRun* x : by_algorithm[a])
            by_evaluations = by_evaluations && x->history_evaluations.size() == x->history.size();
    std::map<std::string, Curve> summaries;
    std::map<std::string, double> levels;
    double lo = kInf, hi = -kInf;
    const auto see = [&](double v) {
        if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
    };
    for (const auto& a : curves) {
        summaries[a] = as_steps(summarise(by_algorithm[a], by_evaluations, shown));
        for (const auto* v : {&summaries[a].median, &summaries[a].q1, &summaries[a].q3})
            for (const double y : *v) see(y);
    }
    for (const auto& a : flat) {
        std::vector<double> finals;
        for (const StoredRun* x : by_algorithm[a]) finals.push_back(shown(x->best.value_or(kInf)));
        std::sort(finals.begin(), finals.end());
        levels[a] = quantile(finals, 0.5);
        see(levels[a]);
    }
    // Precisions on a log axis; values too where they are positive and span a decade or more.
    const bool log = precision || (lo > 0 && hi > 10 * lo);
    const std::string what = fronts      ? "hypervolume gap 1 - HV / HV_ref"
                             : precision ? "precision f - f_opt"
                                         : "best value f";
    if (!fronts) {
        Figure f(problem + ": convergence",
                 Axis{by_evaluations ? "evaluations" : "iterations", Scale::linear, std::nullopt, std::nullopt},
                 Axis{what, log ? Scale::log : Scale::linear, std::nullopt, std::nullopt});
        for (const auto& a : curves) {
            const Curve& c = summaries[a];
            f.band(c.x, c.q1, c.q3, page.colour(a));
            f.line(c.x, c.median, page.colour(a), a, page.dash(a));
        }
        for (const auto& a : flat) f.hline(levels[a], page.colour(a), a + " (whole map)", page.dash(a));
        f.subtitle(fmt::format("median and interquartile band over the seeds, against {}{}",
                               by_evaluations ? "evaluations" : "iterations (not every run records its evaluations)",
                               floored ? fmt::format("; precisions <= {:g} drawn at {:g}", kFloor, kFloor) : ""));
        page.add(f, page.file("convergence", problem), problem + ": convergence",
                 fmt::format("Convergence on {}: the {} after each {} (median line, quartile band over the seeds).",
                             escape(problem), what, by_evaluations ? "evaluation count recorded" : "iteration"));
    }
    {
        floored = false;
        std::vector<std::vector<double>> finals;
        lo = kInf, hi = -kInf;
        std::string missing;
        for (const auto& [a, rs] : by_algorithm) {
            finals.emplace_back();
            std::size_t none = 0;
            for (const StoredRun* x : rs) {
                finals.back().push_back(shown(x->best.value_or(kInf)));
                see(finals.back().back());
                none += x->best ? 0 : 1;
            }
            if (none) missing += fmt::format(" {}: {} of {} runs found no feasible value.", escape(a), none, rs.size());
        }
        const bool log_finals = precision || (lo > 0 && hi > 10 * lo);
        Figure g(problem + ": final values", Axis{"algorithm", Scale::linear, std::nullopt, std::nullopt},
                 Axis{"final " + what, log_finals ? Scale::log : Scale::linear, std::nullopt, std::nullopt});
        std::size_t i = 0;
        for (const auto& [a, rs] : by_algorithm) g.box(a, finals[i++], page.colour(a));
        g.subtitle(fmt::format("boxes: quartiles and median; whiskers: 1.5 IQR; circles: beyond{}",
                               floored ? fmt::format("; precisions <= {:g} drawn at {:g}", kFloor, kFloor) : ""));
        page.add(g, page.file("final", problem), problem + ": final values",
                 fmt::format("Final {} of every run on {}.{}", what, escape(problem), missing));
    }
    if (fronts) {
        front_figures(page, s, extra, problem);
        return;
    }

    // Grids: each algorithm's best path on the map, and where cheap the exact Pareto front.
    const auto info =
        std::find_if(extra.grids.begin(), extra.grids.end(), [&](const GridProblemInfo& g) { return g.id == problem; });
    if (info == extra.grids.end()) return;
    std::vector<const BestPath*> best;
    for (const BestPath& b : extra.best_paths)
        if (b.problem == problem) best.push_back(&b);
    const auto map = picture_map(page, &*info);
    if (!map) return;
    std::vector<grid::Polyline> paths;
    std::vector<std::string> labels;
    std::vector<Rgb> colours;
    for (const BestPath* b : best) {
        paths.push_back(b->polyline.empty() ? grid::polyline_of(b->path) : b->polyline);
        std::string label = fmt::format("{}: {} (seed {})", b->algorithm, num(b->value), b->seed);
        if (b->optimum) label += fmt::format(", exact optimum {}", num(*b->optimum));
        labels.push_back(label);
        colours.push_back(page.colour(b->algorithm));
    }
    const std::string paths_file = page.file("paths", problem);
    draw_grid_paths(*map, info->start, info->goal, paths, labels, page.create(paths_file), PictureFormat::svg, colours);
    std::string none;
    for (const auto& entry : by_algorithm) {
        const std::string& a = entry.first;  // (clang 14 captures no structured binding)
        if (std::none_of(best.begin(), best.end(), [&](const BestPath* b) { return b->algorithm == a; }))
            none += " " + escape(a) + " found no feasible path.";
    }
    page.put(paths_file, problem + ": best paths",
             fmt::format("The best path of each algorithm on {} (its lowest value over the seeds), with the exact "
                         "optimum of the objective where the campaign computed it; start green, goal red.{}",
                         escape(problem), none));
    if (map->size() > kParetoCells) {
        page.notes += fmt::format(
            "<p>No Pareto front: the map has {} cells, more than the {} up to which the report computes it (pride "
            "pareto computes it on any map).</p>\n",
            map->size(), kParetoCells);
        return;
    }
    grid::ParetoOptions options;
    options.corner_cutting = info->corner_cutting;
    options.max_labels = kParetoLabels;
    std::vector<grid::FrontPoint> front;
    try {
        front = grid::pareto_front(*map, info->start, info->goal, grid::Criteria{true, true, false}, options);
    } catch (const InputError& e) {
        page.notes += "<p class=\"note\">No Pareto front: " + escape(e.what()) + "</p>\n";
        return;
    }
    if (front.empty()) return;
    Figure f(problem + ": Pareto front of length and turns", Axis{"path length", Scale::linear, {}, {}},
             Axis{"turns", Scale::linear, {}, {}});
    std::vector<double> xs, ys;
    for (const auto& p : front) xs.push_back(p.length), ys.push_back(p.turns);
    f.line(xs, ys, {0.55, 0.55, 0.6}, "", 0, true);
    f.markers(xs, ys, {0.35, 0.35, 0.4},
              fmt::format("exact front ({} point{})", front.size(), front.size() == 1 ? "" : "s"), Marker::circle);
    const Marker shapes[] = {Marker::diamond, Marker::square, Marker::cross};
    std::size_t k = 0;
    for (const BestPath* b : best) {
        const grid::PathMetrics m = grid::metrics(b->path);
        f.markers({m.length}, {static_cast<double>(m.turns)}, page.colour(b->algorithm),
                  fmt::format("{}: length {}, {} turns", b->algorithm, num(m.length), m.turns), shapes[k++ % 3]);
    }
    f.subtitle("as pride pareto --objectives length,turns computes it; the best path of each algorithm beside it");
    page.add(f, page.file("pareto", problem), problem + ": Pareto front",
             fmt::format("The exact Pareto front of path length and turns on {} (every path that no other beats in "
                         "both), and where each algorithm's best path lies.",
                         escape(problem)));
}

void problem_section(Page& page, const std::string& problem, const std::vector<const StoredRun*>& runs,
                     const ReportData& r, const storage::CampaignStore& s, const PageStore& extra) {
    page.html += fmt::format("<h3 id=\"problem-{}\">{}</h3>\n<div class=\"figures\">\n", escape(page.names.at(problem)),
                             escape(problem));
    page.notes.clear();
    problem_figures(page, problem, runs, r, s, extra);
    page.html += "</div>\n" + page.notes;
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
        std::map<std::string, std::vector<const StoredRun*>> by_problem;
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

#include "experiment/html/problem_figures.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <vector>

#include <fmt/format.h>

#include "experiment/html/colour.hpp"
#include "experiment/html/draw.hpp"
#include "experiment/html/figure.hpp"
#include "experiment/html/front_figures.hpp"
#include "experiment/html/page.hpp"
#include "experiment/html/page_store.hpp"
#include "experiment/storage/reader.hpp"
#include "framework/error.hpp"
#include "problems/grid/pareto.hpp"
#include "problems/grid/path.hpp"

namespace pride::html {
namespace {

using report::ReportData;
using report::ReportRow;
using storage::StoredRun;

constexpr double kInfinity = std::numeric_limits<double>::infinity();
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
                values[i] = at[i] == 0 ? kInfinity : shown(r.history[at[i] - 1]);
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

    // Convergence: algorithms whose runs record a history; the others (whole-map planners, sampling
    // planners) as a line at their median value.
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
    double lo = kInfinity, hi = -kInfinity;
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
        for (const StoredRun* x : by_algorithm[a]) finals.push_back(shown(x->best.value_or(kInfinity)));
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
        // Named as the notes name them: "whole map" only for the planners that evaluate no objective
        // (storage::CampaignStore::whole_map_algorithms); another run without a history (a sampling
        // planner's) is its final value.
        for (const auto& a : flat)
            f.hline(levels[a], page.colour(a),
                    a + (s.whole_map_algorithms.count(a) ? " (whole map)" : " (final value, no history)"),
                    page.dash(a));
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
        lo = kInfinity, hi = -kInfinity;
        std::string missing;
        for (const auto& [a, rs] : by_algorithm) {
            finals.emplace_back();
            std::size_t none = 0;
            for (const StoredRun* x : rs) {
                finals.back().push_back(shown(x->best.value_or(kInfinity)));
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
        labels.push_back(best_path_label(*b, *map));
        colours.push_back(page.colour(b->algorithm));
    }
    const std::string paths_file = page.file("paths", problem);
    const MapWindow window = paths_window(*map, info->start, info->goal, paths);
    draw_grid_paths(*map, info->start, info->goal, paths, labels, page.create(paths_file), PictureFormat::svg, colours,
                    window);
    std::string none;
    for (const auto& entry : by_algorithm) {
        const std::string& a = entry.first;  // (clang 14 captures no structured binding)
        if (std::none_of(best.begin(), best.end(), [&](const BestPath* b) { return b->algorithm == a; }))
            none += " " + escape(a) + " found no feasible path.";
    }
    page.put(paths_file, problem + ": best paths",
             fmt::format("The best path of each algorithm on {} (its lowest value over the seeds), with the exact "
                         "optimum of the objective where the campaign computed it; start green, goal red.{}{}",
                         escape(problem), window_words(*map, window), none));
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

}  // namespace

std::string best_path_label(const BestPath& b, const grid::GridMap& map) {
    std::string label = fmt::format("{}: {} (seed {})", b.algorithm, num(b.value), b.seed);
    if (b.optimum) label += fmt::format(", exact optimum {}", num(*b.optimum));
    if (const auto& frame = map.frame()) {
        // Its length in metres beside cells (the map's frame).
        const grid::Polyline line = b.polyline.empty() ? grid::polyline_of(b.path) : b.polyline;
        double length = 0.0;
        for (std::size_t k = 1; k < line.size(); ++k)
            length += std::hypot(line[k].x - line[k - 1].x, line[k].y - line[k - 1].y);
        label += ", " + length_words(length, *frame);
    }
    return label;
}

void problem_section(Page& page, const std::string& problem, const std::vector<const StoredRun*>& runs,
                     const ReportData& r, const storage::CampaignStore& s, const PageStore& extra) {
    page.html += fmt::format("<h3 id=\"problem-{}\">{}</h3>\n<div class=\"figures\">\n", escape(page.names.at(problem)),
                             escape(problem));
    page.notes.clear();
    problem_figures(page, problem, runs, r, s, extra);
    page.html += "</div>\n" + page.notes;
}

}  // namespace pride::html

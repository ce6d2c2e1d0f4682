#include "experiment/html/front_figures.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>

#include <fmt/format.h>

#include "engine/specs.hpp"
#include "experiment/html/draw.hpp"
#include "experiment/html/figure.hpp"
#include "experiment/html/page.hpp"
#include "framework/error.hpp"
#include "framework/pareto/attainment.hpp"

namespace pride::html {
namespace {

const Rgb kReference{0.74, 0.74, 0.78};  // light: the runs' markers are drawn over it
constexpr Marker kShapes[] = {Marker::diamond, Marker::square, Marker::cross, Marker::circle};

std::string joined(const std::vector<std::string>& names, const char* between) {
    std::string out;
    for (const auto& n : names) out += (out.empty() ? "" : between) + n;
    return out;
}

std::vector<double> row(const Matrix& m, Eigen::Index i) {
    return std::vector<double>(m.row(i).begin(), m.row(i).end());
}

/// A surface's corners as the staircase it bounds: up to `top` above its first corner, out to
/// `right` after its last, so that the line shows the whole region it encloses.
void staircase(const Matrix& corners, double right, double top, std::vector<double>& x, std::vector<double>& y) {
    x.clear(), y.clear();
    if (corners.cols() == 0) return;
    x.push_back(corners(0, 0)), y.push_back(std::max(top, corners(1, 0)));
    for (Eigen::Index j = 0; j < corners.cols(); ++j) x.push_back(corners(0, j)), y.push_back(corners(1, j));
    x.push_back(std::max(right, corners(0, corners.cols() - 1))), y.push_back(corners(1, corners.cols() - 1));
}

/// "length 27.3, turns 4" for a point of a front.
std::string point_words(const std::vector<std::string>& objectives, const Matrix& f, Eigen::Index j) {
    std::string out;
    for (Eigen::Index i = 0; i < f.rows(); ++i)
        out += fmt::format("{}{} {}", i ? ", " : "", objectives[static_cast<std::size_t>(i)], num(f(i, j)));
    return out;
}

}  // namespace

std::size_t attainment_k(double q, std::size_t runs) {
    return std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(q * static_cast<double>(runs))));
}

ProblemFronts problem_fronts(const PageStore& extra, const std::string& problem) {
    ProblemFronts out;
    // The objectives are those of most runs (of equals, the first named): one hand-made run does
    // not decide them.
    std::vector<std::pair<std::vector<std::string>, std::size_t>> counts;
    for (const StoredFront& f : extra.fronts) {
        if (f.problem != problem || !f.error.empty()) continue;
        const auto it =
            std::find_if(counts.begin(), counts.end(), [&](const auto& c) { return c.first == f.objectives; });
        if (it == counts.end())
            counts.emplace_back(f.objectives, 1);
        else
            ++it->second;
    }
    std::size_t most = 0;
    for (const auto& [names, n] : counts)
        if (n > most) out.objectives = names, most = n;
    std::map<std::string, std::vector<const StoredFront*>> by_algorithm;
    for (const StoredFront& f : extra.fronts) {
        if (f.problem != problem) continue;
        const std::string run = fmt::format("{}, seed {}", f.algorithm, f.seed);
        if (!f.error.empty()) {
            out.notes.push_back(
                fmt::format("The front of {} is left out: its solution is damaged ({}).", run, f.error));
            continue;
        }
        if (f.objectives != out.objectives) {
            out.notes.push_back(
                fmt::format("The front of {} is left out: its objectives are {}, those of the other runs {}.", run,
                            joined(f.objectives, ", "), joined(out.objectives, ", ")));
            continue;
        }
        by_algorithm[f.algorithm].push_back(&f);
    }
    for (auto& [algorithm, runs] : by_algorithm) {
        AlgorithmFronts a;
        a.algorithm = algorithm;
        a.runs = runs;
        std::vector<const StoredFront*> ranked = runs;
        std::stable_sort(ranked.begin(), ranked.end(), [](const StoredFront* x, const StoredFront* y) {
            return x->hypervolume_ratio > y->hypervolume_ratio;  // stable: ties stay in seed order
        });
        a.median = ranked[(ranked.size() - 1) / 2];
        if (out.objectives.size() == 2) {
            std::vector<Matrix> sets;
            for (const StoredFront* f : runs) sets.push_back(f->f);
            for (const double q : kAttainmentLevels) {
                a.k.push_back(attainment_k(q, runs.size()));
                a.surfaces.push_back(pareto::attainment_surface(sets, a.k.back()));
            }
        }
        out.algorithms.push_back(std::move(a));
    }
    return out;
}

engine::Problem stored_problem(const storage::CampaignStore& s, const PageStore& extra, const std::string& problem,
                               const std::vector<std::string>& objectives) {
    const auto grid =
        std::find_if(extra.grids.begin(), extra.grids.end(), [&](const GridProblemInfo& g) { return g.id == problem; });
    if (grid != extra.grids.end()) {
        require(!grid->map.empty(), "map", "the map was given in code, not as a file");
        engine::GridSpec spec;
        grid::MapReadOptions read;
        read.unknown_free = grid->unknown_free;
        read.named_in_file = true;  // the store names it: never standard input
        spec.map = engine::load_map(grid->map, grid->inflate, read);
        spec.start = grid->start;
        spec.goal = grid->goal;
        spec.corner_cutting = grid->corner_cutting;
        spec.objectives = joined(objectives, ",");
        return engine::Problem(spec);
    }
    require(s.problems.has_value(), "problem", "the store is from before problems were stored");
    const auto p = std::find_if(s.problems->begin(), s.problems->end(),
                                [&](const storage::StoredProblem& q) { return q.id == problem; });
    require(p != s.problems->end() && p->function && engine::is_multiobjective_problem(*p->function), "problem",
            "the store does not name it as a problem of the multi-objective catalog");
    return engine::Problem(
        engine::ContinuousSpec{*p->function, p->dim, std::nullopt, static_cast<std::int64_t>(objectives.size())});
}

void front_figures(Page& page, const storage::CampaignStore& s, const PageStore& extra, const std::string& problem) {
    const ProblemFronts fronts = problem_fronts(extra, problem);
    for (const auto& note : fronts.notes) page.notes += "<p class=\"note\">" + escape(note) + "</p>\n";
    if (fronts.algorithms.empty()) {
        page.notes += "<p class=\"note\">No front of a run could be read: no figure of fronts.</p>\n";
        return;
    }
    const auto& names = fronts.objectives;
    const std::size_t m = names.size();

    // The reference front, rebuilt as the campaign had it (the same code: engine::Problem).
    std::optional<engine::Problem> reference;
    Matrix front;
    std::string reference_words;
    try {
        reference.emplace(stored_problem(s, extra, problem, names));
        front = reference->reference_front();
        reference_words = fmt::format(
            "{} ({} point{})", reference->is_grid() ? "exact front" : "reference front, the analytic one sampled",
            front.cols(), front.cols() == 1 ? "" : "s");
    } catch (const InputError& e) {
        reference.reset();
        front.resize(0, 0);
        page.notes += "<p class=\"note\">No reference front beside the runs' fronts: " + escape(e.what()) + "</p>\n";
    }
    const bool grid = reference ? reference->is_grid()
                                : std::any_of(extra.grids.begin(), extra.grids.end(),
                                              [&](const GridProblemInfo& g) { return g.id == problem; });
    const std::string x_name = names[0], y_name = names[1];
    const std::string projection =
        m > 2 ? fmt::format("; objectives {} and {} of {} ({}): a projection", x_name, y_name, m, joined(names, ", "))
              : "";

    // Attainment surfaces: two objectives only (a surface of three is not a staircase to draw).
    if (m == 2) {
        double right = front.cols() ? front.row(0).maxCoeff() : -std::numeric_limits<double>::infinity();
        double top = front.cols() ? front.row(1).maxCoeff() : -std::numeric_limits<double>::infinity();
        for (const auto& a : fronts.algorithms)
            for (const Matrix& c : a.surfaces)
                if (c.cols()) right = std::max(right, c.row(0).maxCoeff()), top = std::max(top, c.row(1).maxCoeff());
        Figure f(problem + ": empirical attainment surfaces", Axis{x_name, Scale::linear, {}, {}},
                 Axis{y_name, Scale::linear, {}, {}});
        if (front.cols()) f.markers(row(front, 0), row(front, 1), kReference, reference_words, Marker::circle);
        for (const auto& a : fronts.algorithms) {
            static constexpr int dashes[] = {2, 0, 1};  // 25 %, 50 %, 75 %
            std::vector<double> x, y;
            for (std::size_t l = 0; l < a.surfaces.size(); ++l) {
                staircase(a.surfaces[l], right, top, x, y);
                f.line(x, y, page.colour(a.algorithm),
                       fmt::format("{}: {:g} % (k = {} of {}){}", a.algorithm, 100 * kAttainmentLevels[l], a.k[l],
                                   a.runs.size(), x.empty() ? ": nothing attained" : ""),
                       dashes[l], true);
            }
        }
        f.subtitle("per algorithm: 25 % dotted, 50 % solid, 75 % dashed; k-th surface of n runs, k = ceil(q n)");
        page.add(f, page.file("attainment", problem), problem + ": attainment surfaces",
                 fmt::format("Empirical attainment surfaces on {} (Fonseca and Fleming 1996): per algorithm, the "
                             "boundary of what at least k of its n runs attained (a point is attained by a run when a "
                             "point of its front is no worse in both objectives), for k = ceil(q n), q = 25 %, 50 % "
                             "(the median surface) and 75 %; {}{}.",
                             escape(problem), front.cols() ? "markers: the " : "no reference front",
                             front.cols() ? escape(reference_words) : ""));
    } else {
        page.notes +=
            fmt::format("<p>No attainment surfaces: {} has {} objectives, and they are drawn for two only.</p>\n",
                        escape(problem), m);
    }

    // Each algorithm's median run against the reference front (objectives 1 and 2).
    {
        Figure f(problem + ": fronts of the median runs", Axis{x_name, Scale::linear, {}, {}},
                 Axis{y_name, Scale::linear, {}, {}});
        if (front.cols()) f.markers(row(front, 0), row(front, 1), kReference, reference_words, Marker::circle);
        std::size_t shape = 0;
        std::string which;
        for (const auto& a : fronts.algorithms) {
            const StoredFront& r = *a.median;
            f.markers(row(r.f, 0), row(r.f, 1), page.colour(a.algorithm),
                      fmt::format("{} (seed {}, HV ratio {:.4g}, {} points)", a.algorithm, r.seed, r.hypervolume_ratio,
                                  r.f.cols()),
                      kShapes[shape++ % std::size(kShapes)]);
            which += fmt::format("{}{}: seed {}", which.empty() ? "" : "; ", escape(a.algorithm), r.seed);
        }
        f.subtitle("each algorithm's run of median hypervolume ratio" + projection);
        page.add(f, page.file("fronts", problem), problem + ": fronts of the median runs",
                 fmt::format("The front of each algorithm's median run on {} (its runs ordered by hypervolume ratio; "
                             "of an even number, the better of the two middle ones): {}; against the {}{}.",
                             escape(problem), which, front.cols() ? escape(reference_words) : "(no reference front)",
                             m > 2 ? fmt::format(", in objectives {} and {} of {} (a projection)", escape(x_name),
                                                 escape(y_name), m)
                                   : ""));
    }

    // Grids: the paths of each median run's front on the map.
    if (!grid) return;
    const auto info =
        std::find_if(extra.grids.begin(), extra.grids.end(), [&](const GridProblemInfo& g) { return g.id == problem; });
    const auto map = picture_map(page, info == extra.grids.end() ? nullptr : &*info);
    if (!map) return;
    std::set<std::string> used;
    for (const auto& a : fronts.algorithms) {
        const StoredFront& r = *a.median;
        if (r.paths.empty()) continue;
        std::vector<std::string> labels;
        for (Eigen::Index j = 0; j < r.f.cols(); ++j)
            labels.push_back(point_words(names, r.f, j) + (r.legal[static_cast<std::size_t>(j)] ? "" : " (illegal)"));
        // One file per (problem, algorithm); numbered in the rare case two pairs share a name.
        std::string file = page.file("front-paths", problem);
        file = file.substr(0, file.size() - 4) + "-" + storage::file_name(a.algorithm);
        std::string name = file + ".svg";
        for (int n = 2; used.count(name); ++n) name = fmt::format("{}-{}.svg", file, n);
        used.insert(name);
        std::vector<grid::Polyline> lines;
        for (const grid::Path& p : r.paths) lines.push_back(grid::polyline_of(p));
        const MapWindow window = paths_window(*map, info->start, info->goal, lines);
        draw_grid_paths(*map, info->start, info->goal, lines, labels, page.create(name), PictureFormat::svg, {},
                        window);
        page.put(name, problem + ": paths of " + a.algorithm + "'s median front",
                 fmt::format("The {} paths of the front of {}'s median run on {} (seed {}, hypervolume ratio {:.4g}), "
                             "coloured from blue to red in the front's order (increasing {}); start green, goal red.{}",
                             r.paths.size(), escape(a.algorithm), escape(problem), r.seed, r.hypervolume_ratio,
                             escape(x_name), window_words(*map, window)));
    }
}

}  // namespace pride::html

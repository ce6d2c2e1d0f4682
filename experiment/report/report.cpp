// A report made from a campaign store's runs: per problem and algorithm the statistics of the final
// best values (runs of constrained problems in Deb's order), the tests against the best (per
// function over its instances for suites with instances), Friedman's ranks, the fronts and paths;
// and several stores read as one. Rendered by render.cpp.
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

#include "experiment/report/bootstrap.hpp"
#include "experiment/report/natural_order.hpp"
#include "framework/error.hpp"

namespace pride::report {
namespace {

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

/// The algorithms of one problem (or function) compared: the best, the lowest median of the
/// compared values (ties: the lowest mean), and every other one's rank-sum p against it,
/// Holm-corrected over them, and A12.
struct Comparison {
    std::string best;
    std::map<std::string, std::pair<double, double>> tests;  // algorithm -> (p Holm, A12)
};

template <class Cells, class Compared>
Comparison compare(const Cells& by_algorithm, const Compared& compared) {
    Comparison out;
    double best_median = 0, best_mean = 0;
    for (const auto& [algorithm, c] : by_algorithm) {
        const double md = median_of(compared(c)), mn = mean_of(compared(c));
        if (out.best.empty() || md < best_median || (md == best_median && mn < best_mean)) {
            out.best = algorithm;
            best_median = md;
            best_mean = mn;
        }
    }
    std::vector<double> p_values;
    std::vector<std::string> tested;
    const auto& best = compared(by_algorithm.at(out.best));
    for (const auto& [algorithm, c] : by_algorithm)
        if (algorithm != out.best) {
            p_values.push_back(stats::rank_sum_test(compared(c), best).p_value);
            out.tests[algorithm].second = stats::vargha_delaney_a(compared(c), best);
            tested.push_back(algorithm);
        }
    const auto adjusted = stats::holm(p_values);
    for (std::size_t i = 0; i < tested.size(); ++i) out.tests[tested[i]].first = adjusted[i];
    return out;
}

/// A function of a suite with instances, in one dimension: the unit its instances are pooled in.
struct FunctionKey {
    std::string function;
    std::int64_t dim = 0;
    bool operator<(const FunctionKey& o) const {
        const int c = natural_compare(function, o.function);
        return c != 0 ? c < 0 : dim < o.dim;
    }
};
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

/// Published algorithms (storage/published.hpp) enter a problem's comparison of final values only
/// under the protocol of the campaign's runs there: their runs' mean evaluations within 5 % of those
/// of the campaign's algorithms (a published run stopped at its authors' budget, not the
/// campaign's). The cells left out are named in the notes, with the provenance of every published
/// algorithm; the ERT and ECDFs, which compare runtimes to targets across budgets as COCO does,
/// keep all their runs.
template <class Cells>
void leave_out_other_budgets(ReportData& report, const storage::CampaignStore& store, Cells& cells) {
    if (store.published.empty()) return;
    std::map<std::string, std::vector<std::string>> left_out;  // algorithm -> problems
    std::map<std::string, std::pair<double, double>> budgets;  // algorithm -> (its, the campaign's) of the first
    for (auto& [problem, by_algorithm] : cells) {
        std::vector<double> own;
        for (const auto& [algorithm, c] : by_algorithm)
            if (!store.published.count(algorithm) && !store.whole_map_algorithms.count(algorithm))
                own.insert(own.end(), c.evaluations.begin(), c.evaluations.end());
        if (own.empty()) continue;  // published runs alone: compared among themselves
        const double campaign = mean_of(own);
        for (auto it = by_algorithm.begin(); it != by_algorithm.end();) {
            const double theirs = mean_of(it->second.evaluations);
            if (store.published.count(it->first) && std::max(theirs, campaign) > 1.05 * std::min(theirs, campaign)) {
                left_out[it->first].push_back(problem);
                budgets.emplace(it->first, std::pair{theirs, campaign});
                it = by_algorithm.erase(it);
            } else {
                ++it;
            }
        }
    }
    for (const auto& [id, source] : store.published)
        report.notes.push_back(
            fmt::format("{} holds published runs: {}, read from {} ({} data, SHA-256 {}); "
                        "imported, never run by pride.",
                        id, source.citation, source.source, source.format, source.sha256));
    for (const auto& [algorithm, problems] : left_out) {
        std::string list;
        for (const auto& p : problems) list += (list.empty() ? "" : ", ") + p;
        const auto [theirs, campaign] = budgets.at(algorithm);
        report.notes.push_back(fmt::format(
            "{} is left out of the comparison of final values on {} {} ({}): its runs used other evaluation "
            "budgets than the campaign's (on {}: a mean of {:.0f} evaluations, the campaign's {:.0f}; more than "
            "5 % apart), so their final values are not comparable. Its ERT and ECDF, which compare runtimes to "
            "targets across budgets, are in the COCO analysis.",
            algorithm, problems.size(), problems.size() == 1 ? "problem" : "problems", list, problems.front(), theirs,
            campaign));
    }
}

/// A published algorithm's ERT and ECDF pool the instances its authors ran, which may not be the
/// campaign's (COCO's instances changed from year to year, and its comparisons across years pool
/// them alike): the report says where they differ.
void note_other_instances(ReportData& report, const storage::CampaignStore& store) {
    if (store.published.empty() || !store.problems) return;
    std::map<std::string, const storage::StoredProblem*> problems;
    for (const auto& p : *store.problems) problems[p.id] = &p;
    // (function, dim) -> algorithm -> instances
    std::map<std::pair<std::string, std::int64_t>, std::map<std::string, std::set<std::int64_t>>> instances;
    for (const auto& r : store.runs)
        if (const auto it = problems.find(r.problem); it != problems.end() && !r.target_hits.empty())
            instances[{it->second->function.value_or(r.problem), it->second->dim}][r.algorithm].insert(
                it->second->instance);
    const auto text = [](const std::set<std::int64_t>& s) {
        std::string out;
        for (const auto i : s) out += (out.empty() ? "" : ",") + std::to_string(i);
        return out;
    };
    std::map<std::string, std::vector<std::string>> differ;  // algorithm -> cells
    for (const auto& [cell, by_algorithm] : instances) {
        std::set<std::int64_t> own;
        for (const auto& [algorithm, set] : by_algorithm)
            if (!store.published.count(algorithm)) own.insert(set.begin(), set.end());
        if (own.empty()) continue;
        for (const auto& [algorithm, set] : by_algorithm)
            if (store.published.count(algorithm) && set != own)
                differ[algorithm].push_back(
                    fmt::format("{} {}-D: instances {} against {}", cell.first, cell.second, text(set), text(own)));
    }
    for (const auto& [algorithm, cells] : differ) {
        std::string list;
        for (std::size_t k = 0; k < cells.size() && k < 3; ++k) list += (k ? "; " : "") + cells[k];
        report.notes.push_back(fmt::format(
            "{} ran other instances than the campaign's algorithms on {} function and dimension {} ({}{}): its ERT "
            "and ECDF there pool its own instances, as COCO's comparisons across years do.",
            algorithm, cells.size(), cells.size() == 1 ? "cell" : "cells", list, cells.size() > 3 ? "; ..." : ""));
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
    // Problems that are instances of a function (instance >= 1: BBOB's and bbob-constrained's, a
    // function's seeded instances) are tested per function and dimension over all their instances,
    // as COCO treats instances as repetitions; instance 0 (the function as defined), grids, CEC
    // problems and problems given in code are tested on their own.
    std::map<std::string, const storage::StoredProblem*> problem_of;
    if (store.problems)
        for (const storage::StoredProblem& p : *store.problems) problem_of[p.id] = &p;
    const auto function_of = [&](const std::string& problem) -> std::optional<FunctionKey> {
        const auto it = problem_of.find(problem);
        if (it == problem_of.end() || it->second->instance < 1) return std::nullopt;
        return FunctionKey{it->second->function.value_or(it->second->id), it->second->dim};
    };
    std::map<std::string, std::map<std::string, Cell>, NaturalLess> cells;
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

    leave_out_other_budgets(report, store, cells);
    note_other_instances(report, store);

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
        // constraints, the lowest median rank by Deb's order. An instance of a function is tested
        // with the function's other instances below.
        const Comparison comparison = compare(by_algorithm, compared);
        const std::optional<FunctionKey> function = function_of(problem);
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
            r.best = algorithm == comparison.best;
            if (function) r.function = function->function + " " + std::to_string(function->dim) + "-D";
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
            if (!r.best && !function) {
                const auto& [p_holm, a12] = comparison.tests.at(algorithm);
                r.p_holm = p_holm;
                r.a12 = a12;
            }
            rows.push_back(r);
        }
        equal_evaluations_note(report, store, problem, by_algorithm);
    }

    // The instances of each function pooled, per algorithm: precisions f - f_opt whatever the
    // report shows (values f of different instances are not comparable), a run without a feasible
    // point +inf.
    std::map<FunctionKey, std::map<std::string, Cell>> by_function;
    std::map<FunctionKey, std::map<std::string, std::set<std::int64_t>>> instances;
    for (const auto& [problem, by_algorithm] : cells) {
        const std::optional<FunctionKey> key = function_of(problem);
        if (!key) continue;
        for (const auto& [algorithm, c] : by_algorithm) {
            Cell& f = by_function[*key][algorithm];
            if (f.best.empty()) f.f_opt = 0.0;  // cleared below by an instance without f_opt
            if (!c.f_opt) f.f_opt.reset();
            for (std::size_t i = 0; i < c.best.size(); ++i) {
                const double v = c.f_opt && options.raw ? c.best[i] - *c.f_opt : c.best[i];
                f.best.push_back(c.violation[i] > 0 ? inf : v);
                f.violation.push_back(c.violation[i]);
                f.first_feasible.push_back(c.first_feasible[i]);
                f.wall_ms.push_back(c.wall_ms[i]);
                f.evaluations.push_back(c.evaluations[i]);
            }
            f.constrained = f.constrained || c.constrained;
            instances[*key][algorithm].insert(problem_of.at(problem)->instance);
        }
    }
    for (auto& [key, by_algorithm] : by_function) {
        if (std::any_of(by_algorithm.begin(), by_algorithm.end(), [](const auto& a) { return a.second.constrained; })) {
            for (auto& [algorithm, c] : by_algorithm) c.constrained = true;
            rank_by_deb_order(by_algorithm);
        }
        const Comparison comparison = compare(by_algorithm, compared);
        for (const auto& [algorithm, c] : by_algorithm) {
            FunctionRow r;
            r.function = key.function;
            r.dim = key.dim;
            r.algorithm = algorithm;
            r.runs = c.best.size();
            r.instances = instances.at(key).at(algorithm).size();
            std::vector<double> sorted = c.best;
            std::sort(sorted.begin(), sorted.end());
            r.median = median_of(sorted);
            r.p10 = coco::percentile(sorted, 10);
            r.p90 = coco::percentile(sorted, 90);
            r.mean = mean_of(sorted);
            r.precision = c.f_opt.has_value();
            if (r.precision)
                r.solved = static_cast<std::size_t>(
                    std::count_if(sorted.begin(), sorted.end(), [](double v) { return v <= solved_precision; }));
            if (c.constrained)
                r.feasible_runs = static_cast<std::size_t>(
                    std::count_if(c.violation.begin(), c.violation.end(), [](double v) { return v == 0; }));
            r.best = algorithm == comparison.best;
            if (!r.best) {
                const auto& [p_holm, a12] = comparison.tests.at(algorithm);
                r.p_holm = p_holm;
                r.a12 = a12;
            }
            report.functions.push_back(r);
        }
    }

    // Friedman over the blocks, on their median compared values, for the algorithms run on all of
    // them: each problem tested on its own, and each function over its instances.
    std::vector<const std::map<std::string, Cell>*> blocks_of;
    for (const auto& [problem, by_algorithm] : cells)
        if (!function_of(problem)) blocks_of.push_back(&by_algorithm);
    for (const auto& [key, by_algorithm] : by_function) blocks_of.push_back(&by_algorithm);
    std::map<std::string, std::size_t> count;
    for (const auto* block : blocks_of)
        for (const auto& [algorithm, c] : *block) ++count[algorithm];
    std::vector<std::string> algorithms;
    for (const auto& [algorithm, n] : count)
        if (n == blocks_of.size()) algorithms.push_back(algorithm);
    if (algorithms.size() >= 2 && blocks_of.size() >= 2) {
        std::vector<std::vector<double>> blocks;
        for (const auto* block : blocks_of) {
            std::vector<double> values;
            for (const auto& a : algorithms) values.push_back(median_of(compared(block->at(a))));
            blocks.push_back(values);
        }
        report.friedman =
            FriedmanSummary{algorithms, blocks.size(), by_function.size(), stats::friedman(blocks), {}, {}};
        report.friedman->pairs = stats::friedman_pairs(report.friedman->test.average_ranks, blocks.size());
        report.friedman->critical_difference =
            stats::critical_difference(report.friedman->test.average_ranks, blocks.size(), 0.05);
    }
    std::set<std::string, NaturalLess> fronts;
    std::map<std::string, std::map<std::string, std::vector<const storage::StoredRun*>>, NaturalLess> by_front;
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
    std::map<std::string, std::map<std::string, std::vector<const storage::StoredRun*>>, NaturalLess> by_path;
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
            // Metres only where every run with a length has them too (a store resumed across the
            // key's introduction has runs without): a median of some runs' lengths is not the column's.
            if (values[storage::kPathLengthMetres].size() != values[0].size())
                values[storage::kPathLengthMetres].clear();
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

std::vector<std::optional<double>> PathRow::columns(bool metres) const {
    std::vector<std::optional<double>> out;
    for (std::size_t k = 0; k < medians.size(); ++k) {
        if (k == storage::kPathLengthMetres) continue;
        out.push_back(medians[k]);
        if (k == 0 && metres)
            out.push_back(medians.size() > storage::kPathLengthMetres ? medians[storage::kPathLengthMetres]
                                                                      : std::nullopt);
    }
    return out;
}

bool paths_in_metres(const std::vector<PathRow>& rows) {
    return std::any_of(rows.begin(), rows.end(), [](const PathRow& r) {
        return r.medians.size() > storage::kPathLengthMetres && r.medians[storage::kPathLengthMetres];
    });
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
        all.published.insert(s.published.begin(), s.published.end());
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

}  // namespace pride::report

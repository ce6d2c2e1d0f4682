#include "experiment/report/coco.hpp"

#include "experiment/report/bootstrap.hpp"
#include "experiment/report/natural_order.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <tuple>

namespace pride::report::coco {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

/// A string as a JSON string.
std::string json_string(const std::string& s) {
    std::string out = "\"";
    for (const char c : s) {
        if (c == '"' || c == '\\')
            out += std::string("\\") + c;
        else if (static_cast<unsigned char>(c) < 0x20)
            out += fmt::format("\\u{:04x}", static_cast<unsigned>(static_cast<unsigned char>(c)));
        else
            out += c;
    }
    return out + "\"";
}

/// A finite number as JSON (the shortest form that reads back as the same double); null else.
std::string json_number(double v) {
    return std::isfinite(v) ? fmt::format("{}", v) : "null";
}

}  // namespace

Ert ert(const std::vector<TargetRun>& runs) {
    Ert e;
    e.runs = runs.size();
    double spent = 0;
    for (const TargetRun& r : runs) {
        spent += static_cast<double>(r.hit ? *r.hit : r.evaluations);
        if (r.hit) ++e.successes;
    }
    e.value = e.successes ? spent / static_cast<double>(e.successes) : inf;
    return e;
}

Ecdf ecdf(const std::vector<TargetRun>& pairs) {
    // Hansen et al. (2016), "COCO: Performance assessment", arXiv:1605.03560: the ECDF of the
    // runtimes of a set of (run, target) pairs is, for a budget b, the fraction of the pairs
    // whose target was reached within b evaluations; with budgets per dimension, b * dim, and
    // plotted against log10(b). Unreached targets stay in the denominator, so the curve ends
    // below 1 when some target was never reached.
    Ecdf out;
    out.pairs = pairs.size();
    out.max_budget = -inf;
    std::vector<double> runtimes;  // evaluations / dimension of the reached pairs
    for (const TargetRun& p : pairs) {
        const double dim = static_cast<double>(std::max<std::int64_t>(p.dim, 1));
        out.max_budget = std::max(out.max_budget, std::log10(static_cast<double>(p.evaluations) / dim));
        if (p.hit) runtimes.push_back(static_cast<double>(*p.hit) / dim);
    }
    std::sort(runtimes.begin(), runtimes.end());
    for (std::size_t k = 0; k < runtimes.size(); ++k) {
        if (k + 1 < runtimes.size() && runtimes[k + 1] == runtimes[k]) continue;  // one point per runtime
        out.x.push_back(std::log10(runtimes[k]));
        out.y.push_back(static_cast<double>(k + 1) / static_cast<double>(pairs.size()));
    }
    return out;
}

std::optional<std::string> bbob_group(std::int64_t fid) {
    if (fid >= 1 && fid <= 5) return "separable";
    if (fid >= 6 && fid <= 9) return "moderate";
    if (fid >= 10 && fid <= 14) return "ill-conditioned";
    if (fid >= 15 && fid <= 19) return "multimodal";
    if (fid >= 20 && fid <= 24) return "weakly-structured";
    return std::nullopt;
}

std::string bbob_group_title(const std::string& group) {
    if (group == "separable") return "separable functions f1-f5";
    if (group == "moderate") return "low or moderate conditioning f6-f9";
    if (group == "ill-conditioned") return "high conditioning and unimodal f10-f14";
    if (group == "multimodal") return "multimodal, adequate global structure f15-f19";
    if (group == "weakly-structured") return "multimodal, weak global structure f20-f24";
    return "all functions";
}

namespace {
/// The ECDF groups a problem's pairs count in: "all", and its BBOB function group.
std::vector<std::string> groups_of(const storage::StoredProblem& p) {
    std::vector<std::string> in{"all"};
    if (p.suite == "bbob" && p.fid)
        if (const auto g = bbob_group(*p.fid)) in.push_back(*g);
    return in;
}
}  // namespace

std::optional<Analysis> analyse(const storage::CampaignStore& store) {
    if (!store.precisions || store.precisions->empty() || !store.problems) return std::nullopt;
    Analysis a;
    a.precisions = *store.precisions;
    const std::size_t n = a.precisions.size();
    std::map<std::string, const storage::StoredProblem*> problems;
    if (store.problems)
        for (const storage::StoredProblem& p : *store.problems) problems[p.id] = &p;

    // (fid or none, function, dim, algorithm) -> the runs, per precision; and their instances.
    using Key = std::tuple<std::int64_t, std::string, std::int64_t, std::string>;
    struct Cell {
        const storage::StoredProblem* problem = nullptr;
        std::string function;
        std::vector<std::vector<TargetRun>> per_precision;
        std::set<std::pair<std::string, std::int64_t>> instances;  // (problem id, instance)
        std::size_t runs = 0;
    };
    // Functions without a number in natural order (natural_order.hpp), as every listing of the report.
    const auto before = [](const Key& a, const Key& b) {
        if (std::get<0>(a) != std::get<0>(b)) return std::get<0>(a) < std::get<0>(b);
        if (const int c = natural_compare(std::get<1>(a), std::get<1>(b)); c != 0) return c < 0;
        return std::tie(std::get<2>(a), std::get<3>(a)) < std::tie(std::get<2>(b), std::get<3>(b));
    };
    std::map<Key, Cell, decltype(before)> cells(before);
    // group -> algorithm -> (pairs, dims)
    std::map<std::string, std::map<std::string, std::pair<std::vector<TargetRun>, std::set<std::int64_t>>>> groups;
    for (const storage::StoredRun& r : store.runs) {
        if (r.target_hits.empty()) {
            ++a.runs_without_hits;
            continue;
        }
        const auto it = problems.find(r.problem);
        if (it == problems.end()) continue;  // read_store refuses such runs when precisions are recorded
        const storage::StoredProblem& p = *it->second;
        // Instances are pooled only within one family: BBOB's (all >= 1), or a function's seeded
        // instances k >= 1 (shifted and rotated alike); instance 0, the function as defined (its
        // optimum often at the origin), is a problem of its own.
        std::string function = p.function.value_or(p.id);
        if (p.suite != "bbob" && p.instance >= 1) function += " (instances k >= 1)";
        Cell& c = cells[Key{p.fid.value_or(std::numeric_limits<std::int64_t>::max()), function, p.dim, r.algorithm}];
        c.problem = &p;
        c.function = function;
        c.per_precision.resize(n);
        c.instances.emplace(p.id, p.instance);
        ++c.runs;
        const std::vector<std::string> in = groups_of(p);
        for (std::size_t k = 0; k < n; ++k) {
            const TargetRun t{r.evaluations, r.target_hits[k], p.dim};
            c.per_precision[k].push_back(t);
            for (const auto& g : in) {
                auto& [pairs, dims] = groups[g][r.algorithm];
                pairs.push_back(t);
                dims.insert(p.dim);
            }
        }
    }
    // A seed per row and curve, from its name: the same store gives the same intervals and curves.
    const auto seed_of = [](const std::string& text) {
        std::uint64_t h = 1469598103934665603ull;  // FNV-1a
        for (const unsigned char ch : text) h = (h ^ ch) * 1099511628211ull;
        return h;
    };
    // group -> algorithm -> the runs of each (function, dimension, precision): the restarts' pairs
    std::map<std::string, std::map<std::string, std::vector<std::vector<TargetRun>>>> restart_pairs;
    for (const auto& [key, c] : cells) {
        ErtRow row;
        row.function = c.function;
        row.fid = c.problem->fid;
        row.suite = c.problem->suite;
        row.dim = std::get<2>(key);
        row.algorithm = std::get<3>(key);
        row.runs = c.runs;
        row.instances = c.instances.size();
        const std::uint64_t seed = seed_of(fmt::format("{}\x1f{}\x1f{}", row.function, row.dim, row.algorithm));
        for (std::size_t k = 0; k < c.per_precision.size(); ++k) {
            const auto& runs = c.per_precision[k];
            row.ert.push_back(ert(runs));
            row.ert_interval.push_back(ert_confidence(runs, kErtResamples, seed + k));
        }
        const std::vector<std::string> in = groups_of(*c.problem);
        for (const auto& g : in)
            for (const auto& runs : c.per_precision) restart_pairs[g][row.algorithm].push_back(runs);
        a.erts.push_back(std::move(row));
    }
    if (a.erts.empty()) return std::nullopt;  // no run records hits (grids: no known optimum)
    for (const char* g : {"all", "separable", "moderate", "ill-conditioned", "multimodal", "weakly-structured"}) {
        const auto it = groups.find(g);
        if (it == groups.end()) continue;
        for (const auto& [algorithm, data] : it->second)
            a.curves.push_back(EcdfCurve{
                g, algorithm, std::vector<std::int64_t>(data.second.begin(), data.second.end()), ecdf(data.first),
                ecdf_simulated_restarts(restart_pairs.at(g).at(algorithm), kRestartSamples,
                                        seed_of(std::string(g) + "\x1f" + algorithm))});
    }
    return a;
}

std::string ecdf_json(const std::string& campaign, const Analysis& analysis) {
    std::string text = "{\"campaign\": " + json_string(campaign) + ", \"precisions\": [";
    for (std::size_t k = 0; k < analysis.precisions.size(); ++k)
        text += (k ? ", " : "") + json_number(analysis.precisions[k]);
    text += "], \"groups\": [";
    bool first_group = true;
    for (std::size_t i = 0; i < analysis.curves.size();) {
        const std::string& group = analysis.curves[i].group;
        std::set<std::int64_t> dims;
        std::string curves;
        for (; i < analysis.curves.size() && analysis.curves[i].group == group; ++i) {
            const EcdfCurve& c = analysis.curves[i];
            dims.insert(c.dims.begin(), c.dims.end());
            std::string x, y;
            for (std::size_t k = 0; k < c.ecdf.x.size(); ++k) {
                x += (k ? ", " : "") + json_number(c.ecdf.x[k]);
                y += (k ? ", " : "") + json_number(c.ecdf.y[k]);
            }
            std::string rx, ry;
            for (std::size_t k = 0; k < c.restarts.x.size(); ++k) {
                rx += (k ? ", " : "") + json_number(c.restarts.x[k]);
                ry += (k ? ", " : "") + json_number(c.restarts.y[k]);
            }
            curves += fmt::format(
                "{}{{\"algorithm\": {}, \"pairs\": {}, \"max_budget\": {}, \"x\": [{}], \"y\": [{}], "
                "\"restarts\": {{\"pairs\": {}, \"x\": [{}], \"y\": [{}]}}}}",
                curves.empty() ? "" : ", ", json_string(c.algorithm), c.ecdf.pairs, json_number(c.ecdf.max_budget), x,
                y, c.restarts.pairs, rx, ry);
        }
        text +=
            fmt::format("{}{{\"group\": {}, \"title\": {}, \"dims\": [{}], \"curves\": [{}]}}", first_group ? "" : ", ",
                        json_string(group), json_string(bbob_group_title(group)), fmt::join(dims, ", "), curves);
        first_group = false;
    }
    return text + "]}\n";
}

}  // namespace pride::report::coco

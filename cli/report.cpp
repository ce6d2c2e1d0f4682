#include "cli/report.hpp"

#include <fmt/format.h>
#include <sqlite3.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <ostream>
#include <sstream>
#include <vector>

#include "framework/error.hpp"
#include "framework/statistics.hpp"

namespace pride::cli {
namespace {

struct Cell {                  // one (problem, algorithm): its runs
    std::vector<double> best;  // +inf for a run without a feasible value
    std::vector<double> wall_ms, evaluations;
    std::optional<double> optimum;
    std::vector<std::optional<double>> to_target;  // evaluations when the best first reached the target
};

/// The evaluations at which a run's best value first reached `target` (from its history).
std::optional<double> evaluations_to(double target, const std::string& history, const std::string& evaluations) {
    auto numbers = [](std::string text) {
        for (char& c : text)
            if (c == '[' || c == ']' || c == ',') c = ' ';
        std::vector<double> out;
        std::istringstream in(text);
        for (std::string t; in >> t;)
            out.push_back(t == "null" ? std::numeric_limits<double>::infinity() : std::stod(t));
        return out;
    };
    const auto h = numbers(history), e = numbers(evaluations);
    for (std::size_t k = 0; k < h.size() && k < e.size(); ++k)
        if (h[k] <= target) return e[k];
    return std::nullopt;
}

struct Row {
    std::string problem, algorithm;
    std::size_t runs = 0;
    double min = 0, mean = 0, std = 0, median = 0, max = 0, wall = 0, evaluations = 0;
    std::optional<double> optimum, gap, success;
    std::optional<double> p_holm;     // against the best algorithm of the problem; empty for the best itself
    std::size_t reached = 0;          // runs that reached the target
    std::optional<double> to_target;  // their mean evaluations to reach it
    bool best = false;
};

double median_of(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double mean_of(const std::vector<double>& v) {
    return std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
}

/// The sample standard deviation (n - 1); 0 for a single run.
double std_of(const std::vector<double>& v) {
    if (v.size() < 2) return 0.0;
    const double m = mean_of(v);
    double s = 0.0;
    for (double x : v) s += (x - m) * (x - m);
    return std::sqrt(s / static_cast<double>(v.size() - 1));
}

std::map<std::string, std::map<std::string, Cell>> load(const std::string& path, std::string& name,
                                                        std::optional<double>& target) {
    require(std::filesystem::is_regular_file(path), path, "no such store");
    sqlite3* db = nullptr;
    if (sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) != SQLITE_OK) {
        sqlite3_close(db);
        throw InputError(path + ": cannot open the store");
    }
    std::map<std::string, std::map<std::string, Cell>> cells;
    auto query = [&](const char* sql, auto&& row) {
        sqlite3_stmt* s = nullptr;
        if (sqlite3_prepare_v2(db, sql, -1, &s, nullptr) != SQLITE_OK) {
            const std::string why = sqlite3_errmsg(db);
            sqlite3_close(db);
            throw InputError(path + ": not a campaign store (" + why + ")");
        }
        while (sqlite3_step(s) == SQLITE_ROW) row(s);
        sqlite3_finalize(s);
    };
    bool has_target = false;  // stores written before targets existed have no such column
    query("SELECT COUNT(*) FROM pragma_table_info('campaign') WHERE name = 'target'",
          [&](sqlite3_stmt* s) { has_target = sqlite3_column_int(s, 0) > 0; });
    query(
        has_target ? "SELECT name, target FROM campaign WHERE id = 1" : "SELECT name, NULL FROM campaign WHERE id = 1",
        [&](sqlite3_stmt* s) {
            name = reinterpret_cast<const char*>(sqlite3_column_text(s, 0));
            if (sqlite3_column_type(s, 1) != SQLITE_NULL) target = sqlite3_column_double(s, 1);
        });
    query(
        "SELECT problem, algorithm, best, wall_ms, evaluations, optimum, history, history_evaluations FROM runs "
        "ORDER BY problem, algorithm, seed",
        [&](sqlite3_stmt* s) {
            Cell& c = cells[reinterpret_cast<const char*>(sqlite3_column_text(s, 0))]
                           [reinterpret_cast<const char*>(sqlite3_column_text(s, 1))];
            c.best.push_back(sqlite3_column_type(s, 2) == SQLITE_NULL ? std::numeric_limits<double>::infinity()
                                                                      : sqlite3_column_double(s, 2));
            c.wall_ms.push_back(sqlite3_column_double(s, 3));
            c.evaluations.push_back(static_cast<double>(sqlite3_column_int64(s, 4)));
            if (sqlite3_column_type(s, 5) != SQLITE_NULL) c.optimum = sqlite3_column_double(s, 5);
            if (target)
                c.to_target.push_back(evaluations_to(*target, reinterpret_cast<const char*>(sqlite3_column_text(s, 6)),
                                                     reinterpret_cast<const char*>(sqlite3_column_text(s, 7))));
        });
    sqlite3_close(db);
    require(!cells.empty(), path, "holds no runs yet (run pride bench first)");
    return cells;
}

std::string num(double v) {
    return std::isfinite(v) ? fmt::format("{:.6g}", v) : "inf";
}

/// A CSV field, quoted as RFC 4180 says when it holds a comma, a quote or a line break.
std::string csv(const std::string& s) {
    if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
    std::string out = "\"";
    for (const char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

/// Text for a markdown table cell: a | would start a new column.
std::string markdown(const std::string& s) {
    std::string out;
    for (const char c : s) out += c == '|' ? std::string("\\|") : std::string(1, c);
    return out;
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

}  // namespace

namespace {
/// Runs scripts/plot_campaign.py with Debian's python3 (the one python3-matplotlib serves).
void plot(const std::string& store, const std::string& folder) {
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    require(!ec && std::filesystem::is_directory(folder), "--plots", folder + ": cannot create the folder");
    const std::string python = std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
    const std::string script = std::string(PRIDE_SCRIPTS_DIR) + "/plot_campaign.py";
    require(std::filesystem::exists(script), "--plots", script + " is missing");
    const std::string check = "'" + python + "' -c 'import matplotlib' >/dev/null 2>&1";
    require(std::system(check.c_str()) == 0, "--plots",
            "needs python3 with matplotlib (apt-get install python3-matplotlib)");
    const std::string command = "'" + python + "' '" + script + "' '" + store + "' '" + folder + "'";
    require(std::system(command.c_str()) == 0, "--plots", "the plotting script failed (see above)");
}
}  // namespace

int report_command(const ReportOptions& o, std::ostream& out) {
    require(o.format == "md" || o.format == "csv" || o.format == "latex", "--format",
            "expected md, csv or latex, got '" + o.format + "'");
    std::string name;
    std::optional<double> target;
    const auto cells = load(o.store, name, target);

    std::vector<Row> rows;
    std::vector<std::string> algorithms;  // present on every problem, for Friedman
    for (const auto& [problem, by_algorithm] : cells) {
        // The best algorithm of the problem: the lowest median best value (ties: lowest mean).
        std::string best;
        double best_median = 0, best_mean = 0;
        for (const auto& [algorithm, c] : by_algorithm) {
            const double md = median_of(c.best), mn = mean_of(c.best);
            if (best.empty() || md < best_median || (md == best_median && mn < best_mean)) {
                best = algorithm;
                best_median = md;
                best_mean = mn;
            }
        }
        std::vector<double> p_values;
        std::vector<std::size_t> tested;
        for (const auto& [algorithm, c] : by_algorithm) {
            Row r;
            r.problem = problem;
            r.algorithm = algorithm;
            r.runs = c.best.size();
            r.min = *std::min_element(c.best.begin(), c.best.end());
            r.max = *std::max_element(c.best.begin(), c.best.end());
            r.mean = mean_of(c.best);
            r.std = std_of(c.best);
            r.median = median_of(c.best);
            r.wall = mean_of(c.wall_ms);
            r.evaluations = mean_of(c.evaluations);
            r.best = algorithm == best;
            if (target) {
                double sum = 0.0;
                for (const auto& e : c.to_target)
                    if (e) {
                        ++r.reached;
                        sum += *e;
                    }
                if (r.reached) r.to_target = sum / static_cast<double>(r.reached);
            }
            if (c.optimum) {
                r.optimum = c.optimum;
                double gap = 0, success = 0;
                for (double v : c.best) {
                    const bool at = std::abs(v - *c.optimum) <= 1e-9 * std::max(1.0, std::abs(*c.optimum));
                    // gap = (value - optimum) / optimum, as pride path reports it: infinite when the
                    // optimum is 0 and the value is not.
                    gap += at ? 0.0
                              : (*c.optimum != 0 ? (v - *c.optimum) / std::abs(*c.optimum)
                                                 : std::numeric_limits<double>::infinity());
                    success += at ? 1.0 : 0.0;
                }
                r.gap = gap / static_cast<double>(r.runs);
                r.success = success / static_cast<double>(r.runs);
            }
            if (!r.best) {
                p_values.push_back(stats::rank_sum_test(c.best, by_algorithm.at(best).best).p_value);
                tested.push_back(rows.size());
            }
            rows.push_back(r);
        }
        const auto adjusted = stats::holm(p_values);
        for (std::size_t i = 0; i < tested.size(); ++i) rows[tested[i]].p_holm = adjusted[i];
    }
    // Friedman over the problems, on the median best value, for the algorithms run on all of them.
    std::vector<std::vector<double>> blocks;
    std::optional<stats::FriedmanTest> friedman;
    {
        std::map<std::string, std::size_t> count;
        for (const auto& [problem, by_algorithm] : cells)
            for (const auto& [algorithm, c] : by_algorithm) ++count[algorithm];
        for (const auto& [algorithm, n] : count)
            if (n == cells.size()) algorithms.push_back(algorithm);
        if (algorithms.size() >= 2 && cells.size() >= 2) {
            for (const auto& [problem, by_algorithm] : cells) {
                std::vector<double> block;
                for (const auto& a : algorithms) block.push_back(median_of(by_algorithm.at(a).best));
                blocks.push_back(block);
            }
            friedman = stats::friedman(blocks);
        }
    }

    std::string text;
    if (o.format == "csv") {
        text =
            "problem,algorithm,runs,min,mean,std,median,max,mean_wall_ms,mean_evaluations,optimum,mean_gap,success,"
            "p_holm_vs_best,best";
        // Only campaigns with a target have its columns.
        text += target ? ",target,reached_target,mean_evaluations_to_target\n" : "\n";
        for (const auto& r : rows) {
            text += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}", csv(r.problem), csv(r.algorithm),
                                r.runs, num(r.min), num(r.mean), num(r.std), num(r.median), num(r.max), num(r.wall),
                                num(r.evaluations), r.optimum ? num(*r.optimum) : "", r.gap ? num(*r.gap) : "",
                                r.success ? num(*r.success) : "", r.p_holm ? num(*r.p_holm) : "", r.best ? 1 : 0);
            text += target ? fmt::format(",{},{},{}\n", num(*target), r.reached, r.to_target ? num(*r.to_target) : "")
                           : "\n";
        }
    } else {
        const bool md = o.format == "md";
        const std::string sep = md ? " | " : " & ", end = md ? " |\n" : " \\\\\n", begin = md ? "| " : "";
        auto line = [&](const std::vector<std::string>& cols) {
            std::string s = begin;
            for (std::size_t i = 0; i < cols.size(); ++i)
                s += (i ? sep : "") + (md ? markdown(cols[i]) : latex(cols[i]));
            return s + end;
        };
        std::vector<std::string> head{"problem", "algorithm", "runs",    "min", "mean",    "std",
                                      "median",  "max",       "mean ms", "gap", "optimal", "p (Holm)"};
        if (target) head.push_back("evals to target");
        if (md) {
            text += fmt::format(
                "Campaign `{}`. Per problem, `best` marks the algorithm with the lowest median; "
                "p (Holm) is the Wilcoxon rank-sum test of each other algorithm against it, Holm-corrected "
                "over the problem's algorithms, with `*` where p < 0.05.\n\n",
                name);
            text += line(head) + "|";
            for (std::size_t i = 0; i < head.size(); ++i) text += i < 2 ? "---|" : "---:|";
            text += "\n";
        } else {
            text +=
                "\\begin{tabular}{ll" + std::string(head.size() - 2, 'r') + "}\n\\hline\n" + line(head) + "\\hline\n";
        }
        for (const auto& r : rows) {
            const std::string p =
                r.best ? "best" : (r.p_holm ? fmt::format("{:.3g}{}", *r.p_holm, *r.p_holm < 0.05 ? "*" : "") : "");
            std::vector<std::string> cols{r.problem,
                                          r.algorithm,
                                          std::to_string(r.runs),
                                          num(r.min),
                                          num(r.mean),
                                          num(r.std),
                                          num(r.median),
                                          num(r.max),
                                          fmt::format("{:.3f}", r.wall),
                                          r.gap ? fmt::format("{:.2f} %", 100 * *r.gap) : "-",
                                          r.success ? fmt::format("{:.0f} %", 100 * *r.success) : "-",
                                          p};
            if (target)  // mean over the runs that reached it, and how many did
                cols.push_back(r.to_target ? fmt::format("{} ({}/{})", num(*r.to_target), r.reached, r.runs)
                                           : fmt::format("- (0/{})", r.runs));
            text += line(cols);
        }
        if (!md) text += "\\hline\n\\end{tabular}\n";
        if (friedman) {
            text += md ? "\nFriedman average ranks over " : "\n% Friedman average ranks over ";
            text += fmt::format("{} problems (1 = best; median values):", cells.size());
            for (std::size_t j = 0; j < algorithms.size(); ++j)
                text += fmt::format(" {} {:.3g}{}", algorithms[j], friedman->average_ranks[j],
                                    j + 1 < algorithms.size() ? "," : "");
            text += fmt::format("; chi-squared {:.4g}, p = {:.3g}\n", friedman->statistic, friedman->p_value);
        }
    }
    if (!o.plots.empty()) plot(o.store, o.plots);
    out << text;
    return 0;
}

}  // namespace pride::cli

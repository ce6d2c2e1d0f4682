// The grid planners on Moving AI scenarios; prints numbers, asserts nothing.
//   JPS against A* (the same octile lengths; a mismatch is reported): expansions and microseconds
//   per query, medians over the file's queries; Theta* and Lazy Theta*: microseconds, line-of-sight
//   tests per query (medians) and the mean length as a share of A*'s; with --oracle, the exact
//   any-angle oracle too (microseconds per query, and the mean of Theta*'s length over the oracle's);
//   with --ompl (when built with OMPL), each OMPL planner of problems/grid/planners/ompl_planner.hpp on the
//   file's first --ompl-queries queries, each run once with a budget of --ompl-checks validity
//   checks and seed 1: the median milliseconds to its first solution (over the solved queries) and
//   the share of queries solved.
// Each query runs --reps times on one reused planner and keeps its least time (the machine may be
// shared); one planner object serves the whole file, as a connector reuses one.
// Usage: planner_bench --scen FILE.scen ... [--reps N] [--oracle] [--ompl [--ompl-checks N] [--ompl-queries N]]
#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <map>
#include <vector>

#include "problems/grid/map_io.hpp"
#include "problems/grid/planners/any_angle.hpp"
#include "problems/grid/planners/astar.hpp"
#include "problems/grid/planners/jps.hpp"
#include "problems/grid/planners/theta_star.hpp"
#ifdef PRIDE_HAVE_OMPL
#include "problems/grid/planners/ompl_planner.hpp"
#endif

namespace {

using namespace pride::grid;
using Clock = std::chrono::steady_clock;

double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/// The least wall time of `reps` runs of f, in microseconds; f's last result in `result`.
template <class F>
double least_us(int reps, F&& f, double& result) {
    double best = 1e300;
    for (int r = 0; r < reps; ++r) {
        const auto t = Clock::now();
        result = f();
        best = std::min(best, std::chrono::duration<double, std::micro>(Clock::now() - t).count());
    }
    return best;
}

/// What --ompl asks for: 0 queries when it is off.
struct OmplBench {
    int queries = 0;
    long checks = 20000;
};

void bench_file(const std::string& scen, int reps, bool with_oracle, const OmplBench& ompl) {
    const auto entries = read_scenario(scen);
    const auto dir = std::filesystem::path(scen).parent_path();
    std::map<std::string, GridMap> maps;
    for (const auto& e : entries)
        if (!maps.count(e.map)) maps.emplace(e.map, read_map((dir / e.map).string()));
    std::map<std::string, AnyAngleOracle> oracles;
    AStar astar;
    JumpPointSearch jps;
    ThetaStar theta, lazy(true);
    std::vector<double> a_exp, j_exp, a_us, j_us, t_us, l_us, t_los, l_los, o_us;
    double t_share = 0.0, l_share = 0.0, t_over = 0.0, l_over = 0.0;
    int mismatches = 0, counted = 0;
    for (const auto& e : entries) {
        const GridMap& m = maps.at(e.map);
        double la = 0.0, lj = 0.0, lt = 0.0, ll = 0.0, lo = 0.0;
        auto ea = astar.expansions(), ej = jps.expansions();
        a_us.push_back(least_us(
            reps, [&] { return astar.search(m, e.start, e.goal); }, la));
        j_us.push_back(least_us(
            reps, [&] { return jps.search(m, e.start, e.goal); }, lj));
        a_exp.push_back(static_cast<double>(astar.expansions() - ea) / reps);
        j_exp.push_back(static_cast<double>(jps.expansions() - ej) / reps);
        if (std::abs(la - lj) > 1e-9) ++mismatches;
        auto ct = theta.los_checks(), cl = lazy.los_checks();
        t_us.push_back(least_us(
            reps, [&] { return theta.search(m, e.start, e.goal); }, lt));
        l_us.push_back(least_us(
            reps, [&] { return lazy.search(m, e.start, e.goal); }, ll));
        t_los.push_back(static_cast<double>(theta.los_checks() - ct) / reps);
        l_los.push_back(static_cast<double>(lazy.los_checks() - cl) / reps);
        if (la > 0.0) {
            t_share += lt / la;
            l_share += ll / la;
            ++counted;
        }
        if (with_oracle) {
            auto it = oracles.find(e.map);
            if (it == oracles.end()) it = oracles.emplace(e.map, AnyAngleOracle(m)).first;
            o_us.push_back(least_us(
                1, [&] { return it->second.solve(e.start, e.goal); }, lo));
            if (lo > 0.0) {
                t_over += lt / lo;
                l_over += ll / lo;
            }
        }
    }
    const double n = std::max(counted, 1);
    fmt::print("{},{},{},{:.0f},{:.0f},{:.1f},{:.1f},{:.1f},{:.1f},{:.0f},{:.0f},{:.4f},{:.4f}",
               std::filesystem::path(scen).filename().string(), entries.size(), mismatches, median(a_exp),
               median(j_exp), median(a_us), median(j_us), median(t_us), median(l_us), median(t_los), median(l_los),
               t_share / n, l_share / n);
    if (with_oracle) fmt::print(",{:.1f},{:.5f},{:.5f}", median(o_us), t_over / n, l_over / n);
#ifdef PRIDE_HAVE_OMPL
    if (ompl.queries > 0)
        for (const auto& name : ompl_planner_names()) {
            OmplRequest r;
            r.planner = name;
            r.max_checks = ompl.checks;
            std::vector<double> first_ms;
            std::size_t runs = 0;
            for (const auto& e : entries) {
                if (runs == static_cast<std::size_t>(ompl.queries)) break;
                ++runs;
                const OmplOutcome o = plan_with_ompl(maps.at(e.map), e.start, e.goal, r);
                if (o.solved) first_ms.push_back(o.first_solution_ms);
            }
            fmt::print(",{:.2f},{:.3f}", median(first_ms),
                       static_cast<double>(first_ms.size()) / std::max<std::size_t>(runs, 1));
        }
#else
    (void)ompl;
#endif
    fmt::print("\n");
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> scens;
    int reps = 3;
    bool oracle = false, with_ompl = false;
    OmplBench ompl;
    int ompl_queries = 20;
    CLI::App app{"JPS against A*, Theta* and Lazy Theta* on Moving AI scenarios"};
    app.add_option("--scen", scens, "Moving AI scenario files")->required();
    app.add_option("--reps", reps, "runs per query and planner; the least time is kept (default 3)")
        ->check(CLI::PositiveNumber);
    app.add_flag("--oracle", oracle, "also the exact any-angle oracle (slow on large maps)");
    app.add_flag("--ompl", with_ompl, "also OMPL's planners: time to first solution and share solved");
    app.add_option("--ompl-checks", ompl.checks, "validity checks per OMPL run (default 20000)")
        ->check(CLI::PositiveNumber);
    app.add_option("--ompl-queries", ompl_queries, "queries per file for OMPL, the first ones (default 20)")
        ->check(CLI::PositiveNumber);
    CLI11_PARSE(app, argc, argv);
#ifndef PRIDE_HAVE_OMPL
    if (with_ompl) {
        fmt::print(stderr, "planner_bench: --ompl needs a build with OMPL (scripts/deps.sh installs libompl-dev)\n");
        return 2;
    }
#else
    std::string ompl_columns;
    for (const auto& name : ompl_planner_names()) ompl_columns += fmt::format(",{0}_first_ms,{0}_solved", name);
#endif
    if (with_ompl) ompl.queries = ompl_queries;
    try {
        fmt::print(
            "file,queries,jps_length_mismatches,astar_expansions,jps_expansions,astar_us,jps_us,theta_us,lazy_us,"
            "theta_los,lazy_los,theta_over_astar,lazy_over_astar{}{}\n",
            oracle ? ",oracle_us,theta_over_oracle,lazy_over_oracle" : "",
#ifdef PRIDE_HAVE_OMPL
            with_ompl ? ompl_columns : std::string());
#else
            "");
#endif
        for (const auto& s : scens) bench_file(s, reps, oracle, ompl);
    } catch (const std::exception& e) {
        fmt::print(stderr, "planner_bench: {}\n", e.what());
        return 2;
    }
    return 0;
}

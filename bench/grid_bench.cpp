// The grid benchmark; prints numbers, asserts nothing.
//   1. A*: expansions per second and time per query on the larger Moving AI scenario maps
//      (every line of each scenario file given on the command line): `astar,FILE,queries,
//      expansions,exp/s first pass,ms/query first pass,worst length error,exp/s warm` (warm: the
//      same queries repeated on the same AStar for 100 ms).
//   2. Decoding and evaluating one `line` genotype (repair connector, objective cells) on a 20x20
//      map (the bundled zhang2025-20x20.map) and on a 100x100 map with 20 % random obstacles, in the
//      engine's types (linear objective, connector chosen at run time) beside the fixed types.
//   3. PSO, LSO and ILSO (N = 20, T = 50, line + repair, objective cells) on the bundled 10x10 map,
//      run through the engine, and the one-off construction of the rough-set rule book that
//      ILSO's walks use.
//   4. With --sitp only: the time to make N = 40 SITP paths (Zhang et al.'s (2025) initial population) on
//      the bundled 40x40 map, beside N = 40 random walks, through the chain space (objective iqga).
//   5. With --pareto, only: the exact Pareto fronts (problems/grid/pareto.hpp) of (length, turns),
//      (length, angle_penalty) and all three, and the iqga optimum over the 3-D front, on the
//      bundled 20x20 and 40x40 maps and on the 100x100 map with 20 % random obstacles.
//   6. With --whales only: HS-WOA and WOA (N = 20, 50 iterations, chain encoding, objective
//      hswoa) on the bundled 50x50 map (Cai and Du 2021), run through the engine, 51 seeds: the median
//      and least wall time of a run (RunState's clock) and its median processor time (std::clock,
//      steadier than the wall clock on a loaded machine).
//   7. With --init-table only: Zhang et al.'s (2025) table 2, 30 SITP and 30 random-walk initial paths on
//      each bundled zhang2025 map (longest, shortest, mean length, share of legal paths).
// Usage: grid_bench [--scen FILE.scen ...] [--maps DIR] [--sitp | --pareto | --whales | --init-table | --decode |
//        --astar] [--rounds N] [--decode-map NAME] (--decode: only part 2; --astar: only part 1; --rounds: decode
//        rounds, for callgrind; --decode-map: only the decode figures of that map)
#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <map>
#include <memory>
#include <vector>

#include "engine/run.hpp"
#include "engine/target.hpp"
#include "framework/encoding.hpp"
#include "problems/grid/chain.hpp"
#include "problems/grid/encodings.hpp"
#include "problems/grid/map_io.hpp"
#include "problems/grid/objectives.hpp"
#include "problems/grid/pareto.hpp"
#include "problems/grid/planners/astar.hpp"
#include "problems/grid/rough_rules.hpp"

namespace {

using namespace pride;
using namespace pride::grid;

double ms_since(Clock::time_point t) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

void bench_astar(const std::string& scen) {
    const auto entries = read_scenario(scen);
    const auto dir = std::filesystem::path(scen).parent_path();
    std::map<std::string, GridMap> maps;
    for (const auto& e : entries)
        if (!maps.count(e.map)) maps.emplace(e.map, read_map((dir / e.map).string()));
    AStar astar;
    double worst = 0.0;
    const auto pass = [&] {
        for (const auto& e : entries)
            worst = std::max(worst, std::abs(astar.search(maps.at(e.map), e.start, e.goal) - e.optimal));
    };
    const auto start = Clock::now();
    pass();  // a fresh AStar: its arrays and buckets grow during this pass
    const double ms = ms_since(start);
    const auto first = astar.expansions();
    // Then the same queries again on the grown AStar, as a connector reuses one, until 100 ms
    // have passed: on the small files the first pass is mostly the arrays' first growth.
    std::size_t passes = 0;
    const auto warm = Clock::now();
    do {
        pass();
        ++passes;
    } while (ms_since(warm) < 100.0 && passes < 100000);
    const double warm_ms = ms_since(warm);
    fmt::print("astar,{},{},{},{:.4g},{:.4g},{:.2g},{:.4g}\n", std::filesystem::path(scen).filename().string(),
               entries.size(), first, first / (ms / 1000.0), ms / static_cast<double>(entries.size()), worst,
               static_cast<double>(astar.expansions() - first) / (warm_ms / 1000.0));
}

/// A w x h map with `share` of its cells blocked at random, corner to corner connected (the first
/// seed from `seed` on that gives one).
GridMap random_map(int w, int h, double share, std::uint64_t seed) {
    for (;; ++seed) {
        Rng rng(seed);
        std::vector<std::uint8_t> blocked(static_cast<std::size_t>(w) * h);
        for (auto& b : blocked) b = rng.bernoulli(share) ? 1 : 0;
        blocked.front() = blocked.back() = 0;
        GridMap map(w, h, std::move(blocked), fmt::format("random-{}x{}", w, h));
        if (reachable_from(map, {0, 0})[map.size() - 1]) return map;
    }
}

/// A bundled map and the start and goal of its one-line scenario file.
struct Bundled {
    std::shared_ptr<const GridMap> map;
    Cell start, goal;
};
Bundled bundled(const std::string& maps, const std::string& name) {
    const auto scen = read_scenario(maps + "/" + name + ".map.scen");
    return {std::make_shared<const GridMap>(read_map(maps + "/" + name + ".map")), scen.at(0).start, scen.at(0).goal};
}

/// Decode + evaluate of random `line` genotypes by `encoded` (a copy per call, fresh detour memory).
int g_decode_rounds = 2000;  // --rounds: fewer for instruction counts under callgrind
std::string g_decode_map;    // --decode-map: only the decode figures whose map name holds this

template <class E>
double decode_ns(E encoded) {
    Rng rng(7);
    std::vector<std::vector<double>> genotypes(64, std::vector<double>(encoded.dimension()));
    for (auto& x : genotypes)
        for (std::size_t i = 0; i < x.size(); ++i) x[i] = rng.uniform(encoded.lower()[i], encoded.upper()[i]);
    double sink = 0.0;
    for (const auto& x : genotypes) sink += encoded.evaluate(x);  // warm the detour memory, as a run does
    const int rounds = g_decode_rounds;
    const auto start = Clock::now();
    for (int r = 0; r < rounds; ++r)
        for (const auto& x : genotypes) sink += encoded.evaluate(x);
    if (sink == 42.0) fmt::print(stderr, " ");
    return ms_since(start) * 1e6 / (rounds * static_cast<double>(genotypes.size()));
}

/// The cost of a decode + evaluate, in the types the engine runs (the linear objective with cells'
/// weights, the connector chosen at run time) beside the fixed types (CellsObjective,
/// RepairConnector): the run-time choices must cost nothing measurable.
void bench_decode(const std::string& label, std::shared_ptr<const GridMap> map, Cell s, Cell g) {
    if (label.find(g_decode_map) == std::string::npos) return;
    const GridProblem<CellsObjective> fixed(map, s, g);
    const double fixed_ns = decode_ns(Encoded<GridProblem<CellsObjective>, LineEncoding<RepairConnector>>(
        fixed, LineEncoding<RepairConnector>(fixed)));
    const GridProblem<LinearObjective> linear(std::move(map), s, g, LinearObjective::of(CellsObjective{}));
    const engine::GridLine<LinearObjective> engine_line(
        linear, LineEncoding<SelectableConnector>(linear, SelectableConnector(SelectableConnector::Kind::repair)));
    const double engine_ns = decode_ns(engine_line);
    fmt::print("decode,{},{},{:.1f},{:.1f}\n", label, engine_line.dimension(), engine_ns, fixed_ns);
}

/// One algorithm (N = 20, T = 50, line + repair, cells) on the bundled 10x10 map, 200 seeds, run
/// through the engine: the median wall time of a run (RunState's clock: initialisation, walks and
/// all evaluations).
void bench_swarm(const std::string& maps, const std::string& algorithm) {
    const Bundled b = bundled(maps, "wan2022-10x10");
    engine::GridSpec spec;
    spec.map = b.map;
    spec.start = b.start;
    spec.goal = b.goal;
    const engine::Problem problem(spec);  // N = 20 on grids; ilso starts from rule walks
    engine::Budget t50;
    t50.iterations = 50;
    std::vector<double> wall;
    double best = 0.0;
    for (std::uint64_t seed = 1; seed <= 200; ++seed) {
        const auto r = engine::run({algorithm, {}}, problem, t50, seed);
        wall.push_back(r.wall_ms);
        best += r.best_f / 200.0;
    }
    std::sort(wall.begin(), wall.end());
    fmt::print("{},wan2022-10x10,200 runs,median_ms {:.4f},mean_best_cells {:.3f}\n", algorithm, wall[wall.size() / 2],
               best);
}

/// The rule book is built once per process, at its first use (the first line or free encoding
/// whose problem offers rule walks): timed here, before anything else uses it.
void bench_rule_book() {
    const auto start = Clock::now();
    const GridRuleBook& book = grid_rule_book();
    fmt::print("rule book (3^8 table, reducts, minimal rules),{} rules,build_ms {:.3f}\n", book.rules.size(),
               ms_since(start));
}

/// Milliseconds to make a population of 40 chains (the median of `repeats` populations, each from
/// a fresh chain space and seed), and the mean cells and length of the chains.
void bench_sitp(const std::string& maps, int repeats = 51) {
    const Bundled b = bundled(maps, "zhang2025-40x40");
    const GridProblem<IqgaObjective> problem(b.map, b.start, b.goal);
    fmt::print("part,init,paths,ms_per_population_median,ms_min,mean_cells,mean_length\n");
    for (const Walks init : {Walks::sitp, Walks::random}) {
        std::vector<double> ms;
        double cells = 0.0, length = 0.0;
        std::vector<Path> pop(40);
        for (int r = 0; r < repeats; ++r) {
            ChainSpace<IqgaObjective> space(problem);
            space.set_init(init);
            Rng rng(static_cast<std::uint64_t>(r) + 1);
            const auto t = Clock::now();
            // Outside a run: SITP ranks its walks by the objective, called here directly.
            const auto score = [&](const Path& x) { return space.evaluate(x); };
            for (auto& c : pop) space.random_chain(rng, c, score);
            ms.push_back(ms_since(t));
            for (const auto& c : pop) {
                cells += static_cast<double>(c.size());
                length += metrics(c, false).length;
            }
        }
        std::sort(ms.begin(), ms.end());
        const double n = 40.0 * repeats;
        fmt::print("sitp,{},40,{:.3f},{:.3f},{:.1f},{:.2f}\n", init == Walks::sitp ? "sitp" : "walk", ms[ms.size() / 2],
                   ms.front(), cells / n, length / n);
    }
}

/// HS-WOA and WOA, Cai and Du's (2021) setting, on the bundled 50x50 map (section 6 of the header).
void bench_whales(const std::string& maps) {
    const Bundled b = bundled(maps, "cai2021-50x50");
    engine::GridSpec spec;
    spec.map = b.map;
    spec.start = b.start;
    spec.goal = b.goal;
    spec.encoding = "chain";
    spec.objective = "hswoa";
    const engine::Problem problem(spec);  // N = 20 on grids
    engine::Budget t50;
    t50.iterations = 50;
    fmt::print("part,map,runs,median_wall_ms,min_wall_ms,median_cpu_ms,mean_evaluations,mean_value\n");
    for (const char* algorithm : {"hswoa", "woa"}) {
        std::vector<double> wall, cpu;
        double evaluations = 0.0, value = 0.0;
        constexpr int runs = 51;
        for (std::uint64_t seed = 1; seed <= runs; ++seed) {
            const std::clock_t c0 = std::clock();
            const auto r = engine::run({algorithm, {}}, problem, t50, seed);
            cpu.push_back(1000.0 * static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC);
            wall.push_back(r.wall_ms);
            evaluations += static_cast<double>(r.evaluations) / runs;
            value += r.best_f / runs;
        }
        std::sort(wall.begin(), wall.end());
        std::sort(cpu.begin(), cpu.end());
        fmt::print("{},cai2021-50x50,{},{:.2f},{:.2f},{:.2f},{:.0f},{:.3f}\n", algorithm, runs, wall[wall.size() / 2],
                   wall.front(), cpu[cpu.size() / 2], evaluations, value);
    }
}

/// Zhang et al.'s (2025) table 2: 30 initial paths by SITP and by the goal-biased random walk (the chain GA's
/// random initial population) on each bundled zhang2025 map, seed 1: longest, shortest and mean
/// length, and the share of legal paths (checked by path_violation).
void bench_init_table(const std::string& maps) {
    fmt::print("part,map,init,paths,longest,shortest,mean_length,feasible_share\n");
    for (const char* name : {"zhang2025-20x20", "zhang2025-40x40"}) {
        const Bundled b = bundled(maps, name);
        const GridProblem<IqgaObjective> problem(b.map, b.start, b.goal);
        for (const Walks init : {Walks::sitp, Walks::random}) {
            ChainSpace<IqgaObjective> space(problem);
            space.set_init(init);
            Rng rng(1);
            double longest = 0.0, shortest = 1e300, sum = 0.0;
            int legal = 0;
            Path c;
            // Outside a run: SITP ranks its walks by the objective, called here directly.
            const auto score = [&](const Path& x) { return space.evaluate(x); };
            for (int k = 0; k < 30; ++k) {
                space.random_chain(rng, c, score);
                const double l = metrics(c, false).length;
                longest = std::max(longest, l);
                shortest = std::min(shortest, l);
                sum += l;
                legal += path_violation(*b.map, c, b.start, b.goal).empty() ? 1 : 0;
            }
            fmt::print("init,{},{},30,{:.3f},{:.3f},{:.3f},{:.2f}\n", name, init == Walks::sitp ? "sitp" : "walk",
                       longest, shortest, sum / 30.0, legal / 30.0);
        }
    }
}

void bench_swarms(const std::string& maps) {
    for (const char* algorithm : {"pso", "lso", "ilso"}) bench_swarm(maps, algorithm);
}

/// The fronts on one map: the median wall time of `repeats` searches, the front's size and the
/// labels created.
void bench_pareto(const std::string& label, const GridMap& map, Cell s, Cell g, int repeats) {
    const struct {
        const char* name;
        Criteria c;
    } sets[] = {{"length+turns", {true, true, false}},
                {"length+angle", {true, false, true}},
                {"length+angle+turns", {true, true, true}}};
    for (const auto& set : sets) {
        ParetoSearch search;
        std::vector<double> wall;
        std::size_t points = 0;
        for (int r = 0; r < repeats; ++r) {
            const auto start = Clock::now();
            points = search.front(map, s, g, set.c).size();
            wall.push_back(ms_since(start));
        }
        std::sort(wall.begin(), wall.end());
        fmt::print("pareto,{},{},{},{},{:.3f}\n", label, set.name, points, search.labels(), wall[wall.size() / 2]);
    }
    const auto start = Clock::now();
    const auto iqga = iqga_optimum(map, s, g);
    fmt::print("pareto,{},iqga optimum {:.6f},1,,{:.3f}\n", label, iqga.value_or(0.0), ms_since(start));
}

void bench_paretos(const std::string& maps) {
    fmt::print("part,map,objectives,front_points,labels,median_ms\n");
    const Bundled m20 = bundled(maps, "zhang2025-20x20");
    bench_pareto("zhang2025-20x20", *m20.map, m20.start, m20.goal, 11);
    const Bundled m40 = bundled(maps, "zhang2025-40x40");
    bench_pareto("zhang2025-40x40", *m40.map, m40.start, m40.goal, 5);
    bench_pareto("random-100x100-20%", random_map(100, 100, 0.2, 3), {0, 0}, {99, 99}, 3);
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> scens;
    std::string maps = "examples/maps";
    CLI::App app{"grid benchmark: A*, decoding, PSO, LSO and ILSO on the 10x10 map"};
    app.add_option("--scen", scens, "Moving AI scenario files for the A* part");
    app.add_option("--maps", maps, "folder of the bundled maps (default examples/maps)");
    bool sitp = false, pareto = false, whales = false, init_table = false, decode_only = false, astar_only = false;
    app.add_flag("--decode", decode_only, "only the decode + evaluate part");
    app.add_flag("--astar", astar_only, "only the A* part (the --scen files)");
    app.add_option("--rounds", g_decode_rounds, "rounds of 64 genotypes per decode figure (default 2000)")
        ->check(CLI::PositiveNumber);
    app.add_option("--decode-map", g_decode_map,
                   "only the decode figures of the maps whose name holds this (zhang2025, random)");
    app.add_flag("--sitp", sitp, "only: the time to make N = 40 SITP paths on the bundled 40x40 map");
    app.add_flag("--pareto", pareto, "only the exact Pareto fronts (20x20, 40x40, random 100x100)");
    app.add_flag("--whales", whales, "only: HS-WOA and WOA, N = 20, 50 iterations, on the bundled 50x50 map");
    app.add_flag("--init-table", init_table,
                 "only: Zhang et al.'s (2025) table 2 (30 SITP and 30 random-walk paths per map)");
    CLI11_PARSE(app, argc, argv);
    try {
        if (init_table) {
            bench_init_table(maps);
            return 0;
        }
        if (sitp) {
            bench_sitp(maps);
            return 0;
        }
        if (pareto) {
            bench_paretos(maps);
            return 0;
        }
        if (whales) {
            bench_whales(maps);
            return 0;
        }
        if (!decode_only && !astar_only) bench_rule_book();
        if (!decode_only)
            fmt::print("part,what,queries,expansions,expansions_per_s,ms_per_query,max_diff,warm_expansions_per_s\n");
        if (!decode_only)
            for (const auto& s : scens) bench_astar(s);
        if (astar_only) return 0;
        fmt::print("part,map,genes,ns_per_decode_and_evaluate,ns_with_fixed_types\n");
        const Bundled m20 = bundled(maps, "zhang2025-20x20");
        bench_decode("zhang2025-20x20", m20.map, m20.start, m20.goal);
        bench_decode("random-100x100-20%", std::make_shared<const GridMap>(random_map(100, 100, 0.2, 3)), {0, 0},
                     {99, 99});
        if (!decode_only) bench_swarms(maps);
    } catch (const std::exception& e) {
        fmt::print(stderr, "grid_bench: {}\n", e.what());
        return 2;
    }
    return 0;
}

// The grid half of the README's main job: on each bundled map of the papers (examples/maps), the
// exact optimum of the objective `cells` beside PSO, the GA, LSO and ILSO (whose starting points are
// Wan and Gao's (2022) rough-set rule walks) through the `line` encoding with the `repair` connector, and the
// GA on `chain` paths, with the papers' settings N = 20, T = 50 and
// seeds 1..10: mean value, mean gap to the optimum, share of runs that reached it, time per run.
// Usage: plan_paths [MAPS_DIR]   (default: examples/maps)
#include <fmt/format.h>

#include <memory>
#include <string>
#include <vector>

#include "engine/run.hpp"
#include "problems/grid/map_io.hpp"

namespace {

using namespace pride::grid;
namespace engine = pride::engine;

constexpr std::uint64_t kSeeds = 10;

struct Row {
    std::string algorithm;
    double mean = 0.0, gap = 0.0, success = 0.0, ms = 0.0;
};

template <class Run>
Row summarise(const std::string& name, double optimum, Run run) {
    Row row{name};
    for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) {
        const auto [value, ms] = run(seed);
        row.mean += value / kSeeds;
        row.gap += (value - optimum) / optimum / kSeeds;
        row.success += (value == optimum ? 1.0 : 0.0) / kSeeds;
        row.ms += ms / kSeeds;
    }
    return row;
}

void compare(const std::string& dir, const std::string& name) {
    const auto scen = read_scenario(dir + "/" + name + ".map.scen").at(0);
    engine::GridSpec spec;  // objective cells, line encoding, repair connector
    spec.map = engine::load_map(dir + "/" + name + ".map");
    spec.start = scen.start;
    spec.goal = scen.goal;
    const auto& map = spec.map;
    const engine::Problem line(spec);
    spec.encoding = "chain";
    const engine::Problem chain(spec);
    engine::Budget t50;  // on grids the population is the papers' N = 20 unless set
    t50.iterations = 50;
    const double optimum = engine::run({"exact", {}}, line, t50, 1).best_f;

    std::vector<Row> rows;
    auto add = [&](const std::string& label, const std::string& algorithm, const engine::Problem& problem) {
        rows.push_back(summarise(label, optimum, [&](std::uint64_t seed) {
            const engine::RunResult r = engine::run({algorithm, {}}, problem, t50, seed);
            return std::pair{r.best_f, r.wall_ms};
        }));
    };
    add("pso, line + repair", "pso", line);
    add("ga, line + repair", "ga", line);
    add("lso, line + repair", "lso", line);
    add("ilso, line + repair", "ilso", line);  // the problem's starting points: rough-set rule walks
    add("ga, chain", "ga", chain);

    fmt::print("{} ({}x{}), start ({},{}), goal ({},{}): optimum {} cells\n", name, map->width(), map->height(),
               scen.start.x, scen.start.y, scen.goal.x, scen.goal.y, optimum);
    for (const auto& r : rows)
        fmt::print("  {:<20} mean {:7.3f}  gap {:6.2f} %  optimal in {:3.0f} %  {:7.3f} ms/run\n", r.algorithm, r.mean,
                   100.0 * r.gap, 100.0 * r.success, r.ms);
}

}  // namespace

int main(int argc, char** argv) {
    const std::string dir = argc > 1 ? argv[1] : "examples/maps";
    try {
        fmt::print("objective cells, N = 20, T = 50, seeds 1..{}\n\n", kSeeds);
        for (const char* name :
             {"wan2022-10x10", "wan2022-13x13", "zhang2025-20x20", "zhang2025-40x40", "cai2021-50x50"})
            compare(dir, name);
    } catch (const std::exception& e) {
        fmt::print(stderr, "plan_paths: {}\n", e.what());
        return 2;
    }
    return 0;
}

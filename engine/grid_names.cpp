#include "engine/grid_names.hpp"

#include "engine/registry.hpp"
#include "framework/error.hpp"

namespace pride::engine {

const std::vector<NamedItem>& grid_objectives() {
    static const std::vector<NamedItem> items{
        {"cells", "grids: number of cells, start and goal included (Wan and Gao 2022, eq. 13)"},
        {"length", "grids: sum of step lengths, 1 or sqrt(2) (Zhang et al. 2025, eq. 8)"},
        {"weighted", "grids: w_len length + w_turn turns + w_angle angle_penalty (--weights, default 1,1,0.1)"},
        {"iqga", "grids: -(1/length + 1/angle_penalty + 1/turns) (Zhang et al. 2025, eq. 12)"},
        {"hswoa", "grids: length + lambda turns (Cai and Du 2021; --lambda, default 1)"}};
    return items;
}

const std::vector<NamedItem>& grid_encodings() {
    static const std::vector<NamedItem> items{
        {"line", "grids: one gene per row (or column) between start and goal, the waypoint's cross coordinate"},
        {"free", "grids: 2K genes, K waypoints (x, y) anywhere on the map (--waypoints K, default 3)"},
        {"chain",
         "grids: the cell chain itself, with crossover at a common cell and segment-regenerating mutation (ga, "
         "ga-plus)"}};
    return items;
}

const std::vector<NamedItem>& grid_connectors() {
    static const std::vector<NamedItem> items{
        {"repair", "grids (line, free): a blocked join becomes the shortest legal detour (A* in a growing window)"},
        {"penalty", "grids (line, free): the straight cell line; each violation costs M >= 10 W H"}};
    return items;
}

const std::vector<NamedItem>& grid_inits() {
    static const std::vector<NamedItem> items{
        {"uniform", "uniform genotypes in the box"},
        {"walk", "genotypes read off goal-biased random walks with taboo list"},
        {"rules", "genotypes read off Wan and Gao's (2022) rough-set rule walks"},
        {"sitp", "genotypes or chains from Zhang et al.'s (2025) SITP walks (eqs. 3-7)"}};
    return items;
}

bool named_in(const std::vector<NamedItem>& items, const std::string& name) {
    for (const auto& i : items)
        if (i.name == name) return true;
    return false;
}

namespace {

std::string choices(const std::vector<NamedItem>& items) {
    std::string s;
    for (std::size_t i = 0; i < items.size(); ++i)
        s += (i == 0 ? "" : i + 1 == items.size() ? " or " : ", ") + items[i].name;
    return s;
}

}  // namespace

void check_grid_names(const GridSpec& g) {
    // "user": a user's objective on paths, given as GridSpec::path_objective (Python: a callable).
    require(g.objective == "user" || named_in(grid_objectives(), g.objective), "objective",
            "unknown objective '" + g.objective + "' (" + choices(grid_objectives()) + ")");
    require((g.objective == "user") == (g.path_objective && g.path_objective->value), "objective",
            g.objective == "user" ? "user needs the objective's function (a callable on paths)"
                                  : "a function on paths comes with the objective user, not " + g.objective);
    // No encoding: each run plans on its algorithm's own, or its native one (planned_grid).
    require(g.encoding.empty() || named_in(grid_encodings(), g.encoding), "encoding",
            "unknown encoding '" + g.encoding + "' (" + choices(grid_encodings()) + ")");
    require(named_in(grid_connectors(), g.connector), "connector",
            "unknown connector '" + g.connector + "' (" + choices(grid_connectors()) + ")");
    require(g.encoding != "chain" || g.connector == "repair", "connector",
            "chains need no connector: every operator keeps them legal");
    require(g.waypoints >= 1 && g.waypoints <= 1000, "waypoints",
            "must be in [1, 1000], got " + std::to_string(g.waypoints));
    require(g.init.empty() || named_in(grid_inits(), g.init), "init",
            "expected uniform, walk, rules or sitp, got '" + g.init + "'");
    require(g.init != "rules" || g.encoding != "chain", "init " + g.init,
            "only for the line and free encodings (chains start from random walks, or SITP walks with init sitp)");
    require(g.weights.empty() || g.objective == "weighted", "weights", "only for the weighted objective");
    require(!g.lambda || g.objective == "hswoa", "lambda", "only for the hswoa objective");
}

std::string default_grid_objective(const std::string& algo) {
    const AlgorithmEntry* entry = algorithms().find(algo);
    return entry && entry->plans_polylines ? "length" : "cells";
}

}  // namespace pride::engine

// The whale family (algorithms/woa.hpp): woa, the two halves of Cai and Du's (2021) ablation (woa-hs: the
// harmony second step only; woa-balance: the balance factor only) and hswoa (both), four
// configurations of one instantiation (the policies are chosen once per iteration), on boxes and
// on chains (grids with the chain encoding: N = 20 and 50 iterations by default, as Cai and Du (2021)).
#include "algorithms/woa.hpp"

#include "engine/family.hpp"

namespace pride::engine {
namespace {

using Family = Woa<SelectableWhaleDraws, SelectableWhaleMode, SelectableSecondStep, Clamp, SelectableInit>;

std::vector<ParamSpec> whale_params(bool harmony, bool balanced) {
    std::vector<ParamSpec> ps{
        population_param(30, 2), real("b", 1.0, -10.0, 10.0, "shape constant of the logarithmic spiral (eq. 5)"),
        flag("per_coordinate", false,
             "draw r1, r2 and p anew for every coordinate (the vector reading) instead of once per whale (WOA.m)")
            .only_on_boxes()};
    if (balanced) {
        ps.push_back(real("balance", 0.8, 0.0, 1.0, "starting balance factor: the probability of exploring (eq. 9)"));
        ps.push_back(
            integer("thr", 2, 0, 1'000'000, "iterations without improvement before the mode switches (eq. 9)"));
        ps.push_back(real("keep", 0.2, 0.0, 1.0, "share of the pod kept by tournament on stagnation").open_below());
    }
    if (harmony) {
        ps.push_back(real("hmcr", 0.8, 0.0, 1.0, "harmony memory considering rate of the second step"));
        ps.push_back(real("par", 0.3, 0.0, 1.0, "pitch adjusting rate of the second step"));
        ps.push_back(real("bw", 0.01, 0.0, 1.0, "bandwidth as a fraction of each coordinate's range"));
    }
    ps.push_back(walk_init_param(false).only_on_boxes());
    return ps;
}

auto configure(std::string id, bool harmony, bool balanced) {
    return [id = std::move(id), harmony, balanced](const Params& p) {
        Family a;
        a.id = id;
        a.population = p.integer("pop");
        a.b = p.real("b");
        if (p.flag("per_coordinate")) a.draws = PerCoordinateDraws{};
        if (balanced) {
            BalanceMode m;
            m.start = p.real("balance");
            m.thr = p.integer("thr");
            m.keep = p.real("keep");
            a.mode = m;
        }
        if (harmony) {
            HarmonySecondStep s;
            s.rates = {p.real("hmcr"), p.real("par"), p.real("bw")};
            a.second_step = s;
        }
        a.init.suggestions = p.flag("walk_init");
        return a;
    };
}

void add(AlgorithmRegistry& registry, const std::string& name, const std::string& summary, bool harmony,
         bool balanced) {
    auto e = box_algorithm(name, "woa", summary, whale_params(harmony, balanced), configure(name, harmony, balanced));
    // On chains the same configuration runs the chain pod (algorithms/parts/whale/pods.hpp).
    // Cai and Du (2021) plan on chains from eq. 10's walks, shortened by the line of sight.
    add_chain_runner(e, configure(name, harmony, balanced), {"line", "eq10"});
    e.memory = population_memory(2);  // the pod and the reconstruction's copy
    e.native_encoding = "chain";      // Cai and Du (2021) plan on paths
    registry.add(std::move(e));
}

}  // namespace

void register_woa(AlgorithmRegistry& registry) {
    add(registry, "woa", "whale optimisation (Mirjalili and Lewis 2016, reference code WOA.m), a 2 -> 0, b = 1", false,
        false);
    add(registry, "woa-hs", "WOA with HS-WOA's harmony second step only (Cai and Du 2021, eq. 8, HMCR 0.8, PAR 0.3)",
        true, false);
    add(registry, "woa-balance", "WOA with HS-WOA's balance factor only (Cai and Du 2021, eq. 9, balance 0.8, thr 2)",
        false, true);
    add(registry, "hswoa", "HS-WOA (Cai and Du 2021): WOA, harmony second step and balance factor with reconstruction",
        true, true);
}

}  // namespace pride::engine

// The lion swarm family (algorithms/lso.hpp): lso and ilso, two configurations of one
// instantiation (the weight of eqs. 11-12 is chosen once per iteration; the cub thresholds are
// values).
#include "algorithms/lso.hpp"

#include "engine/family.hpp"

namespace pride::engine {
namespace {

using Family = Lso<SelectableWeight, LsoCubs, Clamp, SelectableInit>;

Family configure(const Params& p) {
    Family a;
    a.population = p.integer("pop");
    a.init.suggestions = p.flag("walk_init");
    a.beta = p.real("beta");
    if (const auto step = p.optional("step")) a.step_factor = *step;
    a.cubs.first = p.real("cub_first");
    a.cubs.second = p.real("cub_second");
    a.gamma_per_coordinate = p.flag("gamma_per_coordinate");
    return a;
}

std::vector<ParamSpec> params(bool improved) {
    std::vector<ParamSpec> v{
        population_param(20, 4, "population size (a king, lionesses, cubs)"),
        real("beta", 0.2, 0.0, 1.0, "share of adult lions, eqs. 1-2").open_below().open_above(),
        real("step", 0.0, 0.0, 1.0,
             "fixed r of eq. 5 (default: drawn from U(0,1) once per run; 0.1 in the original LSO)")
            .open_below()
            .no_default(),
        real("cub_first", improved ? 0.3 : 1.0 / 3.0, 0.0, 1.0,
             improved ? "first cub threshold (eq. 12: 3/10)" : "first cub threshold (eq. 9: 1/3)")
            .open_below()
            .open_above(),
        real("cub_second", 2.0 / 3.0, 0.0, 1.0, "second cub threshold (eqs. 9, 12: 2/3)").open_below().open_above(),
        flag("gamma_per_coordinate", false,
             "one gamma per coordinate instead of one per lion (not Wan and Gao's (2022) reading)"),
        walk_init_param(improved)};
    if (improved) {
        v.insert(v.begin() + 3, real("w_max", 0.99, 0.0, 1.5, "inertia weight of eq. 10 at the start"));
        v.insert(v.begin() + 4, real("w_min", 0.35, 0.0, 1.5, "inertia weight of eq. 10 at the end"));
    }
    return v;
}

}  // namespace

void register_lso(AlgorithmRegistry& registry) {
    auto lso = box_algorithm("lso", "lso",
                             "lion swarm (Wan and Gao 2022, eqs. 1-9): king, lionesses, cubs; N 20, beta 0.2, step "
                             "r*(mean high - mean low) with r "
                             "~ U(0,1) per run",
                             params(false), [](const Params& p) {
                                 Family a = configure(p);
                                 a.weight = UnitWeight{};
                                 return a;
                             });
    lso.memory = population_memory(2);  // positions and personal bests
    registry.add(std::move(lso));

    auto ilso = box_algorithm("ilso", "lso",
                              "improved lion swarm (Wan and Gao 2022, eqs. 10-12): LSO with inertia 0.99 -> 0.35 "
                              "(quadratic), cub threshold 3/10, "
                              "starting from the problem's suggestions (rough-set rule walks on grids)",
                              params(true), [](const Params& p) {
                                  Family a = configure(p);
                                  a.id = "ilso";
                                  QuadraticInertia w;
                                  w.start = p.real("w_max");
                                  w.end = p.real("w_min");
                                  a.weight = w;
                                  return a;
                              });
    ilso.memory = population_memory(2);
    registry.add(std::move(ilso));
}

}  // namespace pride::engine

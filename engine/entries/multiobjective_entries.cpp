// The multi-objective algorithms: NSGA-II and NSGA-III (algorithms/nsga2.hpp,
// nsga3.hpp), MOEA/D (moead.hpp) and SMS-EMOA (smsemoa.hpp). Each runner visits the target once
// (engine/target.hpp) and runs typed; the defaults are the papers' (their headers cite them).
// NSGA-II and NSGA-III also run on grid chains with the chain operators (Kind::multiobjective_chain).
// Decided by this project: p_m on chains is a probability per child, 0.1 unless given (IQGA's
// Pm, Zhang et al. (2025), as the GA on chains), since the paper's 1/n per variable has no chain form.
#include <fmt/format.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>

#include "algorithms/moead.hpp"
#include "algorithms/nsga2.hpp"
#include "algorithms/nsga3.hpp"
#include "algorithms/smsemoa.hpp"
#include "engine/family.hpp"
#include "engine/registry.hpp"
#include "framework/error.hpp"
#include "framework/pareto/hypervolume.hpp"
#include "framework/pareto/reference_directions.hpp"

namespace pride::engine {
namespace {

/// An entry whose algorithm is configured from the parameters and M (NSGA-III's directions and
/// MOEA/D's weights depend on it).
template <class Configure>
AlgorithmEntry mo_algorithm(std::string name, std::string summary, std::vector<ParamSpec> params, Configure configure) {
    AlgorithmEntry e;
    e.name = name;
    e.family = std::move(name);
    e.summary = std::move(summary);
    e.params = std::move(params);
    add_runner<MoBoxTarget>(e, Kind::multiobjective, [configure](const RunRequest& r, const MoBoxTarget& target) {
        return std::visit(
            [&](const auto& problem) -> MultiObjectiveResult {
                const auto algorithm = configure(r.params, problem.objectives());
                return algorithm.run(problem, r.termination, r.seed);
            },
            target.problem);
    });
    return e;
}

/// The most work NSGA-III's generation may cost, in M N (4N + 2D + 2M) operations (its check_objectives):
/// about 0.8 s, measured on the 2-core machine at 500 objectives with the default directions and
/// population (docs/reliability.md, "Sizes before work").
constexpr double kNsga3MaxWork = 1e9;

/// The most work MOEA/D's neighbourhoods may cost before its first generation, in N^2 (M + 2)
/// operations for N subproblems in M objectives (its check_objectives).
constexpr double kMoeadMaxSetup = 2e8;

/// p_m on chains when none is given: decided by this project (see register_multiobjective).
constexpr double kChainMutation = 1.0;

std::vector<ParamSpec> variation_params(double eta_c, double p_c) {
    return {real("eta_c", eta_c, 0.0, 1000.0, "SBX distribution index").only_on_boxes(),
            real("p_c", p_c, 0.0, 1.0, "crossover probability per pair (SBX; on chains at a common cell)"),
            real("eta_m", 20.0, 0.0, 1000.0, "polynomial mutation distribution index").only_on_boxes(),
            real("p_m", 0.0, 0.0, 1.0,
                 "mutation probability per variable (default 1/n); on chains per child (default " +
                     fmt::format("{}", kChainMutation) + ")")
                .no_default()};
}

/// NSGA-II's settings on chains (nsga2.hpp's header): the chain mutations and the chain space's.
std::vector<ParamSpec> chain_params() {
    std::vector<ParamSpec> out{
        choice("mutations", {"all", "segment", "iqga"}, "all",
               "on chains, the mutations drawn from: the GA's segment regeneration, Zhang et al.'s "
               "(2025) three (IQGA's deletion, mid-point, turning point), or the four")
            .only_on_chains()};
    for (auto& s : chain_space_params({.sitp_score = "length"})) out.push_back(std::move(s));
    return out;
}

template <class A>
void configure_variation(A& a, const Params& p) {
    a.crossover = SbxCrossover{p.real("eta_c"), p.real("p_c")};
    a.mutation = PolynomialMutation{p.real("eta_m"), p.optional("p_m").value_or(-1.0)};
}

/// The NSGA skeleton configured for boxes, with the chain policies instead (the same population,
/// survival, tournament and p_c), on the chain space set by the parameters.
template <class Box>
void add_mo_chain_runner(AlgorithmEntry& e, Box box_algorithm) {
    for (auto& s : chain_params()) e.params.push_back(std::move(s));
    add_runner<MoChainTarget>(e, Kind::multiobjective_chain,
                              [box_algorithm](const RunRequest& r, const MoChainTarget& target) {
                                  const Params& p = r.params;
                                  const auto box = box_algorithm(p, target.problem.objectives());
                                  Nsga2<ChainCrossover, ChainMutationChoice, std::decay_t<decltype(box.survival)>> a;
                                  a.population = box.population;
                                  a.survival = box.survival;
                                  a.tournament = box.tournament;
                                  a.crossover = ChainCrossover{p.real("p_c")};
                                  const std::string& set = p.choice("mutations");
                                  a.mutation = ChainMutationChoice{p.optional("p_m").value_or(kChainMutation),
                                                                   set == "segment" ? ChainMutationSet::segment
                                                                   : set == "iqga"  ? ChainMutationSet::iqga
                                                                                    : ChainMutationSet::all};
                                  auto problem = target.problem;
                                  configure_space(problem.space(), p);
                                  problem.configured();
                                  return a.run(std::move(problem), r.termination, r.seed);
                              });
}

nsga::Tournament tournament(const Params& p) {
    return p.choice("tournament") == "code" ? nsga::Tournament::code : nsga::Tournament::paper;
}

ParamSpec tournament_param() {
    return choice("tournament", {"paper", "code"}, "paper",
                  "NSGA-II's binary tournament: by rank then crowding (the paper), or Deb's code's "
                  "(dominance, then crowding, then a coin)");
}

/// NSGA-III's reference directions: H = `divisions` (one layer, or two with `inner` > 0), or the
/// paper's Table I for M = 3, 5, 8, 10, 15 (H = 12; 6; 3 and 2; 3 and 2; 2 and 1) and else the
/// largest one-layer lattice of at most 100 directions (M = 2: H = 99).
struct Nsga3Layers {
    std::size_t outer = 0, inner = 0, size = 0;
};
Nsga3Layers nsga3_layers(std::size_t m, std::int64_t divisions, std::int64_t inner) {
    std::size_t outer = static_cast<std::size_t>(divisions), in = static_cast<std::size_t>(inner);
    if (divisions == 0) {
        in = 0;
        switch (m) {
            case 3:
                outer = 12;
                break;
            case 5:
                outer = 6;
                break;
            case 8:
            case 10:
                outer = 3, in = 2;
                break;
            case 15:
                outer = 2, in = 1;
                break;
            default:
                outer = pareto::simplex_lattice_divisions(m, std::max<std::size_t>(m, 100));
        }
    }
    const std::size_t size =
        in == 0 ? pareto::simplex_lattice_size(m, outer) : pareto::two_layer_lattice_size(m, outer, in);
    return {outer, in, size};
}

Matrix nsga3_directions(std::size_t m, std::int64_t divisions, std::int64_t inner) {
    const auto [outer, in, size] = nsga3_layers(m, divisions, inner);
    require(size <= 1'000'000, "nsga3",
            "the reference directions of M = " + std::to_string(m) + " objectives and H = " + std::to_string(outer) +
                (in == 0 ? "" : ", " + std::to_string(in)) + " number more than 1000000");
    return in == 0 ? pareto::simplex_lattice(m, outer) : pareto::two_layer_lattice(m, outer, in);
}

}  // namespace

void register_multiobjective(AlgorithmRegistry& registry) {
    auto nsga2_params = std::vector<ParamSpec>{integer("pop", 100, 4, 10'000'000, "population N, a multiple of 4")};
    for (auto& s : variation_params(20.0, 0.9)) nsga2_params.push_back(std::move(s));
    nsga2_params.push_back(tournament_param());
    nsga2_params.push_back(integers_param("the children's integer and categorical coordinates"));
    for (auto& c : categorical_params()) nsga2_params.push_back(std::move(c));
    const auto nsga2 = [](const Params& p, std::size_t) {
        Nsga2<> a;
        a.population = p.integer("pop");
        configure_variation(a, p);
        typed_operators(a, p);
        a.tournament = tournament(p);
        return a;
    };
    AlgorithmEntry nsga2_entry = mo_algorithm(
        "nsga2",
        "NSGA-II (Deb et al. 2002): non-dominated sorting, crowding, SBX and polynomial mutation; on grid chains the "
        "chain operators",
        std::move(nsga2_params), nsga2);
    add_mo_chain_runner(nsga2_entry, nsga2);
    // Each generation sorts the 2N parents and children: in two objectives in O(N log N), in more
    // by Deb's sort, every pair compared in each objective, M (2N)^2 operations (and (2N)^2 / 8
    // bytes of dominance bits), the first before any time limit is checked. Refused past the
    // work NSGA-III is allowed (before: pop 40000 in 3 objectives ran 17 s under --wall-ms 1000,
    // pop 1000000 met std::bad_alloc).
    nsga2_entry.check_objectives = [](const Params& p, std::size_t objectives) {
        if (objectives <= 2) return;
        const double m = static_cast<double>(objectives), n = static_cast<double>(p.integer("pop"));
        const double work = m * (2.0 * n) * (2.0 * n);
        if (work <= kNsga3MaxWork) return;
        const auto most = static_cast<std::int64_t>(std::floor(std::sqrt(kNsga3MaxWork / m) / 2.0 / 4.0)) * 4;
        throw InputError("pop", fmt::format("NSGA-II sorts its 2N parents and children every generation, comparing "
                                            "every pair in each of the {} objectives: M (2N)^2 = {:.3g} operations "
                                            "for a population of {}, more than the {:.0e} done in about a second, "
                                            "before any time limit is checked (in {} objectives: pop at most {})",
                                            objectives, work, p.integer("pop"), kNsga3MaxWork, objectives, most));
    };
    registry.add(std::move(nsga2_entry));

    auto nsga3_params = std::vector<ParamSpec>{
        integer("pop", 0, 0, 10'000'000,
                "population N, a multiple of 4 (0: the smallest not below the number of directions)"),
        integer("divisions", 0, 0, 1'000'000,
                "H of the reference directions (0: the paper's Table I for M = 3, 5, 8, 10, 15, else at most 100)"),
        integer("inner_divisions", 0, 0, 1'000'000, "H2 of an inner layer (0: one layer)")};
    for (auto& s : variation_params(30.0, 1.0)) nsga3_params.push_back(std::move(s));
    nsga3_params.push_back(tournament_param());
    nsga3_params.push_back(integers_param("the children's integer and categorical coordinates"));
    for (auto& c : categorical_params()) nsga3_params.push_back(std::move(c));
    const auto nsga3 = [](const Params& p, std::size_t m) {
        require(p.integer("inner_divisions") == 0 || p.integer("divisions") > 0, "nsga3",
                "inner_divisions needs divisions");
        Nsga3<> a = make_nsga3(nsga3_directions(m, p.integer("divisions"), p.integer("inner_divisions")));
        if (p.integer("pop") > 0) a.population = p.integer("pop");
        configure_variation(a, p);
        typed_operators(a, p);
        a.tournament = tournament(p);
        return a;
    };
    AlgorithmEntry nsga3_entry =
        mo_algorithm("nsga3", "NSGA-III (Deb and Jain 2014): NSGA-II with niching on reference directions, for M >= 3",
                     std::move(nsga3_params), nsga3);
    add_mo_chain_runner(nsga3_entry, nsga3);
    // A generation costs about M N (4N + 2D + 2M) operations for N members, D directions and M
    // objectives (perf, at M = 1000: the non-dominated sorting of 2N members, the hyperplane's
    // extreme points and intercepts, the association with the directions; the directions
    // themselves take 1%), and the first generation runs before any wall-clock check. Past
    // about 14 objectives the default directions are the M unit vectors and N about M: M^3.
    // Refused past kNsga3MaxWork, 500 objectives with the defaults (measured in
    // docs/reliability.md, "Sizes before work").
    nsga3_entry.check_objectives = [](const Params& p, std::size_t objectives) {
        const auto layers = nsga3_layers(objectives, p.integer("divisions"), p.integer("inner_divisions"));
        const double m = static_cast<double>(objectives), d = static_cast<double>(layers.size);
        const double n = p.integer("pop") > 0 ? static_cast<double>(p.integer("pop")) : std::ceil(d / 4.0) * 4.0;
        const double work = m * n * (4.0 * n + 2.0 * d + 2.0 * m);
        if (work <= kNsga3MaxWork) return;
        std::size_t most = 3;  // the most objectives the defaults allow
        for (;;) {
            const double next = static_cast<double>(most + 1);
            const double dn = static_cast<double>(nsga3_layers(most + 1, 0, 0).size), nn = std::ceil(dn / 4.0) * 4.0;
            if (next * nn * (4.0 * nn + 2.0 * dn + 2.0 * next) > kNsga3MaxWork) break;
            ++most;
        }
        throw InputError("objectives",
                         fmt::format("NSGA-III in {} objectives with {} directions and a population of {}: a "
                                     "generation costs about M N (4N + 2D + 2M) = {:.3g} operations, more than the "
                                     "{:.0e} done in about a second, before any time limit is checked (with the "
                                     "default directions and population: at most {} objectives)",
                                     objectives, layers.size, n, work, kNsga3MaxWork, most));
    };
    registry.add(std::move(nsga3_entry));

    const auto moead = [](const Params& p, std::size_t) {
        Moead<> a;
        a.population = p.integer("pop");
        a.divisions = p.integer("divisions");
        a.neighbours = p.integer("neighbours");
        a.delta = p.real("delta");
        a.replacements = p.integer("replacements");
        a.reproduction.f = p.real("f");
        a.reproduction.cr = p.real("cr");
        a.reproduction.mutation = PolynomialMutation{p.real("eta_m"), p.optional("p_m").value_or(-1.0)};
        a.order = p.choice("order") == "shuffled" ? moead::Order::shuffled : moead::Order::in_order;
        return a;
    };
    AlgorithmEntry moead_entry = mo_algorithm(
        "moead", "MOEA/D-DE (Zhang and Li 2007; Li and Zhang 2009): Tchebycheff subproblems and neighbourhoods",
        {integer("pop", 100, 2, static_cast<std::int64_t>(moead::kMaxSubproblems),
                 "the most subproblems (the largest lattice that fits), unless divisions is set"),
         integer("divisions", 0, 0, 1'000'000, "H of the weight lattice (0: from pop)"),
         integer("neighbours", 20, 2, 1'000'000, "T, the neighbourhood size"),
         real("delta", 0.9, 0.0, 1.0, "probability that parents come from the neighbourhood"),
         integer("replacements", 2, 0, 1'000'000, "n_r, the most members a child replaces (0: no limit)"),
         real("f", 0.5, 0.0, 2.0, "DE's F"), real("cr", 1.0, 0.0, 1.0, "DE's CR"),
         real("eta_m", 20.0, 0.0, 1000.0, "polynomial mutation distribution index"),
         real("p_m", 0.0, 0.0, 1.0, "mutation probability per variable (default 1/n)").no_default(),
         choice("order", {"in_order", "shuffled"}, "in_order", "the order of the subproblems in a generation")},
        moead);
    // Its neighbourhoods B(i) cost N^2 distances in M objectives once, before the first
    // generation and any time limit (measured under load: 0.57 s for N = 4950 and 2.1 s for
    // N = 9870 in 3 objectives, 1.5 s for N = 5005 in 10; the 100000 subproblems pop allows
    // would take minutes). Refused past N^2 (M + 2) = kMoeadMaxSetup, about a second.
    moead_entry.check_objectives = [moead](const Params& p, std::size_t objectives) {
        const auto n = static_cast<double>(moead(p, objectives).weights(objectives).cols());
        const double m = static_cast<double>(objectives), work = n * n * (m + 2.0);
        if (work <= kMoeadMaxSetup) return;
        const auto most = static_cast<std::int64_t>(std::floor(std::sqrt(kMoeadMaxSetup / (m + 2.0))));
        throw InputError(p.given("divisions") ? "divisions" : "pop",
                         fmt::format("MOEA/D finds the neighbours of each of its {} subproblems among all of them "
                                     "before the first generation and any time limit: N^2 (M + 2) = {:.3g} "
                                     "operations in {} objectives, more than the {:.0e} done in about a second (at "
                                     "most {} subproblems in {} objectives)",
                                     n, work, objectives, kMoeadMaxSetup, most, objectives));
    };
    registry.add(std::move(moead_entry));

    auto sms_params = std::vector<ParamSpec>{integer("pop", 100, 2, 10'000'000, "population mu")};
    for (auto& s : variation_params(20.0, 0.9)) sms_params.push_back(std::move(s));
    sms_params.push_back(
        real("reference_offset", 1.0, 0.0, 1e300, "the reference point: the worst front's worst values plus this")
            .open_below());
    AlgorithmEntry sms = mo_algorithm(
        "smsemoa", "SMS-EMOA (Beume et al. 2007): steady state, the least exact hypervolume contribution leaves",
        std::move(sms_params), [](const Params& p, std::size_t) {
            SmsEmoa<> a;
            a.population = p.integer("pop");
            configure_variation(a, p);
            a.reference_offset = p.real("reference_offset");
            return a;
        });
    // Each step computes the exact contributions of the worst front, up to pop + 1 points: a
    // population past their bound would fail at its first step, after the run had started.
    sms.check_objectives = [](const Params& p, std::size_t objectives) {
        const std::size_t most = pareto::exact_hypervolume_points(objectives) / 2;
        // Below the smallest population (pop >= 2: 3 points) no pop would do: the objectives are
        // too many, which is what is said (it said "pop must be at most 0").
        if (most < 3) {
            std::size_t largest = 3;
            while (pareto::exact_hypervolume_points(largest + 1) / 2 >= 3) ++largest;
            throw InputError("objectives",
                             fmt::format("SMS-EMOA computes exact hypervolume contributions of pop + 1 points "
                                         "(pop >= 2), and in {} objectives at most {} are computed in about a "
                                         "second: too many objectives for SMS-EMOA (at most {})",
                                         objectives, most, largest));
        }
        const auto pop = static_cast<std::size_t>(p.integer("pop"));
        require(pop < most, "pop",
                fmt::format("SMS-EMOA computes exact hypervolume contributions of up to pop + 1 points, and in {} "
                            "objectives at most {} are computed in about a second: pop must be at most {}, got {}",
                            objectives, most, most - 1, pop));
    };
    registry.add(std::move(sms));
}

}  // namespace pride::engine

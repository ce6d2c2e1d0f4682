// The CMA-ES family (algorithms/cmaes.hpp): cmaes, ipop-cmaes and bipop-cmaes share one
// instantiation (the restart scheme and the boundary policy are chosen once per run); sep-cmaes is
// the diagonal one. Each also runs on problems with constraints (the `constraints` parameter).
#include "algorithms/cmaes.hpp"

#include "engine/family.hpp"

namespace pride::engine {
namespace {

template <class Covariance>
using Family = Cmaes<Covariance, cma::SelectableRestarts, cma::SelectableBoundary, SelectableInit>;

/// `boundary_default`: bipop-cmaes's is the penalty (the published BIPOP-CMA-ES searched without
/// bounds, and the penalty is the policy that lets the mean leave the box as that search does).
std::vector<ParamSpec> common_params(const char* boundary_default = "resample") {
    return {integer("pop", 0, 0, 1'000'000, "lambda of the first run; 0: 4 + floor(3 ln D) (the tutorial's eq. 48)"),
            real("sigma0", 0.3, 0.0, 10.0, "initial step as a share of each coordinate's range").open_below(),
            choice("boundary", {"resample", "clamp", "penalty"}, boundary_default,
                   "out-of-box samples: drawn again (up to 100 times, then clamped), clamped and used clamped, or "
                   "clamped with a penalty on the distance in the ranking"),
            real("penalty", 1.0, 0.0, 1e12, "the penalty's weight per squared box width (boundary = penalty)"),
            flag("active", true, "negative recombination weights (the tutorial's active update, eq. 53)"),
            real("tol_fun", 1e-12, 0.0, 1.0, "TolFun: range of recent best values that stops a run"),
            real("tol_x", 1e-12, 0.0, 1.0, "TolX: step size, relative to the initial one, that stops a run"),
            flag("max_iter", true, "MaxIter: a run stops after 100 + 50 (D + 3)^2 / sqrt(lambda) generations"),
            flag("equal_fun_values", true,
                 "EqualFunVals: a run stops when its best and (1 + ceil(0.1 + lambda / 4))-th best values are equal "
                 "in more than a third of the last D generations"),
            flag("margin", false,
                 "CMA-ES with margin (Hamano et al. 2022, as python3-cmaes's CMAwM) on integer variables; 0: they are "
                 "real coordinates the problem rounds"),
            real("margin_alpha", 0.0, 0.0, 0.5, "the margin's alpha; 0: 1 / (D lambda)").open_above(),
            choice("c0", {"range", "unit"}, "range",
                   "the initial C: diag(range^2), sigma0 a share of each range, or (min range)^2 I (Optuna's)"),
            choice("mean0", {"random", "centre"}, "random",
                   "each run's initial mean: a point of the initialiser, or the centre of the box (Optuna's)"),
            walk_init_param(false)};
}

template <class Covariance>
Family<Covariance> configure(const Params& p, std::string id, cma::SelectableRestarts restarts) {
    Family<Covariance> a;
    a.id = std::move(id);
    a.population = p.integer("pop");
    a.sigma0 = p.real("sigma0");
    a.active = p.flag("active");
    a.tolerances.fun = p.real("tol_fun");
    a.tolerances.x = p.real("tol_x");
    a.tolerances.max_iter = p.flag("max_iter");
    a.tolerances.equal_fun_values = p.flag("equal_fun_values");
    const std::string& b = p.choice("boundary");
    if (b == "clamp") {
        a.boundary = cma::ClampRepair{};
    } else if (b == "penalty") {
        cma::Penalty penalty;
        penalty.weight = p.real("penalty");
        a.boundary = penalty;
    } else {
        a.boundary = cma::Resample{};
    }
    a.restarts = std::move(restarts);
    a.margin = p.flag("margin");
    a.margin_alpha = p.real("margin_alpha");
    a.unit_covariance = p.choice("c0") == "unit";
    a.centre_start = p.choice("mean0") == "centre";
    a.init.suggestions = p.flag("walk_init");
    return a;
}

/// The restart scheme of `cmaes` and `sep-cmaes`: by default a run that stops before the budget is
/// spent is followed by another with the same lambda from a new mean (as the NLopt adapter
/// restarts), so that the baseline spends the budget it is compared under.
ParamSpec restarts_param(std::vector<std::string> choices) {
    return choice("restarts", std::move(choices), "restart",
                  "after a stopping criterion: restart with the same lambda, none (one run, the budget may be left), "
                  "or IPOP / BIPOP");
}

cma::SelectableRestarts restarts_of(const std::string& name) {
    if (name == "none") return cma::NoRestarts{};
    if (name == "ipop") return cma::Ipop{};
    if (name == "bipop") return cma::Bipop{};
    cma::Ipop same;
    same.factor = 1.0;  // independent restarts: IPOP without growth
    return same;
}

/// The handlers of constraints CMA-ES offers: the DE family's (engine/family.hpp), its static
/// penalty's r named constraint_penalty (`penalty` is the boundary policy's weight), the
/// augmented Lagrangian `al` with its parameters, and stochastic ranking with its P_f; all
/// refused on problems without constraints.
std::vector<ParamSpec> cma_constraint_params() {
    std::vector<ParamSpec> specs;
    for (auto& spec : constraint_params()) {
        if (spec.name == "constraints") {
            spec = choice("constraints", {"deb", "epsilon", "penalty", "al", "stochastic-ranking"}, "deb",
                          "how the lambda points rank under constraints: Deb's (2000) feasibility rules, Takahama and "
                          "Sakai's (2006) epsilon level, the static penalty f + constraint_penalty v, by f plus the "
                          "augmented Lagrangian of Atamna, Auger and Hansen (2016, 2017) as pycma adapts it, or "
                          "Runarsson and Yao's (2000) stochastic ranking")
                       .only_with_constraints();
        } else if (spec.name == "penalty") {
            spec =
                real("constraint_penalty", 1e6, 0.0, 1e300, "r of the static penalty f + r v (constraints = penalty)")
                    .only_with_constraints();
        }
        specs.push_back(std::move(spec));
    }
    specs.push_back(real("al_k1", 3.0, 0.0, 1e6, "k1 of the AL's coefficient step (constraints = al)")
                        .open_below()
                        .only_with_constraints());
    specs.push_back(real("al_k2", 5.0, 0.0, 1e6, "k2 of the AL's coefficient step (constraints = al)")
                        .open_below()
                        .only_with_constraints());
    specs.push_back(
        real("al_dgamma", 5.0, 0.0, 1e6, "d_gamma, the damping of the AL's multiplier step (constraints = al)")
            .open_below()
            .only_with_constraints());
    specs.push_back(real("pf", 0.45, 0.0, 1.0,
                         "P_f, the probability that two neighbours not both feasible compare by f (constraints = "
                         "stochastic-ranking; Runarsson and Yao 2000: 0.45)")
                        .only_with_constraints());
    specs.push_back(real("al_chi", 0.0, 0.0, 1e3,
                         "chi, the factor of the AL's coefficient step; 0: 2^(1 / (5 D)) (constraints = al; else > 1)")
                        .only_with_constraints());
    return specs;
}

/// The configured algorithm with the constraint handling the parameters name.
template <class A>
A with_constraints(A a, const Params& p) {
    const std::string& handler = p.choice("constraints");
    a.augmented_lagrangian = handler == "al";
    a.constraints.handler = handler == "epsilon"              ? ConstraintHandling::Handler::epsilon
                            : handler == "penalty"            ? ConstraintHandling::Handler::penalty
                            : handler == "stochastic-ranking" ? ConstraintHandling::Handler::stochastic_ranking
                                                              : ConstraintHandling::Handler::deb;
    a.constraints.pf = p.real("pf");
    a.constraints.epsilon.cp = p.real("epsilon_cp");
    a.constraints.epsilon.tc = p.integer("epsilon_tc");
    a.constraints.epsilon.theta = p.real("epsilon_theta");
    a.constraints.penalty = p.real("constraint_penalty");
    a.al.k1 = p.real("al_k1");
    a.al.k2 = p.real("al_k2");
    a.al.dgamma = p.real("al_dgamma");
    a.al.chi = p.real("al_chi");
    return a;
}

/// Adds running on boxes with constraints to a CMA-ES entry.
template <class Configure>
void add_cma_constrained_runner(AlgorithmEntry& e, Configure configure) {
    for (auto& spec : cma_constraint_params()) e.params.push_back(std::move(spec));
    add_runner<ConstrainedBoxTarget>(
        e, Kind::constrained_box, [configure](const RunRequest& r, const ConstrainedBoxTarget& target) -> Result {
            const auto algorithm = with_constraints(configure(r.params), r.params);
            const ForwardingObserver forward{r.observer};
            return std::visit(
                [&](const auto& problem) -> Result { return algorithm.run(problem, r.termination, r.seed, forward); },
                target.problem);
        });
}

/// Bytes for dimension n: C, B and the eigen solver's n x n, four n x lambda_max buffers.
auto cma_memory(bool full, double lambda_factor) {
    return [full, lambda_factor](const Params& p, std::size_t dimension) {
        const double n = static_cast<double>(dimension);
        const double first =
            static_cast<double>(p.integer("pop") > 0 ? p.integer("pop") : cma::default_lambda(dimension));
        const double lambda = first * lambda_factor;
        return 8.0 * ((full ? 4.0 * n * n : 0.0) + 4.0 * n * lambda + 5.0 * lambda + 16.0 * n);
    };
}

}  // namespace

void register_cmaes(AlgorithmRegistry& registry) {
    auto cmaes_params = common_params();
    cmaes_params.push_back(restarts_param({"restart", "none"}));
    const auto configure_cmaes = [](const Params& p) {
        return configure<cma::FullCovariance>(p, "cmaes", restarts_of(p.choice("restarts")));
    };
    auto cmaes = box_algorithm(
        "cmaes", "cmaes",
        "CMA-ES (Hansen's 2016 tutorial: active weights, CSA, Hansen 2009's stopping criteria; restarted with the "
        "same lambda until the budget is spent)",
        cmaes_params, configure_cmaes);
    cmaes.grid_population = 0;  // the tutorial's lambda on grids too
    cmaes.memory = cma_memory(true, 1.0);
    add_cma_constrained_runner(cmaes, configure_cmaes);
    registry.add(std::move(cmaes));

    auto ipop_params = common_params();
    ipop_params.push_back(
        real("factor", 2.0, 1.0, 4.0, "population growth at each restart (Auger and Hansen 2005: 2)"));
    const auto configure_ipop = [](const Params& p) {
        cma::Ipop r;
        r.factor = p.real("factor");
        return configure<cma::FullCovariance>(p, "ipop-cmaes", r);
    };
    auto ipop = box_algorithm("ipop-cmaes", "cmaes",
                              "IPOP-CMA-ES: restarts with the population doubled (Auger and Hansen 2005)", ipop_params,
                              configure_ipop);
    ipop.grid_population = 0;  // the tutorial's lambda on grids too
    ipop.memory = cma_memory(true, cma::Ipop::max_lambda_factor());
    add_cma_constrained_runner(ipop, configure_ipop);
    registry.add(std::move(ipop));

    auto bipop_params = common_params("penalty");
    bipop_params.push_back(choice("budgets", {"paper", "pycma"}, "paper",
                                  "the regimes' bookkeeping: Hansen 2009's (the first run booked to neither regime, "
                                  "a small run within half the last large run's evaluations) or pycma's (the first "
                                  "run booked to the small regime, a small run within half of all large runs')"));
    const auto configure_bipop = [](const Params& p) {
        cma::Bipop r;
        r.pycma_budget = p.choice("budgets") == "pycma";
        return configure<cma::FullCovariance>(p, "bipop-cmaes", r);
    };
    auto bipop = box_algorithm("bipop-cmaes", "cmaes",
                               "BIPOP-CMA-ES: restarts in a large and a small population regime (Hansen 2009)",
                               bipop_params, configure_bipop);
    bipop.grid_population = 0;  // the tutorial's lambda on grids too
    bipop.memory = cma_memory(true, cma::Bipop::max_lambda_factor());
    add_cma_constrained_runner(bipop, configure_bipop);
    registry.add(std::move(bipop));

    auto sep_params = common_params();
    sep_params.push_back(restarts_param({"restart", "none", "ipop", "bipop"}));
    const auto configure_sep = [](const Params& p) {
        return configure<cma::DiagonalCovariance>(p, "sep-cmaes", restarts_of(p.choice("restarts")));
    };
    auto sep = box_algorithm("sep-cmaes", "cmaes",
                             "separable CMA-ES: diagonal covariance, O(D) per sample (Ros and Hansen 2008)", sep_params,
                             configure_sep);
    sep.grid_population = 0;  // the tutorial's lambda on grids too
    sep.memory = cma_memory(false, cma::Ipop::max_lambda_factor());
    add_cma_constrained_runner(sep, configure_sep);
    registry.add(std::move(sep));
}

}  // namespace pride::engine

#pragma once
// Harmony search, continuous form.
//
//   Geem, Z. W., Kim, J. H. and Loganathan, G. V. (2001). A new heuristic optimization algorithm:
//     harmony search. Simulation 76(2), 60-68 (the algorithm: memory, HMCR, PAR, replace the worst).
//   Lee, K. S. and Geem, Z. W. (2005). A new meta-heuristic algorithm for continuous engineering
//     optimization: harmony search theory and practice. CMAME 194, 3902-3933 (the continuous
//     pitch adjustment by a bandwidth, x +- U(0,1) BW).
//   Yang, X.-S. (2009). Harmony search as a metaheuristic algorithm. In Music-Inspired Harmony
//     Search Algorithm, Springer, 1-14 (the usual ranges HMCR 0.7-0.95, PAR 0.1-0.5).
//
// The harmony memory is the population (HMS = population): drawn by the Init policy, put in the
// box by the Bounds policy, evaluated and recorded as iteration 0. Then, one harmony at a time:
//   (1) improvise (whale::improvise): per variable, with probability HMCR the value of a random
//       member, then with probability PAR plus U(-1,1) BW (high - low); otherwise U(low, high);
//   (2) the Bounds policy puts it into the box; it is evaluated;
//   (3) it replaces the worst member when strictly better.
// Defaults: HMCR 0.9 and PAR 0.3 (within Yang's ranges, the values most ports use), BW 0.01 of
// each range (Cai and Du's (2021) choice), HMS 30 (this project: the population of the WOA comparisons).
// Decided by this project where the papers are open: an iteration (one history entry) is HMS
// improvisations; the budget may end inside one.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "algorithms/parts/common/run_setup.hpp"
#include "algorithms/parts/whale/moves.hpp"
#include "framework/bounds.hpp"
#include "framework/error.hpp"
#include "framework/initializer.hpp"
#include "framework/observer.hpp"
#include "framework/problem.hpp"
#include "framework/random.hpp"
#include "framework/result.hpp"
#include "framework/run_state.hpp"
#include "framework/termination.hpp"

namespace pride {

template <class Bounds = Clamp, class Init = UniformInit>
class HarmonySearch {
  public:
    std::string id = "hs";
    std::int64_t population = 30;  // HMS
    whale::HarmonyRates rates{0.9, 0.3, 0.01};
    Bounds bounds{};
    Init init{};

    std::string name() const { return id; }

    void validate() const {
        require(population >= 1, name(), "population (HMS) must be >= 1, got " + std::to_string(population));
        require(rates.hmcr >= 0.0 && rates.hmcr <= 1.0, name(), "hmcr must be in [0, 1]");
        require(rates.par >= 0.0 && rates.par <= 1.0, name(), "par must be in [0, 1]");
        require(rates.bw >= 0.0 && rates.bw <= 1.0, name(), "bw must be in [0, 1]");
    }

    template <BoxProblem P, Observer O = NoObserver>
    Result run(P problem, const Termination& termination, std::uint64_t seed, O&& observer = O{}) const {
        auto run = start_box_run(*this, problem, termination, seed, observer);
        const auto lo = run.lo, hi = run.hi;
        Rng& rng = run.rng;
        RunState& state = run.state;
        Matrix& x = run.x;
        std::vector<double>& fx = run.fx;
        std::vector<double> y(run.dim);
        // The worst member changes only when it is replaced: it is looked for again only then.
        std::size_t w = whale::worst(fx);
        while (!state.done()) {
            for (Eigen::Index k = 0; k < x.cols() && !state.exhausted(); ++k) {
                whale::improvise(x, lo, hi, rates, rng, std::span<double>(y));  // (1)
                bounds(std::span<double>(y), lo, hi);                           // (2)
                const double f = state.evaluate(problem, std::span<const double>(y));
                if (f < fx[w]) {  // (3)
                    std::copy(y.begin(), y.end(), x.col(static_cast<Eigen::Index>(w)).data());
                    fx[w] = f;
                    w = whale::worst(fx);
                }
            }
            state.end_iteration(observer, x, fx);
        }
        return state.finish();
    }
};

}  // namespace pride

#pragma once
// NSGA-II on boxes (issue 28).
//
//   Deb, K., Pratap, A., Agarwal, S. and Meyarivan, T. (2002). A fast and elitist multiobjective
//     genetic algorithm: NSGA-II. IEEE Transactions on Evolutionary Computation 6(2), 182-197.
//
// The paper numbers no equations; its sections are cited instead. One generation t (sec. III-C):
//   (1) the offspring Q_t, N of them: parents by binary tournament on the crowded-comparison
//       operator <_n (sec. III-B: the lower front rank wins, then the larger crowding distance),
//       two children per pair by the Crossover policy (SBX), each then through the Mutation policy
//       (polynomial); sec. V's settings: p_c = 0.9, eta_c = 20, p_m = 1/n, eta_m = 20;
//   (2) Q_t evaluated;
//   (3) R_t = P_t u Q_t sorted into fronts (sec. III-A, framework/pareto/sorting.hpp); P_{t+1}
//       takes whole fronts in order while they fit, then the members of the first front that does
//       not fit with the largest crowding distances (the Survival policy: CrowdingSurvival; NSGA-III's
//       reference directions are the other policy of this skeleton); each member of P_{t+1} keeps
//       its rank and crowding distance for the tournaments of (1).
// The initial population: uniform in the box, evaluated, ranked and crowded, recorded as iteration 0.
// The result: the non-dominated members of the final population.
//
// Where the paper is silent this follows Deb's reference code (nsga2-gnu, revision 1.1.6), as
// pagmo2 does: the parents of the N children come from two random permutations of the population,
// each read four at a time (two tournaments, one pair, two children), so every member enters
// exactly two tournaments and N must be a multiple of 4; a tournament whose two entrants tie on
// <_n is decided by a fair coin. The code's tournament asks first which entrant dominates the
// other and only then compares crowding distances, where the paper compares ranks: `tournament =
// Tournament::code` is that reading (the two differ when neither entrant dominates the other but
// their ranks differ). Decided by this project: ties in crowding distance when a front is cut go
// to the lower index in R_t (parents before children), so that one seed gives one result; when
// the budget ends inside a generation, the children not evaluated have +inf in every objective.
#include <algorithm>
#include <cstdint>
#include <numeric>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/parts/crossover.hpp"
#include "algorithms/parts/mutation.hpp"
#include "framework/error.hpp"
#include "framework/mo_run_state.hpp"
#include "framework/multi_objective.hpp"
#include "framework/observer.hpp"
#include "framework/pareto/dominance.hpp"
#include "framework/pareto/sorting.hpp"
#include "framework/random.hpp"
#include "framework/termination.hpp"

namespace pride {

namespace nsga {

/// Each member's place for the tournaments: its front (0 = non-dominated) and crowding distance.
struct Standing {
    std::vector<std::size_t> rank;
    std::vector<double> crowding;
};

/// Buffers a survival step reuses from generation to generation.
struct SurvivalScratch {
    pareto::SortScratch sort;
    std::vector<std::size_t> rank, by_front, front_start, members;
    std::vector<double> distance;
    std::vector<std::pair<double, std::size_t>> cut;
};

/// (3) NSGA-II's survival: whole fronts in order, the last one cut by crowding distance, largest
/// first (sec. III-C). Writes the `keep` survivors' columns of `f` into `chosen` and their
/// standing into `out`.
struct CrowdingSurvival {
    static constexpr const char* name = "crowding";
    static constexpr const char* algorithm = "nsga2";
    /// The tournaments compare the standing (a survival with no ranking of its own says false).
    static constexpr bool ranked_mating = true;
    void operator()(const Matrix& f, std::size_t keep, std::vector<std::size_t>& chosen, Standing& out,
                    SurvivalScratch& s, Rng&) const {
        const auto n = static_cast<std::size_t>(f.cols());
        s.rank.resize(n);
        const std::size_t fronts = pareto::nondominated_sort(f, std::span<std::size_t>(s.rank), s.sort);
        // The members of each front, in index order (a counting sort on the rank).
        s.front_start.assign(fronts + 1, 0);
        for (const std::size_t r : s.rank) ++s.front_start[r + 1];
        for (std::size_t k = 0; k < fronts; ++k) s.front_start[k + 1] += s.front_start[k];
        s.by_front.resize(n);
        s.members.assign(s.front_start.begin(), s.front_start.end() - 1);  // next free slot per front
        for (std::size_t i = 0; i < n; ++i) s.by_front[s.members[s.rank[i]]++] = i;

        chosen.clear();
        out.rank.clear();
        out.crowding.clear();
        for (std::size_t k = 0; k < fronts && chosen.size() < keep; ++k) {
            const auto front = std::span<const std::size_t>(s.by_front)
                                   .subspan(s.front_start[k], s.front_start[k + 1] - s.front_start[k]);
            s.distance.resize(front.size());
            // A front of points not evaluated or with non-finite values (+inf in every objective,
            // mo_run_state.hpp: such points are only equal to each other) is not spread: 0 each.
            if (f.col(static_cast<Eigen::Index>(front[0])).allFinite())
                pareto::crowding_distance(f, front, std::span<double>(s.distance), s.sort);
            else
                std::fill(s.distance.begin(), s.distance.end(), 0.0);
            if (chosen.size() + front.size() <= keep) {
                for (std::size_t j = 0; j < front.size(); ++j) {
                    chosen.push_back(front[j]);
                    out.rank.push_back(k);
                    out.crowding.push_back(s.distance[j]);
                }
                continue;
            }
            s.cut.clear();
            for (std::size_t j = 0; j < front.size(); ++j) s.cut.emplace_back(s.distance[j], front[j]);
            const std::size_t take = keep - chosen.size();
            std::partial_sort(s.cut.begin(), s.cut.begin() + static_cast<std::ptrdiff_t>(take), s.cut.end(),
                              [](const auto& a, const auto& b) {
                                  return a.first > b.first || (a.first == b.first && a.second < b.second);
                              });
            for (std::size_t j = 0; j < take; ++j) {
                chosen.push_back(s.cut[j].second);
                out.rank.push_back(k);
                out.crowding.push_back(s.cut[j].first);
            }
        }
    }
};

/// Which tournament decides between two entrants (see the header comment).
enum class Tournament { paper, code };

}  // namespace nsga

template <class Crossover = SbxCrossover, class Mutation = PolynomialMutation, class Survival = nsga::CrowdingSurvival>
struct Nsga2 {
    std::int64_t population = 100;  // N, a multiple of 4
    Crossover crossover{20.0, 0.9};
    Mutation mutation{20.0, -1.0};  // p_m < 0: 1/n
    Survival survival{};
    nsga::Tournament tournament = nsga::Tournament::paper;

    /// nsga2, or nsga3 with NSGA-III's survival (algorithms/nsga3.hpp).
    static std::string name() { return Survival::algorithm; }

    void validate() const {
        require(population >= 4 && population <= 10'000'000 && population % 4 == 0, name(),
                "population must be a multiple of 4 in [4, 10000000] (two children per two tournaments), got " +
                    std::to_string(population));
        crossover.validate(name());
        mutation.validate(name());
    }

    template <MultiObjectiveProblem P, class O = NoObserver>
    MultiObjectiveResult run(P problem, const Termination& termination, std::uint64_t seed, O&& observer = O{}) const {
        validate();
        auto start = start_multiobjective_run(name(), problem, termination, seed);
        const std::size_t m = start.objectives;
        Rng& rng = start.rng;
        MultiObjectiveRunState& state = start.state;
        if constexpr (requires { survival.validate(m, name()); }) survival.validate(m, name());
        const std::size_t dim = problem.dimension();
        const auto n = static_cast<std::size_t>(population);
        const auto rows = static_cast<Eigen::Index>(dim), mrows = static_cast<Eigen::Index>(m);
        const auto cols = static_cast<Eigen::Index>(n);
        const auto lo = problem.lower(), hi = problem.upper();

        // R_t = [P_t | Q_t]: parents in the first N columns, children in the last N.
        Matrix r(rows, 2 * cols), fr(mrows, 2 * cols), next(rows, cols), fnext(mrows, cols);
        for (Eigen::Index j = 0; j < cols; ++j)
            for (std::size_t i = 0; i < dim; ++i) r(static_cast<Eigen::Index>(i), j) = rng.uniform(lo[i], hi[i]);
        {
            auto parents = fr.leftCols(cols);
            Matrix values(mrows, cols);
            state.evaluate_columns(problem, r.leftCols(cols), values);
            parents = values;
        }
        nsga::Standing standing;
        nsga::SurvivalScratch scratch;
        std::vector<std::size_t> chosen;
        {
            const Matrix f0 = fr.leftCols(cols);
            survival(f0, n, chosen, standing, scratch, rng);  // every member survives: ranks and distances
            // survival lists the members by front; the population keeps its order, so the standing
            // is put back in index order.
            nsga::Standing ordered{std::vector<std::size_t>(n), std::vector<double>(n)};
            for (std::size_t k = 0; k < n; ++k) {
                ordered.rank[chosen[k]] = standing.rank[k];
                ordered.crowding[chosen[k]] = standing.crowding[k];
            }
            standing = std::move(ordered);
        }
        {
            const Matrix p0 = r.leftCols(cols), f0 = fr.leftCols(cols);
            state.end_iteration(observer, p0, f0);
        }

        const auto cross = crossover.prepare(dim);
        const auto mutate = mutation.prepare(dim);
        std::vector<std::size_t> perm(n);
        Matrix fq(mrows, cols);
        while (!state.done()) {
            // (1) two permutations, four entrants at a time: two tournaments, two children.
            std::size_t child = 0;
            for (int pass = 0; pass < 2; ++pass) {
                std::iota(perm.begin(), perm.end(), std::size_t{0});
                for (std::size_t i = n; i > 1; --i)
                    std::swap(perm[i - 1], perm[static_cast<std::size_t>(rng.below(i))]);
                for (std::size_t i = 0; i + 3 < n; i += 4) {
                    const std::size_t a = winner(perm[i], perm[i + 1], fr, standing, rng);
                    const std::size_t b = winner(perm[i + 2], perm[i + 3], fr, standing, rng);
                    const auto c1 = cols + static_cast<Eigen::Index>(child), c2 = c1 + 1;
                    r.col(c1) = r.col(static_cast<Eigen::Index>(a));
                    r.col(c2) = r.col(static_cast<Eigen::Index>(b));
                    cross(column(r, c1), column(r, c2), lo, hi, rng);
                    mutate(column(r, c1), lo, hi, rng);
                    mutate(column(r, c2), lo, hi, rng);
                    child += 2;
                }
            }
            // (2)
            state.evaluate_columns(problem, r.rightCols(cols), fq);
            fr.rightCols(cols) = fq;
            // (3)
            survival(fr, n, chosen, standing, scratch, rng);
            for (std::size_t k = 0; k < n; ++k) {
                next.col(static_cast<Eigen::Index>(k)) = r.col(static_cast<Eigen::Index>(chosen[k]));
                fnext.col(static_cast<Eigen::Index>(k)) = fr.col(static_cast<Eigen::Index>(chosen[k]));
            }
            r.leftCols(cols) = next;
            fr.leftCols(cols) = fnext;
            state.end_iteration(observer, next, fnext);
        }
        std::vector<std::size_t> front;
        for (std::size_t k = 0; k < n; ++k)
            if (standing.rank[k] == 0) front.push_back(k);
        const Matrix p = r.leftCols(cols), f = fr.leftCols(cols);
        return state.finish(p, f, front);
    }

  private:
    /// The winner of a binary tournament between members a and b of the population.
    std::size_t winner(std::size_t a, std::size_t b, const Matrix& f, const nsga::Standing& s, Rng& rng) const {
        if constexpr (!Survival::ranked_mating) return rng.uniform() <= 0.5 ? a : b;
        if (tournament == nsga::Tournament::code) {
            const auto fa = pareto::point(f, static_cast<Eigen::Index>(a));
            const auto fb = pareto::point(f, static_cast<Eigen::Index>(b));
            if (pareto::dominates(fa, fb)) return a;
            if (pareto::dominates(fb, fa)) return b;
        } else {
            if (s.rank[a] != s.rank[b]) return s.rank[a] < s.rank[b] ? a : b;
        }
        if (s.crowding[a] != s.crowding[b]) return s.crowding[a] > s.crowding[b] ? a : b;
        return rng.uniform() <= 0.5 ? a : b;
    }
};

}  // namespace pride

#pragma once
// MOEA/D with Tchebycheff decomposition on boxes.
//
//   Zhang, Q. and Li, H. (2007). MOEA/D: a multiobjective evolutionary algorithm based on
//     decomposition. IEEE Transactions on Evolutionary Computation 11(6), 712-731.
//   Li, H. and Zhang, Q. (2009). Multiobjective optimization problems with complicated Pareto
//     sets, MOEA/D and NSGA-II. IEEE Transactions on Evolutionary Computation 13(2), 284-302
//     (MOEA/D-DE).
//
// The 2007 paper states its problem as maximisation (eq. 1); every objective here is minimised,
// so its ideal point z* is the componentwise minimum. N subproblems, one per weight vector
// lambda^i of Das and Dennis's lattice (framework/pareto/reference_directions.hpp), subproblem i
// being the Tchebycheff aggregation (sec. II-B, eq. 3)
//   g^te(x | lambda, z*) = max_{1<=k<=M} lambda_k |f_k(x) - z*_k|.
// Initialisation (sec. III, step 1): B(i), the T weight vectors closest to lambda^i (Euclidean,
// lambda^i itself first), a population uniform in the box, one member per subproblem, evaluated;
// z* the best value of each objective seen. One generation (step 2), for each subproblem i:
//   (1) the pool P: B(i), or with probability 1 - delta the whole population (Li and Zhang 2009,
//       sec. III; delta = 1 is the 2007 paper);
//   (2) reproduction from two distinct members k, l of P (the Reproduction policy):
//       SbxReproduction, the 2007 paper's operators for ZDT (sec. V: SBX with eta 20 and
//       probability 1, polynomial mutation with eta 20 and p_m = 1/n), or DeReproduction,
//       MOEA/D-DE's y = x^i + F (x^k - x^l) with probability CR per coordinate, repaired into the
//       box, then polynomial mutation (2009: F = 0.5, CR = 1, eta 20, p_m = 1/n);
//   (3) the child evaluated, z* updated with it (step 2.3);
//   (4) the members j of P, in random order, replaced by the child when g^te(child | lambda^j, z*)
//       <= g^te(x^j | lambda^j, z*), at most n_r of them (2009: n_r = 2; the 2007 paper's step 2.4
//       tries every member of B(i): n_r = 0 here, no limit).
// The initial population is iteration 0, each generation one more. (The papers' equation, section
// and step numbers and settings are cited as recalled; they were not checked against the text.)
//
// Defaults: MOEA/D-DE with pagmo2's moead defaults (T = 20, F = 0.5, CR = 1, eta_m = 20,
// delta = 0.9, n_r = 2), the variant most users run; Moead<moead::SbxReproduction> with
// delta = 1 and replacements = 0 is the 2007 paper's algorithm. Where the sources differ:
// - a weight lambda_k = 0 makes g^te blind to objective k, so such a weight counts as 1e-4
//   (`zero_weight`), as pagmo2's decompose_objectives and jMetal's MOEA/D do;
// - DE's repair: pagmo2 moves a coordinate below `lo` to lo + u (x^i - lo) (u uniform, above
//   `hi` likewise), between the bound and the parent; the 2009 paper's step resets it to a
//   uniform value in the box: Repair::toward_parent (default, for the comparison with pagmo2)
//   and Repair::uniform;
// - the order of the subproblems in a generation: 1..N in the papers, a new random permutation
//   each generation in pagmo2 and jMetal: Order::in_order (default) and Order::shuffled;
// - pagmo2 compares with < where the papers write <=, keeps i out of B(i) and tries i first; here
//   the papers.
// Decided by this project: the user gives H (`divisions`), or N (`population`) and the run takes
// the largest H whose lattice has at most N directions (N = 100, M = 3: H = 12, 91 subproblems);
// ties in distance go to the lower index (distances computed on the lattice's integer counts, so
// that equal distances are equal to the bit); k and l may be i itself; a child with a non-finite
// objective (+inf in every one, mo_run_state.hpp) replaces nothing; when the budget ends inside a
// generation the generation ends there. The result is the non-dominated members of the final
// population (no external population, the 2007 paper's EP: the population is what pagmo2 and most
// users read; the same point may stand for several subproblems and then appears more than once).
// With constraints (framework/multi_objective.hpp's ConstrainedMultiObjectiveProblem), step (4)
// replaces by violation first: the child replaces x^j when its violation is smaller, or equal and
// g^te no worse (Jain and Deb 2014, part II, C-MOEA/D's rule; two feasible points compare by g^te
// alone, as above). Decided by this project: z* is the ideal of the feasible points seen once there
// is one (an infeasible point's values would pull it below the feasible front for good), of every
// point until then; the result is the first front of constrained domination (Deb et al. 2002).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/parts/variation/crossover.hpp"
#include "algorithms/parts/variation/mutation.hpp"
#include "framework/error.hpp"
#include "framework/mo_run_state.hpp"
#include "framework/multi_objective.hpp"
#include "framework/observer.hpp"
#include "framework/pareto/constrained_sorting.hpp"
#include "framework/pareto/reference_directions.hpp"
#include "framework/pareto/sorting.hpp"
#include "framework/random.hpp"
#include "framework/termination.hpp"

namespace pride {

namespace moead {

/// The largest number of subproblems: B(i) costs N^2 distances once.
inline constexpr std::size_t kMaxSubproblems = 100'000;

/// For each column i of `directions` (N columns), the `t` nearest columns by Euclidean distance,
/// ties to the lower index, as one row-major N x t array: row i is B(i), nearest first (i itself,
/// at distance 0, unless an earlier column equals it). Compared as squared distances: the same
/// order when they are exact, as on a lattice's integer counts.
inline std::vector<std::size_t> neighbourhoods(const MatrixView& directions, std::size_t t) {
    const auto n = static_cast<std::size_t>(directions.cols());
    require(t >= 1 && t <= n, "neighbourhoods",
            "needs 1 <= T <= N = " + std::to_string(n) + " neighbours, got " + std::to_string(t));
    std::vector<std::size_t> out(n * t);
    std::vector<std::pair<double, std::size_t>> d(n);
    for (std::size_t i = 0; i < n; ++i) {
        const auto a = directions.col(static_cast<Eigen::Index>(i));
        for (std::size_t j = 0; j < n; ++j)
            d[j] = {(directions.col(static_cast<Eigen::Index>(j)) - a).squaredNorm(), j};
        // (distance, index) pairs compare as the rule says: distance, then the lower index.
        std::nth_element(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(t - 1), d.end());
        std::sort(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(t));
        for (std::size_t k = 0; k < t; ++k) out[i * t + k] = d[k].second;
    }
    return out;
}

/// g^te(f | lambda, z*) = max_k lambda_k |f_k - z*_k| (eq. 3), with the weights as given (the
/// caller substitutes zero weights). +inf when f is; z* is finite wherever the algorithm calls it.
inline double tchebycheff(std::span<const double> f, std::span<const double> weights,
                          std::span<const double> ideal) noexcept {
    double g = 0.0;
    for (std::size_t k = 0; k < f.size(); ++k) g = std::max(g, weights[k] * std::abs(f[k] - ideal[k]));
    return g;
}

/// How DE's coordinates outside the box are brought back (see the header comment).
enum class Repair { toward_parent, uniform };

/// In which order a generation visits the subproblems (see the header comment).
enum class Order { in_order, shuffled };

/// The 2007 paper's reproduction: SBX of x^k and x^l, its first child kept, then polynomial
/// mutation (SBX and the mutation keep the child in the box).
struct SbxReproduction {
    static constexpr const char* name = "sbx";
    SbxCrossover crossover{20.0, 1.0};
    PolynomialMutation mutation{20.0, -1.0};  // p_m < 0: 1/n

    void validate(const std::string& where) const {
        crossover.validate(where);
        mutation.validate(where);
    }

    class Prepared {
      public:
        Prepared(const SbxReproduction& r, std::size_t dim)
            : cross_(r.crossover.prepare(dim)), mutate_(r.mutation.prepare(dim)), other_(dim) {}

        void operator()(const Matrix& x, std::size_t, std::size_t k, std::size_t l, std::span<double> child,
                        std::span<const double> lo, std::span<const double> hi, Rng& rng) {
            const auto a = column(x, static_cast<Eigen::Index>(k)), b = column(x, static_cast<Eigen::Index>(l));
            std::copy(a.begin(), a.end(), child.begin());
            std::copy(b.begin(), b.end(), other_.begin());
            cross_(child, std::span<double>(other_), lo, hi, rng);
            mutate_(child, lo, hi, rng);
        }

      private:
        SbxCrossover::Prepared cross_;
        PolynomialMutation::Prepared mutate_;
        std::vector<double> other_;  // SBX's second child, dropped; sized once
    };

    Prepared prepare(std::size_t dim) const { return Prepared(*this, dim); }
};

/// MOEA/D-DE's reproduction: y_j = x^i_j + F (x^k_j - x^l_j) with probability CR (else x^i_j),
/// repaired into the box, then polynomial mutation.
struct DeReproduction {
    static constexpr const char* name = "de";
    double f = 0.5;
    double cr = 1.0;
    PolynomialMutation mutation{20.0, -1.0};  // p_m < 0: 1/n
    Repair repair = Repair::toward_parent;

    void validate(const std::string& where) const {
        require(f >= 0.0 && f <= 2.0, where, "F must be in [0, 2], got " + std::to_string(f));
        require(cr >= 0.0 && cr <= 1.0, where, "CR must be in [0, 1], got " + std::to_string(cr));
        mutation.validate(where);
    }

    class Prepared {
      public:
        Prepared(const DeReproduction& r, std::size_t dim)
            : f_(r.f), cr_(r.cr), repair_(r.repair), mutate_(r.mutation.prepare(dim)) {}

        void operator()(const Matrix& x, std::size_t i, std::size_t k, std::size_t l, std::span<double> child,
                        std::span<const double> lo, std::span<const double> hi, Rng& rng) const {
            const auto base = column(x, static_cast<Eigen::Index>(i));
            const auto a = column(x, static_cast<Eigen::Index>(k)), b = column(x, static_cast<Eigen::Index>(l));
            for (std::size_t j = 0; j < child.size(); ++j) {
                // CR = 1 (the default) draws nothing: every coordinate moves.
                if (cr_ < 1.0 && !(rng.uniform() < cr_)) {
                    child[j] = base[j];
                    continue;
                }
                double y = base[j] + f_ * (a[j] - b[j]);
                if (y < lo[j])
                    y = repair_ == Repair::toward_parent ? lo[j] + rng.uniform() * (base[j] - lo[j])
                                                         : rng.uniform(lo[j], hi[j]);
                else if (y > hi[j])
                    y = repair_ == Repair::toward_parent ? hi[j] - rng.uniform() * (hi[j] - base[j])
                                                         : rng.uniform(lo[j], hi[j]);
                child[j] = y;
            }
            mutate_(child, lo, hi, rng);
        }

      private:
        double f_, cr_;
        Repair repair_;
        PolynomialMutation::Prepared mutate_;
    };

    Prepared prepare(std::size_t dim) const { return Prepared(*this, dim); }
};

}  // namespace moead

template <class Reproduction = moead::DeReproduction>
struct Moead {
    std::int64_t divisions = 0;     // H of the lattice; 0: the largest H whose lattice fits `population`
    std::int64_t population = 100;  // N's upper bound when divisions = 0
    std::int64_t neighbours = 20;   // T, the size of B(i) (i included)
    double delta = 0.9;             // probability that the pool is B(i) rather than the population
    std::int64_t replacements = 2;  // n_r, the most members one child replaces; 0: no limit
    double zero_weight = 1e-4;      // what a weight lambda_k = 0 counts as in g^te
    moead::Order order = moead::Order::in_order;
    Reproduction reproduction{};

    static std::string name() { return "moead"; }

    void validate() const {
        require(divisions >= 0, name(),
                "divisions H must be >= 0 (0: from population), got " + std::to_string(divisions));
        require(divisions > 0 || (population >= 2 && population <= static_cast<std::int64_t>(moead::kMaxSubproblems)),
                name(),
                "population must be in [2, " + std::to_string(moead::kMaxSubproblems) + "], got " +
                    std::to_string(population));
        require(neighbours >= 2, name(), "neighbours T must be >= 2 (two parents), got " + std::to_string(neighbours));
        require(delta >= 0.0 && delta <= 1.0, name(), "delta must be in [0, 1], got " + std::to_string(delta));
        require(replacements >= 0, name(),
                "replacements n_r must be >= 0 (0: no limit), got " + std::to_string(replacements));
        require(zero_weight > 0.0 && zero_weight <= 1.0, name(),
                "zero_weight must be in (0, 1], got " + std::to_string(zero_weight));
        reproduction.validate(name());
    }

    /// The run's weight vectors: M rows, one column per subproblem.
    Matrix weights(std::size_t m) const {
        validate();
        return pareto::simplex_lattice(m, lattice_divisions(m));
    }

    template <MultiObjectiveProblem P, class O = NoObserver>
    MultiObjectiveResult run(P problem, const Termination& termination, std::uint64_t seed, O&& observer = O{}) const {
        validate();
        auto start = start_multiobjective_run(name(), problem, termination, seed);
        const std::size_t m = start.objectives;
        Rng& rng = start.rng;
        MultiObjectiveRunState& state = start.state;
        const std::size_t h = lattice_divisions(m);
        const Matrix lambda = pareto::simplex_lattice(m, h);
        const auto n = static_cast<std::size_t>(lambda.cols());
        const auto t = static_cast<std::size_t>(neighbours);
        require(t <= n, name(),
                "neighbours T must be at most N = " + std::to_string(n) + " subproblems, got " + std::to_string(t));
        const std::size_t dim = problem.dimension();
        const auto rows = static_cast<Eigen::Index>(dim), mrows = static_cast<Eigen::Index>(m);
        const auto cols = static_cast<Eigen::Index>(n);
        const auto lo = problem.lower(), hi = problem.upper();

        // B(i) on the lattice's integer counts H lambda: exact distances, so exact ties.
        const std::vector<std::size_t> b =
            moead::neighbourhoods((lambda * static_cast<double>(h)).array().round().matrix(), t);
        const Matrix w = (lambda.array() == 0.0).select(zero_weight, lambda);

        Matrix x(rows, cols), fx(mrows, cols);
        // Constraints only (empty otherwise): the members' violations, and the child's.
        constexpr bool constrained = ConstrainedMultiObjectiveProblem<P>;
        std::vector<double> vx(constrained ? n : 0), vchild(constrained ? 1 : 0);
        const auto evaluate = [&](MatrixView points, Matrix& out, std::span<double> violation) {
            if constexpr (constrained)
                state.evaluate_columns(problem, points, out, violation);
            else
                state.evaluate_columns(problem, points, out);
        };
        for (Eigen::Index j = 0; j < cols; ++j)
            for (std::size_t i = 0; i < dim; ++i) x(static_cast<Eigen::Index>(i), j) = rng.uniform(lo[i], hi[i]);
        evaluate(x, fx, vx);
        std::vector<double> z(m);  // +inf while no finite point is seen
        // With constraints z* is the feasible points' ideal once one is seen, all points' until then
        // (z_all; see the header comment).
        std::vector<double> z_all;
        bool feasible_seen = false;
        if constexpr (constrained) {
            z.assign(m, kInf);
            z_all.assign(m, kInf);
            for (std::size_t j = 0; j < n; ++j) {
                feasible_seen = feasible_seen || vx[j] == 0.0;
                for (std::size_t k = 0; k < m; ++k) {
                    const double fk = fx(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(j));
                    z_all[k] = std::min(z_all[k], fk);
                    if (vx[j] == 0.0) z[k] = std::min(z[k], fk);
                }
            }
            if (!feasible_seen) z = z_all;
        } else {
            for (std::size_t k = 0; k < m; ++k) z[k] = fx.row(static_cast<Eigen::Index>(k)).minCoeff();
        }
        state.end_iteration(observer, x, fx);

        auto reproduce = reproduction.prepare(dim);
        Matrix child(rows, 1), fchild(mrows, 1);
        const auto y = column(child, 0);
        const auto fy = std::span<const double>(fchild.data(), m);
        std::vector<std::size_t> visit(n), whole(n), pool(t);
        std::iota(visit.begin(), visit.end(), std::size_t{0});
        std::iota(whole.begin(), whole.end(), std::size_t{0});  // any permutation of 0..N-1 will do
        const std::size_t limit = replacements == 0 ? n : static_cast<std::size_t>(replacements);
        while (!state.done()) {
            if (order == moead::Order::shuffled)
                for (std::size_t i = n; i > 1; --i)
                    std::swap(visit[i - 1], visit[static_cast<std::size_t>(rng.below(i))]);
            for (const std::size_t i : visit) {
                if (state.exhausted()) break;
                // (1) delta = 1 draws nothing.
                const bool local = delta >= 1.0 || rng.uniform() < delta;
                std::span<std::size_t> from;
                if (local) {
                    std::copy_n(b.begin() + static_cast<std::ptrdiff_t>(i * t), t, pool.begin());
                    from = pool;
                } else {
                    from = whole;
                }
                const std::size_t size = from.size();
                // (2) two distinct members.
                const auto first = static_cast<std::size_t>(rng.below(size));
                auto second = static_cast<std::size_t>(rng.below(size - 1));
                second += second >= first;
                reproduce(x, i, from[first], from[second], y, lo, hi, rng);
                // (3)
                evaluate(child, fchild, vchild);
                if (!std::isfinite(fy[0])) continue;  // +inf in every objective: replaces nothing
                if constexpr (constrained) {
                    for (std::size_t k = 0; k < m; ++k) z_all[k] = std::min(z_all[k], fy[k]);
                    if (vchild[0] == 0.0) {
                        if (!feasible_seen) std::fill(z.begin(), z.end(), kInf);
                        feasible_seen = true;
                        for (std::size_t k = 0; k < m; ++k) z[k] = std::min(z[k], fy[k]);
                    } else if (!feasible_seen) {
                        z = z_all;
                    }
                } else {
                    for (std::size_t k = 0; k < m; ++k) z[k] = std::min(z[k], fy[k]);
                }
                // (4) Without a limit every member is tried (the order is then irrelevant: no
                // draws); with one, a partial Fisher-Yates shuffle picks them in random order.
                std::size_t replaced = 0;
                const bool all = limit >= size;
                for (std::size_t s = 0; s < size && replaced < limit; ++s) {
                    if (!all) std::swap(from[s], from[s + static_cast<std::size_t>(rng.below(size - s))]);
                    const std::size_t j = from[s];
                    const auto wj = column(w, static_cast<Eigen::Index>(j));
                    const auto fj = column(fx, static_cast<Eigen::Index>(j));
                    bool better;
                    if constexpr (constrained)
                        better = vchild[0] != vx[j] ? vchild[0] < vx[j]
                                                    : moead::tchebycheff(fy, wj, z) <= moead::tchebycheff(fj, wj, z);
                    else
                        better = moead::tchebycheff(fy, wj, z) <= moead::tchebycheff(fj, wj, z);
                    if (better) {
                        x.col(static_cast<Eigen::Index>(j)) = child.col(0);
                        fx.col(static_cast<Eigen::Index>(j)) = fchild.col(0);
                        if constexpr (constrained) vx[j] = vchild[0];
                        ++replaced;
                    }
                }
            }
            state.end_iteration(observer, x, fx);
        }
        std::vector<std::size_t> rank(n), front;
        pareto::ConstrainedSortScratch scratch;
        pareto::constrained_sort(fx, vx, std::span<std::size_t>(rank), scratch);
        for (std::size_t k = 0; k < n; ++k)
            if (rank[k] == 0) front.push_back(k);
        return state.finish(x, fx, front, vx);
    }

  private:
    /// H: `divisions`, or the largest whose lattice has at most `population` directions; checked
    /// against M and kMaxSubproblems before anything is allocated.
    std::size_t lattice_divisions(std::size_t m) const {
        require(m >= 2 && m <= pareto::kMaxLatticeObjectives, name(),
                "needs 2 <= M <= " + std::to_string(pareto::kMaxLatticeObjectives) + " objectives, got " +
                    std::to_string(m));
        if (divisions > 0) {
            const auto h = static_cast<std::size_t>(divisions);
            require(pareto::simplex_lattice_size(m, h) <= moead::kMaxSubproblems, name(),
                    "the lattice of M = " + std::to_string(m) + " objectives and H = " + std::to_string(h) +
                        " has more than " + std::to_string(moead::kMaxSubproblems) + " directions");
            return h;
        }
        const auto cap = static_cast<std::size_t>(population);
        require(cap >= m, name(),
                "population must be at least M = " + std::to_string(m) + " (the lattice of H = 1), got " +
                    std::to_string(cap));
        return pareto::simplex_lattice_divisions(m, cap);
    }
};

}  // namespace pride

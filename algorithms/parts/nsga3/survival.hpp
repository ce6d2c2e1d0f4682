#pragma once
// NSGA-III's survival, the Survival policy of the NSGA-II skeleton (algorithms/nsga2.hpp) that
// makes it NSGA-III:
//
//   Deb, K. and Jain, H. (2014). An evolutionary many-objective optimization algorithm using
//     reference-point-based nondominated sorting approach, part I: solving problems with box
//     constraints. IEEE Transactions on Evolutionary Computation 18(4), 577-601.
//
// From R_t sorted into fronts, S_t = the fronts F_1 .. F_l up to the first one that does not fit
// whole (sec. IV-B, Algorithm 1). P_{t+1} takes F_1 .. F_{l-1}; the K members still missing come
// from F_l by niching on the reference directions Z (columns of `directions`, e.g. Das and
// Dennis's lattice, framework/pareto/reference_directions.hpp):
//   (C) normalisation (sec. IV-C, Algorithm 2): the ideal point z_i = min over S_t of f_i, the
//       translated f'_i = f_i - z_i; for each axis i the extreme point, the member of S_t that
//       minimises ASF(x, w^i) = max_j f'_j(x) / w^i_j, w^i = e_i with 1e-6 elsewhere (eq. 4); the
//       intercepts a_i of the hyperplane through the M extreme points; f^n_i = f'_i / a_i (eq. 5);
//   (D) association (sec. IV-D, Algorithm 3): each member of S_t to the reference line w of least
//       perpendicular distance d(x, w) = |f^n - (w.f^n / |w|^2) w|;
//   (E) niching (sec. IV-E, Algorithm 4): rho_j = the members of P_{t+1} associated with w_j;
//       repeat K times: among the directions not excluded, those of least rho_j, one drawn at
//       random; no member of F_l left on it: excluded; else the member of F_l on it of least d
//       when rho_j = 0, a random one otherwise; rho_j + 1.
// Mating: the paper selects parents at random, with no tournament (sec. IV-F): `ranked_mating` is
// false, so the skeleton's tournaments become fair coins.
// Decided by this project where the paper is silent: when the hyperplane is degenerate (the
// extreme points' matrix singular, or an intercept not above 1e-10 or not finite), a_i falls back
// to the largest f'_i over the first front of S_t (its nadir), and to 1 where that is 0 too;
// extreme points are taken from S_t alone (later codes keep the previous generation's as
// candidates; the paper's Algorithm 2 does not); ties in the association go to the lower direction
// index, in d to the lower column; members with non-finite values (+inf in every objective,
// framework/mo_run_state.hpp) take no part in normalisation, and a last front of such members is
// cut by index. The standing handed back for the tournaments is the rank with crowding 0.
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "algorithms/nsga2.hpp"
#include "framework/error.hpp"
#include "framework/pareto/constrained_sorting.hpp"
#include "framework/pareto/sorting.hpp"
#include "framework/problem.hpp"
#include "framework/random.hpp"

namespace pride::nsga {

struct ReferenceDirectionSurvival {
    static constexpr const char* name = "reference-directions";
    static constexpr const char* algorithm = "nsga3";
    static constexpr bool ranked_mating = false;
    Matrix directions;  // M rows, one column per reference direction

    void validate(std::size_t objectives, const std::string& who) const {
        require(directions.cols() >= 1, who, "needs at least one reference direction");
        require(static_cast<std::size_t>(directions.rows()) == objectives, who,
                "the reference directions have " + std::to_string(directions.rows()) + " objectives, the problem " +
                    std::to_string(objectives));
        require(directions.allFinite() && directions.minCoeff() >= 0.0, who,
                "reference directions must be finite and >= 0");
        for (Eigen::Index j = 0; j < directions.cols(); ++j)
            require(directions.col(j).squaredNorm() > 0.0, who,
                    "reference direction " + std::to_string(j + 1) + " is 0");
    }

    void operator()(const Matrix& f, std::span<const double> v, std::size_t keep, std::vector<std::size_t>& chosen,
                    Standing& out, SurvivalScratch& s, Rng& rng) const {
        const auto n = static_cast<std::size_t>(f.cols());
        const auto m = f.rows();
        s.rank.resize(n);
        const std::size_t fronts = pareto::constrained_sort(f, v, std::span<std::size_t>(s.rank), s.ranking);
        chosen.clear();
        out.rank.clear();
        out.crowding.clear();
        // S_t: whole fronts while they fit; `last` is F_l's rank (fronts when all fit).
        std::vector<std::size_t> count(fronts, 0);
        for (const std::size_t r : s.rank) ++count[r];
        std::size_t last = 0, taken = 0;
        while (last < fronts && taken + count[last] <= keep) taken += count[last++];
        for (std::size_t i = 0; i < n; ++i)
            if (s.rank[i] < last) chosen.push_back(i);
        if (chosen.size() == keep || last == fronts) return finish(chosen, out, s);
        std::vector<std::size_t> tail;  // F_l
        for (std::size_t i = 0; i < n; ++i)
            if (s.rank[i] == last) tail.push_back(i);
        const std::size_t missing = keep - chosen.size();
        // Infeasible (one violation: constrained_sort's fronts) or failed: cut by index.
        if ((!v.empty() && v[tail.front()] != 0.0) || !f.col(static_cast<Eigen::Index>(tail.front())).allFinite()) {
            chosen.insert(chosen.end(), tail.begin(), tail.begin() + static_cast<std::ptrdiff_t>(missing));
            return finish(chosen, out, s);
        }

        // (C) over the finite members of S_t = P_{t+1} u F_l.
        std::vector<std::size_t> st(chosen);
        st.insert(st.end(), tail.begin(), tail.end());
        std::erase_if(st, [&](std::size_t i) { return !f.col(static_cast<Eigen::Index>(i)).allFinite(); });
        const Eigen::VectorXd ideal = gather(f, st).rowwise().minCoeff();
        const Eigen::VectorXd intercepts = find_intercepts(f, st, ideal, s);

        // (D) every member of S_t, by position in st: its direction and distance.
        const auto z = directions.cols();
        std::vector<Eigen::Index> line(st.size());
        std::vector<double> distance(st.size());
        Eigen::VectorXd fn(m);
        for (std::size_t k = 0; k < st.size(); ++k) {
            fn = (f.col(static_cast<Eigen::Index>(st[k])) - ideal).cwiseQuotient(intercepts);
            double best = std::numeric_limits<double>::infinity();
            for (Eigen::Index j = 0; j < z; ++j) {
                const auto w = directions.col(j);
                const double d = (fn - (w.dot(fn) / w.squaredNorm()) * w).norm();
                if (d < best) {
                    best = d;
                    line[k] = j;
                }
            }
            distance[k] = best;
        }

        // (E) niche counts of P_{t+1}, then K members of F_l.
        std::vector<std::size_t> rho(static_cast<std::size_t>(z), 0);
        std::vector<std::vector<std::size_t>> waiting(static_cast<std::size_t>(z));  // positions in st of F_l
        for (std::size_t k = 0; k < st.size(); ++k) {
            if (s.rank[st[k]] < last)
                ++rho[static_cast<std::size_t>(line[k])];
            else
                waiting[static_cast<std::size_t>(line[k])].push_back(k);
        }
        std::vector<char> excluded(static_cast<std::size_t>(z), 0);
        std::vector<std::size_t> least;
        while (chosen.size() < keep) {
            std::size_t low = std::numeric_limits<std::size_t>::max();
            least.clear();
            for (std::size_t j = 0; j < rho.size(); ++j) {
                if (excluded[j]) continue;
                if (rho[j] < low) {
                    low = rho[j];
                    least.clear();
                }
                if (rho[j] == low) least.push_back(j);
            }
            const std::size_t j = least[static_cast<std::size_t>(rng.below(least.size()))];
            auto& members = waiting[j];
            if (members.empty()) {
                excluded[j] = 1;
                continue;
            }
            std::size_t pick = 0;
            if (rho[j] == 0) {
                for (std::size_t q = 1; q < members.size(); ++q)
                    if (distance[members[q]] < distance[members[pick]]) pick = q;
            } else {
                pick = static_cast<std::size_t>(rng.below(members.size()));
            }
            chosen.push_back(st[members[pick]]);
            members.erase(members.begin() + static_cast<std::ptrdiff_t>(pick));
            ++rho[j];
        }
        finish(chosen, out, s);
    }

  private:
    static Matrix gather(const Matrix& f, const std::vector<std::size_t>& columns) {
        Matrix g(f.rows(), static_cast<Eigen::Index>(columns.size()));
        for (std::size_t k = 0; k < columns.size(); ++k)
            g.col(static_cast<Eigen::Index>(k)) = f.col(static_cast<Eigen::Index>(columns[k]));
        return g;
    }

    /// (C): the intercepts a_i, with the fallback of the header comment.
    static Eigen::VectorXd find_intercepts(const Matrix& f, const std::vector<std::size_t>& st,
                                           const Eigen::VectorXd& ideal, const SurvivalScratch& s) {
        const auto m = f.rows();
        Matrix extreme(m, m);  // row i: the translated extreme point of axis i
        for (Eigen::Index i = 0; i < m; ++i) {
            double best = std::numeric_limits<double>::infinity();
            for (const std::size_t c : st) {
                double asf = 0.0;
                for (Eigen::Index j = 0; j < m; ++j)
                    asf = std::max(asf, (f(j, static_cast<Eigen::Index>(c)) - ideal(j)) / (j == i ? 1.0 : 1e-6));
                if (asf < best) {
                    best = asf;
                    extreme.row(i) = (f.col(static_cast<Eigen::Index>(c)) - ideal).transpose();
                }
            }
        }
        Eigen::VectorXd a(m);
        const Eigen::FullPivLU<Matrix> lu(extreme);
        bool good = lu.isInvertible();
        if (good) {
            const Eigen::VectorXd b = lu.solve(Eigen::VectorXd::Ones(m));
            a = b.cwiseInverse();
            good = a.allFinite() && a.minCoeff() > 1e-10;
        }
        if (!good) {
            a.setZero();
            for (const std::size_t c : st)
                if (s.rank[c] == 0) a = a.cwiseMax(f.col(static_cast<Eigen::Index>(c)) - ideal);
            for (Eigen::Index i = 0; i < m; ++i)
                if (!(a(i) > 0.0)) a(i) = 1.0;
        }
        return a;
    }

    static void finish(const std::vector<std::size_t>& chosen, Standing& out, const SurvivalScratch& s) {
        for (const std::size_t c : chosen) {
            out.rank.push_back(s.rank[c]);
            out.crowding.push_back(0.0);
        }
    }
};

}  // namespace pride::nsga

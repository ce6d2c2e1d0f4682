// framework/pareto/ against pagmo2's own algorithms (as oracles), on random sets at M = 2, 3
// and 5: the hypervolume against pagmo's hv2d, hv3d and hvwfg, the non-dominated sort against its
// fast_non_dominated_sorting, the crowding distance against its crowding_distance. Compiled only
// when the build found pagmo2 (scripts/deps.sh --bench installs it); pride itself does not depend
// on it.
#ifdef PRIDE_HAVE_PAGMO
#include <catch2/catch.hpp>

#include <cmath>
#include <cstddef>
#include <vector>

#include <pagmo/utils/hv_algos/hv_hv2d.hpp>
#include <pagmo/utils/hv_algos/hv_hv3d.hpp>
#include <pagmo/utils/hv_algos/hv_hvwfg.hpp>
#include <pagmo/utils/hypervolume.hpp>
#include <pagmo/utils/multi_objective.hpp>

#include "framework/pareto/hypervolume.hpp"
#include "framework/pareto/sorting.hpp"
#include "framework/random.hpp"

namespace {

/// n random points near the unit sphere's positive orthant (mostly non-dominated, some dominated:
/// the radius varies by up to 30 %), as pagmo's vectors and as one column each.
struct RandomSet {
    std::vector<pagmo::vector_double> points;
    pride::Matrix f;
};

RandomSet random_set(std::size_t m, std::size_t n, std::uint64_t seed) {
    pride::Rng rng(seed);
    RandomSet s{{}, pride::Matrix(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(n))};
    for (std::size_t j = 0; j < n; ++j) {
        pagmo::vector_double p(m);
        double norm = 0.0;
        for (double& v : p) {
            v = std::abs(rng.normal()) + 1e-3;
            norm += v * v;
        }
        const double radius = (1.0 + 0.3 * rng.uniform()) / std::sqrt(norm);
        for (std::size_t i = 0; i < m; ++i) {
            p[i] *= radius;
            s.f(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = p[i];
        }
        s.points.push_back(p);
    }
    return s;
}

}  // namespace

TEST_CASE("pareto hypervolume equals pagmo2's hv2d, hv3d and hvwfg on random sets") {
    for (const std::size_t m : {2u, 3u, 5u}) {
        for (const std::size_t n : {1u, 10u, 60u}) {
            for (std::uint64_t seed = 1; seed <= 5; ++seed) {
                const RandomSet s = random_set(m, n, 100 * m + seed);
                const pagmo::vector_double ref(m, 1.5);
                pagmo::hypervolume hv(s.points, true);
                double theirs = 0.0;
                if (m == 2) {
                    pagmo::hv2d algorithm;
                    theirs = hv.compute(ref, algorithm);
                } else if (m == 3) {
                    pagmo::hv3d algorithm;
                    theirs = hv.compute(ref, algorithm);
                } else {
                    pagmo::hvwfg algorithm;
                    theirs = hv.compute(ref, algorithm);
                }
                INFO("M = " << m << ", N = " << n << ", seed " << seed);
                CHECK(pride::pareto::hypervolume(s.f, ref) == Approx(theirs).epsilon(1e-12));
            }
        }
    }
}

TEST_CASE("pareto non-dominated sort and crowding equal pagmo2's on random sets") {
    for (const std::size_t m : {2u, 3u, 5u}) {
        for (std::uint64_t seed = 1; seed <= 5; ++seed) {
            // Coarse values (multiples of 0.1) give ties and duplicates as well.
            pride::Rng rng(seed);
            const std::size_t n = 80;
            std::vector<pagmo::vector_double> points(n, pagmo::vector_double(m));
            pride::Matrix f(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(n));
            for (std::size_t j = 0; j < n; ++j)
                for (std::size_t i = 0; i < m; ++i)
                    f(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = points[j][i] =
                        0.1 * static_cast<double>(rng.below(10));
            std::vector<std::size_t> rank(n);
            pride::pareto::SortScratch scratch;
            pride::pareto::nondominated_sort(f, rank, scratch);
            const auto theirs = std::get<3>(pagmo::fast_non_dominated_sorting(points));
            INFO("M = " << m << ", seed " << seed);
            for (std::size_t j = 0; j < n; ++j) CHECK(rank[j] == theirs[j]);
        }
        // Crowding on one random front without ties (both sum the objectives in order).
        const RandomSet s = random_set(m, 40, 7 * m);
        std::vector<std::size_t> rank(40), front;
        pride::pareto::SortScratch scratch;
        pride::pareto::nondominated_sort(s.f, rank, scratch);
        std::vector<pagmo::vector_double> points;
        for (std::size_t j = 0; j < 40; ++j)
            if (rank[j] == 0) {
                front.push_back(j);
                points.push_back(s.points[j]);
            }
        REQUIRE(front.size() >= 3);
        std::vector<double> ours(front.size());
        pride::pareto::crowding_distance(s.f, front, ours, scratch);
        const auto theirs = pagmo::crowding_distance(points);
        for (std::size_t k = 0; k < front.size(); ++k) {
            if (std::isinf(theirs[k]))
                CHECK(std::isinf(ours[k]));
            else
                CHECK(ours[k] == Approx(theirs[k]).epsilon(1e-12));
        }
    }
}
#endif

// Tests of WFG1-WFG9 (problems/multiobjective/wfg.hpp): pagmo2's values (tests/data/wfg/), the
// optimal points onto the fronts' shapes, the sampled fronts, the catalog's n -> (k, l), runs through
// the engine, and every error path.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstddef>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "engine/multiobjective.hpp"
#include "engine/run.hpp"
#include "framework/error.hpp"
#include "framework/pareto/dominance.hpp"
#include "framework/random.hpp"
#include "problems/multiobjective/catalog.hpp"
#include "problems/multiobjective/wfg.hpp"
#include "tests/cli_runner.hpp"
#include "tests/test_support.hpp"

using namespace pride::multiobjective;
using Catch::Matchers::Contains;
using pride::Matrix;
using pride::test::input_error_message;

namespace {

/// The values of `p` at z.
std::vector<double> eval(const Wfg& p, const std::vector<double>& z) {
    std::vector<double> f(p.objectives());
    p.evaluate(z, f);
    return f;
}

/// How far f is from WFG`problem`'s front (0 on it), by the shape's equation: WFG4-9 |sum (f_m / 2m)^2
/// - 1|; WFG3 |sum f_m / 2m - 1| and, for M >= 3, |h_1 - h_2| (the degenerate line has h_1 = h_2);
/// WFG1 and WFG2 at M = 2: x_1 from f_1 = 2 (1 - cos(x_1 pi / 2)), then |f_2 / 4 - h_2(x_1)|.
double shape_gap(int problem, const std::vector<double>& f) {
    const std::size_t m = f.size();
    double s = 0.0;
    if (problem >= 4) {
        for (std::size_t i = 0; i < m; ++i) s += std::pow(f[i] / (2.0 * static_cast<double>(i + 1)), 2.0);
        return std::abs(s - 1.0);
    }
    if (problem == 3) {
        for (std::size_t i = 0; i < m; ++i) s += f[i] / (2.0 * static_cast<double>(i + 1));
        return std::max(std::abs(s - 1.0), m >= 3 ? std::abs(f[0] / 2.0 - f[1] / 4.0) : 0.0);
    }
    REQUIRE(m == 2);
    const double x = std::acos(1.0 - f[0] / 2.0) * 2.0 / std::numbers::pi;
    const double h =
        problem == 1
            ? 1.0 - x - std::cos(10.0 * std::numbers::pi * x + std::numbers::pi / 2.0) / (10.0 * std::numbers::pi)
            : 1.0 - x * std::pow(std::cos(5.0 * x * std::numbers::pi), 2.0);
    return std::abs(f[1] / 4.0 - h);
}

pride::engine::Budget evaluations(std::int64_t n) {
    pride::engine::Budget b;
    b.evaluations = n;
    return b;
}

}  // namespace

TEST_CASE("wfg: pagmo2's values to the last bit", "[wfg]") {
    std::ifstream in(std::string(PRIDE_SOURCE_DIR) + "/tests/data/wfg/pagmo-2.18.txt");
    REQUIRE(in);
    std::string line;
    int points = 0, equal = 0, pagmo_nan = 0;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream ss(line);
        std::string name, kind;
        std::size_t m = 0, k = 0, l = 0;
        ss >> name >> m >> k >> l >> kind;
        INFO(line.substr(0, 40));
        const Wfg p(name[3] - '0', m, k, l);
        REQUIRE(p.name() == name);
        std::vector<double> z(k + l), expected(m);
        for (auto* v : {&z, &expected})
            for (double& value : *v) {
                std::string token;
                ss >> token;
                value = std::strtod(token.c_str(), nullptr);
            }
        REQUIRE(ss);
        const auto f = eval(p, z);
        ++points;
        if (std::isnan(expected[0])) {
            // pagmo2's NaN at WFG1's optimum (the data's README): pride's value is on the front.
            CHECK(name == "wfg1");
            CHECK(kind == "optimal");
            for (double v : f) CHECK(std::isfinite(v));
            if (m == 2) CHECK(shape_gap(1, f) < 1e-12);
            ++pagmo_nan;
            continue;
        }
        CHECK(f == expected);
        equal += f == expected ? 1 : 0;
    }
    CHECK(points == 9 * 3 * 20);
    CHECK(pagmo_nan == 12);  // WFG1's four optimal points at each M
    CHECK(equal == points - pagmo_nan);
}

TEST_CASE("wfg: optimal points evaluate onto the front's shape", "[wfg]") {
    pride::Rng rng(2006);
    for (int problem = 1; problem <= 9; ++problem)
        for (std::size_t m : {2u, 3u, 5u})
            for (std::size_t l : {2u, 20u}) {
                const Wfg p(problem, m, 2 * (m - 1), l);
                for (int rep = 0; rep < 20; ++rep) {
                    std::vector<double> position(p.k());
                    for (double& v : position) v = rng.uniform();
                    const auto z = p.optimal_solution(position);
                    for (std::size_t i = 0; i < z.size(); ++i) {
                        REQUIRE(z[i] >= p.lower()[i]);
                        REQUIRE(z[i] <= p.upper()[i]);
                    }
                    const auto f = eval(p, z);
                    INFO(p.name() << " M = " << m << " l = " << l);
                    if (problem > 2 || m == 2) CHECK(shape_gap(problem, f) < 1e-12);
                    // Off the optimum (one distance parameter moved), the point is off the front.
                    auto worse = z;
                    worse[p.k()] = 0.5 * (z[p.k()] + p.upper()[p.k()]);
                    if (problem > 2 || m == 2) CHECK(shape_gap(problem, eval(p, worse)) > 1e-6);
                }
            }
}

TEST_CASE("wfg: the sampled fronts lie on the shapes and are non-dominated", "[wfg]") {
    for (int problem = 1; problem <= 9; ++problem)
        for (std::size_t m : {2u, 3u, 5u}) {
            INFO("wfg" << problem << " M = " << m);
            const Matrix front = wfg_reference_front(problem, m, 1000);
            REQUIRE(front.rows() == static_cast<Eigen::Index>(m));
            CHECK(front.cols() <= 1000);
            CHECK(front.cols() >= (problem == 2 ? 100 : problem == 3 ? 1000 : 200));
            CHECK(pride::pareto::nondominated(front).size() == static_cast<std::size_t>(front.cols()));
            for (Eigen::Index j = 0; j < front.cols(); ++j) {
                const std::vector<double> f(front.col(j).data(), front.col(j).data() + m);
                for (std::size_t i = 0; i < m; ++i) CHECK(f[i] >= -1e-15);
                if (problem > 2 || m == 2) CHECK(shape_gap(problem, f) < 1e-12);
            }
        }
    // WFG1 and WFG2 (M = 2): the front runs from (0, 4) to (2, 0) (h_1 = 0 and h_2 = 1 at x_1 = 0).
    for (int problem : {1, 2}) {
        const Matrix front = wfg_reference_front(problem, 2, 100);
        CHECK(front.col(0).minCoeff() == 0.0);
        CHECK(front.row(1).maxCoeff() == 4.0);
        CHECK(front.row(0).maxCoeff() == Approx(2.0).margin(1e-12));
    }
}

TEST_CASE("wfg: WFG3's front is more than its degenerate line for M = 3", "[wfg]") {
    // t = (0.7, 1, 0.1): x = (0.7, 0.55, 0.1), f = 0.1 + (2 0.385, 4 0.315, 6 0.3) = (0.87, 1.36, 1.9).
    // A point (x_1, 2 x_1, 6 (1 - x_1)) of the line dominating it needs x_1 <= 0.68 and x_1 >= 0.6833.
    const Wfg p(3, 3, 2, 2);
    // y_3 = y_4 = 0.2975: s_linear gives 0.15 each, r_nonsep of the pair (0.15 + 0.15) / 3 = t_M.
    const auto f = eval(p, {1.4, 4.0, 6.0 * 0.2975, 8.0 * 0.2975});
    CHECK_THAT(f[0], Catch::Matchers::WithinAbs(0.87, 1e-12));
    CHECK_THAT(f[1], Catch::Matchers::WithinAbs(1.36, 1e-12));
    CHECK_THAT(f[2], Catch::Matchers::WithinAbs(1.9, 1e-12));
    const Matrix line = wfg_reference_front(3, 3, 100'000);
    int dominating = 0;
    for (Eigen::Index j = 0; j < line.cols(); ++j)
        dominating += pride::pareto::weakly_dominates(std::span<const double>(line.col(j).data(), 3), f) ? 1 : 0;
    CHECK(line.cols() == 100'000);
    CHECK(dominating == 0);
}

TEST_CASE("wfg: the catalog maps n to k = 2 (M - 1) and l = n - k", "[wfg]") {
    const Benchmark b("wfg4");
    CHECK(b.objectives() == 3);
    CHECK(b.dimension() == 24);  // k = 4, l = 20
    CHECK(b.upper()[23] == 48.0);
    const Benchmark c("wfg9", 10, 5);
    const Wfg direct(9, 5, 8, 2);
    CHECK(c.dimension() == 10);
    std::vector<double> z(10), f1(5), f2(5);
    for (std::size_t i = 0; i < z.size(); ++i) z[i] = 0.3 * c.upper()[i];
    c.evaluate(z, f1);
    direct.evaluate(z, f2);
    CHECK(f1 == f2);
    CHECK(c.reference_front(1000) == wfg_reference_front(9, 5, 1000));
    for (const char* name : {"wfg1", "wfg2", "wfg3", "wfg4", "wfg5", "wfg6", "wfg7", "wfg8", "wfg9"}) {
        CHECK(find_problem(name) != nullptr);
        CHECK(Benchmark(name).name() == name);
    }
}

TEST_CASE("wfg: the engine runs every multi-objective algorithm on them, with quality", "[wfg]") {
    using pride::engine::AlgorithmSpec;
    using pride::engine::ContinuousSpec;
    using pride::engine::Problem;
    using pride::engine::quality;
    using pride::engine::run;
    const Problem p(ContinuousSpec{"wfg4", 0, std::nullopt, 0});
    const auto q_front = quality(p, p.reference_front());
    CHECK(q_front.hypervolume_ratio == Approx(1.0).epsilon(1e-12));
    CHECK(q_front.igd_plus == 0.0);
    for (const char* name : {"nsga2", "nsga3", "moead", "smsemoa"}) {
        INFO(name);
        const auto r = run(AlgorithmSpec{name, {}}, p, evaluations(3000), 3);
        CHECK(r.evaluations == 3000);
        const auto q = quality(p, r.front->f);
        CHECK(q.hypervolume_ratio > 0.3);
        CHECK(q.hypervolume_ratio <= 1.0 + 1e-9);
    }
}

TEST_CASE("wfg: bad parameters are InputErrors naming what", "[wfg][errors]") {
    CHECK_THAT(input_error_message([] { (void)Wfg(0, 3); }), Contains("wfg: the problems are WFG1-WFG9, got 0"));
    CHECK_THAT(input_error_message([] { (void)Wfg(10, 3); }), Contains("got 10"));
    CHECK_THAT(input_error_message([] { (void)Wfg(4, 1); }), Contains("wfg4: needs 2 <= M <= 10000 objectives, got 1"));
    CHECK_THAT(input_error_message([] { (void)Wfg(4, 4, 4); }),
               Contains("wfg4: needs k (position parameters) a multiple of M - 1 = 3, got k = 4"));
    CHECK_THAT(input_error_message([] { (void)Wfg(2, 3, 4, 21); }),
               Contains("wfg2: needs an even l = n - k (distance parameters), got l = 21"));
    CHECK_THAT(input_error_message([] { (void)Wfg(3, 2, 2, 3); }), Contains("wfg3: needs an even l"));
    CHECK_THAT(input_error_message([] { (void)Wfg(5, 2, 2, kMaxVariables); }),
               Contains("wfg5: is built up to n = k + l = 1000000 variables"));
    CHECK_THAT(input_error_message([] { (void)Benchmark("wfg4", 4, 3); }),
               Contains("wfg4: needs n > k = 2 (M - 1) = 4 variables (l = n - k >= 1), got 4"));
    CHECK_THAT(input_error_message([] { (void)Benchmark("wfg2", 25, 3); }), Contains("wfg2: needs an even l"));
    CHECK_THAT(input_error_message([] { (void)Benchmark("wfg7", 0, 1); }), Contains("wfg7: needs 2 <= M"));
    CHECK_THAT(input_error_message([] { (void)wfg_reference_front(4, 3, 2); }),
               Contains("wfg4: a front of M = 3 objectives needs at least 3 points"));
    CHECK_THAT(input_error_message([] { (void)wfg_reference_front(1, 5, 10); }),
               Contains("wfg1: a front of M = 5 objectives needs at least 2^(M-1) points, got 10"));
    CHECK_THAT(input_error_message([] { (void)wfg_reference_front(3, 2, 1); }),
               Contains("wfg3: a front needs at least 2 points, got 1"));
    CHECK_THAT(input_error_message([] { (void)Wfg(8, 2).optimal_solution(std::vector<double>(3)); }),
               Contains("wfg8: optimal_solution needs k = 2 position values, got 3"));
    for (const auto& message :
         {input_error_message([] { (void)Benchmark("wfg2", 25, 3); }), input_error_message([] { (void)Wfg(4, 4, 4); })})
        CHECK(message.find('\n') == std::string::npos);
    // Through the program: one line, exit status 2.
    const auto r = pride::test::run_pride("front --algo nsga2 --problem wfg2 --dim 25 --evals 100");
    CHECK(r.status == 2);
    CHECK(r.err == "pride: wfg2: needs an even l = n - k (distance parameters), got l = 21\n");
    const auto ok = pride::test::run_pride("front --algo nsga2 --problem wfg2 --dim 24 --objectives 2 --evals 100");
    CHECK(ok.status == 0);
    CHECK(ok.out.find("wfg2 (n = 24, M = 2)") != std::string::npos);
}

#ifdef PRIDE_HAVE_PAGMO
#include <pagmo/problem.hpp>
#include <pagmo/problems/wfg.hpp>

TEST_CASE("wfg: pagmo2 in process, at more sizes, bit for bit where A is even", "[wfg][pagmo]") {
    pride::Rng rng(477);
    struct Size {
        std::size_t m, k, l;
    };
    // k / (M - 1) and l even (r_nonsep's A), l even for WFG2 and WFG3: where pride follows pagmo2.
    for (const Size s : {Size{2, 2, 2}, Size{2, 4, 8}, Size{3, 4, 6}, Size{4, 6, 10}, Size{6, 10, 4}})
        for (int problem = 1; problem <= 9; ++problem) {
            INFO("wfg" << problem << " M = " << s.m << " k = " << s.k << " l = " << s.l);
            const Wfg ours(problem, s.m, s.k, s.l);
            const pagmo::problem theirs{pagmo::wfg(static_cast<unsigned>(problem), s.k + s.l, s.m, s.k)};
            for (int rep = 0; rep < 50; ++rep) {
                std::vector<double> z(s.k + s.l);
                for (std::size_t i = 0; i < z.size(); ++i) z[i] = rng.uniform(0.0, ours.upper()[i]);
                CHECK(eval(ours, z) == theirs.fitness(z));
            }
        }
    // Odd A: pagmo2's r_nonsep normalisation puts WFG6 below its front (the header's note).
    const std::vector<double> z{2.0, 0.0, 6.0, 2.8, 3.5, 4.2};  // x = (1, 0, 1), distance optimal
    const auto f = pagmo::problem{pagmo::wfg(6, 6, 2, 3)}.fitness(z);
    CHECK(f[1] < 0.0);
    CHECK(shape_gap(6, eval(Wfg(6, 2, 3, 3), z)) < 1e-12);
}
#endif

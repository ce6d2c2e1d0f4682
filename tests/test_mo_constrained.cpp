// Constraints in the multi-objective algorithms: constrained domination's sort against its
// definition, the constrained test problems and their fronts, NSGA-II, NSGA-III, MOEA/D and
// SMS-EMOA reaching feasible fronts, every evaluation counted once, and the errors.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <numbers>
#include <span>
#include <vector>

#include "algorithms/moead.hpp"
#include "algorithms/nsga2.hpp"
#include "algorithms/nsga3.hpp"
#include "algorithms/smsemoa.hpp"
#include "engine/multiobjective.hpp"
#include "engine/run.hpp"
#include "framework/pareto/constrained_sorting.hpp"
#include "framework/pareto/reference_directions.hpp"
#include "problems/multiobjective/constrained.hpp"
#include "tests/mo_support.hpp"
#include "tests/test_support.hpp"

using namespace pride;
using Catch::Matchers::Contains;

namespace {

/// A constrained benchmark whose calls are counted (copies share the counter), and which can
/// hide its constraints (then it is a plain multi-objective problem: the same objectives).
struct CountedConstrained {
    multiobjective::ConstrainedBenchmark problem;
    std::shared_ptr<std::int64_t> calls = std::make_shared<std::int64_t>(0);
    std::size_t dimension() const { return problem.dimension(); }
    std::span<const double> lower() const { return problem.lower(); }
    std::span<const double> upper() const { return problem.upper(); }
    std::size_t objectives() const { return problem.objectives(); }
    ConstraintCounts constraint_counts() const { return problem.constraint_counts(); }
    double violation(std::span<const double> g) const { return problem.violation(g); }
    void evaluate(std::span<const double> x, std::span<double> f) {
        ++*calls;
        problem.evaluate(x, f);
    }
    void evaluate_constrained(std::span<const double> x, std::span<double> f, std::span<double> g) {
        ++*calls;
        problem.evaluate_constrained(x, f, g);
    }
};
static_assert(ConstrainedMultiObjectiveProblem<CountedConstrained>);

/// The same problem with its constraints hidden.
struct Unconstrained {
    multiobjective::ConstrainedBenchmark problem;
    std::size_t dimension() const { return problem.dimension(); }
    std::span<const double> lower() const { return problem.lower(); }
    std::span<const double> upper() const { return problem.upper(); }
    std::size_t objectives() const { return problem.objectives(); }
    void evaluate(std::span<const double> x, std::span<double> f) const { problem.evaluate(x, f); }
};
static_assert(!ConstrainedMultiObjectiveProblem<Unconstrained>);

/// Fronts by constrained domination peeled one by one, from the definition (O(N^3)).
std::vector<std::size_t> peeled_ranks(const Matrix& f, const std::vector<double>& v) {
    const auto n = static_cast<std::size_t>(f.cols());
    std::vector<std::size_t> rank(n, std::numeric_limits<std::size_t>::max());
    std::size_t assigned = 0;
    for (std::size_t front = 0; assigned < n; ++front) {
        std::vector<std::size_t> now;
        for (std::size_t i = 0; i < n; ++i) {
            if (rank[i] != std::numeric_limits<std::size_t>::max()) continue;
            bool dominated = false;
            for (std::size_t j = 0; j < n && !dominated; ++j)
                dominated = j != i && rank[j] == std::numeric_limits<std::size_t>::max() &&
                            pareto::constrained_dominates(pareto::point(f, static_cast<Eigen::Index>(j)), v[j],
                                                          pareto::point(f, static_cast<Eigen::Index>(i)), v[i]);
            if (!dominated) now.push_back(i);
        }
        for (const std::size_t i : now) rank[i] = front;
        assigned += now.size();
    }
    return rank;
}

/// The members of a result that are feasible.
std::size_t feasible_count(const MultiObjectiveResult& r) {
    std::size_t k = 0;
    for (const double v : r.violation) k += v == 0.0;
    return k;
}

/// The result's quality against the problem's front, through the engine.
engine::FrontQuality quality_of(const std::string& name, const MultiObjectiveResult& r) {
    const engine::Problem problem(engine::ContinuousSpec{name, 0, std::nullopt, 0});
    return engine::quality(problem, r.f, r.violation);
}

}  // namespace

TEST_CASE("constrained domination ranks feasible fronts first, then one front per violation") {
    // Columns: 0 and 1 feasible and mutually non-dominated; 2 feasible, dominated by 0; 3 and 4
    // infeasible with violation 0.5 (equal: one front) although 3 dominates every other point in
    // the objectives; 5 infeasible with violation 2.
    Matrix f(2, 6);
    f << 1, 2, 3, 0, 5, -1,  //
        2, 1, 3, 0, 5, -1;
    const std::vector<double> v{0, 0, 0, 0.5, 0.5, 2};
    std::vector<std::size_t> rank(6);
    pareto::ConstrainedSortScratch s;
    CHECK(pareto::constrained_sort(f, v, rank, s) == 4);
    CHECK(rank == std::vector<std::size_t>{0, 0, 1, 2, 2, 3});
    // No feasible point: the violations alone.
    const std::vector<double> all_infeasible{3, 1, 1, 2, 5, 4};
    CHECK(pareto::constrained_sort(f, all_infeasible, rank, s) == 5);
    CHECK(rank == std::vector<std::size_t>{2, 0, 0, 1, 4, 3});
    // No violations given: plain non-dominated sorting.
    std::vector<std::size_t> plain(6);
    pareto::SortScratch ps;
    pareto::nondominated_sort(f, std::span<std::size_t>(plain), ps);
    CHECK(pareto::constrained_sort(f, {}, rank, s) == 5);
    CHECK(rank == plain);
}

TEST_CASE("constrained sort equals fronts peeled by the definition on random sets") {
    Rng rng(7);
    pareto::ConstrainedSortScratch s;
    for (int trial = 0; trial < 300; ++trial) {
        const auto m = static_cast<Eigen::Index>(2 + trial % 3);
        const auto n = static_cast<std::size_t>(1 + rng.below(40));
        Matrix f(m, static_cast<Eigen::Index>(n));
        std::vector<double> v(n);
        for (std::size_t j = 0; j < n; ++j) {
            for (Eigen::Index i = 0; i < m; ++i) f(i, static_cast<Eigen::Index>(j)) = static_cast<double>(rng.below(5));
            // About half feasible; a few violations repeat, so that equal-violation fronts occur.
            v[j] = rng.uniform() < 0.5 ? 0.0 : static_cast<double>(1 + rng.below(4)) * 0.25;
        }
        std::vector<std::size_t> rank(n);
        pareto::constrained_sort(f, v, rank, s);
        INFO("trial " << trial);
        CHECK(rank == peeled_ranks(f, v));
    }
}

TEST_CASE("constrained sort refuses a NaN violation and a wrong count") {
    Matrix f(2, 2);
    f << 0, 1, 1, 0;
    std::vector<std::size_t> rank(2);
    pareto::ConstrainedSortScratch s;
    const std::vector<double> nan{0.0, std::nan("")};
    CHECK_THAT(test::input_error_message([&] { pareto::constrained_sort(f, nan, rank, s); }),
               Contains("point 1 has a NaN violation"));
    const std::vector<double> one{0.0};
    CHECK_THAT(test::input_error_message([&] { pareto::constrained_sort(f, one, rank, s); }),
               Contains("violation has 1 entries for 2 points"));
}

TEST_CASE("the constrained problems: their values by hand, their fronts feasible and not dominated") {
    using multiobjective::ConstrainedBenchmark;
    double f[3], g[2];
    SECTION("CONSTR at (0.5, 1): f = (0.5, 4), 6 - 1 - 4.5 = 0.5 violated, 1 + 1 - 4.5 = -2.5 met") {
        const ConstrainedBenchmark p("constr");
        const double x[] = {0.5, 1.0};
        p.evaluate_constrained(x, std::span<double>(f, 2), g);
        CHECK(f[0] == 0.5);
        CHECK(f[1] == 4.0);
        CHECK(g[0] == 0.5);
        CHECK(g[1] == -2.5);
        CHECK(p.violation(g) == 0.5);
    }
    SECTION("TNK at (1, 1): on the disc's border, outside the wavy circle") {
        const ConstrainedBenchmark p("tnk");
        const double x[] = {1.0, 1.0};
        p.evaluate_constrained(x, std::span<double>(f, 2), g);
        CHECK(g[0] == Approx(-1.0 + 0.1 * std::cos(16.0 * std::numbers::pi / 4.0)));
        CHECK(g[1] == 0.0);
        CHECK(p.violation(g) == 0.0);
    }
    SECTION("no feasible point of a dense grid dominates a point of the two-variable fronts") {
        for (const char* name : {"constr", "srn", "tnk"}) {
            const ConstrainedBenchmark p(name);
            const Matrix front = p.reference_front(400);
            REQUIRE(front.cols() > 50);
            const auto lo = p.lower(), hi = p.upper();
            std::size_t dominated = 0, feasible = 0;
            for (int a = 0; a <= 400; ++a)
                for (int b = 0; b <= 400; ++b) {
                    const double x[] = {lo[0] + (hi[0] - lo[0]) * a / 400.0, lo[1] + (hi[1] - lo[1]) * b / 400.0};
                    p.evaluate_constrained(x, std::span<double>(f, 2), g);
                    if (p.violation(g) != 0.0) continue;
                    ++feasible;
                    for (Eigen::Index j = 0; j < front.cols(); ++j) {
                        // A margin of 1e-9 relative: the front's own points are on the grid's
                        // boundary to rounding.
                        const double e0 = 1e-9 * (1.0 + std::abs(front(0, j)));
                        const double e1 = 1e-9 * (1.0 + std::abs(front(1, j)));
                        if (f[0] < front(0, j) - e0 && f[1] < front(1, j) - e1) ++dominated;
                    }
                }
            INFO(name);
            CHECK(feasible > 1000);
            CHECK(dominated == 0);
        }
    }
    SECTION("C1-DTLZ1's and C2-DTLZ2's fronts are feasible") {
        for (const char* name : {"c1-dtlz1", "c2-dtlz2"}) {
            const ConstrainedBenchmark p(name);
            const Matrix front = p.reference_front(2000);
            REQUIRE(front.cols() > 100);
            INFO(name);
            for (Eigen::Index j = 0; j < front.cols(); ++j) {
                const auto fj = front.col(j);
                if (p.name() == "c1-dtlz1") {
                    CHECK(fj(2) / 0.6 + (fj(0) + fj(1)) / 0.5 - 1.0 <= 1e-12);
                } else {
                    double s = 0.0;
                    for (int i = 0; i < 3; ++i) s += (fj(i) - 1.0 / std::sqrt(3.0)) * (fj(i) - 1.0 / std::sqrt(3.0));
                    bool cap = s <= 0.16;
                    for (int i = 0; i < 3; ++i) cap = cap || (fj.squaredNorm() - 2.0 * fj(i) + 1.0 <= 0.16);
                    CHECK(cap);
                }
            }
        }
    }
    SECTION("sizes and names are checked") {
        CHECK_THAT(test::input_error_message([] { (void)ConstrainedBenchmark("constr", 3); }),
                   Contains("has 2 variables, got 3"));
        CHECK_THAT(test::input_error_message([] { (void)ConstrainedBenchmark("srn", 0, 3); }),
                   Contains("has 2 objectives, got 3"));
        CHECK_THAT(test::input_error_message([] { (void)ConstrainedBenchmark("c1-dtlz1", 2, 3); }),
                   Contains("needs n >= M = 3"));
        CHECK_THAT(test::input_error_message([] { (void)ConstrainedBenchmark("nope"); }),
                   Contains("unknown constrained problem 'nope'"));
    }
}

TEST_CASE("nsga2 with constrained domination reaches CONSTR's front, feasible; without it, not") {
    CountedConstrained p{multiobjective::ConstrainedBenchmark("constr")};
    Nsga2<> a;
    const MultiObjectiveResult r = a.run(p, test::evaluations(10'000), 3);
    CHECK(*p.calls == 10'000);  // f and g from one call, counted once
    CHECK(r.evaluations == 10'000);
    REQUIRE(r.violation.size() == static_cast<std::size_t>(r.f.cols()));
    CHECK(feasible_count(r) == r.violation.size());
    REQUIRE(r.first_feasible);
    CHECK(*r.first_feasible >= 1);
    CHECK(*r.first_feasible <= 100);
    const auto q = quality_of("constr", r);
    CHECK(q.hypervolume_ratio > 0.98);
    CHECK(q.igd_plus < 0.01);
    // The same run blind to the constraints: points below the front, infeasible.
    const MultiObjectiveResult blind = a.run(Unconstrained{p.problem}, test::evaluations(10'000), 3);
    CHECK(blind.violation.empty());
    std::size_t infeasible = 0;
    double fs[2], g[2];
    for (Eigen::Index j = 0; j < blind.x.cols(); ++j) {
        p.problem.evaluate_constrained(pareto::point(blind.x, j), fs, g);
        infeasible += p.problem.violation(g) > 0.0;
    }
    CHECK(infeasible > static_cast<std::size_t>(blind.x.cols()) / 2);
}

TEST_CASE("nsga2's code tournament and every algorithm give one result per seed under constraints") {
    const multiobjective::ConstrainedBenchmark srn("srn");
    Nsga2<> a;
    a.tournament = nsga::Tournament::code;
    const auto r1 = a.run(srn, test::evaluations(3000), 11), r2 = a.run(srn, test::evaluations(3000), 11);
    CHECK(r1.f == r2.f);
    CHECK(r1.violation == r2.violation);
    CHECK(feasible_count(r1) == r1.violation.size());
    CHECK(quality_of("srn", r1).hypervolume_ratio > 0.95);
}

TEST_CASE("nsga3 with Jain and Deb's constrained selection reaches C1-DTLZ1's front") {
    CountedConstrained p{multiobjective::ConstrainedBenchmark("c1-dtlz1")};
    const auto a = make_nsga3(pareto::simplex_lattice(3, 12));
    const MultiObjectiveResult r = a.run(p, test::evaluations(92 * 400), 5);
    CHECK(*p.calls == 92 * 400);
    REQUIRE(!r.violation.empty());
    CHECK(feasible_count(r) == r.violation.size());
    const auto q = quality_of("c1-dtlz1", r);
    CHECK(q.igd_plus < 0.05);
    CHECK(q.hypervolume_ratio > 0.9);
}

TEST_CASE("moead replaces by violation first and reaches C2-DTLZ2's feasible caps") {
    CountedConstrained p{multiobjective::ConstrainedBenchmark("c2-dtlz2")};
    Moead<> a;
    const MultiObjectiveResult r = a.run(p, test::evaluations(30'000), 2);
    CHECK(*p.calls == 30'000);
    REQUIRE(!r.violation.empty());
    CHECK(feasible_count(r) == r.violation.size());
    CHECK(quality_of("c2-dtlz2", r).igd_plus < 0.05);
}

TEST_CASE("smsemoa with constrained domination reaches TNK's front") {
    CountedConstrained p{multiobjective::ConstrainedBenchmark("tnk")};
    SmsEmoa<> a;
    a.population = 40;
    const MultiObjectiveResult r = a.run(p, test::evaluations(8000), 4);
    CHECK(*p.calls == 8000);
    REQUIRE(!r.violation.empty());
    CHECK(feasible_count(r) == r.violation.size());
    CHECK(quality_of("tnk", r).hypervolume_ratio > 0.9);
}

TEST_CASE("nsga3's constrained tournament prefers the lesser violation") {
    // A tiny run whose only feasible region is small: the selection must find it. TNK from the
    // corner of its box: feasible points exist only near the wavy unit circle.
    const multiobjective::ConstrainedBenchmark tnk("tnk");
    const auto a = make_nsga3(pareto::simplex_lattice(2, 19));
    const auto r = a.run(tnk, test::evaluations(20 * 150), 8);
    CHECK(feasible_count(r) == r.violation.size());
}

TEST_CASE("the engine runs the constrained problems: violations in the front, quality over feasible points") {
    const engine::Problem problem(engine::ContinuousSpec{"constr", 0, std::nullopt, 0});
    engine::Budget b;
    b.evaluations = 4000;
    const auto r = engine::run(engine::AlgorithmSpec{"nsga2", {}}, problem, b, 1);
    REQUIRE(r.front);
    REQUIRE(r.front->violation.size() == static_cast<std::size_t>(r.front->f.cols()));
    REQUIRE(r.best_violation);
    CHECK(*r.best_violation == 0.0);
    CHECK(r.first_feasible);
    CHECK_THAT(engine::front_json(*r.front), Contains("\"violation\": 0"));
    // Quality counts feasible points only: the same set called infeasible has none.
    const std::vector<double> infeasible(static_cast<std::size_t>(r.front->f.cols()), 1.0);
    const auto q = engine::quality(problem, r.front->f, infeasible);
    CHECK(q.hypervolume == 0.0);
    CHECK(std::isinf(q.igd_plus));
    CHECK(engine::quality(problem, r.front->f, r.front->violation).hypervolume_ratio > 0.9);
    CHECK_THAT(test::input_error_message([&] { (void)engine::quality(problem, r.front->f, std::vector<double>{0.0}); }),
               Contains("1 violations for"));
    CHECK_THAT(engine::multiobjective_problem_names(), Contains("c2-dtlz2"));
}

TEST_CASE("the engine runs the RE and CRE problems: violations for CRE only, fronts from PRIDE_DATA") {
    engine::Budget b;
    b.evaluations = 2000;
    const engine::Problem cre(engine::ContinuousSpec{"cre21", 0, std::nullopt, 0});
    const auto rc = engine::run(engine::AlgorithmSpec{"nsga2", {}}, cre, b, 1);
    REQUIRE(rc.front);
    CHECK(rc.front->violation.size() == static_cast<std::size_t>(rc.front->f.cols()));
    CHECK_THAT(test::input_error_message([&] { (void)engine::quality(cre, rc.front->f, rc.front->violation); }),
               Contains("cre21 has no published reference front"));
    const engine::Problem re(engine::ContinuousSpec{"re21", 0, std::nullopt, 0});
    const auto rr = engine::run(engine::AlgorithmSpec{"nsga2", {}}, re, b, 1);
    REQUIRE(rr.front);
    CHECK(rr.front->violation.empty());  // no constraint declared: none reported
    CHECK(!rr.best_violation);
    CHECK_THAT(test::input_error_message([] {
                   (void)engine::Problem(engine::ContinuousSpec{"re21", 5, std::nullopt, 0});
               }),
               Contains("re21 has 4 variables, got 5"));
    const char* data = std::getenv("PRIDE_DATA");
    if (data == nullptr || *data == 0) {
        WARN("PRIDE_DATA is not set: the RE front's quality is skipped");
        CHECK_THAT(test::input_error_message([&] { (void)engine::quality(re, rr.front->f); }),
                   Contains("which pride does not ship: set PRIDE_DATA"));
        return;
    }
    CHECK(engine::quality(re, rr.front->f).hypervolume_ratio > 0.9);
}

// WOA, harmony search and HS-WOA on boxes (Cai and Du (2021)): each equation on hand-computed
// values with fixed draws, one sweep replayed draw by draw, the schedules' end points, the balance
// switch and the reconstruction, reproducibility, exact budgets, bounds, and WOA on the sphere.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "algorithms/hs.hpp"
#include "algorithms/parts/whale/moves.hpp"
#include "algorithms/woa.hpp"
#include "framework/error.hpp"
#include "framework/termination.hpp"
#include "problems/continuous/functions.hpp"
#include "problems/continuous/yao.hpp"
#include "tests/scripted_draws.hpp"

namespace {

using Vec = std::vector<double>;
namespace whale = pride::whale;

using Script = pride::test::ScriptedDraws;

struct Log {
    std::int64_t calls = 0, outside = 0;
};

/// Counts evaluations and points outside the box, independently of the run's guard.
template <class P>
struct Probe {
    P inner;
    std::shared_ptr<Log> log = std::make_shared<Log>();
    std::size_t dimension() const { return inner.dimension(); }
    std::span<const double> lower() const { return inner.lower(); }
    std::span<const double> upper() const { return inner.upper(); }
    double evaluate(std::span<const double> x) {
        ++log->calls;
        for (std::size_t i = 0; i < x.size(); ++i)
            if (!(x[i] >= lower()[i] && x[i] <= upper()[i])) {
                ++log->outside;
                break;
            }
        return inner.evaluate(x);
    }
};
template <class P>
struct BatchProbe : Probe<P> {
    void evaluate_batch(pride::MatrixView points, std::span<double> values) {
        for (Eigen::Index j = 0; j < points.cols(); ++j)
            values[static_cast<std::size_t>(j)] =
                this->evaluate(std::span<const double>(points.col(j).data(), static_cast<std::size_t>(points.rows())));
    }
};

using Family = pride::Woa<pride::SelectableWhaleDraws, pride::SelectableWhaleMode, pride::SelectableSecondStep>;

Family configuration(const std::string& name, std::int64_t pop = 30) {
    Family a;
    a.id = name;
    a.population = pop;
    if (name == "hswoa" || name == "woa-hs") a.second_step = pride::HarmonySecondStep{};
    if (name == "hswoa" || name == "woa-balance") a.mode = pride::BalanceMode{};
    if (name == "woa-coord") a.draws = pride::PerCoordinateDraws{};
    return a;
}

const char* const kConfigurations[] = {"woa", "woa-coord", "woa-hs", "woa-balance", "hswoa"};

}  // namespace

TEST_CASE("WOA: a falls from 2 to 0 and a2 from -1 to -2, l lies in [a2, 1]", "[woa][equations]") {
    CHECK(whale::a(0, 500) == 2.0);
    CHECK(whale::a(250, 500) == 1.0);
    CHECK(whale::a(500, 500) == 0.0);
    CHECK(whale::a(499, 500) == Approx(2.0 / 500.0).epsilon(1e-12));  // the last iteration that moves
    CHECK(whale::a2(0, 500) == -1.0);
    CHECK(whale::a2(500, 500) == -2.0);
    CHECK(whale::l(-1.0, 0.0) == 1.0);   // r = 0: l = 1
    CHECK(whale::l(-1.0, 1.0) == -1.0);  // r = 1: l = a2
    CHECK(whale::l(-2.0, 1.0) == -2.0);
    CHECK(whale::l(-1.5, 0.5) == -0.25);  // (a2 - 1) r + 1
}

TEST_CASE("WOA eqs. 3-4: A = 2 a r1 - a, C = 2 r2", "[woa][equations]") {
    CHECK(whale::coefficient_a(2.0, 0.0) == -2.0);
    CHECK(whale::coefficient_a(2.0, 1.0) == 2.0);
    CHECK(whale::coefficient_a(1.5, 0.9) == Approx(1.2).epsilon(1e-15));
    CHECK(whale::coefficient_c(0.25) == 0.5);
}

TEST_CASE("WOA eqs. 1-2: encircling the best", "[woa][equations]") {
    // D = |1.5 * 2 - 1| = 2; X = 2 - 0.5 * 2 = 1.
    CHECK(whale::encircle(1.0, 2.0, 0.5, 1.5) == 1.0);
    // A = 0: onto the best.
    CHECK(whale::encircle(7.0, -3.0, 0.0, 1.0) == -3.0);
}

TEST_CASE("WOA eqs. 6-7: search relative to a random whale", "[woa][equations]") {
    // D = |0.5 * (-1) - 3| = 3.5; X = -1 - 1.5 * 3.5 = -6.25.
    CHECK(whale::search(3.0, -1.0, 1.5, 0.5) == -6.25);
    CHECK(whale::search(3.0, 4.0, -1.0, 1.0) == 5.0);  // D = 1; X = 4 + 1
}

TEST_CASE("WOA eq. 5: the spiral", "[woa][equations]") {
    // D' = |3 - 1| = 2.
    CHECK(whale::spiral(1.0, 3.0, whale::spiral_factor(0.0, 1.0)) == 5.0);  // l = 0: D' + X*
    CHECK(whale::spiral(1.0, 3.0, whale::spiral_factor(1.0, 1.0)) ==
          Approx(2.0 * std::exp(1.0) + 3.0));  // cos 2 pi = 1
    CHECK(whale::spiral(1.0, 3.0, whale::spiral_factor(0.5, 1.0)) == Approx(3.0 - 2.0 * std::exp(0.5)));  // cos pi = -1
    CHECK(whale::spiral(1.0, 3.0, whale::spiral_factor(-1.0, 2.0)) == Approx(2.0 * std::exp(-2.0) + 3.0));  // b = 2
    CHECK(whale::spiral(3.0, 3.0, whale::spiral_factor(0.3, 1.0)) == 3.0);  // on the best
}

TEST_CASE("WOA: one sweep replayed draw by draw (search per coordinate, encircling, spiral)", "[woa][equations]") {
    pride::Woa<> woa;
    pride::Matrix x(2, 3);
    x << 1.0, 3.0, -1.0,  //
        2.0, 4.0, 1.0;
    const Vec leader{0.5, 0.5};
    const double a = 1.5, a2 = -1.5;
    Script s;
    // Whale 0: A = 1.2, C = 0.5, l = -0.25, p = 0.3: |A| >= 1, search; the random whale drawn per
    // coordinate: whale 1 for d = 0, whale 0 itself (already moved in place) for d = 1.
    // Whale 1: A = 0.75, C = 1, l = 1, p = 0.2: encircle. Whale 2: A = -1.5, C = 0, l = -0.25, p = 0.5: spiral.
    s.u = {0.9, 0.25, 0.5, 0.3, 0.75, 0.5, 0.0, 0.2, 0.0, 0.0, 0.5, 0.5};
    s.k = {1, 0};
    woa.sweep(pride::PerWhaleDraws{}, pride::ConvergenceMode{}, x, leader, a, a2, 0.0, s);
    CHECK(s.spent());
    CHECK(x(0, 0) == Approx(2.4));                                         // D = |0.5 * 3 - 1| = 0.5; 3 - 1.2 * 0.5
    CHECK(x(1, 0) == Approx(0.8));                                         // D = |0.5 * 2 - 2| = 1; 2 - 1.2 * 1
    CHECK(x(0, 1) == -1.375);                                              // D = |0.5 - 3| = 2.5; 0.5 - 0.75 * 2.5
    CHECK(x(1, 1) == -2.125);                                              // D = 3.5; 0.5 - 0.75 * 3.5
    const double k = std::exp(-0.25) * std::cos(-0.5 * std::numbers::pi);  // ~ 0: cos(-pi/2)
    CHECK(x(0, 2) == Approx(1.5 * k + 0.5));
    CHECK(x(1, 2) == Approx(0.5 * k + 0.5));
}

TEST_CASE("WOA: per-coordinate draws test |A| and p coordinate by coordinate", "[woa][equations]") {
    pride::Woa<pride::PerCoordinateDraws> woa;
    pride::Matrix x(2, 2);
    x << 1.0, 3.0,  //
        2.0, 4.0;
    const Vec leader{0.0, 0.0};
    Script s;
    // Whale 0: r (l = 1); d = 0: A = 2, C = 1, p = 0.1: search, whale 1; d = 1: A = 0, C = 1, p = 0.1: encircle.
    // Whale 1: r = 0.5 (l = -0.5); d = 0: p = 0.9: spiral; d = 1: p = 0.9: spiral.
    s.u = {0.0, 1.0, 0.5, 0.1, 0.5, 0.5, 0.1, 0.5, 0.5, 0.5, 0.9, 0.5, 0.5, 0.9};
    s.k = {1};
    woa.sweep(pride::PerCoordinateDraws{}, pride::ConvergenceMode{}, x, leader, 2.0, -2.0, 0.0, s);
    CHECK(s.spent());
    CHECK(x(0, 0) == 3.0 - 2.0 * std::abs(3.0 - 1.0));  // -1
    CHECK(x(1, 0) == 0.0);                              // A = 0: onto the leader
    CHECK(x(0, 1) == Approx(-3.0 * std::exp(-0.5)));    // D' = 3, cos(-pi) = -1
    CHECK(x(1, 1) == Approx(-4.0 * std::exp(-0.5)));
}

TEST_CASE("HS-WOA: the balance mode explores with probability balance, whatever |A|", "[woa][equations]") {
    pride::Woa<pride::PerWhaleDraws, pride::BalanceMode> woa;
    pride::Matrix x(1, 2);
    x << 1.0, 3.0;
    const Vec leader{0.0};
    Script s;
    // Whale 0: A = 0 (|A| < 1), p = 0.2, q = 0.1 < 0.8: explore anyway (search relative to whale 1).
    // Whale 1: A = 0, p = 0.2, q = 0.9: exploit, p < 0.5: encircle.
    s.u = {0.5, 0.5, 0.0, 0.2, 0.1, 0.5, 0.5, 0.0, 0.2, 0.9};
    s.k = {1};
    woa.sweep(pride::PerWhaleDraws{}, pride::BalanceMode{}, x, leader, 1.0, -1.0, 0.8, s);
    CHECK(s.spent());
    CHECK(x(0, 0) == 3.0);  // 3 - 0 * D
    CHECK(x(0, 1) == 0.0);  // 0 - 0 * D
}

TEST_CASE("HS-WOA eq. 8: towards the best or a random whale by a U(0,1) fraction", "[woa][equations]") {
    CHECK(whale::toward(1.0, 5.0, 0.25) == 2.0);
    CHECK(whale::toward(1.0, 5.0, 0.0) == 1.0);
    CHECK(whale::toward(-2.0, 2.0, 0.5) == 0.0);
}

TEST_CASE("harmony search: one improvisation with fixed draws", "[woa][hs][equations]") {
    pride::Matrix memory(2, 3);
    memory << 1.0, 2.0, 3.0,  //
        4.0, 5.0, 6.0;
    const Vec lo{0.0, 0.0}, hi{10.0, 20.0};
    const whale::HarmonyRates rates{0.8, 0.3, 0.01};
    Vec out(2);
    Script s;
    // d = 0: 0.5 < HMCR: member 2 (3.0); 0.1 < PAR: + (2 * 0.75 - 1) * 0.01 * 10 = +0.05.
    // d = 1: 0.9 >= HMCR: uniform, 0.25 of [0, 20] = 5.
    s.u = {0.5, 0.1, 0.75, 0.9, 0.25};
    s.k = {2};
    whale::improvise(memory, lo, hi, rates, s, std::span<double>(out));
    CHECK(s.spent());
    CHECK(out[0] == Approx(3.05).epsilon(1e-15));
    CHECK(out[1] == 5.0);
    // Considered without pitch adjustment: the member's value exactly.
    s.u = {0.0, 0.3, 0.79, 0.99};
    s.k = {0, 1};
    whale::improvise(memory, lo, hi, rates, s, std::span<double>(out));
    CHECK(s.spent());
    CHECK(out == Vec{1.0, 5.0});
}

TEST_CASE("HS-WOA eq. 9: the balance switch and the stagnation it signals", "[woa][equations]") {
    whale::BalanceState b{0.8, 0, false};
    CHECK_FALSE(whale::balance_step(b, false, 0.8, 2));  // count 1
    CHECK_FALSE(whale::balance_step(b, false, 0.8, 2));  // count 2 = thr: no switch
    CHECK(b.balance == 0.8);
    CHECK_FALSE(whale::balance_step(b, true, 0.8, 2));  // an improvement resets count
    CHECK(b.count == 0);
    for (int i = 0; i < 2; ++i) CHECK_FALSE(whale::balance_step(b, false, 0.8, 2));
    CHECK_FALSE(whale::balance_step(b, false, 0.8, 2));  // count 3 > thr: switch to exploiting
    CHECK(b.balance == Approx(0.2).epsilon(1e-15));
    CHECK(b.exploiting);
    CHECK(b.count == 0);
    for (int i = 0; i < 2; ++i) CHECK_FALSE(whale::balance_step(b, false, 0.8, 2));
    CHECK(whale::balance_step(b, false, 0.8, 2));  // a switch while exploiting: reconstruct
    CHECK(b.balance == 0.8);
    CHECK_FALSE(b.exploiting);
    CHECK(b.count == 0);
}

TEST_CASE("HS-WOA: the reconstruction keeps the best, then tournament winners", "[woa][equations]") {
    const Vec f{5.0, 1.0, 4.0, 3.0, 2.0};
    std::vector<std::size_t> order(5);
    Script s;
    // After the best (1): candidates {0, 2, 3, 4}: 0 (f 5) against 4 (f 2): 4; then {2, 3, 0}: 2 (f 4)
    // against 3 (f 3): 3.
    s.k = {0, 2, 0, 0};
    whale::tournament_keep(std::span<const double>(f), 3, s, std::span<std::size_t>(order));
    CHECK(s.spent());
    CHECK(order[0] == 1);
    CHECK(order[1] == 4);
    CHECK(order[2] == 3);
    // Keeping one: the best alone, no draw.
    whale::tournament_keep(std::span<const double>(f), 1, s, std::span<std::size_t>(order));
    CHECK(order[0] == 1);
    CHECK(s.spent());
}

TEST_CASE("HS-WOA: on a plateau the pod is rebuilt, renewing 80 % of it", "[woa]") {
    // A plateau never improves: every thr + 1 iterations a switch, every second one rebuilds.
    struct Plateau {
        std::vector<double> lo = std::vector<double>(3, -1.0), hi = std::vector<double>(3, 1.0);
        std::size_t dimension() const { return 3; }
        std::span<const double> lower() const { return lo; }
        std::span<const double> upper() const { return hi; }
        double evaluate(std::span<const double>) const { return 1.0; }
    };
    auto a = configuration("woa-balance", 10);
    const auto r = a.run(Plateau{}, pride::max_iterations(30), 3);
    CHECK(r.iterations == 30);
    // 10 initial + 30 sweeps of 10 + 8 per reconstruction, one every 6 iterations: 5 of them.
    CHECK(r.evaluations == 10 + 30 * 10 + 5 * 8);
}

TEST_CASE("WOA family and HS: equal seeds give bit-identical runs, different seeds differ", "[woa][reproducible]") {
    const pride::continuous::Rastrigin f(5);
    for (const char* name : kConfigurations) {
        INFO(name);
        const auto a = configuration(name, 12);
        const auto r1 = a.run(f, pride::max_evaluations(2000), 42);
        const auto r2 = a.run(f, pride::max_evaluations(2000), 42);
        const auto r3 = a.run(f, pride::max_evaluations(2000), 43);
        CHECK(r1.best_f == r2.best_f);
        CHECK(r1.best_x == r2.best_x);
        CHECK(r1.history == r2.history);
        CHECK(r1.best_x != r3.best_x);
    }
    pride::HarmonySearch<> hs;
    const auto h1 = hs.run(f, pride::max_evaluations(2000), 42);
    const auto h2 = hs.run(f, pride::max_evaluations(2000), 42);
    CHECK(h1.history == h2.history);
    CHECK(h1.best_x == h2.best_x);
    CHECK(h1.best_x != hs.run(f, pride::max_evaluations(2000), 43).best_x);
}

TEST_CASE("WOA family and HS spend exactly the evaluation budget and keep points in the box", "[woa][budget]") {
    for (const std::int64_t n : {1, 7, 11, 12, 13, 23, 24, 25, 36, 37, 1001}) {
        for (const char* name : kConfigurations) {
            INFO(name << " budget " << n);
            auto p = Probe<pride::continuous::Rastrigin>{pride::continuous::Rastrigin(4)};
            const auto r = configuration(name, 12).run(p, pride::max_evaluations(n), 9);
            CHECK(r.evaluations == n);
            CHECK(p.log->calls == n);
            CHECK(p.log->outside == 0);
            auto q = BatchProbe<pride::continuous::Sphere>{{pride::continuous::Sphere(3)}};
            const auto rq = configuration(name, 12).run(q, pride::max_evaluations(n), 9);
            CHECK(rq.evaluations == n);
            CHECK(q.log->calls == n);
            CHECK(q.log->outside == 0);
        }
        INFO("hs budget " << n);
        auto p = Probe<pride::continuous::Rastrigin>{pride::continuous::Rastrigin(4)};
        const auto r = pride::HarmonySearch<>{}.run(p, pride::max_evaluations(n), 9);
        CHECK(r.evaluations == n);
        CHECK(p.log->calls == n);
        CHECK(p.log->outside == 0);
    }
}

TEST_CASE("WOA: an iteration limit gives T iterations of N evaluations (HS-WOA: 3N without rebuilds)",
          "[woa][budget]") {
    const pride::continuous::Sphere f(4);
    const auto r = configuration("woa", 10).run(f, pride::max_iterations(7), 1);
    CHECK(r.iterations == 7);
    CHECK(r.evaluations == 10 + 7 * 10);
    const auto h = configuration("woa-hs", 10).run(f, pride::max_iterations(7), 1);
    CHECK(h.evaluations == 10 + 7 * 30);
}

TEST_CASE("WOA reaches 1e-20 on the 30-D sphere (yao-f1) within 15000 evaluations", "[woa][convergence]") {
    const pride::continuous::Sphere f(30, pride::continuous::yao_f1_info);
    for (const std::uint64_t seed : {1u, 2u, 3u, 4u, 5u}) {
        const auto r = configuration("woa", 30).run(f, pride::max_evaluations(15000), seed);
        INFO("seed " << seed << " best " << r.best_f);
        CHECK(r.evaluations == 15000);
        CHECK(r.best_f < 1e-20);
    }
}

TEST_CASE("WOA family and HS: invalid parameters are refused", "[woa][params]") {
    auto a = configuration("hswoa");
    a.population = 1;
    CHECK_THROWS_AS(a.run(pride::continuous::Sphere(2), pride::max_evaluations(10), 1), pride::InputError);
    auto b = configuration("hswoa");
    pride::BalanceMode m;
    m.start = 1.5;
    b.mode = m;
    CHECK_THROWS_AS(b.run(pride::continuous::Sphere(2), pride::max_evaluations(10), 1), pride::InputError);
    // A schedule needs a horizon.
    CHECK_THROWS_AS(configuration("woa").run(pride::continuous::Sphere(2), pride::target_value(1e-3), 1),
                    pride::InputError);
    pride::HarmonySearch<> hs;
    hs.rates.hmcr = 2.0;
    CHECK_THROWS_AS(hs.run(pride::continuous::Sphere(2), pride::max_evaluations(10), 1), pride::InputError);
}

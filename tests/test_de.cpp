// Differential evolution: de, jde, jade, shade, lshade, jso. Each strategy's mutant
// and the crossover on scripted draws, the repair, the memory updates (weighted Lehmer and
// arithmetic means, the terminal value, jSO's halving) and jSO's schedules on hand-computed
// numbers, the archive's rules, L-SHADE's and jSO's populations shrinking from N_init to N_min as
// the LPSR formula says, exact budgets counted on the problem's side, reproducibility, ask and
// tell batches, every validation error, and optimisation sanity with wide margins.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <deque>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "algorithms/de.hpp"
#include "engine/ask_tell.hpp"
#include "engine/registry.hpp"
#include "engine/run.hpp"
#include "framework/error.hpp"
#include "tests/cli_runner.hpp"
#include "tests/scripted_draws.hpp"
#include "tests/test_support.hpp"

namespace {

namespace de = pride::de;
using Catch::Matchers::Contains;
using pride::test::input_error_message;
using Vec = std::vector<double>;

using Script = pride::test::ScriptedDraws;

const char* const kEntries[] = {"de", "jde", "jade", "shade", "lshade", "jso"};

/// A box [-5, 5]^dim whose sphere counts its calls outside the run (copies share the counter).
struct Counted {
    std::shared_ptr<std::int64_t> calls;
    pride::engine::Problem problem;
};

Counted counted_sphere(std::size_t dim) {
    auto calls = std::make_shared<std::int64_t>(0);
    pride::engine::CallbackSpec cb;
    cb.name = "counted-sphere";
    cb.lower.assign(dim, -5.0);
    cb.upper.assign(dim, 5.0);
    cb.scalar = [calls](std::span<const double> x) {
        ++*calls;
        double s = 0.0;
        for (const double v : x) s += v * v;
        return s;
    };
    return {calls, pride::engine::Problem(cb)};
}

pride::engine::Budget evals(std::int64_t n) {
    pride::engine::Budget b;
    b.evaluations = n;
    return b;
}

pride::engine::RunResult run(const std::string& algo, const std::string& problem, std::int64_t dim, std::int64_t n,
                             std::uint64_t seed, const std::vector<std::string>& params = {}) {
    pride::engine::AlgorithmSpec a{algo, {}};
    for (const auto& p : params) a.params.set_from_string(p);
    return pride::engine::run(a, pride::engine::Problem(pride::engine::ContinuousSpec{problem, dim}), evals(n), seed);
}

/// Six points in the plane, one per column, and an order (best first) given by hand.
struct Plane {
    pride::Matrix x{2, 6};
    std::vector<std::size_t> order{4, 1, 0, 2, 3, 5};
    Plane() {
        x << 0.0, 1.0, 3.0, -1.0, 2.0, 4.0,  //
            0.0, 2.0, 5.0, 4.0, -2.0, 1.0;
    }
    de::Generation generation(const pride::Matrix* archive = nullptr, std::size_t archived = 0,
                              de::Spent spent = {}) const {
        return {x, order, archive, archived, spent};
    }
};

template <class Strategy>
Vec mutant_of(const Strategy& s, const de::Generation& g, std::size_t i, Script& draws, double f = 0.5,
              double fw = 0.5) {
    const de::Donors d = s.pick(g, i, draws);
    Vec v(2);
    s.mutant(g, i, d, f, fw, v);
    return v;
}

}  // namespace

TEST_CASE("DE (M1) rand/1: v = x_r1 + F (x_r2 - x_r3), donors drawn by rejection", "[de][equations]") {
    const Plane p;
    Script s;
    s.k = {0, 1, 1, 2, 0, 3};  // r1: 0 is the target, then 1; r2: 1 is r1, then 2; r3: 0, then 3
    const Vec v = mutant_of(de::RandOne{}, p.generation(), 0, s);
    CHECK(s.spent());
    CHECK(v == Vec{1.0 + 0.5 * (3.0 + 1.0), 2.0 + 0.5 * (5.0 - 4.0)});  // (3, 2.5)
}

TEST_CASE("DE (M2) best/1: v = x_best + F (x_r1 - x_r2), the best may be the target", "[de][equations]") {
    const Plane p;
    Script s;
    s.k = {4, 2, 3};  // the target is the best (4): r1 = 2 after 4 is refused, r2 = 3
    const Vec v = mutant_of(de::BestOne{}, p.generation(), 4, s);
    CHECK(s.spent());
    CHECK(v == Vec{4.0, -1.5});  // (2 + 0.5 * 4, -2 + 0.5 * 1)
}

TEST_CASE("DE (M3) current-to-best/1: v = x_i + F (x_best - x_i) + F (x_r1 - x_r2)", "[de][equations]") {
    const Plane p;
    Script s;
    s.k = {5, 1};
    const Vec v = mutant_of(de::CurrentToBestOne{}, p.generation(), 0, s);
    CHECK(s.spent());
    CHECK(v == Vec{0.5 * 2.0 + 0.5 * 3.0, 0.5 * -2.0 + 0.5 * -1.0});  // (2.5, -1.5)
}

TEST_CASE("DE (M4) rand/2: v = x_r1 + F ((x_r2 - x_r3) + (x_r4 - x_r5))", "[de][equations]") {
    const Plane p;
    Script s;
    s.k = {0, 2, 3, 1, 4, 5};  // r1 = 0, r2 = 2, r3 = 3; r4: 1 is the target (refused), then 4; r5 = 5
    const Vec v = mutant_of(de::RandTwo{}, p.generation(), 1, s);
    CHECK(s.spent());
    // r = (0, 2, 3, 4, 5): x0 + 0.5 ((x2 - x3) + (x4 - x5)) = (0.5 (4 - 2), 0.5 (1 - 3))
    CHECK(v == Vec{1.0, -1.0});
}

TEST_CASE("DE (M5) current-to-pbest/1: x_pbest among the best max(2, round(p N)), x~_r2 from P u A",
          "[de][equations]") {
    const Plane p;
    pride::Matrix archive(2, 2);
    archive << 10.0, -10.0,  //
        10.0, 6.0;
    de::CurrentToPBest<de::FixedRate> s;
    s.rate.p = 0.3;  // round(1.8) = 2: x_pbest is x4 or x1
    Script d;
    // x_pbest = order[1] = x1; r1: 0 is the target, then 3; r2 in P u A (8 members): 3 is r1,
    // then 7 = the archive's second member.
    d.k = {1, 0, 3, 3, 7};
    const Vec v = mutant_of(s, p.generation(&archive, 2), 0, d, 0.5, 0.25);
    CHECK(d.spent());
    CHECK(v == Vec{0.25 * 1.0 + 0.5 * (-1.0 + 10.0), 0.25 * 2.0 + 0.5 * (4.0 - 6.0)});  // (4.75, -0.5)
    CHECK(de::pbest_count(0.05, 100) == 5);
    CHECK(de::pbest_count(0.11, 4) == 2);  // round(0.44) = 0: at least 2
    CHECK(de::pbest_count(0.11, 180) == 20);
    CHECK(de::pbest_count(1.0, 6) == 6);
}

TEST_CASE("DE: jSO's x_pbest is drawn again while it is the target, in the first half of the budget",
          "[de][equations][jso]") {
    const Plane p;
    de::CurrentToPBest<de::LinearRate> s;
    s.pbest_not_target_before = 0.5;
    Script d;
    // At 10 % of the budget p = 0.25 - 0.125 * 0.1: round(1.425) = 1, so 2. x_pbest = order[0] = 4 = the target
    // (refused), then order[1] = 1; r1 = 0; r2 = 2.
    d.k = {0, 1, 0, 2};
    CHECK(s.pick(p.generation(nullptr, 0, {10, 100}), 4, d).best == 1);
    CHECK(d.spent());
    d.k = {0, 0, 2};  // at 60 %: the target may be x_pbest
    CHECK(s.pick(p.generation(nullptr, 0, {60, 100}), 4, d).best == 4);
    CHECK(d.spent());
}

TEST_CASE("DE: p's rules (JADE fixed, SHADE's U[2/N, p_max], jSO's 0.25 -> 0.125)", "[de][equations]") {
    Script d;
    CHECK(de::FixedRate{0.05}(100, {}, d) == 0.05);
    d.u = {0.0, 0.5};
    CHECK(de::UniformRate{0.2}(100, {}, d) == 0.02);                         // p_min = 2/N
    CHECK(de::UniformRate{0.2}(100, {}, d) == Approx(0.11).epsilon(1e-15));  // halfway to p_max
    const de::LinearRate jso;
    CHECK(jso(100, {0, 1000}, d) == 0.25);
    CHECK(jso(100, {500, 1000}, d) == 0.1875);
    CHECK(jso(100, {1000, 1000}, d) == 0.125);
    CHECK(d.spent());
}

TEST_CASE("DE (C) binomial crossover: U(0,1) < CR or j = j_rand takes the mutant", "[de][equations]") {
    const Vec x{1.0, 2.0, 3.0}, v{10.0, 20.0, 30.0};
    Vec out(3);
    Script s;
    s.k = {1};
    s.u = {0.7, 0.9, 0.2};
    de::binomial_crossover(x, v, 0.5, s, out);
    CHECK(out == Vec{1.0, 20.0, 30.0});  // 0.7 >= CR: x; j_rand; 0.2 < CR
    s.k = {2};
    s.u = {0.0, 0.0, 0.0};
    de::binomial_crossover(x, v, 0.0, s, out);  // CR = 0: only j_rand
    CHECK(out == Vec{1.0, 2.0, 30.0});
    s.k = {0};
    s.u = {0.999, 0.999, 0.999};
    de::binomial_crossover(x, v, 1.0, s, out);  // CR = 1: every coordinate
    CHECK(out == v);
    CHECK(s.spent());
}

TEST_CASE("DE (R) bound handling: halfway between the target and the bound crossed (JADE), or clamped",
          "[de][equations]") {
    const Vec lo{-1.0, -1.0, -1.0, -1.0}, hi{1.0, 1.0, 1.0, 1.0}, target{0.5, 0.5, -0.5, 0.5};
    Vec u{3.0, -2.0, 0.25, std::nan("")};
    de::MidpointRepair{}(u, target, lo, hi);
    CHECK(u == Vec{0.75, -0.25, 0.25, -0.25});  // NaN goes the lower way
    Vec w{3.0, -2.0, 0.25, 1.0};
    de::ClampRepair{}(w, target, lo, hi);
    CHECK(w == Vec{1.0, -1.0, 0.25, 1.0});
}

TEST_CASE("DE: the weighted Lehmer and arithmetic means on hand-computed numbers", "[de][memory]") {
    // S_F = {0.5, 1}, S_CR = {0.2, 0.6}, gains {1, 3}: w = {1/4, 3/4}.
    const Vec sf{0.5, 1.0}, scr{0.2, 0.6}, gain{1.0, 3.0};
    CHECK(de::weighted_lehmer_mean(sf, gain) == 0.8125 / 0.875);  // (1/16 + 3/4) / (1/8 + 3/4)
    CHECK(de::weighted_arithmetic_mean(scr, gain) == Approx(0.5).epsilon(1e-15));
    CHECK(de::weighted_lehmer_mean(scr, gain) == Approx(0.28 / 0.5).epsilon(1e-15));  // (0.01 + 0.27) / 0.5
    CHECK(de::lehmer_mean(sf) == 1.25 / 1.5);
    CHECK(de::arithmetic_mean(scr) == Approx(0.4).epsilon(1e-15));
    // An infinite gain (a target worth +inf) takes the whole weight.
    CHECK(de::weighted_lehmer_mean(sf, Vec{pride::kInf, 1.0}) == 0.5);
    CHECK(de::weighted_arithmetic_mean(scr, Vec{pride::kInf, pride::kInf}) == Approx(0.4).epsilon(1e-15));
}

TEST_CASE("DE (U2) SHADE: M_CR <- mean_WA, M_F <- mean_WL, slot by slot, no update without success", "[de][memory]") {
    de::ShadeControl c;
    c.memory = 2;
    de::Adaptation a;
    c.start(a, 10);
    CHECK(a.memory_f == Vec{0.5, 0.5});
    de::Successes s(10);
    c.update(a, s);  // empty: nothing changes
    CHECK(a.next == 0);
    s.add(0.5, 0.2, 1.0);
    s.add(1.0, 0.6, 3.0);
    c.update(a, s);
    CHECK(a.memory_f[0] == 0.8125 / 0.875);
    CHECK(a.memory_cr[0] == Approx(0.5).epsilon(1e-15));
    CHECK(a.memory_f[1] == 0.5);
    CHECK(a.next == 1);
    c.update(a, s);
    c.update(a, s);  // k wraps around: slot 0 again
    CHECK(a.next == 1);
}

TEST_CASE("DE (U3) L-SHADE: weighted Lehmer means for both, the terminal value, code and paper readings",
          "[de][memory][lshade]") {
    de::Successes s(4), zeros(4);
    s.add(0.5, 0.2, 1.0);
    s.add(1.0, 0.6, 3.0);
    zeros.add(0.5, 0.0, 1.0);
    zeros.add(0.7, 0.0, 2.0);
    for (const bool sticky : {false, true}) {
        INFO("sticky terminal (the paper): " << sticky);
        de::LshadeControl c;
        c.memory = 1;
        c.sticky_terminal = sticky;
        de::Adaptation a;
        c.start(a, 4);
        c.update(a, s);
        CHECK(a.memory_f[0] == 0.8125 / 0.875);
        CHECK(a.memory_cr[0] == Approx(0.56).epsilon(1e-15));
        c.update(a, zeros);  // every successful CR is 0: the terminal value
        CHECK(a.memory_cr[0] == de::kTerminal);
        CHECK(a.memory_f[0] == Approx((0.25 / 3 + 0.49 * 2 / 3) / (0.5 / 3 + 0.7 * 2 / 3)).epsilon(1e-15));
        // A terminal slot gives CR = 0 with no normal draw.
        Script d;
        d.k = {0};
        d.u = {0.5};
        const auto p = c.sample(a, 0, {}, d);
        CHECK(p.cr == 0.0);
        CHECK(d.spent());
        c.update(a, s);  // Tanabe's code overwrites it; the paper keeps it terminal
        if (sticky)
            CHECK(a.memory_cr[0] == de::kTerminal);
        else
            CHECK(a.memory_cr[0] == Approx(0.56).epsilon(1e-15));
    }
}

TEST_CASE("DE (U4) jSO: the memory halves towards the means, the terminal value averaged as in Brest's code",
          "[de][memory][jso]") {
    const de::JsoControl c;
    de::Adaptation a;
    c.start(a, 4);
    CHECK(a.memory_f == Vec(5, 0.3));
    CHECK(a.memory_cr == Vec(5, 0.8));
    de::Successes s(4), zeros(4);
    s.add(0.5, 0.2, 1.0);
    s.add(1.0, 0.6, 3.0);
    zeros.add(0.5, 0.0, 1.0);
    c.update(a, s);
    CHECK(a.memory_f[0] == (0.8125 / 0.875 + 0.3) / 2.0);
    CHECK(a.memory_cr[0] == Approx((0.56 + 0.8) / 2.0).epsilon(1e-15));
    c.update(a, zeros);
    CHECK(a.memory_cr[1] == Approx(-0.1).epsilon(1e-15));  // (-1 + 0.8) / 2: negative, read as terminal
    for (int k = 0; k < 3; ++k) c.update(a, s);
    CHECK(a.next == 0);  // the fixed last slot is written too (Brest's code), never read
    CHECK(a.memory_cr[4] == Approx((0.56 + 0.8) / 2.0).epsilon(1e-15));
}

TEST_CASE("DE (U1) JADE: mu_CR and mu_F learn at rate c from mean_A and the Lehmer mean", "[de][memory]") {
    const de::JadeControl c;
    de::Adaptation a;
    c.start(a, 4);
    de::Successes s(4);
    s.add(0.5, 0.2, 1.0);
    s.add(1.0, 0.6, 3.0);
    c.update(a, s);
    CHECK(a.memory_cr[0] == Approx(0.9 * 0.5 + 0.1 * 0.4).epsilon(1e-15));
    CHECK(a.memory_f[0] == Approx(0.9 * 0.5 + 0.1 * (1.25 / 1.5)).epsilon(1e-15));
    // (P3): CR = mu_CR + 0.1 z clipped; F = mu_F + 0.1 tan(pi (u - 0.5)), drawn again while <= 0.
    de::Adaptation b;
    c.start(b, 4);
    Script d;
    d.z = {6.0};             // 0.5 + 0.6: clipped to 1
    d.u = {0.0, 0.75, 0.5};  // tan(-pi/2): F <= 0, drawn again; 0.5 + 0.1 tan(pi/4) = 0.6
    const auto p = c.sample(b, 0, {}, d);
    CHECK(p.cr == 1.0);
    CHECK(p.f == Approx(0.6).epsilon(1e-12));
    CHECK(d.u == std::deque<double>{0.5});
}

TEST_CASE("DE (P2) jDE: F_i and CR_i drawn anew with probability tau, kept with the vector", "[de][memory]") {
    const de::JdeControl c;
    de::Adaptation a;
    c.start(a, 3);
    CHECK(a.f == Vec(3, 0.5));
    CHECK(a.cr == Vec(3, 0.9));
    Script d;
    d.u = {0.05, 0.5, 0.5};  // 0.05 < tau1: F = 0.1 + 0.5 * 0.9; 0.5 >= tau2: CR stays
    const auto p = c.sample(a, 1, {}, d);
    CHECK(p.f == 0.1 + 0.5 * 0.9);
    CHECK(p.cr == 0.9);
    d.u = {0.5, 0.01, 0.3};  // F stays; CR = 0.3
    const auto q = c.sample(a, 2, {}, d);
    CHECK(q.f == 0.5);
    CHECK(q.cr == 0.3);
    CHECK(d.spent());
    c.keep(a, 1, p);
    CHECK(a.f == Vec{0.5, 0.1 + 0.5 * 0.9, 0.5});
}

TEST_CASE("DE (P5) jSO's schedules: CR floors, F cap, F_w and the fixed slot by the share of the budget",
          "[de][memory][jso]") {
    const de::JsoControl c;
    de::Adaptation a;
    c.start(a, 4);
    auto sample = [&](std::int64_t spent, std::uint64_t slot, double z, double u) {
        Script d;
        d.k = {slot};
        d.z = {z};
        d.u = {u};
        const auto p = c.sample(a, 0, {spent, 1000}, d);
        CHECK(d.spent());
        return p;
    };
    // Slot 0 (M_F 0.3, M_CR 0.8); z = -5: CR = 0.3 before the floors; u = 0.5: F = M_F.
    auto p = sample(100, 0, -5.0, 0.5);
    CHECK(p.cr == 0.7);  // nfes < 0.25 max_nfes
    CHECK(p.f == 0.3);
    CHECK(p.fw == 0.3 * 0.7);  // nfes < 0.2 max_nfes
    p = sample(200, 0, -5.0, 0.5);
    CHECK(p.cr == 0.7);
    CHECK(p.fw == 0.3 * 0.8);  // 0.2 <= nfes / max_nfes < 0.4
    p = sample(300, 0, -5.0, 0.5);
    CHECK(p.cr == 0.6);  // 0.25 <= . < 0.5
    p = sample(450, 0, -5.0, 0.5);
    CHECK(p.cr == 0.6);
    CHECK(p.fw == Approx(0.3 * 1.2).epsilon(1e-15));  // from 0.4 on
    p = sample(500, 0, -5.0, 0.5);
    CHECK(p.cr == Approx(0.3).epsilon(1e-15));  // no floor from 0.5 on
    // The last slot reads 0.9, 0.9; u = 0.9: F = 0.9 + 0.1 tan(0.4 pi) > 1: 1, capped at 0.7 before 0.6.
    p = sample(500, 4, 0.0, 0.9);
    CHECK(p.cr == 0.9);
    CHECK(p.f == 0.7);
    p = sample(600, 4, 0.0, 0.9);
    CHECK(p.f == 1.0);
    CHECK(p.fw == 1.2);
    // A terminal (negative) M_CR gives CR = 0, then the floors.
    a.memory_cr[0] = -0.1;
    Script d;
    d.k = {0, 0};
    d.u = {0.5, 0.5};
    CHECK(c.sample(a, 0, {100, 1000}, d).cr == 0.7);
    CHECK(c.sample(a, 0, {900, 1000}, d).cr == 0.0);
}

TEST_CASE("DE (L) LPSR: N_{G+1} = round((N_min - N_init) / max_nfes * nfes + N_init), at least N_min", "[de][lpsr]") {
    const de::LinearReduction r{4};
    CHECK(r.next(180, 180, {180, 100000}) == 180);  // round(179.68)
    CHECK(r.next(180, 180, {50000, 100000}) == 92);
    CHECK(r.next(92, 180, {50000, 100000}) == 92);
    CHECK(r.next(100, 180, {99990, 100000}) == 4);  // round(4.02)
    CHECK(r.next(5, 180, {100000, 100000}) == 4);
    CHECK(de::FixedPopulation{}.next(50, 50, {100000, 100000}) == 50);
    CHECK(de::PerDimensionSize{18.0}(10) == 180);
    CHECK(de::LogSqrtSize{25.0}(10) == 182);  // 182.03
    CHECK(de::LogSqrtSize{25.0}(2) == 25);    // 24.505
    CHECK(de::LogSqrtSize{25.0}(1) == 4);     // ln 1 = 0
}

TEST_CASE("DE: the archive appends, replaces at random when full, trims (JADE) and shrinks with N", "[de][archive]") {
    auto point = [](double v) { return Vec{v, -v}; };
    Script d;
    {
        const de::Archive none(2, 10, de::ArchiveRules{});
        CHECK(none.capacity() == 0);
    }
    de::ArchiveRules shade;
    shade.rate = 1.0;
    de::Archive a(2, 3, shade);
    for (double v : {1.0, 2.0, 3.0}) a.add(point(v), d);
    CHECK(a.size() == 3);
    d.k = {1};
    a.add(point(4.0), d);  // full: in place of member 1
    CHECK(a.size() == 3);
    CHECK(Vec(a.member(1).begin(), a.member(1).end()) == point(4.0));
    de::ArchiveRules jade = shade;
    jade.trim_after_generation = true;
    de::Archive b(2, 3, jade);
    for (double v : {1.0, 2.0, 3.0, 4.0, 5.0}) b.add(point(v), d);
    CHECK(b.size() == 5);
    d.k = {0, 3};  // member 0 removed (the last moves in), then member 3
    b.end_generation(d);
    CHECK(b.size() == 3);
    CHECK(Vec(b.member(0).begin(), b.member(0).end()) == point(5.0));
    // L-SHADE's code: |A| = round(2.6 N_init), then (int)(2.6 N) and the last members dropped.
    de::ArchiveRules code;
    code.rate = 2.6;
    code.floor_on_resize = true;
    de::Archive c(2, 5, code);
    CHECK(c.capacity() == 13);
    for (int v = 0; v < 13; ++v) c.add(point(v), d);
    c.resize(4, d);
    CHECK(c.capacity() == 10);  // (int) 10.4
    CHECK(c.size() == 10);
    CHECK(Vec(c.member(9).begin(), c.member(9).end()) == point(9.0));
    // The paper's reading: round(2.6 N), random members deleted.
    code.floor_on_resize = false;
    de::Archive e(2, 5, code);
    for (int v = 0; v < 13; ++v) e.add(point(v), d);
    d.k = {0, 0, 0};
    e.resize(4, d);
    CHECK(e.size() == 10);
    CHECK(Vec(e.member(0).begin(), e.member(0).end()) == point(10.0));
    CHECK(d.spent());
}

TEST_CASE("DE: the registry's entries, their population rules and memory estimates", "[de][engine]") {
    const auto& registry = pride::engine::algorithms();
    for (const char* name : kEntries) {
        INFO(name);
        const auto* e = registry.find(name);
        REQUIRE(e != nullptr);
        CHECK(e->family == "de");
        REQUIRE(e->param("pop") != nullptr);
        CHECK(*e->param("pop")->default_value == 0.0);
        REQUIRE(e->memory);
    }
    // N_init by the papers' rules: the first recorded iteration evaluates the initial population.
    struct Rule {
        const char* algo;
        std::int64_t dim, n_init;
    };
    for (const Rule r : {Rule{"de", 10, 100}, Rule{"de", 3, 30}, Rule{"jde", 10, 100}, Rule{"jade", 30, 100},
                         Rule{"shade", 2, 100}, Rule{"lshade", 10, 180}, Rule{"lshade", 2, 36}, Rule{"jso", 10, 182},
                         Rule{"jso", 2, 25}, Rule{"jso", 1, 4}}) {
        INFO(r.algo << " in dimension " << r.dim);
        const auto result = run(r.algo, "sphere", r.dim, 2000, 1);
        CHECK(result.history_evaluations.front() == r.n_init);
    }
    CHECK(run("lshade", "sphere", 10, 500, 1, {"pop=50"}).history_evaluations.front() == 50);
    // Memory: 8 bytes per number of the population and trials (2 N D), the archive (|A| D) and the
    // vectors (12 N, 2 H, 4 D), at the paper's N_init when pop is 0.
    auto bytes = [&](const char* algo, std::size_t dim, const std::string& set = "") {
        pride::engine::ParamValues v;
        if (!set.empty()) v.set_from_string(set);
        const auto* e = registry.find(algo);
        return e->memory(pride::engine::Params(algo, e->params, v), dim);
    };
    CHECK(bytes("lshade", 10) == 8.0 * ((2.0 * 180 + 468) * 10 + 12.0 * 180 + 2.0 * 6 + 40));
    CHECK(bytes("jade", 10) == 8.0 * ((2.0 * 100 + 200) * 10 + 12.0 * 100 + 2.0 + 40));  // |A| + N for the trim
    CHECK(bytes("de", 20) == 8.0 * (2.0 * 200 * 20 + 12.0 * 200 + 80));
    CHECK(bytes("jso", 1000) > bytes("jso", 100) * 10.0);  // N_init grows with D
    CHECK(bytes("lshade", 10, "pop=20") == 8.0 * ((2.0 * 20 + 52) * 10 + 12.0 * 20 + 2.0 * 6 + 40));
}

TEST_CASE("DE: every entry spends exact budgets, counted on the problem's side", "[de][budget]") {
    for (const char* name : kEntries)
        for (const std::int64_t n : {1, 2, 7, 99, 777, 2345}) {
            INFO(name << " --evals " << n);
            const Counted c = counted_sphere(4);
            const auto r = pride::engine::run({name, {}}, c.problem, evals(n), 3);
            CHECK(*c.calls == n);
            CHECK(r.evaluations == n);
            CHECK(r.history_evaluations.back() == n);
        }
}

TEST_CASE("DE: the same seed gives the same bits, another seed another run", "[de][reproducible]") {
    for (const char* name : kEntries) {
        INFO(name);
        const auto a = run(name, "rastrigin", 5, 3000, 11), b = run(name, "rastrigin", 5, 3000, 11),
                   c = run(name, "rastrigin", 5, 3000, 12);
        CHECK(a.best_f == b.best_f);
        CHECK(a.best_x == b.best_x);
        CHECK(a.history == b.history);
        CHECK(a.history_evaluations == b.history_evaluations);
        CHECK(a.best_x != c.best_x);
    }
    // The readings and the options change the run.
    CHECK(run("lshade", "rastrigin", 5, 3000, 11).history !=
          run("lshade", "rastrigin", 5, 3000, 11, {"reading=paper"}).history);
    CHECK(run("de", "rastrigin", 5, 3000, 11).history != run("de", "rastrigin", 5, 3000, 11, {"bounds=clamp"}).history);
}

TEST_CASE("DE: L-SHADE's and jSO's populations shrink from N_init to N_min as LPSR says", "[de][lpsr]") {
    for (const auto& [name, n_init] : {std::pair<const char*, std::int64_t>{"lshade", 180}, {"jso", 182}}) {
        INFO(name);
        const std::int64_t budget = 20000;
        std::vector<std::int64_t> size, spent;
        const auto r =
            pride::engine::run({name, {}}, pride::engine::Problem(pride::engine::ContinuousSpec{"rastrigin", 10}),
                               evals(budget), 5, [&](const pride::IterationView& v) {
                                   size.push_back(v.population.cols());
                                   spent.push_back(v.evaluations);
                                   CHECK(v.fitness.size() == static_cast<std::size_t>(v.population.cols()));
                                   return true;
                               });
        CHECK(r.evaluations == budget);
        REQUIRE(size.size() > 10);
        CHECK(size.front() == n_init);
        CHECK(size.back() == 4);
        for (std::size_t g = 1; g < size.size(); ++g) {
            INFO("generation " << g);
            CHECK(spent[g] - spent[g - 1] == std::min(size[g - 1], budget - spent[g - 1]));  // one batch of N
            const double plan = std::round((4.0 - static_cast<double>(n_init)) / static_cast<double>(budget) *
                                               static_cast<double>(spent[g]) +
                                           static_cast<double>(n_init));
            CHECK(size[g] == std::max<std::int64_t>(4, static_cast<std::int64_t>(plan)));
            CHECK(size[g] <= size[g - 1]);
        }
    }
}

TEST_CASE("DE: ask and tell hands out each generation's trials as one batch, shrinking with L-SHADE",
          "[de][engine][ask_tell]") {
    pride::engine::AskTell session({"lshade", {}}, Vec(3, -2.0), Vec(3, 2.0), evals(3000), 4);
    std::vector<std::int64_t> batches;
    while (!session.done()) {
        const pride::Matrix& x = session.ask();
        Vec values(static_cast<std::size_t>(x.cols()));
        for (Eigen::Index j = 0; j < x.cols(); ++j) values[static_cast<std::size_t>(j)] = x.col(j).squaredNorm();
        batches.push_back(x.cols());
        session.tell(values);
    }
    REQUIRE(batches.size() > 5);
    CHECK(batches.front() == 54);  // round(18 D): the initial population
    CHECK(batches[1] == 54);
    CHECK(batches.back() <= 5);
    CHECK(std::is_sorted(batches.rbegin(), batches.rend()));
    CHECK(session.result().evaluations == 3000);
}

TEST_CASE("DE: a schedule over the budget needs an evaluation limit (lshade, jso)", "[de][errors]") {
    for (const char* name : {"lshade", "jso"}) {
        INFO(name);
        const Counted c = counted_sphere(3);
        pride::engine::Budget iterations;
        iterations.iterations = 10;
        CHECK_THAT(input_error_message([&] {
                       pride::engine::run({name, {}}, c.problem, iterations, 1);
                   }),
                   Contains(std::string(name) + ": needs an evaluation limit"));
        CHECK(*c.calls == 0);
        // With both limits the evaluation limit is max_nfes.
        pride::engine::Budget both = iterations;
        both.evaluations = 100000;
        CHECK(pride::engine::run({name, {}}, c.problem, both, 1).iterations == 10);
    }
    pride::test::expect_input_error("run --problem sphere --dim 3 --algo jso --iters 5", {"jso", "evaluation limit"});
}

TEST_CASE("DE: pop below what the strategy or the reduction needs is refused", "[de][errors]") {
    pride::test::expect_input_error(
        "run --problem sphere --dim 3 --algo de --param strategy=rand-2-bin --pop 5 --evals 100",
        {"de: pop must be 0 (the paper's rule) or >= 6 for rand/2/bin, got 5"});
    pride::test::expect_input_error("run --problem sphere --dim 3 --algo de --pop 3 --evals 100",
                                    {"de: pop must be 0 (the paper's rule) or >= 4 for rand/1/bin, got 3"});
    pride::test::expect_input_error("run --problem sphere --dim 3 --algo lshade --param n_min=10 --pop 8 --evals 100",
                                    {"lshade: pop must be 0 (the paper's rule) or >= n_min = 10"});
    pride::test::expect_input_error("run --problem sphere --dim 3 --algo de --param strategy=rand/1 --evals 100",
                                    {"strategy"});
}

TEST_CASE("DE: each policy's validation error", "[de][errors]") {
    using Family = pride::De<de::SelectableMutation, de::SelectableControl, de::SelectableRepair, de::SelectableSize,
                             de::SelectableReduction>;
    auto message = [](auto change) {
        Family a;
        a.id = "x";
        change(a);
        return input_error_message([&] { a.validate(); });
    };
    auto control = [&](auto c) { return message([&](Family& a) { a.control = c; }); };
    auto mutation = [&](auto m) { return message([&](Family& a) { a.mutation = m; }); };
    CHECK(message([](Family&) {}) == "<no InputError thrown>");
    CHECK(message([](Family& a) { a.population = -1; }) == "x: pop must be 0 (the paper's rule) or positive, got -1");
    CHECK(control(de::FixedControl{0.0, 0.5}) == "x: F must be in (0, 2], got 0.000000");
    CHECK(control(de::FixedControl{2.5, 0.5}) == "x: F must be in (0, 2], got 2.500000");
    CHECK(control(de::FixedControl{0.5, 1.5}) == "x: CR must be in [0, 1], got 1.500000");
    CHECK(control(de::JdeControl{1.5}) == "x: tau1 must be in [0, 1], got 1.500000");
    CHECK(control(de::JdeControl{0.1, -0.1}) == "x: tau2 must be in [0, 1], got -0.100000");
    CHECK(control(de::JdeControl{0.1, 0.1, 0.0}) == "x: F_l must be in (0, 2], got 0.000000");
    CHECK(control(de::JdeControl{0.1, 0.1, 0.5, 1.8}) ==
          "x: F_u must be in [0, 2 - F_l], got 1.800000 with F_l 0.500000");
    CHECK(control(de::JdeControl{0.1, 0.1, 0.1, 0.9, 0.0}) == "x: the initial F must be in (0, 2], got 0.000000");
    CHECK(control(de::JdeControl{0.1, 0.1, 0.1, 0.9, 0.5, 2.0}) == "x: the initial CR must be in [0, 1], got 2.000000");
    CHECK(control(de::JadeControl{1.5}) == "x: c must be in [0, 1], got 1.500000");
    CHECK(control(de::JadeControl{0.1, 0.0}) == "x: the initial mu_F must be in (0, 1], got 0.000000");
    CHECK(control(de::JadeControl{0.1, 0.5, 1.5}) == "x: the initial mu_CR must be in [0, 1], got 1.500000");
    CHECK(control(de::ShadeControl{{0}}) == "x: memory must be in [1, 1000000], got 0");
    CHECK(control(de::ShadeControl{{5, 0.0}}) == "x: the initial M_F must be in (0, 1], got 0.000000");
    CHECK(control(de::ShadeControl{{5, 0.5, -1.0}}) == "x: the initial M_CR must be in [0, 1], got -1.000000");
    CHECK(control(de::LshadeControl{{0}}) == "x: memory must be in [1, 1000000], got 0");
    CHECK(control(de::JsoControl{1}) == "x: memory must be in [2, 1000000], got 1");
    CHECK(control(de::JsoControl{5, 0.3, 0.8, 0.0}) ==
          "x: the last slot's M_F and M_CR must be in (0, 1], got 0.000000");
    CHECK(mutation(de::CurrentToPBest<de::FixedRate>{{0.0}}) == "x: p must be in (0, 1], got 0.000000");
    CHECK(mutation(de::CurrentToPBest<de::UniformRate>{{1.5}}) == "x: p_max must be in (0, 1], got 1.500000");
    CHECK(mutation(de::CurrentToPBest<de::LinearRate>{{0.0, 0.0}}) == "x: p_max must be in (0, 1], got 0.000000");
    CHECK(mutation(de::CurrentToPBest<de::LinearRate>{{0.2, 0.3}}) ==
          "x: p_min must be in (0, p_max], got 0.300000 with p_max 0.200000");
    CHECK(mutation(de::CurrentToPBest<de::FixedRate>{{0.1}, 2.0}) ==
          "x: the share of the budget with x_pbest distinct from the target must be in [0, 1]");
    CHECK(mutation(de::RandTwo{}) == "<no InputError thrown>");
    CHECK(message([](Family& a) {
              a.mutation = de::RandTwo{};
              a.population = 5;
          }) == "x: pop must be 0 (the paper's rule) or >= 6 for rand/2/bin, got 5");
    CHECK(message([](Family& a) {
              a.mutation = de::BestOne{};  // needs 3: the reduction's own floor speaks
              a.reduction = de::LinearReduction{3};
          }) == "x: n_min must be in [4, 1000000000], got 3");
    CHECK(message([](Family& a) {
              a.reduction = de::LinearReduction{10};
              a.population = 8;
          }) == "x: pop must be 0 (the paper's rule) or >= n_min = 10 (the population size reduction's floor), got 8");
    CHECK(message([](Family& a) {
              a.mutation = de::RandTwo{};
              a.reduction = de::LinearReduction{4};
          }) == "x: n_min must be >= 6 for rand/2/bin, got 4");
    CHECK(message([](Family& a) { a.archive.rate = -1.0; }) == "x: archive rate must be in [0, 100], got -1.000000");
}

TEST_CASE("DE: every entry reaches 1e-8 on the sphere (D = 10) within 100000 evaluations", "[de][sanity]") {
    // Observed: below 1e-38 for every entry and seed; the margin is 30 orders of magnitude.
    for (const char* name : kEntries)
        for (const std::uint64_t seed : {1, 2}) {
            INFO(name << " seed " << seed);
            CHECK(run(name, "sphere", 10, 100000, seed).best_f < 1e-8);
        }
}

TEST_CASE("DE: every entry improves on rastrigin (D = 10), the adaptive ones nearly solve it", "[de][sanity]") {
    for (const char* name : kEntries)
        for (const std::uint64_t seed : {1, 2}) {
            INFO(name << " seed " << seed);
            const auto r = run(name, "rastrigin", 10, 100000, seed);
            CHECK(r.best_f < r.history.front() / 2.0);
            if (std::string(name) != "de") CHECK(r.best_f < 3.0);
        }
}

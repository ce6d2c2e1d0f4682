// docs/adding-a-problem.md's worked example: the header the doc shows (extracted from the doc by
// tests/CMakeLists.txt, as written) compiles, and the numbers the doc shows from its scratch copy are
// what the class gives here: its value, its instance 2 (built as the catalog builds instances) and
// a PSO run on instance 1 with the registry's default PSO. The registration lines are the catalog's
// own pattern, exercised by every other name of it.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "algorithms/pso.hpp"
#include "framework/termination.hpp"
#include "problems/continuous/instance.hpp"
#include "problems/continuous/sum_powers.hpp"  // from the doc
#include "problems/continuous/transformed.hpp"
#include "tests/test_support.hpp"

namespace {

using namespace pride;
using continuous::SumPowers;
using continuous::Transformed;

/// Instance k of SumPowers in dimension `dim`, as catalog.cpp's scalable() makes it.
Transformed<SumPowers> instance(std::size_t dim, std::uint64_t k) {
    SumPowers f(dim);
    const auto lo = f.lower(), hi = f.upper();
    auto t = continuous::instance_transform(lo, hi, f.optimum_point(), k, SumPowers::info.bounded_domain);
    return Transformed<SumPowers>(std::move(f), std::move(t), "sum-powers");
}

/// The value a transcript line of the doc shows after `$ COMMAND` (the line under it).
std::string shown_after(const std::string& command, std::size_t line = 1) {
    const auto lines = pride::test::lines_of(pride::test::slurp(PRIDE_SOURCE_DIR "/docs/adding-a-problem.md"));
    for (std::size_t i = 0; i + line < lines.size(); ++i)
        if (lines[i] == "$ " + command) return lines[i + line];
    FAIL("docs/adding-a-problem.md shows no '$ " << command << "'");
    return {};
}

}  // namespace

TEST_CASE("docs: adding-a-problem.md's example class gives the values the doc shows", "[docs]") {
    CHECK(std::string(SumPowers::info.name) == "sum-powers");
    const std::vector<double> x{0.5, -0.5, 1.0};
    const double f = SumPowers(3).evaluate(x);
    CHECK(f == 0.25 + 0.125 + 1.0);  // |x_i|^(i+1) by hand
    CHECK(fmt::format("{}", f) == shown_after("pride eval --problem sum-powers --x 0.5,-0.5,1"));
    const std::vector<double> origin(3, 0.0);
    CHECK(fmt::format("{}", instance(3, 2).evaluate(origin)) ==
          shown_after("pride eval --problem sum-powers --x 0,0,0 --instance 2"));
}

TEST_CASE("docs: adding-a-problem.md's PSO run on the example is the run the doc shows", "[docs]") {
    const Pso<> pso;  // the registry's pso: every parameter at its default
    const Result r = pso.run(instance(5, 1), max_evaluations(5000), 1);
    CHECK(r.evaluations == 5000);
    const std::string command = "pride run --problem sum-powers --dim 5 --instance 1 --algo pso --evals 5000 | head -4";
    CHECK(shown_after(command, 4) == fmt::format("best_f       {}", r.best_f));
}

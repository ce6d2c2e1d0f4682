// Every input the fuzzers (fuzz/, scripts/fuzz.sh) found a bug with, checked in under
// tests/data/fuzz/TARGET/, replayed through the reader its target drives: each must now be read
// or refused with an InputError, nothing else (under the sanitizer build of CI, without any
// report either). docs/reliability.md lists the bugs; the cases below check what each input gives.
#include <catch2/catch.hpp>

#include <filesystem>
#include <sstream>

#include "cli/commands.hpp"
#include "cli/numbers.hpp"
#include "engine/params.hpp"
#include "experiment/campaign/campaign.hpp"
#include "experiment/campaign/toml.hpp"
#include "experiment/report/ioh_export.hpp"
#include "experiment/report/report.hpp"
#include "problems/grid/map_io.hpp"
#include "roughset/roughset.hpp"
#include "tests/test_support.hpp"

namespace fs = std::filesystem;

namespace {

fs::path findings(const std::string& target) {
    return fs::path(PRIDE_SOURCE_DIR) / "tests" / "data" / "fuzz" / target;
}

std::vector<fs::path> inputs(const std::string& target) {
    std::vector<fs::path> out;
    if (fs::is_directory(findings(target)))
        for (const auto& e : fs::directory_iterator(findings(target))) out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
}

/// Runs `f`; true when it returned, false when it threw InputError (anything else fails the test).
template <class F>
bool accepted(F&& f) {
    try {
        f();
        return true;
    } catch (const pride::InputError& e) {
        CHECK(std::string(e.what()).find('\n') == std::string::npos);
        return false;
    }
}

}  // namespace

TEST_CASE("fuzz regressions: every checked-in input is read or refused as bad input", "[fuzz]") {
    using namespace pride;
    const test::TempDir dir;
    for (const auto& p : inputs("map")) {
        INFO(p);
        accepted([&] { grid::parse_map(test::slurp(p), "fuzz.map"); });
    }
    for (const auto& p : inputs("scenario")) {
        INFO(p);
        accepted([&] { grid::parse_scenario(test::slurp(p), "fuzz.scen"); });
    }
    for (const auto& p : inputs("roughset")) {
        INFO(p);
        accepted([&] { roughset::read_csv(p.string()); });
    }
    for (const auto& p : inputs("campaign")) {
        INFO(p);
        accepted([&] { campaign::read_campaign(p.string()); });
    }
    for (const auto& p : inputs("store")) {
        INFO(p);
        const std::string copy = dir.write("store.sqlite", test::slurp(p));
        accepted([&] { report::render_markdown(report::load_report(copy)); });
        accepted([&] { report::export_ioh(copy, dir.file("ioh")); });
        fs::remove_all(dir.file("ioh"));
    }
    for (const auto& p : inputs("cli")) {
        INFO(p);
        const std::string text = test::slurp(p);
        accepted([&] { cli::parse_point(text, "start"); });
        accepted([&] { engine::ParamValues().set_from_string(text); });
        accepted([&] {
            cli::EvalOptions o;
            o.problem = "sphere";
            o.x = "-";
            std::istringstream in(text);
            std::ostringstream out;
            cli::eval_command(o, in, out);
        });
    }
}

TEST_CASE("fuzz regressions: the inputs that timed out only under load read as they should", "[fuzz]") {
    // Mutated maps and a truncated store that passed 1 s while the machine was at load 19; alone
    // they take 30-150 ms in the fuzz build (docs/reliability.md). The maps are read whole; the
    // store is refused as damaged, naming it.
    using namespace pride;
    for (const char* name : {"load-timeout-8f9b84c0", "load-timeout-cd99313a"}) {
        const auto m = grid::parse_map(test::slurp(findings("map") / name), name);
        CHECK(m.size() > 0);
    }
    const test::TempDir dir;
    const std::string store = dir.write("store.sqlite", test::slurp(findings("store") / "load-timeout-f893e160"));
    CHECK_THAT(test::input_error_message([&] { report::load_report(store); }),
               Catch::Contains("store.sqlite: damaged store"));
}

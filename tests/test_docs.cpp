// The docs are checked like code: docs/adding-an-algorithm.md's example is tests/example_algorithm.cpp
// (compiled into this binary, registered as "example-es") and runs as the doc says; docs/cli.md's
// generated tables are what `pride list --markdown` prints; every command a doc shows prints what the
// doc shows under it (bar timings); every command the README shows runs as written, in a folder
// that holds only the clone's files it names and the build.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <regex>
#include <set>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "engine/registry.hpp"
#include "engine/run.hpp"
#include "framework/error.hpp"
#include "tests/cli_runner.hpp"
#include "tests/test_support.hpp"

// tests/example_algorithm.cpp
pride::engine::RunResult run_example_by_name();
pride::Result run_example_directly(std::int64_t& improvements);

namespace {

using namespace pride;
using pride::test::input_error_message;
using pride::test::lines_of;
using pride::test::slurp;

const std::string kSource = PRIDE_SOURCE_DIR;

engine::RunResult run_es(const engine::Problem& problem, std::int64_t evaluations, std::uint64_t seed,
                         const std::map<std::string, double>& params = {}) {
    engine::AlgorithmSpec spec{"example-es", {}};
    for (const auto& [name, value] : params) spec.params.set(name, value);
    engine::Budget budget;
    budget.evaluations = evaluations;
    return engine::run(spec, problem, budget, seed);
}

/// Every fenced block of a markdown text: its opening line ("```sh") and its lines.
struct Block {
    std::string fence;
    std::vector<std::string> lines;
    std::string preceding;  // the last non-empty line before the fence
};

std::vector<Block> blocks_of(const std::string& markdown) {
    std::vector<Block> out;
    std::string previous;
    Block* open = nullptr;
    for (const auto& line : lines_of(markdown)) {
        if (open) {
            if (line == "```")
                open = nullptr;
            else
                open->lines.push_back(line);
        } else if (line.rfind("```", 0) == 0) {
            out.push_back({line, {}, previous});
            open = &out.back();
        } else if (!line.empty()) {
            previous = line;
        }
    }
    return out;
}

/// The regions of tests/example_algorithm.cpp between "// doc: NAME" and "// doc: end".
std::map<std::string, std::vector<std::string>> example_regions() {
    std::map<std::string, std::vector<std::string>> regions;
    std::vector<std::string>* open = nullptr;
    for (const auto& line : lines_of(slurp(kSource + "/tests/example_algorithm.cpp"))) {
        if (line == "// doc: end")
            open = nullptr;
        else if (line.rfind("// doc: ", 0) == 0)
            open = &regions[line.substr(8)];
        else if (open)
            open->push_back(line);
    }
    return regions;
}

/// Timings differ from run to run: their values are blanked in text and JSON alike.
std::string without_timings(const std::string& text) {
    static const std::regex timing(R"re(((wall_ms|expansions_per_s)"?:?\s+)[-+0-9.e]+)re");
    return std::regex_replace(text, timing, "$1T");
}

/// What `command` prints on stdout and stderr together (as a terminal shows them), run by /bin/sh
/// in `top` with `top`/.bin first on PATH.
std::string shell_output(const pride::test::TempDir& top, const std::string& command) {
    const std::string script = top.write(".command.sh", command + "\n");
    const std::string line = "cd '" + top.path().string() + "' && PATH='" + top.file(".bin") + ":" +
                             std::getenv("PATH") + "' sh '" + script + "' >'" + top.file(".out") + "' 2>&1 </dev/null";
    [[maybe_unused]] const int status = std::system(line.c_str());  // the doc shows statuses with echo $?
    return slurp(top.file(".out"));
}

}  // namespace

TEST_CASE("docs: the example algorithm is listed with its declared parameters", "[docs]") {
    const engine::AlgorithmEntry* es = engine::algorithms().find("example-es");
    REQUIRE(es != nullptr);
    CHECK(es->family == "es");
    CHECK(es->spaces() == std::vector<std::string>{"box"});
    // Its two, then the three every algorithm that plans on grids gets from the registry.
    REQUIRE(es->params.size() == 5);
    CHECK(es->params[2].name == "encoding");
    CHECK(es->params[3].name == "connector");
    CHECK(es->params[4].name == "init");
    CHECK(es->native_encoding == "line");

    const engine::ParamSpec& sigma0 = es->params[0];
    CHECK(sigma0.name == "sigma0");
    CHECK(sigma0.type == engine::ParamType::real);
    CHECK(sigma0.default_value == 0.1);
    CHECK(sigma0.range() == "(0, 1]");

    const engine::ParamSpec& window = es->params[1];
    CHECK(window.name == "window");
    CHECK(window.type == engine::ParamType::integer);
    CHECK(window.default_value == 10.0);
    CHECK(window.range() == "[1, 1000]");
}

TEST_CASE("docs: the example runs by name on a registered problem with an exact budget", "[docs]") {
    const engine::Problem sphere(engine::ContinuousSpec{"sphere", 5});
    for (const std::int64_t budget : {1, 2, 7, 777}) {
        const auto a = run_es(sphere, budget, 42);
        CHECK(a.algorithm == "example-es");
        CHECK(a.evaluations == budget);
        CHECK(a.iterations == budget - 1);  // one evaluation per iteration after the first
        CHECK(std::isfinite(a.best_f));
        CHECK(a.history.size() == static_cast<std::size_t>(a.iterations + 1));
        const auto b = run_es(sphere, budget, 42);
        CHECK(b.best_x == a.best_x);  // exact comparisons on purpose: same seed, same bits
        CHECK(b.history == a.history);
    }
    const auto a = run_es(sphere, 777, 42);
    CHECK(run_es(sphere, 777, 43).best_x != a.best_x);
    CHECK(run_es(sphere, 777, 42, {{"sigma0", 0.3}, {"window", 3}}).best_x != a.best_x);
    CHECK(a.best_f < 1e-3);  // it does optimise: the sphere's box is [-5.12, 5.12]^5
}

TEST_CASE("docs: the example runs on a callback problem", "[docs]") {
    auto calls = std::make_shared<std::int64_t>(0);  // the problem is copied into the run
    engine::CallbackSpec spec;
    spec.name = "shifted-square";
    spec.lower = {-2.0, -2.0, -2.0};
    spec.upper = {3.0, 3.0, 3.0};
    spec.scalar = [calls](std::span<const double> x) {
        ++*calls;
        double s = 0.0;
        for (const double v : x) s += (v - 1.0) * (v - 1.0);
        return s;
    };
    const engine::Problem problem(spec);
    const auto r = run_es(problem, 500, 1);
    CHECK(r.evaluations == 500);
    CHECK(*calls == 500);  // counted on the problem's side too
    CHECK(std::isfinite(r.best_f));
    CHECK(r.best_f < 1e-2);
    REQUIRE(r.best_x.size() == 3);
    for (const double v : r.best_x) CHECK((v >= -2.0 && v <= 3.0));
    CHECK(run_es(problem, 500, 1).best_x == r.best_x);
}

TEST_CASE("docs: the example's parameters are checked against their declared ranges", "[docs]") {
    const engine::Problem sphere(engine::ContinuousSpec{"sphere", 2});
    auto refused = [&](const std::map<std::string, double>& params) {
        return input_error_message([&] { run_es(sphere, 10, 1, params); });
    };
    // The messages docs/adding-an-algorithm.md quotes.
    CHECK(refused({{"sigma0", 2.0}}) ==
          "example-es: sigma0 must be in (0, 1] (initial step, as a fraction of each coordinate's range), got 2");
    CHECK(refused({{"sigma", 0.1}}) ==
          "example-es: unknown parameter 'sigma' (parameters: sigma0, window, encoding, connector, init)");
    CHECK_THAT(refused({{"sigma0", 0.0}}), Catch::Contains("sigma0 must be in (0, 1]"));
    CHECK_THAT(refused({{"window", 0.0}}), Catch::Contains("window must be an integer in [1, 1000]"));
    CHECK_THAT(refused({{"window", 2.5}}), Catch::Contains("window must be an integer"));
}

TEST_CASE("docs: the example's typed run is the run by name", "[docs]") {
    std::int64_t improvements = 0;
    const Result direct = run_example_directly(improvements);
    CHECK(direct.evaluations == 1000);
    CHECK(improvements > 10);
    CHECK(improvements <= direct.iterations);
    const auto by_name = run_example_by_name();
    CHECK(by_name.evaluations == 1000);
    CHECK(by_name.best_x == direct.best_x);
    CHECK(by_name.history == direct.history);
}

TEST_CASE("docs: adding-an-algorithm.md shows tests/example_algorithm.cpp as it is", "[docs]") {
    const auto regions = example_regions();
    REQUIRE(regions.size() == 3);
    const std::string marker = "<!-- tests/example_algorithm.cpp: ";
    std::map<std::string, int> shown;
    for (const auto& block : blocks_of(slurp(kSource + "/docs/adding-an-algorithm.md"))) {
        if (block.preceding.rfind(marker, 0) != 0) continue;
        const std::string name = block.preceding.substr(marker.size(), block.preceding.size() - marker.size() - 4);
        INFO("the block marked '" << block.preceding << "'");
        CHECK(block.fence == "```cpp");
        REQUIRE(regions.count(name) == 1);
        CHECK(block.lines == regions.at(name));
        ++shown[name];
    }
    for (const auto& [name, lines] : regions) {
        INFO("region '" << name << "' of tests/example_algorithm.cpp");
        CHECK(shown[name] == 1);
    }
}

TEST_CASE("docs: cli.md's generated tables are what pride list --markdown prints", "[docs]") {
    const std::string doc = slurp(kSource + "/docs/cli.md");
    const std::string begin = "<!-- generated by: pride list --markdown -->\n", end = "<!-- end generated -->\n";
    const auto from = doc.find(begin);
    REQUIRE(from != std::string::npos);
    const auto to = doc.find(end, from);
    REQUIRE(to != std::string::npos);
    const auto r = pride::test::run_pride("list --markdown");
    REQUIRE(r.status == 0);
    INFO("regenerate: see docs/cli.md, `pride list`");
    std::string shown = doc.substr(from + begin.size(), to - from - begin.size());
    if (!engine::algorithms().find("ompl:RRTstar")) {
        // A build without OMPL (the sanitized one) lists no ompl: entries: the doc's rows and
        // parameter section of them, made where OMPL is built, are left out of the comparison.
        std::string kept;
        bool in_ompl_section = false;
        for (const auto& line : lines_of(shown)) {
            if (line.rfind("#### ", 0) == 0) in_ompl_section = line.rfind("#### `ompl:", 0) == 0;
            if (!in_ompl_section && line.rfind("| `ompl:", 0) != 0) kept += line + "\n";
        }
        shown = kept;
    }
    CHECK(shown == "\n" + r.out + "\n");
}

TEST_CASE("docs: every command the docs show prints what they show", "[docs]") {
    // Each doc runs in a folder of its own laid out as the top of a clone (examples/,
    // reference-data/, scripts/, tests/ linked from the source; docs/img/ empty, for the pictures a doc
    // draws), its commands in order (a later one may read what an earlier one wrote), with `pride`
    // on PATH the one just built. A transcript is a fenced block whose first line starts with "$ ";
    // one marked "<!-- scratch copy" shows a modified build and is checked elsewhere
    // (test_docs_problem.cpp); one marked "<!-- needs OMPL" only where OMPL is built (not in the
    // sanitized build, whose PRIDE_OMPL is off); one marked "<!-- needs $PRIDE_DATA/FOLDER" (the
    // public data of others, which the repository does not hold) only where that folder is, and
    // PRIDE_DATA reaches the commands, which name it so.
    namespace fs = std::filesystem;
    std::size_t checked = 0, cli = 0;
    std::map<std::string, bool> shared;  // PRIDE_DATA's folders, each looked up (and its absence told) once
    const std::string needs_data = "<!-- needs $PRIDE_DATA/";
    for (const auto& entry : fs::directory_iterator(fs::path(kSource) / "docs")) {
        if (entry.path().extension() != ".md") continue;
        const std::string doc = "docs/" + entry.path().filename().string();
        const pride::test::TempDir top("pride-doc");
        for (const char* name : {"examples", "reference-data", "scripts", "tests"})
            fs::create_directory_symlink(fs::path(kSource) / name, top.path() / name);
        fs::create_directories(top.path() / "docs" / "img");
        fs::create_directory(top.path() / ".bin");
        fs::create_symlink(PRIDE_EXE, top.path() / ".bin" / "pride");
        for (const auto& block : blocks_of(slurp(entry.path().string()))) {
            if (block.lines.empty() || block.lines.front().rfind("$ ", 0) != 0) continue;
            if (block.preceding.rfind("<!-- scratch copy", 0) == 0) continue;
            if (block.preceding.rfind("<!-- needs OMPL", 0) == 0 && !engine::algorithms().find("ompl:RRTstar"))
                continue;
            if (block.preceding.rfind(needs_data, 0) == 0) {
                const std::string rest = block.preceding.substr(needs_data.size());
                const std::string folder = rest.substr(0, rest.find_first_of(" :"));
                if (!shared.count(folder))
                    shared[folder] = pride::test::shared_data(folder, "for the docs' transcripts on it").has_value();
                if (!shared[folder]) continue;
            }
            for (std::size_t i = 0; i < block.lines.size();) {
                const std::string command = block.lines[i].substr(2);
                std::string shown;
                for (++i; i < block.lines.size() && block.lines[i].rfind("$ ", 0) != 0; ++i)
                    shown += block.lines[i] + "\n";
                INFO(doc << ": $ " << command);
                CHECK(without_timings(shell_output(top, command)) == without_timings(shown));
                ++checked;
                if (doc == "docs/cli.md") ++cli;
            }
        }
    }
    CHECK(cli >= 30);
    CHECK(checked >= 95);
}

TEST_CASE("docs: the README's main-job command builds every program it runs and the test command all",
          "[docs][readme]") {
    // The main job's command builds only its own targets (the first result does not wait
    // for the tests); a program it runs that is not among them would be missing on a fresh clone,
    // which the test above cannot see, since it runs the commands against this whole build.
    std::vector<std::string> commands;
    for (const auto& block : blocks_of(slurp(kSource + "/README.md")))
        if (block.fence == "```sh" && !block.lines.empty()) commands.push_back(block.lines.front());
    REQUIRE(commands.size() >= 2);
    const std::string& main_job = commands[0];
    const std::string build = "cmake --build build --target ";
    const std::size_t at = main_job.find(build);
    REQUIRE(at != std::string::npos);
    std::set<std::string> targets;
    {
        const std::size_t from = at + build.size();
        std::istringstream names(main_job.substr(from, main_job.find(" && ", from) - from));
        for (std::string name; names >> name;) targets.insert(name);
    }
    CHECK(targets.size() >= 3);
    const std::regex program(R"(\./build/([a-z]+)/([A-Za-z0-9_]+))");
    std::size_t programs = 0;
    for (std::sregex_iterator m(main_job.begin(), main_job.end(), program), end; m != end; ++m, ++programs) {
        const std::string dir = (*m)[1], name = (*m)[2];
        INFO("README's main job runs ./build/" << dir << "/" << name);
        CHECK(targets.count(name) == 1);
        CHECK(std::filesystem::exists(std::filesystem::path(PRIDE_BUILD_DIR) / dir / name));
    }
    CHECK(programs >= 4);
    // The test command builds everything (the tests and the Python module included).
    CHECK(commands[1].find("cmake --build build && ctest ") != std::string::npos);
}

TEST_CASE("docs: every command the README shows runs as written", "[docs][readme]") {
    // A folder laid out as the top of a clone (examples/, reference-data/, scripts/ linked from the
    // source; build/ holding links to this build's programs), so that the README's paths resolve
    // as written and what its commands write (build/...) stays out of the checkout.
    namespace fs = std::filesystem;
    const pride::test::TempDir top("pride-readme");
    for (const char* name : {"examples", "reference-data", "scripts"})
        fs::create_directory_symlink(fs::path(kSource) / name, top.path() / name);
    fs::create_directory(top.path() / "build");
    const bool python = fs::exists(fs::path(PRIDE_BUILD_DIR) / "python" / "pride");
    for (const char* name : {"cli", "examples", "python"})
        if (fs::exists(fs::path(PRIDE_BUILD_DIR) / name))
            fs::create_directory_symlink(fs::path(PRIDE_BUILD_DIR) / name, top.path() / "build" / name);
    std::size_t run = 0;
    for (const auto& block : blocks_of(slurp(kSource + "/README.md"))) {
        if (block.fence != "```sh") continue;
        for (std::size_t i = 0; i < block.lines.size(); ++i) {
            std::string line = block.lines[i];
            while (!line.empty() && line.back() == '\\' && i + 1 < block.lines.size())
                line = line.substr(0, line.size() - 1) + block.lines[++i];
            // The set-up steps (install, configure, build, ctest) are this build's own: the rest of
            // a command line runs as written.
            std::string command;
            std::size_t from = 0;
            while (from <= line.size()) {
                const std::size_t to = std::min(line.find(" && ", from), line.size());
                const std::string part = line.substr(from, to - from);
                const bool setup = part.rfind("bash scripts/deps.sh", 0) == 0 || part.rfind("cmake ", 0) == 0 ||
                                   part.rfind("ctest ", 0) == 0;
                if (!setup) command += (command.empty() ? "" : " && ") + part;
                from = to + 4;
            }
            if (command.empty()) continue;
            if (command.find("build/python") != std::string::npos && !python) continue;  // sanitized builds
            INFO("README: " << command);
            const std::string script = top.write("command.sh", command + "\n");
            const std::string shell =
                "cd '" + top.path().string() + "' && sh '" + script + "' >'" + top.file("out") + "' 2>&1 </dev/null";
            const int status = std::system(shell.c_str());
            INFO(slurp(top.file("out")));
            CHECK(status == 0);
            ++run;
        }
    }
    CHECK(run >= (python ? 17u : 16u));  // sanitized builds have no Python module
    CHECK(fs::exists(top.path() / "build" / "continuous.sqlite"));
    CHECK(fs::exists(top.path() / "build" / "path.png"));
}

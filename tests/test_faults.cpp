// Faults outside the campaign engine, through the real `pride` executable: write
// errors on standard output (a full device, a closed stream) for every subcommand; pictures onto
// devices, onto /dev/stdout and twice onto one file; IOHprofiler folders from algorithm ids that
// are not file names; `--version`; `report --plots` on a store the plotting script cannot read;
// a truncated store. The stores are written by `pride bench` itself.
#include <sqlite3.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "tests/cli_runner.hpp"
#include "tests/test_support.hpp"

namespace {

namespace fs = std::filesystem;
using pride::test::check_input_error;
using pride::test::CliOutput;
using pride::test::run_pride;
using pride::test::slurp;
using pride::test::TempDir;

std::string quote(const std::string& s) {
    return "'" + s + "'";
}

/// `pride ARGS` with standard output sent where `redirect` says (a shell redirection such as
/// ">/dev/full" or ">&-"), stderr captured.
CliOutput run_redirected(const std::string& args, const std::string& redirect) {
    const TempDir io("pride-redirect");
    const std::string cmd = quote(PRIDE_EXE) + " " + args + " </dev/null " + redirect + " 2>" + quote(io.file("err"));
    const int raw = std::system(cmd.c_str());
    CliOutput r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.err = slurp(io.file("err"));
    return r;
}

std::string map_file() {
    return std::string(PRIDE_SOURCE_DIR) + "/examples/maps/wan2022-10x10.map";
}

/// A small store written by pride bench, with the algorithm ids given.
std::string small_store(const TempDir& dir, const std::vector<std::string>& algorithm_ids,
                        const std::string& name = "s") {
    std::string text = "name = \"" + name +
                       "\"\nseeds = 2\n[budget]\niterations = 5\n"
                       "[[problem]]\nid = \"sphere\"\ntype = \"sphere\"\ndim = 2\n"
                       "[[problem]]\nid = \"grid\"\ntype = \"grid\"\nmap = \"" +
                       map_file() + "\"\nstart = [0, 0]\ngoal = [9, 9]\n";
    for (const auto& id : algorithm_ids) text += "[[algorithm]]\nid = \"" + id + "\"\ntype = \"pso\"\npop = 6\n";
    const std::string config = dir.write(name + ".toml", text);
    const std::string store = dir.file(name + ".sqlite");
    const auto r = run_pride("bench " + quote(config) + " --jobs 1 --out " + quote(store));
    INFO(r.out << r.err);
    REQUIRE(r.status == 0);
    return store;
}

}  // namespace

TEST_CASE("cli: every subcommand fails with one line when standard output is full or closed", "[cli][faults]") {
    const TempDir dir("pride-stdout");
    const std::string store = small_store(dir, {"pso"});
    const std::string map = map_file();
    const std::vector<std::string> commands{
        "--version",
        "--help",
        "list",
        "list --json",
        "run --problem sphere --dim 2 --algo pso --evals 200",
        "eval --problem sphere --x 1,2",
        "path --map " + quote(map) + " --start 0,0 --goal 9,9 --algo astar",
        "pareto --map " + quote(map) + " --start 0,0 --goal 9,9 --objectives length,turns",
        "roughset --grid",
        "report " + quote(store),
        "export " + quote(store) + " --ioh " + quote(dir.file("ioh")),
        "bench " + quote(dir.file("s.toml")) + " --jobs 1 --out " + quote(store),
    };
    for (const auto& args : commands) {
        for (const std::string redirect : {">/dev/full", ">&-"}) {
            INFO("pride " << args << " " << redirect);
            const CliOutput r = run_redirected(args, redirect);
            check_input_error(r, {"standard output"});
        }
    }
    // The same commands succeed when the output can be written.
    for (const auto& args : commands) {
        INFO("pride " << args);
        CHECK(run_redirected(args, ">/dev/null").status == 0);
    }
}

TEST_CASE("cli: --version prints the version", "[cli][faults]") {
    const CliOutput r = run_pride("--version");
    CHECK(r.status == 0);
    CHECK(r.err.empty());
    CHECK(r.out.rfind("pride ", 0) == 0);
    CHECK(std::count(r.out.begin(), r.out.end(), '\n') == 1);
}

TEST_CASE("path: pictures onto devices are written directly, never renamed over them", "[cli][faults][draw]") {
    const TempDir dir("pride-draw");
    const std::string base = "path --map " + quote(map_file()) + " --start 0,0 --goal 9,9 --algo astar";
    {
        INFO("--png /dev/full: a write error, and the device stays a device");
        check_input_error(run_pride(base + " --png /dev/full"), {"/dev/full"});
        struct stat st {};
        REQUIRE(::stat("/dev/full", &st) == 0);
        CHECK(S_ISCHR(st.st_mode));
        CHECK(dir.entries().empty());
    }
    {
        INFO("--svg /dev/stdout: the picture goes to standard output; /dev/stdout stays a link");
        const std::string out = dir.file("out.svg");
        // Through a pipe: the picture, then the text (a redirection to a file would be opened
        // twice, each writer at its own offset).
        const int raw =
            std::system((quote(PRIDE_EXE) + " " + base + " --svg /dev/stdout | cat >" + quote(out)).c_str());
        CHECK(WIFEXITED(raw));
        CHECK(WEXITSTATUS(raw) == 0);
        CHECK(slurp(out).find("<svg") != std::string::npos);
        CHECK(fs::is_symlink("/dev/stdout"));
    }
    {
        INFO("--png F --svg F: refused before anything is drawn");
        const std::string same = dir.file("same");
        check_input_error(run_pride(base + " --png " + quote(same) + " --svg " + quote(same)), {same, "two pictures"});
        CHECK(!fs::exists(same));
        const std::string via = dir.file("./same");
        check_input_error(run_pride(base + " --png " + quote(same) + " --svg " + quote(via)), {"two pictures"});
        CHECK(dir.entries() == std::vector<std::string>{"out.svg"});
    }
    {
        INFO("a folder as the picture");
        fs::create_directories(dir.path() / "folder");
        check_input_error(run_pride(base + " --png " + quote(dir.file("folder"))), {dir.file("folder"), "folder"});
        CHECK(fs::is_empty(dir.path() / "folder"));
    }
    {
        INFO("a regular file is replaced whole");
        const std::string png = dir.file("p.png");
        dir.write("p.png", "old");
        CHECK(run_pride(base + " --png " + quote(png)).status == 0);
        CHECK(slurp(png).substr(1, 3) == "PNG");
    }
}

TEST_CASE("export: algorithm ids that are not file names get safe folders of their own", "[export][faults]") {
    const TempDir dir("pride-ids");
    // (Ids with one file name, such as a/b and a_b, are refused by the campaign: test_report_precision.cpp.)
    const std::vector<std::string> ids{"..", "a/b", "b_c", ".hidden", "x y"};
    const std::string store = small_store(dir, ids);
    fs::create_directories(dir.path() / "out");
    const std::string out = dir.file("out/ioh");
    // Reading a store may leave SQLite's -wal and -shm files beside it: not counted.
    const auto listing = [&] {
        std::vector<std::string> names;
        for (const auto& n : dir.entries())
            if (n.find("-wal") == std::string::npos && n.find("-shm") == std::string::npos) names.push_back(n);
        return names;
    };
    const auto before = listing();
    const CliOutput r = run_pride("export " + quote(store) + " --ioh " + quote(out));
    INFO(r.out << r.err);
    REQUIRE(r.status == 0);
    CHECK(listing() == before);  // nothing beside the folder named
    CHECK(fs::directory_iterator(dir.path() / "out") != fs::directory_iterator());
    std::vector<std::string> folders;
    for (const auto& e : fs::directory_iterator(out)) {
        CHECK(e.is_directory());
        folders.push_back(e.path().filename().string());
    }
    CHECK(folders.size() == ids.size());                                             // one each, none shared
    CHECK(std::set<std::string>(folders.begin(), folders.end()).count("b_c") == 1);  // a safe id keeps its name
    for (const auto& f : folders) {
        INFO(f);
        CHECK(f.front() != '.');
        CHECK(f.find('/') == std::string::npos);
    }
    // Every algorithm's own files, and the count printed is the count written.
    std::size_t files = 0;
    for (const auto& e : fs::recursive_directory_iterator(out))
        if (e.is_regular_file()) ++files;
    CHECK(files == ids.size() * 2 * 2);  // per algorithm: 2 problems x (.info + .dat)
    CHECK(r.out.find(std::to_string(files) + " IOHprofiler files written") != std::string::npos);
    for (const auto& f : folders) {
        std::size_t info = 0;
        for (const auto& e : fs::directory_iterator(fs::path(out) / f))
            if (e.path().extension() == ".info") {
                ++info;
                const std::string text = slurp(e.path());
                bool named = false;
                for (const auto& id : ids) named = named || text.find("algId = \"" + id + "\"") != std::string::npos;
                CHECK(named);
            }
        CHECK(info == 2);
    }
}

TEST_CASE("report --plots: a store the plotting script cannot read is one line, no traceback",
          "[report][plots][faults]") {
    const TempDir dir("pride-plots-damaged");
    const std::string store = small_store(dir, {"pso"});
    for (const auto& [name, sql] : std::vector<std::pair<std::string, std::string>>{
             {"solution", "UPDATE runs SET solution = '[1, ' WHERE seed = 1"},
             {"history", "UPDATE runs SET history = '[\"x\"]' WHERE seed = 1"}}) {
        INFO(name);
        const std::string copy = dir.file(name + ".sqlite");
        fs::copy_file(store, copy);
        sqlite3* db = nullptr;
        REQUIRE(sqlite3_open(copy.c_str(), &db) == SQLITE_OK);
        REQUIRE(sqlite3_exec(db, sql.c_str(), nullptr, nullptr, nullptr) == SQLITE_OK);
        sqlite3_close(db);
        const CliOutput r = run_pride("report " + quote(copy) + " --plots " + quote(dir.file(name + "-plots")));
        check_input_error(r, {copy, "damaged store", "column " + name});
        CHECK(r.err.find("Traceback") == std::string::npos);
    }
    // A good store: figures and no word on stderr (library warnings are silenced).
    const CliOutput ok = run_pride("report " + quote(store) + " --plots " + quote(dir.file("plots")));
    INFO(ok.err);
    CHECK(ok.status == 0);
    CHECK(ok.err.empty());
    CHECK(fs::exists(dir.file("plots/sphere-convergence.png")));
}

TEST_CASE("report, export: a truncated store says so, with the sizes", "[report][export][damaged][faults]") {
    const TempDir dir("pride-truncated");
    const std::string store = small_store(dir, {"pso", "ga"});
    const auto size = fs::file_size(store);
    REQUIRE(size > 8192);
    const std::string cut = dir.file("cut.sqlite");
    fs::copy_file(store, cut);
    fs::resize_file(cut, size - 4096);
    check_input_error(run_pride("report " + quote(cut)),
                      {cut + ": damaged store: ", "truncated", std::to_string(size - 4096)});
    check_input_error(run_pride("export " + quote(cut) + " --ioh " + quote(dir.file("x"))),
                      {cut + ": damaged store: ", "truncated"});
    CHECK(!fs::exists(dir.file("x")));
}

TEST_CASE("faults: an error message that cannot be written still exits with the error's status", "[faults][cli]") {
    // fmt's print used to throw from main's error handler when stderr could not be written, and
    // the process aborted (SIGABRT, 134). The message is lost; the status is the error's.
    const std::string map = map_file();
    const std::vector<std::pair<std::string, int>> failing{
        {"run --problem x --dim 2 --algo pso", 2},                      // bad input
        {"run --problem sphere --dim 2 --algo pso --no-such-flag", 2},  // a parse error
        {"path --map " + quote(map) + " --start 0,0 --goal 99,99 --algo astar", 2},
        {"report " + quote("/nonexistent/s.sqlite"), 2},
    };
    for (const auto& [args, status] : failing) {
        for (const std::string redirect : {"2>/dev/full", "2>&-"}) {
            INFO("pride " << args << " " << redirect);
            const int raw = std::system((quote(PRIDE_EXE) + " " + args + " </dev/null >/dev/null " + redirect).c_str());
            REQUIRE(WIFEXITED(raw));
            CHECK(WEXITSTATUS(raw) == status);
        }
        // A closed pipe with SIGPIPE ignored: the reader (true) is gone before pride writes, the
        // write fails with EPIPE, and the status stays.
        INFO("pride " << args << " 2>| a closed pipe, SIGPIPE ignored");
        const TempDir dir("pride-stderr-pipe");
        const std::string status_file = dir.file("status");
        const int raw = std::system(("trap '' PIPE; { sleep 0.2; " + quote(PRIDE_EXE) + " " + args +
                                     " </dev/null; echo $? >" + quote(status_file) + "; } 2>&1 >/dev/null | true")
                                        .c_str());
        REQUIRE(WIFEXITED(raw));
        CHECK(WEXITSTATUS(raw) == 0);
        CHECK(slurp(status_file) == std::to_string(status) + "\n");
    }
}

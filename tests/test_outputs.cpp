// Outputs complete or absent (docs/reliability.md "Outputs: complete or absent"):
// framework/output_files.hpp on its own (commit, discard, a rename that fails, a write that fails),
// then every command that writes files, through the real `pride`: a full disk simulated with
// RLIMIT_FSIZE (writes past N bytes fail with EFBIG, SIGXFSZ ignored) and standard output on
// /dev/full leave none of the new files and no temporary; problem ids "x/y" and "x_y" get figures
// of their own; empty paths are refused; `bench --out` on something that is not a regular file
// creates nothing; and stores on a read-only file system are read.
#include <sqlite3.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "experiment/storage/file_name.hpp"
#include "experiment/storage/reader.hpp"
#include "framework/output_files.hpp"
#include "tests/cli_runner.hpp"
#include "tests/sqlite_support.hpp"
#include "tests/test_support.hpp"

using pride::test::exec_sql;

namespace {

namespace fs = std::filesystem;
using pride::OutputFiles;
using pride::test::check_input_error;
using pride::test::CliOutput;
using pride::test::run_pride;
using pride::test::run_pride_in;
using pride::test::slurp;
using pride::test::TempDir;

/// `s` as one word for /bin/sh, whatever it holds (quotes too: commands are nested in sh -c).
std::string quote(const std::string& s) {
    std::string out = "'";
    for (const char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

/// Every file and folder under `dir` (relative paths), with the size of each file: what a
/// failed command must leave as it found. SQLite's -wal and -shm files, which a reader of a store
/// may leave or remove, are not counted.
std::map<std::string, std::uintmax_t> tree(const fs::path& dir) {
    std::map<std::string, std::uintmax_t> out;
    if (!fs::exists(dir)) return out;
    for (const auto& e : fs::recursive_directory_iterator(dir)) {
        const std::string name = fs::relative(e.path(), dir).string();
        if (name.ends_with("-wal") || name.ends_with("-shm")) continue;
        out[name] = e.is_regular_file() ? e.file_size() : 0;
    }
    return out;
}

/// The temporaries of OutputFiles (".NAME.pride-PID-N.tmp", ".old") and scratch folders under `dir`.
std::vector<std::string> temporaries(const fs::path& dir) {
    std::vector<std::string> out;
    if (!fs::exists(dir)) return out;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.path().filename().string().find(".pride-") != std::string::npos) out.push_back(e.path().string());
    return out;
}

/// `pride ARGS` (a shell's words) with files limited to `max_bytes` each (RLIMIT_FSIZE) and
/// SIGXFSZ ignored, so that a write past the limit fails with EFBIG as on a full disk.
CliOutput run_limited(const std::string& args, rlim_t max_bytes) {
    const TempDir io("pride-limited");
    const std::string out = io.file("out"), err = io.file("err");
    const pid_t pid = ::fork();
    REQUIRE(pid >= 0);
    if (pid == 0) {
        const rlimit limit{max_bytes, max_bytes};
        ::setrlimit(RLIMIT_FSIZE, &limit);
        std::signal(SIGXFSZ, SIG_IGN);  // ignored signals stay ignored through exec
        const std::string cmd = quote(PRIDE_EXE) + " " + args + " </dev/null >" + quote(out) + " 2>" + quote(err);
        ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    int raw = 0;
    ::waitpid(pid, &raw, 0);
    CliOutput r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
}

std::string map_file() {
    return std::string(PRIDE_SOURCE_DIR) + "/examples/maps/wan2022-10x10.map";
}

/// A store of two problems (a sphere and a grid) and two algorithms, written by pride bench.
std::string small_store(const TempDir& dir, const std::string& name = "s", int iterations = 30) {
    const std::string config = dir.write(
        name + ".toml", "name = \"" + name + "\"\nseeds = 2\n[budget]\niterations = " + std::to_string(iterations) +
                            "\n"
                            "[[problem]]\nid = \"sphere\"\ntype = \"sphere\"\ndim = 2\n"
                            "[[problem]]\nid = \"grid\"\ntype = \"grid\"\nmap = \"" +
                            map_file() +
                            "\"\nstart = [0, 0]\ngoal = [9, 9]\n"
                            "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\npop = 6\n"
                            "[[algorithm]]\nid = \"ga\"\ntype = \"ga\"\npop = 6\n");
    const std::string store = dir.file(name + ".sqlite");
    const auto r = run_pride("bench " + quote(config) + " --jobs 1 --out " + quote(store));
    INFO(r.out << r.err);
    REQUIRE(r.status == 0);
    return store;
}

/// A small bbob campaign (COCO traces, target hits: ECDFs and the COCO export).
std::string bbob_store(const TempDir& dir) {
    const std::string config = dir.write("b.toml",
                                         "name = \"b\"\nseeds = 1\n[budget]\nevaluations = 300\n[[suite]]\nname = "
                                         "\"bbob\"\nfunctions = [1, 2]\ninstances = [1]\ndimensions = [2]\n"
                                         "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\npop = 6\n");
    const std::string store = dir.file("b.sqlite");
    const auto r = run_pride("bench " + quote(config) + " --jobs 1 --out " + quote(store));
    INFO(r.out << r.err);
    REQUIRE(r.status == 0);
    return store;
}

bool has_matplotlib() {
    return std::system("/usr/bin/python3 -c 'import matplotlib' >/dev/null 2>&1") == 0;
}

}  // namespace

TEST_CASE("outputs: files appear only at commit, and discarded nothing is left", "[outputs]") {
    const TempDir dir("pride-out-unit");
    const fs::path out = dir.path() / "new" / "deeper";
    {
        OutputFiles files;
        CHECK_THROWS_WITH(files.create(out / "a.txt"),
                          Catch::Contains("a.txt: cannot write: No such file or directory"));
        files.make_folder(out / "sub");
        files.write(out / "a.txt", "alpha");
        OutputFiles::File& b = files.create(out / "sub" / "b.txt");
        b.write("beta");
        b.close();
        CHECK(!fs::exists(out / "a.txt"));  // only temporaries so far
        CHECK(fs::exists(b.written_at()));
        CHECK(fs::path(b.written_at()).filename().string().rfind(".b.txt.pride-", 0) == 0);
        // Not committed: everything goes, the folders it made too.
    }
    CHECK(dir.entries().empty());
    {
        OutputFiles files;
        files.make_folder(out / "sub");
        files.write(out / "a.txt", "alpha");
        files.write(out / "sub" / "b.txt", "beta");
        files.commit();
    }
    CHECK(slurp(out / "a.txt") == "alpha");
    CHECK(slurp(out / "sub" / "b.txt") == "beta");
    CHECK(temporaries(dir.path()).empty());
    {
        INFO("discarded into an existing folder: the folder and its files stay as they were");
        const auto before = tree(dir.path());
        OutputFiles files;
        files.write(out / "a.txt", "changed");
        files.write(out / "c.txt", "new");
        files.discard();
        CHECK(tree(dir.path()) == before);
        CHECK(slurp(out / "a.txt") == "alpha");
    }
    {
        INFO("one file named twice, a folder as a file");
        OutputFiles files;
        files.write(out / "x.txt", "x");
        CHECK_THROWS_WITH(files.create(out / "." / "x.txt"), Catch::Contains("named twice"));
        CHECK_THROWS_WITH(files.create(out / "sub"), Catch::Contains("it is a folder"));
        CHECK_THROWS_WITH(files.make_folder(out / "a.txt"), Catch::Contains("a.txt: exists and is not a folder"));
        CHECK_THROWS_WITH(files.make_folder(out / "a.txt" / "inside"),
                          Catch::Contains("a.txt/inside: cannot create the folder: Not a directory"));
    }
    CHECK(!fs::exists(out / "x.txt"));
    CHECK(temporaries(dir.path()).empty());
}

TEST_CASE("outputs: a rename that fails at commit puts back what was renamed before it", "[outputs]") {
    const TempDir dir("pride-out-rename");
    const fs::path out = dir.path() / "o";
    fs::create_directories(out);
    dir.write("o/first.txt", "old first");
    const auto before = tree(dir.path());
    OutputFiles files;
    files.write(out / "first.txt", "new first");
    files.write(out / "second.txt", "new second");
    files.write(out / "third.txt", "new third");
    fs::create_directories(out / "third.txt" / "inside");  // now a folder holds its name: rename(2) fails
    CHECK_THROWS_WITH(files.commit(), Catch::Contains("third.txt: cannot write: "));
    fs::remove_all(out / "third.txt");
    CHECK(tree(dir.path()) == before);  // first.txt old again, second.txt gone, no temporary
    CHECK(slurp(out / "first.txt") == "old first");
}

TEST_CASE("outputs: a write that fails (a full disk) names the file and the reason", "[outputs]") {
    const TempDir dir("pride-out-full");
    // In a child: RLIMIT_FSIZE makes the second file's write fail with EFBIG.
    const std::string message = dir.file("message");
    const pid_t pid = ::fork();
    REQUIRE(pid >= 0);
    if (pid == 0) {
        const rlimit limit{1000, 1000};
        ::setrlimit(RLIMIT_FSIZE, &limit);
        std::signal(SIGXFSZ, SIG_IGN);
        int status = 0;
        try {
            OutputFiles files;
            files.make_folder(dir.path() / "out");
            files.write(dir.path() / "out" / "small.txt", std::string(100, 's'));
            files.write(dir.path() / "out" / "large.txt", std::string(5000, 'l'));
            files.commit();
        } catch (const pride::InputError& e) {
            std::FILE* f = std::fopen(message.c_str(), "w");
            std::fputs(e.what(), f);
            std::fclose(f);
            status = 2;
        }
        ::_exit(status);
    }
    int raw = 0;
    ::waitpid(pid, &raw, 0);
    REQUIRE(WIFEXITED(raw));
    CHECK(WEXITSTATUS(raw) == 2);
    CHECK(slurp(message) == (dir.path() / "out" / "large.txt").string() + ": cannot write: File too large");
    CHECK(dir.entries() == std::vector<std::string>{"message"});  // no out/, no small.txt, no temporary
}

TEST_CASE("outputs: devices are written directly, and their write errors named", "[outputs]") {
    OutputFiles files;
    CHECK(OutputFiles::writes_directly("/dev/null"));
    CHECK(!OutputFiles::writes_directly("/tmp/no-such-pride-file"));
    files.write("/dev/null", "nothing");
    OutputFiles::File& full = files.create("/dev/full");
    CHECK_THROWS_WITH(full.write(std::string(100, 'x')), "/dev/full: cannot write: No space left on device");
    CHECK_THROWS_WITH(full.close(), "/dev/full: cannot write: No space left on device");  // the first error, kept
}

TEST_CASE("outputs: a full disk leaves no part of any command's files", "[outputs][cli]") {
    const TempDir dir("pride-out-cli");
    const std::string store = small_store(dir);
    const std::string bbob = bbob_store(dir);
    const std::string map = map_file();
    struct Case {
        std::string name, args;  // args with OUT for the output
        bool folder;             // OUT is a folder
    };
    std::vector<Case> cases{
        {"export --ioh", "export " + quote(store) + " --ioh OUT", true},
        {"export --coco", "export " + quote(bbob) + " --coco OUT", true},
        {"report --html", "report " + quote(bbob) + " --html OUT", true},
        {"path --png", "path --map " + quote(map) + " --start 0,0 --goal 9,9 --algo astar --png OUT", false},
        {"path --svg", "path --map " + quote(map) + " --start 0,0 --goal 9,9 --algo astar --oracle --svg OUT", false},
        {"pareto --png", "pareto --map " + quote(map) + " --start 0,0 --goal 9,9 --objectives length,turns --png OUT",
         false},
    };
    if (has_matplotlib()) cases.push_back({"report --plots", "report " + quote(bbob) + " --plots OUT", true});
    for (const auto& c : cases) {
        INFO(c.name);
        const auto with = [&](const std::string& out) {
            std::string args = c.args;
            args.replace(args.find("OUT"), 3, quote(out));
            return args;
        };
        // Once without a limit: the files it writes, and their sizes.
        const std::string reference = dir.file("reference-" + std::to_string(&c - cases.data()));
        const CliOutput ok = run_pride(with(reference));
        INFO(ok.err);
        REQUIRE(ok.status == 0);
        std::vector<std::uintmax_t> sizes;
        if (c.folder) {
            for (const auto& e : fs::recursive_directory_iterator(reference))
                if (e.is_regular_file()) sizes.push_back(e.file_size());
        } else {
            sizes.push_back(fs::file_size(reference));
        }
        std::sort(sizes.begin(), sizes.end());
        const std::uintmax_t largest = sizes.back();
        REQUIRE(largest > 64);
        // Then with every file limited to one byte less than the largest: the others can be
        // written, that one cannot. Into a new folder, and into one that holds an older output.
        for (const bool over_older : {false, true}) {
            INFO((over_older ? "over an older output" : "into a new path"));
            const std::string out = dir.file("out-" + std::to_string(&c - cases.data()) + (over_older ? "-old" : ""));
            if (over_older) {
                if (c.folder)
                    fs::copy(reference, out, fs::copy_options::recursive);
                else
                    fs::copy_file(reference, out);
            }
            const auto before = tree(dir.path());
            const CliOutput r = run_limited(with(out), largest - 1);
            check_input_error(r, {out, "File too large"});
            CHECK(tree(dir.path()) == before);
            CHECK(temporaries(dir.path()).empty());
        }
        CHECK((sizes.size() == 1 || sizes.front() < largest));  // a failure part-way: others could be written
    }
}

TEST_CASE("outputs: links planted inside an output folder are replaced or refused, never followed", "[outputs][cli]") {
    // Before: out/index.html a link to a file elsewhere made `report --html out` write the report
    // into that file, and a link planted as an export's folder received the export.
    const TempDir dir("pride-out-links");
    const std::string store = small_store(dir);
    const std::string bbob = bbob_store(dir);
    std::vector<std::pair<std::string, std::string>> cases{
        {"export --ioh", "export " + quote(store) + " --ioh "},
        {"export --coco", "export " + quote(bbob) + " --coco "},
        {"report --html", "report " + quote(bbob) + " --html "},
    };
    if (has_matplotlib()) cases.emplace_back("report --plots", "report " + quote(bbob) + " --plots ");
    const std::string victim = dir.write("victim.txt", "keep me\n");
    const fs::path victims = dir.file("victims");
    fs::create_directories(victims);
    for (const auto& [name, args] : cases) {
        INFO(name);
        const std::string reference = dir.file("reference-" + std::to_string(&name - &cases.front().first));
        REQUIRE(run_pride(args + quote(reference)).status == 0);
        // One file and one folder of what the command writes (every entry would take minutes
        // under the sanitizers): the first of each by name.
        std::vector<fs::directory_entry> planted_on;
        for (const bool folder : {false, true}) {
            std::vector<fs::directory_entry> of_kind;
            for (const auto& e : fs::directory_iterator(reference))
                if (e.is_directory() == folder) of_kind.push_back(e);
            std::sort(of_kind.begin(), of_kind.end());
            if (!of_kind.empty()) planted_on.push_back(of_kind.front());
        }
        REQUIRE(!planted_on.empty());
        for (const auto& entry : planted_on) {
            const std::string planted = entry.path().filename().string();
            INFO(planted);
            const fs::path out = dir.file("out");
            fs::remove_all(out);
            fs::create_directories(out);
            fs::create_symlink(entry.is_directory() ? victims : fs::path(victim), out / planted);
            const CliOutput r = run_pride(args + quote(out.string()));
            if (entry.is_directory()) {
                check_input_error(r, {(out / planted).string(), "is a symbolic link"});
            } else {
                INFO(r.err);
                REQUIRE(r.status == 0);
                CHECK(fs::is_regular_file(fs::symlink_status(out / planted)));
                CHECK(fs::file_size(out / planted) > 0);
            }
            CHECK(slurp(victim) == "keep me\n");
            CHECK(fs::is_empty(victims));
        }
    }
    // The folder the user names may itself be a link: it is followed, as documented.
    const fs::path linked = dir.file("linked");
    fs::create_directories(dir.file("real"));
    fs::create_directory_symlink(dir.file("real"), linked);
    REQUIRE(run_pride("report " + quote(bbob) + " --html " + quote(linked.string())).status == 0);
    CHECK(fs::is_regular_file(dir.file("real/index.html")));
}

TEST_CASE("outputs: files are committed only once standard output was written", "[outputs][cli]") {
    const TempDir dir("pride-out-stdout");
    const std::string store = small_store(dir);
    const std::string map = map_file();
    std::vector<std::string> commands{
        "path --map " + quote(map) + " --start 0,0 --goal 9,9 --algo astar --png OUT",
        "path --map " + quote(map) + " --start 0,0 --goal 9,9 --algo astar --json --svg OUT",
        "pareto --map " + quote(map) + " --start 0,0 --goal 9,9 --objectives length,turns --svg OUT",
        "export " + quote(store) + " --ioh OUT",
        "report " + quote(store) + " --html OUT",
    };
    if (has_matplotlib()) commands.push_back("report " + quote(store) + " --plots OUT");
    for (std::string args : commands) {
        const std::string out = dir.file("out");
        args.replace(args.find("OUT"), 3, quote(out));
        INFO("pride " << args << " >/dev/full");
        const auto before = tree(dir.path());
        const TempDir io("pride-out-err");
        const int raw =
            std::system((quote(PRIDE_EXE) + " " + args + " </dev/null >/dev/full 2>" + quote(io.file("err"))).c_str());
        REQUIRE(WIFEXITED(raw));
        CHECK(WEXITSTATUS(raw) == 2);
        const std::string err = slurp(io.file("err"));
        CHECK(err == "pride: cannot write to standard output: No space left on device\n");
        CHECK(tree(dir.path()) == before);
        CHECK(!fs::exists(out));
    }
}

TEST_CASE("outputs: problem ids x/y and x_y get figures of their own", "[outputs][report]") {
    const TempDir dir("pride-out-ids");
    // Campaigns refuse such ids (test_report_precision.cpp); merged or older stores can hold them.
    const std::string store = small_store(dir, "s", 5);
    exec_sql(
        store,
        "UPDATE problems SET id = 'x/y' WHERE id = 'sphere'; UPDATE runs SET problem = 'x/y' WHERE problem = "
        "'sphere'; UPDATE problems SET id = 'x_y' WHERE id = 'grid'; UPDATE runs SET problem = 'x_y' WHERE problem "
        "= 'grid'");
    const auto names = pride::storage::unique_file_names({"x/y", "x_y"});
    REQUIRE(names.at("x_y") == "x_y");
    REQUIRE(names.at("x/y") != "x_y");
    {
        const CliOutput r = run_pride("report " + quote(store) + " --html " + quote(dir.file("page")));
        INFO(r.err);
        REQUIRE(r.status == 0);
        for (const auto& [id, name] : names) {
            INFO(id);
            CHECK(fs::exists(dir.path() / "page" / ("convergence-" + name + ".svg")));
            CHECK(fs::exists(dir.path() / "page" / ("final-" + name + ".svg")));
        }
        CHECK(fs::exists(dir.path() / "page" / "paths-x_y.svg"));  // the grid's, not replaced by the sphere's
        const std::string html = slurp(dir.path() / "page" / "index.html");
        CHECK(html.find("id=\"problem-" + names.at("x/y") + "\"") != std::string::npos);
        CHECK(html.find("id=\"problem-x_y\"") != std::string::npos);
    }
    if (has_matplotlib()) {
        const CliOutput r = run_pride("report " + quote(store) + " --plots " + quote(dir.file("plots")));
        INFO(r.err);
        REQUIRE(r.status == 0);
        for (const auto& [id, name] : names)
            for (const char* kind : {"-convergence.png", "-convergence.svg", "-final.png", "-final.svg"}) {
                INFO(id << kind);
                CHECK(fs::exists(dir.path() / "plots" / (name + kind)));
            }
        CHECK(fs::exists(dir.path() / "plots" / "x_y-paths.svg"));
    }
    {
        const CliOutput r = run_pride("export " + quote(store) + " --ioh " + quote(dir.file("ioh")));
        INFO(r.err);
        REQUIRE(r.status == 0);
        std::size_t files = 0;
        for (const auto& e : fs::recursive_directory_iterator(dir.path() / "ioh")) files += e.is_regular_file();
        CHECK(files == 2 * 2 * 2);  // 2 algorithms x 2 problems x (.info + .dat): none replaced
        CHECK(r.out.find(std::to_string(files) + " IOHprofiler files written") != std::string::npos);
    }
}

TEST_CASE("outputs: an empty path is refused wherever a path is taken", "[outputs][cli]") {
    const TempDir dir("pride-out-empty");
    const std::string map = map_file();
    const std::string grid = "--map " + quote(map) + " --start 0,0 --goal 9,9";
    const std::string store = dir.file("missing.sqlite");
    for (const auto& [args, flag] : std::vector<std::pair<std::string, std::string>>{
             {"path " + grid + " --algo astar --png ''", "--png"},
             {"path " + grid + " --algo astar --svg ''", "--svg"},
             {"path --map '' --start 0,0 --goal 9,9 --algo astar", "--map"},
             {"pareto " + grid + " --objectives length,turns --png ''", "--png"},
             {"pareto " + grid + " --objectives length,turns --svg ''", "--svg"},
             {"bench " + quote(dir.file("c.toml")) + " --out ''", "--out"},
             {"bench ''", "config"},
             {"report " + quote(store) + " --plots ''", "--plots"},
             {"report " + quote(store) + " --html ''", "--html"},
             {"report ''", "stores"},
             {"export " + quote(store) + " --ioh ''", "--ioh"},
             {"export " + quote(store) + " --coco ''", "--coco"},
             {"merge " + quote(store) + " " + quote(store) + " --out ''", "--out"},
             {"scen ''", "file"},
             {"roughset ''", "table"},
         }) {
        INFO("pride " << args);
        check_input_error(run_pride_in(dir.path().string(), args), {flag, "expected a path, got ''"});
        CHECK(dir.entries().empty());
    }
}

TEST_CASE("outputs: bench --out on a device or a pipe is refused before SQLite creates anything", "[outputs][bench]") {
    const TempDir dir("pride-out-device");
    const std::string config = dir.write(
        "c.toml",
        "name = \"c\"\nseeds = 1\n[budget]\niterations = 2\n[[problem]]\nid = \"s\"\ntype = \"sphere\"\ndim = "
        "2\n[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\npop = 4\n");
    const std::string fifo = dir.file("fifo");
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    fs::create_directories(dir.path() / "folder");
    const auto before = dir.entries();
    check_input_error(run_pride("bench " + quote(config) + " --out " + quote(fifo)), {fifo, "not a regular file"});
    check_input_error(run_pride("bench " + quote(config) + " --out " + quote(dir.file("folder"))),
                      {"folder", "it is a folder"});
    CHECK(dir.entries() == before);  // no fifo-journal, fifo-wal, fifo-shm
    CHECK(fs::is_empty(dir.path() / "folder"));
    const bool journal_before = fs::exists("/dev/null-journal");
    check_input_error(run_pride("bench " + quote(config) + " --out /dev/null"), {"/dev/null", "not a regular file"});
    if (!journal_before) CHECK(!fs::exists("/dev/null-journal"));
}

namespace {

/// Runs `command` (a shell's words) with `folder` made read-only: a read-only bind mount in a new
/// mount namespace (unshare; the real "read-only file system", also for root, whom permission
/// bits do not stop), else, for a user that is not root, the folder's write permission taken
/// away. Empty when neither can be done here.
std::optional<CliOutput> run_read_only(const fs::path& folder, const std::string& command) {
    const TempDir io("pride-ro");
    const std::string redirect = " </dev/null >" + quote(io.file("out")) + " 2>" + quote(io.file("err"));
    const std::string mount = "mount --bind " + quote(folder.string()) + " " + quote(folder.string()) +
                              " && mount -o remount,bind,ro " + quote(folder.string());
    const auto result = [&](int raw) {
        CliOutput r;
        r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
        r.out = slurp(io.file("out"));
        r.err = slurp(io.file("err"));
        return r;
    };
    for (const char* unshare : {"unshare -rm", "unshare -m"}) {
        const std::string probe = std::string(unshare) + " sh -c " +
                                  quote(mount + " && ! touch " + quote((folder / ".probe").string()) + " 2>/dev/null") +
                                  " >/dev/null 2>&1";
        if (std::system(probe.c_str()) != 0) continue;
        return result(
            std::system((std::string(unshare) + " sh -c " + quote(mount + " && " + command) + redirect).c_str()));
    }
    if (::geteuid() != 0) {
        fs::permissions(folder, fs::perms::owner_write | fs::perms::group_write | fs::perms::others_write,
                        fs::perm_options::remove);
        const int raw = std::system((command + redirect).c_str());
        fs::permissions(folder, fs::perms::owner_write, fs::perm_options::add);
        return result(raw);
    }
    return std::nullopt;
}

}  // namespace

TEST_CASE("outputs: a finished store on a read-only file system is read", "[outputs][store]") {
    const TempDir dir("pride-out-ro");
    // A name that an SQLite URI must escape ('?', '#', '%', a space).
    const fs::path stores = dir.path() / "stores";
    fs::create_directories(stores);
    const std::string made = small_store(dir, "s", 5);
    const std::string store = (stores / "a?b#c%d e.sqlite").string();
    fs::copy_file(made, store);
    const std::string copy = (stores / "copy.sqlite").string();  // another file of the same runs
    fs::copy_file(made, copy);
    REQUIRE(!fs::exists(store + "-wal"));
    const std::string out = dir.file("out");
    const auto exe = quote(PRIDE_EXE) + " ";
    std::vector<std::pair<std::string, std::string>> commands{
        {"report", exe + "report " + quote(store)},
        {"report --html", exe + "report " + quote(store) + " --html " + quote(out + "/page")},
        {"export --ioh", exe + "export " + quote(store) + " --ioh " + quote(out + "/ioh")},
        {"merge", exe + "merge " + quote(store) + " " + quote(copy) + " --out " + quote(out + "/merged.sqlite")},
    };
    if (has_matplotlib())
        commands.emplace_back("report --plots", exe + "report " + quote(store) + " --plots " + quote(out + "/plots"));
    for (const auto& [name, command] : commands) {
        INFO(name);
        const auto r = run_read_only(stores, command);
        if (!r) {
            WARN("no read-only file system or folder can be made here (root without unshare): not tested");
            return;
        }
        INFO(r->err);
        CHECK(r->status == 0);
        CHECK(r->err.empty());
    }
    CHECK(fs::exists(out + "/page/index.html"));
    CHECK(fs::exists(out + "/ioh"));
    CHECK(fs::exists(out + "/merged.sqlite"));
    const std::vector<std::string> expected{"a?b#c%d e.sqlite", "copy.sqlite"};
    std::vector<std::string> left;
    for (const auto& e : fs::directory_iterator(stores)) left.push_back(e.path().filename().string());
    std::sort(left.begin(), left.end());
    CHECK(left == expected);  // nothing written beside it

    // A store whose write-ahead log still holds changes, without its -shm: SQLite cannot open
    // the log read-only, and reading the file alone (immutable) would miss them: refused, saying so.
    const fs::path busy = dir.path() / "busy";
    fs::create_directories(busy);
    {
        const std::string live = dir.file("live.sqlite");
        fs::copy_file(made, live);
        sqlite3* db = nullptr;
        REQUIRE(sqlite3_open(live.c_str(), &db) == SQLITE_OK);
        REQUIRE(sqlite3_exec(db, "PRAGMA journal_mode=WAL; PRAGMA wal_autocheckpoint=0; UPDATE campaign SET name = 'n'",
                             nullptr, nullptr, nullptr) == SQLITE_OK);
        fs::copy_file(live, busy / "w.sqlite");
        fs::copy_file(live + "-wal", busy / "w.sqlite-wal");  // while it is open: the log holds the update
        sqlite3_close(db);
    }
    REQUIRE(fs::file_size(busy / "w.sqlite-wal") > 0);
    const auto r = run_read_only(busy, exe + "report " + quote((busy / "w.sqlite").string()));
    REQUIRE(r);
    check_input_error(*r, {"w.sqlite: cannot read the store", "w.sqlite-wal", "read-only"});
}

TEST_CASE("outputs: read_only_uri escapes the name and says mode=ro where the folder is writable", "[outputs][store]") {
    const TempDir dir("pride-out-uri");
    const std::string made = small_store(dir, "s", 3);
    const std::string odd = dir.file("x?y#z%w.sqlite");
    fs::copy_file(made, odd);
    const std::string uri = pride::storage::read_only_uri(odd);
    CHECK(uri.rfind("file:///", 0) == 0);
    CHECK(uri.find("x%3Fy%23z%25w.sqlite?mode=ro") != std::string::npos);
    CHECK(pride::storage::read_store(odd).runs.size() == pride::storage::read_store(made).runs.size());
}

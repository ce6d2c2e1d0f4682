// Inputs made to break pride from outside (docs/reliability.md): each class is refused in one line
// with exit status 2, or handled, where every front end passes through it; none hangs, crashes or
// touches a file the user did not name as output.
#include <sys/stat.h>
#include <sys/types.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include "tests/cli_runner.hpp"
#include "tests/test_support.hpp"

namespace fs = std::filesystem;
using pride::test::CliOutput;
using pride::test::run_pride;
using pride::test::TempDir;

namespace {

std::string q(const std::string& s) {
    return "'" + s + "'";
}

const std::string kCampaign =
    "name = \"h\"\nseeds = 2\n[budget]\nevaluations = 200\n"
    "[[problem]]\nid = \"s\"\ntype = \"sphere\"\ndim = 2\n"
    "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\npop = 6\n";

/// A small store of kCampaign named `name` in `dir`.
std::string small_store(const TempDir& dir, const std::string& name) {
    const auto r = run_pride("bench " + q(dir.write(name + ".toml", kCampaign)) + " --out " + q(dir.file(name)));
    INFO(r.err);
    REQUIRE(r.status == 0);
    return dir.file(name);
}

/// One line on stderr, exit status 2, naming `words`.
void refused(const CliOutput& r, const std::string& words) {
    INFO(r.out << r.err);
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Catch::Contains(words));
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
}

}  // namespace

TEST_CASE("hostile: merge never removes or writes a file it was not asked to write", "[hostile][merge]") {
    const TempDir dir("pride-hostile-merge");
    const std::string a = small_store(dir, "a.sqlite");
    const std::string b = small_store(dir, "b.sqlite");
    // An input named as OUT.part (the name merge used to clear for its temporary) stays an input.
    fs::copy_file(a, dir.file("keep.sqlite.part"));
    const std::string before = pride::test::slurp(dir.file("keep.sqlite.part"));
    auto r =
        run_pride("merge " + q(dir.file("keep.sqlite.part")) + " " + q(b) + " --out " + q(dir.file("keep.sqlite")));
    INFO(r.err);
    CHECK(r.status == 0);
    CHECK(pride::test::slurp(dir.file("keep.sqlite.part")) == before);
    CHECK(fs::exists(dir.file("keep.sqlite")));
    // A user's own file beside the output is kept.
    dir.write("m.sqlite.part", "precious\n");
    r = run_pride("merge " + q(a) + " " + q(b) + " --out " + q(dir.file("m.sqlite")));
    CHECK(r.status == 0);
    CHECK(pride::test::slurp(dir.file("m.sqlite.part")) == "precious\n");
    // Nothing hidden is left beside the outputs.
    for (const auto& name : dir.entries()) CHECK(name.find(".pride-merge-") == std::string::npos);
    // One file named twice, by its name or through a link, would count its runs twice.
    refused(run_pride("merge " + q(a) + " " + q(a) + " --out " + q(dir.file("x.sqlite"))), a + ": named twice");
    fs::create_symlink(a, dir.file("link.sqlite"));
    refused(run_pride("merge " + q(a) + " " + q(dir.file("link.sqlite")) + " --out " + q(dir.file("x.sqlite"))),
            dir.file("link.sqlite") + ": the same file as " + a);
    CHECK(!fs::exists(dir.file("x.sqlite")));
}

TEST_CASE("hostile: a FIFO or folder where SQLite keeps a store's journal is refused, never waited on",
          "[hostile][store]") {
    const TempDir dir("pride-hostile-journal");
    const std::string store = small_store(dir, "st.sqlite");
    const std::string other = small_store(dir, "other.sqlite");
    const std::string campaign = dir.file("st.sqlite.toml");
    for (const char* suffix : {"-journal", "-wal", "-shm"}) {
        INFO(suffix);
        const std::string side = store + suffix;
        REQUIRE(::mkfifo(side.c_str(), 0600) == 0);
        const std::string words = side + ": not a regular file (a FIFO)";
        refused(run_pride("report " + q(store)), words);
        refused(run_pride("report " + q(store) + " --html " + q(dir.file("html"))), words);
        refused(run_pride("export " + q(store) + " --ioh " + q(dir.file("ioh"))), words);
        refused(run_pride("bench " + q(campaign) + " --out " + q(store)), words);
        refused(run_pride("merge " + q(other) + " " + q(store) + " --out " + q(dir.file("m.sqlite"))), words);
        fs::remove(side);
        fs::create_directory(side);
        refused(run_pride("report " + q(store)), side + ": not a regular file (a folder)");
        fs::remove(side);
    }
    // A new store too: the writer checks before SQLite makes the file.
    const std::string fresh = dir.file("new.sqlite");
    REQUIRE(::mkfifo((fresh + "-journal").c_str(), 0600) == 0);
    refused(run_pride("bench " + q(campaign) + " --out " + q(fresh)), fresh + "-journal: not a regular file (a FIFO)");
    CHECK(!fs::exists(fresh));
    CHECK(!fs::exists(dir.file("m.sqlite")));
    CHECK(run_pride("report " + q(store)).status == 0);
    // A FIFO in the store's own place is named as one (before: "no such store").
    const std::string fifo = dir.file("fifo.sqlite");
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    const std::string is_fifo = fifo + ": not a regular file (a FIFO): a store is an SQLite file";
    refused(run_pride("report " + q(fifo)), is_fifo);
    refused(run_pride("report " + q(fifo) + " --html " + q(dir.file("html"))), is_fifo);
    refused(run_pride("export " + q(fifo) + " --ioh " + q(dir.file("ioh"))), is_fifo);
    refused(run_pride("merge " + q(other) + " " + q(fifo) + " --out " + q(dir.file("m.sqlite"))), is_fifo);
    refused(run_pride("report " + q(dir.file("absent.sqlite"))), "absent.sqlite: no such store");
    CHECK(!fs::exists(dir.file("html")));
    CHECK(!fs::exists(dir.file("ioh")));
}

TEST_CASE("hostile: standard input named inside a file is refused, never read", "[hostile][readers]") {
    const TempDir dir("pride-hostile-stdin");
    const std::string words =
        "/dev/stdin: standard input is read only when named on the command line, not inside a file";
    const std::string map = dir.write("m.map", "type octile\nheight 2\nwidth 2\nmap\n..\n..\n");
    // A campaign's map.
    const std::string campaign =
        dir.write("c.toml",
                  "name = \"c\"\nseeds = 1\n[budget]\nevaluations = 50\n[[problem]]\nid = \"g\"\ntype = \"grid\"\n"
                  "map = \"/dev/stdin\"\nstart = [0, 0]\ngoal = [1, 1]\n[[algorithm]]\nid = \"a\"\ntype = \"astar\"\n");
    refused(run_pride("bench " + q(campaign) + " --out " + q(dir.file("c.sqlite")), pride::test::slurp(map)), words);
    CHECK(!fs::exists(dir.file("c.sqlite")));
    // A scenario line's map.
    const std::string scen = dir.write("s.scen", "version 1\n0 /dev/stdin 2 2 0 0 1 1 1.41421356\n");
    refused(run_pride("scen " + q(scen), pride::test::slurp(map)), words);
    // A map_server YAML's image.
    const std::string yaml =
        dir.write("m.yaml",
                  "image: /dev/stdin\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.65\n"
                  "free_thresh: 0.196\n");
    refused(run_pride("path --map " + q(yaml) + " --start 0,0 --goal 1,1 --algo astar", pride::test::slurp(map)),
            words);
    // A FIFO there is refused as before; the user's own /dev/stdin still reads.
    REQUIRE(::mkfifo(dir.file("fifo.pgm").c_str(), 0600) == 0);
    dir.write("f.yaml", "image: fifo.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n");
    refused(
        run_pride("path --map " + q(dir.file("f.yaml")) + " --start 0,0 --goal 1,1 --algo astar"),
        "fifo.pgm: not a regular file (a FIFO): map image files named inside a file are read from regular files only");
    const auto own = run_pride("path --map /dev/stdin --start 0,0 --goal 1,1 --algo astar", pride::test::slurp(map));
    INFO(own.err);
    CHECK(own.status == 0);
}

TEST_CASE("hostile: instances past COCO's generator are refused, not wrapped", "[hostile][cli]") {
    // Before: instance 2147483648 evaluated as instance 1.
    refused(run_pride("eval --problem bbob-f1 --x 1,2 --instance 2147483648"),
            "bbob-f1: COCO's instances are 1 to 2147483646");
    const auto last = run_pride("eval --problem bbob-f1 --x 1,2 --instance 2147483646");
    const auto first = run_pride("eval --problem bbob-f1 --x 1,2 --instance 1");
    CHECK(last.status == 0);
    CHECK(last.out != first.out);
    refused(run_pride("run --problem bbob-f3 --dim 2 --algo pso --evals 50 --instance 2147483650"),
            "COCO's instances are 1 to 2147483646");
    const TempDir dir("pride-hostile-instance");
    const std::string c =
        dir.write("c.toml",
                  "name = \"c\"\nseeds = 1\n[budget]\nevaluations = 50\n[[problem]]\nid = \"f3\"\ntype = \"bbob-f3\"\n"
                  "dim = 2\ninstance = [3, 2147483650]\n[[algorithm]]\nid = \"p\"\ntype = \"pso\"\n");
    refused(run_pride("bench " + q(c) + " --out " + q(dir.file("c.sqlite"))), "COCO's instances are 1 to 2147483646");
    CHECK(!fs::exists(dir.file("c.sqlite")));
}

TEST_CASE("hostile: a campaign's seeds have the one limit Python's have", "[hostile][campaign]") {
    const TempDir dir("pride-hostile-seeds");
    const std::string c = dir.write("c.toml",
                                    "name = \"c\"\nseeds = 1000001\n[budget]\nevaluations = 50\n"
                                    "[[problem]]\nid = \"s\"\ntype = \"sphere\"\ndim = 2\n"
                                    "[[algorithm]]\nid = \"p\"\ntype = \"pso\"\n");
    refused(run_pride("bench " + q(c) + " --out " + q(dir.file("c.sqlite"))),
            c + ":2: 'seeds' must be in [1, 1000000], got 1000001");
    CHECK(!fs::exists(dir.file("c.sqlite")));
}

TEST_CASE("hostile: a population out of range gets one message with the parameter's own range", "[hostile][cli]") {
    // Before: "--pop: must be an integer in [1, 1e15]" from the flag, "[2, 1e12]" from the parameter,
    // "pop must be an integer, got 9.223372036854776e+18" from a campaign.
    const std::string range = "pso: pop must be an integer in [2, 1000000000000] (population size), got ";
    refused(run_pride("run --problem sphere --dim 2 --algo pso --pop 1"), range + "1");
    refused(run_pride("run --problem sphere --dim 2 --algo pso --pop 9223372036854775807"), range);
    refused(run_pride("run --problem sphere --dim 2 --algo pso --pop 1e3"), range + "'1e3'");
    refused(run_pride("run --problem sphere --dim 2 --algo pso --param pop=2.5"), range + "2.5");
    const TempDir dir("pride-hostile-pop");
    std::string rows;
    for (int i = 0; i < 10; ++i) rows += "..........\n";
    const std::string map = dir.write("m.map", "type octile\nheight 10\nwidth 10\nmap\n" + rows);
    refused(run_pride("path --map " + q(map) + " --start 0,0 --goal 9,9 --algo pso --pop 1"), range + "1");
    const std::string c = dir.write("c.toml",
                                    "name = \"c\"\nseeds = 1\n[budget]\nevaluations = 50\n"
                                    "[[problem]]\nid = \"s\"\ntype = \"sphere\"\ndim = 2\n"
                                    "[[algorithm]]\nid = \"p\"\ntype = \"pso\"\npop = 9223372036854775807\n");
    refused(run_pride("bench " + q(c) + " --out " + q(dir.file("c.sqlite"))), range + "9223372036854775808");
}

TEST_CASE("hostile: whole-map planners refuse settings they do not use", "[hostile][grid]") {
    const TempDir dir("pride-hostile-planners");
    std::string rows;
    for (int i = 0; i < 10; ++i) rows += "..........\n";
    const std::string map = dir.write("m.map", "type octile\nheight 10\nwidth 10\nmap\n" + rows);
    const std::string base = "path --map " + q(map) + " --start 0,0 --goal 9,9 --algo ";
    for (const char* algo : {"astar", "exact", "jps", "theta-star", "lazy-theta-star", "any-angle-exact"}) {
        INFO(algo);
        const std::string objective =
            std::string(algo).find("theta") != std::string::npos || std::string(algo) == "any-angle-exact"
                ? " --objective length"
                : "";
        const std::string run = base + algo + objective;
        const std::string says = std::string(": ") + algo + " plans on the whole map";
        refused(run_pride(run + " --encoding free"), "--encoding" + says);
        refused(run_pride(run + " --init walk"), "--init" + says);
        refused(run_pride(run + " --connector penalty"), "--connector" + says);
        refused(run_pride(run + " --threads 2"), "--threads" + says);
        refused(run_pride(run + " --evals 1"), "--evals" + says);
        refused(run_pride(run + " --iters 5"), "--iters" + says);
        CHECK(run_pride(run).status == 0);
        // start = goal: the one-cell path, with its metrics, for every planner.
        const auto same =
            run_pride("path --map " + q(map) + " --start 4,4 --goal 4,4 --json --algo " + algo + objective);
        INFO(same.err);
        CHECK(same.status == 0);
        CHECK_THAT(same.out, Catch::Contains("\"feasible\": true"));
        CHECK_THAT(same.out, Catch::Contains("\"path\": [[4,4]]"));
        CHECK_THAT(same.out, !Catch::Contains("\"metrics\": null"));
    }
}

TEST_CASE("hostile: world coordinates of a fine frame stay distinct", "[hostile][grid]") {
    // Before: resolution 1e-10 printed every cell's world point as [0, 0].
    const TempDir dir("pride-hostile-world");
    dir.write("m.pgm", "P5\n4 4\n255\n" + std::string(16, '\xfe'));
    const std::string yaml = dir.write("m.yaml", "image: m.pgm\nresolution: 1e-10\norigin: [0, 0, 0]\n");
    const auto r = run_pride("path --map " + q(yaml) + " --start 0,0 --goal 3,0 --algo astar --json");
    INFO(r.err);
    REQUIRE(r.status == 0);
    CHECK_THAT(r.out, Catch::Contains("\"path_world\": [[5e-11, 3.5e-10], [1.5e-10, 3.5e-10], [2.5e-10, 3.5e-10], "
                                      "[3.5e-10, 3.5e-10]]"));
    // The usual frames print as before: -10 + 0.5 * 0.05 is -9.975.
    dir.write("n.yaml", "image: m.pgm\nresolution: 0.05\norigin: [-10, -10, 0]\n");
    const auto usual = run_pride("path --map " + q(dir.file("n.yaml")) + " --start 0,3 --goal 1,3 --algo astar --json");
    CHECK_THAT(usual.out, Catch::Contains("\"path_world\": [[-9.975, -9.975], [-9.925, -9.975]]"));
}

TEST_CASE("hostile: planted links to one file in an output folder are two files, each replaced", "[hostile][outputs]") {
    const TempDir dir("pride-hostile-links");
    const std::string store = small_store(dir, "s.sqlite");
    const std::string victim = dir.write("v.txt", "victim\n");
    fs::create_directory(dir.file("h2"));
    fs::create_symlink(victim, dir.file("h2/index.html"));
    const auto r = run_pride("report " + q(store) + " --html " + q(dir.file("h2")));
    INFO(r.err);
    CHECK(r.status == 0);
    CHECK(pride::test::slurp(victim) == "victim\n");
    CHECK(!fs::is_symlink(dir.file("h2/index.html")));
    // Links to one file planted for the page and every figure: before, "named twice in one output".
    int figures = 0;
    for (const auto& e : fs::directory_iterator(dir.file("h2")))
        if (e.path().extension() == ".svg") {
            fs::remove(e.path());
            fs::create_symlink(victim, e.path());
            ++figures;
        }
    CHECK(figures >= 1);
    fs::remove(dir.file("h2/index.html"));
    fs::create_symlink(victim, dir.file("h2/index.html"));
    const auto again = run_pride("report " + q(store) + " --html " + q(dir.file("h2")));
    INFO(again.err);
    CHECK(again.status == 0);
    CHECK(pride::test::slurp(victim) == "victim\n");
    for (const auto& e : fs::directory_iterator(dir.file("h2"))) CHECK(!fs::is_symlink(e.path()));
}

TEST_CASE("hostile: the exact any-angle search is refused past its corners, in one line at once", "[hostile][grid]") {
    // 40,000 isolated obstacles: 160,000 convex corners (the search's time grows with their
    // square: 21.7 s for 170,781 corners, over 60 s for 683,161).
    const TempDir dir("pride-hostile-any-angle");
    std::string rows;
    for (int y = 0; y < 400; ++y) {
        for (int x = 0; x < 400; ++x) rows += x % 2 == 1 && y % 2 == 1 ? '@' : '.';
        rows += '\n';
    }
    const std::string map = dir.write("m.map", "type octile\nheight 400\nwidth 400\nmap\n" + rows);
    const std::string words =
        "m.map: the exact any-angle shortest path is searched among at most 100000 convex obstacle corners";
    const auto start = std::chrono::steady_clock::now();
    refused(run_pride("path --map " + q(map) + " --start 0,0 --goal 398,398 --algo any-angle-exact --objective length"),
            words);
    refused(run_pride("path --map " + q(map) + " --start 0,0 --goal 398,398 --algo astar --gaps"), words);
    CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(20));
    // Under the bound it plans: a quarter of the map.
    std::string small;
    for (int y = 0; y < 200; ++y) small += rows.substr(static_cast<std::size_t>(y) * 401, 200) + '\n';
    const std::string quarter = dir.write("q.map", "type octile\nheight 200\nwidth 200\nmap\n" + small);
    CHECK(
        run_pride("path --map " + q(quarter) + " --start 0,0 --goal 198,198 --algo any-angle-exact --objective length")
            .status == 0);
}

TEST_CASE("hostile: a campaign of planners refuses the settings they do not use, at the entry and key",
          "[hostile][campaign][grid]") {
    // Before: a campaign whose algorithms all plan on the whole map took a problem's encoding,
    // init, connector and waypoints, a budget and threads, and ran ignoring them, exit 0.
    const TempDir dir("pride-hostile-campaign-planners");
    std::string rows;
    for (int i = 0; i < 10; ++i) rows += "..........\n";
    dir.write("m.map", "type octile\nheight 10\nwidth 10\nmap\n" + rows);
    const std::string head = "name = \"c\"\nseeds = 1\n";
    const std::string problem =
        "[[problem]]\nid = \"g\"\ntype = \"grid\"\nmap = \"m.map\"\nstart = [0, 0]\ngoal = [9, 9]\n"
        "objective = \"length\"\n";
    const std::string planners =
        "[[algorithm]]\nid = \"a\"\ntype = \"astar\"\n[[algorithm]]\nid = \"t\"\n"
        "type = \"theta-star\"\n";
    const auto bench = [&](const std::string& text) {
        const std::string store = dir.file("c.sqlite");
        fs::remove(store);
        const auto r = run_pride("bench " + q(dir.write("c.toml", text)) + " --out " + q(store));
        if (r.status != 0) CHECK(!fs::exists(store));
        return r;
    };
    const std::string whole = " (every algorithm of this campaign plans on the whole map)";
    // A problem's settings: at the [[problem]] entry (line 3), naming the key.
    for (const char* setting : {"encoding = \"free\"", "init = \"walk\"", "connector = \"penalty\"", "waypoints = 5"}) {
        INFO(setting);
        const std::string key = std::string(setting).substr(0, std::string(setting).find(' '));
        refused(bench(head + problem + setting + "\n" + planners),
                "c.toml:3: problem 'g': " + key + ": astar plans on the whole map");
    }
    // The budget and threads, at their keys.
    refused(bench(head + "[budget]\nevaluations = 100\n" + problem + planners),
            "c.toml:4: [budget] evaluations: astar plans on the whole map and evaluates no objective");
    refused(bench(head + "[budget]\niterations = 5\n" + problem + planners),
            "c.toml:4: [budget] iterations: astar plans on the whole map in one search, not in iterations; it has no "
            "meaning there: leave it out" +
                whole);
    refused(bench(head + "threads = 2\n" + problem + planners), "c.toml:3: threads: astar plans on the whole map");
    // An [[algorithm]] entry of a planner naming how to plan through an encoding: at the key.
    refused(bench(head + problem + "[[algorithm]]\nid = \"a\"\ntype = \"astar\"\nencoding = \"line\"\n"),
            "c.toml:13:12: encoding: astar plans on the whole map, not through an encoding");
    // Planners alone need no budget, and run.
    auto r = bench(head + problem + planners);
    INFO(r.err);
    CHECK(r.status == 0);
    // Beside an algorithm that plans through an encoding, the problem's settings and the budget are
    // that algorithm's (shared: the planners take them without using them).
    r = bench(head + "[budget]\nevaluations = 60\n" + problem + "encoding = \"free\"\n" + planners +
              "[[algorithm]]\nid = \"p\"\ntype = \"pso\"\npop = 6\n");
    INFO(r.err);
    CHECK(r.status == 0);
}

TEST_CASE("hostile: NSGA-II's sorting in many objectives is bounded before the run", "[hostile][mo]") {
    // Before: pop 40000 in 3 objectives ran 17 s under --wall-ms 1000 (its first sorts come before
    // any time check), and pop 1000000 ended as "internal error: std::bad_alloc", exit 1.
    const auto start = std::chrono::steady_clock::now();
    const std::string words = "pop: NSGA-II sorts its 2N parents and children every generation";
    refused(run_pride("front --algo nsga2 --problem dtlz2 --pop 40000 --no-reference --evals 80000 --wall-ms 1000"),
            words +
                ", comparing every pair in each of the 3 objectives: M (2N)^2 = 1.92e+10 operations for a "
                "population of 40000, more than the 1e+09 done in about a second, before any time limit is "
                "checked (in 3 objectives: pop at most 9128)");
    refused(run_pride("front --algo nsga2 --problem dtlz2 --pop 1000000 --no-reference --evals 2000000"), words);
    refused(run_pride("front --algo nsga2 --problem dtlz2 --objectives 1000 --pop 10000 --no-reference --evals 20000"),
            "(in 1000 objectives: pop at most 500)");
    CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(10));
    // A campaign: at the algorithm, no store.
    const TempDir dir("pride-hostile-nsga2");
    const std::string file = dir.write("mo.toml",
                                       "name = \"mo\"\nseeds = 1\n[budget]\nevaluations = 80000\n[[problem]]\n"
                                       "id = \"d\"\ntype = \"dtlz2\"\n[[algorithm]]\nid = \"n\"\ntype = \"nsga2\"\n"
                                       "pop = 40000\n");
    refused(run_pride("bench " + q(file) + " --out " + q(dir.file("mo.sqlite"))),
            file + ":8: algorithm 'n' on problem 'd': pop: NSGA-II sorts");
    CHECK(!fs::exists(dir.file("mo.sqlite")));
    // At the bound it runs; in two objectives the sort is O(N log N) and no bound applies.
    CHECK(run_pride("front --algo nsga2 --problem dtlz2 --pop 9128 --no-reference --evals 9128").status == 0);
    CHECK(run_pride("front --algo nsga2 --problem zdt1 --pop 40000 --no-reference --evals 40000").status == 0);
}

TEST_CASE("hostile: SMS-EMOA and MOEA/D keep to a time limit with large populations", "[hostile][mo]") {
    // Before: SMS-EMOA read --wall-ms once per generation of pop steps (pop 20000: 13.9 s for
    // 2000 steps under --wall-ms 1000; pop 100000: about an hour a generation), and MOEA/D's
    // neighbourhoods, N^2 distances before the first generation, took 9.8 s for 19900 subproblems
    // under --wall-ms 1000 (minutes for the 100000 its pop allows).
    auto start = std::chrono::steady_clock::now();
    const auto r =
        run_pride("front --algo smsemoa --problem zdt1 --pop 20000 --no-reference --evals 100000000 --wall-ms 300");
    INFO(r.err);
    CHECK(r.status == 0);
    CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(8));
    // Stopped inside its first generation (the initial population is 20000 evaluations).
    CHECK_THAT(r.out, Catch::Contains("iterations   1\n"));
    start = std::chrono::steady_clock::now();
    refused(run_pride("front --algo moead --problem dtlz2 --pop 20000 --no-reference --evals 100000 --wall-ms 1000"),
            "pop: MOEA/D finds the neighbours of each of its 19900 subproblems among all of them before the first "
            "generation and any time limit: N^2 (M + 2) = 1.98e+09 operations in 3 objectives, more than the 2e+08 "
            "done in about a second (at most 6324 subproblems in 3 objectives)");
    refused(run_pride("front --algo moead --problem dtlz2 --param divisions=300 --no-reference --evals 100000"),
            "divisions: MOEA/D finds the neighbours");
    CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(5));
    CHECK(run_pride("front --algo moead --problem dtlz2 --pop 6000 --no-reference --evals 100 --wall-ms 1000").status ==
          0);
}

TEST_CASE("hostile: a PNG that does not parse shows none of its bytes", "[hostile][readers]") {
    // Before: libpng's message led with the chunk it stopped at, four bytes of the file
    // ("bad PNG: ET[20]h: invalid chunk type" for a text after the PNG signature).
    const TempDir dir("pride-hostile-png");
    const std::string png =
        dir.write("g.png", std::string("\x89PNG\r\n\x1a\n", 8) + "SECRET hunter2 SECRET hunter2 SECRET\n");
    const auto r = run_pride("path --map " + q(png) + " --start 0,0 --goal 1,1 --algo astar");
    refused(r, png + ": bad PNG: invalid chunk type");
    const std::string said = r.err.substr(std::min(r.err.size(), r.err.find("g.png")));
    CHECK(said.find("ET") == std::string::npos);
    CHECK(said.find("hunt") == std::string::npos);
}

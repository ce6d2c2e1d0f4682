// `pride report STORE --html DIR`: the page and its SVG figures from a real campaign, checked for
// structure here and opened in Debian's headless Chromium (skipped, saying so, without it).
#include <sqlite3.h>

#include <catch2/catch.hpp>

#include <cstdint>
#include <filesystem>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "experiment/html/draw.hpp"
#include "tests/cli_runner.hpp"
#include "tests/test_support.hpp"

namespace fs = std::filesystem;
using pride::test::run_pride;
using pride::test::slurp;
using pride::test::TempDir;

namespace {

std::string quote(const std::string& s) {
    return "'" + s + "'";
}

/// A campaign of two BBOB problems (precisions, ERT and ECDF) and one grid map (paths, Pareto
/// front), two algorithms, three seeds; its store in `dir`.
std::string small_campaign(const fs::path& dir) {
    const fs::path map = fs::path(PRIDE_SOURCE_DIR) / "examples" / "maps" / "zhang2025-20x20.map";
    const std::string config = (dir / "c.toml").string();
    std::ofstream(config) << "name = \"html-test\"\nseeds = 3\n[budget]\nevaluations = 600\n"
                             "[[suite]]\nname = \"bbob\"\nfunctions = [1]\ninstances = [1, 2]\ndimensions = [2]\n"
                             "[[problem]]\nid = \"map\"\ntype = \"grid\"\nmap = \""
                          << map.string()
                          << "\"\nstart = [0, 19]\ngoal = [19, 0]\nobjective = \"length\"\n"
                             "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\n"
                             "[[algorithm]]\nid = \"ga\"\ntype = \"ga\"\n";
    const std::string store = (dir / "c.sqlite").string();
    const auto bench = run_pride("bench " + quote(config) + " --jobs 2 --out " + quote(store));
    INFO(bench.out << bench.err);
    REQUIRE(bench.status == 0);
    return store;
}

/// The src of every <img> of a page.
std::vector<std::string> images_of(const std::string& html) {
    std::vector<std::string> out;
    static const std::regex img(R"re(<img src="([^"]+)")re");
    for (auto it = std::sregex_iterator(html.begin(), html.end(), img); it != std::sregex_iterator(); ++it)
        out.push_back((*it)[1]);
    return out;
}

/// Parsed as XML by Python's standard library, with an <svg> root.
bool valid_svg(const fs::path& file) {
    const std::string text = slurp(file);
    if (text.rfind("<?xml", 0) != 0 || text.find("<svg") == std::string::npos) return false;
    const std::string check =
        "/usr/bin/python3 -c 'import sys, xml.etree.ElementTree as E; "
        "sys.exit(E.parse(sys.argv[1]).getroot().tag != \"{http://www.w3.org/2000/svg}svg\")' " +
        quote(file.string());
    return std::system(check.c_str()) == 0;
}

void exec(const std::string& store, const std::string& sql) {
    sqlite3* db = nullptr;
    REQUIRE(sqlite3_open(store.c_str(), &db) == SQLITE_OK);
    char* message = nullptr;
    const int rc = sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &message);
    INFO(sql << ": " << (message ? message : ""));
    sqlite3_free(message);
    sqlite3_close(db);
    REQUIRE(rc == SQLITE_OK);
}

/// A copy of `store` changed by `sql`.
std::string tampered(const TempDir& dir, const std::string& store, const std::string& name, const std::string& sql) {
    const std::string copy = dir.file(name + ".sqlite");
    fs::copy_file(store, copy, fs::copy_options::overwrite_existing);
    exec(copy, sql);
    return copy;
}

/// Nothing left of a report's staging folder beside or inside `dir`.
bool no_staging(const fs::path& dir) {
    for (const fs::path& folder : {dir.parent_path(), dir})
        if (fs::is_directory(folder))
            for (const auto& e : fs::directory_iterator(folder))
                if (e.path().filename().string().find(".pride-") != std::string::npos) return false;
    return true;
}

}  // namespace

TEST_CASE("report --html: one page with provenance, the report's rows, statistics and every figure", "[report][html]") {
    const TempDir dir("pride-html");
    const std::string store = small_campaign(dir.path());
    const fs::path out = dir.path() / "page";
    const auto r = run_pride("report " + quote(store) + " --html " + quote(out.string()));
    INFO(r.err);
    REQUIRE(r.status == 0);
    const std::string html = slurp(out / "index.html");
    const auto images = images_of(html);
    CHECK(r.out ==
          (out / "index.html").string() + ": the report, with " + std::to_string(images.size()) + " figures\n");

    // Every figure referenced is there and is SVG; every SVG there is referenced.
    const std::set<std::string> referenced(images.begin(), images.end());
    CHECK(referenced.size() == images.size());
    std::set<std::string> written;
    for (const auto& e : fs::directory_iterator(out))
        if (e.path().filename() != "index.html") written.insert(e.path().filename().string());
    CHECK(written == referenced);
    for (const auto& name : images) {
        INFO(name);
        CHECK(valid_svg(out / name));
    }
    for (const char* name :
         {"convergence-bbob-f1-i1-d2.svg", "final-bbob-f1-i2-d2.svg", "convergence-map.svg", "final-map.svg",
          "paths-map.svg", "pareto-map.svg", "ecdf-all.svg", "ecdf-separable.svg"}) {
        INFO(name);
        CHECK(referenced.count(name) == 1);
    }
    CHECK(referenced.count("paths-bbob-f1-i1-d2.svg") == 0);  // paths only on grids

    // Provenance, the campaign's own text, the tests named.
    for (const char* words :
         {"<th>pride</th><td>", "<th>git commit</th><td>", "<th>compiler</th><td>", "<th>machine</th><td>",
          "<th>report made</th><td>", " UTC</td>", "name = &quot;html-test&quot;", "Wilcoxon rank-sum test", "Holm",
          "Vargha-Delaney A12", "Friedman test", "Expected running time", "exact optimum"}) {
        INFO(words);
        CHECK(html.find(words) != std::string::npos);
    }
    const std::string svg_paths = slurp(out / "paths-map.svg");
    CHECK(svg_paths.find("<svg") != std::string::npos);
    // The rows of the markdown report, each as a row of the page's table.
    const auto md = run_pride("report " + quote(store));
    REQUIRE(md.status == 0);
    std::size_t rows = 0;
    for (const auto& line : pride::test::lines_of(md.out)) {
        if (line.rfind("## ", 0) == 0) break;  // the ERT tables follow
        static const std::regex row(R"(^\| (\S+) \| (\S+) \| (\d+) \|)");
        std::smatch m;
        if (!std::regex_search(line, m, row) || m[1] == "problem") continue;
        INFO(line);
        CHECK(html.find("<td>" + m[1].str() + "</td><td>" + m[2].str() + "</td><td class=\"n\">" + m[3].str() +
                        "</td>") != std::string::npos);
        ++rows;
    }
    CHECK(rows == 6);
    // Self-contained: nothing fetched, no staging left.
    CHECK(html.find("http") == std::string::npos);
    CHECK(html.find("<link") == std::string::npos);
    CHECK(no_staging(out));

    // Again into the same folder: replaced, and a file of the user's kept.
    std::ofstream(out / "mine.txt") << "mine";
    const auto again = run_pride("report " + quote(store) + " --html " + quote(out.string() + "/") + " --raw");
    REQUIRE(again.status == 0);
    CHECK(slurp(out / "mine.txt") == "mine");
    CHECK(slurp(out / "index.html").find("f as run (--raw)") != std::string::npos);
    CHECK(no_staging(out));
}

TEST_CASE("report --html: the page in headless Chromium loads every figure with no console error",
          "[report][html][browser]") {
    const char* chromium = "/usr/bin/chromium";
    if (!fs::exists(chromium)) {
        WARN("skipped: /usr/bin/chromium is absent (scripts/deps.sh installs Debian's chromium)");
        return;
    }
    const TempDir dir("pride-html-browser");
    const std::string store = small_campaign(dir.path());
    // Kept in the build folder, with the screenshot, for a person to look at.
    const fs::path kept = fs::path(PRIDE_BUILD_DIR) / "report-html";
    fs::remove_all(kept);
    const auto r = run_pride("report " + quote(store) + " --html " + quote(kept.string()));
    REQUIRE(r.status == 0);
    const std::size_t figures = images_of(slurp(kept / "index.html")).size();
    // ?check: every figure loaded at once (they are lazy otherwise) and the tables measured.
    const std::string url = "file://" + (kept / "index.html").string() + "?check";
    const std::string browser = std::string("timeout 120 ") + chromium +
                                " --headless --no-sandbox --disable-gpu --user-data-dir=" + quote(dir.file("profile")) +
                                " --enable-logging=stderr --v=0 ";
    const int dumped = std::system((browser + "--window-size=1400,1000 --dump-dom " + quote(url) + " >" +
                                    quote(dir.file("dom")) + " 2>" + quote(dir.file("log")))
                                       .c_str());
    REQUIRE(dumped == 0);
    const std::string dom = slurp(dir.file("dom")), log = slurp(dir.file("log"));
    INFO(log);
    // The page's script writes whether every <img> loaded with a width into <body>.
    CHECK(dom.find("data-figures=\"loaded " + std::to_string(figures) + "\"") != std::string::npos);
    // Every table fits a 1400-pixel window (none scrolls or reaches past the page).
    CHECK(dom.find("data-overflow=\"none\"") != std::string::npos);
    // Figures load lazily when the page is only read.
    CHECK(images_of(slurp(kept / "index.html")).size() == figures);
    CHECK(slurp(kept / "index.html").find("loading=\"lazy\"") != std::string::npos);
    CHECK(log.find(":CONSOLE") == std::string::npos);  // console messages, script errors included
    const fs::path shot = kept / "screenshot.png";
    const int shown = std::system((browser + "--hide-scrollbars --screenshot=" + quote(shot.string()) +
                                   " --window-size=1280,4000 " + quote(url) + " >/dev/null 2>&1")
                                      .c_str());
    REQUIRE(shown == 0);
    const std::string png = slurp(shot);
    CHECK(png.rfind("\x89PNG", 0) == 0);
    CHECK(png.size() > 50000);  // a page, not a blank window
}

TEST_CASE("report --html: bad folders, options and stores are one line, exit 2, and write no page", "[report][html]") {
    const TempDir dir("pride-html-errors");
    const std::string store = small_campaign(dir.path());
    const std::string file = dir.write("a-file", "text");
    const auto no_page = [&](const std::string& args, const std::vector<std::string>& words) {
        INFO("pride report " << args);
        pride::test::check_input_error(run_pride("report " + args), words);
        CHECK(no_staging(dir.file("x")));
    };
    no_page(quote(store) + " --html " + quote(file), {"--html", "a-file", "is not a folder"});
    CHECK(slurp(file) == "text");
    no_page(quote(store) + " --html " + quote(file + "/sub"), {"--html", "cannot create the folder"});
    no_page(quote(store) + " --html /proc/self", {"--html", "/proc/self", "cannot write into the folder"});
    no_page(quote(store) + " --html " + quote(dir.file("x")) + " --format csv", {"--format", "--html"});
    no_page(quote(store) + " " + quote(store) + " --html " + quote(dir.file("x")), {"--html", "one store"});
    no_page(quote(store) + " --html " + quote(dir.file("x")) + " --plots " + quote(dir.file("p")),
            {"--plots", "--html"});
    no_page(quote(dir.file("missing.sqlite")) + " --html " + quote(dir.file("x")), {"missing.sqlite"});
    // Damaged where only the page reads: a path that is not a list of cells, a start that is no cell.
    const std::string bad_path = tampered(dir, store, "bad-path",
                                          "UPDATE runs SET solution = '[[1, 2], \"x\"]' WHERE problem = 'map' AND "
                                          "algorithm = 'ga'");
    no_page(quote(bad_path) + " --html " + quote(dir.file("x")),
            {"damaged store", "algorithm 'ga'", "column solution"});
    const std::string not_json =
        tampered(dir, store, "not-json", "UPDATE runs SET solution = '[[1, 2' WHERE problem = 'map'");
    no_page(quote(not_json) + " --html " + quote(dir.file("x")), {"damaged store", "column solution"});
    const std::string bad_start =
        tampered(dir, store, "bad-start", "UPDATE problems SET start = 'a,b' WHERE id = 'map'");
    no_page(quote(bad_start) + " --html " + quote(dir.file("x")), {"damaged store", "problems row 'map'", "start"});
    CHECK(!fs::exists(dir.file("x")));
    CHECK(!fs::exists(dir.file("p")));

    // A figure that cannot be moved into place (a folder holds its name): named, index.html not
    // written, the staging folder gone.
    const fs::path existing = dir.path() / "existing";
    fs::create_directories(existing / "paths-map.svg" / "inside");
    no_page(quote(store) + " --html " + quote(existing.string()), {"--html", "paths-map.svg", "cannot write"});
    CHECK(!fs::exists(existing / "index.html"));
    CHECK(no_staging(existing));
}

TEST_CASE("report --html: a map that is gone, or a store from before maps were stored, leaves the paths out",
          "[report][html]") {
    const TempDir dir("pride-html-nomap");
    const std::string store = small_campaign(dir.path());
    const std::string moved = tampered(dir, store, "moved", "UPDATE problems SET map = '/nonexistent/m.map'");
    const auto r = run_pride("report " + quote(moved) + " --html " + quote(dir.file("page")));
    INFO(r.err);
    REQUIRE(r.status == 0);
    const std::string html = slurp(dir.path() / "page" / "index.html");
    CHECK(html.find("No picture of the paths: /nonexistent/m.map") != std::string::npos);
    CHECK(html.find("paths-map.svg") == std::string::npos);
    CHECK(fs::exists(dir.path() / "page" / "convergence-map.svg"));

    // A store from before the problems table: reported, without precisions or pictures of maps.
    const std::string old = tampered(dir, store, "old", "DROP TABLE problems");
    const auto o = run_pride("report " + quote(old) + " --html " + quote(dir.file("old-page")));
    INFO(o.err);
    REQUIRE(o.status == 0);
    CHECK(fs::exists(dir.path() / "old-page" / "convergence-map.svg"));
    CHECK(!fs::exists(dir.path() / "old-page" / "paths-map.svg"));
}

TEST_CASE("report --html: whole-map planners as lines, x in iterations when runs record no evaluations",
          "[report][html]") {
    const TempDir dir("pride-html-grid");
    const fs::path map = fs::path(PRIDE_SOURCE_DIR) / "examples" / "maps" / "wan2022-10x10.map";
    const std::string config = dir.write("g.toml",
                                         "name = \"g\"\nseeds = 3\n[budget]\niterations = 8\n"
                                         "[[problem]]\nid = \"m\"\ntype = \"grid\"\nmap = \"" +
                                             map.string() +
                                             "\"\nstart = [0, 0]\ngoal = [9, 9]\n"
                                             "[[algorithm]]\nid = \"ga\"\ntype = \"ga\"\npop = 10\n"
                                             "[[algorithm]]\nid = \"astar\"\ntype = \"astar\"\n");
    const std::string store = dir.file("g.sqlite");
    REQUIRE(run_pride("bench " + quote(config) + " --out " + quote(store)).status == 0);
    // A store whose runs recorded no evaluations per iteration (as older ones).
    exec(store, "UPDATE runs SET history_evaluations = '[]'");
    const auto r = run_pride("report " + quote(store) + " --html " + quote(dir.file("page")));
    INFO(r.err);
    REQUIRE(r.status == 0);
    const std::string html = slurp(dir.path() / "page" / "index.html");
    CHECK(html.find("after each iteration") != std::string::npos);
    CHECK(html.find("No Friedman test") != std::string::npos);
    CHECK(valid_svg(dir.path() / "page" / "convergence-m.svg"));
    CHECK(valid_svg(dir.path() / "page" / "paths-m.svg"));
}

TEST_CASE("report --html: the paths figure of a large map shows the paths' region, and says so", "[report][html]") {
    const TempDir dir("pride-html-crop");
    // 200 x 120 cells, free but for a wall; start and goal near the top-left corner.
    std::string rows = "type octile\nheight 120\nwidth 200\nmap\n";
    for (int y = 0; y < 120; ++y) {
        for (int x = 0; x < 200; ++x) rows += (x == 20 && y < 25) ? '@' : '.';
        rows += '\n';
    }
    const std::string map = dir.write("big.map", rows);
    const std::string config = dir.write("c.toml",
                                         "name = \"crop\"\nseeds = 1\n"
                                         "[[problem]]\nid = \"big\"\ntype = \"grid\"\nmap = \"" +
                                             map +
                                             "\"\nstart = [5, 5]\ngoal = [35, 10]\nobjective = \"length\"\n"
                                             "[[algorithm]]\nid = \"astar\"\ntype = \"astar\"\n"
                                             "[[algorithm]]\nid = \"theta\"\ntype = \"theta-star\"\n");
    const std::string store = dir.file("c.sqlite");
    REQUIRE(run_pride("bench " + quote(config) + " --out " + quote(store)).status == 0);
    const auto r = run_pride("report " + quote(store) + " --html " + quote(dir.file("page")));
    INFO(r.err);
    REQUIRE(r.status == 0);
    const std::string html = slurp(dir.path() / "page" / "index.html");
    static const std::regex said(
        R"(Cropped to the paths' region: columns (\d+)-(\d+) and rows (\d+)-(\d+) of the 200 x 120 map\.)");
    std::smatch m;
    REQUIRE(std::regex_search(html, m, said));
    // The region holds start (5, 5) and goal (35, 10) with a margin of at least 5 cells, and is a
    // small part of the map.
    CHECK(std::stoi(m[1]) == 0);
    CHECK(std::stoi(m[2]) >= 40);
    CHECK(std::stoi(m[2]) < 120);
    CHECK(std::stoi(m[3]) == 0);
    CHECK(std::stoi(m[4]) >= 15);
    CHECK(std::stoi(m[4]) < 84);
    CHECK(valid_svg(dir.path() / "page" / "paths-big.svg"));
}

TEST_CASE("paths_window: the region around start, goal and the paths, or the whole map when that is most of it",
          "[report][html]") {
    using pride::grid::Cell;
    using pride::grid::GridMap;
    using pride::grid::Polyline;
    const GridMap map(100, 50, std::vector<std::uint8_t>(5000, 0));
    // Start and goal only: their box (10..30 x 5..8), 5 cells of margin (a tenth of 20 is less).
    auto w = pride::html::paths_window(map, Cell{10, 5}, Cell{30, 8}, {});
    CHECK((w.x0 == 5 && w.x1 == 36 && w.y0 == 0 && w.y1 == 14));
    CHECK_FALSE(w.whole(map));
    // A path's vertex far out widens it; the margin is a tenth of the larger side.
    w = pride::html::paths_window(map, Cell{10, 5}, Cell{30, 8}, {Polyline{{10, 5}, {60, 20}, {30, 8}}});
    CHECK((w.x0 == 5 && w.x1 == 66 && w.y0 == 0 && w.y1 == 26));
    // Covering 70 % or more of both sides: the whole map.
    w = pride::html::paths_window(map, Cell{2, 2}, Cell{90, 40}, {});
    CHECK(w.whole(map));
    CHECK(pride::html::window_words(map, w).empty());
}

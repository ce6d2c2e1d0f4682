// Published runs in a store (`pride import STORE --coco FOLDER`, experiment/report/coco_import.hpp):
// pride's own COCO export read back equals the runs it came from, beside them in one store; the
// campaign never runs them again and grows around them; merges and reports treat them by their
// protocol; bad input is one line naming file and line, exit 2, with nothing written.
#include <sqlite3.h>

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "experiment/report/coco.hpp"
#include "experiment/report/report.hpp"
#include "experiment/storage/reader.hpp"
#include "tests/cli_runner.hpp"
#include "tests/sqlite_support.hpp"
#include "tests/test_support.hpp"

namespace fs = std::filesystem;
using pride::test::expect_input_error;
using pride::test::run_pride;
using pride::test::slurp;

namespace {

constexpr const char* kCampaign =
    "name = \"published\"\nseeds = 2\n[budget]\nevaluations_per_dim = 300\n"
    "[[suite]]\nname = \"bbob\"\nfunctions = [1, 15]\ninstances = [1, 2]\ndimensions = [2, 3]\n"
    "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\npop = 10\n"
    "[[algorithm]]\nid = \"ga\"\ntype = \"ga\"\npop = 10\n";

std::string scalar(const std::string& store, const std::string& sql) {
    sqlite3* db = nullptr;
    REQUIRE(sqlite3_open_v2(store.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK);
    sqlite3_stmt* s = nullptr;
    REQUIRE(sqlite3_prepare_v2(db, sql.c_str(), -1, &s, nullptr) == SQLITE_OK);
    std::string out;
    if (sqlite3_step(s) == SQLITE_ROW && sqlite3_column_text(s, 0))
        out = reinterpret_cast<const char*>(sqlite3_column_text(s, 0));
    sqlite3_finalize(s);
    sqlite3_close(db);
    return out;
}

/// A campaign's store and its runs exported as COCO data (DIR/coco/pso, DIR/coco/ga).
struct Exported {
    pride::test::TempDir tmp{"pride-import"};
    std::string store = tmp.file("c.sqlite"), toml = tmp.file("c.toml");
    fs::path coco = tmp.path() / "coco";
    Exported() {
        std::ofstream(toml) << kCampaign;
        REQUIRE(run_pride("bench '" + toml + "' --jobs 2 --out '" + store + "'").status == 0);
        REQUIRE(run_pride("export '" + store + "' --coco '" + coco.string() + "'").status == 0);
    }
    std::string import(const std::string& into, const std::string& folder, const std::string& name) const {
        return "import '" + into + "' --coco '" + folder + "' --name " + name + " --citation 'pride (2026), test'";
    }
};

/// The runs of `algorithm` in `store` by (problem, seed).
std::map<std::pair<std::string, std::int64_t>, pride::storage::StoredRun> runs_of(
    const pride::storage::CampaignStore& s, const std::string& algorithm) {
    std::map<std::pair<std::string, std::int64_t>, pride::storage::StoredRun> out;
    for (const auto& r : s.runs)
        if (r.algorithm == algorithm) out.emplace(std::pair{r.problem, r.seed}, r);
    return out;
}

}  // namespace

TEST_CASE("import --coco: pride's own export read back equals the runs it came from", "[import][coco]") {
    const Exported e;
    const auto r = run_pride(e.import(e.store, (e.coco / "pso").string(), "pso-2026"));
    INFO(r.out << r.err);
    REQUIRE(r.status == 0);
    // 2 functions x 2 dimensions x 2 instances x 2 seeds, on the campaign's own 8 problems.
    CHECK(r.out == "16 runs of published:pso-2026 imported into " + e.store + " (8 problems of the store, 0 added)\n");
    const auto s = pride::storage::read_store(e.store);
    REQUIRE(s.published.count("published:pso-2026"));
    const auto& source = s.published.at("published:pso-2026");
    CHECK(source.source == "pso");
    CHECK(source.citation == "pride (2026), test");
    CHECK(source.format == "coco-bbob");
    CHECK(source.sha256.size() == 64);
    const auto own = runs_of(s, "pso"), published = runs_of(s, "published:pso-2026");
    REQUIRE(published.size() == 16);
    for (const auto& [key, p] : published) {
        INFO(key.first << " trial " << key.second);
        // The export writes a function's runs by instance, then seed: trial k of an instance is seed k.
        REQUIRE(own.count(key));
        const auto& o = own.at(key);
        CHECK(p.evaluations == o.evaluations);
        CHECK(p.target_hits == o.target_hits);
        CHECK(*p.best == Approx(*o.best).epsilon(1e-9));  // printed with 10 digits
        CHECK(p.trace_targets.size() >= o.trace_targets.size());
        CHECK(p.history.empty());
    }
    // The same target hits give the same ERT, cell by cell.
    const auto analysis = pride::report::coco::analyse(s);
    REQUIRE(analysis);
    std::map<std::pair<std::string, std::int64_t>, std::vector<pride::report::coco::Ert>> ert;
    for (const auto& row : analysis->erts)
        if (row.algorithm == "pso") ert[{row.function, row.dim}] = row.ert;
    std::size_t compared = 0;
    for (const auto& row : analysis->erts)
        if (row.algorithm == "published:pso-2026") {
            const auto& mine = ert.at({row.function, row.dim});
            for (std::size_t k = 0; k < mine.size(); ++k) {
                CHECK(row.ert[k].value == mine[k].value);
                CHECK(row.ert[k].successes == mine[k].successes);
            }
            ++compared;
        }
    CHECK(compared == 4);

    // The same budget: in the comparison of final values, named with its provenance.
    const auto md = run_pride("report '" + e.store + "'");
    REQUIRE(md.status == 0);
    CHECK_THAT(md.out, Catch::Contains("| published:pso-2026 |"));
    CHECK_THAT(md.out, Catch::Contains("published:pso-2026 holds published runs: pride (2026), test, read from pso "
                                       "(coco-bbob data, SHA-256 " +
                                       source.sha256 + "); imported, never run by pride."));
    CHECK_THAT(md.out, !Catch::Contains("is left out"));
}

TEST_CASE("import: the campaign never runs published runs, grows around them, merges keep them", "[import][coco]") {
    const Exported e;
    const std::string before = e.tmp.file("before.sqlite");
    fs::copy_file(e.store, before);
    REQUIRE(run_pride(e.import(e.store, (e.coco / "ga").string(), "ga-2026")).status == 0);
    const std::string count = "SELECT COUNT(*) FROM runs";
    CHECK(scalar(e.store, count) == "48");  // 32 of the campaign, 16 published
    // Resumed: nothing missing, nothing run, the published rows as they were.
    const auto resumed = run_pride("bench '" + e.toml + "' --out '" + e.store + "'");
    INFO(resumed.out << resumed.err);
    REQUIRE(resumed.status == 0);
    CHECK_THAT(resumed.out, Catch::Contains("0 runs stored in " + e.store + " (32 were there already, 32 in all)"));
    CHECK(scalar(e.store, count) == "48");
    // Grown by a seed: the campaign's new runs only.
    std::ofstream(e.toml) << std::string(kCampaign).replace(std::string(kCampaign).find("seeds = 2"), 9, "seeds = 3");
    REQUIRE(run_pride("bench '" + e.toml + "' --jobs 2 --out '" + e.store + "'").status == 0);
    CHECK(scalar(e.store, count) == "64");
    CHECK(scalar(e.store, "SELECT COUNT(*) FROM runs WHERE algorithm = 'published:ga-2026'") == "16");

    // A store with the same published runs merges; one where the name holds other data does not.
    const std::string same = e.tmp.file("same.sqlite"), other = e.tmp.file("other.sqlite");
    fs::copy_file(before, same);
    REQUIRE(run_pride(e.import(same, (e.coco / "ga").string(), "ga-2026")).status == 0);
    fs::copy_file(before, other);
    REQUIRE(run_pride(e.import(other, (e.coco / "pso").string(), "ga-2026")).status == 0);
    const std::string merged = e.tmp.file("m.sqlite");
    const auto m = run_pride("merge '" + before + "' '" + same + "' --out '" + merged + "'");
    INFO(m.out << m.err);
    REQUIRE(m.status == 0);
    CHECK(pride::storage::read_store(merged).published.count("published:ga-2026") == 1);
    expect_input_error("merge '" + same + "' '" + other + "' --out '" + e.tmp.file("n.sqlite") + "'",
                       {"other.sqlite", "published:ga-2026", "not merged"});
    CHECK(!fs::exists(e.tmp.file("n.sqlite")));
    // A store of published runs alone is no campaign's: a campaign is not run into it.
    const std::string alone = e.tmp.file("alone.sqlite");
    REQUIRE(run_pride(e.import(alone, (e.coco / "ga").string(), "ga-2026")).status == 0);
    CHECK(scalar(alone, "SELECT name FROM campaign") == "published runs");
    expect_input_error("bench '" + e.toml + "' --out '" + alone + "'", {"another campaign ('published runs'"});
    CHECK(scalar(alone, count) == "16");
}

TEST_CASE("report: published runs of another budget are left out of the final values, named", "[import][report]") {
    const Exported e;
    // The pso runs' evaluations, as another budget would have given them.
    const fs::path folder = e.tmp.path() / "longer";
    fs::copy(e.coco / "pso", folder, fs::copy_options::recursive);
    for (const auto& f : fs::recursive_directory_iterator(folder))
        if (f.path().extension() == ".tdat") {
            // After each run's last line, one more at ten times its evaluations.
            std::istringstream in(slurp(f.path()));
            std::string out, line, last;
            const auto longer = [&] {
                if (last.empty()) return;
                const std::size_t space = last.find(' ');
                out += std::to_string(10 * std::stoll(last.substr(0, space))) + last.substr(space) + "\n";
                last.clear();
            };
            while (std::getline(in, line)) {
                if (line.rfind('%', 0) == 0)
                    longer();
                else
                    last = line;
                out += line + "\n";
            }
            longer();
            std::ofstream(f.path()) << out;
        }
    REQUIRE(run_pride(e.import(e.store, folder.string(), "longer")).status == 0);
    const auto s = pride::storage::read_store(e.store);
    const auto report = pride::report::make_report(s);
    for (const auto& row : report.rows) CHECK(row.algorithm != "published:longer");
    std::size_t ert_rows = 0;
    for (const auto& row : report.coco->erts) ert_rows += row.algorithm == "published:longer";
    CHECK(ert_rows == 4);
    const auto md = run_pride("report '" + e.store + "'");
    REQUIRE(md.status == 0);
    CHECK_THAT(md.out, Catch::Contains("published:longer is left out of the comparison of final values on 8 problems "
                                       "(bbob-f1-i1-d2, "));
    CHECK_THAT(md.out, Catch::Contains("other evaluation budgets than the campaign's (on bbob-f1-i1-d2: a mean of 6000 "
                                       "evaluations, the campaign's 600;"));
}

TEST_CASE("import: bad input is one line naming file and line, exit 2, nothing written", "[import][coco]") {
    const Exported e;
    const std::string store = e.tmp.file("s.sqlite");
    const fs::path bad = e.tmp.path() / "bad";
    const auto fresh = [&] {
        fs::remove_all(bad);
        fs::copy(e.coco / "pso", bad, fs::copy_options::recursive);
    };
    const auto edit = [&](const fs::path& file, std::size_t line, const std::string& text) {
        std::string all = slurp(file), out;
        std::size_t n = 0, at = 0;
        for (std::size_t next; (next = all.find('\n', at)) != std::string::npos; at = next + 1)
            out += (++n == line ? text : all.substr(at, next - at)) + "\n";
        std::ofstream(file) << out;
    };
    const auto refused = [&](const std::vector<std::string>& words) {
        expect_input_error(e.import(store, bad.string(), "x"), words);
        CHECK(!fs::exists(store));  // no store left behind
    };
    expect_input_error(e.import(store, (e.tmp.path() / "none").string(), "x"), {"none: no such folder"});
    expect_input_error(e.import(store, e.toml, "x"), {"c.toml: not a folder", "extract a .tgz first"});
    expect_input_error(e.import(store, e.tmp.path().string() + "/coco/pso/data_f1", "x"), {"no .info file"});
    expect_input_error("import '" + store + "' --coco '" + (e.coco / "pso").string() + "' --name x", {"--citation"});
    CHECK(!fs::exists(store));
    // A campaign cannot take the prefix of published runs.
    std::ofstream(e.tmp.file("p.toml")) << "name = \"p\"\nseeds = 1\n[budget]\nevaluations = 20\n"
                                           "[[problem]]\nid = \"s\"\ntype = \"sphere\"\ndim = 2\n"
                                           "[[algorithm]]\nid = \"published:pso\"\ntype = \"pso\"\n";
    expect_input_error("bench '" + e.tmp.file("p.toml") + "' --out '" + store + "'",
                       {"algorithm id 'published:pso'", "kept for published runs"});

    const fs::path info = bad / "bbobexp_f1.info", dat = bad / "data_f1" / "bbobexp_f1_DIM2.dat";
    fresh();
    edit(info, 3, "data_f1/bbobexp_f1_DIM2.dat, 1:600|x");
    refused({info.string() + ":3", "expected a run as 'instance:evaluations|final f - f_target', got '1:600|x'"});
    fresh();
    edit(info, 1, "suite = 'bbob-biobj', funcId = 1, DIM = 2");
    refused({info.string() + ":1", "suite 'bbob-biobj'"});
    fresh();
    edit(info, 1, "funcId = 101, DIM = 2");
    refused({info.string() + ":1", "f1-f24 only"});
    fresh();
    edit(dat, 2, "12 0 x");
    refused({dat.string() + ":2", "expected best f - f_opt, a number, in column 3, got 'x'"});
    fresh();
    edit(dat, 2, "1 0");
    refused({dat.string() + ":2", "3 columns or more"});
    fresh();
    edit(dat, 1, "% no optimum here");
    refused({dat.string() + ":2", "no 'Fopt (...)'"});
    fresh();
    fs::remove(dat);
    refused({dat.string() + ": no such file (named at " + info.string() + ":3)"});
    fresh();
    edit(info, 3, "data_f1/bbobexp_f1_DIM2.dat, 1:600|1e-3");
    refused({dat.string() + ": holds 4 runs, " + info.string() + ":3 lists 1"});

    // Into a store that holds the name already, or whose instances differ: nothing changes.
    REQUIRE(run_pride(e.import(e.store, (e.coco / "pso").string(), "x")).status == 0);
    const std::string bytes = slurp(e.store);
    expect_input_error(e.import(e.store, (e.coco / "ga").string(), "x"),
                       {e.store + ": holds the algorithm 'published:x' already, imported from pso"});
    fresh();
    const std::string text = slurp(dat);
    const std::size_t at = text.find("Fopt (") + 6;
    edit(dat, 1, text.substr(0, at) + "1.5e+00) + sum g_i+ | x");
    expect_input_error(e.import(e.store, bad.string(), "y"),
                       {dat.string() + ":2", "bbob f1 instance 1 in 2-D has f_opt 1.5 here", "not the same protocol"});
    CHECK(slurp(e.store) == bytes);
    CHECK(scalar(e.store, "SELECT COUNT(*) FROM runs WHERE algorithm = 'published:y'") == "0");
}

TEST_CASE("report: published runs on other instances are in the ERT, and said so", "[import][report]") {
    const Exported e;
    // The pso runs of instance 2 relabelled instance 3 in each .info line (the campaign ran 1 and 2).
    const fs::path folder = e.tmp.path() / "relabelled";
    fs::copy(e.coco / "pso", folder, fs::copy_options::recursive);
    for (const int fid : {1, 15}) {
        const fs::path info = folder / ("bbobexp_f" + std::to_string(fid) + ".info");
        std::string text = slurp(info);
        for (std::size_t at; (at = text.find(", 2:")) != std::string::npos;) text.replace(at, 4, ", 3:");
        std::ofstream(info) << text;
    }
    const auto r = run_pride(e.import(e.store, folder.string(), "relabelled"));
    INFO(r.out << r.err);
    REQUIRE(r.status == 0);
    CHECK(r.out ==
          "16 runs of published:relabelled imported into " + e.store + " (4 problems of the store, 4 added)\n");
    const auto md = run_pride("report '" + e.store + "'");
    REQUIRE(md.status == 0);
    CHECK_THAT(md.out, Catch::Contains("published:relabelled ran other instances than the campaign's algorithms on 4 "
                                       "function and dimension cells (bbob-f1 2-D: instances 1,3 against 1,2; "));
    // Its problems of instance 3 are its own, compared among themselves; its ERT pools both instances.
    CHECK_THAT(md.out, Catch::Contains("| published:bbob-f1-i3-d2 | published:relabelled | 2 |"));
    const auto s = pride::storage::read_store(e.store);
    const auto analysis = pride::report::coco::analyse(s);
    REQUIRE(analysis);
    for (const auto& row : analysis->erts)
        if (row.algorithm == "published:relabelled") CHECK(row.instances == 2);
}

// IOHprofiler files as published runs (`pride import STORE --ioh FOLDER`,
// experiment/report/ioh_import.hpp): `pride export --ioh` of a campaign read back onto the
// campaign's own problems equals the runs it came from, to what the files carry (each iteration's
// best so far, the final value with 17 digits); reports and merges treat the rows by their protocol;
// bad input is one line naming file and line, exit 2, with nothing written.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "experiment/report/coco.hpp"
#include "experiment/report/report.hpp"
#include "experiment/storage/reader.hpp"
#include "tests/cli_runner.hpp"
#include "tests/test_support.hpp"

namespace fs = std::filesystem;
using pride::test::expect_input_error;
using pride::test::run_pride;
using pride::test::slurp;

namespace {

// Two BBOB functions (their runs named by instance in the files) and a problem outside a suite
// (its runs named by seed).
constexpr const char* kCampaign =
    "name = \"ioh\"\nseeds = 2\n[budget]\nevaluations_per_dim = 300\n"
    "[[suite]]\nname = \"bbob\"\nfunctions = [1, 15]\ninstances = [1, 2]\ndimensions = [2, 3]\n"
    "[[problem]]\nid = \"sphere-3\"\ntype = \"sphere\"\ndim = 3\n"
    "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\npop = 10\n"
    "[[algorithm]]\nid = \"ga\"\ntype = \"ga\"\npop = 10\n";

/// A campaign's store and its IOH export (DIR/ioh/pso, DIR/ioh/ga).
struct Exported {
    pride::test::TempDir tmp{"pride-import-ioh"};
    std::string store = tmp.file("c.sqlite"), toml = tmp.file("c.toml");
    fs::path ioh = tmp.path() / "ioh";
    Exported() {
        std::ofstream(toml) << kCampaign;
        REQUIRE(run_pride("bench '" + toml + "' --jobs 2 --out '" + store + "'").status == 0);
        REQUIRE(run_pride("export '" + store + "' --ioh '" + ioh.string() + "'").status == 0);
    }
    /// A copy of the campaign's store, named `name`.
    std::string copy(const std::string& name) const {
        const std::string to = tmp.file(name);
        fs::copy_file(store, to);
        return to;
    }
    static std::string import(const std::string& into, const fs::path& folder, const std::string& name) {
        return "import '" + into + "' --ioh '" + folder.string() + "' --name " + name +
               " --citation 'pride (2026), test'";
    }
};

std::map<std::pair<std::string, std::int64_t>, pride::storage::StoredRun> runs_of(
    const pride::storage::CampaignStore& s, const std::string& algorithm) {
    std::map<std::pair<std::string, std::int64_t>, pride::storage::StoredRun> out;
    for (const auto& r : s.runs)
        if (r.algorithm == algorithm) out.emplace(std::pair{r.problem, r.seed}, r);
    return out;
}

/// The runtimes the files carry: per target precision, the evaluations of the first iteration whose
/// best so far is within it (computed here from the original run's history, independently of pride's
/// reader).
std::vector<std::optional<std::int64_t>> iteration_runtimes(const pride::storage::StoredRun& r, double f_opt,
                                                            const std::vector<double>& precisions) {
    std::vector<std::optional<std::int64_t>> out;
    for (const double p : precisions) {
        std::optional<std::int64_t> hit;
        for (std::size_t k = 0; k < r.history.size() && !hit; ++k)
            if (std::isfinite(r.history[k]) && r.history[k] - f_opt <= p) hit = r.history_evaluations[k];
        out.push_back(hit);
    }
    return out;
}

}  // namespace

TEST_CASE("import --ioh: pride's own IOH export read back equals the runs it came from", "[import][ioh]") {
    const Exported e;
    const std::string store = e.copy("s.sqlite");
    const auto r = run_pride(Exported::import(store, e.ioh / "pso", "pso-ioh"));
    INFO(r.out << r.err);
    REQUIRE(r.status == 0);
    // 2 functions x 2 dimensions x 2 instances x 2 seeds, and sphere-3's 2 seeds: the store's 9 problems.
    CHECK(r.out == "18 runs of published:pso-ioh imported into " + store + " (9 problems of the store, 0 added)\n");
    const auto s = pride::storage::read_store(store);
    REQUIRE(s.published.count("published:pso-ioh"));
    const auto& source = s.published.at("published:pso-ioh");
    CHECK(source.format == "iohprofiler");
    CHECK(source.source == "pso");
    CHECK(source.citation == "pride (2026), test");
    CHECK(source.sha256.size() == 64);
    REQUIRE(s.precisions);
    std::map<std::string, double> f_opt;
    for (const auto& p : *s.problems) f_opt[p.id] = p.f_opt.value_or(0.0);

    const auto own = runs_of(s, "pso"), published = runs_of(s, "published:pso-ioh");
    REQUIRE(published.size() == 18);
    std::size_t earlier = 0;
    for (const auto& [key, p] : published) {
        INFO(key.first << " seed " << key.second);
        // The runs of an instance are trials 1, 2, ... in the files' order, which is the seeds'.
        REQUIRE(own.count(key));
        const auto& o = own.at(key);
        CHECK(p.evaluations == o.evaluations);
        CHECK(p.best.has_value());
        // The store keeps f_opt + (best - f_opt): the 17 digits written, within f_opt's rounding.
        CHECK(std::abs(*p.best - *o.best) <= 4e-16 * std::max(std::abs(*o.best), std::abs(f_opt.at(key.first))));
        // The .dat rows are the history, value for value.
        CHECK(p.history == o.history);
        CHECK(p.history_evaluations == o.history_evaluations);
        // Runtimes at iterations: those the history gives, never before pride's exact ones, the
        // same targets reached.
        const auto expected = iteration_runtimes(o, f_opt.at(key.first), *s.precisions);
        CHECK(p.target_hits == expected);
        REQUIRE(o.target_hits.size() == p.target_hits.size());
        for (std::size_t k = 0; k < p.target_hits.size(); ++k) {
            CHECK(p.target_hits[k].has_value() == o.target_hits[k].has_value());
            if (p.target_hits[k] && o.target_hits[k]) {
                CHECK(*p.target_hits[k] >= *o.target_hits[k]);
                earlier += *p.target_hits[k] > *o.target_hits[k];
            }
        }
    }
    // The rows are written at iterations of 10 evaluations: some targets were reached within one.
    CHECK(earlier > 0);

    // The ERT of every function, dimension and target is that of the iteration runtimes.
    const auto analysis = pride::report::coco::analyse(s);
    REQUIRE(analysis);
    std::map<std::string, std::string> function_of;
    std::map<std::string, std::int64_t> dim_of;
    for (const auto& p : *s.problems) function_of[p.id] = p.function.value_or(p.id), dim_of[p.id] = p.dim;
    std::size_t cells = 0;
    for (const auto& row : analysis->erts) {
        if (row.algorithm != "published:pso-ioh") continue;
        ++cells;
        for (std::size_t k = 0; k < row.ert.size(); ++k) {
            double sum = 0;
            std::size_t successes = 0, runs = 0;
            for (const auto& [key, o] : own)
                if (function_of.at(key.first) == row.function && dim_of.at(key.first) == row.dim) {
                    const auto hit = iteration_runtimes(o, f_opt.at(key.first), *s.precisions)[k];
                    sum += static_cast<double>(hit ? *hit : o.evaluations);
                    successes += hit.has_value();
                    ++runs;
                }
            INFO(row.function << " " << row.dim << "-D, precision " << (*s.precisions)[k]);
            CHECK(row.ert[k].runs == runs);
            CHECK(row.ert[k].successes == successes);
            if (successes)
                CHECK(row.ert[k].value == Approx(sum / static_cast<double>(successes)).epsilon(1e-12));
            else
                CHECK(std::isinf(row.ert[k].value));
        }
    }
    CHECK(cells == 5);  // f1 and f15 in 2-D and 3-D, sphere in 3-D

    // The final values: the same table rows (and tests) as the runs they came from.
    const auto report = pride::report::make_report(s);
    std::map<std::string, const pride::report::ReportRow*> mine;
    for (const auto& row : report.rows)
        if (row.algorithm == "pso") mine[row.problem] = &row;
    std::size_t compared = 0;
    for (const auto& row : report.rows)
        if (row.algorithm == "published:pso-ioh") {
            INFO(row.problem);
            const auto& m = *mine.at(row.problem);
            CHECK(row.runs == m.runs);
            CHECK(row.mean_evaluations == m.mean_evaluations);
            for (const auto& [a, b] : {std::pair{row.min, m.min},
                                       {row.median, m.median},
                                       {row.mean, m.mean},
                                       {row.max, m.max},
                                       {row.std, m.std}})
                CHECK(a == Approx(b).epsilon(1e-12).margin(1e-12));
            ++compared;
        }
    CHECK(compared == 9);
    const auto md = run_pride("report '" + store + "'");
    REQUIRE(md.status == 0);
    CHECK_THAT(md.out, Catch::Contains("| published:pso-ioh |"));
    CHECK_THAT(md.out, Catch::Contains("published:pso-ioh holds published runs: pride (2026), test, read from pso "
                                       "(iohprofiler data, SHA-256 " +
                                       source.sha256 + "); imported, never run by pride."));
    CHECK_THAT(md.out, !Catch::Contains("is left out"));

    // The campaign resumed runs none of them: they are not its runs.
    const auto resumed = run_pride("bench '" + e.toml + "' --out '" + store + "'");
    REQUIRE(resumed.status == 0);
    CHECK_THAT(resumed.out, Catch::Contains("0 runs stored in " + store + " (36 were there already, 36 in all)"));

    // Exported again, the imported runs give the same .dat files.
    const fs::path again = e.tmp.path() / "again";
    REQUIRE(run_pride("export '" + store + "' --ioh '" + again.string() + "'").status == 0);
    fs::path folder;  // the published algorithm's, its id made a file name
    for (const auto& f : fs::directory_iterator(again))
        if (f.path().filename().string().rfind("published_pso-ioh", 0) == 0) folder = f.path();
    REQUIRE(!folder.empty());
    std::size_t dats = 0;
    for (const auto& f : fs::recursive_directory_iterator(e.ioh / "pso"))
        if (f.path().extension() == ".dat") {
            const fs::path other = folder / fs::relative(f.path(), e.ioh / "pso");
            INFO(other);
            REQUIRE(fs::exists(other));
            CHECK(slurp(other) == slurp(f.path()));
            ++dats;
        }
    CHECK(dats == 5);
}

TEST_CASE("import --ioh: merges keep one source, other budgets are left out of the final values, named",
          "[import][ioh]") {
    const Exported e;
    // A store with the same published runs merges; one where the name holds other runs does not.
    const std::string same = e.copy("same.sqlite"), again = e.copy("again.sqlite"), other = e.copy("other.sqlite");
    REQUIRE(run_pride(Exported::import(same, e.ioh / "ga", "ga-ioh")).status == 0);
    REQUIRE(run_pride(Exported::import(again, e.ioh / "ga", "ga-ioh")).status == 0);
    REQUIRE(run_pride(Exported::import(other, e.ioh / "pso", "ga-ioh")).status == 0);
    const std::string merged = e.tmp.file("m.sqlite");
    const auto m = run_pride("merge '" + same + "' '" + again + "' --out '" + merged + "'");
    INFO(m.out << m.err);
    REQUIRE(m.status == 0);
    CHECK(pride::storage::read_store(merged).published.count("published:ga-ioh") == 1);
    expect_input_error("merge '" + same + "' '" + other + "' --out '" + e.tmp.file("n.sqlite") + "'",
                       {"other.sqlite", "published:ga-ioh", "not merged"});
    CHECK(!fs::exists(e.tmp.file("n.sqlite")));

    // The same campaign under twice the budget: the runs are in the ERT, not in the final values.
    const pride::test::TempDir longer("pride-import-ioh-longer");
    const std::string toml = longer.file("c.toml"), store = longer.file("c.sqlite");
    std::string text = kCampaign;
    text.replace(text.find("evaluations_per_dim = 300"), 25, "evaluations_per_dim = 600");
    std::ofstream(toml) << text;
    REQUIRE(run_pride("bench '" + toml + "' --jobs 2 --out '" + store + "'").status == 0);
    const auto r = run_pride(Exported::import(store, e.ioh / "pso", "pso-300"));
    INFO(r.out << r.err);
    REQUIRE(r.status == 0);
    const auto s = pride::storage::read_store(store);
    const auto report = pride::report::make_report(s);
    for (const auto& row : report.rows) CHECK(row.algorithm != "published:pso-300");
    std::size_t ert_rows = 0;
    for (const auto& row : report.coco->erts) ert_rows += row.algorithm == "published:pso-300";
    CHECK(ert_rows == 5);
    const auto md = run_pride("report '" + store + "'");
    REQUIRE(md.status == 0);
    CHECK_THAT(md.out, Catch::Contains("published:pso-300 is left out of the comparison of final values on 9 problems "
                                       "(bbob-f1-i1-d2, "));
    CHECK_THAT(md.out, Catch::Contains("(on bbob-f1-i1-d2: a mean of 600 evaluations, the campaign's 1200;"));
}

TEST_CASE("import --ioh: bad input is one line naming file and line, exit 2, nothing written", "[import][ioh]") {
    const Exported e;
    const std::string store = e.copy("s.sqlite"), bytes = slurp(store);
    const fs::path bad = e.tmp.path() / "bad";
    const auto fresh = [&] {
        fs::remove_all(bad);
        fs::copy(e.ioh / "pso", bad, fs::copy_options::recursive);
    };
    const auto edit = [&](const fs::path& file, std::size_t line, const std::string& text) {
        std::string all = slurp(file), out;
        std::size_t n = 0, at = 0;
        for (std::size_t next; (next = all.find('\n', at)) != std::string::npos; at = next + 1)
            out += (++n == line ? text : all.substr(at, next - at)) + "\n";
        std::ofstream(file) << out;
    };
    const auto line_of = [&](const fs::path& file, std::size_t line) {
        const auto lines = pride::test::lines_of(slurp(file));
        REQUIRE(line <= lines.size());
        return lines[line - 1];
    };
    const auto refused = [&](const std::vector<std::string>& words) {
        expect_input_error(Exported::import(store, bad, "x"), words);
        CHECK(slurp(store) == bytes);  // nothing written
    };
    expect_input_error(Exported::import(store, e.tmp.path() / "none", "x"), {"none: no such folder"});
    expect_input_error(Exported::import(store, e.toml, "x"), {"c.toml: not a folder"});
    expect_input_error(Exported::import(store, e.ioh / "pso" / "data_f1_Sphere", "x"), {"holds no .info file"});
    expect_input_error(Exported::import(e.tmp.file("none.sqlite"), e.ioh / "pso", "x"), {"none.sqlite"});
    CHECK(!fs::exists(e.tmp.file("none.sqlite")));
    expect_input_error("import '" + store + "' --ioh '" + (e.ioh / "pso").string() + "' --name x", {"--citation"});
    expect_input_error("import '" + store + "' --name x --citation c",
                       {"import: name the data to read", "--cec2017 FOLDER", "--ioh FOLDER"});
    CHECK(slurp(store) == bytes);

    const fs::path info = bad / "IOHprofiler_f1_Sphere.info";
    const fs::path dat = bad / "data_f1_Sphere" / "IOHprofiler_f1_DIM2.dat";
    fresh();
    // Garbage and NaN in a row.
    edit(dat, 2, "x 1 1 1 1");
    refused({dat.string() + ":2", "expected a count of evaluations (at least 1) in column 1, got 'x'"});
    fresh();
    {
        const std::string row = line_of(dat, 3);
        edit(dat, 3, row.substr(0, row.find(' ')) + " nan nan nan nan");
    }
    refused({dat.string() + ":3", "expected best-so-far f(x), a finite number or None, in column 3, got 'nan'"});
    // Evaluations that decrease.
    fresh();
    {
        const std::string second = line_of(dat, 3);
        edit(dat, 3, "1" + second.substr(second.find(' ')));
    }
    refused({dat.string() + ":3", "expected evaluations that never decrease, got 1 after"});
    // Truncated: a row cut short, and the last run's block gone.
    fresh();
    {
        const std::string row = line_of(dat, 2);
        edit(dat, 2, row.substr(0, row.find(' ', row.find(' ') + 1)));
    }
    refused({dat.string() + ":2", "expected 5 columns, as the header line at 1 names, got 2 (a truncated file?)"});
    fresh();
    {
        const std::string text = slurp(dat);
        std::ofstream(dat) << text.substr(0, text.rfind("\"function evaluation\""));
    }
    refused({dat.string() + ": holds 3 runs, " + info.string() + ":3 lists 4 (a truncated file?)"});
    fresh();
    {
        const std::string text = slurp(dat);
        std::ofstream(dat) << text.substr(0, text.size() / 2);  // cut mid-line, mid-block
    }
    expect_input_error(Exported::import(store, bad, "x"), {dat.string()});
    CHECK(slurp(store) == bytes);
    // A row beyond the run's evaluations (the last run's last row).
    fresh();
    const std::size_t last = pride::test::lines_of(slurp(dat)).size();
    {
        const std::string row = line_of(dat, last);
        edit(dat, last, "100000" + row.substr(row.find(' ')));
    }
    refused({dat.string() + ":" + std::to_string(last), "a row at 100000 evaluations, beyond the run's"});
    fresh();
    fs::remove(dat);
    refused({dat.string() + ": no such file (named at " + info.string() + ":3)"});

    // A problem the store has not: another function, dimension or instance, and a maximised one.
    const std::string header = [&] {
        fresh();
        return line_of(info, 1);
    }();
    const auto replaced = [&](const std::string& from, const std::string& to) {
        std::string h = header;
        h.replace(h.find(from), from.size(), to);
        return h;
    };
    fresh();
    edit(info, 1, replaced("funcId = 1,", "funcId = 7,"));
    refused({info.string() + ":1", "suite 'BBOB' funcId 7 ('Sphere') in 2-D is none of the store's problems"});
    fresh();
    edit(info, 1, replaced("funcName = \"Sphere\"", "funcName = \"OneMax\""));
    refused({info.string() + ":1",
             "funcId 1 ('OneMax') in 2-D is none of the store's problems: its funcId 1 in "
             "2-D is suite 'BBOB' 'Sphere'"});
    fresh();
    edit(info, 1, replaced("DIM = 2,", "DIM = 5,"));
    refused({info.string() + ":1", "funcId 1 ('Sphere') in 5-D is none of the store's problems"});
    fresh();
    edit(info, 1, replaced("maximization = \"F\"", "maximization = \"T\""));
    refused({info.string() + ":1", "maximization = \"T\""});
    fresh();
    {
        std::string data = line_of(info, 3);
        data.replace(data.find(", 1:"), 4, ", 9:");
        edit(info, 3, data);
    }
    refused({info.string() + ":3", "instance 9 of funcId 1 in 2-D is none of the store's problems"});
    fresh();
    {
        std::string data = line_of(info, 3);
        const auto bar = data.find('|');
        data.replace(bar, data.find(',', bar) - bar, "|None");
        edit(info, 3, data);
    }
    refused({info.string() + ":3", "expected a run as 'number:evaluations|best f(x)'"});
    fresh();
    edit(info, 3, "data_f1_Sphere/IOHprofiler_f1_DIM2.dat");
    refused({info.string() + ":3", "expected a data line"});
    fresh();
    edit(info, 1, "% " + header);
    refused({info.string() + ":3", "expected a header line ('suite = ..., funcId = ..., DIM = ...') first"});
    fresh();
    edit(info, 1, replaced("funcId = 1,", "funcId = one,"));
    refused({info.string() + ":1", "expected 'funcId = N'"});
    fresh();
    edit(info, 1, replaced("DIM = 2,", "DIM = 0,"));
    refused({info.string() + ":1", "expected 'DIM = D'"});
    fresh();
    edit(info, 1, replaced("algId = \"pso\"", "algId = \"\""));
    refused({info.string() + ":1", "expected 'algId = \"...\"'"});
    // A header naming no columns the reader takes.
    fresh();
    edit(dat, 1, "\"function evaluation\" \"current f(x)\"");
    refused({dat.string() + ":1", "\"best-so-far f(x)\""});
    fresh();
    edit(dat, 1, "12 3 3 3 3");
    refused({dat.string() + ":1", "expected a header line of column names"});

    // Two algorithms: a .info of ga's beside pso's, and one function given twice.
    fresh();
    fs::copy_file(e.ioh / "ga" / "IOHprofiler_f1_Sphere.info", bad / "IOHprofiler_f1_Sphere_ga.info");
    refused({(bad / "IOHprofiler_f1_Sphere_ga.info").string() + ":1", "names the algorithm 'ga', ", ":1 names 'pso'",
             "import one algorithm's folder at a time"});
    expect_input_error(Exported::import(store, e.ioh, "x"), {"names the algorithm 'pso'", "names 'ga'"});
    fresh();
    fs::copy_file(info, bad / "IOHprofiler_f1_Sphere_copy.info");
    refused({(bad / "IOHprofiler_f1_Sphere_copy.info").string() + ":1",
             "funcId 1 in 2-D again, as at " + info.string() + ":1"});

    // A name the store holds already: refused, the store as it was.
    const std::string held = e.copy("held.sqlite");
    REQUIRE(run_pride(Exported::import(held, e.ioh / "pso", "x")).status == 0);
    const std::string before = slurp(held);
    expect_input_error(Exported::import(held, e.ioh / "ga", "x"),
                       {held + ": holds the algorithm 'published:x' already, imported from pso"});
    CHECK(slurp(held) == before);
}

// The bad-input contract of docs/cli.md ("Bad input: what you see"), row by row: every class of
// bad input a subcommand or a file format can get, run through `pride` as a user would, must end
// with exit status 2, nothing on stdout, one line on stderr naming the option, key or file (and
// line) and, for numbers, the accepted range; no byte of it a raw control character. Each table
// below is one section of that page; a new kind of bad input is a new row here and there.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "framework/problem.hpp"
#include "problems/continuous/catalog.hpp"
#include "problems/continuous/function.hpp"
#include "tests/cli_runner.hpp"
#include "tests/test_support.hpp"

namespace {

using pride::test::check_input_error;
using pride::test::run_pride;
using pride::test::TempDir;

struct Row {
    std::string args;                // after `pride`, shell-quoted; FILES is replaced by the folder of inputs
    std::vector<std::string> words;  // each must appear in the one line on stderr
    std::string stdin_text = {};
};

/// The inputs the rows name, written once per test into a fresh folder.
class Inputs {
  public:
    Inputs() {
        const std::string map = std::string(PRIDE_SOURCE_DIR) + "/examples/maps/wan2022-10x10.map";
        dir_.write("m.map", pride::test::slurp(map));
        dir_.write("empty.map", "");
        dir_.write("binary.map", std::string("\x7f"
                                             "ELF\x02\x01\x01\0\0\x1b[31m\xff\xfe",
                                             16));
        dir_.write("latin1.map", "type octile\nheight 2\nwidth 2\nmap\n.\xe9\n..\n");
        dir_.write("huge.map", "type octile\nheight 1000000000000\nwidth 1000000000000\nmap\n");
        dir_.write("wide.map", "type octile\nheight 100000\nwidth 100000\nmap\n");
        dir_.write("empty.csv", "");
        dir_.write("binary.csv", std::string("\x01\x02\x1b[2J\0\xff", 9));
        dir_.write("ragged.csv", "a,b,d\n1,2\n");
        dir_.write("empty.scen", "");
        dir_.write("binary.scen", std::string("\x1b]0;title\x07\xff\0", 11));
        dir_.write("empty.toml", "");
        dir_.write("binary.toml", std::string("\x1b[31m\xff\xfe\0\x01", 10));
        dir_.write("duplicate.toml", "name = \"a\"\nname = \"b\"\n");
        dir_.write("unknown.toml", "name = \"a\"\nseeds = 1\nbogus = 3\n");
        std::filesystem::create_directory(dir_.path() / "folder");
    }
    /// `args` with FILES replaced by the folder of inputs (quoted by the row itself).
    std::string expand(std::string args) const {
        for (std::size_t at; (at = args.find("FILES")) != std::string::npos;) args.replace(at, 5, dir_.path().string());
        return args;
    }
    /// A campaign file: one continuous problem and one algorithm, with `budget`, `problem` and
    /// `algorithm` lines added to those tables.
    std::string campaign(const std::string& name, const std::string& budget, const std::string& problem,
                         const std::string& algorithm, const std::string& top = "seeds = 1") const {
        return dir_.write(name, "name = \"c\"\n" + top + "\n[budget]\n" + budget +
                                    "\n[[problem]]\nid = \"s\"\ntype = \"sphere\"\ndim = 2\n" + problem +
                                    "\n[[algorithm]]\nid = \"p\"\ntype = \"pso\"\n" + algorithm + "\n");
    }
    /// A campaign file with one grid problem on m.map (the 10x10 map of Wan and Gao (2022)).
    std::string grid_campaign(const std::string& name, const std::string& problem) const {
        return dir_.write(name,
                          "name = \"g\"\nseeds = 1\n[budget]\niterations = 5\n[[problem]]\nid = \"g\"\n"
                          "type = \"grid\"\nmap = \"m.map\"\n" +
                              problem + "\n[[algorithm]]\nid = \"p\"\ntype = \"pso\"\n");
    }
    const TempDir& dir() const { return dir_; }

  private:
    TempDir dir_{"pride-contract"};
};

/// No raw control byte (ESC, BEL, NUL, CR...) and no DEL anywhere but the final newline.
void check_printable(const std::string& err) {
    for (std::size_t i = 0; i + 1 < err.size(); ++i) {
        const auto c = static_cast<unsigned char>(err[i]);
        INFO("byte " << i << " of the message is " << static_cast<int>(c));
        CHECK((c >= 0x20 && c != 0x7f));
    }
}

void check_rows(const Inputs& in, const std::vector<Row>& rows) {
    for (const Row& row : rows) {
        const std::string args = in.expand(row.args);
        INFO("pride " << args);
        const auto r = run_pride(args, row.stdin_text);
        check_input_error(r, row.words);
        check_printable(r.err);
    }
}

const std::string big = "18446744073709551616";  // 2^64: one past the largest seed

}  // namespace

TEST_CASE("cli contract: run refuses every bad number with its range", "[cli][contract][errors]") {
    const Inputs in;
    const std::string run = "run --problem sphere --dim 2 --algo pso ";
    const std::string count = "[1, 1000000000000000]";
    check_rows(in, {
                       {run + "--dim nan", {"--dim", "integer", count, "'nan'"}},
                       {run + "--dim -1", {"--dim", count, "-1"}},
                       {run + "--dim 1e999", {"--dim", count}},
                       {run + "--dim " + big, {"--dim", count, big}},
                       {run + "--dim 2.5", {"--dim", "integer"}},
                       {"run --problem sphere --dim 100000000 --algo pso", {"pso", "memory"}},
                       {run + "--evals nan", {"--evals", count}},
                       {run + "--evals -5", {"--evals", count}},
                       {run + "--evals 0", {"--evals", count}},
                       {run + "--evals 1e3", {"--evals", "integer", "'1e3'"}},
                       {run + "--evals " + big, {"--evals", count, big}},
                       {run + "--iters inf", {"--iters", "[0, 1000000000000000]"}},
                       {run + "--iters -1", {"--iters", "[0, 1000000000000000]"}},
                       // --pop is checked against the algorithm's own range, as a campaign's pop is.
                       {run + "--pop 1e12", {"pso: pop must be an integer in [2, 1000000000000]", "'1e12'"}},
                       {run + "--pop -3", {"pso: pop must be an integer in [2, 1000000000000]", "got -3"}},
                       {run + "--pop 2000000000", {"pso", "2000000000", "memory"}},
                       {run + "--pop 1", {"pso", "population"}},
                       {run + "--seed " + big, {"--seed", "[0, 18446744073709551615]", big}},
                       {run + "--seed -1", {"--seed", "[0, 18446744073709551615]"}},
                       {run + "--seed nan", {"--seed", "integer"}},
                       {run + "--seed 1.5", {"--seed", "integer"}},
                       {run + "--instance -1", {"--instance", "[0, 9223372036854775807]"}},
                       {run + "--instance " + big, {"--instance", big}},
                       {run + "--target nan", {"--target", "finite number", "'nan'"}},
                       {run + "--target inf", {"--target", "finite number", "'inf'"}},
                       {run + "--target -1e999", {"--target", "finite number"}},
                       {run + "--wall-ms nan", {"--wall-ms", "finite number"}},
                       {run + "--wall-ms inf", {"--wall-ms", "finite number"}},
                       {run + "--wall-ms -1", {"--wall-ms", "> 0"}},
                       {run + "--param w_start=nan", {"--param w_start", "finite number"}},
                       {run + "--param w_start=inf", {"--param w_start", "finite number"}},
                       {run + "--param w_start=1e300", {"w_start", "[0, 1.5]", "1e+300"}},
                       {run + "--param w_start=-1", {"w_start", "[0, 1.5]"}},
                       {run + "--param pop=1e300", {"pop", "integer"}},
                       {run + "--param nosuch=1", {"pso", "unknown parameter 'nosuch'"}},
                       {run + "--param pop", {"pop", "NAME=VALUE"}},
                       {run + "--evals 10 --bogus", {"--bogus"}},
                       {run + "--bogus $'\\x1b[31m'", {"\\x1b[31m"}},
                   });
}

TEST_CASE("cli contract: eval refuses bad points, sizes and seeds", "[cli][contract][errors]") {
    const Inputs in;
    check_rows(in, {
                       {"eval --problem sphere --x nan,1", {"--x coordinate 1", "'nan' is not a finite number"}},
                       {"eval --problem sphere --x 1,inf", {"--x coordinate 2", "finite number"}},
                       {"eval --problem sphere --x 1e999", {"--x coordinate 1", "finite number"}},
                       {"eval --problem sphere --x 1,,2", {"--x", "coordinate 2 is empty"}},
                       {"eval --problem sphere --dim -1 --x 1", {"--dim", "[1, 1000000000000000]", "-1"}},
                       {"eval --problem sphere --dim nan --x 1", {"--dim", "integer"}},
                       {"eval --problem sphere --dim 3 --x 1,2", {"--x", "expected 3 coordinates"}},
                       {"eval --problem sphere --seed -1 --x 1", {"--seed", "[0, 18446744073709551615]"}},
                       {"eval --problem sphere --seed " + big + " --x 1", {"--seed", big}},
                       {"eval --problem sphere --x -", {"stdin", "no points"}, ""},
                       {"eval --problem sphere --x -", {"stdin line 1", "\\x1b", "\\x01"}, "\x1b[2J\x01\n"},
                       {"eval --problem sphere --x -", {"stdin line 1", "\\xff"}, "1,\xff\n"},
                       {"eval --problem sphere --x -", {"stdin line 2", "expected 2 coordinates"}, "1,2\r\n1\r\n"},
                       {"eval --problem nosuch --x 1", {"--problem", "nosuch"}},
                   });
}

TEST_CASE("cli contract: path refuses bad cells, numbers and maps", "[cli][contract][errors]") {
    const Inputs in;
    const std::string path = "path --map FILES/m.map --algo pso ";
    const std::string run = path + "--start 0,0 --goal 9,9 ";
    check_rows(in, {
                       {path + "--start 50,0 --goal 9,9", {"--start", "outside"}},
                       {path + "--start -1,0 --goal 9,9", {"--start", "outside"}},
                       {path + "--start 0,0 --goal 9,1000000", {"--goal", "outside"}},
                       {path + "--start 5,1 --goal 9,9", {"--start", "blocked"}},
                       {path + "--start 0,0 --goal 6,1", {"--goal", "blocked"}},
                       {path + "--start nan,0 --goal 9,9", {"--start X", "finite number"}},
                       {path + "--start 1e300,0 --goal 9,9", {"--start", "integer coordinates"}},
                       {path + "--start 0.5,0 --goal 9,9", {"--start", "integer coordinates"}},
                       {path + "--start 0 --goal 9,9", {"--start", "expected X,Y"}},
                       {run + "--pop nan", {"pop must be an integer", "'nan'"}},
                       {run + "--pop 3000000000", {"pso", "memory"}},
                       {run + "--iters -1", {"--iters", "[0, 1000000000000000]"}},
                       {run + "--evals " + big, {"--evals", big}},
                       {run + "--seed " + big, {"--seed", "[0, 18446744073709551615]"}},
                       {run + "--inflate 1001", {"--inflate", "[0, 1000]"}},
                       {run + "--inflate -1", {"--inflate", "[0, 1000]"}},
                       {run + "--waypoints 0 --encoding free", {"--waypoints", "[1, 1000]"}},
                       {run + "--objective hswoa --lambda inf", {"--lambda", "finite number", "[0, 1000000000]"}},
                       {run + "--objective hswoa --lambda nan", {"--lambda", "finite number"}},
                       {run + "--objective hswoa --lambda -1", {"--lambda", "[0, 1000000000]"}},
                       {run + "--objective weighted --weights 1e308,1e308,1e308 --oracle", {"--weights", "1e+308"}},
                       {run + "--objective weighted --weights nan,1,1", {"--weights coordinate 1", "finite number"}},
                       {run + "--objective weighted --weights -1,1,1", {"--weights", "[0, 1000000000]"}},
                       {run + "--objective weighted --weights 1,1", {"--weights", "three weights"}},
                       {"path --map FILES/empty.map --algo pso --start 0,0 --goal 1,1", {"empty.map"}},
                       {"path --map FILES/binary.map --algo pso --start 0,0 --goal 1,1", {"binary.map:1"}},
                       {"path --map FILES/latin1.map --algo pso --start 0,0 --goal 1,1", {"latin1.map:5", "not UTF-8"}},
                       {"path --map FILES/huge.map --algo pso --start 0,0 --goal 1,1", {"huge.map"}},
                       {"path --map FILES/nosuch.map --algo pso --start 0,0 --goal 1,1", {"nosuch.map"}},
                       {"path --map FILES/folder --algo pso --start 0,0 --goal 1,1", {"folder"}},
                   });
}

TEST_CASE("cli contract: picture paths that cannot be written leave nothing behind", "[cli][contract][errors]") {
    const Inputs in;
    const std::string run = "path --map FILES/m.map --algo astar --start 0,0 --goal 9,9 ";
    check_rows(in, {
                       {run + "--svg FILES/folder", {"folder"}},
                       {run + "--png FILES/missing/p.png", {"missing"}},
                       {run + "--svg FILES/missing/p.svg --png FILES/ok.png", {"missing"}},
                   });
    // Nothing was written: not the good picture of the last row, no temporary file.
    CHECK(!std::filesystem::exists(in.dir().path() / "ok.png"));
    CHECK(std::filesystem::is_empty(in.dir().path() / "folder"));
    CHECK(!std::filesystem::exists(in.dir().path() / "missing"));
}

TEST_CASE("cli contract: pareto, scen and roughset refuse bad input", "[cli][contract][errors]") {
    const Inputs in;
    const std::string pareto = "pareto --map FILES/m.map --objectives length,turns ";
    check_rows(in, {
                       {pareto + "--start 5,1 --goal 9,9", {"--start", "blocked"}},
                       {pareto + "--start 0,0 --goal 99,9", {"--goal", "outside"}},
                       {pareto + "--start 0,0 --goal 9,9 --inflate nan", {"--inflate", "[0, 1000]"}},
                       {"pareto --map FILES/m.map --start 0,0 --goal 9,9 --objectives length,bogus", {"--objectives"}},
                       {"scen FILES/empty.scen", {"empty.scen"}},
                       {"scen FILES/binary.scen", {"binary.scen:1", "UTF-8"}},
                       {"scen FILES/nosuch.scen", {"nosuch.scen"}},
                       {"roughset FILES/empty.csv", {"empty.csv"}},
                       {"roughset FILES/binary.csv", {"binary.csv"}},
                       {"roughset FILES/ragged.csv", {"ragged.csv:2"}},
                       {"roughset FILES/folder", {"folder"}},
                   });
}

TEST_CASE("cli contract: campaign files name the file, line and key", "[cli][contract][errors][bench]") {
    const Inputs in;
    const std::string out = " --out FILES/out.sqlite";
    auto bench = [&](const std::string& file) { return "bench '" + file + "'" + out; };
    check_rows(
        in, {
                {"bench FILES/empty.toml" + out, {"empty.toml", "missing key 'name'"}},
                {"bench FILES/binary.toml" + out, {"binary.toml:1"}},
                {"bench FILES/duplicate.toml" + out,
                 {"duplicate.toml:2:8: not valid TOML: Error while parsing key-value pair: cannot redefine existing "
                  "string"}},
                {"bench FILES/unknown.toml" + out, {"unknown.toml:3", "unknown key 'bogus'"}},
                {"bench FILES/nosuch.toml" + out, {"nosuch.toml"}},
                {bench(in.campaign("nan-param.toml", "evaluations = 100", "", "c1 = nan")),
                 {"nan-param.toml:10", "c1", "finite number"}},
                {bench(in.campaign("range-param.toml", "evaluations = 100", "", "c1 = 99")),
                 {"range-param.toml:10", "c1", "[0, 10]"}},
                {bench(in.campaign("unknown-param.toml", "evaluations = 100", "", "nosuch = 1")),
                 {"unknown-param.toml:10", "nosuch"}},
                {bench(in.campaign("float-evals.toml", "evaluations = 1e3", "", "")),
                 {"float-evals.toml:4", "'evaluations' must be an integer"}},
                {bench(in.campaign("huge-evals.toml", "evaluations = 9223372036854775807", "", "")),
                 {"huge-evals.toml:4", "'evaluations' must be in [1, 1000000000000000]"}},
                {bench(in.campaign("neg-iters.toml", "iterations = -1", "", "")), {"neg-iters.toml:4", "iterations"}},
                {bench(in.campaign("nan-target.toml", "evaluations = 10\ntarget = nan", "", "")),
                 {"nan-target.toml:5", "'target' must be a finite number"}},
                {bench(in.campaign("neg-seeds.toml", "evaluations = 10", "", "", "seeds = -1")),
                 {"neg-seeds.toml:2", "seeds"}},
                {bench(in.campaign("huge-seeds.toml", "evaluations = 10", "", "", "seeds = 18446744073709551615")),
                 {"huge-seeds.toml:2:", "not valid TOML", "[-9223372036854775808, 9223372036854775807]"}},
                {bench(in.campaign("twice-seeds.toml", "evaluations = 10", "", "", "seeds = [4, 5, 4]")),
                 {"twice-seeds.toml:2:16: 'seeds' lists seed 4 twice"}},
                {bench(in.campaign("empty-seeds.toml", "evaluations = 10", "", "", "seeds = { from = 5, to = 4 }")),
                 {"empty-seeds.toml:2:9: 'seeds' from 5 to 4 is empty"}},
                {bench(in.campaign("shard.toml", "evaluations = 10", "", "")) + " --shard 4/3",
                 {"--shard: must be K/N, part K of N with integers 1 <= K <= N (e.g. 2/3), got '4/3'"}},
                {bench(in.campaign("neg-dim.toml", "evaluations = 10", "dim = -1", "")), {"neg-dim.toml", "dim"}},
                {bench(in.grid_campaign("outside.toml", "start = [50, 0]\ngoal = [9, 9]")),
                 {"outside.toml", "start", "outside"}},
                {bench(in.grid_campaign("blocked.toml", "start = [5, 1]\ngoal = [9, 9]")),
                 {"blocked.toml", "start", "blocked"}},
                {bench(in.grid_campaign("nan-weights.toml",
                                        "start = [0, 0]\ngoal = [9, 9]\nobjective = \"weighted\"\n"
                                        "weights = [nan, 1, 1]")),
                 {"nan-weights.toml", "weights"}},
                {bench(in.grid_campaign("inf-lambda.toml",
                                        "start = [0, 0]\ngoal = [9, 9]\nobjective = \"hswoa\"\nlambda = inf")),
                 {"inf-lambda.toml", "lambda", "finite number"}},
                {"bench FILES/folder" + out, {"folder", "not a campaign file"}},
            });
    CHECK(!std::filesystem::exists(in.dir().path() / "out.sqlite"));
}

TEST_CASE("cli contract: report and export refuse what is not a store", "[cli][contract][errors]") {
    const Inputs in;
    check_rows(in, {
                       {"report FILES/nosuch.sqlite", {"nosuch.sqlite"}},
                       {"report FILES/folder", {"folder"}},
                       {"report FILES/binary.csv", {"binary.csv"}},
                       {"export FILES/nosuch.sqlite --ioh FILES/ioh", {"nosuch.sqlite"}},
                   });
    CHECK(!std::filesystem::exists(in.dir().path() / "ioh"));
}

TEST_CASE("problems: no function is NaN at a finite point far outside its box", "[problems][contract]") {
    // Far out, formulas overflow (x^4 - 16 x^2 is inf - inf, cos(2 pi x) is cos(inf)): the value
    // there is beyond the largest double, so it is +inf, or finite where the function is bounded
    // (Ackley: 20 at every integer point far out). Scalar and batch evaluation agree.
    int checked = 0;
    for (const auto& item : pride::continuous::catalog().items()) {
        if (item.entry.suite.starts_with("cec")) continue;  // the official data: tests/test_cec.cpp
        const std::size_t dim =
            item.entry.fixed_dim ? item.entry.fixed_dim : std::max<std::size_t>(item.entry.min_dim, 2);
        auto f = pride::continuous::make_function(item.name, static_cast<std::int64_t>(dim));
        for (const double v : {1e308, -1e308, 1e200, -1e160, 1e20, -3e15}) {
            INFO(item.name << " at " << v);
            const std::vector<double> x(dim, v);
            const double value = f.evaluate(x);
            CHECK(!std::isnan(value));
            pride::Matrix m(static_cast<Eigen::Index>(dim), 1);
            for (std::size_t i = 0; i < dim; ++i) m(static_cast<Eigen::Index>(i), 0) = v;
            std::vector<double> batch(1);
            f.evaluate_batch(m, batch);
            CHECK(!std::isnan(batch[0]));
            if (!f.noisy()) CHECK((batch[0] == value || (std::isinf(value) && std::isinf(batch[0]))));
            ++checked;
        }
    }
    CHECK(checked >= 6 * 70);
    auto ackley = pride::continuous::make_function("ackley", 2);
    CHECK(ackley.evaluate(std::vector<double>{1e308, 1e308}) == Approx(20.0));
    CHECK(ackley.evaluate(std::vector<double>{-1e300, 1e16}) == Approx(20.0));
    auto rastrigin = pride::continuous::make_function("rastrigin", 2);
    CHECK(rastrigin.evaluate(std::vector<double>{1e308, 0.0}) == std::numeric_limits<double>::infinity());
    // A NaN coordinate is not an overflow: it stays NaN (the run state turns it into +inf).
    CHECK(std::isnan(rastrigin.evaluate(std::vector<double>{std::nan(""), 0.0})));
}

// `pride export STORE --ioh DIR`: IOHprofiler .info/.dat files from a real campaign store.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "tests/cec_synthetic.hpp"
#include "tests/cli_runner.hpp"
#include "tests/test_support.hpp"

namespace fs = std::filesystem;
using pride::test::slurp;

TEST_CASE("export: IOHprofiler files, one folder per algorithm, one block per run", "[export]") {
    const pride::test::TempDir tmp("pride-ioh");  // removed with its files at the end of the test
    const fs::path& dir = tmp.path();
    {
        std::ofstream f(dir / "c.toml");
        f << "name = \"ioh\"\nseeds = 3\n[budget]\nevaluations = 200\n"
             "[[problem]]\nid = \"sphere5\"\ntype = \"sphere\"\ndim = 5\n"
             "[[problem]]\nid = \"ackley3\"\ntype = \"ackley\"\ndim = 3\n"
             "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\npop = 20\n"
             "[[algorithm]]\nid = \"ga\"\ntype = \"ga\"\npop = 20\n";
    }
    REQUIRE(pride::test::run_pride("bench '" + (dir / "c.toml").string() + "' --jobs 2 --out '" +
                                   (dir / "c.sqlite").string() + "'")
                .status == 0);
    const auto r =
        pride::test::run_pride("export '" + (dir / "c.sqlite").string() + "' --ioh '" + (dir / "ioh").string() + "'");
    REQUIRE(r.status == 0);
    CHECK(r.out.find("8 IOHprofiler files") != std::string::npos);
    for (const char* algorithm : {"pso", "ga"}) {
        const fs::path a = dir / "ioh" / algorithm;
        const std::string info = slurp(a / "IOHprofiler_f1001_sphere5.info");
        // As IOHexperimenter's Analyzer writes them: double quotes.
        CHECK(info.find("suite = \"pride\", funcId = 1001, funcName = \"sphere5\", DIM = 5, maximization = \"F\", "
                        "algId = \"" +
                        std::string(algorithm) + "\"") != std::string::npos);
        CHECK(info.find("data_f1001_sphere5/IOHprofiler_f1001_DIM5.dat, 1:200|") != std::string::npos);
        CHECK(info.find(", 3:200|") != std::string::npos);
        const std::string dat = slurp(a / "data_f1001_sphere5" / "IOHprofiler_f1001_DIM5.dat");
        std::size_t headers = 0;
        for (std::size_t at = dat.find("\"function evaluation\""); at != std::string::npos;
             at = dat.find("\"function evaluation\"", at + 1))
            ++headers;
        CHECK(headers == 3);  // one block per seed
        // Evaluation counts increase within a block and the best-so-far never rises.
        std::istringstream in(dat);
        std::string line;
        long last_evals = 0;
        double last_best = 1e300;
        while (std::getline(in, line)) {
            if (line.rfind("\"function", 0) == 0) {
                last_evals = 0;
                last_best = 1e300;
                continue;
            }
            std::istringstream fields(line);
            long evals = 0;
            double current = 0, best = 0;
            fields >> evals >> current >> best;
            CHECK(evals > last_evals);
            CHECK(best <= last_best);
            last_evals = evals;
            last_best = best;
        }
        CHECK(fs::exists(a / "IOHprofiler_f1002_ackley3.info"));
        CHECK(fs::exists(a / "data_f1002_ackley3" / "IOHprofiler_f1002_DIM3.dat"));
    }
    const auto missing =
        pride::test::run_pride("export '" + (dir / "none.sqlite").string() + "' --ioh '" + (dir / "x").string() + "'");
    CHECK(missing.status == 2);
}

TEST_CASE("export: BBOB's f1 and the classic suite's F1 are two IOH functions", "[export]") {
    const pride::test::TempDir tmp("pride-ioh-ids");
    const std::string file = tmp.write("c.toml",
                                       "name = \"ids\"\nseeds = 1\n[budget]\nevaluations = 100\n"
                                       "[[problem]]\nid = \"b\"\ntype = \"bbob-f1\"\ndim = 2\n"
                                       "[[problem]]\nid = \"y\"\ntype = \"yao-f1\"\ndim = 2\n"
                                       "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\npop = 10\n");
    REQUIRE(pride::test::run_pride("bench '" + file + "' --out '" + tmp.file("c.sqlite") + "'").status == 0);
    REQUIRE(pride::test::run_pride("export '" + tmp.file("c.sqlite") + "' --ioh '" + tmp.file("ioh") + "'").status ==
            0);
    const fs::path a = fs::path(tmp.file("ioh")) / "pso";
    CHECK(slurp(a / "IOHprofiler_f1_Sphere.info").rfind("suite = \"BBOB\", funcId = 1, funcName = \"Sphere\"", 0) == 0);
    CHECK(slurp(a / "IOHprofiler_f101_yao-f1.info")
              .rfind("suite = \"classic\", funcId = 101, funcName = \"yao-f1\"", 0) == 0);
}

TEST_CASE("export: the CEC suites' F1 are IOH functions of their own, apart from the classic F1", "[export][cec]") {
    // On synthetic data in the official format (tests/cec_synthetic.hpp): the ids do not depend on it.
    const pride::test::TempDir tmp("pride-ioh-cec");
    for (const int year : {2017, 2022})
        pride::test::cec_synthetic::write_input_data(tmp.file("data" + std::to_string(year)), year);
    const std::string file = tmp.write("c.toml",
                                       "name = \"ids\"\nseeds = 1\n[budget]\nevaluations = 100\n"
                                       "[[problem]]\nid = \"y\"\ntype = \"yao-f1\"\ndim = 2\n"
                                       "[[suite]]\nname = \"cec2017\"\nfunctions = [1]\ndimensions = [10]\n"
                                       "[[suite]]\nname = \"cec2022\"\nfunctions = [1]\ndimensions = [10]\n"
                                       "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\npop = 10\n");
    const std::string data =
        "PRIDE_CEC2017_DATA='" + tmp.file("data2017") + "' PRIDE_CEC2022_DATA='" + tmp.file("data2022") + "' ";
    const std::string bench =
        data + "'" + PRIDE_EXE + "' bench '" + file + "' --out '" + tmp.file("c.sqlite") + "' >/dev/null 2>&1";
    REQUIRE(std::system(bench.c_str()) == 0);
    REQUIRE(pride::test::run_pride("export '" + tmp.file("c.sqlite") + "' --ioh '" + tmp.file("ioh") + "'").status ==
            0);
    const fs::path a = fs::path(tmp.file("ioh")) / "pso";
    CHECK(slurp(a / "IOHprofiler_f101_yao-f1.info").rfind("suite = \"classic\", funcId = 101", 0) == 0);
    CHECK(slurp(a / "IOHprofiler_f201_cec2017-f1.info")
              .rfind("suite = \"cec2017\", funcId = 201, funcName = \"cec2017-f1\"", 0) == 0);
    CHECK(slurp(a / "IOHprofiler_f301_cec2022-f1.info")
              .rfind("suite = \"cec2022\", funcId = 301, funcName = \"cec2022-f1\"", 0) == 0);
}

// pride bench under mpirun (built with -DPRIDE_MPI=ON): local ranks (2 with one thread or two each,
// 3, and 4 resuming a store) store the same values as a threaded run, and a store rank 0 cannot
// open ends every rank. Compiled only into MPI builds.
#ifdef PRIDE_HAVE_MPI
#include <sqlite3.h>
#include <sys/wait.h>
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "tests/cli_runner.hpp"
#include "tests/test_support.hpp"

namespace fs = std::filesystem;

namespace {
std::vector<std::string> rows(const fs::path& store) {
    sqlite3* db = nullptr;
    REQUIRE(sqlite3_open_v2(store.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK);
    sqlite3_stmt* s = nullptr;
    REQUIRE(sqlite3_prepare_v2(db,
                               "SELECT problem || '|' || algorithm || '|' || seed || '|' || feasible || '|' || "
                               "quote(best) || '|' || evaluations || '|' || iterations || '|' || quote(optimum) || '|' "
                               "|| solution || '|' || history FROM runs ORDER BY problem, algorithm, seed",
                               -1, &s, nullptr) == SQLITE_OK);
    std::vector<std::string> out;
    while (sqlite3_step(s) == SQLITE_ROW) out.emplace_back(reinterpret_cast<const char*>(sqlite3_column_text(s, 0)));
    sqlite3_finalize(s);
    sqlite3_close(db);
    return out;
}

/// `pride bench CONFIG ARGS --out STORE` on `ranks` local MPI ranks, its output in `log`; the exit
/// status. Open MPI leaks in its own libraries at exit, which LeakSanitizer (sanitizer builds)
/// reports: leak checking is off for the ranks, and only for them.
int mpi_bench(int ranks, const std::string& config, const std::string& args, const fs::path& store,
              const fs::path& log) {
    const std::string command = std::string("ASAN_OPTIONS=detect_leaks=0 '") + PRIDE_MPIEXEC +
                                "' --allow-run-as-root --oversubscribe -np " + std::to_string(ranks) + " '" +
                                PRIDE_EXE + "' bench '" + config + "' " + args + " --out '" + store.string() + "' > '" +
                                log.string() + "' 2>&1";
    return std::system(command.c_str());
}
}  // namespace

TEST_CASE("bench: mpirun -np 2 stores the same values as a threaded run", "[bench][mpi]") {
    const pride::test::TempDir tmp("pride-mpi");  // removed with its files at the end of the test
    const fs::path& dir = tmp.path();
    const fs::path maps = fs::path(PRIDE_SOURCE_DIR) / "examples" / "maps";
    {
        std::ofstream f(dir / "c.toml");
        f << "name = \"mpi\"\nseeds = 3\n[budget]\niterations = 20\n"
             "[[problem]]\nid = \"rastrigin\"\ntype = \"shifted-rastrigin\"\ndim = 6\n"
             "[[problem]]\nid = \"map\"\ntype = \"grid\"\nmap = \""
          << (maps / "wan2022-10x10.map").string()
          << "\"\nstart = [0, 0]\ngoal = [9, 9]\n"
             "[[algorithm]]\nid = \"ga\"\ntype = \"ga\"\npop = 10\n"
             "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\npop = 10\n";
    }
    const std::string config = (dir / "c.toml").string();
    REQUIRE(pride::test::run_pride("bench '" + config + "' --jobs 2 --out '" + (dir / "threads.sqlite").string() + "'")
                .status == 0);
    REQUIRE(mpi_bench(2, config, "", dir / "mpi.sqlite", dir / "out") == 0);
    const auto a = rows(dir / "threads.sqlite"), b = rows(dir / "mpi.sqlite");
    CHECK(a.size() == 12);
    CHECK(a == b);
    {
        // One summary line, from rank 0 alone, naming the ranks.
        std::ifstream f(dir / "out");
        std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
        INFO(text);
        CHECK(text.find("12 runs stored in") != std::string::npos);
        CHECK(text.find("2 MPI ranks") != std::string::npos);
        CHECK(text.find("0 runs stored") == std::string::npos);
    }
    // Every rank runs --jobs threads (rank 0 beside handing runs out): the same values again.
    REQUIRE(mpi_bench(2, config, "--jobs 2", dir / "mpi-jobs.sqlite", dir / "out2") == 0);
    CHECK(rows(dir / "mpi-jobs.sqlite") == a);
}

TEST_CASE("bench: mpirun -np 3 on many short runs (the ranks add slots) stores each run once", "[bench][mpi]") {
    // Runs far shorter than a message round trip make the other ranks' threads run dry, so they ask
    // for more slots while rank 0 hands out runs and then says "no more": every run is stored once,
    // with the values of a threaded run, and every rank exits.
    const pride::test::TempDir tmp("pride-mpi3");  // removed with its files at the end of the test
    const fs::path& dir = tmp.path();
    {
        std::ofstream f(dir / "c.toml");
        f << "name = \"short\"\nseeds = 300\n[budget]\nevaluations = 40\n"
             "[[problem]]\nid = \"sphere\"\ntype = \"sphere\"\ndim = 3\n"
             "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\npop = 10\n"
             "[[algorithm]]\nid = \"ga\"\ntype = \"ga\"\npop = 10\n";
    }
    const std::string config = (dir / "c.toml").string();
    REQUIRE(pride::test::run_pride("bench '" + config + "' --jobs 2 --out '" + (dir / "threads.sqlite").string() + "'")
                .status == 0);
    REQUIRE(mpi_bench(3, config, "", dir / "mpi.sqlite", dir / "out") == 0);
    const auto a = rows(dir / "threads.sqlite"), b = rows(dir / "mpi.sqlite");
    CHECK(a.size() == 600);
    CHECK(a == b);
}

TEST_CASE("bench: mpirun -np 4 resumes a store a threaded run began", "[bench][mpi]") {
    // 4 ranks (more than the cores of a small machine) on a store that holds a third of the runs:
    // each missing run is stored once, with the values of a threaded run, and the summary counts
    // the others.
    const pride::test::TempDir tmp("pride-mpi4");  // removed with its files at the end of the test
    const fs::path& dir = tmp.path();
    const auto campaign = [&](const fs::path& file, int seeds) {
        std::ofstream f(file);
        f << "name = \"short\"\nseeds = " << seeds << "\n[budget]\nevaluations = 40\n"
          << "[[problem]]\nid = \"sphere\"\ntype = \"sphere\"\ndim = 3\n"
             "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\npop = 10\n"
             "[[algorithm]]\nid = \"ga\"\ntype = \"ga\"\npop = 10\n";
    };
    campaign(dir / "part.toml", 100);
    campaign(dir / "c.toml", 300);
    const std::string config = (dir / "c.toml").string();
    REQUIRE(pride::test::run_pride("bench '" + config + "' --jobs 2 --out '" + (dir / "threads.sqlite").string() + "'")
                .status == 0);
    REQUIRE(pride::test::run_pride("bench '" + (dir / "part.toml").string() + "' --jobs 1 --out '" +
                                   (dir / "mpi.sqlite").string() + "'")
                .status == 0);
    REQUIRE(mpi_bench(4, config, "", dir / "mpi.sqlite", dir / "out") == 0);
    CHECK(rows(dir / "mpi.sqlite") == rows(dir / "threads.sqlite"));
    std::ifstream f(dir / "out");
    const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    INFO(text);
    CHECK(text.find("400 runs stored in") != std::string::npos);
    CHECK(text.find("200 were there already, 600 in all; 4 MPI ranks") != std::string::npos);
}

TEST_CASE("bench: under mpirun, a store rank 0 cannot open is one error, exit status 2, every rank exits",
          "[bench][mpi]") {
    // The other ranks wait for runs from rank 0: told "no more", they exit, and so does mpirun (it
    // hung, rank 0 waiting in MPI_Finalize for ranks that waited for it).
    const pride::test::TempDir tmp("pride-mpi-bad");  // removed with its files at the end of the test
    const fs::path& dir = tmp.path();
    {
        std::ofstream f(dir / "c.toml");
        f << "name = \"short\"\nseeds = 3\n[budget]\nevaluations = 40\n"
             "[[problem]]\nid = \"sphere\"\ntype = \"sphere\"\ndim = 3\n"
             "[[algorithm]]\nid = \"pso\"\ntype = \"pso\"\npop = 10\n";
    }
    const int status = mpi_bench(3, (dir / "c.toml").string(), "", dir / "no-such-folder" / "s.sqlite", dir / "out");
    REQUIRE(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 2);
    std::ifstream f(dir / "out");
    const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    INFO(text);
    CHECK(text.find("pride: ") != std::string::npos);
    CHECK(text.find("s.sqlite") != std::string::npos);
}
TEST_CASE("bench: mpirun -np 2 sends a constrained run's violation and first feasible evaluation to rank 0",
          "[bench][mpi][constraints]") {
    const pride::test::TempDir tmp("pride-mpi-con");  // removed with its files at the end of the test
    const fs::path& dir = tmp.path();
    {
        std::ofstream f(dir / "c.toml");
        f << "name = \"con\"\nseeds = 3\n[budget]\nevaluations = 300\n"
             "[[problem]]\nid = \"g06\"\ntype = \"cec2006-g06\"\ndim = 2\n"
             "[[algorithm]]\nid = \"de\"\ntype = \"de\"\npop = 10\n";
    }
    const std::string config = (dir / "c.toml").string();
    REQUIRE(pride::test::run_pride("bench '" + config + "' --out '" + (dir / "threads.sqlite").string() + "'").status ==
            0);
    REQUIRE(mpi_bench(2, config, "", dir / "mpi.sqlite", dir / "out") == 0);
    const auto violations = [](const fs::path& store) {
        sqlite3* db = nullptr;
        REQUIRE(sqlite3_open_v2(store.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK);
        sqlite3_stmt* s = nullptr;
        REQUIRE(sqlite3_prepare_v2(db,
                                   "SELECT seed || '|' || feasible || '|' || printf('%!.17g', best) || '|' || "
                                   "printf('%!.17g', best_violation) || '|' || quote(first_feasible) FROM runs ORDER "
                                   "BY seed",
                                   -1, &s, nullptr) == SQLITE_OK);
        std::vector<std::string> out;
        while (sqlite3_step(s) == SQLITE_ROW)
            out.emplace_back(reinterpret_cast<const char*>(sqlite3_column_text(s, 0)));
        sqlite3_finalize(s);
        sqlite3_close(db);
        return out;
    };
    const auto a = violations(dir / "threads.sqlite");
    CHECK(a.size() == 3);
    CHECK(a == violations(dir / "mpi.sqlite"));
    CHECK(rows(dir / "threads.sqlite") == rows(dir / "mpi.sqlite"));
    // Seed 2 ends infeasible (its violation kept), seeds 1 and 3 feasible (their first feasible evaluation).
    REQUIRE(a.size() == 3);
    CHECK(a[1].find("|0|") != std::string::npos);
    CHECK(a[1].substr(a[1].size() - 5) == "|NULL");
    CHECK(a[0].substr(a[0].size() - 4) == "|153");
}
#endif

#include "experiment/campaign/run.hpp"

#include <fmt/format.h>

#include <cstdlib>
#include <string>

#include "experiment/campaign/ledger.hpp"
#include "experiment/campaign/mpi.hpp"
#include "experiment/campaign/pool.hpp"
#include "framework/error.hpp"

#ifdef PRIDE_HAVE_MPI
#include <mpi.h>
#endif

namespace pride::campaign {

int launched_ranks() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"})
        if (const char* v = std::getenv(name)) return std::max(1, std::atoi(v));
    return 1;
}

BenchSummary run_campaign(const Campaign& c, const std::string& store_path, std::int64_t jobs, const Progress& progress,
                          const Stop& stop, const Shard& shard) {
    require(jobs >= 1 && jobs <= 1024, "jobs", "must be in [1, 1024], got " + std::to_string(jobs));
    require(shard.count >= 1 && shard.index >= 1 && shard.index <= shard.count, "shard",
            fmt::format("must be part K of N with 1 <= K <= N, got {}/{}", shard.index, shard.count));
#ifdef PRIDE_HAVE_MPI
    if (launched_ranks() > 1) {  // MPI only under mpirun: a plain run needs no MPI runtime
        int initialised = 0;
        MPI_Initialized(&initialised);
        if (!initialised) {
            // On one machine (every rank local) and with no PML chosen, Open MPI's start-up first
            // opens its cm PML, which probes network layers (PSM, PSM2) for 0.2 s before it settles
            // on ob1 over shared memory; asking for ob1 directly saves that in every rank. A PML
            // the user names (mpirun --mca pml X, or OMPI_MCA_pml) is left as it is.
            const char* local = std::getenv("OMPI_COMM_WORLD_LOCAL_SIZE");
            const char* world = std::getenv("OMPI_COMM_WORLD_SIZE");
            if (local && world && std::string(local) == world) ::setenv("OMPI_MCA_pml", "ob1", 0);
            int provided = 0;  // only the main thread calls MPI; the others only run
            MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
        }
        struct Finalise {
            ~Finalise() {
                int finalised = 0;
                MPI_Finalized(&finalised);
                if (!finalised) MPI_Finalize();
            }
        } finalise;
        int rank = 0, size = 1;
        MPI_Comm_rank(MPI_COMM_WORLD, &rank);
        MPI_Comm_size(MPI_COMM_WORLD, &size);
        if (size > 1) {
            if (rank != 0) {
                mpi_worker(c, jobs, shard);
                BenchSummary none;
                none.ranks = 0;  // a worker rank: rank 0 reports
                return none;
            }
            Remotes remotes(size);
            try {
                Ledger ledger(c, store_path, 4 * static_cast<std::size_t>(jobs) * static_cast<std::size_t>(size),
                              shard);
                BenchSummary s = run_local(ledger, jobs, progress, stop, &remotes);
                s.ranks = size;
                return s;
            } catch (...) {
                // A store that cannot be opened, say: the other ranks wait for runs, and
                // MPI_Finalize would wait for them. Told "no more", they finish (a second call
                // finds every rank closed).
                remotes.release_all();
                throw;
            }
        }
    }
#else
    require(launched_ranks() == 1, "pride bench",
            "this pride was built without MPI, so under mpirun every rank would run the whole campaign; install "
            "Open MPI (bash scripts/deps.sh) and rebuild with `cmake -S . -B build -DPRIDE_MPI=ON && cmake "
            "--build build` (a build configured before Open MPI was installed keeps PRIDE_MPI off until told)");
#endif
    // Claims in batches of 4 runs per thread: one transaction for several short runs, and still
    // small enough for two processes on one store to share the work evenly.
    Ledger ledger(c, store_path, 4 * static_cast<std::size_t>(jobs), shard);
    return run_local(ledger, jobs, progress, stop, nullptr);
}

}  // namespace pride::campaign

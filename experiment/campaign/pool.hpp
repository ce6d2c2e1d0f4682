#pragma once
// The local pool: a campaign's runs on threads of this process, committed from one thread.
#include <cstdint>

#include "experiment/campaign/ledger.hpp"
#include "experiment/campaign/mpi.hpp"
#include "experiment/campaign/run.hpp"

namespace pride::campaign {

/// Runs the ledger's runs on `jobs` threads of this process (and the other MPI ranks, when
/// `remotes`), committing what finishes in batches from this thread alone, so that the commits
/// never hold up the runs.
BenchSummary run_local(Ledger& ledger, std::int64_t jobs, const Progress& progress, const Stop& stop, Remotes* remotes);

}  // namespace pride::campaign

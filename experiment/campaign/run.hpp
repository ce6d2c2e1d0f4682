#pragma once
// Running a prepared campaign: every run not yet stored, on threads or MPI ranks, committed to the
// store in batches, stoppable by a signal with nothing lost.
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>

#include "experiment/campaign/campaign.hpp"

namespace pride::campaign {

struct BenchSummary {
    std::size_t stored = 0;   // runs stored by this call
    std::size_t already = 0;  // runs of the campaign the store held before
    std::size_t total = 0;    // runs of the campaign
    std::size_t others = 0;   // runs left to another pride bench that is running them on the same store
    int ranks = 1;            // MPI ranks (1: threads only; 0: an MPI rank other than 0, which reports nothing)
};

/// Called from the storing thread after each stored batch: (runs in the store, runs in all, seconds).
using Progress = std::function<void(std::size_t done, std::size_t total, double seconds)>;

/// A campaign stopped by a signal (SIGINT, SIGTERM): what the store holds, and which signal.
struct Interrupted : std::runtime_error {
    Interrupted(std::size_t in_store, std::size_t total, int signal)
        : std::runtime_error("interrupted"), in_store(in_store), total(total), signal(signal) {}
    std::size_t in_store, total;
    int signal;
};

/// How a caller stops a campaign: `signal` is polled (every few milliseconds) by the storing
/// thread; once it is non-zero, the finished runs are committed, the claims of the running ones
/// dropped, the store closed, and `on_stop` called with what the store holds. `on_stop` may end
/// the process (the command line does, abandoning the running runs); when it returns, the
/// running runs are waited for (not stored) and Interrupted is thrown.
struct Stop {
    const std::atomic<int>* signal = nullptr;
    std::function<void(const Interrupted&)> on_stop;
};

/// Part `index` of `count` of a campaign's runs (`pride bench --shard K/N`): the runs at positions
/// index - 1, index - 1 + count, ... of its ordered list (all_tasks: problems, then algorithms,
/// then seeds), so that the parts differ by one run at most and share each problem's and
/// algorithm's runs. A run depends only on (problem, algorithm, seed): the parts, run apart into
/// stores of their own and merged, are the store of the whole campaign. {1, 1}: every run.
struct Shard {
    std::int64_t index = 1;
    std::int64_t count = 1;
};

/// Runs every (problem, algorithm, seed) not yet in `store` on `jobs` threads (or, under mpirun
/// in an MPI build, over the ranks) and commits finished runs in batches. Several processes may
/// run one campaign on one store at once: each takes runs the others have not (claims in the
/// store). The campaign must be prepared. Store errors (a read-only or full file system, a store
/// deleted meanwhile) are InputErrors naming the file.
/// With `shard`, only that part of the runs is run and counted (a store may hold any runs of
/// the campaign: the others' parts, or none).
BenchSummary run_campaign(const Campaign& campaign, const std::string& store, std::int64_t jobs,
                          const Progress& progress = {}, const Stop& stop = {}, const Shard& shard = {});

/// The number of processes mpirun (Open MPI, or a PMI launcher) started, or 1 outside mpirun.
int launched_ranks();
}  // namespace pride::campaign

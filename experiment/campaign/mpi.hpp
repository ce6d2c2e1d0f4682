#pragma once
// Runs spread over MPI ranks (in a build with PRIDE_MPI): rank 0 owns the store and hands out task
// numbers; the other ranks run them and send the records back. Values equal those of a threaded
// run: a run depends only on its task. Without MPI, Remotes is an empty stand-in.
#include <cstddef>
#include <cstdint>
#include <list>
#include <string>
#include <vector>

#include "experiment/campaign/campaign.hpp"
#include "experiment/campaign/run.hpp"
#include "experiment/campaign/run_one.hpp"

#ifdef PRIDE_HAVE_MPI
#include <mpi.h>
#endif

namespace pride::campaign {

#ifdef PRIDE_HAVE_MPI
/// A rank other than 0: `jobs` threads fed by slots, each slot asking rank 0 for a run and sending
/// back its record (which asks for the next) until rank 0 answers "no more" (-1). A thread that
/// finds no run waiting, after its first, adds a slot. Only this thread calls MPI.
/// `shard` as rank 0's (run.hpp): both number the same runs alike.
void mpi_worker(const Campaign& c, std::int64_t jobs, const Shard& shard);

/// Rank 0's view of the other ranks: each has slots; a slot asks for a run, gets one, and sends its
/// record back, which asks for the next. An empty message is a slot asking, so a rank may add
/// slots; rank 0 counts them as they arrive.
class Remotes {
  public:
    explicit Remotes(int size)
        : idle_(static_cast<std::size_t>(size), 0),
          open_(static_cast<std::size_t>(size), 0),
          closed_(static_cast<std::size_t>(size), false) {}

    /// Reads the messages waiting; the records go to `finished`, the slots asking for work to the
    /// idle counts. A failure on a rank is thrown. Receives are non-blocking: a record over the
    /// eager limit needs its sender to act, and a blocking receive would poll a core meanwhile.
    void poll(std::vector<RunRecord>& finished);
    /// The number of slots waiting for a run.
    std::size_t idle() const {
        std::size_t n = 0;
        for (const std::int64_t k : idle_) n += static_cast<std::size_t>(k);
        return n;
    }
    void give(long long task);
    /// Sends "no more" to every slot, waiting for the ones still running (their records dropped),
    /// until every rank has said it adds no slot ("#", sent on its first "no more") and has had
    /// "no more" for each slot it asked for.
    void release_all();

  private:
    struct Received {
        std::string payload;
        int source;
    };
    std::vector<std::int64_t> idle_;  // per rank, slots waiting for a run
    std::vector<std::int64_t> open_;  // per rank, slots not yet told "no more"
    std::vector<bool> closed_;        // per rank, "#" received: it asks for no more slots
    std::list<Received> receiving_;   // receives under way, in order (a list: the buffers stay put)
    std::vector<MPI_Request> requests_;
};

#else
class Remotes {
  public:
    void poll(std::vector<RunRecord>&) {}
    std::size_t idle() const { return 0; }
    void give(long long) {}
    void release_all() {}
};
#endif

}  // namespace pride::campaign

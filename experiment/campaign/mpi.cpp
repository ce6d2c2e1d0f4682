#include "experiment/campaign/mpi.hpp"

#ifdef PRIDE_HAVE_MPI
#include <fmt/format.h>

#include <chrono>
#include <condition_variable>
#include <deque>
#include <list>
#include <mutex>
#include <thread>

#include "experiment/campaign/ledger.hpp"
#include "experiment/campaign/run_one.hpp"
#include "framework/error.hpp"

namespace pride::campaign {
namespace {

// Runs spread over MPI ranks: rank 0 owns the store and hands out task numbers; the other ranks
// run them and send the records back. Values equal those of a threaded run: a run depends only
// on its task.
constexpr int kTagResult = 1, kTagTask = 2;
constexpr char kSep = '\x1f';

std::string serialise(const RunRecord& r) {
    return fmt::format(
        "{1}{0}{2}{0}{3}{0}{4}{0}{5:.17g}{0}{6}{0}{7}{0}{8:.17g}{0}{9}{0}{10}{0}{11}{0}{12}{0}{13}{0}{14}{0}{15}{0}{"
        "16}{0}{17}{0}{18}{0}{19}{0}{20}{0}{21}{0}{22}",
        kSep, r.problem, r.algorithm, r.seed, r.feasible ? 1 : 0, r.best, r.evaluations, r.iterations, r.wall_ms,
        r.optimum ? fmt::format("{:.17g}", *r.optimum) : "", r.solution, r.history, r.history_evaluations,
        r.target_hits, r.encoding, r.trace_targets, r.trace_evaluations,
        r.max_evaluations ? std::to_string(*r.max_evaluations) : "", r.checkpoints, r.path_metrics, r.polyline,
        r.best_violation ? fmt::format("{:.17g}", *r.best_violation) : "",
        r.first_feasible ? std::to_string(*r.first_feasible) : "");
}

RunRecord deserialise(const std::string& text) {
    std::vector<std::string> f;
    for (std::size_t start = 0;;) {
        const std::size_t end = text.find(kSep, start);
        f.push_back(text.substr(start, end == std::string::npos ? std::string::npos : end - start));
        if (end == std::string::npos) break;
        start = end + 1;
    }
    if (f.size() != 22) throw std::runtime_error("MPI: a malformed run record");
    RunRecord r;
    r.problem = f[0];
    r.algorithm = f[1];
    r.seed = std::stoll(f[2]);
    r.feasible = f[3] == "1";
    r.best = std::stod(f[4]);
    r.evaluations = std::stoll(f[5]);
    r.iterations = std::stoll(f[6]);
    r.wall_ms = std::stod(f[7]);
    if (!f[8].empty()) r.optimum = std::stod(f[8]);
    r.solution = f[9];
    r.history = f[10];
    r.history_evaluations = f[11];
    r.target_hits = f[12];
    r.encoding = f[13];
    r.trace_targets = f[14];
    r.trace_evaluations = f[15];
    if (!f[16].empty()) r.max_evaluations = std::stoll(f[16]);
    r.checkpoints = f[17];
    r.path_metrics = f[18];
    r.polyline = f[19];
    if (!f[20].empty()) r.best_violation = std::stod(f[20]);
    if (!f[21].empty()) r.first_feasible = std::stoll(f[21]);
    return r;
}

}  // namespace

/// Runs asked for per thread of a rank other than 0, at first: with two a thread finds its next
/// run waiting instead of idling for a message round trip.
constexpr std::int64_t kSlotsPerThread = 2;
/// At most this many per thread: a rank whose threads still run dry (runs shorter than a round
/// trip, which is up to two 1 ms polls) asks for one more run each time, up to here.
constexpr std::int64_t kMaxSlotsPerThread = 32;

void mpi_worker(const Campaign& c, std::int64_t jobs, const Shard& shard) {
    const std::vector<Task> tasks = all_tasks(c, shard);
    std::mutex mutex;
    std::condition_variable to_workers, to_main;
    std::deque<long long> work;
    std::deque<std::string> results;  // "!..." a failure; else a record
    std::int64_t ran_dry = 0;         // times a thread, after its first run, found no run waiting
    bool done = false;
    auto worker = [&] {
        for (bool first = true;; first = false) {
            long long index = -1;
            {
                std::unique_lock lock(mutex);
                if (work.empty() && !done && !first) {
                    ++ran_dry;
                    to_main.notify_one();
                }
                to_workers.wait(lock, [&] { return done || !work.empty(); });
                if (work.empty()) return;
                index = work.front();
                work.pop_front();
            }
            std::string payload;
            try {
                const Task& t = tasks[static_cast<std::size_t>(index)];
                payload = serialise(run_one(*t.problem, *t.algorithm, c.budget, t.seed));
            } catch (const std::exception& e) {
                payload = std::string("!") + e.what();
            }
            {
                const std::lock_guard lock(mutex);
                results.push_back(std::move(payload));
            }
            to_main.notify_one();
        }
    };
    std::vector<std::thread> pool;
    for (std::int64_t j = 0; j < jobs; ++j) pool.emplace_back(worker);
    std::list<std::string> sending;               // records being sent, in order
    std::vector<MPI_Request> requests;            // their sends
    std::int64_t slots = jobs * kSlotsPerThread;  // asked for so far
    std::int64_t open = 0;                        // slots that have not been told "no more"
    bool finishing = false;                       // rank 0 has said "no more" to a slot
    const auto ask = [&] {
        MPI_Send(nullptr, 0, MPI_CHAR, 0, kTagResult, MPI_COMM_WORLD);
        ++open;
    };
    for (std::int64_t j = 0; j < slots; ++j) ask();
    while (open > 0) {
        for (int flag = 1; flag;) {
            MPI_Iprobe(0, kTagTask, MPI_COMM_WORLD, &flag, MPI_STATUS_IGNORE);
            if (!flag) break;
            long long index = -1;
            MPI_Recv(&index, 1, MPI_LONG_LONG, 0, kTagTask, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            if (index < 0) {
                --open;
                if (!finishing) {  // no slot is added after this, as rank 0 learns from it
                    MPI_Send("#", 1, MPI_CHAR, 0, kTagResult, MPI_COMM_WORLD);
                    finishing = true;
                }
                continue;
            }
            {
                const std::lock_guard lock(mutex);
                work.push_back(index);
            }
            to_workers.notify_one();
        }
        std::deque<std::string> ready;
        std::int64_t dry = 0;
        {
            std::unique_lock lock(mutex);
            to_main.wait_for(lock, std::chrono::milliseconds(1), [&] { return !results.empty() || ran_dry > 0; });
            ready.swap(results);
            std::swap(dry, ran_dry);
        }
        for (; dry > 0 && !finishing && slots < jobs * kMaxSlotsPerThread; --dry, ++slots) ask();
        // Non-blocking: a record over Open MPI's eager limit (a few KB) waits for rank 0 to take it,
        // and a blocking send spent that wait polling, on a core the runs need. The payloads stay
        // alive (a list: no moves) until their sends complete.
        for (auto& payload : ready) {
            sending.push_back(std::move(payload));
            requests.emplace_back();
            MPI_Isend(sending.back().data(), static_cast<int>(sending.back().size()), MPI_CHAR, 0, kTagResult,
                      MPI_COMM_WORLD, &requests.back());
        }
        while (!requests.empty()) {  // the finished sends, oldest first
            int complete = 0;
            MPI_Test(&requests.front(), &complete, MPI_STATUS_IGNORE);
            if (!complete) break;
            requests.erase(requests.begin());
            sending.pop_front();
        }
    }
    if (!requests.empty()) MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
    {
        const std::lock_guard lock(mutex);
        done = true;
    }
    to_workers.notify_all();
    for (auto& t : pool) t.join();
}

void Remotes::poll(std::vector<RunRecord>& finished) {
    for (;;) {
        int flag = 0;
        MPI_Message message;
        MPI_Status status;
        MPI_Improbe(MPI_ANY_SOURCE, kTagResult, MPI_COMM_WORLD, &flag, &message, &status);
        if (!flag) break;
        int length = 0;
        MPI_Get_count(&status, MPI_CHAR, &length);
        receiving_.push_back({std::string(static_cast<std::size_t>(length), '\0'), status.MPI_SOURCE});
        requests_.emplace_back();
        MPI_Imrecv(receiving_.back().payload.data(), length, MPI_CHAR, &message, &requests_.back());
    }
    while (!requests_.empty()) {  // the finished receives, oldest first
        int complete = 0;
        MPI_Test(&requests_.front(), &complete, MPI_STATUS_IGNORE);
        if (!complete) break;
        Received got = std::move(receiving_.front());
        requests_.erase(requests_.begin());
        receiving_.pop_front();
        const auto r = static_cast<std::size_t>(got.source);
        if (got.payload == "#") {  // the rank's last slot has asked already (messages keep their order)
            closed_[r] = true;
            continue;
        }
        ++idle_[r];  // a new slot asking, or a record, which frees its slot for the next run
        if (got.payload.empty()) {
            ++open_[r];
            continue;
        }
        if (got.payload.front() == '!') throw InputError(got.payload.substr(1));
        finished.push_back(deserialise(got.payload));
    }
}

void Remotes::give(long long task) {
    for (std::size_t r = 1; r < idle_.size(); ++r)
        if (idle_[r] > 0) {
            MPI_Send(&task, 1, MPI_LONG_LONG, static_cast<int>(r), kTagTask, MPI_COMM_WORLD);
            --idle_[r];
            return;
        }
}

void Remotes::release_all() {
    std::vector<RunRecord> ignored;
    for (;;) {
        for (std::size_t r = 1; r < idle_.size(); ++r)
            for (; idle_[r] > 0; --idle_[r]) {
                const long long none = -1;
                MPI_Send(&none, 1, MPI_LONG_LONG, static_cast<int>(r), kTagTask, MPI_COMM_WORLD);
                --open_[r];
            }
        bool any_open = false;
        for (std::size_t r = 1; r < open_.size(); ++r) any_open = any_open || open_[r] > 0 || !closed_[r];
        if (!any_open && requests_.empty()) break;
        try {
            poll(ignored);
        } catch (...) {
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
}

}  // namespace pride::campaign
#endif

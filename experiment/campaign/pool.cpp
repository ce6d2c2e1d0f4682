#include "experiment/campaign/pool.hpp"

#include <chrono>
#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <thread>

#include "experiment/campaign/run_one.hpp"

namespace pride::campaign {

using engine::Budget;

BenchSummary run_local(Ledger& ledger, std::int64_t jobs, const Progress& progress, const Stop& stop,
                       Remotes* remotes) {
    const std::vector<Task>& tasks = ledger.tasks();
    const Budget budget = ledger.budget();
    std::mutex mutex;
    std::condition_variable to_workers, to_main;
    std::deque<std::size_t> work;  // claimed, not started
    bool no_more = false, quit = false;
    std::vector<RunRecord> finished;
    std::exception_ptr failure;
    const std::size_t width = static_cast<std::size_t>(jobs);
    // The main thread shares the cores with the runs, so the threads wake it only when it has
    // something to do: the queue below half its length, `kBatch` records waiting, the last runs
    // or a failure; else it wakes every 20 ms to commit. (Waking it per run cost 14 % more CPU at
    // --jobs 2 on runs of 1 ms: bench/campaign_scaling.toml.) The queue keeps 4 runs per thread,
    // and a thread that finds it empty lengthens it by one run per thread, up to 64: the main
    // thread is late when a commit waits for the disk (a checkpoint's syncs, 10-20 ms, idled
    // both threads of a campaign of 1 ms runs) or when other processes hold the cores.
    constexpr std::size_t kBatch = 16;
    std::size_t queue_length = 4 * width;  // guarded by `mutex`
    const std::size_t longest_queue = 64 * width;
    auto worker = [&] {
        for (bool first = true;; first = false) {
            std::size_t i = 0;
            {
                std::unique_lock lock(mutex);
                if (work.empty() && !no_more && !quit && !first)
                    queue_length = std::min(longest_queue, queue_length + width);
                to_workers.wait(lock, [&] { return quit || !work.empty() || no_more; });
                if (quit || work.empty()) return;
                i = work.front();
                work.pop_front();
                if (2 * work.size() < queue_length && !no_more) to_main.notify_one();  // the main thread claims more
            }
            bool wake = true;
            try {
                RunRecord r = run_one(*tasks[i].problem, *tasks[i].algorithm, budget, tasks[i].seed);
                const std::lock_guard lock(mutex);
                finished.push_back(std::move(r));
                wake = finished.size() >= kBatch || (no_more && work.empty());
            } catch (...) {
                const std::lock_guard lock(mutex);
                if (!failure) failure = std::current_exception();
                quit = true;
            }
            if (wake) {
                to_main.notify_one();
                to_workers.notify_all();
            }
        }
    };
    std::vector<std::thread> pool;
    for (std::size_t j = 0; j < std::min(width, ledger.todo()); ++j) pool.emplace_back(worker);
    const auto shut_down = [&] {
        {
            const std::lock_guard lock(mutex);
            quit = true;
        }
        to_workers.notify_all();
        for (auto& t : pool) t.join();
        pool.clear();
    };

    if (pool.empty() && !remotes) return ledger.finish();
    const auto start = std::chrono::steady_clock::now();
    std::size_t in_flight = 0;  // handed out (here or to a rank), not finished
    bool exhausted = false;
    std::deque<std::size_t> spare;   // claimed for the ranks, not yet given
    std::vector<RunRecord> waiting;  // finished, not yet committed
    auto oldest = std::chrono::steady_clock::now();
    try {
        for (;;) {
            std::vector<RunRecord> batch;
            if (remotes) remotes->poll(batch);
            // Keep the queue full for the threads, and a run for each idle slot of a rank.
            std::size_t queued = 0, length = 0;
            {
                const std::lock_guard lock(mutex);
                queued = work.size();
                length = queue_length;
            }
            const std::size_t wanted_here = pool.empty() ? 0 : (queued < length ? length - queued : 0);
            const std::size_t wanted_there = remotes ? remotes->idle() : 0;
            while (!exhausted && spare.size() < wanted_here + wanted_there) {
                const auto got = ledger.take();
                if (got.empty()) exhausted = true;
                spare.insert(spare.end(), got.begin(), got.end());
            }
            for (std::size_t k = 0; k < wanted_there && !spare.empty(); ++k) {
                remotes->give(static_cast<long long>(spare.front()));
                spare.pop_front();
                ++in_flight;
            }
            {
                const std::lock_guard lock(mutex);
                for (std::size_t k = 0; k < wanted_here && !spare.empty(); ++k) {
                    work.push_back(spare.front());
                    spare.pop_front();
                    ++in_flight;
                }
                if (exhausted && spare.empty()) no_more = true;
            }
            if (remotes && exhausted && spare.empty()) {
                // The last runs: a rank waiting for one takes this process's queued runs (the last
                // queued first), which the threads here would start only after their present ones.
                std::vector<std::size_t> moved;
                {
                    const std::lock_guard lock(mutex);
                    for (std::size_t k = remotes->idle(); k > 0 && !work.empty(); --k) {
                        moved.push_back(work.back());
                        work.pop_back();
                    }
                }
                for (const std::size_t task : moved) remotes->give(static_cast<long long>(task));
            }
            to_workers.notify_all();
            {
                std::unique_lock lock(mutex);
                // Ranks are polled every millisecond; threads wake this one themselves.
                to_main.wait_for(lock, remotes ? std::chrono::milliseconds(1) : std::chrono::milliseconds(20), [&] {
                    return finished.size() >= kBatch || failure || (no_more && work.empty() && !finished.empty()) ||
                           (!exhausted && 2 * work.size() < queue_length && !pool.empty());
                });
                for (auto& r : finished) batch.push_back(std::move(r));
                finished.clear();
            }
            in_flight -= batch.size();
            if (!batch.empty() && waiting.empty()) oldest = std::chrono::steady_clock::now();
            for (auto& r : batch) waiting.push_back(std::move(r));
            // A transaction per 20 ms (or per kBatch runs): short runs do not wait for one commit
            // each, the commits take a small share of the cores the runs use, and a finished run
            // is in the store within 20 ms.
            const bool last_ones = exhausted && spare.empty() && in_flight == 0;
            if (!waiting.empty() && (waiting.size() >= kBatch || last_ones ||
                                     std::chrono::steady_clock::now() - oldest >= std::chrono::milliseconds(20))) {
                ledger.commit(waiting);
                waiting.clear();
                if (progress)
                    progress(ledger.in_store(), tasks.size(),
                             std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
            }
            if (stop.signal && stop.signal->load() != 0) {
                std::vector<RunRecord> last = std::move(waiting);  // finished, not yet committed
                waiting.clear();
                {
                    const std::lock_guard lock(mutex);
                    quit = true;  // the queued runs are not started
                    for (auto& r : finished) last.push_back(std::move(r));
                    finished.clear();
                }
                ledger.commit(last);
                const Interrupted stopped(ledger.in_store(), tasks.size(), stop.signal->load());
                ledger.close();
                if (stop.on_stop) stop.on_stop(stopped);
                shut_down();
                if (remotes) remotes->release_all();
                throw stopped;
            }
            {
                const std::lock_guard lock(mutex);
                if (failure) break;
            }
            if (exhausted && spare.empty() && in_flight == 0) break;
        }
    } catch (const Interrupted&) {
        throw;
    } catch (...) {
        shut_down();
        if (remotes) remotes->release_all();
        throw;
    }
    shut_down();
    if (remotes) remotes->release_all();
    {
        // What finished before a failure is kept.
        for (auto& r : finished) waiting.push_back(std::move(r));
        ledger.commit(waiting);
    }
    if (failure) std::rethrow_exception(failure);
    return ledger.finish();
}

}  // namespace pride::campaign

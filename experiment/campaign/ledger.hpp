#pragma once
// The runs of a campaign as one process owns them: the tasks every process numbers alike, and the
// ledger of what the store still lacks and what this process has committed.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "experiment/campaign/identity.hpp"
#include "experiment/campaign/run.hpp"
#include "experiment/campaign/run_one.hpp"
#include "experiment/storage/writer.hpp"
#include "framework/error.hpp"

namespace pride::campaign {

struct Task {
    const CampaignProblem* problem;
    const CampaignAlgorithm* algorithm;
    std::int64_t seed;
};

/// Every (problem, algorithm, seed) of the campaign, in a fixed order that every process shares,
/// or of it every shard.count-th from the shard.index-th (run.hpp: Shard).
inline std::vector<Task> all_tasks(const Campaign& c, const Shard& shard = {}) {
    std::vector<Task> tasks;
    const auto count = static_cast<std::uint64_t>(shard.count), part = static_cast<std::uint64_t>(shard.index - 1);
    tasks.reserve(c.problems.size() * c.algorithms.size() * static_cast<std::size_t>(c.seeds) / count + 1);
    std::uint64_t position = 0;
    for (const auto& p : c.problems)
        for (const auto& a : c.algorithms)
            for (std::int64_t k = 0; k < c.seeds; ++k)
                if (position++ % count == part) tasks.push_back({&p, &a, seed_at(c, k)});
    return tasks;
}

/// The process that owns the store: the runs still to take (claimed from the store in batches,
/// so that other processes on the same store take others), and the commits of finished ones.
class Ledger {
  public:
    Ledger(const Campaign& c, const std::string& path, std::size_t batch, const Shard& shard = {})
        : tasks_(all_tasks(c, shard)), budget_(c.budget), batch_(std::max<std::size_t>(batch, 1)) {
        store_.emplace(path);
        store_->claim(store_rows(c));
        // The campaign's runs the store holds (a grown store may hold runs of other seeds,
        // problems or algorithms too, and a shard's the other shards' runs: they stay, and are
        // not counted here).
        const auto done = store_->done();
        for (std::size_t i = 0; i < tasks_.size(); ++i) {
            storage::RunKey key{tasks_[i].problem->id, tasks_[i].algorithm->id, tasks_[i].seed};
            if (done.count(key)) {
                ++already_;
                continue;
            }
            todo_.push_back(i);
            keys_.push_back(std::move(key));
        }
    }

    const std::vector<Task>& tasks() const { return tasks_; }
    const engine::Budget& budget() const { return budget_; }
    std::size_t todo() const { return todo_.size(); }
    std::size_t in_store() const { return already_ + stored_; }

    /// The next runs to do (task numbers), claimed in the store; empty when none is left that
    /// no live process holds.
    std::vector<std::size_t> take() {
        try {
            return take_from_store();
        } catch (const InputError& e) {
            throw with_count(e);
        }
    }

    void commit(const std::vector<RunRecord>& records) {
        try {
            stored_ += store_->insert(records);
        } catch (const InputError& e) {
            throw with_count(e);
        }
    }

  private:
    /// A store error with what the store holds and how to go on.
    InputError with_count(const InputError& e) const {
        return InputError(fmt::format("{} ({} runs are stored and kept; run the same command again to resume)",
                                      e.what(), in_store()));
    }

    std::vector<std::size_t> take_from_store() {
        for (;;) {
            std::vector<std::size_t> out;
            for (const std::size_t at : store_->take(keys_, cursor_, batch_, busy_)) out.push_back(todo_[at]);
            if (!out.empty() || cursor_ < keys_.size()) return out;
            // Everything looked at: the runs other processes hold are retried once such a
            // process has died (its claims dropped).
            if (busy_.empty() || !store_->drop_dead_claims()) return out;
            std::vector<std::size_t> todo;
            std::vector<storage::RunKey> keys;
            for (const std::size_t at : busy_) {
                todo.push_back(todo_[at]);
                keys.push_back(keys_[at]);
            }
            todo_ = std::move(todo);
            keys_ = std::move(keys);
            busy_.clear();
            cursor_ = 0;
        }
    }

  public:
    /// The summary once every run is done; throws when the store's file went away meanwhile.
    BenchSummary finish() {
        store_->check_same_file();
        // This list's runs the store lacks: not the store's count, which holds runs of other
        // shards, seeds, problems and algorithms too.
        const auto done = store_->done();
        std::size_t missing = 0;
        for (const Task& t : tasks_)
            if (!done.count(storage::RunKey{t.problem->id, t.algorithm->id, t.seed})) ++missing;
        return {stored_, already_, tasks_.size(), missing, 1};
    }

    /// Drops the claims of the runs not finished, and closes the store.
    void close() { store_.reset(); }

  private:
    std::vector<Task> tasks_;
    engine::Budget budget_;
    std::optional<storage::Writer> store_;
    std::size_t batch_;
    std::size_t already_ = 0, stored_ = 0;
    std::vector<std::size_t> todo_;      // task numbers not stored when this process started
    std::vector<storage::RunKey> keys_;  // their keys
    std::size_t cursor_ = 0;             // keys_[cursor_...] not looked at yet
    std::vector<std::size_t> busy_;      // positions in keys_ another process held
};

}  // namespace pride::campaign

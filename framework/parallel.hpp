#pragma once
// Parallel evaluation of one population inside one run: a batch of points is cut into
// as many contiguous slices as there are threads, and slice k is evaluated by copy k of the
// problem (problems keep scratch buffers, so each thread owns a copy). Values land in the caller's
// span at their column's place, and the evaluation guard (RunState::evaluate_columns) then counts
// them, sanitises them and looks for a new best in column order on the run's thread: the result
// is bit-identical to one thread whenever a point's value depends on the point alone. Problems
// with noise (Reseedable) draw their noise in evaluation order and are refused at compile time.
//
// The pool is made once per run (threads - 1 workers; the run's own thread evaluates slice 0) and
// woken once per batch: no allocation, no std::function and no lock per evaluation.
#include <algorithm>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <memory>
#include <mutex>
#include <span>
#include <thread>
#include <utility>
#include <vector>

#include "framework/problem.hpp"

namespace pride {

/// threads - 1 workers that run one task, `task(slice)` for slices 1..threads-1, per call of
/// run(); the caller runs slice 0 itself. The first exception of a batch is rethrown by run().
class EvaluationPool {
  public:
    explicit EvaluationPool(std::size_t threads) : errors_(threads) {
        workers_.reserve(threads > 0 ? threads - 1 : 0);
        for (std::size_t k = 1; k < threads; ++k) workers_.emplace_back([this, k] { work(k); });
    }
    EvaluationPool(const EvaluationPool&) = delete;
    EvaluationPool& operator=(const EvaluationPool&) = delete;
    ~EvaluationPool() {
        {
            std::lock_guard lock(mutex_);
            stop_ = true;
        }
        wake_.notify_all();
        // std::jthread joins on destruction.
    }

    std::size_t threads() const noexcept { return workers_.size() + 1; }

    /// Runs task(k) for every slice k in 0..threads-1 (slice 0 on this thread) and returns when
    /// all are done. `Task` is called through a plain function pointer: one indirect call per slice.
    template <class Task>
    void run(Task& task) {
        {
            std::lock_guard lock(mutex_);
            call_ = [](void* t, std::size_t k) { (*static_cast<Task*>(t))(k); };
            context_ = &task;
            pending_ = workers_.size();
            ++generation_;
        }
        wake_.notify_all();
        try {
            task(0);
        } catch (...) {
            errors_[0] = std::current_exception();
        }
        std::unique_lock lock(mutex_);
        done_.wait(lock, [&] { return pending_ == 0; });
        std::exception_ptr first;
        for (auto& e : errors_)
            if (auto taken = std::exchange(e, nullptr); taken && !first) first = taken;
        if (first) std::rethrow_exception(first);
    }

  private:
    void work(std::size_t k) {
        std::uint64_t seen = 0;
        for (;;) {
            void (*call)(void*, std::size_t) = nullptr;
            void* context = nullptr;
            {
                std::unique_lock lock(mutex_);
                wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
                if (stop_) return;
                seen = generation_;
                call = call_;
                context = context_;
            }
            try {
                call(context, k);
            } catch (...) {
                errors_[k] = std::current_exception();
            }
            std::lock_guard lock(mutex_);
            if (--pending_ == 0) done_.notify_one();
        }
    }

    std::mutex mutex_;
    std::condition_variable wake_, done_;
    std::uint64_t generation_ = 0;
    std::size_t pending_ = 0;
    bool stop_ = false;
    void (*call_)(void*, std::size_t) = nullptr;
    void* context_ = nullptr;
    std::vector<std::exception_ptr> errors_;  // one per slice, each written by its own thread only
    std::vector<std::jthread> workers_;       // last: joined before the members above go
};

/// One copy of `P` per thread and a pool: evaluate_batch(points, values) evaluates slice k of the
/// columns with copy k. Copies of a ParallelBatch share the copies and the pool, so one run
/// (one thread calling at a time) may copy it freely; two runs must not share one.
template <BoxProblem P>
requires(!Reseedable<P>) class ParallelBatch {
  public:
    ParallelBatch(const P& problem, std::size_t threads)
        : shared_(std::make_shared<Shared>(problem, std::max<std::size_t>(threads, 1))) {}

    std::size_t threads() const noexcept { return shared_->pool.threads(); }
    /// Copy 0, for what is not a batch (dimension, box, suggestions, a single evaluation).
    P& first() noexcept { return shared_->copies.front(); }
    const P& first() const noexcept { return shared_->copies.front(); }

    double evaluate(std::span<const double> x) { return first().evaluate(x); }

    void evaluate_batch(MatrixView points, std::span<double> values) {
        const Eigen::Index n = points.cols();
        const auto slices = static_cast<Eigen::Index>(threads());
        if (n < 2 || slices < 2) {
            evaluate_slice(first(), points, values, 0, n);
            return;
        }
        // Slice k: columns [k n / T, (k + 1) n / T), contiguous, as even as they come.
        auto task = [&](std::size_t k) {
            const auto ik = static_cast<Eigen::Index>(k);
            evaluate_slice(shared_->copies[k], points, values, ik * n / slices, (ik + 1) * n / slices);
        };
        shared_->pool.run(task);
    }

  private:
    static void evaluate_slice(P& p, const MatrixView& points, std::span<double> values, Eigen::Index from,
                               Eigen::Index to) {
        if (from >= to) return;
        if constexpr (BatchBoxProblem<P>) {
            p.evaluate_batch(points.middleCols(from, to - from),
                             values.subspan(static_cast<std::size_t>(from), static_cast<std::size_t>(to - from)));
        } else {
            const auto rows = static_cast<std::size_t>(points.rows());
            for (Eigen::Index j = from; j < to; ++j)
                values[static_cast<std::size_t>(j)] = p.evaluate(std::span<const double>(points.col(j).data(), rows));
        }
    }

    struct Shared {
        Shared(const P& problem, std::size_t threads) : copies(threads, problem), pool(threads) {}
        std::vector<P> copies;
        EvaluationPool pool;
    };
    std::shared_ptr<Shared> shared_;
};

}  // namespace pride

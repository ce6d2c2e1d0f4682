#pragma once
// The least of 7 timings of about 20 ms each, in ns per item: what bench programs report for
// evaluation costs. Timed by the calling thread's CPU clock, so that the time the thread spends
// descheduled on a shared machine is not counted (the minimum then removes most of what is left:
// caches and the core shared with other processes).
#include <algorithm>
#include <chrono>
#include <ctime>

namespace pride::bench {

/// `pass` handles `count` items per call; it is first called once to size the timings.
template <class Pass>
double best_ns(Pass&& pass, long count) {
    const auto now = [] {
        timespec t{};
        clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
        return static_cast<double>(t.tv_sec) * 1e9 + static_cast<double>(t.tv_nsec);
    };
    double start = now();
    pass();
    const double one = now() - start;
    const long passes = std::max(1L, static_cast<long>(2e7 / std::max(one, 1.0)));
    double best = 1e300;
    for (int r = 0; r < 7; ++r) {
        start = now();
        for (long k = 0; k < passes; ++k) pass();
        const double ns = now() - start;
        best = std::min(best, ns / static_cast<double>(passes * count));
    }
    return best;
}

/// The least wall time of `rounds` calls of `batch`, in ns, divided by `per` (what `batch` handles).
template <class F>
double least_ns(int rounds, double per, F&& batch) {
    using Clock = std::chrono::steady_clock;
    double best = 1e300;
    for (int r = 0; r < rounds; ++r) {
        const auto start = Clock::now();
        batch();
        best = std::min(best, std::chrono::duration<double, std::nano>(Clock::now() - start).count());
    }
    return best / per;
}

}  // namespace pride::bench

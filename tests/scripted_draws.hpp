#pragma once
// Scripted draws for operator tests: uniform(), normal() and below(n) return the next value of
// their own queue, so that a test can feed an operator the numbers of a worked example (the DE
// and WOA tests). An empty queue or a below(n) value not under n fails the test.
#include <catch2/catch.hpp>

#include <cstdint>
#include <deque>

namespace pride::test {

struct ScriptedDraws {
    std::deque<double> u, z;
    std::deque<std::uint64_t> k;
    double uniform() { return next(u); }
    double normal() { return next(z); }
    std::uint64_t below(std::uint64_t n) {
        const std::uint64_t v = next(k);
        REQUIRE(v < n);
        return v;
    }
    /// Every scripted value was drawn.
    bool spent() const { return u.empty() && z.empty() && k.empty(); }

  private:
    template <class T>
    static T next(std::deque<T>& queue) {
        REQUIRE(!queue.empty());
        const T v = queue.front();
        queue.pop_front();
        return v;
    }
};

}  // namespace pride::test

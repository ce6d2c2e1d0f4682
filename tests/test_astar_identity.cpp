// A* must stay bit for bit what it was when it was made faster: the same paths (so the
// same tie-breaking), the same lengths to the last bit and the same number of expansions, on the
// Moving AI scenarios and on random maps with windows and corner cutting. The reference digests
// were taken with the A* of main at 8834815, before the speed work.
#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "framework/random.hpp"
#include "problems/grid/map.hpp"
#include "problems/grid/map_io.hpp"
#include "problems/grid/path.hpp"
#include "problems/grid/planners/astar.hpp"
#include "tests/grid_support.hpp"

using namespace pride::grid;

namespace {

/// FNV-1a over 64-bit words.
struct Digest {
    std::uint64_t h = 14695981039346656037ull;
    void add(std::uint64_t v) noexcept {
        for (int i = 0; i < 8; ++i) {
            h ^= (v >> (8 * i)) & 0xff;
            h *= 1099511628211ull;
        }
    }
};

/// One query into the digest: its length's bits, its path cell by cell, its expansions.
void record(Digest& d, AStar& astar, const GridMap& map, Cell s, Cell g, const Window* window, bool cc) {
    Path path;
    const std::int64_t before = astar.expansions();
    const double length = astar.search(map, s, g, &path, window, cc);
    d.add(std::bit_cast<std::uint64_t>(length));
    d.add(path.size());
    for (const Cell c : path) d.add(static_cast<std::uint64_t>(c.y) << 32 | static_cast<std::uint32_t>(c.x));
    d.add(static_cast<std::uint64_t>(astar.expansions() - before));
}

}  // namespace

TEST_CASE("A* paths, lengths and expansions on the Moving AI scenarios are those of 8834815", "[grid][astar]") {
    // Every 10th line of every scenario file (lines 0, 10, 20, ...), files in name order, one
    // AStar for all (the generation stamps carry over between maps of different sizes).
    namespace fs = std::filesystem;
    const auto data = pride::test::shared_data("movingai", "Moving AI maps and scenarios");
    if (!data) return;
    const fs::path dir = *data;
    const std::vector<fs::path> scenarios = pride::test::movingai_scenarios(dir);
    REQUIRE(scenarios.size() == 16);
    AStar astar;
    Digest d;
    std::size_t queries = 0;
    for (const auto& scen : scenarios) {
        const auto entries = read_scenario(scen.string());
        const GridMap map = read_map((dir / entries.front().map).string());
        for (std::size_t i = 0; i < entries.size(); i += 10, ++queries)
            record(d, astar, map, entries[i].start, entries[i].goal, nullptr, false);
    }
    CHECK(queries == 810);
    CHECK(astar.expansions() == 2875910);
    CHECK(d.h == 0xcf68f81b36f6ed14ull);
}

TEST_CASE("A* on random maps with windows and corner cutting is that of 8834815", "[grid][astar]") {
    // 400 maps from 1 x 1 to 40 x 40 cells with 0 to 45 % obstacles; per map 6 queries: strict
    // and corner cutting, whole map and a random window (which may leave out either end).
    pride::Rng rng(15);
    AStar astar;
    Digest d;
    for (int m = 0; m < 400; ++m) {
        const int w = 1 + static_cast<int>(rng.below(40)), h = 1 + static_cast<int>(rng.below(40));
        const double density = 0.45 * rng.uniform();
        std::vector<std::uint8_t> blocked(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
        for (auto& b : blocked) b = rng.uniform() < density ? 1 : 0;
        const GridMap map(w, h, std::move(blocked), "random");
        for (int q = 0; q < 6; ++q) {
            const auto cell = [&] {
                return Cell{static_cast<int>(rng.below(static_cast<std::uint64_t>(w))),
                            static_cast<int>(rng.below(static_cast<std::uint64_t>(h)))};
            };
            const Cell s = cell(), g = cell(), a = cell(), b = cell();
            const Window window{std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y)};
            record(d, astar, map, s, g, q >= 4 ? &window : nullptr, q % 2 == 1);
        }
    }
    CHECK(astar.expansions() == 27175);
    CHECK(d.h == 0x19c33dba23825683ull);
}

TEST_CASE("A*'s key rounding equals std::llround where the keys need it", "[grid][astar]") {
    // round_half_up replaced std::llround in the keys; it must agree on 0 and [0.5, 2^52): at the
    // half-integers, one ulp either side of them, at binade edges, and on random values.
    std::vector<double> xs{0.0, 0.5, 1.0, 1.5, 2.5, 0x1p51, 0x1p51 + 0.5, 0x1p52 - 0.5, 0x1p52 - 1.0};
    for (double k = 0.0; k < 64.0; k += 1.0) {
        const double half = k + 0.5, edge = std::ldexp(1.0, static_cast<int>(k) % 52);
        for (const double x : {half, std::nextafter(half, 0.0), std::nextafter(half, 1e300), edge,
                               std::nextafter(edge, 0.0), edge - 0.5, std::nextafter(edge - 0.5, 0.0)})
            if (x == 0.0 || (x >= 0.5 && x < 0x1p52)) xs.push_back(x);
    }
    pride::Rng rng(2);
    for (int i = 0; i < 100000; ++i) xs.push_back(0.5 + std::ldexp(rng.uniform(), static_cast<int>(rng.below(52))));
    for (const double x : xs) {
        INFO(x);
        CHECK(round_half_up(x) == static_cast<std::uint64_t>(std::llround(x)));
    }
}

namespace {

/// The radix heap A* used before OpenList, kept as the reference for monotone keys
/// (no key below the last popped), where its order is "least key, then the last push".
class OldRadixHeap {
  public:
    bool empty() const noexcept { return size_ == 0; }
    void push(OpenNode n) {
        const std::size_t b = bucket(n.key);
        buckets_[b].push_back(n);
        if (b > 0) used_ |= std::uint64_t{1} << (b - 1);
        ++size_;
    }
    OpenNode pop() {
        if (buckets_[0].empty()) {
            const std::size_t i = 1 + static_cast<std::size_t>(std::countr_zero(used_));
            std::uint64_t least = buckets_[i].front().key;
            for (const OpenNode& n : buckets_[i]) least = std::min(least, n.key);
            last_ = least;
            used_ &= ~(std::uint64_t{1} << (i - 1));
            std::vector<OpenNode> moved;
            moved.swap(buckets_[i]);
            for (const OpenNode& n : moved) {
                const std::size_t b = bucket(n.key);
                buckets_[b].push_back(n);
                if (b > 0) used_ |= std::uint64_t{1} << (b - 1);
            }
        }
        const OpenNode n = buckets_[0].back();
        buckets_[0].pop_back();
        --size_;
        return n;
    }

  private:
    std::size_t bucket(std::uint64_t key) const noexcept {
        return key == last_ ? 0 : 64 - static_cast<std::size_t>(std::countl_zero(key ^ last_));
    }
    std::vector<OpenNode> buckets_[65];
    std::uint64_t used_ = 0, last_ = 0;
    std::size_t size_ = 0;
};

/// The order OpenList must keep, by definition: least key, then the node pushed last.
class ExactOrder {
  public:
    bool empty() const noexcept { return nodes_.empty(); }
    void push(OpenNode n) { nodes_.push_back(n); }
    OpenNode pop() {
        std::size_t best = 0;
        for (std::size_t i = 1; i < nodes_.size(); ++i)
            if (nodes_[i].key <= nodes_[best].key) best = i;  // later pushes win ties
        const OpenNode n = nodes_[best];
        nodes_.erase(nodes_.begin() + static_cast<std::ptrdiff_t>(best));
        return n;
    }

  private:
    std::vector<OpenNode> nodes_;
};

constexpr std::uint64_t kBucket = std::uint64_t{1} << OpenList::kShift;  // keys per bucket

/// A key near `base`: mostly a few buckets above (A*'s case), with many equal keys, and with the
/// given odds a key below `base` (by a hair or by many buckets) or far beyond the ring.
std::uint64_t draw_key(pride::Rng& rng, std::uint64_t base, double below, double beyond) {
    const double u = rng.uniform();
    if (u < below) {
        const std::uint64_t drop = rng.uniform() < 0.5 ? rng.below(4) : rng.below(2000) * kBucket;
        return base > drop ? base - drop : 0;
    }
    if (u < below + beyond) return base + (OpenList::kSlots + rng.below(3 * OpenList::kSlots)) * kBucket;
    const std::uint64_t up = rng.below(8) == 0 ? 0 : rng.below(4 * kBucket);
    return base + (up & ~static_cast<std::uint64_t>(rng.below(2) == 0 ? 0xff : 0));  // coarse steps make ties
}

/// Pushes and pops interleaved on `list` and `ref`, the keys drawn near the last popped; every pop
/// must give the same node (its index names its push).
template <class Ref>
void compare(pride::Rng& rng, OpenList& list, Ref& ref, double below, double beyond, int steps) {
    std::uint32_t pushed = 0;
    std::uint64_t last = 1ull << 40;
    for (int i = 0; i < steps; ++i) {
        if (list.empty() || rng.uniform() < 0.55) {
            const OpenNode n{draw_key(rng, last, below, beyond), pushed++};
            list.push(n);
            ref.push(n);
        } else {
            const OpenNode a = list.pop(), b = ref.pop();
            REQUIRE(a.index == b.index);
            REQUIRE(a.key == b.key);
            last = a.key;
        }
    }
    while (!list.empty()) {
        REQUIRE(!ref.empty());
        const OpenNode a = list.pop(), b = ref.pop();
        REQUIRE(a.index == b.index);
    }
    CHECK(ref.empty());
}

}  // namespace

TEST_CASE("OpenList pops what the old radix heap popped when no key falls below the last pop", "[grid][astar]") {
    pride::Rng rng(7);
    for (int round = 0; round < 20; ++round) {
        OpenList list;
        OldRadixHeap old;
        compare(rng, list, old, 0.0, round % 2 == 0 ? 0.0 : 0.02, 20000);
        if (round % 2 == 1) CHECK(list.overflowed() > 0);
    }
}

TEST_CASE("OpenList keeps least key then last push for any keys, its fallbacks included", "[grid][astar]") {
    // Keys below the last pop (into the cursor's bucket, below it within the ring, and so far below
    // that the ring is rebuilt) and beyond the ring (the overflow), checked against the definition.
    pride::Rng rng(8);
    std::size_t overflowed = 0, rebuilds = 0;
    for (int round = 0; round < 30; ++round) {
        OpenList list;
        ExactOrder exact;
        compare(rng, list, exact, 0.05, 0.03, 4000);
        overflowed += list.overflowed();
        rebuilds += list.rebuilds();
        // Reused after clear() with nodes left in it, as A* does per query.
        for (std::uint32_t i = 0; i < 50; ++i) list.push({draw_key(rng, 1ull << 40, 0.1, 0.1), i});
        list.clear();
        ExactOrder again;
        compare(rng, list, again, 0.02, 0.01, 1000);
    }
    CHECK(overflowed > 100);
    CHECK(rebuilds > 100);
}

#pragma once
// The per-node arrays of a search (A*, the oracle's Dijkstra, the walks), reused across queries:
// g values, parents, and "seen" and "closed" marks kept as generation stamps, so that a new query
// clears nothing but bumps one counter.
#include <algorithm>
#include <cstdint>
#include <vector>

namespace pride::grid {

struct SearchArrays {
    std::vector<double> g;
    std::vector<std::uint32_t> parent;
    std::vector<std::uint32_t> seen, closed;  // == generation: seen / closed in this query
    std::uint32_t generation = 0;

    /// Ready for a query over `nodes` nodes: resized when the count changes, stamps cleared only
    /// when the generation counter wraps (once every 2^32 queries).
    void prepare(std::size_t nodes) {
        if (g.size() != nodes) {
            g.assign(nodes, 0.0);
            parent.assign(nodes, 0);
            seen.assign(nodes, 0);
            closed.assign(nodes, 0);
            generation = 0;
        }
        if (++generation == 0) {
            std::fill(seen.begin(), seen.end(), 0);
            std::fill(closed.begin(), closed.end(), 0);
            generation = 1;
        }
    }
};

/// The per-node records of A* packed together: g, parent and one stamp per node in 16 bytes, so
/// that a neighbour's test (closed? seen with a better g?) reads one cache line instead of three
/// arrays. The stamp says both marks: `open` (seen this query) or `open + 1` (closed this query);
/// a query advances `open` by 2 and clears nothing unless the counter wraps (every 2^31 queries).
struct PackedSearchArrays {
    struct Record {
        double g;
        std::uint32_t parent;
        std::uint32_t stamp;
    };
    std::vector<Record> records;
    std::uint32_t open = 0;  // this query's "seen" stamp; open + 1 is its "closed" stamp

    void prepare(std::size_t nodes) {
        if (records.size() != nodes) {
            records.assign(nodes, Record{0.0, 0, 0});
            open = 0;
        }
        open += 2;
        if (open == 0) {  // wrapped: stamps from 2^31 queries ago would look current
            for (Record& r : records) r.stamp = 0;
            open = 2;
        }
    }
    std::uint32_t closed() const noexcept { return open + 1; }
};

/// One set of visit marks as generation stamps: the taboo list of a walk (RandomWalker, RuleWalker).
class VisitMarks {
  public:
    /// A new walk over `cells` cells: nothing cleared unless the size changes or the stamp wraps.
    void begin(std::size_t cells) {
        if (marks_.size() != cells) {
            marks_.assign(cells, 0);
            stamp_ = 0;
        }
        if (++stamp_ == 0) {
            std::fill(marks_.begin(), marks_.end(), 0);
            stamp_ = 1;
        }
    }
    bool visited(std::size_t cell) const noexcept { return marks_[cell] == stamp_; }
    void visit(std::size_t cell) noexcept { marks_[cell] = stamp_; }

  private:
    std::vector<std::uint32_t> marks_;
    std::uint32_t stamp_ = 0;
};

}  // namespace pride::grid

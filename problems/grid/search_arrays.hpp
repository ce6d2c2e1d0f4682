#pragma once
// The per-node arrays of a best-first search (A*, the oracle's Dijkstra), reused across queries:
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

}  // namespace pride::grid

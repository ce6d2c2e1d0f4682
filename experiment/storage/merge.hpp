#pragma once
// Stores merged into one (`pride merge A B ... --out C`): the runs of compatible campaigns (the same
// budget and target precisions, every shared problem and algorithm id defined alike), a run stored
// in several of them kept once when they agree bit for bit (wall times aside), refused, naming the
// first that differs, when they do not. The inputs are only read; the output is written whole or
// not at all.
#include <cstddef>
#include <string>
#include <vector>

namespace pride::storage {

struct MergeSummary {
    std::size_t runs = 0;    // runs in the merged store
    std::size_t shared = 0;  // runs found in more than one input (equal, kept once)
};

/// InputError naming the store and what differs; `out` must not exist.
MergeSummary merge_stores(const std::vector<std::string>& inputs, const std::string& out);

}  // namespace pride::storage

#pragma once
// A select without a branch, for tests on random coins: GCC turns `c ? a : b` on doubles into a
// conditional jump when it judges that cheaper, and a jump on a coin is mispredicted every other
// time (SBX's swap and its two spread-factor tests were three such jumps per crossed
// coordinate). The value is a or b, bit for bit.
#include <bit>
#include <cstdint>

namespace pride::detail {

[[gnu::always_inline]] inline double select(bool c, double a, double b) noexcept {
    const std::uint64_t mask = 0 - static_cast<std::uint64_t>(c);
    return std::bit_cast<double>((std::bit_cast<std::uint64_t>(a) & mask) | (std::bit_cast<std::uint64_t>(b) & ~mask));
}

}  // namespace pride::detail

// The CEC data files (problems/continuous/cec/data.hpp): the official loader's three readings of a
// file, numbers, rows of a line each, and permutations. The sizes asked for come from the input's
// first bytes, so that short and long demands both meet any text. What is read must be what was
// asked: that many finite numbers, or permutations of 1..dim.
#include <cmath>
#include <vector>

#include "fuzz/fuzz_support.hpp"
#include "problems/continuous/cec/data.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace pride;
    if (size < 3) return 0;
    const std::size_t rows = 1 + data[0] % 12, dim = 1 + data[1] % 40, count = 1 + data[2] % 4;
    const std::string_view text = fuzz::text(data + 3, size - 3);
    try {
        const std::vector<double> v = continuous::cec::read_numbers(text, rows * dim, "fuzz.txt");
        fuzz::expect(v.size() == rows * dim, "read_numbers returned another count");
        for (const double x : v) fuzz::expect(std::isfinite(x), "read_numbers returned a non-finite number");
    } catch (const InputError&) {
    }
    try {
        const std::vector<double> v = continuous::cec::read_rows(text, rows, dim, "fuzz.txt");
        fuzz::expect(v.size() == rows * dim, "read_rows returned another count");
        for (const double x : v) fuzz::expect(std::isfinite(x), "read_rows returned a non-finite number");
    } catch (const InputError&) {
    }
    try {
        const std::vector<int> p = continuous::cec::read_permutations(text, count, dim, "fuzz.txt");
        fuzz::expect(p.size() == count * dim, "read_permutations returned another count");
        for (std::size_t k = 0; k < count; ++k) {
            std::vector<bool> seen(dim, false);
            for (std::size_t j = 0; j < dim; ++j) {
                const int e = p[k * dim + j];
                fuzz::expect(e >= 0 && static_cast<std::size_t>(e) < dim && !seen[static_cast<std::size_t>(e)],
                             "read_permutations returned something other than a permutation");
                seen[static_cast<std::size_t>(e)] = true;
            }
        }
    } catch (const InputError&) {
    }
    return 0;
}

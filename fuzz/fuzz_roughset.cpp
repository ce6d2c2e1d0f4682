// Rough-set CSV tables through the whole of `pride roughset TABLE --json` (cli/roughset.hpp):
// the reader (roughset/csv.hpp), then the core, reducts and rules of what it read. The JSON it
// prints must be valid UTF-8 whatever bytes the table held.
#include <sstream>

#include "cli/roughset.hpp"
#include "fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace pride;
    cli::RoughsetOptions o;
    o.table = fuzz::write_input(fuzz::text(data, size), "table.csv");
    o.json = true;
    std::ostringstream out;
    try {
        cli::roughset_command(o, out);
        fuzz::expect(fuzz::valid_utf8(out.str()), "pride roughset --json printed invalid UTF-8");
    } catch (const InputError&) {
    }
    return 0;
}

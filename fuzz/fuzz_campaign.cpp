// Campaign files through the whole campaign check of `pride bench` (experiment/campaign_toml.hpp:
// read_campaign, which parses the TOML, checks every key and prepares every problem and
// algorithm), not only toml++. The file is written to SCRATCH/campaigns/, beside a copy of the
// bundled maps in SCRATCH/maps/, so that the examples' `map = "../maps/..."` resolve and the grid
// problems of the seeds are prepared too.
#include <filesystem>

#include "engine/registry.hpp"
#include "experiment/campaign/campaign.hpp"
#include "experiment/campaign/toml.hpp"
#include "framework/error.hpp"
#include "fuzz/fuzz_support.hpp"
#include "problems/continuous/cec/functions.hpp"
#include "problems/grid/rough_rules.hpp"

// Built once per process, not per input: Wan and Gao's (2022) rule book (the reducts of the grid decision
// table, 0.6 s in this build), the registry and the CEC data, so that the first input is not
// charged with them against the 1 s hang limit.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
    (void)pride::grid::grid_rule_book();
    (void)pride::engine::algorithms();
    // The official CEC data where the environment names it (CI does): every function in every
    // dimension, read and checked here once, as data.hpp keeps it per process; else the first
    // input to ask for a suite pays for its files (60 problems of CEC 2017 took 1.2 s so).
    using namespace pride::continuous::cec;
    for (const Suite suite : {Suite::y2017, Suite::y2022}) {
        if (environment_directory(suite).empty()) continue;
        for (int f = 1; f <= size(suite); ++f) {
            for (const std::size_t dim : dimensions(suite, f)) {
                try {
                    (void)data_fingerprint(suite, f, dim);
                } catch (const pride::InputError&) {  // a file missing: the inputs meet its error
                }
            }
        }
    }
    return 0;
}

namespace {
constexpr std::size_t max_prepared_problems = 64;
// Each (problem, algorithm) pair's run is checked too (0.25 ms of CPU a pair here: the CEC 2017
// example's 60 x 16 took 0.7-1 s on a loaded machine).
constexpr std::size_t max_prepared_pairs = 256;
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace pride;
    static const bool maps_copied = [] {
        namespace fs = std::filesystem;
        fs::create_directories(fuzz::scratch() / "campaigns");
        fs::create_directories(fuzz::scratch() / "maps");
        for (const auto& e : fs::directory_iterator(fs::path(PRIDE_SOURCE_DIR) / "examples" / "maps"))
            if (e.path().extension() == ".map") fs::copy_file(e.path(), fuzz::scratch() / "maps" / e.path().filename());
        return true;
    }();
    (void)maps_copied;
    const std::string path = fuzz::write_input(fuzz::text(data, size), "campaigns/campaign.toml");
    try {
        // Preparing builds every problem, linear in their number (4 ms a BBOB problem at D = 20
        // under this build's instrumentation: examples/campaigns/baselines-bbob.toml's 720 take
        // 3 s, over the 1 s hang limit, as its mutants do). Larger campaigns (or those of more
        // pairs) are parsed and checked only; prepare's checks are the same for every problem and
        // are reached by the smaller ones.
        const campaign::Campaign parsed = campaign::parse_campaign(path);
        if (parsed.problems.size() > max_prepared_problems ||
            parsed.problems.size() * parsed.algorithms.size() > max_prepared_pairs)
            return 0;
        const campaign::Campaign c = campaign::read_campaign(path);
        fuzz::expect(c.seeds >= 1, "a campaign with no seeds accepted");
    } catch (const InputError&) {
    }
    return 0;
}

// Campaign files through the whole campaign check of `pride bench` (experiment/campaign_toml.hpp:
// read_campaign, which parses the TOML, checks every key and prepares every problem and
// algorithm), not only toml++. The file is written to SCRATCH/campaigns/, beside a copy of the
// bundled maps in SCRATCH/maps/, so that the examples' `map = "../maps/..."` resolve and the grid
// problems of the seeds are prepared too.
#include <filesystem>

#include "experiment/campaign_toml.hpp"
#include "engine/registry.hpp"
#include "fuzz/fuzz_support.hpp"
#include "problems/grid/rough_rules.hpp"

// Built once per process, not per input: file 000's rule book (the reducts of the grid decision
// table, 0.6 s in this build) and the registry, so that the first input is not charged with them
// against the 1 s hang limit.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
    (void)pride::grid::grid_rule_book();
    (void)pride::engine::algorithms();
    return 0;
}

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
        const engine::Campaign c = engine::read_campaign(path);
        fuzz::expect(c.seeds >= 1, "a campaign with no seeds accepted");
    } catch (const InputError&) {
    }
    return 0;
}

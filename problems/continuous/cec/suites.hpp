#pragma once
// The CEC suites as campaigns take them and their reports count them: their functions (registered as cec2017-fN and
// cec2022-fN, problems/continuous/catalog.cpp, with the dimensions of the official data in
// CatalogEntry::dims), and the budget and number of runs each competition prescribes (section 2.1,
// "Experimental Settings", of each technical report): CEC 2017, "Runs / problem: 51", "MaxFES:
// 10000*D"; CEC 2022, "Runs / problem: 30", MaxFES 200,000 at D = 10 and 1,000,000 at D = 20 (no
// MaxFES for the D = 2 the official 2022 code also defines); CEC 2020 real-world constrained (the
// problems cec2020rw-rcNN, each of its own dimension), 25 runs and MaxFEs by D (Kumar et al. 2020,
// the guidelines' section 1 and eq. 1).
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace pride::continuous::cec {

struct SuiteRules {
    std::string_view name;  // "cec2017", "cec2022", "cec2020rw"
    int functions = 0;      // F1 ... F<functions>
    std::int64_t runs = 0;  // runs per problem the competition prescribes
};

/// The rules of the suite `name`, or nullptr for a name that is no CEC suite.
inline const SuiteRules* suite_rules(std::string_view name) {
    static constexpr SuiteRules rules[] = {{"cec2017", 30, 51}, {"cec2022", 12, 30}, {"cec2020rw", 57, 25}};
    for (const SuiteRules& r : rules)
        if (r.name == name) return &r;
    return nullptr;
}

/// MaxFES as the competition's rules give it: CEC 2017 10000 D; CEC 2022 200,000 at D = 10 and
/// 1,000,000 at D = 20; CEC 2020 real-world by D (its guidelines' eq. 1: 100,000 up to D = 10, then
/// 200,000 up to 30, 400,000 up to 50, 800,000 up to 150, 1,000,000 above); empty for another suite
/// or dimension.
inline std::optional<std::int64_t> default_evaluations(std::string_view suite, std::int64_t dim) {
    if (suite == "cec2017") return 10000 * dim;
    if (suite == "cec2020rw")
        return dim <= 10 ? 100'000 : dim <= 30 ? 200'000 : dim <= 50 ? 400'000 : dim <= 150 ? 800'000 : 1'000'000;
    if (suite == "cec2022" && dim == 10) return 200'000;
    if (suite == "cec2022" && dim == 20) return 1'000'000;
    return std::nullopt;
}

/// One checkpoint: its label ("0.05" of MaxFES for 2017, "k=3" for 2022) and its evaluations
/// (each suite's section 2.2, "Results Record", quoted in experiment/report/cec.hpp).
struct Checkpoint {
    std::string label;
    std::int64_t evaluations = 0;
};

/// CEC 2017's 14 checkpoints for a budget of `max_evaluations`: floor((0.01, 0.02, 0.03, 0.05,
/// 0.1, 0.2, ..., 0.9, 1.0) x MaxFES), each at least 1.
std::vector<Checkpoint> checkpoints_2017(std::int64_t max_evaluations);

/// CEC 2022's 16 checkpoints: floor(D^(k/5-3) x MaxFES) for k = 0..15, each at least 1 (k = 15
/// is MaxFES itself).
std::vector<Checkpoint> checkpoints_2022(std::int64_t max_evaluations, std::int64_t dim);

/// The checkpoints of a problem of `suite` ("cec2022": 2022's; any other: 2017's).
std::vector<Checkpoint> checkpoints(std::string_view suite, std::int64_t max_evaluations, std::int64_t dim);

/// What a campaign records in every run of a problem with a known f* (RunResult::checkpoints):
/// the evaluations of both suites' checkpoints, increasing, each once, so that a store answers
/// for either convention.
std::vector<std::int64_t> recorded_evaluations(std::int64_t max_evaluations, std::int64_t dim);

}  // namespace pride::continuous::cec

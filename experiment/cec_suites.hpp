#pragma once
// The CEC suites as campaigns take them: their functions (registered as cec2017-fN and
// cec2022-fN, problems/continuous/catalog.cpp, with the dimensions of the official data in
// CatalogEntry::dims), and the budget and number of runs each competition prescribes (section 2.1,
// "Experimental Settings", of each technical report): CEC 2017, "Runs / problem: 51", "MaxFES:
// 10000*D"; CEC 2022, "Runs / problem: 30", MaxFES 200,000 at D = 10 and 1,000,000 at D = 20 (no
// MaxFES for the D = 2 the official 2022 code also defines).
#include <cstdint>
#include <optional>
#include <string_view>

namespace pride::engine::cec {

struct SuiteRules {
    std::string_view name;  // "cec2017", "cec2022"
    int functions = 0;      // F1 ... F<functions>
    std::int64_t runs = 0;  // runs per problem the competition prescribes
};

/// The rules of the suite `name`, or nullptr for a name that is no CEC suite.
inline const SuiteRules* suite_rules(std::string_view name) {
    static constexpr SuiteRules rules[] = {{"cec2017", 30, 51}, {"cec2022", 12, 30}};
    for (const SuiteRules& r : rules)
        if (r.name == name) return &r;
    return nullptr;
}

/// MaxFES as the competition's rules give it: CEC 2017 10000 D; CEC 2022 200,000 at D = 10 and
/// 1,000,000 at D = 20; empty for another suite or dimension.
inline std::optional<std::int64_t> default_evaluations(std::string_view suite, std::int64_t dim) {
    if (suite == "cec2017") return 10000 * dim;
    if (suite == "cec2022" && dim == 10) return 200'000;
    if (suite == "cec2022" && dim == 20) return 1'000'000;
    return std::nullopt;
}

}  // namespace pride::engine::cec

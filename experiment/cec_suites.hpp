#pragma once
// The CEC suites as campaigns take them (issue 26): their functions (registered as cec2017-fN and
// cec2022-fN, problems/continuous/catalog.cpp), the dimensions the official data covers, and the
// budget and number of runs each competition prescribes. Data-free: a campaign file is checked
// against these before any data file is read.
//
// Dimensions with data, from the official archives' input_data folders (M_k_Dd.txt,
// shuffle_data_k_Dd.txt): CEC 2017 (CEC17_fast_pow-C++.zip) has every function at D = 10, 30, 50,
// 100; at D = 20 F1-F10 and F20-F28 (no shuffle data for the other hybrids, and none for the
// compositions of hybrids F29, F30); at D = 2 F1-F10 and F21-F28 (no shuffle data at all, so no
// hybrid and no composition of hybrids). CEC 2022 (CEC2022.zip): D = 10 and 20, every function.
//
// Budgets and runs (section 2.1, "Experimental Settings", of each technical report): CEC 2017,
// "Runs / problem: 51", "MaxFES: 10000*D"; CEC 2022, "Runs / problem: 30", MaxFES 200,000 at
// D = 10 and 1,000,000 at D = 20.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

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

/// The dimensions in which the official data defines function `function` of `suite` (empty for
/// a function or suite that does not exist).
inline std::vector<std::int64_t> data_dimensions(std::string_view suite, int function) {
    if (suite == "cec2022")
        return function >= 1 && function <= 12 ? std::vector<std::int64_t>{10, 20} : std::vector<std::int64_t>{};
    if (suite != "cec2017" || function < 1 || function > 30) return {};
    std::vector<std::int64_t> dims;
    if (function <= 10 || (function >= 21 && function <= 28)) dims.push_back(2);
    dims.push_back(10);
    if (function <= 10 || (function >= 20 && function <= 28)) dims.push_back(20);
    for (const std::int64_t d : {30, 50, 100}) dims.push_back(d);
    return dims;
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

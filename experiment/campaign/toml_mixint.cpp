#include "experiment/campaign/toml_mixint.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "experiment/campaign/prepare.hpp"
#include "experiment/campaign/toml_nodes.hpp"
#include "problems/continuous/bbob/instance.hpp"
#include "problems/continuous/bbob_mixint/bbob_mixint.hpp"

namespace pride::campaign {

using namespace toml_nodes;

SuiteLists read_suite_lists(const std::string& file, const toml::table& t, const std::string& name,
                            std::int64_t function_count) {
    const std::string where = fmt::format("{}:{}", file, t.source().begin.line);
    SuiteLists l;
    l.instances = {1, 2, 3, 4, 5};
    for (std::int64_t f = 1; f <= function_count; ++f) l.functions.push_back(f);
    if (const auto* n = t.get("functions")) l.functions = need_integers(file, *n, "functions");
    if (const auto* n = t.get("instances")) l.instances = need_integers(file, *n, "instances");
    if (const auto* n = t.get("dimensions"))
        l.dimensions = need_integers(file, *n, "dimensions");
    else
        fail(where, "a [[suite]] needs 'dimensions' (a list of integers)");
    for (auto* list : {&l.functions, &l.instances, &l.dimensions})
        if (list->empty()) fail(where, "the lists of a [[suite]] must not be empty");
    for (const std::int64_t f : l.functions)
        if (f < 1 || f > function_count)
            fail(at(file, *t.get("functions")),
                 fmt::format("function {} is not in the {} suite (1-{})", f, name, function_count));
    for (const std::int64_t k : l.instances)
        if (k < 1 || k > continuous::bbob::kMaxInstance)
            fail(at(file, *t.get("instances")), continuous::bbob::instance_range_message(name, k));
    for (const std::int64_t d : l.dimensions)
        if (std::find(l.distinct_dimensions.begin(), l.distinct_dimensions.end(), d) == l.distinct_dimensions.end())
            l.distinct_dimensions.push_back(d);
    return l;
}

const char* longest_list(const toml::table& t) {
    const char* key = "dimensions";
    for (const char* other : {"instances", "functions"})
        if (const auto* node = t.get(other);
            node && node->as_array() && node->as_array()->size() > t.get(key)->as_array()->size())
            key = other;
    return key;
}

void add_bbob_mixint_suite(std::vector<CampaignProblem>& out, const std::string& file, const toml::table& t,
                           const ExpandCheck& expand) {
    namespace mi = continuous::bbob_mixint;
    const int line = static_cast<int>(t.source().begin.line);
    const std::string where = fmt::format("{}:{}", file, line);
    const std::string name = "bbob-mixint";
    const std::string prefix = t.get("id") ? need_name(file, t, "id", where) : name;
    const auto [functions, instances, dimensions, dims] = read_suite_lists(file, t, name, mi::kFunctions);
    for (const std::int64_t d : dimensions)
        if (d < static_cast<std::int64_t>(mi::kMinDimension) || d > static_cast<std::int64_t>(mi::kMaxDimension) ||
            d % 5 != 0)
            fail(at(file, *t.get("dimensions")),
                 fmt::format("dimension {}: the {} functions take a multiple of 5 from 5 to 40 (the suite's: 5, 10, "
                             "20, 40; COCO's 80 and 160 use its bbob-largescale functions, which pride does not have)",
                             d, name));
    {
        double memory = 0.0;
        for (const std::int64_t f : functions)
            for (const std::int64_t d : dims)
                memory += static_cast<double>(instances.size()) *
                          problem_memory(engine::ContinuousSpec{mi::name_of(static_cast<int>(f)), d, 1});
        const char* key = longest_list(t);
        expand(functions.size() * instances.size() * dims.size(), memory, at_column(file, *t.get(key)),
               fmt::format("'{}': this [[suite]] expands to {} functions x {} instances x {} dimensions, or", key,
                           functions.size(), instances.size(), dims.size()));
    }
    for (const std::int64_t f : functions)
        for (const std::int64_t d : dims)
            for (const std::int64_t k : instances) {
                CampaignProblem p;
                p.line = line;
                p.suite = name;
                p.id = fmt::format("{}-f{}-i{}-d{}", prefix, f, k, d);
                p.spec = engine::ContinuousSpec{mi::name_of(static_cast<int>(f)), d, k};
                out.push_back(std::move(p));
            }
}

}  // namespace pride::campaign

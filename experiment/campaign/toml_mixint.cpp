#include "experiment/campaign/toml_mixint.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "experiment/campaign/prepare.hpp"
#include "experiment/campaign/toml_nodes.hpp"
#include "problems/continuous/bbob/instance.hpp"
#include "problems/continuous/bbob_mixint/bbob_mixint.hpp"

namespace pride::campaign {

using namespace toml_nodes;

void add_bbob_mixint_suite(std::vector<CampaignProblem>& out, const std::string& file, const toml::table& t,
                           const ExpandCheck& expand) {
    namespace mi = continuous::bbob_mixint;
    const int line = static_cast<int>(t.source().begin.line);
    const std::string where = fmt::format("{}:{}", file, line);
    const std::string name = "bbob-mixint";
    const std::string prefix = t.get("id") ? need_name(file, t, "id", where) : name;
    std::vector<std::int64_t> functions, instances{1, 2, 3, 4, 5}, dimensions;
    for (std::int64_t f = 1; f <= mi::kFunctions; ++f) functions.push_back(f);
    if (const auto* n = t.get("functions")) functions = need_integers(file, *n, "functions");
    if (const auto* n = t.get("instances")) instances = need_integers(file, *n, "instances");
    if (const auto* n = t.get("dimensions"))
        dimensions = need_integers(file, *n, "dimensions");
    else
        fail(where, "a [[suite]] needs 'dimensions' (a list of integers)");
    for (auto* list : {&functions, &instances, &dimensions})
        if (list->empty()) fail(where, "the lists of a [[suite]] must not be empty");
    for (const std::int64_t f : functions)
        if (f < 1 || f > mi::kFunctions)
            fail(at(file, *t.get("functions")),
                 fmt::format("function {} is not in the {} suite (1-{})", f, name, mi::kFunctions));
    for (const std::int64_t k : instances)
        if (k < 1 || k > continuous::bbob::kMaxInstance)
            fail(at(file, *t.get("instances")), continuous::bbob::instance_range_message(name, k));
    for (const std::int64_t d : dimensions)
        if (d < static_cast<std::int64_t>(mi::kMinDimension) || d > static_cast<std::int64_t>(mi::kMaxDimension) ||
            d % 5 != 0)
            fail(at(file, *t.get("dimensions")),
                 fmt::format("dimension {}: the {} functions take a multiple of 5 from 5 to 40 (the suite's: 5, 10, "
                             "20, 40; COCO's 80 and 160 use its bbob-largescale functions, which pride does not have)",
                             d, name));
    std::vector<std::int64_t> dims;
    for (const std::int64_t d : dimensions)
        if (std::find(dims.begin(), dims.end(), d) == dims.end()) dims.push_back(d);
    {
        double memory = 0.0;
        for (const std::int64_t f : functions)
            for (const std::int64_t d : dims)
                memory += static_cast<double>(instances.size()) *
                          problem_memory(engine::ContinuousSpec{mi::name_of(static_cast<int>(f)), d, 1});
        // Blamed on the longest list the table gives.
        const char* key = "dimensions";
        for (const char* other : {"instances", "functions"})
            if (const auto* node = t.get(other);
                node && node->as_array() && node->as_array()->size() > t.get(key)->as_array()->size())
                key = other;
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

#include "experiment/campaign/toml_seeds.hpp"

#include <fmt/format.h>

#include <cstdint>
#include <set>
#include <utility>
#include <vector>

#include "experiment/campaign/prepare.hpp"
#include "experiment/campaign/toml_nodes.hpp"
#include "framework/error.hpp"

namespace pride::campaign {

// A list or a range gives the seeds themselves, so that one campaign's seeds can be split across
// files and machines and their stores grown into one another and merged (a run is known by its
// seed's value).
void read_seeds(Campaign& c, const std::string& file, const toml::node& value) {
    // FILE:LINE as the older keys say it (a count), FILE:LINE:COLUMN for the lists and ranges.
    const auto at = [&](const toml::node& n) { return toml_nodes::at(file, n); };
    const auto at_column = [&](const toml::node& n) { return toml_nodes::at_column(file, n); };
    using toml_nodes::fail;
    const auto in_range = [](std::int64_t s) { return s >= 1 && s <= max_campaign_seeds; };
    if (value.is_integer()) {
        c.seeds = **value.as_integer();
        if (!in_range(c.seeds)) fail(at(value), "'seeds' " + seeds_range_message(c.seeds));
        return;
    }
    std::vector<std::int64_t> seeds;
    if (const toml::array* a = value.as_array()) {
        if (a->empty()) fail(at_column(value), "'seeds' must not be an empty list");
        std::set<std::int64_t> seen;
        for (const toml::node& n : *a) {
            if (!n.is_integer()) fail(at_column(n), "'seeds' must list integers (the seeds)");
            const std::int64_t s = **n.as_integer();
            if (!in_range(s)) fail(at_column(n), "'seeds': a seed " + seeds_range_message(s));
            if (!seen.insert(s).second) fail(at_column(n), fmt::format("'seeds' lists seed {} twice", s));
            seeds.push_back(s);
        }
    } else if (const toml::table* t = value.as_table()) {
        for (auto&& [key, v] : *t)
            if (key.str() != "from" && key.str() != "to")
                fail(at_column(v), "unknown key '" + std::string(key.str()) + "' in the range 'seeds' (from, to)");
        const toml::node* from = t->get("from");
        const toml::node* to = t->get("to");
        if (!from || !to) fail(at_column(value), "the range 'seeds' needs 'from' and 'to' (its first and last seeds)");
        for (const auto& [name, n] : {std::pair{"from", from}, std::pair{"to", to}}) {
            if (!n->is_integer()) fail(at_column(*n), fmt::format("'seeds': '{}' must be an integer", name));
            if (!in_range(**n->as_integer()))
                fail(at_column(*n), fmt::format("'seeds': '{}' {}", name, seeds_range_message(**n->as_integer())));
        }
        const std::int64_t first = **from->as_integer(), last = **to->as_integer();
        if (first > last)
            fail(at_column(value),
                 fmt::format("'seeds' from {} to {} is empty ('from' must be at most 'to': both are included)", first,
                             last));
        seeds.reserve(static_cast<std::size_t>(last - first + 1));
        for (std::int64_t s = first; s <= last; ++s) seeds.push_back(s);
    } else {
        fail(at(value),
             "'seeds' must be an integer N (seeds 1..N), a list of seeds ([4, 5, 9]) or a range ({ from = 4, to = 10 "
             "})");
    }
    c.seeds = static_cast<std::int64_t>(seeds.size());
    c.seed_list = std::move(seeds);
}

}  // namespace pride::campaign

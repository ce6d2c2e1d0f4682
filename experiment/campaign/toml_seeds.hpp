#pragma once
// A campaign file's `seeds` (toml.cpp reads the rest of the file): a count, a list of seeds or a
// range. Internal to the campaign files' reader (it takes toml++'s nodes; not installed).
#include <string>

#include <toml++/toml.h>

#include "experiment/campaign/campaign.hpp"

namespace pride::campaign {

/// Sets `c.seeds`, and `c.seed_list` for a list or a range, from the value of `seeds`: a count N
/// (seeds 1..N), a list of distinct seeds ([4, 5, 9]) or a range with both ends included ({ from =
/// 4, to = 10 }), each seed in [1, max_campaign_seeds], the limit Python's campaigns have too.
/// Anything else is an InputError naming the file, the line (and column) and the key.
void read_seeds(Campaign& c, const std::string& file, const toml::node& value);

}  // namespace pride::campaign

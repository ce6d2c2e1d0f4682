#pragma once
// [[suite]] name = "bbob-mixint" in a campaign file (toml.cpp's add_suite hands the table here).
// Internal to the campaign files' reader (it takes toml++'s nodes; not installed).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "experiment/campaign/campaign.hpp"

namespace pride::campaign {

/// Called once with what the suite expands to, before any problem is made: the number of
/// problems, the memory they need, where to blame and the words to begin a refusal with.
using ExpandCheck =
    std::function<void(std::size_t problems, double memory, const std::string& where, const std::string& what)>;

/// The lists of a COCO suite's [[suite]] table (bbob-constrained's and bbob-mixint's): `functions`
/// (default 1..function_count, each checked to lie there), `instances` (default 1-5, each a bbob
/// instance), `dimensions` (required; each suite checks its own), and the dimensions without
/// repeats, in the file's order. An InputError at the key of a bad list.
struct SuiteLists {
    std::vector<std::int64_t> functions, instances, dimensions, distinct_dimensions;
};
SuiteLists read_suite_lists(const std::string& file, const toml::table& t, const std::string& name,
                            std::int64_t function_count);

/// The key a [[suite]]'s expansion is blamed on: the longest of its lists that the table gives.
const char* longest_list(const toml::table& t);

/// COCO's mixed-integer suite: `functions` (1-24, default all), `instances` (from 1, default 1-5
/// as bbob's), `dimensions` (required; multiples of 5 from 5 to 40, the suite's own below its
/// largescale ones being 5, 10, 20, 40); one problem per (function, dimension, instance),
/// "PREFIX-fN-iK-dD" on bbob-mixint-fN. A bad list is an InputError at its key.
void add_bbob_mixint_suite(std::vector<CampaignProblem>& out, const std::string& file, const toml::table& t,
                           const ExpandCheck& expand);

}  // namespace pride::campaign
